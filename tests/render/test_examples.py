"""Every spec example draws: its posture and, where the file gives rates, its polygons.

One sheet per example holds its posture and polygons (ids prefixed by the
diagram for velocity and acceleration); each step must be there as a group,
each named point of a moving link as a letter, and the drawing must agree
with the analytic solver (the results table).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET

import pytest
from spec_data import EXAMPLES

from graphkin.mechanisms.model import FRAME

NAMES = sorted(p.stem for p in EXAMPLES.glob("*.toml") if p.stem != "expected") \
    if EXAMPLES.exists() else []


@pytest.mark.parametrize("name", NAMES)
def test_spec_example_draws_every_construction(gk, name):
    sol = gk.solved(name)
    expected = ["posture"] + (["velocity", "acceleration"] if sol.mechanism.has_rates else [])
    sheet = "+".join(expected)
    root = ET.fromstring(gk.svg(name, sheet))
    ids = {el.get("id") for el in root.iter() if el.get("id")}
    for d in expected:
        assert d in sol.constructions
        prefix = "" if d == "posture" else f"{d}-"
        missing = [s.step_id for s in sol.constructions[d] if prefix + s.step_id not in ids]
        assert not missing, f"{d}: {missing}"
    mech = sol.mechanism
    for n in mech.point_names:
        if n in mech.helper_points:  # drawn as the line or slot it defines (issue 11)
            assert f"label-{n}" not in ids, n
        elif any(lid != FRAME for lid in mech.point_links[n]):
            assert f"label-{n}" in ids, n
    helpers = {f"{q}_{n}" for n in mech.helper_points for q in ("V", "A", "R")}
    assert not helpers & {r.key for r in gk.drawn(name, sheet).sheet.rows}
    rows = gk.drawn(name, sheet).sheet.rows
    assert rows and all(r.diff is not None and r.diff < 1e-6 for r in rows), \
        [(r.key, r.diff) for r in rows if r.diff is None or r.diff >= 1e-6]


@pytest.mark.parametrize("name", NAMES)
def test_spec_example_centers_and_curvature_are_deterministic_svg(gk, name):
    # issue 5's acceptance: the centers diagram for every file, the curvature diagram
    # where the file gives rates; valid SVG, the same bytes twice, every step a group and
    # every point's letter real <text>.
    from graphkin.kinematics.curvature import curvature_constructions
    from graphkin.kinematics.instant_centers import instant_centers
    from graphkin.render import draw, to_bytes

    sol = gk.solved(name)
    sheets = [("centers", None, instant_centers(sol).construction)]
    if sol.mechanism.has_rates:
        # the curvature of every link that turns about a moving pole (not a frame pivot)
        for lid, cx in curvature_constructions(sol).items():
            if len(cx) > 1:
                sheets.append(("curvature", lid, cx))
    for diagram, link, cx in sheets:
        first = to_bytes(draw(sol, diagram, link=link).figure)
        assert first == to_bytes(draw(sol, diagram, link=link).figure)
        root = ET.fromstring(first)
        ids = {el.get("id") for el in root.iter() if el.get("id")}
        texts = {"".join(el.itertext()) for el in root.iter() if el.tag.endswith("text")}
        assert cx.steps, diagram
        missing = [s.step_id for s in cx if not any(i.endswith(s.step_id) for i in ids)]
        assert not missing, f"{diagram} {link}: {missing}"
        mech = sol.mechanism
        for n in mech.point_names:
            if n in mech.helper_points:
                assert not any(i.endswith(f"label-{n}") for i in ids), (diagram, n)
            elif any(lid != FRAME for lid in mech.point_links[n]):
                # (a sheet of several panels prefixes its ids: inflection-label-C)
                assert n in texts or any(i.endswith(f"label-{n}") for i in ids), (diagram, n)
