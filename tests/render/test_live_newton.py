"""The live page of a mechanism only Newton's method solves (render/live_newton.py).

A rolling contact whose roller turns with its travel and is found with its
position (Example 3.9's wheel): the page runs Newton's method on the analytic solver's rows
written out as JavaScript (kinematics/analytic/jsrows.py) from the previous
posture.  After random drags, every value the page shows
(read in headless Chromium) must be what ``graphkin solve`` says of the file
the page saves, to 1e-9 of its scale; the rolling contact's saved angle makes
that file's posture the page's.  Skipped without Chromium.
"""

from __future__ import annotations

import math
import zlib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from live_edit import homogeneous
from live_edit import page_file as _page
from strategies import examples, scotch_yokes
from strategies_rolling import rolling_arrangements

import graphkin
from graphkin.files import load_toml
from graphkin.render.live import live_html

ROOT = Path(__file__).resolve().parents[2]
REL = 1e-9

NEWTON = ["gallery/mechanisms/fig3_18_rolling_wheel.toml",
          "examples/ex3_9_rolling_wheel.toml"]




def _said_why(status: str) -> bool:
    """The page's one line for a posture it cannot show: not assembled, or no polygons."""
    return "cannot be assembled" in status or "polygons have no clean construction" in status


def _same_as_solve(browser, tmp_path: Path, wheel: bool = False) -> dict:
    """Positions, velocities and accelerations of the page against solve of its saved file.

    ``wheel``: Example 3.9's wheel, whose polygons the page constructs at Newton's posture.
    """
    r = browser.js("window.graphkinLive.state()")["result"]
    assert r is not None
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    sol = graphkin.load(saved).solve()
    mech = sol.mechanism
    names = [n for lid, lk in mech.links.items() if lid != "1" for n in lk.points]
    scale = 1.0 + max(abs(v) for n in names for v in r[n])
    for n in names:
        np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=REL * scale, err_msg=n)
    if mech.has_rates:
        for pre, of in (("v", sol.velocity), ("a", sol.acceleration)):
            s = 1.0 + max(abs(v) for n in names for v in r[f"{pre}({n})"])
            for n in names:
                np.testing.assert_allclose(r[f"{pre}({n})"], of(n), rtol=0, atol=REL * s,
                                           err_msg=f"{pre}({n})")
        for lid in mech.links:
            np.testing.assert_allclose(r[f"ω{lid}"], sol.omega(lid), rtol=0,
                                       atol=REL * (1 + abs(sol.omega(lid))))
            np.testing.assert_allclose(r[f"α{lid}"], sol.alpha(lid), rtol=0,
                                       atol=REL * (1 + abs(sol.alpha(lid))))
        if wheel:
            # the saved file's polygons are constructed ("Solved by the graphic
            # constructions"), and so are the page's: the wheel's contact point c'4 is the
            # construction's own image (Eq. 4.19); on straight ground it is ω4² ρ from C
            # toward the center G (a_G = -α ρ along the ground cancels α × R_CG)
            assert sol.method == "construction"
            lab = "a(rolling[0]:C@4)"
            ca = np.asarray(r[lab]) - np.asarray(r["o_a"])
            acc = sol.values["acceleration"]
            np.testing.assert_allclose(ca, np.asarray(acc[lab])[:2] - np.asarray(acc["o_a"])[:2],
                                       rtol=0, atol=REL * s)
            g, w = np.asarray(r["G"]), float(r["ω4"])
            c = np.array([g[0], 0.0])  # the ground is the line y = 0 in both files
            np.testing.assert_allclose(ca, w * w * (g - c), rtol=0, atol=REL * s)
    return r


