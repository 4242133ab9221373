"""The live page moves a drive that follows the first by a law with it, as ``graphkin sweep``.

The five-bars of Examples 5.1-5.4 (Fig. 5.5) with θ3 coupled to θ2
(examples/fivebar_coupled.toml: θ3 = 3 θ2 − 315°; fivebar_stretched.toml:
θ3 = θ2 + 180°; fivebar_table.toml: the periodic spline through (θ2, θ3)
rows).  The page's evaluation of a law's coefficients (render/live_laws.py,
``gkLaw``) is held to graphkin's :class:`~graphkin.mechanisms.laws.Law` and to
what a law is by definition (a linear law's ``k x + c``, a spline through its
rows, a periodic one repeating every turn).  Then the page is dragged in
headless Chromium (the drive moved, a frame pivot moved) and every value it
holds (posture, velocity and acceleration polygons, ω and α of every link, the
instant centers and the curvature panel) is
compared with ``graphkin solve`` of the file the page saves, to 1e-9; the
saved file keeps the law.
"""

from __future__ import annotations

import json
import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from cdp import browser_or_skip
from hypothesis import given
from hypothesis import strategies as st
from jsrun import run_js
from live_edit import homogeneous, same_center, same_curvature
from strategies import examples

import graphkin
from graphkin.files import load_toml
from graphkin.kinematics.curvature.link import curvature
from graphkin.kinematics.instant_centers import instant_centers
from graphkin.mechanisms.laws import linear_law, table_law
from graphkin.render.live import live_data, live_html
from graphkin.render.live_laws import LAWS_JS, law_data

ROOT = Path(__file__).resolve().parents[2]
FILES = ["fivebar_coupled", "fivebar_stretched", "fivebar_table"]
REL = 1e-9


def _fail(why: str) -> Exception:
    return ValueError(why)


def _page_eval(law, xs: np.ndarray) -> np.ndarray:
    """``gkLaw`` of the page at ``xs``: rows f, f', f'' (NaN where JSON says null)."""
    src = (LAWS_JS + f"const L = {json.dumps(law_data(law))};\n"
           f"const X = {json.dumps([float(x) for x in xs])};\n"
           "const RESULT = [0, 1, 2].map((o) => X.map((x) => gkLaw(L, x, o)));")
    out = run_js(src)
    return np.array([[np.nan if v is None else v for v in row] for row in out], dtype=float)


def _same_as_graphkin(law, xs: np.ndarray) -> np.ndarray:
    got = _page_eval(law, xs)
    ref = np.array([law.value(xs), law.slope(xs), law.curve(xs)])
    assert np.array_equal(np.isnan(got), np.isnan(ref))
    for order in range(3):  # the same arithmetic: equal to round-off of each row's scale
        scale = 1.0 + float(np.nanmax(np.abs(ref[order]), initial=0.0))
        np.testing.assert_allclose(np.nan_to_num(got[order]), np.nan_to_num(ref[order]),
                                   rtol=0, atol=1e-12 * scale, err_msg=f"order {order}")
    return got


def test_a_linear_law_on_the_page_is_k_x_plus_c():
    # fivebar_coupled.toml: θ3 = 3 θ2 − 315°, so f' = 3 and f'' = 0 everywhere
    law = graphkin.load(ROOT / "examples" / "fivebar_coupled.toml").drives[1].law
    xs = np.radians([-400.0, -90.0, 0.0, 120.0, 359.0, 725.0])
    got = _same_as_graphkin(law, xs)
    np.testing.assert_allclose(got[0], 3 * xs - math.radians(315.0), rtol=0, atol=1e-12)
    np.testing.assert_allclose(got[1], 3.0, rtol=0, atol=0)
    np.testing.assert_allclose(got[2], 0.0, rtol=0, atol=0)


@examples(25)
@given(n=st.integers(2, 12), periodic=st.booleans(), angle=st.booleans(),
       seed=st.integers(0, 2**32 - 1))
