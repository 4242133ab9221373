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
        if any(lid != FRAME for lid in mech.point_links[n]):
            assert f"label-{n}" in ids, n
    rows = gk.drawn(name, sheet).sheet.rows
    assert rows and all(r.diff is not None and r.diff < 1e-6 for r in rows), \
        [(r.key, r.diff) for r in rows if r.diff is None or r.diff >= 1e-6]
