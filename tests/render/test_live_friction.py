"""The live page redoes friction at sliders and straight slots (Sec. 11.10) as graphkin does.

The book's way, which graphkin's force analysis follows
(:func:`graphkin.forces.solve_forces`): solve first without friction to find
the sense of each normal force, lean each rough joint's force by the
friction angle φ = atan μ from the guide's normal against the impending
motion, solve again; where the force found pulls the block instead, try the
other sense; where neither holds, the posture is self-locking.  The page
writes every act out through the one table of templates (the frictionless
construction, the senses, the leant lines, the check: ``force_scale``,
``force_normal_sense``, ``force_friction_normal``, ``force_turned``) and runs
them on JavaScript numbers.  For random loaded slider-cranks, inverted
slider-cranks and slotted links with a random μ and impending motion on every
straight guide, dragged at random, the page's forces are those of
``graphkin solve`` of the edited file (to 1e-9 of the forces' scale), and
where graphkin says self-locking the page says so too, and only there.
"""

from __future__ import annotations

import copy
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
from strategies import examples, inverted_slider_cranks, slider_cranks, slotted

import graphkin
from graphkin.errors import GraphkinError, InputError
from graphkin.files import load_toml
from graphkin.forces import solve_forces
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data, live_html
from graphkin.render.live_app import LIVE_LIB

EX11_4 = ROOT / "gallery" / "mechanisms" / "ex11_4_slider_crank_friction.toml"
FAMILIES = {"slider-crank": slider_cranks(), "inverted slider-crank": inverted_slider_cranks(),
            "slotted": slotted()}


@pytest.fixture(scope="module", autouse=True)
def _js():
    js_or_skip()
    yield
    close()


@st.composite
def rough(draw: Any, family: Any) -> dict[str, Any]:
    """A loaded random mechanism with Coulomb friction on every straight guide."""
    data = draw(loaded(family))
    for table in ("sliders", "slots"):
        for entry in data.get(table, []):
            if table == "slots" and "line" not in entry:
                continue
            entry["friction"] = draw(st.floats(0.05, 1.5))
            way = draw(st.sampled_from(["ahead", "behind", None]))
            if way is not None:  # else graphkin takes it from the block's velocity
                entry["impending"] = way
    return data


def _self_locking(exc: GraphkinError) -> bool:
    return "self-locking" in str(exc)


def _check(file: dict[str, Any], offset: float) -> None:
    mech = from_dict(file, source="<random rough>")
    try:
        data, js = live_data(mech, file, "<random rough>")
    except InputError:
        return  # no construction (Newton): refused in one line, tested in test_live.py
    F = data["forces"]
    if "why" in F:
        # a circular slot, or no graphic order (or self-locking) at the file's posture
        circular = any(not t.is_line for t in mech.slots)
        try:
            fs = solve_forces(mech.solve())
        except GraphkinError as exc:
            assert "no force analysis" in F["why"] and str(exc) in F["why"]
            return
        assert circular or fs.method == "analytic", F["why"]
        return
    if mech.friction:
        assert F["rough"], "friction but no rough joint on the page"
    d = data["drive"]
    drive = d["value"] + offset * (1.0 if d["degrees"] else mech.scale)
    out = page_forces(data, js, drive)
    if out is None:
        return  # this posture cannot be assembled: the page says so (test_live.py)
    try:
        sol = from_dict(edited(data, drive, out["r"]), source="<edited>").solve()
    except GraphkinError:
        return
    if not bool(np.all(sol.valid)):
        return
    try:
        fs = solve_forces(sol)
    except GraphkinError as exc:
        if _self_locking(exc):
            assert out["f"] is not None and "selfLocking" in out["f"], (str(exc), out["f"])
        if "at rest relative to its guide" in str(exc):
            assert out["f"] is not None and "atRest" in out["f"], (str(exc), out["f"])
        return  # equilibrium cannot be held there for graphkin either
    if out["f"] is None:
        # a dead center of the force construction (as without friction): huge forces
        loads = [float(np.hypot(*ld.force)) for ld in mech.loads if ld.force is not None]
        big = max(float(np.hypot(*w[:2])) for w in fs.forces.values())
        assert big > 1e3 * max(loads + [0.0]), "the page refused a clean posture"
        return
    assert "selfLocking" not in out["f"], "the page says self-locking, graphkin solves it"
    assert "atRest" not in out["f"], "the page says at rest, graphkin solves it"
    same_forces(out["f"], F, fs)
    polygons_close(out["f"], F)


@pytest.mark.parametrize("family", sorted(FAMILIES))
def test_page_friction_equals_graphkins_after_a_drag(family: str) -> None:

    @examples(10)
    @given(data=rough(FAMILIES[family]), offset=st.floats(-0.15, 0.15))
    def check(data: dict[str, Any], offset: float) -> None:
        _check(data, offset)

    check()


