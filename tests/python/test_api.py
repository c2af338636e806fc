"""The Python API beyond the CLI: round trips, approx views, progress, plots, files."""

import os
import resource
import signal
import threading
from fractions import Fraction as F

import numpy as np
import pytest

import fixel

import json

from conftest import SCENE_DIR, cli_json, run_cli


@pytest.fixture(scope="module")
def polygon():
    return fixel.Scene.load(SCENE_DIR / "polygon.json")


@pytest.mark.parametrize("name", ["example1.json", "example2.json", "blob.json", "nonunique_part.json"])
def test_to_dict_and_from_dict_give_back_the_same_scene(name):
    scene = fixel.Scene.load(SCENE_DIR / name)
    d = scene.to_dict()
    again = fixel.Scene.from_dict(d)
    assert again.to_dict() == d
    assert fixel.seating_set(again).halfspaces == fixel.seating_set(scene).halfspaces


def test_friction_intervals_survive_to_dict_pickle_and_save(polygon, tmp_path):
    import pickle

    d = polygon.to_dict()
    d["fixels"][0]["mu"] = ["1/10", "1/2"]
    d["pusher"] = {"mu": ["0", "1/5"]}
    scene = fixel.Scene.from_dict(d, "intervals")
    # to_dict once wrote only the lower ends: a pickled scene (a worker's
    # copy) was then judged at the wrong friction.
    assert scene.to_dict()["fixels"][0]["mu"] == ["1/10", "1/2"]
    assert scene.to_dict()["pusher"]["mu"] == ["0", "1/5"]
    assert pickle.loads(pickle.dumps(scene)).to_dict() == scene.to_dict()
    scene.save(tmp_path / "intervals.json")
    assert fixel.Scene.load(tmp_path / "intervals.json").to_dict() == scene.to_dict()
    # The CLI reads the saved file and judges J at the upper ends, as for the dict.
    assert cli_json("seat", tmp_path / "intervals.json", "--sustained")["sustained"] == cli_json(
        "seat", _saved(tmp_path, d), "--sustained"
    )["sustained"]


def _saved(tmp_path, d):
    path = tmp_path / "from_dict.json"
    path.write_text(json.dumps(d))
    return path


def test_save_refuses_a_missing_folder_and_keeps_an_earlier_file(polygon, example2, tmp_path):
    path = tmp_path / "scene.json"
    polygon.save(path)
    before = path.read_text()
    # The write fails half-way (a file-size limit, as a full disk would).
    soft, hard = resource.getrlimit(resource.RLIMIT_FSIZE)
    handler = signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
    try:
        resource.setrlimit(resource.RLIMIT_FSIZE, (256, hard))
        with pytest.raises(fixel.InputError, match="scene.json could not be written completely"):
            example2.save(path)
    finally:
        resource.setrlimit(resource.RLIMIT_FSIZE, (soft, hard))
        signal.signal(signal.SIGXFSZ, handler)
    assert path.read_text() == before
    assert [p.name for p in tmp_path.iterdir()] == ["scene.json"]  # no temporary file left
    with pytest.raises(fixel.InputError):
        polygon.save(tmp_path / "no such folder" / "scene.json")
    with pytest.raises(TypeError, match="path"):
        polygon.save(3)


def test_from_dict_accepts_fractions_and_ints(example2):
    d = example2.to_dict()
    d["fixels"][0]["mu"] = F(1, 10)
    d["time_step"] = 1
    d["body"]["velocity"] = np.array([0, 0, 0])
    assert fixel.seating_set(fixel.Scene.from_dict(d)).apex == fixel.seating_set(example2).apex


def test_values_are_fractions(example2):
    S = fixel.seating_set(example2)
    assert all(type(x) is F for x in S.apex)
    assert all(type(x) is F for r in S.rays for x in r)
    assert all(type(c) is F and all(type(x) is F for x in a) for a, c in S.halfspaces)
    assert (-1, -1, -1) in S


def test_approx_views_are_doubles(example2):
    a = fixel.seating_set(example2).approx
    assert a.apex.dtype == np.float64 and a.rays.shape == (3, 3) and a.normals.shape[1] == 3


