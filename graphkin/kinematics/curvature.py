"""Curvature theory: Euler-Savary, inflection and Bresse circles, Γ, cubic of stationary curvature.

For every moving link ``k`` that turns (``ω_k ≠ 0``) the motion ``k/1`` is
studied the way Secs. 4.12-4.17 of the book do it, as a recorded
:class:`~graphkin.construction.Construction` (``diagram="curvature"``) whose
steps carry the book's words, with a closed-form evaluation beside it:

1. **Velocity pole I** (Sec. 4.12): the meet of the perpendiculars to the
   velocities of two points of ``k`` -- the rays ``AA'`` and ``BB'`` of two
   pairs of conjugate points when they are known by inspection.
2. **Inflection pole J and the inflection circle** (diameter ``IJ``,
   Eq. 4.41).  *By Bobillier's construction* (Sec. 4.13, Fig. 4.29, Example
   4.13) when two pairs of conjugate points are known by inspection: a pin
   ``A`` of ``k`` whose other link turns about a frame pivot ``O`` has its
   center of curvature ``A' = O``; a point held on a frame-fixed straight line
   (a pin to a slider on the frame, a pin in a straight slot of the frame) has
   ``A'`` at infinity, normal to the line.  When the construction through
   ``W`` degenerates (``AB ∥ A'B'``, as in Example 4.16) the inflection points
   ``J_A``, ``J_B`` are laid off by Eq. 4.43, ``R_AJ_A = R_AI²/R_AA'``, as in
   Examples 4.14 and 4.16.  *From accelerations* otherwise: the point of ``k``
   at ``I`` has the acceleration ``A_I = ω² R_JI`` directed from ``I`` toward
   ``J`` (Eqs. 4.46-4.47), so ``J = I + A_I/ω²``; it is found from two points'
   accelerations by the acceleration image (Mehmke's theorem).
3. **Centrode normal and tangent.**  The positive centrode normal ``N``
   points from ``I`` toward ``J`` (the direction of ``A_I``, Sec. 4.15); the
   positive centrode tangent ``T`` is ``N`` turned 90° clockwise, so that
   ``N`` is 90° counterclockwise from ``T`` as Sec. 4.12 requires.  This is
   the book's own choice in Example 4.16 ("the centrode normal N is directed
   from I toward J, and the centrode tangent T is 90° clockwise from N"), and
   it makes ``R_JI`` positive.  With it the pole velocity is
   ``v = ω k × R_JI = -ω R_JI T`` (Eq. 4.47).
4. **Conjugate points** (centers of curvature of the paths): the
   Euler-Savary equation ``1/R_AI - 1/R_A'I = 1/R_J_AI`` (Eq. 4.42,
   ``R_J_AI = R_JI sin ψ``, Eq. 4.41) in closed form; graphically by
   Bobillier's construction of Fig. 4.30 (Example 4.13) or by the Hartmann
   construction of Fig. 4.25, which needs only the pole velocity and works
   for every point but ``I``.
5. **Bresse circle and Γ** (Secs. 4.14-4.15): the Bresse circle has the
   diameter ``b = R_JI ω²/α`` (Eq. 4.48) along the centrode tangent, on its
   negative side when ``α > 0``; it meets the inflection circle at ``I`` and at
   the instantaneous center of acceleration ``Γ``, which the four-circle
   method of Fig. 4.33 also finds from two points' accelerations.
6. **The cubic of stationary curvature** by Hain's construction (Sec. 4.17,
   Fig. 4.38) from two points of constant path curvature, its parameters of
   Eq. 4.55, ``1/r = 1/(M sin ψ) - 1/(N cos ψ)`` with ``r`` from ``I`` and
   ``ψ`` counterclockwise from ``T``; Ball's point (its intersection with the
   inflection circle); and the curvatures of the two centrodes from
   Eq. 4.56, ``1/M = (1/R_JI - 1/R_IO_M)/3``, and Eq. 4.40 with ``A = J``:
   ``1/R_IO_F = 1/R_JI + 1/R_IO_M`` (``R_IO = I - O`` measured along ``N``).

Signs of the cubic
------------------
In coordinates ``x`` along ``T`` and ``y`` along ``N`` from ``I``, Eq. 4.57
``(x² + y²)(x/M - y/N) = xy`` is linear in ``1/M`` and ``1/N``: two points of
the cubic give them.  In Hain's construction a point ``S`` of the cubic gives
``S_G = (r/cos ψ, r/sin ψ)``, and Eq. 4.55 becomes the straight line
``Y/M - X/N = 1``: the auxiliary line ``G``.  Hence ``G`` meets ``N`` at
``G_N = I + M N̂`` and ``T`` at ``G_T = I - N T̂``: ``M`` is the diameter of the
circle centered on the centrode *normal* that osculates the branch of the
cubic tangent to ``T``, and ``|N|`` that of the circle centered on the
centrode *tangent*.  (The sentence after Eq. 4.56 in the book, "M and N are,
respectively, the diameters IG_T and IG_N", has the two swapped; the
paragraph before it and Example 4.16 agree with the above.)

Ball's point ``U`` is on the inflection circle, so its ``S_G`` lies on the
tangent to that circle at ``J``: ``U`` is found by Hain's construction from
the point where ``G`` crosses that tangent.  When ``N`` is infinite the cubic
contains the centrode normal and ``U = J`` (Example 4.16).

Example 4.16: two misprinted centrode radii
-------------------------------------------
The book's Example 4.16 (``R_JI = 2√2`` in, ``M = -2√2`` in, ``N = ∞``)
substitutes ``R_JI = M = -2√2`` in Eq. 4.56 ("M = -R_BI = R_JI = -2√2 in",
Eq. 7), although its own Ans. (3) and its sign rule (``N`` from ``I`` toward
``J``) make ``R_JI = +2√2`` in, so ``M = -R_JI``.  It then finds
``R_IO_M = √2`` in (the moving centrode "coalesces with the inflection
circle") and ``R_IO_F = 2√2`` in (``O_F`` "coincident with J").  With
``M = -R_JI`` the same equations give::

    1/R_IO_M = 1/R_JI - 3/M = 4/R_JI   ->  R_IO_M = R_JI/4 = √2/2 = 0.7071 in
    1/R_IO_F = 1/R_JI + 1/R_IO_M = 5/R_JI -> R_IO_F = R_JI/5 = 2√2/5 = 0.5657 in

both positive: ``O_M`` and ``O_F`` lie on the side of ``I`` away from ``J``,
at ``O_M = (0.5, -0.5)`` in and ``O_F = (0.4, -0.6)`` in with ``O_2`` at the
origin (``I = (0, -1)``, ``J = (-2, -3)``).  The evidence is independent of
these formulas: the loci of ``I13`` in the frame and in the coupler,
differentiated numerically over the crank angle, have exactly these
curvatures (``tests/kinematics/test_curvature.py``); the book's values fail
the same check.  (Its figure caption also gives ``R_BO4 = 5.657`` in where the
solution uses ``R_BB' = √2 = 1.414`` in, Eq. 2, which the posture requires.)

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 4.12-4.17 (Eqs. 4.40-4.57, Figs. 4.25-4.40, Examples 4.12-4.16).

Examples
--------
Example 4.16: the four-bar with link 2 perpendicular to the frame and the
coupler parallel to it.

>>> import graphkin
>>> sol = graphkin.loads('''
... units = { length = "in" }
... [links.1]
... O2 = [0, 0]
... O4 = [1, 0]
... [links.2]
... O2 = [0, 0]
... A = [1, 0]
... [links.3]
... A = [0, 0]
... B = [2, 0]
... C = [1, 0]
... [links.4]
... O4 = [0, 0]
... B = [1.4142135623730951, 0]
... [drive]
... link = 2
... angle = 90
... omega = 1
... [assembly]
... B = [2, 1]
... ''').solve()
>>> k = link_curvature(sol, "3")

Here ``AB ∥ A'B'``, so the construction through ``W`` has no answer and the
inflection points are laid off by Eq. 4.43, as the book does:

>>> k.method
'euler-savary'
>>> np.round(k.velocity_pole, 6) + 0.0, np.round(k.inflection_pole, 6) + 0.0
(array([ 0., -1.]), array([-2., -3.]))
>>> round(k.inflection_diameter, 6), round(k.cubic.M, 6), k.cubic.N
(2.828427, -2.828427, inf)
>>> np.round(k.ball_point, 6)
array([-2., -3.])
>>> round(k.moving_centrode[0], 6), round(k.fixed_centrode[0], 6)
(0.707107, 0.565685)
"""

from __future__ import annotations

import math
import weakref
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import partial
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction import Construction, Role
from graphkin.construction.ops import OPS, op
from graphkin.errors import ConstructionError, GraphkinError
from graphkin.geometry import ops as g
from graphkin.kinematics.solution import Solution, perp
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = [
    "Cubic",
    "LinkCurvature",
    "PathCurvature",
    "euler_savary",
    "inflection_points_on_ray",
    "radius_of_curvature",
    "inflection_pole",
    "pole_velocity",
    "acceleration_center",
    "bresse_pole",
    "stationary_curvature_cubic",
    "ball_point",
    "centrode_radii",
    "path_curvature",
    "known_conjugates",
    "link_curvature",
    "curvature",
    "curvature_constructions",
    "path_curvatures",
    "curvature_json",
    "paths_json",
    "curvature_text",
]

Array = np.ndarray

# Conditioning of the drawings (which construction to draw), not tolerances of
# geometric decisions (those come from a Tolerance):
_FAR = 0.05
"""A point nearer than this fraction of the figure to a center makes poor rays from it."""
_USABLE = 1e-6
"""Relative size below which a known point is taken as at I, or two rays from I as one."""
_RAY_FROM_N = 0.1
"""Fig. 4.30 is drawn for rays at least ~6° (cos ψ > 0.1) away from the centrode normal ..."""
_FROM_CIRCLE = 0.05
"""... and for points not within 5 % of the inflection circle or of J; Hartmann otherwise."""
_RAYS = 0.02
"""Bobillier's construction is chosen when its two rays cross at more than ~1° at I."""
_AGREE = 1e-6
"""The construction through W is kept when it agrees with the closed form to this (relative)."""
_TEXT_ZERO = 1e-12
"""Coordinates below this fraction of the figure print as 0 in the text report."""


# ---------------------------------------------------------------------------
# the one construction operation that is curvature's own
# ---------------------------------------------------------------------------

