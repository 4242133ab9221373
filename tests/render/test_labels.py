"""Labels collide with nothing: boxes from matplotlib's font metrics, read back from the drawing.

Issue 11's acceptance: for every spec example and every gallery file, each
diagram kind, no label box overlaps another label box or crosses a line, arc
or outline of another group; mathtext sub- and superscripts are at least 6 pt;
every component of an acceleration polygon is lettered.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from spec_data import EXAMPLES

import graphkin
from graphkin.render import DiagramUnavailable, draw
from graphkin.render.labels import collisions
from graphkin.render.text import is_math

GALLERY = Path(__file__).resolve().parents[2] / "gallery"
DIAGRAMS = ("posture", "velocity", "acceleration", "centers", "curvature")
FILES = sorted(p for p in EXAMPLES.glob("ex*.toml") if p.stem != "expected") + sorted(
    p for folder in ("mechanisms", "centers", "curvature") for p in (GALLERY / folder).glob(
        "*.toml"))
SHRINK = 0.7
"""mathtext's subscript size relative to its text (matplotlib's SHRINK_FACTOR)."""


def _solved(path: Path) -> graphkin.Solution:
    return graphkin.load(path).solve()


CROWDED: dict[str, str] = {}
"""Files with a known collision, each with why (strict: the test fails once it is gone)."""


def _case(p: Path):
    marks = [pytest.mark.xfail(reason=CROWDED[p.stem], strict=True)] if p.stem in CROWDED else []
    return pytest.param(p, marks=marks, id=f"{p.parent.name}/{p.stem}")


@pytest.mark.parametrize("path", [_case(p) for p in FILES])
def test_no_label_collides_in_any_diagram(path):
    sol = _solved(path)
    found = {}
    for diagram in DIAGRAMS:
        try:
            d = draw(sol, diagram)
        except DiagramUnavailable:
            continue
        bad = collisions(d)
        if bad:
            found[diagram] = bad
        for t in d.texts.values():
            if is_math(t.get_text()):
                # (6/0.7 pt) × 0.7 is 6 pt less a round-off
                assert t.get_fontsize() * SHRINK >= 6.0 - 1e-9, (diagram, t.get_text())
    assert not found, found


def test_every_acceleration_component_is_lettered():
    # Example 4.7 (cam and follower as a pin in a slot): A_B = A_BA^n + A_BA^t,
    # A_B3 = A_D + A_B3D^n + A_B3D^t = A_B - A_B/3^c - A_B/3^t, A_C = A_D + A_CD^n + A_CD^t
    d = draw(_solved(EXAMPLES / "ex4_7_cam_follower.toml"), "acceleration")
    texts = {t.get_text() for t in d.texts.values()}
    for want in ("$A^{n}_{BA}$", "$A^{t}_{BA}$", "$A^{n}_{B3D}$", "$A^{t}_{B3D}$",
                 "$A^{c}_{B/3}$", "$A^{t}_{B/3}$", "$A^{n}_{CD}$", "$A^{t}_{CD}$"):
        assert want in texts, (want, sorted(texts))


def test_collisions_finds_an_overlap():
    # the measurement itself can fail: two labels moved onto one another are reported
    d = draw(_solved(EXAMPLES / "ex3_1_fourbar.toml"), "posture")
    a, b = d.texts["B"], d.texts["C"]
    b.set_position(a.get_position())
    assert any(kind == "label" for kind, *_ in collisions(d))


@pytest.mark.parametrize("target", ["title-text-cubic", "scale-text-cubic"])
def test_collisions_finds_a_label_on_a_panel_title_or_scale(target):
    # a panel's title and scale text are obstacles: a label moved onto one is reported
    d = draw(_solved(EXAMPLES / "ex3_1_fourbar.toml"), "cubic")
    assert not [c for c in collisions(d) if c[2] == target]
    fixed = next(t for t in d.figure.findobj() if getattr(t, "get_gid", lambda: None)() == target)
    label = d.texts["B"]
    label.set_transform(fixed.get_transform())
    label.set_position(fixed.get_position())
    label.set_ha(fixed.get_ha())
    label.set_va(fixed.get_va())
    assert ("label", label.get_gid(), target) in collisions(d)


def _far_gaps(d):
    """For every far point's label of a drawing: the gap (inches) between its box and its arrow."""
    from graphkin.render.labels import text_size
    from graphkin.render.style import STYLES

    out = []
    for p in d.sheet.panels:
        placed = {i.text for g in p.groups for i in g.items if i.kind == "text"}
        # a list of far points placed whole, else its entries one by one
        reqs = [r for r in p.labels if r.arrow is not None or r.parts] + \
            [q for r in p.labels if r.text not in placed for q in r.parts]
        for req in reqs:
            items = [i for i in req.group.items if i.kind == "text" and i.gid == req.gid
                     and i.text in (req.text, *req.fallback)]
            if not items:
                continue
            a = p.to_paper(req.arrow.xy[0] if req.arrow is not None else req.anchor)
            c = p.to_paper(items[-1].xy)[0]
            w, h = text_size(items[-1].text, float(STYLES[req.style].get("size", 8)), req.style)
            gap = float(np.hypot(max(abs(c[0] - a[0]) - w / 2, 0),
                                 max(abs(c[1] - a[1]) - h / 2, 0)))
            out.append((gap, items[-1].text))
    return out


@pytest.mark.parametrize("path", [p for p in FILES if p.parent.name == "spec"],
                         ids=lambda p: p.stem)
def test_a_far_point_label_stays_beside_its_arrow(path):
    # Issue 11: "every label next to its own point".  A far point is an arrow at the edge
    # with "name, distance from I"; points that lie the same way share the arrow and are
    # listed in one label beside it, and a label that finds no room at the edge takes its
    # arrow along.  Before, a label of Ex. 3.2's cubic figure stood 1.55 in from its arrow.
    sol = _solved(path)
    try:
        d = draw(sol, "curvature")
    except DiagramUnavailable:
        pytest.skip("no curvature figures")
    gaps = _far_gaps(d)
    if not gaps:
        pytest.skip("every point of its curvature figures is on the drawing")
    worst = max(gaps)
    assert worst[0] <= 0.5, worst


@pytest.mark.parametrize("paper", ["a4", "letter"])
@pytest.mark.parametrize("path", [p for p in FILES if p.parent.name == "spec"],
                         ids=lambda p: p.stem)
def test_a_curvature_handout_page_has_no_collision(path, paper):
    # `draw -d curvature --sheet a4`: the four figures on one page, smaller than on a sheet
    # of their own; Hain's construction (d) once left two far-point labels over its lines
    # (Ex 4.14).  A list of far points too wide for its place is set narrow, and a crowded
    # panel is drawn a scale larger where the page has room.
    sol = _solved(path)
    try:
        d = draw(sol, "curvature", sheet=paper)
    except DiagramUnavailable:
        pytest.skip("no curvature figures")
    assert not collisions(d), collisions(d)
    gaps = _far_gaps(d)
    assert not gaps or max(gaps)[0] <= 0.5, max(gaps)
