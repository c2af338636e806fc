"""The pushing region: exact result objects and progress reporting."""

import dataclasses
import json
import time
from dataclasses import dataclass, field
from fractions import Fraction
from typing import Optional, Tuple

from . import _fixel
from ._exact import engine_settings, frac, parse, text, whole
from ._worker import seconds_limit, stoppable
from .errors import InputError


@dataclass(frozen=True)
class Magnitudes:
    """Push magnitudes |p| (N·s): from lo to hi (None = +∞), ends open or closed."""

    lo: Fraction
    lo_closed: bool
    hi: Optional[Fraction]
    hi_closed: bool

    @property
    def half_line(self):
        """Whether every magnitude from lo on seats the part (hi is +∞)."""
        return self.hi is None

    def contains(self, x):
        """Whether the magnitude x (exact) is in the range, ends as closed or open."""
        x = parse(x, "x")
        above = x > self.lo or (self.lo_closed and x == self.lo)
        below = self.hi is None or x < self.hi or (self.hi_closed and x == self.hi)
        return above and below

    @classmethod
    def _of(cls, t):
        if t is None:
            return None
        lo, lo_closed, hi, hi_closed = t
        return cls(frac(lo), lo_closed, None if hi is None else frac(hi), hi_closed)


@dataclass(frozen=True)
class AlgebraicEnd:
    """An irrational end of the exact region (``region(..., exact=True)``):
    the only root of ``poly`` (integer coefficients c0, c1, ...) in the
    rational interval ``isolating``; ``approx`` is for display only."""

    poly: Tuple[int, ...]
    isolating: Tuple[Fraction, Fraction]
    approx: float

    @classmethod
    def _of(cls, t):
        if t is None:
            return None
        poly, (lo, hi), approx = t
        return cls(tuple(int(frac(c)) for c in poly), (frac(lo), frac(hi)), approx)


@dataclass(frozen=True)
class RegionInterval:
    """A stretch [u0, u1] of curve ``curve`` with status "in", "out" or "partial".

    In an exact region an irrational end is ``exact_u0`` / ``exact_u1``
    (an AlgebraicEnd); ``u0`` / ``u1`` then hold a rational inside its
    isolating interval."""

    curve: int
    u0: Fraction
    u1: Fraction
    status: str
    half_line: bool
    magnitudes: Optional[Magnitudes]  # IN only, as in `fixel region --json`
    magnitude_set: Tuple[Optional[Magnitudes], ...] = ()  # with a guaranteed set
    exact_u0: Optional[AlgebraicEnd] = None
    exact_u1: Optional[AlgebraicEnd] = None


@dataclass(frozen=True)
class RegionStats:
    cone_tests: int
    lp_tests: int
    point_tests: int
    depth: int
    partial_length: Fraction
    seconds: float  # wall time, display only
    roots: int = 0  # exact region (exact=True): real roots isolated in the pieces' interiors


