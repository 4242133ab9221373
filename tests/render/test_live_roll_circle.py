"""The live page of a gear train rolling on circles is the construction, with both polygons.

Example 11.7 (Fig. 11.17, a reverted planetary train) and the planet round a
fixed sun or in a fixed ring (examples/planetary_*.toml): each gear's angle is
laid off from its arm's by the ``roll_circle_angle`` step (no slip integrated
on the covering, Sec. 2.19, Sec. 7.15), so the page is the recorded
construction written out as JavaScript, with the velocity and acceleration
polygons, not Newton's method.  After random drags, and after the crank is
dragged round more than a whole turn, every position, velocity and
acceleration on the page equals ``graphkin solve`` of the file the page saves
(each contact's angle saved with it) to 1e-9.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from live_edit import homogeneous, same_as_saved_solve
from live_edit import page_file as _page
from strategies import examples
from strategies_rolling import rolling_arrangements

import graphkin
from graphkin.render.live import live_html

ROOT = Path(__file__).resolve().parents[2]
REL = 1e-9
FILES = ["gallery/gears/ex11_7.toml", "examples/planetary_outside.toml",
         "examples/planetary_inside.toml"]


def _same_as_solve(browser, tmp_path: Path) -> graphkin.Solution:
    return same_as_saved_solve(browser, tmp_path, REL)[1]


def _screen(browser) -> tuple[np.ndarray, float]:
    """The drive's pivot on the screen and the posture panel's scale (pixels per unit)."""
    st = browser.js("window.graphkinLive.state()")
    r = st["result"]
    tip = browser.js("(function () { var e = document.querySelector("
                     "'.gk-handle[data-kind=\"drive\"]'); var b = e.getBoundingClientRect();"
                     " return [b.x + b.width / 2, b.y + b.height / 2, e.getAttribute("
                     "'data-name')]; })()")
    mech_pivot, name = "O", tip[2]
    w_tip, w_piv = np.asarray(r[name]), np.asarray(r[mech_pivot])
    # the panel is a similarity with y pointing down: measure its scale from a second posture
    d = st["drive"]
    browser.js(f"window.graphkinLive.setDrive({d + 0.5!r})")
    tip2 = browser.js("(function () { var b = document.querySelector("
                      "'.gk-handle[data-kind=\"drive\"]').getBoundingClientRect();"
                      " return [b.x + b.width / 2, b.y + b.height / 2]; })()")
    w_tip2 = np.asarray(browser.js("window.graphkinLive.state()")["result"][name])
    browser.js(f"window.graphkinLive.setDrive({d!r})")
    s = math.hypot(tip2[0] - tip[0], tip2[1] - tip[1]) / float(np.hypot(*(w_tip2 - w_tip)))
    pivot = np.array([tip[0] - s * (w_tip[0] - w_piv[0]), tip[1] + s * (w_tip[1] - w_piv[1])])
    return pivot, s


def test_dragging_the_arm_round_one_and_a_half_turns_counts_on(browser, tmp_path):
    # Example 11.7: the arm 3 dragged by its pin A round O, 540° counterclockwise in steps of
    # 15°: the drive goes on past 2π (the covering), the gears turn with it at the train's
    # ratios (ω2/ω3 = -35/16, ω4/ω3 = 25/8: Example 7.4's train), and the page still equals
    # solve of its saved file
    browser.open(_page(tmp_path, ROOT / FILES[0]))
    st0 = browser.js("window.graphkinLive.state()")
    d0, th0 = st0["drive"], st0["result"]
    pivot, s = _screen(browser)
    start = np.asarray(th0["A"]) - np.asarray(th0["O"])
    rad = s * float(np.hypot(*start))
    a0 = math.atan2(start[1], start[0])
    pts = [pivot + rad * np.array([math.cos(a0 + t), -math.sin(a0 + t)])
           for t in np.radians(np.arange(0.0, 541.0, 15.0))]
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=pts[0][0], y=pts[0][1])
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=pts[0][0], y=pts[0][1],
                 button="left", clickCount=1)
    for p in pts[1:]:
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=p[0], y=p[1],
                     button="left", buttons=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=pts[-1][0],
                 y=pts[-1][1], button="left", clickCount=1)
    st = browser.js("window.graphkinLive.state()")
    turned = st["drive"] - d0
    assert abs(turned - 3 * math.pi) < 1e-6  # the pointer's own rounding, far below a step
    r = st["result"]
    for lid, ratio in (("3", 1.0), ("2", -35 / 16), ("4", 25 / 8)):
        np.testing.assert_allclose(r[f"θ{lid}"] - th0[f"θ{lid}"], ratio * turned, rtol=0,
                                   atol=1e-9 * 30, err_msg=f"θ{lid}")
    _same_as_solve(browser, tmp_path)
    assert browser.errors() == []


def test_the_instant_centers_follow_the_constructed_posture(browser, tmp_path):
    # Example 11.7 after a drag: the page's centers (I14, I24 at the pitch points on the line
    # of centers, Sec. 3.13) are graphkin's own centers of the saved file
    from graphkin.kinematics.instant_centers import instant_centers

    browser.open(_page(tmp_path, ROOT / FILES[0]))
    d = browser.js("window.graphkinLive.state()")["drive"]
    assert browser.js(f"window.graphkinLive.setDrive({d + 2.1!r})") is not None
    sol = _same_as_solve(browser, tmp_path)
    page = browser.js("window.graphkinLive.state()")["centers"]
    ic = instant_centers(sol)
    labels = [c.label for c in ic.centers.values()]
    assert {"I14", "I24"} <= set(labels) <= set(page)
    for lab in labels:
        got = np.asarray(homogeneous(page[lab]), dtype=float)
        want = np.asarray(ic.values[lab], dtype=float)
        np.testing.assert_allclose(got[:2] / got[2], want[:2] / want[2], rtol=0,
                                   atol=1e-9 * 5, err_msg=lab)
    assert browser.errors() == []


@examples(8)
@given(rm=st.one_of(rolling_arrangements("gears"), rolling_arrangements("gear chain"),
                    rolling_arrangements("planet")),
       steps=st.lists(st.floats(-4.0, 4.0), min_size=2, max_size=2))
def test_random_trains_and_drags_equal_solve(browser, tmp_path_factory, rm, steps):
    # random trains of tests/strategies_rolling.py (gears on fixed pivots, three in a row, a
    # planet round a fixed sun or in a ring, driven with its sun, driving a ring), dragged
    # by random drive steps of up to 4 rad: the page is the construction (no Newton), and
    # after each step it equals solve of the saved file to 1e-9
    tmp = tmp_path_factory.mktemp("trains")
    mech = rm.mechanism()
    page = tmp / "train.html"
    page.write_text(live_html(mech, rm.data, "train.toml"), encoding="utf-8")
    browser.open(page)
    assert browser.errors() == []
    assert browser.js("typeof gkNewton") == "undefined", rm.kind
    _same_as_solve(browser, tmp)
    for step in steps:
        d = browser.js("window.graphkinLive.state()")["drive"]
        assert browser.js(f"window.graphkinLive.setDrive({d + step!r})") is not None
        _same_as_solve(browser, tmp)
        assert _pitch_letters_off_their_panel(browser) == []
    assert browser.errors() == []


def _pitch_letters_off_their_panel(browser) -> list[str]:
    """The points of contact's letters (``c′₄ (4/2)``) whose box leaves their panel."""
    browser.js("window.graphkinLive.redraw(true)")
    return browser.js(
        "Array.from(document.querySelectorAll('.gk-pitch')).filter(function (e) {"
        " var r = e.getBoundingClientRect(), b = e.ownerSVGElement.getBoundingClientRect();"
        " return r.left < b.left || r.right > b.right || r.top < b.top"
        " || r.bottom > b.bottom; }).map(function (e) { return e.textContent; })")


