"""A cam on a link the linkage moves (a four-bar's rocker): read, solved and swept.

The cam's angle is its link's as the linkage places it (graphkin/cams/linkage.py).
Oracles, none of them graphkin's reading of the cam on a linkage:

* the four-bar in closed form: θ4 by the two circles' intersection (the cosine
  rule), ω3, ω4 and α3, α4 from the loop closure a e^{iθ2} + b e^{iθ3} = d + c e^{iθ4}
  differentiated by hand (Secs. 3.6, 4.4);
* the follower's lift from the program by hand, Y = 10 (1 − cos Θ) with Θ = θ4
  (tests/data/live25/harmonic_cam.toml: harmonic rise of 20 mm over 180° and back,
  Eq. 6.12), Ẏ = 10 sin θ4 ω4, Ÿ = 10 (cos θ4 ω4² + sin θ4 α4) (Eqs. 6.1-6.3);
* for random cams, the same cam on a drive turned to the closed-form θ4 at the
  closed-form ω4, α4 (the cam-on-a-drive joint, tests/cams/test_cams_joint.py);
* over the cycle, ``solve`` of the file at each swept crank angle.
"""

from __future__ import annotations

import copy
import math
import tempfile
from pathlib import Path

import numpy as np
import pytest
from cam_strategies import cam_toml, cams
from hypothesis import assume, given, settings
from hypothesis import strategies as st

import graphkin
from graphkin.cams import FollowerKind
from graphkin.errors import GraphkinError, InputError
from graphkin.files import load_toml
from graphkin.mechanisms import from_dict

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "tests" / "data" / "live25" / "cam_on_rocker.toml"
_TMP = Path(tempfile.mkdtemp(prefix="graphkin-cam-linkage-"))


def _file() -> dict:
    data = load_toml(SRC)
    data["cams"][0]["file"] = str((SRC.parent / data["cams"][0]["file"]).resolve())
    return data


def four_bar(a: float, b: float, c: float, d: float, th2: float, w2: float,
             a2: float) -> tuple[float, float, float]:
    """θ4, ω4, α4 of the four-bar O2 = 0, O4 = (d, 0), B counterclockwise of A → O4.

    B = A + b e^{i(φ+β)}: φ the direction A → O4, cos β = (b² + e² − c²)/(2be),
    e = |O4 − A| (the cosine rule).  The loop a e^{iθ2} + b e^{iθ3} = d + c e^{iθ4}
    differentiated once, i a ω2 e^{iθ2} + i b ω3 e^{iθ3} = i c ω4 e^{iθ4}, and twice,
    (i α2 − ω2²) a e^{iθ2} + (i α3 − ω3²) b e^{iθ3} = (i α4 − ω4²) c e^{iθ4}: two real
    equations each, linear in (ω3, ω4), then in (α3, α4).
    """
    A = a * np.exp(1j * th2)
    e = d - A
    beta = math.acos((b * b + abs(e) ** 2 - c * c) / (2 * b * abs(e)))
    B = A + b * np.exp(1j * (np.angle(e) + beta))
    th3, th4 = float(np.angle(B - A)), float(np.angle(B - d))
    u2, u3, u4 = (np.exp(1j * t) for t in (th2, th3, th4))
    m = np.array([[(1j * b * u3).real, (-1j * c * u4).real],
                  [(1j * b * u3).imag, (-1j * c * u4).imag]])
    rhs = -1j * a * w2 * u2
    w3, w4 = np.linalg.solve(m, [rhs.real, rhs.imag])
    rhs = -(1j * a2 - w2 * w2) * a * u2 + w3 * w3 * b * u3 - w4 * w4 * c * u4
    _, al4 = np.linalg.solve(m, [rhs.real, rhs.imag])
    return th4, float(w4), float(al4)


@pytest.mark.parametrize("crank", [60.0, 0.0, 123.0, 200.0, 301.5])
def test_the_follower_lifts_by_the_program_at_the_rocker_s_angle(crank) -> None:
    data = _file()
    data["drive"]["angle"] = crank
    mech = from_dict(data, source=str(SRC))
    sol = mech.solve()
    th4, w4, a4 = four_bar(30.0, 110.0, 70.0, 100.0, math.radians(crank), 10.0, 3.0)
    assert abs(mech.cams[0].theta - th4 % (2 * math.pi)) < 1e-12
    assert abs(float(sol.angle_rad("4")) - th4) < 1e-12
    y = 10.0 * (1.0 - math.cos(th4))
    v = 10.0 * math.sin(th4) * w4
    acc = 10.0 * (math.cos(th4) * w4 * w4 + math.sin(th4) * a4)
    np.testing.assert_allclose(sol.position("T5"), [100.0, 40.0 + y], rtol=0, atol=1e-10)
    np.testing.assert_allclose(sol.velocity("T5"), [0.0, v], rtol=0, atol=1e-9)
    np.testing.assert_allclose(sol.acceleration("T5"), [0.0, acc], rtol=0, atol=1e-8)
    assert abs(mech.cams[0].Y - y) < 1e-10


