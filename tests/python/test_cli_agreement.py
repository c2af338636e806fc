"""The bindings agree with the CLI's JSON on every bundled scene, as Fractions."""

from fractions import Fraction as F

import pytest

import fixel

from conftest import SCENE_DIR, SCENES, cli_error, cli_json, run_cli

IMPULSES = {"example2.json": "-1,-1,-1", "nonunique.json": "29157/10540,-71119/105400,-1169839/263500"}


def fr(v):
    return tuple(F(x) for x in v)


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_seat_agrees(path):
    scene = fixel.Scene.load(path)
    doc = cli_json("seat", path)
    S = fixel.seating_set(scene)
    assert S.apex == fr(doc["apex"])
    assert S.rays == [fr(r) for r in doc["rays"]]
    assert S.halfspaces == [(fr(h["a"]), F(h["c"])) for h in doc["halfspaces"]]
    assert S.sliding == tuple(doc["sliding"])
    assert S.velocity_after == fr(doc["velocity_after"])
    assert S.tangential_velocity == fr(doc["tangential_velocity"])


def impulse_for(path):
    """The documented impulse, else apex + Σ rays (a point inside S)."""
    if path.name in IMPULSES:
        return IMPULSES[path.name]
    S = fixel.seating_set(fixel.Scene.load(path))
    p = [S.apex[k] + sum(r[k] for r in S.rays) for k in range(S.dof)]
    return ",".join(f"{x.numerator}/{x.denominator}" for x in p)


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_impulse_commands_agree(path):
    scene, text = fixel.Scene.load(path), impulse_for(path)
    # The CLI applies the scene's background impulse b0 (docs/cli.md); the library takes the total impulse.
    b0 = [F(x) for x in scene.to_dict()["background_impulse"]]
    p = [F(x) + b for x, b in zip(text.split(","), b0)]
    seat = cli_json("seat", path, "--impulse", text)
    S = fixel.seating_set(scene)
    assert S.contains(p) == seat["contains"]
    if "y" in seat:  # eq. (27): y = K⁻¹(P p + a) = linear − threshold
        names, linear, threshold = S.eq27(p)
        assert names == seat["y_names"]
        assert [a - b for a, b in zip(linear, threshold)] == [F(y) for y in seat["y"]]
    sim = cli_json("simulate", path, "--impulse", text)
    mine = fixel.simulate(scene, p)
    assert mine.seated == sim["seated"]
    for a, b in zip(mine.steps, sim["steps"]):
        keys = ("q", "velocity", "gaps", "p_n", "p_f")
        assert (a.q, a.velocity, a.gaps, a.p_n, a.p_f) == tuple(fr(b[k]) for k in keys)
    sols = cli_json("solutions", path, "--impulse", text)["solutions"]
    mine = fixel.solutions(scene, p)
    assert len(mine) == len(sols)
    for a, b in zip(mine, sols):
        assert (a.seated, a.modes, a.isolated) == (b["seated"], b["modes"], b["isolated"])
        assert (a.velocity, a.gaps, a.p_n, a.p_t) == tuple(fr(b[k]) for k in ("velocity", "gaps", "p_n", "p_t"))


def magnitudes(doc):
    if doc is None:
        return None
    return (F(doc["min"]), doc["min_inclusive"], None if doc["max"] is None else F(doc["max"]), doc["max_inclusive"])


REGION_SCENES = [p for p in SCENES if "boundary" in p.read_text()]


@pytest.mark.parametrize("path", REGION_SCENES, ids=lambda p: p.name)
def test_region_agrees(path):
    doc = cli_json("region", path)  # default resolution 1/1024 on both sides
    r = fixel.region(fixel.Scene.load(path))
    assert len(r.intervals) == len(doc["intervals"])
    for a, b in zip(r.intervals, doc["intervals"]):
        want = (b["curve"], F(b["u0"]), F(b["u1"]), b["status"], b["half_line"])
        assert (a.curve, a.u0, a.u1, a.status, a.half_line) == want
        m = a.magnitudes
        assert (None if m is None else (m.lo, m.lo_closed, m.hi, m.hi_closed)) == magnitudes(b["magnitudes"])
    assert r.counts() == doc["counts"]
    assert {k: F(v) for k, v in doc["lengths"].items() if not k.endswith("_approx")} == r.lengths()
    assert r.stats.cone_tests == doc["stats"]["cone_tests"] and r.stats.depth == doc["stats"]["depth"]
    assert r.resolution == F(1, 1024) and r.pusher_mu == F(doc["pusher_mu"])


