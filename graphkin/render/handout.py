"""A handout page (``draw --sheet a4|letter``): one page of paper an instructor hands out as it is.

The page holds, from the top: the panels at the largest scales of the 1-2-5
series that let everything fit, in rows centred on the page; then a band with
the compact results table, the line-style legend and the title block
(mechanism, diagrams, scales; no date), bottom right as on a drawing sheet.
Portrait or landscape, whichever allows the larger drawing (portrait on a tie).

What an ``all`` page shows (a careful instructor's one page): the posture,
the velocity and acceleration polygons, the instant centers with the Kennedy
circle, and of the curvature figures only (a), the inflection and Bresse
circles; the other curvature figures stay one command away
(``-d curvature --sheet a4`` or ``-d bobillier``...).  When even that does
not fit legibly (no panel smaller than :data:`MIN_BIG` inches), the curvature
panel is left off and the title block says which command draws it; the
Kennedy circle always stays beside the instant centers (issue 11: on every
centers figure).

The results table lists the answers the page's diagrams show, in the units
of each diagram's scale bar (ft/s under a ``1 in = 20 ft/s`` bar, even when
the file is in inches), without the analytic comparison; ``--upto K`` leaves
out the answers the construction has not reached.

This module lays the page out (pure arithmetic on font metrics);
:func:`render_page` draws the band into a matplotlib figure.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 and 4.3 (a polygon drawn to a
stated scale, Figs. 3.5 and 4.4); Sec. 3.13 (Fig. 3.22b, the Kennedy circle);
Sec. 4.17 (Figs. 4.33-4.35, the inflection and Bresse circles).
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Callable, Collection, Sequence
from dataclasses import dataclass, field
from typing import Any

from graphkin.render import legend as lg
from graphkin.render.results import (
    Row,
    compact_cells,
    row_diagram,
    scale_factor,
)
from graphkin.render.scale import quantity_unit
from graphkin.render.scene import Panel
from graphkin.render.sheet import GAP, Sheet, build_sheet, sheet_diagrams
from graphkin.render.sources import CURVATURE_PANELS, DiagramUnavailable, Source
from graphkin.render.table import Table, folds_for, measure, table_size

__all__ = ["PAPERS", "PAGE_MARGIN", "Page", "build_paper_sheet", "render_page", "MIN_BIG",
           "block_lines", "place_on_page", "arrange_on_paper", "round_off"]

PAPERS = {"a4": (8.27, 11.69), "letter": (8.5, 11.0)}
"""Paper sizes in inches, portrait (A4 is 210 × 297 mm)."""
PAGE_MARGIN = 0.4
"""Clearance around the page's content, in inches."""
BLOCK_W = 2.7
"""Width of the title block, in inches."""
BIGS = (5.0, 4.2, 3.6, 3.2, 2.8, 2.5, 2.2, 2.0, 1.8, 1.6)
"""The largest panel side tried, in inches, largest first."""
MIN_BIG = 1.6
"""Below this a panel is no longer legible: the page leaves panels off instead."""
BLOCK_PT = 6.5
"""Size of the title block's text (points)."""
@dataclass
class Page:
    """The band of a handout page: where the table, the legend and the title block go.

    Boxes are ``(x, y, width, height)`` in inches from the page's lower-left corner.
    """

    paper: str
    table: Table | None = None
    table_box: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    legend: list[lg.LegendEntry] = field(default_factory=list)
    legend_cols: int = 1
    legend_box: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    block: list[tuple[str, str]] = field(default_factory=list)
    block_box: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 0.0)
    dropped: tuple[str, ...] = ()


# ---------------------------------------------------------------------------- content


def _panel_for(sheet: Sheet, diagram: str) -> Panel | None:
    """The panel whose scale bar a row of ``diagram`` is read against."""
    for p in sheet.panels:
        if diagram == "curvature" and (p.name in CURVATURE_PANELS or p.name == "curvature"):
            return p
        if p.name == diagram:
            return p
    if diagram in ("posture",):  # a single-diagram sheet: the mechanism panel
        for p in sheet.panels:
            if p.mechanism:
                return p
    return None


