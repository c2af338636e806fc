"""Property tests: random exact impulses, membership checked independently."""

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
def test_random_impulse_membership(cases, name, p):
    S, h = cases[name]
    assert S.contains(p) == in_h_form(h, p)


@given(name=st.sampled_from(DOF3), lam=st.lists(weights, min_size=4, max_size=4))
def test_near_boundary_membership(cases, name, lam):
    """apex + Σ λ_k r_k with some λ exactly 0: points on facets, exactly."""
    S, h = cases[name]
    p = [S.apex[k] + sum(lam[j % 4] * r[k] for j, r in enumerate(S.rays)) for k in range(3)]
    assert S.contains(p) == in_h_form(h, p)
    if all(x >= 0 for x in lam[: len(S.rays)]):
        assert S.contains(p)


@given(p=st.tuples(fractions, fractions, fractions))
def test_example2_v_form_from_physics(example2, p):
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
