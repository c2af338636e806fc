"""fixel from Python: exact seating sets, outcomes and pushing regions.

Every exact value comes out as ``fractions.Fraction``; every input accepts a
``Fraction``, an ``int`` or a string (``"p/q"``, ``"0.1"``). A ``float`` is
refused with ``TypeError`` (use ``fixel.exact(x)`` to take its binary value on
purpose). Doubles appear only in ``.approx`` views and in ``fixel.plot``.
See docs/python.md.
"""

import contextlib
import json
import os
import time
from types import SimpleNamespace

import numpy as np

from . import _fixel
from ._exact import engine_settings, exact, frac, fracs, text, vector, whole
from ._design import Candidate, Design, Layout, design, design_candidates, design_scene
from ._region import AlgebraicEnd, Magnitudes, Region, RegionInterval, RegionStats, region, sample
from ._worker import seconds_limit, stoppable
from .errors import Error, InputError, ParseError, SceneError, StoppedError, UnsupportedError

__version__ = _fixel.__version__

__all__ = [
    "Error", "InputError", "ParseError", "SceneError", "StoppedError", "UnsupportedError",
    "Scene", "SeatingSet", "GuaranteedSet", "Region", "RegionInterval", "RegionStats", "Magnitudes", "AlgebraicEnd",
    "exact", "seating_set", "guaranteed_set", "simulate", "solutions", "region", "sample",
    "to_off", "to_svg", "SustainedSet", "sustained_set", "ApproachSet", "approach_set", "push", "push_plan",
    "design", "design_candidates", "design_scene", "Design", "Layout", "Candidate", "exact_only", "filter_stats",
    "directed_rounding_works",
]  # fmt: skip


def _approx(values):
    return np.array([float(v) for v in values], dtype=float)


class Scene:
    """A validated scene (the library's parse_scene/load_scene)."""

    def __init__(self, impl):
        if not isinstance(impl, _fixel.Scene):
            raise TypeError(
                f"Scene: {impl!r} is not a parsed scene; use fixel.Scene.load(path) or fixel.Scene.from_dict(d)"
            )
        self._impl = impl

    @classmethod
    def load(cls, path, max_seconds=None):
        """Reads a scene file; InputError if unreadable, ParseError/SceneError if
        invalid. A huge outline's checks take a while: ``max_seconds`` and
        Ctrl-C stop them as in region (``fixel info --max-seconds``)."""
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path: {path!r} is not a file path")
        path = os.fspath(path)
        return cls(stoppable(lambda c: _fixel.load_scene(path, c), max_seconds))

    @classmethod
    def from_dict(cls, d, source="scene", max_seconds=None):
        """Validates a scene given as a dict in the scene-file format. Numbers
        may be strings, ints or Fractions; floats are refused (not exact).
        ``max_seconds`` and Ctrl-C as in load."""
        if not isinstance(source, str):
            raise TypeError(f"source: {source!r} is not a string (the name error messages give the scene)")
        if not isinstance(d, dict):
            raise TypeError(f"{source}: a scene is a dict in the scene-file format, not {type(d).__name__}")
        # Serialised and parsed by the C++ parser, so validation and messages
        # are exactly those of the CLI.
        limit = seconds_limit(max_seconds)
        _fixel.Control(limit)  # a bad max_seconds is refused before any work
        started = time.monotonic()
        _check_nesting(d, source)
        text = json.dumps(_jsonable(d, "", _Deadline(limit)))
        left = None if limit is None else max(limit - (time.monotonic() - started), 1e-9)
        return cls(stoppable(lambda c: _fixel.parse_scene(text, source, c), left))

    def to_dict(self):
        """The scene in the scene-file format, every number an exact string,
        friction intervals as ["lo", "hi"], derived values (mass, inertia,
        centre of mass from the outline) written out: Scene.from_dict of it
        gives the same scene."""
        return json.loads(self._impl.to_json(True))

    def save(self, path):
        """Writes the scene file (`to_dict`'s content, less the mass
        properties the outline gave, which reading derives again; as `fixel
        design --scene-out` writes one): to a temporary file beside `path`, then
        renamed over it, so an error leaves an earlier file whole.
        InputError naming the path when it cannot be written."""
        if not isinstance(path, (str, os.PathLike)):
            raise TypeError(f"path: {path!r} is not a file path")
        _fixel.save_scene(self._impl, os.fspath(path))

    name = property(lambda self: self._impl.name, doc="The scene's name (its file's, or from_dict's source).")
    dof = property(lambda self: self._impl.dof, doc="Degrees of freedom: 3 for a rigid body, 2 for a point mass.")
    num_contacts = property(lambda self: self._impl.num_contacts, doc="Number of fixels (contacts), n_c.")
    has_boundary = property(lambda self: self._impl.has_boundary, doc="Whether the body has an outline.")
    num_curves = property(lambda self: self._impl.num_curves, doc="Curves of the outline (0 without one).")
    pusher_mu = property(
        lambda self: frac(self._impl.pusher_mu),
        doc="Pusher friction μ_p (Fraction): an interval's upper end, at which every analysis judges it "
        "(to_dict() has the interval).",
    )

    @property
    def background_impulse(self):
        """b₀ (Fractions; N·s, N·s and, for dof 3, N·m·s; world frame, moment
        about the centre of mass): the scene's background impulse. The CLI's
        ``seat --impulse``, ``simulate`` and ``solutions`` apply b₀ + p;
        ``S.contains``, ``S.eq27``, ``G.contains``, ``simulate`` and
        ``solutions`` here take the total impulse, as the C++ library does,
        so pass ``[b + q for b, q in zip(scene.background_impulse, p)]``.
        ``region`` and ``push_plan`` add b₀ themselves, as the CLI does."""
        return tuple(frac(v) for v in self.to_dict()["background_impulse"])

    def curve_range(self, k):
        """(u_begin, u_end) of curve k as Fractions."""
        return fracs(_fixel.curve_range(self._impl, whole(k, "k")))

    def __reduce__(self):
        # Pickled as its exact dict (for multiprocessing over many layouts),
        # the outline's mass properties left to be derived again (so they
        # stay marked derived).
        return (_scene_from_dict, (json.loads(self._impl.to_json(False)), self.name))

    def __repr__(self):
        return f"<fixel.Scene {self.name!r} dof={self.dof} contacts={self.num_contacts}>"


