"""A disk cam as a joint of a mechanism file (``[[cams]]``, Sec. 4.7 and Ch. 6).

The oracle is the cam's own program, differentiated by hand: the cam turns at
dΘ/dt = s·ω2 (s = +1 counterclockwise), so the follower's velocity is
y'(Θ)·dΘ/dt and its acceleration y''(Θ)·(dΘ/dt)² + y'(Θ)·d²Θ/dt² (Eqs. 6.9-6.11;
for an oscillating follower the arm turns σ times these, σ = +1 when it rises
counterclockwise).  Nothing here reads graphkin's construction code.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
from cam_strategies import cam_toml, cams
from hypothesis import given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.cams import Cam
from graphkin.errors import GraphkinError, InputError
from graphkin.forces import solve_forces
from graphkin.kinematics.instant_centers.kennedy import instant_centers
from graphkin.mechanisms import from_dict

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "cams"
_TMP = Path(tempfile.mkdtemp(prefix="graphkin-cam-joint-"))


def _mechanism(cam_file: Path | str, theta2_deg: float, omega: float, alpha: float,
               axis: float = 90.0, units: str = "mm") -> graphkin.Mechanism:
    return from_dict({"units": units, "links": {"1": {"O2": [3.0, -2.0]}},
                      "cams": {"link": 2, "follower": 4, "file": str(cam_file), "axis": axis},
                      "drive": {"link": 2, "angle": theta2_deg, "omega": omega,
                                "alpha": alpha}})


def _expected(cam: Cam, theta: float, omega: float, alpha: float) -> tuple[float, float]:
    """(velocity, acceleration) of the follower from the program, differentiated by hand."""
    k = cam.program.evaluate([theta])
    dth, ddth = cam.s * omega, cam.s * alpha
    return float(k.y1[0] * dth), float(k.y2[0] * dth**2 + k.y1[0] * ddth)


def _check(mech: graphkin.Mechanism, cam: Cam, omega: float, alpha: float,
           axis: float, scale: float = 1.0) -> None:
    joint = mech.cams[0]
    sol = mech.solve()
    v, a = _expected(cam, joint.theta, omega, alpha)
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    if f.kind.oscillating:
        sig = f.rise.sign
        w4, a4 = sig * v, sig * a
        big = max(1.0, abs(w4) ** 2, abs(omega) ** 2, abs(alpha))
        assert abs(float(sol.omega("4")) - w4) < 1e-7 * max(1.0, abs(omega))
        assert abs(float(sol.alpha("4")) - a4) < 1e-6 * big
        return
    d = np.array([math.cos(math.radians(axis)), math.sin(math.radians(axis))])
    vt, at = np.asarray(sol.velocity("T4")), np.asarray(sol.acceleration("T4"))
    tol = 1e-7 * size * scale * max(1.0, abs(omega) ** 2, abs(alpha))
    assert abs(float(vt @ d) - v * scale) < tol
    assert abs(float(vt[0] * d[1] - vt[1] * d[0])) < tol      # along the guide only
    assert abs(float(at @ d) - a * scale) < tol


def test_example_6_6_in_a_mechanism_at_30_degrees():
    """Ex 6.6 at Θ = 30° (Y = 15(1 − cos 2Θ) mm): y' = 30 sin 60° = 25.981 mm/rad,
    y'' = 60 cos 60° = 30 mm/rad²; at ω2 = 10 rad/s, α2 = 5 rad/s²: V = 259.81 mm/s,
    A = 3000 + 129.90 = 3129.90 mm/s² (the book's Eqs. 2a-2b of Ex 6.6)."""
    m = _mechanism(EXAMPLES / "ex6_6_roller.toml", 30.0, 10.0, 5.0)
    sol = m.solve()
    v, a = sol.velocity("T4"), sol.acceleration("T4")
    assert abs(v[1] - 259.8076211) < 1e-6 and abs(v[0]) < 1e-9
    assert abs(a[1] - 3129.9038106) < 1e-6
    j = m.cams[0]
    assert abs(math.degrees(j.pressure) - 28.68) < 0.005          # Ex 6.6 (c)
    # the instant center of cam and follower: on the common normal, y' from O2 along the
    # normal to the follower's motion (Sec. 6.10, Fig. 6.27): (3 + 25.981, -2)
    p = instant_centers(sol).center(2, 4).xy
    assert abs(p[0] - (3 + 25.98076211)) < 1e-6 and abs(p[1] + 2) < 1e-6


def test_example_6_7_in_a_mechanism_at_45_degrees():
    """Ex 6.7 at Θ = 45°: θ4' = −1 rad/rad (harmonic, 1 rad in 90°: (π/2)(1/(π/2)) sin 90°,
    the arm rising clockwise), θ4'' = 0: ω4 = −ω2 and α4 = −α2."""
    m = _mechanism(EXAMPLES / "ex6_7_oscillating.toml", 45.0, 10.0, 3.0, axis=90.0)
    sol = m.solve()
    assert abs(float(sol.omega("4")) + 10.0) < 1e-9
    assert abs(float(sol.alpha("4")) + 3.0) < 1e-7


CIRCLE = """
# Ex 4.7's circular cam (radius R = 1.5 + 1 = 2.5 in, its center B e = 1 in from O2) under a
# radial flat face: the face's height R + e sin θB = R0 + e(1 - cos Θ) is harmonic motion
units = "in"
[cam]
prime = 1.5
[follower]
kind = "flat-face"
face = 6
[[segment]]
motion = "harmonic"
lift = 2
angle = 180
[[segment]]
motion = "harmonic"
lift = -2
angle = 180
"""


@pytest.mark.parametrize("theta2", [0.0, 45.572996483, 100.0, 200.0, 300.0])
def test_the_circular_cam_is_example_4_7s_pin_in_slot(theta2, tmp_path):
    """The circular cam (Sec. 4.7, Ex 4.7; an eccentric, Sec. 6.12) as ``[[cams]]``.

    By hand: B = e(cos θB, sin θB), θB = θ2 − 90° (the low point under the face at Θ = 0);
    the face (and the follower) stands at R + e sin θB, so it moves with
    V = e ω cos θB, A = −e ω² sin θB + e α cos θB; the profile's radius of curvature is R
    everywhere (Eq. 6.27: R0 + Y + y'' = 1.5 + 1 = 2.5), so the center of curvature is B
    itself: the equivalent linkage is Example 4.7's pin-in-slot (Fig. 4.18c).
    """
    path = tmp_path / "circle.toml"
    path.write_text(CIRCLE)
    omega, alpha, e = -10.0, -25.0, 1.0            # Ex 4.7: 10 rad/s cw, 25 rad/s² cw
    m = from_dict({"units": "in", "links": {"1": {"O2": [0.0, 0.0]}},
                   "cams": {"link": 2, "follower": 3, "file": str(path)},
                   "drive": {"link": 2, "angle": theta2, "omega": omega, "alpha": alpha}})
    sol = m.solve()
    tb = math.radians(theta2 - 90.0)
    k = sol.position("K3")
    assert abs(k[0] - e * math.cos(tb)) < 1e-9 and abs(k[1] - e * math.sin(tb)) < 1e-9
    assert abs(sol.velocity("T3")[1] - e * omega * math.cos(tb)) < 1e-8
    assert abs(sol.acceleration("T3")[1] - (-e * omega**2 * math.sin(tb) +
                                            e * alpha * math.cos(tb))) < 1e-7


@settings(max_examples=30, deadline=None)
@given(cams(), st.floats(0.0, 360.0, exclude_max=True), st.floats(-20.0, 20.0),
       st.floats(-50.0, 50.0), st.sampled_from([90.0, 0.0, 210.0]))
def test_random_cam_mechanisms_agree_with_the_program(cam, theta2, omega, alpha, axis):
    """Any cam, any follower kind, any cam angle, any rates, the cam file turned anywhere:
    the follower's velocity and acceleration are the program's y'Θ̇ and y''Θ̇² + y'Θ̈."""
    path = _TMP / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam))
    theta = cam.s * math.radians(theta2 - (axis - 90.0))
    prof = graphkin.cams.profile(cam, [theta])
    if not np.isfinite(prof.contact[0]):
        return                   # the follower cannot follow here (said by the design checks)
    try:
        mech = _mechanism(path, theta2, omega, alpha, axis)
    except InputError as exc:    # a straight piece of surface, or a coupler too short to build
        assert "straight" in str(exc) or "range" in str(exc) or "short" in str(exc) or \
            "longest" in str(exc), str(exc)
        return
    try:
        _check(mech, cam, omega, alpha, axis)
    except GraphkinError as exc:
        pytest.fail(f"the cam mechanism did not solve: {exc}")


