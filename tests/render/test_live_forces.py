"""The live page's force polygons equal graphkin's force analysis, for random loads and drags.

The page's written-out functions (the posture construction, then the force
construction of Secs. 11.5-12.5 from the force operations' templates, its
givens taken from the posture by ``gkForceInputs``) are run on JavaScript
numbers (node, else headless Chromium) at a drive moved from the file's; the
file is edited the way the page saves it and solved by graphkin in Python:
:func:`graphkin.forces.solve_forces`, the numpy operations replayed on the new
posture (or the matrix method, when the graphic method finds no order), is
the reference.  Every joint force and the drive's torque (or input force)
must agree to 1e-9 of the forces' scale (moments to that times the
mechanism's size).  The spec's force examples are then opened in headless
Chromium: the panel is drawn, no NaN is shown, and after a drag the page's
forces are ``solve`` of the file the page saves.
"""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from jsrun import close, js_or_skip, run_js
from live_edit import edited
from live_loads import loaded, page_forces, polygons_close, same_forces
from spec_data import ROOT
from strategies import (
    examples,
    fourbars,
    inverted_slider_cranks,
    six_bars,
    slider_cranks,
    slotted,
)

import graphkin
from graphkin.errors import GraphkinError, InputError
from graphkin.files import load_toml
from graphkin.forces import solve_forces
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data, live_html
from graphkin.render.live_app import LIVE_LIB

REL = 1e-9
FORCES = ROOT / "tests" / "data" / "forces"
FRICTION = ROOT / "tests" / "data" / "hostile" / "load_1e95_friction.toml"


@pytest.fixture(scope="module", autouse=True)
def _js():
    js_or_skip()
    yield
    close()


FAMILIES = {"fourbar": fourbars(other_rates=False), "slider-crank": slider_cranks(),
            "inverted slider-crank": inverted_slider_cranks(), "six-bar": six_bars(),
            "slotted": slotted()}


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_page_forces_equal_graphkins_after_a_drag(family: str) -> None:

    @examples(8)
    @given(data=loaded(FAMILIES[family]), offset=st.floats(-0.1, 0.1))
    def check(data: dict[str, Any], offset: float) -> None:
        _check(data, offset)

    check()


def _check(file: dict[str, Any], offset: float) -> None:
    mech = from_dict(file, source="<random loaded>")
    try:
        data, js = live_data(mech, file, "<random loaded>")
    except InputError:
        return  # no construction (Newton): refused in one line, tested in test_live.py
    F = data["forces"]
    if "why" in F:
        # only a pin in a circular slot, or a mechanism the graphic method finds no order
        # for, says why (frictionless here)
        circular = any(not t.is_line for t in mech.slots)
        assert circular or solve_forces(mech.solve()).method == "analytic", F["why"]
        return
    d = data["drive"]
    drive = d["value"] + offset * (1.0 if d["degrees"] else mech.scale)
    out = page_forces(data, js, drive)
    if out is None:
        return  # this posture cannot be assembled: the page says so (test_live.py)
    try:
        sol = from_dict(edited(data, drive, out["r"]), source="<edited>").solve()
        fs = solve_forces(sol)
    except GraphkinError:
        return  # equilibrium cannot be held there for graphkin either
    if not bool(np.all(sol.valid)):
        return
    if out["f"] is None:
        # the page refuses only near a dead center of the force construction: a line of
        # action through a pin, or parallel lines of a polygon; graphkin's forces are then
        # huge against the loads
        loads = [float(np.hypot(*ld.force)) for ld in mech.loads if ld.force is not None]
        big = max(float(np.hypot(*w[:2])) for w in fs.forces.values())
        assert big > 1e3 * max(loads + [0.0]), "the page refused a clean posture"
        return
    same_forces(out["f"], F, fs)
    polygons_close(out["f"], F)


def test_the_file_posture_is_graphkins_own() -> None:
    # at the file's drive the page's forces are graphkin forces' of the file (Ex 12.4: the
    # inertia forces of links 3 and 4 and the load at C, superposed, Sec. 12.5)
    for path in sorted(FORCES.glob("ex[0-9]*.toml")):
        mech = graphkin.load(path)
        data, js = live_data(mech, load_toml(path), path.name)
        out = page_forces(data, js, data["drive"]["value"])
        assert out is not None and out["f"] is not None, path.name
        same_forces(out["f"], data["forces"], solve_forces(mech.solve()))


def test_rates_of_another_link_are_said_in_one_line() -> None:
    # Ex 12.3's trammel with its rates given for the coupler ([rates]): the page has no
    # accelerations to make the inertia force from, and says so
    path = ROOT / "tests" / "data" / "hostile" / "rates_1e8_trammel.toml"
    data, _ = live_data(graphkin.load(path), load_toml(path), path.name)
    assert data["forces"]["why"].startswith("the inertia forces need the accelerations")


def _open(browser, tmp_path: Path, path: Path) -> None:
    out = tmp_path / (path.stem + ".html")
    out.write_text(live_html(graphkin.load(path), load_toml(path), path.name), encoding="utf-8")
    browser.open(out)


