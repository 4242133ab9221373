"""A turning cam page's instant centers are graphkin's at every cam angle of the cycle.

The page of a cam (a cam file, or a mechanism file with ``[[cams]]``) rebuilds
the cam's equivalent linkage at every angle (render/live_cam_turn.py), and its
instant centers are found on a route that chooses, at each posture, the pair
of lines of centers that meets best (``kennedy_center``,
kinematics/instant_centers/route.py), so no route chosen at the file's
posture is carried to angles where its lines are parallel or coincide.
Tested in headless Chromium: at angles spread over the whole cycle (and
random ones) the centers the page gives (``state().centers``) are those of
:func:`instant_centers` (numpy, graphkin's own search at that posture) of the
file with the drive at the page's angle, to 1e-9 (a center at infinity as its
direction), and the page never says its route is off.  In a dwell the page
draws no centers and says why (the follower stands still).  The template of
``kennedy_center`` is held to its numpy function on random lines.
"""

from __future__ import annotations

import copy
import json
import math
from pathlib import Path

import numpy as np
import pytest
from cam_strategies import cam_toml, cams
from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from jsrun import run_js
from live_cams_shared import TMP, cam_file
from live_edit import homogeneous
from strategies import examples

from graphkin.cams.as_mechanism import cam_mechanism
from graphkin.cams.parse import load_cam
from graphkin.construction import Construction
from graphkin.construction.jsgen import RUNTIME, generate_js
from graphkin.construction.ops import kennedy  # noqa: F401  (registers kennedy_center)
from graphkin.errors import GraphkinError
from graphkin.files import load_toml
from graphkin.kinematics.instant_centers import instant_centers
from graphkin.mechanisms import from_dict
from graphkin.render.live import live_data, live_html
from graphkin.tolerance import DEFAULT_TOL

ROOT = Path(__file__).resolve().parents[2]
CAM_FILES = sorted((ROOT / "gallery" / "cams").glob("ex6_*.toml"))
MECHANISMS = [ROOT / "examples" / "cams" / "cam_mechanism.toml",
              ROOT / "tests" / "data" / "audit7" / "cam_mech.toml"]
REL = 1e-9
NOTE = "document.getElementById('gk-centers-note').textContent"


def _data(path: Path) -> dict:
    """The file as the page reads it: a cam file as the mechanism it means."""
    data = load_toml(path)
    if "cam" in data:
        return cam_mechanism(load_cam(path).cam, str(path))
    return data


def _at(data: dict, theta2: float) -> dict:
    d = copy.deepcopy(data)
    dr = d["drive"][0] if isinstance(d["drive"], list) else d["drive"]
    dr["angle"] = math.degrees(theta2)
    return d


def _same(got, ref, size: float, lab: str) -> None:
    g = np.asarray(got, dtype=float)
    r = np.asarray(ref, dtype=float)
    if r[2] == 0.0 or g[2] == 0.0:
        # at infinity: the page gives it as a direction, graphkin as the point at infinity
        assert g[2] == 0.0 and r[2] == 0.0, (lab, got, ref)
        u, v = g[:2] / np.hypot(*g[:2]), r[:2] / np.hypot(*r[:2])
        np.testing.assert_allclose(u * np.sign(np.dot(u, v)), v, rtol=0, atol=REL, err_msg=lab)
        return
    q = r[:2] / r[2]
    np.testing.assert_allclose(g[:2], q, rtol=0, atol=REL * (size + np.hypot(*q)), err_msg=lab)


def _check_cycle(browser, data: dict, source: str, angles) -> int:
    """The page's centers at each drive angle are graphkin's; returns how many were compared."""
    compared = 0
    for th in angles:
        browser.js(f"window.graphkinLive.setDrive({th})")
        state = browser.js("window.graphkinLive.state()")
        assert browser.errors() == []
        note = browser.js(NOTE)
        assert "another one" not in note, (th, note)
        if state["result"] is None:          # no linkage, or no assembly, here: said
            continue
        assert "no clean answer" not in note, (th, note)
        if state["centers"] is None:         # only in a dwell: said so
            assert "dwells here" in note, (th, note)
            continue
        try:
            sol = from_dict(_at(data, state["drive"]), source=source).solve()
        except GraphkinError:
            continue
        ic = instant_centers(sol)
        size = 1.0 + sol.mechanism.scale
        for lab, entry in state["centers"].items():
            assert entry is not None, (th, lab)
            _same(homogeneous(entry), ic.values[lab], size, f"{lab} at {math.degrees(th):g}°")
            compared += 1
    return compared


def _open(browser, tmp_path: Path, data: dict, source: str) -> None:
    mech = from_dict(data, source=source)
    page = tmp_path / "page.html"
    page.write_text(live_html(mech, data, source), encoding="utf-8")
    browser.open(page)
    d = browser.js("JSON.parse(document.getElementById('gk-data').textContent)")
    assert d.get("turn") is not None
    assert d["centers"]["fn"] is not None, d["centers"]["why"]


@pytest.mark.parametrize("path", CAM_FILES + MECHANISMS, ids=lambda p: p.stem)
def test_every_cam_page_s_centers_are_graphkin_s_over_the_cycle(browser, tmp_path,
                                                                path: Path) -> None:
    data = _data(path)
    _open(browser, tmp_path, data, str(path))
    d0 = from_dict(data, source=str(path)).drives[0].value
    # 9 angles over the turn
    angles = [d0 + math.radians(a) for a in np.arange(0.0, 360.0, 40.0) + 7.0]
    assert _check_cycle(browser, data, str(path), angles) > 0