_MAX_SCENE_DEPTH = 64  # the C++ scene loader's limit, with the same message
# The most values a scene text within the loader's 256 MiB can hold (each
# takes at least a digit and a comma).
_MAX_SCENE_VALUES = (256 << 20) // 2


def _check_nesting(d, source):
    """Before anything recurses over the dict: a dict or list that contains
    itself is an InputError naming where, and nesting past 64 levels the
    ParseError the scene loader gives for the same text (both used to be a
    RecursionError, or "nested too deeply" past Python's limit). A tree
    whose text would pass the loader's 256 MiB is an InputError: a list
    shared twice at each of 30 levels unrolls to 2^30 values, and the walk
    that wrote it out took hours. Each dict or list is walked once (its
    count of values and its height kept), so this takes time in the
    objects, not in the values they unroll to."""
    seen = {}  # id -> (values, height in dicts and lists)
    on_path = set()

    def walk(x, path, depth):
        if not isinstance(x, (dict, list, tuple)):
            return 1, 0
        key = id(x)
        if key in on_path:
            kind = "a dict" if isinstance(x, dict) else "a list"
            raise InputError.make(path or source, kind, "contains itself: a scene is a tree of dicts and lists")
        if depth > _MAX_SCENE_DEPTH:
            raise ParseError.make(source, f"depth {depth}", f"nests deeper than {_MAX_SCENE_DEPTH} levels")
        if key not in seen:
            on_path.add(key)
            values, height = 1, 1
            items = x.items() if isinstance(x, dict) else enumerate(x)
            for k, v in items:
                where = (f"{path}.{k}" if path else str(k)) if isinstance(x, dict) else f"{path}[{k}]"
                n, h = walk(v, where, depth + 1)
                values, height = values + n, max(height, h + 1)
            on_path.discard(key)
            seen[key] = (values, height)
        values, height = seen[key]
        if depth + height - 1 > _MAX_SCENE_DEPTH:  # met before, deeper now
            deepest = _MAX_SCENE_DEPTH + 1
            raise ParseError.make(source, f"depth {deepest}", f"nests deeper than {_MAX_SCENE_DEPTH} levels")
        return values, height

    values, _ = walk(d, "", 1)
    if values > _MAX_SCENE_VALUES:
        raise InputError.make(
            source,
            f"{values} values",
            f"is larger than a scene file can be (256 MiB as text, at most {_MAX_SCENE_VALUES} values): "
            "a list or dict shared many times?",
        )


