"""The cam's operations of the one table (construction/ops/cam_program.py) in both languages.

``cam_program`` and ``cam_center`` are templates written out as Python
(``codegen.generate``) and JavaScript (``jsgen.generate_js``); the live page
turns a cam with them (render/live_cam_turn.py).  Held here, for random cams
of every knife-edge and roller kind (tests/cam_strategies.py) at random cam
link angles, to answers that share no code with them:

* the program's ``Y, y', y''`` to ``Program.evaluate`` (cams/motions.py, the
  book's Eqs. 6.12-6.25 written once more, as numpy functions);
* the center of curvature, ``|ρ|``, the trace point and the contact to
  ``cams/analytic.profile`` (complex numbers, Eqs. 6.36-6.37) and
  ``cams/equivalent.equivalent_linkage`` (what ``graphkin solve`` builds);
* the JavaScript (node, else headless Chromium) to the Python, to 1e-9.

And: a straight pitch curve (ρ infinite) has no center in either language, as
``equivalent_linkage`` refuses it; the kinds the operations do not express are
refused with the reason.
"""

from __future__ import annotations

import cmath
import json
import math
from pathlib import Path

import numpy as np
import pytest
from cam_strategies import cam_toml, cams
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from live_cams_shared import straight_angle

from graphkin.cams import Cam, FollowerKind, Motion
from graphkin.cams.analytic import profile
from graphkin.cams.equivalent import equivalent_linkage
from graphkin.cams.examples import example_6_6
from graphkin.cams.turning import TurnSteps, turn_steps
from graphkin.construction.codegen import generate
from graphkin.construction.jsgen import RUNTIME, generate_js
from graphkin.errors import InputError
from graphkin.mechanisms import from_dict

REL = 1e-9
KINDS = [k for k in FollowerKind if not k.flat]


@pytest.fixture(scope="module", autouse=True)
def _js():
    js_or_skip()
    yield
    close()


def _joint(cam: Cam, tmp: Path, axis: float, o2: tuple[float, float], theta2: float):
    path = tmp / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam), encoding="utf-8")
    return from_dict({"units": "mm", "links": {"1": {"O2": list(o2)}},
                      "cams": {"link": 2, "follower": 4, "file": str(path), "axis": axis},
                      "drive": {"link": 2, "angle": theta2}}).cams[0]


def _python(t: TurnSteps, th2: np.ndarray) -> dict[str, np.ndarray] | None:
    req = [(t.theta, "value"), (t.lift, "value"), ("y'4", "value"), ("y''4", "value"),
           (t.center, "x"), (t.center, "y"), (t.length, "value"), (t.trace, "x"),
           (t.trace, "y"), (t.contact, "x"), (t.contact, "y"), (t.rho, "value")]
    fn = generate(t.steps, varying=["θ2"], requests=req)
    got = fn.fn(th2)
    if got is None:
        return None
    return {f"{lab}.{part}": np.broadcast_to(np.asarray(v, dtype=float), th2.shape)
            for (lab, part), v in zip(req, got)}


def _javascript(t: TurnSteps, th2: np.ndarray) -> list:
    fn = generate_js(t.steps, requests=[t.theta, t.lift, "y'4", "y''4", t.center, t.length,
                                        t.trace, t.contact, t.rho], name="cam")
    cases = [{"θ2": float(x)} for x in th2]
    return run_js(RUNTIME + fn.source + f"\nconst K = {json.dumps(fn.values)};\n"
                  f"const RESULT = {json.dumps(cases)}.map((I) => cam(I, K));")


def _off_the_joints(cam: Cam, theta: np.ndarray) -> bool:
    """No angle within 1e-7 rad of a segment's boundary (where y'' may jump)."""
    th = np.mod(theta, 2 * math.pi)
    b = np.concatenate([cam.program.starts, [2 * math.pi]])
    return bool(np.all(np.abs(th[:, None] - b[None, :]).min(axis=1) > 1e-7))


def _close(got, ref, scale: float, lab: str) -> None:
    np.testing.assert_allclose(np.asarray(got, dtype=float), np.asarray(ref, dtype=float),
                               rtol=REL, atol=REL * scale, err_msg=lab)