@settings(examples(3), deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(data=st.data(), theta2=st.floats(0.0, 360.0), axis=st.sampled_from([90.0, 0.0, 210.0]),
       turns=st.tuples(st.floats(-math.pi, math.pi), st.floats(0.5, 1.5),
                       st.floats(-math.pi, math.pi), st.floats(0.5, 1.5)).filter(
                           lambda t: abs(math.sin(t[2] - t[0])) > 0.2),
       angles=st.lists(st.floats(0.0, 2 * math.pi), min_size=3, max_size=5))
def test_random_cam_mechanisms_centers_are_graphkin_s(browser, tmp_path_factory, data, theta2,
                                                      axis, turns, angles) -> None:
    cam = data.draw(cams())
    path = TMP / f"cam-{abs(hash(cam_toml(cam)))}.toml"
    path.write_text(cam_toml(cam))
    file = cam_file(cam, path, theta2, axis, 2.0, 1.0, turns)
    if file is None:
        return
    try:
        _open(browser, tmp_path_factory.mktemp("cams"), file, "random.toml")
    except GraphkinError:
        return
    _check_cycle(browser, file, "random.toml", angles)


@examples(8)
@given(pts=st.lists(st.tuples(st.floats(-5.0, 5.0), st.floats(-5.0, 5.0),
                              st.sampled_from([1.0, 1.0, 0.0])), min_size=6, max_size=6),
       normal=st.tuples(st.floats(-math.pi, math.pi), st.floats(-5.0, 5.0)),
       near=st.sampled_from([0.0, 1e-7, 1e-3]), at_infinity=st.booleans())
def test_the_kennedy_center_template_is_the_operation(pts, normal, near, at_infinity) -> None:
    # three lines through pairs of random centers (one pair nearly coincident: a line of no
    # clean direction) and a given line: the JavaScript of the template against the numpy
    pts = [list(p) for p in pts]
    pts[1] = [pts[0][0] + near, pts[0][1], pts[0][2]] if pts[0][2] else pts[1]
    if not any(p[2] for p in pts):
        pts[0][2] = 1.0
    pts = [p if p[2] or math.hypot(p[0], p[1]) > 0.1 else [1.0, 0.0, 0.0] for p in pts]
    cx = Construction()
    names = [f"P{k}" for k in range(6)]
    for n, p in zip(names, pts):
        cx.add("point" if p[2] else "ideal_point", (), (n,),
               **({"xy": (p[0], p[1])} if p[2] else {"direction": (p[0], p[1])}))
    c, s = math.cos(normal[0]), math.sin(normal[0])
    cx.add("point", (), ("N0",), xy=(normal[1] * c, normal[1] * s))
    cx.add("ideal_point", (), ("N1",), direction=(c, s))
    cx.add("join", ("N0", "N1"), ("n",))
    lines = ((0, 1), (2, 3), (4, 5), (6,))
    pairs = tuple((a,) for a in range(4)) if at_infinity else \
        tuple((a, b) for a in range(4) for b in range(a + 1, 4))
    cx.add("kennedy_center", (*names, "n"), ("I", "I|a", "I|b", "I|k"), lines=lines,
           pairs=pairs, scale=3.0)
    ref = cx.replay({}, strict=False).values
    fn = generate_js(cx.steps, requests=["I", "I|a", "I|b", "I|k"],
                     given=[*names, "N0", "N1"])
    ins = {n: p for n, p in zip(names, pts)}
    ins.update(N0=[normal[1] * c, normal[1] * s, 1.0], N1=[c, s, 0.0])
    got = run_js(RUNTIME + fn.source + f"\nconst RESULT = {fn.name}({json.dumps(ins)}, "
                 f"{json.dumps(fn.values)});")
    r = np.asarray(ref["I"], dtype=float)
    if not np.all(np.isfinite(r)):
        assert got is None
        return
    assert got is not None
    assert got["I|k"] == float(ref["I|k"])
    for lab in ("I", "I|a", "I|b"):
        g, q = np.asarray(got[lab], dtype=float), np.asarray(ref[lab], dtype=float)
        if lab == "I":
            g, q = g / np.linalg.norm(g), q / np.linalg.norm(q)
        np.testing.assert_allclose(g * np.sign(np.dot(g, q)), q, rtol=0, atol=1e-12,
                                   err_msg=lab)
    # the definition: the center lies on both lines it reports (the point at infinity of one)
    for lab in ("I|a", "I|b"):
        ln = np.asarray(ref[lab], dtype=float)
        assert abs(float(np.dot(ln, r))) <= 1e-9 * (1.0 + abs(ln[2])), lab
    assert DEFAULT_TOL.angle < 1e-6


@pytest.mark.parametrize("path", MECHANISMS, ids=lambda p: p.stem)
def test_the_route_does_not_rest_on_round_off(path: Path) -> None:
    # every length of the file and the drive's angle moved by 1e-12 of their size: the same
    # route on the page (its centers, lines, candidate pairs and what it says)
    data = _data(path)
    src = str(path)
    ref, _ = live_data(from_dict(data, source=src), data, src)
    bumped = copy.deepcopy(data)
    mech = from_dict(data, source=src)
    for lk in bumped["links"].values():
        for n, xy in lk.items():
            lk[n] = [v + 1e-12 * mech.scale for v in xy]
    dr = bumped["drive"][0] if isinstance(bumped["drive"], list) else bumped["drive"]
    dr["angle"] = dr["angle"] * (1.0 + 1e-12)
    got, _ = live_data(from_dict(bumped, source=src), bumped, src)
    for key in ("labels", "lines", "joins", "meets", "kennedy", "why"):
        assert got["centers"][key] == ref["centers"][key], key
