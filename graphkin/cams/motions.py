"""The standard cam motions: one segment's displacement and its derivatives (Secs. 6.3-6.7).

Every motion is a *shape* ``f(u)`` on ``u = θ/β ∈ [0, 1]`` with ``f(0) = 0``
and ``f(1) = 1``; a segment of lift ``h`` (positive for a rise, negative for
a return) and cam angle ``β`` then has

    y = h f(u),   y' = h f'(u)/β,   y'' = h f''(u)/β²,   y''' = h f'''(u)/β³,

the kinematic coefficients of Eqs. (6.2)-(6.4).  A return is the rise turned
upside down (``h < 0``), which is how Eqs. (6.15), (6.16) and (6.20)-(6.25)
follow from Eqs. (6.12), (6.13) and (6.18)-(6.23); the one exception is the
eighth-order polynomial, whose return, Eq. (6.17), is its rise run backward
(the nonzero "acceleration" at the start), as in the book.

Every function here takes arrays and returns arrays of the same shape: no
loop over cam angles.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.3 (uniform, parabolic, harmonic,
cycloidal), 6.5 (Ex 6.1, Eqs. 6.5-6.6), 6.7 (Eqs. 6.12-6.25, Figs. 6.12-6.23).
The 3-4-5 polynomial and the modified trapezoid are the standard ones of the
cam literature (Chen [2] of the book's Sec. 6.17).
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["Motion", "Rest", "Shape", "shape", "HALF_FORMS", "table_shape"]

Array = np.ndarray
Shape = Callable[[Array], tuple[Array, Array, Array, Array]]
"""``f(u) -> (f, f', f'', f''')``, derivatives with respect to ``u = θ/β``."""


class Motion(enum.Enum):
    """The standard motions of a segment, by the name a cam file uses."""

    DWELL = "dwell"
    UNIFORM = "uniform"
    PARABOLIC = "parabolic"          # Ex 6.1, Eqs. (6.5)-(6.6), Fig. 6.12
    HARMONIC = "harmonic"            # full rise/return, Eqs. (6.12), (6.15)
    CYCLOIDAL = "cycloidal"          # full rise/return, Eqs. (6.13), (6.16)
    POLYNOMIAL8 = "polynomial8"      # eighth-order polynomial, Eqs. (6.14), (6.17)
    HALF_HARMONIC = "half-harmonic"  # Eqs. (6.18)-(6.21), Figs. 6.20-6.21
    HALF_CYCLOIDAL = "half-cycloidal"  # Eqs. (6.22)-(6.25), Figs. 6.22-6.23
    POLYNOMIAL345 = "3-4-5"          # 10u³ − 15u⁴ + 6u⁵
    MODIFIED_TRAPEZOID = "modified-trapezoid"
    TABLE = "table"                  # points given, a cubic spline through them


class Rest(enum.Enum):
    """Which end of a half motion has zero slope (the follower comes from or goes to rest).

    ``START`` is the book's form (a) (Figs. 6.20a, 6.21a, 6.22a, 6.23a), ``END``
    its form (b).
    """

    START = "start"
    END = "end"


HALF_FORMS = {
    (Motion.HALF_HARMONIC, True, Rest.START): "Eq. (6.18), Fig. 6.20a",
    (Motion.HALF_HARMONIC, True, Rest.END): "Eq. (6.19), Fig. 6.20b",
    (Motion.HALF_HARMONIC, False, Rest.START): "Eq. (6.20), Fig. 6.21a",
    (Motion.HALF_HARMONIC, False, Rest.END): "Eq. (6.21), Fig. 6.21b",
    (Motion.HALF_CYCLOIDAL, True, Rest.START): "Eq. (6.22), Fig. 6.22a",
    (Motion.HALF_CYCLOIDAL, True, Rest.END): "Eq. (6.23), Fig. 6.22b",
    (Motion.HALF_CYCLOIDAL, False, Rest.START): "Eq. (6.24), Fig. 6.23a",
    (Motion.HALF_CYCLOIDAL, False, Rest.END): "Eq. (6.25), Fig. 6.23b",
}
"""(motion, rise?, rest) -> the book's equation and figure."""

_PI = math.pi


def _dwell(u: Array) -> tuple[Array, Array, Array, Array]:
    z = np.zeros_like(u)
    return z, z, z, z


