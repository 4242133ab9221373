"""A cam mechanism over the cycle (``sweep``, ``plot``, ``animate``): the follower by its program.

Two independent oracles for every swept posture:

* ``solve`` of the same file with its drive at that cam angle (the equivalent
  linkage through the centers of curvature, Sec. 4.7: another construction
  altogether);
* the program differentiated by hand: the cam turns at dΘ/dt = s·ω2, so the
  follower moves with y'·sω2 and y''·ω2² + y'·sα2 (Eqs. 6.1-6.3), along its
  guide turned ``axis − 90°`` (a translating follower, its trace point at
  height y0 + Y over O2, y0 = √(R0² − ε²), or R0 for a flat face) or about
  its pivot (an oscillating one, σ times these).
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
from graphkin.cams import Cam, FollowerKind
from graphkin.errors import InputError
from graphkin.mechanisms import from_dict

EXAMPLES = Path(__file__).resolve().parents[2] / "examples" / "cams"
_TMP = Path(tempfile.mkdtemp(prefix="graphkin-cam-cycle-"))
O2 = np.array([3.0, -2.0])


def _data(cam_file: Path | str, theta2: float, omega: float, alpha: float, axis: float,
          p: tuple[float, float]) -> dict:
    return {"units": "mm", "links": {"1": {"O2": O2.tolist()}, "4": {"P": list(p)}},
            "cams": {"link": 2, "follower": 4, "file": str(cam_file), "axis": axis},
            "drive": {"link": 2, "angle": theta2, "omega": omega, "alpha": alpha}}


def _solved(data: dict, theta2: float) -> graphkin.Solution | None:
    """``solve`` at θ2 through the equivalent linkage, or None where it has none."""
    d = dict(data, drive={**data["drive"], "angle": float(theta2)})
    try:
        return from_dict(d).solve()
    except InputError as exc:          # a straight piece of surface: no center of curvature
        assert "straight" in str(exc) or "short" in str(exc) or "longest" in str(exc) \
            or "range" in str(exc), str(exc)
        return None


def _closed_form(cam: Cam, sw, axis: float, omega: float, alpha: float) -> None:
    """The follower's columns against the program differentiated by hand, at every posture."""
    c = sw.columns
    th2 = np.radians(np.asarray(c["drive"], dtype=float))
    shift = math.radians(axis - 90.0)
    s = cam.s
    k = cam.program.evaluate(s * (th2 - shift))
    dth, ddth = s * omega, s * alpha
    v, a = k.y1 * dth, k.y2 * dth**2 + k.y1 * ddth
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    big = max(1.0, omega**2, abs(alpha))
    if f.kind.oscillating:
        sig = f.rise.sign
        # θ4 = θ4(Y = 0) + σY, the cam file's frame turned by axis − 90°
        want = np.degrees(cam.arm0 + sig * k.Y + shift)
        got = np.asarray(c["angle_4"], dtype=float)
        assert np.allclose(np.mod(got - want + 180.0, 360.0) - 180.0, 0.0, atol=1e-9)
        assert np.allclose(c["omega_4"], sig * v, atol=1e-9 * max(1.0, abs(omega)))
        assert np.allclose(c["alpha_4"], sig * a, atol=1e-9 * big)
        return
    y0 = cam.prime if f.kind.flat else math.sqrt(cam.prime**2 - f.offset**2)
    mm = {"mm": 1.0, "in": 25.4}[cam.unit]       # the cam file's unit in the mechanism's (mm)
    y0, e, Y, v, a, size = y0 * mm, f.offset * mm, k.Y * mm, v * mm, a * mm, size * mm
    d = np.array([math.cos(math.radians(axis)), math.sin(math.radians(axis))])
    n = np.array([d[1], -d[0]])                  # the cam file's +x, turned
    t = O2[:, None] + np.outer(n, np.full_like(th2, e)) + np.outer(d, y0 + Y)
    tol = 1e-9 * size
    assert np.allclose(c["x_T4"], t[0], atol=tol) and np.allclose(c["y_T4"], t[1], atol=tol)
    vt = np.stack([c["vx_T4"], c["vy_T4"]])
    at = np.stack([c["ax_T4"], c["ay_T4"]])
    assert np.allclose(d @ vt, v, atol=tol * max(1.0, abs(omega)))
    assert np.allclose(n @ vt, 0.0, atol=tol * max(1.0, abs(omega)))   # along the guide only
    assert np.allclose(d @ at, a, atol=tol * big)


