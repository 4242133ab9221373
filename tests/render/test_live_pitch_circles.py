"""The pitch circles on the live page's posture panel (render/live_pitch.py).

``graphkin draw`` draws every circle of a rolling contact (a planet's and its
sun's or ring's pitch circles, a wheel, a roller) numbered with its link; the
page draws them too and moves them with the drag.  Read back from the page's
SVG in headless Chromium, by id (``roller-<key>``, ``rolls-on-<key>``, as
draw's gids) after the drive is set to several angles: every circle is
centred on its gear's center and has its pitch radius, both as ``graphkin
solve`` of the file the page saves places them (the model's radii, the
solution's positions), and each link with a circle is numbered once.
Skipped without Chromium.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from live_edit import page_file

import graphkin
from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[2]
REL = 1e-9

FILES = ["gallery/gears/ex11_7.toml", "examples/planetary_inside.toml",
         "examples/planetary_outside.toml", "gallery/gears/ex7_1.toml",
         "gallery/mechanisms/fig3_18_rolling_wheel.toml"]

_READ = """(function () {
  var svg = document.getElementById('gk-posture'), b = svg.getBoundingClientRect();
  var vb = svg.getAttribute('viewBox').split(' ').map(Number);
  return {box: [b.x, b.y, b.width / vb[2], b.height / vb[3]],
          circles: [].map.call(svg.querySelectorAll('.gk-pitch-circle'), function (e) {
            return [e.id, +e.getAttribute('cx'), +e.getAttribute('cy'), +e.getAttribute('r'),
                    e.getAttribute('stroke'), e.getAttribute('fill')]; }),
          numbers: [].map.call(svg.querySelectorAll('.gk-link-number'), function (e) {
            return e.textContent; }),
          at: [].map.call(svg.querySelectorAll('.gk-link-number'), function (e) {
            return [e.getAttribute('data-link'), +e.getAttribute('x'),
                    +e.getAttribute('y') - 5]; })};
})()"""


def _expected(sol) -> dict[str, tuple[str, np.ndarray, float]]:
    """draw's circles of the solved file: id -> (link, center, radius), once each."""
    from graphkin.render.scene import safe_id

    out: dict[str, tuple[str, np.ndarray, float]] = {}
    seen: set[tuple[str, tuple[float, float], float]] = set()

    def add(cid: str, lid: str, c: np.ndarray, radius: float) -> None:
        key = (lid, (round(float(c[0]), 9), round(float(c[1]), 9)), round(radius, 12))
        if key not in seen:
            seen.add(key)
            out[cid] = (lid, c, radius)

    for r in sol.mechanism.rolling:
        add(f"roller-{safe_id(r.key)}", r.link,
            np.asarray(sol.position(r.center, r.link), dtype=float), r.radius)
        if r.on_center is not None and r.on_radius is not None:
            add(f"rolls-on-{safe_id(r.key)}", r.on,
                np.asarray(sol.links[r.on].position(r.on_center), dtype=float), r.on_radius)
    return out


def _check_circles(browser, tmp_path: Path) -> dict[str, tuple[str, np.ndarray, float]]:
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    sol = graphkin.load(saved).solve()
    want = _expected(sol)
    got = browser.js(_READ)
    x0, y0, kx, ky = got["box"]
    ids = {}
    for cid, cx, cy, r, stroke, fill in got["circles"]:
        suffix = next(k for k in want if cid.endswith("-" + k))  # the page prefixes its UID
        ids[suffix] = (cx, cy, r)
        assert fill == "none" and stroke in ("#000000", "#000"), stroke  # the links' ink
    assert set(ids) == set(want)
    size = 1.0 + sol.mechanism.scale
    for cid, (_, c, radius) in want.items():
        # the world point c and c + (radius, 0) in client pixels, by the page's own mapping
        p, q = (np.asarray(browser.js("window.graphkinLive.toClient('posture', "
                                      f"{[float(x) for x in v]!r})"))
                for v in (c, c + [radius, 0.0]))
        cx, cy, r = ids[cid]
        s = (q[0] - p[0]) / kx / radius  # SVG units per length unit
        np.testing.assert_allclose([x0 + cx * kx, y0 + cy * ky], p, rtol=0,
                                   atol=REL * size * s * kx, err_msg=cid)
        np.testing.assert_allclose(r, radius * s, rtol=REL, err_msg=cid)
    # each link with a circle numbered once, with its number (as draw numbers a link), inside
    # one of its circles, at 0.6 of its radius from the center (SVG units: the circle's own)
    assert sorted(got["numbers"]) == sorted({lid for lid, _, _ in want.values()})
    for lid, x, y in got["at"]:
        assert any(abs(math.hypot(x - ids[cid][0], y - ids[cid][1]) - 0.6 * ids[cid][2])
                   < 1e-6 * ids[cid][2] for cid, w in want.items() if w[0] == lid), lid
    return want


def _open(browser, tmp_path: Path, name: str) -> None:
    path = ROOT / name
    if "gears/ex7" in name:  # a gear file: the pair in mesh, written as a mechanism
        page = tmp_path / "gears.html"
        assert main(["live", str(path), "-o", str(page)]) == 0
    else:
        page = page_file(tmp_path, path)
    browser.open(page)
    assert browser.errors() == []


@pytest.mark.parametrize("name", FILES)
def test_the_pitch_circles_follow_the_drag(browser, tmp_path, name):
    _open(browser, tmp_path, name)
    _check_circles(browser, tmp_path)
    d0 = browser.js("window.graphkinLive.state()")["drive"]
    for turn in (0.35, -0.8):
        assert browser.js(f"window.graphkinLive.setDrive({d0 + turn!r})") is not None
        _check_circles(browser, tmp_path)
    assert browser.errors() == []


def test_example_11_7_by_the_book(browser, tmp_path):
    # Example 11.7 (Fig. 11.17): sun 2 (R = 1.00 in) and the fixed gear 6 (frame, R = 1.70 in)
    # about O; the compound planet 4-5 (R = 1.50 and 0.80 in) on the arm 3 at A, 2.50 in
    # from O (the file sets A at (0, 2.5) in the arm's coordinates: at the arm's angle θ3,
    # A = 2.5 (-sin θ3, cos θ3), (-2.5, 0) at the file's θ3 = 90°).  The arm driven to
    # θ3 = 130°: the planet's two circles are centred there, the sun's and gear 6's at O
    _open(browser, tmp_path, "gallery/gears/ex11_7.toml")
    assert browser.js(f"window.graphkinLive.setDrive({math.radians(130.0)!r})") is not None
    want = _check_circles(browser, tmp_path)
    a = 2.5 * np.array([-math.sin(math.radians(130.0)), math.cos(math.radians(130.0))])
    book = {"roller-rolling_0_": ("4", a, 1.5), "rolls-on-rolling_0_": ("2", [0, 0], 1.0),
            "roller-rolling_1_": ("4", a, 0.8), "rolls-on-rolling_1_": ("1", [0, 0], 1.7)}
    assert set(want) == set(book)
    for cid, (lid, c, radius) in book.items():
        assert want[cid][0] == lid and want[cid][2] == radius
        np.testing.assert_allclose(want[cid][1], c, rtol=0, atol=1e-12)
