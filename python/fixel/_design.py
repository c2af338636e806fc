"""Fixture design (docs/design.md): the best three fixels for one push.

``fixel.design(part, ...)`` runs on the C++ oneTBB thread pool, or, with
``client=`` a ``dask.distributed.Client`` (or a scheduler address), maps
batches of triples over a Dask cluster. Exact results travel as strings and
come back as ``Fraction``; a batch is a pure function of its arguments, so
Dask's retries recompute a lost one, and a JSON-lines ``output`` file lets a
rerun skip the batches that already finished.
"""

import hashlib
import json
import os
import threading
import time
import uuid
from dataclasses import dataclass
from fractions import Fraction
from typing import List, Optional, Tuple

from . import _fixel
from ._exact import frac, text
from .errors import Error, InputError


@dataclass(frozen=True)
class Candidate:
    """A place for a fixel: parameter u of curve `curve`, with the boundary
    point and its inward normal (not unit), all exact."""

    curve: int
    u: Fraction
    point: Tuple[Fraction, Fraction]
    normal: Tuple[Fraction, Fraction]


@dataclass(frozen=True)
class Layout:
    """One ranked layout: candidate indices, the ranking score and both
    push models' scores (Fractions of the boundary's parameter length)."""

    rank: int
    triple: Tuple[int, int, int]
    fixels: Tuple[Candidate, Candidate, Candidate]
    score: Fraction
    sustained_score: Optional[Fraction]
    sustained_empty: Optional[bool]
    step_score: Optional[Fraction]
    j_width: Optional[float]  # display only
    note: str = ""


@dataclass(frozen=True)
class Design:
    """The answer of fixel.design: `layouts` best first, `stats` (counts),
    `no_layout` (why there is none, or None), `shipped` (the scene's own
    layout scored alike, or None) and `document` (the `fixel design --json`
    dict, exact strings)."""

    layouts: List[Layout]
    stats: dict
    no_layout: Optional[str]
    shipped: Optional[dict]
    document: dict

    def ranking(self):
        """[(triple, score)] best first: what must agree between runs."""
        return [(l.triple, l.score) for l in self.layouts]


def _opt_frac(x):
    return None if x is None else frac(x)


def _candidate(d):
    return Candidate(d["curve"], frac(d["u"]), tuple(map(frac, d["point"])), tuple(map(frac, d["normal"])))


def _design_of(doc):
    layouts = [
        Layout(
            rank=l["rank"],
            triple=tuple(l["triple"]),
            fixels=tuple(_candidate(f) for f in l["fixels"]),
            score=frac(l["score"]),
            sustained_score=_opt_frac(l["sustained_score"]),
            sustained_empty=l["sustained_empty"],
            step_score=_opt_frac(l["step_score"]),
            j_width=l["j_width"],
            note=l.get("note", ""),
        )
        for l in doc["layouts"]
    ]
    return Design(layouts, doc["stats"], doc["no_layout"], doc["shipped"], doc)


def _mu_pair(mu, name):
    if isinstance(mu, (list, tuple)):
        if len(mu) != 2:
            raise InputError.make(name, repr(mu), "must be one number or (lo, hi)")
        return text(mu[0], name), text(mu[1], name)
    return text(mu, name), None


def _options(scene, push, resolution, mu, pusher_mu, gap, top, jobs, exhaustive=False):
    if mu is None:  # as the CLI: the scene's largest fixel mu, else 1/10
        mus = [f["mu"] for f in scene.to_dict().get("fixels", [])]
        flat = [Fraction(m[-1] if isinstance(m, list) else m) for m in mus]
        mu = max(flat) if flat else Fraction(1, 10)
    lo, hi = _mu_pair(mu, "mu")
    if pusher_mu is None:
        pusher_mu = scene.to_dict().get("pusher", {}).get("mu", "0")
        if isinstance(pusher_mu, list):
            pusher_mu = pusher_mu[-1]
    else:
        plo, phi = _mu_pair(pusher_mu, "pusher_mu")
        pusher_mu = phi if phi is not None else plo
    if not isinstance(top, int) or isinstance(top, bool):
        raise TypeError(f"top: {top!r} is not an int")
    if jobs is not None and (not isinstance(jobs, int) or isinstance(jobs, bool)):
        raise TypeError(f"jobs: {jobs!r} is not an int")
    if not isinstance(exhaustive, bool):
        raise TypeError(f"exhaustive: {exhaustive!r} is not a bool")
    return {
        "push": str(push),
        "resolution": text(resolution, "resolution"),
        "mu": lo,
        "mu_hi": hi,
        "pusher_mu": text(pusher_mu, "pusher_mu"),
        "gap": text(gap, "gap"),
        "top": top,
        "jobs": 0 if jobs is None else jobs,
        "bound": not exhaustive,
    }


