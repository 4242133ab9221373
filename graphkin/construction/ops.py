"""The operations a construction step may perform, by name.

Each operation takes the arrays named by the step's ``inputs`` (any common
leading shape), the step's ``params`` and a tolerance, and returns a tuple of
arrays, one per output.  They are thin wrappers over :mod:`graphkin.geometry.ops`;
none of them loops over postures.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 1-4), 3.4-3.5 and 4.2-4.3
(velocity and acceleration polygons and images).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

__all__ = ["OPS", "op", "OUTPUT_KIND"]

Array = np.ndarray
OPS: dict[str, Callable[..., tuple[Array, ...]]] = {}
OUTPUT_KIND: dict[str, str] = {}


def op(name: str, kind: str = "point") -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Register an operation under ``name``; ``kind`` is the kind of its outputs."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        OPS[name] = f
        OUTPUT_KIND[name] = kind
        return f

    return deco


@op("point")
def _point(*, tol: Tolerance, xy: tuple[float, float]) -> tuple[Array]:
    """A fixed point given by its coordinates (a frame pivot)."""
    return (g.point(*xy),)


@op("ideal_point")
def _ideal(*, tol: Tolerance, direction: tuple[float, float]) -> tuple[Array]:
    """A fixed point at infinity."""
    return (g.ideal_point(*direction),)


@op("rigid")
def _rigid(p: Array, theta: Array, *, tol: Tolerance, local_p: tuple[float, float],
           local_q: tuple[float, float], offset: float = 0.0) -> tuple[Array]:
    """Lay off a link: ``Q = P + R(θ + offset)(q - p)`` (case 1: magnitude and direction known)."""
    d = np.subtract(local_q, local_p)
    v = g.rotate(d, np.asarray(theta) + offset)
    return (g.translate(p, v),)


@op("similar")
def _similar(a: Array, b: Array, *, tol: Tolerance, local_a: tuple[float, float],
             local_b: tuple[float, float], local_p: tuple[float, float]) -> tuple[Array]:
    """The image of a point similar to its link (placement, velocity and acceleration images)."""
    return (g.similar_point(a, b, local_a, local_b, local_p),)


@op("link_angle", kind="scalar")
def _link_angle(a: Array, b: Array, *, tol: Tolerance, local_a: tuple[float, float],
                local_b: tuple[float, float]) -> tuple[Array]:
    """Angle of a link's x axis from two of its placed points."""
    d = g.xy(b) - g.xy(a)
    dl = np.subtract(local_b, local_a)
    return (np.arctan2(d[..., 1], d[..., 0]) - np.arctan2(dl[1], dl[0]),)


@op("add_angle", kind="scalar")
def _add_angle(theta: Array, *, tol: Tolerance, offset: float) -> tuple[Array]:
    """An angle that differs from a known one by a constant (a slider keeps its angle)."""
    return (np.asarray(theta) + offset,)


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


