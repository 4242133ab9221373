"""Drives between two moving links (θ3/2, Problems 5.7-5.11) and by a point's coordinates
(x_C, y_C, Problem 5.13): hand derivations, the analytic solver, and random mechanisms.

The constructions (graphkin.kinematics.posture_drives, polygons) are checked against
values derived here by hand (written out in the comments) and against the analytic
solver (graphkin.kinematics.analytic), whose drive rows are θ_i − θ_j and v·R_P.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from strategies import examples

import graphkin
from graphkin.kinematics.analytic import solve_analytic
from graphkin.kinematics.solve import superposition

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
SETTINGS = examples(40)


def _e(t: float) -> np.ndarray:
    return np.array([math.cos(t), math.sin(t)])


def _perp(v: np.ndarray) -> np.ndarray:
    return np.array([-v[1], v[0]])


def _meet_circles(c1: np.ndarray, r1: float, c2: np.ndarray, r2: float,
                  near: np.ndarray) -> np.ndarray:
    """The intersection of two circles nearer ``near`` (law of cosines along the center line)."""
    d = float(np.hypot(*(c2 - c1)))
    a = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = math.sqrt(r1 * r1 - a * a)
    u = (c2 - c1) / d
    m = c1 + a * u
    cands = [m + h * _perp(u), m - h * _perp(u)]
    return min(cands, key=lambda p: float(np.hypot(*(p - near))))


def _th(sol, lid: str) -> float:
    """A link's angle (rad) in a solution."""
    return float(sol.links[lid].angle)


def _angle(v: np.ndarray) -> float:
    return math.atan2(v[1], v[0])


def _close_angle(a: float, b: float, tol: float = 1e-9) -> bool:
    return abs(math.remainder(a - b, 2 * math.pi)) < tol


# ---------------------------------------------------------------------------
# Problem 5.7/5.8: two robots hand over P
# ---------------------------------------------------------------------------

def test_problem_5_7_robots_by_hand():
    mech = graphkin.load(EXAMPLES / "p5_7_robots.toml")
    sol = mech.solve()
    assert sol.method == "construction"
    # θ3 = θ2 + θ3/2 = 45° − 15° = 30° (P5.7: θ3/2 = θ3 − θ2 is what the joint motor sets)
    t2, t3 = math.radians(45), math.radians(30)
    o2, o4 = np.array([0.0, 0.0]), np.array([1.0, 0.0])
    a = o2 + 0.3 * _e(t2)
    p = a + 0.4 * _e(t3)
    b = _meet_circles(o4, 0.3, p, 0.4, np.array([0.9, 0.3]))
    np.testing.assert_allclose(sol.position("P"), p, atol=1e-12)
    np.testing.assert_allclose(sol.position("B"), b, atol=1e-12)
    assert _close_angle((_th(sol, "3")), t3)
    assert _close_angle((_th(sol, "4")), _angle(b - o4))
    assert _close_angle((_th(sol, "5")), _angle(p - b))
    # P5.8: ω2 = 10 cw, ω3/2 = 15 ccw, so ω3 = ω2 + ω3/2 = 5 rad/s ccw;
    # V_P = ω2 k × R_AO2 + ω3 k × R_PA;  V_B = ω4 k × R_BO4 = V_P + ω5 k × R_BP:
    # two scalar equations in ω4, ω5
    w2, w3 = -10.0, 5.0
    vp = w2 * _perp(a - o2) + w3 * _perp(p - a)
    m = np.column_stack([_perp(b - o4), -_perp(b - p)])
    w4, w5 = np.linalg.solve(m, vp)
    assert float(sol.omega("3")) == pytest.approx(w3, abs=1e-12)
    assert float(sol.omega("4")) == pytest.approx(w4, rel=1e-10)
    assert float(sol.omega("5")) == pytest.approx(w5, rel=1e-10)
    np.testing.assert_allclose(sol.velocity("P"), vp, atol=1e-12)