def test_a_table_law_on_the_page_is_graphkins_spline(n, periodic, angle, seed):
    rng = np.random.default_rng(seed)
    if periodic:  # one whole turn of the first drive: the law repeats (turns of an angle)
        x = np.sort(np.concatenate([[0.0, 2 * math.pi], rng.uniform(0.1, 6.1, n - 2)]))
        x = x + rng.uniform(-3.0, 3.0)
        y = rng.uniform(-2.0, 2.0, len(x))
        turns = int(rng.integers(-3, 4)) if angle else 0
        y[-1] = y[0] + turns * 2 * math.pi
    else:
        x = np.sort(rng.uniform(-3.0, 3.0, n))
        y = rng.uniform(-50.0, 50.0, n)
    if np.any(np.diff(x) < 1e-3):
        return
    law = table_law(x, y, angle=periodic, follower_angle=angle, fail=_fail)
    assert (law.period is not None) == periodic
    lo, hi = x[0], x[-1]
    xs = np.concatenate([x, rng.uniform(lo, hi, 20), [lo - 1.0, hi + 0.5, hi + 7.0]])
    got = _same_as_graphkin(law, xs)
    # what a spline law is, whatever its code: through its rows; periodic, repeating every
    # turn with the follower's whole turns added; otherwise, no value outside its rows
    np.testing.assert_allclose(got[0][:len(x)], y, rtol=0, atol=1e-9 * (1 + np.ptp(y)))
    if periodic:
        shifted = _page_eval(law, xs[len(x):-3] + 2 * math.pi)
        np.testing.assert_allclose(shifted[0], got[0][len(x):-3] + (y[-1] - y[0]), rtol=0,
                                   atol=1e-9 * (1 + np.ptp(y)))
        np.testing.assert_allclose(shifted[1:], got[1:, len(x):-3], rtol=0,
                                   atol=1e-9 * (1 + np.ptp(y)))
    else:
        assert np.all(np.isnan(got[:, -3:]))


def test_the_linear_law_data_is_the_laws_coefficients():
    assert law_data(linear_law(3.0, -1.5)) == {"k": 3.0, "c": -1.5}


@pytest.fixture(scope="module")
def browser():
    b = browser_or_skip(1300, 1000)
    yield b
    b.close()


def _check_saved(browser, tmp_path: Path, state: dict, data: dict) -> None:
    """The page's values are ``solve``'s of the file it saves, which keeps the law.

    The posture, polygons, ω and α; the instant centers (I23 from the velocities,
    Sec. 5.4) and the curvature panel (Sec. 4.15) as graphkin finds them.
    """
    r = state["result"]
    text = browser.js("window.graphkinLive.toml()")
    saved = tmp_path / "saved.toml"
    saved.write_text(text, encoding="utf-8")
    f = tomllib.loads(text)
    # the follower keeps its law: no angle of its own written; the first drive's angle moved
    assert "follows" in f["drive"][1] and "angle" not in f["drive"][1]
    assert math.radians(f["drive"][0]["angle"]) == pytest.approx(state["drive"], abs=1e-12)
    sol = graphkin.load(saved).solve()
    assert bool(np.all(sol.valid))
    mech = sol.mechanism
    names = [n for lid, lk in mech.links.items() if lid != "1" for n in lk.points]
    size = 1.0 + max(abs(v) for n in names for v in r[n])
    for n in names:
        np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=REL * size, err_msg=n)
    frame = set(mech.links["1"].points)
    moving = [n for n in names if n not in frame]
    vs = 1.0 + max(abs(v) for n in moving for v in r[f"v({n})"])
    as_ = 1.0 + max(abs(v) for n in moving for v in r[f"a({n})"])
    for n in moving:
        np.testing.assert_allclose(np.subtract(r[f"v({n})"], r["o_v"]), sol.velocity(n),
                                   rtol=0, atol=REL * vs, err_msg=n)
        np.testing.assert_allclose(np.subtract(r[f"a({n})"], r["o_a"]), sol.acceleration(n),
                                   rtol=0, atol=REL * as_, err_msg=n)
    # ω and α to 1e-9 of the polygons' scales (a velocity over a link at least 1 in long)
    for lid in mech.links:
        if lid == "1":
            continue
        for lab, ref, sc in ((f"θ{lid}", sol.angle_rad(lid), 2 * math.pi),
                             (f"ω{lid}", sol.omega(lid), vs), (f"α{lid}", sol.alpha(lid), as_)):
            if lab in r:
                got = r[lab]
                if lab.startswith("θ"):  # the same direction: a whole turn apart at most
                    got = ref + math.remainder(got - float(ref), 2 * math.pi)
                np.testing.assert_allclose(got, ref, rtol=0, atol=REL * sc, err_msg=lab)
    assert state["centers"] is not None
    ic = instant_centers(sol)
    for lab in data["centers"]["labels"]:
        same_center(homogeneous(state["centers"][lab]), ic.values[lab], lab)
    # the curvature constructions (Sec. 4.15, from the accelerations) lose digits as 1/sin² of
    # the angle at B where links 4 and 5 near a line (the stretched five-bar at θ2 = 180°):
    # held to 1e-9 away from there (sin > 0.1)
    ab, cb = np.subtract(r["B"], r["A"]), np.subtract(r["B"], r["C"])
    sin_b = abs(ab[0] * cb[1] - ab[1] * cb[0]) / float(np.linalg.norm(ab) * np.linalg.norm(cb))
    if state.get("curvature") is not None and sin_b > 0.1:
        lc = curvature(sol)[data["curvature"]["link"]]
        same_curvature(data, state["curvature"], lc.values, size, steps=lc.construction.steps)


