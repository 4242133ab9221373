"""Ruler-and-compass operations: lines, circles and their intersections (Sec. 2.8)."""

from __future__ import annotations

import numpy as np

from graphkin.construction.ops.registry import op
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray


@op("circle", kind="circle")
def _circle(center: Array, *, tol: Tolerance, radius: float) -> tuple[Array]:
    """Draw a circle of known radius about a point."""
    return (g.circle(center, radius),)


@op("circle_on_diameter", kind="circle")
def _thales(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The circle on the diameter PQ (Thales: every point sees PQ at a right angle)."""
    return (g.circle(g.midpoint(p, q), g.distance(p, q) / 2),)


@op("intersect_circles")
def _cc(c1: Array, c2: Array, *, tol: Tolerance, branch: str) -> tuple[Array]:
    """Intersect two arcs (case 4) and keep the named branch."""
    left, right = g.intersect_circles(c1, c2, tol)
    return (left if branch == "left" else right,)


@op("intersect_line_circle")
def _lc(line: Array, c: Array, *, tol: Tolerance, branch: str) -> tuple[Array]:
    """Intersect a line and an arc (case 2) and keep the named branch."""
    behind, ahead = g.intersect_line_circle(line, c, tol)
    return (behind if branch == "behind" else ahead,)


@op("join", kind="line")
def _join(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """Draw the line through two points."""
    return (g.join(p, q, tol),)


@op("meet")
def _meet(l1: Array, l2: Array, *, tol: Tolerance) -> tuple[Array]:
    """Intersect two lines (case 3); the result may be a point at infinity."""
    return (g.meet(l1, l2, tol),)


@op("line_at_angle", kind="line")
def _line_at_angle(p: Array, theta: Array, *, tol: Tolerance, offset: float = 0.0) -> tuple[Array]:
    """The line through P at the angle θ + offset."""
    t = np.asarray(theta) + offset
    return (g.line_through(p, g.vector(np.cos(t), np.sin(t))),)


@op("parallel", kind="line")
def _parallel(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P draw a line parallel to a given line."""
    return (g.parallel(line, p),)


@op("perpendicular", kind="line")
def _perpendicular(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P draw a line perpendicular to a given line."""
    return (g.perpendicular(line, p),)


@op("tangent_foot")
def _tangent_foot(p: Array, s: Array, *, tol: Tolerance, offset: float,
                  branch: str) -> tuple[Array]:
    """The foot T of the perpendicular from P to a tangent from S to the circle (P, d).

    T is where the circle of radius ``d = offset`` about P meets Thales' circle
    on the diameter PS.  Evaluated in closed form, ``T = P + (d²/D) ŝ ± (d t/D) k × ŝ``
    with ``D = |PS|``, ``ŝ`` the unit vector P → S and ``t = √(D² − d²)`` (the
    tangent's length), which stays accurate when the path passes close to P.
    ``left``/``right`` follow :class:`~graphkin.construction.Side` for the
    directed line P → S.
    """
    a, b = g.xy(p), g.xy(s)
    v = b - a
    dist = np.hypot(v[..., 0], v[..., 1])
    d = float(offset)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.sqrt(np.where(dist >= d, (dist - d) * (dist + d), np.nan))
        u = v / dist[..., None]
    nrm = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    sign = 1.0 if branch == "left" else -1.0
    q = a + (d * d / dist)[..., None] * u + sign * (d * t / dist)[..., None] * nrm
    return (g.point(q[..., 0], q[..., 1]),)


@op("angle_along", kind="scalar")
def _angle_along(t: Array, s: Array, *, tol: Tolerance, local_angle: float,
                 sign: float) -> tuple[Array]:
    """Angle of a link whose line runs from T through S (``sign`` −1: from S through T).

    ``θ = ∠(sign · (S − T)) − local_angle``, the line's direction in the link.
    """
    v = (g.xy(s) - g.xy(t)) * sign
    return (np.arctan2(v[..., 1], v[..., 0]) - local_angle,)


@op("circumcircle", kind="circle")
def _circumcircle(p: Array, q: Array, r: Array, *, tol: Tolerance) -> tuple[Array]:
    """The circle through three points: its center is where two bisectors meet."""
    b1 = g.perpendicular(g.join(p, q, tol), g.midpoint(p, q))
    b2 = g.perpendicular(g.join(q, r, tol), g.midpoint(q, r))
    c = g.meet(b1, b2, tol)
    with np.errstate(invalid="ignore"):
        return (g.circle(c, g.distance(c, p)),)


@op("other_intersection")
def _other_intersection(c1: Array, c2: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Two circles through a point P meet again at P's mirror in their line of centers."""
    c1, c2 = np.asarray(c1, dtype=float), np.asarray(c2, dtype=float)
    o1 = g.point(c1[..., 0], c1[..., 1])
    o2 = g.point(c2[..., 0], c2[..., 1])
    return (g.reflect(p, g.join(o1, o2, tol)),)


@op("second_on_circle")
def _second_on_circle(line: Array, c: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """A line through a point P of a circle meets the circle again (P itself if tangent)."""
    c = np.asarray(c, dtype=float)
    foot = g.xy(g.project(g.point(c[..., 0], c[..., 1]), line))
    q = 2.0 * foot - g.xy(p)
    return (g.point(q[..., 0], q[..., 1]),)


@op("perpendicular_cw", kind="line")
def _perpendicular_cw(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P the perpendicular to a line, directed 90° clockwise from it."""
    return (-g.perpendicular(line, p),)