class _Deadline:
    """from_dict's max_seconds while it writes the dict out (a shared list
    is written once per use, as its text holds it)."""

    def __init__(self, seconds):
        self.at = None if seconds is None or not seconds < 1e9 else time.monotonic() + seconds
        self.values = 0

    def tick(self):
        self.values += 1
        if self.values % 4096 == 0 and self.at is not None and time.monotonic() > self.at:
            raise StoppedError(f"load: time limit reached after {self.values} values written out; no result")


def _jsonable(x, path, deadline=None):
    """The dict with every number as exact text; a float anywhere is a TypeError
    naming its JSON path (json.dumps would otherwise write its decimal repr)."""
    if deadline is not None:
        deadline.tick()
    if isinstance(x, dict):
        return {k: _jsonable(v, f"{path}.{k}" if path else str(k), deadline) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [_jsonable(v, f"{path}[{i}]", deadline) for i, v in enumerate(x)]
    if type(x) is int and x.bit_length() > 13000:
        return text(x, path)  # beyond json.dumps (4300 digits): as exact text
    if x is None or isinstance(x, (str, bool)) or type(x) is int:
        return x  # left to the C++ parser, which names the field if it is wrong
    if getattr(x, "dtype", None) is not None and getattr(x, "ndim", 0) > 0:
        return _jsonable(list(x), path) if x.dtype.kind not in "fc" else vector(x, path)
    return text(x, path)


def _scene_from_dict(d, source):
    return Scene.from_dict(d, source)


def _expect(x, cls, name):
    if not isinstance(x, cls):
        raise TypeError(f"{name}: expected a fixel.{cls.__name__}, not {type(x).__name__}")
    return x


def _same_scene(owner_scene, scene, field):
    """InputError naming ``field`` unless ``owner_scene`` (the scene an
    object was built from) is ``scene``: the same object, or one equal to it
    in the scene-file format. An object of another scene would give a wrong
    answer silently."""
    if owner_scene is scene or owner_scene._impl is scene._impl:
        return
    there, here = owner_scene.to_dict(), scene.to_dict()
    if there == here:
        return
    raise InputError.make(
        field,
        f"built from scene {owner_scene.name!r}",
        f"belongs to another scene than {scene.name!r}: {_first_difference(there, here, '')}; "
        "build it from this scene",
    )


def _first_difference(there, here, path):
    """Where two scene dicts first differ, with both values: "fixels[0].gap
    is '1/5' here, '1/10' in the scene it was built from" (the name and
    description last: they change no answer)."""
    if isinstance(there, dict) and isinstance(here, dict):
        keys = list(there) + [k for k in here if k not in there]
        for key in sorted(keys, key=lambda k: not path and k in ("name", "description")):
            where = f"{path}.{key}" if path else key
            if key not in here or key not in there:
                return f"{where} is {'absent' if key not in here else 'given'} here, " \
                    f"{'absent' if key not in there else 'given'} in the scene it was built from"
            if there[key] != here[key]:
                return _first_difference(there[key], here[key], where)
    if isinstance(there, list) and isinstance(here, list) and len(there) == len(here):
        for i, (a, b) in enumerate(zip(there, here)):
            if a != b:
                return _first_difference(a, b, f"{path}[{i}]")
    shown = [repr(v) if not isinstance(v, (dict, list)) else f"a {type(v).__name__} of {len(v)}" for v in (here, there)]
    return f"{path} is {shown[0]} here, {shown[1]} in the scene it was built from"


def _scene(scene):
    """A Scene from a Scene, a scene dict or a scene file's path (str or
    os.PathLike), as every function that takes a scene accepts."""
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, dict):
        return Scene.from_dict(scene)
    if isinstance(scene, (str, os.PathLike)):
        return Scene.load(scene)
    raise TypeError(f"scene: expected a fixel.Scene, a scene dict or a path, not {type(scene).__name__}")


