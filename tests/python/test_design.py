"""fixel.design: the thread pool, and the same run mapped over a Dask
LocalCluster on loopback (docs/design.md)."""

import json
import time
from fractions import Fraction

import pytest

import fixel
from conftest import SCENE_DIR, cli_json
from fixel._design import _record_check

# The mirror-symmetric "house" of tests/design_test.cpp: the rectangle
# [-1, 1] x [-1, 0] under the roof (1, 0), (0, 1), (-1, 0).
HOUSE = {
    "name": "house",
    "time_step": "1",
    "body": {
        "dof": 3,
        "mass": "1",
        "boundary": [{"type": "polyline", "points": [[-1, -1], [1, -1], [1, 0], [0, 1], [-1, 0], [-1, -1]]}],
    },
    "fixels": [],
}
# B1 = (-1/2, -1), B2 = (1/2, -1), L = (-1, -1/2), R = (1, -1/2).
HOUSE_CANDIDATES = [(0, "1/4"), (0, "3/4"), (0, "9/2"), (0, "3/2")]
SMALL = dict(resolution="1/32", top=5)


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("dask.distributed")
    cluster = distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1", dashboard_address=None
    )
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def polygon_candidates():
    # Every third default candidate: 8 candidates, 56 triples.
    return [(c.curve, c.u) for c in fixel.design_candidates(SCENE_DIR / "polygon.json")[::3]]


@pytest.fixture(scope="module")
def twelve_candidates():
    # Every other default candidate: 12 candidates, 220 triples.
    return [(c.curve, c.u) for c in fixel.design_candidates(SCENE_DIR / "polygon.json")[::2]]


def test_the_house_ranks_its_mirror_pair_first_with_equal_exact_scores():
    d = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, mu=0, pusher_mu=0, resolution="1/64", top=10, jobs=1)
    assert d.stats["triples"] == 4 and d.stats["singular"] == 2
    assert [l.triple for l in d.layouts] == [(0, 1, 2), (0, 1, 3)]
    assert d.layouts[0].score == d.layouts[1].score
    assert isinstance(d.layouts[0].score, Fraction)
    # By hand: IN only on the right roof for t in (0, 1/2); at resolution 1/64
    # the cells touching t = 0 and t = 1/2 are partial, so IN is [1/64, 31/64]:
    # 15/32 of the outline's 5 units of parameter, a score of 3/32.
    assert d.layouts[0].score == Fraction(3, 32)
    assert d.layouts[0].fixels[2].point == (Fraction(-1), Fraction(-1, 2))


def test_a_pusher_friction_interval_is_judged_at_its_upper_end_and_kept_in_the_layouts_scene():
    ranged = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, mu=0, pusher_mu=("1/20", "1/10"), **SMALL)
    upper = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, mu=0, pusher_mu="1/10", **SMALL)
    assert [l.score for l in ranged.layouts] == [l.score for l in upper.layouts]
    assert ranged.document["pusher_mu"] == ["1/20", "1/10"]
    assert fixel.design_scene(HOUSE, ranged).to_dict()["pusher"]["mu"] == ["1/20", "1/10"]
    assert fixel.design_scene(HOUSE, upper).to_dict()["pusher"]["mu"] == "1/10"


def test_a_layout_as_a_scene_gives_its_score_through_the_region():
    d = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, mu=("1/20", "1/10"), pusher_mu="1/50", **SMALL)
    scene = fixel.design_scene(HOUSE, d)
    fixels = scene.to_dict()["fixels"]
    assert [f["mu"] for f in fixels] == [["1/20", "1/10"]] * 3
    assert all(f["gap"] == "0" and "off_boundary" not in f for f in fixels)  # the house's normals are exact
    assert scene.pusher_mu == Fraction(1, 50)
    r = fixel.region(scene, push="sustained", resolution=SMALL["resolution"])
    in_length = sum((i.u1 - i.u0 for i in r.intervals if i.status == "in"), Fraction(0))
    assert in_length > 0 and in_length / 5 == d.layouts[0].score
    assert scene.name == "house-layout-1"
    assert fixel.design_scene(HOUSE, d, rank=2).name == "house-layout-2"


