"""The forces drawing, read back: every free body and polygon by gid, polygons closed."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.render import draw, to_svg

DATA = Path(__file__).resolve().parent.parent / "data" / "forces"


@pytest.fixture(scope="module")
def ex12_4():
    return draw(graphkin.load(DATA / "ex12_4_dynamic_fourbar.toml").solve(), "forces")


def _ids(fig) -> set[str]:
    root = ET.fromstring(to_svg(fig))
    return {el.get("id") for el in root.iter() if el.get("id")}


def test_layout_of_fig_11_5(ex12_4):
    """(a) mechanism, (b-d) free bodies of 2, 3, 4, then polygons (partials and totals)."""
    ids = _ids(ex12_4.figure)
    for gid in ("panel-forces-mechanism", "panel-fbd-2", "panel-fbd-3", "panel-fbd-4",
                "panel-polygon-3", "panel-polygon-4", "panel-polygon-3-′", "panel-polygon-4-″",
                "force-scale", "fbd-2-torque"):
        assert gid in ids, gid
    # every force on link 4's free body is drawn: P4, the inertia force, F34, F14
    for lab in ("P₄", "−m₄A_G₄", "F₃₄", "F₁₄"):
        assert f"fbd-4-{lab}" in ids


def test_polygons_close(ex12_4):
    """Σ F = 0: the last head returns to the first tail (Fig. 11.5f)."""
    assert ex12_4.vectors
    for name, vecs in ex12_4.vectors.items():
        start, end = vecs[0][1], vecs[-1][2]
        size = max(float(np.hypot(*(h - t))) for _, t, h in vecs)
        assert float(np.hypot(*(end - start))) <= 1e-9 * size, name
        for (_, _, h), (_, t, _) in zip(vecs, vecs[1:]):
            np.testing.assert_allclose(h, t)  # head to tail


@pytest.mark.parametrize("path", sorted((Path(__file__).resolve().parents[2] / "gallery"
                                          / "mechanisms").glob("ex1[12]_*.toml")),
                         ids=lambda p: p.stem)
def test_gallery_polygons_close(path):
    """Every force polygon of the gallery's Chapter 11-12 examples closes."""
    d = draw(graphkin.load(path).solve(), "forces")
    assert d.vectors
    for name, vecs in d.vectors.items():
        size = max(float(np.hypot(*(h - t))) for _, t, h in vecs)
        assert float(np.hypot(*(vecs[-1][2] - vecs[0][1]))) <= 1e-9 * size, name


def test_scale_is_stated(ex12_4):
    text = ex12_4.texts["force-scale"].get_text()
    assert re.search(r"forces 1 (in|cm) = [0-9.]+ k?N", text)
    assert re.search(r"lengths 1 (in|cm) = ", text)


def test_no_forces_no_diagram():
    from graphkin.render import DiagramUnavailable

    with pytest.raises(DiagramUnavailable):
        draw(graphkin.examples.fourbar().solve(), "forces")


def test_upto_draws_what_is_found(tmp_path):
    """Step by step (Ex 11.1): before the three-force step F34 is not drawn; at it, it is
    drawn in the highlight colour with the polygon of link 4."""
    from graphkin.forces import solve_forces
    from graphkin.render.style import HIGHLIGHT

    sol = graphkin.load(DATA / "ex11_1_static_fourbar.toml").solve()
    fs = solve_forces(sol)
    k = next(i for i, s in enumerate(fs.construction) if s.op == "force_three")
    before = draw(sol, "forces", upto=k - 1)
    at = draw(sol, "forces", upto=k)
    assert "fbd-4-F₃₄" not in before and "polygon-4" not in before.vectors
    assert "fbd-4-F₃₄" in at and "polygon-4" in at.vectors
    from matplotlib.colors import to_hex
    assert to_hex(at["fbd-4-F₃₄"].get_color()) == HIGHLIGHT


def test_steps_page(tmp_path):
    from graphkin.cli import main

    out = tmp_path / "f.html"
    assert main(["steps", str(DATA / "ex11_1_static_fourbar.toml"), "-d", "forces", "-o",
                 str(out), "--frames", str(tmp_path / "fr")]) == 0
    text = out.read_text()
    assert text.count("<section class='frame'") == 8
    assert "three-force member" in text and "<svg" in text
    assert len(list((tmp_path / "fr").glob("forces-*.svg"))) == 8
