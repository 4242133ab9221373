"""Checks shared by the gear-train layout tests (a laid-out train read back).

Meshes touch at their operating pitch circles (Eq. 7.2: radii in the ratio of
the teeth); gears that do not mesh stand clear (apart, or inside a ring), but
for two on one axis or the two axes of a mesh (one behind the other).
"""

from __future__ import annotations

import math
from typing import Any

import pytest


def assert_meshes_touch_and_others_clear(train: Any, lay: Any, sol: Any, kind: str) -> None:
    """Assert the layout ``lay`` of ``train``, solved as ``sol``, meshes and clears."""
    size = max(lay.radius.values())
    center = {g: tuple(float(c) for c in sol.position(p)) for g, p in lay.axis_point.items()}
    ring = set()
    pairs = set()
    for m, (ra, rb) in zip(train.meshes, lay.operating, strict=True):
        c = math.dist(center[m.driver], center[m.driven])
        internal = m.contact == "internal"
        assert c == pytest.approx(abs(ra - rb) if internal else ra + rb, abs=1e-9 * size)
        n1, n2 = float(train.size[m.driver]), float(train.size[m.driven])
        assert ra / rb == pytest.approx(n1 / n2, rel=1e-12)       # Eq. (7.2)
        if internal:
            ring.add(m.driven if n2 > n1 else m.driver)
        pairs.add((center[m.driver], center[m.driven]))
    gears = list(train.size)
    for i, g in enumerate(gears):
        for h in gears[i + 1:]:
            p, q = center[g], center[h]
            if math.dist(p, q) <= 1e-9 * size or (p, q) in pairs or (q, p) in pairs:
                continue            # one axis, or the two axes of a mesh: one behind the other
            d, r, s = math.dist(p, q), lay.radius[g], lay.radius[h]
            apart = d >= r + s
            inside = (h in ring and d + r <= s) or (g in ring and d + s <= r)
            assert apart or inside, (kind, g, h, d, r, s)
    assert not any("overlap" in n for n in lay.notes)    # nothing drawn overlapping
