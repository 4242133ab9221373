"""The live page (graphkin live): dragged in headless Chromium, it computes what `solve` says.

A drag is simulated with the DevTools protocol's mouse events (the page sees
pointer events), the page's state is read back, the edited mechanism the page
saves is loaded and solved by graphkin in Python (the replay of the recorded
construction, not the page's JavaScript), and the positions, velocities and
accelerations must agree to 1e-9 of their scale.  Skipped without Chromium.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from live_edit import homogeneous
from live_edit import page_file as _page
from spec_data import EXAMPLES

import graphkin
from graphkin.errors import InputError
from graphkin.files import load_toml
from graphkin.render.live import live_html, script_json

REL = 1e-9




def _handle(browser, kind: str, name: str | None = None) -> tuple[float, float]:
    sel = f'.gk-handle[data-kind="{kind}"]' + (f'[data-name="{name}"]' if name else "")
    r = browser.js(f"(function () {{ var r = document.querySelector('{sel}')"
                   ".getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2];"
                   " })()")
    return r[0], r[1]


def _drag(browser, start: tuple[float, float], stop: tuple[float, float], n: int = 6) -> None:
    x0, y0 = start
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x0, y=y0)
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=x0, y=y0, button="left",
                 clickCount=1)
    for k in range(1, n + 1):
        x = x0 + (stop[0] - x0) * k / n
        y = y0 + (stop[1] - y0) * k / n
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y, button="left",
                     buttons=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=stop[0], y=stop[1],
                 button="left", clickCount=1)


def _same_as_solve(browser, tmp_path: Path) -> dict:
    """The page's values against `solve` of the file the page saves; returns the state."""
    state = browser.js("window.graphkinLive.state()")
    r = state["result"]
    assert r is not None
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    sol = graphkin.load(saved).solve()
    assert bool(np.all(sol.valid))
    mech = sol.mechanism
    names = [n for lid, lk in mech.links.items() if lid != "1" for n in lk.points]
    scale = 1.0 + max(abs(v) for n in names for v in r[n])
    for n in names:
        np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=REL * scale, err_msg=n)
    if "o_v" in r:
        frame = set(mech.links["1"].points)
        # every moving point has its images (the frame's points are the poles)
        names = [n for n in names if n not in frame]
        assert all(f"v({n})" in r and f"a({n})" in r for n in names)
        vs = 1.0 + max(abs(v) for n in names for v in r[f"v({n})"])
        as_ = 1.0 + max(abs(v) for n in names for v in r[f"a({n})"])
        for n in names:
            v = np.subtract(r[f"v({n})"], r["o_v"])
            a = np.subtract(r[f"a({n})"], r["o_a"])
            np.testing.assert_allclose(v, sol.velocity(n), rtol=0, atol=REL * vs, err_msg=n)
            np.testing.assert_allclose(a, sol.acceleration(n), rtol=0, atol=REL * as_,
                                       err_msg=n)
    return state


def test_dragging_the_crank_changes_the_polygons_as_solve_says(browser, tmp_path):
    # Example 3.1 (Fig. 3.6): drag B; the drive follows the pointer and every value the page
    # shows is the one `graphkin solve` gives for the file the page saves
    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    before = browser.js("window.graphkinLive.state()")
    bx, by = _handle(browser, "drive")
    ax, ay = _handle(browser, "frame", "A")
    # turn the crank by about 20° about A (screen y points down)
    t = math.atan2(-(by - ay), bx - ax) - math.radians(20.0)
    rr = math.hypot(bx - ax, by - ay)
    _drag(browser, (bx, by), (ax + rr * math.cos(t), ay - rr * math.sin(t)))
    state = _same_as_solve(browser, tmp_path)
    turned = math.degrees(state["drive"] - before["drive"])
    assert -22.0 < turned < -18.0  # the crank followed the pointer (pixel rounding aside)
    assert browser.errors() == []


def test_dragging_frame_pivots_edits_the_mechanism(browser, tmp_path):
    # drag D, then A: the saved file has the new pivots, and solve agrees with the page
    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    dx, dy = _handle(browser, "frame", "D")
    _drag(browser, (dx, dy), (dx + 25, dy - 10))
    ax, ay = _handle(browser, "frame", "A")
    _drag(browser, (ax, ay), (ax - 8, ay + 12))
    state = _same_as_solve(browser, tmp_path)
    r = state["result"]
    assert r["D"][0] > 10.3 and r["D"][1] > 0.1  # moved right and up, in inches
    assert r["A"][0] < -0.1 and r["A"][1] < -0.1
    # undo twice, then the pivots are the book's again
    browser.js("document.getElementById('gk-undo').click()")
    browser.js("document.getElementById('gk-undo').click()")
    r = browser.js("window.graphkinLive.state()")["result"]
    assert r["A"] == [0, 0] and r["D"] == [10, 0]
    assert browser.errors() == []