class SeatingSet:
    """S = {apex + Σ λ_k rays_k : λ ≥ 0} = {p : a·p ≥ c for every (a, c) in halfspaces}."""

    def __init__(self, scene, impl):
        self._scene = scene
        self._impl = impl
        self.dof = impl.dof
        self.apex = fracs(impl.apex)
        self.rays = [fracs(r) for r in impl.rays]
        self.halfspaces = [(fracs(a), frac(c)) for a, c in impl.halfspaces]
        self.velocity_after = fracs(impl.velocity_after)
        self.tangential_velocity = fracs(impl.tangential_velocity)
        self.sliding = tuple(impl.sliding)

    # Read-only: the set is of this scene (pickling rebuilds it from it).
    scene = property(lambda self: self._scene, doc="The Scene this set was built from (read-only).")

    def contains(self, p):
        """Exact membership of the total impulse p (N·s, N·s, N·m·s; world
        frame; b₀ included: Scene.background_impulse). Boundary points are
        members."""
        return self._impl.contains(vector(p, "p"))

    def __contains__(self, p):
        return self.contains(p)

    def __reduce__(self):
        return (seating_set, (self.scene,))  # recomputed exactly on unpickling

    def eq27(self, p):
        """Eq. (27) of the paper at p: (names, K⁻¹P p, −K⁻¹a), with p ∈ S iff
        linear ≥ threshold entrywise. UnsupportedError when a contact sticks."""
        system = _fixel.seating_system(self.scene._impl, self._impl)
        return (list(system.y_names), fracs(system.linear_part(vector(p, "p"))), fracs(system.threshold()))

    @property
    def approx(self):
        """Doubles for display: apex, rays, halfspace normals and offsets."""
        return SimpleNamespace(
            apex=_approx(self.apex),
            rays=np.array([_approx(r) for r in self.rays]),
            normals=np.array([_approx(a) for a, _ in self.halfspaces]),
            offsets=_approx([c for _, c in self.halfspaces]),
        )

    def __repr__(self):
        return f"<fixel.SeatingSet apex={tuple(str(x) for x in self.apex)} rays={len(self.rays)}>"


def seating_set(scene):
    """The seating set S of a scene (n_c == dof)."""
    scene = _scene(scene)
    return SeatingSet(scene, _fixel.seating_set(scene._impl))


def _rows(rows):
    return [(fracs(a), frac(c)) for a, c in rows]


class GuaranteedSet:
    """G ⊂ S: the impulses whose every one-step outcome seats the part.

    ``pieces``: G as disjoint convex pieces (the JSON's "pieces"), each a
    SimpleNamespace(dimension, closed, strict): the total impulses p (b₀
    included) with a·p ≥ c for every (a, c) in ``closed`` and a·p > c for
    every (a, c) in ``strict`` (Fractions). A piece of dimension below dof
    has no volume but is kept, so that the pieces partition G exactly.
    ``non_seating``: (modes, open_fixel) of each non-seating set that meets
    S, and ``non_seating_impulses`` its impulses in the same order, as
    SimpleNamespace(closed, strict)."""

    def __init__(self, seating, impl):
        self._seating = seating
        self._impl = impl
        self.num_pieces = impl.num_pieces
        self.non_seating = [(tuple(modes), fixel) for modes, fixel in impl.non_seating]
        self.pieces = [
            SimpleNamespace(dimension=dim, closed=_rows(closed), strict=_rows(strict))
            for dim, closed, strict in impl.pieces
        ]
        self.non_seating_impulses = [
            SimpleNamespace(closed=_rows(closed), strict=_rows(strict)) for closed, strict in impl.non_seating_rows
        ]

    seating = property(lambda self: self._seating, doc="The SeatingSet G refines (read-only).")

    def contains(self, p):
        """Exact membership: every one-step outcome at the total impulse p
        (b₀ included: Scene.background_impulse) seats the part."""
        return self._impl.contains(vector(p, "p"))

    def __reduce__(self):
        return (_guaranteed_from, (self.seating,))  # recomputed exactly on unpickling

    def __contains__(self, p):
        return self.contains(p)

    def __repr__(self):
        return f"<fixel.GuaranteedSet pieces={self.num_pieces} of S of scene {self.seating.scene.name!r}>"

    def lost_fraction(self, grid=6):
        """Fraction of sample points of S that are not in G (exact)."""
        return frac(self._impl.lost_fraction(whole(grid, "grid")))


