"""Every documented bad input raises the documented exception (docs/python.md)."""

import json
from decimal import Decimal
from fractions import Fraction as F

import numpy as np
import pytest

import fixel

from conftest import SCENE_DIR, cli_error

P = (-1, -1, -1)


@pytest.fixture(scope="module")
def S(example2):
    return fixel.seating_set(example2)


@pytest.mark.parametrize(
    "bad, exc",
    [
        ((-1.0, -1, -1), TypeError),  # a float is not exact
        ((np.float64(-1), -1, -1), TypeError),
        (np.array([-1.0, -1.0, -1.0]), TypeError),  # numpy float array
        (np.array([-1, -1, -1], dtype=np.float32), TypeError),
        (None, TypeError),
        ((None, -1, -1), TypeError),
        ((True, -1, -1), TypeError),
        ("-1,-1,-1", TypeError),  # a string is not a vector
        ((1 + 2j, 0, 0), TypeError),
        (-1, TypeError),  # a number is not a vector
        ((-1, -1), fixel.InputError),  # wrong shape for dof 3
        ((-1, -1, -1, -1), fixel.InputError),
        (np.zeros((3, 1), dtype=int), fixel.InputError),
        (("-1", "x", "-1"), fixel.ParseError),
        (("1/0", "-1", "-1"), fixel.ParseError),
    ],
)
def test_contains_refuses_a_vector_of_the_wrong_length_or_type(S, bad, exc):
    with pytest.raises(exc):
        S.contains(bad)


def test_float_message_says_why(S):
    with pytest.raises(TypeError, match="not exact"):
        S.contains((0.1, 0, 0))
    with pytest.raises(TypeError, match="fixel.exact"):
        S.contains((0.1, 0, 0))


def test_exact_inputs_accepted(S):
    for p in [(F(-1), -1, "-1"), ("-1", "-1.0", "-10/10"), np.array([-1, -1, -1]), (Decimal("-1"), -1, -1),
              np.array([F(-1), F(-1), F(-1)], dtype=object), [np.int64(-1)] * 3]:  # fmt: skip
        assert S.contains(p)


def test_wrong_shape_error_carries_field(S):
    with pytest.raises(fixel.InputError) as e:
        S.contains((-1, -1))
    assert e.value.field == "p" and e.value.value == "(-1, -1)"
    assert isinstance(e.value, ValueError) and isinstance(e.value, fixel.Error)


def test_parse_error_names_entry(S):
    with pytest.raises(fixel.ParseError) as e:
        S.contains(("-1", "0.1.2", "-1"))
    assert e.value.field == "p[1]" and e.value.value.strip('"') == "0.1.2"


def bad_scene(tmp_path, **fixel1):
    d = json.loads((SCENE_DIR / "example2.json").read_text())
    d["fixels"][1].update(fixel1)
    path = tmp_path / "bad.json"
    path.write_text(json.dumps(d))
    return d, path


@pytest.mark.parametrize(
    "change, exc, field",
    [
        ({"normal": ["3/5", "3/5"]}, fixel.SceneError, "fixels[1].normal"),
        ({"mu": "-1"}, fixel.SceneError, "fixels[1].mu"),
        ({"gap": "abc"}, fixel.ParseError, "fixels[1].gap"),
        ({"colour": "red"}, fixel.InputError, None),
    ],
)
def test_scene_errors_match_cli(tmp_path, change, exc, field):
    d, path = bad_scene(tmp_path, **change)
    message = cli_error("seat", path)
    with pytest.raises(exc) as from_file:
        fixel.Scene.load(path)
    assert str(from_file.value) == message
    with pytest.raises(exc) as from_dict:
        fixel.Scene.from_dict(d, source=str(path))
    assert str(from_dict.value) == message
    if field:
        assert from_file.value.field == field