def test_the_arm_between_a_driven_sun_and_a_fixed_ring_on_the_page(browser, tmp_path):
    # the sun 2 driven, the ring 1 fixed, the arm 4 the output (tests/kinematics/
    # test_roll_circle.py): the arm by planetary_arm, the planet by roll_circle_angle; the
    # sun turned 2.5 turns by steps, the page equals solve of its saved file, ω4 = ω2/3
    browser.open(_page(tmp_path, ROOT / "tests/data/sun_and_ring_planetary.toml"))
    assert browser.errors() == []
    assert browser.js("typeof gkNewton") == "undefined"
    st0 = browser.js("window.graphkinLive.state()")
    d0 = st0["drive"]
    for k in range(1, 11):
        assert browser.js(f"window.graphkinLive.setDrive({d0 + k * math.pi / 2!r})") is not None
        sol = _same_as_solve(browser, tmp_path)
        assert float(sol.omega("4")) == pytest.approx(2.0, abs=1e-9)
    r = browser.js("window.graphkinLive.state()")["result"]
    np.testing.assert_allclose(r["θ4"] - st0["result"]["θ4"], 5 * math.pi / 3, atol=1e-9)
    assert browser.errors() == []


def _cross(w: float, v: np.ndarray) -> np.ndarray:
    return w * np.array([-v[1], v[0]])


