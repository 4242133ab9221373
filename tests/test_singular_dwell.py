"""Limit positions through a dwell (Sec. 1.10 with the cam programs of Sec. 6.3).

A follower at rest through a dwell has a velocity of round-off (1e-17 of
either sign).  The limit positions once took that sign for a sense: a dwell
between two returns (Problem 6.30's 290°-310°) was two limit positions, a
dwell between a return and a rise was reported at one end only, and a rocker
driven off the follower lost its reversals at the dwells (its ω exactly 0
there), so a time ratio was printed from two of its four limit positions.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.kinematics.sweep.singular import _reversals, time_ratios

DATA = Path(__file__).parent / "data" / "audit7"


def _lift(theta: float) -> float:
    """Problem 6.30's program by hand (Eqs. 6.12, 6.13, 6.15, 6.16), mm, Θ in degrees."""
    t = theta % 360.0
    if t < 45:
        return 0.0
    if t < 120:
        return 17.5 * (1 - math.cos(math.pi * (t - 45) / 75))
    if t < 130:
        return 35.0
    if t < 180:
        u = (t - 130) / 50
        return 35.0 + 15 * (u - math.sin(2 * math.pi * u) / (2 * math.pi))
    if t < 210:
        return 50.0
    if t < 290:
        return 30.0 + 10 * (1 + math.cos(math.pi * (t - 210) / 80))
    if t < 310:
        return 30.0
    u = (t - 310) / 50
    return 30.0 * (1 - u + math.sin(2 * math.pi * u) / (2 * math.pi))


def _root(f, a: float, b: float) -> float:
    fa = f(a)
    for _ in range(80):
        m = 0.5 * (a + b)
        if (f(m) > 0) == (fa > 0):
            a, fa = m, f(m)
        else:
            b = m
    return 0.5 * (a + b)


def test_cam_mechanism_limits_through_dwells() -> None:
    # The offset roller follower (ε = 20, R0 = 60): the trace point T4 stands at
    # y0 = √(60² − 20²) = 56.5685 at zero lift, on the guide from G4a = (20, 0).
    # The follower reverses through the dwells 0°-45° (after the return, before the
    # rise) and 180°-210° (at the top), and not through 120°-130° (between two rises)
    # or 290°-310° (between two returns).  The sweep runs from the file's 230°.
    sw = graphkin.load(DATA / "cam_mech.toml").sweep(count=720)
    lim = [s for s in sw.singular if s.kind == "limit"]
    y0 = math.sqrt(60.0 ** 2 - 20.0 ** 2)
    # A dwell's edge is where the speed falls to round-off, 1e-9 of S = the larger of
    # its peak and the mechanism's size (under 200 mm here), per radian of cam: at the
    # end of a cycloidal segment V = (L/β)(1 − cos 2πu) ≈ (L/β) 2π² u², so the edge is
    # u = √(1e-9 S / (2π² L/β)) early; the worst, the 15 mm rise over 50° (L/β = 17.2
    # mm/rad), gives u ≤ 2.4e-5, 1.2e-3° of its 50°: the dwells' ends to 2e-3°.
    edge = 2e-3
    slider = [s for s in lim if s.label == "4"]
    assert [(s.drive, s.end) for s in slider] == [
        (pytest.approx(360.0, abs=edge), pytest.approx(405.0, abs=edge)),
        (pytest.approx(540.0, abs=edge), pytest.approx(570.0, abs=edge))]
    assert f"T4 at {y0:.4g} mm" in slider[0].note and "(a dwell)" in slider[0].note
    assert f"T4 at {y0 + 50:.4g} mm" in slider[1].note
    # Rocker 6 (O6 = (120, 60), O6H = 60) driven by rod PH = 100 from P, 40 above T4
    # on the line x = 20: ω6 = 0 where PH is square to V_P (vertical), so H = (120, y_P)
    # and |O6H| = 60 gives y_P = 120: lift Y = 120 − 40 − y0 = 23.4315, met once on the
    # rise and once on the last return; and it reverses with the follower in its dwells.
    y_star = 120.0 - 40.0 - y0
    rise = _root(lambda t: _lift(t) - y_star, 45.0, 120.0)
    back = _root(lambda t: _lift(t) - y_star, 310.0, 359.0)
    rocker = [s for s in lim if s.label == "6"]
    got = [(s.drive, s.end) for s in rocker]
    assert got == [(pytest.approx(back, abs=1e-6), None),
                   (pytest.approx(360.0, abs=edge), pytest.approx(405.0, abs=edge)),
                   (pytest.approx(rise + 360.0, abs=1e-6), None),
                   (pytest.approx(540.0, abs=edge), pytest.approx(570.0, abs=edge))]
    # four reversals of link 6: no time ratio of two strokes
    assert not any("link 6" in line for line in time_ratios(sw))


