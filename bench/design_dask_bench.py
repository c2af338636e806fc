"""Dask LocalCluster (2 workers, loopback) against the C++ thread pool for
fixel.design, each with the bound and exhaustive, and Dask's overhead per
task (docs/design.md).

    PYTHONPATH=build/python /usr/bin/python3 bench/design_dask_bench.py [--part polygon] [--every 2]
        [--spacing S] [--resolution 1/256] [--batch 16] [--wave 8] [--no-exhaustive]
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
    ap.add_argument("--every", type=int, default=2, help="keep every k-th of the candidates")
    ap.add_argument("--spacing", default=None, help="candidates every this arc length (default: 24)")
    ap.add_argument("--resolution", default="1/256")
    ap.add_argument("--batch", type=int, default=16)
    ap.add_argument("--wave", type=int, default=8, help="batches per round of the bounded search")
    ap.add_argument("--tasks", type=int, default=2000, help="no-op tasks for the overhead figure")
    ap.add_argument("--no-exhaustive", action="store_true", help="skip the runs that score every triple")
    a = ap.parse_args()
    from dask.distributed import Client, LocalCluster

    part = ROOT / "data" / "scenes" / f"{a.part}.json"
    cands = [(c.curve, c.u) for c in fixel.design_candidates(part, spacing=a.spacing)[:: a.every]]
    common = dict(candidates=cands, resolution=a.resolution, top=5)
    runs = [("bound", False)] + ([] if a.no_exhaustive else [("every triple", True)])
    pool = {}
    for name, exhaustive in runs:
        t0 = time.perf_counter()
        pool[name] = fixel.design(part, jobs=2, exhaustive=exhaustive, **common)
        pool[name + " s"] = time.perf_counter() - t0
    triples = pool["bound"].stats["triples"]
    print(f"{a.part}: {len(cands)} candidates, {triples} triples, resolution {a.resolution}")
    for name, _ in runs:
        d = pool[name]
        print(f"thread pool, 2 threads, {name}: {pool[name + ' s']:.2f} s, {scored(d)} layouts scored")
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                      dashboard_address=None) as cluster, Client(cluster) as client:  # fmt: skip
        t0 = time.perf_counter()
        futures = client.map(noop, range(a.tasks), pure=False)
        client.gather(futures)
        t_noop = time.perf_counter() - t0
        print(f"Dask overhead: {a.tasks} no-op tasks in {t_noop:.2f} s = {1e3 * t_noop / a.tasks:.2f} ms per task")
        for name, exhaustive in runs:
            t0 = time.perf_counter()
            dask = fixel.design(part, client=client, batch_size=a.batch, wave=a.wave, exhaustive=exhaustive, **common)
            t_dask = time.perf_counter() - t0
            s = dask.stats
            print(f"Dask LocalCluster, 2 workers, {name}: {t_dask:.2f} s, {scored(dask)} layouts scored in "
                  f"{s['batches']} batches of at most {a.batch} ({s['rounds']} rounds); "
                  f"same ranking as the pool: {dask.ranking() == pool[name].ranking()}; "
                  f"Dask / thread pool time: {t_dask / pool[name + ' s']:.2f}")  # fmt: skip


def scored(d):
    s = d.stats
    return s["triples"] - s["singular"] - s["bounded"]


if __name__ == "__main__":
    main()
