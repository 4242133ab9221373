"""Handout pages (``draw --sheet a4|letter``) read back: one page, nothing crossing anything.

Issue 11, item 5: every spec example's ``all`` sheet on one page of A4 and of
Letter at round 1-2-5 scales, with a compact results table in the scale bars'
units, a line-style legend, a title block and fills that stay distinct in
greyscale.  Text boxes are measured with matplotlib's font metrics (the Agg
renderer), the page size is read back from the SVG.
"""

from __future__ import annotations

import io
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from spec_data import EXAMPLES, assert_round_scales

from graphkin.render import draw, to_bytes
from graphkin.render.labels import collisions
from graphkin.render.scale import SERIES_125, nice_ceil
from graphkin.render.sources import as_source

NAMES = sorted(p.stem for p in EXAMPLES.glob("ex*.toml") if p.stem != "expected")
PAGES = {"a4": (210 / 25.4, 297 / 25.4), "letter": (8.5, 11.0)}
"""A4 is 210 × 297 mm; Letter 8.5 × 11 in."""
READ_BACK = ("ex3_1_fourbar", "ex4_4_coriolis_block", "ex4_7_cam_follower")
"""The pages whose SVG is written and read back (portrait/landscape, in and mm files)."""


_PAGES: dict[tuple[str, str], object] = {}


def _page(gk, name: str, paper: str):
    """The ``all`` page of a spec example (solved once per session by the ``gk`` fixture)."""
    if (name, paper) not in _PAGES:
        _PAGES[name, paper] = draw(gk.solved(name), "all", sheet=paper)
    return _PAGES[name, paper]


