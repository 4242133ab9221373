"""Complex-number synthesis (Sec. 9.12): the independent check of every construction.

Nothing here draws or records a step.  A posture of the moving body is a
complex number ``p`` (its reference point) and an angle ``θ``; the finite
displacement from posture 1 to posture j is ``z ↦ e^{iα_j} z + b_j`` with
``α_j = θ_j − θ_1`` (the rotation angle θ1j of Eq. 9.2) and
``b_j = p_j − e^{iα_j} p_1``.  A circle point ``a`` (in posture 1) and its
center point ``m`` satisfy the *dyad equations*

``|e^{iα_j} a + b_j − m|² = |a − m|²``,  j = 2, ..., N,

which, expanded, are linear in ``a`` for a given ``m`` (and in ``m`` for a
given ``a``):

``2 Re(a w_j) = |m|² − |b_j − m|²``,  ``w_j = e^{iα_j} conj(b_j − m) + conj(m)``.

Three postures: a circle point gives its center point, and the reverse, by a
2 × 2 linear solve.  Four postures: three equations in the two unknowns of
``a`` are consistent only where the 3 × 3 determinant vanishes, a cubic in
``m`` (the center-point curve, Sec. 9.5); the circle-point curve is the same
cubic of the inverse motion.  Five postures: the Burmester points are the
common points of the cubics of postures 1234 and 1235 other than the poles
P12, P13, P23, found here from the resultant of the two cubics.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.3-9.6, 9.11 (Eqs. 9.24-9.27) and
9.12 (Example 9.8, Eqs. 2-10).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Motion", "motion", "pole", "positions", "center_of", "circle_point_of",
           "cubic", "cubic_value", "circle_cubic", "burmester", "freudenstein",
           "freudenstein_lengths", "crank_coupler_dyad", "rocker_dyad", "chebyshev"]


@dataclass(frozen=True)
class Motion:
    """Finite displacements from posture 1: ``D_j(z) = rot[j] * z + shift[j]`` (complex).

    ``rot[0] = 1`` and ``shift[0] = 0`` (posture 1 itself).
    """

    rot: np.ndarray
    shift: np.ndarray

    def inverse(self) -> Motion:
        """The motion of the frame seen from the body in posture 1 (kinematic inversion)."""
        rot = np.conj(self.rot)
        return Motion(rot, -rot * self.shift)

    def apply(self, z: np.ndarray | complex) -> np.ndarray:
        """The N positions of the point(s) ``z`` of posture 1: shape ``(N, *shape(z))``."""
        z = np.asarray(z, dtype=complex)
        shape = (len(self.rot),) + (1,) * z.ndim
        return self.rot.reshape(shape) * z + self.shift.reshape(shape)


def motion(points: np.ndarray, angles: np.ndarray) -> Motion:
    """The displacements of a body whose reference point is ``points[j]`` at angle ``angles[j]``.

    Parameters
    ----------
    points : array of complex, shape (N,)
    angles : array of float, shape (N,), radians
    """
    p = np.asarray(points, dtype=complex)
    rot = np.exp(1j * (np.asarray(angles, dtype=float) - float(angles[0])))
    return Motion(rot, p - rot * p[0])


def pole(p_i: complex, theta_i: float, p_j: complex, theta_j: float) -> complex:
    """The pole P_ij: the point of the body with zero displacement (Sec. 9.3).

    ``P = (p_j − e^{iθ} p_i) / (1 − e^{iθ})`` with θ = θ_j − θ_i.  A pure
    translation has no finite pole: ``complex(inf, inf)`` is returned.
    """
    e = np.exp(1j * (theta_j - theta_i))
    den = 1.0 - e
    if abs(den) == 0.0:
        return complex(np.inf, np.inf)
    return complex((p_j - e * p_i) / den)


def positions(mo: Motion, a1: complex) -> np.ndarray:
    """A_1 ... A_N: the positions of the body's point that is ``a1`` in posture 1."""
    return mo.rot * a1 + mo.shift