def test_region_paper_cone_and_pusher_mu_agree():
    path = [p for p in SCENES if p.name == "example2_rounded.json"][0]
    doc = cli_json("region", path, "--resolution", "1/32", "--cone", "paper", "--pusher-mu", "1/10")
    r = fixel.region(fixel.Scene.load(path), resolution="1/32", cone="paper", pusher_mu=F(1, 10))
    got = [(a.curve, a.u0, a.u1, a.status) for a in r.intervals]
    assert got == [(b["curve"], F(b["u0"]), F(b["u1"]), b["status"]) for b in doc["intervals"]]
    assert r.to_json()["intervals"] == doc["intervals"]


def test_sample_agrees():
    path = [p for p in SCENES if p.name == "polygon.json"][0]
    doc = cli_json("sample", path, "--points", "16")
    r = fixel.sample(fixel.Scene.load(path), 16)
    assert [(a.curve, a.u0, a.status) for a in r.intervals] == [
        (b["curve"], F(b["u0"]), b["status"]) for b in doc["intervals"]
    ]


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.name)
def test_guaranteed_agrees(path):
    text = impulse_for(path)
    doc = cli_json("seat", path, "--guaranteed", "--impulse", text)
    G = fixel.guaranteed_set(fixel.Scene.load(path))
    assert G.contains([F(x) for x in text.split(",")]) == doc["guaranteed"]
    assert G.lost_fraction() == F(doc["guaranteed_set"]["lost_fraction"])
    assert G.num_pieces == len(doc["guaranteed_set"]["pieces"])
    assert [(list(m), k) for m, k in G.non_seating] == [
        (n["modes"], n["open_fixel"]) for n in doc["guaranteed_set"]["non_seating"]
    ]


def test_a_region_without_an_outline_gives_the_clis_error():
    path = [p for p in SCENES if p.name == "example2.json"][0]
    message = cli_error("region", path)
    with pytest.raises(fixel.SceneError) as e:
        fixel.region(fixel.Scene.load(path))
    assert str(e.value) == message


def magnitude_list(doc):
    return [magnitudes(m) for m in doc.get("magnitude_intervals", [])]


def as_tuples(ms):
    return [None if m is None else (m.lo, m.lo_closed, m.hi, m.hi_closed) for m in ms]


@pytest.mark.parametrize("command", ["region", "sample"])
def test_guaranteed_region_agrees(command):
    path = [p for p in SCENES if p.name == "nonunique_part.json"][0]
    doc = cli_json(command, path, "--guaranteed")
    scene = fixel.Scene.load(path)
    r = fixel.region(scene, guaranteed=True) if command == "region" else fixel.sample(scene, 64, guaranteed=True)
    assert len(r.intervals) == len(doc["intervals"])
    for a, b in zip(r.intervals, doc["intervals"]):
        assert (a.curve, a.u0, a.u1, a.status) == (b["curve"], F(b["u0"]), F(b["u1"]), b["status"])
        assert as_tuples(a.magnitude_set) == magnitude_list(b)


def _q_sqrt_d(text):
    """The value of "a", "a+b*sqrt(d)", "a-b*sqrt(d)" or "b*sqrt(d)" (display)."""
    import math
    import re

    m = re.fullmatch(r"(-?[0-9/]+)?(?:([+-]?)([0-9/]+)\*sqrt\((\d+)\))?", text)
    assert m, text
    a = F(m.group(1)) if m.group(1) else F(0)
    if not m.group(3):
        return float(a)
    b = F(m.group(3)) * (-1 if m.group(2) == "-" else 1)
    return float(a) + float(b) * math.sqrt(int(m.group(4)))


