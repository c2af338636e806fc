"""What running the core in a reused worker thread costs a short call
(docs/python.md, "Stopping a run"): one step of `fixel.simulate` on the
polygon in the caller's thread (no max_seconds) against the same call in a
worker (a max_seconds of an hour sends it there), alternated, best of
--rounds rounds of --calls calls each.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_worker_bench.py
"""

import argparse
import os
import time

import fixel

SCENE = os.path.join(os.path.dirname(__file__), "..", "data", "scenes", "polygon.json")


def per_call(scene, calls, **kw):
    t0 = time.perf_counter()
    for _ in range(calls):
        fixel.simulate(scene, [0, -1, 0], **kw)
    return (time.perf_counter() - t0) / calls


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--calls", type=int, default=500)
    ap.add_argument("--rounds", type=int, default=5)
    args = ap.parse_args()
    scene = fixel.Scene.load(SCENE)
    caller, worker = [], []
    for _ in range(args.rounds):
        caller.append(per_call(scene, args.calls))
        worker.append(per_call(scene, args.calls, max_seconds=3600))
    a, b = min(caller), min(worker)
    print(f"caller's thread {a * 1e6:.0f} us, worker {b * 1e6:.0f} us: the worker adds {(b - a) * 1e6:.0f} us")


if __name__ == "__main__":
    main()