def test_problem_5_7_robots_equal_the_analytic_solver():
    mech = graphkin.load(EXAMPLES / "p5_7_robots.toml")
    sol, ref = mech.solve(), solve_analytic(mech)
    for lid in mech.moving:
        assert _close_angle((_th(sol, lid)), (_th(ref, lid)))
        assert float(sol.omega(lid)) == pytest.approx(float(ref.omega(lid)), rel=1e-9, abs=1e-9)
        assert float(sol.alpha(lid)) == pytest.approx(float(ref.alpha(lid)), rel=1e-9, abs=1e-9)


def test_joint_angles_reported():
    from graphkin.output import solution_to_dict, text_report

    mech = graphkin.load(EXAMPLES / "p5_7_robots.toml")
    sol = mech.solve()
    d = solution_to_dict(sol)
    # θ3/2 is the drive: −15°, ω3/2 = 15 rad/s ccw, α3/2 = 0 (the file's)
    assert d["joint_angles"]["3/2"]["angle"] == pytest.approx(-15.0, abs=1e-12)
    assert d["joint_angles"]["3/2"]["omega"] == pytest.approx(15.0, abs=1e-12)
    # θ5/4 = θ5 − θ4, the answer P5.7 asks for
    want = math.degrees(math.remainder((_th(sol, "5")) - (_th(sol, "4")),
                                       2 * math.pi))
    assert d["joint_angles"]["5/4"]["angle"] == pytest.approx(want, abs=1e-9)
    assert "θ3/2 = -15.0000°" in text_report(sol)
    # a file without a relative drive has no such section
    assert "joint_angles" not in solution_to_dict(graphkin.examples.fourbar().solve())


def test_relative_drive_laid_off_backward():
    # θ2/3 given with θ3 ... here θ2 is absolute and the drive is link 2 relative to 3:
    # θ3 = θ2 − θ2/3 (the step goes from link 2 back to link 3)
    text = (EXAMPLES / "p5_7_robots.toml").read_text()
    text = text.replace("link = 3\nrelative_to = 2\nangle = -15",
                        "link = 2\nrelative_to = 3\nangle = 15")
    text = text.replace('omega = "15 rad/s"', 'omega = "15 rad/s cw"')
    mech = graphkin.loads(text)
    sol = mech.solve()
    assert sol.method == "construction"
    assert _close_angle((_th(sol, "3")), math.radians(30))
    # ω2/3 = ω2 − ω3 = −15, so ω3 = −10 + 15 = 5 as before
    assert float(sol.omega("3")) == pytest.approx(5.0, abs=1e-12)


# ---------------------------------------------------------------------------
# Problem 5.13: the pantograph traced by C
# ---------------------------------------------------------------------------

def test_problem_5_13_pantograph_by_similar_triangles():
    # O2-A-B is one link (O2A = 300, AB = 200), ABDC a parallelogram (AC = BD = 300,
    # AB = CD = 200) and B-D-P one link (DP = 200): the triangles O2AC and O2BP are
    # similar with the ratio O2B/O2A = 500/300, so R_P = (5/3) R_C, and differentiating,
    # V_P = (5/3) V_C and A_P = (5/3) A_C: the kinematic coefficients ∂x_P/∂x_C =
    # ∂y_P/∂y_C = 5/3 and ∂x_P/∂y_C = ∂y_P/∂x_C = 0.
    mech = graphkin.load(EXAMPLES / "p5_13_pantograph.toml")
    sol = mech.solve()
    assert sol.method == "construction"
    k = 5.0 / 3.0
    np.testing.assert_allclose(sol.position("P"), k * np.array([350.0, 150.0]), atol=1e-9)
    np.testing.assert_allclose(sol.velocity("P"), k * sol.velocity("C"), atol=1e-9)
    np.testing.assert_allclose(sol.acceleration("P"), k * sol.acceleration("C"), atol=1e-9)
    np.testing.assert_allclose(sol.velocity("C"), [100.0, 0.0], atol=1e-12)
    # superposition (Sec. 5.4): one case per input, x_C then y_C, each at the file's rate
    text = (EXAMPLES / "p5_13_pantograph.toml").read_text().replace("vy = 0", "vy = 100")
    cases = superposition(graphkin.loads(text))
    assert [i for i, _ in cases] == [0, 1]
    np.testing.assert_allclose(cases[0][1].velocity("P"), [k * 100.0, 0.0], atol=1e-9)
    np.testing.assert_allclose(cases[1][1].velocity("P"), [0.0, k * 100.0], atol=1e-9)


