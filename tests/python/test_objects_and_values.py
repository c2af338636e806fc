"""Objects passed between calls belong to their scene, vectors keep their
order, exact values of any size convert, and option values that were
accepted or refused wrongly (a second review of the Python API)."""

from decimal import Decimal
from fractions import Fraction as F

import numpy as np
import pytest

import fixel
from fixel._exact import frac, int_text

from conftest import SCENE_DIR, run_cli


@pytest.fixture(scope="module")
def polygon():
    return fixel.Scene.load(SCENE_DIR / "polygon.json")


@pytest.fixture(scope="module")
def rounded():
    return fixel.Scene.load(SCENE_DIR / "example2_rounded.json")


# --- vectors -----------------------------------------------------------------


def test_a_generator_is_read_once_in_order_whatever_its_entries(example2):
    S = fixel.seating_set(example2)
    # A Decimal sends the conversion to its slow path, which once read the
    # generator a second time and tested what was left of it.
    with pytest.raises(fixel.InputError) as e:
        S.contains(x for x in [1, Decimal(2), -1, -1, -1])
    assert e.value.field == "p"
    for p in ([Decimal(-1), -1, -1], [-1, -1, -1], [F(1, 3), 0, 5]):
        assert S.contains(x for x in p) == S.contains(list(p))


@pytest.mark.parametrize("unordered", [{-1, -2, -3}, frozenset({-1, -2, -3}), {0: -1, 1: -2, 2: -3}])
def test_an_unordered_container_is_not_a_vector(example2, unordered):
    with pytest.raises(TypeError, match="has no order"):
        fixel.seating_set(example2).contains(unordered)


@pytest.mark.parametrize("raw", [memoryview(b"abc"), bytearray(b"abc"), b"abc"])
def test_bytes_are_not_a_vector(example2, raw):
    with pytest.raises(TypeError, match="not a sequence of exact numbers"):
        fixel.seating_set(example2).contains(raw)


def test_a_list_of_arrays_and_a_two_dimensional_array_are_impulses_per_step(example2):
    lists = fixel.simulate(example2, [[-1, -1, -1], [0, 0, 0]], steps=2)
    arrays = fixel.simulate(example2, [np.array([-1, -1, -1]), np.array([0, 0, 0])], steps=2)
    table = fixel.simulate(example2, np.array([[-1, -1, -1], [0, 0, 0]]), steps=2)
    for run in (arrays, table):
        assert [s.q for s in run.steps] == [s.q for s in lists.steps]
        assert [s.p_n for s in run.steps] == [s.p_n for s in lists.steps]


# --- exact values of any size ------------------------------------------------


@pytest.mark.parametrize(
    "n", [7**20000, -(3**30001), 10**4300, 10**4299 - 1, 10**8000 + 1, 0, -1], ids=lambda n: f"{n.bit_length()}-bits"
)
def test_integers_beyond_pythons_text_limit_convert_both_ways(n):
    # Python refuses int(str) and str(int) past 4300 digits. Two checks
    # independent of the conversion: the round trip, and casting out nines
    # (a number and its digit sum agree modulo 9).
    t = int_text(n)
    assert frac(t) == n
    assert frac(f"{t}/7") == F(n, 7)
    digits = t.lstrip("-")
    assert (t[0] == "-") == (n < 0)
    assert digits == "0" or not digits.startswith("0")
    assert sum(map(int, digits)) % 9 == abs(n) % 9


def test_a_tiny_gap_gives_an_exact_apex_with_thousands_of_digits(polygon):
    d = polygon.to_dict()
    d["fixels"][0]["gap"] = "1e-9999"
    S = fixel.seating_set(fixel.Scene.from_dict(d))
    # The apex is a point of S: every facet a·p ≥ c holds, with equality on
    # at least one (checked in Fractions, independently of the core).
    slack = [sum(a_k * p_k for a_k, p_k in zip(a, S.apex)) - c for a, c in S.halfspaces]
    assert min(slack) == 0
    assert any(x.denominator.bit_length() > 14000 for x in S.apex)


def test_a_huge_integer_in_a_scene_dict_is_read_exactly(example2):
    d = example2.to_dict()
    d["body"]["mass"] = 10**5000
    heavy = fixel.Scene.from_dict(d)
    assert heavy.to_dict()["body"]["mass"] == int_text(10**5000)