def test_design_scene_refuses_a_part_with_the_same_points_but_another_outline():
    # The polygon's best layout has a fixel at u = 713/256 on edge 2. Turning
    # edge 2 about that point keeps all three points but changes the outline:
    # design_scene described the scene with the polygon's score.
    polygon = fixel.Scene.load(str(SCENE_DIR / "polygon.json"))
    d = fixel.design(polygon, top=1, jobs=1)
    fixels = d.layouts[0].fixels
    assert [c.u for c in fixels][1] == Fraction(713, 256)
    t = Fraction(201, 256)  # the fixel's place along edge 2, from (3/2, 1/2) to (1/4, 3/2)
    p = fixels[1].point
    turned = (Fraction(-5, 4), Fraction(9, 8))  # edge 2's direction (-5/4, 1), turned
    doc = polygon.to_dict()
    points = doc["body"]["boundary"][0]["points"]
    points[2] = [str(p[0] - t * turned[0]), str(p[1] - t * turned[1])]
    points[3] = [str(p[0] + (1 - t) * turned[0]), str(p[1] + (1 - t) * turned[1])]
    for key in ("mass", "inertia", "center_of_mass"):
        doc["body"].pop(key, None)  # the outline's own, derived again
    other = fixel.Scene.from_dict(doc)
    assert [fixel.design_candidates(other, [(c.curve, c.u) for c in fixels])[k].point for k in range(3)] == [
        c.point for c in fixels
    ]
    with pytest.raises(fixel.InputError) as e:
        fixel.design_scene(other, d)
    assert e.value.field == "layout.score" and e.value.value == str(d.layouts[0].score)
    assert fixel.design_scene(polygon, d).name == "polygon-layout-1"


def test_design_scene_is_the_scene_the_cli_writes(tmp_path, polygon_candidates):
    path = tmp_path / "candidates.json"
    path.write_text(json.dumps({"candidates": [{"curve": c, "u": str(u)} for c, u in polygon_candidates]}))
    out = tmp_path / "best.json"
    cli_json("design", SCENE_DIR / "polygon.json", "--candidates", path, "--resolution", "1/32", "--scene-out", out)
    d = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, **SMALL)
    scene = fixel.design_scene(SCENE_DIR / "polygon.json", d)
    scene.save(tmp_path / "mine.json")
    assert (tmp_path / "mine.json").read_text() == out.read_text()  # the same file, byte for byte
    # which reads back as the same scene (the outline's mass properties derived again)
    assert fixel.Scene.load(out).to_dict() == scene.to_dict()
    assert "mass" not in json.loads(out.read_text())["body"]


def test_conditioning_is_the_smallest_singular_value_numpy_finds_for_the_layouts_wrenches():
    # A second method: numpy's SVD of W_n built here from the candidates,
    # the centre of mass and the radius of gyration (display values).
    import numpy as np

    for name in ("polygon", "fig6"):
        part = fixel.Scene.load(str(SCENE_DIR / f"{name}.json"))
        body = part.to_dict()["body"]
        cx, cy = (float(Fraction(v)) for v in body["center_of_mass"])
        rho = (float(Fraction(body["inertia"])) / float(Fraction(body["mass"]))) ** 0.5
        d = fixel.design(part, top=3, jobs=1)
        for layout in d.layouts:
            rows = []
            for c in layout.fixels:
                (px, py), (nx, ny) = (float(v) for v in c.point), (float(v) for v in c.normal)
                length = (nx * nx + ny * ny) ** 0.5
                nx, ny = nx / length, ny / length
                rows.append([nx, ny, ((px - cx) * ny - (py - cy) * nx) / rho])
            expected = np.linalg.svd(np.array(rows).T, compute_uv=False).min()
            assert layout.conditioning == pytest.approx(expected, rel=1e-6, abs=1e-12), (name, layout.rank)
            assert layout.nearly_singular == (expected < 0.03)
            # fig6's outline is one cubic B-spline, the polygon's a polyline.
            assert layout.curved_contacts == (3 if name == "fig6" else 0), (name, layout.rank)
    # fig6's two best layouts are the nearly singular ones (their normal lines nearly meet).
    assert [l.nearly_singular for l in d.layouts] == [True, True, False]


