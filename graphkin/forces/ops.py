"""The operations of a force construction (free bodies and force polygons).

A force is carried through a construction as a planar *wrench* ``(Fx, Fy, M)``:
the force vector and its moment about the world origin.  Its line of action is
the set of points ``x`` with ``x × F = M`` (the homogeneous line
``(-Fy, Fx, M)/|F|``, directed along F); a couple is ``(0, 0, T)``.  Adding
wrenches is the book's resultant of Sec. 11.8 (the sum of the vectors acting
where their lines meet); every operation below is one act of the graphic
method, computed exactly so that a replay over a sweep needs no loop.

Operations are registered in :data:`graphkin.construction.ops.OPS` under names
that begin with ``force_``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.5-11.8 (two-, three- and
four-force members, force polygons), Sec. 12.4 (Eq. 12.18, the offset h).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.construction.ops import op
from graphkin.geometry import ops as g
from graphkin.tolerance import VERDICT_REL, Tolerance

__all__ = ["wrench", "line_of", "moment_about", "KIND"]

Array = np.ndarray
KIND = "force"
"""The output kind of a wrench-valued step."""


def _w(f: Array, m: Array) -> Array:
    f = np.asarray(f, dtype=float)
    m = np.asarray(m, dtype=float)
    shape = np.broadcast_shapes(f.shape[:-1], m.shape)
    out = np.empty((*shape, 3))
    out[..., :2] = f
    out[..., 2] = m
    return out


def wrench(force: Any, through: Any) -> Array:
    """The wrench of a force acting through a point (Cartesian ``(x, y)``)."""
    f = np.asarray(force, dtype=float)
    p = np.asarray(through, dtype=float)
    return _w(f, p[..., 0] * f[..., 1] - p[..., 1] * f[..., 0])


def moment_about(w: Any, p: Any) -> Array:
    """Moment (ccw positive) of a wrench about a point ``(x, y)``: ``M - P × F``."""
    w = np.asarray(w, dtype=float)
    p = np.asarray(p, dtype=float)
    return w[..., 2] - (p[..., 0] * w[..., 1] - p[..., 1] * w[..., 0])


def line_of(w: Any) -> Array:
    """The line of action of a wrench, directed along its force (NaN for a couple)."""
    w = np.asarray(w, dtype=float)
    n = np.hypot(w[..., 0], w[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.stack([-w[..., 1], w[..., 0], w[..., 2]], axis=-1) / n[..., None]


def _line_or_infinity(w: Array) -> Array:
    """The line of action of a wrench; the line at infinity for a couple (or nothing)."""
    w = np.asarray(w, dtype=float)
    n = np.hypot(w[..., 0], w[..., 1])
    safe = np.where((n > 0)[..., None], w, np.array([0.0, 0.0, 1.0]))
    return line_of(np.where((n > 0)[..., None], safe, np.array([1.0, 0.0, 0.0]))) * \
        (n > 0)[..., None] + np.array([0.0, 0.0, 1.0]) * (n == 0)[..., None]


def _concurrency(l1: Array, l2: Array) -> Array:
    """Where two lines of action meet: a finite point, or a point at infinity.

    Unlike :func:`graphkin.geometry.ops.meet` it accepts the line at infinity
    ``(0, 0, 1)`` (the "line" of a couple): the meet is then the ideal point of
    the other line.
    """
    x = np.cross(np.asarray(l1, dtype=float), np.asarray(l2, dtype=float))
    w = x[..., 2]
    n = np.hypot(x[..., 0], x[..., 1])
    finite = np.abs(w) > 1e-12 * n
    with np.errstate(invalid="ignore", divide="ignore"):
        fin = x / np.where(finite, w, 1.0)[..., None]
        ideal = np.concatenate([x[..., :2] / n[..., None], np.zeros((*w.shape, 1))], axis=-1)
    return np.where(finite[..., None], fin, ideal)


def _unit_on(line: Array) -> tuple[Array, Array]:
    """A unit direction of a line and its foot point nearest the origin."""
    line = np.asarray(line, dtype=float)
    a, b, c = line[..., 0], line[..., 1], line[..., 2]
    n = np.hypot(a, b)
    d = np.stack([b, -a], axis=-1) / n[..., None]
    p0 = np.stack([-a * c, -b * c], axis=-1) / (n * n)[..., None]
    return d, p0


@op("force_load", kind=KIND)
def _load(p: Array, *, tol: Tolerance, force: tuple[float, float]) -> tuple[Array]:
    """An applied force of known vector acting through a point of the link (Sec. 11.4)."""
    return (wrench(np.broadcast_to(np.asarray(force, float), g.xy(p).shape), g.xy(p)),)


@op("force_couple", kind=KIND)
def _couple(*, tol: Tolerance, torque: float) -> tuple[Array]:
    """An applied couple (two equal, opposite, parallel forces): the wrench ``(0, 0, T)``."""
    return (np.array([0.0, 0.0, float(torque)]),)


@op("force_zero", kind=KIND)
def _zero(*, tol: Tolerance) -> tuple[Array]:
    """A joint force found to be zero (two two-force members meeting on different lines)."""
    return (np.zeros(3),)


@op("force_inertia", kind=KIND)
def _inertia(gp: Array, a_g: Array, alpha: Array, *, tol: Tolerance, mass: float,
             moment: float) -> tuple[Array]:
    """D'Alembert's inertia force ``-m A_G`` with the inertia torque ``-I_G α`` (Sec. 12.4).

    As one force: ``-m A_G`` offset from G by ``h = I_G α / (m A_G)`` to the side
    where its moment about G is ``-I_G α`` (Eq. 12.18, Fig. 12.7c).
    """
    f = -mass * np.asarray(a_g, dtype=float)
    w = wrench(f, g.xy(gp))
    w[..., 2] -= moment * np.asarray(alpha, dtype=float)
    return (w,)


@op("force_weight", kind=KIND)
def _weight(gp: Array, *, tol: Tolerance, mass: float,
            gravity: tuple[float, float]) -> tuple[Array]:
    """The weight ``m g`` acting through the center of mass."""
    f = mass * np.asarray(gravity, dtype=float)
    return (wrench(np.broadcast_to(f, g.xy(gp).shape), g.xy(gp)),)


@op("force_resultant", kind=KIND)
def _resultant(*ws: Array, tol: Tolerance) -> tuple[Array]:
    """The resultant of known forces: their vector sum acting where their lines meet (Sec. 11.8)."""
    out = np.asarray(ws[0], dtype=float)
    for w in ws[1:]:
        out = out + np.asarray(w, dtype=float)
    return (out,)


@op("force_reverse", kind=KIND)
def _reverse(w: Array, *, tol: Tolerance) -> tuple[Array]:
    """Action and reaction: ``F_ji = -F_ij`` on the same line of action (Newton's third law)."""
    return (-np.asarray(w, dtype=float),)


@op("force_line", kind="line")
def _line(p: Array, d: Array, *, tol: Tolerance) -> tuple[Array]:
    """The line of action through P in a known direction (a slider's or slot's normal)."""
    return (g.line_through(p, d),)


@op("force_line_of", kind="line")
def _line_of(w: Array, *, tol: Tolerance) -> tuple[Array]:
    """The line of action of a known force."""
    return (line_of(w),)


@op("force_three", kind=KIND)
def _three(r: Array, line1: Array, p: Array, *, tol: Tolerance) -> tuple[Array, Array, Array]:
    """A three-force member (Sec. 11.7, Fig. 11.5e): a known R, a known line, a pin P.

    The known resultant R, a force on a known line and a force through the pin P.

    The lines of R and of the first force meet at the concurrency point X; the
    third force acts along PX; the force polygon R + F1 + F2 = 0 gives both
    magnitudes (case 3).  Computed as ``Σ M_P = 0``, which is the same
    construction and holds when R is parallel to the line (X at infinity) or a
    couple.  Outputs F1, F2 (wrenches) and X.
    """
    pp = g.xy(p)
    d1, p0 = _unit_on(line1)
    unit = wrench(d1, p0)
    with np.errstate(invalid="ignore", divide="ignore"):
        a = -moment_about(r, pp) / moment_about(unit, pp)
    f1 = unit * a[..., None]
    f2 = -(np.asarray(r, dtype=float) + f1)
    return f1, f2, _concurrency(line1, _line_or_infinity(r))


@op("force_slide_three", kind=KIND)
def _slide_three(r: Array, line1: Array, n2: Array, *,
                 tol: Tolerance) -> tuple[Array, Array, Array]:
    """A three-force member whose third force has a known direction but no known line.

    The third force is a slider's normal force (Ex 11.2 step 4).

    The force polygon R + F1 + F2 = 0 with both directions known gives the
    magnitudes (case 3); F2 then acts through the concurrency point X of R and
    F1.  Outputs F1, F2 (wrenches) and X.
    """
    d1, p0 = _unit_on(line1)
    n2 = np.asarray(n2, dtype=float)
    rf = np.asarray(r, dtype=float)[..., :2]
    det = g.cross2(d1, n2)
    with np.errstate(invalid="ignore", divide="ignore"):
        a = -g.cross2(rf, n2) / det
    f1 = wrench(d1, p0) * a[..., None]
    f2 = -(np.asarray(r, dtype=float) + f1)
    return f1, f2, _concurrency(line1, _line_or_infinity(f2))


@op("force_four", kind=KIND)
def _four(r: Array, line1: Array, line2: Array, line3: Array, *,
          tol: Tolerance) -> tuple[Array, Array, Array, Array]:
    """A four-force member (Sec. 11.8, Ex 11.3): a known R and three forces on known lines.

    The lines of the first two unknowns meet at q; ``Σ M_q = 0`` leaves one
    unknown, the third force; then R plus the third acts along the line to q
    and the force polygon gives the other two.  Computed as the three
    equilibrium equations at once.  Outputs F1, F2, F3 (wrenches) and q.
    """
    cols = []
    for ln in (line1, line2, line3):
        d, p0 = _unit_on(ln)
        cols.append(wrench(d, p0))
    m = np.stack(cols, axis=-1)  # (..., 3, 3): unit wrenches as columns
    rr = np.asarray(r, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        try:
            a = np.linalg.solve(m, -rr[..., None])[..., 0]
        except np.linalg.LinAlgError:
            a = np.full(rr.shape, np.nan)
    f1, f2, f3 = (cols[k] * a[..., k:k + 1] for k in range(3))
    return f1, f2, f3, _concurrency(line1, line2)


@op("force_balance", kind=KIND)
def _balance(r: Array, *, tol: Tolerance) -> tuple[Array]:
    """The one unknown force on a link: equal and opposite to the resultant of the others."""
    return (-np.asarray(r, dtype=float),)


@op("force_drive_reaction", kind=KIND)
def _drive_reaction(r: Array, o: Array, *, tol: Tolerance) -> tuple[Array]:
    """The frame's force on the drive link at its pivot O: it balances ΣF (Ex 11.1 step 7)."""
    rr = np.asarray(r, dtype=float)
    return (wrench(-rr[..., :2], g.xy(o)),)


@op("force_drive_torque", kind="scalar")
def _drive_torque(r: Array, o: Array, *, tol: Tolerance) -> tuple[Array]:
    """The drive's torque ``T_12 = -(arm × force)``: it balances ``Σ M_O`` (Ex 11.1 step 7)."""
    return (-moment_about(r, g.xy(o)),)


@op("force_drive_force", kind=KIND)
def _drive_force(r: Array, p: Array, u: Array, n: Array, *,
                 tol: Tolerance) -> tuple[Array, Array]:
    """A slider drive (Ex 12.3): the input force and the guide's normal force.

    The input force acts along the line through the slider's
    point with the guide's normal force; the polygon gives both magnitudes, the
    normal force acts where the moments balance.  Outputs the input force and
    the normal force.
    """
    rr = np.asarray(r, dtype=float)
    u = np.asarray(u, dtype=float)
    n = np.asarray(n, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore"):
        f = -g.cross2(rr[..., :2], n) / g.cross2(u, n)
    drive = wrench(u * f[..., None], g.xy(p))
    return drive, -(rr + drive)


@op("force_along", kind="scalar")
def _along(w: Array, u: Array, *, tol: Tolerance) -> tuple[Array]:
    """The signed size of a force along a unit direction (the input force F_A)."""
    return (g.dot2(np.asarray(w, dtype=float)[..., :2], u),)


@op("force_add_torques", kind="scalar")
def _add(*ts: Array, tol: Tolerance) -> tuple[Array]:
    """Superposition of the drive's torques (or forces) of the partial analyses (Sec. 12.5)."""
    out = np.asarray(ts[0], dtype=float)
    for t in ts[1:]:
        out = out + np.asarray(t, dtype=float)
    return (out,)


# ---- friction at a slider or a straight slot (Sec. 11.10) --------------------------------
# The book solves first without friction to find the sense of each normal force, then leans
# the force by the friction angle against the impending motion, then checks the sense it
# was leant from.  These operations are the arithmetic of those three acts (solve.py runs
# them on the matrix method's forces; the live page writes them out with the graphic
# construction's, render/live_forces.py).  A sense is a verdict: 0 within
# :data:`graphkin.tolerance.VERDICT_REL` of the forces' scale, where none may be taken.


@op("force_scale", kind="scalar")
def _scale(*xs: Array, tol: Tolerance, kinds: tuple[str, ...], size: float) -> tuple[Array]:
    """The size of the forces (:func:`graphkin.forces.solve.force_scale`).

    The largest ``|F|`` of the inputs of kind ``"force"`` (or ``|V|`` of a
    velocity), ``|M| / size`` of those of kind ``"couple"`` (a couple over the
    mechanism's size), ``|ω| size`` of those of kind ``"rate"`` (as
    :meth:`graphkin.kinematics.Solution.velocity_scale` counts an angular
    velocity) and ``|x|`` of those of kind ``"scale"`` (a size found before).
    """
    big: Array = np.asarray(0.0)
    for x, kind in zip(xs, kinds):
        a = np.asarray(x, dtype=float)
        if kind == "couple":
            v = np.abs(a[..., 2]) / size
        elif kind == "rate":
            v = np.abs(a) * size
        elif kind == "scale":
            v = np.abs(a)
        else:
            v = np.hypot(a[..., 0], a[..., 1])
        big = np.maximum(big, v)
    return (big,)


def _on_block(w: Array, block: str) -> Array:
    """The joint force F_lo,hi as the force ON the block (link ``hi``, or ``lo``: reversed)."""
    f = np.asarray(w, dtype=float)[..., :2]
    return f if block == "hi" else -f


@op("force_normal_sense", kind="scalar")
def _normal_sense(w: Array, n: Array, scale: Array, *, tol: Tolerance,
                  block: str) -> tuple[Array]:
    """The sense of a joint's force on the block along the guide's normal n (Sec. 11.10).

    ``+1`` along n, ``-1`` against it, ``0`` within round-off of ``scale`` (no
    normal force: no friction, and no verdict on its sense).  ``block`` says
    which link of the joint F_lo,hi is the block: ``"hi"`` or ``"lo"``.
    """
    c = g.dot2(_on_block(w, block), np.asarray(n, dtype=float)[..., :2])
    zero = np.abs(c) <= VERDICT_REL * np.abs(np.asarray(scale, dtype=float))
    return (np.where(zero, 0.0, np.sign(c)),)


@op("force_impending", kind="scalar")
def _impending(vp: Array, vq: Array, q: Array, p: Array, omega: Array, u: Array,
               vscale: Array, *, tol: Tolerance) -> tuple[Array]:
    """The sense of the block's motion along its guide: its impending motion (Sec. 11.10).

    The velocity of the block's point P less that of the guide's point at P,
    ``V_Q + ω × (P - Q)`` (Q a point of the guide, ω its angular velocity: zero
    for the frame), along the guide's direction u: ``+1`` ahead, ``-1``
    behind, ``0`` at rest within round-off of ``vscale`` (the velocities'
    size), where no verdict may be taken and the file must say which way.
    """
    vp = np.asarray(vp, dtype=float)[..., :2]
    vq = np.asarray(vq, dtype=float)[..., :2]
    d = np.asarray(p, dtype=float)[..., :2] - np.asarray(q, dtype=float)[..., :2]
    w = np.asarray(omega, dtype=float)
    rel = vp - vq - w[..., None] * np.stack([-d[..., 1], d[..., 0]], axis=-1)
    speed = g.dot2(rel, np.asarray(u, dtype=float)[..., :2])
    zero = np.abs(speed) <= VERDICT_REL * np.abs(np.asarray(vscale, dtype=float))
    return (np.where(zero, 0.0, np.sign(speed)),)


@op("force_friction_normal", kind="vector")
def _friction_normal(n: Array, u: Array, sense: Array, *moving: Array, tol: Tolerance,
                     mu: float, impending: float | None = None) -> tuple[Array]:
    """The line of a rough joint's force on the block: the normal leant by φ = atan μ.

    ``sense · n - μ s u`` made a unit vector, s = ±1 the impending motion of the
    block along the guide's direction u (the file's ``impending``, or a fourth
    input: :func:`_impending` of the velocities): the friction force opposes it
    (Sec. 11.10, Fig. 11.11).  With no normal force (``sense`` 0) the normal n
    itself: no friction.
    """
    n = np.asarray(n, dtype=float)[..., :2]
    u = np.asarray(u, dtype=float)[..., :2]
    s = np.asarray(sense, dtype=float)[..., None]
    imp = np.asarray(moving[0] if impending is None else impending, dtype=float)[..., None]
    d = s * n - mu * imp * u
    d = d / np.hypot(d[..., 0], d[..., 1])[..., None]
    return (np.where(s != 0.0, d, n),)


@op("force_turned", kind="scalar")
def _turned(w: Array, d: Array, scale: Array, sense: Array, *, tol: Tolerance,
            block: str) -> tuple[Array]:
    """1 where the force found pulls the block along its leant line d instead of pressing.

    Friction turned the sense it was leant from over (near self-locking, Sec.
    11.10): the other sense is to be tried.  0 where it presses, where it is
    round-off of ``scale``, and for a joint without friction (``sense`` 0).
    """
    (c,) = _normal_sense(w, d, scale, tol=tol, block=block)
    return (np.where((np.asarray(sense) != 0.0) & (c < 0.0), 1.0, 0.0),)
