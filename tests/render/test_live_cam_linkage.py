"""A cam on a link the linkage moves turns with it on the live page (the rocker of a four-bar).

tests/data/live25/cam_on_rocker.toml: a cam on the rocker of a crank-rocker four-bar,
its radial roller follower lifting Y = 10 (1 − cos θ4) mm.  The page turns the cam to
the rocker's angle as the posture's construction places the rocker
(render/live_cam_turn.py, ``via``), instead of holding the page at the file's angle.
Tested in headless Chromium: the crank dragged by its pin A, the follower's points
equal ``graphkin solve`` of the file the page saves (to 1e-9) and the closed form of
the rocker angle (Freudenstein's, tests/cams/test_cams_linkage.py).
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
from cam_strategies import cam_toml, cams
from hypothesis import assume, given, settings
from hypothesis import strategies as st
from live_cams_shared import drag, page_state, same_as_solve

import graphkin
from graphkin.cams import FollowerKind
from graphkin.errors import GraphkinError
from graphkin.files import load_toml
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data, live_html

ROOT = Path(__file__).resolve().parents[2]
SRC = ROOT / "tests" / "data" / "live25" / "cam_on_rocker.toml"
_TMP = Path(tempfile.mkdtemp(prefix="graphkin-live-cam-linkage-"))


def _file() -> dict:
    """The test file, its cam file's path made absolute (the page's saved file reads it)."""
    data = load_toml(SRC)
    data["cams"][0]["file"] = str((SRC.parent / data["cams"][0]["file"]).resolve())
    return data


def _lift(theta2: float) -> tuple[float, float]:
    """θ4 of the open four-bar (B above the ground line) and the roller's height above O4.

    O2 = 0, O4 = (100, 0), crank a = 30, coupler b = 110, rocker c = 70: B is on the
    circle of radius b about A = a e^{iθ2} and of radius c about O4, at the angle β
    from A → O4 given by the cosine rule, counterclockwise from it (the side of the
    file's hint B = (120, 60)); then θ4 = arg(B − O4), the lift Y = 10 (1 − cos θ4)
    (Θ = θ4: axis 90°, Eq. 6.12) and the roller's center T5 = O4 + (0, R0 + Y).
    """
    a, b, c, d = 30.0, 110.0, 70.0, 100.0
    ax, ay = a * math.cos(theta2), a * math.sin(theta2)
    ex, ey = d - ax, -ay                    # A → O4
    e = math.hypot(ex, ey)
    # B = A + b(cos, sin)(φ + β) with φ the direction A → O4 and cos β by the cosine rule
    beta = math.acos((b * b + e * e - c * c) / (2 * b * e))
    phi = math.atan2(ey, ex)
    bx, by = ax + b * math.cos(phi + beta), ay + b * math.sin(phi + beta)
    th4 = math.atan2(by, bx - d)
    return th4, 40.0 + 10.0 * (1.0 - math.cos(th4))


def test_the_cam_on_the_rocker_turns_not_held() -> None:
    data = _file()
    mech = from_dict(data, source=SRC.name)
    d, _ = live_data(mech, data, SRC.name)
    assert d.get("turn") is not None and d["cam"]["why"] == ""
    c = d["turn"]["cams"][0]
    assert c["via"] is not None and c["via"]["theta"] == "θ4"
    # the crank keeps its handle (its pin A): the page is dragged by it
    assert d["drive"]["pivot"] == "O2" and d["drive"]["tip"] == "A"


def test_dragging_the_crank_moves_the_follower_as_solve_says(browser, tmp_path) -> None:
    data = _file()
    mech = from_dict(data, source=SRC.name)
    page = tmp_path / "page.html"
    page.write_text(live_html(mech, data, SRC.name), encoding="utf-8")
    browser.open(page)
    # a drag of the crank's pin A about O2, by the pointer (a quarter turn back)
    r = browser.js("(function () { var r = document.querySelector('.gk-handle[data-kind="
                   "\"drive\"]').getBoundingClientRect(); return [r.x + r.width / 2, "
                   "r.y + r.height / 2]; })()")
    o = browser.js("window.graphkinLive.toClient('posture', "
                   "window.graphkinLive.state().result.O2)")
    rr, a0 = math.hypot(r[0] - o[0], r[1] - o[1]), math.atan2(r[1] - o[1], r[0] - o[0])
    a1 = a0 + math.radians(80.0)
    stop = (o[0] + rr * math.cos(a1), o[1] + rr * math.sin(a1))
    drag(browser, (r[0], r[1]), stop, n=8)
    shown = []
    for crank in (None, 150.0, 275.0):
        if crank is not None:
            browser.js(f"window.graphkinLive.setDrive({math.radians(crank)})")
        state = page_state(browser)
        res = state["result"]
        assert res is not None
        th2 = state["drive"]
        shown.append(math.degrees(th2))
        th4, y = _lift(th2)
        # the page's follower: the closed form of the rocker's angle, and solve's
        assert abs(res["θ4"] - th4) < 1e-9
        assert abs(res["T5"][0] - 100.0) < 1e-9 and abs(res["T5"][1] - y) < 1e-9
        assert abs(res["P"][1] - (y + 30.0)) < 1e-9
        same_as_solve(browser, tmp_path, mech, state)
        saved = graphkin.load(tmp_path / "saved.toml")
        assert abs(saved.cams[0].theta - th4 % (2 * math.pi)) < 1e-9
    # the drag turned the crank (the screen's y runs down: 80° clockwise on the page)
    assert abs((shown[0] - 60.0 + 80.0 + 180.0) % 360.0 - 180.0) < 3.0
    assert browser.errors() == []


def test_the_page_s_verdicts_do_not_move_with_round_off() -> None:
    # the page's words (convex, concave, undercut, straight), the roller's branch and the
    # rocker's angle at crank angles moved by a few ulps and by 1e-12: the same
    # (decisions on values above round-off, graphkin/tolerance.py)
    import json

    from jsrun import run_js

    data = _file()
    mech = from_dict(data, source=SRC.name)
    d, js = live_data(mech, data, SRC.name)
    angles = [math.radians(a) for a in (0.0, 37.0, 60.0, 95.0, 144.0, 181.0, 230.0, 300.0)]
    cases = [a * (1.0 + e) + e for a in angles for e in (0.0, 4e-16, -4e-16, 1e-12, -1e-12)]
    got = run_js(js + f"\nconst T = {json.dumps(d['turn'])}, K0 = {json.dumps(d['K'])};\n"
                 f"const I0 = {json.dumps(d['inputs'])};\n"
                 f"const RESULT = {json.dumps(cases)}.map((x) => {{ "
                 "const J = Object.assign({}, I0); J[T.label] = x; "
                 "const s = gkTurnSolve(T, J, K0.slice(), construction); "
                 "const n = gkTurnNote(T, s.t, x); return [s.t.why ? 'straight' : '', "
                 "(n.match(/convex|concave|undercut/g) || []).join(','), "
                 "s.r ? s.r['\u03b84'] : null, s.r ? s.r.T5 : null]; });")
    for k in range(0, len(cases), 5):
        words = {tuple(g[:2]) for g in got[k:k + 5]}
        assert len(words) == 1, (math.degrees(cases[k]), got[k:k + 5])
        for g in got[k:k + 5]:
            th4, y = _lift(cases[k])
            assert g[3] is not None and abs(g[2] - th4) < 1e-9
            assert abs(g[3][1] - y) < 1e-9 and abs(g[3][0] - 100.0) < 1e-9
    assert any("convex" in g[1] for g in got)


def test_a_cam_on_an_earlier_cam_s_follower_turns_on_the_page_as_solve_says() -> None:
    # tests/data/live25/cam_on_cam_follower.toml: the second cam turns with the first cam's
    # follower; the page's posture (run by node, or Chromium) at several crank angles equals
    # graphkin solve of the file at those angles
    import json

    from jsrun import run_js

    src = ROOT / "tests" / "data" / "live25" / "cam_on_cam_follower.toml"
    data = load_toml(src)
    for e in data["cams"]:
        e["file"] = str((src.parent / e["file"]).resolve())
    mech = from_dict(data, source=src.name)
    d, js = live_data(mech, data, src.name)
    assert d.get("turn") is not None, d["cam"]["why"]
    assert [c["via"] and c["via"]["theta"] for c in d["turn"]["cams"]] == [None, "θ4"]
    cranks = [30.0, 75.0, 140.0, 222.0, 333.0]
    got = run_js(js + f"\nconst T = {json.dumps(d['turn'])}, K0 = {json.dumps(d['K'])};\n"
                 f"const I0 = {json.dumps(d['inputs'])};\n"
                 f"const RESULT = {json.dumps([math.radians(c) for c in cranks])}.map((x) => "
                 "{ const J = Object.assign({}, I0); J[T.label] = x; "
                 "const s = gkTurnSolve(T, J, K0.slice(), construction); "
                 "return s.r ? [s.r.T6, s.r.P, s.r['v(T6)'], s.r['a(T6)']] : null; });")
    for crank, g in zip(cranks, got):
        there = dict(data, drive={**data["drive"], "angle": crank})
        sol = from_dict(there).solve()
        assert g is not None, crank
        for got_xy, ref in zip(g, (sol.position("T6"), sol.position("P"), sol.velocity("T6"),
                                   sol.acceleration("T6"))):
            np.testing.assert_allclose(got_xy, ref, rtol=0, atol=1e-9 * (1 + abs(ref).max()))


def _page_at(data: dict, source: str, cranks: list[float]) -> list:
    """The page's posture (run by node, or Chromium) at the crank angles (degrees)."""
    import json

    from jsrun import run_js

    mech = from_dict(data, source=source)
    d, js = live_data(mech, data, source)
    assert d.get("turn") is not None, d["cam"]["why"]
    return run_js(js + f"\nconst T = {json.dumps(d['turn'])}, K0 = {json.dumps(d['K'])};\n"
                  f"const I0 = {json.dumps(d['inputs'])};\n"
                  f"const RESULT = {json.dumps([math.radians(c) for c in cranks])}.map((x) => "
                  "{ const J = Object.assign({}, I0); J[T.label] = x; "
                  "const s = gkTurnSolve(T, J, K0.slice(), construction); return s.r; });")


@settings(max_examples=8, deadline=None)
@given(cam=cams(kinds=(FollowerKind.ROLLER, FollowerKind.KNIFE_EDGE,
                       FollowerKind.OSCILLATING_ROLLER)),
       dims=st.tuples(st.floats(0.15, 0.45), st.floats(0.9, 1.6), st.floats(0.5, 1.1)),
       crank=st.floats(0.0, 360.0), axis=st.sampled_from([90.0, 30.0, 200.0]),
       turns=st.lists(st.floats(-180.0, 180.0), min_size=2, max_size=3))
def test_random_cams_on_random_rockers_turn_on_the_page_as_solve_says(cam, dims, crank, axis,
                                                                     turns) -> None:
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    d = 3.0 * size
    a, b, c = (k * d for k in dims)
    assume(a + max(b, c) < min(b, c) + d - 0.05 * d)       # Grashof, a crank-rocker
    path = _TMP / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam))
    hint = complex(d, 0.0) + c * 1j              # B above the ground line: the open branch
    data = {"units": "mm",
            "links": {"1": {"O2": [0.0, 0.0], "O4": [d, 0.0]}, "2": {"O2": [0, 0], "A": [a, 0]},
                      "3": {"A": [0, 0], "B": [b, 0]}, "4": {"O4": [0, 0], "B": [c, 0]}},
            "cams": {"link": 4, "follower": 5, "file": str(path), "axis": axis,
                     "center": "O4", "pivot": "Q5"},
            "drive": {"link": 2, "angle": crank, "omega": 7.0, "alpha": -2.0},
            "assembly": {"B": [hint.real, hint.imag]}}
    try:
        from_dict(data, source="r.toml").solve()
    except GraphkinError:
        assume(False)            # no equivalent linkage at the file's angle (a straight curve)
    cranks = [crank + t for t in turns]
    got = _page_at(data, "r.toml", cranks)
    for at, r in zip(cranks, got):
        there = dict(data, drive={**data["drive"], "angle": at})
        try:
            sol = from_dict(there).solve()
        except GraphkinError:
            assert r is None, at           # no linkage there: the page shows no posture either
            continue
        assert r is not None, at
        for n in ("B", "K5", "T5"):
            np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=1e-9 * size)
        scale = size * (1.0 + 7.0 + 49.0 + 2.0) * (1.0 + abs(float(sol.omega("4"))) * 10)
        np.testing.assert_allclose(r["v(T5)"], sol.velocity("T5"), rtol=0, atol=1e-9 * scale)
        np.testing.assert_allclose(r["a(T5)"], sol.acceleration("T5"), rtol=0,
                                   atol=1e-8 * scale)


