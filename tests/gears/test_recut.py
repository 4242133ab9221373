"""The tooth outline re-cut by the mate where the teeth interfere (Sec. 7.7, Figs. 7.18, 7.25).

The check is independent of the boolean difference that makes the outline:
the path of the mate's tip corner (:func:`graphkin.gears.profile.tip_path`,
the pair's rolling inverted in closed form) runs through the original tooth
(the interference, Eq. 7.12) and never inside the re-cut one; where the
teeth do not interfere nothing is cut.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from shapely.geometry import Point, Polygon

from graphkin.gears import Gear, GearPair, layout
from graphkin.gears.file import load
from graphkin.gears.profile import mesh_phases, tip_path, tooth_template
from graphkin.gears.tooth import GearKind
from graphkin.render.gears_recut import recut_template

ROOT = Path(__file__).resolve().parents[2]


def _tooth(lay, cut: int, tpl: np.ndarray) -> Polygon:
    o = np.array(lay.points[f"O{cut}"])
    th = tpl[:, 1] + mesh_phases(lay.pair)[cut - 2]
    xy = np.stack([o[0] + tpl[:, 0] * np.cos(th), o[1] + tpl[:, 0] * np.sin(th)], axis=-1)
    return Polygon(np.vstack([[o], xy]))


@pytest.mark.parametrize(("lay", "cut"), [
    pytest.param(layout(load(ROOT / "examples" / "gears" / "fig7_18.toml")), 2, id="fig7_18-2"),
    pytest.param(layout(load(ROOT / "examples" / "gears" / "fig7_18.toml")), 3, id="fig7_18-3"),
    pytest.param(layout(GearPair(
        Gear("pinion", 2, 12, 1.0, math.radians(20), 1.0, 1.25, clearance=0.25),
        Gear("rack", 3, 0, 1.0, math.radians(20), 1.0, 1.25, clearance=0.25,
             kind=GearKind.RACK))), 2, id="12-teeth-and-a-rack"),
])
def test_the_recut_tooth_keeps_clear_of_the_mates_tip(lay, cut):
    gear = lay.pair.driver if cut == 2 else lay.pair.driven
    m = gear.module
    original = _tooth(lay, cut, tooth_template(gear, lay.pair.outside_radii[cut - 2]))
    tpl = recut_template(lay, cut)
    assert tpl is not None
    recut = _tooth(lay, cut, tpl)
    assert recut.is_valid and recut.area < original.area
    assert recut.difference(original).area < 1e-9 * m * m    # only material removed
    path = tip_path(lay.pair, lay.points, 3 if cut == 2 else 2)
    inner = recut.buffer(-1e-6 * m)
    assert any(original.buffer(-1e-3 * m).contains(Point(p)) for p in path)  # it did interfere
    assert not any(inner.contains(Point(p)) for p in path)


@pytest.mark.parametrize("name", ["ex7_1.toml", "prob7_19.toml", "fig7_21.toml"])
def test_nothing_is_cut_without_interference(name):
    lay = layout(load(ROOT / "examples" / "gears" / name))
    assert not lay.interference
    assert recut_template(lay, 2) is None and recut_template(lay, 3) is None