def test_a_posture_that_cannot_be_assembled_is_said_so(browser, tmp_path):
    # Example 3.1 (AB 4, BC 18, CD 11, AD 10): the arcs about B and D meet only where
    # |DB| >= 18 - 11 = 7, and |DB|² = 116 - 80 cos θ2 < 49 for cos θ2 > 0.8375 (θ2 < 33.1°):
    # at θ2 = 10° the four-bar cannot be assembled
    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    r = browser.js(f"window.graphkinLive.setDrive({math.radians(10.0)})")
    assert r is None
    status = browser.js("document.getElementById('gk-status').textContent")
    assert "cannot be assembled" in status
    body = browser.js("document.body.innerText")
    assert "NaN" not in body and "Infinity" not in body
    # reset: back to the file's posture, assembled
    browser.js("document.getElementById('gk-reset').click()")
    assert browser.js("window.graphkinLive.state()")["result"] is not None
    assert browser.js("document.getElementById('gk-status').textContent") == ""


@pytest.mark.parametrize("name", sorted(p.name for p in EXAMPLES.glob("ex[0-9]*.toml")))
def test_every_spec_example_opens_offline(browser, tmp_path, name):
    page = _page(tmp_path, EXAMPLES / name)
    text = page.read_text(encoding="utf-8")
    assert not re.search(r"""(src|href)\s*=\s*["']?(https?:)?//""", text)  # nothing fetched
    assert len(text.encode("utf-8")) < 1_000_000
    browser.open(page)
    assert browser.errors() == []
    assert browser.js("window.graphkinLive.state()")["result"] is not None
    _same_as_solve(browser, tmp_path)
    # every handle dragged a little: still what solve says of the saved file
    handles = browser.js("[].map.call(document.querySelectorAll('.gk-handle'), function (h) {"
                         " return [h.getAttribute('data-kind'), h.getAttribute('data-name')]; })")
    assert handles
    for kind, n in handles:
        x, y = _handle(browser, kind, n)
        _drag(browser, (x, y), (x + 4, y - 3), n=2)
        if browser.js("window.graphkinLive.state()")["result"] is None:
            browser.js("document.getElementById('gk-undo').click()")  # cannot be assembled
            continue
        _same_as_solve(browser, tmp_path)
    assert browser.errors() == []


def test_hostile_title_is_text(browser, tmp_path):
    title = 'x</script><!--<script>alert(1)</script>"\' & \u2028 </title>'
    src = (EXAMPLES / "ex3_1_fourbar.toml").read_text(encoding="utf-8")
    src = re.sub(r'^title = .*$', lambda m: "title = " + json.dumps(title), src, count=1,
                 flags=re.M)
    path = tmp_path / "hostile.toml"
    path.write_text(src, encoding="utf-8")
    page = _page(tmp_path, path)
    browser.open(page)
    assert browser.errors() == []
    assert browser.js("document.querySelector('h1').textContent") == title
    assert browser.js("document.querySelectorAll('script').length") == 2
    # the saved file keeps the title exactly
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    assert graphkin.load(saved).title == title


def test_script_json_cannot_close_the_script():
    s = script_json({"t": "</script><!-- & \u2028"})
    assert "<" not in s and ">" not in s and "&" not in s
    assert json.loads(s) == {"t": "</script><!-- & \u2028"}


def test_a_mechanism_without_a_construction_is_one_line(monkeypatch):
    # an operation with no template: one InputError naming the file (the CLI: one line, exit 2)
    import graphkin.render.live as live
    from graphkin.construction.codegen import Unsupported

    def refuse(*a, **k):
        raise Unsupported("the operation 'x' has no template")

    monkeypatch.setattr(live, "generate_js", refuse)
    mech = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml")
    with pytest.raises(InputError, match="no live page: the operation 'x'") as e:
        live_html(mech, load_toml(EXAMPLES / "ex3_1_fourbar.toml"), "ex3_1_fourbar.toml")
    assert e.value.file == "ex3_1_fourbar.toml"


def test_dragging_a_coupler_point_changes_the_link(browser, tmp_path):
    # Example 3.1: drag E (a point of the coupler 3 only); the saved file has E's new local
    # coordinates on link 3, and solve agrees with the page's posture and polygons
    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    ex, ey = _handle(browser, "point", "E")
    before = browser.js("window.graphkinLive.state()")["result"]
    _drag(browser, (ex, ey), (ex + 20, ey + 15))
    state = _same_as_solve(browser, tmp_path)
    r = state["result"]
    # E moved right and down; B and C did not move (the coupler's shape changed, not the loop)
    assert r["E"][0] > before["E"][0] + 0.2 and r["E"][1] < before["E"][1] - 0.2
    np.testing.assert_allclose(r["C"], before["C"], rtol=0, atol=1e-12)
    saved = load_toml(tmp_path / "saved.toml")
    assert saved["links"]["3"]["E"] != [10, -4]
    assert browser.errors() == []


