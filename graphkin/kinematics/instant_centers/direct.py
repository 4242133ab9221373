"""Every instant center of a large mechanism at once, from the velocities (Sec. 3.12).

A mechanism of n links has n(n-1)/2 instant centers (Eq. 3.20): 435 for 30
links, half a million for 1000.  The step-by-step search of Kennedy's
theorem (:mod:`graphkin.kinematics.instant_centers.kennedy`) records a
construction step for every one and is meant for the figures of a textbook
mechanism; beyond :data:`DIRECT_ABOVE` centers the report finds them all at
once instead: the center ``Iij`` is the point where links i and j have the
same velocity, ``P = k × (u_i − u_j) / (ω_i − ω_j)`` with ``u_k`` the
velocity of the point of link k at the world origin (Eq. 3.18 for the
relative motion), or at infinity perpendicular to ``u_i − u_j`` when
``ω_i = ω_j``.  The centers at the pins are the pins themselves.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14 (Eqs. 3.18, 3.20).
"""

from __future__ import annotations

from dataclasses import dataclass, field, replace

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.kinematics.instant_centers.labels import sort_links
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME

__all__ = ["DIRECT_ABOVE", "DirectCenters", "direct_centers"]

#: More instant centers than this (a mechanism of more than 45 links) are found all at
#: once from the velocities, not step by step (the search grows faster than their number).
DIRECT_ABOVE = 1000


@dataclass
class DirectCenters:
    """The instant centers of a large mechanism.

    Attributes
    ----------
    links : list of str
        The link ids in order.
    pairs : (ia, ib)
        Index arrays into ``links`` of every pair, lower id first.
    points : ndarray, shape (N, 3)
        Homogeneous points (w = 1 finite, w = 0 a unit direction); NaN where
        the center is not known.
    primary : dict
        Pair index -> the pin that is that center.
    notes : list of str
    """

    links: list[str]
    pairs: tuple[np.ndarray, np.ndarray]
    points: np.ndarray
    primary: dict[int, str] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    @property
    def count(self) -> int:
        """n(n-1)/2 (Eq. 3.20)."""
        return len(self.pairs[0])


def _velocities(sol: Solution) -> Solution | None:
    """The solution with velocities, or, for one degree of freedom, at a unit input speed."""
    if sol.has_rates:
        return sol
    mech = sol.mechanism
    if len(mech.drives) != 1:
        return None
    from graphkin.kinematics.analytic import solve_analytic

    unit = replace(mech, drives=(replace(mech.drives[0], rate=1.0, rate2=0.0),), rates=None)
    guess = {lid: (float(st.origin[0]), float(st.origin[1]), float(st.angle))
             for lid, st in sol.links.items() if lid != FRAME}
    try:
        return solve_analytic(unit, guess=guess)
    except GraphkinError:
        return None


def direct_centers(sol: Solution) -> DirectCenters:
    """Every instant center at once (one posture): pins by inspection, the rest from velocities.

    Examples
    --------
    >>> import graphkin
    >>> dc = direct_centers(graphkin.examples.fourbar().solve())
    >>> dc.count, dc.links
    (6, ['1', '2', '3', '4'])
    """
    mech = sol.mechanism
    links = sort_links(mech.links)
    n = len(links)
    index = {k: i for i, k in enumerate(links)}
    ia, ib = np.triu_indices(n, 1)
    pts = np.full((len(ia), 3), np.nan)
    notes: list[str] = []
    vel = _velocities(sol)
    if vel is not None:
        u = np.zeros((n, 2))
        w = np.zeros(n)
        for lid, st in vel.links.items():
            k = index[lid]
            w[k] = float(st.omega) if st.omega is not None else 0.0
            ov = np.zeros(2) if st.origin_velocity is None else np.asarray(st.origin_velocity)
            # the velocity of the point of the link at the world origin: V_o − ω k × R_o
            o = np.asarray(st.origin, dtype=float)
            u[k] = ov - w[k] * np.array([-o[1], o[0]])
        du = u[ia] - u[ib]
        dw = w[ia] - w[ib]
        scale = mech.scale
        speed = np.hypot(du[:, 0], du[:, 1])
        big = np.maximum(np.max(np.abs(w), initial=0.0), np.max(speed, initial=0.0) / scale)
        still = (np.abs(dw) <= 1e-12 * max(big, 1e-300)) & (speed <= 1e-12 * scale
                                                              * max(big, 1e-300))
        turns = np.abs(dw) * scale > 1e-9 * speed
        with np.errstate(invalid="ignore", divide="ignore"):
            px = -du[:, 1] / dw
            py = du[:, 0] / dw
            dx, dy = -du[:, 1] / speed, du[:, 0] / speed
        pts[:, 0] = np.where(turns, px, dx)
        pts[:, 1] = np.where(turns, py, dy)
        pts[:, 2] = np.where(turns, 1.0, 0.0)
        pts[still] = np.nan
        if np.any(still):
            notes.append(f"{int(np.sum(still))} pairs of links have no relative motion here: "
                         "their centers are not defined")
    else:
        notes.append("the velocities are not known (several inputs and no rates), so only "
                     "the centers at the pins are given (Sec. 5.4)")
    primary: dict[int, str] = {}
    pair_index = {(int(a), int(b)): m for m, (a, b) in enumerate(zip(ia, ib))}
    for pin in mech.pins:
        ks = sorted(index[k] for k in pin.links)
        xy = sol.position(pin.name)
        for x in range(len(ks)):
            for y in range(x + 1, len(ks)):
                m = pair_index[(ks[x], ks[y])]
                if m not in primary:
                    primary[m] = pin.name
                    pts[m] = (float(xy[0]), float(xy[1]), 1.0)
    return DirectCenters(links, (ia, ib), pts, primary, notes)
