"""A planetary train given as a mechanism file: the book's table and formula beside the rolling.

``graphkin gears MECHFILE`` reads the train off the ``[[rolling]]`` circles
(:mod:`graphkin.gears.mechanism_train`) and prints the formula method
(Eq. 7.25) and the tabular method (Sec. 7.16), checked against the rolling-
contact kinematics of the same file.  Also the arrangements of issue 26,
drawn at random and held to the analytic solver (loop closure, Secs. 3.9,
4.9) and to hand derivations: a planet on an arm rolling on a driven sun
whose center is the frame pivot, a pinion pinned to a driven slider rolling
on a rack pivoted at O4, and the 15/45-teeth pair standing at the file's angle.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.cli import main
from graphkin.gears.mechanism_train import train_of
from graphkin.gears.train import tabular
from graphkin.kinematics.analytic import solve_analytic
from graphkin.output.trains import mechanism_train_json, mechanism_train_text

ROOT = Path(__file__).resolve().parents[2]
RING = ROOT / "tests" / "data" / "rolling" / "planet_arm_driven_sun_fixed_ring.toml"
EX11_7 = Path(__file__).resolve().parent / "data" / "ex11_7_planetary.toml"
GEARS_15_45 = ROOT / "tests" / "data" / "rolling" / "gears_15_45.toml"
SLOW = settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])


def analytic_agrees(mech: graphkin.Mechanism, sol: graphkin.Solution) -> None:
    """Every link's angle, ω and α of ``sol`` equal the analytic solver's."""
    guess = {lid: (float(s.origin[0]), float(s.origin[1]), float(s.angle))
             for lid, s in sol.links.items() if lid != "1"}
    exact = solve_analytic(mech, guess=guess)
    for lid, s in sol.links.items():
        e = exact.links[lid]
        w = max(1.0, abs(float(e.omega)))
        assert math.isclose(math.cos(float(s.angle) - float(e.angle)), 1.0, abs_tol=1e-12)
        assert math.isclose(float(s.omega), float(e.omega), rel_tol=1e-7, abs_tol=1e-9 * w)
        a = max(1.0, abs(float(e.alpha)), w * w)
        assert math.isclose(float(s.alpha), float(e.alpha), rel_tol=1e-7, abs_tol=1e-9 * a)


def test_the_books_table_for_a_planetary_mechanism(capsys):
    """Sun 4 (R = 40) at 10 rad/s about the frame pivot, planet 3 (20) on arm 2, ring (80) fixed.

    Table 7.3's steps with the arm 2 and the sun turned: ω4 = ω2 + ω4/2 = 10 and the ring
    ω1 = ω2 + (20/80)(−40/20) ω4/2 = ω2 − ω4/2/2 = 0, so ω4/2 = 20/3 and ω2 = 10/3 rad/s;
    the planet ω3 = ω2 + (−40/20) ω4/2 = 10/3 − 40/3 = −10 rad/s."""
    sol = graphkin.load(RING).solve()
    data = mechanism_train_json(sol)
    assert data is not None
    assert data["table"]["omega_arm"] == pytest.approx(10 / 3, rel=1e-12)
    assert data["table"]["omega_turned_relative"] == pytest.approx(20 / 3, rel=1e-12)
    assert data["members"]["3"]["omega"] == pytest.approx(-10.0, rel=1e-12)
    assert all(c["difference"] == 0.0 for c in data["check"].values()), data["check"]
    assert main(["gears", str(RING)]) == 0
    out = capsys.readouterr().out
    assert "2. Arm fixed           (20/80)(-40/20)ω4/2" in out
    assert "they agree" in out
    assert main(["gears", str(RING), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["check"]["2"]["train"] == pytest.approx(10 / 3)


def test_example_11_7_train_read_off_the_mechanism():
    """Example 11.7's compound planet 4-5 is one link with two circles (4 and 4').

    Eq. (7.24): θ'62/3 = (−R2/R4)(−R5/R6) = (1/1.5)(0.8/1.7) = 16/51; with gear 6 fixed,
    (0 − ω3)/(ω2 − ω3) = 16/51, so ω2 = −35/16 ω3: −2.1875 rad/s for ω3 = 1."""
    text = EX11_7.read_text(encoding="utf-8").replace("angle = 90", "angle = 90\nomega = 1")
    sol = graphkin.loads(text).solve()
    out = mechanism_train_text(sol)
    assert out is not None and "θ'_12/3 = 16/51" in out and "they agree" in out
    data = mechanism_train_json(sol)
    assert data is not None
    assert data["members"]["2"]["omega"] == pytest.approx(-35 / 16, rel=1e-12)
    assert data["members"]["4"]["omega"] == data["members"]["4'"]["omega"]


def test_what_is_not_a_train_is_one_line(tmp_path, capsys):
    assert main(["gears", str(ROOT / "examples" / "fourbar.toml")]) == 2
    assert "not a gear file" in capsys.readouterr().err
    assert main(["gears", str(EX11_7)]) == 2    # no omega
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "drive.omega" in err


def _planetary(sun: float, planet: float, drive: str, w: float, a: float, angle: float) -> str:
    ring = sun + 2 * planet
    c = sun + planet
    return f"""
