"""The teeth of a gear as outlines to draw: involute flanks, top and bottom lands (Sec. 7.5).

A tooth centred on the polar angle ψ has its flanks at ``ψ ± β(r)`` where
``β(r) = t_p / 2R + inv φ − inv ϕ(r)`` is its angular half-thickness
(Sec. 7.10, Eq. d); inside the base circle the flank is carried down to the
dedendum circle by a radial line (Step 6: "this portion of the curve is not
involute"; the fillet and any undercut are not drawn).  The top land is an
arc of the addendum circle, the bottom land an arc of the dedendum circle
(Step 8).  One template tooth is computed and turned to every tooth's
angle with numpy: no loop over teeth.

:func:`mesh_phases` sets the two gears of a pair as in Fig. 7.9: the
driving flank of a tooth of 2 and the driven flank of a tooth of 3 touch at
the pitch point P.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.5 (Steps 6-8), 7.10.
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.gears.mesh import GearPair
from graphkin.gears.tooth import Gear

__all__ = ["tooth_template", "gear_teeth", "mesh_phases", "tip_path", "rack_teeth", "ring_overlap",
           "TIP_SAMPLES"]

TIP_SAMPLES = 241
"""Points along a tip's path relative to the other gear."""

FLANK = 24
"""Points along each involute flank."""
LAND = 8
"""Points along each top or bottom land."""


def tooth_template(g: Gear, outside: float) -> np.ndarray:
    """One tooth centred on the polar angle 0, with the bottom land to the next tooth.

    Returns
    -------
    numpy.ndarray
        ``(n, 2)`` polar coordinates ``(r, θ)``: up the flank at ``−β``
        (the clockwise side), across the top land, down the flank at ``+β``,
        and along the bottom land to ``2π/N − β`` (where the next tooth starts).
    """
    if g.internal:
        return _ring_tooth(g, outside)
    rb, rr = g.base_radius, g.root_radius
    tip = min(outside, g.pointed_radius())
    lo = max(rb, rr)
    if tip <= lo:   # no involute above the root: a tooth of radial lines
        lo = tip
    r = np.linspace(lo, tip, FLANK)
    beta = np.asarray(g.half_angle(r), dtype=float)
    if rr < rb:   # the radial line from the dedendum circle up to the base circle
        r = np.concatenate([[rr], r])
        beta = np.concatenate([[beta[0]], beta])
    up = np.stack([r, -beta], axis=-1)
    top_t = np.linspace(-beta[-1], beta[-1], LAND)[1:-1]
    top = np.stack([np.full_like(top_t, tip), top_t], axis=-1)
    down = np.stack([r[::-1], beta[::-1]], axis=-1)
    pitch = 2.0 * math.pi / g.teeth
    root_t = np.linspace(beta[0], pitch - beta[0], LAND)[1:]
    bottom = np.stack([np.full_like(root_t, rr), root_t], axis=-1)
    return np.concatenate([up, top, down, bottom])


def _ring_tooth(g: Gear, inside: float) -> np.ndarray:
    """One tooth of an internal gear (Fig. 7.11): its tip on the addendum circle ``inside``.

    The teeth point inward and widen outward, ``β'(r) = π/N − β(r)``
    (:meth:`Gear.half_angle`): from the dedendum circle (outside) down the
    flank at ``−β'`` to the tip, across the top land, back up the flank at
    ``+β'`` and along the bottom land to the next tooth.  The whole flank lies
    outside the base circle (the file refuses a ring whose tips do not).
    """
    rr = g.root_radius
    r = np.linspace(rr, inside, FLANK)
    beta = np.asarray(g.half_angle(r), dtype=float)
    down = np.stack([r, -beta], axis=-1)
    top_t = np.linspace(-beta[-1], beta[-1], LAND)[1:-1]
    top = np.stack([np.full_like(top_t, inside), top_t], axis=-1)
    up = np.stack([r[::-1], beta[::-1]], axis=-1)
    pitch = 2.0 * math.pi / g.teeth
    root_t = np.linspace(beta[0], pitch - beta[0], LAND)[1:]
    bottom = np.stack([np.full_like(root_t, rr), root_t], axis=-1)
    return np.concatenate([down, top, up, bottom])


def gear_teeth(g: Gear, outside: float, center: tuple[float, float], phase: float,
               template: np.ndarray | None = None) -> np.ndarray:
    """Every tooth of a gear, shape ``(N, n, 2)`` in Cartesian coordinates.

    Parameters
    ----------
    g : Gear
    outside : float
        The addendum-circle radius as cut.
    center : (float, float)
        The gear's center.
    phase : float
        The polar angle of the center line of tooth 0 (radians).
    template : numpy.ndarray, optional
        One tooth, polar as :func:`tooth_template` gives it (a tooth re-cut
        by its mate, :mod:`graphkin.render.gears_recut`); by default the
        involute tooth.
    """
    tpl = tooth_template(g, outside) if template is None else template
    angles = phase + 2.0 * math.pi * np.arange(g.teeth) / g.teeth
    th = tpl[None, :, 1] + angles[:, None]
    r = np.broadcast_to(tpl[None, :, 0], th.shape)
    return np.stack([center[0] + r * np.cos(th), center[1] + r * np.sin(th)], axis=-1)