def test_other_scene_errors_name_their_field(tmp_path):
    with pytest.raises(fixel.InputError) as e:
        fixel.Scene.load(tmp_path / "missing.json")
    assert str(e.value) == cli_error("seat", tmp_path / "missing.json")
    (tmp_path / "broken.json").write_text("{")
    with pytest.raises(fixel.ParseError):
        fixel.Scene.load(tmp_path / "broken.json")
    d = json.loads((SCENE_DIR / "example2.json").read_text())
    d["fixels"][0]["mu"] = 0.1
    with pytest.raises(TypeError, match=r"fixels\[0\]\.mu.*not exact"):
        fixel.Scene.from_dict(d)
    with pytest.raises(TypeError):
        fixel.Scene.from_dict(None)
    with pytest.raises(TypeError):
        fixel.Scene.load(None)
    with pytest.raises(TypeError):
        fixel.seating_set(b"example2.json")  # bytes name no path here
    with pytest.raises(fixel.InputError, match="cannot be opened"):
        fixel.seating_set(str(tmp_path / "example2.json"))  # a path is read, and this one is missing


def test_a_singular_scene_is_a_scene_error_naming_the_fixel(tmp_path):
    d = json.loads((SCENE_DIR / "example2.json").read_text())
    d["fixels"][2] = dict(d["fixels"][1])
    scene = fixel.Scene.from_dict(d)  # loads: the rank of W_n is the analyses' rule
    with pytest.raises(fixel.SceneError) as e:
        fixel.seating_set(scene)
    assert "makes W_n singular" in str(e.value)


def test_bad_region_options_are_refused_naming_the_option():
    scene = fixel.Scene.load(SCENE_DIR / "polygon.json")
    with pytest.raises(fixel.InputError) as e:
        fixel.region(scene, push="sustained", guaranteed=True)
    assert e.value.field == "guaranteed"
    with pytest.raises(fixel.InputError):
        fixel.region(scene, push="shove")
    with pytest.raises(fixel.InputError):
        fixel.region(scene, cone="round")
    with pytest.raises(fixel.InputError):
        fixel.region(scene, resolution=0)
    with pytest.raises(TypeError):
        fixel.region(scene, resolution=0.01)
    with pytest.raises(fixel.InputError):
        fixel.region(scene, pusher_mu=-1)
    with pytest.raises(TypeError):
        fixel.region(scene, pusher_mu=0.1)
    with pytest.raises(TypeError):
        fixel.region(scene, progress="yes")


def test_the_exact_region_of_g_is_refused_in_the_clis_words():
    # The CLI checks before building G; its reason was other words than the library's.
    scene = fixel.Scene.load(SCENE_DIR / "polygon.json")
    with pytest.raises(fixel.UnsupportedError) as e:
        fixel.region(scene, exact=True, guaranteed=True)
    cli = cli_error("region", SCENE_DIR / "polygon.json", "--exact", "--guaranteed")
    assert cli.startswith("--exact: ") and str(e.value).startswith("exact: ")
    assert str(e.value)[len("exact: ") :] == cli[len("--exact: ") :]


def test_a_friction_interval_refused_by_the_one_step_model_is_explained_in_the_librarys_terms():
    # The refusal once named CLI commands and flags (seat --sustained, ...),
    # which a Python caller cannot run; it names the analyses instead.
    d = fixel.Scene.load(SCENE_DIR / "polygon.json").to_dict()
    d["fixels"][0]["mu"] = ["1/20", "1/10"]
    scene = fixel.Scene.from_dict(d, "interval")
    with pytest.raises(fixel.UnsupportedError) as e:
        fixel.seating_set(scene)
    assert e.value.field == "fixels[0].mu" and e.value.value == "[1/20, 1/10]"
    message = str(e.value)
    assert message.startswith("fixels[0].mu: [1/20, 1/10] is an interval: the one-step model needs one value")
    assert "sustained-push set J" in message and "fixture design" in message
    assert "--" not in message
    # The analyses it names do accept the scene.
    assert fixel.sustained_set(scene) is not None


def test_exact_region_refuses_the_options_it_would_ignore():
    # Root isolation has no resolution and builds no segment cones: as the CLI.
    scene = fixel.Scene.load(SCENE_DIR / "polygon.json")
    for kw, field in (({"resolution": "1/3"}, "resolution"), ({"cone": "paper"}, "cone")):
        with pytest.raises(fixel.InputError) as e:
            fixel.region(scene, exact=True, **kw)
        assert e.value.field == field
    assert fixel.region(scene, exact=True).resolution is None
    assert fixel.region(scene).resolution == F(1, 1024)  # None means 1/1024