def test_the_cycle_moves_the_follower_by_the_program_at_the_rocker_s_angle() -> None:
    mech = graphkin.load(SRC)
    sw = mech.sweep(count=36)
    c = sw.columns
    for k, crank in enumerate(np.asarray(c["drive"], dtype=float)):
        th4, w4, a4 = four_bar(30.0, 110.0, 70.0, 100.0, math.radians(crank), 10.0, 3.0)
        assert abs(c["y_T5"][k] - 40.0 - 10.0 * (1.0 - math.cos(th4))) < 1e-9
        assert abs(c["vy_T5"][k] - 10.0 * math.sin(th4) * w4) < 1e-8
        acc = 10.0 * (math.cos(th4) * w4 * w4 + math.sin(th4) * a4)
        assert abs(c["ay_T5"][k] - acc) < 1e-7 * (1.0 + abs(acc))
        assert abs(c["y_P"][k] - c["y_T5"][k] - 30.0) < 1e-9


ROCKER = st.tuples(st.floats(0.15, 0.45), st.floats(0.9, 1.6), st.floats(0.5, 1.1))


@settings(max_examples=12, deadline=None)
@given(cam=cams(kinds=(FollowerKind.ROLLER, FollowerKind.KNIFE_EDGE,
                       FollowerKind.OSCILLATING_ROLLER)),
       dims=ROCKER, crank=st.floats(0.0, 360.0), axis=st.sampled_from([90.0, 30.0, 200.0]),
       w2=st.floats(-20.0, 20.0), a2=st.floats(-50.0, 50.0))
def test_random_cams_on_random_rockers_are_the_cam_on_a_drive_at_the_rocker_s_angle(
        cam, dims, crank, axis, w2, a2) -> None:
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    d = 3.0 * size
    a, b, c = (k * d for k in dims)
    assume(a + max(b, c) < min(b, c) + d - 0.05 * d)       # Grashof, a crank-rocker: a shortest
    path = _TMP / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam))
    th4, w4, a4 = four_bar(a, b, c, d, math.radians(crank), w2, a2)
    O4 = [d, 0.0]
    on_rocker = {"units": "mm",
                 "links": {"1": {"O2": [0.0, 0.0], "O4": O4}, "2": {"O2": [0, 0], "A": [a, 0]},
                           "3": {"A": [0, 0], "B": [b, 0]}, "4": {"O4": [0, 0], "B": [c, 0]}},
                 "cams": {"link": 4, "follower": 5, "file": str(path), "axis": axis,
                          "center": "O4", "pivot": "Q5"},
                 "drive": {"link": 2, "angle": crank, "omega": w2, "alpha": a2},
                 "assembly": {"B": [d + c * math.cos(th4), c * math.sin(th4)]}}
    on_drive = {"units": "mm", "links": {"1": {"O4": O4}},
                "cams": {"link": 4, "follower": 5, "file": str(path), "axis": axis,
                         "center": "O4", "pivot": "Q5"},
                "drive": {"link": 4, "angle": math.degrees(th4), "omega": w4, "alpha": a4}}
    try:
        ref = from_dict(on_drive).solve()
    except GraphkinError:
        assume(False)           # no equivalent linkage at that angle (a straight pitch curve)
    mech = from_dict(on_rocker)
    sol = mech.solve()
    # Θ = s (θ4 − (axis − 90°)), taken into [0, 2π): equal on the circle
    big = mech.cams[0].theta - cam.s * (th4 - math.radians(axis - 90.0))
    assert abs(math.remainder(big, 2 * math.pi)) < 1e-9
    scale = size + abs(w4) * size + (w4 * w4 + abs(a4)) * size
    for n in ("T5", "K5"):
        np.testing.assert_allclose(sol.position(n), ref.position(n), rtol=0, atol=1e-9 * size)
    np.testing.assert_allclose(sol.velocity("T5"), ref.velocity("T5"), rtol=0,
                               atol=1e-9 * scale)
    np.testing.assert_allclose(sol.acceleration("T5"), ref.acceleration("T5"), rtol=0,
                               atol=1e-8 * scale)
    # over the cycle: solve of the file at each swept crank angle (its equivalent linkage there)
    sw = mech.sweep(count=3).columns
    for k, at in enumerate(np.asarray(sw["drive"], dtype=float)):
        there = dict(on_rocker, drive={**on_rocker["drive"], "angle": float(at)})
        try:
            got = from_dict(there).solve()
        except GraphkinError:
            continue             # no linkage there (a straight pitch curve), or no assembly
        for pre, v in (("", got.position("T5")), ("v", got.velocity("T5")),
                       ("a", got.acceleration("T5"))):
            for i, xy in enumerate("xy"):
                assert abs(sw[f"{pre}{xy}_T5"][k] - v[i]) < 1e-8 * scale, (pre, xy, at)


