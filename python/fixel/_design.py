"""Fixture design (docs/design.md): the best three fixels for one push.

``fixel.design(part, ...)`` runs on the C++ oneTBB thread pool, or, with
``client=`` a ``dask.distributed.Client`` (or a scheduler address), maps
batches of triples over a Dask cluster, in rounds in the order of the pair
bound (or, exhaustive, every triple). Exact results travel as strings and
come back as ``Fraction``; a batch is a pure function of its arguments, so
Dask's retries recompute a lost one, and a JSON-lines ``output`` file lets a
rerun skip the batches that already finished.
"""

import errno
import hashlib
import json
import math
import numbers
import os
import time
import uuid
from dataclasses import dataclass
from fractions import Fraction
from typing import List, Optional, Tuple

from . import _fixel
from ._exact import frac, text, whole
from ._worker import seconds_limit, stoppable
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
    # The smallest singular value of W_n (moment over the radius of gyration),
    # display only; nearly_singular: below fixel's warning level (docs/design.md).
    conditioning: Optional[float] = None
    nearly_singular: Optional[bool] = None
    # Contacts on curved pieces (degree above 1): a nearly singular layout is
    # warned of only with one (docs/design.md).
    curved_contacts: Optional[int] = None
    # With a gap: why the one-step scene has no seated pose (None if it has one).
    step_seat: Optional[str] = None


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
            conditioning=l["conditioning"],
            nearly_singular=l["nearly_singular"],
            curved_contacts=l["curved_contacts"],
            step_seat=l["step_seat"],
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
        flat = [frac(m[-1] if isinstance(m, list) else m) for m in mus]
        mu = max(flat) if flat else Fraction(1, 10)
    lo, hi = _mu_pair(mu, "mu")
    if pusher_mu is None:
        pusher_mu = scene.to_dict().get("pusher", {}).get("mu", "0")
    # Judged at the upper end; the lower end goes into a layout's scene.
    plo, phi = _mu_pair(pusher_mu, "pusher_mu")
    pusher_mu, pusher_mu_lo = (phi, plo) if phi is not None else (plo, None)
    top = whole(top, "top")
    jobs = None if jobs is None else whole(jobs, "jobs")
    if not isinstance(exhaustive, bool):
        raise TypeError(f"exhaustive: {exhaustive!r} is not a bool")
    return {
        "push": str(push),
        "resolution": text(resolution, "resolution"),
        "mu": lo,
        "mu_hi": hi,
        "pusher_mu": text(pusher_mu, "pusher_mu"),
        "pusher_mu_lo": pusher_mu_lo,
        "gap": text(gap, "gap"),
        "top": top,
        "jobs": 0 if jobs is None else jobs,
        "bound": not exhaustive,
    }


def _candidates(scene, candidates, spacing):
    if isinstance(candidates, str) and candidates == "boundary":
        return _fixel.design_candidates(scene._impl, None if spacing is None else text(spacing, "spacing"))
    if isinstance(candidates, (str, os.PathLike)):
        path = os.fspath(candidates)
        if not os.path.exists(path):  # a typo of "boundary" too: say how the string was read
            raise InputError.make(
                "candidates",
                os.fsdecode(path),
                f'is not "boundary", so it is read as a candidate file path, which cannot be opened: '
                f"{os.strerror(errno.ENOENT)}",
            )
        return _fixel.design_load_candidates(scene._impl, path)
    if not hasattr(candidates, "__iter__") or isinstance(candidates, (bytes, dict)):
        raise TypeError(
            f"candidates: {candidates!r} is neither 'boundary', a file path nor a list of (curve, u) pairs"
        )
    pairs = []
    for i, c in enumerate(candidates):
        field = f"candidates[{i}]"
        if isinstance(c, dict):
            missing = [k for k in ("curve", "u") if k not in c]
            if missing:
                raise InputError.make(field, repr(c), f"has no {missing[0]!r} (a candidate is {{'curve': k, 'u': u}})")
            c = (c["curve"], c["u"])
        if isinstance(c, (str, bytes)) or not isinstance(c, (tuple, list)) or len(c) != 2:
            raise InputError.make(field, repr(c), "is not a (curve, u) pair")
        curve, u = c
        pairs.append((whole(curve, f"{field}.curve"), text(u, f"{field}.u")))
    return _fixel.design_check_candidates(scene._impl, pairs)