def _uniform(u: Array) -> tuple[Array, Array, Array, Array]:
    z = np.zeros_like(u)
    return u.copy(), np.ones_like(u), z, z


def _parabolic(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eqs. (6.5) for u ≤ 1/2 and (6.6) beyond: two parabolas meeting at mid-rise."""
    first = u <= 0.5
    f = np.where(first, 2 * u**2, 1 - 2 * (1 - u) ** 2)
    f1 = np.where(first, 4 * u, 4 * (1 - u))
    f2 = np.where(first, 4.0, -4.0)
    return f, f1, f2, np.zeros_like(u)


def _harmonic(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eq. (6.12): y = L/2 (1 − cos πθ/β)."""
    c, s = np.cos(_PI * u), np.sin(_PI * u)
    return 0.5 * (1 - c), 0.5 * _PI * s, 0.5 * _PI**2 * c, -0.5 * _PI**3 * s


def _cycloidal(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eq. (6.13): y = L (θ/β − sin(2πθ/β)/2π)."""
    c, s = np.cos(2 * _PI * u), np.sin(2 * _PI * u)
    return u - s / (2 * _PI), 1 - c, 2 * _PI * s, 4 * _PI**2 * c


_P8 = np.array([0.0, 0.0, 0.0, 6.09755, 0.0, -20.78040, 26.73155, -13.60965, 2.56095])
"""Eq. (6.14a): the coefficients of u⁰ … u⁸ of the eighth-order polynomial rise."""


def _poly(coef: Array) -> Shape:
    c0 = np.polynomial.Polynomial(coef)
    c1, c2, c3 = c0.deriv(1), c0.deriv(2), c0.deriv(3)

    def f(u: Array) -> tuple[Array, Array, Array, Array]:
        return c0(u), c1(u), c2(u), c3(u)

    return f


_polynomial8 = _poly(_P8)
_polynomial345 = _poly(np.array([0.0, 0, 0, 10, -15, 6]))


def _reversed(f: Shape) -> Shape:
    """The shape run backward and turned over, ``1 − f(1 − u)``: a rise starting where f ends."""

    def g(u: Array) -> tuple[Array, Array, Array, Array]:
        a, b, c, d = f(1 - u)
        return 1 - a, b, -c, d

    return g


def _half_harmonic_start(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eq. (6.18): y = L (1 − cos πθ/2β)."""
    k = _PI / 2
    c, s = np.cos(k * u), np.sin(k * u)
    return 1 - c, k * s, k**2 * c, -k**3 * s


def _half_harmonic_end(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eq. (6.19): y = L sin πθ/2β."""
    k = _PI / 2
    c, s = np.cos(k * u), np.sin(k * u)
    return s, k * c, -k**2 * s, -k**3 * c


def _half_cycloidal_start(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eq. (6.22): y = L (θ/β − sin(πθ/β)/π)."""
    c, s = np.cos(_PI * u), np.sin(_PI * u)
    return u - s / _PI, 1 - c, _PI * s, _PI**2 * c


def _half_cycloidal_end(u: Array) -> tuple[Array, Array, Array, Array]:
    """Eq. (6.23): y = L (θ/β + sin(πθ/β)/π)."""
    c, s = np.cos(_PI * u), np.sin(_PI * u)
    return u + s / _PI, 1 + c, -_PI * s, -_PI**2 * c


@dataclass(frozen=True)
class _Piece:
    """``a(x) = A sin ωt + B cos ωt + C`` with ``t = x − ref`` on ``[x0, x1]``."""

    x0: float
    x1: float
    A: float
    B: float
    C: float
    ref: float
    w: float

    def V(self, t: Array) -> Array:
        return -self.A * np.cos(self.w * t) / self.w + self.B * np.sin(self.w * t) / self.w \
            + self.C * t

    def S(self, t: Array) -> Array:
        w2 = self.w * self.w
        return -self.A * np.sin(self.w * t) / w2 - self.B * np.cos(self.w * t) / w2 \
            + 0.5 * self.C * t * t


def _integrate(pieces: list[_Piece]) -> tuple[list[tuple[float, float]], float]:
    """Each piece's starting velocity and displacement, and the scale making ``f(1) = 1``."""
    starts: list[tuple[float, float]] = []
    v0 = s0 = 0.0
    for p in pieces:
        starts.append((v0, s0))
        t0, t1 = p.x0 - p.ref, p.x1 - p.ref
        arr0, arr1 = np.asarray(t0), np.asarray(t1)
        v1 = v0 + float(p.V(arr1) - p.V(arr0))
        s1 = s0 + (v0 - float(p.V(arr0))) * (p.x1 - p.x0) + float(p.S(arr1) - p.S(arr0))
        v0, s0 = v1, s1
    return starts, 1.0 / s0


def piece_rows(motion: Motion) -> list[tuple[float, ...]]:
    """A piecewise motion's pieces as numbers: ``(x0, ref, ω, A, B, C, c0, c1)`` each.

    On ``[x0, next x0)``, with ``t = u − ref``:
    ``f = c0 + c1 u + S(t)``, ``f' = c1 + V(t)``, ``f'' = A sin ωt + B cos ωt + C``,
    ``V = (−A cos ωt + B sin ωt)/ω + C t``, ``S = −(A sin ωt + B cos ωt)/ω² + C t²/2``
    (already scaled so that ``f(1) = 1``): the form the live page's ``cam_program``
    operation evaluates (:mod:`graphkin.construction.ops.cam_program`).

    Raises
    ------
    KeyError
        A motion that is not piecewise.
    """
    pieces = _PIECEWISE[motion]
    starts, k = _integrate(pieces)
    out: list[tuple[float, ...]] = []
    for p, (va, sa) in zip(pieces, starts):
        t0 = np.asarray(p.x0 - p.ref)
        c1 = va - float(p.V(t0))
        c0 = sa - c1 * p.x0 - float(p.S(t0))
        out.append((p.x0, p.ref, p.w, k * p.A, k * p.B, k * p.C, k * c0, k * c1))
    return out


def _piecewise(pieces: list[_Piece]) -> Shape:
    """The shape whose "acceleration" is given piece by piece, integrated in closed form.

    The velocity and displacement start at zero and run on continuously from
    piece to piece; the result is scaled so that ``f(1) = 1``.
    """
    starts, scale = _integrate(pieces)
    edges = np.array([p.x1 for p in pieces[:-1]])

    def f(u: Array) -> tuple[Array, Array, Array, Array]:
        k = np.searchsorted(edges, u, side="right")
        out = [np.zeros_like(u) for _ in range(4)]
        for i, p in enumerate(pieces):
            m = k == i
            if not np.any(m):
                continue
            x = u[m]
            t, t0 = x - p.ref, p.x0 - p.ref
            va, sa = starts[i]
            wt = p.w * t
            out[0][m] = sa + (va - p.V(np.asarray(t0))) * (x - p.x0) + p.S(t) - p.S(np.asarray(t0))
            out[1][m] = va + p.V(t) - p.V(np.asarray(t0))
            out[2][m] = p.A * np.sin(wt) + p.B * np.cos(wt) + p.C
            out[3][m] = p.w * (p.A * np.cos(wt) - p.B * np.sin(wt))
        return out[0] * scale, out[1] * scale, out[2] * scale, out[3] * scale

    return f


_W = 4 * _PI
_MODIFIED_TRAPEZOID = [
    _Piece(0.0, 0.125, 1.0, 0.0, 0.0, 0.0, _W),         # sine ramp up
    _Piece(0.125, 0.375, 0.0, 0.0, 1.0, 0.0, _W),       # constant
    _Piece(0.375, 0.625, 0.0, 1.0, 0.0, 0.375, _W),     # cosine from +1 to −1
    _Piece(0.625, 0.875, 0.0, 0.0, -1.0, 0.0, _W),      # constant
    _Piece(0.875, 1.0, 1.0, 0.0, 0.0, 1.0, _W),         # sine ramp back to zero
]
_modified_trapezoid = _piecewise(_MODIFIED_TRAPEZOID)
"""The modified trapezoid: constant "acceleration" with sine ramps over eighths of the rise
(peak ``4.8881 L/β²``)."""

_PIECEWISE: dict[Motion, list[_Piece]] = {Motion.MODIFIED_TRAPEZOID: _MODIFIED_TRAPEZOID}

_SHAPES: dict[Motion, Shape] = {
    Motion.DWELL: _dwell,
    Motion.UNIFORM: _uniform,
    Motion.PARABOLIC: _parabolic,
    Motion.HARMONIC: _harmonic,
    Motion.CYCLOIDAL: _cycloidal,
    Motion.POLYNOMIAL8: _polynomial8,
    Motion.POLYNOMIAL345: _polynomial345,
    Motion.MODIFIED_TRAPEZOID: _modified_trapezoid,
}


def shape(motion: Motion, *, rise: bool = True, rest: Rest | None = None) -> Shape:
    """The unit shape of a standard motion.

    Parameters
    ----------
    motion : Motion
        Not ``TABLE`` (see :func:`table_shape`).
    rise : bool
        A rise (the lift positive) or a return; only the eighth-order
        polynomial's return differs in shape from its rise (Eq. 6.17).
    rest : Rest, optional
        For the half motions: the end at which the slope is zero.

    Returns
    -------
    callable
        ``f(u) -> (f, f', f'', f''')``.

    Examples
    --------
    >>> import numpy as np
    >>> f = shape(Motion.CYCLOIDAL)
    >>> [round(float(v), 9) for v in f(np.array(0.5))]   # Eq. (6.13) at mid-rise: L/2, 2L/β
    [0.5, 2.0, 0.0, -39.478417604]
    """
    if motion is Motion.POLYNOMIAL8 and not rise:
        return _reversed(_polynomial8)
    if motion is Motion.HALF_HARMONIC:
        return _half_harmonic_end if rest is Rest.END else _half_harmonic_start
    if motion is Motion.HALF_CYCLOIDAL:
        return _half_cycloidal_end if rest is Rest.END else _half_cycloidal_start
    return _SHAPES[motion]


def table_shape(theta: Array, y: Array) -> tuple[Shape, float, float]:
    """A natural cubic spline through points of a table, as a unit shape.

    Parameters
    ----------
    theta : array
        Cam angles from the segment's start (rad), increasing, first 0.
    y : array
        Displacements at those angles.

    Returns
    -------
    shape, y0, lift
        The shape ``f`` (on ``u = θ/β``), the first displacement and the lift
        ``y[-1] − y[0]`` (the shape is ``(y − y0)/lift``; for a table whose
        ends are equal the shape is ``y − y0`` and the lift 1).

    Notes
    -----
    The spline's second derivative is zero at both ends (natural), so its
    "acceleration" is continuous inside and zero at the ends; its "jerk" is
    constant between points.
    """
    x = np.asarray(theta, dtype=float) / float(theta[-1])
    yy = np.asarray(y, dtype=float)
    y0 = float(yy[0])
    lift = float(yy[-1] - yy[0])
    unit = lift if lift != 0 else 1.0
    v = (yy - y0) / unit
    n = len(x)
    hk = np.diff(x)
    # natural spline: solve for the second derivatives m at the knots
    a = np.zeros((n, n))
    r = np.zeros(n)
    a[0, 0] = a[-1, -1] = 1.0
    for i in range(1, n - 1):   # n small: the table's own points, not cam angles
        a[i, i - 1] = hk[i - 1]
        a[i, i] = 2 * (hk[i - 1] + hk[i])
        a[i, i + 1] = hk[i]
        r[i] = 6 * ((v[i + 1] - v[i]) / hk[i] - (v[i] - v[i - 1]) / hk[i - 1])
    m = np.linalg.solve(a, r)

    def f(u: Array) -> tuple[Array, Array, Array, Array]:
        k = np.clip(np.searchsorted(x, u, side="right") - 1, 0, n - 2)
        h = hk[k]
        t0, t1 = u - x[k], x[k + 1] - u
        m0, m1 = m[k], m[k + 1]
        f0 = (m0 * t1**3 + m1 * t0**3) / (6 * h) + (v[k] / h - m0 * h / 6) * t1 \
            + (v[k + 1] / h - m1 * h / 6) * t0
        f1 = (-m0 * t1**2 + m1 * t0**2) / (2 * h) - (v[k] / h - m0 * h / 6) \
            + (v[k + 1] / h - m1 * h / 6)
        f2 = (m0 * t1 + m1 * t0) / h
        f3 = (m1 - m0) / h
        return f0, f1, f2, f3

    return f, y0, (lift if lift != 0 else 1.0)
