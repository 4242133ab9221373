"""Bodies drawn as the book draws them, read back from the SVG (Fig. 4.18a, issue 11 item 4)."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.render import draw, to_bytes

ROOT = Path(__file__).resolve().parents[2]
CAM = ROOT / "gallery/mechanisms/fig4_18_cam_follower.toml"


def _paths(svg: bytes, gid: str) -> np.ndarray:
    """Every vertex of the paths in group ``gid`` (SVG pixels, y down)."""
    root = ET.fromstring(svg)
    group = next(el for el in root.iter() if el.get("id") == gid)
    pts = []
    for el in group.iter():
        d = el.get("d")
        if d:
            nums = [float(v) for v in re.findall(r"-?\d+(?:\.\d+)?(?:e-?\d+)?", d)]
            pts += list(zip(nums[0::2], nums[1::2], strict=False))
    return np.array(pts)


@pytest.mark.parametrize("diagram", ["posture", "velocity", "acceleration"])
def test_the_cam_disc_touches_the_follower_face(diagram):
    # Example 4.7: the cam's center B stays 1.5 in (its radius) from the follower's face,
    # so the disc drawn about B touches the face drawn through C (Fig. 4.18a).
    svg = to_bytes(draw(graphkin.load(CAM).solve(), diagram).figure)
    disc = _paths(svg, "body-0")
    face = _paths(svg, "body-1")
    lo, hi = disc.min(axis=0), disc.max(axis=0)
    width, height = hi - lo
    assert width == pytest.approx(height, rel=0.01)     # a circle, not an ellipse
    centre, radius = (lo + hi) / 2, width / 2
    # the face is a bar: its long axis (principal direction) is the face's line
    mean = face.mean(axis=0)
    _, _, vt = np.linalg.svd(face - mean)
    u = vt[0]
    n = np.array([-u[1], u[0]])
    gap = abs(float(n @ (centre - mean)))    # from the disc's center to the face's line
    assert gap == pytest.approx(radius, rel=0.01)


def test_a_file_without_bodies_draws_none():
    svg = to_bytes(draw(graphkin.load(ROOT / "tests/data/spec/ex4_7_cam_follower.toml").solve(),
                        "posture").figure)
    assert b'id="body-' not in svg


def test_a_follower_face_a_roller_rolls_on_is_drawn_to_the_contact():
    # Example 4.8 (Fig. 4.20a): the follower 3 is its pivot D and a flat face x = -1.4 in
    # (link 3's coordinates) that the roller of radius 1.5 in touches; its face points are
    # no corners of a body, but the face itself is drawn, out to the roller.
    from shapely.geometry import Point, Polygon

    from graphkin.render.mechanism import BAR_HALF

    svg = to_bytes(draw(graphkin.load(ROOT / "gallery/mechanisms/fig4_20_roller_follower.toml")
                        .solve(), "posture").figure)
    roller = _paths(svg, "roller-4")
    lo, hi = roller.min(axis=0), roller.max(axis=0)
    centre, radius = Point(*((lo + hi) / 2)), float((hi - lo)[0] / 2)
    follower = Polygon(_paths(svg, "link-3"))
    # the bar's centre line is the face: its edge is half a bar width (72 px/in) nearer
    assert follower.distance(centre) == pytest.approx(radius - BAR_HALF * 72, abs=1.0)
