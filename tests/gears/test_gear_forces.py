"""Gear tooth forces resolved as Sec. 11.11 resolves them: transmitted and radial.

Checked by hand (W_t = T/R, W_r = W_t tan φ, W = W_t / cos φ, Eq. 11.12), on
Example 11.7's planetary train (the book's numbers, and where it rounds), and
over random pressure angles and load couples.
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.forces import solve_forces
from graphkin.forces.gear_teeth import tooth_forces
from graphkin.mechanisms import from_dict

ROOT = Path(__file__).resolve().parents[2]
SPUR = ROOT / "tests" / "forces" / "data" / "spur_gears.toml"
EX11_7 = Path(__file__).resolve().parent / "data" / "ex11_7_planetary.toml"


def _spur(phi: float = 20.0, torque: float = -600.0) -> dict:
    data = tomllib.loads(SPUR.read_text(encoding="utf-8"))
    data["rolling"][0]["pressure_angle"] = phi
    data["loads"][0]["torque"] = torque
    return data


def test_spur_pair_by_hand(capsys):
    """Pinion 2 (R2 = 40 mm) drives gear 3 (R3 = 60 mm) against 600 N·mm cw on 3, φ = 20°.

    On gear 3: W_t = T/R3 = 600/60 = 10 N (Eq. 11.12), W_r = 10 tan 20° = 3.6397 N toward
    O3, W = 10/cos 20° = 10.642 N; on the pinion W_t R2 = 400 N·mm, the drive's torque."""
    assert main(["solve", str(SPUR), "--json"]) == 0
    g = json.loads(capsys.readouterr().out)["forces"]["gears"]["rolling[0]"]
    t = math.tan(math.radians(20))
    assert g["tangential"] == pytest.approx(10.0, rel=1e-12)
    assert g["radial"] == pytest.approx(10.0 * t, rel=1e-12)
    assert g["force"] == pytest.approx(10.0 / math.cos(math.radians(20)), rel=1e-12)
    assert g["pressure_angle"] == pytest.approx(20.0)
    assert g["torque"] == {"3": pytest.approx(600.0), "2": pytest.approx(400.0)}
    assert g["radius"] == {"3": 60.0, "2": 40.0}
    assert main(["solve", str(SPUR)]) == 0
    text = capsys.readouterr().out
    assert "transmitted F₂₃^t 10.00 N + radial F₂₃^r 3.640 N toward the center of 3" in text


def test_example_11_7_planetary_train():
    """Example 11.7: T12 = -100 in·lb on gear 2 (R2 = 1.00 in).

    By hand: F42^t = T12/R2 = 100 lb, F42 = 100/cos 20° = 106.4 lb (book: 106 lb);
    the planet carries T = 1.50 × 100 = 150 in·lb to gear 5: F65^t = 150/0.80 = 187.5 lb,
    F65 = 187.5/cos 20° = 199.5 lb (book: 200 lb); T16 = 1.70 × 187.5 = 318.75 in·lb
    (book: 319). The arm: the planet's net tangential force 187.5 − 100 = 87.5 lb at
    2.50 in, T13 = 218.75 in·lb cw; by power instead, ω3/ω2 = −16/35 (θ'62/3 = 16/51
    with ω6 = 0), T13 = −T12 ω2/ω3 = −(−100)(−35/16) = −218.75. The book prints 221: it
    carries its rounded 200 lb (200 cos 20° = 187.9 lb) into the arm's moment."""
    data = tomllib.loads(EX11_7.read_text(encoding="utf-8"))
    data["drive"]["omega"] = "1 rad/s"     # for the power balance below
    sol = from_dict(data, source=str(EX11_7)).solve()
    fs = solve_forces(sol)
    teeth = {t.key: t for t in tooth_forces(fs)}
    c = math.cos(math.radians(20))
    g24, g14 = teeth["rolling[0]"], teeth["rolling[1]"]
    assert g24.tangential == pytest.approx(100.0, rel=1e-9)
    assert g24.force == pytest.approx(100.0 / c, rel=1e-9)
    assert g24.radial == pytest.approx(100.0 * math.tan(math.radians(20)), rel=1e-9)
    assert g14.tangential == pytest.approx(187.5, rel=1e-9)
    assert g14.force == pytest.approx(187.5 / c, rel=1e-9)
    assert abs(g14.torque["1"]) == pytest.approx(318.75, rel=1e-9)
    assert fs.torque(3) == pytest.approx(-218.75, rel=1e-9)
    w2, w3 = sol.links["2"].omega, sol.links["3"].omega
    assert w3 / w2 == pytest.approx(-16 / 35, rel=1e-9)   # the train value, Eq. (7.25)
    assert -100.0 * w2 + fs.torque(3) * w3 == pytest.approx(0.0, abs=1e-9)   # power


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.floats(5, 35), st.floats(-2000, 2000).filter(lambda t: abs(t) > 1))
def test_components_obey_section_11_11(phi, torque):
    """W_t = |T3|/R3, W_r = W_t tan φ toward O3, W = W_t / cos φ, W_t R2 = |T12|."""
    fs = solve_forces(from_dict(_spur(phi, torque), source="<spur>").solve())
    (t,) = tooth_forces(fs)
    wt = abs(torque) / 60.0
    assert t.tangential == pytest.approx(wt, rel=1e-9)
    assert t.radial == pytest.approx(wt * math.tan(math.radians(phi)), rel=1e-9)
    assert t.force == pytest.approx(wt / math.cos(math.radians(phi)), rel=1e-9)
    assert abs(t.torque["2"]) == pytest.approx(abs(fs.torque(2)), rel=1e-9)
    assert abs(t.torque["2"]) == pytest.approx(wt * 40.0, rel=1e-9)
    # the moment on 3 balances the load couple
    assert t.torque["3"] == pytest.approx(-torque, rel=1e-9)