@pytest.mark.parametrize("name", FILES)
def test_the_page_moves_the_follower_with_the_drive_as_solve_says(browser, tmp_path, name):
    path = ROOT / "examples" / f"{name}.toml"
    mech = graphkin.load(path)
    data, _ = live_data(mech, load_toml(path), path.name)
    page = tmp_path / f"{name}.html"
    page.write_text(live_html(mech, load_toml(path), path.name), encoding="utf-8")
    browser.open(page)
    k0 = browser.js("window.graphkinLive.state().K")
    pivot = data["frame"]["O3"]
    law = mech.drives[1].law
    seen = []

    @examples(6)
    @given(turn=st.floats(-180.0, 180.0), dx=st.floats(-0.3, 0.3), dy=st.floats(-0.3, 0.3),
           move_pivot=st.booleans())
    def check(turn: float, dx: float, dy: float, move_pivot: bool) -> None:
        k = list(k0)
        if move_pivot:  # a drag of the frame pivot O3 (link 3's, the follower's)
            k[pivot[0]] += dx
            k[pivot[1]] += dy
        drive = data["drive"]["value"] + math.radians(turn)
        browser.js(f"window.graphkinLive.load({{K: {k!r}, drive: {drive!r}}})")
        state = browser.js("window.graphkinLive.state()")
        assert browser.errors() == []
        if state["result"] is None:  # the stretched five-bar past its stretched posture
            status = browser.js("document.getElementById('gk-status').textContent")
            assert "cannot be assembled" in status
            return
        r = state["result"]
        # θ3 is the law's at the new θ2 (the same direction: whole turns apart)
        ref = float(law.value(drive))
        assert abs(math.remainder(r["θ3"] - ref, 2 * math.pi)) <= 1e-12 * (1 + abs(ref))
        _check_saved(browser, tmp_path, state, data)
        seen.append(turn)

    check()
    assert seen  # at least one posture was compared


