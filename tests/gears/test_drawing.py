"""The drawing of a pair in mesh (``graphkin draw GEARFILE -d gears``) read back from its SVG.

Every step of the layout's construction is a group found by its id in both
panels, the teeth, the path of contact, the angles of approach and recess
and (only when the teeth interfere, Fig. 7.18) the interference have their
own groups, the letters are real text, and no label collides with another
label or with a line of another group (font metrics, as every figure).
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from graphkin.cli import main
from graphkin.gears import Gear, GearPair, layout
from graphkin.gears.file import load
from graphkin.render.gears import draw_gears
from graphkin.render.labels import collisions
from graphkin.render.svg import to_bytes

SVG = "{http://www.w3.org/2000/svg}"


def _ids(data: bytes) -> dict[str, ET.Element]:
    ids: dict[str, ET.Element] = {}
    for el in ET.fromstring(data).iter():
        i = el.get("id")
        if i is not None:
            assert i not in ids, f"duplicate id {i}"
            ids[i] = el
    return ids


def _text(el: ET.Element) -> str:
    return "".join((t.text or "") for t in el.iter() if t.tag in (f"{SVG}text", f"{SVG}tspan"))


def _check(lay, drawing) -> dict[str, ET.Element]:
    ids = _ids(to_bytes(drawing.figure))
    for prefix in ("pair-", "action-"):
        for step in lay.construction:
            assert prefix + step.step_id in ids, prefix + step.step_id
        for gid in ("teeth-2", "teeth-3", "path-of-contact"):
            assert prefix + gid in ids
    for gid in ("approach-2", "recess-2"):
        assert "pair-" + gid in ids
    # (c) the involute struck on its tangents (Step 6): every arc, tangent and point T_k
    from graphkin.render.gears import INVOLUTE_PARTS

    for k in range(1, INVOLUTE_PARTS + 1):
        for what in (f"T{k}", f"t{k}", f"k{k}", f"A{k}"):
            assert any(i.startswith("involute-step-") and i.endswith(f"-{what}") for i in ids)
    assert "involute-involute-curve" in ids
    assert ("action-interference" in ids) == lay.interference
    # the letters of the zone of action (Figs. 7.9, 7.17): C, D and P, and A and B unless
    # they lie far along the line of action (a gear much larger than its pinion)
    reach = max(3 * lay.path, 6 * lay.pair.driver.module)
    for step in lay.construction:
        near = math.dist(lay.points.get(step.label, (0.0, 0.0)), lay.points["P"]) <= reach
        if step.label in ("C", "D", "P") or (step.label in ("A", "B") and near):
            el = ids[f"label-action-{step.step_id}-letter"]
            assert _text(el) == step.label
    assert collisions(drawing) == []
    return ids


@pytest.mark.parametrize("name", ["ex7_1.toml", "ex7_3.toml", "fig7_18.toml", "fig7_21.toml",
                                  "fig7_11.toml"])
def test_book_figures_read_back(gear_examples, name):
    lay = layout(load(gear_examples / name))
    ids = _check(lay, draw_gears(lay))
    # the results table: the contact ratio read off the construction beside Eq. (7.9)
    table = "".join(_text(el) for el in ids.values() if el.tag == f"{SVG}g")
    assert "contact ratio" in table


@settings(max_examples=4, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(10, 40), st.sampled_from([10, 25, 60, 90, 400]),
       st.sampled_from([14.5, 20.0, 25.0]),
       st.floats(0.0, 0.5))
def test_random_pairs_read_back(n2, n3, phi, stretch):
    m = 2.0
    g2 = Gear("pinion", 2, n2, m, math.radians(phi), m, 1.25 * m, clearance=0.25 * m)
    g3 = Gear("gear", 3, n3, m, math.radians(phi), m, 1.25 * m, clearance=0.25 * m)
    # mounted up to half a module apart (Fig. 7.21b)
    pair = GearPair(g2, g3, g2.pitch_radius + g3.pitch_radius + stretch * m)
    lay = layout(pair)
    _check(lay, draw_gears(lay, table=False))


def test_cli_draws_a_gear_file(gear_examples, tmp_path, capsys):
    out = tmp_path / "mesh.svg"
    assert main(["draw", str(gear_examples / "fig7_18.toml"), "-d", "gears", "-o", str(out)]) == 0
    ids = _ids(out.read_bytes())
    assert "action-interference" in ids
    assert main(["draw", str(gear_examples / "ex7_1.toml"), "-d", "velocity", "-o",
                 str(out)]) == 2
    assert "-d gears" in capsys.readouterr().err


def test_step_frames_draw_the_construction_so_far(gear_examples):
    """`steps -d gears`: frame k draws steps 0..k only, the newest highlighted, no teeth yet."""
    lay = layout(load(gear_examples / "ex7_1.toml"))
    step = lay.construction.step_of("A")
    d = draw_gears(lay, table=False, upto=step.index)
    ids = _ids(to_bytes(d.figure))
    assert "action-" + step.step_id in ids
    later = lay.construction.step_of("C")
    assert "action-" + later.step_id not in ids and "action-teeth-2" not in ids
    assert d.groups["action-" + step.step_id].get_children()   # A is drawn
    assert collisions(d) == []


def test_steps_gears_refuses_a_mechanism_file(tmp_path, capsys):
    from pathlib import Path

    mech = Path(__file__).resolve().parents[2] / "examples" / "fourbar.toml"
    assert main(["steps", str(mech), "-d", "gears", "-o", str(tmp_path / "s.html")]) == 2
    assert "-d gears" in capsys.readouterr().err


def test_teeth_too_fine_to_see_are_left_to_their_circles():
    """Two 10000-tooth gears: panel (a) draws their circles only (the teeth would be a grey
    band); the zone of action still draws its teeth one by one."""
    m = 1.0
    g2 = Gear("a", 2, 10000, m, math.radians(20), m, 1.25 * m, clearance=0.25 * m)
    g3 = Gear("b", 3, 10000, m, math.radians(20), m, 1.25 * m, clearance=0.25 * m)
    d = draw_gears(layout(GearPair(g2, g3)), table=False)
    assert not d.groups["pair-teeth-2"].get_children()
    assert d.groups["action-teeth-2"].get_children()