def _ex11_4(mu: float, impending: str, angle: float) -> dict[str, Any]:
    d = copy.deepcopy(load_toml(EX11_4))
    d.pop("gallery", None)
    d["sliders"][0].update(friction=mu, impending=impending)
    d["drive"]["angle"] = angle
    return d


def test_ex11_4_leans_by_the_friction_angle_against_the_impending_motion() -> None:
    # Example 11.4 (Fig. 11.12): μ = 0.25, the block's motion impending to the left; the
    # ground's force F_14 on the block leans φ = atan 0.25 = 14.04° from the normal (up,
    # the frictionless sense), toward +x (friction opposes the motion to the left)
    mech = graphkin.load(EX11_4)
    data, js = live_data(mech, load_toml(EX11_4), EX11_4.name)
    F = data["forces"]
    assert [j["key"] for j in F["rough"]] == ["1-4"]
    got = page_forces(data, js, data["drive"]["value"])["f"]
    f14 = np.asarray(got[F["joints"]["1-4"]][:2])  # F_14: by the ground (1) on the block (4)
    assert f14[1] > 0 and f14[0] > 0
    assert abs(math.atan2(f14[0], f14[1]) - math.atan(0.25)) < 1e-12
    same_forces(got, F, solve_forces(mech.solve()))


def test_self_locking_is_said_where_graphkin_says_it() -> None:
    # Ex 11.4's slider-crank with μ = 5 (φ = 78.7°) and the block pushed to the right: at
    # θ2 = 90° the rod's force on the block is within φ of the ground's normal (graphkin
    # solve: self-locking); at θ2 = 0° it is not.  Nudged by 1e-12 rad: the same verdicts.
    for angle, locked in ((90.0, True), (0.0, False)):
        file = _ex11_4(5.0, "ahead", angle)
        mech = from_dict(file, source="ex11_4_mu5.toml")
        try:
            solve_forces(mech.solve())
            python_locked = False
        except GraphkinError as exc:
            python_locked = _self_locking(exc)
        assert python_locked == locked
        # the page made at θ2 = 0° (a posture that holds), dragged to the angle
        data, js = live_data(from_dict(_ex11_4(5.0, "ahead", 0.0), source="x"),
                             _ex11_4(5.0, "ahead", 0.0), "x")
        for nudge in (0.0, 1e-12, -1e-12):
            out = page_forces(data, js, math.radians(angle) + nudge)["f"]
            assert out is not None
            assert ("selfLocking" in out) == locked, (angle, nudge)
            if locked:
                assert out["selfLocking"] == {"key": "1-4", "link": "4",
                                              "phi": math.degrees(math.atan(5.0))}


def test_impending_from_the_velocities() -> None:
    # Example 11.4 without `impending`, the crank turning at ω2 = 10 rad/s ccw: graphkin takes
    # the block's impending motion from its velocity.  Ex 11.4's line passes through O2, so
    # at θ2 = 120° the block moves to the left (toward S: "behind", as the book's file says),
    # and at θ2 = 0° (crank and rod in line along the guide) it is at rest: no verdict, the
    # file must say which way; the page says so where graphkin does
    file = load_toml(EX11_4)
    del file["sliders"][0]["impending"]
    file["drive"]["omega"] = 10.0
    mech = from_dict(file, source=EX11_4.name)
    data, js = live_data(mech, file, EX11_4.name)
    F = data["forces"]
    assert "why" not in F
    given = graphkin.load(EX11_4)  # impending = "behind" given
    got = page_forces(data, js, data["drive"]["value"])["f"]
    same_forces(got, F, solve_forces(given.solve()))
    for angle in (0.0, 1e-12, 35.0, 200.0, 300.0):
        out = page_forces(data, js, math.radians(angle))
        try:
            fs = solve_forces(from_dict(edited(data, math.radians(angle), out["r"]),
                                        source="x").solve())
        except GraphkinError as exc:
            assert "at rest relative to its guide" in str(exc), str(exc)
            assert out["f"] == {"atRest": F["rough"][0]}, angle
            continue
        assert angle not in (0.0, 1e-12)
        same_forces(out["f"], F, fs)


