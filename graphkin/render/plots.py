"""Curves over a sweep: angles, rates, coupler curves and the transmission angle.

Each item of ``what`` is drawn on its own axes of one
:class:`matplotlib.figure.Figure` (no pyplot state):

* ``angle``, ``omega``, ``alpha``: every moving link's θ (degrees, unwrapped
  so the curve is continuous), ω (rad/s) or α (rad/s²) over the drive;
  ``angle:3``, ``omega:4`` for one link;
* ``velocity:P``, ``acceleration:P``: the magnitude of a point's velocity or
  acceleration over the drive;
* ``path:P``: the path of a point (a coupler curve), drawn to scale, with its
  osculating circle at the first posture and, for a coupler point, Ball's
  point of its link and the nearly straight stretch it traces;
* ``center:I24``: the path of an instant center in the frame (to scale);
* ``centrode:3``: the fixed and moving centrodes of link 3 (Sec. 3.20);
* ``transmission``: the transmission angle at every pin found by two arcs,
  with the 45° rule of thumb of Sec. 1.10.

Postures that cannot be assembled leave gaps.  Every curve has a ``gid``
(``curve-omega-3``, ``path-E``, ``transmission-C``) so that tests and
stylesheets can find it in the SVG.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.10 (transmission angle), Sec. 2.13
(coupler curves), Secs. 3.4 and 4.3 (ω and α).
"""

from __future__ import annotations

import dataclasses
import math
import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from graphkin.errors import GraphkinError, InputError
from graphkin.mechanisms.model import FRAME
from graphkin.render.text import plain

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from graphkin.kinematics.sweep import Sweep

__all__ = ["ITEMS", "parse_what", "sweep_figure", "save_figure"]

ITEMS = ("angle", "omega", "alpha", "velocity", "acceleration", "path", "transmission",
         "center", "centrode", "torque")
"""What can be plotted (``item`` or ``item:which``)."""

_UNITS = {"angle": "°", "omega": "rad/s", "alpha": "rad/s²"}
_NAMES = {"angle": "θ", "omega": "ω", "alpha": "α"}


def parse_what(text: str | Sequence[str]) -> list[tuple[str, str | None]]:
    """Split ``"omega,alpha,path:E"`` into ``[("omega", None), ("alpha", None), ("path", "E")]``.

    Raises
    ------
    InputError
        An unknown item, or one that needs a point and has none.

    Examples
    --------
    >>> parse_what("omega, path:E")
    [('omega', None), ('path', 'E')]
    """
    parts = [p.strip() for p in (text.split(",") if isinstance(text, str) else text)]
    out: list[tuple[str, str | None]] = []
    for p in parts:
        if not p:
            continue
        item, _, which = p.partition(":")
        item = item.strip().lower()
        if item not in ITEMS:
            raise InputError(f"cannot plot {p!r}; valid: {', '.join(ITEMS)} "
                             "(path, velocity and acceleration take a point: path:E)", key="what")
        if item in ("path", "velocity", "acceleration") and not which.strip():
            raise InputError(f"{item} needs a point, as in {item}:E", key="what")
        if item == "center" and not which.strip():
            raise InputError("center needs an instant center, as in center:I24", key="what")
        if item == "centrode" and not which.strip():
            raise InputError("centrode needs a link, as in centrode:3", key="what")
        out.append((item, which.strip() or None))
    if not out:
        raise InputError("nothing to plot; valid: " + ", ".join(ITEMS), key="what")
    return out


def _drive_label(sw: Sweep) -> str:
    d = sw.drive
    if d.is_angle:
        return f"{d.label} (drive), °"
    return f"{d.label} (drive), {sw.mechanism.length_unit}"


def _segments(valid: np.ndarray) -> list[slice]:
    """Slices of consecutive True entries."""
    out = []
    start = None
    for i, v in enumerate(valid.tolist() + [False]):
        if v and start is None:
            start = i
        elif not v and start is not None:
            out.append(slice(start, i))
            start = None
    return out


def _unwrapped(deg: np.ndarray) -> np.ndarray:
    """Angles in degrees made continuous within each assembled run (NaN kept).

    Each run after a gap is shifted by whole turns to start nearest where the
    run before it ended.

    Examples
    --------
    >>> _unwrapped(np.array([170.0, -170.0, np.nan, -150.0]))
    array([170., 190.,  nan, 210.])
    """
    out = np.full_like(deg, np.nan)
    last = None
    for sl in _segments(np.isfinite(deg)):
        seg = np.degrees(np.unwrap(np.radians(deg[sl])))
        if last is not None:
            seg += 360.0 * np.round((last - seg[0]) / 360.0)
        out[sl] = seg
        last = seg[-1]
    return out