def _rows(mo: Motion, m: np.ndarray, js: tuple[int, ...]) -> tuple[list[np.ndarray], ...]:
    """Coefficients of ``a = (ax, ay)`` and right sides of the dyad equations j in js."""
    cx, cy, rhs = [], [], []
    for j in js:
        w = mo.rot[j] * np.conj(mo.shift[j] - m) + np.conj(m)
        cx.append(2 * w.real)
        cy.append(-2 * w.imag)
        rhs.append(np.abs(m) ** 2 - np.abs(mo.shift[j] - m) ** 2)
    return cx, cy, rhs


def circle_point_of(mo: Motion, m: complex, js: tuple[int, int] = (1, 2)) -> complex:
    """The circle point (posture 1) of center point ``m``: two dyad equations solved (Cramer)."""
    cx, cy, rhs = _rows(mo, np.asarray(m, dtype=complex), js)
    det = cx[0] * cy[1] - cx[1] * cy[0]
    ax = (rhs[0] * cy[1] - rhs[1] * cy[0]) / det
    ay = (cx[0] * rhs[1] - cx[1] * rhs[0]) / det
    return complex(ax + 1j * ay)


def center_of(mo: Motion, a1: complex) -> complex:
    """The center point of circle point ``a1``: the circumcenter of A1, A2, A3 (Sec. 9.4)."""
    z = positions(mo, a1)[:3]
    # |m - z_k|^2 equal: 2 Re(m conj(z_k - z_0)) = |z_k|^2 - |z_0|^2, k = 1, 2
    d1, d2 = z[1] - z[0], z[2] - z[0]
    r1 = abs(z[1]) ** 2 - abs(z[0]) ** 2
    r2 = abs(z[2]) ** 2 - abs(z[0]) ** 2
    det = 2 * (d1.real * d2.imag - d1.imag * d2.real)
    x = (r1 * d2.imag - r2 * d1.imag) / det
    y = (d1.real * r2 - d2.real * r1) / det
    return complex(x + 1j * y)


# ---- the cubic of four postures ---------------------------------------------------