@pytest.mark.parametrize("name", NEWTON)
def test_random_drags_equal_solve_of_the_saved_file(browser, tmp_path, name):
    path = ROOT / name
    browser.open(_page(tmp_path, path))
    assert browser.errors() == []
    _same_as_solve(browser, tmp_path, wheel=True)
    # the wheel's polygons are constructed at Newton's posture (live_newton_polygons.py):
    # drawn, none refused, with the contact's images lettered as in Fig. 3.18
    why = browser.js("[].map.call(document.querySelectorAll('.gk-refused'),"
                     " function (e) { return e.textContent; })")
    assert why == []
    for panel in ("velocity", "acceleration"):
        shown = browser.js(f"getComputedStyle(document.getElementById('gk-{panel}')"
                           ".parentNode).display")
        assert shown != "none"
    pitch = browser.js("[].map.call(document.querySelectorAll('.gk-pitch'),"
                       " function (e) { return e.textContent; })")
    assert "c₄ = c₁" in pitch and "c′₄" in pitch
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    answered = 0
    for step in rng.uniform(-1.2, 1.2, size=4):  # radians of the drive, from where it is
        d = browser.js("window.graphkinLive.state()")["drive"]
        r = browser.js(f"window.graphkinLive.setDrive({d + float(step)!r})")
        if r is None:  # cannot be assembled there: said so, never NaN
            assert _said_why(browser.js("document.getElementById('gk-status').textContent"))
            body = browser.js("document.body.innerText")
            assert "NaN" not in body and "Infinity" not in body
            browser.js(f"window.graphkinLive.setDrive({d!r})")
            continue
        _same_as_solve(browser, tmp_path, wheel=True)
        answered += 1
    assert answered >= 1
    assert browser.errors() == []


def test_a_posture_without_a_polygon_construction_is_null_not_nan(browser, tmp_path):
    # the polygons read the posture's points only: with the coupler's pin B moved onto A
    # (R_BA = 0, no direction for V_BA ⊥ R_BA, Sec. 3.4) the construction has no clean
    # answer: null, and the page's one line for it names the polygons
    browser.open(_page(tmp_path, ROOT / "examples/ex3_9_rolling_wheel.toml"))
    got = browser.js("(function () { var r = window.graphkinLive.state().result;"
                     " var out = Object.assign({}, r, {B: r.A});"
                     " return [gkNewtonPolygons(GKN.polygons, Object.assign({}, r)) !== null,"
                     " gkNewtonPolygons(GKN.polygons, out), GKN.polygons.why]; })()")
    assert got[0] is True and got[1] is None
    assert "polygons have no clean construction" in got[2] and "NaN" not in got[2]


def test_the_wheel_rolls_its_travel(browser, tmp_path):
    # Example 3.9 (Fig. 3.18): the wheel of radius 100 rolls on the ground, so its center G
    # moves along the ground by -ρ Δθ4 (to the left as the wheel turns counterclockwise)
    browser.open(_page(tmp_path, ROOT / "gallery/mechanisms/fig3_18_rolling_wheel.toml"))
    r0 = browser.js("window.graphkinLive.state()")["result"]
    r1 = browser.js(f"window.graphkinLive.setDrive({math.radians(90.0 - 25.0)!r})")
    assert r1 is not None
    dth = r1["θ4"] - r0["θ4"]
    assert abs(dth) > 0.01
    np.testing.assert_allclose(r1["G"][0] - r0["G"][0], -100.0 * dth, rtol=0, atol=1e-9 * 300)
    assert abs(r1["G"][1] - 100.0) < 1e-9 * 300  # the center stays one radius up
    # back to the file's drive: the wheel is where it was (no slip, the same path back)
    r2 = browser.js(f"window.graphkinLive.setDrive({math.radians(90.0)!r})")
    np.testing.assert_allclose(r2["G"], r0["G"], rtol=0, atol=1e-9 * 300)


def test_dragging_a_pivot_of_the_rolling_wheel(browser, tmp_path):
    # Fig. 3.18: drag the crank's pivot O2; Newton follows from the posture before, and the
    # saved file (O2 moved) solves to the page's posture and rates
    browser.open(_page(tmp_path, ROOT / "gallery/mechanisms/fig3_18_rolling_wheel.toml"))
    xy = browser.js("(function () { var r = document.querySelector('.gk-handle[data-kind="
                    "\"frame\"]').getBoundingClientRect(); return [r.x + r.width / 2,"
                    " r.y + r.height / 2]; })()")
    x0, y0 = xy
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0, y=y0)
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=x0, y=y0, button="left",
                 clickCount=1)
    for k in range(1, 5):
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0 + 3 * k, y=y0 - 2 * k,
                     button="left", buttons=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=x0 + 12, y=y0 - 8,
                 button="left", clickCount=1)
    r = _same_as_solve(browser, tmp_path, wheel=True)
    saved = load_toml(tmp_path / "saved.toml")
    assert saved["links"]["1"]["O2"] != [0, 0]
    assert r["O2"] == saved["links"]["1"]["O2"]
    assert browser.errors() == []