title = "random planetary train"
[links.1]
O = [0, 0]
[links.2]
O = [0, 0]
P = [{c}, 0]
[links.3]
P = [{c}, 0]
[links.4]
O = [0, 0]
[[rolling]]
link = 3
on = 4
circle = {{ center = "P", radius = {planet} }}
on_circle = {{ center = "O", radius = {sun} }}
[[rolling]]
link = 3
on = 1
circle = {{ center = "P", radius = {planet} }}
on_circle = {{ center = "O", radius = {ring} }}
contact = "inside"
[drive]
link = {drive}
angle = {angle}
omega = {w}
alpha = {a}
"""


@SLOW
@given(st.floats(10, 80), st.floats(5, 40), st.sampled_from(["2", "4"]),
       st.floats(1, 20) | st.floats(-20, -1), st.floats(-5, 5), st.floats(-180, 180))
def test_random_planet_on_an_arm_round_a_driven_sun(sun, planet, drive, w, a, angle):
    """The sun (center the frame pivot O) or the arm driven, the ring fixed.

    Formula method by hand, Eq. (7.25) from the sun to the ring seen from the arm:
    θ'_ring,sun/arm = −R_s/R_r = (0 − ω_A)/(ω_s − ω_A), so ω_A = ω_s R_s/(R_s + R_r); the
    planet (ω_p − ω_A) = −(R_s/R_p)(ω_s − ω_A).  The rolling kinematics, the analytic solver,
    the train's mesh equations and the book's table must all give these."""
    mech = graphkin.loads(_planetary(sun, planet, drive, w, a, angle))
    sol = mech.solve()
    analytic_agrees(mech, sol)
    ring = sun + 2 * planet
    ratio = sun / (sun + ring)          # ω_A / ω_s
    w_sun = w if drive == "4" else w / ratio
    w_arm = w_sun * ratio
    w_planet = w_arm - sun / planet * (w_sun - w_arm)
    for lid, expect in (("2", w_arm), ("3", w_planet), ("4", w_sun)):
        assert float(sol.links[lid].omega) == pytest.approx(expect, rel=1e-9)
    train = train_of(mech, {drive: w})
    assert train is not None
    tab = tabular(train)
    assert tab is not None
    for lid, expect in (("2", w_arm), ("3", w_planet), ("4", w_sun), ("1", 0.0)):
        assert tab.omega[lid] == pytest.approx(expect, rel=1e-9, abs=1e-9 * abs(w_sun))
    data = mechanism_train_json(sol)
    assert data is not None
    big = max(abs(w_sun), abs(w_planet))
    assert all(abs(c["difference"]) <= 1e-9 * big for c in data["check"].values())


def _slider_rack(s: float, r: float, h: float, v: float, acc: float) -> str:
    return f"""
title = "pinion pinned to a driven slider, rolling on a rack pivoted at O4"
[links.1]
S0 = [0, 0]
S1 = [100, 0]
O4 = [0, {h}]
[links.2]
P = [{s}, 0]
[links.3]
P = [{s}, 0]
[links.4]
O4 = [0, {h}]
F1 = [0, {h}]
F2 = [100, {h}]
[[sliders]]
link = 2
on = 1
point = "P"
line = ["S0", "S1"]
[[rolling]]
link = 3
on = 4
circle = {{ center = "P", radius = {r} }}
line = ["F1", "F2"]
side = "right"
[drive]
link = 2
position = {s}
velocity = {v}
acceleration = {acc}
"""


@SLOW
@given(st.floats(30, 150), st.floats(5, 20), st.floats(0.3, 0.9), st.floats(-10, 10),
       st.floats(-3, 3))
def test_random_pinion_on_a_driven_slider_and_a_pivoted_rack(s, r, lift, v, acc):
    """The rack's line starts at its pivot O4 (F1 = O4), so v(F1) is at the pole.

    Geometry by hand: the rack stays tangent to the pinion, so the distance from the
    pinion's center P = (s, 0) to the rack's line through O4 = (0, h) is r, with h = r/lift
    (O4 outside the pinion).  Whatever the construction chooses to carry v(F2), the rates
    must be the analytic solver's, and a regular posture is no toggle."""
    h = r / lift
    mech = graphkin.loads(_slider_rack(s, r, h, v, acc))
    sol = mech.solve()
    assert not any("toggle" in n for n in sol.notes), sol.notes
    analytic_agrees(mech, sol)
    t4 = float(sol.links["4"].angle)
    u = (math.cos(t4), math.sin(t4))
    o4 = (0.0, h)
    dist = abs((s - o4[0]) * u[1] - (0.0 - o4[1]) * u[0])
    assert dist == pytest.approx(r, rel=1e-9)


