"""One table for every figure that shows one: columns placed from the font's own metrics.

A results table used to be one monospace string per row, padded with
spaces; its columns drifted as soon as a cell held a subscript, a degree sign
or a proportional glyph.  Here every cell is its own text, placed at a column
edge measured with matplotlib's font metrics (:func:`~graphkin.render.labels.text_size`),
numbers right-aligned on the column's right edge, words left-aligned.  A long
table folds into side-by-side blocks (a handout page's table is wide and low).

:func:`table_size` is pure arithmetic on those metrics (no figure); :func:`add_table`
draws a :class:`Table` into a figure.  Group ids read back by tests: the axes
``results``, the group ``results-table``, ``results-title``, each heading
``results-head-F-C`` (fold F, column C), each cell ``row-KEY-C``, the
``results-rule-F`` under each heading and ``results-agreement`` (the footnote).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 and 4.3: the book lists the values
read off each polygon beside the figure (Figs. 3.5, 4.4).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

from graphkin.render.labels import text_size
from graphkin.render.style import STYLES
from graphkin.render.text import shown_size

__all__ = ["Table", "measure", "table_size", "column_widths", "add_table", "folds_for", "ROW_H",
           "PAD"]

ROW_H = 0.15
"""Height of one row, in inches (a 7 pt line and its leading)."""
PAD = 0.08
"""Clearance between the table's box and its text, in inches."""
COL_GAP = 0.12
"""Space between two columns, in inches."""
FOLD_GAP = 0.3
"""Space between two folds of a long table, in inches."""