def test_a_step_layout_whose_gaps_no_pose_closes_says_so():
    part = fixel.Scene.load(str(SCENE_DIR / "polygon.json"))
    d = fixel.design(part, push="step", gap="1/20", top=1, jobs=1)
    assert "would touch the line of its edge beyond the edge's end" in d.layouts[0].step_seat
    assert fixel.design(part, top=1, jobs=1).layouts[0].step_seat is None  # gap 0: the scene pose


def test_design_scene_refuses_a_rank_it_does_not_have():
    d = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, mu=0, **SMALL)
    with pytest.raises(fixel.InputError, match="rank: 0"):
        fixel.design_scene(HOUSE, d, rank=0)
    with pytest.raises(fixel.InputError, match=f"must be 1 to {len(d.layouts)}"):
        fixel.design_scene(HOUSE, d, rank=len(d.layouts) + 1)
    with pytest.raises(TypeError, match="design"):
        fixel.design_scene(HOUSE, d.document)
    # Another part whose parameter ranges fit: its points are not the design's.
    moved = json.loads(json.dumps(HOUSE))
    moved["body"]["boundary"][0]["points"][1] = [2, -1]  # the bottom right corner moved out
    with pytest.raises(fixel.InputError, match="is not the part of this design: its fixel 0"):
        fixel.design_scene(moved, d)
    none = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES[:2], mu=0, **SMALL)
    with pytest.raises(fixel.InputError, match="no layout"):
        fixel.design_scene(HOUSE, none)


def test_the_python_thread_pool_agrees_with_the_cli(tmp_path, polygon_candidates):
    path = tmp_path / "candidates.json"
    path.write_text(json.dumps({"candidates": [{"curve": c, "u": str(u)} for c, u in polygon_candidates]}))
    doc = cli_json("design", SCENE_DIR / "polygon.json", "--candidates", path, "--resolution", "1/32", "--top", 5)
    d = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, **SMALL)
    assert [(tuple(l["triple"]), Fraction(l["score"])) for l in doc["layouts"]] == d.ranking()


def test_dask_gives_the_thread_pools_ranking(client, polygon_candidates):
    pool = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, jobs=2, exhaustive=True, **SMALL)
    dask = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, client=client, batch_size=10,
                        exhaustive=True, **SMALL)  # fmt: skip
    assert dask.ranking() == pool.ranking()
    assert len(pool.layouts) == 5
    # Both score every triple.
    for key in ("triples", "singular", "no_form_closure", "j_empty", "regions", "bounded"):
        assert dask.stats[key] == pool.stats[key]
    assert pool.stats["bounded"] == 0 and dask.stats["batches"] == 6 and dask.stats["rounds"] == 0
    assert [l.step_score for l in dask.layouts] == [l.step_score for l in pool.layouts]


def test_dask_scores_in_the_bounds_order_and_gives_the_exhaustive_ranking(client, twelve_candidates):
    every = fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, jobs=2, exhaustive=True, **SMALL)
    pool = fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, jobs=2, **SMALL)
    for batch_size, wave in ((3, 1), (4, 2), (32, 1)):
        dask = fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, client=client,
                            batch_size=batch_size, wave=wave, **SMALL)  # fmt: skip
        assert dask.ranking() == every.ranking()
        s = dask.stats
        assert s["singular"] + s["no_form_closure"] + s["j_empty"] + s["regions"] + s["bounded"] == s["triples"] == 220
        assert s["singular"] == every.stats["singular"] and s["bounded"] > 0
        # The pilot is one batch; the rest come in rounds of at most `wave`.
        assert s["rounds"] >= 1 and s["batches"] <= 1 + wave * s["rounds"]
        if (batch_size, wave) == (32, 1):  # the thread pool's blocks: its counts too
            for key in ("no_form_closure", "j_empty", "regions", "bounded"):
                assert s[key] == pool.stats[key]
    with pytest.raises(fixel.InputError) as e:
        fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, client=client, wave=0)
    assert (e.value.field, e.value.value) == ("wave", "0")