def _check_point(sw: Sweep, name: str) -> None:
    if name not in sw.mechanism.point_links:
        raise InputError(f"no point {name!r}; the points are "
                         f"{', '.join(sw.mechanism.point_names)}", key="what")


def _links(sw: Sweep, which: str | None) -> list[str]:
    if which is None:
        return list(sw.mechanism.moving)
    if which not in sw.mechanism.links:
        raise InputError(f"no link {which!r}; the links are {', '.join(sw.mechanism.links)}",
                         key="what")
    return [which]


def sweep_figure(sw: Sweep, what: str | Sequence[str], *, fig: Figure | None = None,
                 width: float = 6.0) -> Figure:
    """Plot curves over a sweep on one figure, one axes per item.

    Parameters
    ----------
    sw : Sweep
        From :func:`graphkin.kinematics.sweep.sweep` (for ``transmission``
        without the column, the angle is computed here).
    what : str or sequence of str
        Items as in :func:`parse_what`.
    fig : matplotlib.figure.Figure, optional
        Draw on this figure (cleared first); a new one otherwise.
    width : float
        Figure width in inches.

    Returns
    -------
    matplotlib.figure.Figure

    Raises
    ------
    InputError
        Unknown items, points or links; rates asked of a file without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 1.10, 2.13, 3.4, 4.3.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.crank_rocker()
    >>> fig = sweep_figure(mech.sweep(count=90), "omega,path:P")
    >>> [a.get_gid() for a in fig.axes]
    ['plot-omega', 'plot-path-P']
    """
    from matplotlib.figure import Figure

    items = parse_what(what)
    cols = sw.columns
    rated = "omega_" + FRAME in cols
    heights = [1.0 if item in ("path", "center", "centrode") else 0.55 for item, _ in items]
    if fig is None:
        fig = Figure(figsize=(width, width * sum(heights) * 0.75 + 0.3), layout="constrained")
    else:
        fig.clear()
    axes = fig.subplots(len(items), 1, squeeze=False, height_ratios=heights)[:, 0]
    x = np.asarray(cols["drive"], dtype=float)
    for ax, (item, which) in zip(axes, items):
        ax.set_gid(f"plot-{item}" + (f"-{which}" if which else ""))
        ax.grid(True, lw=0.4, alpha=0.5)
        if item in ("angle", "omega", "alpha"):
            if item != "angle" and not rated:
                raise InputError(f"{item} needs rates: the file gives none", key="what")
            for lid in _links(sw, which):
                y = np.asarray(cols[f"{item}_{lid}"], dtype=float)
                if item == "angle":
                    y = _unwrapped(y)
                (line,) = ax.plot(x, y, lw=1.2, label=f"{_NAMES[item]}{lid}")
                line.set_gid(f"curve-{item}-{lid}")
            if item != "angle":
                _clip_toggles(ax, x, [np.asarray(cols[f"{item}_{lid}"], dtype=float)
                                      for lid in _links(sw, which)])
            ax.set_ylabel(f"{_NAMES[item]}, {_UNITS[item]}")
            ax.set_xlabel(_drive_label(sw))
            ax.legend(loc="best", fontsize="small", frameon=False)
        elif item == "torque":  # the drive's torque over the cycle (graphkin.forces.sweep)
            from graphkin.forces.sweep import force_columns

            fc = {k: v for k, v in cols.items() if k.startswith(("torque_", "force_"))} \
                or force_columns(sw)
            mech = sw.mechanism
            for name, y in fc.items():
                kind, _, lid = name.partition("_")
                sym = f"T1{lid}" if kind == "torque" else f"F{lid}"
                (line,) = ax.plot(x, np.asarray(y, dtype=float), lw=1.2, label=sym)
                line.set_gid(f"curve-{name}")
            unit = f"{mech.force_unit}·{mech.length_unit}" if any(
                k.startswith("torque_") for k in fc) else mech.force_unit
            ax.set_ylabel(f"drive torque, {unit}")
            ax.set_xlabel(_drive_label(sw))
            ax.legend(loc="best", fontsize="small", frameon=False)
        elif item in ("velocity", "acceleration"):
            if not rated:
                raise InputError(f"{item} needs rates: the file gives none", key="what")
            assert which is not None
            _check_point(sw, which)
            k = "v" if item == "velocity" else "a"
            unit = sw.mechanism.length_unit + ("/s" if k == "v" else "/s²")
            guide = _guide(sw, which)
            if guide is not None:
                # a point that slides on the frame: its signed rate along the guide, so a
                # ram's cutting and return strokes read apart (Sec. 1.7)
                u, toward = guide
                y = np.asarray(cols[f"{k}x_{which}"], dtype=float) * u[0] \
                    + np.asarray(cols[f"{k}y_{which}"], dtype=float) * u[1]
                name = f"{k.upper()}_{which} along its guide (+ toward {toward})"
                zero = ax.axhline(0.0, lw=0.6, color="0.3")
                zero.set_gid(f"zero-{item}-{which}")
            else:
                y = np.hypot(cols[f"{k}x_{which}"], cols[f"{k}y_{which}"])
                name = f"|{k.upper()}_{which}|"
            (line,) = ax.plot(x, y, lw=1.2, label=name)
            line.set_gid(f"curve-{item}-{which}")
            ax.set_ylabel(f"{name}, {unit}" if guide is None else f"{k.upper()}_{which}, {unit}")
            if guide is not None:
                ax.legend(loc="best", fontsize="small", frameon=False)
            ax.set_xlabel(_drive_label(sw))
        elif item == "path":
            assert which is not None
            _path_panel(ax, sw, which, rated)
        elif item == "center":
            assert which is not None
            _center_path(ax, sw, which)
        elif item == "centrode":
            assert which is not None
            _centrodes(ax, sw, which)
        else:  # transmission
            tcols = {k: v for k, v in cols.items() if k.startswith("transmission_")}
            if not tcols:
                from graphkin.kinematics.sweep import _transmission_columns

                tcols = _transmission_columns(sw)
            if not tcols:
                raise InputError("no transmission angle: the mechanism has no pin found by two "
                                 "arcs", key="what")
            for name, y in tcols.items():
                pin = name.split("_", 1)[1]
                (line,) = ax.plot(x, y, lw=1.2, label=f"γ at {pin}")
                line.set_gid(f"transmission-{pin}")
            for g in (45.0, 135.0):
                guide = ax.axhline(g, lw=0.8, ls="--", color="0.5")
                guide.set_gid(f"guide-{g:g}")
            ax.set_ylim(0, 180)
            ax.set_ylabel("transmission angle γ, °")
            ax.set_xlabel(_drive_label(sw))
            ax.legend(loc="best", fontsize="small", frameon=False)
    for ax, (item, _which) in zip(axes, items):
        if item not in ("path", "center", "centrode"):
            _shade_unassembled(ax, x, cols)
            _mark_special(ax, sw, x)
    fig.suptitle(plain(sw.mechanism.title or "sweep"), fontsize="medium")
    _legends_off_the_curves(fig, [ax for ax, (item, _w) in zip(axes, items)
                                  if item not in ("path", "center", "centrode")])
    return fig


