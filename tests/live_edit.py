"""The live page's "save the edited mechanism", in Python, for the tests of the page's values.

The page (graphkin/render/live_app.py, ``edited()``) writes the file with the
drive moved and ``[assembly]`` hints at its points, so that ``graphkin solve``
of the saved file takes the branch the page shows.  The tests that run the
page's functions without the page (node) edit the parsed file the same way.
"""

from __future__ import annotations

import copy
import json
import math
from typing import Any


def edited(data: dict[str, Any], drive: float, r: dict[str, Any]) -> dict[str, Any]:
    """The file as the page saves it: the drive moved, assembly hints at the page's points."""
    f = copy.deepcopy(data["file"])
    d = data["drive"]
    dr = f["drive"][d["index"]] if isinstance(f["drive"], list) else f["drive"]
    dr[d["key"]] = math.degrees(drive) if d["degrees"] else drive
    if data["assembly"]:
        f["assembly"] = dict(f.get("assembly", {}))
        for n in data["assembly"]:
            f["assembly"][n] = [r[n][0], r[n][1]]
    return f


def homogeneous(entry: Any) -> Any:
    """A center of the page's ``state()`` (``{position}`` or ``{direction}``, the JSON's shape)
    as a homogeneous point ``[x, y, 1]`` or ``[dx, dy, 0]``; None stays None."""
    if entry is None:
        return None
    assert set(entry) in ({"position"}, {"direction"}), entry
    if "direction" in entry:
        dx, dy = entry["direction"]
        assert abs(math.hypot(dx, dy) - 1.0) < 1e-12, entry  # a unit vector
        return [dx, dy, 0.0]
    return [*entry["position"], 1.0]


def same_center(got: Any, ref: Any, lab: str, atol: float = 1e-8) -> None:
    """Two points of the projective plane are the same: unit vectors equal up to sign."""
    import numpy as np

    g = np.asarray(got, dtype=float)
    r = np.asarray(ref, dtype=float)
    g, r = g / np.linalg.norm(g), r / np.linalg.norm(r)
    if float(np.dot(g, r)) < 0:
        g = -g
    np.testing.assert_allclose(g, r, rtol=0, atol=atol, err_msg=lab)


def same_curvature(data: dict[str, Any], got: dict[str, Any], ref: dict[str, Any],
                   size: float, rel: float = 1e-9, steps: Any = ()) -> int:
    """The page's curvature values against graphkin's (points Cartesian, circles, lines).

    A value the page leaves out (``null``: no clean answer in Cartesian
    coordinates) must be one graphkin's construction reaches through a point at
    infinity at this posture (Hain's G_T where the cubic's n is infinite,
    Example 4.16): ``steps`` is graphkin's construction, whose ``ref`` values
    are homogeneous.  Returns the number of values compared.
    """
    import numpy as np

    v = data["curvature"]
    kinds = {o: s.kind for s in steps for o in s.outputs}
    made = {o: s for s in steps for o in s.outputs}

    def at_infinity(lab: str) -> bool:
        todo, seen = [lab], set()
        while todo:
            x = todo.pop()
            if x in seen:
                continue
            seen.add(x)
            h = np.asarray(ref.get(x, np.nan), dtype=float)
            if kinds.get(x) == "point" and h.shape == (3,) and (
                    not np.all(np.isfinite(h)) or abs(h[2]) <= 1e-8 * np.hypot(h[0], h[1])):
                return True
            if x in made:
                todo.extend(made[x].inputs)
        return False

    figure = 0.0
    for p in ("I", "J"):
        h = np.asarray(ref.get(p, np.nan), dtype=float)
        if h.shape == (3,) and np.all(np.isfinite(h)) and abs(h[2]) > 1e-8 * np.hypot(h[0], h[1]):
            figure = max(figure, float(np.abs(h[:2] / h[2]).max()))
    n = 0
    for lab in v["labels"]:
        if got[lab] is None:
            # none in graphkin either at this posture (the Bresse circle where α = 0), or one
            # it reaches through a point at infinity
            assert lab not in ref or at_infinity(lab), (
                f"{lab}: null on the page, finite in graphkin")
            continue
        assert lab in ref, f"{lab}: drawn on the page, none in graphkin"
        g = np.asarray(got[lab], dtype=float)
        r = np.asarray(ref[lab], dtype=float)
        if v["kinds"][lab] == "point":
            r = r[:2] / r[2]
        # round-off of the construction's own figure: the inflection circle (I, J) can be
        # far larger than the mechanism (a cam's nearly straight pitch curve: IJ = 600
        # beside a size of 8), and Ball's point U is found through it
        scale = max(size, float(np.abs(r).max(initial=0.0)), figure)
        np.testing.assert_allclose(g, r, rtol=0, atol=rel * scale, err_msg=lab)
        n += 1
    return n


