"""The live page's table prints round-off as 0; messages never move the panels; a let-go refits.

A crank standing straight up from its pivot has x = 0 by hand (O2 at the origin, A
at 90°: x_A = r cos 90° = 0), which ``r*cos(pi/2)`` computes as 6.1e-17 r; the
table used to print that as "6.12323e-16".  A value within 1e-9 of its column's
scale (graphkin/tolerance.py, VERDICT_REL) reads "0", as ``graphkin solve`` would
print it.  Skipped without Chromium.
"""

from __future__ import annotations

from pathlib import Path

from live_edit import page_file

from graphkin.cli import main

ROOT = Path(__file__).resolve().parents[2]

# a four-bar whose crank O2A (2 in, along link 2's own x axis) stands at 90°:
# A = (2 cos 90°, 2 sin 90°) = (0, 2) by hand
UPRIGHT = """
title = "crank straight up"
units = "in"
[links.1]
O2 = [0, 0]
O4 = [4, 0]
[links.2]
O2 = [0, 0]
A = [2, 0]
[links.3]
A = [0, 0]
B = [4, 0]
[links.4]
O4 = [0, 0]
B = [3, 0]
[drive]
link = 2
angle = 90
omega = 10
[assembly]
B = [3.5, 3]
"""

_CELLS = """[].map.call(document.querySelectorAll('#gk-table tr'), function (r) {
  return [].map.call(r.children, function (c) { return c.textContent; }); })"""


def _rows(browser) -> dict[str, list[str]]:
    return {r[0]: r[1:] for r in browser.js(_CELLS)[1:]}


def test_round_off_reads_zero(browser, tmp_path):
    path = tmp_path / "upright.toml"
    path.write_text(UPRIGHT, encoding="utf-8")
    browser.open(page_file(tmp_path, path))
    assert browser.errors() == []
    rows = _rows(browser)
    assert rows["A"][:2] == ["0", "2"], rows["A"]
    # no cell anywhere is round-off printed with an exponent
    assert not [c for r in rows.values() for c in r if "e-1" in c], rows


def test_gear_train_table_has_no_round_off(browser, tmp_path):
    # Example 7.4 laid out: A₂, the pitch point of gear 2, straight above O₂ at θ₂ = 0
    page = tmp_path / "ex7_4.html"
    assert main(["live", str(ROOT / "gallery/gears/ex7_4.toml"), "-o", str(page)]) == 0
    browser.open(page)
    assert browser.errors() == []
    rows = _rows(browser)
    assert not [c for r in rows.values() for c in r if "e-1" in c], rows


def test_a_long_message_does_not_move_the_panels(browser, tmp_path):
    browser.open(page_file(tmp_path, ROOT / "tests/data/spec/ex3_1_fourbar.toml"))
    top = "document.getElementById('gk-posture').getBoundingClientRect().top"
    before = browser.js(top)
    browser.js("document.getElementById('gk-status').textContent = "
               "'this posture cannot be assembled: ' + 'the coupler does not reach. '.repeat(12)")
    assert browser.js(top) == before


_SLIDE = """(function (deg) {
  var s = document.getElementById('gk-drive');
  s.value = String(deg);
  s.dispatchEvent(new Event('input'));
  s.dispatchEvent(new Event('change'));
  var out = [];
  ['gk-velocity', 'gk-acceleration'].forEach(function (id) {
    var svg = document.getElementById(id), b = svg.getBoundingClientRect();
    [].forEach.call(svg.querySelectorAll('circle, text'), function (c) {
      var r = c.getBoundingClientRect();
      var x = (r.left + r.right) / 2, y = (r.top + r.bottom) / 2;
      if (x < b.left || x > b.right || y < b.top || y > b.bottom) out.push([id, x, y]);
    });
  });
  return out;
})"""


def test_letting_go_of_the_slider_refits_the_polygons(browser, tmp_path):
    # Example 3.1 turned through its cycle with the drive slider: the velocity polygon at
    # θ2 = 120° is a fraction of its size at θ2 = 60° (V_B = ω2·O2B, the coupler and
    # rocker turning faster), so a polygon kept at the file's scale runs off its panel;
    # letting go refits every panel (issue 29: the full placement when the pointer stops).
    # Every vertex mark and letter of both polygons lies inside its panel.
    browser.open(page_file(tmp_path, ROOT / "tests/data/spec/ex3_1_fourbar.toml"))
    for deg in range(-180, 180, 20):  # the slider's whole range on this page (-180° to 180°)
        assert browser.js(_SLIDE + f"({deg})") == [], deg