def _units(sheet: Sheet, file_unit: str) -> dict[str, tuple[str, float]]:
    """Diagram -> (the unit its scale bar is written in, the factor from the file's unit)."""
    out: dict[str, tuple[str, float]] = {}
    for d in ("posture", "velocity", "acceleration", "centers", "curvature"):
        p = _panel_for(sheet, d)
        if p is None or p.scale is None:
            continue
        plane = p.plane if d in ("velocity", "acceleration") else "posture"
        data_unit = quantity_unit(file_unit, plane)
        out[d] = (p.scale.unit, scale_factor(data_unit, p.scale.unit))
    return out


def shown_rows(sheet: Sheet, rows: list[Row]) -> list[Row]:
    """The rows of the quantities the page's diagrams show.

    Positions are left out when the page shows more than the posture (the
    drawing is the position); a curvature row is kept when its point is drawn
    on a curvature panel of the page (``all`` shows only panel (a)).
    """
    more = any(row_diagram(r.key) != "posture" for r in rows)
    drawn: set[str] = set()
    for d, painter in sheet.painters.items():
        if d in CURVATURE_PANELS:
            drawn |= {o for s in painter.cx.steps for o in s.outputs}
    out = []
    for r in rows:
        if more and r.key.startswith("R_"):
            continue
        if r.key.startswith("curvature-"):
            need = ("I", "J") if r.quantity == "|IJ|" else (r.quantity,)
            if not all(n in drawn for n in need):
                continue
        out.append(r)
    return out


def results_table(sheet: Sheet, rows: list[Row], file_unit: str) -> Table:
    """The compact results table of a handout page (no analytic column, no differences)."""
    units = _units(sheet, file_unit)
    tiny = round_off(rows)
    cells: list[tuple[str, ...]] = [compact_cells(r, units, tiny[_kind(r.key)]) for r in rows]
    head: tuple[str, ...] = ("quantity", "value", "direction", "unit")
    align: tuple[str, ...] = ("left", "right", "left", "left")
    if all(not c[2] for c in cells):  # no vector and no rate: no direction column
        cells = [(c[0], c[1], c[3]) for c in cells]
        head, align = ("quantity", "value", "unit"), ("left", "right", "left")
    return Table(head, cells, [r.key for r in rows], align,
                 title="Results read off the construction")


def _kind(key: str) -> str:
    """The kind of quantity a row holds: ``omega``, ``alpha``, ``V_``, ``A_`` or ``length``."""
    for k in ("omega", "alpha", "V_", "A_"):
        if key.startswith(k):
            return k
    return "length"


def round_off(rows: Sequence[Row]) -> dict[str, float]:
    """Kind of quantity -> the magnitude at or below which it is round-off (printed as 0).

    1e-9 of the largest finite magnitude of that kind on the page: a pole at
    ``(6, 8.9e-16)`` in prints as ``(6.000, 0)`` (the elliptic trammel of
    Ex. 12.3), a point really near the origin keeps its digits.

    >>> from graphkin.render.results import Row
    >>> r = [Row("curvature-J", "J", "in", "", "", None, drawn_value=(0.0, 8.9e-16)),
    ...      Row("curvature-I", "I", "in", "", "", None, drawn_value=(6.0, 8.0))]
    >>> round_off(r)["length"]
    1e-08
    """
    big: dict[str, float] = {k: 0.0 for k in ("omega", "alpha", "V_", "A_", "length")}
    for r in rows:
        v = [float(c) for c in r.drawn_value]
        if len(v) == 3:  # homogeneous: a center at infinity has no magnitude
            if abs(v[2]) <= 1e-12 * max(abs(v[0]), abs(v[1]), 1e-300):
                continue
            v = [v[0] / v[2], v[1] / v[2]]
        if r.key.startswith("theta"):
            continue
        m = max((abs(c) for c in v if math.isfinite(c)), default=0.0)
        big[_kind(r.key)] = max(big[_kind(r.key)], m)
    return {k: 1e-9 * m for k, m in big.items()}