@dataclass(eq=False, repr=False)
class Region:
    """The intervals tile every curve's parameter range, in order. A status
    holds at every point of its interval, ends included, except at an end
    listed in ``corners`` (``(curve, u, status)``): there the corner's own
    status holds for its whole fan of pushes, the interval's only for its own
    edge's normal. (With ``exact=True`` a status holds strictly between the
    ends.)"""

    scene: object
    seating: object
    intervals: list
    stats: RegionStats
    cone: str
    resolution: Optional[Fraction]
    pusher_mu: Fraction
    _impl: object = field(repr=False)
    resolution_length: Optional[Fraction] = None  # with region(resolution_length=L): L (m); resolution is then None
    guaranteed: object = field(default=None, repr=False)  # the GuaranteedSet classified against, if any
    corners: list = field(default_factory=list)  # (curve, u, status): corners whose status an interval ending there lacks

    def __copy__(self):
        # copy.copy goes through __reduce__ otherwise: a shallow copy shares
        # the C++ region, as the original's fields do.
        return dataclasses.replace(self)

    def __reduce__(self):
        # Unpickling by recomputation, as S, G and J do, would redo the whole
        # region in the receiving process (a pool's parent, say): refused.
        raise TypeError(
            "a fixel.Region does not pickle (its exact data lives in the C++ core): return region.to_json() "
            "from a worker process, or pass the scene and arguments and call fixel.region there"
        )

    def __repr__(self):
        # Short: a sampled region can hold tens of thousands of intervals.
        c = self.counts()
        return (
            f"<fixel.Region of {self.scene.name!r}: {len(self.intervals)} intervals "
            f"(in {c['in']}, out {c['out']}, partial {c['partial']}), {len(self.corners)} corners listed>"
        )

    @property
    def meaning(self):
        """What IN means here, naming the model, as every report says it
        (e.g. "one-step: can seat", "sustained push: seats and stays")."""
        return self._impl.meaning

    def counts(self):
        """Number of intervals per status: {"in": .., "out": .., "partial": ..}."""
        out = {"in": 0, "out": 0, "partial": 0}
        for r in self.intervals:
            out[r.status] += 1
        return out

    def lengths(self):
        """Total parameter length per status (exact)."""
        out = {"in": Fraction(0), "out": Fraction(0), "partial": Fraction(0)}
        for r in self.intervals:
            out[r.status] += r.u1 - r.u0
        return out

    def validate(
        self, pushes, time=20, max_seconds=None, steps_per_h=1000, velocity_iterations=20, position_iterations=10
    ):
        """The Box2D check of ``fixel region --json --validate N --time T``
        (docs/physics.md): ``pushes`` pushes at seeded pseudo-random points
        of every IN interval, each held for ``time`` time steps h, and the
        region's document with "validation" added, as a dict (per IN
        interval {"pushes", "seated", ...}, and the total with the seed and
        the model). A measurement, not a decision: the region's statuses are
        unchanged. The one-step push uses each interval's certified
        magnitudes (so not an ``exact=True`` region), the sustained push the
        unit wrench at the seat. ``steps_per_h``, ``velocity_iterations`` and
        ``position_iterations`` set the engine's accuracy as in
        :func:`fixel.push`. ``max_seconds`` and Ctrl-C as in region."""
        from . import SeatingSet, SustainedSet

        pushes = whole(pushes, "pushes")
        if not 1 <= pushes <= 2**31 - 1:
            raise InputError.make("pushes", str(pushes), "must be 1 to 2147483647")
        if not isinstance(self.seating, (SeatingSet, SustainedSet)):
            raise TypeError(f"region.seating: {type(self.seating).__name__} is neither a SeatingSet nor a SustainedSet")
        t = text(time, "time")
        e = engine_settings(steps_per_h, velocity_iterations, position_iterations)
        doc = stoppable(
            lambda c: _fixel.validate_region_json(self.scene._impl, self._impl, self.seating._impl, pushes, t, *e, c),
            max_seconds,
        )
        return json.loads(doc)

    def to_json(self):
        """The document of `fixel region --json` (same C++ writer)."""
        from . import SustainedSet

        J = self.seating._impl if isinstance(self.seating, SustainedSet) else None
        doc = _fixel.region_json(self.scene._impl, self._impl, J)
        return json.loads(doc)


def _pusher_mu(pusher_mu):
    """The pusher μ as exact text, or None: one number, or (lo, hi) judged at
    hi as the CLI's ``--pusher-mu lo,hi`` (the region shrinks as μ grows)."""
    if pusher_mu is None:
        return None
    if isinstance(pusher_mu, (list, tuple)):
        if len(pusher_mu) != 2:
            raise InputError.make("pusher_mu", repr(pusher_mu), "must be one number or (lo, hi)")
        lo, hi = (_fixel.parse_rational(text(x, "pusher_mu"), "pusher_mu") for x in pusher_mu)
        if frac(hi) < frac(lo):
            raise InputError.make("pusher_mu", f"({lo}, {hi})", "has lo > hi")
        if frac(lo) < 0:
            raise InputError.make("pusher_mu", f"({lo}, {hi})", "must be >= 0")
        return hi
    return text(pusher_mu, "pusher_mu")


def _region_of(scene, S, impl, cone, resolution, pusher_mu):
    intervals = [
        RegionInterval(
            d["curve"], frac(d["u0"]), frac(d["u1"]), d["status"], d["half_line"],
            Magnitudes._of(d["magnitudes"]), tuple(Magnitudes._of(m) for m in d["magnitude_set"]),
            AlgebraicEnd._of(d["exact_u0"]), AlgebraicEnd._of(d["exact_u1"]),
        )
        for d in impl.intervals
    ]  # fmt: skip
    s = impl.stats
    stats = RegionStats(
        s["cone_tests"], s["lp_tests"], s["point_tests"], s["depth"], frac(s["partial_length"]), s["seconds"],
        s["roots"],
    )  # fmt: skip
    mu = frac(impl.pusher_mu)  # the friction the region was computed with (an interval's upper end)
    corners = [(c, frac(u), status) for c, u, status in impl.corners]
    return Region(scene, S, intervals, stats, cone, resolution, mu, impl, corners=corners)