@op("translate")
def _translate(p: Array, v: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known vector from a point (case 1)."""
    return (g.translate(p, v),)


@op("vector", kind="vector")
def _vector(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The vector from P to Q."""
    return (g.xy(q) - g.xy(p),)


@op("scale_vector", kind="vector")
def _scale_vector(v: Array, s: Array, *, tol: Tolerance, factor: float = 1.0) -> tuple[Array]:
    """A vector times a scalar (and a constant factor)."""
    return (np.asarray(v) * (np.asarray(s) * factor)[..., None],)


@op("input", kind="scalar")
def _input(*, tol: Tolerance, name: str) -> tuple[Array]:  # pragma: no cover - never called
    """A given input (a drive angle or travel): its value is supplied at evaluation."""
    raise KeyError(name)


@op("scalar", kind="scalar")
def _scalar(*, tol: Tolerance, value: float) -> tuple[Array]:
    """A constant (the frame's angle)."""
    return (np.asarray(float(value)),)


@op("along_line")
def _along_line(p0: Array, p1: Array, s: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off the travel ``s`` from P0 toward P1 (a slider's given position)."""
    a, b = g.xy(p0), g.xy(p1)
    d = b - a
    n = np.hypot(d[..., 0], d[..., 1])
    q = a + d * (np.asarray(s) / n)[..., None]
    return (g.point(q[..., 0], q[..., 1]),)


@op("image")
def _image(a: Array, b: Array, img_a: Array, img_b: Array, p: Array, *,
           tol: Tolerance) -> tuple[Array]:
    """Image of a point of a link from its position: the triangle abp is similar to ABP.

    Mehmke's theorem (Sec. 3.5, 4.3): ``p' = a' + (b' - a') (P - A) / (B - A)``.
    """
    za, zb, zp = g.xy(a), g.xy(b), g.xy(p)
    return (g.similar_point(img_a, img_b, za, zb, zp),)


# ---- velocity and acceleration polygons (images are points of the polygon's plane) ----

@op("velocity_difference")
def _velocity_difference(img_a: Array, omega: Array, a: Array, x: Array, *,
                         tol: Tolerance) -> tuple[Array]:
    """Case 1: ``V_X = V_A + ω × R_XA`` (Eq. 3.4); the image of X from the image of A."""
    r = g.xy(x) - g.xy(a)
    w = np.asarray(omega)[..., None]
    return (g.translate(img_a, w * np.stack([-r[..., 1], r[..., 0]], axis=-1)),)


@op("acceleration_difference")
def _acceleration_difference(img_a: Array, omega: Array, alpha: Array, a: Array, x: Array, *,
                             tol: Tolerance) -> tuple[Array]:
    """Case 1: ``A_X = A_A + α × R_XA − ω² R_XA`` (Eq. 4.5)."""
    r = g.xy(x) - g.xy(a)
    w = np.asarray(omega)[..., None]
    al = np.asarray(alpha)[..., None]
    return (g.translate(img_a, al * np.stack([-r[..., 1], r[..., 0]], axis=-1) - w**2 * r),)


@op("angular_rate", kind="scalar")
def _angular_rate(a: Array, b: Array, img_a: Array, img_b: Array, *,
                  tol: Tolerance) -> tuple[Array]:
    """ω (or α) of a link from two of its points and their images.

    ``ω = (R_BA × V_BA)/R_BA²``: the length of the image line over the link
    line, with the sense from the image's turn (Sec. 3.4).  For accelerations
    the normal component is along R_BA and drops out, leaving α (Sec. 4.3).
    """
    r = g.xy(b) - g.xy(a)
    v = g.xy(img_b) - g.xy(img_a)
    return (g.cross2(r, v) / g.dot2(r, r),)


@op("normal_component", kind="vector")
def _normal_component(p: Array, c: Array, img_p: Array, img_c: Array, *,
                      tol: Tolerance) -> tuple[Array]:
    """``A_CP^n = −(V_CP²/R_CP) R̂_CP``: toward P, of length V²/R (Eq. 4.7)."""
    r = g.xy(c) - g.xy(p)
    v = g.xy(img_c) - g.xy(img_p)
    return (-(g.dot2(v, v) / g.dot2(r, r))[..., None] * r,)


@op("coriolis", kind="vector")
def _coriolis(omega: Array, img_p: Array, img_pk: Array, *, tol: Tolerance) -> tuple[Array]:
    """Coriolis component ``2 ω × V_rel`` (Eq. 4.15), with ω of the link that carries the path."""
    v = g.xy(img_p) - g.xy(img_pk)
    w = np.asarray(omega)[..., None]
    return (2 * w * np.stack([-v[..., 1], v[..., 0]], axis=-1),)


@op("apparent_normal", kind="vector")
def _apparent_normal(s: Array, center: Array, img_s: Array, img_sk: Array, *,
                     tol: Tolerance) -> tuple[Array]:
    """Apparent normal component ``V_rel²/ρ`` toward the path's center of curvature (Eq. 4.15)."""
    r = g.xy(center) - g.xy(s)
    v = g.xy(img_s) - g.xy(img_sk)
    return ((g.dot2(v, v) / g.dot2(r, r))[..., None] * r,)


@op("add_along")
def _add_along(p: Array, p0: Array, p1: Array, s: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known amount ``s`` along the direction P0 → P1 from a point."""
    d = g.xy(p1) - g.xy(p0)
    n = np.hypot(d[..., 0], d[..., 1])
    return (g.translate(p, d * (np.asarray(s) / n)[..., None]),)


@op("subtract")
def _subtract(p: Array, v: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known vector backward from a point (vector subtraction)."""
    return (g.translate(p, -np.asarray(v)),)


@op("rolling_normal", kind="vector")
def _rolling_normal(c: Array, center: Array, omega_i: Array, omega_j: Array, *,
                    tol: Tolerance, factor: float = 1.0) -> tuple[Array]:
    """Rolling-contact component ``A^r`` (Eq. 4.19), normal to the surfaces.

    The contact point of a circle of radius ρ, seen from the link it rolls on,
    has the acceleration ``factor · ρ ω_rel²`` toward the circle's center:
    ``factor`` is 1 on a line and ``R/(R ± ρ)`` on a circle of radius R
    (outside / inside).
    """
    r = g.xy(center) - g.xy(c)
    w = (np.asarray(omega_i) - np.asarray(omega_j))[..., None]
    return (factor * w**2 * r,)


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


# ---- instant centers and curvature ------------------------------------------------

@op("at_infinity_on")
def _at_infinity_on(line: Array, *, tol: Tolerance) -> tuple[Array]:
    """The point at infinity of a line (where it meets every parallel to it)."""
    d = g.direction(line)
    return (g.ideal_point(d[..., 0], d[..., 1]),)


@op("same_point")
def _same_point(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """Two centers that coincide: a third center is that same point (Kennedy)."""
    return (np.asarray(p, dtype=float).copy(),)


@op("copy_point")
def _copy_point(p: Array, *, tol: Tolerance) -> tuple[Array]:
    """A point that coincides with a known one."""
    return (np.asarray(p, dtype=float).copy(),)


@op("homogeneous_point")
def _homogeneous_point(*, tol: Tolerance, h: Any) -> tuple[Array]:
    """A point given by homogeneous coordinates ``(x, y, w)``, finite or at infinity."""
    return (g.normalize_point(np.asarray(h, dtype=float), tol),)


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


@op("parallelogram")
def _parallelogram(p: Array, a: Array, b: Array, *, tol: Tolerance) -> tuple[Array]:
    """Complete the parallelogram P, A, G, B: ``G = A + B - P``.

    A vertex at infinity makes the opposite vertex that same point at infinity
    (the two sides through it are parallel to it).
    """
    p, a, b = (np.asarray(x, dtype=float) for x in (p, a, b))
    fin = g.point(*np.moveaxis(g.xy(a) + g.xy(b) - g.xy(p), -1, 0))
    out = np.where(g.is_ideal(b)[..., None], b, fin)
    return (np.where(g.is_ideal(a)[..., None], a, out),)


# ---------------------------------------------------------------------------
# Compiled kernels: the same operations, specialised once per step.
#
# A construction evaluated on whole arrays (a sweep) spends its time in the
# temporaries of the general functions above (np.stack, np.where, hypot,
# homogeneous divisions) and in reading data that has left the cache.  Each
# kernel below does the arithmetic of one step with its constants bound once:
# a point's Cartesian rows are read once per evaluation and shared; points
# stored with w == 1 skip the homogeneous division; tolerance decisions are
# made exactly, but only where a cheap bound cannot rule them out; outputs
# are written row by row straight into one block ``(k, ...)`` seen as
# ``(..., k)``; the cosine and sine of a link angle measured from two points
# are those points' direction; a constant zero is not subtracted.  The
# results are those of the general functions up to rounding (``sqrt(x² + y²)``
# for ``hypot``, the direction for ``cos(atan2(y, x))``), with the same NaN
# entries.  An operation without a kernel runs through its
# general function.
# ---------------------------------------------------------------------------

Kernel = Callable[["Runtime"], "bool | None"]
"""A compiled step: returns True when its outputs are certainly finite (given finite inputs)."""
KernelFactory = Callable[..., "Kernel | None"]
KERNELS: dict[str, KernelFactory] = {}
ORIGINATING: set[str] = set()
"""Operations that can turn finite inputs into non-finite outputs (the others cannot)."""

_ND = np.ndarray


def kernel(name: str, originating: bool = False) -> Callable[[KernelFactory], KernelFactory]:
    """Register the kernel factory of operation ``name``.

    The factory is called as ``factory(step, tol, info)`` and returns a
    callable ``run(rt)`` that reads the step's inputs from the runtime and
    stores its outputs, or ``None`` to fall back to the general function.
    ``originating`` operations can give non-finite outputs for finite inputs
    (no intersection, a division by a length that may vanish).
    """

    def deco(f: KernelFactory) -> KernelFactory:
        KERNELS[name] = f
        if originating:
            ORIGINATING.add(name)
        return f

    return deco


class CompileInfo:
    """What is known of the labels when a construction is compiled.

    Attributes
    ----------
    const : dict
        Labels whose values are constant (folded): label -> array.
    radius : dict
        Circles whose radius is a step constant: label -> radius.
    """

    def __init__(self) -> None:
        self.const: dict[str, Array] = {}
        self.radius: dict[str, float] = {}

    def forget(self, label: str) -> None:
        """A step (re)defines ``label``: drop what was known of it."""
        self.const.pop(label, None)
        self.radius.pop(label, None)


def _shape(*xs: Any) -> tuple[int, ...]:
    """The broadcast shape of the arguments (arrays, numpy scalars, floats)."""
    s: tuple[int, ...] = ()
    for x in xs:
        if type(x) is _ND:
            t = x.shape
            if t != s:
                s = t if not s else np.broadcast_shapes(s, t)
    return s


def _zero(v: Any) -> bool:
    """True for a constant (a float) equal to zero: subtracting it is skipped."""
    return type(v) is float and v == 0.0


def _vmin(x: Any) -> float:
    """Smallest entry, NaN ignored (NaN when every entry is NaN)."""
    if type(x) is not _ND or x.ndim == 0:
        return float(x)
    return float(np.fmin.reduce(x, axis=None))


def _absmax(a: Any) -> float:
    """Largest absolute entry (NaN ignored)."""
    if type(a) is not _ND or a.ndim == 0:
        return abs(float(a))
    return float(np.fmax.reduce(np.abs(a), axis=None))


def _drawn_join(rt: Runtime, out: str, p: Any, q: Any) -> bool:
    """True when this replay already drew the line ``out`` through these very point arrays.

    The acceleration polygon redraws the posture's lines that the velocity
    polygon drew; replayed together they are drawn once.
    """
    hit = rt.joins.get(out)
    return hit is not None and hit[0] is p and hit[1] is q and rt.env.get(out) is hit[2]


class Runtime:
    """The state of one compiled evaluation.

    Attributes
    ----------
    env : dict
        Label -> array (what :class:`~graphkin.construction.protocol.Evaluation` returns).
    xy : dict
        Label -> Cartesian rows ``(x, y)`` of a point (or a circle's center,
        or a vector's components), read once.  Constant points have floats.
    unit : set
        Point labels stored with ``w == 1`` (or all NaN): their first two
        rows are their Cartesian coordinates.
    trig : dict
        Angle label -> ``(cos, sin)``.
    dirty : set
        Labels whose consumers must be checked for non-finite entries:
        inputs given with non-finite entries, points that may be at infinity.
    joins : dict
        Line label -> the point arrays it was drawn through (and the line).
    """

    __slots__ = ("env", "xy", "unit", "trig", "trig_off", "dirty", "joins")

    def __init__(self, env: dict[str, Array]) -> None:
        self.env = env
        self.xy: dict[str, tuple[Any, Any]] = {}
        self.unit: set[str] = set()
        self.trig: dict[str, tuple[Any, Any]] = {}
        self.trig_off: dict[tuple[str, float], tuple[Any, Any]] = {}
        self.dirty: set[str] = set()
        self.joins: dict[str, tuple[Any, Any, Any]] = {}

    # ---- inputs --------------------------------------------------------
    def arr(self, label: str) -> Array:
        """The value of ``label`` as a float array."""
        a = self.env[label]
        if type(a) is not _ND or a.dtype != np.float64:
            a = np.asarray(a, dtype=float)
        return a

    def P(self, label: str) -> tuple[Any, Any]:
        """Cartesian rows of a point (NaN for a point at infinity)."""
        r = self.xy.get(label)
        if r is not None:
            return r
        p = self.arr(label)
        if (p[..., 2] == 1.0).all():
            r = (p[..., 0], p[..., 1])
            self.unit.add(label)
        else:
            q = g.xy(p)
            r = (q[..., 0], q[..., 1])
            self.dirty.add(label)
        self.xy[label] = r
        return r

    def is_unit(self, label: str) -> bool:
        """True when the point's ``w`` is exactly 1 (so its rows are its Cartesian coordinates)."""
        if label not in self.xy:
            self.P(label)
        return label in self.unit

    def C(self, label: str) -> tuple[Any, Any]:
        """First two rows of a circle (its center) or of a vector (its components)."""
        r = self.xy.get(label)
        if r is not None:
            return r
        c = self.arr(label)
        r = (c[..., 0], c[..., 1])
        self.xy[label] = r
        return r

    V = C

    def rows(self, label: str) -> tuple[Any, Any, Any]:
        """The three homogeneous rows of a point, line or circle."""
        a = self.arr(label)
        return a[..., 0], a[..., 1], a[..., 2]

    def cs(self, label: str, offset: float = 0.0) -> tuple[Any, Any]:
        """The cosine and sine of an angle (plus a constant offset), computed once."""
        if offset == 0.0:
            r = self.trig.get(label)
            if r is None:
                t = self.arr(label)
                r = self.trig[label] = (np.cos(t), np.sin(t))
            return r
        r = self.trig_off.get((label, offset))
        if r is None:
            t = self.arr(label) + offset
            r = self.trig_off[(label, offset)] = (np.cos(t), np.sin(t))
        return r

    # ---- outputs -------------------------------------------------------
    def _forget(self, label: str) -> None:
        self.xy.pop(label, None)
        self.unit.discard(label)
        self.dirty.discard(label)
        self.trig.pop(label, None)
        if self.trig_off:
            for k in [k for k in self.trig_off if k[0] == label]:
                del self.trig_off[k]

    def new_point(self, label: str, shape: tuple[int, ...]) -> tuple[Array, Array]:
        """Store a new finite-form point ``(x, y, 1)``; returns its x and y rows to fill."""
        base = np.empty((3, *shape))
        base[2] = 1.0
        if shape:
            x, y = base[0], base[1]
            self.env[label] = base.T if len(shape) == 1 else np.moveaxis(base, 0, -1)
        else:
            x, y = base[0, ...], base[1, ...]
            self.env[label] = base
        self.xy[label] = (x, y)
        self.unit.add(label)
        if self.dirty:
            self.dirty.discard(label)
        if self.trig:
            self.trig.pop(label, None)
        if self.trig_off:
            for k in [k for k in self.trig_off if k[0] == label]:
                del self.trig_off[k]
        return x, y

    def new_rows(self, label: str, k: int, shape: tuple[int, ...], *,
                 center: bool = False) -> tuple[Array, ...]:
        """Store a new line, circle (``k = 3``) or vector (``k = 2``); returns its rows to fill.

        The block itself comes last.
        """
        base = np.empty((k, *shape))
        self._forget(label)
        if shape:
            rows = tuple(base[i] for i in range(k))
            self.env[label] = base.T if len(shape) == 1 else np.moveaxis(base, 0, -1)
        else:
            rows = tuple(base[i, ...] for i in range(k))
            self.env[label] = base
        if center or k == 2:
            self.xy[label] = (rows[0], rows[1])
        return (*rows, base)

    def put(self, label: str, value: Any) -> None:
        """Store any value (a scalar array, or what a general function returned)."""
        self._forget(label)
        self.env[label] = value


def generic_kernel(step: Any, tol: Tolerance) -> Kernel:
    """Run a step through its general function (no kernel, or an exact fallback)."""
    fn = OPS[step.op]
    ins, outs, params = step.inputs, step.outputs, step.params
    points = step.kind == "point"

    def run(rt: Runtime) -> None:
        vals = fn(*[rt.env[i] for i in ins], tol=tol, **params)
        for name, v in zip(outs, vals):
            rt.put(name, v)
            if points:
                rt.dirty.add(name)

    return run


@kernel("rigid")
def _k_rigid(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, th = step.inputs
    (out,) = step.outputs
    d0, d1 = (float(v) for v in np.subtract(step.params["local_q"], step.params["local_p"]))
    offset = float(step.params.get("offset", 0.0))

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(p)
        c, s = rt.cs(th, offset)
        x, y = rt.new_point(out, _shape(ax, c))
        # Q = P + R(θ) d: the rotation (c d0 - s d1, s d0 + c d1); a zero component drops out
        if d1 == 0.0:
            np.multiply(c, d0, out=x)
            np.multiply(s, d0, out=y)
        elif d0 == 0.0:
            np.multiply(s, -d1, out=x)
            np.multiply(c, d1, out=y)
        else:
            np.subtract(c * d0, s * d1, out=x)
            np.add(s * d0, c * d1, out=y)
        np.add(x, ax, out=x)
        np.add(y, ay, out=y)

    return run


@kernel("circle")
def _k_circle(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    (center,) = step.inputs
    (out,) = step.outputs
    r = float(step.params["radius"])

    def run(rt: Runtime) -> None:
        x, y = rt.P(center)
        cx, cy, cr, _ = rt.new_rows(out, 3, _shape(x, y), center=True)
        cx[...] = x
        cy[...] = y
        cr[...] = r

    return run


@kernel("intersect_circles", originating=True)
def _k_cc(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    c1, c2 = step.inputs
    (out,) = step.outputs
    left = step.params["branch"] == "left"
    k1, k2 = info.radius.get(c1), info.radius.get(c2)
    la, lr = tol.length_abs, tol.length_rel

    def run(rt: Runtime) -> bool:
        x1, y1 = rt.C(c1)
        x2, y2 = rt.C(c2)
        r1 = k1 if k1 is not None else rt.arr(c1)[..., 2]
        r2 = k2 if k2 is not None else rt.arr(c2)[..., 2]
        dx = x2 - x1
        dy = y2 - y1
        dd = dx * dx + dy * dy
        # along and across the line of centers, in units of its length d:
        # a/d = (d² + r1² - r2²) / 2d², (h/d)² = r1²/d² - (a/d)²
        p = (dd + (r1 * r1 - r2 * r2)) / (2.0 * dd)
        q2 = (r1 * r1) / dd - p * p
        clean = True
        if not _vmin(q2) >= 0.0:
            clean = False
            # tangency: a tiny negative h² from a length error below eps counts as zero
            dist = np.sqrt(dd)
            scale = np.maximum(np.maximum(r1, r2), dist)
            eps = la + lr * np.abs(scale)
            q2 = np.where((q2 < 0) & (q2 * dd > -2 * eps * scale), 0.0, q2)
        q = np.sqrt(q2)
        if not _vmin(dd) > (2.0 * (la + lr * max(_absmax(r1), _absmax(r2)))) ** 2:
            clean = False
            # concentric circles (within tolerance) have no intersection
            dist = np.sqrt(dd)
            scale = np.maximum(np.maximum(r1, r2), dist)
            q = np.where(dist <= la + lr * np.abs(scale), np.nan, q)
        x, y = rt.new_point(out, _shape(dx, x1, x2))
        # C1 + a u ± h k × u with u the unit vector from center 1 to center 2
        if left:
            np.subtract(p * dx, q * dy, out=x)
            np.add(p * dy, q * dx, out=y)
        else:
            np.add(p * dx, q * dy, out=x)
            np.subtract(p * dy, q * dx, out=y)
        np.add(x, x1, out=x)
        np.add(y, y1, out=y)
        # finite inputs, every arc pair meets, no concentric pair: every entry is finite
        return clean

    return run


@kernel("intersect_line_circle", originating=True)
def _k_lc(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    line, c = step.inputs
    (out,) = step.outputs
    behind = step.params["branch"] == "behind"
    kr = info.radius.get(c)
    la, lr = tol.length_abs, tol.length_rel

    def run(rt: Runtime) -> bool:
        l0, l1, l2 = rt.rows(line)
        cx, cy = rt.C(c)
        r = kr if kr is not None else rt.arr(c)[..., 2]
        s = l0 * cx + l1 * cy + l2
        h2 = r * r - s * s
        clean = True
        if not _vmin(h2) >= 0.0:
            clean = False
            eps = la + lr * np.abs(np.maximum(r, np.abs(s)))
            h2 = np.where((h2 < 0) & (h2 > -2 * eps * np.maximum(r, 1e-300)), 0.0, h2)
        h = np.sqrt(h2)
        x, y = rt.new_point(out, _shape(s, cx, cy))
        # the foot of the perpendicular from the center, then ∓ h along the line (l1, -l0)
        if behind:
            np.add(s * l0, h * l1, out=x)
            np.subtract(s * l1, h * l0, out=y)
        else:
            np.subtract(s * l0, h * l1, out=x)
            np.add(s * l1, h * l0, out=y)
        np.subtract(cx, x, out=x)
        np.subtract(cy, y, out=y)
        return clean

    return run


@kernel("link_angle")
def _k_link_angle(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    a, b = step.inputs
    (out,) = step.outputs
    dl = np.subtract(step.params["local_b"], step.params["local_a"])
    phi = float(np.arctan2(dl[1], dl[0]))
    cphi, sphi = math.cos(phi), math.sin(phi)

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        bx, by = rt.P(b)
        dx = bx if _zero(ax) else bx - ax
        dy = by if _zero(ay) else by - ay
        t = np.arctan2(dy, dx)
        rt.put(out, t - phi if phi != 0.0 else t)
        # the direction AB gives cos and sin of the line's angle (not where A == B,
        # whose angle atan2 takes as 0)
        n = np.sqrt(dx * dx + dy * dy)
        if _vmin(n) > 0.0:
            c = dx / n
            s = dy / n
            if phi != 0.0:
                c, s = c * cphi + s * sphi, s * cphi - c * sphi
            rt.trig[out] = (c, s)

    return run


@kernel("angle_along")
def _k_angle_along(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    t_, s_ = step.inputs
    (out,) = step.outputs
    phi = float(step.params["local_angle"])
    sign = float(step.params["sign"])

    def run(rt: Runtime) -> None:
        tx, ty = rt.P(t_)
        sx, sy = rt.P(s_)
        dx = (sx - tx) * sign
        dy = (sy - ty) * sign
        rt.put(out, np.arctan2(dy, dx) - phi)

    return run


@kernel("add_angle")
def _k_add_angle(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    (th,) = step.inputs
    (out,) = step.outputs
    offset = step.params["offset"]

    def run(rt: Runtime) -> None:
        rt.put(out, np.asarray(rt.env[th]) + offset)

    return run


@kernel("join", originating=True)
def _k_join(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, q = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> bool:
        env = rt.env
        pa, qa = env[p], env[q]
        if _drawn_join(rt, out, pa, qa):
            return False
        if not (rt.is_unit(p) and rt.is_unit(q)):
            rt.put(out, g.join(pa, qa, tol))
            rt.joins[out] = (pa, qa, env[out])
            return False
        px, py = rt.P(p)
        qx, qy = rt.P(q)
        # the cross product (px, py, 1) × (qx, qy, 1)
        a_, b_, c_, base = rt.new_rows(out, 3, _shape(px, qx))
        np.subtract(py, qy, out=a_)
        np.subtract(qx, px, out=b_)
        np.subtract(px * qy, py * qx, out=c_)
        n = np.sqrt(a_ * a_ + b_ * b_)
        # coincident points: n = |P - Q| within the length tolerance of the larger of |P|, |Q|;
        # as max(|P|, |Q|) <= |Q| + n, none is when n (1 - rel) > abs + rel |Q| everywhere
        far = pa if (np.ndim(px) == 0 and np.ndim(qx) != 0) else qa
        big = _absmax(np.asarray(far, dtype=float)[..., :2])
        clean = True
        if not _vmin(n) * (1.0 - tol.length_rel) > tol.length(2.0 * big):
            clean = False
            scale = np.maximum(np.sqrt(px * px + py * py), np.sqrt(qx * qx + qy * qy))
            n = np.where(n <= tol.length(scale), np.nan, n)
        np.divide(base, n, out=base)
        rt.joins[out] = (pa, qa, env[out])
        return clean

    return run


@kernel("perpendicular")
def _k_perpendicular(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    line, p = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        a, b, _ = rt.rows(line)
        px, py, pw = rt.rows(p)
        unit = rt.is_unit(p)
        o0, o1, o2, _ = rt.new_rows(out, 3, _shape(a, px))
        np.negative(b, out=o0)
        o1[...] = a
        np.subtract(b * px, a * py, out=o2)
        if not unit:
            np.divide(o2, pw, out=o2)

    return run


@kernel("parallel")
def _k_parallel(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    line, p = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        a, b, _ = rt.rows(line)
        px, py, pw = rt.rows(p)
        unit = rt.is_unit(p)
        o0, o1, o2, _ = rt.new_rows(out, 3, _shape(a, px))
        o0[...] = a
        o1[...] = b
        np.add(a * px, b * py, out=o2)
        np.negative(o2, out=o2)
        if not unit:
            np.divide(o2, pw, out=o2)

    return run


@kernel("meet", originating=True)
def _k_meet(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    l1, l2 = step.inputs
    (out,) = step.outputs
    # |w| <= angle n (ideal) or |w| <= angle (coincident lines), tested on squares with margin
    gate = (tol.angle * (1.0 + 1e-6)) ** 2

    def run(rt: Runtime) -> bool:
        a1, b1, c1 = rt.rows(l1)
        a2, b2, c2 = rt.rows(l2)
        pw = a1 * b2 - b1 * a2
        px = b1 * c2 - c1 * b2
        py = c1 * a2 - a1 * c2
        n2 = px * px + py * py
        if not bool(np.all(pw * pw > gate * np.maximum(n2, 1.0))):
            # somewhere parallel (an ideal point), coincident, or not known (NaN): exactly
            rt.put(out, g.meet(rt.env[l1], rt.env[l2], tol))
            rt.dirty.add(out)
            return False
        x, y = rt.new_point(out, _shape(pw, px, py))
        # a finite point: (px, py, pw) / pw
        np.divide(px, pw, out=x)
        np.divide(py, pw, out=y)
        return True

    return run


def _point_and_vector(ufunc: Any) -> KernelFactory:
    """Kernel factory of a point moved by a vector: ``ufunc`` is np.add or np.subtract."""

    def factory(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
        p, v = step.inputs
        (out,) = step.outputs

        def run(rt: Runtime) -> None:
            ax, ay = rt.P(p)
            vx, vy = rt.V(v)
            x, y = rt.new_point(out, _shape(ax, vx))
            ufunc(ax, vx, out=x)
            ufunc(ay, vy, out=y)

        return run

    return factory


kernel("translate")(_point_and_vector(np.add))
kernel("subtract")(_point_and_vector(np.subtract))


@kernel("vector")
def _k_vector(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, q = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        px, py = rt.P(p)
        qx, qy = rt.P(q)
        v0, v1, _ = rt.new_rows(out, 2, _shape(px, qx))
        np.subtract(qx, px, out=v0)
        np.subtract(qy, py, out=v1)

    return run


@kernel("scale_vector")
def _k_scale_vector(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    v, s = step.inputs
    (out,) = step.outputs
    factor = step.params.get("factor", 1.0)

    def run(rt: Runtime) -> None:
        vx, vy = rt.V(v)
        k = rt.arr(s) * factor
        v0, v1, _ = rt.new_rows(out, 2, _shape(vx, k))
        np.multiply(vx, k, out=v0)
        np.multiply(vy, k, out=v1)

    return run


@kernel("similar")
def _k_similar(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel | None:
    a, b = step.inputs
    (out,) = step.outputs
    la = np.asarray(step.params["local_a"], dtype=float)
    lb = np.asarray(step.params["local_b"], dtype=float)
    lp = np.asarray(step.params["local_p"], dtype=float)
    if la.shape != (2,) or lb.shape != (2,) or lp.shape != (2,):
        return None
    zr, zp = lb - la, lp - la
    den = zr[0] ** 2 + zr[1] ** 2
    if den == 0.0:
        return None
    # p = a + (b - a) q with the complex ratio q = (P - A) / (B - A) of the link
    qr = float((zp[0] * zr[0] + zp[1] * zr[1]) / den)
    qi = float((zp[1] * zr[0] - zp[0] * zr[1]) / den)

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        bx, by = rt.P(b)
        d0 = bx if _zero(ax) else bx - ax
        d1 = by if _zero(ay) else by - ay
        x, y = rt.new_point(out, _shape(d0, ax))
        np.subtract(d0 * qr, d1 * qi, out=x)
        np.add(d0 * qi, d1 * qr, out=y)
        np.add(x, ax, out=x)
        np.add(y, ay, out=y)

    return run


@kernel("velocity_difference")
def _k_vdiff(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    img, omega, a, x_ = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        xx, xy_ = rt.P(x_)
        ix, iy = rt.P(img)
        w = rt.arr(omega)
        rx = xx if _zero(ax) else xx - ax
        ry = xy_ if _zero(ay) else xy_ - ay
        x, y = rt.new_point(out, _shape(rx, ix, w))
        # V_X = V_A + ω k × R_XA
        np.multiply(w, ry, out=x)
        np.subtract(ix, x, out=x)
        np.multiply(w, rx, out=y)
        np.add(iy, y, out=y)

    return run


@kernel("acceleration_difference")
def _k_adiff(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    img, omega, alpha, a, x_ = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(a)
        xx, xy_ = rt.P(x_)
        ix, iy = rt.P(img)
        w = rt.arr(omega)
        al = rt.arr(alpha)
        w2 = w * w
        rx = xx if _zero(ax) else xx - ax
        ry = xy_ if _zero(ay) else xy_ - ay
        x, y = rt.new_point(out, _shape(rx, ix, w, al))
        # A_X = A_A + α k × R_XA - ω² R_XA
        np.add(al * ry, w2 * rx, out=x)
        np.subtract(ix, x, out=x)
        np.subtract(al * rx, w2 * ry, out=y)
        np.add(iy, y, out=y)

    return run


def _differences(rt: Runtime, a: str, b: str, ia: str,
                 ib: str) -> tuple[Any, Any, Any, Any]:
    """``R_BA`` and the image difference ``b − a`` as components (a zero term is skipped)."""
    ax, ay = rt.P(a)
    bx, by = rt.P(b)
    iax, iay = rt.P(ia)
    ibx, iby = rt.P(ib)
    return (bx if _zero(ax) else bx - ax, by if _zero(ay) else by - ay,
            ibx if _zero(iax) else ibx - iax, iby if _zero(iay) else iby - iay)


@kernel("angular_rate", originating=True)
def _k_angular_rate(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    a, b, ia, ib = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> bool:
        r0, r1, v0, v1 = _differences(rt, a, b, ia, ib)
        den = r0 * r0 + r1 * r1
        rt.put(out, (r0 * v1 - r1 * v0) / den)
        # finite inputs and two distinct points: a finite rate
        return _vmin(den) > 0.0

    return run


@kernel("normal_component", originating=True)
def _k_normal(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, c, ip, ic = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> bool:
        r0, r1, v0, v1 = _differences(rt, p, c, ip, ic)
        den = r0 * r0 + r1 * r1
        k = -((v0 * v0 + v1 * v1) / den)
        o0, o1, _ = rt.new_rows(out, 2, _shape(k, r0))
        np.multiply(k, r0, out=o0)
        np.multiply(k, r1, out=o1)
        return _vmin(den) > 0.0

    return run


@kernel("apparent_normal", originating=True)
def _k_apparent_normal(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    s, center, i_s, i_sk = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        sx, sy = rt.P(s)
        cx, cy = rt.P(center)
        ax, ay = rt.P(i_s)
        bx, by = rt.P(i_sk)
        r0 = cx - sx
        r1 = cy - sy
        v0 = ax - bx
        v1 = ay - by
        k = (v0 * v0 + v1 * v1) / (r0 * r0 + r1 * r1)
        o0, o1, _ = rt.new_rows(out, 2, _shape(k, r0))
        np.multiply(k, r0, out=o0)
        np.multiply(k, r1, out=o1)

    return run


@kernel("coriolis")
def _k_coriolis(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    omega, ip, ipk = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(ip)
        bx, by = rt.P(ipk)
        w2 = 2 * rt.arr(omega)
        v0 = ax - bx
        v1 = ay - by
        o0, o1, _ = rt.new_rows(out, 2, _shape(w2, v0))
        # 2 ω k × V_rel
        np.multiply(-w2, v1, out=o0)
        np.multiply(w2, v0, out=o1)

    return run


@kernel("add_along", originating=True)
def _k_add_along(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p, p0, p1, s = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        ax, ay = rt.P(p)
        x0, y0 = rt.P(p0)
        x1, y1 = rt.P(p1)
        d0 = x1 - x0
        d1 = y1 - y0
        k = rt.arr(s) / np.sqrt(d0 * d0 + d1 * d1)
        x, y = rt.new_point(out, _shape(ax, d0, k))
        np.multiply(d0, k, out=x)
        np.add(ax, x, out=x)
        np.multiply(d1, k, out=y)
        np.add(ay, y, out=y)

    return run


@kernel("along_line", originating=True)
def _k_along_line(step: Any, tol: Tolerance, info: CompileInfo) -> Kernel:
    p0, p1, s = step.inputs
    (out,) = step.outputs

    def run(rt: Runtime) -> None:
        x0, y0 = rt.P(p0)
        x1, y1 = rt.P(p1)
        d0 = x1 - x0
        d1 = y1 - y0
        k = rt.arr(s) / np.sqrt(d0 * d0 + d1 * d1)
        x, y = rt.new_point(out, _shape(x0, d0, k))
        np.multiply(d0, k, out=x)
        np.add(x0, x, out=x)
        np.multiply(d1, k, out=y)
        np.add(y0, y, out=y)

    return run


@op("along_ray")
def _along_ray(o: Array, x: Array, *, tol: Tolerance, distance: float) -> tuple[Array]:
    """The point at a known distance from O toward X (a contact point on the line of centers)."""
    a, b = g.xy(o), g.xy(x)
    d = b - a
    n = np.hypot(d[..., 0], d[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        q = a + d * (distance / n)[..., None]
    return (g.point(q[..., 0], q[..., 1]),)
