"""Instant-center and curvature drawings: generic over their recorded steps."""

from __future__ import annotations

import numpy as np
import pytest
from numpy.testing import assert_allclose
from spec_data import EXPECTED

from graphkin.construction import Construction
from graphkin.render import DiagramUnavailable, draw, repr_svg
from graphkin.render import sources as render_sources


def test_centers_drawing_has_every_kennedy_step_at_its_place(gk):
    d = gk.drawn("ex3_1_fourbar", "centers")
    cx = d.sheet.painters["centers"].cx
    assert {s.step_id for s in cx} <= set(d.groups)
    want = EXPECTED["ex3_1_fourbar.toml"]["instant_centers.1-3.position"][0]
    assert_allclose(d["I13"].get_xydata()[0], want, atol=1e-3)
    rows = [r for r in d.sheet.rows if r.key.startswith("center-")]
    assert len(rows) == 6  # n(n-1)/2 for n = 4 (Eq. 3.20)
    assert all(r.diff is not None and r.diff < 1e-9 for r in rows)


def test_curvature_drawing_shows_the_inflection_circle(gk):
    d = gk.drawn("ex4_14_inflection_bresse", "curvature")
    # the sheet is split into the book's figures (issue 11): every step is in one of them
    cx = gk.solved("ex4_14_inflection_bresse")
    from graphkin.kinematics.curvature import curvature

    steps = {s.step_id for s in curvature(cx)["3"].construction}
    assert all(any(g.endswith(sid) for g in d.groups) for sid in steps)
    circle = d["inflection-inflection circle"]
    # Example 4.14: inflection circle diameter 19.26 in (book); 19.24904 exact (expected.toml)
    want = EXPECTED["ex4_14_inflection_bresse.toml"]["curvature.3.inflection_diameter"][0]
    assert 2 * circle.get_radius() == pytest.approx(want, abs=1e-3)
    rows = {r.key: r for r in d.sheet.rows}
    assert rows["curvature-inflection-diameter"].exact_value[0] == pytest.approx(want, abs=1e-3)
    assert all(r.diff is not None and r.diff < 1e-6 for r in d.sheet.rows)


def test_missing_module_says_not_available_yet(gk, monkeypatch):
    monkeypatch.setitem(render_sources.optional_modules, "centers", "graphkin.no_such_module")
    with pytest.raises(DiagramUnavailable, match="not available yet"):
        draw(gk.solved("ex3_1_fourbar"), "centers")


def test_repr_svg_of_a_solution_and_of_constructions(gk):
    sol = gk.solved("ex2_5_open")
    svg = repr_svg(sol)
    assert svg is not None and svg.lstrip().startswith("<?xml")
    assert all(f'id="{s.step_id}"' in svg for s in sol.constructions["posture"])
    cx = Construction()
    cx.add("point", (), ("A",), xy=(0.0, 0.0), role="given")
    cx.add("point", (), ("D",), xy=(8.0, 0.0), role="given")
    cx.add("circle", ("A",), ("k_A",), radius=5.0)
    cx.add("circle", ("D",), ("k_D",), radius=5.0)
    cx.add("intersect_circles", ("k_A", "k_D"), ("C",), branch="left", role="result")
    d = draw(cx, "posture")
    # the 3-4-5 triangle: C = (4, 3) by hand
    assert_allclose(d["C"].get_xydata()[0], [4.0, 3.0], atol=1e-12)
    assert np.isclose(d["k_A"].width / 2, 5.0)
    # a polygon construction cannot be evaluated without its posture: no drawing, no error
    assert repr_svg(gk.solved("ex3_1_fourbar").constructions["velocity"]) is None
