"""Array geometry in homogeneous coordinates: the one engine under every construction.

Every function takes arrays whose last axis holds homogeneous coordinates and
broadcasts over any leading axes, so the same call works on one posture
(shape ``(3,)``) and on a sweep (shape ``(N, 3)``) without a Python loop.

* A point is ``(x, y, w)``: finite points are kept with ``w = 1``; a point at
  infinity (an *ideal* point) has ``w = 0`` and a unit direction ``(x, y)``.
* A line is ``(a, b, c)`` meaning ``a x + b y + c w = 0``, kept with a unit
  normal ``a² + b² = 1``.  Its *direction* is ``(b, -a)``: the line
  ``join(P, Q)`` is directed from ``P`` to ``Q``.
* A circle is ``(cx, cy, r)`` with ``r >= 0``.
* A free vector is ``(x, y)``.

Geometry never raises.  An entry with no answer (arcs that do not meet, the
join of coincident points) comes back as NaN; the construction layer decides
what that means and names the step.  The meet of parallel lines is an ideal
point, not a failure.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (graphic solution of the planar vector equation).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike, NDArray

from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = [
    "point",
    "ideal_point",
    "vector",
    "xy",
    "normalize_point",
    "normalize_line",
    "join",
    "meet",
    "line_through",
    "parallel",
    "perpendicular",
    "direction",
    "project",
    "reflect",
    "midpoint",
    "translate",
    "distance",
    "signed_distance",
    "angle_of",
    "angle_between",
    "circle",
    "intersect_circles",
    "intersect_line_circle",
    "similar_point",
    "rotate",
    "cross2",
    "dot2",
    "is_ideal",
]

Array = NDArray[np.float64]


def _f(a: ArrayLike) -> Array:
    return np.asarray(a, dtype=float)


def point(x: ArrayLike, y: ArrayLike) -> Array:
    """Finite point(s) ``(x, y, 1)``.

    Examples
    --------
    >>> point(3, 4)
    array([3., 4., 1.])
    """
    x, y = np.broadcast_arrays(_f(x), _f(y))
    return np.stack([x, y, np.ones_like(x)], axis=-1)


def ideal_point(dx: ArrayLike, dy: ArrayLike) -> Array:
    """Point(s) at infinity in the direction ``(dx, dy)`` (normalised to unit length).

    Examples
    --------
    >>> ideal_point(0, 2)
    array([0., 1., 0.])
    """
    dx, dy = np.broadcast_arrays(_f(dx), _f(dy))
    n = np.hypot(dx, dy)
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.stack([dx / n, dy / n, np.zeros_like(dx)], axis=-1)


def vector(x: ArrayLike, y: ArrayLike) -> Array:
    """Free vector(s) ``(x, y)``."""
    x, y = np.broadcast_arrays(_f(x), _f(y))
    return np.stack([x, y], axis=-1)


def xy(p: ArrayLike) -> Array:
    """Cartesian coordinates of finite point(s); NaN for an ideal point.

    Examples
    --------
    >>> xy([2.0, 4.0, 2.0])
    array([1., 2.])
    """
    p = _f(p)
    with np.errstate(invalid="ignore", divide="ignore"):
        w = np.where(p[..., 2] == 0.0, np.nan, p[..., 2])
        return p[..., :2] / w[..., None]


def is_ideal(p: ArrayLike) -> NDArray[np.bool_]:
    """True where the point is at infinity (``w == 0`` after normalisation)."""
    return _f(p)[..., 2] == 0.0


def normalize_point(p: ArrayLike, tol: Tolerance | None = None) -> Array:
    """Bring point(s) to canonical form: ``w = 1``, or ``w = 0`` with a unit direction.

    A point is taken as ideal when ``|w|`` is below ``tol.angle`` times the
    length of ``(x, y)``: for the meet of two unit-normal lines ``w`` is the
    sine of their angle, so this is the angle test for parallel lines.
    An all-zero vector (no point at all) becomes NaN.
    """
    tol = tol or DEFAULT_TOL
    p = _f(p)
    n = np.hypot(p[..., 0], p[..., 1])
    w = p[..., 2]
    ideal = np.abs(w) <= tol.angle * n
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        fin = p / np.where(w == 0.0, np.nan, w)[..., None]
        ide = np.stack([p[..., 0] / n, p[..., 1] / n, np.zeros_like(w)], axis=-1)
    out = np.where(ideal[..., None], ide, fin)
    nothing = (n == 0.0) & (w == 0.0)
    return np.where(nothing[..., None], np.nan, out)


def normalize_line(line: ArrayLike) -> Array:
    """Scale line(s) to a unit normal; NaN where the normal vanishes (no line)."""
    line = _f(line)
    n = np.hypot(line[..., 0], line[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        return line / np.where(n == 0.0, np.nan, n)[..., None]


def join(p: ArrayLike, q: ArrayLike, tol: Tolerance | None = None) -> Array:
    """The line through two points, directed from ``p`` to ``q``.

    Either point may be ideal (the line through the other point in that
    direction).  Coincident points give NaN (the domain raises
    ``DegenerateError``).

    Examples
    --------
    >>> join(point(0, 0), point(2, 0))
    array([0., 1., 0.])
    >>> direction(join(point(1, 1), ideal_point(0, 1)))
    array([0., 1.])
    """
    tol = tol or DEFAULT_TOL
    p, q = _f(p), _f(q)
    line = np.cross(p, q)
    n = np.hypot(line[..., 0], line[..., 1])
    scale = np.maximum(np.hypot(p[..., 0], p[..., 1]), np.hypot(q[..., 0], q[..., 1]))
    both_finite = (p[..., 2] != 0.0) & (q[..., 2] != 0.0)
    small = np.where(both_finite, n <= tol.length(_f(scale)), n <= tol.angle)
    with np.errstate(invalid="ignore", divide="ignore"):
        out = line / n[..., None]
    return np.where(small[..., None], np.nan, out)


def meet(line1: ArrayLike, line2: ArrayLike, tol: Tolerance | None = None) -> Array:
    """The point common to two lines; an ideal point when they are parallel.

    The lines are taken with unit normals (as every line here is kept), so the
    ``w`` of their cross product is the sine of the angle between them: they
    are parallel when it is below ``tol.angle``.  Coincident lines give NaN.

    Examples
    --------
    >>> meet(join(point(0, 0), point(1, 1)), join(point(0, 2), point(1, 1)))
    array([1., 1., 1.])
    >>> abs(meet(join(point(0, 0), point(1, 0)), join(point(0, 1), point(1, 1))))
    array([1., 0., 0.])
    """
    tol = tol or DEFAULT_TOL
    l1, l2 = _f(line1), _f(line2)
    p = np.cross(l1, l2)
    # with unit normals, w is the sine of the angle between the lines: the parallel test
    # is an angle test, whatever the length unit (a meet far away is still finite)
    w = p[..., 2]
    n = np.hypot(p[..., 0], p[..., 1])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        fin = p / np.where(w == 0.0, np.nan, w)[..., None]
        ide = np.stack([p[..., 0] / n, p[..., 1] / n, np.zeros_like(w)], axis=-1)
    out = np.where((np.abs(w) <= tol.angle)[..., None], ide, fin)
    # coincident lines: parallel and the same offset
    same = (np.abs(p[..., 2]) <= tol.angle) & (
        np.abs(l1[..., 2] - np.sign(dot2(l1, l2)) * l2[..., 2])
        <= tol.length(np.maximum(np.abs(l1[..., 2]), np.abs(l2[..., 2])) + 1.0))
    return np.where(same[..., None], np.nan, out)


def direction(line: ArrayLike) -> Array:
    """Unit direction ``(b, -a)`` of line(s)."""
    line = _f(line)
    return np.stack([line[..., 1], -line[..., 0]], axis=-1)


def line_through(p: ArrayLike, d: ArrayLike) -> Array:
    """The line through finite point(s) ``p`` with direction ``d`` (a free vector).

    Examples
    --------
    >>> line_through(point(0, 1), vector(1, 0))
    array([ 0.,  1., -1.])
    """
    d = _f(d)
    return join(p, ideal_point(d[..., 0], d[..., 1]))


def parallel(line: ArrayLike, through: ArrayLike) -> Array:
    """The line parallel to ``line`` through the point ``through`` (same direction).

    ``line`` and ``through`` broadcast against each other (one line, many points).

    >>> parallel([0.0, 1.0, 0.0], [[0.0, 2.0, 1.0], [5.0, -1.0, 1.0]])
    array([[ 0.,  1., -2.],
           [ 0.,  1.,  1.]])
    """
    line, p = np.broadcast_arrays(_f(line), _f(through))
    with np.errstate(invalid="ignore", divide="ignore"):  # through an ideal point: no line
        c = -(line[..., 0] * p[..., 0] + line[..., 1] * p[..., 1]) / p[..., 2]
    return np.stack([line[..., 0], line[..., 1], c], axis=-1)


def perpendicular(line: ArrayLike, through: ArrayLike) -> Array:
    """The line perpendicular to ``line`` through ``through``.

    Its direction is ``line``'s normal ``(a, b)``: ``line``'s direction turned
    90° counterclockwise.

    Examples
    --------
    >>> direction(perpendicular(join(point(0, 0), point(1, 0)), point(3, 3)))
    array([0., 1.])
    """
    line, p = np.broadcast_arrays(_f(line), _f(through))
    a, b = line[..., 0], line[..., 1]
    with np.errstate(invalid="ignore", divide="ignore"):  # through an ideal point: no line
        c = (b * p[..., 0] - a * p[..., 1]) / p[..., 2]
    return np.stack([-b, a, c], axis=-1)


def project(p: ArrayLike, line: ArrayLike) -> Array:
    """The foot of the perpendicular from point ``p`` to ``line``."""
    return meet(line, perpendicular(line, p))


def reflect(p: ArrayLike, line: ArrayLike) -> Array:
    """The mirror image of finite point ``p`` in ``line``."""
    p = _f(p)
    s = signed_distance(line, p)
    line = _f(line)
    return point(p[..., 0] - 2 * s * line[..., 0], p[..., 1] - 2 * s * line[..., 1])


def midpoint(p: ArrayLike, q: ArrayLike) -> Array:
    """Midpoint of two finite points."""
    a, b = xy(p), xy(q)
    m = (a + b) / 2
    return point(m[..., 0], m[..., 1])


def translate(p: ArrayLike, v: ArrayLike) -> Array:
    """Finite point ``p`` moved by the free vector ``v`` (the tip of ``v`` laid off from ``p``)."""
    a, v = xy(p), _f(v)
    return point(a[..., 0] + v[..., 0], a[..., 1] + v[..., 1])


def distance(p: ArrayLike, q: ArrayLike) -> Array:
    """Distance between finite points."""
    d = xy(q) - xy(p)
    return np.hypot(d[..., 0], d[..., 1])


def signed_distance(line: ArrayLike, p: ArrayLike) -> Array:
    """Signed distance of finite point ``p`` from ``line``: positive on the normal's side."""
    line, q = _f(line), xy(p)
    return line[..., 0] * q[..., 0] + line[..., 1] * q[..., 1] + line[..., 2]