@settings(max_examples=10, deadline=None)
@given(crank=st.floats(0.0, 360.0), rel=st.sampled_from([1e-12, -1e-12, 4e-16]))
def test_the_verdicts_do_not_move_with_round_off(crank, rel) -> None:
    # the rocker's branch (pass one) and the roller's (the whole file), and the cam's angle,
    # at the crank and every length moved by 1e-12 of their size: the same posture
    data = _file()
    data["drive"]["angle"] = crank
    moved = copy.deepcopy(data)
    moved["drive"]["angle"] = crank * (1.0 + rel) + rel
    for pts in moved["links"].values():
        for n, xy in pts.items():
            pts[n] = [v * (1.0 + rel) for v in xy]
    s0, s1 = (from_dict(x, source="m.toml").solve() for x in (data, moved))
    for n in ("B", "K5", "T5", "P"):
        np.testing.assert_allclose(s0.position(n), s1.position(n), rtol=0, atol=1e-8)


def test_a_cam_its_follower_turns_is_refused_in_one_line() -> None:
    # the rocker pinned to the follower as well: the follower moves the cam's link, so the
    # linkage without the follower does not place it
    data = _file()
    data["links"]["5"]["B"] = [10.0, 0.0]
    with pytest.raises(InputError) as e:
        from_dict(data, source="m.toml")
    said = e.value.one_line()
    assert said.startswith("m.toml: cams[0].link: ") and "\n" not in said
    assert "not a drive" in said and "follower" in said


def test_a_cam_link_without_its_center_is_refused_in_one_line() -> None:
    data = _file()
    data["cams"][0]["center"] = "O2"       # the crank's pivot, not the rocker's
    with pytest.raises(InputError) as e:
        from_dict(data, source="m.toml")
    said = e.value.one_line()
    assert said.startswith("m.toml: cams[0].center: ") and "\n" not in said
    assert "O2" in said and "[links.4]" in said


def test_a_cam_on_a_link_not_pinned_to_the_frame_is_refused_in_one_line() -> None:
    # the cam moved onto the coupler 3 (A, B: neither a point of the frame): it has no
    # frame pivot to turn about, so no center can be named on it; said so, not "name O4"
    data = _file()
    data["cams"][0]["link"] = 3
    with pytest.raises(InputError) as e:
        from_dict(data, source="m.toml")
    said = e.value.one_line()
    assert said.startswith("m.toml: cams[0].link: ") and "\n" not in said
    assert "no pin with the frame" in said and "[links.1]" in said


@pytest.mark.parametrize("rocker", [{"O4": [0.0, 0.0]}, {"O4": [0.0, 0.0], "B": [0.0, 0.0]}])
def test_a_cam_link_whose_angle_two_points_do_not_define_is_refused_in_one_line(rocker) -> None:
    # the rocker reduced to its center (its pin B moved to another rocker, or onto O4)
    data = _file()
    data["links"]["4"] = rocker
    if "B" not in rocker:
        data["links"]["1"]["O6"] = [170.0, 0.0]
        data["links"]["6"] = {"O6": [0.0, 0.0], "B": [70.0, 0.0]}
    with pytest.raises(InputError) as e:
        from_dict(data, source="m.toml")
    said = e.value.one_line()
    assert said.startswith("m.toml: cams[0].link: ") and "\n" not in said
    assert "not defined by two of its points" in said