def test_a_cam_on_a_gear_turned_by_rolling_turns_on_the_page() -> None:
    # tests/data/live25/cam_on_gear.toml: θ3 = −(θ2 − 40°)/2 (no slip on the pitch circles,
    # 30 and 60 mm, outside), ω3 = −ω2/2, α3 = −α2/2; the follower at O3 + (0, 40 + Y),
    # Y = 10 (1 − cos θ3), Ẏ = 10 sin θ3 ω3, Ÿ = 10 (cos θ3 ω3² + sin θ3 α3)
    src = ROOT / "tests" / "data" / "live25" / "cam_on_gear.toml"
    data = load_toml(src)
    data["cams"][0]["file"] = str((src.parent / data["cams"][0]["file"]).resolve())
    cranks = [40.0, 95.0, 181.0, -77.0, 400.0]
    got = _page_at(data, src.name, cranks)
    for crank, r in zip(cranks, got):
        th3 = -math.radians(crank - 40.0) / 2.0
        w3, a3 = -2.0, -0.5
        assert r is not None, crank
        assert abs(math.remainder(r["θ3"] - th3, 2 * math.pi)) < 1e-12
        y = 10.0 * (1.0 - math.cos(th3))
        np.testing.assert_allclose(r["T4"], [90.0, 40.0 + y], rtol=0, atol=1e-9)
        np.testing.assert_allclose(r["v(T4)"], [0.0, 10.0 * math.sin(th3) * w3], rtol=0,
                                   atol=1e-9)
        acc = 10.0 * (math.cos(th3) * w3 * w3 + math.sin(th3) * a3)
        np.testing.assert_allclose(r["a(T4)"], [0.0, acc], rtol=0, atol=1e-9)