def _guaranteed_from(S):
    return guaranteed_set(S.scene, S)


def guaranteed_set(scene, seating=None, progress=None, max_seconds=None):
    """G for a scene; pass its SeatingSet to reuse it. ``progress``,
    ``max_seconds`` and Ctrl-C as in region."""
    from ._region import _run

    scene = _scene(scene)
    S = _expect(seating, SeatingSet, "seating") if seating is not None else seating_set(scene)
    _same_scene(S.scene, scene, "seating")
    impl = _run(lambda c: _fixel.guaranteed_set(scene._impl, S._impl, c), progress, "fixel.guaranteed_set", max_seconds)
    return GuaranteedSet(S, impl)


def _vectors(d, keys):
    return {k: (fracs(v) if k in keys else v) for k, v in d.items()}


# At most this many steps, without max_seconds, simulate runs in the
# caller's thread (docs/python.md, "Stopping a run").
_SHORT_SIMULATION = 100


def simulate(scene, impulse, steps=1, max_seconds=None):
    """Simulates ``steps`` steps, applying ``impulse`` in the first (or a list
    of impulses, one per step): total impulses (N·s, N·s, N·m·s; world
    frame), b₀ not added (Scene.background_impulse). Returns
    SimpleNamespace(seated, steps) where each step has q (x m, y m, θ rad),
    velocity, gaps, p_n, p_f (Fractions) and pivots.
    ``max_seconds`` and Ctrl-C stop it as in region (Ctrl-C only past 100
    steps: a shorter run is not worth a worker thread)."""
    scene = _scene(scene)
    steps = whole(steps, "steps")
    impulses = impulse if _is_list_of_vectors(impulse) else [impulse]
    p = [vector(x, "impulse") for x in impulses]
    if steps <= _SHORT_SIMULATION and max_seconds is None:
        seated, records = _fixel.simulate(scene._impl, p, steps, None)  # a worker would cost half a step
    else:
        seated, records = stoppable(lambda c: _fixel.simulate(scene._impl, p, steps, c), max_seconds)
    keys = {"q", "velocity", "gaps", "p_n", "p_f"}
    return SimpleNamespace(seated=seated, steps=[SimpleNamespace(**_vectors(r, keys)) for r in records])


def _is_list_of_vectors(x):
    """Whether ``impulse`` is one impulse per step: a list or tuple of
    vectors (lists, tuples or 1-D arrays), or a 2-D array, one row a step."""
    if getattr(x, "ndim", None) == 2:
        return True
    return (
        isinstance(x, (list, tuple))
        and len(x) > 0
        and all(isinstance(e, (list, tuple)) or getattr(e, "ndim", None) == 1 for e in x)
    )


def solutions(scene, impulse, max_seconds=None):
    """Every distinct outcome of one step at the total ``impulse`` (the
    CLI's ``solutions`` at b₀ + p; b₀ is not added here:
    Scene.background_impulse): SimpleNamespaces with seated, modes,
    velocity, gaps, p_n, p_t, isolated. ``max_seconds`` and Ctrl-C stop it as in region."""
    scene = _scene(scene)
    keys = {"velocity", "gaps", "p_n", "p_t"}
    p = vector(impulse, "impulse")
    out = stoppable(lambda c: _fixel.solutions(scene._impl, p, c), max_seconds)
    return [SimpleNamespace(**_vectors(o, keys)) for o in out]


def to_off(scene, seating, directory, length=1, guaranteed=None):
    """Writes S (and G's pieces, the outline, the segment cones) as OFF/OBJ
    files into ``directory``, like ``fixel dump --off``; each .off file has a
    JSON sidecar of the same stem with its metadata. Returns the paths."""
    scene = _scene(scene)
    _expect(seating, SeatingSet, "seating")
    _same_scene(seating.scene, scene, "seating")
    if guaranteed is not None:
        _expect(guaranteed, GuaranteedSet, "guaranteed")
        _same_scene(guaranteed.seating.scene, scene, "guaranteed")
    g = guaranteed._impl if guaranteed is not None else None
    return _fixel.dump_off(scene._impl, seating._impl, str(directory), text(length, "length"), g)


