"""The forces drawing's labels collide with nothing (the font-metric test of tests/render).

The same measurement as ``tests/render/test_labels.py`` (text boxes from
matplotlib's font metrics against each other and against every drawn segment
of another group, :func:`graphkin.render.labels.collisions`), for the forces
drawing of every forces example (tests/data/forces), every Chapter 11-12
gallery file and the rolling-contact files of tests/forces/data, on a free
sheet and on an A4 handout page.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.render import draw
from graphkin.render.labels import collisions

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "tests" / "data" / "forces").glob("ex1*.toml")) + sorted(
    (ROOT / "gallery" / "mechanisms").glob("ex1[12]_*.toml")) + sorted(
    (ROOT / "tests" / "forces" / "data").glob("*.toml"))


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


def test_rough_joint_components_are_lettered():
    """Ex 11.4: the ground's force on the block with its normal and friction components."""
    d = draw(graphkin.load(ROOT / "gallery" / "mechanisms" / "ex11_4_slider_crank_friction.toml")
             .solve(), "forces")
    texts = {t.get_text() for t in d.texts.values()}
    assert {"$F^{n}_{14}$", "$F^{t}_{14}$", "F₁₄"} <= texts
    # the components add up to the force (a parallelogram with one corner at its point)
    f, n, t = (d[f"fbd-4-F₁₄{s}"] for s in ("", "-n", "-t"))
    np.testing.assert_allclose(f.tip, n.tip)
    np.testing.assert_allclose((n.tip - n.tail) + (t.tip - t.tail), f.tip - f.tail, atol=1e-9)


def test_gears_draw_pitch_circles_and_the_pitch_point():
    d = draw(graphkin.load(ROOT / "tests" / "forces" / "data" / "spur_gears.toml").solve(),
             "forces")
    texts = {k: t.get_text() for k, t in d.texts.items()}
    assert texts["fbd-3-label-F₂₃"] == "F₂₃" and texts["fbd-2-circles-label-P"] == "P"
    assert texts["fbd-3-M_3-label"] == "M₃ cw"
    assert "forces" not in d.texts["force-scale"].get_text()  # no polygon, no force scale


def test_key_names_what_the_drawing_uses():
    """Ex 12.3: a key to the colours, with the inertia force; the input force F_A lettered."""
    d = draw(graphkin.load(ROOT / "gallery" / "mechanisms" / "ex12_3_elliptic_trammel.toml")
             .solve(), "forces")
    texts = {t.get_text() for t in d.texts.values()}
    assert "$F_{A}$" in texts and "F_A" not in texts
    d2 = draw(graphkin.load(FILES[0]).solve(), "forces")  # Ex 11.1: static, no inertia
    from graphkin.render import to_svg

    svg, svg2 = to_svg(d.figure), to_svg(d2.figure)
    assert "legend-0" in svg and "inertia force" in svg
    assert "legend-0" in svg2 and "inertia force" not in svg2