def block_lines(entries: Sequence[tuple[str, str, int]]) -> list[tuple[str, str]]:
    """Title-block lines: each ``(text, weight, most lines)`` wrapped to the block's width.

    A text longer than its most lines is cut with an ellipsis.
    """
    from graphkin.render.text import plain

    width = BLOCK_W - 0.16
    lines: list[tuple[str, str]] = []
    for text, weight, most in entries:
        style = "title" if weight == "bold" else "caption"
        chars = max(int(len(text) * width / max(measure(text, BLOCK_PT, style)[0],
                                                1e-9)), 12)
        got = textwrap.wrap(text, chars) or [""]
        while chars > 12 and any(measure(g, BLOCK_PT, style)[0] > width for g in got):
            chars -= 2
            got = textwrap.wrap(text, chars)
        if len(got) > most:
            got = got[:most]
            got[-1] = got[-1][: max(len(got[-1]) - 1, 1)] + "…"
        lines.extend((plain(g), weight) for g in got)
    return lines


def title_block(sheet: Sheet, src: Source) -> list[tuple[str, str]]:
    """The title block's lines: the mechanism, the diagrams, the scales (no date)."""
    names = [p.title.split(") ", 1)[-1] for p in sheet.panels]
    scales = [f"{p.title.split(') ', 1)[-1].lower()} {p.scale.text}" for p in sheet.panels
              if p.scale is not None]
    lines = [
        (sheet.title or (src.mechanism.source if src.mechanism else "") or "Construction",
         "bold", 3),
        ("Diagrams: " + ", ".join(n[:1].lower() + n[1:] for n in names), "normal", 3),
        ("Scales: " + "; ".join(scales), "normal", 6),
        ("Values in the units of each scale bar.", "normal", 1)]
    if sheet.diagram == "all" and "curvature" in sheet_diagrams(src, "all") \
            and not any(p.name in CURVATURE_PANELS for p in sheet.panels):
        # left off to keep the rest legible (build_paper_sheet): say where it is
        lines.append(("Curvature figures: draw -d curvature --sheet " + (sheet.paper or "a4"),
                      "normal", 2))
    return block_lines(lines)


# ---------------------------------------------------------------------------- layout


def _pack(sizes: list[tuple[float, float]], width: float,
          height: float) -> list[tuple[float, float]] | None:
    """Rows of boxes (shelves) centred across ``width``, spread down ``height``; None if too tall.

    Returns the lower-left corner of each box, measured from the area's
    lower-left corner.
    """
    rows: list[list[int]] = [[]]
    used = 0.0
    for i, (w, _) in enumerate(sizes):
        if w > width:
            return None
        if rows[-1] and used + GAP + w > width:
            rows.append([])
            used = 0.0
        used += (GAP if rows[-1] else 0.0) + w
        rows[-1].append(i)
    heights = [max(sizes[i][1] for i in r) for r in rows]
    # an unbounded height (a forced placement) packs the rows tight: no spare to share out
    spare = height - sum(heights) - GAP * (len(rows) - 1) if math.isfinite(height) else 0.0
    if spare < 0:
        return None
    gap_y = GAP + spare / (len(rows) + 1)  # the spare height shared out around the rows
    used_h = sum(heights) + GAP * (len(rows) - 1)
    top = (height if math.isfinite(height) else used_h) - spare / (len(rows) + 1)
    out: list[tuple[float, float]] = [(0.0, 0.0)] * len(sizes)
    y = top
    for r, h in zip(rows, heights):
        row_w = sum(sizes[i][0] for i in r)
        gap_x = GAP if len(r) == 1 else max(GAP, min((width - row_w) / (len(r) + 1), 0.6))
        x = (width - row_w - gap_x * (len(r) - 1)) / 2
        for i in r:
            out[i] = (x, y - (h + sizes[i][1]) / 2)  # centred in its row's height
            x += sizes[i][0] + gap_x
        y -= h + gap_y
    return out


