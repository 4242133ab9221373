"""The forces drawing on a handout page (``draw -d forces --sheet a4|letter``), read back.

The page is every other handout's (tests/render/test_handout.py): the paper's
size, every box (panels, table, legend, title block) inside the page and
overlapping no other, every text inside its own box, no label over another
label or line (:func:`graphkin.render.labels.collisions`), 1-2-5 scales, a
title block naming the mechanism, "forces" and both scales, and a compact
table read off the drawing in the force scale bar's unit with no analytic
column.  The table's values are checked against the matrix method (the
independent Newton-Euler solution, Sec. 11.9) and the book's answers.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from spec_data import assert_round_scales

import graphkin
from graphkin.render import draw, to_bytes
from graphkin.render.labels import collisions

ROOT = Path(__file__).resolve().parents[2]
FILES = sorted((ROOT / "tests" / "data" / "forces").glob("ex1*.toml")) + sorted(
    (ROOT / "gallery" / "mechanisms").glob("ex1[12]_*.toml"))
PAGES = {"a4": (210 / 25.4, 297 / 25.4), "letter": (8.5, 11.0)}
"""A4 is 210 × 297 mm; Letter 8.5 × 11 in."""

_CACHE: dict[tuple[str, str, int | None], object] = {}


def _page(path: Path, paper: str, upto: int | None = None):
    key = (str(path), paper, upto)
    if key not in _CACHE:
        _CACHE[key] = draw(graphkin.load(path).solve(), "forces", sheet=paper, upto=upto)
    return _CACHE[key]


def _overlap(a, b) -> float:
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return max(w, 0.0) * max(h, 0.0)


def _texts(d, prefix: str) -> list[str]:
    return [t.get_text() for t in d.figure.texts + [t for ax in d.figure.axes for t in ax.texts]
            if (t.get_gid() or "").startswith(prefix)]


def _force_scale(d):
    return next(p.scale for p in d.sheet.panels if p.name.startswith("polygon-"))


@pytest.mark.parametrize("paper", sorted(PAGES))
@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_forces_page_is_a_handout(path, paper):
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.text import Text

    from graphkin.render.style import rc_context

    d = _page(path, paper)
    fig = d.figure
    assert sorted(fig.get_size_inches()) == pytest.approx(sorted(PAGES[paper]), abs=0.01)
    assert not collisions(d), collisions(d)
    W, H = fig.bbox.width, fig.bbox.height
    axes = list(fig.axes)
    gids = {a.get_gid() for a in axes}
    assert {"title-block", "legend", "results"} <= gids, gids
    assert "panel-legend" not in gids  # the free sheet's key: the band's legend replaces it
    for i, a in enumerate(axes):
        b = a.bbox
        assert b.x0 >= -0.5 and b.y0 >= -0.5 and b.x1 <= W + 0.5 and b.y1 <= H + 0.5, a.get_gid()
        for other in axes[i + 1:]:
            assert _overlap(b, other.bbox) < 1.0, (a.get_gid(), other.get_gid())
    with rc_context():
        r = FigureCanvasAgg(fig).get_renderer()
        for t in fig.findobj(Text):
            if not t.get_text().strip() or not t.get_visible():
                continue
            box = t.get_window_extent(r)
            assert box.x0 >= 0 and box.y0 >= 0 and box.x1 <= W and box.y1 <= H, t.get_text()
            if t.axes is not None:
                ab = t.axes.bbox
                assert box.x0 >= ab.x0 - 1 and box.x1 <= ab.x1 + 1 and box.y0 >= ab.y0 - 1 \
                    and box.y1 <= ab.y1 + 1, (t.get_gid(), t.get_text(), t.axes.get_gid())
    assert_round_scales(d.sheet)  # 1-2-5 series
    # the title block: the mechanism, "forces", the length and the force scale
    fscale = _force_scale(d)
    lscale = d.sheet.panel("forces-mechanism").scale
    block = " ".join(_texts(d, "title-block-")).replace("\xa0", " ")
    assert "force analysis" in block and "forces" in block.split("Diagram:", 1)[1]
    assert f"lengths {lscale.text}" in block and f"forces {fscale.text}" in block, block
    # the compact table, in the force scale bar's unit, no analytic column
    t = d.sheet.page.table
    assert t.head == ("quantity", "value", "direction", "unit")
    for key, row in zip(t.keys, t.rows):
        if key.startswith("T_"):
            assert row[3].startswith(f"{fscale.unit}·") and row[2] in ("cw", "ccw")
        else:
            assert row[3] == fscale.unit and row[2].startswith("∠")
    assert "force-scale" not in d.texts  # the title block states the scales


def test_a_page_reads_back_from_svg():
    """Ex 11.1 on Letter: the SVG's size in points and the band's ids."""
    d = _page(FILES[0], "letter")
    root = ET.fromstring(to_bytes(d.figure))
    w, h = (float(root.get(k, "0").removesuffix("pt")) / 72 for k in ("width", "height"))
    assert sorted((w, h)) == pytest.approx(sorted(PAGES["letter"]), abs=0.01)
    ids = {e.get("id") for e in root.iter()}
    assert {"title-block", "legend", "results", "legend-joint-force", "legend-load",
            "legend-drive"} <= ids
    assert "legend-inertia" not in ids  # static: no inertia force drawn, none in the legend


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_table_values_are_the_matrix_methods(path):
    """Each F_ij and the drive on the page agree with the independent matrix method (4 figures)."""
    from graphkin.forces.solve import solve_forces
    from graphkin.render.forces import force_name
    from graphkin.render.results import scale_factor

    sol = graphkin.load(path).solve()
    ref = solve_forces(sol, method="analytic")
    d = _page(path, "a4")
    fscale = _force_scale(d)
    lscale = d.sheet.panel("forces-mechanism").scale
    t = d.sheet.page.table
    rows = dict(zip(t.keys, t.rows))
    labels = {f"F_{j.key}": force_name(j.label(j.hi)) for j in ref.joints}
    assert {k for k in rows if k.startswith("F_") and not k.startswith("F_drive")} \
        == set(labels)
    for key, label in labels.items():
        v = ref.forces[key[2:]][:2]
        q, value, direction, _ = rows[key]
        assert q == label
        size = float(np.hypot(*v))
        assert float(value) == pytest.approx(size / fscale.factor, rel=6e-4, abs=1e-9)
        if size > 0:
            ang = float(direction.strip("∠°"))
            want = math.degrees(math.atan2(v[1], v[0]))
            assert abs(math.remainder(ang - want, 360.0)) <= 0.051
    mech = sol.mechanism
    for lid, (what, val) in ref.drives.items():
        if what != "torque":
            continue
        q, value, sense, unit = rows[f"T_1{lid}"]
        fu, lu = unit.split("·")  # read in the units printed, converted by pint
        per = scale_factor(mech.force_unit, fu) * scale_factor(mech.length_unit, lu)
        assert fu == fscale.unit and lu in (lscale.unit, "m")
        assert float(value) == pytest.approx(abs(val) * per, rel=6e-4)
        assert sense == ("ccw" if val > 0 else "cw")


def test_book_example_11_4_on_the_page():
    """Ex 11.4 (Sec. 11.9): T₁₂ = (4.11 in)(97 lb) = 399 in·lb cw, F₃₄ ≈ 97 lb."""
    d = _page(ROOT / "gallery" / "mechanisms" / "ex11_4_slider_crank_friction.toml", "a4")
    rows = {r[0]: r for r in d.sheet.page.table.rows}
    assert rows["T₁₂"][2:] == ("cw", "lbf·in")
    assert float(rows["T₁₂"][1]) == pytest.approx(399.0, rel=0.005)
    assert float(rows["F₃₄"][1]) == pytest.approx(97.0, rel=0.005)


def test_a_large_torque_in_millimetre_file_is_written_in_newton_metres():
    """Ex 12.4 (mm, N): the torque of about 18 000 N·mm is written in N·m (÷ 1000)."""
    from graphkin.forces.solve import solve_forces

    path = ROOT / "tests" / "data" / "forces" / "ex12_4_dynamic_fourbar.toml"
    d = _page(path, "a4")
    row = next(r for r in d.sheet.page.table.rows if r[0] == "T₁₂")
    want = solve_forces(graphkin.load(path).solve(), method="analytic").drives["2"][1]
    assert row[3] == "N·m" and float(row[1]) == pytest.approx(abs(want) / 1000, rel=6e-4)
    assert "legend-inertia" in {a.get_gid() for a in d.figure.findobj(lambda a: bool(a.get_gid()))}


def test_upto_leaves_out_the_answers_not_reached():
    """Ex 11.1 started: the table lists only the forces the construction has found.

    The book's order (Ex 11.1, Fig. 11.5): the load P₄, link 3 a two-force
    member (its line), then F₃₄ and F₁₄ at once by the concurrency point of
    link 4; F₄₃, F₂₃, F₃₂, F₁₂ and last T₁₂.
    """
    full = _page(FILES[0], "a4")
    sol = graphkin.load(FILES[0]).solve()
    want = {0: None, 1: None, 2: ["F_1-4", "F_3-4"], 3: ["F_1-4", "F_3-4"],
            4: ["F_1-4", "F_2-3", "F_3-4"], 6: ["F_1-2", "F_1-4", "F_2-3", "F_3-4"],
            7: ["F_1-2", "F_1-4", "F_2-3", "F_3-4", "T_12"]}
    for k, keys in want.items():
        table = draw(sol, "forces", sheet="a4", upto=k).sheet.page.table
        assert (None if table is None else table.keys) == keys, k
    assert full.sheet.page.table.keys == want[7]  # the last step: the whole table


def test_unknown_paper_is_refused():
    from graphkin.render.sources import DiagramUnavailable

    with pytest.raises(DiagramUnavailable, match="unknown paper"):
        draw(graphkin.load(FILES[0]).solve(), "forces", sheet="a3")