def design_candidates(part, candidates="boundary", spacing=None):
    """The candidates fixel.design would use, as `Candidate`s (exact)."""
    scene = _part(part)
    out = []
    for curve, u in _candidates(scene, candidates, spacing):
        doc = _fixel.design_candidate(scene._impl, curve, u)
        out.append(Candidate(curve, frac(u), tuple(map(frac, doc[0])), tuple(map(frac, doc[1]))))
    return out


def design_scene(part, design, rank=1):
    """Layout `rank` (1 = best) of `design` (fixel.design's answer for
    `part`) as a fixel.Scene, as `fixel design --scene-out` writes it: the
    part with the layout's three fixels, as the ranking push model scored
    them (sustained: gap 0, the design's mu and pusher mu, exact unit
    normals; a normal of irrational length is rounded to a rational unit
    vector and its fixel marked off_boundary, which the description says).
    Analyse it with fixel.region, push or push_plan, or save it with
    Scene.save. InputError when `design` has no layout `rank`."""
    if not isinstance(design, Design):
        raise TypeError(f"design: expected the fixel.Design that fixel.design returned, not {type(design).__name__}")
    rank = whole(rank, "rank")
    count = len(design.layouts)
    if not 1 <= rank <= count:
        why = f"the design has no layout ({design.no_layout})" if count == 0 else f"must be 1 to {count}"
        raise InputError.make("rank", str(rank), why)
    scene = _part(part)
    doc = design.document
    lo, hi = _mu_pair(doc["mu"], "mu")
    plo, phi = _mu_pair(doc["pusher_mu"], "pusher_mu")
    options = {
        "push": doc["push"],
        "resolution": doc["resolution"],
        "mu": lo,
        "mu_hi": hi,
        "pusher_mu": phi if phi is not None else plo,
        "pusher_mu_lo": plo if phi is not None else None,
        "gap": doc["gap"],
    }
    layout = design.layouts[rank - 1]
    three = [(c.curve, text(c.u, "u")) for c in layout.fixels]
    # The design's exact points must be this part's: another part with the
    # same parameter ranges would give a scene the score does not describe.
    for k, c in enumerate(layout.fixels):
        try:
            point = tuple(map(frac, _fixel.design_candidate(scene._impl, c.curve, text(c.u, "u"))[0]))
        except Error as e:
            raise InputError.make("part", scene.name, f"is not the part of this design: its fixel {k} ({e})") from None
        if point != c.point:
            raise InputError.make(
                "part",
                scene.name,
                f"is not the part of this design: its fixel {k} (curve {c.curve}, u = {c.u}) is at "
                f"({point[0]}, {point[1]}) on it, the design's at ({c.point[0]}, {c.point[1]})",
            )
    from . import Scene

    impl, _ = _fixel.design_scene(scene._impl, three, options, text(layout.score, "score"), rank)
    return Scene(impl)


def _part(part):
    from . import Scene

    scene = Scene.load(part) if isinstance(part, (str, os.PathLike)) else part
    if isinstance(scene, dict):
        scene = Scene.from_dict(scene)
    if not isinstance(scene, Scene):
        raise TypeError(f"part: expected a fixel.Scene, a scene dict or a path, not {type(part).__name__}")
    return scene


def _check_address(address):
    """ValueError for an address Dask cannot read (no port, an unknown
    scheme), found without making a Client: one whose start failed is
    closed again only when collected, and that can stall the interpreter's
    exit."""
    try:
        from distributed.comm import registry
        from distributed.comm.addressing import parse_address
    except ImportError:  # another layout of distributed: Client says it
        return
    scheme, loc = parse_address(address)
    try:
        registry.get_backend(scheme).get_address_host_port(loc)
    except NotImplementedError:  # not host:port (inproc://...): nothing to check
        pass


def _connect(address, timeout):
    from dask.distributed import Client

    try:
        _check_address(address)
        return Client(address, timeout=timeout)
    except (OSError, TimeoutError) as e:
        raise InputError.make(
            "client", str(address), f"is unreachable: no Dask scheduler answered within {timeout:g} s ({e})"
        ) from e
    except ValueError as e:  # no port, an unknown scheme, ...
        raise InputError.make("client", str(address), f"is not a Dask scheduler address ({e})") from e