def rack_teeth(g: Gear, x_range: tuple[float, float], side: float = 1.0) -> np.ndarray:
    """The teeth of a rack below a pinion, its pitch line the x axis (Sec. 7.5, Fig. 7.10).

    Straight flanks at φ from the line of centers, the tooth ``p/2`` thick on
    the pitch line, its top land on the addendum line ``y = a`` (toward the
    pinion) and its bottom land on the dedendum line ``y = −d``.  The tooth in
    mesh at P has its flank through P, the tooth itself on the side ``−side``
    of P (``side``: the sign of x of A, where the line of action leaves P
    toward the pinion; the flank is normal to the line of action).

    Returns
    -------
    numpy.ndarray
        ``(K, n, 2)``: every tooth whose pitch lies in ``x_range``, up one
        flank, across the top land, down the other flank and along the bottom
        land to the next tooth.
    """
    p, a, d = g.circular_pitch, g.addendum, g.dedendum
    tan = math.tan(g.pressure_angle)
    wb = p / 4.0 + d * tan
    wt, top = p / 4.0 - a * tan, a
    if wt < 0.0:   # the flanks meet below the addendum line: a pointed tooth
        wt, top = 0.0, p / (4.0 * tan)
    corners = np.array([[-wb, -d], [-wt, top], [wt, top], [wb, -d], [p - wb, -d]])
    t = np.linspace(0.0, 1.0, FLANK)[:-1, None]
    tpl = np.concatenate([c0 + t * (c1 - c0) for c0, c1 in zip(corners[:-1], corners[1:])]
                         + [corners[-1:]])
    x0 = -side * p / 4.0
    k = np.arange(math.floor((x_range[0] - x0) / p) - 1, math.ceil((x_range[1] - x0) / p) + 2)
    out = np.broadcast_to(tpl, (k.size, *tpl.shape)).copy()
    out[..., 0] += (x0 + k * p)[:, None]
    return out


def mesh_phases(pair: GearPair) -> tuple[float, float]:
    """The tooth phases ψ2, ψ3 of the layout of :func:`graphkin.gears.mesh.mesh_construction`.

    Gear 2 (above, clockwise) drives with the clockwise flank of a tooth,
    ``ψ2 − β2(R'_2) = −90°`` at P; gear 3 (below) is driven on the clockwise
    flank of its tooth, ``ψ3 − β3(R'_3) = 90°``.  The two flanks are tangent
    at P, their common normal the line of action.
    """
    r2p, r3p = pair.operating_pitch_radii
    b2 = float(pair.driver.half_angle(r2p))
    if pair.driven.rack:   # the rack's teeth are placed by :func:`rack_teeth`, not by a phase
        return -math.pi / 2 + b2, 0.0
    b3 = float(pair.driven.half_angle(r3p))
    if pair.driven.internal:   # O3 above P too: the ring's tooth left of P, its flank at P
        return -math.pi / 2 + b2, -math.pi / 2 - b3
    return -math.pi / 2 + b2, math.pi / 2 + b3


def tip_path(pair: GearPair, points: dict[str, tuple[float, float]], cutter: int
             ) -> np.ndarray:
    """The path of a tooth tip of gear ``cutter`` relative to the other gear (Fig. 7.18).

    Where the teeth interfere (Sec. 7.7), the tip corner of the tooth in mesh
    at P sweeps through the other gear's flank inside its base circle; a
    generating cutter shaped like it removes that material: the undercut.
    The gears turn as in the layout (2 clockwise, 3 with ``ω3/ω2 = ∓N2/N3``);
    the path is written in the other gear's frame at the drawn posture,
    ``p = O_o + R(−θ_o)(O_c + R(θ_c)(q − O_c) − O_o)``, over the turns that
    bring the tip from the path of contact's end through the flank and out.

    Parameters
    ----------
    pair : GearPair
    points : dict
        The layout's points (``O2``, ``O3``, ``P``).
    cutter : int
        2 (the driver's tip cuts gear 3's flank, after B) or 3 (gear 3's tip
        cuts the driver's flank, before A).

    Returns
    -------
    numpy.ndarray
        ``(TIP_SAMPLES, 2)`` points.
    """
    g2, g3 = pair.driver, pair.driven
    if g3.rack:
        return _rack_tip_path(pair, points)
    ra2, ra3 = pair.outside_radii
    r2p, r3p = pair.operating_pitch_radii
    psi2, psi3 = mesh_phases(pair)
    o2, o3 = np.array(points["O2"]), np.array(points["O3"])
    k = g2.teeth / g3.teeth * (-1.0 if g3.internal else 1.0)   # θ3 per θ (θ2 = −θ)
    span = 2.0 * 2.0 * math.pi / g2.teeth                        # two base pitches of 2
    th = np.linspace(-span, span, TIP_SAMPLES)
    if cutter == 3:   # the corner of 3's tooth on the flank that touches 2 at P
        b = float(g3.half_angle(ra3))
        ang = psi3 + b if g3.internal else psi3 - b
        q = o3 + ra3 * np.array([math.cos(ang), math.sin(ang)])
        c_ang, o_ang, oc, oo = k * th, -th, o3, o2
    else:
        ang = psi2 - float(g2.half_angle(ra2))
        q = o2 + ra2 * np.array([math.cos(ang), math.sin(ang)])
        c_ang, o_ang, oc, oo = -th, k * th, o2, o3
    qc = q - oc
    moved = oc + np.stack([np.cos(c_ang) * qc[0] - np.sin(c_ang) * qc[1],
                           np.sin(c_ang) * qc[0] + np.cos(c_ang) * qc[1]], axis=-1)
    d = moved - oo
    back = -o_ang
    return oo + np.stack([np.cos(back) * d[:, 0] - np.sin(back) * d[:, 1],
                          np.sin(back) * d[:, 0] + np.cos(back) * d[:, 1]], axis=-1)