@pytest.mark.parametrize("name", sorted(p.name for p in FORCES.glob("ex[0-9]*.toml")))
def test_spec_force_examples_open_with_the_panel_and_follow_a_drag(browser, tmp_path,
                                                                   name: str) -> None:
    path = FORCES / name
    _open(browser, tmp_path, path)
    assert browser.errors() == []
    shown = browser.js("document.getElementById('gk-forces').parentNode.style.display")
    assert shown != "none"
    assert browser.js("document.querySelectorAll('#gk-forces .gk-force').length") > 0
    text = browser.js("document.body.innerText")
    assert "NaN" not in text and "undefined" not in text
    # the table names the forces as draw -d forces does (F_23 -> F₂₃, render/forces.py)
    table = browser.js("document.getElementById('gk-force-table').innerText")
    assert "F₂₃" in table and "_" not in table
    # the applied forces drawn where they act on the posture (the free bodies' loads)
    acting = browser.js("[].map.call(document.querySelectorAll('#gk-posture .gk-acting'),"
                        " function (e) { return [e.getAttribute('data-name'),"
                        " e.getAttribute('x1'), e.getAttribute('y2')]; })")
    names = {a[0] for a in acting}
    assert "P_4" in names and all(math.isfinite(float(v)) for a in acting for v in a[1:])
    if "12_4" in name:
        assert {"-m3A_G3", "-m4A_G4"} <= names
    state = browser.js("window.graphkinLive.state()")
    data = json.loads(browser.js("document.getElementById('gk-data').textContent"))
    same_forces(state["forces"], data["forces"], solve_forces(graphkin.load(path).solve()))
    # drag the crank by 12°: the page's forces are graphkin's of the file the page saves
    browser.js(f"window.graphkinLive.setDrive({state['drive'] + math.radians(12.0)})")
    after = browser.js("window.graphkinLive.state()")
    assert after["forces"] is not None
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    same_forces(after["forces"], data["forces"], solve_forces(graphkin.load(saved).solve()))
    assert not np.allclose(after["forces"][data["forces"]["joints"]["2-3"]],
                           state["forces"][data["forces"]["joints"]["2-3"]])
    assert "NaN" not in browser.js("document.body.innerText")
    assert browser.errors() == []


def test_a_huge_load_with_friction_is_redone_not_refused(browser, tmp_path) -> None:
    # issue 25's file: a 1e95 load with friction at the slider (Sec. 11.10, live since the
    # page redoes friction: tests/render/test_live_friction.py); no NaN, graphkin's forces
    _open(browser, tmp_path, FRICTION)
    assert browser.errors() == []
    assert browser.js("document.getElementById('gk-forces-note').textContent") == ""
    assert browser.js("document.querySelectorAll('#gk-forces .gk-force').length") > 0
    state = browser.js("window.graphkinLive.state()")
    data = json.loads(browser.js("document.getElementById('gk-data').textContent"))
    same_forces(state["forces"], data["forces"], solve_forces(graphkin.load(FRICTION).solve()))
    assert "NaN" not in browser.js("document.body.innerText")


def test_a_pin_on_the_known_line_is_refused_not_a_number() -> None:
    # Ex 11.1: link 3 is a two-force member along AB, link 4 a three-force member with its
    # pin O4; Σ M_O4 = 0 divides by the distance of O4 from AB (Fig. 11.5e).  O4 on AB (or
    # within round-off of it, 1e-12 of the size) has no clean answer: null, never NaN; 1e-3
    # of the size away it has one.
    path = FORCES / "ex11_1_static_fourbar.toml"
    mech = graphkin.load(path)
    data, js = live_data(mech, load_toml(path), path.name)
    size = mech.scale
    src = (js + LIVE_LIB + f"\nconst D = {json.dumps(data)};"
           "\nconst I = Object.assign({}, D.inputs);"
           "\nI[D.drive.label] = D.drive.value;"
           "\nconst r = construction(I, D.K);"
           "\nconst J = gkForceInputs(D.forces, r);"
           "\nconst A = J.A, B = J.B, dx = B[0] - A[0], dy = B[1] - A[1];"
           "\nconst n = Math.hypot(dx, dy);"
           "\nfunction at(h) { const K = Object.assign({}, J);"
           "\n  K.O4 = [A[0] + 1.7 * dx - h * dy / n, A[1] + 1.7 * dy + h * dx / n];"
           "\n  return forces(K, D.forces.K); }"
           f"\nconst RESULT = [at(0), at({1e-12 * size!r}), at({-1e-12 * size!r}),"
           f" at({1e-3 * size!r})];")
    on, up, down, away = run_js(src)
    assert on is None and up is None and down is None
    assert away is not None and all(np.all(np.isfinite(away[lab]))
                                    for lab in data["forces"]["joints"].values())


