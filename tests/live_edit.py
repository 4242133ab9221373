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