def _register() -> None:
    if "euler_savary_inflection" not in OPS:
        @op("euler_savary_inflection")
        def _es_inflection(i: Array, a: Array, a_conj: Array, *,
                           tol: Tolerance) -> tuple[Array]:
            """Lay off ``R_AJ_A = R_AI²/R_AA'`` from A along the ray (Eq. 4.43): J_A."""
            return (inflection_points_on_ray(i, a, a_conj),)


_register()


# ---------------------------------------------------------------------------
# closed forms (any leading shape)
# ---------------------------------------------------------------------------

def _xy(p: ArrayLike) -> Array:
    p = np.asarray(p, dtype=float)
    return g.xy(p) if p.shape[-1] == 3 else p


def _dot(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]


def _cross(u: Array, v: Array) -> Array:
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def euler_savary(pole: ArrayLike, inflection_pole: ArrayLike, point: ArrayLike,
                 tol: Tolerance | None = None, scale: float = 0.0) -> Array:
    """The conjugate point (center of curvature of the path) of a point, by Euler-Savary.

    With positions measured from the velocity pole ``I`` along the ray
    through the point ``A``, Eq. 4.42 reads ``1/x_A - 1/x_A' = 1/x_J`` where
    ``x_J = R_JI sin ψ`` (Eq. 4.41) is where the ray meets the inflection
    circle again.  Writing ``r² = |A - I|²`` and ``q = (J - I)·(A - I)``, this is
    ``A' = I + q (A - I)/(q - r²)`` and ``ρ = R_AA' = r³/|r² - q|`` (Eq. 4.43).

    Parameters
    ----------
    pole, inflection_pole, point : array_like, shape (..., 2) or (..., 3)
        ``I``, ``J`` and ``A`` (finite points).
    tol : Tolerance, optional
    scale : float
        Size of the figure.  The path is taken as straight when
        ``ρ ≥ s/tol.angle`` with ``s = max(scale, R_AI, R_JI)``, and ``A`` as at
        rest when ``R_AI ≤ tol.length(s)``.

    Returns
    -------
    ndarray, shape (..., 3)
        ``A'`` in homogeneous coordinates: finite; at infinity along the ray
        when ``A`` is on the inflection circle (its path is straight here);
        NaN when ``A`` is at ``I`` (it is at rest).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.12, Eqs. 4.41-4.43.

    Examples
    --------
    A wheel of radius 1 rolling on the x axis: ``I`` is the contact point and
    ``J`` the wheel's center.  The top of the wheel has its center of
    curvature 4 radii below it (the cycloid's apex); the center moves straight.

    >>> euler_savary([0, 0], [0, 1], [0, 2])
    array([ 0., -2.,  1.])
    >>> euler_savary([0, 0], [0, 1], [0, 1])
    array([0., 1., 0.])
    """
    tol = tol or DEFAULT_TOL
    i, j, a = _xy(pole), _xy(inflection_pole), _xy(point)
    w = a - i
    r2 = _dot(w, w)
    r = np.sqrt(r2)
    q = _dot(j - i, w)
    s = np.maximum(np.maximum(r, np.hypot(*np.moveaxis(j - i, -1, 0))), scale)
    rest = r <= tol.length(s)
    den = q - r2
    straight = ~rest & (np.abs(den) * s <= tol.angle * r2 * r)
    with np.errstate(invalid="ignore", divide="ignore"):
        f = q / np.where(straight | rest, 1.0, den)
        fin = i + f[..., None] * w
        ray = w / np.where(rest, 1.0, r)[..., None]
    out = np.concatenate([fin, np.ones_like(r)[..., None]], axis=-1)
    ideal = g.ideal_point(ray[..., 0], ray[..., 1])
    out = np.where(straight[..., None], ideal, out)
    return np.where(rest[..., None], np.nan, out) + 0.0


