#!/usr/bin/env python3
"""Writes the bundled region scenes of data/scenes/ (exact decimal strings).

example2_rounded: the paper's Example 2 (same fixels, m = I = h = 1, centre
of mass at the origin) with an outline: the rectangle [-1, 7/5] x [-1, 1]
with its four corners rounded by cubic Beziers (radius 3/10), straight edges
as polylines.
"""
import json
from fractions import Fraction as F

def s(q):
    q = F(q)
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"

def pt(x, y):
    return [s(x), s(y)]

def rounded_rectangle(x0, x1, y0, y1, r, k=F(11, 20)):
    """Counter-clockwise: bottom edge, BR corner, right edge, TR, top, TL, left, BL."""
    curves = []
    def corner(c, a, b):
        # cubic Bezier from c+a to c+b (a, b are radius vectors), k ~ 4(sqrt2-1)/3
        p0 = (c[0] + a[0], c[1] + a[1]); p3 = (c[0] + b[0], c[1] + b[1])
        p1 = (p0[0] + k * b[0], p0[1] + k * b[1]); p2 = (p3[0] + k * a[0], p3[1] + k * a[1])
        curves.append({"type": "bspline", "degree": 3, "knots": ["0"] * 4 + ["1"] * 4,
                       "control_points": [pt(*p0), pt(*p1), pt(*p2), pt(*p3)]})
    def edge(a, b):
        curves.append({"type": "polyline", "points": [pt(*a), pt(*b)]})
    edge((x0 + r, y0), (x1 - r, y0))
    corner((x1 - r, y0 + r), (0, -r), (r, 0))
    edge((x1, y0 + r), (x1, y1 - r))
    corner((x1 - r, y1 - r), (r, 0), (0, r))
    edge((x1 - r, y1), (x0 + r, y1))
    corner((x0 + r, y1 - r), (0, r), (-r, 0))
    edge((x0, y1 - r), (x0, y0 + r))
    corner((x0 + r, y0 + r), (-r, 0), (0, -r))
    return curves