def _supported(cam: Cam) -> bool:
    return all(s.motion is not Motion.TABLE for s in cam.program.segments)


@settings(max_examples=40, deadline=None)
@given(cam=cams(kinds=KINDS), axis=st.floats(-180.0, 180.0),
       o2=st.tuples(st.floats(-50.0, 50.0), st.floats(-50.0, 50.0)),
       theta2=st.lists(st.floats(-720.0, 720.0), min_size=1, max_size=12))
def test_both_languages_equal_the_analytic_cam(tmp_path_factory, cam, axis, o2, theta2) -> None:
    assume(_supported(cam))
    j = _joint(cam, tmp_path_factory.getbasetemp(), axis, o2, 0.0)
    t = turn_steps(j, "θ2")
    th2 = np.radians(np.asarray(theta2))
    theta = cam.s * (th2 - (j.axis - math.pi / 2))
    assume(_off_the_joints(cam, theta))
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    # the program: Program.evaluate (cams/motions.py), Eqs. 6.12-6.25
    k = cam.program.evaluate(theta)
    pr = profile(cam, theta)
    assert pr.rho_pitch is not None and pr.pitch is not None
    assume(bool(np.all(np.abs(pr.rho_pitch) < 1e5 * size)))   # no straight pitch curve here
    py = _python(t, th2)
    assert py is not None
    lift = 1.0 + float(np.abs(k.Y).max())
    _close(py[f"{t.theta}.value"], k.theta, 2 * math.pi, "Θ")
    for lab, ref in (("Y4", k.Y), ("y'4", k.y1), ("y''4", k.y2)):
        _close(py[f"{lab}.value"], ref, lift + float(np.abs(ref).max()), lab)
    # the equivalent linkage solve builds at each angle (cams/equivalent.py)
    rot = cmath.exp(1j * (j.axis - math.pi / 2))
    o = complex(*o2)
    for i, th in enumerate(theta):
        eq = equivalent_linkage(cam, float(th))
        rho = abs(float(pr.rho_pitch[i]))
        reach = size + rho
        _close([py["K4.x"][i], py["K4.y"][i]], np.multiply(eq["links"]["2"]["K"], j.scale),
               reach, "K4")
        _close(py["|ρ|4.value"][i], eq["links"]["3"]["T"][0] * j.scale, reach, "|ρ|")
        tt = o + rot * complex(*eq["assembly"]["T"]) * j.scale
        _close([py["T4.x"][i], py["T4.y"][i]], [tt.real, tt.imag], size, "T4")
        c = o + rot * cmath.exp(1j * cam.s * k.theta[i]) * complex(pr.contact[i]) * j.scale
        _close([py["C4.x"][i], py["C4.y"][i]], [c.real, c.imag], size, "C4")
        _close(py["ρ4.value"][i], pr.rho_pitch[i], reach, "ρ")
    # the JavaScript: the same template, JavaScript's numbers
    js = _javascript(t, th2)
    for i, v in enumerate(js):
        _close(v["Θ4"], py[f"{t.theta}.value"][i], 2 * math.pi, "Θ (js)")
        for lab in ("Y4", "y'4", "y''4", "|ρ|4", "ρ4"):
            ref = py[f"{lab}.value"][i]
            _close(v[lab], ref, lift + abs(float(ref)), f"{lab} (js)")
        for lab in ("K4", "T4", "C4"):
            ref = [py[f"{lab}.x"][i], py[f"{lab}.y"][i]]
            _close(v[lab], ref, size + float(np.abs(ref).max()), f"{lab} (js)")


def test_a_straight_pitch_curve_has_no_center() -> None:
    cam = example_6_6()
    th = straight_angle()
    with pytest.raises(InputError, match="straight"):
        equivalent_linkage(cam, th)
    j = from_dict({"links": {"1": {"O2": [0, 0]}},
                   "cams": {"link": 2, "follower": 4,
                            "file": "examples/cams/ex6_6_roller.toml"},
                   "drive": {"link": 2, "angle": 30}}).cams[0]
    t = turn_steps(j, "θ2")       # axis 90°: θ2 = Θ
    assert _python(t, np.array([th])) is None
    assert _javascript(t, np.array([th])) == [None]
    # a degree away the center is back, in both
    assert _python(t, np.array([th + 0.02])) is not None
    assert _javascript(t, np.array([th + 0.02]))[0] is not None


