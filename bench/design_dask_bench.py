"""Dask LocalCluster (2 workers, loopback) against the C++ thread pool for
fixel.design, and Dask's overhead per task (docs/design.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/design_dask_bench.py [--part polygon] [--every 2]
        [--resolution 1/256] [--batch 16]
"""

import argparse
import pathlib
import time

import fixel

ROOT = pathlib.Path(__file__).resolve().parents[1]


def noop(x):
    return x


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--part", default="polygon")
    ap.add_argument("--every", type=int, default=2, help="keep every k-th of the 24 default candidates")
    ap.add_argument("--resolution", default="1/256")
    ap.add_argument("--batch", type=int, default=16)
    ap.add_argument("--tasks", type=int, default=2000, help="no-op tasks for the overhead figure")
    a = ap.parse_args()
    from dask.distributed import Client, LocalCluster

    part = ROOT / "data" / "scenes" / f"{a.part}.json"
    cands = [(c.curve, c.u) for c in fixel.design_candidates(part)[:: a.every]]
    common = dict(candidates=cands, resolution=a.resolution, top=5)
    t0 = time.perf_counter()
    pool = fixel.design(part, jobs=2, **common)
    t_pool = time.perf_counter() - t0
    triples = pool.stats["triples"]
    print(f"{a.part}: {len(cands)} candidates, {triples} triples, resolution {a.resolution}")
    print(f"thread pool, 2 threads: {t_pool:.2f} s ({triples / t_pool:.1f} layouts/s)")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as client:  # fmt: skip
        t0 = time.perf_counter()
        futures = client.map(noop, range(a.tasks), pure=False)
        client.gather(futures)
        t_noop = time.perf_counter() - t0
        print(f"Dask overhead: {a.tasks} no-op tasks in {t_noop:.2f} s = {1e3 * t_noop / a.tasks:.2f} ms per task")
        t0 = time.perf_counter()
        dask = fixel.design(part, client=client, batch_size=a.batch, **common)
        t_dask = time.perf_counter() - t0
        batches = dask.stats["batches"]
        print(f"Dask LocalCluster, 2 workers, {batches} batches of {a.batch}: {t_dask:.2f} s "
              f"({triples / t_dask:.1f} layouts/s), same ranking: {dask.ranking() == pool.ranking()}")  # fmt: skip
        print(f"Dask / thread pool time: {t_dask / t_pool:.2f}")


if __name__ == "__main__":
    main()
