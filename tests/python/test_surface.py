"""The module's surface: what every scene argument accepts, what dir(fixel)
lists, what does not pickle, and G's pieces against a second method."""

import inspect
import json
import itertools
import pickle
from fractions import Fraction as F

import pytest

import fixel

from conftest import SCENE_DIR, cli_json


def _rows_text(rows):
    return [([str(x) for x in a], str(c)) for a, c in rows]


def _json_rows(rows):
    return [(r["a"], r["c"]) for r in rows]


def _in_piece(piece, p):
    """Membership in one piece from its rows alone, in Fractions."""

    def dot(a):
        return sum(x * y for x, y in zip(a, p))

    return all(dot(a) >= c for a, c in piece.closed) and all(dot(a) > c for a, c in piece.strict)


@pytest.mark.parametrize("name", ["nonunique_part.json", "polygon.json", "example2.json"])
def test_gs_pieces_and_non_seating_sets_are_the_clis_rows(name):
    G = fixel.guaranteed_set(SCENE_DIR / name)
    cli = cli_json("seat", SCENE_DIR / name, "--guaranteed")["guaranteed_set"]
    assert [p.dimension for p in G.pieces] == [p["dimension"] for p in cli["pieces"]]
    assert [(_rows_text(p.closed), _rows_text(p.strict)) for p in G.pieces] == [
        (_json_rows(p["closed"]), _json_rows(p["strict"])) for p in cli["pieces"]
    ]
    assert [(_rows_text(n.closed), _rows_text(n.strict)) for n in G.non_seating_impulses] == [
        (_json_rows(n["closed"]), _json_rows(n["strict"])) for n in cli["non_seating"]
    ]
    assert [(list(m), f) for m, f in G.non_seating] == [(n["modes"], n["open_fixel"]) for n in cli["non_seating"]]


@pytest.mark.parametrize("name", ["nonunique_part.json", "nonunique.json"])  # the scenes where G is not S
def test_gs_pieces_partition_g_and_recount_its_lost_fraction(name):
    # A second method: lost_fraction's own sample of S (apex + t·Σ w_j r_j,
    # w on the simplex grid, five magnitudes t), judged here by the pieces'
    # rows in Fractions, gives the C++ count exactly, and no point lies in
    # two pieces.
    G = fixel.guaranteed_set(SCENE_DIR / name)
    S = G.seating
    grid, k = 4, len(S.rays)
    lost = total = 0
    for w in itertools.product(range(grid + 1), repeat=k):
        if sum(w) != grid:
            continue
        d = [sum(F(wj, grid) * r[i] for wj, r in zip(w, S.rays)) for i in range(S.dof)]
        for t in (F(1, 4), F(1, 2), F(1), F(2), F(4)):
            p = [a + t * x for a, x in zip(S.apex, d)]
            inside = [_in_piece(piece, p) for piece in G.pieces]
            assert sum(inside) <= 1, p  # disjoint
            assert any(inside) == G.contains(p), p
            total += 1
            lost += not any(inside)
    assert 0 < lost < total  # the sample sees both G and S minus G
    assert F(lost, total) == G.lost_fraction(grid)


def test_every_function_that_takes_a_scene_takes_its_path_too():
    path = SCENE_DIR / "polygon.json"
    scene = fixel.Scene.load(path)
    assert fixel.seating_set(str(path)).halfspaces == fixel.seating_set(scene).halfspaces
    assert fixel.sustained_set(path).cones == fixel.sustained_set(scene).cones
    assert fixel.region(path, resolution="1/16").to_json()["intervals"] == fixel.region(
        scene, resolution="1/16"
    ).to_json()["intervals"]
    assert fixel.push_plan(path, at="0:1/2") == fixel.push_plan(scene, at="0:1/2")
    apex = fixel.seating_set(scene).apex
    assert fixel.simulate(path, apex).seated == fixel.simulate(scene, apex).seated
    with pytest.raises(fixel.InputError) as e:
        fixel.seating_set(SCENE_DIR / "no_such_scene.json")
    assert "no_such_scene.json" in str(e.value)
    with pytest.raises(TypeError, match="a fixel.Scene, a scene dict or a path"):
        fixel.seating_set(42)


def test_dir_lists_the_public_api_and_no_imported_helper():
    names = dir(fixel)
    assert set(fixel.__all__) <= set(names)
    for helper in ("np", "os", "json", "contextlib", "frac", "fracs", "text", "whole", "vector", "stoppable"):
        assert helper not in names
        assert hasattr(fixel, helper)  # still there for the submodules
    assert all(hasattr(fixel, n) for n in names)