def _program(widths: list[float], senses: list[int]):
    """A speed made of bumps: sense_k · sin(π (x − a_k)/w_k), 0 where sense_k = 0.

    At rest the speed is round-off of either sign (1e-18 · sin(1e6 x)).
    """
    edges = np.concatenate([[0.0], np.cumsum(widths)])

    def v(x):
        x = np.asarray(x, dtype=float)
        k = np.clip(np.searchsorted(edges, x, side="right") - 1, 0, len(widths) - 1)
        a, w, s = edges[k], np.asarray(widths)[k], np.asarray(senses)[k]
        bump = s * np.sin(np.pi * np.clip((x - a) / w, 0.0, 1.0))
        return np.where(s == 0, 1e-18 * np.sin(1e6 * x), bump)
    return v, edges


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(5.0, 40.0), st.sampled_from([-1, 0, 1])),
                min_size=2, max_size=8))
@example([(5.0, 0), (5.0, 0)])            # at rest throughout: round-off only, no limit
def test_reversals_of_a_program_of_strokes_and_dwells(segs) -> None:
    # Expected by reading the program: between two consecutive moving segments of
    # opposite sense lies one limit position, at their common edge when they touch,
    # else held over the dwells between them (from the first's end to the second's
    # start); moving segments of one sense, with or without a dwell between, none.
    widths = [w for w, _ in segs]
    senses = [s for _, s in segs]
    v, edges = _program(widths, senses)
    dv = np.linspace(0.0, edges[-1], 4001)
    moving = [k for k, s in enumerate(senses) if s != 0]
    want: list[tuple[float, float | None]] = []
    for p, q in zip(moving, moving[1:]):
        if senses[p] != senses[q]:
            want.append((edges[q], None) if q == p + 1 else (edges[p + 1], edges[q]))
    # samples near the ends of the program (a bump starting or ending there) are
    # too slow to have a sense; the program's first and last edges are not limits
    # the bumps' natural size is 1 (a program wholly at rest is round-off only)
    got = _reversals(dv, v(dv), np.ones(dv.size, dtype=bool), v, 1.0)
    assert len(got) == len(want)
    for (ga, gb), (wa, wb) in zip(got, want):
        assert ga == pytest.approx(wa, abs=1e-6)
        if wb is None:
            assert gb is None
        else:
            assert gb == pytest.approx(wb, abs=1e-6)


def test_time_ratio_is_given_whatever_alpha_the_file_states() -> None:
    # The offset slider-crank in inches (crank 2, rod 7, offset 1; α7 = 150 rad/s² in the
    # file) once got no time ratio because of its α.  By hand (Sec. 1.7): the slider
    # stops with crank and rod in line, extended at θ = asin(1/9) and folded at
    # θ = 180° + asin(1/5); the crank turns α = 180° + asin(1/5) − asin(1/9) on one
    # stroke and 360° − α on the other, Q = α/(360° − α) at a constant crank speed.
    sw = graphkin.load(DATA / "offset_in.toml").sweep(count=360)
    a = 180.0 + math.degrees(math.asin(1 / 5)) - math.degrees(math.asin(1 / 9))
    (line,) = [ln for ln in time_ratios(sw) if "slider 12" in ln]
    assert f"Q = α/β = {a:.2f}°/{360 - a:.2f}° = {a / (360 - a):.3f}" in line
    assert "at a constant crank speed" in line