def _cluster_arguments(client, batch_size, wave, output, retries, timeout):
    """The Dask-only arguments, checked before any work (TypeError for a
    wrong type, InputError naming the argument for a wrong value):
    (batch_size, wave, output path or None, retries, timeout in seconds)."""
    if not isinstance(client, str):
        try:
            from dask.distributed import Client
        except ImportError:  # without Dask no object is a Client
            Client = ()
        if not isinstance(client, Client):
            raise TypeError(
                f"client: {client!r} ({type(client).__name__}) is neither a dask.distributed.Client nor a "
                "scheduler address (for a cluster object, pass Client(cluster) or cluster.scheduler_address)"
            )
    batch_size, wave = whole(batch_size, "batch_size"), whole(wave, "wave")
    for name, value in (("batch_size", batch_size), ("wave", wave)):
        if value <= 0:
            raise InputError.make(name, str(value), "must be a positive int")
    retries = whole(retries, "retries")
    if retries < 0:
        raise InputError.make("retries", str(retries), "must be an int >= 0")
    if isinstance(timeout, bool) or not isinstance(timeout, numbers.Real):
        raise TypeError(f"timeout: {timeout!r} ({type(timeout).__name__}) is not a number of seconds")
    try:
        seconds = float(timeout)
    except OverflowError:  # an int or Fraction beyond doubles
        seconds = math.inf if timeout > 0 else -math.inf
    if not (0 < seconds < math.inf):
        raise InputError.make("timeout", str(timeout), "must be a positive, finite number of seconds")
    if output is not None:
        if not isinstance(output, (str, os.PathLike)):
            raise TypeError(f"output: {output!r} ({type(output).__name__}) is not a file path")
        output = os.fspath(output)
        if isinstance(output, bytes):
            output = os.fsdecode(output)
        if output == "":
            raise InputError.make("output", "''", "is not a file path")
        folder = os.path.dirname(os.path.abspath(output))
        if os.path.isdir(output):
            raise InputError.make("output", output, "is a directory, not a .jsonl file")
        if not os.path.isdir(folder):
            raise InputError.make("output", output, f"cannot be written: its directory {folder} does not exist")
        if not os.access(output if os.path.exists(output) else folder, os.W_OK):
            raise InputError.make("output", output, "cannot be written: permission denied")
    return batch_size, wave, output, retries, seconds


def _run_batch(scene_dict, candidates, options, first, count, fail_once=None, indices=None):
    """One batch of triples (runs on a Dask worker): [first, first + count),
    or the triples `indices` when given. Pure: the same arguments give the
    same result, so a retry after a lost worker is safe. `fail_once` (tests
    only) is a file path: the first call that finds it missing creates it
    and raises, as a worker that dies mid-batch would."""
    if fail_once is not None and not os.path.exists(fail_once):
        with open(fail_once, "w") as f:
            f.write("failed once\n")
        raise RuntimeError(f"injected failure in the batch at triple {first}")
    from . import Scene

    scene = Scene.from_dict(scene_dict)
    if indices is None:
        layouts, counts = _fixel.design_batch(scene._impl, candidates, options, first, count)
    else:
        layouts, counts = _fixel.design_batch_indices(scene._impl, candidates, options, indices)
    return {"first": first, "count": count, "layouts": [list(l) for l in layouts], "counts": list(counts)}


def _run_key(scene_dict, candidates, options, batch_size):
    # Neither the threads nor the bound (unused by batches) change a batch's
    # answer. The batch size does change the ranges: range batch 5 of 64
    # triples is not range batch 5 of 16 (the number is all that finds it).
    skip = ("jobs", "bound")
    settings = {k: v for k, v in options.items() if k not in skip}
    blob = json.dumps([scene_dict, candidates, settings, {"batch_size": batch_size}], sort_keys=True)
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def _record_check(rec):
    """A digest of a record without its "check": an edit that does not
    recompute it (a changed score or layout) shows when the run resumes."""
    body = {k: v for k, v in rec.items() if k != "check"}
    return hashlib.sha256(json.dumps(body, sort_keys=True).encode()).hexdigest()[:16]


