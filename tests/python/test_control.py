"""Stopping a run from Python: max_seconds, Ctrl-C, and the reused worker threads."""

import _thread
import json
import multiprocessing
import threading
import time
from fractions import Fraction as F

import numpy as np
import pytest

import fixel
from conftest import SCENE_DIR

# A deadline already past at the core's first poll: every run below polls
# before it finishes, so each one must stop, whatever the machine's speed.
PAST = 1e-9

# blob32's region at resolution 2^-200: about 2 s, polled once per segment.
FINE = "1/%d" % 2**200
# With the paper's cone at 2^-60 it runs for minutes.
SLOW = dict(cone="paper", resolution="1/%d" % 2**60)


@pytest.fixture(scope="module")
def polygon():
    return fixel.Scene.load(SCENE_DIR / "polygon.json")


@pytest.fixture(scope="module")
def blob32():
    return fixel.Scene.load(SCENE_DIR / "blob32.json")


CALLS = {
    "region": lambda s: fixel.region(s, max_seconds=PAST),
    "sustained region": lambda s: fixel.region(s, push="sustained", max_seconds=PAST),
    "sample": lambda s: fixel.sample(s, 64, max_seconds=PAST),
    "guaranteed set": lambda s: fixel.guaranteed_set(s, max_seconds=PAST),
    "simulate": lambda s: fixel.simulate(s, [0, -1, 0], steps=3, max_seconds=PAST),
    "solutions": lambda s: fixel.solutions(s, [0, -1, 0], max_seconds=PAST),
    "push": lambda s: fixel.push(s, wrench=[0, -1, 0], max_seconds=PAST),
}
# J is built in the same run, and its first exact step, the seated pose, stops first.
TASKS = {"sustained region": "seated pose q\\*"}


@pytest.mark.parametrize("name", CALLS)
def test_max_seconds_stops_every_long_call_with_stopped_error(polygon, name):
    task = TASKS.get(name, name)
    with pytest.raises(fixel.StoppedError, match=f"^{task}: time limit reached after .*; no result$"):
        CALLS[name](polygon)


def test_a_generous_max_seconds_changes_no_answer(polygon):
    assert fixel.region(polygon, max_seconds=60).to_json()["intervals"] == fixel.region(polygon).to_json()["intervals"]
    a = fixel.simulate(polygon, [0, -1, 0], steps=3, max_seconds=60)
    b = fixel.simulate(polygon, [0, -1, 0], steps=3)
    assert a.seated == b.seated and [s.q for s in a.steps] == [s.q for s in b.steps]


def test_bad_max_seconds_is_named(polygon):
    for call in (fixel.region, fixel.guaranteed_set):
        with pytest.raises(fixel.InputError) as e:
            call(polygon, max_seconds=0)
        assert e.value.field == "max_seconds"
        with pytest.raises(TypeError, match="max_seconds"):
            call(polygon, max_seconds="1")
    with pytest.raises(fixel.InputError) as e:
        fixel.simulate(polygon, [0, -1, 0], max_seconds=float("nan"))
    assert e.value.field == "max_seconds"
    with pytest.raises(TypeError, match="max_seconds"):
        fixel.sample(polygon, 8, max_seconds=True)


def test_a_limit_of_a_billion_seconds_or_more_is_no_limit(polygon):
    # steady_clock's nanoseconds overflow past 292 years: 1e10 s once set a
    # deadline in the past, and the run stopped before it began.
    plain = fixel.region(polygon).counts()
    for limit in (1e9, 1e10, 1e300, float("inf"), 10**400):
        assert fixel.region(polygon, max_seconds=limit).counts() == plain
    unlimited = fixel.simulate(polygon, [0, -1, 0], steps=200, max_seconds=float("inf"))
    assert [s.q for s in unlimited.steps] == [s.q for s in fixel.simulate(polygon, [0, -1, 0], steps=200).steps]