def test_every_sustained_row_has_doubles_beside_its_exact_entries():
    # Rows with entries in Q(sqrt d) once had no a_approx (rational ones did).
    doc = cli_json("seat", SCENES[[s.stem for s in SCENES].index("polygon")], "--sustained")["sustained"]
    cones = [doc["cone"], *doc["jam_cones"], *doc["pieces"]]
    irrational = 0
    for cone in cones:
        for row in cone["halfspaces"]:
            assert len(row["a_approx"]) == 3
            for exact, shown in zip(row["a"], row["a_approx"]):
                irrational += "sqrt" in exact
                assert shown == pytest.approx(_q_sqrt_d(exact), rel=1e-12, abs=1e-15)  # display, not a decision
    assert irrational > 0


def _without_seconds(doc):
    doc = dict(doc)
    doc.pop("stats", None)  # wall time differs between runs
    return doc


@pytest.mark.parametrize(
    "push, approach, args",
    [
        ("step", False, ["--validate", "2", "--time", "10"]),
        ("sustained", False, ["--push", "sustained", "--validate", "3"]),
        ("sustained", True, ["--push", "sustained", "--approach", "--validate", "2"]),
        ("sustained", False, ["--push", "sustained", "--validate", "2", "--steps-per-h", "2000"]),
    ],
    ids=["step", "sustained", "approach", "finer-engine"],
)
def test_region_validate_agrees(push, approach, args):
    # The same engine runs on the same seeded points: the same counts, push for push.
    scene = fixel.Scene.load(SCENE_DIR / "polygon.json")
    r = fixel.region(scene, push=push, approach=approach)
    steps_per_h = int(args[args.index("--steps-per-h") + 1]) if "--steps-per-h" in args else 1000
    mine = r.validate(
        int(args[args.index("--validate") + 1]), time=10 if push == "step" else 20, steps_per_h=steps_per_h
    )
    assert mine["validation"]["steps_per_h"] == steps_per_h
    cli = cli_json("region", SCENE_DIR / "polygon.json", *args, "--quiet")
    assert _without_seconds(mine) == _without_seconds(cli)
    assert mine["validation"]["pushes"] > 0
    assert sum(1 for iv in mine["intervals"] if "validation" in iv) == r.counts()["in"]


def test_region_validate_refuses_what_the_cli_refuses():
    scene = fixel.Scene.load(SCENE_DIR / "example2_rounded.json")
    r = fixel.region(scene, resolution="1/64")
    with pytest.raises(fixel.InputError, match="^pushes: 0 must be 1 to 2147483647$"):
        r.validate(0)
    with pytest.raises(fixel.InputError) as e:
        r.validate(1, time=10**9)
    assert e.value.field == "time"
    exact = fixel.region(scene, exact=True)
    with pytest.raises(fixel.InputError, match="needs the certified magnitudes of subdivision"):
        exact.validate(1)
    code, _, err = run_cli("region", SCENE_DIR / "example2_rounded.json", "--exact", "--validate", "1")
    assert code == 2 and "needs the certified magnitudes of subdivision" in err
    with pytest.raises(fixel.StoppedError, match="^validate: time limit reached after"):
        r.validate(1000, max_seconds=1e-9)


@pytest.mark.parametrize("p", [(0, 0, 0), (-1, 0, 0), (F(-1, 2), F(1, 3), -2)])
def test_the_total_impulse_b0_plus_p_gives_the_clis_seat_verdict(p):
    # The CLI adds the scene's b0 to --impulse; the library's S.contains takes the total.
    scene = fixel.Scene.load(SCENE_DIR / "nonunique_part.json")
    b0 = scene.background_impulse
    assert b0 != (0, 0, 0) and all(isinstance(b, F) for b in b0)
    cli = cli_json("seat", SCENE_DIR / "nonunique_part.json", "--impulse", ",".join(str(v) for v in p))
    total = [b + q for b, q in zip(b0, p)]
    assert [F(v) for v in cli["impulse"]] == total
    assert fixel.seating_set(scene).contains(total) == cli["contains"]