def test_the_cam_file_s_unit_is_converted():
    """Ex 6.6 (mm) in a mechanism in inches: T4 is 47.5 mm = 1.8701 in above O2 at Θ = 30°."""
    m = _mechanism(EXAMPLES / "ex6_6_roller.toml", 30.0, 10.0, 0.0, units="in")
    sol = m.solve()
    assert abs(sol.position("T4")[1] - (-2.0 + 47.5 / 25.4)) < 1e-9
    assert abs(sol.velocity("T4")[1] - 259.8076211 / 25.4) < 1e-6


def test_the_follower_drives_the_rest_of_the_mechanism():
    """A rod from the follower (Ex 6.6) to a slider: its velocity by hand.

    Follower point P = T4 + (30 along the rise) = (3, 75.5); rod P-Q 80 mm, Q on the
    horizontal line y = 78 - ...: with the slider's line through P's height + 2.5 the rod's
    angle is asin(2.5/80); V_Q follows from V_P (vertical, 259.81) and the rod:
    V_Q = V_P tan(φ), φ = asin(2.5/80) (the rod nearly horizontal).
    """
    data = {"units": "mm", "links": {"1": {"O2": [0, 0]}, "4": {"P": [30.0, 0.0]},
                                     "6": {"P": [0, 0], "Q": [80.0, 0]}, "7": {"Q": [0, 0]}},
            "sliders": [{"link": 7, "on": 1, "point": "Q", "line": [[0, 80.0], [100, 80.0]]}],
            "cams": {"link": 2, "follower": 4, "file": str(EXAMPLES / "ex6_6_roller.toml")},
            "drive": {"link": 2, "angle": 30, "omega": 10}, "assembly": {"Q": [100, 80]}}
    sol = from_dict(data).solve()
    # P is 30 mm above T4 (47.5): at 77.5, 2.5 below the slider's line y = 80
    assert abs(sol.position("P")[1] - 77.5) < 1e-9
    phi = math.asin(2.5 / 80.0)
    assert abs(sol.velocity("Q")[0] - 259.8076211 * math.tan(phi)) < 1e-6