def test_the_coupler_curve_is_the_analytic_sweep(browser, tmp_path):
    # a rack sliding under a driven pinion (graphkin has no step yet laying off the rack's
    # travel from the pinion's angle) over the whole turn, from the page, against
    # graphkin's sweep (Newton's method in Python, each posture from the one before)
    path = ROOT / "tests/data/rolling/rack_under_driven_pinion.toml"
    browser.open(_page(tmp_path, path))
    state = browser.js("window.graphkinLive.state()")
    mech = graphkin.load(path)
    start = math.degrees(state["drive"])
    sw = mech.sweep(count=360, start=start)
    for n, curve in state["curves"].items():
        got = np.array([p if p is not None else [np.nan, np.nan] for p in curve], dtype=float)
        x, y = sw.columns[f"x_{n}"], sw.columns[f"y_{n}"]
        assert np.all(np.isfinite(got[:, 0]) == np.isfinite(x))
        ok = np.isfinite(x)
        np.testing.assert_allclose(got[ok, 0], x[ok], rtol=0, atol=1e-9 * 200)
        np.testing.assert_allclose(got[ok, 1], y[ok], rtol=0, atol=1e-9 * 200)
    # drawing the curves left the posture where it was
    assert browser.js("window.graphkinLive.state()")["result"] == state["result"]


def _same_as_sweep(r: dict, mech, path: np.ndarray, tol_scale: float) -> None:
    """The page's values at the end of ``path`` against graphkin's analytic sweep along it."""
    from graphkin.kinematics.analytic import solve_analytic_many

    sol = solve_analytic_many(mech, path)
    assert bool(np.asarray(sol.valid)[-1])
    names = [n for lid, lk in mech.links.items() if lid != "1" for n in lk.points]
    for n in names:
        np.testing.assert_allclose(r[n], np.asarray(sol.position(n))[-1], rtol=0,
                                   atol=REL * tol_scale, err_msg=n)
    if not mech.has_rates:
        return
    for pre, of in (("v", sol.velocity), ("a", sol.acceleration)):
        pole = r["o_" + pre]
        got = {n: np.subtract(r[f"{pre}({n})"], pole) for n in names if f"{pre}({n})" in r}
        # a construction page gives the images of the moving points only (a train of gears
        # on fixed pivots has none: its rates are the links' ω and α)
        s = 1.0 + max((abs(v) for x in got.values() for v in x), default=0.0)
        for n, x in got.items():
            np.testing.assert_allclose(x, np.asarray(of(n))[-1], rtol=0, atol=REL * s,
                                       err_msg=f"{pre}({n})")


@examples(10)
@given(rm=st.one_of(rolling_arrangements(), scotch_yokes()),
       steps=st.lists(st.floats(-0.6, 0.6), min_size=2, max_size=2))
def test_random_mechanisms_and_drags_equal_the_sweep(browser, tmp_path_factory, rm, steps):
    # every rolling arrangement of tests/strategies_rolling.py (a construction page when the
    # roller's angle follows its travel by a step, else Newton's method) and random Scotch
    # yokes (a construction page: two slides meet, case 3), dragged by random drive
    # steps: the page's values are graphkin's analytic sweep along the same path of drive
    # values (each posture continuing the one before)
    tmp = tmp_path_factory.mktemp("newton")
    mech = rm.mechanism()
    page = tmp / "random.html"
    page.write_text(live_html(mech, rm.data, "random.toml"), encoding="utf-8")
    browser.open(page)
    assert browser.errors() == []
    d0 = browser.js("window.graphkinLive.state()")["drive"]
    assert browser.js("window.graphkinLive.state()")["result"] is not None
    angle = mech.drives[0].kind in ("angle", "relative")
    done = [d0]
    for step in steps:
        step = step if angle else step * 0.2 * rm.scale()
        d = browser.js("window.graphkinLive.state()")["drive"]
        r = browser.js(f"window.graphkinLive.setDrive({d + step!r})")
        if r is None:
            assert _said_why(browser.js("document.getElementById('gk-status').textContent"))
            browser.js(f"window.graphkinLive.setDrive({d!r})")
            continue
        done.append(d + step)
        # the same path of drive values, in steps of at most 1° (or 1 % of the size)
        dense = [d0]
        for a, b in zip(done, done[1:]):
            n = max(1, math.ceil(abs(b - a) / (math.radians(1.0) if angle else
                                               0.01 * rm.scale())))
            dense += list(np.linspace(a, b, n + 1)[1:])
        vals = np.array(dense)
        if len(mech.drives) > 1:
            vals = np.column_stack([vals] + [np.full_like(vals, x.value)
                                             for x in mech.drives[1:]])
        _same_as_sweep(r, mech, vals, rm.scale())
    assert browser.errors() == []