def test_the_exact_helper_converts_numbers_without_rounding():
    assert fixel.exact(0.1) == F(3602879701896397, 36028797018963968)
    assert fixel.exact("0.1") == F(1, 10) and fixel.exact(3) == 3
    with pytest.raises(TypeError):
        fixel.exact(None)


def test_a_region_holds_exact_intervals_stats_and_counts(polygon):
    r = fixel.region(polygon, resolution="1/64")
    assert r.intervals and all(isinstance(i, fixel.RegionInterval) for i in r.intervals)
    assert all(type(i.u0) is F and type(i.u1) is F for i in r.intervals)
    # The intervals tile each curve's parameter range exactly, in order.
    for k in range(polygon.num_curves):
        mine = [i for i in r.intervals if i.curve == k]
        lo, hi = polygon.curve_range(k)
        assert mine[0].u0 == lo and mine[-1].u1 == hi
        assert all(a.u1 == b.u0 for a, b in zip(mine, mine[1:]))
    for i in r.intervals:
        if i.magnitudes is not None:
            assert i.status == "in" and i.magnitudes.half_line == (i.magnitudes.hi is None)
    assert isinstance(r.stats, fixel.RegionStats) and type(r.stats.partial_length) is F


def test_resolution_length_gives_each_piece_its_own_width_as_the_cli_does(polygon):
    # Per-piece widths from the speed bound: the edges of the house are 5/2,
    # 3/2, sqrt(41)/4 (twice) and 3/2 long; L = 1/4 halves them 4, 3, 3, 3, 3 times.
    r = fixel.region(polygon, resolution_length="1/4")
    assert r.resolution is None and r.resolution_length == F(1, 4)
    doc = r.to_json()
    assert doc["resolution_length"] == "1/4" and doc["piece_widths"] == ["1/16", "1/8", "1/8", "1/8", "1/8"]
    code, out, _ = run_cli("region", SCENE_DIR / "polygon.json", "--resolution-length", "1/4", "--json")
    assert code == 0 and json.loads(out)["intervals"] == doc["intervals"]
    with pytest.raises(fixel.InputError, match="resolution_length"):
        fixel.region(polygon, resolution_length="0")
    with pytest.raises(fixel.InputError, match="resolution_length"):
        fixel.region(polygon, resolution_length="1/4", exact=True)


# blob32's region with the paper's cone at resolution 2^-60 runs for
# minutes (the default region took 0.2 s before the filters, now 2 ms),
# stopped at 0.6 s: long enough for the ticks below on any machine.
LONG = dict(cone="paper", resolution="1/%d" % 2**60)


def test_the_progress_callback_ticks_while_the_core_runs(polygon):
    events = []
    blob32 = fixel.Scene.load(SCENE_DIR / "blob32.json")
    with pytest.raises(fixel.StoppedError):
        fixel.region(blob32, **LONG, max_seconds=0.6, progress=lambda stage, t: events.append((stage, t)))
    assert events[0] == ("start", 0.0) and events[-1][0] == "done"  # "done" also when stopped
    running = [t for stage, t in events[1:-1]]
    assert all(stage == "running" for stage, _ in events[1:-1])
    assert len(running) >= 2 and running == sorted(running)  # every 0.1 s, in order
    fixel.region(polygon, resolution="1/64", progress=True)  # the tqdm bar stays hidden under 1 s


def test_guaranteed_set_progress_tells_start_and_done_and_changes_nothing(polygon):
    events = []
    G = fixel.guaranteed_set(polygon, progress=lambda stage, t: events.append(stage))
    assert events[0] == "start" and events[-1] == "done"
    assert G.num_pieces == fixel.guaranteed_set(polygon).num_pieces


def test_progress_error_propagates(polygon):
    with pytest.raises(fixel.InputError):
        fixel.region(polygon, resolution="0", push="sustained", progress=True)
    with pytest.raises(fixel.InputError):
        fixel.region(polygon, resolution="-1", progress=lambda *a: None)