def to_svg(path, result, theta=None, impulse=None):
    """Draws ``result`` to an SVG file: a Region (from fixel.region) like
    ``fixel region --svg``, or a GuaranteedSet (dof 3) like ``fixel seat
    --guaranteed --svg``: the slice p_θ = theta (default: the impulse's, else
    that of apex + Σ rays, through S's interior) of S and G, with ``impulse``
    marked."""
    if isinstance(result, GuaranteedSet):
        S = result.seating
        p = None if impulse is None else vector(impulse, "impulse")
        if theta is None:
            # The impulse's slice, else the one through apex + Σ rays (default_slice_theta).
            theta = p[2] if p is not None and len(p) == 3 else S.apex[2] + sum(r[2] for r in S.rays)
        _fixel.write_guaranteed_svg(str(path), S.scene._impl, S._impl, result._impl, text(theta, "theta"), p)
        return
    r = _expect(result, Region, "region")
    if isinstance(r.seating, SustainedSet):  # region(push="sustained"): the picture against J
        _fixel.write_sustained_region_svg(str(path), r.scene._impl, r.seating._impl, r._impl)
        return
    g = None if r.guaranteed is None else r.guaranteed._impl
    _fixel.write_region_svg(str(path), r.scene._impl, r.seating._impl, r._impl, g)


class SustainedSet:
    """J: the held wrenches (world frame: force through the centre of mass,
    moment about it) that drive the part into its seat and keep it there,
    judged at the exact seated pose q* (docs/theory.md §10). ``empty`` is
    None (unknown) when J's pieces are not decided (``pieces_decided``
    False), as the CLI's null."""

    scene = property(lambda self: self._scene, doc="The Scene J was built from (read-only).")

    def __init__(self, scene, impl):
        self._scene = scene
        self._impl = impl
        self.empty = impl.empty if impl.pieces_decided else None
        self.empty_reason = impl.empty_reason
        self.strongly_stable = impl.strongly_stable
        self.pieces_decided = impl.pieces_decided
        self.mu = fracs(impl.mu)
        doc = json.loads(_fixel.sustained_json(scene._impl, impl))
        #: The "seated_pose" object of ``fixel seat --sustained --json``.
        self.seated_pose = doc["seated_pose"]
        #: The "sustained" object: cone, jam_cones, pieces (exact strings "a+b*sqrt(d)").
        self.cones = doc["sustained"]

    def why_not(self, w):
        """"" when w is in J, else the reason (it can escape, or two fixels hold it)."""
        return self._impl.why_not(vector(w, "wrench"))

    def contains(self, w):
        """Exact membership of the world-frame wrench w in J."""
        return self.why_not(w) == ""

    def __reduce__(self):
        return (sustained_set, (self.scene,))  # recomputed exactly on unpickling

    def __contains__(self, w):
        return self.contains(w)

    def __repr__(self):
        state = "empty" if self.empty else ("strongly stable" if self.strongly_stable else "not strongly stable")
        return f"<fixel.SustainedSet J of scene {self.scene.name!r}: {state}>"


def push(
    scene,
    wrench=None,
    at=None,
    time=20,
    max_seconds=None,
    steps_per_h=1000,
    velocity_iterations=20,
    position_iterations=10,
):
    """Run a held push in Box2D (``fixel push``): a measurement, not a
    decision. ``wrench`` (exact, world frame: force through the centre of
    mass, moment about it) or ``at="K:U"`` (a frictionless unit push at
    parameter U of curve K, at the seated pose), held for ``time`` steps h
    (at most 10^8 engine steps). The engine's accuracy: dt = h/``steps_per_h``
    (1000 to 2^31 − 1) and Box2D's ``velocity_iterations`` and
    ``position_iterations`` per step (1 to 1000); a failure that goes away
    with finer settings was the solver's (docs/physics.md, "Engine
    settings"). Returns the ``fixel push --json`` document as a dict:
    "outcome" is "seated", "jammed", "escaped" or "timeout". ``max_seconds``
    and Ctrl-C stop it as in region."""
    scene = _scene(scene)
    if wrench is None and at is None:
        raise InputError.make("wrench", "None", "and at=None: give one of wrench= and at=")
    if wrench is not None and at is not None:
        raise InputError.make("at", repr(at), "and a wrench are both given: give only one of wrench= and at=")
    w = None if wrench is None else vector(wrench, "wrench")
    if at is not None and not isinstance(at, str):
        raise TypeError(f"at: {at!r} is not a string 'K:U'")
    t = text(time, "time")
    e = engine_settings(steps_per_h, velocity_iterations, position_iterations)
    return json.loads(stoppable(lambda c: _fixel.push(scene._impl, w, at, t, *e, c), max_seconds))


