"""Property tests: random exact impulses against the H-form that `fixel seat
--json` prints (the same core, but evaluated here in Fractions), S of
Example 2 derived here from the physics, and G's lost fraction recounted by
enumerating outcomes."""

from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import fixel

from conftest import SCENE_DIR, cli_json
from test_example2 import derive, solve3

fractions = st.fractions(min_value=-20, max_value=20, max_denominator=10**6)
weights = st.one_of(st.just(F(0)), st.fractions(min_value=-1, max_value=4, max_denominator=1000))
DOF3 = ["example2.json", "nonunique.json", "polygon.json", "blob.json", "fig6.json"]


@pytest.fixture(scope="module")
def cases():
    """Per scene: the binding's S and the CLI's H-form as Fractions."""
    out = {}
    for name in DOF3:
        path = SCENE_DIR / name
        doc = cli_json("seat", path)
        h = [([F(x) for x in hs["a"]], F(hs["c"])) for hs in doc["halfspaces"]]
        out[name] = (fixel.seating_set(fixel.Scene.load(path)), h)
    return out


def in_h_form(h, p):
    return all(sum(ai * pi for ai, pi in zip(a, p)) >= c for a, c in h)


@given(name=st.sampled_from(DOF3), p=st.tuples(fractions, fractions, fractions))
def test_a_random_impulse_is_in_s_exactly_when_it_meets_every_halfspace(cases, name, p):
    S, h = cases[name]
    assert S.contains(p) == in_h_form(h, p)


@given(name=st.sampled_from(DOF3), lam=st.lists(weights, min_size=4, max_size=4))
def test_impulses_exactly_on_facets_are_members_as_the_h_form_says(cases, name, lam):
    """apex + Σ λ_k r_k with some λ exactly 0: points on facets, exactly."""
    S, h = cases[name]
    p = [S.apex[k] + sum(lam[j % 4] * r[k] for j, r in enumerate(S.rays)) for k in range(3)]
    assert S.contains(p) == in_h_form(h, p)
    if all(x >= 0 for x in lam[: len(S.rays)]):
        assert S.contains(p)


@given(p=st.tuples(fractions, fractions, fractions))
def test_example2s_s_derived_here_from_the_physics_is_the_cores(example2, p):
    """Example 2: S = apex + cone(−g_i) with apex and g_i derived in the test."""
    apex, generators, linear, threshold = derive(example2.to_dict(), list(p))
    rays = [[-x for x in g] for g in generators]
    R = [[rays[j][k] for j in range(3)] for k in range(3)]
    lam = solve3(R, [p[k] - apex[k] for k in range(3)])
    S = fixel.seating_set(example2)
    assert S.contains(p) == all(x >= 0 for x in lam)
    names, lin, thr = S.eq27(p)
    assert list(lin) == linear and list(thr) == threshold
    assert S.contains(p) == all(a >= b for a, b in zip(lin, thr))


@given(x=st.floats(allow_nan=False, allow_infinity=False))
def test_exact_is_the_binary_value(x):
    assert fixel.exact(x) == F(x)
    assert fixel.exact(F(x)) == F(x)


@given(p=st.tuples(fractions, fractions, fractions))
def test_inputs_in_any_exact_form_agree(example2, p):
    S = fixel.seating_set(example2)
    as_text = [f"{x.numerator}/{x.denominator}" for x in p]
    assert S.contains(p) == S.contains(as_text) == S.contains(list(p))


@settings(max_examples=30)  # each enumerates 4^3 contact modes exactly (~70 ms)
@given(name=st.sampled_from(["example2.json", "nonunique.json"]), lam=st.lists(weights, min_size=3, max_size=3))
def test_membership_means_a_seating_outcome(cases, name, lam):
    """p ∈ S iff one of the step LCP's outcomes at p seats the part: S checked
    against the outcome enumeration, a different algorithm."""
    S, _ = cases[name]
    p = [S.apex[k] + sum(lam[j] * r[k] for j, r in enumerate(S.rays)) for k in range(3)]
    scene = fixel.Scene.load(SCENE_DIR / name)
    assert S.contains(p) == any(o.seated for o in fixel.solutions(scene, p))


def test_the_lost_fraction_of_g_is_the_share_of_grid_impulses_with_a_non_seating_outcome():
    """Second method for G's lost fraction (docs/theory.md, "Lost fraction"):
    at the 140 grid points apex + t·Σ w_j r_j (w on the simplex grid of step
    1/6, t in {1/4, 1/2, 1, 2, 4}) enumerate every one-step outcome; the
    share with a non-seating one must be G.lost_fraction(), and those points
    exactly the ones G leaves out."""
    scene = fixel.Scene.load(SCENE_DIR / "nonunique.json")
    S = fixel.seating_set(scene)
    G = fixel.guaranteed_set(scene, S)
    assert len(S.rays) == 3
    points = lost = 0
    for k0 in range(7):
        for k1 in range(7 - k0):
            w = (F(k0, 6), F(k1, 6), F(6 - k0 - k1, 6))
            for t in (F(1, 4), F(1, 2), F(1), F(2), F(4)):
                p = [S.apex[c] + t * sum(w[j] * S.rays[j][c] for j in range(3)) for c in range(3)]
                every_outcome_seats = all(o.seated for o in fixel.solutions(scene, p))
                assert G.contains(p) == every_outcome_seats, p
                points += 1
                lost += not every_outcome_seats
    assert points == 140 and 0 < lost < points
    assert G.lost_fraction() == F(lost, points)