def test_the_pitch_points_images_are_drawn_and_are_no_slip(browser, tmp_path):
    # Example 11.7 after a drag: the points of contact on the line of centers, C at
    # R2 = 1.00 from O (gears 4 and 2) and P at R6 = 1.70 (gear 5 of 4 on the fixed 6).
    # Sec. 3.7: c₄ = c₂ one velocity image, V_C4 = V_A + ω4 × R_CA = ω2 × R_CO (no slip,
    # Eq. 3.13); on the frame V_C4 = 0, c₄ = c₁ at the pole. Sec. 4.7: each link's own
    # acceleration image, A_C4 = A_A + α4 × R_CA - ω4² R_CA, A_C2 = α2 × R_CO - ω2² R_CO
    browser.open(_page(tmp_path, ROOT / FILES[0]))
    d = browser.js("window.graphkinLive.state()")["drive"]
    assert browser.js(f"window.graphkinLive.setDrive({d + 2.0!r})") is not None
    browser.js("window.graphkinLive.redraw(true)")
    texts = browser.js("Array.from(document.querySelectorAll('.gk-pitch'))"
                       ".map(function (e) { return e.textContent; })")
    # the second contact is P, C being taken by the first (Sec. 3.7 names it P)
    assert set(texts) == {"c₄ = c₂", "p₄ = p₁", "c′₄ (4/2)", "c′₂", "p′₄ (4/1)"}
    assert _pitch_letters_off_their_panel(browser) == []
    sol = _same_as_solve(browser, tmp_path)
    r = browser.js("window.graphkinLive.state()")["result"]
    o, a = np.asarray(sol.position("O"), float), np.asarray(sol.position("A"), float)
    u = (a - o) / np.linalg.norm(a - o)
    va, aa = np.asarray(sol.velocity("A"), float), np.asarray(sol.acceleration("A"), float)
    w2, w4 = float(sol.omega("2")), float(sol.omega("4"))
    al2, al4 = float(sol.alpha("2")), float(sol.alpha("4"))
    ov, oa = np.asarray(r["o_v"]), np.asarray(r["o_a"])
    for key, radius in (("rolling[0]:C", 1.0), ("rolling[1]:P", 1.7)):
        c = o + radius * u
        v4 = va + _cross(w4, c - a)
        a4 = aa + _cross(al4, c - a) - w4 ** 2 * (c - a)
        np.testing.assert_allclose(np.asarray(r[f"a({key}@4)"]) - oa, a4, rtol=0,
                                   atol=1e-9 * 100)
        if key == "rolling[1]:P":
            np.testing.assert_allclose(v4, 0.0, rtol=0, atol=1e-9 * 10)  # on the fixed 6
            continue
        np.testing.assert_allclose(np.asarray(r[f"v({key}@4)"]) - ov, v4, rtol=0,
                                   atol=1e-9 * 10)
        np.testing.assert_allclose(v4, _cross(w2, c - o), rtol=0, atol=1e-9 * 10)
        np.testing.assert_allclose(np.asarray(r[f"a({key}@2):r"]) - oa,
                                   _cross(al2, c - o) - w2 ** 2 * (c - o), rtol=0,
                                   atol=1e-9 * 100)
    assert browser.errors() == []
