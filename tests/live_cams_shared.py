"""What the live pages of cam mechanisms' tests share: a page's state, a drag, ``solve``'s values.

tests/render/test_live_cams.py (the page held at the file's cam angle) and
tests/render/test_live_cam_turn.py (the cam turned) compare the page with
``graphkin solve`` of the file it saves, build random cam mechanisms the same
way, and drag with the same pointer events.
"""

from __future__ import annotations

import math
import tempfile
from pathlib import Path

import numpy as np
from live_edit import homogeneous, same_curvature

import graphkin
from graphkin.cams import Cam
from graphkin.cams.analytic import profile
from graphkin.cams.examples import example_6_6
from graphkin.errors import GraphkinError
from graphkin.kinematics.curvature.link import curvature
from graphkin.kinematics.instant_centers import instant_centers
from graphkin.mechanisms import from_dict

REL = 1e-9
TMP = Path(tempfile.mkdtemp(prefix="graphkin-live-cams-"))


def page_state(browser) -> dict:
    st_ = browser.js("window.graphkinLive.state()")
    assert browser.errors() == []
    return st_


def handle(browser, name: str) -> tuple[float, float]:
    """The client coordinates of the point ``name``'s drag handle on the posture."""
    r = browser.js("(function () { var r = document.querySelector('.gk-handle[data-kind="
                   f'"point"][data-name="{name}"]\').getBoundingClientRect(); return '
                   "[r.x + r.width / 2, r.y + r.height / 2]; })()")
    return r[0], r[1]


def drag(browser, start: tuple[float, float], stop: tuple[float, float], n: int = 4) -> None:
    """A drag of the pointer (DevTools mouse events: the page sees pointer events)."""
    browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=start[0], y=start[1])
    browser.send("Input.dispatchMouseEvent", type="mousePressed", x=start[0], y=start[1],
                 button="left", clickCount=1)
    for k in range(1, n + 1):
        x, y = (start[i] + (stop[i] - start[i]) * k / n for i in (0, 1))
        browser.send("Input.dispatchMouseEvent", type="mouseMoved", x=x, y=y, button="left",
                     buttons=1)
    browser.send("Input.dispatchMouseEvent", type="mouseReleased", x=stop[0], y=stop[1],
                 button="left", clickCount=1)


def same_center(got, ref, size: float, lab: str) -> None:
    """A center of the page (homogeneous) is graphkin's: a point, or a direction at infinity."""
    g = np.asarray(got, dtype=float)
    r = np.asarray(ref, dtype=float)
    if r[2] == 0.0:
        u, v = g[:2] / np.hypot(*g[:2]), r[:2] / np.hypot(*r[:2])
        np.testing.assert_allclose(u * np.sign(np.dot(u, v)), v, rtol=0, atol=REL, err_msg=lab)
        return
    q = r[:2] / r[2]
    np.testing.assert_allclose(g[:2] / g[2], q, rtol=0, atol=REL * (size + np.hypot(*q)),
                               err_msg=lab)


def same_as_solve(browser, tmp_path: Path, mech: graphkin.Mechanism, state: dict) -> None:
    """Every point, velocity, acceleration, link rate, instant center and curvature is
    ``solve``'s (the equivalent linkage of the saved file, at its cam angle)."""
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    sol = graphkin.load(saved).solve()
    D = browser.js("JSON.parse(document.getElementById('gk-data').textContent)")
    size = 1.0 + mech.scale
    if state["centers"] is not None:
        ic = instant_centers(sol)
        for lab in D["centers"]["labels"]:
            same_center(homogeneous(state["centers"][lab]), ic.values[lab], size, lab)
    if state["curvature"] is not None:
        lc = curvature(sol)[D["curvature"]["link"]]
        same_curvature(D, state["curvature"], lc.values, size, steps=lc.construction.steps)
    r = state["result"]
    checked = 0
    for lk in mech.links.values():
        for n in lk.points:
            if n not in r:
                continue
            checked += 1
            np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=REL * size,
                                       err_msg=n)
            for pre, get in (("v", sol.velocity), ("a", sol.acceleration)):
                if f"{pre}({n})" in r:
                    ref = np.asarray(get(n), dtype=float)
                    scale = size + float(np.abs(ref).max())
                    np.testing.assert_allclose(r[f"{pre}({n})"], ref, rtol=0,
                                               atol=REL * scale, err_msg=f"{pre}({n})")
    for lid in mech.links:
        for w, get in (("ω", sol.omega), ("α", sol.alpha)):
            if f"{w}{lid}" in r:
                ref = float(get(lid))
                assert abs(r[f"{w}{lid}"] - ref) <= REL * (1.0 + abs(ref)), f"{w}{lid}"
    assert checked >= 3


def cam_file(cam: Cam, path: Path, theta2: float, axis: float, omega: float, alpha: float,
          turns: tuple[float, float, float, float]) -> dict | None:
    """A cam whose follower's point P drives a dyad P-Q-O7 to a frame pivot O7 (draggable).

    The dyad is laid out at the file's cam angle (Q and O7 at random directions from P),
    so it assembles there; None where the cam has no equivalent linkage at that angle.
    """
    f = cam.follower
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    mm = {"mm": 1.0, "in": 25.4}[cam.unit]
    size *= mm
    data = {"units": "mm", "links": {"1": {"O2": [3.0, -2.0]}, "4": {"P": [0.4 * size,
                                                                          0.3 * size]}},
            "cams": {"link": 2, "follower": 4, "file": str(path), "axis": axis},
            "drive": {"link": 2, "angle": theta2, "omega": omega, "alpha": alpha}}
    try:
        p = np.asarray(from_dict(data).solve().position("P"), dtype=float)
    except GraphkinError:
        return None
    a, la, b, lb = turns
    q = p + la * size * np.array([math.cos(a), math.sin(a)])
    o7 = q + lb * size * np.array([math.cos(b), math.sin(b)])
    data["links"]["1"]["O7"] = o7.tolist()
    data["links"]["6"] = {"P": [0.0, 0.0], "Q": [la * size, 0.0], "E": [0.5 * la * size,
                                                                      0.3 * size]}
    data["links"]["7"] = {"O7": [0.0, 0.0], "Q": [lb * size, 0.0]}
    data["assembly"] = {"Q": q.tolist()}
    return data


def straight_angle() -> float:
    """A cam angle of Ex 6.6 where the pitch curve is straight (1/ρ = 0), by bisection.

    Found on cams/analytic.profile alone: Eq. (6.37)'s curvature changes sign between
    the convex flank (Θ = 30°, ρ = 72.757 mm) and the concave valley (Θ = 181°).
    """
    cam = example_6_6()

    def kappa(th: float) -> float:
        pr = profile(cam, np.array([th]))
        assert pr.rho_pitch is not None
        return 1.0 / float(pr.rho_pitch[0])

    grid = np.radians(np.arange(30.0, 182.0, 1.0))
    vals = [kappa(t) for t in grid]
    i = next(k for k in range(len(vals) - 1) if vals[k] > 0 >= vals[k + 1])
    a, b = float(grid[i]), float(grid[i + 1])
    for _ in range(200):
        m = 0.5 * (a + b)
        if m in (a, b):
            break
        a, b = (m, b) if kappa(m) > 0 else (a, m)
    return a if abs(kappa(a)) < abs(kappa(b)) else b