def test_a_cam_on_a_link_the_linkage_cannot_place_is_refused_in_one_line() -> None:
    # the rocker's pin B is the coupler's no more: link 4 turns free about O4
    data = _file()
    data["links"]["4"] = {"O4": [0.0, 0.0], "E": [70.0, 0.0]}
    data["links"]["1"]["O5"] = [150.0, 0.0]
    data["links"]["3"]["B"] = [110.0, 0.0]
    data["links"]["6"] = {"O5": [0.0, 0.0], "B": [70.0, 0.0]}
    data["assembly"] = {"B": [120, 60]}
    with pytest.raises(InputError) as e:
        from_dict(data, source="m.toml")
    said = e.value.one_line()
    assert said.startswith("m.toml: cams[0].link: ") and "\n" not in said


CHAIN = ROOT / "tests" / "data" / "live25" / "cam_on_cam_follower.toml"


@pytest.mark.parametrize("crank", [30.0, 100.0, 250.0])
def test_a_cam_on_an_earlier_cam_s_follower_turns_with_it(crank) -> None:
    # the second cam's angle is the first follower's θ4 (solved through the first cam's
    # equivalent linkage); its follower stands 40 + 10 (1 − cos θ4) mm above O4 (in inches)
    data = load_toml(CHAIN)
    for e in data["cams"]:
        e["file"] = str((CHAIN.parent / e["file"]).resolve())
    data["drive"]["angle"] = crank
    mech = from_dict(data, source=str(CHAIN))
    sol = mech.solve()
    th4 = float(sol.angle_rad("4"))
    assert abs(math.remainder(mech.cams[1].theta - th4, 2 * math.pi)) < 1e-12
    y = (40.0 + 10.0 * (1.0 - math.cos(th4))) / 25.4
    np.testing.assert_allclose(sol.position("T6"), [3.0, y], rtol=0, atol=1e-12)
    # ω4 and α4 carried through: Ẏ = 10 sin θ4 ω4, Ÿ = 10 (cos θ4 ω4² + sin θ4 α4)
    w4, a4 = float(sol.omega("4")), float(sol.alpha("4"))
    v = 10.0 * math.sin(th4) * w4 / 25.4
    acc = 10.0 * (math.cos(th4) * w4 * w4 + math.sin(th4) * a4) / 25.4
    np.testing.assert_allclose(sol.velocity("T6"), [0.0, v], rtol=0, atol=1e-10)
    np.testing.assert_allclose(sol.acceleration("T6"), [0.0, acc], rtol=0, atol=1e-9)


def test_a_cam_on_an_earlier_cam_s_follower_sweeps_as_solve_says() -> None:
    data = load_toml(CHAIN)
    for e in data["cams"]:
        e["file"] = str((CHAIN.parent / e["file"]).resolve())
    sw = from_dict(data, source=str(CHAIN)).sweep(count=12).columns
    for k, at in enumerate(np.asarray(sw["drive"], dtype=float)):
        there = dict(data, drive={**data["drive"], "angle": float(at)})
        got = from_dict(there).solve()
        for pre, v in (("", got.position("T6")), ("v", got.velocity("T6")),
                       ("a", got.acceleration("T6"))):
            assert abs(sw[f"{pre}y_T6"][k] - v[1]) < 1e-9 * (1.0 + abs(v[1])), (pre, at)


def test_a_cam_on_a_gear_sweeps_its_posture_and_refuses_its_rates_in_one_line() -> None:
    # tests/data/live25/cam_on_gear.toml: θ3 = −(θ2 − 40°)/2 by no slip (radii 30, 60 mm,
    # outside); the follower at 40 + 10 (1 − cos θ3) mm above O3 at every swept angle
    src = ROOT / "tests" / "data" / "live25" / "cam_on_gear.toml"
    data = load_toml(src)
    data["cams"][0]["file"] = str((src.parent / data["cams"][0]["file"]).resolve())
    with pytest.raises(InputError) as e:
        from_dict(data, source="g.toml").sweep(count=4)
    said = e.value.one_line()
    assert said.startswith("g.toml: cams: ") and "rolling" in said and "\n" not in said
    for k in ("omega", "alpha"):
        del data["drive"][k]
    c = from_dict(data, source="g.toml").sweep(count=24).columns
    th3 = -np.radians(np.asarray(c["drive"], dtype=float) - 40.0) / 2.0
    np.testing.assert_allclose(c["y_T4"], 40.0 + 10.0 * (1.0 - np.cos(th3)), rtol=0, atol=1e-9)
    np.testing.assert_allclose(c["x_T4"], 90.0, rtol=0, atol=1e-9)