def _against_solve(cam: Cam, data: dict, sw) -> int:
    """Every column of T4, P and the follower equal to ``solve``'s at the same cam angle."""
    c = sw.columns
    f = cam.follower
    size = (cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm) * {
        "mm": 1.0, "in": 25.4}[cam.unit]
    om, al = data["drive"]["omega"], data["drive"]["alpha"]
    big = max(1.0, om**2, abs(al))
    axis = data["cams"]["axis"]
    checked = 0
    for i, th2 in enumerate(np.asarray(c["drive"], dtype=float)):
        theta = cam.s * math.radians(th2 - (axis - 90.0))
        if not np.isfinite(graphkin.cams.profile(cam, [theta]).contact[0]):
            continue                # the follower cannot follow here (the design checks say)
        sol = _solved(data, th2)
        if sol is None:
            continue
        checked += 1
        for p in [q for q in ("T4", "P") if f"x_{q}" in c]:  # no T4 on an oscillating face
            assert np.allclose([c[f"x_{p}"][i], c[f"y_{p}"][i]], sol.position(p),
                               atol=1e-9 * size)
            assert np.allclose([c[f"vx_{p}"][i], c[f"vy_{p}"][i]], sol.velocity(p),
                               atol=1e-7 * size * max(1.0, abs(om)))
            assert np.allclose([c[f"ax_{p}"][i], c[f"ay_{p}"][i]], sol.acceleration(p),
                               atol=1e-6 * size * big)
        turn = (c["angle_4"][i] - float(sol.angle("4")) + 180.0) % 360.0 - 180.0
        assert abs(turn) < 1e-7
        assert abs(c["omega_4"][i] - float(sol.omega("4"))) < 1e-7 * max(1.0, abs(om))
        assert abs(c["alpha_4"][i] - float(sol.alpha("4"))) < 1e-6 * big
    return checked


@pytest.mark.parametrize("kind", list(FollowerKind), ids=lambda k: k.value)
@settings(max_examples=8, deadline=None)
@given(data=st.data(), start=st.floats(0.0, 360.0), span=st.floats(10.0, 350.0),
       omega=st.floats(-20.0, 20.0), alpha=st.floats(-50.0, 50.0),
       axis=st.sampled_from([90.0, 0.0, 210.0]))
def test_random_cam_mechanisms_swept_agree_with_solve_and_the_program(kind, data, start, span,
                                                                     omega, alpha, axis):
    """Every follower kind, any program, the cam file turned anywhere, random cam angles: the
    swept columns are ``solve``'s at those angles and the program's closed form."""
    cam = data.draw(cams(kinds=(kind,)))
    path = _TMP / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam))
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    file = _data(path, start, omega, alpha, axis, (0.3 * size, 0.2 * size))
    try:
        mech = from_dict(file)
    except InputError:              # no equivalent linkage at the file's angle: not this test
        return
    sw = mech.sweep(count=5, start=start, stop=start + span)
    assert sw.assembled.all()
    _closed_form(cam, sw, axis, omega, alpha)
    _against_solve(cam, file, sw)


@pytest.mark.parametrize("name, axis", [("ex6_6_roller.toml", 90.0),
                                        ("ex6_3_flat_face.toml", 30.0),
                                        ("ex6_7_oscillating.toml", 90.0),
                                        ("ex6_5_roller.toml", 200.0)])
def test_the_book_s_cams_swept_over_a_turn(name, axis):
    """Each follower kind of the book's examples, a whole turn in 24 steps from θ2 = 7°."""
    from graphkin.cams.parse import load_cam

    cam = load_cam(EXAMPLES / name).cam
    data = _data(EXAMPLES / name, 7.0, 3.0, -2.0, axis, (5.0, 4.0))
    sw = from_dict(data).sweep(count=24)
    _closed_form(cam, sw, axis, 3.0, -2.0)
    assert _against_solve(cam, data, sw) >= 20


