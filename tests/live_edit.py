"""The live page's "save the edited mechanism", in Python, for the tests of the page's values.

The page (graphkin/render/live_app.py, ``edited()``) writes the file with the
drive moved and ``[assembly]`` hints at its points, so that ``graphkin solve``
of the saved file takes the branch the page shows.  The tests that run the
page's functions without the page (node) edit the parsed file the same way.
"""

from __future__ import annotations

import copy
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
                   size: float, rel: float = 1e-9) -> None:
    """The page's curvature values against graphkin's (points Cartesian, circles, lines)."""
    import numpy as np

    v = data["curvature"]
    for lab in v["labels"]:
        g = np.asarray(got[lab], dtype=float)
        r = np.asarray(ref[lab], dtype=float)
        if v["kinds"][lab] == "point":
            r = r[:2] / r[2]
        scale = max(size, float(np.abs(r).max(initial=0.0)))
        np.testing.assert_allclose(g, r, rtol=0, atol=rel * scale, err_msg=lab)
