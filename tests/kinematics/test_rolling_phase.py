"""Rolling contact: the arrangements of issue 26, item 1, each checked by hand.

The mechanisms are in ``tests/data/rolling/``.  Every value below is derived in
the comment beside it (no slip, Eq. 3.13: the contact points have one
velocity; Eq. 4.19 for accelerations), and every solution is also held to the
analytic solver (loop closure, Secs. 3.9 and 4.9).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.kinematics.analytic import solve_analytic
from graphkin.kinematics.analytic.phase import rolling_phases

DATA = Path(__file__).resolve().parents[1] / "data" / "rolling"


def solve(name: str, **replace: str) -> graphkin.Solution:
    text = (DATA / name).read_text()
    for old, new in replace.items():
        assert old in text
        text = text.replace(old, new)
    mech = graphkin.loads(text)
    sol = mech.solve()
    assert sol.method == "construction", sol.notes
    assert not any("toggle" in n or "analytic" in n for n in sol.notes), sol.notes
    guess = {lid: (float(s.origin[0]), float(s.origin[1]), float(s.angle))
             for lid, s in sol.links.items() if lid != "1"}
    exact = solve_analytic(mech, guess=guess)
    for lid, s in sol.links.items():
        e = exact.links[lid]
        assert math.isclose(float(s.angle), float(e.angle), abs_tol=1e-9)
        assert math.isclose(float(s.omega), float(e.omega), rel_tol=1e-9, abs_tol=1e-9)
        assert math.isclose(float(s.alpha), float(e.alpha), rel_tol=1e-9, abs_tol=1e-9)
    return sol


def test_planet_between_a_driven_sun_and_a_fixed_ring() -> None:
    # was KeyError: 'rolling[0]:slot:O'.  The planet's center P moves at ω2·60; the planet
    # touches the fixed ring 20 beyond P (contact at rest) and the sun 20 before P, where the
    # sun's pitch point moves at ω4·40 = 400: so the planet turns about its ring contact,
    # 400 = ω3·(−40) → ω3 = −10, and V_P = ω3·(−20) = 200 = 60 ω2 → ω2 = 10/3 rad/s
    # (the book's formula method, Sec. 7.16: ω_arm = ω_sun R_s/(R_s + R_r) = 10·40/120).
    # The rates are linear in the input: α4 = 2 gives α3 = −2, α2 = 2/3.
    sol = solve("planet_arm_driven_sun_fixed_ring.toml")
    assert math.isclose(float(sol.links["2"].omega), 10 / 3)
    assert math.isclose(float(sol.links["3"].omega), -10.0)
    assert math.isclose(float(sol.links["2"].alpha), 2 / 3)
    assert math.isclose(float(sol.links["3"].alpha), -2.0)
    # at the file's drive (the sun at 30°) the arm and the planet stand as drawn
    assert abs(float(sol.links["2"].angle)) < 1e-12
    assert abs(float(sol.links["3"].angle)) < 1e-12
    assert [(p.link, p.kind) for p in rolling_phases(sol.mechanism)] == \
        [("3", "angle"), ("2", "angle")]


def test_pinion_on_a_driven_slider_rolling_on_a_pivoted_rack() -> None:
    # was "toggle or dead-center posture": the rack's line starts at its pivot (F1 at O4),
    # so v(F1) and v(O4) are both at the pole and cannot carry v(F2).  The posture is
    # regular: V_P = 5 along the slide, parallel to the rack, so the rack stays at rest
    # (ω4 = 0) and the pinion rolls on it: 5 = ω3 · 20, ω3 = 0.25 rad/s ccw.
    sol = solve("pinion_on_slider_pivoted_rack.toml")
    assert abs(float(sol.links["4"].omega)) < 1e-12
    assert math.isclose(float(sol.links["3"].omega), 0.25)
    assert sol.velocity("F2") == pytest.approx([0.0, 0.0], abs=1e-12)


@pytest.mark.parametrize(("angle", "expected"), [(None, 0.0), (10.0, 10.0), (-170.0, -170.0)])
def test_gear_stands_as_the_file_says(angle: float | None, expected: float) -> None:
    # was θ3 = −174.64° at the file's drive (and no posture at all at θ2 = 30°).  The pinion
    # is driven, so the contact places the gear: as drawn (0°) or at the file's `angle`;
    # the speed ratio is 15/45: ω3 = −10/3 rad/s.
    replace = {} if angle is None else {
        'on_circle = { center = "O3", radius = 45 }':
            f'on_circle = {{ center = "O3", radius = 45 }}\nangle = {angle}'}
    sol = solve("gears_15_45.toml", **replace)
    assert math.isclose(math.degrees(float(sol.links["2"].angle)), 30.0)
    assert math.isclose(math.degrees(float(sol.links["3"].angle)), expected, abs_tol=1e-9)
    assert math.isclose(float(sol.links["3"].omega), -10 / 3)
    drawn = "" if angle is not None else " (as drawn)"
    assert f"rolling[0]: at the file's drive the contact places link 3 at θ3 = " \
           f"{expected:g}°{drawn}" in sol.notes


def test_rack_sliding_under_a_driven_pinion() -> None:
    # the rack keeps its distance from the pinion's fixed center by its slider alone (no
    # equivalent slot: Kutzbach's count was one short).  Pinion ccw at 10 rad/s, α = 2,
    # radius 20, the rack below: V_rack = ω r = 200 along +x, A_rack = α r = 40.
    sol = solve("rack_under_driven_pinion.toml")
    assert sol.velocity("R") == pytest.approx([200.0, 0.0])
    assert sol.acceleration("R") == pytest.approx([40.0, 0.0])
    # at the file's drive the rack stands as drawn (its origin on the frame's)
    assert sol.position("R") == pytest.approx([0.0, -30.0])


def test_driven_rack_turns_a_pinion() -> None:
    # the rack moves at 10 (+x) under the pinion (radius 20): 10 = 20 ω2, ω2 = 0.5 ccw
    sol = solve("driven_rack_turns_pinion.toml")
    assert math.isclose(float(sol.links["2"].omega), 0.5)
    assert math.isclose(float(sol.links["2"].alpha), 0.1)


def test_internal_gears_on_fixed_centers() -> None:
    # a pinion (r = 20) inside a ring (R = 40), both on fixed pivots: the pitch points move
    # together, 20 ω2 = 40 ω3, the same sense: ω3 = 5, α3 = 1
    sol = solve("internal_gears_fixed_centers.toml")
    assert math.isclose(float(sol.links["3"].omega), 5.0)
    assert math.isclose(float(sol.links["3"].alpha), 1.0)


def test_wheel_on_a_carriage() -> None:
    # the carriage keeps the wheel's center 20 above the ground: V = 10 → ω3 = −10/20
    sol = solve("wheel_on_carriage.toml")
    assert math.isclose(float(sol.links["3"].omega), -0.5)
    assert math.isclose(float(sol.links["3"].alpha), -0.1)


def test_a_carriage_that_does_not_hold_the_wheel_on_the_ground() -> None:
    text = (DATA / "wheel_on_carriage.toml").read_text().replace("radius = 20", "radius = 25")
    with pytest.raises(graphkin.GraphkinError, match=r"keeps the center P 20 to the left of "
                       r"the line; rolling on its left needs 25") as info:
        graphkin.loads(text)
    assert getattr(info.value, "key", None) == "rolling[0].circle.radius"


def test_drive_relative_to_a_rolling_planet() -> None:
    # was StopIteration.  θ3/2 = 30°, ω3/2 = 10: the planet (r = 20) round the fixed sun
    # (R = 40) turns (R + r)/r = 3 times as fast as its arm, ω3 = 3 ω2, so ω3 − ω2 = 2 ω2 = 10:
    # ω2 = 5, ω3 = 15 rad/s.  The contact places the planet as drawn (θ3 = 0), the arm at −30°.
    mech = graphkin.load(DATA / "planet_driven_relative_to_arm.toml")
    sol = mech.solve()
    assert math.isclose(float(sol.links["2"].omega), 5.0)
    assert math.isclose(float(sol.links["3"].omega), 15.0)
    assert math.isclose(math.degrees(float(sol.links["2"].angle)), -30.0)
    sw = mech.sweep(count=5)  # over the cycle: Δθ2 = Δθ3/2 / 2, Δθ3 = 3 Δθ2
    th2, th3 = sw.columns["angle_2"], sw.columns["angle_3"]
    assert np.allclose(np.diff(np.unwrap(np.radians(th2))), math.radians(72 / 2))
    assert np.allclose(np.diff(np.unwrap(np.radians(th3))), math.radians(3 * 72 / 2))


@pytest.mark.parametrize("name", ["spur_gears.toml", "rolling_wheel_loaded.toml"])
def test_torque_over_a_sweep_of_a_rolling_mechanism(name: str) -> None:
    # was TypeError: hypot() over the sweep's arrays; each row's torque is the torque of the
    # posture solved alone (Sec. 11.11)
    from graphkin.forces import solve_forces
    from graphkin.forces.sweep import force_columns

    mech = graphkin.load(Path(__file__).resolve().parents[1] / "forces" / "data" / name)
    sw = mech.sweep(count=6, stop=math.degrees(mech.drives[0].value) + 30.0)
    cols = force_columns(sw, joints=False)
    alone = solve_forces(mech.solve())
    assert math.isclose(float(cols["torque_2"][0]), alone.torque(2), rel_tol=1e-9)
    assert np.all(np.isfinite(cols["torque_2"]))


@pytest.mark.parametrize("shift", [0.0, 1e-12, 1e-13, -1e-14])
def test_only_a_real_toggle_is_called_one(shift: float) -> None:
    # Example 3.9 with the crank at −asin(50/150): A = (141.42, −50), B = (141.42, 150) and the
    # contact C = (141.42, 0) in line; V_B ⊥ CB and V_B − V_A ⊥ AB are both horizontal while
    # V_A has the vertical component 141.42 ω2: the wheel cannot move, a dead point.  The
    # verdict does not move when the drive moves by a little of itself.  (Toward the
    # assembled side, 1e-12 of the drive puts B's two branches √(2·200·3e-11) ≈ 1e-4 apart and
    # the polygon's lines 5e-7 from parallel: the general toggle threshold, SINGULAR_SINE =
    # 1e-7 in solve.py, then calls it regular; not a question of rolling contact.)
    text = (DATA / "wheel_dead_point.toml").read_text()
    a = -19.47122063449069
    sol = graphkin.loads(text.replace(f"angle = {a}", f"angle = {a * (1 + shift)!r}")).solve()
    assert any("toggle or dead-center" in n for n in sol.notes), sol.notes
    assert not sol.has_rates


@pytest.mark.parametrize("shift", [1e-12, -1e-12])
def test_coincident_images_are_no_toggle_when_moved_a_little(shift: float) -> None:
    # the rack's line starting 1e-12 of the size away from its pivot: still a regular posture
    text = (DATA / "pinion_on_slider_pivoted_rack.toml").read_text()
    text = text.replace("F1 = [0, 20]", f"F1 = [{100 * shift!r}, {20 + 100 * shift!r}]")
    sol = graphkin.loads(text).solve()
    assert not any("toggle" in n for n in sol.notes), sol.notes
    assert math.isclose(float(sol.links["3"].omega), 0.25)


def test_sweeps_start_where_the_file_stands() -> None:
    # the gear stands as drawn at the file's drive (θ2 = 30°) and turns back a third as far:
    # θ3 = −(θ2 − 30°)/3; the planetary's arm turns a third as far as its sun (10/3 of 10)
    mech = graphkin.load(DATA / "gears_15_45.toml")
    sw = mech.sweep(count=5)
    th2 = np.unwrap(np.radians(sw.columns["angle_2"]))
    th3 = np.unwrap(np.radians(sw.columns["angle_3"]))
    assert np.allclose(th3, -(th2 - math.radians(30)) / 3, atol=1e-9)
    mech = graphkin.load(DATA / "planet_arm_driven_sun_fixed_ring.toml")
    sw = mech.sweep(count=5)
    th4 = np.unwrap(np.radians(sw.columns["angle_4"]))
    th2 = np.unwrap(np.radians(sw.columns["angle_2"]))
    assert np.allclose(th2, (th4 - math.radians(30)) / 3, atol=1e-9)


@pytest.mark.parametrize(("name", "why"), [
    ("planet_driven_relative_to_arm.toml", "the rates are the analytic solver's"),
    ("wheel_dead_point.toml", "the posture is a toggle or dead center")])
def test_why_no_velocity_polygon(name: str, why: str, tmp_path: Path,
                                 capsys: pytest.CaptureFixture[str]) -> None:
    from graphkin.cli import main

    assert main(["draw", str(DATA / name), "-d", "velocity", "-o",
                 str(tmp_path / "v.svg")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and why in err, err
    # the posture is still the construction's, and is drawn
    assert main(["draw", str(DATA / name), "-d", "posture", "-o",
                 str(tmp_path / "p.svg")]) == 0


def test_an_angle_for_a_contact_that_places_a_travel_is_refused() -> None:
    # the driven pinion fixes its own angle and the rack cannot turn: this contact places the
    # rack's travel, so an `angle` would be silently ignored
    text = (DATA / "rack_under_driven_pinion.toml").read_text().replace(
        'side = "left"', 'side = "left"\nangle = 10')
    with pytest.raises(graphkin.GraphkinError, match="places the slider 3 by its travel") as e:
        graphkin.loads(text).solve()
    assert getattr(e.value, "key", None) == "rolling[0].angle"


@pytest.mark.parametrize("json", [False, True])
def test_solve_at_a_dead_point_reports_the_posture(json: bool,
                                                   capsys: pytest.CaptureFixture[str]) -> None:
    # Example 3.9 at its dead point (above): no rates, so no gear-train section to set beside
    # them; `solve` printed "cannot handle this input: TypeError" from the train's check
    from graphkin.cli import main

    assert main(["solve", str(DATA / "wheel_dead_point.toml"), *(["--json"] if json else [])]) == 0
    out = capsys.readouterr().out
    assert "toggle or dead-center" in out
    assert "R_B = (141.421, 150) mm" in out or json