def test_gil_released_during_region():
    """Another Python thread keeps running while the core computes."""
    scene = fixel.Scene.load(SCENE_DIR / "blob32.json")
    ticks, done = [], threading.Event()

    def count():
        while not done.is_set():
            ticks.append(1)
            done.wait(0.001)

    t = threading.Thread(target=count)
    t.start()
    with pytest.raises(fixel.StoppedError):
        fixel.region(scene, **LONG, max_seconds=0.6)
    done.set()
    t.join()
    assert len(ticks) > 10  # about 600 with the GIL released, 1 if it were held


def test_the_guaranteed_region_is_the_clis(polygon):
    r = fixel.region(polygon, resolution="1/16", guaranteed=True)
    cli = cli_json("region", SCENE_DIR / "polygon.json", "--guaranteed", "--resolution", "1/16")
    assert r.to_json()["intervals"] == cli["intervals"]
    assert r.counts()["in"] > 0  # G is not empty here, so the comparison sees IN stretches


def test_a_guaranteed_set_given_alone_brings_its_own_seating_set(polygon):
    # fixel.region(scene, guaranteed=G) used to build a new S and refuse G
    # ("belongs to another seating set"): S is now the one G was built from.
    G = fixel.guaranteed_set(polygon)
    given = fixel.region(polygon, resolution="1/16", guaranteed=G)
    built = fixel.region(polygon, resolution="1/16", guaranteed=True)
    assert [(i.u0, i.u1, i.status) for i in given.intervals] == [(i.u0, i.u1, i.status) for i in built.intervals]
    assert given.seating is G.seating
    sampled = fixel.sample(polygon, 8, guaranteed=G)
    assert [i.status for i in sampled.intervals] == [
        i.status for i in fixel.sample(polygon, 8, guaranteed=True).intervals
    ]
    # With a seating set of its own, the mismatch says what to pass.
    with pytest.raises(fixel.InputError, match=r"G\.seating"):
        fixel.region(polygon, resolution="1/16", guaranteed=G, seating=fixel.seating_set(polygon))


def test_svg_and_off_files_are_written_for_regions_and_sets(tmp_path, polygon):
    r = fixel.region(polygon, resolution="1/64")
    fixel.to_svg(tmp_path / "r.svg", r)
    assert "<svg" in (tmp_path / "r.svg").read_text()
    paths = fixel.to_off(polygon, r.seating, tmp_path / "off", length=2)
    assert any(p.endswith("seating_set.off") for p in paths)
    G = fixel.guaranteed_set(polygon, r.seating)
    paths = fixel.to_off(polygon, r.seating, tmp_path / "offg", guaranteed=G)
    cli = cli_json("seat", SCENE_DIR / "polygon.json", "--guaranteed")["guaranteed_set"]
    assert G.num_pieces == len(cli["pieces"]) > 0
    assert sum("guaranteed_" in p and p.endswith(".off") for p in paths) == G.num_pieces
    fixel.to_svg(tmp_path / "g.svg", G, impulse=G.seating.apex)
    assert "<svg" in (tmp_path / "g.svg").read_text()
    assert fixel.__version__.count(".") == 2
    other = fixel.seating_set(polygon)
    with pytest.raises(fixel.InputError):
        fixel.to_off(polygon, other, tmp_path / "bad", guaranteed=G)
    # "-" made a folder named "-"; it names no folder (./- does).
    cwd = os.getcwd()
    try:
        os.chdir(tmp_path)
        with pytest.raises(fixel.InputError, match="not an output folder"):
            fixel.to_off(polygon, r.seating, "-")
        assert not os.path.exists("-")
        assert fixel.to_off(polygon, r.seating, "./-")
    finally:
        os.chdir(cwd)


def test_the_plot_helpers_draw_the_region_and_the_wrench_sphere(polygon):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import fixel.plot

    r = fixel.region(polygon, resolution="1/64")
    fig, (a, b) = plt.subplots(1, 2)
    assert fixel.plot.region(a, polygon, r) is a
    assert fixel.plot.wrench_sphere(b, polygon, r) is b
    assert a.lines and b.lines
    # The legend names the model, as every report does.
    labels = [line.get_label() for line in a.lines]
    assert r.meaning == "one-step: can seat" and "in: one-step: can seat" in labels
    assert fixel.region(polygon, push="sustained", resolution="1/16").meaning == "sustained push: seats and stays"
    plt.close(fig)