def test_exact_reads_strings_as_the_core_does():
    assert fixel.exact("0.1") == F(1, 10)
    assert fixel.exact("-3/7") == F(-3, 7)
    assert fixel.exact("1e-3") == F(1, 1000)
    assert fixel.exact(0.1) == F(3602879701896397, 36028797018963968)
    for refused in (" 1/2 ", "1_000", "abc", "1/0"):
        with pytest.raises(fixel.ParseError) as e:
            fixel.exact(refused)
        assert e.value.field == "x"
    with pytest.raises(fixel.ParseError, match="exponent"):
        fixel.exact("1e1000000000")  # once built 10**(10**9) in Python
    for x in (float("nan"), float("inf"), np.float64("-inf")):
        with pytest.raises(fixel.InputError, match="not a finite number"):
            fixel.exact(x)


# --- objects from another scene ----------------------------------------------


def test_a_seating_set_of_another_scene_is_refused_by_every_call(polygon, rounded):
    S_other = fixel.seating_set(polygon)
    G_other = fixel.guaranteed_set(polygon)
    for call, field in (
        (lambda: fixel.region(rounded, seating=S_other), "seating"),
        (lambda: fixel.region(rounded, guaranteed=G_other), "guaranteed"),
        (lambda: fixel.sample(rounded, 5, seating=S_other), "seating"),
        (lambda: fixel.guaranteed_set(rounded, seating=S_other), "seating"),
        (lambda: fixel.to_off(rounded, S_other, "/nonexistent"), "seating"),
        (lambda: fixel.approach_set(rounded, sustained=fixel.sustained_set(polygon)), "sustained"),
        (lambda: fixel.region(rounded, push="sustained", seating=fixel.sustained_set(polygon)), "seating"),
    ):
        with pytest.raises(fixel.InputError, match="another scene") as e:
            call()
        assert e.value.field == field


def test_the_refusal_names_the_first_field_that_differs_and_both_values(polygon):
    d = polygon.to_dict()
    d["fixels"][0]["gap"] = "1/5"
    moved = fixel.Scene.from_dict(d, source="moved")
    with pytest.raises(fixel.InputError) as e:
        fixel.region(moved, guaranteed=fixel.guaranteed_set(polygon))
    assert e.value.field == "guaranteed"
    want = polygon.to_dict()["fixels"][0]["gap"]  # the polygon's own gap, as its dict writes it
    assert str(e.value) == (
        f"guaranteed: built from scene 'polygon' belongs to another scene than {moved.name!r}: "
        f"fixels[0].gap is '1/5' here, {want!r} in the scene it was built from; build it from this scene"
    )
    # A description only: the Python layer wants equal scenes, and says which key.
    d = polygon.to_dict()
    d["description"] = "another"
    with pytest.raises(fixel.InputError, match=r": description is .another. here, "):
        fixel.region(fixel.Scene.from_dict(d, source="polygon"), guaranteed=fixel.guaranteed_set(polygon))


def test_a_set_of_an_equal_scene_loaded_twice_is_accepted(rounded):
    again = fixel.Scene.load(SCENE_DIR / "example2_rounded.json")
    assert again is not rounded
    own = fixel.region(rounded)
    shared = fixel.region(rounded, seating=fixel.seating_set(again))
    assert [(i.curve, i.u0, i.u1, i.status) for i in shared.intervals] == [
        (i.curve, i.u0, i.u1, i.status) for i in own.intervals
    ]


def test_a_sustained_set_given_as_seating_is_the_j_the_region_uses(polygon, example2):
    J = fixel.sustained_set(polygon)
    given = fixel.region(polygon, push="sustained", seating=J)
    built = fixel.region(polygon, push="sustained")
    assert given.seating is J
    assert [(i.curve, i.u0, i.u1, i.status) for i in given.intervals] == [
        (i.curve, i.u0, i.u1, i.status) for i in built.intervals
    ]
    with pytest.raises(TypeError, match="SustainedSet"):
        fixel.region(polygon, push="sustained", seating=fixel.seating_set(polygon))


# --- option values -------------------------------------------------------------


@pytest.mark.parametrize("text, message", [("abc", "not an exact number"), ("nan", "not an exact number"),
                                           ("1/0", "zero denominator")])  # fmt: skip