def test_the_bound_skips_triples_and_keeps_the_exhaustive_ranking(polygon_candidates):
    bounded = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, jobs=2, top=2, resolution="1/32")
    every = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, jobs=2, top=2, resolution="1/32",
                         exhaustive=True)  # fmt: skip
    assert bounded.ranking() == every.ranking()
    assert bounded.stats["bounded"] > 0 and every.stats["bounded"] == 0
    s = bounded.stats
    assert s["singular"] + s["no_form_closure"] + s["j_empty"] + s["regions"] + s["bounded"] == s["triples"]
    assert s["singular"] == every.stats["singular"]
    with pytest.raises(TypeError, match="exhaustive"):
        fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, exhaustive="yes")


def test_dask_scores_every_triple_once_when_the_pilot_scores_nothing(client):
    # On nonunique_part every layout scores 0: after the pilot, the ranges.
    cands = [(c.curve, c.u) for c in fixel.design_candidates(SCENE_DIR / "nonunique_part.json")[::2]]
    pool = fixel.design(SCENE_DIR / "nonunique_part.json", candidates=cands, jobs=2, **SMALL)
    dask = fixel.design(SCENE_DIR / "nonunique_part.json", candidates=cands, client=client, batch_size=16, **SMALL)
    assert dask.ranking() == pool.ranking() and pool.layouts[0].score == 0
    for key in ("triples", "singular", "no_form_closure", "j_empty", "regions", "bounded"):
        assert dask.stats[key] == pool.stats[key]
    assert dask.stats["batches"] == 1 + 14 and dask.stats["rounds"] == 0  # the pilot, then 220 triples by 16


def test_too_many_range_batches_is_a_clear_error_before_any_is_mapped(client):
    # 4,121 candidates: 11,655,753,980 triples in batches of 64.
    with pytest.raises(fixel.InputError) as e:
        fixel.design(SCENE_DIR / "polygon.json", spacing="1/500", client=client, exhaustive=True)
    assert (e.value.field, e.value.value) == ("batch_size", "64")
    assert "11655753980 triples" in str(e.value)


def _fail_once(monkeypatch, batch, marker):
    """The cluster path's batch `batch` fails once (the first call that finds
    `marker` missing creates it and raises), as a worker dying mid-batch."""
    import fixel._design as design_module

    monkeypatch.setattr(design_module, "_FAIL_ONCE", (batch, marker))


def test_a_batch_that_raises_once_is_retried_without_losing_a_result(client, twelve_candidates, tmp_path, monkeypatch):
    pool = fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, jobs=1, **SMALL)
    marker = str(tmp_path / "failed-once")
    _fail_once(monkeypatch, 1, marker)
    d = fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, client=client, batch_size=3, wave=1,
                     retries=1, **SMALL)  # fmt: skip
    assert (tmp_path / "failed-once").exists()  # it did fail once
    assert d.ranking() == pool.ranking()
    assert d.stats["jobs"] == len(client.scheduler_info()["workers"])  # the cluster's workers, not jobs=


def test_a_rerun_with_the_output_file_resumes_after_a_failed_batch(client, polygon_candidates, tmp_path, monkeypatch):
    pool = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, jobs=1, **SMALL)
    out = str(tmp_path / "design.jsonl")
    marker = str(tmp_path / "failed-once")
    with pytest.raises(fixel.Error, match="rerun with it to resume"):
        _fail_once(monkeypatch, 3, marker)
        fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, client=client, batch_size=10,
                     retries=0, output=out, exhaustive=True, **SMALL)  # fmt: skip
    monkeypatch.undo()
    with open(out) as f:
        assert len(f.readlines()) == 5  # 6 batches of 56 triples, one failed
    d = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, client=client, batch_size=10,
                     retries=0, output=out, exhaustive=True, **SMALL)  # fmt: skip
    assert d.stats["batches"] == 6 and d.stats["batches_resumed"] == 5
    assert d.ranking() == pool.ranking()