def test_tqdm_bar_after_one_second(capsys):
    import time

    from fixel._region import _run

    assert _run(lambda control: time.sleep(1.3) or 7, True, "fixel.region") == 7
    assert "fixel.region" in capsys.readouterr().err
    assert _run(lambda control: 8, True, "fixel.region") == 8
    assert "fixel.region" not in capsys.readouterr().err  # quick runs show nothing


def test_a_point_mass_scene_gives_a_two_dimensional_seating_set():
    scene = fixel.Scene.load(SCENE_DIR / "example1.json")
    S = fixel.seating_set(scene)
    assert scene.dof == 2 and len(S.apex) == 2
    assert S.contains(S.apex)
    with pytest.raises(fixel.InputError):
        S.contains((0, 0, 0))


def test_concurrent_calls_agree():
    """The core runs without the GIL; threads must not disturb each other."""
    from concurrent.futures import ThreadPoolExecutor

    scenes = [fixel.Scene.load(SCENE_DIR / n) for n in ("polygon.json", "blob.json", "fig6.json")] * 2

    def intervals(s):
        return [(i.u0, i.u1, i.status) for i in fixel.region(s, resolution="1/128").intervals]

    serial = [intervals(s) for s in scenes]
    with ThreadPoolExecutor(4) as pool:
        parallel = list(pool.map(intervals, scenes))
    assert parallel == serial


def test_a_scene_and_its_seating_set_pickle_as_the_same_exact_objects(example2):
    import pickle

    S = fixel.seating_set(example2)
    T = pickle.loads(pickle.dumps(S))
    assert T.halfspaces == S.halfspaces and T.scene.to_dict() == example2.to_dict()
    G = fixel.guaranteed_set(example2, S)
    H = pickle.loads(pickle.dumps(G))
    assert H.num_pieces == G.num_pieces and H.non_seating == G.non_seating
    for p in ([-1, -1, -1], [1, 1, 1], [F(29157, 10540), F(-71119, 105400), -1]):
        assert H.contains(p) == G.contains(p)


def test_sustained_and_approach_sets_pickle_as_the_same_exact_sets(polygon):
    import pickle

    J = fixel.sustained_set(polygon)
    A = fixel.approach_set(polygon, J)
    K = pickle.loads(pickle.dumps(J))
    B = pickle.loads(pickle.dumps(A))
    assert K.cones == J.cones and K.seated_pose == J.seated_pose and K.mu == J.mu
    assert (B.decided, B.t_star, B.on_edges, B.empty) == (A.decided, A.t_star, A.on_edges, A.empty)
    assert B.J.cones == J.cones
    for w in ([-1, -1, 0], [0, -1, 0], [1, 0, 0], [-1, -2, F(1, 3)]):
        assert K.why_not(w) == J.why_not(w) and B.why_not(w) == A.why_not(w)
    assert any(J.contains(w) for w in ([-1, -1, 0], [0, -1, 0]))  # the comparison sees members too


def test_a_sets_scene_is_read_only_so_its_pickle_is_rebuilt_from_its_own_scene(polygon, example2):
    # Pickling rebuilds a set from its scene: a writable .scene let a
    # pickle give another scene's set, silently.
    S = fixel.seating_set(polygon)
    J = fixel.sustained_set(polygon)
    A = fixel.approach_set(polygon, J)
    G = fixel.guaranteed_set(example2)
    for obj, name, other in ((S, "scene", example2), (J, "scene", example2), (A, "scene", example2),
                             (A, "J", None), (G, "seating", None)):  # fmt: skip
        with pytest.raises(AttributeError):
            setattr(obj, name, other)
    assert A.J is J and A.scene is polygon and G.seating.scene is example2
    import pickle

    assert pickle.loads(pickle.dumps(S)).apex == S.apex