def page_file(tmp_path: Any, path: Any) -> Any:
    """The live page of the mechanism file ``path``, written into ``tmp_path``."""
    import graphkin
    from graphkin.files import load_toml
    from graphkin.render.live import live_html

    out = tmp_path / (path.stem + ".html")
    out.write_text(live_html(graphkin.load(path), load_toml(path), path.name), encoding="utf-8")
    return out


def same_as_saved_solve(browser: Any, tmp_path: Any, rel: float = 1e-9) -> tuple[dict, Any]:
    """The page's every moving point, its images, and each θ, ω, α against ``solve`` of the
    file the page saves (``saved.toml`` in ``tmp_path``); ``(state's result, solution)``.

    An angle is compared modulo 2π (the page counts a gear's angle on past 360°); a file
    without rates has its positions compared only.
    """
    import numpy as np

    import graphkin

    r = browser.js("window.graphkinLive.state()")["result"]
    assert r is not None
    saved = tmp_path / "saved.toml"
    saved.write_text(browser.js("window.graphkinLive.toml()"), encoding="utf-8")
    sol = graphkin.load(saved).solve()
    mech = sol.mechanism
    frame = set(mech.links["1"].points)
    names = [n for lid, lk in mech.links.items() if lid != "1" for n in lk.points
             if n not in frame]
    # (a train of gears on fixed pivots has no moving point: its rates are the links')
    scale = 1.0 + max((abs(v) for n in names for v in r[n]), default=0.0)
    for n in names:
        np.testing.assert_allclose(r[n], sol.position(n), rtol=0, atol=rel * scale, err_msg=n)
    if not mech.has_rates:
        return r, sol
    vs = 1.0 + max((abs(v) for n in names for v in np.subtract(r[f"v({n})"], r["o_v"])),
                   default=0.0)
    as_ = 1.0 + max((abs(v) for n in names for v in np.subtract(r[f"a({n})"], r["o_a"])),
                    default=0.0)
    for n in names:
        np.testing.assert_allclose(np.subtract(r[f"v({n})"], r["o_v"]), sol.velocity(n),
                                   rtol=0, atol=rel * vs, err_msg=f"v({n})")
        np.testing.assert_allclose(np.subtract(r[f"a({n})"], r["o_a"]), sol.acceleration(n),
                                   rtol=0, atol=rel * as_, err_msg=f"a({n})")
    for lid in mech.links:
        np.testing.assert_allclose(r[f"ω{lid}"], sol.omega(lid), rtol=0,
                                   atol=rel * (1 + abs(sol.omega(lid))), err_msg=f"ω{lid}")
        np.testing.assert_allclose(r[f"α{lid}"], sol.alpha(lid), rtol=0,
                                   atol=rel * (1 + abs(sol.alpha(lid)) + sol.omega(lid) ** 2),
                                   err_msg=f"α{lid}")
        if lid != "1":  # the page's angle may be on the covering: the same posture mod 2π
            d = float(r[f"θ{lid}"]) - float(sol.angle_rad(lid))
            assert abs(math.remainder(d, 2 * math.pi)) < rel * (1 + abs(d)), f"θ{lid}"
    return r, sol


def curvature_page(data: dict[str, Any], js: str, drive: float) -> Any:
    """The live page's construction and curvature panel at ``drive``, run in node.

    ``RESULT`` is ``{r, v}``: the construction's values and ``gkCurvature``'s
    panel, or null where the posture cannot be assembled.
    """
    from jsrun import run_js

    from graphkin.render.live_app import LIVE_LIB

    src = (js + LIVE_LIB + f"\nconst D = {json.dumps(data)};"
           "\nconst I = Object.assign({}, D.inputs);"
           f"\nI[D.drive.label] = {float(drive)!r};"
           "\nconst r = construction(I, D.K);"
           "\nconst RESULT = r === null ? null : {r: r, v: gkCurvature(D.curvature, r)};")
    return run_js(src)


def open_random_page(browser: Any, tmp_path: Any, mech: Any, raw: dict[str, Any]) -> Any:
    """Open the live page of a random mechanism; its page data, or None where live refuses it.

    ``raw`` is the mechanism's file data (``RandomMechanism.data``); a mechanism
    the page cannot hold (:class:`~graphkin.errors.InputError`) gives None.
    """
    from graphkin.errors import InputError
    from graphkin.render.live import live_data, live_html

    try:
        data, _ = live_data(mech, raw, "random.toml")
    except InputError:
        return None
    page = tmp_path / "random.html"
    page.write_text(live_html(mech, raw, "random.toml"), encoding="utf-8")
    browser.open(page)
    return data