def angle_of(v: ArrayLike) -> Array:
    """Direction angle (rad, counterclockwise from +x) of free vector(s)."""
    v = _f(v)
    return np.arctan2(v[..., 1], v[..., 0])


def angle_between(line1: ArrayLike, line2: ArrayLike) -> Array:
    """Angle (rad) from the direction of ``line1`` to that of ``line2``, in (-π, π]."""
    d1, d2 = direction(line1), direction(line2)
    return np.arctan2(cross2(d1, d2), dot2(d1, d2))


def circle(center: ArrayLike, radius: ArrayLike) -> Array:
    """Circle(s) ``(cx, cy, r)`` from a finite center and a radius."""
    c = xy(center)
    r = _f(radius)
    shape = np.broadcast_shapes(c.shape[:-1], r.shape)
    c = np.broadcast_to(c, (*shape, 2))
    return np.concatenate([c, np.broadcast_to(r, shape)[..., None]], axis=-1)


def cross2(u: ArrayLike, v: ArrayLike) -> Array:
    """Z component of the cross product of 2-D vectors (first two components used)."""
    u, v = _f(u), _f(v)
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def dot2(u: ArrayLike, v: ArrayLike) -> Array:
    """Dot product of 2-D vectors (first two components used)."""
    u, v = _f(u), _f(v)
    return u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]