_CURVES = ("curve-", "transmission-")
"""The gids of the curves a legend over the drive must not cover."""


def legend_covers_curve(ax: Any, renderer: Any) -> bool:
    """Whether the legend of ``ax``, where it is drawn, covers a stretch of one of its curves.

    The curves are the lines whose gid starts ``curve-`` or ``transmission-``, as
    drawn (display coordinates, the gaps of postures that cannot be assembled left
    out), against the legend's box as laid out by ``renderer``.
    """
    from shapely import LineString, Point, box

    leg = ax.get_legend()
    if leg is None:
        return False
    b = leg.get_window_extent(renderer)
    frame = box(b.x0, b.y0, b.x1, b.y1)
    for line in ax.get_lines():
        if not str(line.get_gid() or "").startswith(_CURVES):
            continue
        xy = np.column_stack([np.asarray(line.get_xdata(), dtype=float),
                              np.asarray(line.get_ydata(), dtype=float)])
        ok = np.isfinite(xy).all(axis=1)
        for sl in _segments(ok):
            run = ax.transData.transform(xy[sl])
            if len(run) >= 2 and LineString(run).intersects(frame):
                return True
            if len(run) == 1 and frame.intersects(Point(run[0])):
                return True
    return False


def _legends_off_the_curves(fig: Any, axes: list[Any]) -> None:
    """Keep every legend of a plot over the drive off its curves (issue 24).

    Matplotlib's ``loc="best"`` picks the corner that covers least; when every
    corner covers some curve (three ω curves fill the axes), the legend goes out
    beside the axes, on the right, and the constrained layout makes room for it.
    """
    if not any(ax.get_legend() is not None for ax in axes):
        return
    fig.draw_without_rendering()  # the layout and each legend's "best" place
    renderer = fig._get_renderer()
    for ax in axes:
        leg = ax.get_legend()
        if leg is None:
            continue
        if legend_covers_curve(ax, renderer):
            handles, labels = ax.get_legend_handles_labels()
            leg = ax.legend(handles, labels, loc="upper left", bbox_to_anchor=(1.01, 1.0),
                            borderaxespad=0.0, fontsize="small", frameon=False)
        leg.set_gid("legend-" + str(ax.get_gid() or "plot").removeprefix("plot-"))


