"""A curvature step page draws each step on its own figure (issue 24, item 3).

Every step of ``graphkin steps -d curvature`` was drawn on the whole sheet of
four figures, each a quarter of the frame: hard to follow, 3.4 MB and ~30 s.
Each step is now drawn on the one figure that makes it ((a) to (d), Figs.
4.25-4.39), a size larger, and every figure of the sheet appears in turn.
"""

from __future__ import annotations

import re

from spec_data import EXAMPLES

import graphkin
from graphkin.render.teach import steps_html


def test_each_curvature_step_is_drawn_on_its_own_figure():
    # Example 3.1's coupler: J by Bobillier (b), the circles (a), E' by Bobillier's
    # conjugate construction (c) and Hain's construction of the cubic (d): all four figures
    sol = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml").solve()
    page = steps_html(sol, "curvature")
    sections = page.split('<section class="step')[1:]
    figures = [set(re.findall(r'panel-(inflection|bobillier|hartmann|cubic)"', s))
               for s in sections]
    drawn = [f for f in figures if f]
    assert drawn and all(len(f) == 1 for f in drawn), figures
    assert set().union(*drawn) == {"inflection", "bobillier", "hartmann", "cubic"}
    # one figure a step, not four: the page is a fraction of its former 3.4 MB
    assert len(page.encode()) < 2_500_000