def _pmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Product of two bivariate polynomials given as coefficient arrays ``c[i, k]`` of x^i y^k."""
    out = np.zeros((a.shape[0] + b.shape[0] - 1, a.shape[1] + b.shape[1] - 1))
    for i in range(a.shape[0]):
        for k in range(a.shape[1]):
            if a[i, k] != 0.0:
                out[i:i + b.shape[0], k:k + b.shape[1]] += a[i, k] * b
    return out


def _padd(*ps: np.ndarray) -> np.ndarray:
    n = max(p.shape[0] for p in ps)
    m = max(p.shape[1] for p in ps)
    out = np.zeros((n, m))
    for p in ps:
        out[:p.shape[0], :p.shape[1]] += p
    return out


def cubic(mo: Motion, js: tuple[int, int, int] = (1, 2, 3)) -> np.ndarray:
    """The center-point curve as a polynomial: ``c[i, k]`` is the coefficient of x^i y^k.

    The curve is ``det [2 Re w_j, −2 Im w_j, |m|² − |b_j − m|²] = 0`` over the
    postures ``js`` (with posture 1): each entry is linear in ``m = x + iy``
    (the ``|m|²`` cancel), so the determinant is a cubic (Sec. 9.5).
    """
    def lin(c0: float, cx: float, cy: float) -> np.ndarray:
        return np.array([[c0, cy], [cx, 0.0]])

    rows = []
    for j in js:
        e, b = mo.rot[j], mo.shift[j]
        # w = e conj(b) - e conj(m) + conj(m) = e conj(b) + (1 - e) (x - i y)
        u = 1.0 - e
        w0 = e * np.conj(b)
        # w = w0 + u x - i u y
        wre = lin(w0.real, u.real, u.imag)
        wim = lin(w0.imag, u.imag, -u.real)
        # |m|^2 - |b - m|^2 = -|b|^2 + 2 (bx x + by y)
        rhs = lin(-abs(b) ** 2, 2 * b.real, 2 * b.imag)
        rows.append((2 * wre, -2 * wim, rhs))
    (a, b_, c), (d, e_, f), (g, h, k) = rows
    return _padd(_pmul(a, _padd(_pmul(e_, k), -_pmul(f, h))),
                 -_pmul(b_, _padd(_pmul(d, k), -_pmul(f, g))),
                 _pmul(c, _padd(_pmul(d, h), -_pmul(e_, g))))


def cubic_value(c: np.ndarray, z: np.ndarray | complex) -> np.ndarray:
    """The polynomial ``c`` at the point(s) ``z`` (complex)."""
    z = np.asarray(z, dtype=complex)
    return np.polynomial.polynomial.polyval2d(z.real, z.imag, c)


def circle_cubic(mo: Motion, js: tuple[int, int, int] = (1, 2, 3)) -> np.ndarray:
    """The circle-point curve (posture 1): the center-point curve of the inverse motion."""
    return cubic(mo.inverse(), js)


# ---- five postures ------------------------------------------------------------------

def _in_y(c: np.ndarray, x: float) -> np.ndarray:
    """Coefficients (ascending powers of y) of the cubic at a given x."""
    return np.array([np.polynomial.polynomial.polyval(x, c[:, k]) for k in range(c.shape[1])])


def _sylvester(p: np.ndarray, q: np.ndarray) -> float:
    """The resultant of two polynomials (ascending coefficients) by the Sylvester matrix."""
    p, q = p[::-1], q[::-1]
    m, n = len(p) - 1, len(q) - 1
    s = np.zeros((m + n, m + n))
    for i in range(n):
        s[i, i:i + m + 1] = p
    for i in range(m):
        s[n + i, i:i + n + 1] = q
    return float(np.linalg.det(s))


REACH = 10.0
"""Burmester points farther than REACH figure sizes from the postures are left out."""


def burmester(mo: Motion, scale: float, middle: complex = 0j) -> list[tuple[complex, complex]]:
    """The Burmester points of five postures: (center point, circle point) pairs, real ones.

    The center-point cubics of postures 1234 and 1235 meet in nine points:
    the poles P12, P13, P23, the two circular points at infinity, and the four
    Burmester center points (0, 2 or 4 of them real, Sec. 9.6).  The resultant
    in y of the two cubics (a polynomial in x of degree at most 9, found by
    interpolation at Chebyshev nodes over ``REACH`` figure sizes about
    ``middle``) gives their abscissae; each is polished by Newton's method on
    the two cubics and the poles are set aside.
    """
    c1, c2 = cubic(mo, (1, 2, 3)), cubic(mo, (1, 2, 4))
    poles = [pole(0j, 0.0, mo.shift[j], float(np.angle(mo.rot[j]))) for j in (1, 2)]
    poles.append(pole(mo.shift[1], float(np.angle(mo.rot[1])), mo.shift[2],
                      float(np.angle(mo.rot[2]))))
    finite = [p for p in poles if np.isfinite(p)]
    center = complex(middle)
    span = REACH * scale
    out: list[tuple[complex, complex]] = []
    # abscissae from the resultant in y, ordinates from the resultant in x (the cubics
    # transposed), each interpolated over 1, 3 and 10 figure sizes (near roots in a
    # cluster are blurred by the widest fit): every candidate is polished on both cubics
    # and checked
    passes = [(c1, c2, center.real, False, w) for w in (1.0, 3.0, 10.0)] + \
        [(c1.T, c2.T, center.imag, True, w) for w in (1.0, 3.0, 10.0)]
    for a1, a2, c0, swap, width in passes:
        for u in _resultant_roots(a1, a2, c0, span * width / 10.0):
            for v in np.roots(_trim(_in_y(a1, u))[::-1]):
                if abs(v.imag) > 1e-3 * span:
                    continue
                start = complex(v.real, u) if swap else complex(u, v.real)
                z = _polish(c1, c2, start)
                if z is None or abs(z - start) > 0.1 * scale:
                    continue
                if any(abs(z - p) < 1e-6 * scale for p in finite):
                    continue
                if abs(z - center) > span or any(abs(z - o[0]) < 1e-7 * scale for o in out):
                    continue
                out.append((z, circle_point_of(mo, z)))
    return out


def _resultant_roots(c1: np.ndarray, c2: np.ndarray, mid: float, span: float) -> list[float]:
    """The real roots (and the real parts of near-real ones) of the resultant in y."""
    nodes = mid + span * np.cos(np.pi * (np.arange(40) + 0.5) / 40)
    vals = np.array([_sylvester(_trim(_in_y(c1, x)), _trim(_in_y(c2, x))) for x in nodes])
    cheb = np.polynomial.Chebyshev.fit(nodes, vals, 9, domain=[mid - span, mid + span])
    roots = np.asarray(cheb.roots(), dtype=complex)
    keep = (np.abs(roots.imag) <= 1e-3 * span) & (np.abs(roots.real - mid) <= span)
    return [float(x) for x in roots.real[keep]]


def _trim(p: np.ndarray) -> np.ndarray:
    """Drop leading (highest-degree) coefficients that vanish to round-off."""
    big = np.max(np.abs(p)) if p.size else 0.0
    k = len(p)
    while k > 1 and abs(p[k - 1]) <= 1e-12 * big:
        k -= 1
    return p[:k]


def _polish(c1: np.ndarray, c2: np.ndarray, z: complex) -> complex | None:
    """Newton's method on the two cubics from z; None when it does not settle on both."""
    dx1 = np.polynomial.polynomial.polyder(c1, axis=0)
    dy1 = np.polynomial.polynomial.polyder(c1, axis=1)
    dx2 = np.polynomial.polynomial.polyder(c2, axis=0)
    dy2 = np.polynomial.polynomial.polyder(c2, axis=1)
    pv = np.polynomial.polynomial.polyval2d
    x, y = z.real, z.imag
    for _ in range(60):
        f = np.array([pv(x, y, c1), pv(x, y, c2)])
        jac = np.array([[pv(x, y, dx1), pv(x, y, dy1)], [pv(x, y, dx2), pv(x, y, dy2)]])
        try:
            step = np.linalg.solve(jac, f)
        except np.linalg.LinAlgError:
            return None
        x, y = x - step[0], y - step[1]
        if abs(step[0]) + abs(step[1]) <= 1e-15 * (1.0 + abs(x) + abs(y)):
            break
    g1 = np.hypot(pv(x, y, dx1), pv(x, y, dy1))
    g2 = np.hypot(pv(x, y, dx2), pv(x, y, dy2))
    if abs(pv(x, y, c1)) > 1e-8 * g1 * (1 + abs(x) + abs(y)) or \
            abs(pv(x, y, c2)) > 1e-8 * g2 * (1 + abs(x) + abs(y)):
        return None
    return complex(x, y)


