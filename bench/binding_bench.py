"""The Python side of the binding-overhead figures in docs/python.md.

    PYTHONPATH=build/python /usr/bin/python3 bench/binding_bench.py
Compare with build/bench/binding_bench (the same calls in C++).
"""

import pathlib
import statistics
import timeit
from fractions import Fraction

import fixel
from fixel import _fixel

scenes = pathlib.Path(__file__).resolve().parents[1] / "data" / "scenes"
S = fixel.seating_set(fixel.Scene.load(scenes / "example2.json"))
rounded = fixel.Scene.load(scenes / "example2_rounded.json")
S_rounded = fixel.seating_set(rounded)


def median(stmt, number, repeat=7):
    """Median per-call time over ``repeat`` runs, like the C++ side's median."""
    return statistics.median(timeit.repeat(stmt, number=number, repeat=repeat, globals=globals())) / number


cases = [
    ("contains, ints", "S.contains((-1, -1, -1))", 20000),
    ("contains, Fractions", "S.contains(p_frac)", 20000),
    ("contains, strings", "S.contains(('-1', '-1', '-1'))", 20000),
    ("contains, raw _fixel (text in)", "S._impl.contains(['-1', '-1', '-1'])", 20000),
    ("region 1/1024 (fixel.region)", "fixel.region(rounded, seating=S_rounded)", 10),
    ("region 1/1024 (raw _fixel)", "_fixel.compute_region(rounded._impl, S_rounded._impl, '1/1024', 'tight', None, None)", 10),
]  # fmt: skip
p_frac = (Fraction(-1), Fraction(-1), Fraction(-1))
for name, stmt, number in cases:
    t = median(stmt, number)
    print(f"{name:<34} {t * 1e6:12.2f} us" if t < 1e-2 else f"{name:<34} {t * 1e3:12.2f} ms")