def test_a_table_segment_is_its_spline(tmp_path) -> None:
    # Ex 6.6's first rise given as a table of displacements (a natural cubic spline through
    # them, cams/motions.table_shape): cam_program's Y, y', y'' are Program.evaluate's at
    # angles inside each interval, on the knots and in the other segments, in both languages
    src = Path("examples/cams/ex6_6_roller.toml").read_text(encoding="utf-8")
    table = src.replace('motion = "harmonic"\nlift = 30\nangle = 90',
                        'motion = "table"\nangle = 90\npoints = [[0, 0], [20, 4], [45, 20], '
                        '[70, 27], [90, 30]]', 1)
    assert table != src
    (tmp_path / "table.toml").write_text(table, encoding="utf-8")
    j = from_dict({"links": {"1": {"O2": [0, 0]}},
                   "cams": {"link": 2, "follower": 4, "file": str(tmp_path / "table.toml")},
                   "drive": {"link": 2, "angle": 30}}).cams[0]
    t = turn_steps(j, "θ2")          # axis 90°, counterclockwise: θ2 = Θ
    deg = np.array([0.0, 7.0, 20.0, 33.3, 45.0, 61.0, 70.0, 89.9, 90.0, 133.0, 271.0, 359.0])
    th2 = np.radians(deg)
    k = j.cam.program.evaluate(th2)
    py = _python(t, th2)
    assert py is not None
    for lab, ref in (("Y4", k.Y), ("y'4", k.y1), ("y''4", k.y2)):
        _close(py[f"{lab}.value"], ref, 30.0 + float(np.abs(ref).max()), lab)
    for i, v in enumerate(_javascript(t, th2)):
        for lab in ("Y4", "y'4", "y''4"):
            ref = py[f"{lab}.value"][i]
            _close(v[lab], ref, 30.0 + abs(float(ref)), f"{lab} (js)")


@settings(max_examples=30, deadline=None)
@given(cam=cams(kinds=(FollowerKind.FLAT_FACE,)), axis=st.floats(-180.0, 180.0),
       o2=st.tuples(st.floats(-50.0, 50.0), st.floats(-50.0, 50.0)),
       theta2=st.lists(st.floats(-720.0, 720.0), min_size=1, max_size=8))
def test_a_translating_flat_face_equals_its_linkage(tmp_path_factory, cam, axis, o2,
                                                    theta2) -> None:
    # the profile's center of curvature K runs in a slot of the follower at x = −ρ in its own
    # coordinates (x along the guide; equivalent_linkage, Example 4.7), the slot's start F4a
    # = T + (−size, −ρ) in the fixed cam frame, the contact and ρ (cams/analytic.profile)
    assume(_supported(cam))
    j = _joint(cam, tmp_path_factory.getbasetemp(), axis, o2, 0.0)
    t = turn_steps(j, "θ2")
    th2 = np.radians(np.asarray(theta2))
    theta = cam.s * (th2 - (j.axis - math.pi / 2))
    assume(_off_the_joints(cam, theta))
    size = cam.prime + abs(cam.program.lift)
    k = cam.program.evaluate(theta)
    pr = profile(cam, theta)
    assume(bool(np.all(np.abs(pr.rho) < 1e5 * size)))
    py = _python(t, th2)
    assert py is not None
    rot = cmath.exp(1j * (j.axis - math.pi / 2))
    o = complex(*o2)
    for i, th in enumerate(theta):
        eq = equivalent_linkage(cam, float(th))
        reach = size + abs(float(pr.rho[i]))
        _close([py["K4.x"][i], py["K4.y"][i]], np.multiply(eq["links"]["2"]["K"], j.scale),
               reach, "K4")
        x, h = eq["links"]["4"]["L1"]
        _close(py["|ρ|4.value"][i], x * j.scale, reach, "x")
        start = complex(*eq["assembly"]["T"]) + complex(-h, x)
        start = o + rot * start * j.scale
        _close([py["T4.x"][i], py["T4.y"][i]], [start.real, start.imag], reach, "F4a")
        c = o + rot * cmath.exp(1j * cam.s * k.theta[i]) * complex(pr.contact[i]) * j.scale
        _close([py["C4.x"][i], py["C4.y"][i]], [c.real, c.imag], reach, "C4")
        _close(py["ρ4.value"][i], pr.rho[i], reach, "ρ")
    js = _javascript(t, th2)
    for i, v in enumerate(js):
        for lab in ("|ρ|4", "ρ4"):
            ref = py[f"{lab}.value"][i]
            _close(v[lab], ref, size + abs(float(ref)), f"{lab} (js)")
        for lab in ("K4", "T4", "C4"):
            ref = [py[f"{lab}.x"][i], py[f"{lab}.y"][i]]
            _close(v[lab], ref, size + float(np.abs(ref).max()), f"{lab} (js)")