def test_problem_5_13_pantograph_equals_the_analytic_solver():
    mech = graphkin.load(EXAMPLES / "p5_13_pantograph.toml")
    sol = mech.solve()
    ref = solve_analytic(mech, guess={lid: (float(sol.links[lid].origin[0]),
                                            float(sol.links[lid].origin[1]),
                                            (_th(sol, lid))) for lid in mech.moving})
    for name in mech.point_names:
        np.testing.assert_allclose(sol.position(name), ref.position(name), atol=1e-9)
        np.testing.assert_allclose(sol.velocity(name), ref.velocity(name), atol=1e-9)
        np.testing.assert_allclose(sol.acceleration(name), ref.acceleration(name), atol=1e-9)


# ---------------------------------------------------------------------------
# Random robot arms and pantograph-like chains (Hypothesis)
# ---------------------------------------------------------------------------

def _local(pose: tuple[float, float, float], p: np.ndarray) -> list[float]:
    """World point -> a link's own coordinates (origin pose[:2], x axis at pose[2])."""
    d = p - np.array(pose[:2])
    c, s = math.cos(pose[2]), math.sin(pose[2])
    return [float(c * d[0] + s * d[1]), float(-s * d[0] + c * d[1])]


@st.composite
def robot_pairs(draw):
    """Two 2R arms pinned to the frame that share their tip P (P5.7), drawn from a posture.

    The left arm is driven by θ2 and its joint angle θ3/2 (or θ2/3 backward); the right
    arm follows.  Returns (file dict, world points, link angles, backward).
    """
    f = st.floats
    o2 = np.array([draw(f(-5, 5)), draw(f(-5, 5))])
    t2, t3 = draw(f(-math.pi, math.pi)), draw(f(-math.pi, math.pi))
    l2, l3 = draw(f(1, 4)), draw(f(1, 4))
    a = o2 + l2 * _e(t2)
    p = a + l3 * _e(t3)
    t5, l5 = draw(f(-math.pi, math.pi)), draw(f(1, 4))
    b = p - l5 * _e(t5)
    t4, l4 = draw(f(-math.pi, math.pi)), draw(f(1, 4))
    o4 = b - l4 * _e(t4)
    # away from the right arm's toggle: B's transmission angle between 25° and 155°
    mu = abs(math.degrees(math.remainder(t5 - t4, 2 * math.pi)))
    assume(25 < mu < 155)
    assume(abs(math.remainder(t3 - t2, 2 * math.pi)) > 0.2)  # arm not folded or stretched
    assume(float(np.hypot(*(o4 - o2))) > 0.5)
    rot = [draw(f(-math.pi, math.pi)) for _ in range(4)]  # each link's own frame
    poses = {}
    for lid, (org, th) in {"2": (o2, t2), "3": (a, t3), "4": (o4, t4), "5": (b, t5)}.items():
        r = rot[int(lid) - 2]
        poses[lid] = (float(org[0]), float(org[1]), th + r)
    pts = {"O2": o2, "O4": o4, "A": a, "B": b, "P": p}
    members = {"2": ["O2", "A"], "3": ["A", "P"], "4": ["O4", "B"], "5": ["B", "P"]}
    links = {"1": {"O2": o2.tolist(), "O4": o4.tolist()}}
    for lid, names in members.items():
        links[lid] = {n: _local(poses[lid], pts[n]) for n in names}
    backward = draw(st.booleans())
    w2, w32 = draw(f(-20, 20)), draw(f(-20, 20))
    al2, al32 = draw(f(-50, 50)), draw(f(-50, 50))
    # the angle of a link is the direction of its own x axis (docs/formats/mechanism.md)
    th2, th3 = poses["2"][2], poses["3"][2]
    rel = math.degrees(math.remainder(th3 - th2, 2 * math.pi))
    if backward:  # θ2/3 = −θ3/2, its rates too
        joint = {"link": 2, "relative_to": 3, "angle": -rel, "omega": -w32, "alpha": -al32}
    else:
        joint = {"link": 3, "relative_to": 2, "angle": rel, "omega": w32, "alpha": al32}
    data = {"links": links,
            "drive": [{"link": 2, "angle": math.degrees(th2), "omega": w2, "alpha": al2},
                      joint],
            "assembly": {"B": b.tolist()}}
    angles = {lid: poses[lid][2] for lid in poses}
    return data, pts, angles


