"""The approach-aware set J' from Python: the CLI's answers, J' inside J, the
region against J', and typed errors."""

import itertools
import json
from fractions import Fraction as F

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import fixel

from conftest import SCENE_DIR, run_cli

POLYGON = SCENE_DIR / "polygon.json"


@pytest.fixture(scope="module")
def polygon_approach():
    return fixel.approach_set(fixel.Scene.load(POLYGON))


def test_approach_set_agrees_with_the_cli(polygon_approach):
    A = polygon_approach
    code, out, err = run_cli("seat", POLYGON, "--sustained", "--json")
    assert code == 0, err
    cli = json.loads(out)["approach"]
    assert A.decided and cli["decided"]
    assert A.t_star == cli["t_star"] == "15-1*sqrt(226)"
    assert A.on_edges == cli["on_edges"]
    assert A.empty == cli["empty"] and A.empty in (True, None)


@pytest.mark.parametrize("w", [["-1/2", "-9/10", "-3/5"], ["-1", "-3", "0"], ["-1", "-1", "0"], ["1", "0", "0"]])
def test_each_wrench_gets_the_cli_verdict(polygon_approach, w):
    code, out, err = run_cli("seat", POLYGON, "--sustained", "--wrench", ",".join(w), "--json")
    assert code == 0, err
    cli = json.loads(out)["approach"]
    A = polygon_approach
    assert A.contains(w) == cli["contains"]
    assert A.why_not(w) == cli.get("why_not", "")
    hold = A.hold(w)
    if "hold" in cli:
        assert list(hold["fixels"]) == cli["hold"]["fixels"] and hold["t"] == cli["hold"]["t"]
    else:
        assert hold is None


def test_a_wrench_held_on_the_way_is_in_j_but_not_in_j_prime(polygon_approach):
    # Derived by the exact test and seen in the CLI: fixels 0 and 2 hold the
    # part under this push at the scene's rotation (θ = 0), before it turns.
    w = [F(-1, 2), F(-9, 10), F(-3, 5)]
    A = polygon_approach
    assert A.J.contains(w)
    assert not A.contains(w)
    assert A.hold(w) == {"fixels": (0, 2), "theta": 0.0, "t": "0", "slide": None}


# Around (-1, -1, 0), a push into the polygon's seat that J' keeps: about a
# quarter of these wrenches are in J', so the implication is exercised.
_near_seat_push = st.tuples(
    *(st.fractions(min_value=c - F(3, 2), max_value=c + F(3, 2), max_denominator=20) for c in (-1, -1, 0))
)


@settings(max_examples=60, deadline=None)
@given(_near_seat_push)
def test_j_prime_lies_inside_j(polygon_approach, w):
    A = polygon_approach
    if A.contains(w):
        assert A.J.contains(w)


def test_on_a_grid_of_wrenches_j_prime_lies_inside_j_and_leaves_some_of_j_out(polygon_approach):
    A = polygon_approach
    grid = [F(k, 4) for k in range(-8, 9)]
    in_j = in_j_prime = 0
    for w in itertools.product(grid, grid, grid):
        j, j_prime = A.J.contains(w), A.contains(w)
        assert j or not j_prime, w
        in_j += j
        in_j_prime += j_prime
    assert 0 < in_j_prime < in_j  # not vacuous, and J' is a true refinement here


def test_the_region_against_j_prime_matches_the_cli_and_lies_inside_js():
    scene = fixel.Scene.load(POLYGON)
    r = fixel.region(scene, resolution="1/256", push="sustained", approach=True)
    code, out, err = run_cli("region", POLYGON, "--push", "sustained", "--approach", "--resolution", "1/256", "--json")
    assert code == 0, err
    cli = json.loads(out)
    assert cli["target"] == "J'"
    assert [(i.curve, i.u0, i.u1, i.status) for i in r.intervals] == [
        (d["curve"], F(d["u0"]), F(d["u1"]), d["status"]) for d in cli["intervals"]
    ]
    rj = fixel.region(scene, resolution="1/256", push="sustained")
    in_a = sum(i.u1 - i.u0 for i in r.intervals if i.status == "in")
    in_j = sum(i.u1 - i.u0 for i in rj.intervals if i.status == "in")
    assert 0 < in_a < in_j


