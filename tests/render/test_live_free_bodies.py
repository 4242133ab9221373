"""The live page's free bodies: every force on each link drawn where it acts, as ``draw`` does.

Fig. 11.5b-d of Uicker, Pennock & Shigley (5th ed., Sec. 11.5): each moving
link cut free, every force on it (the joint forces F_ij by the book's name,
the loads, the inertia forces -m A_G offset by h, Eq. 12.18) an arrow whose
head is at its point of action, in the colours and names of
``graphkin draw -d forces``.  The page is opened in headless Chromium,
dragged, and its arrows read back: each arrow's direction is the force on that
link by ``graphkin solve`` of the file the page saves (numpy, the matrix or
graphic method in Python), and its head is the force's point of action
(:meth:`graphkin.forces.ForceSolution.point`: the pin; for a slider, where
its line of action crosses the sliding line), mapped from the drawing's
millimetres through the body's own pins (each body is drawn to scale: a
similarity taking the pins' world positions to their drawn circles).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from spec_data import ROOT

import graphkin
from graphkin.files import load_toml
from graphkin.forces import solve_forces
from graphkin.render.forces import force_name
from graphkin.render.forces_sheet import INERTIA, JOINT, LOAD
from graphkin.render.live import live_html

FILES = [ROOT / "tests" / "data" / "forces" / "ex11_1_static_fourbar.toml",
         ROOT / "tests" / "data" / "forces" / "ex12_4_dynamic_fourbar.toml",
         ROOT / "gallery" / "mechanisms" / "ex11_2_slider_crank_static.toml"]

READ = """(function () {
  var out = {};
  document.querySelectorAll('#gk-bodies .gk-body').forEach(function (g) {
    var b = {points: {}, forces: {}, torques: {}};
    g.querySelectorAll('.gk-body-point').forEach(function (c) {
      b.points[c.getAttribute('data-name')] = [+c.getAttribute('cx'), +c.getAttribute('cy')];
    });
    g.querySelectorAll('.gk-body-force').forEach(function (l) {
      var t = l.nextElementSibling;
      b.forces[l.getAttribute('data-name')] = {
        xy: ['x1', 'y1', 'x2', 'y2'].map(function (k) { return +l.getAttribute(k); }),
        color: l.getAttribute('stroke'), text: t ? t.textContent : null};
    });
    g.querySelectorAll('.gk-body-torque').forEach(function (p) {
      b.torques[p.getAttribute('data-name')] = p.getAttribute('data-sense');
    });
    out[g.getAttribute('data-link')] = b;
  });
  return out;
})()"""


def _cross(a, b) -> float:  # type: ignore[no-untyped-def]
    return float(a[0] * b[1] - a[1] * b[0])


def _to_world(sol, lid: str, drawn: dict[str, list[float]]):  # type: ignore[no-untyped-def]
    """The similarity (uniform scale, y up) from the body's drawn pins to world coordinates."""
    names = [n for n in drawn if n in sol.mechanism.links[lid].points]
    assert len(names) >= 2, (lid, drawn)
    a, b = names[0], names[1]
    wa, wb = np.asarray(sol.position(a, lid)), np.asarray(sol.position(b, lid))
    pa, pb = np.asarray(drawn[a]), np.asarray(drawn[b])
    s = float(np.hypot(*(pb - pa)) / np.hypot(*(wb - wa)))
    # the drawing is to scale, not turned: every other pin lands where the link puts it
    for n in names:
        q = wa + (np.asarray(drawn[n]) - pa) * np.array([1.0, -1.0]) / s
        assert np.allclose(q, sol.position(n, lid), atol=1e-6 * sol.mechanism.scale), n
    return lambda p: wa + (np.asarray(p) - pa) * np.array([1.0, -1.0]) / s


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.stem)
def test_free_bodies_draw_each_force_where_it_acts(browser, tmp_path: Path, path: Path) -> None:
    out = tmp_path / (path.stem + ".html")
    out.write_text(live_html(graphkin.load(path), load_toml(path), path.name), encoding="utf-8")
    browser.open(out)
    drive = browser.js("window.graphkinLive.state().drive")
    for turn in (0.0, 9.0):  # the file's posture, then dragged: the bodies follow
        browser.js(f"window.graphkinLive.setDrive({drive + math.radians(turn)})")
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        fs = solve_forces(graphkin.load(saved).solve())
        sol, mech = fs.solution, fs.mechanism
        bodies = browser.js(READ)
        assert sorted(bodies) == sorted(mech.moving)
        big = max(float(np.hypot(*w[:2])) for w in fs.forces.values())
        for j in fs.joints:
            for lid in (j.lo, j.hi):
                if lid not in bodies:
                    continue  # the frame is not cut free
                w = fs.forces[j.key][:2] * (1.0 if lid == j.hi else -1.0)  # the force ON lid
                name = j.label(lid)
                if float(np.hypot(*w)) <= 1e-9 * big:
                    assert name not in bodies[lid]["forces"]
                    continue
                got = bodies[lid]["forces"][name]
                x1, y1, x2, y2 = got["xy"]
                # the arrow points along the force (screen y down)
                d = np.array([x2 - x1, y1 - y2])
                assert abs(_cross(d, w)) <= 1e-9 * np.hypot(*d) * np.hypot(*w), name
                assert float(d @ w) > 0, name
                # its head at the point of action: the pin, or on the sliding line
                at = _to_world(sol, lid, bodies[lid]["points"])((x2, y2))
                assert np.allclose(at, fs.point(j.key), atol=1e-6 * mech.scale), (name, at)
                assert got["color"] == JOINT and got["text"] == force_name(name)
        # the loads and the inertia forces in their colours, by their book names; an inertia
        # force's head on its line of action, offset from G by h (Eq. 12.18)
        for lid, b in bodies.items():
            for name, f in b["forces"].items():
                if name.startswith("P_"):
                    assert f["color"] == LOAD and f["text"] == force_name(name)
                elif name.startswith("-m"):
                    assert f["color"] == INERTIA and f["text"] == force_name(name)
                    inr = fs.inertia[lid]
                    at = _to_world(sol, lid, b["points"])(f["xy"][2:])
                    off = _cross(at - inr.point, inr.force)
                    assert abs(off) <= 1e-6 * mech.scale * np.hypot(*inr.force), name
        # the drive's torque turns the way graphkin's sense says
        d = mech.drives[0]
        if d.kind == "angle":
            t = fs.torque(d.link)
            assert bodies[d.link]["torques"][f"T_1{d.link}"] == fs.sense(t), t
    assert browser.errors() == []