def _compare_with_analytic(mech, sol, size):
    ref = solve_analytic(mech, guess={lid: (float(sol.links[lid].origin[0]),
                                            float(sol.links[lid].origin[1]),
                                            (_th(sol, lid))) for lid in mech.moving})
    w = max(abs(float(ref.omega(k))) for k in mech.moving)
    al = max(abs(float(ref.alpha(k))) for k in mech.moving)
    for lid in mech.moving:
        assert float(sol.omega(lid)) == pytest.approx(float(ref.omega(lid)),
                                                      abs=1e-7 * (w + 1))
        assert float(sol.alpha(lid)) == pytest.approx(float(ref.alpha(lid)),
                                                      abs=1e-7 * (al + w * w + 1))
    for name in mech.point_names:
        v = float(np.hypot(*ref.velocity(name)))
        np.testing.assert_allclose(sol.velocity(name), ref.velocity(name),
                                   atol=1e-7 * (v + w * size + 1))


def _constructed_through(data, pts):
    """Solve by construction and check the posture passes through the generating points."""
    mech = graphkin.from_dict(data)
    sol = mech.solve()
    assert sol.method == "construction", sol.notes
    size = mech.scale
    for name, xy in pts.items():
        np.testing.assert_allclose(sol.position(name), xy, atol=1e-9 * size)
    return mech, sol, size


@SETTINGS
@given(robot_pairs())
def test_random_robot_pairs_relative_drive(case):
    data, pts, angles = case
    mech, sol, size = _constructed_through(data, pts)
    for lid, th in angles.items():
        assert _close_angle((_th(sol, lid)), th, 1e-8)
    # ω3 = ω2 + ω3/2 and α3 = α2 + α3/2 in plane motion, whichever way the file gives it
    d2, dj = mech.drives
    sign = 1.0 if dj.link == "3" else -1.0
    assert float(sol.omega("3")) == pytest.approx(d2.rate + sign * dj.rate, abs=1e-9)
    assert float(sol.alpha("3")) == pytest.approx(d2.rate2 + sign * dj.rate2, abs=1e-9)
    _compare_with_analytic(mech, sol, size)