@pytest.mark.parametrize("patch, key, words", [
    ({"cams": {"link": 2, "follower": 4}}, "cams[0].file", "missing"),
    ({"cams": {"link": 2, "follower": 2, "file": "x"}}, "cams[0].follower", "another link"),
    ({"cams": {"link": 2, "follower": 4, "file": "nope.toml"}}, "cams[0].file", "no cam file"),
    ({"cams": {"link": 2, "follower": 4, "file": "EX", "centre": "O2"}}, "centre",
     "did you mean 'center'"),
    ({"cams": {"link": 2, "follower": 4, "file": "EX", "center": "Z"}}, "cams[0].center",
     "no point"),
    ({"cams": {"link": 3, "follower": 4, "file": "EX"}}, "cams[0].link", "must be the drive"),
    ({"cams": {"link": 2, "follower": 4, "file": "EX", "guide_friction": 0.1},
      "links": {"1": {"O2": [0, 0]}, "4": {"T4": [1.0, 0.0]}}}, "links.4.T4", "rename yours"),
])
def test_bad_cam_entries_are_one_line_naming_the_key(patch, key, words):
    data = {"units": "mm", "links": {"1": {"O2": [0, 0]}},
            "drive": {"link": 2, "angle": 30, "omega": 10}}
    data.update(patch)
    if data["cams"].get("file") == "EX":
        data["cams"] = {**data["cams"], "file": str(EXAMPLES / "ex6_6_roller.toml")}
    with pytest.raises(InputError) as err:
        from_dict(data, source="m.toml")
    line = err.value.one_line()
    assert "\n" not in line and key in line and words in line, line


