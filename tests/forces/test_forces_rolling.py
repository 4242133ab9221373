"""Rolling contact with loads (Sec. 11.11): the contact as a pin at the point of contact,
and gear teeth (a pressure angle): the force along the pressure line.

A wheel rolling without slip transmits a force with two unknown components
through the point of contact (the friction holds).  Checked by hand (a wheel
pushed at its center, Fig. 3.18's mechanism), against the matrix method and
against the power balance over random postures, loads and masses.
"""

from __future__ import annotations

import tomllib
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.errors import InputError
from graphkin.forces import power_balance, solve_forces
from graphkin.mechanisms import from_dict

WHEEL = Path(__file__).resolve().parents[2] / "gallery" / "mechanisms" / \
    "fig3_18_rolling_wheel.toml"


def _wheel() -> dict[str, Any]:
    data = tomllib.loads(WHEEL.read_text())
    data.pop("gallery", None)
    data["units"]["force"] = "N"
    return data


def test_wheel_pushed_at_its_center_by_hand():
    """Crank O2A = 150 mm at 90°, coupler AB horizontal (A = (0, 150), B = (200, 150)),
    wheel of radius 100 on the ground, B 50 mm above its center G = (200, 100).

    P = 50 N to the left at G.  Link 3 is a two-force member along AB (horizontal).
    Moments about the point of contact (200, 0) on the wheel: -50·(-100)... written out,
    P_x·100 + F34_x·150 = 0, so F34 = +33.33 N (to the right) and F14 = -(P + F34) =
    (16.67, 0) N through the contact.  F32 = (-33.33, 0) N at A: T12 = -(0·0 - 150·(-33.33))
    = -5000 N·mm (cw)."""
    data = _wheel()
    data["loads"] = [{"link": 4, "point": "G", "force": "50 N at 180 deg"}]
    fs = solve_forces(from_dict(data, source="<wheel>").solve())
    assert fs.method == "construction"
    np.testing.assert_allclose(fs.force(3, 4), [100 / 3, 0], atol=1e-9)
    np.testing.assert_allclose(fs.force(1, 4), [50 / 3, 0], atol=1e-9)
    np.testing.assert_allclose(fs.point("1-4"), [200, 0], atol=1e-9)
    assert fs.torque(2) == pytest.approx(-5000, rel=1e-12)


@st.composite
def wheels(draw: st.DrawFn) -> dict[str, Any]:
    data = _wheel()
    data["drive"]["angle"] = draw(st.floats(60, 120))
    data["drive"]["alpha"] = draw(st.floats(-50, 50))
    data["links"]["4"]["B"] = [draw(st.floats(-40, 40)), draw(st.floats(30, 70))]
    data["links"]["4"]["H"] = [draw(st.floats(-90, 90)), draw(st.floats(-90, 90))]
    data["links"]["3"]["M"] = [draw(st.floats(20, 180)), draw(st.floats(-30, 30))]
    data.pop("assembly", None)
    data["assembly"] = {"B": [200 + data["links"]["4"]["B"][0], 100 + data["links"]["4"]["B"][1]]}
    loads = []
    for link, pt in (("4", "H"), ("3", "M")):
        if draw(st.booleans()):
            size, angle = draw(st.floats(1, 100)), draw(st.floats(-180, 180))
            loads.append({"link": int(link), "point": pt, "force": f"{size} N at {angle} deg"})
    if draw(st.booleans()):
        loads.append({"link": 4, "torque": draw(st.floats(-2000, 2000))})
    if not loads or draw(st.booleans()):
        data["inertia"] = {"4": {"center": "G", "mass": f"{draw(st.floats(0.1, 5))} kg",
                                 "moment": f"{draw(st.floats(0.001, 0.05))} kg*m^2"},
                           "3": {"center": "M", "mass": f"{draw(st.floats(0.1, 2))} kg",
                                 "moment": f"{draw(st.floats(0.001, 0.02))} kg*m^2"}}
    if loads:
        data["loads"] = loads
    return data


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(wheels())
def test_rolling_agrees_with_matrix_method_and_power(data: dict[str, Any]) -> None:
    try:
        mech = from_dict(data, source="<random wheel>")
        sol = mech.solve()
    except InputError:
        return  # a posture the random wheel cannot reach
    graphic = solve_forces(sol)
    assert graphic.method == "construction", graphic.notes
    matrix = solve_forces(sol, method="analytic")
    big = max([float(np.hypot(*w[:2])) for w in matrix.forces.values()] + [1.0])
    for key, w in matrix.forces.items():
        assert np.all(np.abs(graphic.forces[key][:2] - w[:2]) <= 1e-9 * big), key
        assert abs(graphic.forces[key][2] - w[2]) <= 1e-9 * big * mech.scale, key
    t, tm = graphic.torque(2), matrix.torque(2)
    assert abs(t - tm) <= 1e-9 * big * mech.scale
    residual, size = power_balance(sol, graphic.dynamic, {"2": t})
    assert abs(residual) <= 1e-9 * size


