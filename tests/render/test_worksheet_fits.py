"""A worksheet's mechanism fits its box, on the page, for any mechanism (audit9, item 1).

``graphkin worksheet`` of a slider-crank on an inclined line cut the slider's
block and ground off at the top of the mechanism's box.  Read back from the
SVG the worksheet writes (text as text, ``svg_boxes``): every text and stroke
lies on the page, and everything the mechanism's drawing puts down (links,
blocks, hatching, labels) lies inside the mechanism's box, unclipped.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from shapely import box as shapely_box
from strategies import mechanisms
from svg_boxes import page, strokes, texts

import graphkin
from graphkin.check.tolerances import read_scale
from graphkin.render.worksheet import fit_mechanism, save_worksheet, worksheet_figure
from graphkin.render.worksheet_layout import worksheet_layout

DATA = Path(__file__).resolve().parents[1] / "data" / "worksheet"
PT = 72 / 25.4
"""Points per millimetre: the SVG is in points, the layout in mm."""
SHEET = ("marker-", "worksheet-", "scale-text-", "pole", "polygon-area")
"""The gids of what the sheet itself prints (not the mechanism's drawing)."""


def _write_svg(sol, tmp: Path, diagram: str = "velocity", paper: str = "a4"):
    layout = fit_mechanism(sol, worksheet_layout(sol, diagram, paper, "0" * 10))
    fig = worksheet_figure(sol, layout, title="t")
    out = tmp / "ws.svg"
    save_worksheet(fig, layout, out)
    return ET.parse(out).getroot(), layout


def assert_fits(root, layout) -> None:
    """Every element on the page; the mechanism's drawing inside its box (0.5 pt slack)."""
    w, h = layout.size
    sheet = page(root)
    assert sheet.bounds == pytest.approx((0, 0, w * PT, h * PT), abs=0.01)
    x0, y0, x1, y1 = layout.mechanism_box          # mm, y up; the SVG's y runs down
    mech = shapely_box(x0 * PT, (h - y1) * PT, x1 * PT, (h - y0) * PT).buffer(0.5)
    items = [(n.gid, n.box, f"text {n.text!r}") for n in texts(root)]
    items += [(g, line, "a stroke") for g, line in strokes(root)]
    assert items
    for gid, geom, what in items:
        assert sheet.buffer(0.5).contains(geom), f"{what} of {gid!r} off the page"
        if not gid.startswith(SHEET):
            assert mech.contains(geom), (f"{what} of {gid!r} outside the mechanism's box "
                                         f"{mech.bounds} at {geom.bounds}")


def test_the_inclined_slider_crank_is_not_cut_off_at_the_top(tmp_path):
    # the audit's file: the block and the guide at B (-120, 60) mm stood above the box
    sol = graphkin.load(DATA / "sc_incl.toml").solve()
    root, layout = _write_svg(sol, tmp_path, "acceleration")
    assert_fits(root, layout)


def test_the_acceleration_scale_is_written_with_a_superscript_two():
    # the rest of the output writes mm/s² (output/units.py); the scale reads back the same
    sol = graphkin.load(DATA / "sc_incl.toml").solve()
    layout = worksheet_layout(sol, "acceleration", "a4", "0" * 10)
    assert layout.scale_text.endswith(" mm/s²")
    assert "^" not in layout.identity_line()
    assert read_scale(layout.scale_text, "mm").per_mm == layout.per_mm


@settings(max_examples=12, deadline=None, suppress_health_check=[HealthCheck.too_slow,
                                                                  HealthCheck.function_scoped_fixture])
@given(rm=mechanisms())
def test_any_mechanism_fits_its_box_on_the_page(rm, tmp_path):
    sol = rm.mechanism().solve()
    root, layout = _write_svg(sol, tmp_path)
    assert_fits(root, layout)
