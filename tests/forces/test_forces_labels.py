"""The forces drawing's labels collide with nothing (the font-metric test of tests/render).

The same measurement as ``tests/render/test_labels.py`` (text boxes from
matplotlib's font metrics against each other and against every drawn segment
of another group, :func:`graphkin.render.labels.collisions`), for the forces
drawing of every forces example (tests/data/forces) and every Chapter 11-12
gallery file, on a free sheet and on an A4 handout page.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import graphkin
from graphkin.render import draw
from graphkin.render.labels import collisions

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "tests" / "data" / "forces").glob("ex1*.toml")) + sorted(
    (ROOT / "gallery" / "mechanisms").glob("ex1[12]_*.toml"))


@pytest.mark.parametrize("sheet", [None, "a4"])
@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_no_force_label_collides(path, sheet):
    d = draw(graphkin.load(path).solve(), "forces", sheet=sheet)
    bad = collisions(d)
    assert not bad, bad


def test_every_force_is_lettered():
    """Ex 12.4: each force on each free body and in each polygon carries its book name."""
    d = draw(graphkin.load(ROOT / "tests" / "data" / "forces" / "ex12_4_dynamic_fourbar.toml")
             .solve(), "forces")
    texts = {t.get_text() for t in d.texts.values()}
    for want in ("F₃₄", "F₁₄", "F₂₃", "F₄₃", "F₁₂", "F₃₂", "T₁₂ ccw", "$-m_{3}A_{G_{3}}$",
                 "$-m_{4}A_{G_{4}}$", "h", "P₄"):
        assert want in texts, (want, sorted(texts))


def test_collisions_sees_a_force_label_moved_onto_a_line():
    """The measurement can fail: a label moved onto its neighbour's arrow is reported."""
    d = draw(graphkin.load(FILES[0]).solve(), "forces")
    arrow = d["fbd-4-F₁₄"]
    t = d.texts["fbd-4-label-F₃₄"]
    t.set_position(tuple((arrow.tail + arrow.tip) / 2))
    assert collisions(d)