def test_the_rest_of_the_mechanism_is_driven_by_the_follower():
    """examples/cams/cam_mechanism.toml: Ex 6.6's follower (Y = 15(1 − cos 2Θ) mm, R0 = 40)
    drives a rod P-Q (80 mm, P 30 mm up the follower) and a slider Q on y = 80.

    By hand: P = (0, 70 + Y), Q = (√(80² − (80 − P_y)²), 80) (Q to the right, as assembled);
    the rod's velocity equation along P-Q, V_Q·(Q − P) = V_P·(Q − P), gives
    V_Q = V_P (Q_y − P_y) / (Q_x − P_x) with V_P = y'ω = 30 sin 2Θ · 10.
    """
    mech = graphkin.load(EXAMPLES / "cam_mechanism.toml")
    sw = mech.sweep(count=36, start=0.0, centers=True)
    c = sw.columns
    th = np.radians(np.asarray(c["drive"], dtype=float))
    Y = 15.0 * (1.0 - np.cos(2.0 * th))
    # the instant center of cam and follower: y' from O2, normal to the follower's motion
    # (Sec. 6.10, Fig. 6.27), where the follower moves (y' = 30 sin 2Θ clear of 0)
    moving = np.abs(np.sin(2.0 * th)) > 0.1
    assert np.allclose(np.asarray(c["x_I24"])[moving], 30.0 * np.sin(2.0 * th[moving]))
    assert np.allclose(np.asarray(c["y_I24"])[moving], 0.0, atol=1e-9)
    py = 70.0 + Y
    qx = np.sqrt(80.0**2 - (80.0 - py) ** 2)
    assert np.allclose(c["y_P"], py, atol=1e-9) and np.allclose(c["x_Q"], qx, atol=1e-9)
    vp = 30.0 * np.sin(2.0 * th) * 10.0
    assert np.allclose(c["vy_P"], vp, atol=1e-9)
    assert np.allclose(c["vx_Q"], vp * (80.0 - py) / qx, atol=1e-8)
    # and the slider's acceleration against solve at a few cam angles
    for i in (3, 17, 29):
        sol = graphkin.mechanisms.from_dict({**graphkin.files.load_toml(
            EXAMPLES / "cam_mechanism.toml"), "drive": {"link": 2, "angle": float(c["drive"][i]),
                                                        "omega": 10, "alpha": 5}},
            source=str(EXAMPLES / "cam_mechanism.toml")).solve()
        assert np.allclose([c["ax_Q"][i], c["ay_Q"][i]], sol.acceleration("Q"), atol=1e-7)


def test_two_cams_on_one_shaft_each_move_their_follower():
    """Ex 6.6's cam twice on link 2: follower 4 rising up (axis 90°), follower 5 along +x
    (axis 0°, so Θ5 = θ2 + 90°). By hand, V_T4 = 30 sin 2θ2 · ω and
    V_T5 = 30 sin(2θ2 + 180°) · ω = −V_T4 along x; and each equals solve's."""
    ex = str(EXAMPLES / "ex6_6_roller.toml")
    data = {"units": "mm", "links": {"1": {"O2": [0, 0]}},
            "cams": [{"link": 2, "follower": 4, "file": ex},
                     {"link": 2, "follower": 5, "file": ex, "axis": 0}],
            "drive": {"link": 2, "angle": 30, "omega": 10, "alpha": 0}}
    sw = from_dict(data).sweep(count=12)
    c = sw.columns
    th = np.radians(np.asarray(c["drive"], dtype=float))
    assert np.allclose(c["vy_T4"], 300.0 * np.sin(2 * th), atol=1e-9)
    assert np.allclose(c["vx_T5"], -300.0 * np.sin(2 * th), atol=1e-9)
    assert np.allclose(c["x_T5"], 40.0 + 15.0 * (1 + np.cos(2 * th)), atol=1e-9)
    for i in (1, 7):
        sol = from_dict({**data, "drive": {**data["drive"], "angle": float(c["drive"][i])}}
                        ).solve()
        for p in ("T4", "T5"):
            assert np.allclose([c[f"ax_{p}"][i], c[f"ay_{p}"][i]], sol.acceleration(p),
                               atol=1e-7)


def test_follow_sweeps_a_cam_mechanism_too():
    mech = graphkin.load(EXAMPLES / "cam_mechanism.toml")
    a, b = mech.sweep(count=12), graphkin.kinematics.sweep.sweep(mech, count=12, follow=True)
    assert np.allclose(a.columns["x_Q"], b.columns["x_Q"])