def test_an_oscillating_follower_has_no_guide_friction():
    data = {"links": {"1": {"O2": [0, 0]}},
            "cams": {"link": 2, "follower": 4, "file": str(EXAMPLES / "ex6_7_oscillating.toml"),
                     "guide_friction": 0.1},
            "drive": {"link": 2, "angle": 30, "omega": 10}}
    with pytest.raises(InputError, match="no guide"):
        from_dict(data, source="m.toml")


def test_the_contact_force_is_along_the_common_normal():
    """A load on the follower (Ex 6.6, 20 N down at T4): the coupler through the centers of
    curvature is a two-force member, so the cam's force on the roller acts along the common
    normal, which leans the pressure angle φ = 28.68° from the follower's motion (Ex 6.6 (c));
    the cam's torque is 20 N · y' = 20 · 25.981 = 519.6 N·mm (virtual work)."""
    data = {"units": {"length": "mm", "force": "N"}, "links": {"1": {"O2": [0, 0]}},
            "cams": {"link": 2, "follower": 4, "file": str(EXAMPLES / "ex6_6_roller.toml")},
            "drive": {"link": 2, "angle": 30},
            "loads": [{"link": 4, "point": "T4", "force": "20 N at -90 deg"}]}
    m = from_dict(data)
    fa = solve_forces(m.solve())
    f = np.asarray(fa.force("4", m.cams[0].coupler))[:2]
    lean = math.degrees(math.atan2(abs(f[0]), abs(f[1])))
    assert abs(lean - 28.68) < 0.01
    assert abs(abs(fa.torque("2")) - 20 * 25.98076211) < 1e-6


def test_the_shipped_cam_mechanism_solves_by_the_constructions():
    """examples/cams/cam_mechanism.toml (docs/formats/mechanism.md#cams): V_T4 = y'ω."""
    sol = graphkin.load(EXAMPLES / "cam_mechanism.toml").solve()
    assert sol.method == "construction"
    assert abs(sol.velocity("T4")[1] - 259.8076211) < 1e-6


def test_the_report_says_what_the_linkage_stands_for():
    """solve --json "cams": Ex 6.6 at Θ = 30° with ω2 = 10, α2 = 5 (the hand values of
    test_example_6_6_in_a_mechanism_at_30_degrees), and the contact (23.473, 29.139) of the
    cam's frame turned 30° into the frame: (5.758, 36.972)."""
    from graphkin.output import solution_to_dict

    sol = _mechanism(EXAMPLES / "ex6_6_roller.toml", 30.0, 10.0, 5.0).solve()
    c = solution_to_dict(sol)["cams"][0]
    assert abs(c["theta"] - 30) < 1e-9 and abs(c["lift"] - 7.5) < 1e-9
    assert abs(c["follower_rate"] - 259.8076211) < 1e-6
    assert abs(c["follower_rate2"] - 3129.9038106) < 1e-6
    u, v, t = 23.4729, 29.1394, math.radians(30)
    assert abs(c["contact"][0] - (3 + u * math.cos(t) - v * math.sin(t))) < 1e-3
    assert abs(c["contact"][1] - (-2 + u * math.sin(t) + v * math.cos(t))) < 1e-3
    assert abs(c["pressure_angle"] - 28.677) < 1e-3 and abs(c["normal"] + 61.323) < 1e-3


def test_live_of_a_cam_mechanism_turns_the_cam(tmp_path, capsys):
    """The live page turns a roller follower's cam: the equivalent linkage rebuilt at every
    angle from the cam's own operations (render/live_cam_turn.py; tests/render/
    test_live_cam_turn.py drags it); nothing is said of a hold."""
    import json
    import re

    from graphkin.cli import main

    f = str(EXAMPLES / "cam_mechanism.toml")
    out = tmp_path / "live.html"
    assert main(["live", f, "-o", str(out)]) == 0
    text = out.read_text(encoding="utf-8")
    m = re.search(r'<script id="gk-data" type="application/json">\n(.*?)</script>', text, re.S)
    assert m is not None
    data = json.loads(m.group(1))
    assert data["cam"]["why"] == "" and [c["key"] for c in data["turn"]["cams"]] == ["cams[0]"]
    assert data["drive"]["tip"] == "C4"        # the cam is dragged by its contact point