def test_coupler_curve_is_the_sweep(browser, tmp_path):
    # the coupler curve of E over the whole turn, from the page, against graphkin's sweep of
    # the same file (the compiled kernels in Python); the postures that cannot be assembled
    # (θ2 < 33.1° past the file's 120°, see above) are null in the page and NaN in the sweep
    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    curve = browser.js("window.graphkinLive.state()")["curves"]["E"]
    assert len(curve) == 360
    mech = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml")
    sw = mech.sweep(count=360, start=120.0)
    x, y = sw.columns["x_E"], sw.columns["y_E"]
    got = np.array([p if p is not None else [np.nan, np.nan] for p in curve], dtype=float)
    # the sweep marks unclean postures it still assembles; the page refuses them: compare
    # where both answer, and the page never answers where the sweep cannot assemble
    assert not np.any(np.isfinite(got[:, 0]) & ~sw.assembled)
    both = np.isfinite(got[:, 0]) & np.isfinite(x)
    assert both.sum() > 250
    np.testing.assert_allclose(got[both, 0], x[both], rtol=0, atol=1e-9 * 30)
    np.testing.assert_allclose(got[both, 1], y[both], rtol=0, atol=1e-9 * 30)


def test_instant_centers_follow_the_drag(browser, tmp_path):
    # Example 3.1 (Fig. 3.19's four-bar): after a drag of D, the page's I13 and I24 (Kennedy's
    # lines through the pins) are graphkin's instant centers of the saved file
    from graphkin.kinematics.instant_centers import instant_centers

    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    dx, dy = _handle(browser, "frame", "D")
    _drag(browser, (dx, dy), (dx + 15, dy - 20))
    state = _same_as_solve(browser, tmp_path)
    ic = instant_centers(graphkin.load(tmp_path / "saved.toml").solve())
    for lab in ("I13", "I24", "I23", "I34"):
        ref = np.asarray(ic.values[lab], dtype=float)
        got = np.asarray(homogeneous(state["centers"][lab]), dtype=float)
        np.testing.assert_allclose(got[:2] / got[2], ref[:2] / ref[2], rtol=0,
                                   atol=1e-9 * 30, err_msg=lab)
    assert browser.js("document.querySelectorAll('.gk-kennedy').length") == 4


def test_switching_the_branch_is_the_other_assembly(browser, tmp_path):
    # Example 3.1 at θ2 = 120°: C on the other side of the line BD (the crossed four-bar,
    # Sec. 2.8 case 4): C mirrored in BD, and solve of the saved file (its assembly hints
    # at the page's points) gives the same posture and polygons
    browser.open(_page(tmp_path, EXAMPLES / "ex3_1_fourbar.toml"))
    r0 = browser.js("window.graphkinLive.state()")["result"]
    browser.js("document.getElementById('gk-branch').value = 'C';"
               "document.getElementById('gk-switch').click()")
    r = _same_as_solve(browser, tmp_path)["result"]
    b, d, c0 = (np.asarray(r0[n], dtype=float) for n in ("B", "D", "C"))
    u = (d - b) / np.linalg.norm(d - b)
    mirror = b + 2 * np.dot(c0 - b, u) * u - (c0 - b)
    np.testing.assert_allclose(r["C"], mirror, rtol=0, atol=1e-9 * 30)
    browser.js("document.getElementById('gk-undo').click()")
    np.testing.assert_allclose(browser.js("window.graphkinLive.state()")["result"]["C"],
                               r0["C"], rtol=0, atol=0)


def test_every_gallery_file_opens(browser, tmp_path):
    # the gallery's mechanisms: every page opens without an error and equals solve (a
    # mechanism only Newton's method solves runs it on the page: render/live_newton.py)
    root = Path(__file__).resolve().parents[2] / "gallery"
    opened = 0
    for path in sorted((*root.glob("mechanisms/*.toml"), *root.glob("centers/*.toml"),
                        *root.glob("curvature/*.toml"), root / "gears" / "ex11_7.toml")):
        page = _page(tmp_path, path)
        browser.open(page)
        assert browser.errors() == [], path.name
        assert browser.js("window.graphkinLive.state()")["result"] is not None, path.name
        _same_as_solve(browser, tmp_path)
        opened += 1
    assert opened >= 25


def test_the_command_writes_the_page_or_says_why_in_one_line(tmp_path, capsys):
    from graphkin.cli import main

    out = tmp_path / "live.html"
    assert main(["live", str(EXAMPLES / "ex3_1_fourbar.toml"), "-o", str(out)]) == 0
    assert out.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    capsys.readouterr()
    root = Path(__file__).resolve().parents[2]
    # a rolling wheel (Newton's method on the page) opens too
    assert main(["live", str(root / "examples" / "ex3_9_rolling_wheel.toml"), "-o",
                 str(tmp_path / "w.html")]) == 0
    capsys.readouterr()
    # a second drive that follows the first by a law moves with it (test_live_laws.py)
    assert main(["live", str(root / "examples" / "fivebar_coupled.toml"), "-o",
                 str(tmp_path / "f.html")]) == 0
    capsys.readouterr()
    rc = main(["live", str(root / "examples" / "nonexistent.toml"), "-o",
               str(tmp_path / "n.html")])
    err = capsys.readouterr().err.strip().splitlines()
    assert rc == 2 and len(err) == 1 and "nonexistent.toml" in err[0]