def rotate(v: ArrayLike, angle: ArrayLike) -> Array:
    """Free vector(s) turned counterclockwise by ``angle`` (rad)."""
    v, t = _f(v), _f(angle)
    c, s = np.cos(t), np.sin(t)
    return np.stack([c * v[..., 0] - s * v[..., 1], s * v[..., 0] + c * v[..., 1]], axis=-1)


def intersect_circles(c1: ArrayLike, c2: ArrayLike,
                      tol: Tolerance | None = None) -> tuple[Array, Array]:
    """The two points common to two circles: ``(left, right)``.

    ``left`` lies to the left of the directed line from the first center to the
    second (positive cross product), ``right`` to its right.  Tangent circles
    (within tolerance) give the same point twice; circles that do not meet
    give NaN; concentric circles give NaN.  This is case 4 of Table 2.2.

    Examples
    --------
    >>> left, right = intersect_circles([0, 0, 5], [8, 0, 5])
    >>> xy(left), xy(right)
    (array([4., 3.]), array([ 4., -3.]))
    """
    tol = tol or DEFAULT_TOL
    c1, c2 = _f(c1), _f(c2)
    d = c2[..., :2] - c1[..., :2]
    dist = np.hypot(d[..., 0], d[..., 1])
    r1, r2 = c1[..., 2], c2[..., 2]
    scale = np.maximum(np.maximum(r1, r2), dist)
    eps = tol.length(_f(scale))
    with np.errstate(invalid="ignore", divide="ignore"):
        a = (dist**2 + r1**2 - r2**2) / (2 * dist)
        h2 = r1**2 - a**2
        # tangency: clamp tiny negative h² that comes from a length error below eps
        h2 = np.where((h2 < 0) & (h2 > -2 * eps * scale), 0.0, h2)
        h = np.sqrt(np.where(h2 >= 0, h2, np.nan))
        h = np.where(dist <= eps, np.nan, h)
        u = d / dist[..., None]
    base = c1[..., :2] + a[..., None] * u
    nrm = np.stack([-u[..., 1], u[..., 0]], axis=-1)
    left = base + h[..., None] * nrm
    right = base - h[..., None] * nrm
    return point(left[..., 0], left[..., 1]), point(right[..., 0], right[..., 1])