def test_ex11_4_page_follows_a_drag_and_says_self_locking(browser, tmp_path: Path) -> None:
    out = tmp_path / "ex11_4.html"
    file = _ex11_4(5.0, "ahead", 0.0)
    out.write_text(live_html(from_dict(file, source="ex11_4.toml"), file, "ex11_4.toml"),
                   encoding="utf-8")
    browser.open(out)
    data = json.loads(browser.js("document.getElementById('gk-data').textContent"))
    for angle in (10.0, 90.0, 200.0):
        browser.js(f"window.graphkinLive.setDrive({math.radians(angle)})")
        state = browser.js("window.graphkinLive.state()")
        note = browser.js("document.getElementById('gk-forces-note').textContent")
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        try:
            fs = solve_forces(graphkin.load(saved).solve())
        except GraphkinError as exc:
            assert _self_locking(exc)
            assert note.startswith("Self-locking at this posture: the force on link 4")
            assert state["forces"] is None
            assert browser.js("document.querySelectorAll('#gk-bodies .gk-body-force')"
                              ".length") == 0
            continue
        assert note == ""
        same_forces(state["forces"], data["forces"], fs)
        # the rough force drawn on the block's free body where it crosses the sliding line,
        # with its normal and friction components (Fig. 11.11b): the ground's line S-T is
        # horizontal, so F^n is vertical and F^t horizontal, and at impending motion
        # |F^t| = μ |F^n| (Coulomb, Sec. 11.9), μ = 5
        assert browser.js("document.querySelectorAll('#gk-bodies .gk-body-force"
                          "[data-name=\"F_14\"]').length") == 1
        comp = browser.js("(function () { var o = {}; document.querySelectorAll("
                          "'#gk-bodies .gk-body-component').forEach(function (l) {"
                          " o[l.getAttribute('data-name')] = ['x1', 'y1', 'x2', 'y2'].map("
                          "function (k) { return +l.getAttribute(k); }); }); return o; })()")
        (nx1, ny1, nx2, ny2), (tx1, ty1, tx2, ty2) = comp["F_14n"], comp["F_14t"]
        assert abs(nx2 - nx1) < 1e-9 and abs(ty2 - ty1) < 1e-9
        assert abs(abs(tx2 - tx1) / abs(ny2 - ny1) - 5.0) < 1e-9
    assert "NaN" not in browser.js("document.body.innerText")
    assert browser.errors() == []


@examples(20)
@given(xy=st.lists(st.floats(-5.0, 5.0), min_size=12, max_size=12),
       torque=st.floats(-9.0, 9.0), mu=st.floats(0.0, 2.0),
       way=st.sampled_from([-1.0, 1.0]), omega=st.floats(-20.0, 20.0))
def test_friction_templates_compute_the_friction_operations(xy: list[float], torque: float,
                                                            mu: float, way: float,
                                                            omega: float) -> None:
    # the written-out templates against the numpy operations of graphkin.forces.ops on one
    # small construction: the forces' and the velocities' scales, a sense, the impending
    # motion, the leant line and the turnover check
    import graphkin.forces.templates  # noqa: F401
    from graphkin.construction import Construction
    from graphkin.construction.jsgen import RUNTIME, generate_js

    a, b, c, vp, vq, q = (np.asarray(xy[2 * k:2 * k + 2]) for k in range(6))
    if math.hypot(*c) < 1e-3:
        return
    n = c / np.hypot(*c)
    cx = Construction()
    for lab, v in (("A", a), ("N", n), ("U", (-n[1], n[0])), ("VP", vp), ("VQ", vq),
                   ("Q", q)):
        cx.add("point", (), (lab,), xy=tuple(float(x) for x in v))
    cx.add("force_load", ("A",), ("P",), force=tuple(float(x) for x in b))
    cx.add("force_couple", (), ("M",), torque=torque)
    cx.add("scalar", (), ("w",), value=omega)
    cx.add("force_scale", ("P", "M"), ("s",), kinds=("force", "couple"), size=3.0)
    cx.add("force_scale", ("VP", "VQ", "w"), ("v",), kinds=("force", "force", "rate"),
           size=2.0)
    cx.add("force_normal_sense", ("P", "N", "s"), ("σ",), block="lo")
    cx.add("force_impending", ("VP", "VQ", "Q", "A", "w", "U", "v"), ("ι",))
    cx.add("force_friction_normal", ("N", "U", "σ"), ("d",), mu=mu, impending=way)
    cx.add("force_friction_normal", ("N", "U", "σ", "ι"), ("e",), mu=mu, impending=None)
    cx.add("force_turned", ("P", "d", "s", "σ"), ("τ",), block="hi")
    ref = cx.replay().values
    fn = generate_js(cx.steps, requests=["s", "v", "σ", "ι", "d", "e", "τ"])
    got = run_js(RUNTIME + LIVE_LIB + fn.source
                 + f"\nconst RESULT = construction({{}}, {fn.values});")
    for lab in ("s", "v"):
        assert abs(got[lab] - float(ref[lab])) <= 1e-12 * float(ref[lab])
    for lab in ("σ", "ι", "τ"):  # verdicts: away from their round-off the same
        assert got[lab] == float(ref[lab]), lab
    for lab in ("d", "e"):
        assert np.allclose(got[lab], np.asarray(ref[lab])[:2], rtol=0, atol=1e-12), lab