def _rack_tip_path(pair: GearPair, points: dict[str, tuple[float, float]]) -> np.ndarray:
    """The path of the rack's tip corner relative to the pinion (Sec. 7.7, Figs. 7.18, 7.25).

    The pinion turns clockwise by θ while the rack moves ``−R_2 θ`` along its
    pitch line (rolling at P); in the pinion's frame the corner ``q`` of the
    tooth in mesh at P is ``O_2 + R(θ)(q − R_2 θ x̂ − O_2)``.
    """
    g2, g3 = pair.driver, pair.driven
    o2 = np.array(points["O2"])
    side = 1.0 if points["A"][0] >= points["P"][0] else -1.0
    corner = min(g3.addendum, g3.circular_pitch / (4.0 * math.tan(g3.pressure_angle)))
    q = np.array([-side * corner * math.tan(g3.pressure_angle), corner])
    span = 2.0 * 2.0 * math.pi / g2.teeth
    th = np.linspace(-span, span, TIP_SAMPLES)
    moved = np.stack([q[0] - g2.pitch_radius * th, np.full_like(th, q[1])], axis=-1) - o2
    return o2 + np.stack([np.cos(th) * moved[:, 0] - np.sin(th) * moved[:, 1],
                          np.sin(th) * moved[:, 0] + np.cos(th) * moved[:, 1]], axis=-1)


def ring_overlap(pair: GearPair, points: dict[str, tuple[float, float]],
                 steps: int = TIP_SAMPLES) -> float:
    """How deep the pinion's teeth enter the ring's over one pitch of motion (tip interference).

    A pinion inside a ring of few more teeth can foul the ring's tips away
    from the path of contact, where the two addendum circles cross (the book
    does not treat it; it is the check a designer makes beside Eq. 7.12).
    Every point of every pinion tooth (its involute flanks, top lands and the
    radial lines below its base circle) is carried through one circular
    pitch of the rolling (2 clockwise, the ring ``N2/N3`` as fast, the same
    sense; the motion repeats after a pitch), written in the ring's frame,
    and measured against the ring's teeth: a point at ``R_a3 < r < R_root3``
    whose angle from the nearest ring tooth's center line is below that
    tooth's half angle ``β'(r)`` is inside it, by ``r (β'(r) − |offset|)``.

    Returns
    -------
    float
        The largest such depth (a length), 0 when no point enters.
    """
    g2, g3 = pair.driver, pair.driven
    if not g3.internal:
        return 0.0
    ra2, ra3 = pair.outside_radii
    psi2, psi3 = mesh_phases(pair)
    o2, o3 = np.array(points["O2"]), np.array(points["O3"])
    teeth = gear_teeth(g2, ra2, (float(o2[0]), float(o2[1])), psi2).reshape(-1, 2)
    th = np.linspace(0.0, 2.0 * math.pi / g2.teeth, steps)
    d = teeth - o2
    c, s = np.cos(-th)[:, None], np.sin(-th)[:, None]
    px = o2[0] + c * d[:, 0] - s * d[:, 1] - o3[0]
    py = o2[1] + s * d[:, 0] + c * d[:, 1] - o3[1]
    back = g2.teeth / g3.teeth * th[:, None]          # undo the ring's turn, −(N2/N3) θ
    qx = np.cos(back) * px - np.sin(back) * py
    qy = np.sin(back) * px + np.cos(back) * py
    r = np.hypot(qx, qy)
    pitch3 = 2.0 * math.pi / g3.teeth
    off = (np.arctan2(qy, qx) - psi3 + 0.5 * pitch3) % pitch3 - 0.5 * pitch3
    band = (r > ra3) & (r < g3.root_radius)
    rr = np.where(band, r, g3.root_radius)
    half = np.asarray(g3.half_angle(rr), dtype=float)
    depth = np.where(band, rr * (half - np.abs(off)), 0.0)
    return float(max(depth.max(), 0.0))