def test_bad_input_is_a_typed_error_naming_the_field(polygon_approach):
    scene = fixel.Scene.load(POLYGON)
    with pytest.raises(fixel.InputError, match="approach"):
        fixel.region(scene, push="sustained", approach="yes")
    with pytest.raises(fixel.InputError, match="approach"):
        fixel.region(scene, approach=True)
    with pytest.raises(fixel.UnsupportedError, match="exact"):
        fixel.region(scene, push="sustained", approach=True, exact=True)
    with pytest.raises(fixel.InputError, match="wrench"):
        polygon_approach.contains([1, 2])
    with pytest.raises(TypeError, match="sustained"):  # a wrong type is a TypeError, as everywhere
        fixel.approach_set(scene, sustained="J")


@pytest.mark.parametrize("at", ["0:17/8", "0:19/8", "0:2", "0:1/2"])
def test_push_plan_is_the_cli_document(at):
    code, out, err = run_cli("push-plan", POLYGON, "--at", at, "--json")
    assert code == 0, err
    assert fixel.push_plan(fixel.Scene.load(POLYGON), at=at) == json.loads(out)


@pytest.fixture(scope="module")
def polygon_j_prime_region(polygon_approach):
    return fixel.region(fixel.Scene.load(POLYGON), push="sustained", approach=polygon_approach, resolution="1/256")


@settings(max_examples=30, deadline=None)
@given(st.fractions(min_value=F(1, 64), max_value=F(319, 64), max_denominator=64))
def test_push_plan_j_prime_status_is_inside_j_and_is_the_regions(polygon_j_prime_region, u):
    # The region decides whole stretches by cones, the plan one push.
    plan = fixel.push_plan(fixel.Scene.load(POLYGON), at=f"0:{u}")
    j, jp = plan["sustained"]["status"], plan["sustained"]["approach"]["status"]
    if jp == "in":
        assert j == "in"
    if j == "out" and not plan["corner"]:
        assert jp == "out"
    for r in polygon_j_prime_region.intervals:
        if r.u0 < u < r.u1 and r.status != "partial":
            assert jp == r.status


def test_push_plan_bad_points_raise_input_errors_naming_at():
    scene = fixel.Scene.load(POLYGON)
    for at in ["0:9", "3:1", "x"]:
        with pytest.raises(fixel.InputError, match="at"):
            fixel.push_plan(scene, at=at)
    with pytest.raises(TypeError, match="at"):
        fixel.push_plan(scene, at=(0, 1))


@settings(max_examples=20, deadline=None)
@given(st.fractions(min_value=F(1, 64), max_value=F(319, 64), max_denominator=64))
def test_push_plan_j_prime_at_a_smooth_point_is_the_part_frame_verdict_on_g(polygon_approach, u):
    plan = fixel.push_plan(fixel.Scene.load(POLYGON), at=f"0:{u}")
    approach = plan["sustained"]["approach"]
    if plan["corner"]:
        assert "contains" not in approach
        return
    g = plan["wrench_direction"]  # frame B at the seat
    assert approach["contains"] == polygon_approach.contains(g, frame="part")
    assert approach["status"] == ("in" if approach["contains"] else "out")
    assert approach.get("why_not", "") == polygon_approach.why_not(g, frame="part")
    hold = polygon_approach.hold(g, frame="part")
    assert (hold is None) == ("hold" not in approach)
    if hold is not None:
        assert list(hold["fixels"]) == approach["hold"]["fixels"] and hold["t"] == approach["hold"]["t"]


def test_a_frame_other_than_world_or_part_is_an_input_error(polygon_approach):
    with pytest.raises(fixel.InputError, match="frame"):
        polygon_approach.contains(["-1", "-1", "0"], frame="body")


def test_an_undecided_j_prime_reads_as_unknown_not_as_empty():
    # example2_rounded seats on curved contacts: q* is only enclosed, so J's
    # pieces and J' are not decided. Their fields are None, as the CLI's null.
    scene = fixel.Scene.load(SCENE_DIR / "example2_rounded.json")
    A = fixel.approach_set(scene)
    assert A.decided is False and A.undecided_reason
    assert A.t_star is None and A.on_edges is None and A.empty is None
    assert A.J.pieces_decided is False and A.J.empty is None
    code, out, err = run_cli("seat", SCENE_DIR / "example2_rounded.json", "--sustained", "--json")
    assert code == 0, err
    doc = json.loads(out)
    assert doc["approach"]["t_star"] is None and doc["approach"]["empty"] is None
    assert doc["sustained"]["empty"] is None