# ---- function generation --------------------------------------------------------------

def chebyshev(x0: float, x1: float, n: int) -> np.ndarray:
    """Chebyshev spacing of n precision points in [x0, x1] (Eq. 9.22)."""
    j = np.arange(1, n + 1)
    return 0.5 * (x1 + x0) - 0.5 * (x1 - x0) * np.cos((2 * j - 1) * np.pi / (2 * n))


def freudenstein(phi: np.ndarray, psi: np.ndarray) -> np.ndarray:
    """K1, K2, K3 of Freudenstein's equation (9.24) through three postures (Eqs. i)."""
    phi, psi = np.asarray(phi, dtype=float), np.asarray(psi, dtype=float)
    a = np.stack([np.cos(phi), np.cos(psi), np.ones_like(phi)], axis=-1)
    return np.linalg.solve(a, np.cos(phi - psi))


def freudenstein_lengths(k: np.ndarray, r1: float) -> tuple[float, float, float, float]:
    """r1, r2, r3, r4 from K1, K2, K3 (Eqs. 9.25-9.27); r3² must come out positive."""
    r4 = float(r1 / k[0])
    r2 = float(r1 / k[1])
    r3sq = 2 * r2 * r4 * k[2] + r1 ** 2 + r2 ** 2 + r4 ** 2
    return float(r1), r2, float(np.sqrt(r3sq)) if r3sq > 0 else float("nan"), r4