def test_sustained_set_agrees_with_the_cli_and_decides_exactly():
    path = SCENE_DIR / "polygon.json"
    scene = fixel.Scene.load(path)
    J = fixel.sustained_set(scene)
    assert not J.empty and J.strongly_stable
    assert list(J.mu) == [F(1, 10)] * 3
    code, out, err = run_cli("seat", path, "--sustained", "--json")
    assert code == 0, err
    cli = json.loads(out)
    assert J.cones == cli["sustained"]
    assert J.seated_pose["algebraic"] == cli["seated_pose"]["algebraic"]
    assert J.contains([-1, -1, 0])
    assert "escape" in J.why_not([1, 0, 0])
    with pytest.raises(TypeError):
        J.contains([-1.0, -1, 0])


def test_sustained_region_matches_the_cli():
    path = SCENE_DIR / "polygon.json"
    r = fixel.region(fixel.Scene.load(path), resolution="1/256", push="sustained")
    code, out, err = run_cli("region", path, "--push", "sustained", "--resolution", "1/256", "--json")
    assert code == 0, err
    cli = json.loads(out)
    assert [(i.curve, i.u0, i.u1, i.status) for i in r.intervals] == [
        (d["curve"], F(d["u0"]), F(d["u1"]), d["status"]) for d in cli["intervals"]
    ]
    assert any(i.status == "in" for i in r.intervals)
    doc = r.to_json()
    assert doc["seated_pose"]["theta_abs"] == cli["seated_pose"]["theta_abs"]
    assert doc["seat_note"] == cli["seat_note"] and doc["seat_note"].startswith("note: |theta*|")
    assert list(doc)[-1] == "push"


def test_region_corners_list_the_corner_an_in_interval_ends_at(polygon, tmp_path):
    d = polygon.to_dict()
    for f in d["fixels"]:
        f["gap"] = "0"
    path = tmp_path / "gaps0.json"
    path.write_text(json.dumps(d))
    r = fixel.region(fixel.Scene.from_dict(d), resolution="1/1024")
    assert r.corners == [(0, F(2), "out")]
    assert any(i.u0 == 2 and i.status == "in" for i in r.intervals)
    cli = cli_json("region", path)
    assert cli["corners"] == [{"curve": 0, "u": "2", "u_approx": 2.0, "status": "out"}]
    assert r.to_json()["corners"] == cli["corners"]
    assert fixel.region(polygon, resolution="1/1024").corners == []


def test_a_pusher_friction_interval_reads_as_its_upper_end_as_every_analysis_judges_it(polygon, tmp_path):
    d = polygon.to_dict()
    d["pusher"] = {"mu": ["0", "1/10"]}
    scene = fixel.Scene.from_dict(d)
    assert scene.pusher_mu == F(1, 10)
    r = fixel.region(scene, resolution="1/64")
    path = tmp_path / "pusher_interval.json"
    path.write_text(json.dumps(d))
    cli = cli_json("region", path, "--resolution", "1/64")
    assert r.pusher_mu == F(cli["pusher_mu"]) == F(1, 10)
    assert r.to_json()["pusher_mu"] == "1/10"
    assert fixel.region(scene, resolution="1/64", pusher_mu="1/20").pusher_mu == F(1, 20)


def test_a_pusher_mu_pair_is_judged_at_its_upper_end_as_the_clis_lo_hi():
    path = SCENE_DIR / "example2_rounded.json"
    scene = fixel.Scene.load(path)
    pair = fixel.region(scene, pusher_mu=("0", "1/10"), resolution="1/64")
    cli = cli_json("region", path, "--pusher-mu", "0,1/10", "--resolution", "1/64")
    assert pair.pusher_mu == F(1, 10)
    assert [(i.curve, i.u0, i.u1, i.status) for i in pair.intervals] == [
        (d["curve"], F(d["u0"]), F(d["u1"]), d["status"]) for d in cli["intervals"]
    ]
    with pytest.raises(fixel.InputError, match="lo > hi"):
        fixel.region(scene, pusher_mu=("1/5", "1/10"))
    with pytest.raises(fixel.InputError, match="one number or"):
        fixel.region(scene, pusher_mu=("0", "1/10", "1/5"))