def test_a_bad_resolution_string_is_the_cores_parse_error(rounded, text, message):
    for kwargs in ({"resolution": text}, {"resolution_length": text}):
        with pytest.raises(fixel.ParseError, match=message) as e:
            fixel.region(rounded, **kwargs)
        assert e.value.field == next(iter(kwargs))


def test_option_types_are_checked_not_coerced(polygon, example2):
    with pytest.raises(TypeError, match="guaranteed"):
        fixel.region(example2, guaranteed=5)
    with pytest.raises(TypeError, match="guaranteed: 'no' is not a bool"):
        fixel.push_plan(polygon, at="0:1/2", guaranteed="no")
    with pytest.raises(TypeError, match="source"):
        fixel.Scene.from_dict(example2.to_dict(), source=None)
    with pytest.raises(TypeError, match="Scene.load"):
        fixel.Scene("x")


def test_push_names_what_is_missing_or_doubled(polygon):
    with pytest.raises(fixel.InputError, match="give one of") as e:
        fixel.push(polygon)
    assert e.value.field == "wrench"
    with pytest.raises(fixel.InputError, match="give only one") as e:
        fixel.push(polygon, wrench=(0, -1, 0), at="0:1/2")
    assert e.value.field == "at"


@pytest.mark.parametrize(
    "candidates, exc, field",
    [
        ([(F(7, 10), "1/3"), (0, "3/2"), (0, "5/2")], TypeError, None),  # a curve index is an int
        ([(True, "1/3"), (0, "3/2"), (0, "5/2")], TypeError, None),
        ([(0, "1/3"), (0, "1/3"), (0, "5/2"), (0, "7/2")], fixel.InputError, "candidates[1]"),
        ([{"curve": 0}], fixel.InputError, "candidates[0]"),
        ([(0, 0, 0)], fixel.InputError, "candidates[0]"),
        (["abc"], fixel.InputError, "candidates[0]"),
        (5, TypeError, None),
    ],
)
def test_bad_design_candidates_name_the_entry(polygon, candidates, exc, field):
    with pytest.raises(exc) as e:
        fixel.design_candidates(polygon, candidates)
    if field is not None:
        assert e.value.field == field


def test_a_duplicate_candidate_names_the_first(polygon):
    with pytest.raises(fixel.InputError, match=r"same boundary point as candidates\[0\]"):
        fixel.design_candidates(polygon, [(0, "1/3"), (0, "3/2"), (0, "1/3")])


def test_a_missing_candidate_file_says_why(polygon, tmp_path):
    with pytest.raises(fixel.InputError, match="No such file or directory"):
        fixel.design_candidates(polygon, tmp_path / "none.json")
    with pytest.raises(fixel.InputError, match="is a directory"):
        fixel.design_candidates(polygon, tmp_path)


# --- results -------------------------------------------------------------------


def test_the_exact_regions_root_count_is_in_its_stats(rounded):
    r = fixel.region(rounded, exact=True)
    assert r.stats.roots == r.to_json()["stats"]["roots"]
    assert r.stats.roots > 0
    assert fixel.region(rounded).stats.roots == 0


def test_a_sustained_region_draws_as_the_cli_draws_it(polygon, tmp_path):
    py_svg, cli_svg = tmp_path / "py.svg", tmp_path / "cli.svg"
    fixel.to_svg(py_svg, fixel.region(polygon, push="sustained"))
    code, _, err = run_cli("region", SCENE_DIR / "polygon.json", "--push", "sustained", "--svg", cli_svg)
    assert code == 0, err
    assert py_svg.read_text() == cli_svg.read_text()


def test_a_region_against_g_draws_with_g_as_the_cli_draws_it(tmp_path):
    part = fixel.Scene.load(SCENE_DIR / "nonunique_part.json")
    py_svg, cli_svg = tmp_path / "py.svg", tmp_path / "cli.svg"
    fixel.to_svg(py_svg, fixel.region(part, guaranteed=True))
    code, _, err = run_cli("region", SCENE_DIR / "nonunique_part.json", "--guaranteed", "--svg", cli_svg)
    assert code == 0, err
    assert py_svg.read_text() == cli_svg.read_text()


def test_every_set_has_a_readable_repr(example2, polygon):
    assert "example2" in repr(fixel.guaranteed_set(example2))
    assert "polygon" in repr(fixel.sustained_set(polygon))
    assert "polygon" in repr(fixel.approach_set(polygon))