@st.composite
def traced_chains(draw):
    """A pantograph-like chain: 2R arm O2-A-C traced at C, and a dyad B-D hung from it.

    Link 2 (O2, A, B), link 3 (A, C), link 4 (B, D, P), link 5 (C, D): C given by x and
    y (both drives), or by x or y only with θ2 as the other drive.  Drawn from a posture.
    """
    f = st.floats
    o2 = np.array([draw(f(-5, 5)), draw(f(-5, 5))])
    t2, t3 = draw(f(-math.pi, math.pi)), draw(f(-math.pi, math.pi))
    l2, l3 = draw(f(1, 4)), draw(f(1, 4))
    a = o2 + l2 * _e(t2)
    c = a + l3 * _e(t3)
    bb = a + draw(f(0.5, 3)) * _e(t2 + draw(f(-1, 1)))  # B on link 2, off its line
    t4, t5 = draw(f(-math.pi, math.pi)), draw(f(-math.pi, math.pi))
    d = c + draw(f(1, 4)) * _e(t5)
    assume(float(np.hypot(*(d - bb))) > 0.5)
    pp = d + draw(f(0.5, 3)) * _e(t4)
    # transmission angles at A (arms of links 2 and 3) and at D (links 4 and 5)
    mu_a = abs(math.degrees(math.remainder(t3 - t2, 2 * math.pi)))
    mu_d = abs(math.degrees(math.remainder(_angle(d - bb) - t5, 2 * math.pi)))
    assume(25 < mu_a < 155 and 25 < mu_d < 155)
    pts = {"O2": o2, "A": a, "B": bb, "C": c, "D": d, "P": pp}
    members = {"2": ["O2", "A", "B"], "3": ["A", "C"], "4": ["B", "D", "P"], "5": ["C", "D"]}
    links = {"1": {"O2": o2.tolist()}}
    th2 = 0.0
    for lid, names in members.items():
        pose = (float(pts[names[0]][0]), float(pts[names[0]][1]),
                draw(f(-math.pi, math.pi)))
        links[lid] = {n: _local(pose, pts[n]) for n in names}
        if lid == "2":
            th2 = pose[2]
    which = draw(st.sampled_from(["xy", "x", "y"]))
    vx, vy, ax, ay = (draw(f(-10, 10)) for _ in range(4))
    drive: dict = {"point": "C"}
    if "x" in which:
        drive.update(x=float(c[0]), vx=vx, ax=ax)
    if "y" in which:
        drive.update(y=float(c[1]), vy=vy, ay=ay)
    drives = [drive]
    if which != "xy":
        # the arm must cut the line x = x_C (or y = y_C) steeply: C's motion about A
        # makes at least 20° with the line
        u = _perp(c - a) / float(np.hypot(*(c - a)))
        along = abs(u[1]) if which == "x" else abs(u[0])
        assume(along < math.cos(math.radians(20)))
        drives.insert(0, {"link": 2, "angle": math.degrees(th2), "omega": draw(f(-10, 10)),
                          "alpha": draw(f(-10, 10))})
    data = {"links": links, "drive": drives,
            "assembly": {"A": a.tolist(), "C": c.tolist(), "D": d.tolist()}}
    return data, pts, which


@SETTINGS
@given(traced_chains())
def test_random_traced_chains_coordinate_drive(case):
    data, pts, which = case
    mech, sol, size = _constructed_through(data, pts)
    # the given components of V_C and A_C are laid off as given
    drive = next(d for d in data["drive"] if "point" in d)
    for k, axis in enumerate("xy"):
        if axis in drive:
            assert float(sol.velocity("C")[k]) == pytest.approx(drive[f"v{axis}"], abs=1e-9)
            assert float(sol.acceleration("C")[k]) == pytest.approx(drive[f"a{axis}"],
                                                                    abs=1e-7)
    _compare_with_analytic(mech, sol, size)


# ---------------------------------------------------------------------------
# Sweeps of the new drives
# ---------------------------------------------------------------------------

def test_sweep_of_the_joint_angle_equals_solves():
    # the relative drive first: the sweep turns θ3/2 with θ2 held
    text = (EXAMPLES / "p5_7_robots.toml").read_text()
    head, first, second = text.split("[[drive]]")
    second, rest = second.split("[assembly]")
    text = f"{head}[[drive]]{second}[[drive]]{first}[assembly]{rest}"
    mech = graphkin.loads(text)
    assert mech.drives[0].kind == "relative"
    sw = mech.sweep(count=8, start=-15, stop=-5)
    for k, deg in enumerate(np.linspace(-15, -5, 8, endpoint=False)):
        moved = text.replace("angle = -15", f"angle = {float(deg)!r}")
        sol = solve_analytic(graphkin.loads(moved))
        assert float(sw.columns["angle_5"][k]) == pytest.approx(
            math.degrees(math.remainder((_th(sol, "5")), 2 * math.pi)), abs=1e-7)
        assert float(sw.columns["omega_4"][k]) == pytest.approx(float(sol.omega("4")),
                                                                rel=1e-7, abs=1e-9)