# ---- the dyads of Example 9.8 -------------------------------------------------------------

def crank_coupler_dyad(phi: np.ndarray, alpha: np.ndarray,
                       s: np.ndarray) -> tuple[complex, complex, complex]:
    """r2, r3 and r1 of a crank and coupler through three precision postures (Sec. 9.12, Eq. 3).

    ``phi``: crank angles φ_j, ``alpha``: coupler rotations α_j from posture 1
    (α_1 = 0), ``s``: the coupler point's positions (complex).
    """
    e2 = np.exp(1j * (np.asarray(phi[1:]) - phi[0])) - 1.0
    e3 = np.exp(1j * np.asarray(alpha[1:])) - 1.0
    d = np.asarray(s[1:], dtype=complex) - s[0]
    det = e2[0] * e3[1] - e2[1] * e3[0]
    r2 = (d[0] * e3[1] - d[1] * e3[0]) / det
    r3 = (e2[0] * d[1] - e2[1] * d[0]) / det
    return complex(r2), complex(r3), complex(s[0] - r2 - r3)


def rocker_dyad(alpha: np.ndarray, c: np.ndarray) -> list[tuple[complex, complex, float, float]]:
    """The rocker dyads r4, r5 whose pin is at a point of the coupler (Sec. 9.12, Eqs. 5-10).

    ``r5 + r4 e^{iβ_j} + c_j = 0`` for j = 1, 2, 3 (``c_j``: the pin's position
    vector in posture j, negated into the book's form).  The determinant of
    Eq. 7 vanishes for two values of β3; the trivial root β2 = β3 = 0 (rows
    equal) is left out.  Returns ``(r4, r5, β2, β3)`` for each real root.
    """
    c = np.asarray(c, dtype=complex)
    # det [[1,1,c1],[1,e2,c2],[1,e3,c3]] = A e2 + B e3 + C
    a_ = c[2] - c[0]
    b_ = c[0] - c[1]
    c_ = c[1] - c[2]
    # e2 = -(B e3 + C) / A ; |e2| = 1  ->  |B e3 + C|^2 = |A|^2
    # |B|^2 + |C|^2 + 2 Re(B conj(C) e3) = |A|^2
    k = b_ * np.conj(c_)
    rhs = (abs(a_) ** 2 - abs(b_) ** 2 - abs(c_) ** 2) / 2
    # k.real cos b3 - k.imag sin b3 = rhs
    amp = abs(k)
    out: list[tuple[complex, complex, float, float]] = []
    if amp == 0.0 or abs(rhs) > amp:
        return out
    base = -np.angle(k)
    for sgn in (1.0, -1.0):
        b3 = float(base + sgn * np.arccos(np.clip(rhs / amp, -1.0, 1.0)))
        b3 = float(np.angle(np.exp(1j * b3)))
        e3 = np.exp(1j * b3)
        e2 = -(b_ * e3 + c_) / a_
        if abs(e3 - 1.0) < 1e-9:
            continue
        r4 = (c[0] - c[1]) / (e2 - 1.0)
        r5 = -r4 - c[0]
        out.append((complex(r4), complex(r5), float(np.angle(e2)), b3))
    return out