def _candidates(scene, candidates, spacing):
    if isinstance(candidates, str) and candidates == "boundary":
        return _fixel.design_candidates(scene._impl, None if spacing is None else text(spacing, "spacing"))
    if isinstance(candidates, (str, os.PathLike)):
        return _fixel.design_load_candidates(scene._impl, os.fspath(candidates))
    pairs = []
    for i, c in enumerate(candidates):
        if isinstance(c, dict):
            c = (c["curve"], c["u"])
        curve, u = c
        pairs.append((int(curve), text(u, f"candidates[{i}].u")))
    return _fixel.design_check_candidates(scene._impl, pairs)


def design_candidates(part, candidates="boundary", spacing=None):
    """The candidates fixel.design would use, as `Candidate`s (exact)."""
    from . import Scene

    scene = _part(part)
    out = []
    for curve, u in _candidates(scene, candidates, spacing):
        doc = _fixel.design_candidate(scene._impl, curve, u)
        out.append(Candidate(curve, frac(u), tuple(map(frac, doc[0])), tuple(map(frac, doc[1]))))
    return out


def _part(part):
    from . import Scene

    scene = Scene.load(part) if isinstance(part, (str, os.PathLike)) else part
    if isinstance(scene, dict):
        scene = Scene.from_dict(scene)
    if not isinstance(scene, Scene):
        raise TypeError(f"part: expected a fixel.Scene, a scene dict or a path, not {type(part).__name__}")
    return scene


def _connect(address, timeout):
    from dask.distributed import Client

    try:
        return Client(address, timeout=timeout)
    except (OSError, TimeoutError) as e:
        raise InputError.make(
            "client", str(address), f"is unreachable: no Dask scheduler answered within {timeout} s ({e})"
        ) from e


def _run_batch(scene_dict, candidates, options, first, count, fail_once=None):
    """One batch of triples (runs on a Dask worker). Pure: the same
    arguments give the same result, so a retry after a lost worker is safe.
    `fail_once` (tests only) is a file path: the first call that finds it
    missing creates it and raises, as a worker that dies mid-batch would."""
    if fail_once is not None and not os.path.exists(fail_once):
        with open(fail_once, "w") as f:
            f.write("failed once\n")
        raise RuntimeError(f"injected failure in the batch at triple {first}")
    from . import Scene

    scene = Scene.from_dict(scene_dict)
    layouts, counts = _fixel.design_batch(scene._impl, candidates, options, first, count)
    return {"first": first, "count": count, "layouts": [list(l) for l in layouts], "counts": list(counts)}


def _run_key(scene_dict, candidates, options):
    # Neither the threads nor the bound (unused by batches) change a batch's answer.
    skip = ("jobs", "bound")
    blob = json.dumps([scene_dict, candidates, {k: v for k, v in options.items() if k not in skip}], sort_keys=True)
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def _read_finished(output, key):
    finished = {}
    if output is None or not os.path.exists(output):
        return finished
    with open(output) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            try:
                rec = json.loads(line)
            except json.JSONDecodeError:
                continue  # a line cut short by a crash: that batch runs again
            if rec.get("run") == key:
                finished[rec["batch"]] = rec
    return finished


