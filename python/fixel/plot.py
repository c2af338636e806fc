"""Matplotlib drawings of fixel results, into an axis the caller owns.

Display only: exact results are rounded to doubles here and nowhere else.
Nothing in this module calls ``plt.show()`` or creates a figure.
"""

import math

import numpy as np

from . import _fixel
from ._exact import frac, text
from .errors import InputError

#: Status colours, as in `fixel region --svg`.
COLOURS = {"in": "#1a9850", "out": "#bdbdbd", "partial": "#fdae61"}


def _samples(interval, per_unit):
    width = float(interval.u1 - interval.u0)
    return max(1, min(200, int(math.ceil(width * per_unit))))


def region(ax, scene, region, samples_per_unit=48, fixels=True, linewidth=3):
    """Draws the outline coloured by status, the fixels (points, inward
    normals) and the centre of mass into ``ax``. Returns ``ax``."""
    impl = scene._impl
    drawn = []
    for r in region.intervals:
        u0, u1 = text(r.u0, "u0"), text(r.u1, "u1")
        if r.u0 == r.u1:  # a corner sample
            (x, y), _ = _fixel.sample_curve(impl, r.curve, u0, u1, 1)
            ax.plot([x], [y], "o", color=COLOURS[r.status], markersize=5, zorder=3)
            continue
        pts = np.array(_fixel.sample_curve(impl, r.curve, u0, u1, _samples(r, samples_per_unit)))
        drawn.append(pts)
        ax.plot(pts[:, 0], pts[:, 1], color=COLOURS[r.status], linewidth=linewidth, solid_capstyle="butt")
    d = scene.to_dict()
    span = float(np.ptp(np.vstack(drawn), axis=0).max()) if drawn else 1.0
    if fixels:
        for i, f in enumerate(d["fixels"]):
            x, y = (float(v) for v in _fractions(f["point"]))
            nx, ny = (float(v) for v in _fractions(f["normal"]))
            ax.plot([x], [y], "o", color="#08519c", zorder=4)
            ax.annotate("", xy=(x + 0.15 * span * nx, y + 0.15 * span * ny), xytext=(x, y), arrowprops={"arrowstyle": "->"})
            ax.annotate(f"f{i}", (x, y), textcoords="offset points", xytext=(6, -12), color="#08519c")
    cx, cy = map(float, _fractions(d["body"]["center_of_mass"]))
    ax.plot([cx], [cy], "+", color="black", markersize=10, markeredgewidth=2)
    ax.set_aspect("equal")
    # Labelled by model, as every report is: "in" alone would not say in what.
    meaning = region._impl.meaning
    for status, colour in COLOURS.items():
        label = f"in: {meaning}" if status == "in" else ("partial (undecided)" if status == "partial" else status)
        ax.plot([], [], color=colour, linewidth=linewidth, label=label)
    return ax


def _fractions(values):
    return [frac(v) for v in values]


def _lonlat(w):
    fx, fy, m = w
    return math.degrees(math.atan2(fy, fx)), math.degrees(math.atan2(m, math.hypot(fx, fy)))


def wrench_sphere(ax, scene, region=None, seating=None, grid=(120, 60), samples_per_unit=48):
    """Unit wrench directions (fx, fy, m) in a longitude/latitude projection
    (dof 3): shaded where the ray b0 + τ w meets S (seating set; doubles on a
    display grid), and, with a region, the boundary's frictionless push
    wrenches coloured by status. Returns ``ax``."""
    if scene.dof != 3:
        raise InputError.make("scene", f"dof {scene.dof}", "has no wrench sphere: wrench_sphere needs dof 3")
    if seating is None:
        seating = region.seating if region is not None else None
    if seating is not None and not hasattr(seating, "approx"):
        raise TypeError(
            f"wrench_sphere draws the one-step seating set S (or a region against it), not a "
            f"{type(seating).__name__}: for J draw the region with fixel.plot.region"
        )
    if seating is not None:
        approx = seating.approx
        b0 = np.array([float(v) for v in _fractions(scene.to_dict()["background_impulse"])])
        nlon, nlat = grid
        lon = np.linspace(-180, 180, nlon)
        lat = np.linspace(-90, 90, nlat)
        LON, LAT = np.meshgrid(np.radians(lon), np.radians(lat))
        W = np.stack([np.cos(LAT) * np.cos(LON), np.cos(LAT) * np.sin(LON), np.sin(LAT)], axis=-1)
        ax.contourf(lon, lat, _ray_hits(approx, b0, W), levels=[0.5, 1.5], colors=["#c6dbef"])
    if region is not None:
        for r in region.intervals:
            if r.u0 == r.u1:
                continue
            n = _samples(r, samples_per_unit)
            ws = _fixel.sample_wrench(scene._impl, r.curve, text(r.u0, "u0"), text(r.u1, "u1"), n)
            pts = [_lonlat(w) for w in ws if w is not None]
            for run in _split_at_seam(pts):
                arr = np.array(run)
                ax.plot(arr[:, 0], arr[:, 1], color=COLOURS[r.status], linewidth=3)
    ax.set_xlim(-180, 180)
    ax.set_ylim(-90, 90)
    ax.set_xlabel("longitude: push direction (deg)")
    ax.set_ylabel("latitude: atan(moment / |force|) (deg)")
    return ax


def _ray_hits(approx, b0, W):
    """1 where {τ > 0 : b0 + τ w ∈ S} is non-empty (doubles, display only)."""
    lo = np.zeros(W.shape[:-1])
    hi = np.full(W.shape[:-1], np.inf)
    ok = np.ones(W.shape[:-1], dtype=bool)
    for a, c in zip(approx.normals, approx.offsets):
        s = W @ a
        b = c - a @ b0
        with np.errstate(divide="ignore", invalid="ignore"):
            t = b / s
        lo = np.where(s > 1e-15, np.maximum(lo, t), lo)
        hi = np.where(s < -1e-15, np.minimum(hi, t), hi)
        ok &= ~((np.abs(s) <= 1e-15) & (b > 0))
    return (ok & (lo <= hi)).astype(float)


def _split_at_seam(pts):
    runs, run = [], []
    for p in pts:
        if run and abs(p[0] - run[-1][0]) > 180:
            runs.append(run)
            run = []
        run.append(p)
    if run:
        runs.append(run)
    return runs