def inflection_points_on_ray(pole: ArrayLike, point: ArrayLike, conjugate: ArrayLike) -> Array:
    """The inflection point ``J_A`` on the ray ``IA`` from a pair of conjugate points ``A, A'``.

    Eq. 4.43 laid off from ``A``: ``R_AJ_A = R_AI²/R_AA'``.  When ``A'`` is at
    infinity (``A`` moves on a straight line), ``J_A = A``.

    Parameters
    ----------
    pole : array_like, shape (..., 2) or (..., 3)
        The velocity pole ``I``.
    point : array_like
        ``A``.
    conjugate : array_like, shape (..., 3)
        ``A'``, finite or at infinity (homogeneous).

    Returns
    -------
    ndarray, shape (..., 3)

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Eq. 4.43 and Examples 4.12, 4.14, 4.16.

    Examples
    --------
    Example 4.16: ``R_AI = 2`` in, ``A' = O_2`` 1 in from ``A``; ``J_A`` is 4 in from ``A``.

    >>> inflection_points_on_ray([0, -1], [0, 1], [0, 0, 1])
    array([ 0., -3.,  1.])
    """
    i, a = _xy(pole), _xy(point)
    c = np.asarray(conjugate, dtype=float)
    w = a - i
    xa = np.hypot(w[..., 0], w[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        u = w / xa[..., None]
        xc = _dot(_xy(c) - i, u)
        xj = xa * xc / (xc - xa)
    fin = i + xj[..., None] * u
    out = np.where(g.is_ideal(c)[..., None], a, fin)
    return g.point(out[..., 0], out[..., 1])


def radius_of_curvature(point: ArrayLike, conjugate: ArrayLike) -> Array:
    """``ρ = R_AA'``, the distance from a point to its conjugate (Eq. 4.43); ``inf`` if ideal.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.12, Eq. 4.43.

    Examples
    --------
    >>> radius_of_curvature([0, 2], euler_savary([0, 0], [0, 1], [0, 2]))
    array(4.)
    >>> radius_of_curvature([0, 1], euler_savary([0, 0], [0, 1], [0, 1]))
    array(inf)
    """
    c = np.asarray(conjugate, dtype=float)
    with np.errstate(invalid="ignore"):
        d = g.distance(g.point(*np.moveaxis(_xy(point), -1, 0)), c)
    return np.where(g.is_ideal(c), np.inf, d)


def inflection_pole(pole: ArrayLike, pole_acceleration: ArrayLike, omega: ArrayLike) -> Array:
    """``J = I + A_I/ω²``: the point of the link at ``I`` accelerates toward ``J`` (Eqs. 4.46-4.47).

    Examples
    --------
    >>> inflection_pole([1.0, 0.0], [0.0, 8.0], 2.0)
    array([1., 2.])

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eqs. 4.46-4.47.
    """
    w = np.asarray(omega, dtype=float)
    return _xy(pole) + np.asarray(pole_acceleration, dtype=float) / (w**2)[..., None]


def pole_velocity(pole: ArrayLike, inflection_pole: ArrayLike, omega: ArrayLike) -> Array:
    """The pole velocity ``v = ω k × R_JI``: ``|v| = ω R_JI`` (Eq. 4.47), along the tangent T.

    Examples
    --------
    A wheel of radius 1 rolling to the right turns clockwise (``ω = -2``); its
    contact point moves with the wheel's center, at 2 to the right.

    >>> pole_velocity([0, 0], [0, 1], -2.0)
    array([2., 0.])

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eq. 4.47.
    """
    w = np.asarray(omega, dtype=float)
    return w[..., None] * perp(_xy(inflection_pole) - _xy(pole)) + 0.0


def acceleration_center(point: ArrayLike, acceleration: ArrayLike, omega: ArrayLike,
                        alpha: ArrayLike) -> Array:
    """The instantaneous center of acceleration Γ from one point's acceleration.

    ``A_A = ω² R_ΓA R̂_ΓA - α R_ΓA (k × R̂_ΓA)`` (Sec. 4.14, Eq. b) solved for
    ``Γ``: ``Γ = A + (ω² A_A + α k × A_A)/(ω⁴ + α²)``; ``|R_ΓA| = A_A/√(ω⁴ + α²)``
    (Eq. 4.45) and the angle of Eq. 4.44, ``γ = tan⁻¹(α/ω²)``.

    Examples
    --------
    A wheel turning about the origin at ω = 1: the point (2, 0) accelerates
    toward the origin, which is Γ.

    >>> acceleration_center([2.0, 0.0], [-2.0, 0.0], 1.0, 0.0)
    array([0., 0.])

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.14, Eqs. 4.44-4.45.
    """
    a = np.asarray(acceleration, dtype=float)
    w, al = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    den = (w**4 + al**2)[..., None]
    return _xy(point) + ((w**2)[..., None] * a + al[..., None] * perp(a)) / den


def bresse_pole(pole: ArrayLike, inflection_pole: ArrayLike, omega: ArrayLike,
                alpha: ArrayLike) -> Array:
    """The far end ``E`` of the Bresse circle's diameter through ``I``.

    The Bresse circle (the points with no tangential acceleration) has the
    diameter ``b = R_JI ω²/α`` (Eq. 4.48) along the centrode tangent:
    ``E = I + (ω²/α) k × R_JI``, on the negative side of ``T`` when ``α > 0``.
    NaN (no circle: it becomes the centrode normal) when ``α = 0``.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eq. 4.48, Fig. 4.34.

    Examples
    --------
    >>> bresse_pole([0, 0], [0, 2], 1.0, 0.5)
    array([-4.,  0.])
    """
    w, al = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        k = np.where(al == 0.0, np.nan, w**2 / np.where(al == 0.0, 1.0, al))
        out = _xy(pole) + k[..., None] * perp(_xy(inflection_pole) - _xy(pole))
    return np.where(np.isfinite(out), out, np.nan)


def _tn(pole: Array, tangent: Array, p: Array) -> tuple[Array, Array]:
    r = _xy(p) - _xy(pole)
    return _dot(r, tangent), _cross(tangent, r)


def stationary_curvature_cubic(pole: ArrayLike, tangent: ArrayLike, p1: ArrayLike,
                               p2: ArrayLike, scale: float = 1.0,
                               tol: Tolerance | None = None) -> tuple[float, float]:
    """``M`` and ``N`` of the cubic of stationary curvature through two of its points.

    Eq. 4.57, ``(x² + y²)(x/M - y/N) = xy`` with ``x`` along the centrode
    tangent and ``y`` along the normal, is linear in ``1/M`` and ``1/N``.

    Parameters
    ----------
    pole : array_like, shape (2,)
        The velocity pole ``I``.
    tangent : array_like, shape (2,)
        The unit positive centrode tangent ``T`` (``N`` is 90° ccw from it).
    p1, p2 : array_like, shape (2,)
        Two points of the cubic (points of constant path curvature: pins to
        links that turn about frame pivots, points held on frame-fixed lines).
    scale : float
        Size of the figure: ``1/M`` below ``tol.angle/scale`` is taken as 0.
    tol : Tolerance, optional

    Returns
    -------
    (M, N) : tuple of float
        ``inf`` where the parameter is infinite (a degenerate cubic).

    Raises
    ------
    ConstructionError
        The two points do not determine the cubic.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.17, Eqs. 4.55 and 4.57.

    Examples
    --------
    Example 4.16: ``I = (0, -1)``, ``T`` at 135°, pins ``A = (0, 1)``, ``B = (2, 1)``.

    >>> t = np.array([-1.0, 1.0]) / np.sqrt(2.0)
    >>> m, n = stationary_curvature_cubic([0, -1], t, [0, 1], [2, 1])
    >>> round(m, 6), n
    (-2.828427, inf)
    """
    tol = tol or DEFAULT_TOL
    rows, rhs = [], []
    for p in (p1, p2):
        x, y = (float(v) for v in _tn(np.asarray(pole, float), np.asarray(tangent, float),
                                       np.asarray(p, float)))
        s = x * x + y * y
        rows.append([s * x, -s * y])
        rhs.append(x * y)
    a = np.array(rows)
    det = float(np.linalg.det(a))
    norm = float(np.abs(a).max()) ** 2
    if norm == 0.0 or abs(det) <= tol.angle * norm:
        raise ConstructionError("the two points do not determine the cubic of stationary "
                                "curvature", step="cubic")
    m, n = np.linalg.solve(a, np.array(rhs))
    small = tol.angle / max(scale, 1e-300)
    big_m = math.inf if abs(m) <= small else 1.0 / float(m)
    big_n = math.inf if abs(n) <= small else 1.0 / float(n)
    return big_m, big_n


def ball_point(pole: ArrayLike, inflection_pole: ArrayLike, tangent: ArrayLike, M: float,
               N: float, tol: Tolerance | None = None) -> Array | None:
    """Ball's point: where the cubic of stationary curvature meets the inflection circle again.

    With the inflection circle ``x² + y² = d y`` (``d = R_JI``), Eq. 4.57 gives
    ``x (d/M - 1) = (d/N) y``: a line through ``I`` that meets the circle at
    Ball's point.  ``None`` when that line is indeterminate (the cubic
    contains the whole inflection circle) or tangent to the circle at ``I``.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.17 (Ball's point), Example 4.16.

    Examples
    --------
    Example 4.16: ``N = ∞``, so Ball's point is the inflection pole ``J``.

    >>> t = np.array([-1.0, 1.0]) / np.sqrt(2.0)
    >>> ball_point([0, -1], [-2, -3], t, -2 * np.sqrt(2.0), np.inf)
    array([-2., -3.])
    """
    tol = tol or DEFAULT_TOL
    i, j = np.asarray(pole, dtype=float), np.asarray(inflection_pole, dtype=float)
    t = np.asarray(tangent, dtype=float)
    nrm = perp(t)
    d = float(np.hypot(*(j - i)))
    dm = 0.0 if math.isinf(M) else d / M
    dn = 0.0 if math.isinf(N) else d / N
    ux, uy = dn, dm - 1.0  # the line's direction in (T, N) coordinates
    h = math.hypot(ux, uy)
    if h <= tol.angle:
        return None
    ux, uy = ux / h, uy / h
    r = d * uy
    if abs(r) <= tol.length(max(d, 1.0)):
        return None
    return i + r * (ux * t + uy * nrm)


def centrode_radii(inflection_diameter: float, M: float) -> tuple[float, float]:
    """Signed radii ``R_IO_M``, ``R_IO_F`` of the moving and fixed centrodes (Eqs. 4.56, 4.40).

    ``1/R_IO_M = 1/R_JI - 3/M`` (Eq. 4.56) and ``1/R_IO_F = 1/R_JI + 1/R_IO_M``
    (Eq. 4.40 for the point ``J``, whose conjugate is at infinity).  Both are
    ``I - O`` measured along the positive centrode normal: positive when the
    center lies on the side of ``I`` away from ``J``.  ``inf`` for a straight
    centrode.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12 and 4.17, Eqs. 4.40, 4.56.

    Examples
    --------
    Example 4.16 with the sign of ``R_JI`` put right (see the module notes):

    >>> [round(r, 6) for r in centrode_radii(2 * np.sqrt(2.0), -2 * np.sqrt(2.0))]
    [0.707107, 0.565685]
    """
    d = float(inflection_diameter)
    km = 1.0 / d - (0.0 if math.isinf(M) else 3.0 / M)
    rm = math.inf if km == 0.0 else 1.0 / km
    kf = 1.0 / d + km
    rf = math.inf if kf == 0.0 else 1.0 / kf
    return float(rm), float(rf)


def path_curvature(position: ArrayLike, velocity: ArrayLike, acceleration: ArrayLike,
                   tol: Tolerance | None = None) -> tuple[Array, Array]:
    """Radius and center of curvature of a path from a point's velocity and acceleration.

    ``ρ = V²/A^n`` (Eq. 4.49), the center on the side the normal acceleration
    points to.  Radius ``inf`` and center NaN where the path is straight here
    (``V × A = 0``); both NaN where the point is at rest.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.16, Eq. 4.49.

    Examples
    --------
    >>> path_curvature([2.0, 0.0], [0.0, 2.0], [-2.0, 0.0])
    (array(2.), array([0., 0.]))
    """
    tol = tol or DEFAULT_TOL
    p = np.asarray(position, dtype=float)
    v, a = np.asarray(velocity, dtype=float), np.asarray(acceleration, dtype=float)
    v2 = _dot(v, v)
    c = _cross(v, a)
    va = np.sqrt(v2) * np.hypot(a[..., 0], a[..., 1])
    straight = np.abs(c) <= tol.angle * va
    rest = v2 == 0.0
    with np.errstate(invalid="ignore", divide="ignore"):
        k = np.where(straight, np.nan, v2 / np.where(straight, 1.0, c))
        center = p + k[..., None] * perp(v)
        rho = np.where(straight, np.inf, np.abs(k) * np.sqrt(v2))
    rho = np.where(rest, np.nan, rho)
    center = np.where((rest | straight)[..., None], np.nan, center)
    return rho, center


# ---------------------------------------------------------------------------
# the conjugates known by inspection
# ---------------------------------------------------------------------------

def _frame_pins(mech: Mechanism, lid: str) -> list[str]:
    frame = mech.links[FRAME].points
    return [n for n in mech.links[lid].points if n in frame]


def _ideal_normal(p0: tuple[float, float], p1: tuple[float, float]) -> Array:
    dx, dy = p1[0] - p0[0], p1[1] - p0[1]
    return g.ideal_point(-dy, dx)


def known_conjugates(mech: Mechanism, link: str) -> dict[str, tuple[Array, str]]:
    """The points of a link whose paths have a constant curvature known by inspection.

    A pin ``A`` of the link shared with a link that turns about a frame pivot
    ``O`` has its center of curvature at ``O``; a point held on a frame-fixed
    straight line (a pin to a slider on the frame, a pin in a straight slot of
    the frame) has it at infinity, normal to the line; a pin in a circular
    slot of the frame has it at the slot's center.  These are the pairs of
    conjugate points "found by inspection" of Sec. 4.13 (Examples 4.12-4.14).

    Parameters
    ----------
    mech : Mechanism
    link : str

    Returns
    -------
    dict
        Point name -> (homogeneous conjugate point, shape (3,), the reason in words).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.13.

    Examples
    --------
    A slider-crank: the rod's pin A turns about O2, its pin B slides on the x axis.

    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... [links.1]
    ... O2 = [0, 0]
    ... [links.2]
    ... O2 = [0, 0]
    ... A = [2, 0]
    ... [links.3]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [links.4]
    ... B = [0, 0]
    ... [[sliders]]
    ... link = 4
    ... on = 1
    ... point = "B"
    ... line = [[0, 0], [1, 0]]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''')
    >>> {n: h.tolist() for n, (h, why) in known_conjugates(mech, "3").items()}
    {'A': [0.0, 0.0, 1.0], 'B': [0.0, 1.0, 0.0]}
    """
    out: dict[str, tuple[Array, str]] = {}
    frame = mech.links[FRAME].points
    for name in mech.links[link].points:
        if name in frame:
            continue
        for m in mech.point_links[name]:
            if m in (link, FRAME):
                continue
            pins = _frame_pins(mech, m)
            if len(pins) == 1:
                o = pins[0]
                out[name] = (g.point(*frame[o]),
                             f"{name} is a pin of link {m}, which turns about the frame pivot "
                             f"{o}: the path of {name} is a circle about {o}, so {name}' = {o}")
                break
            for s in mech.sliders:
                if s.link == m and s.on == FRAME:
                    out[name] = (_ideal_normal(s.p0, s.p1),
                                 f"{name} is a pin of the slider {m}, which moves on a "
                                 f"frame-fixed line: the path of {name} is straight, so its "
                                 f"conjugate {name}' is at infinity, normal to the line")
                    break
            if name in out:
                break
        if name in out:
            continue
        for sl in mech.slots:
            if sl.point == name and sl.on == FRAME:
                if sl.is_line:
                    assert sl.p0 is not None and sl.p1 is not None
                    out[name] = (_ideal_normal(sl.p0, sl.p1),
                                 f"{name} moves in a straight slot of the frame: its conjugate "
                                 f"{name}' is at infinity, normal to the slot")
                else:
                    assert sl.center is not None
                    out[name] = (g.point(*sl.center),
                                 f"{name} moves in a circular slot of the frame: {name}' is "
                                 "the slot's center")
                break
    return out


# ---------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------

@dataclass
class Cubic:
    """The cubic of stationary curvature of a motion (Eq. 4.55).

    Attributes
    ----------
    pole : ndarray, shape (2,)
        The velocity pole ``I``.
    tangent, normal : ndarray, shape (2,)
        Unit positive centrode tangent ``T`` and normal ``N`` (90° ccw from ``T``).
    M, N : float
        The parameters of ``1/r = 1/(M sin ψ) - 1/(N cos ψ)``; ``inf`` where infinite.
    g_n, g_t : ndarray or None
        Where Hain's auxiliary line ``G`` meets ``N`` and ``T`` (``None`` at infinity).
    """

    pole: Array
    tangent: Array
    normal: Array
    M: float
    N: float
    g_n: Array | None = None
    g_t: Array | None = None

    def radius(self, psi: ArrayLike) -> Array:
        """``r(ψ)`` of Eq. 4.55 (``inf`` where the ray meets the cubic only at ``I``)."""
        psi = np.asarray(psi, dtype=float)
        im = 0.0 if math.isinf(self.M) else 1.0 / self.M
        in_ = 0.0 if math.isinf(self.N) else 1.0 / self.N
        with np.errstate(divide="ignore", invalid="ignore"):
            inv = im / np.sin(psi) - in_ / np.cos(psi)
            return 1.0 / inv

    def point(self, psi: ArrayLike) -> Array:
        """The point of the cubic on the ray at ``ψ`` from ``T``."""
        psi = np.asarray(psi, dtype=float)
        r = self.radius(psi)
        u = (np.cos(psi)[..., None] * self.tangent + np.sin(psi)[..., None] * self.normal)
        return self.pole + r[..., None] * u

    def residual(self, p: ArrayLike) -> Array:
        """``(x² + y²)(x/M - y/N) - xy`` (Eq. 4.57): zero on the cubic."""
        x, y = _tn(self.pole, self.tangent, np.asarray(p, dtype=float))
        im = 0.0 if math.isinf(self.M) else 1.0 / self.M
        in_ = 0.0 if math.isinf(self.N) else 1.0 / self.N
        return (x * x + y * y) * (x * im - y * in_) - x * y


@dataclass
class LinkCurvature:
    """The curvature theory of one link's motion relative to the frame.

    Attributes
    ----------
    link : str
    omega, alpha : float
    velocity_pole : ndarray, shape (2,)
        ``I`` (the instant center ``I1k``).
    inflection_pole : ndarray, shape (2,)
        ``J``.
    inflection_diameter : float
        ``R_JI``, the inflection circle's diameter.
    normal, tangent : ndarray or None
        Unit positive centrode normal (from ``I`` toward ``J``) and tangent
        (90° clockwise from ``N``); ``None`` when ``J = I``.
    pole_velocity : ndarray
        ``v = ω k × R_JI`` (Eq. 4.47).
    pole_acceleration : ndarray
        ``A_I = ω² R_JI``, the acceleration of the point of the link at ``I``
        (Eq. 4.46), directed from ``I`` toward ``J``.
    acceleration_center : ndarray
        ``Γ``.
    gamma : float
        ``γ = tan⁻¹(α/ω²)`` (Eq. 4.44): ``R_ΓI`` is ``N`` turned by ``γ``.
    bresse_pole : ndarray or None
        The far end of the Bresse circle's diameter from ``I`` (``None`` when ``α = 0``).
    bresse_diameter : float or None
        ``|b| = R_JI ω²/|α|`` (Eq. 4.48); ``None`` when ``α = 0`` (to round-off:
        ``|α| ≤ tol.angle`` times the largest ``ω² + |α|`` of the mechanism).
    conjugates : dict
        Point name -> its conjugate (center of curvature), homogeneous ``(3,)``:
        at infinity for a straight path, NaN for a point at rest.
    conjugate_methods : dict
        Point name -> how its conjugate was found: ``"inspection"`` (given),
        ``"bobillier"`` (Fig. 4.30), ``"hartmann"`` (Fig. 4.25),
        ``"euler-savary"`` (closed form, Eq. 4.42) or ``"pivot"``.
    known : dict
        Point name -> why its conjugate is known by inspection.
    cubic : Cubic or None
    ball_point : ndarray or None
    moving_centrode, fixed_centrode : tuple or None
        ``(R_IO, O)``: signed radius (``I - O`` along ``N``; ``inf`` if straight)
        and center (``None`` if straight).
    method : str
        How ``J`` was found: ``"bobillier"``, ``"euler-savary"`` (Eq. 4.43
        lay-off), ``"accelerations"``, ``"pivot"`` (the link turns about a
        frame pivot) or ``"closed form"``.
    construction : Construction or None
        The recorded steps (``diagram="curvature"``).
    values : dict
        Label -> value after evaluating ``construction``.
    notes : list of str
    """

    link: str
    omega: float
    alpha: float
    velocity_pole: Array
    inflection_pole: Array
    inflection_diameter: float
    normal: Array | None
    tangent: Array | None
    pole_velocity: Array
    pole_acceleration: Array
    acceleration_center: Array
    gamma: float
    bresse_pole: Array | None
    bresse_diameter: float | None
    conjugates: dict[str, Array]
    conjugate_methods: dict[str, str]
    known: dict[str, str]
    cubic: Cubic | None
    ball_point: Array | None
    moving_centrode: tuple[float, Array | None] | None
    fixed_centrode: tuple[float, Array | None] | None
    method: str
    construction: Construction | None
    values: dict[str, Array] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)


@dataclass
class PathCurvature:
    """Radius and center of curvature of a named point's absolute path.

    Attributes
    ----------
    name : str
    link : str or None
        The link whose curvature theory gave it (``None``: from its velocity
        and acceleration, Eq. 4.49, because no link carrying it turns).
    radius : float or None
        ``None`` where the path is straight here or the point is at rest.
    center : ndarray or None
    how : str
        How the center was found: ``"inspection"``, ``"bobillier"``,
        ``"hartmann"``, ``"euler-savary"``, ``"pivot"``, ``"velocity-acceleration"``
        (Eq. 4.49); or ``"straight"``, ``"at rest"``.
    """

    name: str
    link: str | None
    radius: float | None
    center: Array | None
    how: str


# ---------------------------------------------------------------------------
# the construction of one link
# ---------------------------------------------------------------------------

_Section = Callable[[], None]


class _Build:
    """Record and evaluate the curvature construction of one link, section by section."""

    def __init__(self, sol: Solution, lid: str, tol: Tolerance) -> None:
        self.sol, self.mech, self.lid, self.tol = sol, sol.mechanism, lid, tol
        st = sol.links[lid]
        self.st = st
        self.w = float(st.omega)  # type: ignore[arg-type]
        self.a = float(st.alpha)  # type: ignore[arg-type]
        self.sgn = 1.0 if self.w > 0 else -1.0
        # α is zero when it is round-off of the mechanism's accelerations (ω² + |α| per length)
        ref = max(float(s.omega or 0.0) ** 2 + abs(float(s.alpha or 0.0))
                  for s in sol.links.values())
        self.a_zero = abs(self.a) <= tol.angle * ref
        self.L = _figure_size(sol)
        self.local = dict(self.mech.links[lid].points)
        self.names = list(self.local)
        self.reserved = set(self.mech.point_names)
        self.cx = Construction(title=f"{self.mech.title or self.mech.source}: curvature of the "
                                     f"motion {lid}/1")
        self.env: dict[str, Array] = {}
        self.made: dict[str, str] = {}  # cache key -> label
        self.notes: list[str] = []
        c, s = math.cos(float(st.angle)), math.sin(float(st.angle))
        self._rot = np.array([[c, -s], [s, c]])
        self.origin = np.asarray(st.origin, dtype=float)

    # -- world data of body points --
    def to_local(self, p: Array) -> Array:
        return self._rot.T @ (np.asarray(p, dtype=float) - self.origin)

    def pos(self, loc: ArrayLike) -> Array:
        return np.asarray(self.st.position(loc), dtype=float)

    def vel(self, loc: ArrayLike) -> Array:
        return np.asarray(self.st.velocity(loc), dtype=float)

    def acc(self, loc: ArrayLike) -> Array:
        return np.asarray(self.st.acceleration(loc), dtype=float)

    # -- labels and steps --
    def lab(self, x: str) -> str:
        """A construction label that does not clash with a named point of the file."""
        while x in self.reserved:
            x += "*"
        return x

    def add(self, op_name: str, inputs: tuple[str, ...], out: str, note: str,
            role: Role = Role.AUXILIARY, **params: Any) -> str:
        if self.has(out):
            raise ConstructionError(f"the label {out!r} is taken", step=out)
        self.cx.add(op_name, inputs, (out,), role=role, note=note, diagram="curvature", **params)
        return out

    def has(self, label: str) -> bool:
        return label in self.env or any(label in s.outputs for s in self.cx.steps)

    def given(self, label: str, xy: Array, note: str) -> str:
        if not self.has(label):
            self.add("point", (), label, note, Role.GIVEN,
                     xy=(float(xy[0]) + 0.0, float(xy[1]) + 0.0))
        return label

    def given_h(self, label: str, h: Array, note: str) -> str:
        if not self.has(label):
            if h[2] == 0.0:
                self.add("ideal_point", (), label, note, Role.GIVEN,
                         direction=(float(h[0]), float(h[1])))
            else:
                self.add("point", (), label, note, Role.GIVEN,
                         xy=(float(h[0] / h[2]), float(h[1] / h[2])))
        return label

    def line(self, p: str, q: str, note: str) -> str:
        key = f"join:{p}:{q}"
        if key not in self.made:
            self.made[key] = self.add("join", (p, q), self.lab(f"{p}{q}"), note)
        return self.made[key]

    def section(self, fn: _Section) -> bool:
        """Record a group of steps and evaluate it; undo it if it has no answer."""
        n0, made = len(self.cx.steps), dict(self.made)
        try:
            fn()
            ev = self.cx.evaluate(values=self.env, start=n0, tol=self.tol)
        except GraphkinError:
            del self.cx.steps[n0:]
            self.made = made
            return False
        self.env = dict(ev.values)
        return True

    def val(self, label: str) -> Array:
        return np.asarray(self.env[label], dtype=float)

    def pt(self, label: str) -> Array:
        return g.xy(self.val(label))


def _figure_size(sol: Solution) -> float:
    """The size of the drawing: the largest distance between two named points."""
    pts = np.array([sol.position(n) for n in sol.mechanism.point_names], dtype=float)
    if len(pts) < 2:
        return float(sol.mechanism.scale)
    ext = pts.max(axis=0) - pts.min(axis=0)
    size = float(np.hypot(*ext))
    return size if size > 0.0 else float(sol.mechanism.scale)


def _unit(v: Array) -> Array:
    return v / float(np.hypot(*v))


def _sin_angle(u: Array, v: Array) -> float:
    nu, nv = float(np.hypot(*u)), float(np.hypot(*v))
    if nu == 0.0 or nv == 0.0:
        return 0.0
    return abs(float(_cross(u, v))) / (nu * nv)


class _Curvature(_Build):
    """The sections of Secs. 4.12-4.17 for one link."""

    def __init__(self, sol: Solution, lid: str, tol: Tolerance) -> None:
        super().__init__(sol, lid, tol)
        o_v = np.asarray(self.st.origin_velocity, dtype=float)
        o_a = np.asarray(self.st.origin_acceleration, dtype=float)
        # closed-form references (Eq. 3.4 and Secs. 4.14-4.15)
        self.I0 = self.origin + perp(o_v) / self.w
        self.AI0 = self.acc(self.to_local(self.I0))
        self.J0 = inflection_pole(self.I0, self.AI0, self.w)
        self.G0 = acceleration_center(self.origin, o_a, self.w, self.a)
        self.known = known_conjugates(self.mech, lid)
        self.method = "closed form"
        self.I_label = self.J_label = None  # type: str | None

    # -- candidate points for the acceleration route and the four-circle method --
    def candidates(self, center: Array, prefix: str) -> list[tuple[str, Array, bool]]:
        """The named points of the link, and auxiliary body points around ``center``."""
        out = [(n, np.asarray(loc, dtype=float), True) for n, loc in self.local.items()]
        for k, t in enumerate((0.0, 0.5 * math.pi, 0.25 * math.pi, 0.75 * math.pi), start=1):
            p = center + self.L * np.array([math.cos(t), math.sin(t)])
            out.append((self.lab(f"{prefix}{k}"), self.to_local(p), False))
        return out

    def pick_pair(self, center: Array, prefix: str) -> tuple[tuple[str, Array, bool],
                                                            tuple[str, Array, bool]]:
        """Two body points seen from ``center`` at a good angle: lines through them cross well.

        Named points are preferred when they make at least 30° at ``center``;
        auxiliary ones are labelled ``prefix`` + a number.
        """
        cands = self.candidates(center, prefix)
        best, best_s = None, -1.0
        for i in range(len(cands)):
            for j in range(i + 1, len(cands)):
                p, q = self.pos(cands[i][1]), self.pos(cands[j][1])
                far = min(float(np.hypot(*(p - center))), float(np.hypot(*(q - center))))
                s = _sin_angle(p - center, q - center) if far > _FAR * self.L else 0.0
                if cands[i][2] and cands[j][2] and s >= 0.5:
                    s += 0.5
                if s > best_s:
                    best, best_s = (cands[i], cands[j]), s
        assert best is not None
        return best

    def point_given(self, name: str, loc: Array, named: bool) -> str:
        if named:
            return self.given(name, self.pos(loc), f"{name}: a point of link {self.lid}.")
        return self.given(name, self.pos(loc),
                          f"{name}: an auxiliary point of link {self.lid} (any point will do).")

    def vtip(self, name: str, loc: Array) -> str:
        tip = self.pos(loc) + self.vel(loc) / abs(self.w)
        return self.given(self.lab(f"V_{name}"), tip,
                          f"V_{name}, drawn from {name} to the scale 1/|ω{self.lid}| "
                          f"(from the velocity polygon).")

    def atip(self, name: str, loc: Array) -> str:
        tip = self.pos(loc) + self.acc(loc) / self.w**2
        return self.given(self.lab(f"A_{name}"), tip,
                          f"A_{name}, drawn from {name} to the scale 1/ω{self.lid}² "
                          f"(from the acceleration polygon).")

    # -- velocity pole and inflection pole --
    def pivot(self, o: str) -> None:
        xy = self.mech.links[FRAME].points[o]
        self.I_label = self.given(self.lab("I"), np.asarray(xy, dtype=float),
                                  f"Link {self.lid} turns about the frame pivot {o}: {o} is its "
                                  f"velocity pole I (the instant center I1{self.lid}); the "
                                  f"path of every point is a circle about {o}, so the "
                                  f"inflection circle shrinks to the point {o}.")
        self.method = "pivot"

    def bobillier(self, a: str, b: str, layoff: bool) -> None:
        """Fig. 4.29 (Example 4.13), or Eq. 4.43 laid off (Examples 4.14, 4.16)."""
        lab = self.lab
        ha, hb = self.known[a][0], self.known[b][0]
        for n, h in ((a, ha), (b, hb)):
            self.given(n, self.pos(self.local[n]), f"{n}: a point of link {self.lid}.")
            self.given_h(lab(f"{n}'"), h, self.known[n][1] + ".")
        ap, bp = lab(f"{a}'"), lab(f"{b}'")
        raa = self.line(a, ap, f"Draw the ray {a}{a}': the normal to the path of {a}, "
                               f"perpendicular to V_{a}.")
        rbb = self.line(b, bp, f"Draw the ray {b}{b}': the normal to the path of {b}, "
                               f"perpendicular to V_{b}.")
        i = self.add("meet", (raa, rbb), lab("I"),
                     f"Locate the velocity pole I (the instant center I1{self.lid}) at the "
                     f"intersection of {a}{a}' and {b}{b}'.", Role.RESULT)
        self.I_label = i
        ja, jb = lab(f"J_{a}"), lab(f"J_{b}")
        if not layoff:
            rab = self.line(a, b, f"Draw the line {a}{b}.")
            rpp = self.line(ap, bp, f"Draw the line {a}'{b}'.")
            q = self.add("meet", (rab, rpp), lab("Q"),
                         f"Locate Q at the intersection of {a}{b} and {a}'{b}'.")
            ax = self.add("join", (i, q), lab("IQ"),
                          "Line IQ is the collineation axis (Bobillier's theorem: the angle "
                          "from the collineation axis to the first ray equals the angle from "
                          "the second ray to the centrode tangent).")
            par = self.add("parallel", (rpp, i), lab(f"I∥{a}'{b}'"),
                           f"Through I draw a line parallel to {a}'{b}'.")
            w = self.add("meet", (par, rab), lab("W"), f"It meets {a}{b} at W.")
            wq = self.add("parallel", (ax, w), lab("W∥IQ"),
                          "Through W draw a line parallel to the collineation axis IQ.")
            self.add("meet", (wq, raa), ja,
                     f"It locates J_{a} on {a}{a}', a point of the inflection circle.")
            self.add("meet", (wq, rbb), jb,
                     f"It locates J_{b} on {b}{b}', another point of the inflection circle.")
            self.method = "bobillier"
        else:
            self.add("euler_savary_inflection", (i, a, ap), ja,
                     f"Lay off R_{a}J_{a} = R_{a}I²/R_{a}{a}' from {a} along the ray "
                     f"(Eq. 4.43): the inflection point J_{a}.")
            self.add("euler_savary_inflection", (i, b, bp), jb,
                     f"Lay off R_{b}J_{b} = R_{b}I²/R_{b}{b}' from {b} (Eq. 4.43): the "
                     f"inflection point J_{b}.")
            self.method = "euler-savary"
        pa = self.add("perpendicular", (raa, ja), lab(f"⊥{a}{a}'@J_{a}"),
                      f"Through J_{a} draw a perpendicular to {a}{a}'.")
        pb = self.add("perpendicular", (rbb, jb), lab(f"⊥{b}{b}'@J_{b}"),
                      f"Through J_{b} draw a perpendicular to {b}{b}'.")
        self.J_label = self.add("meet", (pa, pb), lab("J"),
                                "The perpendiculars intersect at the inflection pole J "
                                "(a triangle inscribed in a semicircle is a right triangle).",
                                Role.RESULT)

    def collineation_axis(self, a: str, b: str) -> None:
        """Record the collineation axis of the two rays (for Bobillier's theorem and Hain)."""
        lab = self.lab
        ap, bp = lab(f"{a}'"), lab(f"{b}'")
        rab = self.line(a, b, f"Draw the line {a}{b}.")
        rpp = self.line(ap, bp, f"Draw the line {a}'{b}'.")
        q = self.add("meet", (rab, rpp), lab("Q"),
                     f"Locate Q at the intersection of {a}{b} and {a}'{b}' (for pins of two "
                     "links turning about frame pivots, their instant center: I24 of "
                     "Example 4.14).")
        self.add("join", (self.I_label or "I", q), lab("IQ"),
                 "Line IQ is the collineation axis: the angle from it to the first ray equals "
                 "the angle from the second ray to the centrode tangent (Bobillier).")

    def accelerations(self) -> None:
        """I from two velocities; J from the acceleration image of the point at I (Sec. 4.15)."""
        lab = self.lab
        (pn, pl, pnamed), (qn, ql, qnamed) = self.pick_pair(self.I0, "K")
        p, q = self.point_given(pn, pl, pnamed), self.point_given(qn, ql, qnamed)
        vp, vq = self.vtip(pn, pl), self.vtip(qn, ql)
        lp = self.line(p, vp, f"The line of V_{pn}.")
        lq = self.line(q, vq, f"The line of V_{qn}.")
        np_ = self.add("perpendicular", (lp, p), lab(f"⊥V_{pn}"),
                       f"Through {pn} draw a perpendicular to V_{pn}.")
        nq = self.add("perpendicular", (lq, q), lab(f"⊥V_{qn}"),
                      f"Through {qn} draw a perpendicular to V_{qn}.")
        self.I_label = self.add("meet", (np_, nq), lab("I"),
                                f"They meet at the velocity pole I (the instant center "
                                f"I1{self.lid}).", Role.RESULT)
        ap, aq = self.atip(pn, pl), self.atip(qn, ql)
        self.J_label = self.add(
            "image", (p, q, ap, aq, self.I_label), lab("J"),
            f"The acceleration of the point of link {self.lid} at I, from its acceleration "
            f"image (the triangle is similar to {pn}{qn}I), drawn from I to the scale "
            f"1/ω{self.lid}²: since A_I = ω² R_JI is directed from I toward J (Eqs. 4.46-4.47), "
            "its tip is the inflection pole J.", Role.RESULT)
        self.method = "accelerations"

    def circle(self) -> None:
        lab = self.lab
        i, j = self.I_label or "I", self.J_label or "J"
        self.add("circle_on_diameter", (i, j), lab("inflection circle"),
                 "Draw the inflection circle on the diameter IJ (Eq. 4.41): every point of "
                 "the link on it is at an inflection point of its path.", Role.RESULT)
        self.add("join", (i, j), lab("N"),
                 "The centrode normal N through I and J, positive from I toward J.")
        self.add("perpendicular_cw", (lab("N"), i), lab("T"),
                 "The centrode tangent T through I, its positive sense 90° clockwise from N "
                 "(so N is 90° counterclockwise from T, Sec. 4.12; Example 4.16).")
        self.add("similar", (i, j), lab("v"),
                 f"The pole velocity v = ω{self.lid} R_JI (Eq. 4.47), along the centrode "
                 f"tangent, drawn from I to the scale 1/|ω{self.lid}|.",
                 local_a=(0.0, 0.0), local_b=(1.0, 0.0), local_p=(0.0, self.sgn))

    def bresse(self) -> None:
        lab = self.lab
        i, j = self.I_label or "I", self.J_label or "J"
        if self.a_zero:
            self.add("copy_point", (j,), lab("Γ"),
                     f"α{self.lid} = 0: the Bresse circle becomes the centrode normal, and the "
                     "instantaneous center of acceleration Γ coincides with J (Sec. 4.15).",
                     Role.RESULT)
            return
        k = self.w**2 / self.a
        e = self.add("similar", (i, j), lab("E"),
                     f"Lay off the Bresse diameter b = R_JI ω²/α = {k:.6g} R_JI (Eq. 4.48) from "
                     "I along the centrode tangent: on its negative side when α > 0, on its "
                     "positive side when α < 0.",
                     local_a=(0.0, 0.0), local_b=(1.0, 0.0), local_p=(0.0, k))
        self.add("circle_on_diameter", (i, e), lab("Bresse circle"),
                 "Draw the Bresse circle on the diameter IE: the points of the link with no "
                 "tangential acceleration.", Role.RESULT)
        self.add("other_intersection", (lab("inflection circle"), lab("Bresse circle"), i),
                 lab("Γ"),
                 "The inflection and Bresse circles meet at I and at Γ, the instantaneous "
                 "center of acceleration (Fig. 4.34).", Role.RESULT)

    def four_circles(self) -> None:
        lab = self.lab
        (pn, pl, pnamed), (qn, ql, qnamed) = self.pick_pair(self.G0, "H")
        p, q = self.point_given(pn, pl, pnamed), self.point_given(qn, ql, qnamed)
        ap, aq = self.atip(pn, pl), self.atip(qn, ql)
        lp = self.line(p, ap, f"Extend A_{pn}.")
        lq = self.line(q, aq, f"Extend A_{qn}.")
        x = self.add("meet", (lp, lq), lab("Q_Γ"),
                     f"A_{pn} and A_{qn} extended intersect at Q_Γ (Fig. 4.33).")
        c1 = self.add("circumcircle", (p, q, x), lab(f"circle {pn}{qn}Q_Γ"),
                      f"Construct a circle through {pn}, {qn} and Q_Γ.")
        c2 = self.add("circumcircle", (ap, aq, x), lab(f"circle A_{pn}A_{qn}Q_Γ"),
                      f"Draw another circle through the termini of A_{pn} and A_{qn} and Q_Γ.")
        self.add("other_intersection", (c1, c2, x), lab("Γ (four circles)"),
                 "The second intersection of the two circles locates Γ, the instantaneous "
                 "center of acceleration (the four-circle method, Fig. 4.33).", Role.RESULT)

    def hartmann(self, name: str) -> None:
        """Fig. 4.25: the conjugate of a point from the pole velocity."""
        lab = self.lab
        loc = np.asarray(self.local[name], dtype=float)
        c = self.given(name, self.pos(loc), f"{name}: a point of link {self.lid}.")
        vc = self.vtip(name, loc)
        i = self.I_label or "I"
        ray = self.line(i, c, f"Draw the line I{name}.")
        pi = self.add("perpendicular", (ray, i), lab(f"⊥I{name}@I"),
                      f"Through I draw the line perpendicular to I{name}: it carries u, the "
                      f"component of the pole velocity v parallel to V_{name}.")
        pv = self.add("perpendicular", (pi, lab("v")), lab(f"v∥I{name}"),
                      f"Through the terminus of v draw a line parallel to I{name}.")
        u = self.add("meet", (pv, pi), lab(f"u_{name}"),
                     "The terminus of u (u = v sin ψ, Eq. d).")
        tt = self.line(vc, u, f"Connect the termini of V_{name} and u.")
        self.add("meet", (tt, ray), lab(f"{name}'"),
                 f"The line through the termini meets the line {name}I at the conjugate point "
                 f"{name}', the center of curvature of the path of {name} (the Hartmann "
                 "construction, Fig. 4.25).", Role.RESULT)

    def bobillier_conjugate(self, name: str) -> None:
        """Fig. 4.30 (Example 4.13): the conjugate of a point from the inflection circle."""
        lab = self.lab
        loc = np.asarray(self.local[name], dtype=float)
        c = self.given(name, self.pos(loc), f"{name}: a point of link {self.lid}.")
        i, j = self.I_label or "I", self.J_label or "J"
        ray = self.line(i, c, f"Draw the ray I{name}.")
        jc = self.add("second_on_circle", (ray, lab("inflection circle"), i), lab(f"J_{name}"),
                      f"It meets the inflection circle at J_{name}.")
        jj = self.line(jc, j, f"Draw the line J_{name}J.")
        ax = self.add("parallel", (jj, i), lab(f"IQ_{name}"),
                      f"The collineation axis belonging to the rays I{name} and IJ: a line "
                      f"through I parallel to J_{name}J.")
        jcl = self.line(j, c, f"Draw the line J{name}.")
        qc = self.add("meet", (ax, jcl), lab(f"Q_{name}"),
                      f"Q_{name} is the intersection of this collineation axis and J{name}.")
        pn = self.add("parallel", (lab("N"), qc), lab(f"Q_{name}∥N"),
                      f"Through Q_{name} draw a line parallel to the centrode normal (it "
                      "passes through J' at infinity).")
        self.add("meet", (pn, ray), lab(f"{name}'"),
                 f"Its intersection with the ray I{name} is {name}', the center of curvature "
                 f"of the path of {name} (Bobillier, Fig. 4.30).", Role.RESULT)

    def hain(self, a: str, b: str) -> None:
        """Fig. 4.38: the auxiliary line G of Hain's construction."""
        lab = self.lab
        i = self.I_label or "I"
        corners = []
        for n in (a, b):
            self.given(n, self.pos(self.local[n]), f"{n}: a point of link {self.lid}.")
            ray = self.line(i, n, f"Draw the line I{n}.")
            pp = self.add("perpendicular", (ray, n), lab(f"⊥I{n}@{n}"),
                          f"Through {n} draw a line perpendicular to I{n}.")
            xn = self.add("meet", (pp, lab("N")), lab(f"{n}_N"),
                          f"It intersects the centrode normal at {n}_N.")
            xt = self.add("meet", (pp, lab("T")), lab(f"{n}_T"),
                          f"It intersects the centrode tangent at {n}_T.")
            corners.append(self.add("parallelogram", (i, xn, xt), lab(f"{n}_G"),
                                    f"Complete the rectangle I{n}_N{n}_G{n}_T."))
        gl = self.add("join", tuple(corners), lab("G"),
                      f"{a}_G and {b}_G define the auxiliary line G: for every point S of the "
                      "cubic of stationary curvature, S_G lies on G.")
        self.add("meet", (gl, lab("N")), lab("G_N"),
                 "G meets the centrode normal at G_N: IG_N = M, the diameter of the circle "
                 "(centered on N) that osculates the branch of the cubic tangent to T.",
                 Role.RESULT)
        self.add("meet", (gl, lab("T")), lab("G_T"),
                 "G meets the centrode tangent at G_T: IG_T = -N, the diameter of the circle "
                 "(centered on T) that osculates the branch of the cubic tangent to N.",
                 Role.RESULT)

    def ball(self) -> None:
        lab = self.lab
        i, j = self.I_label or "I", self.J_label or "J"
        tj = self.add("parallel", (lab("T"), j), lab("T@J"),
                      "Draw the tangent to the inflection circle at J (parallel to T): the "
                      "S_G of every point of the inflection circle lies on it.")
        ug = self.add("meet", (lab("G"), tj), lab("U_G"), "It meets G at U_G.")
        un = self.add("parallel", (lab("N"), ug), lab("U_G∥N"),
                      "Through U_G draw a ray parallel to N.")
        ut = self.add("meet", (un, lab("T")), lab("U_T"),
                      "It locates U_T on the centrode tangent (U_N is J).")
        tl = self.line(ut, j, "Connect U_T with U_N = J.")
        pl = self.add("perpendicular", (tl, i), lab("⊥U_TJ@I"),
                      "Through I draw a perpendicular to this line.")
        self.add("meet", (pl, tl), lab("U"),
                 "Its foot is Ball's point U: the point of the cubic of stationary curvature "
                 "on the inflection circle, whose path is nearly straight for a long way.",
                 Role.RESULT)

    def ball_at_j(self) -> None:
        self.add("copy_point", (self.J_label or "J",), self.lab("U"),
                 "N is infinite: the cubic contains the centrode normal, so it meets the "
                 "inflection circle at J, and Ball's point U is the inflection pole "
                 "(Example 4.16).", Role.RESULT)


def _is_batch(sol: Solution) -> bool:
    return np.ndim(sol.links[FRAME].angle) > 0


def _turning(sol: Solution, lid: str, tol: Tolerance) -> bool:
    """True when the link turns at this instant: ``|ω| L`` beyond round-off of the speeds."""
    st = sol.links[lid]
    if st.omega is None:
        return False
    w = abs(float(st.omega))
    if w == 0.0:
        return False
    mech = sol.mechanism
    speeds = [float(np.hypot(*sol.velocity(n))) for n in mech.point_names]
    ref = max(speeds + [abs(float(s.omega or 0.0)) * mech.scale for s in sol.links.values()])
    return w * mech.scale > tol.angle * max(ref, 1e-300)


def _finite_or_none(h: Array) -> Array | None:
    if not np.all(np.isfinite(h)) or h[2] == 0.0:
        return None
    return np.asarray(h[:2] / h[2], dtype=float)


def link_curvature(sol: Solution, link: str, *, tol: Tolerance | None = None,
                   method: str = "auto") -> LinkCurvature:
    """The curvature theory of the motion of ``link`` relative to the frame, at one posture.

    Parameters
    ----------
    sol : Solution
        One solved posture with rates.
    link : str
        A moving link whose angular velocity is not zero.
    tol : Tolerance, optional
    method : {"auto", "bobillier", "euler-savary", "accelerations"}
        How to find the inflection pole: ``"auto"`` uses Bobillier's
        construction (Fig. 4.29) when two pairs of conjugate points are known
        by inspection -- or, when it degenerates, the Eq. 4.43 lay-off of
        Examples 4.14 and 4.16 -- and the accelerations otherwise.

    Returns
    -------
    LinkCurvature

    Raises
    ------
    ConstructionError
        A batch solution, a solution without rates, a link that does not turn,
        or a ``method`` that does not apply.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    tol = tol or DEFAULT_TOL
    if _is_batch(sol):
        raise ConstructionError("the curvature constructions are drawn for one posture, "
                                "not a sweep", step="curvature")
    if not sol.has_rates or not sol.has_accelerations:
        raise ConstructionError("curvature needs the rates (the file gives none)",
                                step="curvature")
    if link == FRAME or link not in sol.links:
        raise ConstructionError(f"no moving link {link!r}; valid: "
                                f"{', '.join(sol.mechanism.moving)}", step="curvature")
    if not _turning(sol, link, tol):
        raise ConstructionError(f"link {link} does not turn at this instant (ω = 0): its "
                                "velocity pole is at infinity", step="curvature")
    if method not in ("auto", "bobillier", "euler-savary", "accelerations"):
        raise ConstructionError(f"unknown method {method!r}; valid: auto, bobillier, "
                                "euler-savary, accelerations", step="curvature")
    b = _Curvature(sol, link, tol)
    mech = sol.mechanism
    pins = _frame_pins(mech, link)
    if len(pins) > 1:
        raise ConstructionError(f"link {link} is pinned to the frame twice", step="curvature")
    pivot = pins[0] if pins else None

    # the two points of constant path curvature (by inspection), not on one ray from I
    pair: tuple[str, str] | None = None
    crossing = 0.0
    known = [n for n in b.known
             if float(np.hypot(*(b.pos(b.local[n]) - b.I0))) > _USABLE * b.L]
    for x in range(len(known)):
        for y in range(x + 1, len(known)):
            pa, pb = b.pos(b.local[known[x]]), b.pos(b.local[known[y]])
            sa = _sin_angle(pa - b.I0, pb - b.I0)
            if sa > _USABLE and sa > crossing:
                pair, crossing = (known[x], known[y]), sa
    # in "auto", rays that cross at less than ~1° locate I poorly: use the accelerations
    rays_ok = method != "auto" or crossing > _RAYS
    if method in ("bobillier", "euler-savary") and (pair is None or pivot is not None):
        raise ConstructionError(f"link {link} does not carry two points whose conjugates are "
                                "known by inspection", step="curvature")

    core = False
    if pivot is not None:
        core = b.section(lambda: b.pivot(pivot))
    else:
        if pair is not None and rays_ok and method in ("auto", "bobillier"):
            core = b.section(lambda: b.bobillier(pair[0], pair[1], layoff=False))
            if core:
                # the W construction is ill-conditioned when W runs far away: check it
                jj = b.pt(b.J_label or "J")
                ref = b.L + float(np.hypot(*(b.J0 - b.I0)))
                if float(np.hypot(*(jj - b.J0))) > _AGREE * ref:
                    b.notes.append("Bobillier's construction through W was ill-conditioned; "
                                   "J laid off by Eq. 4.43 instead.")
                    b.cx = Construction(title=b.cx.title)
                    b.env, b.made = {}, {}
                    core = False
        if not core and pair is not None and rays_ok and method in ("auto", "bobillier",
                                                                     "euler-savary"):
            core = b.section(lambda: b.bobillier(pair[0], pair[1], layoff=True))
            if core:
                b.section(lambda: b.collineation_axis(pair[0], pair[1]))
        if not core and method in ("auto", "accelerations"):
            core = b.section(b.accelerations)
    if not core:
        b.notes.append("the construction has no answer here; the values are closed-form")
        b.method = "closed form"

    # values (construction first, closed form otherwise)
    big_i = b.pt(b.I_label) if core and b.I_label else b.I0
    if pivot is not None:
        big_i = np.asarray(mech.links[FRAME].points[pivot], dtype=float)
        big_j = big_i.copy()
    else:
        big_j = b.pt(b.J_label) if core and b.J_label else b.J0
    d = float(np.hypot(*(big_j - big_i)))
    has_axes = pivot is None and d > tol.length(b.L)
    circle_ok = core and has_axes and b.section(b.circle)
    normal = _unit(big_j - big_i) if has_axes else None
    tangent = np.array([normal[1], -normal[0]]) if normal is not None else None
    v_pole = pole_velocity(big_i, big_j, b.w)
    a_pole = b.w**2 * (big_j - big_i)

    # Bresse circle and Γ
    gamma = math.atan2(b.a, b.w**2)
    if pivot is not None:
        big_g = big_i.copy()
    elif circle_ok and b.section(b.bresse):
        big_g = b.pt(b.lab("Γ"))
    else:
        big_g = b.G0
    if pivot is None and not b.a_zero:
        b.section(b.four_circles)
    if b.a_zero:
        e_pole, bd = None, None
    else:
        e_pole = b.pt(b.lab("E")) if b.has(b.lab("E")) else bresse_pole(big_i, big_j, b.w, b.a)
        bd = d * b.w**2 / abs(b.a)  # inf (not a warning) when α is tiny: null in the JSON
        if not np.all(np.isfinite(e_pole)):
            e_pole = None

    # conjugates of every named point
    conj: dict[str, Array] = {}
    conj_how: dict[str, str] = {}
    for n, loc in b.local.items():
        p = b.pos(loc)
        if pivot is not None:
            conj[n] = (g.point(*big_i) if float(np.hypot(*(p - big_i))) > tol.length(b.L)
                       else np.full(3, np.nan))
            conj_how[n] = "pivot"
            continue
        if n in b.known and b.has(b.lab(f"{n}'")) and pair is not None and n in pair:
            conj[n] = b.val(b.lab(f"{n}'"))
            conj_how[n] = "inspection"
            continue
        closed = euler_savary(big_i, big_j, p, tol, scale=b.L)
        conj_how[n] = "euler-savary"
        rp = float(np.hypot(*(p - big_i)))
        if not circle_ok or not np.all(np.isfinite(closed)) or closed[2] == 0.0:
            conj[n] = closed  # at rest or straight (decided relative to the figure's size)
            continue
        w_hat = (p - big_i) / rp
        cos_psi = abs(float(_dot(w_hat, tangent)))  # type: ignore[arg-type]
        q = float(_dot(big_j - big_i, p - big_i))
        well = (b.method in ("bobillier", "euler-savary") and cos_psi > _RAY_FROM_N
                and abs(q - rp * rp) > _FROM_CIRCLE * rp * rp
                and float(np.hypot(*(p - big_j))) > _FROM_CIRCLE * d)
        ok = well and b.section(partial(b.bobillier_conjugate, n))
        how = "bobillier"
        if not ok:
            ok = b.section(partial(b.hartmann, n))
            how = "hartmann"
        h = b.val(b.lab(f"{n}'")) if ok else closed
        if ok and h[2] != 0.0:
            conj[n], conj_how[n] = h, how
        else:
            conj[n] = closed

    # the cubic of stationary curvature (Hain), Ball's point, the centrodes
    cubic = None
    ball = None
    mc = fc = None
    if pair is not None and pivot is None and normal is not None and tangent is not None:
        m_val = n_val = None
        gn = gt = None
        if circle_ok and b.section(lambda: b.hain(pair[0], pair[1])):
            gn_h, gt_h = b.val(b.lab("G_N")), b.val(b.lab("G_T"))
            m_val = math.inf if gn_h[2] == 0.0 else float(_dot(g.xy(gn_h) - big_i, normal))
            n_val = math.inf if gt_h[2] == 0.0 else -float(_dot(g.xy(gt_h) - big_i, tangent))
            gn, gt = _finite_or_none(gn_h), _finite_or_none(gt_h)
        if m_val is None or n_val is None:
            try:
                m_val, n_val = stationary_curvature_cubic(
                    big_i, tangent, b.pos(b.local[pair[0]]), b.pos(b.local[pair[1]]),
                    scale=b.L, tol=tol)
            except GraphkinError:
                m_val = n_val = None
        if m_val is not None and n_val is not None:
            cubic = Cubic(big_i, tangent, normal, m_val, n_val, gn, gt)
            closed_u = ball_point(big_i, big_j, tangent, m_val, n_val, tol)
            if closed_u is None:
                ball = None  # the cubic contains the inflection circle, or touches it at I
            elif math.isinf(n_val):
                if circle_ok and b.section(b.ball_at_j):
                    ball = b.pt(b.lab("U"))
                else:
                    ball = closed_u
            elif closed_u is not None and circle_ok and b.has(b.lab("G")) \
                    and b.section(b.ball):
                ball = b.pt(b.lab("U"))
            else:
                ball = closed_u
            rm, rf = centrode_radii(d, m_val)
            mc = (rm, None if math.isinf(rm) else big_i - rm * normal)
            fc = (rf, None if math.isinf(rf) else big_i - rf * normal)

    return LinkCurvature(
        link=link, omega=b.w, alpha=b.a, velocity_pole=big_i, inflection_pole=big_j,
        inflection_diameter=d, normal=normal, tangent=tangent, pole_velocity=v_pole,
        pole_acceleration=a_pole, acceleration_center=big_g, gamma=gamma,
        bresse_pole=e_pole, bresse_diameter=bd, conjugates=conj, conjugate_methods=conj_how,
        known={n: why for n, (_, why) in b.known.items()}, cubic=cubic, ball_point=ball,
        moving_centrode=mc, fixed_centrode=fc, method=b.method,
        construction=b.cx if len(b.cx) else None, values=dict(b.env), notes=b.notes)


# ---------------------------------------------------------------------------
# every link, every path
# ---------------------------------------------------------------------------

_CACHE: dict[int, tuple[Any, Tolerance, dict[str, LinkCurvature]]] = {}


def curvature(sol: Solution, *, tol: Tolerance | None = None) -> dict[str, LinkCurvature]:
    """:func:`link_curvature` of every moving link that turns at this instant.

    Empty for a batch or a solution without rates.  The result is cached per
    solution object.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    tol = tol or DEFAULT_TOL
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return {}
    hit = _CACHE.get(id(sol))
    if hit is not None and hit[0]() is sol and hit[1] == tol:
        return hit[2]
    out = {lid: link_curvature(sol, lid, tol=tol) for lid in sol.mechanism.moving
           if _turning(sol, lid, tol)}
    key = id(sol)

    def forget(_ref: Any) -> None:
        _CACHE.pop(key, None)

    _CACHE[key] = (weakref.ref(sol, forget), tol, out)
    return out


def curvature_constructions(sol: Solution, *,
                            tol: Tolerance | None = None) -> dict[str, Construction]:
    """Link id -> its recorded curvature construction (``diagram="curvature"``)."""
    return {lid: k.construction for lid, k in curvature(sol, tol=tol).items()
            if k.construction is not None}


def path_curvatures(sol: Solution, *, tol: Tolerance | None = None) -> dict[str, PathCurvature]:
    """Radius and center of curvature of the absolute path of every named point of a moving link.

    A point shared by several moving links is one world point with one path:
    it is taken from the first of them that turns (its conjugate point by the
    constructions of Secs. 4.12-4.13); when none turns, from the point's
    velocity and acceleration (Eq. 4.49).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.13 and 4.16.
    """
    tol = tol or DEFAULT_TOL
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return {}
    curv = curvature(sol, tol=tol)
    mech = sol.mechanism
    out: dict[str, PathCurvature] = {}
    for name in mech.point_names:
        carriers = [lid for lid in mech.point_links[name] if lid != FRAME]
        if not carriers:
            continue
        p = np.asarray(sol.position(name), dtype=float)
        if FRAME in mech.point_links[name]:
            out[name] = PathCurvature(name, carriers[0], None, None, "at rest")
            continue
        turning = [lid for lid in carriers if lid in curv]
        if turning:
            k = curv[turning[0]]
            h = k.conjugates[name]
            how = k.conjugate_methods.get(name, "euler-savary")
            if not np.all(np.isfinite(h)):
                out[name] = PathCurvature(name, k.link, None, None, "at rest")
            elif h[2] == 0.0:
                out[name] = PathCurvature(name, k.link, None, None, "straight")
            else:
                c = h[:2] / h[2]
                out[name] = PathCurvature(name, k.link, float(np.hypot(*(p - c))), c, how)
            continue
        rho, c = path_curvature(p, sol.velocity(name), sol.acceleration(name), tol)
        rho_f = float(rho)
        if math.isnan(rho_f):
            out[name] = PathCurvature(name, None, None, None, "at rest")
        elif math.isinf(rho_f):
            out[name] = PathCurvature(name, None, None, None, "straight")
        else:
            out[name] = PathCurvature(name, None, rho_f, np.asarray(c, dtype=float),
                                      "velocity-acceleration")
    return out


# ---------------------------------------------------------------------------
# output (spec/output.md)
# ---------------------------------------------------------------------------

def _num(x: float | None) -> float | None:
    if x is None or not math.isfinite(x):
        return None
    return float(x) + 0.0


def _pair(p: Array | None) -> list[float] | None:
    if p is None or not np.all(np.isfinite(p)):
        return None
    return [float(p[0]) + 0.0, float(p[1]) + 0.0]


def curvature_json(sol: Solution) -> dict[str, Any] | None:
    """The ``curvature`` section of ``graphkin solve --json`` (``spec/output.md``).

    Keyed by link id, for every moving link that turns: ``velocity_pole``,
    ``inflection_pole``, ``inflection_diameter``, ``acceleration_center``,
    ``bresse_diameter`` (``null`` when ``α = 0``) and, for a link that carries
    two points of constant path curvature, ``cubic`` (``tangent``, ``M``,
    ``N``; ``null`` where infinite) and ``ball_point``.  Extra keys:
    ``normal``, ``pole_velocity``, ``pole_acceleration``, ``bresse_pole``,
    ``gamma`` (degrees), ``moving_centrode`` / ``fixed_centrode``
    (``radius``, signed ``R_IO`` along ``N``, and ``center``), ``method``.
    ``None`` for a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 0
    ... omega = 2
    ... alpha = 1
    ... ''').solve()
    >>> curvature_json(sol)["2"]["velocity_pole"], curvature_json(sol)["2"]["bresse_diameter"]
    ([0.0, 0.0], 0.0)
    """
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    out: dict[str, Any] = {}
    for lid, k in curvature(sol).items():
        e: dict[str, Any] = {
            "velocity_pole": _pair(k.velocity_pole),
            "inflection_pole": _pair(k.inflection_pole),
            "inflection_diameter": _num(k.inflection_diameter),
            "acceleration_center": _pair(k.acceleration_center),
            "bresse_diameter": _num(k.bresse_diameter),
        }
        if k.cubic is not None:
            e["cubic"] = {"tangent": _pair(k.cubic.tangent), "M": _num(k.cubic.M),
                          "N": _num(k.cubic.N)}
            e["ball_point"] = _pair(k.ball_point)
        e.update({
            "normal": _pair(k.normal),
            "tangent": _pair(k.tangent),
            "pole_velocity": _pair(k.pole_velocity),
            "pole_acceleration": _pair(k.pole_acceleration),
            "bresse_pole": _pair(k.bresse_pole),
            "gamma": _num(math.degrees(k.gamma)),
            "method": k.method,
        })
        for key, cen in (("moving_centrode", k.moving_centrode),
                         ("fixed_centrode", k.fixed_centrode)):
            if cen is not None:
                e[key] = {"radius": _num(abs(cen[0])), "R_IO": _num(cen[0]),
                          "center": _pair(cen[1])}
        out[lid] = e
    return out


def paths_json(sol: Solution) -> dict[str, Any] | None:
    """The ``paths`` section of ``graphkin solve --json`` (``spec/output.md``).

    For every named point of a moving link: ``radius_of_curvature`` (a
    magnitude) and ``center_of_curvature`` of its absolute path, both
    ``null`` where the path is straight here or the point is at rest; plus
    ``how`` it was found and the ``link`` whose motion gave it.  ``None`` for
    a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.13, 4.16.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 0
    ... omega = 2
    ... ''').solve()
    >>> paths_json(sol)["B"]["radius_of_curvature"], paths_json(sol)["A"]["how"]
    (5.0, 'at rest')
    """
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    out: dict[str, Any] = {}
    for name, pc in path_curvatures(sol).items():
        out[name] = {"radius_of_curvature": _num(pc.radius),
                     "center_of_curvature": _pair(pc.center), "how": pc.how, "link": pc.link}
    return out


def _fmt(p: Array | None, unit: str, scale: float = 1.0) -> str:
    if p is None or not np.all(np.isfinite(p)):
        return "—"
    x, y = (0.0 if abs(float(c)) < _TEXT_ZERO * scale else float(c) for c in p[:2])
    return f"({x:.6g}, {y:.6g}) {unit}"


def _deg(v: Array) -> float:
    return math.degrees(math.atan2(float(v[1]), float(v[0])))


def curvature_text(sol: Solution) -> str | None:
    """The curvature part of the text report: per link, then the paths of the named points.

    ``None`` for a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    u = sol.mechanism.length_unit
    sc = float(sol.mechanism.scale)
    lines: list[str] = []
    how = {"bobillier": "Bobillier's construction (Fig. 4.29)",
           "euler-savary": "the Euler-Savary lay-off R_AJ_A = R_AI²/R_AA' (Eq. 4.43)",
           "accelerations": "the acceleration of the point at I (A_I = ω² R_JI, Eq. 4.46)",
           "pivot": "inspection (the link turns about a frame pivot)",
           "closed form": "the closed forms"}
    for lid, k in curvature(sol).items():
        lines.append(f"  Motion {lid}/1: ω{lid} = {k.omega:.6g} rad/s, α{lid} = {k.alpha:.6g} "
                     f"rad/s²; J by {how[k.method]}")
        lines.append(f"    velocity pole I = {_fmt(k.velocity_pole, u, sc)}, inflection pole "
                     f"J = {_fmt(k.inflection_pole, u, sc)}, "
                     f"R_JI = {k.inflection_diameter:.6g} {u}")
        if k.tangent is not None:
            lines.append(f"    centrode tangent T ∠{_deg(k.tangent):.2f}°, normal N "
                         f"∠{_deg(k.normal):.2f}°; pole velocity "  # type: ignore[arg-type]
                         f"v = {float(np.hypot(*k.pole_velocity)):.6g} {u}/s, "
                         f"A_I = {float(np.hypot(*k.pole_acceleration)):.6g} {u}/s²")
        b = "∞ (α = 0)" if k.bresse_diameter is None else f"{k.bresse_diameter:.6g} {u}"
        lines.append(f"    Γ = {_fmt(k.acceleration_center, u, sc)}, Bresse diameter b = {b}, "
                     f"γ = {math.degrees(k.gamma):.2f}°")
        if k.cubic is not None:
            m = "∞" if math.isinf(k.cubic.M) else f"{k.cubic.M:.6g} {u}"
            n = "∞" if math.isinf(k.cubic.N) else f"{k.cubic.N:.6g} {u}"
            lines.append(f"    cubic of stationary curvature (Hain): M = {m}, N = {n}; "
                         f"Ball's point U = {_fmt(k.ball_point, u, sc)}")
        if k.moving_centrode is not None and k.fixed_centrode is not None:
            rm, rf = k.moving_centrode[0], k.fixed_centrode[0]
            lines.append(f"    centrodes: R_IO_M = {'∞' if math.isinf(rm) else f'{rm:.6g}'}, "
                         f"R_IO_F = {'∞' if math.isinf(rf) else f'{rf:.6g}'} {u}")
        for note in k.notes:
            lines.append(f"    note: {note}")
    paths = path_curvatures(sol)
    if paths:
        lines.append("  Paths (radius and center of curvature)")
        for name, pc in paths.items():
            if pc.radius is None:
                lines.append(f"    {name}: {pc.how}")
            else:
                lines.append(f"    {name}: ρ = {pc.radius:.6g} {u}, center "
                             f"{_fmt(pc.center, u, sc)}")
    return "\n".join(lines) if lines else None
