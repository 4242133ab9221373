"""Loaded random mechanisms and the live page's forces read back, for the live force tests.

``loaded(family)`` gives a random mechanism of a family of tests/strategies.py
with a force, a couple or mass properties on its links; ``page_forces`` runs
the page's own functions (the posture construction, then ``gkForces``) on
JavaScript numbers (node, else headless Chromium); ``same_forces`` holds them
to graphkin's force analysis in Python (1e-9 of the forces' scale, moments to
that times the mechanism's size) and ``polygons_close`` checks Σ F = 0 on
each link (Sec. 12.4).
"""

from __future__ import annotations

import copy
import json
from typing import Any

import numpy as np
from hypothesis import strategies as st
from jsrun import run_js

from graphkin.render.live_app import LIVE_LIB

REL = 1e-9


@st.composite
def loaded(draw: Any, family: Any) -> dict[str, Any]:
    """A random mechanism of ``family`` with a force, a couple or mass properties on its links."""
    rm = draw(family)
    data = copy.deepcopy(rm.data)
    s = rm.scale()
    num = st.floats(-1.0, 1.0, allow_nan=False)
    loads: list[dict[str, Any]] = []
    inertia: dict[str, Any] = {}
    moving = [lid for lid in data["links"] if str(lid) != "1"]
    for lid in draw(st.lists(st.sampled_from(moving), min_size=1, max_size=len(moving),
                             unique=True)):
        pts = list(data["links"][lid].values())
        what = draw(st.sampled_from(["force", "couple", "inertia", "force+inertia"]))
        if "force" in what:
            name = f"Q{lid}"
            if all(p == pts[0] for p in pts):  # a block: load its own point
                name = next(iter(data["links"][lid]))
            else:
                data["links"][lid][name] = [draw(num) * s, draw(num) * s]
            loads.append({"link": int(lid), "point": name,
                          "force": f"{draw(st.floats(1.0, 1000.0))} N at "
                                   f"{draw(st.floats(-180.0, 180.0))} deg"})
        if what == "couple":
            loads.append({"link": int(lid), "torque": draw(st.floats(1.0, 1000.0)) * s
                          * draw(st.sampled_from([-1, 1]))})
        if "inertia" in what and not all(p == pts[0] for p in pts):
            name = f"G{lid}"
            data["links"][lid][name] = [draw(num) * s, draw(num) * s]
            inertia[str(lid)] = {"center": name, "mass": f"{draw(st.floats(0.01, 10.0))} kg",
                                 "moment": f"{draw(st.floats(0.0, 1.0))} kg*m^2"}
    if not loads and not inertia:  # a block alone drew mass properties: load it instead
        loads.append({"link": int(moving[-1]), "torque": s * draw(st.floats(1.0, 1000.0))})
    data["loads"] = loads
    if inertia:
        data["inertia"] = inertia
        if draw(st.booleans()):
            data["gravity"] = {"acceleration": "9.80665 m/s^2 at -90 deg"}
    data.setdefault("units", {})["force"] = "N"
    return data


def page_forces(data: dict, js: str, drive: float) -> dict | None:
    """What the page computes at the drive ``drive``: the posture and its forces."""
    src = (js + LIVE_LIB + f"\nconst D = {json.dumps(data)};"
           "\nconst I = Object.assign({}, D.inputs);"
           f"\nI[D.drive.label] = {float(drive)!r};"
           "\nconst r = construction(I, D.K);"
           "\nconst RESULT = r === null ? null : {r: r, f: gkForces(D.forces, r)};")
    return run_js(src)


def same_forces(got: dict[str, Any], F: dict[str, Any], fs: Any) -> None:
    """Every joint force and drive of the page equals graphkin's, to 1e-9 of their scale."""
    mech = fs.mechanism
    big = max([float(np.hypot(*w[:2])) for w in fs.forces.values()] + [1e-300])
    arm = 1.0 + mech.scale
    for key, lab in F["joints"].items():
        w, g = np.asarray(got[lab], dtype=float), fs.forces[key]
        assert np.all(np.abs(w[:2] - g[:2]) <= REL * big), (key, w, g)
        assert abs(w[2] - g[2]) <= REL * big * arm, (key, w, g)
    for lid, d in F["drives"].items():
        kind, t = fs.drives[lid]
        size = big * arm if kind == "torque" else big
        assert abs(float(got[d["label"]]) - t) <= REL * size, (lid, got[d["label"]], t)


def polygons_close(got: dict[str, Any], F: dict[str, Any]) -> None:
    """Each link's force polygon closes (Σ F = 0 with the inertia forces, Sec. 12.4)."""
    big = max([float(np.hypot(*got[lab][:2])) for lab in F["joints"].values()] + [1e-300])
    for lid, poly in F["polygons"].items():
        total = np.zeros(2)
        for f in poly:
            if "along" in f:
                total += float(got[f["label"]]) * np.asarray(got[f["along"]], dtype=float)
            else:
                total += f["sign"] * np.asarray(got[f["label"]][:2], dtype=float)
        assert np.all(np.abs(total) <= REL * big), (lid, total)