def intersect_line_circle(line: ArrayLike, c: ArrayLike,
                          tol: Tolerance | None = None) -> tuple[Array, Array]:
    """The two points common to a line and a circle: ``(behind, ahead)``.

    The points are ordered along the line's direction: ``behind`` comes first,
    ``ahead`` second.  A tangent line (within tolerance) gives the foot twice;
    a line that misses gives NaN.  This is case 2 of Table 2.2.

    Examples
    --------
    >>> behind, ahead = intersect_line_circle(join(point(-9, 0), point(9, 0)), [0, 0, 5])
    >>> xy(behind), xy(ahead)
    (array([-5.,  0.]), array([5., 0.]))
    """
    tol = tol or DEFAULT_TOL
    line, c = _f(line), _f(c)
    r = c[..., 2]
    s = line[..., 0] * c[..., 0] + line[..., 1] * c[..., 1] + line[..., 2]
    foot = c[..., :2] - s[..., None] * line[..., :2]
    eps = tol.length(np.maximum(r, np.abs(s)))
    h2 = r**2 - s**2
    h2 = np.where((h2 < 0) & (h2 > -2 * eps * np.maximum(r, 1e-300)), 0.0, h2)
    with np.errstate(invalid="ignore"):
        h = np.sqrt(np.where(h2 >= 0, h2, np.nan))
    d = direction(line)
    behind = foot - h[..., None] * d
    ahead = foot + h[..., None] * d
    return point(behind[..., 0], behind[..., 1]), point(ahead[..., 0], ahead[..., 1])


def similar_point(a: ArrayLike, b: ArrayLike, local_a: ArrayLike, local_b: ArrayLike,
                  local_p: ArrayLike) -> Array:
    """The point that stands to ``a, b`` as ``local_p`` stands to ``local_a, local_b``.

    Complex ratio ``p = a + (b - a) (P - A) / (B - A)``: the directly similar
    triangle.  This one operation places a link from two of its points, and
    builds the velocity and acceleration images of a link (Mehmke's theorem,
    Sec. 3.5, 4.3).  When ``a == b`` (a translating link's image) every point
    maps to ``a``.

    Examples
    --------
    >>> similar_point(point(0, 0), point(0, 2), [0, 0], [1, 0], [1, 1])
    array([-2.,  2.,  1.])
    """
    pa, pb = xy(a), xy(b)
    la, lb, lp = _f(local_a), _f(local_b), _f(local_p)
    zr = lb - la
    zp = lp - la
    den = zr[..., 0] ** 2 + zr[..., 1] ** 2
    # ratio q = zp / zr as a complex number
    qr = (zp[..., 0] * zr[..., 0] + zp[..., 1] * zr[..., 1]) / den
    qi = (zp[..., 1] * zr[..., 0] - zp[..., 0] * zr[..., 1]) / den
    d = pb - pa
    x = pa[..., 0] + d[..., 0] * qr - d[..., 1] * qi
    y = pa[..., 1] + d[..., 0] * qi + d[..., 1] * qr
    return point(x, y)