def _read_finished(output, key):
    """Finished batches of run `key` in `output`: a range batch under its
    number, a batch of listed triples under the tuple of its triples."""
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
            if isinstance(rec, dict) and rec.get("run") == key:
                if "check" not in rec:
                    continue  # written before records carried a check: that batch runs again
                if rec["check"] != _record_check(rec):
                    raise InputError.make(
                        "output",
                        str(output),
                        f"holds a record of batch {rec.get('batch')!r} that was changed after fixel wrote it "
                        "(its check does not match): remove that line, or the file, and run again",
                    )
                finished[tuple(rec["triples"]) if "triples" in rec else rec.get("batch")] = rec
    return finished


def _check_resumed(output, rec, number, first, count):
    """A record of this run's key must be the batch it stands for: the same
    first triple and count (else the file was written by other settings,
    or edited, and reusing it would count triples twice or never)."""
    if rec.get("first") != first or rec.get("count") != count:
        raise InputError.make(
            "output",
            str(output),
            f"belongs to a run with other settings: its batch {number} holds {rec.get('count')!r} triples "
            f"from index {rec.get('first')!r}, this run's holds {count} from {first}; "
            "use another file, or the settings that wrote it",
        )


# Tests only: (batch number, marker path) makes that batch of the cluster
# path fail once, as a worker that dies mid-batch would (_run_batch). A
# module variable rather than an argument, so design()'s signature shows
# only what a user may pass.
_FAIL_ONCE = None


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
    wave=8,
    output=None,
    progress=False,
    retries=2,
    timeout=10,
    exhaustive=False,
    max_seconds=None,
):
    """The best `top` layouts of three fixels for `part` (a Scene, a scene
    dict or a path; its fixels are ignored except for the default mu).

    candidates: "boundary" (every `spacing` of arc length; 24 without one),
    a candidate file path, or a list of (curve, u). push: "sustained" or
    "step" (the ranking score). mu: a number or (lo, hi); default the
    scene's largest fixel mu, else 1/10. jobs: threads of the C++ pool
    (default one per core). exhaustive: score every triple (default: in
    order of the pair bound, stopping when no triple left can enter the
    top; the same layouts, docs/design.md).

    client: a dask.distributed.Client or a scheduler address: batches of
    `batch_size` triples are mapped over the cluster with `retries`. With
    the bound, this process computes the bound (on `jobs` threads) and the
    cluster scores rounds of `wave` batches in its order; without it, every
    triple in ranges of consecutive indices. `output` (a .jsonl path)
    records each finished batch and a rerun with the same file, part,
    candidates, options and `batch_size` skips those (records of other
    settings are not reused); `progress=True` shows a tqdm bar of finished
    batches. An address is connected to within `timeout` seconds, and that
    Client is closed when the call returns or raises. The cluster path
    takes no `max_seconds`, and Ctrl-C does not stop this process's bound
    computation (it takes effect when that returns). There `stats["jobs"]`
    is the cluster's worker count (docs/formats.md). Returns a `Design`.

    On the thread pool, `progress=True` shows a tqdm bar per stage (pair
    bounds, triple bounds, layouts), or a callable(task, done, total, unit)
    gets the reports; `max_seconds` stops the run with StoppedError, and
    Ctrl-C stops it and raises KeyboardInterrupt.
    """
    scene = _part(part)
    options = _options(scene, push, resolution, mu, pusher_mu, gap, top, jobs, exhaustive)
    _fixel.design_check_options(scene._impl, options)
    cands = _candidates(scene, candidates, spacing)
    seconds_limit(max_seconds)
    if client is None:
        work = lambda control: _fixel.design_json(scene._impl, cands, options, control)  # noqa: E731
        return _design_of(json.loads(_controlled(work, max_seconds, progress)))
    if max_seconds is not None:
        raise InputError.make("max_seconds", repr(max_seconds), "applies to the thread pool, not to a cluster")
    batch_size, wave, output, retries, timeout = _cluster_arguments(client, batch_size, wave, output, retries, timeout)
    if not isinstance(client, str):
        return _design_dask(scene, cands, options, client, batch_size, wave, output, progress, retries, _FAIL_ONCE)
    own = _connect(client, timeout)  # opened here, so closed here, also on an error
    try:
        return _design_dask(scene, cands, options, own, batch_size, wave, output, progress, retries, _FAIL_ONCE)
    finally:
        own.close()