def test_sweep_of_a_coordinate_equals_solves():
    mech = graphkin.load(EXAMPLES / "p5_13_pantograph.toml")
    sw = mech.sweep(count=5, start=300, stop=400)
    # the pen follows the tracer: x_P = (5/3) x_C at every posture
    np.testing.assert_allclose(sw.columns["x_P"], 5 / 3 * np.asarray(sw.columns["x_C"]),
                               atol=1e-9)
    np.testing.assert_allclose(sw.columns["x_C"], np.linspace(300, 400, 5, endpoint=False),
                               atol=1e-9)


# ---------------------------------------------------------------------------
# What the file cannot say
# ---------------------------------------------------------------------------

_ROBOT = (EXAMPLES / "p5_7_robots.toml").read_text()
_PANTO = (EXAMPLES / "p5_13_pantograph.toml").read_text()


@pytest.mark.parametrize("text, key, words", [
    (_ROBOT.replace("relative_to = 2", "relative_to = 1"), "drive[1].relative_to",
     "absolute angle"),
    (_ROBOT.replace("relative_to = 2", "relative_to = 3"), "drive[1].relative_to", "itself"),
    (_ROBOT.replace("relative_to = 2", "relative_to = 9"), "drive[1].relative_to", "no link"),
    (_ROBOT.replace("relative_to = 2\nangle = -15", "relative_to = 2\nposition = 1"),
     "drive[1].position", "relative drive"),
    # without relative_to, link 3's absolute angle drives it (solved analytically, issue 25)
    (_PANTO.replace('point = "C"', 'point = "Z"'), "drive[0].point", "no link"),
    (_PANTO.replace('point = "C"', 'point = "O2"'), "drive[0].point", "fixed"),
    (_PANTO.replace("vy = 0", "vy = 0\nomega = 3"), "drive[0].omega", "coordinate"),
    (_PANTO.replace("[assembly]", '[[drive]]\npoint = "C"\nx = 1\nvx = 0\n\n[assembly]'),
     "drive[1].x", "driven twice"),
    (_PANTO.replace("x = 350\n", ""), "drive[0].vx", "does not give"),
    (_PANTO.replace('point = "C"', 'point = "C"\nlink = 2'), "drive[0].link", "no point"),
    (_ROBOT + '\n[[loads]]\nlink = 3\npoint = "P"\nforce = "10 N at 270 deg"\n', "drive[1]",
     "not supported yet"),
    (_PANTO + '\n[[loads]]\nlink = 4\npoint = "P"\nforce = "10 N at 270 deg"\n', "drive[0]",
     "not supported yet"),
    (_PANTO.replace("vx = 100\n", "").replace("vy = 0\n", "").replace("ax = 0\n", "")
     .replace("ay = 0\n", "") + "\n[rates]\nlink = 2\nomega = 1\n", "rates", "single input"),
])
def test_contradictory_drives_are_one_line(tmp_path, text, key, words):
    f = tmp_path / "m.toml"
    f.write_text(text)
    with pytest.raises(graphkin.InputError) as exc:
        graphkin.load(f)
    assert exc.value.key == key
    line = exc.value.one_line()
    assert words in line and str(f) in line and key in line and "\n" not in line


def test_contradictory_drive_exits_2(tmp_path, capsys):
    from graphkin.cli import main

    f = tmp_path / "m.toml"
    f.write_text(_ROBOT.replace("relative_to = 2", "relative_to = 3"))
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "drive[1].relative_to" in err[0] and "m.toml" in err[0]
