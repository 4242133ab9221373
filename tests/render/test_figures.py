"""Required elements of the figures, read back from the SVG by group id (issue 11)."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest
from spec_data import EXAMPLES

from graphkin.render.style import FONT_PT

NAMES = sorted(p.stem for p in EXAMPLES.glob("ex*.toml") if p.stem != "expected")


def _ids(svg: bytes) -> set[str]:
    return {el.get("id") for el in ET.fromstring(svg).iter() if el.get("id")}


@pytest.mark.parametrize("name", NAMES)
def test_centers_figure_has_the_kennedy_circle(gk, name):
    sol = gk.solved(name)
    ids = _ids(gk.svg(name, "centers"))
    n = len(sol.mechanism.links)
    assert "kennedy-circle" in ids and "panel-kennedy" in ids
    assert all(f"kennedy-link-{lid}" in ids for lid in sol.mechanism.links)
    # one chord per pair of links: N = n(n-1)/2 (Eq. 3.20)
    chords = {i for i in ids if re.fullmatch(r"kennedy-I\d+(-\d+)?", i)}
    assert len(chords) == n * (n - 1) // 2
    d = gk.drawn(name, "centers")
    ic = d.sheet.painters["centers"].src.extras["centers"]
    for c in ic.centers.values():
        assert f"kennedy-order-{c.label}" in ids
        assert d.texts[f"order {c.label}"].get_text() == str(c.order)


@pytest.mark.parametrize("name", ["ex3_1_fourbar", "ex5_4_fivebar"])
def test_instant_center_letters_are_black_at_point_label_size(gk, name):
    d = gk.drawn(name, "centers")
    ic = d.sheet.painters["centers"].src.extras["centers"]
    for c in ic.centers.values():
        t = d.texts.get(c.label)
        if t is None:
            continue  # a center at infinity is an arrow marked ∞
        assert t.get_fontsize() == FONT_PT
        assert t.get_color() in ("k", "#000000", "black")


def test_a_center_at_infinity_is_printed_as_a_direction(gk):
    # Example 4.7 at its posture: the follower's face is vertical, so the common normal
    # through B and the line I12-I13 are parallel: I23 is at infinity along x.
    d = gk.drawn("ex4_7_cam_follower", "centers")
    row = {r.key: r for r in d.sheet.rows}["center-I23"]
    assert row.drawn.startswith("∞ along (1, 0)") and row.exact.startswith("∞ along (1, 0)")
    texts = {t.get_text() for t in d.texts.values()}
    assert "I₂₃ ∞" in texts


@pytest.mark.parametrize("name", ["ex4_14_inflection_bresse", "ex4_16_cubic"])
def test_curvature_sheet_is_split_into_the_books_figures(gk, name):
    # Figs. 4.33-4.35 (a), 4.29 (b), 4.25/4.30 (c), 4.37-4.39 (d): one idea per panel
    ids = _ids(gk.svg(name, "curvature"))
    for panel in ("inflection", "bobillier", "hartmann", "cubic"):
        assert f"panel-{panel}" in ids, panel
    for gid in ("inflection-inflection-circle", "inflection-Bresse-circle", "cubic-cubic",
                "cubic-ball-point", "inflection-label-N", "inflection-label-T"):
        assert gid in ids, gid
    d = gk.drawn(name, "curvature")
    texts = {t.get_text() for t in d.texts.values()}
    assert "inflection circle" in texts and "Bresse circle" in texts
    # no literal underscores: J_B, A_N, G_T are real subscripts
    assert not [t for t in texts if "_" in t and not t.startswith("$")], texts


def test_each_curvature_figure_alone(gk):
    from graphkin.render import draw

    sol = gk.solved("ex4_14_inflection_bresse")
    for panel in ("inflection", "bobillier", "hartmann", "cubic"):
        d = draw(sol, panel)
        assert [p.name for p in d.sheet.panels] == [panel]


def test_a_link_about_a_frame_pivot_gets_a_sentence(gk):
    d = gk.drawn("ex4_7_cam_follower", "curvature")
    assert "turns about the frame pivot" in d.texts["curvature note"].get_text()


def test_image_fills_stay_distinct_in_greyscale():
    from graphkin.render.style import IMAGE_FILLS

    def grey(h: str) -> float:  # ITU-R BT.601 luma, as a photocopier sees it
        r, g, b = (int(h[i:i + 2], 16) / 255 for i in (1, 3, 5))
        return 0.299 * r + 0.587 * g + 0.114 * b

    lum = [grey(h) for h in IMAGE_FILLS[:4]]
    assert min(abs(a - b) for i, a in enumerate(lum) for b in lum[i + 1:]) >= 0.06


def test_upto_stops_every_curvature_figure_at_the_same_step(gk):
    from graphkin.render import draw

    d = draw(gk.solved("ex4_14_inflection_bresse"), "curvature", upto=20)
    numbers = [int(g.split("step-")[1][:2]) for g in d.groups if "step-" in g]
    assert numbers and max(numbers) == 20


def test_a_started_drawing_does_not_print_the_answers_it_has_not_reached(gk):
    from graphkin.render import draw

    sol = gk.solved("ex3_1_fourbar")
    cx = sol.constructions["velocity"]
    first = next(s.index for s in cx.steps if "v(B)" in s.outputs)
    keys = {r.key for r in draw(sol, "velocity", upto=first).sheet.rows}
    assert "V_B" in keys and "V_C" not in keys and "omega3" not in keys
    full = {r.key for r in draw(sol, "velocity").sheet.rows}
    assert {"V_C", "omega3"} <= full


CURVATURE_DIAGRAMS = ["inflection", "bobillier", "hartmann", "cubic"]


@pytest.mark.parametrize("name", ["ex3_1_fourbar", "ex4_14_inflection_bresse", "ex4_16_cubic"])
@pytest.mark.parametrize("diagram", CURVATURE_DIAGRAMS)
def test_a_far_point_is_named_with_its_distance_never_its_coordinates(gk, name, diagram):
    # A point beyond the panel is an arrow toward it labelled with its name and its distance
    # from the pole ("Γ_T, 254 in from P"), as the book would; never "G_T (-189.9, -167.5)".
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    root = ET.fromstring(gk.svg(name, diagram), parser=parser)
    seen = 0
    coords = re.compile(r"\(\s*-?[\d.]+(e[-+]?\d+)?\s*,\s*-?[\d.]+(e[-+]?\d+)?\s*\)")
    for el in root.iter():
        gid = el.get("id") or ""
        if not gid.startswith("label-"):
            continue
        text = " ".join(c.text or "" for c in el.iter(ET.Comment))
        seen += bool(text.strip())
        assert not coords.search(text), (gid, text)
    assert seen >= 1  # the labels' texts were read


@pytest.mark.parametrize("diagram,point", [("cubic", "G_T"), ("bobillier", "W")])
def test_a_far_point_gives_its_distance_from_the_pole(gk, diagram, point):
    # Example 3.1: G_T of Hain's construction (Fig. 4.38) and W of Bobillier's (Fig. 4.29,
    # x = -35.6 in) lie beyond their panels; each is an arrow whose label gives its distance
    # |point - I| computed here from the construction's own values.
    d = gk.drawn("ex3_1_fourbar", diagram)
    painter = d.sheet.painters[diagram]
    far, pole = painter.xy(point), painter.xy("I")
    x0, y0, x1, y1 = d.sheet.panels[0].inner
    assert not (x0 <= far[0] <= x1 and y0 <= far[1] <= y1)  # it is off the drawing
    texts = [t.get_text() for t in d.texts.values()]
    # one entry per line; points that lie the same way are listed in one label (when
    # narrow, "U_T, 395 in" ... "(from I)"), and a crowded edge puts a name over its
    # distance ("W,\n33.9 in from I")
    entries = []
    for t in texts:
        lines = t.replace(",\n", ", ").split("\n")
        ref = lines.pop()[1:-1] if len(lines) > 1 and lines[-1].startswith("(from ") else None
        entries += [e if ref is None else f"{e} {ref}" for e in lines]
    name = "$G_{T}$" if point == "G_T" else point
    text = next((e for e in entries if e.startswith(name + ",")), None)
    assert text is not None, texts
    m = re.search(r", ([\d.]+) in from I$", text)
    assert m is not None, text
    assert float(m.group(1)) == pytest.approx(float(np.hypot(*(far - pole))), rel=5e-3)


def test_a_circle_cut_by_the_title_strip_is_drawn_as_the_arcs_inside():
    from graphkin.render.scene import inside_spans

    # a unit circle under the line y = 0.5: sin t <= 0.5 outside 30° < t < 150°, so one arc
    # from 150° to 390° (240°) stays inside; a circle well inside is drawn whole (None)
    spans = inside_spans(np.array([0.0, 0.0]), 1.0, (-2.0, -2.0, 2.0, 0.5))
    assert spans is not None and len(spans) == 1
    t1, t2 = spans[0]
    assert t1 == pytest.approx(150.0, abs=0.3) and t2 - t1 == pytest.approx(240.0, abs=0.6)
    assert inside_spans(np.array([0.0, 0.0]), 1.0, (-2.0, -2.0, 2.0, 2.0)) is None
    assert inside_spans(np.array([9.0, 9.0]), 1.0, (-2.0, -2.0, 2.0, 2.0)) == []


@pytest.mark.parametrize("dpi", [50, 75, 90, 120, 150])
@pytest.mark.parametrize("name,diagram", [("ex3_1_fourbar", "posture"),
                                          ("fig4_23_rapsons_slide", "centers"),
                                          ("ex11_5_cam_follower_friction", "all")])
def test_every_text_stays_on_the_png_at_any_resolution(gk, dpi, name, diagram):
    # Issue 11: at 90 dpi the results table's footnote ("The drawing agrees with the analytic
    # solution to round-off ...") ran 9 px past the right edge of the PNG, and a long bold
    # sheet title 20 px (it was measured in the regular weight): hinted glyphs set up to 9 %
    # wider than the metrics at 72 dpi said.
    from pathlib import Path

    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.text import Text

    import graphkin
    from graphkin.render import draw
    from graphkin.render.style import rc_context

    if name.startswith("ex3_"):
        d = gk.drawn(name, diagram)
    else:  # a gallery file whose title is wider than its panels
        path = Path(__file__).resolve().parents[2] / "gallery" / "mechanisms" / f"{name}.toml"
        d = draw(graphkin.load(path).solve(), diagram)
    fig = d.figure
    old = fig.dpi
    try:
        fig.set_dpi(dpi)
        with rc_context():
            r = FigureCanvasAgg(fig).get_renderer()
            W, H = fig.bbox.width, fig.bbox.height
            for t in fig.findobj(Text):
                if not t.get_text().strip() or not t.get_visible():
                    continue
                b = t.get_window_extent(r)
                assert b.x0 >= -0.5 and b.y0 >= -0.5 and b.x1 <= W + 0.5 and b.y1 <= H + 0.5, \
                    (t.get_text(), b, W, H)
    finally:
        fig.set_dpi(old)


@pytest.mark.parametrize("diagram,styles", [
    # (a): the mechanism, construction lines, the line of centres N, the two result circles
    ("inflection", {"link", "aux-line", "result-arc"}),
    # (d): Hain's construction and the cubic itself (dashed, Fig. 4.39)
    ("cubic", {"link", "aux-line", "cubic"}),
    ("curvature", {"link", "aux-line", "result-arc", "cubic"}),
])
def test_a_curvature_sheet_has_a_legend_of_its_line_styles(gk, diagram, styles):
    # Issue 11, item 1: "a legend for line styles" on the curvature figures.  Each entry
    # is read back by its gid from the SVG; an entry names a style the sheet draws.
    ids = _ids(gk.svg("ex4_14_inflection_bresse", diagram))
    assert "legend" in ids and "legend-frame" in ids
    shown = {i.removeprefix("legend-") for i in ids
             if i.startswith("legend-") and not i.endswith(("-sample", "-frame"))}
    assert styles <= shown, shown
    if diagram == "inflection":
        assert "cubic" not in shown  # the cubic is figure (d)'s, not drawn in (a)
    d = gk.drawn("ex4_14_inflection_bresse", diagram)
    drawn = {it.style for p in d.sheet.panels for g in p.groups for it in g.items}
    from graphkin.render.legend import LEGEND

    for styles_of, style, _ in LEGEND:  # an entry exactly when one of its styles is drawn
        assert (style in shown) == bool(drawn & set(styles_of)), style


def test_a_posture_sheet_has_no_legend(gk):
    assert "legend" not in _ids(gk.svg("ex3_1_fourbar", "posture"))