def test_a_bounded_rerun_resumes_the_batches_it_would_hand_out_again(client, twelve_candidates, tmp_path, monkeypatch):
    every = fixel.design(SCENE_DIR / "polygon.json", candidates=twelve_candidates, jobs=1, exhaustive=True, **SMALL)
    out = str(tmp_path / "design.jsonl")
    marker = str(tmp_path / "failed-once")
    run = dict(candidates=twelve_candidates, client=client, batch_size=3, wave=2, retries=0, output=out, **SMALL)
    with pytest.raises(fixel.Error, match="rerun with it to resume"):
        _fail_once(monkeypatch, 2, marker)
        fixel.design(SCENE_DIR / "polygon.json", **run)
    monkeypatch.undo()
    with open(out) as f:
        recorded = [json.loads(line) for line in f]
    assert [r["batch"] for r in recorded] == [0, 1]  # the pilot, and batch 2's partner in its round
    assert all(len(r["triples"]) == r["count"] for r in recorded)
    d = fixel.design(SCENE_DIR / "polygon.json", **run)
    assert d.stats["batches_resumed"] == 2 and d.stats["batches"] > 2
    assert d.ranking() == every.ranking()
    # A third run finds every batch it hands out in the file.
    again = fixel.design(SCENE_DIR / "polygon.json", **run)
    assert again.stats["batches_resumed"] == again.stats["batches"] == d.stats["batches"]
    assert again.ranking() == every.ranking()


def _same_as_the_pool(d, pool):
    """Layouts (triples, every score) and counts as on the thread pool."""
    scores = lambda x: [(l.triple, l.score, l.sustained_score, l.step_score) for l in x.layouts]  # noqa: E731
    assert scores(d) == scores(pool)
    for key in ("triples", "singular", "no_form_closure", "j_empty", "regions", "bounded"):
        assert d.stats[key] == pool.stats[key], key


def test_a_rerun_with_another_batch_size_does_not_take_the_other_sizes_batches(client, polygon_candidates, tmp_path):
    # 56 triples: 3 ranges of 20, then 7 of 8. Range 1 of 20 is not range 1 of 8.
    pool = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, jobs=2, exhaustive=True, **SMALL)
    out = str(tmp_path / "design.jsonl")
    run = dict(candidates=polygon_candidates, client=client, output=out, exhaustive=True, **SMALL)
    first = fixel.design(SCENE_DIR / "polygon.json", batch_size=20, **run)
    _same_as_the_pool(first, pool)
    d = fixel.design(SCENE_DIR / "polygon.json", batch_size=8, **run)
    _same_as_the_pool(d, pool)
    assert d.stats["batches"] == 7 and d.stats["batches_resumed"] == 0
    # The file now holds both runs; each size finds its own batches.
    for batch_size, batches in ((20, 3), (8, 7)):
        again = fixel.design(SCENE_DIR / "polygon.json", batch_size=batch_size, **run)
        _same_as_the_pool(again, pool)
        assert again.stats["batches"] == again.stats["batches_resumed"] == batches


def test_a_recorded_batch_that_is_not_the_batch_it_stands_for_is_refused(client, polygon_candidates, tmp_path):
    out = tmp_path / "design.jsonl"
    run = dict(candidates=polygon_candidates, client=client, batch_size=20, output=str(out), exhaustive=True, **SMALL)
    fixel.design(SCENE_DIR / "polygon.json", **run)
    records = [json.loads(line) for line in out.read_text().splitlines()]
    for r in records:
        if r["batch"] == 1:
            r["first"], r["count"] = 16, 16  # as if written with batch_size=16
            r["check"] = _record_check(r)  # a consistent record, as fixel would write it
    out.write_text("".join(json.dumps(r) + "\n" for r in records))
    with pytest.raises(fixel.InputError, match="belongs to a run with other settings") as e:
        fixel.design(SCENE_DIR / "polygon.json", **run)
    assert (e.value.field, e.value.value) == ("output", str(out))