def test_a_cam_on_another_drive_s_link_is_held_over_the_cycle():
    # a sweep turns the first drive (link 8) and holds every other input at its value, the
    # cam's drive (θ2 = 30°) too: the follower stands at the program's Y(30°) = 15(1 − cos 60°)
    # = 7.5 mm above its zero-lift height R0 = 40 mm, at rest (Ex 6.6's program, Eq. 6.12)
    data = _data(EXAMPLES / "ex6_6_roller.toml", 30.0, 1.0, 0.0, 90.0, (5.0, 0.0))
    data["links"]["8"] = {"O8": [100.0, 0.0], "A": [10.0, 0.0]}
    data["links"]["1"]["O8"] = [100.0, 0.0]
    data["drive"] = [{"link": 8, "angle": 0, "omega": 1, "alpha": 0}, data["drive"]]
    mech = from_dict(data, source="m.toml")
    c = mech.sweep(count=4).columns
    np.testing.assert_allclose(c["y_T4"], O2[1] + 47.5, rtol=0, atol=1e-9)
    np.testing.assert_allclose(c["vy_T4"], 0.0, rtol=0, atol=1e-9)
    np.testing.assert_allclose(c["ay_T4"], 0.0, rtol=0, atol=1e-9)


def test_a_batch_of_designs_of_a_cam_mechanism_is_refused_in_one_line():
    from graphkin.kinematics.sweep.batch import batch

    mech = graphkin.load(EXAMPLES / "cam_mechanism.toml")
    with pytest.raises(InputError, match="batch") as err:
        batch(mech, {"links.6.Q": [[80.0, 0.0], [81.0, 0.0]]}, count=4)
    assert err.value.key == "cams"


def test_the_commands(tmp_path, capsys):
    """sweep, plot and animate turn the cam; the forces over the cycle are refused in one line."""
    from graphkin.cli import main

    f = str(EXAMPLES / "cam_mechanism.toml")
    csv = tmp_path / "c.csv"
    assert main(["sweep", f, "--count", "8", "--csv", str(csv)]) == 0
    head, first = csv.read_text().splitlines()[:2]
    row = dict(zip(head.split(","), first.split(","), strict=True))
    assert abs(float(row["vy_T4"]) - 259.8076211) < 1e-6         # Ex 6.6 at Θ = 30°: y'ω
    assert main(["plot", f, "--count", "12", "--what", "path:P,velocity:Q",
                 "-o", str(tmp_path / "p.svg")]) == 0
    assert main(["animate", f, "--count", "12", "-o", str(tmp_path / "a.html")]) == 0
    capsys.readouterr()
    for argv in (["sweep", f, "--torque", "--csv", str(tmp_path / "t.csv")],
                 ["plot", f, "--what", "torque", "-o", str(tmp_path / "t.svg")]):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "cam mechanism" in err, err


def _edge_distance(p: np.ndarray, poly: np.ndarray) -> float:
    """The least distance from ``p`` to the closed polygon ``poly`` (its edges)."""
    a, b = poly, np.roll(poly, -1, axis=0)
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", p - a, ab) / np.einsum("ij,ij->i", ab, ab), 0.0, 1.0)
    return float(np.min(np.hypot(*(a + t[:, None] * ab - p).T)))


def test_the_animation_turns_the_cam_under_its_roller():
    """animate's data: the cam's profile (an outline of link 2) turned with the cam, the roller
    (a circle about T4, 12 mm) moved with the follower; the roller touches the profile at every
    posture: T4 stands 12 mm from the turned outline (to within the outline's 144 chords,
    whose sagitta is ρ(1 − cos(π/144)) < 0.02 mm on Ex 6.6's cam)."""
    from graphkin.render.cycle_data import cycle_data

    d = cycle_data(graphkin.load(EXAMPLES / "cam_mechanism.toml"), count=24)
    bodies = {b["kind"]: b for b in d["bodies"]}
    cam, roller = bodies["outline"], bodies["circle"]
    assert cam["link"] == "2" and roller["link"] == "4" and roller["r"] == 12.0
    qL = d["q"]["L"]
    local = np.array(cam["local"])
    for i in range(d["n"]):
        a = math.radians(cam["angle"][i] * 1e-4)
        rot = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
        world = np.array([cam["ox"][i], cam["oy"][i]]) * qL + local @ rot.T
        t4 = np.array([d["points"]["T4"]["x"][i], d["points"]["T4"]["y"][i]]) * qL
        turn = a - math.radians(d["drive"]["values"][i])          # the cam turns with θ2
        assert abs((turn + math.pi) % (2 * math.pi) - math.pi) < 1e-5
        gap = _edge_distance(t4, world) - 12.0
        assert abs(gap) < 0.02, gap