class _TqdmProgress:
    """progress=True: a tqdm bar of elapsed seconds, shown only after ~1 s."""

    def __init__(self, description):
        self.description = description
        self.bar = None
        self.shown = 0.0

    def __call__(self, stage, elapsed):
        from tqdm import tqdm  # imported only when asked for

        if self.bar is None:
            fmt = "{desc}: {elapsed} elapsed{postfix}"
            self.bar = tqdm(total=None, desc=self.description, delay=1.0, bar_format=fmt, leave=False)
        self.bar.update(elapsed - self.shown)
        self.shown = elapsed
        if stage == "done":
            self.bar.close()


def _run(work, progress, description, max_seconds=None, interval=0.1):
    """Runs ``work(control)`` (a C++ call that releases the GIL and polls
    ``control``) in a worker thread: past ``max_seconds`` it stops with
    StoppedError, and Ctrl-C stops it and raises KeyboardInterrupt
    (fixel/_worker.py).

    The callback is told ("start", 0.0), then ("running", elapsed_seconds)
    every ``interval`` seconds while the core computes, then ("done",
    total), also when the run stops early.
    """
    if progress is None or progress is False:
        return stoppable(work, max_seconds, None, interval)
    callback = _TqdmProgress(description) if progress is True else progress
    if not callable(callback):
        raise TypeError(f"progress: {progress!r} is neither a callable, True nor None")
    seconds_limit(max_seconds)  # before "start"
    start = time.perf_counter()
    callback("start", 0.0)
    try:
        tick = lambda control: callback("running", time.perf_counter() - start)  # noqa: E731
        return stoppable(work, max_seconds, tick, interval)
    finally:
        callback("done", time.perf_counter() - start)


def _guaranteed_of(guaranteed, scene, S):
    """The GuaranteedSet asked for (None, False, True or one given), or None."""
    from . import GuaranteedSet, guaranteed_set

    if guaranteed is None or guaranteed is False:
        return None
    if guaranteed is True:
        return guaranteed_set(scene, S)
    if not isinstance(guaranteed, GuaranteedSet):
        raise TypeError(f"guaranteed: {guaranteed!r} is neither True, False, None nor a fixel.GuaranteedSet")
    return guaranteed


