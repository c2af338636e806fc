"""The paper's Example 2 end to end, from Python (docs/python.md).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/example2.py
"""

import pathlib
from fractions import Fraction

import fixel

scene = fixel.Scene.load(pathlib.Path(__file__).resolve().parents[2] / "data" / "scenes" / "example2.json")
S = fixel.seating_set(scene)
print(scene)
print("apex      ", [str(x) for x in S.apex])
for k, r in enumerate(S.rays):
    print(f"ray {k}     ", [str(x) for x in r])
for a, c in S.halfspaces:
    print("facet      a =", [str(x) for x in a], " c =", c)

p = (-1, -1, -1)
print("p =", p, "in S:", S.contains(p))

# Eq. (27): p is in S iff K⁻¹P p ≥ −K⁻¹a, entry by entry (the paper's table).
names, linear, threshold = S.eq27(p)
print(f"{'y entry':<10} {'K^-1 P p':>10} {'-K^-1 a':>10}")
for name, lin, thr in zip(names, linear, threshold):
    print(f"{name:<10} {str(lin):>10} {str(thr):>10}   ({float(lin):.4f} >= {float(thr):.4f})")

sim = fixel.simulate(scene, p)
print("one step seats the part:", sim.seated, " gaps after:", [str(g) for g in sim.steps[0].gaps])
assert S.contains(p) and sim.seated and linear[3] == Fraction(90, 101)