@dataclass
class Table:
    """A table's content: headings, rows of cells, and how each column is aligned.

    Attributes
    ----------
    head : tuple of str
        The column headings.
    rows : list of tuple of str
        One tuple of cells a row (as many as ``head``).
    keys : list of str
        A stable id a row (``V_B``): the cells' gids are ``row-KEY-C``.
    align : tuple of str
        ``left`` or ``right`` a column.
    title : str
        A line above the headings (empty: none).
    foot : str
        A line under the rows (empty: none).
    folds : int
        Side-by-side blocks the rows are split into.
    """

    head: tuple[str, ...]
    rows: Sequence[tuple[str, ...]]
    keys: list[str]
    align: tuple[str, ...]
    title: str = ""
    foot: str = ""
    folds: int = 1
    style: str = "table"
    head_style: str = "table-head"
    widths: list[float] = field(default_factory=list)

    @property
    def per_fold(self) -> int:
        """Rows in each fold (the last may hold fewer)."""
        return max(-(-len(self.rows) // max(self.folds, 1)), 1)


HINTING = 1.06
"""Widths measured at 72 dpi run a little short of the text drawn at 100-300 dpi (hinting)."""


def measure(text: str, size: float, style: str) -> tuple[float, float]:
    """Width and height of a line of ``text`` in inches, wide enough at any resolution."""
    w, h = text_size(text or " ", float(size), style)
    return w * HINTING, h


def _size(text: str, style: str) -> tuple[float, float]:
    return measure(text, float(STYLES[style].get("size", 7.0)), style)


def column_widths(t: Table) -> list[float]:
    """The width of each column: its widest cell or heading, from the font metrics (inches)."""
    widths = [_size(h, t.head_style)[0] for h in t.head]
    for row in t.rows:
        for c, cell in enumerate(row):
            widths[c] = max(widths[c], _size(cell, t.style)[0])
    return widths


def _fold_width(t: Table) -> float:
    ws = t.widths or column_widths(t)
    return sum(ws) + COL_GAP * (len(ws) - 1)


def table_size(t: Table, folds: int | None = None) -> tuple[float, float]:
    """Width and height of the table's box in inches, for ``folds`` folds (default ``t.folds``).

    The title and the footnote may be wider than the columns: the box then
    grows to hold them whole.
    """
    if not t.widths:
        t.widths = column_widths(t)
    n = max(folds if folds is not None else t.folds, 1)
    per = max(-(-len(t.rows) // n), 1)
    w = n * _fold_width(t) + (n - 1) * FOLD_GAP
    for line in (t.title, t.foot):
        if line:
            # 4 % for hinting: at 90 dpi a long sentence sets 1.6 % wider than its metrics
            w = max(w, 1.04 * _size(line, t.head_style if line is t.title else t.style)[0])
    lines = per + 1 + (1.25 if t.title else 0.0) + (1.25 if t.foot else 0.0)
    return w + 2 * PAD, lines * ROW_H + 2 * PAD


def folds_for(t: Table, max_width: float, max_folds: int = 4) -> int:
    """The most folds (up to ``max_folds``, at most one per row) whose box fits ``max_width``."""
    best = 1
    for n in range(1, min(max_folds, max(len(t.rows), 1)) + 1):
        if table_size(t, n)[0] <= max_width:
            best = n
    return best


def add_table(fig: Any, t: Table, origin: tuple[float, float], size: tuple[float, float],
              page: tuple[float, float], gid: str = "results") -> Any:
    """Draw ``t`` in a box of ``size`` inches at ``origin`` (lower left) of a ``page``-sized figure.

    Returns
    -------
    StepGroup
        The group (id ``results-table``) holding every text and rule.
    """
    from matplotlib.lines import Line2D
    from matplotlib.text import Text

    from graphkin.render.mpl import StepGroup

    if not t.widths:
        t.widths = column_widths(t)
    W, H = page
    x, y = origin
    w, h = size
    ax = fig.add_axes((x / W, y / H, w / W, h / H))
    ax.set_axis_off()
    ax.set_xlim(0, w)
    ax.set_ylim(0, h)
    ax.set_gid(gid)
    arts: list[Any] = []

    def text(xx: float, yy: float, s: str, style: str, tid: str, ha: str = "left") -> None:
        st = STYLES[style]
        a = Text(xx, yy, s, fontsize=shown_size(s, st.get("size", 7.0)),
                 family=st.get("family", "sans-serif"),
                 fontweight=st.get("weight", "normal"), ha=ha, va="center",
                 color=st.get("color", "k"))
        a.set_gid(tid)
        arts.append(a)

    yy = h - PAD - ROW_H / 2
    if t.title:
        text(PAD, yy, t.title, t.head_style, f"{gid}-title")
        yy -= 1.25 * ROW_H
    y_head = yy
    fold_w = _fold_width(t)
    lefts = [sum(t.widths[:c]) + COL_GAP * c for c in range(len(t.widths))]
    n = max(t.folds, 1)
    for f in range(n):
        x0 = PAD + f * (fold_w + FOLD_GAP)
        for c, head in enumerate(t.head):
            right = t.align[c] == "right"
            text(x0 + lefts[c] + (t.widths[c] if right else 0.0), y_head, head, t.head_style,
                 f"{gid}-head-{f}-{c}", "right" if right else "left")
        rule = Line2D([x0, x0 + fold_w], [y_head - ROW_H / 2] * 2, color="k", lw=0.5)
        rule.set_gid(f"{gid}-rule-{f}")
        arts.append(rule)
    per = t.per_fold
    for k, (key, row) in enumerate(zip(t.keys, t.rows)):
        f, r = divmod(k, per)
        x0 = PAD + f * (fold_w + FOLD_GAP)
        ry = y_head - ROW_H * (r + 1)
        for c, cell in enumerate(row):
            right = t.align[c] == "right"
            text(x0 + lefts[c] + (t.widths[c] if right else 0.0), ry, cell, t.style,
                 f"row-{key}-{c}", "right" if right else "left")
    if t.foot:
        text(PAD, y_head - ROW_H * (per + 1.25), t.foot, t.style, f"{gid}-agreement")
    for a in arts:
        a.set_transform(ax.transData)
        a.set_figure(fig)
        a.axes = ax
    sg = StepGroup(f"{gid}-table", arts, 3.0)
    ax.add_artist(sg)
    return sg
