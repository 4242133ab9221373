"""Curves over a sweep: angles, rates, coupler curves and the transmission angle.

Each item of ``what`` is drawn on its own axes of one
:class:`matplotlib.figure.Figure` (no pyplot state):

* ``angle``, ``omega``, ``alpha``: every moving link's θ (degrees, unwrapped
  so the curve is continuous), ω (rad/s) or α (rad/s²) over the drive;
  ``angle:3``, ``omega:4`` for one link;
* ``velocity:P``, ``acceleration:P``: the magnitude of a point's velocity or
  acceleration over the drive;
* ``path:P``: the path of a point (a coupler curve), drawn to scale;
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

import os
from collections.abc import Sequence
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from graphkin.errors import InputError
from graphkin.mechanisms.model import FRAME

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from graphkin.kinematics.sweep import Sweep

__all__ = ["ITEMS", "parse_what", "sweep_figure", "save_figure"]

ITEMS = ("angle", "omega", "alpha", "velocity", "acceleration", "path", "transmission")
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
        out.append((item, which.strip() or None))
    if not out:
        raise InputError("nothing to plot; valid: " + ", ".join(ITEMS), key="what")
    return out


def _drive_label(sw: Sweep) -> str:
    d = sw.drive
    if d.kind == "angle":
        return f"θ{d.link} (drive), °"
    return f"s{d.link} (drive), {sw.mechanism.length_unit}"


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
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [12, 0]
    ... E = [6, -3]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... omega = 10
    ... [assembly]
    ... C = [9, 11]
    ... ''')
    >>> fig = sweep_figure(mech.sweep(count=90), "omega,path:E")
    >>> [a.get_gid() for a in fig.axes]
    ['plot-omega', 'plot-path-E']
    """
    from matplotlib.figure import Figure

    items = parse_what(what)
    cols = sw.columns
    rated = "omega_" + FRAME in cols
    heights = [1.0 if item == "path" else 0.55 for item, _ in items]
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
            ax.set_ylabel(f"{_NAMES[item]}, {_UNITS[item]}")
            ax.set_xlabel(_drive_label(sw))
            ax.legend(loc="best", fontsize="small", frameon=False)
        elif item in ("velocity", "acceleration"):
            if not rated:
                raise InputError(f"{item} needs rates: the file gives none", key="what")
            assert which is not None
            _check_point(sw, which)
            k = "v" if item == "velocity" else "a"
            y = np.hypot(cols[f"{k}x_{which}"], cols[f"{k}y_{which}"])
            (line,) = ax.plot(x, y, lw=1.2, label=f"|{k.upper()}_{which}|")
            line.set_gid(f"curve-{item}-{which}")
            unit = sw.mechanism.length_unit + ("/s" if k == "v" else "/s²")
            ax.set_ylabel(f"|{k.upper()}_{which}|, {unit}")
            ax.set_xlabel(_drive_label(sw))
        elif item == "path":
            assert which is not None
            _check_point(sw, which)
            px = np.asarray(cols[f"x_{which}"], dtype=float)
            py = np.asarray(cols[f"y_{which}"], dtype=float)
            (line,) = ax.plot(px, py, lw=1.2, label=f"path of {which}")
            line.set_gid(f"path-{which}")
            ok = np.flatnonzero(np.isfinite(px) & np.isfinite(py))
            if ok.size:
                (m,) = ax.plot(px[ok[0]], py[ok[0]], "o", ms=4)
                m.set_gid(f"path-{which}-start")
            frame = sw.mechanism.links[FRAME].points
            if frame:
                fx, fy = zip(*frame.values())
                (pivots,) = ax.plot(fx, fy, "^", ms=6, color="0.3")
                pivots.set_gid("frame-pivots")
            ax.set_aspect("equal", adjustable="datalim")
            unit = sw.mechanism.length_unit
            ax.set_xlabel(f"x, {unit}")
            ax.set_ylabel(f"y, {unit}")
            ax.set_title(f"path of {which} (coupler curve)", fontsize="medium")
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
    fig.suptitle(sw.mechanism.title or "sweep", fontsize="medium")
    return fig


def save_figure(fig: Figure, path: str | os.PathLike[str]) -> Path:
    """Save deterministically (SVG ids salted, no date, text as text); the suffix picks the format.

    Returns
    -------
    Path
    """
    from graphkin.render.svg import save

    return save(fig, path)