def test_any_real_number_is_a_time_limit(polygon):
    from fractions import Fraction

    plain = fixel.simulate(polygon, [0, -1, 0], steps=120)
    for limit in (np.int64(60), np.float32(60), Fraction(60), 60, 60.0):
        run = fixel.simulate(polygon, [0, -1, 0], steps=120, max_seconds=limit)
        assert [s.q for s in run.steps] == [s.q for s in plain.steps]


def _ellipse_dict(edges):
    # A polyline ellipse with `edges` edges (exact points on a rational
    # parametrisation), fixel-free: the load's outline checks poll per edge.
    points = []
    for k in range(edges):
        t = F(2 * k - edges, edges)  # t in [-1, 1): (1 - t²)/(1 + t²), 2t/(1 + t²) on the circle
        x, y = (1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)
        points.append([str(2 * x), str(y)])
    points.append(points[0])
    return {"name": "ellipse", "time_step": "1", "body": {"dof": 3, "mass": "1",
            "boundary": [{"type": "polyline", "points": points}]}, "fixels": []}  # fmt: skip


def test_loading_a_huge_outline_stops_at_its_time_limit_and_loads_without_one(tmp_path):
    d = _ellipse_dict(4000)
    with pytest.raises(fixel.StoppedError, match="^load: time limit reached after"):
        fixel.Scene.from_dict(d, max_seconds=PAST)
    path = tmp_path / "ellipse.json"
    path.write_text(json.dumps(d))
    with pytest.raises(fixel.StoppedError, match="^load: time limit reached after"):
        fixel.Scene.load(path, max_seconds=PAST)
    assert fixel.Scene.load(path, max_seconds=60).num_curves == fixel.Scene.from_dict(d).num_curves == 1


def test_a_push_longer_than_the_engine_step_limit_is_refused_naming_time(polygon):
    with pytest.raises(fixel.InputError) as e:
        fixel.push(polygon, wrench=[0, 0, 0], time=100001)
    assert e.value.field == "time" and e.value.value == "100001"
    assert fixel.push(polygon, wrench=[0, 0, 0], time=1)["outcome"] == "timeout"  # a part at rest, nothing decided


def test_a_stopped_region_still_tells_its_progress_callback_done(blob32):
    events = []
    with pytest.raises(fixel.StoppedError):
        fixel.region(blob32, resolution=FINE, max_seconds=0.3, progress=lambda stage, t: events.append(stage))
    assert events[0] == "start" and events[-1] == "done"


def test_a_progress_callback_that_raises_stops_the_core(blob32):
    # Without the cancel the call would return only at the 30 s backstop.
    def abort(stage, t):
        if stage == "running":
            raise RuntimeError("abort from the callback")

    t0 = time.monotonic()
    with pytest.raises(RuntimeError, match="abort from the callback"):
        fixel.region(blob32, progress=abort, max_seconds=30, **SLOW)
    assert time.monotonic() - t0 < 25
    events = []
    with pytest.raises(ZeroDivisionError):
        fixel.design(blob32, spacing="1/8", max_seconds=30, progress=lambda *a: events.append(a) or 1 / 0)
    assert len(events) == 1  # raised at its first report, and the run ended there


def _interrupted(call):
    """Raises KeyboardInterrupt in the main thread 0.3 s into ``call()``;
    returns the seconds until ``call`` gave up."""
    timer = threading.Timer(0.3, _thread.interrupt_main)
    t0 = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            call()
    finally:
        timer.cancel()
    return time.monotonic() - t0


@pytest.mark.parametrize("name", ["region", "sample", "simulate", "push"])
def test_ctrl_c_stops_the_core_and_raises_keyboard_interrupt(blob32, polygon, name):
    # max_seconds is only a safety net: a missed interrupt fails with
    # StoppedError instead of hanging. Unstopped, each runs for minutes.
    call = {
        "region": lambda: fixel.region(blob32, **SLOW, max_seconds=20),
        "sample": lambda: fixel.sample(blob32, 10**6, max_seconds=20),
        "simulate": lambda: fixel.simulate(polygon, [0, -1, 0], steps=10**8, max_seconds=20),
        "push": lambda: fixel.push(polygon, wrench=[0, 0, 0], time=100000, max_seconds=20),  # at rest: 10^8 steps
    }[name]
    assert _interrupted(call) < 10
    # The core stopped and its worker is free: the next run answers.
    assert fixel.region(polygon, resolution="1/64").intervals


