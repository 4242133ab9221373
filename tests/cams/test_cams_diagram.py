"""Figs. 6.6-6.7: the constructed harmonic and cycloidal diagrams lie on Eqs. (6.12a), (6.13a)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.cams import Motion, Program, Segment
from graphkin.cams.diagram import cycloidal_diagram, harmonic_diagram, parabolic_diagram


def _closed_form(motion, lift, k, n):
    """The program's own Y at θ = kβ/n for a rise of ``lift`` in β = 120°."""
    beta = math.radians(120)
    p = Program((Segment(motion, lift, beta), Segment(Motion.CYCLOIDAL, -lift, 2 * math.pi - beta)))
    return p.evaluate(k * beta / n).Y


@settings(max_examples=30, deadline=None)
@given(st.floats(0.1, 100), st.floats(0.5, 20), st.integers(2, 24))
def test_the_constructions_land_on_the_closed_forms(lift, width, n):
    k = np.arange(n + 1)
    for build, motion in ((harmonic_diagram, Motion.HARMONIC),
                          (cycloidal_diagram, Motion.CYCLOIDAL)):
        d = build(lift, width, n)
        pts = d.points()
        assert np.allclose(pts[:, 0], width * k / n, rtol=0, atol=1e-12 * width)
        assert np.allclose(pts[:, 1], _closed_form(motion, lift, k, n), rtol=0,
                           atol=1e-12 * (lift + width))


def test_the_steps_are_the_book_s():
    """Fig. 6.7: the circle of radius L/2π, projection to the ordinate, parallel to OB."""
    cx = cycloidal_diagram(3.0, 5.0).construction
    assert [s.op for s in cx if s.label in ("OB", "k", "g", "D")] == ["join", "circle", "parallel",
                                                                     "meet"]
    assert cx.step_of("k").params["radius"] == 3.0 / (2 * math.pi)


@settings(max_examples=20, deadline=None)
@given(st.floats(0.1, 100), st.floats(0.5, 20), st.integers(1, 12))
def test_the_parabolic_construction_lands_on_eqs_6_5_and_6_6(lift, width, n):
    """Fig. 6.5b, both halves: Ex 6.1's parabolas at θ = (β/2)(k/n) and β − (β/2)(k/n)."""
    pts = parabolic_diagram(lift, width, n).points()
    t = np.arange(n + 1) / n
    k = np.concatenate([t / 2, (1 - t / 2)[::-1]])           # θ/β of each point
    assert np.allclose(pts[:, 0], width * k, rtol=0, atol=1e-12 * width)
    beta = math.radians(120)
    p = Program((Segment(Motion.PARABOLIC, lift, beta),
                 Segment(Motion.CYCLOIDAL, -lift, 2 * math.pi - beta)))
    y = p.evaluate(np.minimum(k, 1 - 1e-15) * beta).Y
    assert np.allclose(pts[:, 1], y, rtol=0, atol=1e-12 * (lift + width))