def _path_kind(sw: Sweep, name: str) -> str:
    """What the path of a point is called: a slider's position, a circle, a coupler curve.

    A point that runs on a line of the frame is a slider's point: its path is
    the position of that slider.  A point of a link pinned to the frame
    moves on a circle about the pivot.  Any other point of a moving link
    traces a coupler curve (Sec. 2.13).
    """
    mech = sw.mechanism
    for s in mech.sliders:
        if s.point == name and s.on == FRAME:
            return f"position of slider {s.link}"
    owners = [lid for lid in mech.point_links.get(name, []) if lid != FRAME]
    frame = mech.links[FRAME].points
    for lid in owners:
        pivots = [n for n in mech.links[lid].points if n in frame and n != name]
        if pivots:
            return f"circle about {pivots[0]}"
    if name in frame:
        return "fixed point"
    return "coupler curve"


def _path_panel(ax: Any, sw: Sweep, which: str, rated: bool) -> None:
    """The path of a point, framed around the curve, with the mechanism drawn faintly.

    The view is the curve's own extent and the mechanism's at the file's
    posture (with a margin), not the reach of every point over the cycle nor
    far construction points (Ball's point may lie outside); the mechanism
    stands in light grey at that posture, and a legend names the curve, its
    start, the mechanism and the fixed pivots.
    """
    _check_point(sw, which)
    cols = sw.columns
    px = np.asarray(cols[f"x_{which}"], dtype=float)
    py = np.asarray(cols[f"y_{which}"], dtype=float)
    kind = _path_kind(sw, which)
    (line,) = ax.plot(px, py, lw=1.4, label=plain(f"{kind} ({which})"), zorder=3)
    line.set_gid(f"path-{which}")
    ok = np.flatnonzero(np.isfinite(px) & np.isfinite(py))
    if ok.size:
        start = float(cols["drive"][ok[0]])
        unit = "°" if sw.drive.kind == "angle" else f" {sw.mechanism.length_unit}"
        sym = "θ" if sw.drive.kind == "angle" else "s"
        (m,) = ax.plot(px[ok[0]], py[ok[0]], "o", ms=4, zorder=4,
                       label=plain(f"start, {sym}{sw.drive.link} = {start:.4g}{unit}"))
        m.set_gid(f"path-{which}-start")
    posture = _faint_mechanism(ax, sw)
    frame = {n: q for n, q in sw.mechanism.links[FRAME].points.items()
             if n not in sw.mechanism.helper_points}  # a slider line's points are no pivots
    if frame:
        fx, fy = zip(*frame.values())
        (pivots,) = ax.plot(fx, fy, "^", ms=6, color="0.3", label="fixed pivots", zorder=4)
        pivots.set_gid("frame-pivots")
    if rated and ok.size:
        _curvature_marks(ax, sw, which, int(ok[0]))
    ax.set_aspect("equal", adjustable="box")
    if ok.size:
        # the curve and the mechanism at one posture: not every point's reach over the cycle
        xs = np.concatenate([px[ok], posture[:, 0]])
        ys = np.concatenate([py[ok], posture[:, 1]])
        x0, x1, y0, y1 = float(xs.min()), float(xs.max()), float(ys.min()), float(ys.max())
        pad = 0.08 * max(x1 - x0, y1 - y0) + 0.02 * sw.mechanism.size
        ax.set_xlim(x0 - pad, x1 + pad)
        ax.set_ylim(y0 - pad, y1 + pad)
    unit = sw.mechanism.length_unit
    ax.set_xlabel(f"x, {unit}")
    ax.set_ylabel(f"y, {unit}")
    ax.set_title(plain(f"path of {which}: {kind}"), fontsize="medium")
    ax.legend(loc="best", fontsize="small", frameon=True, framealpha=0.85)