def test_a_recorded_score_that_the_triple_does_not_have_is_refused(client, polygon_candidates, tmp_path):
    out = tmp_path / "design.jsonl"
    run = dict(candidates=polygon_candidates, client=client, batch_size=20, output=str(out), exhaustive=True, **SMALL)
    first = fixel.design(SCENE_DIR / "polygon.json", **run)
    records = [json.loads(line) for line in out.read_text().splitlines()]
    best = first.layouts[0].score
    # A layout that is not the best, edited to outscore it: trusted, it would displace a true top layout.
    edited = next(r for r in records if any(Fraction(l[4]) < best for l in r["layouts"]))
    layout = next(l for l in edited["layouts"] if Fraction(l[4]) < best)
    layout[4] = "999"
    out.write_text("".join(json.dumps(r) + "\n" for r in records))
    # Edited by hand: the record's check no longer matches.
    with pytest.raises(fixel.InputError, match=f"batch {edited['batch']} that was changed after fixel wrote it") as e:
        fixel.design(SCENE_DIR / "polygon.json", **run)
    assert (e.value.field, e.value.value) == ("output", str(out))
    # Its check recomputed too: the report's own scoring of the top triples refuses it.
    edited["check"] = _record_check(edited)
    out.write_text("".join(json.dumps(r) + "\n" for r in records))
    with pytest.raises(fixel.InputError, match=f"records triple {layout[3]} with score 999, but it scores") as e:
        fixel.design(SCENE_DIR / "polygon.json", **run)
    assert (e.value.field, e.value.value) == ("output", str(out))


@pytest.mark.parametrize(
    "bad, exc, field",
    [
        (dict(client=5), TypeError, "client"),
        (dict(client="nonsense"), fixel.InputError, "client"),
        (dict(client="foo://127.0.0.1:8786"), fixel.InputError, "client"),
        (dict(timeout="x"), TypeError, "timeout"),
        (dict(timeout=True), TypeError, "timeout"),
        (dict(timeout=0), fixel.InputError, "timeout"),
        (dict(timeout=float("nan")), fixel.InputError, "timeout"),
        (dict(retries="x"), TypeError, "retries"),
        (dict(retries=1.0), TypeError, "retries"),
        (dict(retries=True), TypeError, "retries"),
        (dict(retries=-1), fixel.InputError, "retries"),
        (dict(batch_size=2.0), TypeError, "batch_size"),
        (dict(batch_size=True), TypeError, "batch_size"),
        (dict(batch_size=0), fixel.InputError, "batch_size"),
        (dict(wave=1.5), TypeError, "wave"),
        (dict(wave=-1), fixel.InputError, "wave"),
        (dict(output="{tmp}"), fixel.InputError, "output"),
        (dict(output="{tmp}/missing/run.jsonl"), fixel.InputError, "output"),
        (dict(output=5), TypeError, "output"),
    ],
)
def test_dask_arguments_are_checked_before_any_batch_runs(
    client, polygon_candidates, tmp_path, bad, exc, field, monkeypatch
):
    marker = tmp_path / "a-batch-ran"
    _fail_once(monkeypatch, 0, str(marker))
    args = dict(candidates=polygon_candidates, client=client, retries=0, **SMALL)
    args.update({k: v.format(tmp=tmp_path) if isinstance(v, str) else v for k, v in bad.items()})
    t0 = time.monotonic()
    with pytest.raises(exc) as e:
        fixel.design(SCENE_DIR / "polygon.json", **args)
    if exc is TypeError:
        assert str(e.value).startswith(field + ":")
    else:
        assert e.value.field == field
    assert not marker.exists() and time.monotonic() - t0 < 10


def test_a_client_opened_from_an_address_is_closed_also_on_an_error(client, polygon_candidates, tmp_path, monkeypatch):
    import fixel._design as design_module

    def clients():
        return len(client.run_on_scheduler(lambda dask_scheduler: list(dask_scheduler.clients)))

    opened, connect = [], design_module._connect
    monkeypatch.setattr(design_module, "_connect", lambda *a: opened.append(connect(*a)) or opened[-1])
    before = clients()
    address = client.scheduler.address
    run = dict(candidates=polygon_candidates, client=address, timeout=Fraction(10), batch_size=20, **SMALL)
    pool = fixel.design(SCENE_DIR / "polygon.json", candidates=polygon_candidates, jobs=1, **SMALL)
    assert fixel.design(SCENE_DIR / "polygon.json", **run).ranking() == pool.ranking()
    with pytest.raises(fixel.Error, match="failed after 0 retries"):
        monkeypatch.setattr(design_module, "_FAIL_ONCE", (0, str(tmp_path / "failed")))
        fixel.design(SCENE_DIR / "polygon.json", retries=0, **run)
    assert len(opened) == 2 and all(c.status == "closed" for c in opened)
    t0 = time.monotonic()
    while clients() != before and time.monotonic() - t0 < 10:
        time.sleep(0.1)
    assert clients() == before