def test_a_roller_turning_with_its_travel_is_constructed_on_the_page(browser, tmp_path):
    # Example 4.8 (Fig. 4.20): the roller 4 is pinned to the crank at its center B, so its
    # angle follows its travel along the follower's face by one step (roll_angle,
    # θ4 = θ3 + c - σ s/ρ): the page is the construction with both polygons, and after
    # drags it equals solve of the saved file (the roller's angle saved with it)
    browser.open(_page(tmp_path, ROOT / "gallery/mechanisms/fig4_20_roller_follower.toml"))
    assert browser.js("document.querySelectorAll('.gk-refused').length") == 0
    assert browser.js("window.graphkinLive.state()")["result"]["o_v"] is not None
    # near θ2 = 0 the roller cannot reach the face (graphkin's sweep: nothing from -30° to
    # 30°): the page says so there, like the sweep
    sw = graphkin.load(ROOT / "gallery/mechanisms/fig4_20_roller_follower.toml").sweep(
        count=1, start=0.0)
    assert not bool(sw.assembled[0])
    assert browser.js("window.graphkinLive.setDrive(0)") is None
    for deg in (70.0, 130.0, -100.0, 170.0):
        assert browser.js(f"window.graphkinLive.setDrive({math.radians(deg)!r})") is not None
        r = browser.js("window.graphkinLive.state()")["result"]
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        sol = graphkin.load(saved).solve()
        for n in ("B", "F1", "F2"):
            np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=1e-9 * 10)
            v = np.subtract(r[f"v({n})"], r["o_v"])
            a = np.subtract(r[f"a({n})"], r["o_a"])
            np.testing.assert_allclose(v, sol.velocity(n), rtol=0, atol=1e-9 * 100)
            np.testing.assert_allclose(a, sol.acceleration(n), rtol=0, atol=1e-9 * 1000)
        np.testing.assert_allclose(r["θ4"], float(sol.angle_rad("4")), rtol=0, atol=1e-9)
    assert browser.errors() == []


@pytest.mark.parametrize("name", ["gallery/mechanisms/fig3_18_rolling_wheel.toml",
                                  "tests/data/rolling/planet_driven_relative_to_arm.toml"])
def test_the_instant_centers_follow_newtons_posture(browser, tmp_path, name):
    # the centers `graphkin draw -d centers` draws (a rolling contact's I14 at the foot of
    # the normal from the wheel's center, Sec. 3.13; a pin in a slot's center on the normal
    # to the slot; two gears' center on their line of centers), re-found on the page from
    # Newton's posture after a drag: graphkin's own centers of the saved file
    from graphkin.kinematics.instant_centers import instant_centers

    browser.open(_page(tmp_path, ROOT / name))
    d = browser.js("window.graphkinLive.state()")["drive"]
    assert browser.js(f"window.graphkinLive.setDrive({d + 0.3!r})") is not None
    _same_as_solve(browser, tmp_path)
    page = browser.js("window.graphkinLive.state()")["centers"]
    ic = instant_centers(graphkin.load(tmp_path / "saved.toml").solve())
    labels = [c.label for c in ic.centers.values()]
    assert labels and set(labels) <= set(page)
    size = graphkin.load(ROOT / name).scale
    for lab in labels:
        got = np.asarray(homogeneous(page[lab]), dtype=float)
        want = np.asarray(ic.values[lab], dtype=float)
        if abs(want[2]) > 1e-9:  # finite: the same point
            w = want[:2] / want[2]  # a far center (nearly parallel lines) carries more error
            np.testing.assert_allclose(got[:2] / got[2], w, rtol=0,
                                       atol=1e-9 * (size + float(np.hypot(*w))), err_msg=lab)
        else:  # at infinity: the same direction
            assert abs(got[2]) < 1e-9 * max(abs(got[0]), abs(got[1]))
            assert abs(got[0] * want[1] - got[1] * want[0]) < 1e-9, lab
    assert browser.errors() == []