def test_the_table_page_meets_the_rows_and_the_chain_rule(browser, tmp_path):
    # fivebar_table.toml: at θ2 = 150° the table's row says θ3 = 142.5°; ω2 = 10 rad/s and
    # α2 = 0, so ω3 = f'(θ2) ω2 and α3 = f''(θ2) ω2² (the chain rule, Sec. 6.3), with f' and
    # f'' estimated here by central differences of the page's own θ3 (h = 1e-4 rad)
    path = ROOT / "examples" / "fivebar_table.toml"
    mech = graphkin.load(path)
    page = tmp_path / "table.html"
    page.write_text(live_html(mech, load_toml(path), path.name), encoding="utf-8")
    browser.open(page)
    h = 1e-4
    th = {}
    for k in (-1, 0, 1):
        x = math.radians(150.0) + k * h
        th[k] = browser.js(f"window.graphkinLive.setDrive({x!r})")
    r = th[0]
    assert math.degrees(r["θ3"]) % 360 == pytest.approx(142.5, abs=1e-9)
    d1 = (th[1]["θ3"] - th[-1]["θ3"]) / (2 * h)
    d2 = (th[1]["θ3"] - 2 * th[0]["θ3"] + th[-1]["θ3"]) / h**2
    assert r["ω3"] == pytest.approx(d1 * 10.0, rel=1e-6)
    assert r["α3"] == pytest.approx(d2 * 100.0, rel=1e-4, abs=1e-3)
    data, _ = live_data(mech, load_toml(path), path.name)
    _check_saved(browser, tmp_path, browser.js("window.graphkinLive.state()"), data)


def test_a_table_over_part_of_a_turn_moves_within_its_rows_and_says_why_beyond(browser,
                                                                              tmp_path):
    # fivebar_table.toml without its last two rows: θ3's table covers θ2 from 0° to 300° only
    # (a natural spline, not periodic); beyond, the page has no posture and says why
    text = (ROOT / "examples" / "fivebar_table.toml").read_text(encoding="utf-8")
    cut = text.replace(", [330, 667.5000],\n  [360, 765.0000],", ",")
    assert cut != text
    path = tmp_path / "partial.toml"
    path.write_text(cut, encoding="utf-8")
    mech = graphkin.load(path)
    assert mech.drives[1].law.domain == pytest.approx((0.0, math.radians(300.0)))
    data, _ = live_data(mech, load_toml(path), path.name)
    page = tmp_path / "partial.html"
    page.write_text(live_html(mech, load_toml(path), path.name), encoding="utf-8")
    browser.open(page)
    for deg, inside in ((210.0, True), (-10.0, False), (330.0, False), (300.0, True),
                        (45.0, True)):
        r = browser.js(f"window.graphkinLive.setDrive({math.radians(deg)!r})")
        status = browser.js("document.getElementById('gk-status').textContent")
        assert browser.errors() == []
        if inside:
            assert r is not None and status == ""
            if deg == 300.0:  # the last row: θ3 = 572.0096°
                assert math.degrees(r["θ3"]) % 360 == pytest.approx(572.0096 - 360, abs=1e-9)
            _check_saved(browser, tmp_path, browser.js("window.graphkinLive.state()"), data)
        else:
            assert r is None
            assert status == ("θ2 is outside the rows of the table θ3 follows it by (0° to "
                              "300°), which says nothing beyond them: drag back.")


_SUN = """\
title = "Planet on an arm rolling on a sun gear that follows the arm"
[links.1]
O = [0, 0]
[links.2]
O = [0, 0]
P = [60, 0]
[links.3]
P = [0, 0]
Q = [20, 0]
[links.4]
O = [0, 0]
S = [40, 0]
[[rolling]]
link = 4
on = 3
circle = { center = "O", radius = 40 }
on_circle = { center = "P", radius = 20 }
contact = "outside"
[[drive]]
link = 2
angle = 30
omega = 10
alpha = 3
[[drive]]
link = 4
follows = { link = 2, ratio = -0.5, offset = 15 }
"""