def test_simulate_and_solutions_refuse_bad_input_naming_it(example2):
    with pytest.raises(fixel.InputError):
        fixel.simulate(example2, P, steps=0)
    with pytest.raises(TypeError):
        fixel.simulate(example2, P, steps=1.0)
    with pytest.raises(fixel.InputError):
        fixel.simulate(example2, (-1, -1))
    with pytest.raises(TypeError):
        fixel.solutions(example2, np.array([-1.0, -1.0, -1.0]))
    with pytest.raises(fixel.InputError):
        fixel.solutions(example2, (-1, -1))
    with pytest.raises(TypeError):
        fixel.solutions(example2, None)


HUGE = 10**10  # beyond the core's int: pybind11 used to answer "incompatible function arguments"


@pytest.mark.parametrize(
    "field, call",
    [
        ("points", lambda s: fixel.sample(s, HUGE)),
        ("steps", lambda s: fixel.simulate(s, (0, -1, 0), steps=HUGE)),
        ("digits", lambda s: fixel.region(s, exact=True, digits=HUGE)),
        ("digits", lambda s: fixel.region(s, exact=True, digits=-HUGE)),
        ("top", lambda s: fixel.design(s, top=HUGE)),
        ("jobs", lambda s: fixel.design(s, jobs=HUGE)),
        ("grid", lambda s: fixel.guaranteed_set(s).lost_fraction(grid=HUGE)),
        ("k", lambda s: s.curve_range(HUGE)),
    ],
)
def test_an_int_beyond_the_cores_range_is_an_input_error_naming_it(field, call):
    polygon = fixel.Scene.load(SCENE_DIR / "polygon.json")
    with pytest.raises(fixel.InputError) as e:
        call(polygon)
    assert e.value.field == field
    assert e.value.value in (str(HUGE), str(-HUGE))


def test_numpy_integers_count_as_ints():
    polygon = fixel.Scene.load(SCENE_DIR / "polygon.json")
    assert fixel.sample(polygon, np.int64(8)).to_json()["intervals"] == fixel.sample(polygon, 8).to_json()["intervals"]
    assert len(fixel.simulate(polygon, (0, -1, 0), steps=np.int32(2)).steps) == 2
    with pytest.raises(TypeError, match="points"):
        fixel.sample(polygon, True)
    with pytest.raises(TypeError, match="points"):
        fixel.sample(polygon, 8.0)


def test_eq27_is_unsupported_when_a_contact_sticks(example2):
    # Gaps (1/10, 0, 0): ν⁺ is along fixel 0's normal, so fixel 0 sticks.
    d = example2.to_dict()
    d["fixels"][1]["gap"] = d["fixels"][2]["gap"] = "0"
    S = fixel.seating_set(fixel.Scene.from_dict(d))
    assert S.sliding[0] == 0 and len(S.rays) == 4
    with pytest.raises(fixel.UnsupportedError) as e:
        S.eq27((0, 0, 0))
    assert isinstance(e.value, NotImplementedError)


def test_none_never_crashes(example2, tmp_path):
    for call in [
        lambda: fixel.seating_set(None),
        lambda: fixel.guaranteed_set(example2, seating="S"),
        lambda: fixel.to_off(example2, None, tmp_path),
        lambda: fixel.to_svg(tmp_path / "x.svg", None),
        lambda: fixel._fixel.seating_set(None),  # the raw module too
        lambda: fixel._fixel.guaranteed_set(example2._impl, None),
        lambda: fixel._fixel.compute_region(None, None, "1/8", "tight", None, None, False, 0, None),
    ]:
        with pytest.raises(TypeError):
            call()


