"""The standard motions (Secs. 6.5-6.7) against the book's equations, typed in independently."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.cams import Motion, Program, Rest, Segment
from graphkin.cams.motions import shape, table_shape

PI = math.pi
U = np.linspace(0.0, 1.0, 101)


# The book's equations, one per line, y(θ/β) for lift L and angle β, and y' (per rad).
BOOK = {
    # Eq. (6.5)/(6.6), Ex 6.1
    ("parabolic", 1, None): (lambda u, L, b: np.where(u <= .5, 2 * L * u**2,
                                                      L * (1 - 2 * (1 - u)**2)),
                             lambda u, L, b: np.where(u <= .5, 4 * L / b * u, 4 * L / b * (1 - u))),
    ("harmonic", 1, None): (lambda u, L, b: L / 2 * (1 - np.cos(PI * u)),                # 6.12
                            lambda u, L, b: PI * L / (2 * b) * np.sin(PI * u)),
    ("cycloidal", 1, None): (lambda u, L, b: L * (u - np.sin(2 * PI * u) / (2 * PI)),  # 6.13
                             lambda u, L, b: L / b * (1 - np.cos(2 * PI * u))),
    ("polynomial8", 1, None): (lambda u, L, b: L * (6.09755 * u**3 - 20.78040 * u**5      # 6.14
                                                    + 26.73155 * u**6 - 13.60965 * u**7
                                                    + 2.56095 * u**8),
                               lambda u, L, b: L / b * (18.29265 * u**2 - 103.90200 * u**4
                                                        + 160.38930 * u**5 - 95.26755 * u**6
                                                        + 20.48760 * u**7)),
    ("harmonic", -1, None): (lambda u, L, b: L / 2 * (1 + np.cos(PI * u)),               # 6.15
                             lambda u, L, b: -PI * L / (2 * b) * np.sin(PI * u)),
    ("cycloidal", -1, None): (lambda u, L, b: L * (1 - u + np.sin(2 * PI * u) / (2 * PI)),  # 6.16
                              lambda u, L, b: -L / b * (1 - np.cos(2 * PI * u))),
    ("polynomial8", -1, None): (lambda u, L, b: L * (1 - 2.63415 * u**2 + 2.78055 * u**5    # 6.17
                                                     + 3.17060 * u**6 - 6.87795 * u**7
                                                     + 2.56095 * u**8),
                                lambda u, L, b: -L / b * (5.26830 * u - 13.90275 * u**4
                                                          - 19.02360 * u**5 + 48.14565 * u**6
                                                          - 20.48760 * u**7)),
    ("half-harmonic", 1, "start"): (lambda u, L, b: L * (1 - np.cos(PI * u / 2)),        # 6.18
                                    lambda u, L, b: PI * L / (2 * b) * np.sin(PI * u / 2)),
    ("half-harmonic", 1, "end"): (lambda u, L, b: L * np.sin(PI * u / 2),                # 6.19
                                  lambda u, L, b: PI * L / (2 * b) * np.cos(PI * u / 2)),
    ("half-harmonic", -1, "start"): (lambda u, L, b: L * np.cos(PI * u / 2),             # 6.20
                                     lambda u, L, b: -PI * L / (2 * b) * np.sin(PI * u / 2)),
    ("half-harmonic", -1, "end"): (lambda u, L, b: L * (1 - np.sin(PI * u / 2)),         # 6.21
                                   lambda u, L, b: -PI * L / (2 * b) * np.cos(PI * u / 2)),
    ("half-cycloidal", 1, "start"): (lambda u, L, b: L * (u - np.sin(PI * u) / PI),      # 6.22
                                     lambda u, L, b: L / b * (1 - np.cos(PI * u))),
    ("half-cycloidal", 1, "end"): (lambda u, L, b: L * (u + np.sin(PI * u) / PI),        # 6.23
                                   lambda u, L, b: L / b * (1 + np.cos(PI * u))),
    ("half-cycloidal", -1, "start"): (lambda u, L, b: L * (1 - u + np.sin(PI * u) / PI),  # 6.24
                                      lambda u, L, b: -L / b * (1 - np.cos(PI * u))),
    ("half-cycloidal", -1, "end"): (lambda u, L, b: L * (1 - u - np.sin(PI * u) / PI),   # 6.25
                                    lambda u, L, b: -L / b * (1 + np.cos(PI * u))),
}


@pytest.mark.parametrize("key", list(BOOK),
                         ids=lambda k: f"{k[0]}-{'rise' if k[1] > 0 else 'return'}-{k[2]}")
def test_each_segment_is_the_book_s_equation(key):
    """y and y' of a segment of lift L, angle β, over θ/β ∈ [0, 1] (Eqs. 6.5-6.25).

    A return in the book starts at y = L; in a program it starts where the
    segment before left off, here L (after a uniform rise of L in 0.1 rad).
    """
    name, sign, rest = key
    L, beta = 2.5, 1.3
    f, df = BOOK[key]
    lift = sign * L
    segs = []
    if sign < 0:
        segs.append(Segment(Motion.UNIFORM, L, 0.1))
    segs.append(Segment(Motion(name), lift, beta, None if rest is None else Rest(rest)))
    if sign > 0:
        segs.append(Segment(Motion.UNIFORM, -L, 2 * PI - beta))
    else:
        segs.append(Segment(Motion.DWELL, 0.0, 2 * PI - beta - 0.1))
    p = Program(tuple(segs))
    start = 0.1 if sign < 0 else 0.0
    k = p.evaluate(start + U[:-1] * beta)
    u = U[:-1]
    # the book prints the polynomials' coefficients to 5 decimals
    tol = 2e-5 * L if name == "polynomial8" else 1e-12 * L
    assert np.allclose(k.Y, f(u, L, beta), rtol=0, atol=tol)
    assert np.allclose(k.y1, df(u, L, beta), rtol=0, atol=tol / beta * 20)


ALL = [(m, r) for m in Motion if m not in (Motion.DWELL, Motion.TABLE)
       for r in ((Rest.START, Rest.END) if m.value.startswith("half") else (None,))]


@pytest.mark.parametrize("motion, rest", ALL)
@pytest.mark.parametrize("rise", [True, False])
def test_shapes_run_from_0_to_1_and_their_derivatives_are_derivatives(motion, rest, rise):
    """f(0) = 0, f(1) = 1, and f', f'', f''' are the slopes of f, f', f'' (central differences)."""
    f = shape(motion, rise=rise, rest=rest)
    a, b, c, d = f(np.array([0.0, 1.0]))
    assert abs(a[0]) < 1e-12 and abs(a[1] - 1) < 1e-12
    h = 1e-5
    u = np.linspace(0.013, 0.987, 61)
    # away from the knots of the piecewise motions (parabolic at 1/2, trapezoid at 1/8s)
    u = u[np.min(np.abs(u[:, None] - np.arange(0, 9)[None, :] / 8), axis=1) > 3 * h]
    lo, hi = f(u - h), f(u + h)
    for k in range(3):
        fd = (hi[k] - lo[k]) / (2 * h)
        assert np.allclose(fd, f(u)[k + 1], rtol=0, atol=1e-5 * max(1, np.abs(f(u)[k + 1]).max()))