def _faint_mechanism(ax: Any, sw: Sweep) -> np.ndarray:
    """The mechanism at the file's posture in light grey (each link the outline of its points).

    Returns the points drawn (an empty (0, 2) array when the posture cannot be assembled).
    """
    mech = sw.mechanism
    drawn: list[np.ndarray] = [np.zeros((0, 2))]
    try:
        sol = mech.solve()
    except GraphkinError:
        return drawn[0]  # the file's own posture cannot be assembled: the curve alone
    d = mech.drives[0] if mech.drives else None
    at = ""
    if d is not None:
        at = (f" (θ{d.link} = {np.degrees(d.value):.4g}°)" if d.kind == "angle"
              else f" (s{d.link} = {d.value:.4g} {mech.length_unit})")
    first = True
    for lid in mech.moving:
        names = [n for n in mech.links[lid].points if n not in mech.helper_points]
        pts = np.array([sol.position(n, lid) for n in names], dtype=float)
        if not len(pts) or not np.all(np.isfinite(pts)):
            continue
        if len(pts) >= 3:
            from shapely.geometry import MultiPoint

            hull = MultiPoint([tuple(p) for p in pts]).convex_hull
            if hull.geom_type == "Polygon":
                pts = np.asarray(hull.exterior.coords)
        (ln,) = ax.plot(pts[:, 0], pts[:, 1], "-o", color="0.72", lw=2.0, ms=3.5, mfc="white",
                        zorder=1, label=plain(f"mechanism{at}") if first else None)
        ln.set_gid(f"mechanism-link-{lid}")
        drawn.append(pts)
        first = False
    for s in mech.sliders:
        q = np.asarray(sol.position(s.point, s.link), dtype=float)
        (blk,) = ax.plot(*q, "s", ms=8, mfc="white", mec="0.6", zorder=1)
        blk.set_gid(f"mechanism-slider-{s.link}")
    return np.vstack(drawn)


def _clip_toggles(ax: Any, x: np.ndarray, ys: list[np.ndarray]) -> None:
    """Clip rate curves that run away near a toggle (Sec. 1.10) and mark where they do.

    A sample farther than 20 times the median size from zero is near a
    toggle: the axis keeps the range of the others and a dotted line marks it.
    """
    y = np.concatenate([v[np.isfinite(v)] for v in ys]) if ys else np.zeros(0)
    if y.size < 5:
        return
    typical = float(np.median(np.abs(y)))
    if typical == 0:
        return
    wild = np.zeros_like(x, dtype=bool)
    for v in ys:
        own = float(np.nanmedian(np.abs(v))) if np.isfinite(v).any() else 0.0
        with np.errstate(invalid="ignore"):
            wild |= np.abs(v) > 20 * max(own, 1e-300)
    if not wild.any():
        return
    tame = np.concatenate([v[np.isfinite(v) & ~wild] for v in ys])
    if tame.size:
        lo, hi = float(tame.min()), float(tame.max())
        pad = 0.15 * max(hi - lo, typical)
        ax.set_ylim(lo - pad, hi + pad)
    first = True
    for sl in _segments(wild):
        at = float(np.mean(x[sl]))
        mark = ax.axvline(at, ls=":", lw=1.0, color="0.3",
                          label="near a toggle (clipped)" if first else None)
        mark.set_gid(f"toggle-{at:g}")
        first = False
    ax.legend(loc="best", fontsize="small", frameon=False)


def _guide(sw: Sweep, name: str) -> tuple[np.ndarray, str] | None:
    """The unit direction of the frame line a point slides on, and what its + end is toward.

    A point of a link that slides on the frame (a piston, a ram) moves along
    the slider's line; None for any other point.
    """
    mech = sw.mechanism
    for s in mech.sliders:
        if s.on != FRAME or name not in mech.links[s.link].points:
            continue
        d = np.array([s.p1[0] - s.p0[0], s.p1[1] - s.p0[1]], dtype=float)
        n = float(np.hypot(*d))
        if n <= 0:
            continue
        toward = next((q for q, xy in mech.links[FRAME].points.items()
                       if tuple(map(float, xy)) == tuple(map(float, s.p1))
                       and q in mech.helper_points), "")
        deg = math.degrees(math.atan2(d[1], d[0]))
        return d / n, (toward or f"{deg:.0f}°")
    return None