example2 = {
    "name": "example2_rounded",
    "description": "The paper's Example 2 fixels (m = I = h = 1, centre of mass at the origin) on an outline: the "
                   "rectangle [-1, 7/5] x [-1, 1] with its corners rounded by cubic Beziers (radius 3/10). Every "
                   "fixel point is on a straight edge, with that edge's inward normal.",
    "time_step": "1",
    "body": {"dof": 3, "mass": "1", "inertia": "1", "velocity": ["0", "0", "0"], "center_of_mass": ["0", "0"],
             "boundary": rounded_rectangle(F(-1), F(7, 5), F(-1), F(1), F(3, 10))},
    "fixels": [
        {"point": ["-1", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
        {"point": ["0", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
        {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/5"}],
    "pusher": {"mu": "0"}, "background_impulse": ["0", "0", "0"]}

with open("data/scenes/example2_rounded.json", "w") as f:
    json.dump(example2, f, indent=1)
    f.write("\n")

# blob: a closed uniform cubic B-spline (B-splines only). Fixels sit on the
# curve: u = 3 is (P0 + 4 P1 + P2)/6 = (-32/15, 0) with tangent (P2 - P0)/2
# = (0, -1), normal (1, 0); u = 11/2 is (P2 + 23 P3 + 23 P4 + P5)/48 =
# (0, -53/30) with a horizontal tangent, normal (0, 1); the third is at
# u = 6, (P3 + 4 P4 + P5)/6 = (5/6, -5/3), tangent (3, 4/5)/2, whose normal
# (-4/15, 1)/|.| is irrational: the scene uses the rational unit (-7/25, 24/25)
# and marks that fixel "off_boundary" (the outline check skips it).
# Fixel friction 1/10 as in Example 2 (with 1/5 the blob's region is a thin
# stretch whose wrenches graze the boundary of the hit set).
ctrl = [(-2, 1), (F(-11, 5), 0), (-2, -1), (-1, F(-9, 5)), (1, F(-9, 5)), (2, -1), (F(11, 5), 0), (2, 1),
        (1, F(9, 5)), (-1, F(9, 5))]
ctrl = ctrl + ctrl[:3]
blob = {
    "name": "blob",
    "description": "A closed uniform cubic B-spline blob with the fixel pattern of Example 2. Fixels 0 and 1 are on "
                   "the outline at exact inward normals. Fixel 2's point (5/6, -5/3) is on the outline (u = 6), but "
                   "the inward normal there, (-4, 15)/sqrt(241), is irrational: the scene uses the rational unit "
                   "(-7/25, 24/25), 1.3 degrees away, and marks that fixel off_boundary.",
    "time_step": "1",
    "body": {"dof": 3, "mass": "1", "velocity": ["0", "0", "0"],
             "boundary": [{"type": "bspline", "degree": 3, "knots": [str(k) for k in range(len(ctrl) + 4)],
                           "control_points": [pt(*c) for c in ctrl]}]},
    "fixels": [
        {"point": pt(F(-32, 15), 0), "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
        {"point": pt(0, F(-53, 30)), "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
        {"point": pt(F(5, 6), F(-5, 3)), "normal": ["-7/25", "24/25"], "mu": "1/10", "gap": "3/20",
         "off_boundary": True}],
    "pusher": {"mu": "0"}}
with open("data/scenes/blob.json", "w") as f:
    json.dump(blob, f, indent=1)
    f.write("\n")

# polygon: a house-shaped pentagon; centre of mass and inertia come from the
# outline (density 1).
house = {
    "name": "polygon",
    "description": "A house-shaped pentagon; mass, centre of mass and inertia come from the outline (density 1). "
                   "Every fixel point is on an edge, with its inward normal. The bundled scene for the sustained "
                   "push (seat --sustained, region --push sustained).",
    "time_step": "1",
    "body": {"dof": 3, "velocity": ["0", "0", "0"],
             "boundary": [{"type": "polyline",
                           "points": [pt(-1, -1), pt(F(3, 2), -1), pt(F(3, 2), F(1, 2)), pt(F(1, 4), F(3, 2)),
                                      pt(-1, F(1, 2)), pt(-1, -1)]}]},
    "fixels": [
        {"point": ["-1", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10"},
        {"point": ["-1/2", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20"},
        {"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "3/20"}],
    "pusher": {"mu": "0"}}
with open("data/scenes/polygon.json", "w") as f:
    json.dump(house, f, indent=1)
    f.write("\n")

# blob32: a 32-piece closed uniform cubic B-spline (the benchmark's goal
# part), the blob's control polygon refined to 32 points on the same ellipse-
# like shape, with the blob's fixels (on the control hull's scale).
import math
n = 32
ctrl32 = []
for k in range(n):
    a = 2 * math.pi * k / n + math.pi  # start on the left, counter-clockwise
    ctrl32.append((F(round(2.2 * math.cos(a) * 1000), 1000), F(round(1.9 * math.sin(a) * 1000), 1000)))
ctrl32 = ctrl32 + ctrl32[:3]
blob32 = json.loads(json.dumps(blob))
blob32["name"] = "blob32"
blob32["body"]["boundary"] = [{"type": "bspline", "degree": 3, "knots": [str(k) for k in range(len(ctrl32) + 4)],
                               "control_points": [pt(*c) for c in ctrl32]}]
# The fixels sit on this outline: at the knots u = 34 (the leftmost point,
# (P31 + 4 P0 + P1)/6, vertical tangent (P1 - P31)/2) and u = 10 (the lowest
# point, horizontal tangent), and at the knot u = 12 near the blob's third
# fixel, whose inward normal (-283, 793)/|.| is irrational: the rational unit
# (-145/433, 408/433) is 0.08 degrees from it, and the fixel is off_boundary.
def knot_point(j):
    P = ctrl32 + ctrl32[:3]
    return tuple((P[j - 3][c] + 4 * P[j - 2][c] + P[j - 1][c]) / 6 for c in range(2))
blob32["description"] = ("A 32-piece closed uniform cubic B-spline (the benchmark's goal part). Fixels 0 and 1 are on "
                         "the outline at exact inward normals (u = 34 and u = 10). Fixel 2 is on it at u = 12, where "
                         "the inward normal (-283, 793)/sqrt(708938) is irrational: the scene uses the rational unit "
                         "(-145/433, 408/433), 0.08 degrees away, and marks that fixel off_boundary.")
blob32["fixels"][0]["point"] = pt(*knot_point(34))
blob32["fixels"][1]["point"] = pt(*knot_point(10))
blob32["fixels"][2]["point"] = pt(*knot_point(12))
blob32["fixels"][2]["normal"] = ["-145/433", "408/433"]
blob32 = {k: blob32[k] for k in ["name", "description", "time_step", "body", "fixels", "pusher"]}
with open("data/scenes/blob32.json", "w") as f:
    json.dump(blob32, f, indent=1)
    f.write("\n")

# nonunique_part: the DESIGN §3 nonuniqueness scene (m = 1, I = 1/2, centre
# of mass at the origin, as given there) with a round outline: a closed
# uniform cubic B-spline on 12 control points at radius 1.1.
n = 12
ring = [(F(round(1.1 * math.cos(2 * math.pi * k / n) * 1000), 1000), F(round(1.1 * math.sin(2 * math.pi * k / n) * 1000), 1000))
        for k in range(n)]
ring = ring + ring[:3]
with open("data/scenes/nonunique.json") as f:
    nonunique = json.load(f)
nonunique["name"] = "nonunique_part"
nonunique["description"] = (
    "The nonuniqueness scene (nonunique.json: m = 1, I = 1/2, centre of mass at the origin) with a round outline "
    "(a closed uniform cubic B-spline on 12 control points at radius 1.1) for the pushing region. The fixels keep "
    "nonunique's contact points and normals, which set the dynamics but are not on this outline (up to 0.2 m and "
    "30 degrees off), so each is marked off_boundary. The background impulse is nonunique's p = apex - sum g_i: "
    "interior to S but not guaranteed.")
for fx in nonunique["fixels"]:
    fx["off_boundary"] = True
nonunique = {k: nonunique[k] for k in ["name", "description"] + [k for k in nonunique if k not in ("name", "description")]}
# The background impulse is the DESIGN's impulse p = apex − Σ g_i: interior
# to S but not guaranteed, so every push starts inside S and the question is
# which pushes also reach G.
nonunique["background_impulse"] = ["29157/10540", "-71119/105400", "-1169839/263500"]
nonunique["body"]["boundary"] = [{"type": "bspline", "degree": 3, "knots": [str(k) for k in range(len(ring) + 4)],
                                  "control_points": [pt(*c) for c in ring]}]
with open("data/scenes/nonunique_part.json", "w") as f:
    json.dump(nonunique, f, indent=1)
    f.write("\n")