def test_a_regions_repr_is_short_and_counts_its_intervals(polygon):
    r = fixel.sample(polygon, points=2000)
    c = r.counts()
    assert repr(r) == (
        f"<fixel.Region of 'polygon': 2000 intervals (in {c['in']}, out {c['out']}, partial {c['partial']}), "
        "0 corners listed>"
    )


def test_resolution_and_resolution_length_together_are_refused_as_by_the_cli(polygon):
    with pytest.raises(fixel.InputError, match="resolution: 1/8 cannot be combined with resolution_length"):
        fixel.region(polygon, resolution="1/8", resolution_length="1/100")
    code, _, err = run_cli("region", SCENE_DIR / "polygon.json", "--resolution", "1/8", "--resolution-length", "1/100")
    assert code == 2 and "--resolution excludes --resolution-length" in err


def test_the_wrench_sphere_of_a_sustained_region_is_a_clear_type_error(polygon):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    import fixel.plot

    fig, ax = plt.subplots()
    with pytest.raises(TypeError, match="wrench_sphere draws the one-step seating set S"):
        fixel.plot.wrench_sphere(ax, polygon, region=fixel.region(polygon, push="sustained", resolution="1/16"))
    plt.close(fig)


def test_push_runs_the_engine_and_agrees_with_the_cli():
    path = SCENE_DIR / "polygon.json"
    r = fixel.push(fixel.Scene.load(path), wrench=[-1, -1, 0], time=5)
    code, out, err = run_cli("push", path, "--wrench", "-1,-1,0", "--time", "5", "--json")
    assert code == 0, err
    assert r["outcome"] == json.loads(out)["outcome"] == "seated"
    with pytest.raises(TypeError):
        fixel.push(fixel.Scene.load(path), wrench=[-1.0, -1, 0])
    with pytest.raises(fixel.InputError):
        fixel.push(fixel.Scene.load(path))


def test_push_takes_the_engines_accuracy_as_the_cli_does():
    path = SCENE_DIR / "polygon.json"
    scene = fixel.Scene.load(path)
    r = fixel.push(scene, at="0:1/2", time=2, steps_per_h=4000, velocity_iterations=30, position_iterations=15)
    engine = ["--steps-per-h", "4000", "--velocity-iterations", "30", "--position-iterations", "15"]
    code, out, err = run_cli("push", path, "--at", "0:1/2", "--time", "2", *engine, "--json")
    assert code == 0, err
    cli = json.loads(out)
    assert (r["steps_per_h"], r["velocity_iterations"], r["position_iterations"]) == (4000, 30, 15)
    assert r["outcome"] == cli["outcome"] and r["steps"] == cli["steps"] and r["final_pose"] == cli["final_pose"]
    assert r["dt"] == cli["dt"] == 1 / 4000  # h = 1 s
    for field, value, message in [
        ("steps_per_h", 999, "must be >= 1000"),
        ("velocity_iterations", 0, "must be 1 to 1000"),
        ("position_iterations", 1001, "must be 1 to 1000"),
    ]:
        with pytest.raises(fixel.InputError, match=f"^{field}: {value} {message}") as e:
            fixel.push(scene, at="0:1/2", **{field: value})
        assert e.value.field == field and e.value.value == str(value)
        region = fixel.region(scene, push="sustained", resolution="1/16")
        with pytest.raises(fixel.InputError) as e:
            region.validate(1, **{field: value})
        assert e.value.field == field
    with pytest.raises(TypeError):
        fixel.push(scene, at="0:1/2", steps_per_h=1000.0)
    # The step limit names the steps per h that broke it, as the CLI does.
    with pytest.raises(fixel.InputError, match="^steps_per_h: 99999999 with time 20 holds the push for") as e:
        fixel.push(scene, at="0:1/2", steps_per_h=99999999)
    assert e.value.field == "steps_per_h"
    # A non-zero component below the engine's floats is refused, not pushed as a zero wrench.
    with pytest.raises(fixel.InputError, match="below the engine's float range") as e:
        fixel.push(scene, wrench=["1e-400", 0, 0])
    assert e.value.field == "wrench[0]"


