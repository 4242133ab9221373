"""The tooth outline re-cut by the mate's tips where the teeth interfere (Sec. 7.7, Fig. 7.18).

"When gear teeth are produced by a generating process, interference is
automatically eliminated, since the cutting tool removes the interfering
portion of the tooth flank" (Sec. 7.7).  :func:`recut_template` takes the
mate as that tool: the tooth of the cut gear that stands at P, less every
position of the mate's teeth near P as the pair turns through two pitches
each way (the rolling of the layout, gear 2 clockwise; a rack translating
``R_2`` per radian), by shapely's boolean difference.  Every tooth is the
same, so the one re-cut tooth is returned as a template, polar about its
center and relative to its phase, for :func:`graphkin.gears.profile.gear_teeth`.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 7.7 (Figs. 7.18, 7.25).
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import Polygon

from graphkin.gears.mesh import MeshLayout
from graphkin.gears.profile import FLANK, LAND, mesh_phases, rack_teeth, tooth_template

__all__ = ["recut_template", "MOTION_STEPS", "AREA_FLOOR"]

MOTION_STEPS = 241
"""Positions of the mate through four pitches of the cut gear."""

AREA_FLOOR = 1e-6
"""Less removed than this many square modules is no undercut: the flank polylines' chords."""


def _polar_to_xy(tpl: np.ndarray, center: np.ndarray, phase: float) -> np.ndarray:
    th = tpl[:, 1] + phase
    return np.stack([center[0] + tpl[:, 0] * np.cos(th), center[1] + tpl[:, 0] * np.sin(th)],
                    axis=-1)


def _mate_teeth(lay: MeshLayout, cut: int) -> tuple[np.ndarray, np.ndarray | None]:
    """The mate's teeth near P as closed outlines ``(K, n, 2)``, and its center (None: a rack)."""
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    ra2, ra3 = pair.outside_radii
    psi2, psi3 = mesh_phases(pair)
    if cut == 2 and g3.rack:
        side = 1.0 if lay.points["A"][0] >= lay.points["P"][0] else -1.0
        span = 3.0 * g3.circular_pitch + 2.0 * math.pi * g2.pitch_radius / g2.teeth * 2.0
        teeth = rack_teeth(g3, (-span, span), side)
        n = FLANK - 1   # each tooth: its two flanks and top land, closed along the bottom
        return teeth[:, : 3 * n + 1], None
    mate, ra, psi, o = ((g3, ra3, psi3, lay.points["O3"]) if cut == 2
                        else (g2, ra2, psi2, lay.points["O2"]))
    tpl = tooth_template(mate, ra)
    tooth = tpl[: -(LAND - 1)]   # without its bottom land: closed along its root chord
    center = np.array(o)
    out = []
    for k in range(-3, 4):
        out.append(_polar_to_xy(tooth, center, psi + 2.0 * math.pi * k / mate.teeth))
    return np.array(out), center


def recut_template(lay: MeshLayout, cut: int) -> np.ndarray | None:
    """The tooth of gear ``cut`` (2 or 3) re-cut by its mate, polar ``(r, θ − ψ)``; None if uncut.

    Parameters
    ----------
    lay : MeshLayout
    cut : int
        2: the driver's tooth, cut by the driven gear's (or the rack's) tips
        where contact begins before A; 3: the driven gear's, after B.

    Returns
    -------
    numpy.ndarray or None
        The outline in the order of :func:`graphkin.gears.profile.tooth_template`
        (up a flank, over the top land, down, along the bottom land), or None
        when the mate removes nothing above round-off (no interference).
    """
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    gear = g2 if cut == 2 else g3
    if gear.rack or gear.internal:
        return None
    ra = pair.outside_radii[cut - 2]
    psi = mesh_phases(pair)[cut - 2]
    o = np.array(lay.points[f"O{cut}"])
    tpl = tooth_template(gear, ra)
    pitch = 2.0 * math.pi / gear.teeth
    own = Polygon(np.vstack([[o], _polar_to_xy(tpl, o, psi)]))
    mate, mate_center = _mate_teeth(lay, cut)
    th = np.linspace(-2.0 * pitch, 2.0 * pitch, MOTION_STEPS)   # the cut gear's turn
    # the mate's motion while the cut gear turns by th (2 clockwise: θ2 = −th)
    if cut == 2:
        rot_cut = -th
        if mate_center is None:     # the rack moves −R2 th along its pitch line
            shift = np.stack([-g2.pitch_radius * th, np.zeros_like(th)], axis=-1)
            moved = mate[None] + shift[:, None, None, :]
        else:
            k = g2.teeth / g3.teeth * (-1.0 if g3.internal else 1.0)
            moved = _turned(mate, mate_center, k * th, batched=False)
    else:
        rot_cut = g2.teeth / g3.teeth * th
        moved = _turned(mate, np.array(lay.points["O2"]), -th, batched=False)
    # into the cut gear's frame: turn back by its own rotation about its center
    rel = _turned(moved, o, -rot_cut, batched=True)
    polys = [Polygon(t) for pos in rel for t in pos]
    swept = shapely.union_all([p.buffer(0) for p in polys])
    left = own.difference(swept)
    if own.area - left.area <= AREA_FLOOR * gear.module ** 2:
        return None
    piece = max(getattr(left, "geoms", [left]), key=lambda g: g.area)
    xy = np.asarray(piece.exterior.coords)[:-1]
    rel_xy = xy - o
    r = np.hypot(rel_xy[:, 0], rel_xy[:, 1])
    ang = (np.arctan2(rel_xy[:, 1], rel_xy[:, 0]) - psi + math.pi / 2) % (2 * math.pi) \
        - math.pi / 2
    at_center = int(np.argmin(r))
    order = np.roll(np.arange(len(r)), -at_center)[1:]   # start after the center vertex
    r, ang = r[order], ang[order]
    if ang[0] > ang[-1]:
        r, ang = r[::-1], ang[::-1]
    return np.stack([r, ang], axis=-1)


def _turned(pts: np.ndarray, c: np.ndarray, th: np.ndarray, *, batched: bool) -> np.ndarray:
    """``pts`` turned about ``c`` by each angle of ``th``.

    ``batched``: ``pts`` is ``(T, ..., 2)``, position t turned by ``th[t]``;
    else ``pts`` is ``(..., 2)`` and the result ``(T, ..., 2)``.
    """
    d = pts - c
    extra = d.ndim - 2 if batched else d.ndim - 1
    shape = (-1,) + (1,) * extra
    cos, sin = np.cos(th).reshape(shape), np.sin(th).reshape(shape)
    return np.stack([c[0] + cos * d[..., 0] - sin * d[..., 1],
                     c[1] + sin * d[..., 0] + cos * d[..., 1]], axis=-1)
