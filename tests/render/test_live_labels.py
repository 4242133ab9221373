"""The live page's labels are written as ``graphkin draw`` writes them.

Read back from the page's SVG in headless Chromium: the poles are O with a
subscript V or A (draw's mathtext ``$O_V$``, ``$O_A$``), not "O_V"; a point's
trailing digits are subscripts (``O2`` -> ``O₂``, render/scene.py
``point_text``); the images are lowercase, primed in the acceleration polygon
(``a(B)`` -> ``b′``, render/paint.py ``image_text``; Secs. 3.5 and 4.3); an
instant center's digits are subscripts (``I13`` -> ``I₁₃``); a curvature
label's part after "_" is a subscript (``G_N``); a force is named as ``draw -d
forces`` names it (``P₄``, render/forces.py ``force_name``).  The expected
texts come from draw's own Python functions, the page's from its JavaScript.
Skipped without Chromium.
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from live_edit import page_file

import graphkin
from graphkin.render.forces import force_name
from graphkin.render.kennedy import _pretty as center_text
from graphkin.render.paint import image_text
from graphkin.render.scene import point_text

ROOT = Path(__file__).resolve().parents[2]

# a four-bar with a coupler point (Example 3.1), a dynamic four-bar with loads and inertia
# forces (Example 12.4: G3, O2, P4, -m3A_G3), Example 12.3 (Hain's G_N in the curvature
# panel) and the rolling wheel (Example 3.9, its page solved by Newton's method)
FILES = ["tests/data/spec/ex3_1_fourbar.toml", "gallery/mechanisms/ex12_4_fourbar_dynamic.toml",
         "gallery/mechanisms/ex12_3_elliptic_trammel.toml",
         "gallery/mechanisms/fig3_18_rolling_wheel.toml"]

_READ = """(function () {
  var out = {};
  ['posture', 'velocity', 'acceleration', 'kennedy', 'curvature', 'forces', 'bodies']
    .forEach(function (p) {
      var svg = document.getElementById('gk-' + p);
      out[p] = svg ? [].map.call(svg.querySelectorAll('text'), function (e) {
        return [e.textContent, [].map.call(e.querySelectorAll('tspan.gk-sub'),
          function (t) { return [t.textContent, t.getAttribute('dy')]; })]; }) : [];
    });
  out.poles = [].map.call(document.querySelectorAll('.gk-pole'), function (e) {
    return [e.firstChild.nodeValue, e.querySelector('tspan.gk-sub').textContent,
            e.closest('svg').id]; });
  return out;
})()"""


@pytest.mark.parametrize("name", FILES)
def test_the_pages_labels_are_draws(browser, tmp_path, name):
    browser.open(page_file(tmp_path, ROOT / name))
    assert browser.errors() == []
    D = json.loads(browser.js("document.getElementById('gk-data').textContent"))
    d = browser.js("window.graphkinLive.state()")["drive"]
    for turn in (0.0, 0.2):  # at the file's posture and after a drag (every label redrawn)
        assert browser.js(f"window.graphkinLive.setDrive({d + turn!r})") is not None
        got = browser.js(_READ)
        texts = {p: [t for t, _ in got[p]] for p in got if p != "poles"}
        # the poles: O with the subscript V (A), as draw's $O_V$ ($O_A$); nowhere "O_V"
        if D["rates"]:
            assert sorted(got["poles"]) == [["O", "A", "gk-acceleration"],
                                            ["O", "V", "gk-velocity"]]
        for p, ts in texts.items():
            assert not {"O_V", "O_A"} & set(ts), p
        # every point of a moving link as draw prints it, and its images
        moving = {n for lid, pts in D["links"].items() if lid != "1" for n in pts}
        assert {point_text(n) for n in moving} <= set(texts["posture"])
        r = browser.js("window.graphkinLive.state()")["result"]
        if D["rates"]:  # (a frame pivot's image is the pole: the page finds none)
            for pre, panel in (("v", "velocity"), ("a", "acceleration")):
                want = {image_text(f"{pre}({n})") for n in moving if r.get(f"{pre}({n})")}
                assert want and want <= set(texts[panel]), panel
        # the Kennedy circle's centers, I₁₃
        if D.get("centers"):
            assert {center_text(lab) for lab in D["centers"]["pairs"]} <= set(texts["kennedy"])
        # no other plain underscore: what has one is a force named as draw -d forces names it
        # (−m₃A_G₃, draw's own text) or a label whose subscript is set below it
        names = {force_name(e["label"]) for e in D.get("forces", {}).get("acting", [])}
        names |= {force_name(e["label"]) for ps in D.get("forces", {}).get("polygons", {})
                  .values() for e in ps}
        for p, ts in texts.items():
            for t in ts:
                assert "_" not in t or t in names, (p, t)
        # the tables: each point as draw prints it (O₂), each force as draw -d forces (F₂₃)
        rows = browser.js("[].map.call(document.querySelectorAll('#gk-table tr > th'),"
                          " function (e) { return e.textContent; })")
        assert set(rows) >= {
            point_text(n) for n in moving if r.get(n)} and not [t for t in rows if "_" in t]
        forces = browser.js("[].map.call(document.querySelectorAll('#gk-force-table tr > th'),"
                            " function (e) { return e.textContent; })")
        F = D.get("forces", {})
        named = {force_name(lab) for lab in F.get("joints", {}).values()} | {
            force_name(dv["label"]) + (" (ccw)" if dv["kind"] == "torque" else "")
            for dv in F.get("drives", {}).values()}
        assert set(forces) <= named | {"force", "x", "y", "|F|"}, forces
        assert bool(F) == bool(set(forces) & named)
        # the drive as draw writes it (θ₂ = ..., render/joint_angle.py)
        drive = graphkin.load(ROOT / name).drives[0].label
        assert browser.js("document.getElementById('gk-drive-val').textContent").startswith(
            drive.translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")) + " = ")
        # a curvature label with a subscript (Hain's G_N, Example 12.3) is set below its letter
        for t, subs in got["curvature"]:
            for s, dy in subs:
                assert dy == "0.3em" and s in t, (t, subs)
    assert browser.errors() == []


def test_example_12_3s_hain_points_have_subscripts(browser, tmp_path):
    # Example 12.3's curvature panel shows Hain's G_N (the cubic of stationary curvature,
    # Sec. 4.17): "G" with "N" as a subscript tspan, as draw's $G_{N}$
    browser.open(page_file(tmp_path, ROOT / "gallery/mechanisms/ex12_3_elliptic_trammel.toml"))
    got = browser.js(_READ)["curvature"]
    subs = {t: s for t, s in got if s}
    assert subs.get("GN") == [["N", "0.3em"]], got


def test_a_coordinate_drive_has_its_subscript(browser, tmp_path):
    # Problem 5.13's pantograph is driven by its point C's x: draw writes x_C as x with the
    # subscript C, and so does the page beside its slider
    browser.open(page_file(tmp_path, ROOT / "gallery/mechanisms/p5_13_pantograph.toml"))
    html = browser.js("document.getElementById('gk-drive-val').innerHTML")
    assert html.startswith("x<sub>C</sub> = ") and html.endswith(" mm"), html