def push_plan(scene, at, guaranteed=False, max_seconds=None):
    """How hard to push at one boundary point (``fixel push-plan``):
    ``at="K:U"`` is parameter U (exact) of curve K, pushed by a frictionless
    finger along the inward normal at the scene pose, whatever the scene's
    pusher mu (region uses it; "pusher_mu" and "scene_pusher_mu" say
    which). Returns the ``fixel
    push-plan --json`` document as a dict: "one_step" (S: status and the
    window of |p|), "guaranteed" (G, with ``guaranteed=True``; dof 3),
    "sustained" (J's status, and "approach": the exact verdict of the
    approach-aware J' on the push, with the pair that can hold the part on
    its way; at a corner the fan's status as ``region(push="sustained",
    approach=True)`` classifies it), "corner". Exact values are
    strings. ``max_seconds`` and Ctrl-C stop it as in region."""
    scene = _scene(scene)
    if not isinstance(at, str):
        raise TypeError(f"at: {at!r} is not a string 'K:U'")
    if not isinstance(guaranteed, bool):
        raise TypeError(f"guaranteed: {guaranteed!r} is not a bool")
    g = guaranteed
    return json.loads(stoppable(lambda c: _fixel.push_plan(scene._impl, at, g, c), max_seconds))


def sustained_set(scene, max_seconds=None):
    """The sustained-push set J of a scene (``fixel seat --sustained``).
    Building it is one exact step that takes milliseconds on ordinary
    numbers and can take minutes on numbers of many thousands of digits:
    ``max_seconds`` and Ctrl-C stop it as in region."""
    scene = _scene(scene)
    return SustainedSet(scene, stoppable(lambda c: _fixel.sustained_set(scene._impl, c), max_seconds))


class ApproachSet:
    """The approach-aware sustained-push set J' (docs/theory.md §10.7): the
    wrenches of J that no pair of fixels can hold at any two-contact pose
    between the scene pose and the seat. Decided exactly per wrench.

    ``decided`` (False: ``undecided_reason`` says why, and membership raises
    UnsupportedError), ``t_star`` (tan(θ*/2), exact text), ``theta_star``
    (rad, display), ``on_edges`` (False: a contact leaves its edge on the way
    and J' is empty; ``edge_reason`` says where), ``empty`` (True when J' is
    known to be empty, else None: J' is decided per wrench, so it is never
    known to be non-empty; the CLI's JSON has null), and ``J``, the
    SustainedSet it refines. When not ``decided``, ``t_star`` and
    ``on_edges`` are None (unknown) too."""

    scene = property(lambda self: self._J.scene, doc="The Scene J' was built from (read-only).")
    J = property(lambda self: self._J, doc="The SustainedSet J' refines (read-only).")

    def __init__(self, J, impl):
        self._J = J
        self._impl = impl
        self.decided = impl.decided
        self.undecided_reason = impl.undecided_reason
        # Unknown (None) when J' is undecided, as the CLI's JSON has them (null).
        self.t_star = impl.t_star if impl.decided else None
        self.theta_star = impl.theta_star
        self.on_edges = impl.on_edges if impl.decided else None
        self.edge_reason = impl.edge_reason
        self.empty = True if impl.decided and impl.empty else None  # true or null, as the CLI's JSON

    def why_not(self, w, frame="world", max_seconds=None):
        """"" when w is in J', else the reason (as J's, or the pair that can
        hold the part on the way, or the edge a contact leaves). ``frame``:
        "world" (w = (fx, fy, moment), world frame) or "part" (frame B at
        the seat, as a finger's push at a boundary point: the world-frame
        wrench held on the way is R(θ*)·w, in Q(√d)). ``max_seconds`` and
        Ctrl-C stop the test between its pairs of fixels (StoppedError,
        KeyboardInterrupt); one pair's root isolation is not interrupted."""
        return self._why_not(w, frame, max_seconds)[0]

    def hold(self, w, frame="world", max_seconds=None):
        """None, or where a pair can hold the part under w on the way:
        {"fixels": (i, j), "theta": rad (display), "t": tan(theta/2) exact
        text or "t_star", "slide": display float for a pair on parallel
        edges, else None}. ``frame`` and ``max_seconds`` as in why_not."""
        return self._why_not(w, frame, max_seconds)[1]

    def contains(self, w, frame="world", max_seconds=None):
        """Exact membership of w in J' (``frame`` and ``max_seconds`` as in
        why_not); UnsupportedError when J' is undecided for the scene."""
        return self.why_not(w, frame, max_seconds) == ""

    def __contains__(self, w):
        return self.contains(w)

    def __reduce__(self):
        return (_approach_from, (self.J,))  # recomputed exactly on unpickling (J with it)

    def __repr__(self):
        if not self.decided:
            state = "undecided"
        else:
            state = "empty" if self.empty else f"t* = {self.t_star}"
        return f"<fixel.ApproachSet J' of scene {self.scene.name!r}: {state}>"

    def _why_not(self, w, frame, max_seconds):
        if frame not in ("world", "part"):
            raise InputError.make("frame", repr(frame), 'must be "world" or "part"')
        v = vector(w, "wrench")
        return stoppable(lambda c: self._impl.why_not(v, frame == "part", c), max_seconds)