def _band(page: Page, cw: float) -> float:
    """Arrange table, legend and title block across the content width ``cw``; the band's height.

    Two arrangements are tried, the lower one kept: the legend across the page
    above the table and the title block; or the table across the page above the
    legend and the title block.  Boxes are set relative to the band's lower left.
    """
    blk_h = len(page.block) * lg.LINE_H + 0.14
    t = page.table
    best: tuple[float, Any] | None = None
    beside = cw - BLOCK_W - GAP
    for arrangement in ("legend-top", "table-top"):
        if arrangement == "legend-top":
            lc = lg.legend_cols(page.legend, cw)
            lw, lh = lg.legend_size(page.legend, lc)
            tf = folds_for(t, beside) if t else 1
            tw, th = table_size(t, tf) if t else (0.0, 0.0)
            if tw > beside:
                continue
            low = max(th, blk_h)
            h = (lh + GAP if lh else 0.0) + low
            boxes = ((0.0, low - th, tw, th), (0.0, low + GAP, lw, lh), lc, tf, low)
        else:
            tf = folds_for(t, cw) if t else 1
            tw, th = table_size(t, tf) if t else (0.0, 0.0)
            lc = lg.legend_cols(page.legend, beside)
            lw, lh = lg.legend_size(page.legend, lc)
            if tw > cw or lw > beside:
                continue
            low = max(lh, blk_h)
            h = (th + GAP if th else 0.0) + low
            boxes = ((0.0, low + GAP, tw, th), (0.0, low - lh, lw, lh), lc, tf, low)
        if best is None or h < best[0] - 1e-9:
            best = (h, boxes)
    if best is None:  # nothing fits side by side: everything stacked
        tf = folds_for(t, cw) if t else 1
        tw, th = table_size(t, tf) if t else (0.0, 0.0)
        lc = lg.legend_cols(page.legend, cw)
        lw, lh = lg.legend_size(page.legend, lc)
        low = blk_h
        best = (th + lh + blk_h + 2 * GAP,
                ((0.0, blk_h + lh + 2 * GAP, tw, th), (0.0, blk_h + GAP, lw, lh), lc, tf, low))
    h, (tbox, lbox, lc, tf, low) = best
    if t is not None:
        t.folds = tf
    page.table_box, page.legend_box, page.legend_cols = tbox, lbox, lc
    page.block_box = (cw - BLOCK_W, low - blk_h, BLOCK_W, blk_h)
    return float(h)


def build_paper_sheet(src: Source, diagram: str, paper: str, *, upto: int | None = None,
                      highlight: int | Collection[int] | None = None,
                      table: bool = True) -> Sheet:
    """A sheet on one page of ``paper`` (``a4`` or ``letter``) at round scales.

    The panels are drawn at the largest scales of the 1-2-5 series at which
    the panels, the results table, the legend and the title block all fit
    the page, portrait or landscape.

    Raises
    ------
    DiagramUnavailable
        The diagram cannot be drawn; or ``paper`` is not a known size.
    """
    if paper not in PAPERS:
        raise DiagramUnavailable(f"unknown paper {paper!r}; valid: {', '.join(PAPERS)}",
                                 diagram=diagram)
    pw, ph = PAPERS[paper]
    unit = src.length_unit
    first = build_sheet(src, diagram, upto=upto, paper=paper, dry=True, table=table,
                        max_inches=BIGS[0])
    rows = shown_rows(first, first.rows) if table else []
    drops: list[tuple[str, ...]] = [()]
    if diagram == "all" and "curvature" in sheet_diagrams(src, "all"):
        # the curvature figures have their own page (-d curvature); the Kennedy circle belongs
        # with the instant centers it finds (Fig. 3.22b), so it is never left off
        drops += [("curvature",)]
    if "centers" in sheet_diagrams(src, diagram):
        # the last resort before a page that overflows: the Kennedy circle left off (the
        # instant centers' panel and table still give every center; issue 24's six-bar)
        drops += [(*drops[-1], "kennedy")]
    found: tuple[float, list[tuple[float, float]], tuple[str, ...]] | None = None
    all_rows = rows
    sheet: Sheet | None = None
    for first_drop in range(len(drops)):
        found = None
        for drop in drops[first_drop:]:
            # a panel left off takes its answers with it
            rows = [r for r in all_rows
                    if not (r.key.startswith("curvature-") and "curvature" in drop)]
            for big in BIGS:
                if big < MIN_BIG and drop != drops[-1]:
                    break
                trial = build_sheet(src, diagram, paper=paper, dry=True, table=False,
                                    max_inches=big, drop=drop)
                sizes = [(w, h) for w, h in ((pw, ph), (ph, pw))
                         if _arrange(trial, src, rows, unit, (w, h), paper) is not None]
                if sizes:
                    found = (big, sizes, drop)
                    break
            if found:
                break
        if found is None:  # the smallest panels, everything dropped: the best there is
            found = (BIGS[-1], [(pw, ph)], drops[-1])
        sheet = _kept(src, diagram, paper, rows, unit, found, upto, highlight)
        if not any(p.crowded for p in sheet.panels) or found[2] == drops[-1]:
            break
        # a label found no clear place: the page is too full; leave the next panel off
    assert sheet is not None and sheet.page is not None
    sheet.rows = rows
    return sheet