def _mark_special(ax: Any, sw: Sweep, x: np.ndarray) -> None:
    """Limit positions and dead centers (Sec. 1.10) as dotted lines across a plot over the drive."""
    if len(x) < 2:
        return
    lo, hi = float(np.nanmin(x)), float(np.nanmax(x))
    seen: set[str] = set()
    for sp in getattr(sw, "singular", ()):
        if sp.kind not in ("limit", "dead-center"):
            continue
        v = float(sp.drive)
        if sw.drive.is_angle:  # the same posture a turn on, where the axis shows it
            v = lo + (v - lo) % 360.0
        if not lo - 1e-9 <= v <= hi + 1e-9:
            continue
        what = "limit position" if sp.kind == "limit" else "dead center"
        color = "#1565c0" if sp.kind == "limit" else "#c62828"
        line = ax.axvline(v, lw=0.9, ls=":", color=color,
                          label=what if what not in seen else None)
        line.set_gid(f"{sp.kind}-{v:g}")
        if sp.kind == "limit" and sp.end is not None:   # held through a dwell: a band
            w = float(sp.end) - float(sp.drive)
            ax.axvline(v + w, lw=0.9, ls=":", color=color).set_gid(f"{sp.kind}-end-{v + w:g}")
            ax.axvspan(min(v, v + w), max(v, v + w), color=color, alpha=0.08, lw=0)
        seen.add(what)
    if seen:
        ax.legend(loc="best", fontsize="small", frameon=False)


def _shade_unassembled(ax: Any, x: np.ndarray, cols: Any) -> None:
    """Shade and name the drive angles where the linkage cannot be assembled."""
    angles = [np.asarray(v, dtype=float) for k, v in cols.items() if k.startswith("angle_")]
    if not angles:
        return
    bad = ~np.all(np.isfinite(np.vstack(angles)), axis=0)
    first = True
    for sl in _segments(bad):
        i0, i1 = sl.start, sl.stop - 1
        a = float(x[max(i0 - 1, 0)]) if i0 > 0 else float(x[i0])
        b = float(x[min(i1 + 1, len(x) - 1)])
        span = ax.axvspan(a, b, color="0.85", zorder=0,
                          label="cannot be assembled" if first else None)
        span.set_gid(f"unassembled-{a:g}")
        first = False
    if not first:
        ax.legend(loc="best", fontsize="small", frameon=False)


def _to_frame(sw: Sweep, lid: str, k: np.ndarray | int, local: np.ndarray) -> np.ndarray:
    """World position, at posture(s) ``k``, of the body point of ``lid`` at ``local``."""
    cols, link = sw.columns, sw.mechanism.links[lid]
    name, (lx, ly) = next(iter(link.points.items()))
    th = np.radians(np.asarray(cols[f"angle_{lid}"], dtype=float)[k])
    c, s = np.cos(th), np.sin(th)
    ox = np.asarray(cols[f"x_{name}"], dtype=float)[k] - (c * lx - s * ly)
    oy = np.asarray(cols[f"y_{name}"], dtype=float)[k] - (s * lx + c * ly)
    x, y = local[..., 0], local[..., 1]
    return np.stack([ox + c * x - s * y, oy + s * x + c * y], axis=-1)


def _to_link(sw: Sweep, lid: str, world: np.ndarray) -> np.ndarray:
    """Coordinates in ``lid``'s own frame of world points, one per posture."""
    cols, link = sw.columns, sw.mechanism.links[lid]
    name, (lx, ly) = next(iter(link.points.items()))
    th = np.radians(np.asarray(cols[f"angle_{lid}"], dtype=float))
    c, s = np.cos(th), np.sin(th)
    ox = np.asarray(cols[f"x_{name}"], dtype=float) - (c * lx - s * ly)
    oy = np.asarray(cols[f"y_{name}"], dtype=float) - (s * lx + c * ly)
    dx, dy = world[..., 0] - ox, world[..., 1] - oy
    return np.stack([c * dx + s * dy, -s * dx + c * dy], axis=-1)