@SLOW
@given(st.floats(-180, 180), st.floats(-179, 179), st.floats(-20, 20))
def test_random_15_45_pair_stands_at_the_files_angle(drive, angle, w):
    """The pinion (15 teeth, R = 15) as the rolling link, the gear (45, R = 45) placed by the
    contact: at the file's drive the gear stands at the file's ``angle`` (was −174.64°),
    and ω3 = −(15/45) ω2 (Eq. 7.5); the analytic solver agrees."""
    text = GEARS_15_45.read_text(encoding="utf-8")
    text = text.replace("angle = 30", f"angle = {drive}").replace(
        'omega = "10 rad/s"', f"omega = {w}").replace(
        'on_circle = { center = "O3", radius = 45 }',
        f'on_circle = {{ center = "O3", radius = 45 }}\nangle = {angle}')
    mech = graphkin.loads(text)
    sol = mech.solve()
    assert math.isclose(math.cos(math.radians(drive) - float(sol.links["2"].angle)), 1.0,
                        abs_tol=1e-12)
    d = math.radians(angle) - float(sol.links["3"].angle)
    assert math.isclose(math.cos(d), 1.0, abs_tol=1e-12)
    assert float(sol.links["3"].omega) == pytest.approx(-w / 3, rel=1e-12, abs=1e-12)
    analytic_agrees(mech, sol)


def test_solve_prints_the_train_of_a_planetary_mechanism(capsys):
    """`graphkin solve` of a planetary mechanism adds the book's table and formula method
    (the same numbers as `graphkin gears MECHFILE`, derived in the test above: ω2 = 10/3,
    ω3 = −10 rad/s), and a mechanism with no gears has no such section."""
    assert main(["solve", str(RING)]) == 0
    out = capsys.readouterr().out
    assert "Gear train (Secs. 7.15-7.16)" in out
    assert "2. Arm fixed           (20/80)(-40/20)ω4/2" in out and "they agree" in out
    assert main(["solve", str(RING), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)["gear_train"]
    assert data["members"]["2"]["omega"] == pytest.approx(10 / 3, rel=1e-12)
    assert data["members"]["3"]["omega"] == pytest.approx(-10.0, rel=1e-12)
    assert main(["solve", str(ROOT / "examples" / "fourbar.toml"), "--json"]) == 0
    assert "gear_train" not in json.loads(capsys.readouterr().out)


def test_solve_gives_the_train_in_the_reports_units(capsys):
    """`solve --units "mm, rev/min"` gives the train's ω in rev/min too, not rad/s (the
    links table already did): ω2 = 10/3 rad/s = (10/3)(60/2π) = 31.831 rev/min and the
    planet ω3 = −10 rad/s = −95.493 rev/min (hand derivation above)."""
    rpm = 60.0 / (2.0 * math.pi)
    assert main(["solve", str(RING), "--json", "--units", "mm, rev/min"]) == 0
    data = json.loads(capsys.readouterr().out)["gear_train"]
    assert data["unit"] == "rev/min"
    assert data["members"]["2"]["omega"] == pytest.approx(10 / 3 * rpm, rel=1e-12)
    assert data["members"]["3"]["omega"] == pytest.approx(-10.0 * rpm, rel=1e-12)
    assert all(c["difference"] == 0.0 for c in data["check"].values())
    assert main(["solve", str(RING), "--units", "mm, rev/min"]) == 0
    out = capsys.readouterr().out.split("Gear train (Secs. 7.15-7.16)")[1]
    assert "rad/s" not in out and "-95.493 rev/min" in out and "they agree" in out