def _kept(src: Source, diagram: str, paper: str, rows: list[Row], unit: str,
          found: tuple[float, list[tuple[float, float]], tuple[str, ...]],
          upto: int | None, highlight: int | Collection[int] | None) -> Sheet:
    """The page drawn at the scales found, portrait or landscape, panels grown where room."""
    big, sizes, drop = found
    # portrait or landscape: the one whose panels grow the larger (portrait on a tie)
    best: tuple[float, tuple[float, float], dict[str, float]] | None = None
    for size in sizes:
        grow, area = _grow(src, diagram, paper, rows, unit, size, big, drop)
        if best is None or area > best[0] * 1.05:
            best = (area, size, grow)
    assert best is not None
    _, size, grow = best
    sheet = build_sheet(src, diagram, upto=upto, highlight=highlight, paper=paper,
                        table=False, max_inches=big, drop=drop, grow=grow)
    page = _arrange(sheet, src, rows, unit, size, paper, force=True)
    assert page is not None
    # a panel where a label found no clear place: a scale larger, while the page has room
    tried: set[str] = set()
    while True:
        crowded = sorted((p for p in sheet.panels if p.crowded and p.scale is not None
                          and p.name not in tried), key=lambda p: -p.crowded)
        if not crowded:
            break
        p = crowded[0]
        tried.add(p.name)
        assert p.scale is not None
        more = dict(grow)
        more[p.name] = more.get(p.name, 1.0) * _next_scale(p.scale.value)
        trial = build_sheet(src, diagram, upto=upto, highlight=highlight, paper=paper,
                            table=False, max_inches=big, drop=drop, grow=more)
        if sum(q.crowded for q in trial.panels) >= sum(q.crowded for q in sheet.panels):
            continue
        tpage = _arrange(trial, src, rows, unit, size, paper)
        if tpage is not None:
            sheet, page, grow = trial, tpage, more
    page.dropped = drop
    return sheet


def _next_scale(v: float) -> float:
    """The factor on a panel's room that draws it at the next larger 1-2-5 scale."""
    mant = v / 10 ** math.floor(math.log10(v) + 1e-9)
    return (2.5 if abs(mant - 5.0) < 1e-6 else 2.0) * (1 + 1e-6)  # 5 -> 2, 2 -> 1, 1 -> 0.5


def _grow(src: Source, diagram: str, paper: str, rows: list[Row], unit: str,
          size: tuple[float, float], big: float,
          drop: tuple[str, ...]) -> tuple[dict[str, float], float]:
    """Draw each panel one scale larger where the page still has room (smallest panels first).

    Returns panel name -> the factor on its room that gives the next larger
    scale of the 1-2-5 series, and the panels' total area then (square inches).
    """
    grow: dict[str, float] = {}
    base = build_sheet(src, diagram, paper=paper, dry=True, table=False, max_inches=big,
                       drop=drop)
    area = sum(p.size[0] * p.size[1] for p in base.panels)
    order = sorted((p for p in base.panels if p.scale is not None),
                   key=lambda p: p.size[0] * p.size[1])
    for p in order:
        assert p.scale is not None
        trial = dict(grow)
        trial[p.name] = _next_scale(p.scale.value)
        sheet = build_sheet(src, diagram, paper=paper, dry=True, table=False, max_inches=big,
                            drop=drop, grow=trial)
        if _arrange(sheet, src, rows, unit, size, paper) is not None:
            grow = trial
            area = sum(q.size[0] * q.size[1] for q in sheet.panels)
    return grow, area


def _arrange(sheet: Sheet, src: Source, rows: list[Row], unit: str,
             size: tuple[float, float], paper: str, force: bool = False) -> Page | None:
    """Place the panels and the band on a page of ``size``; None when they do not fit."""
    page = Page(paper)
    page.table = results_table(sheet, rows, unit) if rows else None
    page.legend = lg.legend_entries(sheet.panels)
    page.block = title_block(sheet, src)
    return place_on_page(sheet, page, size, force)


