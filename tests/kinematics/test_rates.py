"""Rates given for a link other than the drive ([rates]), by superposition (Sec. 5.4)."""

from __future__ import annotations

import pytest
from spec_data import EXAMPLES

import graphkin


def test_slider_rates_on_a_crank_driven_posture():
    # The offset slider-crank of Ex. 3.2 driven by the crank at the posture the slider
    # drive gives (θ2 = 44.939811°, expected.toml), with the slider's speed -10 m/s given
    # in [rates]: the rates must be those of the slider-driven file, whose exact values
    # are in expected.toml (ω2 = 197.8568, ω3 = -54.44968, α2 = -24586.69, α3 = 16241.58).
    text = (EXAMPLES / "ex3_2_slider_driven.toml").read_text()
    text = text.replace('[drive]\nlink = 4\nposition = 164\nvelocity = "-10 m/s"\n'
                        'acceleration = 0',
                        '[drive]\nlink = 2\nangle = 44.939811\n[rates]\nlink = 4\n'
                        'velocity = "-10 m/s"\nacceleration = 0')
    sol = graphkin.loads(text).solve()
    assert float(sol.omega("2")) == pytest.approx(197.8568, abs=0.01)
    assert float(sol.omega("3")) == pytest.approx(-54.44968, abs=0.01)
    assert float(sol.alpha("2")) == pytest.approx(-24586.69, abs=2.0)
    assert float(sol.alpha("3")) == pytest.approx(16241.58, abs=2.0)


def test_rates_of_the_coupler_set_the_crank():
    # Ex. 4.14: ω3 = 5 rad/s ccw and α3 = 20 rad/s² cw are given for the coupler.
    sol = graphkin.load(EXAMPLES / "ex4_14_inflection_bresse.toml").solve()
    assert float(sol.omega("3")) == pytest.approx(5.0, rel=1e-12)
    assert float(sol.alpha("3")) == pytest.approx(-20.0, rel=1e-12)
    # the book: ω2 = 11.78 rad/s ccw (expected.toml, exact 11.77877)
    assert float(sol.omega("2")) == pytest.approx(11.77877, abs=1e-4)