def region(
    scene, resolution=None, cone="tight", pusher_mu=None, push="step", guaranteed=None, seating=None,
    progress=None, exact=False, digits=0, resolution_length=None, max_seconds=None, approach=False,
):  # fmt: skip
    """The pushing region by exact recursive subdivision (``fixel region``).

    ``resolution``: stop splitting at this curve-parameter width (exact;
    None is 1/1024; not with ``exact``, which has none).
    ``resolution_length``: a length L (m) instead (``--resolution-length``):
    each Bézier piece stops at its own parameter width, so that every stretch
    left is at most L long (docs/cli.md); ``resolution`` must then be None.
    ``cone``: "tight" or "paper". ``pusher_mu``: overrides the scene's (one number, or (lo, hi) judged at hi).
    ``push``: "step" (one impulse, against S) or "sustained" (a held wrench,
    against the sustained-push set J at the seated pose; ``seating`` is then
    the SustainedSet and IN intervals carry no magnitudes).
    ``approach``: with push="sustained", True (or an ApproachSet) classifies
    against the approach-aware set J' (``--approach``, docs/theory.md §10.7):
    exact IN and OUT, a wider partial band; not with ``exact``.
    ``guaranteed``: True, or a GuaranteedSet, classifies against G instead of S.
    ``progress``: None, True (tqdm bar after ~1 s) or callable(stage, elapsed).
    ``exact``: root isolation instead of subdivision (``fixel region --exact``):
    no partial stretch, irrational ends as AlgebraicEnd; ``digits`` refines
    their isolating intervals to width 10**-digits. Not with ``guaranteed``.
    ``max_seconds``: stop the run after that many seconds with StoppedError
    (``--max-seconds``). Ctrl-C stops it too and raises KeyboardInterrupt.
    """
    from . import _scene

    scene = _scene(scene)
    if push not in ("step", "sustained"):
        raise InputError.make("push", repr(push), "is not a push model (step or sustained)")
    if cone not in ("tight", "paper"):
        raise InputError.make("cone", repr(cone), "is not a cone method (tight or paper)")
    # Root isolation uses neither: refused, not ignored (as the CLI does).
    if exact and resolution is not None:
        raise InputError.make(
            "resolution", str(resolution), "cannot be combined with exact=True (root isolation has no resolution)"
        )
    if exact and cone != "tight":
        raise InputError.make(
            "cone", repr(cone), "cannot be combined with exact=True (root isolation builds no segment cones)"
        )
    # Read by the core first, so that bad text is its ParseError naming the argument.
    res = _fixel.parse_rational(text("1/1024" if resolution is None else resolution, "resolution"), "resolution")
    res_len = None
    if resolution_length is not None:
        res_len = _fixel.parse_rational(text(resolution_length, "resolution_length"), "resolution_length")
    if res_len is not None and exact:
        raise InputError.make("resolution_length", res_len, "cannot be combined with exact=True")
    if res_len is not None and resolution is not None:  # refused, not ignored, as --resolution-length is
        raise InputError.make(
            "resolution", str(resolution), "cannot be combined with resolution_length (each piece gets its own width)"
        )
    shown = None if exact or res_len is not None else frac(res)
    mu = _pusher_mu(pusher_mu)
    if not isinstance(exact, bool):
        raise TypeError(f"exact: {exact!r} is not a bool")
    digits = whole(digits, "digits")
    if digits != 0 and not exact:
        raise InputError.make("digits", str(digits), "needs exact=True (it refines the exact region's ends)")
    if push == "sustained":
        from . import ApproachSet, SustainedSet, _same_scene

        if guaranteed is not None and guaranteed is not False:
            raise InputError.make("guaranteed", repr(guaranteed), "cannot be combined with push='sustained'")
        if seating is not None:
            if not isinstance(seating, SustainedSet):
                raise TypeError(
                    f"seating: with push='sustained' it is the sustained-push set, a fixel.SustainedSet "
                    f"(fixel.sustained_set(scene)), not {type(seating).__name__}"
                )
            _same_scene(seating.scene, scene, "seating")
        if isinstance(approach, ApproachSet):
            _same_scene(approach.scene, scene, "approach")
            if seating is not None and approach.J is not seating:
                raise InputError.make("seating", repr(seating), "is not the SustainedSet the ApproachSet refines")
            A, J = approach, approach.J
        elif approach is True or approach is False or approach is None:
            A, J = None, seating
        else:
            raise InputError.make("approach", repr(approach), "is not True, False or an ApproachSet")
        build_a = approach is True

        # J and J' not given are built in the same run as the region, under
        # its max_seconds and Ctrl-C (each is one long exact step on numbers
        # of thousands of digits).
        def work(c):
            j = J._impl if J is not None else _fixel.sustained_set(scene._impl, c)
            a = A._impl if A is not None else (_fixel.approach_set(scene._impl, j, c) if build_a else None)
            return j, a, _fixel.compute_region_sustained(scene._impl, j, res, cone, mu, exact, digits, res_len, a, c)

        j, _, impl = _run(work, progress, "fixel.region", max_seconds)
        if J is None:
            J = SustainedSet(scene, j)
        r = _region_of(scene, J, impl, cone, shown, None if mu is None else frac(mu))
        r.resolution_length = None if res_len is None else frac(res_len)
        return r
    if approach not in (False, None):
        raise InputError.make("approach", repr(approach), "needs push='sustained' (J' refines J)")
    S = _seating_for(seating, guaranteed, scene)
    G = _guaranteed_of(guaranteed, scene, S)
    g = None if G is None else G._impl
    impl = _run(
        lambda c: _fixel.compute_region(scene._impl, S._impl, res, cone, mu, g, exact, digits, res_len, c),
        progress, "fixel.region", max_seconds,
    )  # fmt: skip
    r = _region_of(scene, S, impl, cone, shown, None if mu is None else frac(mu))
    r.resolution_length = None if res_len is None else frac(res_len)
    r.guaranteed = G
    return r


def _seating_for(seating, guaranteed, scene):
    """The S a one-step question is asked of: ``seating``, else the one a
    given GuaranteedSet was built from (G is checked against S), else S of
    the scene."""
    from . import GuaranteedSet, SeatingSet, _expect, _same_scene, seating_set

    if seating is not None:
        _expect(seating, SeatingSet, "seating")
        _same_scene(seating.scene, scene, "seating")
        return seating
    if isinstance(guaranteed, GuaranteedSet):
        _same_scene(guaranteed.seating.scene, scene, "guaranteed")
        return guaranteed.seating
    return seating_set(scene)


def sample(scene, points, pusher_mu=None, guaranteed=None, seating=None, max_seconds=None):
    """The point-sampling baseline (``fixel sample``): ``points`` per curve.
    ``max_seconds`` and Ctrl-C stop it as in region."""
    from . import _scene

    scene = _scene(scene)
    points = whole(points, "points")
    mu = _pusher_mu(pusher_mu)
    S = _seating_for(seating, guaranteed, scene)
    G = _guaranteed_of(guaranteed, scene, S)
    g = None if G is None else G._impl
    impl = stoppable(lambda c: _fixel.sample_region(scene._impl, S._impl, points, mu, g, c), max_seconds)
    r = _region_of(scene, S, impl, "sample", None, None if mu is None else frac(mu))
    r.guaranteed = G
    return r