def test_a_planet_page_moves_the_follower_too(browser, tmp_path):
    # a planet on arm 2 rolling on sun gear 4 (rolling contact, Sec. 3.7), the sun following
    # the arm, θ4 = −θ2/2 + 15°, so ω4 = −5 and α4 = −1.5 rad/s² throughout; the planet is
    # laid off from the arm and the sun (roll_circle_angle): the page is the construction
    path = tmp_path / "sun.toml"
    path.write_text(_SUN, encoding="utf-8")
    mech = graphkin.load(path)
    data, _ = live_data(mech, load_toml(path), path.name)
    assert not data.get("newton") and data["follow"]
    page = tmp_path / "sun.html"
    page.write_text(live_html(mech, load_toml(path), path.name), encoding="utf-8")
    browser.open(page)
    for deg in (50.0, 90.0, -20.0, 200.0):
        r = browser.js(f"window.graphkinLive.setDrive({math.radians(deg)!r})")
        assert browser.errors() == [] and r is not None
        assert math.remainder(r["θ4"] - math.radians(15.0 - deg / 2), 2 * math.pi) == \
            pytest.approx(0.0, abs=1e-12)
        assert r["ω4"] == pytest.approx(-5.0, abs=1e-9)
        assert r["α4"] == pytest.approx(-1.5, abs=1e-9)
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        assert "follows" in tomllib.loads(saved.read_text(encoding="utf-8"))["drive"][1]
        sol = graphkin.load(saved).solve()
        for n in ("P", "Q", "S"):
            np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=REL * 100, err_msg=n)
        for lid in ("2", "3", "4"):
            assert r[f"ω{lid}"] == pytest.approx(float(sol.omega(lid)), abs=REL * 100)
            assert r[f"α{lid}"] == pytest.approx(float(sol.alpha(lid)), abs=REL * 1000)


_WHEEL = """\
title = "Example 3.9's wheel rolling on the ground, and a crank that follows the drive"
[links.1]
O2 = [0, 0]
G1 = [0, 0]
G2 = [1, 0]
O5 = [-300, 200]
[links.2]
O2 = [0, 0]
A = [150, 0]
[links.3]
A = [0, 0]
B = [200, 0]
[links.4]
G = [0, 0]
B = [0, 50]
[links.5]
O5 = [0, 0]
C = [80, 0]
[[rolling]]
link = 4
on = 1
circle = { center = "G", radius = 100 }
line = ["G1", "G2"]
side = "left"
[[drive]]
link = 2
angle = 90
omega = 10
alpha = 2
[[drive]]
link = 5
follows = { link = 2, ratio = -0.5, offset = 15 }
[assembly]
B = [200, 150]
"""


def test_a_newton_page_moves_the_follower_too(browser, tmp_path):
    # Example 3.9 (Fig. 3.18): the wheel 4 rolls on the ground, driven by the crank 2 and the
    # coupler 3; no ruler-and-compass step finds B (an arc about A against the trochoid of
    # B), so the page runs Newton's method.  A crank 5 follows the drive, θ5 = −θ2/2 + 15°,
    # so ω5 = −5 and α5 = −1 rad/s² throughout, and the wheel's center stays one radius
    # (100) above the ground
    path = tmp_path / "wheel.toml"
    path.write_text(_WHEEL, encoding="utf-8")
    mech = graphkin.load(path)
    data, _ = live_data(mech, load_toml(path), path.name)
    assert data.get("newton") and data["follow"]
    page = tmp_path / "wheel.html"
    page.write_text(live_html(mech, load_toml(path), path.name), encoding="utf-8")
    browser.open(page)
    for deg in (80.0, 100.0, 70.0, 110.0):
        r = browser.js(f"window.graphkinLive.setDrive({math.radians(deg)!r})")
        assert browser.errors() == [] and r is not None
        assert math.remainder(r["θ5"] - math.radians(15.0 - deg / 2), 2 * math.pi) == \
            pytest.approx(0.0, abs=1e-12)
        assert r["ω5"] == pytest.approx(-5.0, abs=1e-9)
        assert r["α5"] == pytest.approx(-1.0, abs=1e-9)
        assert r["G"][1] == pytest.approx(100.0, abs=1e-9 * 300)
        saved = tmp_path / "saved.toml"
        saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
        assert "follows" in tomllib.loads(saved.read_text(encoding="utf-8"))["drive"][1]
        sol = graphkin.load(saved).solve()
        for n in ("A", "B", "G", "C"):
            np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=REL * 300, err_msg=n)
        for lid in ("2", "3", "4", "5"):
            assert r[f"ω{lid}"] == pytest.approx(float(sol.omega(lid)), abs=REL * 100)
            assert r[f"α{lid}"] == pytest.approx(float(sol.alpha(lid)), abs=REL * 1000)
