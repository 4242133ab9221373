"""Every graphic construction equals the independent analytic solution (Hypothesis).

Random mechanisms are generated from a known posture (tests/strategies.py), so
positions are checked against the generating posture itself; velocities and
accelerations against the analytic solver's constraint-Jacobian linear solves
(graphkin.kinematics.analytic), which shares no code with the constructions.
"""

from __future__ import annotations

import numpy as np
from hypothesis import given
from strategies import (
    double_sliders,
    examples,
    five_bars,
    fourbars,
    inverted_slider_cranks,
    six_bars,
    slider_cranks,
    slotted,
)

import graphkin
from graphkin.kinematics.analytic import solve_analytic

REL = 1e-9
SETTINGS = examples(40)


def _check(rm, *, expect_construction=True):
    mech = rm.mechanism()
    sol = graphkin.solve(mech)
    if expect_construction:
        assert sol.method == "construction", sol.notes
    truth = rm.world_points()
    size = rm.scale()
    for name, xy in truth.items():
        np.testing.assert_allclose(sol.position(name), xy, rtol=0, atol=REL * size)
    if not mech.has_rates:
        return
    ref = solve_analytic(mech, guess=rm.truth)
    # a dimensionally consistent scale for each kind of quantity (one of them may vanish
    # at a special posture; its scale does not): ω ~ V/L, α ~ A/L + ω²
    vmax = max(float(np.hypot(*ref.velocity(n))) for n in truth)
    amax = max(float(np.hypot(*ref.acceleration(n))) for n in truth)
    w = max(abs(float(ref.omega(k))) for k in mech.moving)
    al = max(abs(float(ref.alpha(k))) for k in mech.moving)
    wscale = w + vmax / size
    ascale_w = al + wscale**2 + amax / size
    vscale = vmax + size * wscale
    ascale = amax + size * ascale_w
    if mech.rates is not None and mech.rates.kind == "angle":
        # rates given for another link fix the drive's by a ratio (superposition): the
        # problem amplifies round-off by |ω_drive/ω_given|, whatever the method
        drive = mech.drives[0].link
        ratio = abs(float(ref.omega(drive)) / float(ref.omega(mech.rates.link)))
        amplify = max(1.0, ratio) ** 2
        wscale, ascale_w, vscale, ascale = (x * amplify for x in
                                            (wscale, ascale_w, vscale, ascale))
    for name in truth:
        np.testing.assert_allclose(sol.velocity(name), ref.velocity(name), rtol=0,
                                   atol=REL * vscale)
        np.testing.assert_allclose(sol.acceleration(name), ref.acceleration(name), rtol=0,
                                   atol=REL * ascale)
    for lid in mech.moving:
        assert abs(float(sol.omega(lid)) - float(ref.omega(lid))) <= REL * wscale
        assert abs(float(sol.alpha(lid)) - float(ref.alpha(lid))) <= REL * ascale_w


@SETTINGS
@given(fourbars())
def test_fourbars(rm):
    _check(rm)


@SETTINGS
@given(slider_cranks())
def test_slider_cranks(rm):
    _check(rm)


@SETTINGS
@given(inverted_slider_cranks())
def test_inverted_slider_cranks(rm):
    _check(rm)


@SETTINGS
@given(slotted())
def test_slots_on_moving_links(rm):
    _check(rm)


@SETTINGS
@given(double_sliders())
def test_double_sliders(rm):
    _check(rm)


@SETTINGS
@given(six_bars())
def test_six_bars(rm):
    _check(rm)


@SETTINGS
@given(five_bars())
def test_two_input_five_bars(rm):
    _check(rm)
