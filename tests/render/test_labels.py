"""Labels collide with nothing: boxes from matplotlib's font metrics, read back from the drawing.

Issue 11's acceptance: for every spec example and every gallery file, each
diagram kind, no label box overlaps another label box or crosses a line, arc
or outline of another group; mathtext sub- and superscripts are at least 6 pt;
every component of an acceleration polygon is lettered.
"""

from __future__ import annotations

from pathlib import Path

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
                assert t.get_fontsize() * SHRINK >= 6.0, (diagram, t.get_text())
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