def test_peak_accelerations_of_the_literature():
    """3-4-5: y''max = 10/√3 L/β² = 5.7735; modified trapezoid 4.8881; cycloidal 2π (Eq. 6.13c)."""
    u = np.linspace(0, 1, 200001)
    assert abs(shape(Motion.POLYNOMIAL345)(u)[2].max() - 10 / math.sqrt(3)) < 1e-8
    assert abs(shape(Motion.MODIFIED_TRAPEZOID)(u)[2].max() - 4.8881) < 1e-4
    assert abs(shape(Motion.CYCLOIDAL)(u)[2].max() - 2 * PI) < 1e-8
    # the modified trapezoid's velocity and acceleration are continuous at its knots
    f = shape(Motion.MODIFIED_TRAPEZOID)
    for x in (1 / 8, 3 / 8, 5 / 8, 7 / 8):
        lo, hi = f(np.array(x - 1e-12)), f(np.array(x + 1e-12))
        assert all(abs(float(lo[k]) - float(hi[k])) < 1e-9 for k in range(3))


@settings(max_examples=30, deadline=None)
@given(st.lists(st.floats(-2, 2), min_size=3, max_size=8))
def test_a_table_passes_through_its_points(ys):
    """The spline through a table's points passes through every one, with y'' = 0 at the ends."""
    th = np.linspace(0, 1.0, len(ys))
    f, y0, h = table_shape(th, np.asarray(ys))
    a, _, c, _ = f(th)
    assert np.allclose(y0 + h * a, ys, atol=1e-9)
    assert abs(c[0]) < 1e-9 and abs(c[-1]) < 1e-9
