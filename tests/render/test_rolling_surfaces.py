"""The circle a gear rolls on is drawn: the sun and the ring of a planetary train.

Acceptance input: a sun 2 (pitch radius 30 mm) driven, planet 4 (20 mm) on arm 3
(O to P = 50 mm), ring 70 mm fixed in the frame.  Only the planet, the circle of
each `[[rolling]]` entry's `link`, was drawn; its `on_circle`s (the sun, the
ring) were not, and the panel was sized without them.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.render import draw, to_bytes

DATA = Path(__file__).resolve().parents[1] / "data" / "audit7"


def _groups(svg: bytes, prefix: str) -> dict[str, np.ndarray]:
    """The vertices (SVG pixels) of every group whose id starts with ``prefix``."""
    out = {}
    for g in ET.fromstring(svg).iter():
        gid = g.get("id") or ""
        if not gid.startswith(prefix):
            continue
        pts = []
        for el in g.iter():
            d = el.get("d")
            if d:
                nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", d)]
                pts += list(zip(nums[0::2], nums[1::2], strict=False))
        out[gid] = np.array(pts)
    return out


@pytest.mark.parametrize("diagram", ["posture", "velocity"])
def test_sun_and_ring_are_drawn_about_the_main_axis(diagram: str) -> None:
    svg = to_bytes(draw(graphkin.load(DATA / "planet_mech.toml").solve(), diagram).figure)
    planet = _groups(svg, "roller-4")
    rims = _groups(svg, "rolls-on-")
    assert len(planet) == 1 and len(rims) == 2
    p = next(iter(planet.values()))
    p_r = (p.max(axis=0) - p.min(axis=0)).mean() / 2          # the planet, 20 mm
    p_c = (p.max(axis=0) + p.min(axis=0)) / 2                 # P = (50, 0)
    radii, centres = [], []
    for pts in rims.values():
        radii.append((pts.max(axis=0) - pts.min(axis=0)).mean() / 2)
        centres.append((pts.max(axis=0) + pts.min(axis=0)) / 2)
    # by the file: the sun 30/20 and the ring 70/20 of the planet's radius, both about O,
    # 50/20 planet radii from P along the arm (θ3 = 0: to the left of P)
    assert sorted(r / p_r for r in radii) == pytest.approx([1.5, 3.5], rel=2e-3)
    for c in centres:
        assert c - p_c == pytest.approx([-2.5 * p_r, 0.0], abs=0.5)


def test_the_panel_is_sized_to_hold_the_ring() -> None:
    from graphkin.render import as_source
    from graphkin.render.mechanism import mechanism_extent

    pts = np.array(mechanism_extent(as_source(graphkin.load(DATA / "planet_mech.toml").solve())))
    # the ring: 70 mm about O = (0, 0) every way
    assert pts.min(axis=0) == pytest.approx([-70.0, -70.0], abs=1e-9)
    assert pts.max(axis=0) == pytest.approx([70.0, 70.0], abs=1e-9)


def test_a_compound_planet_is_numbered_once() -> None:
    """Example 11.7's planet 4 is two circles of one link (radii 1.5 and 0.8 in, each in
    its own `[[rolling]]` entry): the drawing names link 4 once, not "4 4"."""
    path = Path(__file__).resolve().parents[2] / "gallery" / "gears" / "ex11_7.toml"
    mech = graphkin.load(path)
    assert sum(r.link == "4" for r in mech.rolling) == 2
    svg = to_bytes(draw(mech.solve(), "posture").figure)
    ids = [g.get("id") or "" for g in ET.fromstring(svg).iter()]
    assert len([i for i in ids if re.fullmatch(r"(.*-)?number-4", i)]) == 1, ids