def design(
    part,
    candidates="boundary",
    spacing=None,
    push="sustained",
    mu=None,
    pusher_mu=None,
    top=5,
    jobs=None,
    gap=0,
    resolution="1/256",
    client=None,
    batch_size=64,
    output=None,
    progress=False,
    retries=2,
    timeout=10,
    exhaustive=False,
    _fail_once=None,
):
    """The best `top` layouts of three fixels for `part` (a Scene, a scene
    dict or a path; its fixels are ignored except for the default mu).

    candidates: "boundary" (every `spacing` of arc length; 24 without one),
    a candidate file path, or a list of (curve, u). push: "sustained" or
    "step" (the ranking score). mu: a number or (lo, hi); default the
    scene's largest fixel mu, else 1/10. jobs: threads of the C++ pool
    (default one per core). client: a dask.distributed.Client or a scheduler
    address: batches of `batch_size` triples are mapped over the cluster
    with `retries`; `output` (a .jsonl path) records each finished batch and
    a rerun with the same file skips those; `progress=True` shows Dask's
    progress bar. exhaustive: score every triple on the thread pool
    (default: in order of the pair bound, stopping when no triple left can
    enter the top; the same layouts, docs/design.md). The cluster always
    scores every triple. Returns a `Design`.
    """
    scene = _part(part)
    options = _options(scene, push, resolution, mu, pusher_mu, gap, top, jobs, exhaustive)
    _fixel.design_check_options(scene._impl, options)
    cands = _candidates(scene, candidates, spacing)
    if client is None:
        return _design_of(json.loads(_fixel.design_json(scene._impl, cands, options)))
    if not isinstance(batch_size, int) or batch_size <= 0:
        raise InputError.make("batch_size", repr(batch_size), "must be a positive int")
    if isinstance(client, str):
        client = _connect(client, timeout)
    return _design_dask(scene, cands, options, client, batch_size, output, progress, retries, _fail_once)


def _design_dask(scene, cands, options, client, batch_size, output, progress, retries, fail_once):
    start = time.perf_counter()
    scene_dict = scene.to_dict()
    total = _fixel.design_triples(len(cands))
    key = _run_key(scene_dict, cands, options)
    finished = _read_finished(output, key)
    batches = [(b, first, min(batch_size, total - first)) for b, first in enumerate(range(0, total, batch_size))]
    todo = [b for b in batches if b[0] not in finished]
    futures = {}
    if todo:
        fail = fail_once if isinstance(fail_once, tuple) else None
        nonce = uuid.uuid4().hex[:8]
        futures_list = client.map(
            _run_batch,
            [scene_dict] * len(todo),
            [cands] * len(todo),
            [options] * len(todo),
            [first for _, first, _ in todo],
            [count for _, _, count in todo],
            [fail[1] if fail and fail[0] == b else None for b, _, _ in todo],
            # A fresh suffix per call: a rerun must not meet an erred task the
            # scheduler still remembers under the same key.
            key=[f"fixel-design-{key}-{b}-{nonce}" for b, _, _ in todo],
            retries=retries,
            pure=False,
        )
        futures = {f.key: (b, f) for (b, _, _), f in zip(todo, futures_list)}
    bar = None
    if progress and futures:
        from dask.distributed import progress as dask_progress

        bar = threading.Thread(target=dask_progress, args=(list(f for _, f in futures.values()),), daemon=True)
        bar.start()
    errors = []
    if futures:
        from dask.distributed import as_completed

        sink = open(output, "a") if output is not None else None
        try:
            for f in as_completed([f for _, f in futures.values()]):
                b = futures[f.key][0]
                if f.status != "finished":
                    errors.append((b, f.exception()))
                    continue
                rec = dict(f.result(), run=key, batch=b)
                finished[b] = rec
                if sink is not None:
                    sink.write(json.dumps(rec) + "\n")
                    sink.flush()
        finally:
            if sink is not None:
                sink.close()
    if bar is not None:
        bar.join(timeout=5)
    if errors:
        b, e = errors[0]
        where = f"; {len(finished)} finished batches are in {output}: rerun with it to resume" if output else ""
        raise Error(f"design: {len(errors)} batch(es) failed after {retries} retries (first: batch {b}: {e}){where}")
    counts = [0, 0, 0, 0]
    layouts = []
    for rec in finished.values():
        for k in range(4):
            counts[k] += rec["counts"][k]
        layouts.extend(rec["layouts"])
    # Best first: higher score, then lower triple index (as the C++ pool).
    layouts.sort(key=lambda l: (-Fraction(l[4]), l[3]))
    indices = [l[3] for l in layouts[: options["top"]]]
    seconds = time.perf_counter() - start
    workers = len(client.scheduler_info().get("workers", {}))
    doc = json.loads(_fixel.design_report(scene._impl, cands, options, indices, counts, seconds, workers))
    doc["stats"]["batches"] = len(batches)
    doc["stats"]["batches_resumed"] = len(batches) - len(todo)
    return _design_of(doc)