class _Bar:
    """progress=True on the thread pool: a tqdm bar per stage of the run."""

    def __init__(self):
        self.bar, self.task = None, None

    def __call__(self, task, done, total, unit):
        from tqdm import tqdm  # imported only when asked for

        if task != self.task:
            if self.bar is not None:
                self.bar.close()
            self.bar = tqdm(desc=task, total=total or None, unit=unit.split()[0] if unit else "it", leave=False)
            self.task = task
        self.bar.update(done - self.bar.n)

    def close(self):
        if self.bar is not None:
            self.bar.close()


def _controlled(work, max_seconds, progress, interval=0.1):
    """Runs ``work(control)`` (a C++ call that releases the GIL and polls
    `control`) in a worker thread (fixel/_worker.py: max_seconds and Ctrl-C
    stop it); progress (True: a tqdm bar, or a callable(task, done, total,
    unit)) gets the core's reports."""
    if progress is True:
        report = _Bar()
    elif progress is None or progress is False:
        report = None
    elif callable(progress):
        report = progress
    else:
        raise TypeError(f"progress: {progress!r} is neither a callable, True nor False")
    seen = [None]

    def tick(control):
        if report is None:
            return
        snap = control.snapshot()
        if snap[0] and snap != seen[0]:
            seen[0] = snap
            report(*snap)

    try:
        return stoppable(work, max_seconds, tick, interval)
    finally:
        if isinstance(report, _Bar):
            report.close()


class _Batches:
    """Maps batches over the cluster with retries, records each finished one
    in `output` and takes those a previous run recorded."""

    def __init__(self, client, scene_dict, cands, options, key, output, progress, retries, fail_once):
        self.client, self.scene_dict, self.cands, self.options = client, scene_dict, cands, options
        self.key, self.output, self.retries = key, output, retries
        self.fail = fail_once if isinstance(fail_once, tuple) else None
        self.finished = _read_finished(output, key)
        self.nonce = uuid.uuid4().hex[:8]
        self.batches = self.resumed = 0
        self.bar = None
        if progress:
            from tqdm import tqdm  # imported only when asked for

            self.bar = tqdm(desc="design: batches", unit="batch", leave=False)

    def run(self, specs):
        """specs: [(number, first, count, triples or None)]. Returns their
        records in that order; raises Error when one failed after its retries."""
        records, todo = {}, []
        for number, first, count, triples in specs:
            self.batches += 1
            rec = self.finished.get(number if triples is None else tuple(triples))
            if rec is not None:
                _check_resumed(self.output, rec, number, first, count)
                records[number] = rec
                self.resumed += 1
            else:
                todo.append((number, first, count, triples))
        errors = []
        if todo:
            futures = self.client.map(
                _run_batch,
                [self.scene_dict] * len(todo),
                [self.cands] * len(todo),
                [self.options] * len(todo),
                [first for _, first, _, _ in todo],
                [count for _, _, count, _ in todo],
                [self.fail[1] if self.fail and self.fail[0] == b else None for b, _, _, _ in todo],
                [triples for _, _, _, triples in todo],
                # A fresh suffix per call: a rerun must not meet an erred task the
                # scheduler still remembers under the same key.
                # Ranges and blocks of listed triples are numbered apart.
                key=[f"fixel-design-{self.key}-{'r' if t is None else 't'}{b}-{self.nonce}" for b, _, _, t in todo],
                retries=self.retries,
                pure=False,
            )
            spec_of = {f.key: t for t, f in zip(todo, futures)}
            from dask.distributed import as_completed

            sink = open(self.output, "a") if self.output is not None else None
            try:
                for f in as_completed(futures):
                    number, _, _, triples = spec_of[f.key]
                    if f.status != "finished":
                        errors.append((number, f.exception()))
                        continue
                    rec = dict(f.result(), run=self.key, batch=number)
                    if triples is not None:
                        rec["triples"] = list(triples)
                    rec["check"] = _record_check(rec)
                    records[number] = rec
                    if sink is not None:
                        sink.write(json.dumps(rec) + "\n")
                        sink.flush()
                    if self.bar is not None:
                        self.bar.update(1)
            finally:
                if sink is not None:
                    sink.close()
        if errors:
            b, e = errors[0]
            where = (
                f"; {self.batches - len(errors)} finished batches are in {self.output}: rerun with it to resume"
                if self.output
                else ""
            )
            raise Error(f"design: {len(errors)} batch(es) failed after {self.retries} retries (first: batch {b}: {e}){where}")
        return [records[number] for number, _, _, _ in specs]

    def close(self):
        if self.bar is not None:
            self.bar.close()