def _pole_path(sw: Sweep, i: str, j: str) -> np.ndarray:
    """The instant center Iij at every posture (NaN where not assembled or at infinity)."""
    cols = sw.columns
    key = f"I{i}{j}" if len(i) == 1 and len(j) == 1 else f"I{i}-{j}"
    if f"x_{key}" not in cols:
        from graphkin.kinematics.sweep import sweep as _sweep

        sw2 = _sweep(sw.mechanism, count=len(cols["drive"]), start=float(cols["drive"][0]),
                     stop=None if len(cols["drive"]) < 2 else
                     float(cols["drive"][0]) + len(cols["drive"]) * float(
                         cols["drive"][1] - cols["drive"][0]), centers=True)
        cols = sw2.columns
        if f"x_{key}" not in cols:
            raise InputError(f"no instant center {key} in this mechanism", key="what")
    return np.stack([np.asarray(cols[f"x_{key}"], dtype=float),
                     np.asarray(cols[f"y_{key}"], dtype=float)], axis=-1)


def _pair(text: str) -> tuple[str, str]:
    t = text.strip().upper().lstrip("I")
    i, _, j = t.partition("-") if "-" in t else (t[:1], "", t[1:])
    if not i or not j:
        raise InputError(f"cannot read the instant center {text!r}; write I24 or I1-13",
                         key="what")
    a, b = sorted((i, j), key=lambda x: (len(x), x))
    return a, b


def _view(ax: Any, sw: Sweep, margin: float = 1.0) -> None:
    """Limit a to-scale plot to the mechanism's own region, widened by ``margin`` times its size.

    Instant centers run off to infinity where two links turn alike; the view
    stays on the mechanism rather than following them.
    """
    cols = sw.columns
    xs = [np.asarray(cols[f"x_{n}"], dtype=float) for n in sw.mechanism.point_names]
    ys = [np.asarray(cols[f"y_{n}"], dtype=float) for n in sw.mechanism.point_names]
    x, y = np.concatenate(xs), np.concatenate(ys)
    x, y = x[np.isfinite(x)], y[np.isfinite(y)]
    if not x.size:
        return
    size = max(float(np.ptp(x)), float(np.ptp(y)), 1e-12)
    cx, cy = (x.min() + x.max()) / 2, (y.min() + y.max()) / 2
    half = size * (0.5 + margin)
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlim(cx - half, cx + half)
    ax.set_ylim(cy - half, cy + half)


def _broken(pts: np.ndarray, sw: Sweep) -> np.ndarray:
    """A polyline with a gap wherever it jumps through infinity (a pole running off)."""
    cols = sw.columns
    xs = np.concatenate([np.asarray(cols[f"x_{n}"], dtype=float)
                         for n in sw.mechanism.point_names])
    size = float(np.nanmax(np.abs(xs))) if np.isfinite(xs).any() else 1.0
    out = np.array(pts, dtype=float)
    jump = np.hypot(*np.diff(out, axis=0).T) > 20 * max(size, 1e-12)
    out[1:][jump] = np.nan
    return out


def _center_path(ax: Any, sw: Sweep, which: str) -> None:
    """The path of an instant center over the sweep (Sec. 3.20: I1k traces the fixed centrode)."""
    i, j = _pair(which)
    pts = _broken(_pole_path(sw, i, j), sw)
    name = f"I{i}{j}" if len(i) == 1 and len(j) == 1 else f"I{i}-{j}"   # I24, I7-12
    (line,) = ax.plot(pts[:, 0], pts[:, 1], lw=1.2, label=name)
    line.set_gid(f"center-{name}")
    _view(ax, sw)
    unit = sw.mechanism.length_unit
    ax.set_xlabel(f"x, {unit}")
    ax.set_ylabel(f"y, {unit}")
    ax.set_title(f"path of the instant center {name}", fontsize="medium")