def place_on_page(sheet: Sheet, page: Page, size: tuple[float, float],
                  force: bool = False) -> Page | None:
    """Place an already-built sheet's panels above a band (table, legend, title block).

    The panels go in rows centred on the page; ``page``'s table, legend and
    title block in the band at the bottom.  Sets the sheet's size and
    ``sheet.page``.  Returns None (changing nothing) when the panels do not
    fit above the band, unless ``force``: then they are placed anyway.
    """
    w, h = size
    cw, ch = w - 2 * PAGE_MARGIN, h - 2 * PAGE_MARGIN
    band = _band(page, cw)
    sizes = [p.size for p in sheet.panels]
    spots = _pack(sizes, cw, ch - band - GAP)
    if spots is None:
        if not force:
            return None
        spots = _pack(sizes, cw, math.inf) or [(0.0, 0.0)] * len(sizes)
        top = max((y + s[1] for (_, y), s in zip(spots, sizes)), default=0.0)
        spots = [(x, y - top + ch - band - GAP) for x, y in spots]
    for p, (x, y) in zip(sheet.panels, spots):
        p.origin = (PAGE_MARGIN + x, PAGE_MARGIN + band + GAP + y)

    def shift(b: tuple[float, float, float, float]) -> tuple[float, float, float, float]:
        return (b[0] + PAGE_MARGIN, b[1] + PAGE_MARGIN, b[2], b[3])

    page.table_box = shift(page.table_box)
    page.legend_box = shift(page.legend_box)
    page.block_box = shift(page.block_box)
    sheet.size = (float(w), float(h))
    sheet.page = page
    sheet.title_offset = None
    return page


def arrange_on_paper(build: Callable[[float], Sheet], band: Callable[[Sheet], Page],
                     paper: str, bigs: Sequence[float] = BIGS) -> Sheet:
    """Put a sheet built elsewhere on one page of ``paper``, as large as it fits.

    The generic entry point for a drawing that builds its own panels (the
    forces drawing, Fig. 11.5): ``build(big)`` makes the sheet with its
    largest panel side ``big`` inches (at the 1-2-5 scales that fit),
    ``band(sheet)`` the page's table, legend and title block.  For portrait
    and for landscape the largest ``big`` of ``bigs`` (largest first) whose
    panels fit above the band is found; the orientation with the larger
    drawing is kept (portrait on a tie).

    Raises
    ------
    DiagramUnavailable
        ``paper`` is not a known size.
    """
    if paper not in PAPERS:
        raise DiagramUnavailable(f"unknown paper {paper!r}; valid: {', '.join(PAPERS)}")
    pw, ph = PAPERS[paper]
    best: tuple[float, tuple[float, float]] | None = None
    for size in ((pw, ph), (ph, pw)):
        for big in bigs:
            if best is not None and big <= best[0]:
                break
            sheet = build(big)
            if place_on_page(sheet, band(sheet), size) is not None:
                best = (big, size)
                break
    big, size = best if best is not None else (bigs[-1], (pw, ph))
    sheet = build(big)
    place_on_page(sheet, band(sheet), size, force=True)
    return sheet


# ---------------------------------------------------------------------------- drawing


def render_page(fig: Any, sheet: Sheet) -> None:
    """Draw a handout page's band: the results table, the legend and the title block."""
    from graphkin.render.table import add_table

    page: Page = sheet.page
    if page.table is not None and page.table.rows:
        x, y, w, h = page.table_box
        add_table(fig, page.table, (x, y), (w, h), sheet.size)
    if page.legend:
        ax = _box_axes(fig, sheet, page.legend_box, "legend")
        lg.draw_legend(ax, page.legend, page.legend_cols, page.legend_box[3])
    _title_block(fig, sheet, page)


def _box_axes(fig: Any, sheet: Sheet, box: tuple[float, float, float, float], gid: str) -> Any:
    return lg.box_axes(fig, sheet.size, box, gid)


def _title_block(fig: Any, sheet: Sheet, page: Page) -> None:
    """The title block, bottom right: mechanism, diagrams, scales (no date)."""
    ax = _box_axes(fig, sheet, page.block_box, "title-block")
    h = page.block_box[3]
    for i, (text, weight) in enumerate(page.block):
        t = ax.text(0.08, h - 0.07 - lg.LINE_H * (i + 0.5), text, fontsize=BLOCK_PT,
                    fontweight=weight, ha="left", va="center")
        t.set_gid(f"title-block-{i}")