def _gears(phi: float | None = 20.0, torque: float = -600.0) -> dict[str, Any]:
    data: dict[str, Any] = {
        "units": {"length": "mm", "force": "N"},
        "links": {"1": {"O2": [0, 0], "O3": [100, 0]}, "2": {"O2": [0, 0]},
                  "3": {"O3": [0, 0]}},
        "rolling": [{"link": 3, "on": 2, "circle": {"center": "O3", "radius": 60},
                     "on_circle": {"center": "O2", "radius": 40}}],
        "drive": {"link": 2, "angle": 0},
        "loads": [{"link": 3, "torque": torque}]}
    if phi is not None:
        data["rolling"][0]["pressure_angle"] = phi
    return data


def test_spur_gears_by_hand():
    """Fig. 11.14 with numbers: pinion 2 (R2 = 40 mm) drives gear 3 (R3 = 60 mm, centers
    100 mm apart) against a load couple of 600 N·mm cw on gear 3; φ = 20°.

    Pitch point P = (40, 0).  On gear 3, ΣM_O3 = 0: (P - O3) × F23 = -60·F23_y = +600, so
    the transmitted force F23^t = -10 N (down); the radial force pushes gear 3 away from
    gear 2, toward O3: F23^r = 10 tan 20° = 3.6397 N (to the right).  On the pinion
    F32 = -F23 at P: T12 = -(40·10) = -400 N·mm (cw), = 600·R2/R3 (Eq. 11.12)."""
    fs = solve_forces(from_dict(_gears(), source="<gears>").solve())
    assert fs.method == "construction"
    f23 = np.array([10 * np.tan(np.radians(20)), -10.0])
    np.testing.assert_allclose(fs.force(2, 3), f23, atol=1e-9)
    np.testing.assert_allclose(fs.force(1, 3), -f23, atol=1e-9)
    np.testing.assert_allclose(fs.force(1, 2), f23, atol=1e-9)
    np.testing.assert_allclose(fs.point("2-3"), [40, 0], atol=1e-9)
    assert fs.torque(2) == pytest.approx(-400, rel=1e-12)
    # the other sense of the load: the transmitted force turns over, the radial one does not
    fs = solve_forces(from_dict(_gears(torque=600.0), source="<gears>").solve())
    np.testing.assert_allclose(fs.force(2, 3), [f23[0], 10.0], atol=1e-9)


@settings(max_examples=30, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(0, 30), st.floats(-180, 180), st.floats(-1000, 1000).filter(
    lambda t: abs(t) > 1), st.floats(5, 60), st.floats(-1, 1), st.floats(-1, 1))
def test_gears_agree_with_matrix_method_and_power(phi, angle, torque, arm, fx, fy):
    """Random pressure angle, posture, load couple and a force on gear 3 at Q."""
    data = _gears(phi, torque)
    data["links"]["3"]["Q"] = [arm, 0]
    data["drive"]["angle"] = angle
    data["drive"]["omega"] = "5 rad/s"
    if abs(fx) + abs(fy) > 0.1:
        data["loads"].append({"link": 3, "point": "Q", "force": [50 * fx, 50 * fy]})
    sol = from_dict(data, source="<gears>").solve()
    graphic = solve_forces(sol)
    matrix = solve_forces(sol, method="analytic")
    big = max([float(np.hypot(*w[:2])) for w in matrix.forces.values()] + [1.0])
    for key, w in matrix.forces.items():
        assert np.all(np.abs(graphic.forces[key][:2] - w[:2]) <= 1e-9 * big), key
    # the force at the pitch point lies on the pressure line: φ from the common tangent
    f = graphic.forces["2-3"][:2]
    if np.hypot(*f) > 1e-9:
        p = graphic.point("2-3")
        o3 = sol.position("O3")
        e = (o3 - p) / np.hypot(*(o3 - p))
        lean = np.degrees(np.arctan2(abs(float(f @ e)), abs(float(f @ [-e[1], e[0]]))))
        assert lean == pytest.approx(phi, abs=1e-7)
    residual, size = power_balance(sol, False, {"2": graphic.torque(2)})
    assert abs(residual) <= 1e-9 * size


def test_gears_on_fixed_centers_need_a_pressure_angle():
    mech = from_dict(_gears(None), source="<gears>")
    with pytest.raises(InputError, match="pressure_angle") as info:
        solve_forces(mech.solve())
    assert info.value.key == "rolling[0].pressure_angle"


@pytest.mark.parametrize("phi", [-5, 45, "20 deg", True])
def test_a_bad_pressure_angle_is_refused(phi):
    with pytest.raises(InputError) as info:
        from_dict(_gears(phi), source="<gears>")
    assert info.value.key == "rolling[0].pressure_angle"
