"""The independent check: all moving links' equilibrium as one linear system.

Each moving link gives three equations, Σ Fx = 0, Σ Fy = 0 and Σ M = 0 about
the world origin (with d'Alembert's inertia forces, Sec. 12.3, these are
Newton-Euler's equations); the unknowns are every joint force's components
(two for a pin or a slider, one for a pin in a slot) and each drive's torque or
force.  This is the matrix method the book uses for Examples 11.9 and 12.4,
written without any of the graphic decisions, so it checks them.

:func:`power_balance` is a second check that needs no joint equations at all:
the drive's power equals minus the power of every load, inertia force and
weight, ``Σ F·V + T·ω = 0`` (virtual work, Sec. 11.11), from the velocity
solution.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.11 (virtual work), Ex 11.9,
Ex 12.4 (Eqs. 12.19-12.21).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.forces.joints import PIN, SLIDE, Geometry, Joint
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME

__all__ = ["applied_wrenches", "solve_matrix", "power_balance"]


def _wrench(f: Any, p: Any) -> np.ndarray:
    f = np.asarray(f, dtype=float)
    p = np.asarray(p, dtype=float)
    return np.array([f[0], f[1], p[0] * f[1] - p[1] * f[0]])


def applied_wrenches(sol: Solution, dynamic: bool, mistake: str | None = None
                     ) -> dict[str, list[tuple[np.ndarray, str]]]:
    """Per link, the applied wrenches ``(Fx, Fy, M_origin)`` with the point each acts at.

    Loads, couples, inertia forces ``-m A_G`` with the torque ``-I_G α``
    (d'Alembert, Sec. 12.3) and weights.  The second item names the point
    whose velocity gives the force's power (``""`` for a pure couple).
    ``mistake`` makes the usual students' errors instead (to diagnose
    them): ``"not-reversed"`` takes ``+m A_G`` and ``+I_G α``, ``"h-side"``
    offsets h to the wrong side (``-m A_G`` with ``+I_G α``).
    """
    mech = sol.mechanism
    out: dict[str, list[tuple[np.ndarray, str]]] = {}
    for ld in mech.loads:
        if ld.force is not None:
            assert ld.point is not None
            out.setdefault(ld.link, []).append(
                (_wrench(ld.force, sol.position(ld.point, ld.link)), ld.point))
        else:
            assert ld.torque is not None
            out.setdefault(ld.link, []).append((np.array([0.0, 0.0, ld.torque]), ""))
    for lid, inr in mech.inertia.items():
        g = sol.position(inr.center, lid)
        if dynamic:
            sf = 1.0 if mistake == "not-reversed" else -1.0
            st = 1.0 if mistake in ("not-reversed", "h-side") else -1.0
            w = _wrench(sf * inr.mass * np.asarray(sol.acceleration(inr.center, lid)), g)
            w[2] += st * inr.moment * float(sol.alpha(lid))
            out.setdefault(lid, []).append((w, inr.center))
        if mech.gravity is not None:
            out.setdefault(lid, []).append(
                (_wrench(inr.mass * np.asarray(mech.gravity), g), inr.center))
    return out


def solve_matrix(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
                 mistake: str | None = None
                 ) -> tuple[dict[str, np.ndarray], dict[str, float], dict[str, np.ndarray]]:
    """Every joint force and drive by one linear solve.

    Returns
    -------
    forces : dict
        Joint key -> wrench of F_lo,hi (by ``lo`` on ``hi``).
    drives : dict
        Drive link -> its torque (ccw, about its pivot) or its force along the slider line.
    drive_wrenches : dict
        Drive link -> the wrench the drive applies to it.

    Raises
    ------
    InputError
        The system is singular: equilibrium cannot be held at this posture.
    """
    mech = sol.mechanism
    moving = mech.moving
    row = {lid: 3 * i for i, lid in enumerate(moving)}
    cols: list[tuple[str, str, np.ndarray]] = []  # (owner, what, wrench on hi per unit)
    for j in joints:
        p = geo.points[j.point]
        if j.kind == PIN:
            cols.append((j.key, "x", np.array([1.0, 0.0, -p[1]])))
            cols.append((j.key, "y", np.array([0.0, 1.0, p[0]])))
        elif j.kind == SLIDE:
            n = geo.normal[j.key]
            cols.append((j.key, "n", np.array([n[0], n[1], 0.0])))
            cols.append((j.key, "m", np.array([0.0, 0.0, 1.0])))
        else:
            n = geo.normal[j.key]
            cols.append((j.key, "n", _wrench(n, p)))
    jmap = {j.key: j for j in joints}
    nd = len(cols)
    for d in mech.drives:
        if d.kind == "angle":
            cols.append((f"drive:{d.link}", "T", np.array([0.0, 0.0, 1.0])))
        else:
            assert d.slider is not None
            key = next(j.key for j in joints if j.source is d.slider)
            p = geo.points[d.slider.point]
            cols.append((f"drive:{d.link}", "F", _wrench(geo.along[key], p)))
    n_eq, n_un = 3 * len(moving), len(cols)
    if n_eq != n_un:
        raise InputError(f"the force analysis has {n_un} unknowns for {n_eq} equations "
                         "(the mechanism is not statically determinate)", key="drive",
                         file=mech.source)
    a = np.zeros((n_eq, n_un))
    b = np.zeros(n_eq)
    for c, (owner, _, w) in enumerate(cols):
        if c < nd:
            j = jmap[owner]
            if j.hi in row:
                a[row[j.hi]:row[j.hi] + 3, c] += w
            if j.lo in row:
                a[row[j.lo]:row[j.lo] + 3, c] -= w
        else:
            lid = owner.split(":", 1)[1]
            a[row[lid]:row[lid] + 3, c] += w
            d = next(d for d in mech.drives if d.link == lid)
            if d.kind == "position" and d.slider is not None and d.slider.on != FRAME:
                a[row[d.slider.on]:row[d.slider.on] + 3, c] -= w
    for lid, items in applied_wrenches(sol, dynamic, mistake).items():
        for w, _ in items:
            b[row[lid]:row[lid] + 3] -= w
    # scale the moment rows so that the condition number measures geometry, not units
    s = mech.scale
    a[2::3] /= s
    b[2::3] /= s
    if not (np.isfinite(a).all() and np.isfinite(b).all()):
        # loads or rates beyond the floats' range (a load of 1e300 with friction)
        raise InputError("the force equations overflow at this posture (loads, masses or "
                         "rates too large for the mechanism's size)", key="loads",
                         file=mech.source)
    cond = np.linalg.cond(a)
    if not np.isfinite(cond) or cond > 1e12:
        raise InputError("equilibrium cannot be held at this posture (the drive is at a "
                         "dead center for these loads: the equations are singular)",
                         key="drive", file=mech.source)
    x = np.linalg.solve(a, b)
    forces: dict[str, np.ndarray] = {j.key: np.zeros(3) for j in joints}
    drives: dict[str, float] = {}
    drive_w: dict[str, np.ndarray] = {}
    for c, (owner, _, w) in enumerate(cols):
        if c < nd:
            forces[owner] = forces[owner] + x[c] * w
        else:
            lid = owner.split(":", 1)[1]
            drives[lid] = float(x[c])
            drive_w[lid] = x[c] * w
    return forces, drives, drive_w


def power_balance(sol: Solution, dynamic: bool, drives: dict[str, float]) -> tuple[float, float]:
    """The virtual power of every load and the drives (Sec. 11.11): it must vanish.

    Returns
    -------
    residual : float
        ``Σ F·V + Σ T·ω`` over loads, couples, inertia forces, weights and drives.
    size : float
        The largest size of a product summed (``|F||V| + |M||ω|``), to judge the
        residual against.
    """
    mech = sol.mechanism
    terms: list[float] = []
    sizes: list[float] = []
    for lid, items in applied_wrenches(sol, dynamic).items():
        w_link = float(sol.omega(lid))
        for w, _point in items:
            st = sol.links[lid]
            # the wrench's power: F·V_O' + M_O'·ω with O' the link point at the origin
            v0 = np.asarray(st.velocity(_local_origin(st)))
            terms.append(float(w[0] * v0[0] + w[1] * v0[1] + w[2] * w_link))
            sizes.append(float(np.hypot(w[0], w[1]) * np.hypot(*v0) + abs(w[2] * w_link)))
    for d in mech.drives:
        t = drives[d.link]
        if d.kind == "angle":
            terms.append(t * float(sol.omega(d.link)))
        else:
            assert d.slider is not None
            p = d.slider.point
            v = np.asarray(sol.velocity(p, d.link)) - np.asarray(
                sol.velocity(p, d.slider.on) if p in mech.links[d.slider.on].points
                else _guide_velocity(sol, d.slider.on, np.asarray(sol.position(p, d.link))))
            st = sol.links[d.slider.on]
            u = st._r(np.subtract(d.slider.p1, d.slider.p0))
            u = u / np.hypot(*u)
            terms.append(t * float(v @ u))
    sizes += [abs(x) for x in terms]
    return float(sum(terms)), max(sizes, default=0.0)


def _local_origin(st: Any) -> np.ndarray:
    """Local coordinates of the world origin in a link."""
    d = -np.asarray(st.origin)
    c, s = np.cos(st.angle), np.sin(st.angle)
    return np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])


def _guide_velocity(sol: Solution, lid: str, world: np.ndarray) -> np.ndarray:
    st = sol.links[lid]
    d = world - np.asarray(st.origin)
    c, s = np.cos(st.angle), np.sin(st.angle)
    return np.asarray(st.velocity(np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])))