def _drag(browser, kind: str, name: str, by: tuple[float, float]) -> None:
    """Drag a handle of the posture panel by ``by`` pixels, in six pointer moves."""
    x0, y0 = browser.js(
        f"(function () {{ var r = document.querySelector('.gk-handle[data-kind=\"{kind}\"]"
        f"[data-name=\"{name}\"]').getBoundingClientRect();"
        " return [r.x + r.width / 2, r.y + r.height / 2]; })()")
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0, y=y0)
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=x0, y=y0, button="left",
                 clickCount=1)
    for k in range(1, 7):
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0 + by[0] * k / 6,
                     y=y0 + by[1] * k / 6, button="left", buttons=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=x0 + by[0],
                 y=y0 + by[1], button="left", clickCount=1)


def test_dragging_the_load_point_the_masses_and_a_pivot_moves_the_forces(browser,
                                                                        tmp_path) -> None:
    # Ex 12.4: drag the load's point C, the center of mass G3 and the pivot O4: the page's
    # forces are those of graphkin solve of the file the page saves (C, G3, O4 moved)
    path = FORCES / "ex12_4_dynamic_fourbar.toml"
    _open(browser, tmp_path, path)
    data = json.loads(browser.js("document.getElementById('gk-data').textContent"))
    before = browser.js("window.graphkinLive.state()")["forces"]
    for kind, name, by in (("point", "C", (25.0, 15.0)), ("point", "G3", (-20.0, 10.0)),
                           ("frame", "O4", (15.0, -10.0))):
        _drag(browser, kind, name, by)
    state = browser.js("window.graphkinLive.state()")
    assert state["forces"] is not None and browser.errors() == []
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    mech = graphkin.load(saved)
    orig = graphkin.load(path)
    for lid, n in (("4", "C"), ("3", "G3"), ("1", "O4")):  # the drags reached the file
        assert not np.allclose(mech.links[lid].points[n], orig.links[lid].points[n]), n
    same_forces(state["forces"], data["forces"], solve_forces(mech.solve()))
    assert not np.allclose(state["forces"]["F_34"], before["F_34"])


@examples(15)
@given(xy=st.lists(st.floats(-1.0, 1.0), min_size=18, max_size=18),
       load=st.tuples(st.floats(-100.0, 100.0), st.floats(-100.0, 100.0)),
       torque=st.floats(-500.0, 500.0))
def test_force_templates_compute_the_force_operations(xy: list[float], load: tuple[float, float],
                                                     torque: float) -> None:
    # the written-out templates against the numpy operations of graphkin.forces.ops, on one
    # random construction using the ones random mechanisms rarely reach: a four-force member
    # (Sec. 11.8), the line of action of a known force, a force of known direction only
    import graphkin.forces.templates  # noqa: F401
    from graphkin.construction import Construction
    from graphkin.construction.jsgen import RUNTIME, generate_js

    cx = Construction()
    # nine points, each within 1 of its place on a grid: no two lines alike
    grid = [(0, 0), (6, 1), (1, 5), (2, -4), (-5, 2), (-4, -6), (3, 3), (7, -2), (-6, 5)]
    pts = [(gx + xy[2 * k], gy + xy[2 * k + 1]) for k, (gx, gy) in enumerate(grid)]
    for k, p in enumerate(pts):
        cx.add("point", (), (f"P{k}",), xy=p)
    for k in range(3):
        cx.add("join", (f"P{2 * k}", f"P{2 * k + 1}"), (f"l{k}",))
    cx.add("force_load", ("P6",), ("R",), force=load)
    cx.add("force_four", ("R", "l0", "l1", "l2"), ("F1", "F2", "F3", "q"))
    cx.add("force_line_of", ("F3",), ("l3",))
    cx.add("force_couple", (), ("M",), torque=torque)
    cx.add("force_resultant", ("R", "M"), ("R2",))
    cx.add("vector", ("P7", "P8"), ("u",))
    cx.add("force_line", ("P7", "u"), ("l4",))
    cx.add("force_slide_three", ("R2", "l3", "u"), ("G1", "G2", "X"))
    try:
        ref = cx.replay().values
    except GraphkinError:
        return
    labels = ["F1", "F2", "F3", "G1", "G2", "X", "l4"]
    vals = np.array([ref[lab] for lab in labels[:5]])
    size = float(np.max(np.abs(vals[:, :2]))) if np.all(np.isfinite(vals)) else math.inf
    if not math.isfinite(size) or size > 1e6 * (1.0 + math.hypot(*load)):
        return  # near-concurrent lines or parallel sides: no clean polygon
    fn = generate_js(cx.steps, requests=labels)
    got = run_js(RUNTIME + fn.source + f"\nconst RESULT = construction({{}}, {fn.values});")
    if got is None:
        return  # the page's margin refuses it (a dead center)
    # the concurrency point of R2 and F3 (homogeneous) and the line through P7 along u
    for lab in ("X", "l4"):
        g, r = np.asarray(got[lab], dtype=float), ref[lab]
        g, r = g / np.linalg.norm(g), r / np.linalg.norm(r)
        assert np.allclose(g * np.sign(g @ r), r, rtol=0, atol=1e-9), lab
    for lab in labels[:5]:
        w = np.asarray(got[lab], dtype=float)
        assert np.all(np.abs(w[:2] - ref[lab][:2]) <= 1e-9 * size), lab
        assert abs(w[2] - ref[lab][2]) <= 1e-9 * size * 30.0, lab
