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
