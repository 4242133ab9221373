"""The curvature panel of a page that solves by Newton's method (render/live_newton.py).

Example 3.9's wheel (Fig. 3.18): away from the file's drive its pin B lies on
a trochoid that no ruler and compass meets, so the page finds the posture by
Newton's method; its polygons are constructed at that posture
(render/live_newton_polygons.py), and so is the curvature of the link
``graphkin draw -d curvature`` draws (the wheel, link 4), from the page's own
posture and polygons (render/live_curvature.py).  Read back from headless
Chromium after drags of the drive and of a frame pivot, the page's values must
be graphkin's curvature construction of the file the page saves, to 1e-9 of
the size, and for the wheel the textbook's (Secs. 4.13-4.14).  Skipped without
Chromium.
"""

from __future__ import annotations

import math
import zlib
from pathlib import Path

import numpy as np
import pytest
from live_edit import page_file, same_curvature

import graphkin
from graphkin.files import load_toml
from graphkin.kinematics.curvature.link import curvature
from graphkin.render.live import live_data

ROOT = Path(__file__).resolve().parents[2]
REL = 1e-9

WHEEL = "gallery/mechanisms/fig3_18_rolling_wheel.toml"
# every Newton page whose polygons are constructed at Newton's posture, with the link draw draws
NEWTON_CURVATURE = {WHEEL: "4", "examples/ex3_9_rolling_wheel.toml": "4",
                    "tests/data/hostile/point_drive_planetary.toml": "3",
                    "tests/data/inline/analytic-cam.toml": "4"}


def _page_curvature(browser, tmp_path: Path, data: dict) -> int:
    """The page's curvature against graphkin's of the file it saves; the values compared."""
    state = browser.js("window.graphkinLive.state()")
    assert state["result"] is not None and state["curvature"] is not None
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    sol = graphkin.load(saved).solve()
    lc = curvature(sol)[data["curvature"]["link"]]
    assert lc.construction is not None
    return same_curvature(data, state["curvature"], lc.values, 1.0 + sol.mechanism.scale,
                          steps=lc.construction.steps)


def _drawn(browser, note: str = "") -> None:
    """The panel is drawn (its inflection circle), with no line saying it is not (``note``:
    the start of the one line naming what it leaves out)."""
    said = browser.js("document.getElementById('gk-curvature-note').textContent")
    assert said.startswith(note) and bool(said) == bool(note) and "\n" not in said, said
    assert "No live curvature" not in said
    assert browser.js("document.querySelectorAll('#gk-curvature .gk-inflection-circle')"
                      ".length") == 1
    body = browser.js("document.body.innerText")
    assert "NaN" not in body and "Infinity" not in body


@pytest.mark.parametrize("name", sorted(NEWTON_CURVATURE))
def test_newtons_curvature_equals_graphkins_after_drags(browser, tmp_path, name):
    path = ROOT / name
    data, _ = live_data(graphkin.load(path), load_toml(path), path.name)
    assert data.get("newton") and data["curvature"]["link"] == NEWTON_CURVATURE[name]
    browser.open(page_file(tmp_path, path))
    assert browser.errors() == []
    # Example 3.9's file has α4 = 0 (the crank turns at a constant ω2 and ω3 = 0 there), so
    # graphkin's construction there has Γ = J and no Bresse circle; the page constructs both
    # for the α of each posture (construction/ops/bresse.py): nothing is left out, and after
    # a turn of the drive the Bresse circle is back, as in graphkin's of the saved file
    note = ""
    _drawn(browser, note)
    assert _page_curvature(browser, tmp_path, data) >= 4
    rng = np.random.default_rng(zlib.crc32(name.encode()))
    answered = 0
    for step in rng.uniform(-0.9, 0.9, size=3):  # radians of the drive, from where it is
        d = browser.js("window.graphkinLive.state()")["drive"]
        if browser.js(f"window.graphkinLive.setDrive({d + float(step)!r})") is None:
            browser.js(f"window.graphkinLive.setDrive({d!r})")  # not assembled: said so
            continue
        _drawn(browser, note)
        assert _page_curvature(browser, tmp_path, data) >= 4
        if "wheel" in name:
            assert browser.js("window.graphkinLive.state()")["curvature"]["Bresse circle"]
            assert browser.js("document.querySelectorAll('#gk-curvature .gk-bresse-circle')"
                              ".length") == 1
        answered += 1
    assert answered >= 1
    assert browser.errors() == []