def _region_counts(path):
    return fixel.region(fixel.Scene.load(path), resolution="1/64").counts()


def test_a_forked_child_runs_with_its_own_workers(polygon):
    expected = fixel.region(polygon, resolution="1/64").counts()  # the parent's pool exists now
    ctx = multiprocessing.get_context("fork")
    with ctx.Pool(1) as pool:
        # The parent's worker threads do not exist in the child: reusing its
        # pool would wait for them forever, hence the timeout.
        assert pool.apply_async(_region_counts, (SCENE_DIR / "polygon.json",)).get(timeout=60) == expected


def test_calls_from_several_threads_get_their_own_answers(polygon, blob32):
    expected = {id(s): fixel.region(s, resolution="1/256").to_json()["intervals"] for s in (polygon, blob32)}
    got, errors = [], []

    def run(s):
        try:
            got.append((id(s), fixel.region(s, resolution="1/256").to_json()["intervals"]))
        except BaseException as e:  # reported below, not lost in the thread
            errors.append(e)

    threads = [threading.Thread(target=run, args=(s,)) for s in (polygon, blob32) * 3]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert not errors
    assert len(got) == 6 and all(intervals == expected[key] for key, intervals in got)


@pytest.fixture(scope="module")
def long_gap():
    """The polygon with a gap of 20,000 digits: building J takes about 30 s
    (one exact step that used to ignore max_seconds and Ctrl-C)."""
    d = json.loads((SCENE_DIR / "polygon.json").read_text())
    d["fixels"][0]["gap"] = "1/" + "7" * 20000
    return fixel.Scene.from_dict(d)


# Building J is two long exact steps on this scene: the seated pose q*
# (about 0.3 s here, longer on a loaded machine) and J's own pieces.
LONG_STEPS = r"(seated pose q\*|sustained set J)"


@pytest.mark.parametrize(
    "call",
    [
        lambda s: fixel.sustained_set(s, max_seconds=0.5),
        lambda s: fixel.approach_set(s, max_seconds=0.5),
        lambda s: fixel.region(s, push="sustained", max_seconds=0.5),
        lambda s: fixel.push_plan(s, "0:1/2", max_seconds=0.5),
    ],
    ids=["sustained_set", "approach_set", "region", "push_plan"],
)
def test_one_long_exact_step_stops_at_max_seconds(long_gap, call):
    t0 = time.monotonic()
    with pytest.raises(
        fixel.StoppedError, match=f"^{LONG_STEPS}: time limit reached after [0-9]+ exact steps; no result$"
    ):
        call(long_gap)
    assert time.monotonic() - t0 < 10  # not the 30 s of the whole step


def test_j_prime_of_a_given_j_stops_at_max_seconds_naming_j_prime(polygon):
    J = fixel.sustained_set(polygon)
    with pytest.raises(fixel.StoppedError, match="^approach-aware J': time limit reached after"):
        fixel.approach_set(polygon, J, max_seconds=PAST)
    assert fixel.approach_set(polygon, J, max_seconds=60).decided  # a generous limit changes nothing


def test_j_prime_membership_of_one_wrench_stops_at_max_seconds_between_pairs(polygon):
    A = fixel.approach_set(polygon)
    w = (-1, -1, 0)  # in J': every pair of fixels is tested, so its loop polls
    assert A.why_not(w) == ""
    for test in (A.why_not, A.hold, A.contains):
        with pytest.raises(
            fixel.StoppedError, match=r"^approach-aware J' \(a wrench's test\): time limit reached after .*; no result$"
        ):
            test(w, max_seconds=PAST)
    assert A.contains(w, max_seconds=60) and A.hold(w, max_seconds=60) is None  # a generous limit changes nothing


def test_ctrl_c_stops_one_long_exact_step(long_gap):
    assert _interrupted(lambda: fixel.sustained_set(long_gap, max_seconds=20)) < 10
