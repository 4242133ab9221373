"""Tip interference (fouling) of a pinion inside a ring of few more teeth.

The verdict of :func:`graphkin.gears.profile.ring_overlap` (each pinion point
tested against the ring's teeth in polar form, a band and a half angle) is
held against an independent computation: shapely's intersection of the
pinion's and the ring's tooth polygons at the same positions.  A 25° pinion
of 20 teeth fouls a ring of 22 (two teeth more) although Eq. (7.12) holds;
the ring of Fig. 7.11 (72 teeth) is clear.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import Polygon
from shapely.ops import unary_union

from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.gears import layout
from graphkin.gears.file import loads
from graphkin.gears.profile import gear_teeth, mesh_phases, ring_overlap

RING = """units = "mm"
module = 2
pressure_angle = {phi}
[gears.pinion]
teeth = {n2}
[gears.ring]
teeth = {n3}
kind = "internal"
"""


def _shapely_overlap(lay, steps: int = 61) -> float:
    """The largest area shared by the pinion's and the ring's teeth over one pinion pitch."""
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    ra2, ra3 = pair.outside_radii
    psi2, psi3 = mesh_phases(pair)
    o2, o3 = lay.points["O2"], lay.points["O3"]
    ring_teeth = gear_teeth(g3, ra3, o3, psi3)
    # the ring's material: the annulus out to beyond its root, less the spaces between teeth
    outline = np.concatenate(list(ring_teeth))
    far = Polygon(np.array(o3) + 2 * g3.root_radius * np.stack(
        [np.cos(np.linspace(0, 2 * np.pi, 181)), np.sin(np.linspace(0, 2 * np.pi, 181))], -1))
    ring = far.difference(Polygon(outline).buffer(0)).buffer(0)
    worst = 0.0
    for th in np.linspace(0.0, 2 * math.pi / g2.teeth, steps):
        pin = unary_union([Polygon(np.vstack([[o2], t])).buffer(0) for t in gear_teeth(
            g2, ra2, o2, psi2 - th)])
        # the ring turns the same way, N2/N3 as far: held still, the pinion turns the difference
        ring_now = ring
        from shapely import affinity

        ring_now = affinity.rotate(ring, -th * g2.teeth / g3.teeth, origin=o3, use_radians=True)
        worst = max(worst, pin.buffer(0).intersection(ring_now.buffer(0)).area)
    return worst


@pytest.mark.parametrize(("phi", "n2", "n3", "fouls"), [
    (25, 20, 22, True), (25, 20, 24, True), (25, 20, 30, False), (20, 20, 72, False),
])
def test_known_rings(phi, n2, n3, fouls, tmp_path, capsys):
    lay = layout(loads(RING.format(phi=phi, n2=n2, n3=n3)))
    assert not lay.interference            # Eq. (7.12) holds in every case
    m = 2.0
    assert (ring_overlap(lay.pair, lay.points) > 1e-6 * m) == fouls
    # polygons of chords touching along the flanks share ~1e-5 m²; fouling shares 0.04 m² and up
    assert (_shapely_overlap(lay) > 1e-3 * m * m) == fouls
    src = tmp_path / "ring.toml"
    src.write_text(RING.format(phi=phi, n2=n2, n3=n3), encoding="utf-8")
    assert main(["gears", str(src), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["mesh"]["tip_interference"] is fouls


@settings(max_examples=8, deadline=None)
@given(st.sampled_from([20.0, 22.5, 25.0]), st.integers(12, 30), st.integers(1, 30))
def test_the_verdict_agrees_with_polygon_overlap(phi, n2, more):
    try:
        lay = layout(loads(RING.format(phi=phi, n2=n2, n3=n2 + more)))
    except InputError:      # the ring's tips inside its base circle: refused, not checked
        return
    depth = ring_overlap(lay.pair, lay.points)
    area = _shapely_overlap(lay)
    m = 2.0
    if depth > 0.05 * m:                   # clearly in: the polygons share area
        assert area > 1e-3 * m * m
    if depth == 0.0:                       # clearly out: the polygons at most touch (chords)
        assert area < 1e-3 * m * m