def _wheel_by_hand(r: dict, v: dict) -> None:
    """Example 3.9's wheel (ρ = 100 on the ground y = 0), its curvature by hand.

    The wheel's velocity pole I is its point of contact, straight under the center
    G (Sec. 3.13); G moves on a straight line parallel to the ground, so it is on
    the inflection circle, diametrically opposite I: J = G, the circle on IG
    (Sec. 4.13).  The pin B's center of curvature B' lies on the ray IB with
    R_BJ_B R_BB' = R_BI² (Eq. 4.43), J_B where the ray meets the inflection circle
    again: the foot of the perpendicular from J to IB.
    """
    g, b = np.asarray(r["G"], dtype=float), np.asarray(r["B"], dtype=float)
    i = np.array([g[0], 0.0])
    tol = REL * 500
    np.testing.assert_allclose(v["I"], i, rtol=0, atol=tol)
    np.testing.assert_allclose(v["J"], g, rtol=0, atol=tol)
    np.testing.assert_allclose(v["inflection circle"], [*(i + g) / 2, 50.0], rtol=0, atol=tol)
    u = (b - i) / np.hypot(*(b - i))
    jb = i + np.dot(g - i, u) * u
    bj = jb - b
    b_prime = b + np.dot(b - i, b - i) / np.dot(bj, bj) * bj
    np.testing.assert_allclose(v["B'"], b_prime, rtol=0, atol=REL * float(np.abs(b_prime).max()))


def test_the_wheels_curvature_by_hand_while_dragging(browser, tmp_path):
    # the drive turned both ways, then the crank's pivot O2 dragged with the mouse: the panel
    # follows, and is the textbook's (and graphkin's of the saved file) at every stop
    path = ROOT / WHEEL
    data, _ = live_data(graphkin.load(path), load_toml(path), path.name)
    browser.open(page_file(tmp_path, path))
    state = browser.js("window.graphkinLive.state()")
    # at the file's posture (Example 3.9): B' = (200, -300) mm, ρ_B = 450 mm (solve says so)
    np.testing.assert_allclose(state["curvature"]["B'"], [200.0, -300.0], rtol=0, atol=1e-9)
    for deg in (65.0, 130.0, 90.0):
        assert browser.js(f"window.graphkinLive.setDrive({math.radians(deg)!r})") is not None
        state = browser.js("window.graphkinLive.state()")
        _wheel_by_hand(state["result"], state["curvature"])
    xy = browser.js("(function () { var r = document.querySelector('.gk-handle[data-kind="
                    "\"frame\"]').getBoundingClientRect(); return [r.x + r.width / 2,"
                    " r.y + r.height / 2]; })()")
    x0, y0 = xy
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0, y=y0)
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=x0, y=y0, button="left",
                 clickCount=1)
    for k in range(1, 5):
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0 + 4 * k, y=y0 - 2 * k,
                     button="left", buttons=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=x0 + 16, y=y0 - 8,
                 button="left", clickCount=1)
    state = browser.js("window.graphkinLive.state()")
    assert state["result"]["O2"] != [0, 0]
    _drawn(browser)
    _wheel_by_hand(state["result"], state["curvature"])
    assert _page_curvature(browser, tmp_path, data) >= 4
    assert browser.errors() == []


@pytest.mark.parametrize(("name", "words"), [
    ("examples/stephenson3_fallback.toml", "the curvature constructions start from the "
                                           "velocity and acceleration polygons"),
    ("tests/data/rolling/wheel_dead_point.toml", "the velocities and accelerations are "
                                                 "undetermined at the file's posture")])
def test_a_newton_page_without_the_panel_says_why(name, words):
    path = ROOT / name
    data, js = live_data(graphkin.load(path), load_toml(path), path.name)
    why = data["curvature"]["why"]
    assert why.startswith(words) and "\n" not in why and "link" not in data["curvature"]
    assert "function curvature(" not in js