def _centrodes(ax: Any, sw: Sweep, lid: str) -> None:
    """The fixed and moving centrodes of link ``lid`` (Sec. 3.20).

    The fixed centrode is the path of the velocity pole I1k in the frame; the
    moving centrode is the path of the same pole in the link's own coordinates,
    drawn where the link stands at the first posture, so that the two touch at
    that posture's pole and roll on each other without slip.
    """
    if lid not in sw.mechanism.links or lid == FRAME:
        raise InputError(f"no moving link {lid!r} for a centrode", key="what")
    fixed = _pole_path(sw, FRAME, lid)
    ok = np.flatnonzero(np.all(np.isfinite(fixed), axis=-1))
    if not ok.size:
        raise InputError(f"link {lid} has no finite velocity pole over this sweep", key="what")
    local = _to_link(sw, lid, fixed)
    moving = _to_frame(sw, lid, int(ok[0]), local)
    fb, mb = _broken(fixed, sw), _broken(moving, sw)
    (f,) = ax.plot(fb[:, 0], fb[:, 1], lw=1.4, label="fixed centrode")
    f.set_gid(f"centrode-fixed-{lid}")
    (m,) = ax.plot(mb[:, 0], mb[:, 1], lw=1.4, ls="--", label="moving centrode")
    m.set_gid(f"centrode-moving-{lid}")
    (p,) = ax.plot(*fixed[ok[0]], "o", ms=4, color="0.2")
    p.set_gid(f"centrode-pole-{lid}")
    ax.annotate(f"I1{lid}" if len(lid) == 1 else f"I1-{lid}", fixed[ok[0]],
                textcoords="offset points", xytext=(4, 4), fontsize="small")
    _view(ax, sw)
    unit = sw.mechanism.length_unit
    ax.set_xlabel(f"x, {unit}")
    ax.set_ylabel(f"y, {unit}")
    ax.legend(loc="best", fontsize="small", frameon=False)
    ax.set_title(f"centrodes of link {lid}", fontsize="medium")


def _curvature_marks(ax: Any, sw: Sweep, name: str, k: int) -> None:
    """On a coupler curve: the osculating circle at posture ``k`` and Ball's point's path.

    ρ = |V|³/|V × A| and the center of curvature lies along the normal toward
    which the path turns (Sec. 4.11); Ball's point of the point's link, where
    the curvature is stationary to third order (Sec. 4.17), is marked with its
    own path.
    """
    cols = sw.columns
    v = np.array([cols[f"vx_{name}"][k], cols[f"vy_{name}"][k]], dtype=float)
    a = np.array([cols[f"ax_{name}"][k], cols[f"ay_{name}"][k]], dtype=float)
    pnt = np.array([cols[f"x_{name}"][k], cols[f"y_{name}"][k]], dtype=float)
    cross = float(v[0] * a[1] - v[1] * a[0])
    speed = float(np.hypot(*v))
    if speed > 0 and cross != 0:
        rho = speed**3 / abs(cross)
        normal = np.array([-v[1], v[0]]) / speed * np.sign(cross)
        center = pnt + rho * normal
        from matplotlib.patches import Circle

        circ = Circle(tuple(center), rho, fill=False, lw=0.8, ls=":", color="0.4")
        circ.set_gid(f"path-{name}-osculating")
        ax.add_patch(circ)
    owners = [lid for lid in sw.mechanism.point_links[name] if lid != FRAME]
    if not owners:
        return
    lid = owners[0]
    from graphkin.kinematics.curvature import link_curvature

    mech, d = sw.mechanism, sw.mechanism.drives[0]
    at = float(cols["drive"][k])
    moved = dataclasses.replace(d, value=np.radians(at) if d.is_angle else at)
    try:
        sol = dataclasses.replace(mech, drives=(moved, *mech.drives[1:])).solve()
        ball = link_curvature(sol, lid).ball_point
    except GraphkinError:
        return
    if ball is None or not np.all(np.isfinite(ball)):
        return
    n = len(cols["drive"])
    local = _to_link(sw, lid, np.broadcast_to(np.asarray(ball, dtype=float), (n, 2)))[k]
    # Ball's point moves on an almost straight line near this posture: draw that stretch
    near = np.arange(max(0, k - n // 12), min(n, k + n // 12 + 1))
    track = _to_frame(sw, lid, near, np.asarray(local))
    (u,) = ax.plot(track[:, 0], track[:, 1], lw=0.9, color="0.45", label="Ball's point")
    u.set_gid(f"path-{name}-ball-point")
    (mark,) = ax.plot(*np.asarray(ball, dtype=float), "s", ms=4, color="0.2")
    mark.set_gid(f"ball-point-{lid}")
    ax.annotate("U", np.asarray(ball, dtype=float), textcoords="offset points",
                xytext=(4, 4), fontsize="small")


def save_figure(fig: Figure, path: str | os.PathLike[str]) -> Path:
    """Save deterministically (SVG ids salted, no date, text as text); the suffix picks the format.

    Returns
    -------
    Path
    """
    from graphkin.render.svg import save

    return save(fig, path)
