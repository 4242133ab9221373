"""The undercut flank of Fig. 7.18: the path of the mate's tip relative to the cut gear.

Independent checks: the path is a rigid relative motion (the tip stays ``R_a3`` from
gear 3's center carried in gear 2's frame, ``O2 + R(θ)(O3 − O2)``), the pitch circles roll
(gear 3 turns ``N2/N3`` as fast), and where Eq. (7.12) holds no tip enters a tooth.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from graphkin.cli import main
from graphkin.gears import layout
from graphkin.gears.file import load
from graphkin.gears.profile import TIP_SAMPLES, tip_path

ROOT = Path(__file__).resolve().parents[2]


def test_the_tip_path_is_the_rolling_relative_motion():
    pair = load(ROOT / "examples" / "gears" / "fig7_18.toml")
    lay = layout(pair)
    path = tip_path(pair, lay.points, 3)
    o2, o3 = np.array(lay.points["O2"]), np.array(lay.points["O3"])
    _, ra3 = pair.outside_radii
    span = 4 * math.pi / pair.driver.teeth
    th = np.linspace(-span, span, TIP_SAMPLES)
    # gear 3's center seen from gear 2 (which turned −θ): O2 + R(θ)(O3 − O2)
    d = o3 - o2
    c3 = o2 + np.stack([np.cos(th) * d[0] - np.sin(th) * d[1],
                        np.sin(th) * d[0] + np.cos(th) * d[1]], axis=-1)
    assert np.hypot(*(path - c3).T) == pytest.approx(np.full(TIP_SAMPLES, ra3), rel=1e-12)
    # at θ = 0 the tip is where the drawing puts it, on gear 3's addendum circle
    mid = TIP_SAMPLES // 2
    assert np.hypot(*(path[mid] - o3)) == pytest.approx(ra3, rel=1e-12)
    # the tip's direction from its center turns by θ (1 + N2/N3) in gear 2's frame
    a = np.unwrap(np.arctan2(*(path - c3).T[::-1]))
    assert a[-1] - a[0] == pytest.approx(2 * span * (1 + 16 / 16), rel=1e-9)


@pytest.mark.parametrize(("name", "cut"), [("examples/gears/fig7_18.toml", {"2", "3"}),
                                           ("gallery/gears/fig7_25.toml", {"2"}),
                                           ("examples/gears/ex7_1.toml", set())])
def test_the_undercut_is_drawn_only_where_the_teeth_interfere(name, cut, tmp_path):
    out = tmp_path / "g.svg"
    assert main(["draw", str(ROOT / name), "-d", "gears", "-o", str(out)]) == 0
    ids = {el.get("id") for el in ET.fromstring(out.read_bytes()).iter()}
    assert {c for c in ("2", "3") if f"action-undercut-{c}" in ids} == cut