# every Newton page whose file's posture has its polygons by construction (the wheel's above)
# (the rack under a driven pinion is saved as drawn, not where the pinion rolled it: its
# positions are not the saved file's, see docs/how-to/live.md)
CONSTRUCTED_AT_NEWTON = ["tests/data/hostile/point_drive_planetary.toml",
                         "tests/data/inline/analytic-cam.toml"]


@pytest.mark.parametrize("name", CONSTRUCTED_AT_NEWTON)
def test_polygons_at_newtons_posture_equal_solve(browser, tmp_path, name):
    # drawn (no panel refused), and after drags of the drive equal to solve of the saved file
    browser.open(_page(tmp_path, ROOT / name))
    assert browser.errors() == []
    assert browser.js("document.querySelectorAll('.gk-refused').length") == 0
    _same_as_solve(browser, tmp_path)
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    for step in rng.uniform(-0.6, 0.6, size=3):
        d = browser.js("window.graphkinLive.state()")["drive"]
        r = browser.js(f"window.graphkinLive.setDrive({d + float(step)!r})")
        if r is None:
            body = browser.js("document.body.innerText")
            assert "NaN" not in body and "Infinity" not in body
            browser.js(f"window.graphkinLive.setDrive({d!r})")
            continue
        _same_as_solve(browser, tmp_path)
    assert browser.errors() == []


def test_a_dead_point_file_says_so_in_one_line(browser, tmp_path):
    # Example 3.9 at its dead point (A, B and the contact C in line, Sec. 3.5): Newton's
    # posture has no rates and the polygons' ⊥BA and ⊥BC are one line: nothing drawn, one
    # line said, never NaN
    browser.open(_page(tmp_path, ROOT / "tests/data/rolling/wheel_dead_point.toml"))
    assert browser.errors() == []
    assert browser.js("window.graphkinLive.state()")["result"] is None
    said = browser.js("document.getElementById('gk-status').textContent")
    assert "dead center" in said and "\n" not in said
    body = browser.js("document.body.innerText")
    assert "NaN" not in body and "Infinity" not in body


def test_a_subnormal_speed_draws_no_infinite_polygon(browser, tmp_path):
    # found by the random Scotch yokes: ω2 = 2.2e-313 rad/s puts every velocity image within
    # 1e-313 of the pole; the panel's scale (its size over that extent) overflowed to
    # Infinity and the links' image outlines had "-Infinity" points (a console error)
    from graphkin.mechanisms import from_dict

    data = {"units": {"length": "m"},
            "links": {"1": {"O2": [0.72, 0.0], "G0": [0.76, -1.05], "G1": [1.76, -1.01]},
                      "2": {"O2": [0.0, 0.0], "A": [0.57, 0.0]}, "3": {"A": [0.0, 0.0]},
                      "4": {"F": [0.0, 0.0], "S0": [0.125, 0.546], "S1": [-0.193, 1.494]}},
            "sliders": [{"link": 3, "on": 4, "point": "A", "line": ["S0", "S1"]},
                        {"link": 4, "on": 1, "point": "F", "line": ["G0", "G1"]}],
            "drive": {"link": 2, "angle": 38.5, "omega": 2.2250738585e-313, "alpha": -48.0},
            "assembly": {"F": [1.38, -1.02]}}
    page = tmp_path / "yoke.html"
    page.write_text(live_html(from_dict(data, source="yoke"), data, "yoke.toml"),
                    encoding="utf-8")
    browser.events = []
    browser.open(page)
    d = browser.js("window.graphkinLive.state()")["drive"]
    browser.js(f"window.graphkinLive.setDrive({d + 0.8!r})")
    assert browser.errors() == []
    svg = browser.js("document.getElementById('gk-velocity').innerHTML")
    assert "Infinity" not in svg and "NaN" not in svg