def test_an_unreachable_scheduler_is_a_clear_error_within_a_bounded_time():
    t0 = time.monotonic()
    with pytest.raises(fixel.InputError) as e:
        fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, client="tcp://127.0.0.1:9", timeout=2)
    assert e.value.field == "client"
    assert "unreachable" in str(e.value)
    assert time.monotonic() - t0 < 30


def test_max_seconds_stops_the_thread_pool_with_stopped_error():
    # 100 candidates, 161,700 triples, every one scored: about 35 s; stopped at 0.3 s.
    t0 = time.monotonic()
    with pytest.raises(fixel.StoppedError, match="design: time limit reached after"):
        fixel.design(SCENE_DIR / "blob.json", spacing="1/8", exhaustive=True, max_seconds=0.3)
    assert time.monotonic() - t0 < 10


def test_ctrl_c_stops_the_core_and_raises_keyboard_interrupt():
    import _thread
    import threading

    timer = threading.Timer(0.3, _thread.interrupt_main)
    t0 = time.monotonic()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            # max_seconds is only a safety net: a missed interrupt fails with StoppedError instead of hanging.
            fixel.design(SCENE_DIR / "blob.json", spacing="1/8", exhaustive=True, max_seconds=20)
    finally:
        timer.cancel()
    assert time.monotonic() - t0 < 10
    # The core stopped: the next run has the pool to itself and answers.
    assert fixel.design(SCENE_DIR / "polygon.json", top=1, resolution="1/32").layouts


def test_a_progress_callable_gets_the_runs_reports():
    reports = []
    fixel.design(SCENE_DIR / "blob.json", exhaustive=True, jobs=1, progress=lambda *r: reports.append(r))
    assert reports, "a run of about 0.7 s reports every 0.1 s"
    assert all(r[0] == "design" and r[2] == 2024 and r[3] == "layouts" for r in reports)
    assert [r[1] for r in reports] == sorted(r[1] for r in reports)
    with pytest.raises(fixel.InputError) as e:
        fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, max_seconds=0)
    assert e.value.field == "max_seconds"
    with pytest.raises(TypeError, match="max_seconds"):
        fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, max_seconds="1")
    with pytest.raises(TypeError, match="progress"):
        fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, progress="yes")


def test_max_seconds_is_refused_with_a_cluster(client):
    with pytest.raises(fixel.InputError) as e:
        fixel.design(HOUSE, candidates=HOUSE_CANDIDATES, client=client, max_seconds=5)
    assert e.value.field == "max_seconds"


def test_fewer_than_three_candidates_is_no_layout_with_a_reason():
    d = fixel.design(HOUSE, candidates=HOUSE_CANDIDATES[:2])
    assert d.layouts == [] and "only 2 candidates" in d.no_layout


def test_bad_input_names_the_field_and_value():
    with pytest.raises(fixel.InputError) as e:
        fixel.design(HOUSE, candidates=[(0, "6")])
    assert (e.value.field, e.value.value) == ("candidates[0].u", "6")
    with pytest.raises(fixel.InputError) as e:
        fixel.design(HOUSE, spacing=0)
    assert e.value.value == "0"
    with pytest.raises(fixel.InputError) as e:
        fixel.design(HOUSE, top=0)
    assert (e.value.field, e.value.value) == ("top", "0")  # the argument name, not the C++ option's
    with pytest.raises(TypeError):
        fixel.design(HOUSE, mu=0.1)
    with pytest.raises(fixel.SceneError):
        fixel.design(SCENE_DIR / "example2.json")  # no outline
    with pytest.raises(fixel.InputError, match="is read as a candidate file path") as e:
        fixel.design(HOUSE, candidates="boundry")  # a typo of "boundary"
    assert (e.value.field, e.value.value) == ("candidates", "boundry")