def _approach_from(J):
    return approach_set(J.scene, J)


def approach_set(scene, sustained=None, max_seconds=None):
    """The approach-aware set J' of a scene (``fixel seat --sustained``
    reports it as "approach"). ``sustained``: its SustainedSet J, when
    already computed. ``max_seconds`` and Ctrl-C as in sustained_set (one
    limit for J, when it is built here, and J' together)."""
    scene = _scene(scene)
    if sustained is not None:
        J = _expect(sustained, SustainedSet, "sustained")
        _same_scene(J.scene, scene, "sustained")
        return ApproachSet(J, stoppable(lambda c: _fixel.approach_set(scene._impl, J._impl, c), max_seconds))

    def both(control):
        j = _fixel.sustained_set(scene._impl, control)
        return j, _fixel.approach_set(scene._impl, j, control)

    j, a = stoppable(both, max_seconds)
    return ApproachSet(SustainedSet(scene, j), a)


@contextlib.contextmanager
def exact_only(on=True):
    """Every filtered decision in exact rationals inside the ``with`` block
    (the CLI's ``--exact-only``, ``FIXEL_FORCE_EXACT=1``): the same answers,
    more slowly. Process-wide, so other threads see it too; the previous
    setting is restored on leaving the block, also on an exception.
    ``exact_only(False)`` turns the filters back on inside the block, unless
    ``directed_rounding_works()`` is False (under valgrind, say): then every
    decision is exact, whatever this says."""
    if not isinstance(on, bool):
        raise TypeError(f"on: {on!r} is not a bool")
    previous = _fixel.force_exact_set()
    _fixel.set_force_exact(on)
    try:
        yield
    finally:
        _fixel.set_force_exact(previous)


def directed_rounding_works():
    """Whether this machine honours the processor's rounding mode, so that
    the interval filters can decide. False under valgrind, which rounds to
    nearest whatever the mode: then every decision is exact (as inside
    ``exact_only()``), the same answers, more slowly."""
    return _fixel.directed_rounding_works()


def filter_stats(reset=False):
    """How often each interval filter decided ("certified") and how often it
    could not and the exact path ran ("fallbacks"), per filter site, since
    the last reset: the line ``FIXEL_FILTER_STATS=1`` prints. Runs under
    ``exact_only()`` count neither. With ``reset=True`` the counters are set
    to zero after reading."""
    if not isinstance(reset, bool):
        raise TypeError(f"reset: {reset!r} is not a bool")
    stats = _fixel.filter_stats()
    if reset:
        _fixel.reset_filter_stats()
    return stats


def __dir__():
    # dir(fixel) lists the public API, not the helpers the module imports
    # (np, os, json, ...); they stay reachable for fixel's own submodules.
    return sorted(set(__all__) | {"__version__"} | ({"plot"} & globals().keys()))