@settings(max_examples=30, deadline=None)
@given(cam=cams(kinds=(FollowerKind.OSCILLATING_FLAT_FACE,)), axis=st.floats(-180.0, 180.0),
       o2=st.tuples(st.floats(-50.0, 50.0), st.floats(-50.0, 50.0)),
       theta2=st.lists(st.floats(-720.0, 720.0), min_size=1, max_size=8))
def test_an_oscillating_flat_face_equals_its_linkage(tmp_path_factory, cam, axis, o2,
                                                     theta2) -> None:
    # the face's slot (equivalent_linkage: the center of curvature K of the PROFILE runs in a
    # slot of the follower at y = −σ(e + ρ) in its own coordinates, Example 4.7), the slot's
    # point at the pivot's foot (its assembly L1), the contact and ρ (cams/analytic.profile)
    assume(_supported(cam))
    j = _joint(cam, tmp_path_factory.getbasetemp(), axis, o2, 0.0)
    t = turn_steps(j, "θ2")
    th2 = np.radians(np.asarray(theta2))
    theta = cam.s * (th2 - (j.axis - math.pi / 2))
    assume(_off_the_joints(cam, theta))
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    k = cam.program.evaluate(theta)
    pr = profile(cam, theta)
    assume(bool(np.all(np.abs(pr.rho) < 1e5 * size)))
    py = _python(t, th2)
    assert py is not None
    rot = cmath.exp(1j * (j.axis - math.pi / 2))
    o = complex(*o2)
    for i, th in enumerate(theta):
        eq = equivalent_linkage(cam, float(th))
        reach = size + abs(float(pr.rho[i]))
        _close([py["K4.x"][i], py["K4.y"][i]], np.multiply(eq["links"]["2"]["K"], j.scale),
               reach, "K4")
        _close(py["|ρ|4.value"][i], eq["links"]["4"]["L1"][1] * j.scale, reach, "y")
        foot = o + rot * complex(*eq["assembly"]["L1"]) * j.scale
        _close([py["T4.x"][i], py["T4.y"][i]], [foot.real, foot.imag], reach, "F4a")
        c = o + rot * cmath.exp(1j * cam.s * k.theta[i]) * complex(pr.contact[i]) * j.scale
        _close([py["C4.x"][i], py["C4.y"][i]], [c.real, c.imag], reach, "C4")
        _close(py["ρ4.value"][i], pr.rho[i], reach, "ρ")
    js = _javascript(t, th2)
    for i, v in enumerate(js):
        for lab in ("|ρ|4", "ρ4"):
            ref = py[f"{lab}.value"][i]
            _close(v[lab], ref, size + abs(float(ref)), f"{lab} (js)")
        for lab in ("K4", "T4", "C4"):
            ref = [py[f"{lab}.x"][i], py[f"{lab}.y"][i]]
            _close(v[lab], ref, size + float(np.abs(ref).max()), f"{lab} (js)")