def _boxes(d):
    """Every text of the figure with its box (pixels), and the box of its axes (or None)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.text import Text

    from graphkin.render.style import rc_context

    with rc_context():
        r = FigureCanvasAgg(d.figure).get_renderer()
        out = []
        for t in d.figure.findobj(Text):
            if not t.get_text().strip() or not t.get_visible():
                continue
            out.append((t, t.get_window_extent(r), t.axes.bbox if t.axes is not None else None))
    return out


def _overlap(a, b) -> float:
    w = min(a.x1, b.x1) - max(a.x0, b.x0)
    h = min(a.y1, b.y1) - max(a.y0, b.y0)
    return max(w, 0.0) * max(h, 0.0)


@pytest.mark.parametrize("paper", sorted(PAGES))
@pytest.mark.parametrize("name", NAMES)
def test_all_sheet_fits_one_page(gk, name, paper):
    d = _page(gk, name, paper)
    want = PAGES[paper]
    if name in READ_BACK:  # the page size read back from the SVG (points)
        root = ET.fromstring(to_bytes(d.figure))
        w_pt, h_pt = (float(root.get(k, "0").removesuffix("pt")) for k in ("width", "height"))
        ids = {e.get("id") for e in root.iter()}
        assert {"title-block", "legend", "results"} <= ids
    else:  # (the SVG takes as long as the page: the figure's size for the others)
        w_pt, h_pt = d.figure.get_size_inches() * 72
    assert sorted((w_pt / 72, h_pt / 72)) == pytest.approx(sorted(want), abs=0.01)
    # no label over another label or over a line of another group
    assert not collisions(d), collisions(d)
    fig = d.figure
    W, H = fig.bbox.width, fig.bbox.height
    # the boxes on the page (panels, table, legend, title block) overlap nothing and stay
    # inside the page
    axes = [ax for ax in fig.axes]
    for i, a in enumerate(axes):
        b = a.bbox
        assert b.x0 >= -0.5 and b.y0 >= -0.5 and b.x1 <= W + 0.5 and b.y1 <= H + 0.5, a.get_gid()
        for other in axes[i + 1:]:
            assert _overlap(b, other.bbox) < 1.0, (a.get_gid(), other.get_gid())
    # every text whole inside its own box: panel titles, labels, table cells, legend, block
    for t, box, ab in _boxes(d):
        assert box.x0 >= 0 and box.y0 >= 0 and box.x1 <= W and box.y1 <= H, t.get_text()
        if ab is not None:
            assert box.x0 >= ab.x0 - 1 and box.x1 <= ab.x1 + 1 and box.y0 >= ab.y0 - 1 \
                and box.y1 <= ab.y1 + 1, (t.get_gid(), t.get_text(), t.axes.get_gid())
    assert_round_scales(d.sheet)  # 1-2-5 series
    # the compact table: no analytic column, no relative differences
    t = d.sheet.page.table
    assert t is not None and t.head[:2] == ("quantity", "value") and t.head[-1] == "unit"
    assert not {"analytic", "rel. diff."} & set(t.head)
    assert not [c for r in t.rows for c in r if re.search(r"\de-\d", c)]  # no round-off
    assert ("direction" in t.head) == any(k.startswith(("V_", "omega")) for k in t.keys)
    # the Kennedy circle stays beside the instant centers (issue 11: on every centers figure);
    # when the page is full it is the curvature panel that goes, with a line saying where
    names = [p.name for p in d.sheet.panels]
    assert "centers" in names and "kennedy" in names
    if "inflection" not in names and "curvature" in as_source(gk.solved(name)).available():
        assert d.sheet.page.dropped == ("curvature",)
        assert any("-d curvature" in text for text, _ in d.sheet.page.block)
        assert not [k for k in t.keys if k.startswith("curvature-")]


def test_handout_values_are_in_the_scale_bars_units(gk):
    # Example 3.1 (file in inches): V_B = ω2 · AB = 94.2478 rad/s × 4 in = 376.99 in/s
    # = 31.42 ft/s; the velocity polygon's bar reads in ft/s, so does the table.
    d = _page(gk, "ex3_1_fourbar", "a4")
    vel = d.sheet.panel("velocity").scale
    assert vel.unit == "ft/s"
    t = d.sheet.page.table
    row = dict(zip(t.keys, t.rows))["V_B"]
    assert row[1] == "31.42" and row[3] == "ft/s"
    # the acceleration bar in ft/s²: A_B = ω2² · AB = 94.2478² × 4 = 35530.6 in/s² = 2961 ft/s²
    assert d.sheet.panel("acceleration").scale.unit == "ft/s²"
    row = dict(zip(t.keys, t.rows))["A_B"]
    assert row[1] == "2961" and row[3] == "ft/s²"
    # positions are not listed on an all sheet (the drawing is the position), and no row
    # of a curvature figure the page does not show (B', the conjugate of B, is in (c))
    assert not [k for k in t.keys if k.startswith("R_")]
    assert "curvature-B_" not in t.keys and "curvature-J" in t.keys


def test_an_all_page_shows_the_inflection_figure_only(gk):
    d = _page(gk, "ex4_14_inflection_bresse", "letter")
    names = [p.name for p in d.sheet.panels]
    assert "inflection" in names and not {"bobillier", "hartmann", "cubic"} & set(names)
    # the other figures stay reachable on their own page
    alone = draw(gk.solved("ex4_14_inflection_bresse"), "cubic", sheet="letter")
    assert [p.name for p in alone.sheet.panels] == ["cubic"]


def test_upto_on_a_handout_leaves_out_the_answers_not_reached(gk):
    sol = gk.solved("ex3_1_fourbar")
    cx = sol.constructions["velocity"]
    first = next(s.index for s in cx.steps if "v(B)" in s.outputs)
    d = draw(sol, "velocity", sheet="a4", upto=first)
    keys = set(d.sheet.page.table.keys)
    assert "V_B" in keys and not {"V_C", "V_E", "omega3", "omega4"} & keys
    svg = to_bytes(d.figure).decode()
    assert 'id="row-V_B-1"' in svg and 'id="row-V_C-1"' not in svg


def test_legend_names_the_line_styles_drawn(gk):
    from matplotlib.lines import Line2D

    d = _page(gk, "ex3_3_inverted_slider", "a4")  # a Coriolis component (Example 3.3)
    gids = {a.get_gid(): a for a in d.figure.findobj(lambda a: bool(a.get_gid()))}
    for style in ("vector-n", "vector-t", "vector-c", "aux-line"):
        assert f"legend-{style}" in gids, style
    n, c, t = (gids[f"legend-vector-{x}-sample"] for x in "nct")
    # tangential solid, normal dashed, Coriolis dash-dotted (Fig. 4.11): three patterns
    assert isinstance(n, Line2D) and t.get_linestyle() == "-" and n.get_linestyle() != "-"
    assert n._unscaled_dash_pattern != c._unscaled_dash_pattern


def test_image_fills_stay_distinct_in_greyscale(gk):
    import matplotlib.image as mpimg
    from shapely.geometry import Polygon

    d = _page(gk, "ex3_1_fourbar", "a4")
    png = to_bytes(d.figure, "png", dpi=100)
    img = mpimg.imread(io.BytesIO(png))
    lum = img[..., :3] @ np.array([0.299, 0.587, 0.114])  # ITU-R 601 luminance
    H = img.shape[0]
    shades = []
    for gid, grp in d.groups.items():
        if not gid.startswith("velocity-image"):
            continue
        art = grp.get_children()[0]
        xy = art.get_transform().transform(art.get_xy())  # display pixels at the figure's dpi
        xy *= 100 / d.figure.dpi
        inner = Polygon(xy).buffer(-4)  # clear of the vectors along its edges
        pt = inner.representative_point()
        col, row = int(pt.x), int(H - pt.y)
        shades.append(float(np.median(lum[row - 1:row + 2, col - 1:col + 2])))
    assert len(shades) == 2
    assert abs(shades[0] - shades[1]) >= 0.08, shades
    assert all(s <= 0.95 for s in shades), shades  # both visibly darker than the paper


def test_handout_scales_are_a_1_2_5_series():
    # 1 cm = 50 mm/s, not 1 in = 16.67: the round numbers of the series and nothing between
    assert [nice_ceil(x, SERIES_125) for x in (1.0, 1.3, 2.2, 2.5, 5.0, 16.67, 0.021)] \
        == [1.0, 2.0, 5.0, 5.0, 5.0, 20.0, 0.05]


def test_table_columns_are_aligned_from_font_metrics(gk):
    d = gk.drawn("ex3_1_fourbar", "velocity")
    cells = {}
    for t, box, _ in _boxes(d):
        gid = t.get_gid() or ""
        if gid.startswith("row-"):
            cells.setdefault(int(gid.rsplit("-", 1)[1]), []).append((t, box))
    # the drawn value (right-aligned): one right edge; the quantity (left-aligned): one left edge
    rights = {round(b.x1, 1) for _, b in cells[1]}
    lefts = {round(b.x0, 1) for _, b in cells[0]}
    assert max(rights) - min(rights) < 1.0 and max(lefts) - min(lefts) < 1.0
    # no two cells of a row touch
    rows: dict[str, list] = {}
    for col in cells.values():
        for t, b in col:
            rows.setdefault(t.get_gid().rsplit("-", 1)[0], []).append(b)
    for boxes in rows.values():
        boxes.sort(key=lambda b: b.x0)
        assert all(a.x1 < b.x0 for a, b in zip(boxes, boxes[1:]))


@pytest.mark.parametrize("name", NAMES)
def test_no_label_collides_on_the_all_sheet(gk, name):
    # the collision test of test_labels.py, on the sheet of every diagram (not a handout)
    d = gk.drawn(name, "all")
    assert not collisions(d), collisions(d)
    for t, box, ab in _boxes(d):
        if (t.get_gid() or "").startswith(("row-", "results")):
            assert ab is not None and box.x0 >= ab.x0 - 1 and box.x1 <= ab.x1 + 1 \
                and box.y0 >= ab.y0 - 1 and box.y1 <= ab.y1 + 1, t.get_text()  # in its table


def test_cli_writes_a_letter_page(tmp_path, capsys):
    from graphkin.cli import main

    out = tmp_path / "p.svg"
    # Example 2.5 (no rates): the posture and the instant centers on one Letter page
    assert main(["draw", str(EXAMPLES / "ex2_5_open.toml"), "--sheet", "letter",
                 "-o", str(out)]) == 0
    root = ET.parse(out).getroot()
    size = sorted(float(root.get(k, "0").removesuffix("pt")) / 72 for k in ("width", "height"))
    assert size == pytest.approx([8.5, 11.0], abs=0.01)
    with pytest.raises(SystemExit) as exc:  # argparse: one line naming the bad choice
        main(["draw", str(EXAMPLES / "ex2_5_open.toml"), "--sheet", "a3", "-o", str(out)])
    assert exc.value.code == 2 and "a3" in capsys.readouterr().err


def test_a_started_cubic_figure_does_not_draw_the_cubic(gk):
    # the cubic of stationary curvature and Ball's point U are answers (Figs. 4.37-4.39):
    # a drawing stopped before Hain's construction finds U shows neither
    sol = gk.solved("ex4_14_inflection_bresse")
    full = draw(sol, "cubic")
    steps = full.sheet.painters["cubic"].cx.steps
    u = next(s.index for s in steps if "U" in s.outputs)

    def answers(d):
        return {a.get_gid() for a in d.figure.findobj(lambda a: bool(a.get_gid()))} \
            & {"cubic", "ball-point"}

    assert answers(full) == {"cubic", "ball-point"}
    assert answers(draw(sol, "cubic", upto=steps[1].index)) == set()
    assert answers(draw(sol, "cubic", upto=u - 1)) == set()
    assert answers(draw(sol, "cubic", upto=u)) == {"cubic", "ball-point"}


def test_arrange_on_paper_puts_a_sheet_built_elsewhere_on_a_page(gk):
    """The generic entry point (used by the forces drawing): the largest size that fits.

    A 40 in panel fits no page (A4 is 8.27 × 11.69 in): it is tried, refused
    with nothing changed, and the next size taken; the band's title block is
    drawn whatever the sheet.
    """
    from graphkin.render.handout import (
        PAGE_MARGIN,
        Page,
        arrange_on_paper,
        block_lines,
        place_on_page,
    )
    from graphkin.render.sheet import build_sheet
    from graphkin.render.sources import as_source

    src = as_source(gk.solved("ex3_1_fourbar"))
    tried: list[float] = []

    def build(big):
        tried.append(big)
        return build_sheet(src, "velocity", paper="a4", dry=True, table=False, max_inches=big)

    def band(sheet):
        return Page("a4", block=block_lines([("Velocity polygon " * 12, "bold", 1),
                                             ("Scales: as drawn", "normal", 1)]))

    huge = build(40.0)
    size, origin = huge.size, [p.origin for p in huge.panels]
    assert place_on_page(huge, band(huge), PAGES["a4"]) is None
    assert huge.size == size and [p.origin for p in huge.panels] == origin and huge.page is None
    sheet = arrange_on_paper(build, band, "a4", bigs=(40.0, 4.0, 2.0))
    assert 40.0 in tried and sheet.page is not None
    assert sorted(sheet.size) == pytest.approx(sorted(PAGES["a4"]), abs=0.01)
    p = sheet.panels[0]
    # portrait: 40 refused, 4 fits; landscape tries only what would be larger (40); 2 never
    assert tried == [40.0, 40.0, 4.0, 40.0, 4.0]
    band_top = sheet.page.block_box[1] + sheet.page.block_box[3]
    assert p.origin[1] >= band_top and p.origin[0] >= PAGE_MARGIN - 1e-9
    assert p.origin[1] + p.size[1] <= sheet.size[1] - PAGE_MARGIN + 1e-9
    # a title longer than its one line is cut with an ellipsis, never runs out of the block
    assert len(sheet.page.block) == 2 and sheet.page.block[0][0].endswith("…")
    with pytest.raises(Exception, match="unknown paper"):
        arrange_on_paper(build, band, "a3")


def test_round_off_prints_as_zero_on_a_handout_table():
    # The elliptic trammel of Ex. 12.3: A = (0, 8) on the vertical guide, B = (6, 0) on the
    # horizontal one (AB = 10 in).  I34 is the pin B itself, (6, 0); the inflection pole J of
    # the coupler is the point of AB's plane at the origin O (the Cardan circle: the centrode
    # of a trammel is a circle of diameter AB = 10 through O, and J lies opposite I on it, so
    # J = O and I = (6, 8)).  Solved, their y's come out ~9e-16: the page prints 0.
    path = Path(__file__).resolve().parents[2] / "gallery" / "mechanisms" / \
        "ex12_3_elliptic_trammel.toml"
    from graphkin import load

    d = draw(load(path).solve(), "all", sheet="a4")
    t = d.sheet.page.table
    row = dict(zip(t.keys, t.rows))
    assert row["center-I34"][1] == "(6.000, 0)"
    assert row["curvature-J"][1] == "(0, 0)" and row["curvature-I"][1] == "(6.000, 8.000)"
    assert not [c for r in t.rows for c in r if re.search(r"\de-\d", c)]