_MAX_RANGES = 10_000_000  # range batches mapped at once when every triple is scored


def _merge(records, top, counts, k):
    """Adds the batches' counts and keeps the best k layouts, best first:
    higher score, then lower triple index (as the C++ pool)."""
    for rec in records:
        for i in range(4):
            counts[i] += rec["counts"][i]
        top.extend(rec["layouts"])
    top.sort(key=lambda l: (-frac(l[4]), l[3]))
    del top[k:]


def _bounded(search, batches, options, batch_size, wave, total):
    """The bounded search (docs/design.md): the pilot, then rounds of `wave`
    blocks of `batch_size` triples in order of their pair bound, each asked
    for with the best K known before the round. None when the pilot scores
    nothing above 0 (then every triple is scored, as on the thread pool)."""
    top, counts = [], [0, 0, 0, 0]
    pilot = list(search.pilot())
    _merge(batches.run([(0, pilot[0], len(pilot), pilot)]), top, counts, options["top"])
    if not search.start([(l[3], l[4]) for l in top]):
        return None
    counts[0] += search.singular()
    number, rounds, over = 1, 0, False
    while not over:
        blocks = []
        for _ in range(wave):
            chosen = search.next([(l[3], l[4]) for l in top], batch_size)
            if chosen is None:
                over = True
                break
            if chosen:
                blocks.append(chosen)
        if blocks:
            rounds += 1
            specs = [(number + i, b[0], len(b), b) for i, b in enumerate(blocks)]
            number += len(blocks)
            _merge(batches.run(specs), top, counts, options["top"])
    return top, counts + [total - sum(counts)], rounds


def _design_dask(scene, cands, options, client, batch_size, wave, output, progress, retries, fail_once):
    start = time.perf_counter()
    scene_dict = scene.to_dict()
    total = _fixel.design_triples(len(cands))
    key = _run_key(scene_dict, cands, options, batch_size)
    batches = _Batches(client, scene_dict, cands, options, key, output, progress, retries, fail_once)
    try:
        search = _fixel.DesignSearch(scene._impl, cands, options)
        found = _bounded(search, batches, options, batch_size, wave, total) if search.applies() else None
        rounds = 0
        if found is None:  # every triple, in ranges of consecutive indices
            if -(-total // batch_size) > _MAX_RANGES:
                raise InputError.make(
                    "batch_size",
                    repr(batch_size),
                    f"cuts the {total} triples into more than {_MAX_RANGES} batches: raise it",
                )
            top, counts = [], [0, 0, 0, 0]
            specs = [(b, first, min(batch_size, total - first), None) for b, first in enumerate(range(0, total, batch_size))]
            _merge(batches.run(specs), top, counts, options["top"])
            counts.append(0)
        else:
            top, counts, rounds = found
    finally:
        batches.close()
    seconds = time.perf_counter() - start
    workers = len(client.scheduler_info().get("workers", {}))
    doc = json.loads(_fixel.design_report(scene._impl, cands, options, [l[3] for l in top], counts, seconds, workers))
    # The report scores the chosen triples again: a recorded score that
    # differs (an edited or foreign output file) could have displaced a
    # layout that belongs in the top K, so it is refused, not trusted.
    rescored = {l["index"]: frac(l["score"]) for l in doc["layouts"]}
    for l in top:
        if rescored.get(l[3]) != frac(l[4]):
            raise InputError.make(
                "output",
                str(output),
                f"records triple {l[3]} with score {l[4]}, but it scores {rescored.get(l[3])}: the file was edited "
                "or written by another version of fixel; remove it (or name another output) and run again",
            )
    doc["stats"]["batches"] = batches.batches
    doc["stats"]["batches_resumed"] = batches.resumed
    doc["stats"]["rounds"] = rounds
    return _design_of(doc)
