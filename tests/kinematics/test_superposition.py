"""The method of superposition for several inputs (Sec. 5.4, Example 5.4)."""

from __future__ import annotations

import numpy as np
import pytest
from spec_data import EXAMPLES

import graphkin
from graphkin.kinematics.analytic import solve_analytic
from graphkin.kinematics.solve import superposition


def test_five_bar_cases_add_up_and_each_is_the_frozen_input_solution():
    text = (EXAMPLES / "ex5_4_fivebar.toml").read_text()
    mech = graphkin.loads(text)
    cases = superposition(mech)
    assert [i for i, _ in cases] == [0, 1]
    full = mech.solve()
    for name in mech.point_names:
        total = sum(sol.velocity(name) for _, sol in cases)
        np.testing.assert_allclose(total, full.velocity(name), atol=1e-9 * 500)
    # case (a): link 3 frozen, ω2 = 10 ccw — compare with the analytic solver on the same
    # file with ω3 = 0 (the other input locked)
    frozen = graphkin.loads(text.replace('omega = "5 rad/s cw"', "omega = 0"))
    ref = solve_analytic(frozen)
    for lid in ("4", "5"):
        assert float(cases[0][1].omega(lid)) == pytest.approx(float(ref.omega(lid)), rel=1e-9)


def test_superposition_needs_rates(examples):
    mech = graphkin.load(examples / "ex2_5_open.toml")
    with pytest.raises(graphkin.InputError):
        superposition(mech)


def test_example_5_7_instant_centers_of_each_frozen_case():
    # Uicker Ex. 5.7 solves Ex. 5.3's five-bar by superposition with the instant centers
    # of each case, measured off its scaled drawings (Figs. 5.12, 5.13; Eqs. 4-6):
    # case (a), link 3 frozen: |I24 I12| = 2.50, |I24 I14| = 10.56, |I25 I12| = 7.76,
    # |I25 I15| = 17.03 in; case (b), link 2 frozen: |I34 I13| = 18.06, |I34 I14| = 25.62,
    # |I35 I13| = 4.00, |I35 I15| = 36.67 in; and the coefficients θ'42 = -0.237,
    # θ'43 = 0.705, θ'52 = 0.455, θ'53 = -0.109.
    from graphkin.kinematics.instant_centers import instant_centers

    mech = graphkin.load(EXAMPLES / "ex5_4_fivebar.toml")
    (_, case_a), (_, case_b) = superposition(mech)

    def dist(ic, a, b):
        return float(np.hypot(*(np.asarray(ic[a].xy) - np.asarray(ic[b].xy))))

    ic = instant_centers(case_a)
    for (a, b), book in {("I24", "I12"): 2.50, ("I24", "I14"): 10.56,
                         ("I25", "I12"): 7.76, ("I25", "I15"): 17.03}.items():
        assert dist(ic, a, b) == pytest.approx(book, rel=0.01)
    ic = instant_centers(case_b)
    for (a, b), book in {("I34", "I13"): 18.06, ("I34", "I14"): 25.62,
                         ("I35", "I13"): 4.00, ("I35", "I15"): 36.67}.items():
        assert dist(ic, a, b) == pytest.approx(book, rel=0.01)
    w2, w3 = 10.0, -5.0
    assert float(case_a.omega("4")) / w2 == pytest.approx(-0.237, abs=0.002)
    assert float(case_a.omega("5")) / w2 == pytest.approx(0.455, abs=0.002)
    assert float(case_b.omega("4")) / w3 == pytest.approx(0.705, abs=0.002)
    assert float(case_b.omega("5")) / w3 == pytest.approx(-0.109, abs=0.002)