def test_design_shows_no_test_hook_in_its_signature():
    assert [p for p in inspect.signature(fixel.design).parameters if p.startswith("_")] == []


def test_a_region_refuses_to_pickle_and_says_what_to_send_instead():
    r = fixel.region(SCENE_DIR / "polygon.json", resolution="1/16")
    with pytest.raises(TypeError, match="to_json"):
        pickle.dumps(r)


def _nested(depth):
    d = x = {}
    for _ in range(depth - 1):
        x["a"] = {}
        x = x["a"]
    return d


def test_a_scene_dict_nested_too_deeply_gets_the_loaders_own_parse_error_at_any_depth():
    from fixel import _fixel

    # The scene loader's message for the same text (second method).
    with pytest.raises(fixel.ParseError) as loader:
        _fixel.parse_scene(json.dumps(_nested(65)), "deep", None)
    for depth in (65, 400, 100_000):  # 65 to about 490 once reached the loader, deeper a RecursionError
        with pytest.raises(fixel.ParseError) as e:
            fixel.Scene.from_dict(_nested(depth), source="deep")
        # The first level past 64 is named, as the loader names it.
        assert (e.value.field, e.value.value) == ("deep", "depth 65")
        assert str(e.value) == str(loader.value) == "deep: depth 65 nests deeper than 64 levels"
    with pytest.raises(fixel.SceneError):  # 64 levels pass the nesting check: the scene itself is wrong
        fixel.Scene.from_dict(_nested(64), source="deep")


def test_a_scene_dict_that_contains_itself_is_named_where():
    d = json.loads((SCENE_DIR / "polygon.json").read_text())
    d["fixels"][1]["extra"] = d["fixels"]
    with pytest.raises(fixel.InputError) as e:
        fixel.Scene.from_dict(d, source="loop")
    assert e.value.field == "fixels[1].extra" and e.value.value == "a list"
    assert "contains itself" in str(e.value)
    d["fixels"][1]["extra"] = {}
    d["self"] = d
    with pytest.raises(fixel.InputError, match="^self: a dict contains itself"):
        fixel.Scene.from_dict(d, source="loop")


def _shared(levels):
    """A list holding the same list twice at each level: levels + 1 lists
    and one string, unrolled to 2^levels strings."""
    a = ["0"]
    for _ in range(levels):
        a = [a, a]
    return a


def test_a_scene_dict_sharing_a_list_is_counted_as_its_text_would_be_and_refused_at_once_past_the_loaders_size():
    import time

    d = json.loads((SCENE_DIR / "polygon.json").read_text())
    d["extra"] = _shared(40)  # 2^40 strings as text; the walk that wrote it out took hours
    started = time.monotonic()
    with pytest.raises(fixel.InputError) as e:
        fixel.Scene.from_dict(d, source="shared")
    assert time.monotonic() - started < 60  # far from hours; a bound, not a timing
    # Its count, by hand: 2^40 strings and 2^0 + 2^1 + ... + 2^40 lists
    # (each use counts, as in the text), and the scene's own values (the
    # same dict without it, counted by a plain walk).
    del d["extra"]
    own = _count(d)
    assert e.value.field == "shared"
    assert e.value.value == f"{2**40 + 2**41 - 1 + own} values"
    assert "larger than a scene file can be" in str(e.value)
    # Shared but small: a closed outline whose last point is its first
    # point's list gives the scene the unshared tree gives.
    points = d["body"]["boundary"][0]["points"]
    assert points[-1] == points[0]
    points[-1] = points[0]
    assert fixel.Scene.from_dict(d).to_dict() == fixel.Scene.from_dict(json.loads(json.dumps(d))).to_dict()


def _count(x):
    if isinstance(x, dict):
        return 1 + sum(_count(v) for v in x.values())
    if isinstance(x, list):
        return 1 + sum(_count(v) for v in x)
    return 1


def test_a_scene_dict_under_the_size_limit_but_slow_to_write_out_stops_at_max_seconds():
    d = json.loads((SCENE_DIR / "polygon.json").read_text())
    d["extra"] = _shared(24)  # 2^25 values: under the limit, many seconds to write out
    with pytest.raises(fixel.StoppedError, match="^load: time limit reached after"):
        fixel.Scene.from_dict(d, max_seconds=0.05)


def test_a_region_copies_shallowly_and_shares_its_core():
    import copy

    r = fixel.region(SCENE_DIR / "polygon.json", resolution="1/16")
    c = copy.copy(r)
    assert c is not r and c._impl is r._impl and c.to_json() == r.to_json()
