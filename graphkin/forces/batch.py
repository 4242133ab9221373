"""The matrix method on arrays of postures, and the rough joints' lines of action over a sweep.

A sweep's torque column must be the torque ``graphkin solve`` finds at the
same posture, friction and gear teeth included (issue 25: the frictionless
torque was swept).  At one posture, :func:`graphkin.forces.solve.solve_forces`
first solves without friction to find the sense of each normal force, then
leans the rough joints' forces by the friction angle against the impending
motion (Sec. 11.10) and tilts the gear teeth's forces onto their pressure
line (Sec. 11.11).  Those senses change over a cycle, so they are found here
for every posture at once: the same linear equations (Σ F = 0, Σ M = 0 for
each moving link, :mod:`graphkin.forces.analytic`) stacked as an array of
systems and solved by one ``numpy.linalg.solve``, no loop over postures.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.10 (friction), Sec. 11.11 (gear
teeth), Ex 11.4, Ex 11.9 (the matrix method), Ex 12.4.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.forces.joints import PIN, SLIDE, SLOT, Geometry, Joint
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME, Rolling, Slider, Slot

__all__ = ["solve_matrix_many", "tilt_many"]


def _col(a: Any, n: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(a, dtype=float), (n,))


def _xy(a: Any, n: int) -> np.ndarray:
    return np.broadcast_to(np.asarray(a, dtype=float), (n, 2))


def _wrench(f: np.ndarray, p: np.ndarray) -> np.ndarray:
    """``(Fx, Fy, M_origin)`` of forces ``f`` at points ``p``, both ``(N, 2)``."""
    return np.stack([f[:, 0], f[:, 1], p[:, 0] * f[:, 1] - p[:, 1] * f[:, 0]], axis=-1)


def applied_many(sol: Solution, dynamic: bool, n: int) -> dict[str, np.ndarray]:
    """Per link, the sum of the applied wrenches ``(N, 3)`` (as ``applied_wrenches``)."""
    mech = sol.mechanism
    out: dict[str, np.ndarray] = {}

    def add(lid: str, w: np.ndarray) -> None:
        out[lid] = out[lid] + w if lid in out else w

    for ld in mech.loads:
        if ld.force is not None:
            assert ld.point is not None
            add(ld.link, _wrench(_xy(ld.force, n), _xy(sol.position(ld.point, ld.link), n)))
        else:
            assert ld.torque is not None
            w = np.zeros((n, 3))
            w[:, 2] = ld.torque
            add(ld.link, w)
    for lid, inr in mech.inertia.items():
        g = _xy(sol.position(inr.center, lid), n)
        if dynamic:
            w = _wrench(-inr.mass * _xy(sol.acceleration(inr.center, lid), n), g)
            w[:, 2] -= inr.moment * _col(sol.alpha(lid), n)
            add(lid, w)
        if mech.gravity is not None:
            add(lid, _wrench(inr.mass * _xy(mech.gravity, n), g))
    return out


def solve_matrix_many(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
                      n: int) -> tuple[dict[str, np.ndarray], dict[str, np.ndarray], np.ndarray]:
    """Every joint force and drive at ``n`` postures by one stacked linear solve.

    Returns
    -------
    forces : dict
        Joint key -> wrenches ``(N, 3)`` of F_lo,hi.
    drives : dict
        Drive link -> ``(N,)`` torques or forces.
    ok : ndarray of bool
        The postures where the equations hold one finite answer (NaN elsewhere).
    """
    mech = sol.mechanism
    moving = mech.moving
    row = {lid: 3 * i for i, lid in enumerate(moving)}
    cols: list[tuple[str, np.ndarray]] = []
    zero, one = np.zeros(n), np.ones(n)
    for j in joints:
        p = _xy(geo.points[j.point], n)
        if j.kind == PIN:
            cols.append((j.key, np.stack([one, zero, -p[:, 1]], -1)))
            cols.append((j.key, np.stack([zero, one, p[:, 0]], -1)))
        elif j.kind == SLIDE:
            nn = _xy(geo.normal[j.key], n)
            cols.append((j.key, np.stack([nn[:, 0], nn[:, 1], zero], -1)))
            cols.append((j.key, np.stack([zero, zero, one], -1)))
        else:
            cols.append((j.key, _wrench(_xy(geo.normal[j.key], n), p)))
    nd = len(cols)
    for d in mech.drives:
        if d.kind == "angle":
            cols.append((d.link, np.stack([zero, zero, one], -1)))
        else:
            assert d.slider is not None
            key = next(j.key for j in joints if j.source is d.slider)
            cols.append((d.link, _wrench(_xy(geo.along[key], n),
                                         _xy(geo.points[d.slider.point], n))))
    n_eq, n_un = 3 * len(moving), len(cols)
    ok = np.ones(n, dtype=bool)
    if n_eq != n_un:
        return {}, {}, ~ok
    jmap = {j.key: j for j in joints}
    a = np.zeros((n, n_eq, n_un))
    b = np.zeros((n, n_eq))
    for c, (owner, w) in enumerate(cols):
        if c < nd:
            j = jmap[owner]
            if j.hi in row:
                a[:, row[j.hi]:row[j.hi] + 3, c] += w
            if j.lo in row:
                a[:, row[j.lo]:row[j.lo] + 3, c] -= w
        else:
            a[:, row[owner]:row[owner] + 3, c] += w
            d = next(d for d in mech.drives if d.link == owner)
            if d.kind == "position" and d.slider is not None and d.slider.on != FRAME:
                a[:, row[d.slider.on]:row[d.slider.on] + 3, c] -= w
    for lid, w in applied_many(sol, dynamic, n).items():
        b[:, row[lid]:row[lid] + 3] -= w
    s = mech.scale
    a[:, 2::3] /= s
    b[:, 2::3] /= s
    ok &= np.isfinite(a).all(axis=(1, 2)) & np.isfinite(b).all(axis=1)
    a[~ok] = np.eye(n_eq)
    b[~ok] = 0.0
    with np.errstate(all="ignore"):
        cond = np.linalg.cond(a)
    ok &= np.isfinite(cond) & (cond <= 1e12)  # as solve_matrix: a dead center for these loads
    a[~ok] = np.eye(n_eq)
    x = np.linalg.solve(a, b[..., None])[..., 0]
    x[~ok] = np.nan
    forces: dict[str, np.ndarray] = {j.key: np.zeros((n, 3)) for j in joints}
    drives: dict[str, np.ndarray] = {}
    for c, (owner, w) in enumerate(cols):
        if c < nd:
            forces[owner] = forces[owner] + x[:, c, None] * w
        else:
            drives[owner] = x[:, c]
    return forces, drives, ok


def _unit(v: np.ndarray) -> np.ndarray:
    with np.errstate(all="ignore"):
        return v / np.hypot(v[:, 0], v[:, 1])[:, None]


def _on(j: Joint, link: str, w: np.ndarray) -> np.ndarray:
    """The force ``(N, 2)`` of joint ``j`` on ``link`` (F_lo,hi acts on hi)."""
    return w[:, :2] if link == j.hi else -w[:, :2]


def tilt_many(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
              n: int) -> np.ndarray:
    """Lean the rough joints' and gear teeth's lines of action at every posture, in ``geo``.

    The arrays version of ``_tilt_for_pressure`` and ``_tilt_for_friction`` of
    :mod:`graphkin.forces.solve`: the senses come from the frictionless
    solution at each posture, a rough slider whose force turns over once leant
    is tried with the other sense, and a posture where neither holds is
    self-locking.

    Returns
    -------
    ndarray of bool
        The postures where the lines are found (False: self-locking, a slider
        at rest relative to its guide with no ``impending`` given, or no answer).
    """
    mech = sol.mechanism
    good = np.ones(n, dtype=bool)
    if mech.pressure:
        plain, _, ok = solve_matrix_many(sol, joints, geo, dynamic, n)
        good &= ok
        for j in joints:
            src = j.source
            if j.kind != SLOT or not isinstance(src, Rolling):
                continue
            phi = mech.pressure[src.key]
            p = _xy(geo.points[j.point], n)
            e = _unit(_xy(sol.position(src.center, src.link), n) - p)
            t = np.stack([-e[:, 1], e[:, 0]], -1)
            sgn = np.sign(np.einsum("ij,ij->i", _on(j, src.link, plain[j.key]), t))
            d = sgn[:, None] * t + np.tan(phi) * e
            geo.normal[j.key] = np.where((sgn != 0)[:, None], _unit(d), t)
    if not mech.friction:
        return good
    plain, _, ok = solve_matrix_many(sol, joints, geo, dynamic, n)
    good &= ok
    rough = []
    for j in joints:
        src = j.source
        if j.kind not in (SLIDE, SLOT) or not isinstance(src, (Slider, Slot)) \
                or src.key not in mech.friction or j.key not in geo.along:
            continue
        mu, impending = mech.friction[src.key]
        nn, u = _xy(geo.normal[j.key], n).copy(), _xy(geo.along[j.key], n)
        c = np.einsum("ij,ij->i", _on(j, src.link, plain[j.key]), nn)
        if impending is None:
            if not sol.has_rates:
                return np.zeros(n, dtype=bool)
            v = _xy(sol.velocity(src.point, src.link), n) - _velocity_in(
                sol, src.on, _xy(sol.position(src.point, src.link), n))
            speed = np.einsum("ij,ij->i", v, u)
            good &= np.abs(speed) > 1e-12 * np.maximum(1.0, np.hypot(v[:, 0], v[:, 1]))
            s = np.where(speed > 0, 1.0, -1.0)
        else:
            s = np.full(n, 1.0 if impending == "ahead" else -1.0)
        rough.append((j, src, nn, u, mu, s, np.sign(c), np.ones(n, dtype=int)))
    if not rough:
        return good
    while True:
        for j, _src, nn, u, mu, s, sense, _ in rough:
            d = _unit(sense[:, None] * nn - mu * s[:, None] * u)
            geo.normal[j.key] = np.where((sense != 0)[:, None], d, nn)
        fw, _, ok = solve_matrix_many(sol, joints, geo, dynamic, n)
        good &= ok
        big = np.max([np.hypot(w[:, 0], w[:, 1]) for w in fw.values()], axis=0)
        big = np.where(np.isfinite(big) & (big > 0), big, 1.0)
        flipped = False
        for j, src, _nn, _u, _mu, _s, sense, tried in rough:
            press = np.einsum("ij,ij->i", _on(j, src.link, fw[j.key]), geo.normal[j.key])
            turned = good & (sense != 0) & (press < -1e-9 * big)
            locked = turned & (tried >= 2)
            good &= ~locked
            again = turned & ~locked
            if again.any():
                tried[again] += 1
                sense[again] = -sense[again]
                flipped = True
        if not flipped:
            return good


def _velocity_in(sol: Solution, lid: str, world: np.ndarray) -> np.ndarray:
    """Velocities ``(N, 2)`` of the points of link ``lid`` at world positions ``(N, 2)``."""
    st = sol.links[lid]
    d = world - np.asarray(st.origin)
    c, s = np.cos(st.angle), np.sin(st.angle)
    local = np.stack([c * d[:, 0] + s * d[:, 1], -s * d[:, 0] + c * d[:, 1]], -1)
    return np.asarray(st.velocity(local), dtype=float)
