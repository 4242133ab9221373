"""The cubic of stationary curvature and Ball's point (Sec. 4.17, Eqs. 4.55-4.57)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction import Role
from graphkin.construction.ops import ball as _ball  # noqa: F401  (registers ball_point)
from graphkin.errors import ConstructionError
from graphkin.kinematics.curvature._vec import _cross, _dot, _xy
from graphkin.kinematics.curvature.construction import _CurvatureBase
from graphkin.kinematics.solution import perp
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["stationary_curvature_cubic", "ball_point", "Cubic"]

Array = np.ndarray


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


class _HainSteps(_CurvatureBase):
    """The steps of Hain's construction of the cubic and of Ball's point (Fig. 4.38)."""

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

    def ball_at_j(self, a: str, b: str) -> None:
        """Ball's point where N is infinite: the operation ``ball_point`` on I, J, A and B.

        Hain's construction meets G with the tangent at J, parallel to it when
        ``N`` is infinite.  ``ball_point`` (:mod:`graphkin.construction.ops.ball`)
        solves Eq. 4.57 through the two points for ``d/M`` and ``d/N`` as one
        homogeneous triple and meets the line it gives with the inflection
        circle, so ``N = ∞`` gives ``U = J`` by the formula itself (Example
        4.16), and the same step finds U at any other posture.
        """
        for n in (a, b):
            self.given(n, self.pos(self.local[n]), f"{n}: a point of link {self.lid}.")
        self.add("ball_point", (self.I_label or "I", self.J_label or "J", a, b), self.lab("U"),
                 "N is infinite: the cubic contains the centrode normal, so it meets the "
                 "inflection circle at J, and Ball's point U is the inflection pole "
                 "(Example 4.16).", Role.RESULT)