def test_point_mass_region_questions_raise_scene_errors():
    # These killed the interpreter (a segfault in the core) before the scene
    # was checked ahead of the target: a point mass has no boundary to push on.
    example1 = fixel.Scene.load(SCENE_DIR / "example1.json")
    with pytest.raises(fixel.SceneError, match="body.boundary"):
        fixel.region(example1)
    d = json.loads((SCENE_DIR / "example1.json").read_text())
    d["body"]["boundary"] = [{"type": "polyline", "points": [["-3", "-3"], ["3", "-3"], ["3", "3"], ["-3", "3"], ["-3", "-3"]]}]
    for f in d["fixels"]:
        f["off_boundary"] = True  # the point mass's contacts are not on this outline
    point_mass = fixel.Scene.from_dict(d)
    for ask in (
        lambda: fixel.region(point_mass),
        lambda: fixel.region(point_mass, exact=True),
        lambda: fixel.sample(point_mass, 8),
        lambda: fixel.push_plan(point_mass, at="0:1/2"),
    ):
        with pytest.raises(fixel.SceneError, match="body.dof"):
            ask()


@pytest.mark.parametrize(
    "call, field",
    [
        (lambda s: fixel.region(s, resolution=0), "resolution"),
        (lambda s: fixel.region(s, pusher_mu="-1"), "pusher_mu"),
        (lambda s: fixel.simulate(s, (-1, -1, -1), steps=0), "steps"),
        (lambda s: fixel.sample(s, 0), "points"),
        (lambda s: fixel.push_plan(s, at="7:1/2"), "at"),
    ],
)
def test_option_errors_name_the_python_argument(call, field):
    # The core names these RegionOptions.resolution, simulate(steps),
    # sample_region(points_per_curve), plan_push(curve): Python says what the
    # caller wrote.
    polygon = fixel.Scene.load(SCENE_DIR / "polygon.json")
    with pytest.raises(fixel.InputError) as e:
        call(polygon)
    assert e.value.field == field
    assert str(e.value).startswith(field + ":")


def test_digits_without_exact_is_refused_not_ignored():
    polygon = fixel.Scene.load(SCENE_DIR / "polygon.json")
    with pytest.raises(fixel.InputError) as e:
        fixel.region(polygon, digits=5)
    assert e.value.field == "digits"


def test_a_decimal_beyond_the_exponent_limit_is_refused_before_any_huge_integer_is_built(S):
    # Fraction(Decimal("1e1000000")) took seconds; the core's ±10000 limit now applies.
    for d in ("1e10001", "1e1000000", "1e999999999", "-1e-10001"):
        with pytest.raises(fixel.ParseError, match="beyond ±10000"):
            S.contains((Decimal(d), 0, 0))
    assert S.contains((Decimal("-1"), Decimal("-1.0"), Decimal("-1E0"))) == S.contains((-1, -1, -1))


def test_an_endless_iterator_is_read_no_further_than_a_vector_can_be_long(S):
    with pytest.raises(fixel.InputError, match="has more than 10000 entries"):
        S.contains(iter(int, 1))
    assert S.contains(iter([-1, -1, -1])) == S.contains((-1, -1, -1))


def test_a_float_is_refused_with_one_clear_error_not_chained_to_an_internal_one():
    S = fixel.seating_set(fixel.Scene.load(SCENE_DIR / "polygon.json"))
    with pytest.raises(TypeError, match=r"^p\[0\]: -0.5 is a float, which is not exact input") as e:
        S.contains((-0.5, -1, 0))
    assert e.value.__context__ is None and e.value.__cause__ is None


def test_messages_composed_in_python_escape_control_characters_and_shorten_as_the_cores_do():
    e = fixel.InputError.make("f", "a\nfixel: error: b\x01", "is bad")
    assert str(e) == "f: a\\nfixel: error: b\\x01 is bad"
    assert e.value == "a\nfixel: error: b\x01"  # kept whole
    long = "7" * 2000
    shown = str(fixel.InputError.make("f", long, "r"))
    assert len(shown) < 900 and shown.startswith("f: " + "7" * 600 + "…[1200 characters]…")
    # The core's own message, for comparison: a newline in a file name is escaped there too.
    with pytest.raises(fixel.InputError) as core:
        fixel.Scene.load("/nonexistent/a\nb.json")
    assert "\n" not in str(core.value) and "a\\nb.json" in str(core.value)