def test_exact_region_has_algebraic_ends_that_match_the_cli():
    path = SCENE_DIR / "polygon.json"
    r = fixel.region(fixel.Scene.load(path), push="sustained", exact=True, digits=8)
    assert r.resolution is None and all(i.status != "partial" or i.u0 == i.u1 for i in r.intervals)
    ends = [e for i in r.intervals for e in (i.exact_u0, i.exact_u1) if e is not None]
    assert ends and all(isinstance(e, fixel.AlgebraicEnd) for e in ends)
    for e in ends:  # a sign change of the defining polynomial across the interval, in exact arithmetic
        lo, hi = e.isolating
        value = lambda x: sum(c * x**k for k, c in enumerate(e.poly))  # noqa: E731
        assert value(lo) * value(hi) < 0 and 0 < hi - lo <= F(1, 10**8)
    code, out, err = run_cli("region", path, "--push", "sustained", "--exact", "--digits", "8", "--json")
    assert code == 0, err
    cli = json.loads(out)

    def end(d, e, u):
        if isinstance(d, str):
            return e is None and F(d) == u
        return e is not None and [int(c) for c in d["poly"]] == list(e.poly) and tuple(map(F, d["isolating"])) == e.isolating

    assert len(cli["intervals"]) == len(r.intervals)
    for d, i in zip(cli["intervals"], r.intervals):
        assert d["status"] == i.status and end(d["u0"], i.exact_u0, i.u0) and end(d["u1"], i.exact_u1, i.u1)
    with pytest.raises(fixel.UnsupportedError):
        fixel.region(fixel.Scene.load(SCENE_DIR / "nonunique_part.json"), exact=True, guaranteed=True)


def _without_seconds(doc):
    if isinstance(doc, dict):
        return {k: _without_seconds(v) for k, v in doc.items() if k != "seconds"}
    if isinstance(doc, list):
        return [_without_seconds(v) for v in doc]
    return doc


def test_exact_only_gives_the_same_region_and_no_filter_counts():
    # Second method: the same region with every decision in rationals.
    scene = fixel.Scene.load(SCENE_DIR / "example2_rounded.json")
    with fixel.exact_only(False):
        fixel.filter_stats(reset=True)
        filtered = fixel.region(scene, resolution="1/256")
        filtered_counts = fixel.filter_stats(reset=True)
    with fixel.exact_only():
        exact = fixel.region(scene, resolution="1/256")
        exact_counts = fixel.filter_stats()
    assert _without_seconds(filtered.to_json()) == _without_seconds(exact.to_json())
    assert set(filtered_counts) >= {"lemke", "ray test", "out test", "orientation", "region test"}
    assert sum(c["certified"] for c in filtered_counts.values()) > 0
    assert all(c == {"certified": 0, "fallbacks": 0} for c in exact_counts.values())


def test_exact_only_restores_the_previous_setting_even_after_an_exception():
    before = fixel._fixel.force_exact()
    with pytest.raises(RuntimeError):
        with fixel.exact_only():
            assert fixel._fixel.force_exact()
            raise RuntimeError("inside the block")
    assert fixel._fixel.force_exact() == before
    with fixel.exact_only():
        with fixel.exact_only(False):
            assert not fixel._fixel.force_exact()
        assert fixel._fixel.force_exact()
    assert fixel._fixel.force_exact() == before
    with pytest.raises(TypeError):
        with fixel.exact_only(1):
            pass
    with pytest.raises(TypeError):
        fixel.filter_stats(reset="yes")


def test_directed_rounding_works_here_so_the_switch_alone_decides():
    assert fixel.directed_rounding_works() is True
    with fixel.exact_only(False):
        assert not fixel._fixel.force_exact()
    with fixel.exact_only(True):
        assert fixel._fixel.force_exact() and fixel._fixel.force_exact_set()
