"""The live pages of the Scotch yoke and of Chapter 11's cam followers are constructions.

The yoke keeps its angle and is held by two slides (the frame's guide and
the block in its slot): one point of it lies on two lines that meet (Sec. 2.8,
case 3; posture.py ``two_slides``), so the page is the recorded construction
written out as JavaScript, with the velocity and acceleration polygons, not
Newton's method.  So is the follower of Examples 11.3 and 11.5, whose slot
passes through both bearings of the frame (its angle from the line through
them) and whose point A is then where its axis meets the cam's face.  After
random drags of the crank and of a frame pivot,
every position and image on the page equals ``graphkin solve`` of the file
the page saves to 1e-9.  Skipped without Chromium.
"""

from __future__ import annotations

import zlib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from live_edit import page_file as _page
from live_edit import same_as_saved_solve
from strategies import examples, scotch_yokes

from graphkin.files import load_toml
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_html

ROOT = Path(__file__).resolve().parents[2]
YOKE = ROOT / "gallery/centers/fig3_27_scotch_yoke.toml"
REL = 1e-9


def _same_as_solve(browser, tmp_path: Path) -> dict:
    return same_as_saved_solve(browser, tmp_path, REL)[0]


def test_random_drags_draw_both_polygons_equal_to_solve(browser, tmp_path):
    browser.open(_page(tmp_path, YOKE))
    assert browser.errors() == []
    assert browser.js("typeof gkNewton") == "undefined"
    assert browser.js("document.querySelectorAll('.gk-refused').length") == 0
    for panel in ("velocity", "acceleration"):
        assert browser.js(f"document.getElementById('gk-{panel}')"
                          ".querySelectorAll('line, path, polyline').length") > 0, panel
    _same_as_solve(browser, tmp_path)
    rng = np.random.default_rng(zlib.crc32(b"scotch yoke"))
    for step in rng.uniform(-2.5, 2.5, size=4):  # radians of the drive, from where it is
        d = browser.js("window.graphkinLive.state()")["drive"]
        assert browser.js(f"window.graphkinLive.setDrive({d + float(step)!r})") is not None
        r = _same_as_solve(browser, tmp_path)
        # Fig. 3.27 by hand: the yoke's foot F runs with A's x, 40 mm from O2 = (0, 0)
        assert abs(r["F"][0] - r["A"][0]) < 1e-9 * 60
    assert browser.errors() == []


def test_dragging_a_pivot_of_the_scotch_yoke(browser, tmp_path):
    # Fig. 3.27: drag the crank's pivot O2; the construction redraws from the moved pivot,
    # and the saved file (O2 moved) solves to the page's posture and rates
    browser.open(_page(tmp_path, YOKE))
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
    r = _same_as_solve(browser, tmp_path)
    saved = load_toml(tmp_path / "saved.toml")
    moved = [n for n in ("O2", "G0", "G1") if saved["links"]["1"][n] != load_toml(YOKE)[
        "links"]["1"][n]]
    assert len(moved) == 1
    assert r[moved[0]] == saved["links"]["1"][moved[0]]
    assert browser.errors() == []


@examples(8)
@given(rm=scotch_yokes(), steps=st.lists(st.floats(-3.0, 3.0), min_size=2, max_size=2))
def test_random_scotch_yokes_and_drags_equal_solve(browser, tmp_path_factory, rm, steps):
    # random Scotch yokes of tests/strategies.py (any guide and slot angle, slot offset,
    # crank), dragged by random drive steps: the page is the construction, and after each
    # step it equals solve of the saved file to 1e-9
    tmp = tmp_path_factory.mktemp("yokes")
    page = tmp / "yoke.html"
    page.write_text(live_html(rm.mechanism(), rm.data, "yoke.toml"), encoding="utf-8")
    browser.open(page)
    assert browser.errors() == []
    assert browser.js("typeof gkNewton") == "undefined"
    _same_as_solve(browser, tmp)
    for step in steps:
        d = browser.js("window.graphkinLive.state()")["drive"]
        assert browser.js(f"window.graphkinLive.setDrive({d + step!r})") is not None
        _same_as_solve(browser, tmp)
    assert browser.errors() == []


CAMS = ["gallery/mechanisms/ex11_3_cam_follower_four_force.toml",
        "gallery/mechanisms/ex11_5_cam_follower_friction.toml"]


@pytest.mark.parametrize("name", CAMS)
@pytest.mark.parametrize("rates", [False, True])
def test_the_cam_follower_pages_are_the_construction(browser, tmp_path, name, rates):
    # the files as they are (no rates: the posture and the force polygons), and with the
    # cam turning at ω2 = 12, α2 = -5 (both polygons); dragged ±30° about the file's drive,
    # where the face stays off the follower's axis
    data = load_toml(ROOT / name)
    if rates:
        data["drive"].update(omega=12.0, alpha=-5.0)
    mech = from_dict(data, source=name)
    page = tmp_path / "cam.html"
    page.write_text(live_html(mech, data, "cam.toml"), encoding="utf-8")
    browser.open(page)
    assert browser.errors() == []
    assert browser.js("typeof gkNewton") == "undefined"
    _same_as_solve(browser, tmp_path)
    d0 = browser.js("window.graphkinLive.state()")["drive"]
    rng = np.random.default_rng(zlib.crc32(name.encode()) + rates)
    for step in rng.uniform(-0.5, 0.5, size=3):
        assert browser.js(f"window.graphkinLive.setDrive({d0 + float(step)!r})") is not None
        r = _same_as_solve(browser, tmp_path)
        assert abs(r["A"][0]) < 1e-9 * 100  # on the follower's axis x = 0, through B and D
    assert browser.errors() == []
