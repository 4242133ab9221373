r"""TikZ: a laid-out sheet written as a LaTeX document holding one ``tikzpicture``.

The same scene the SVG is drawn from (:mod:`graphkin.render.scene`: panels of
groups of items, laid out by :mod:`graphkin.render.sheet`) is written here as
TikZ commands, without matplotlib: every point on paper in inches (the
picture's unit is ``1in``), so that a pin, a line or an arrowhead lands where
the SVG puts it; lines, arcs and vectors clipped to the panel as in the SVG;
labels as real LaTeX text (``ω₃`` becomes ``$\omega_{3}$``, ``A^n_CB``
``$A^{n}_{CB}$``: :func:`graphkin.render.latex.to_latex`), placed at the same
anchors (their glyphs are LaTeX's, so their extent differs slightly).

The file compiles by itself with pdflatex (packages ``tikz`` and ``amssymb``
only; the page is the sheet's size).  To put the figure into lecture notes,
copy the ``tikzpicture`` environment (it needs ``\usepackage{tikz}``,
``\usetikzlibrary{patterns}`` and ``\usepackage{amssymb}``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, 3.4, 4.3 (the drawings).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.render.latex import to_latex
from graphkin.render.scene import Group, Item, Panel, clip_segment
from graphkin.render.style import STYLES, item_style

__all__ = ["sheet_tikz", "drawing_tikz", "PREAMBLE"]

PREAMBLE = ("\\usepackage{tikz}\n\\usetikzlibrary{patterns}\n\\usepackage{amssymb}\n")
"""What the ``tikzpicture`` needs in a document of one's own."""

_DASHES = {"--": (3.7, 1.6), ":": (1.0, 1.65), "-.": (6.4, 1.6, 1.0, 1.6)}
"""Matplotlib's named dash patterns, in line widths (``lines.*_pattern``)."""

_NAMED = {"k": "#000000", "black": "#000000", "white": "#ffffff", "w": "#ffffff",
          "grey": "#808080", "gray": "#808080", "red": "#ff0000", "blue": "#0000ff"}


def _f(v: float) -> str:
    """A coordinate in inches: 4 decimals (2.5 µm), no ``-0``."""
    s = f"{v:.4f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _xy(p: Any) -> str:
    return f"({_f(float(p[0]))},{_f(float(p[1]))})"


def _color(c: Any) -> str | None:
    """A TikZ colour for a matplotlib colour string; None for ``none``."""
    if c is None:
        return None
    if isinstance(c, (tuple, list)):
        r, g, b = (int(round(255 * float(v))) for v in c[:3])
        return f"{{rgb,255:red,{r};green,{g};blue,{b}}}"
    s = str(c).lower()
    if s == "none":
        return None
    s = _NAMED.get(s, s)
    if s.startswith("#") and len(s) in (4, 7):
        if len(s) == 4:
            s = "#" + "".join(ch * 2 for ch in s[1:])
        r, g, b = (int(s[i:i + 2], 16) for i in (1, 3, 5))
        return f"{{rgb,255:red,{r};green,{g};blue,{b}}}"
    return "black"


def _dash(ls: Any, lw: float) -> str | None:
    """A TikZ dash pattern for a matplotlib line style (dashes scale with the line width)."""
    if ls in (None, "-", "solid", "None", "none", ""):
        return None
    if isinstance(ls, str):
        seq: tuple[float, ...] = _DASHES.get(ls, (3.7, 1.6))
    else:
        seq = tuple(float(v) for v in ls[1])
    w = max(lw, 1e-9) if lw > 0 else 1.0
    parts = [f"{'on' if k % 2 == 0 else 'off'} {v * w:.3f}bp" for k, v in enumerate(seq)]
    return "dash pattern=" + " ".join(parts)


_style = item_style


def _stroke(color: Any, lw: float, ls: Any = "-") -> list[str]:
    opts = [f"draw={_color(color) or 'black'}", f"line width={lw:.3f}bp"]
    d = _dash(ls, lw)
    if d:
        opts.append(d)
    return opts


_ANCHOR_H = {"center": "", "left": "west", "right": "east"}
_ANCHOR_V = {"center": "", "top": "north", "bottom": "south", "baseline": "base",
             "center_baseline": "mid"}


def _anchor(ha: str, va: str) -> str:
    v, h = _ANCHOR_V.get(va, ""), _ANCHOR_H.get(ha, "")
    if v == "base" or v == "mid":
        return f"{v} {h}".strip() if h else v
    return f"{v} {h}".strip() or "center"


def text_node(x: float, y: float, text: str, size: float, *, color: Any = "#000000",
              ha: str = "center", va: str = "center", bold: bool = False,
              italic: bool = False) -> str:
    """A TikZ node for one text (several lines centred, or aligned as ``ha``)."""
    lines = [to_latex(s) for s in text.split("\n")]
    font = f"\\fontsize{{{size:g}bp}}{{{1.2 * size:g}bp}}\\selectfont"
    if bold:
        font += "\\bfseries"
    if italic:
        font += "\\itshape"
    opts = [f"anchor={_anchor(ha, va)}", "inner sep=0pt", f"font={font}"]
    c = _color(color)
    if c and c != "{rgb,255:red,0;green,0;blue,0}":
        opts.append(f"text={c}")
    if len(lines) > 1:
        opts.append("align=" + {"left": "left", "right": "right"}.get(ha, "center"))
    body = " \\\\ ".join(lines)
    return f"\\node[{', '.join(opts)}] at {_xy((x, y))} {{{body}}};"


FAR = 100.0
"""Inches from the panel beyond which a line is cut and a circle drawn as its visible part:
TikZ's dimensions stop at 16383 pt (226 in), and a nearly straight path's circle of
curvature can be miles across."""


def _box(p: Panel) -> tuple[float, float, float, float]:
    """The panel on paper, an inch larger all round (TikZ clips the rest exactly)."""
    x0, y0 = p.origin
    w, h = p.size
    return x0 - 1.0, y0 - 1.0, x0 + w + 1.0, y0 + h + 1.0


def _runs(pts: np.ndarray, box: tuple[float, float, float, float]) -> list[np.ndarray]:
    """A polyline cut to ``box``: the runs of it inside, each a polyline."""
    runs: list[np.ndarray] = []
    cur: list[np.ndarray] = []
    for a, b in zip(pts[:-1], pts[1:]):
        seg = clip_segment(a, b, box)
        if seg is None:
            if cur:
                runs.append(np.array(cur))
            cur = []
            continue
        s0, s1 = seg
        if cur and np.allclose(cur[-1], s0, atol=1e-9):
            cur.append(s1)
        else:
            if cur:
                runs.append(np.array(cur))
            cur = [s0, s1]
    if cur:
        runs.append(np.array(cur))
    return runs


def _visible_arc(c: np.ndarray, r: float, t1: float, t2: float,
                 box: tuple[float, float, float, float]) -> list[np.ndarray]:
    """The part of a huge circle (or arc ``t1..t2``, degrees) near ``box``, as polylines.

    From a center outside the box, the box is seen within less than a half
    turn: only the angles between its corners' directions can reach it.  The
    polyline's chords stay within 0.1 µin of the circle.
    """
    x0, y0, x1, y1 = box
    if x0 <= c[0] <= x1 and y0 <= c[1] <= y1:
        return []  # a circle larger than the box about a point inside: none of it shows
    corners = np.array([[x0, y0], [x1, y0], [x1, y1], [x0, y1]]) - c
    mid = math.degrees(math.atan2((y0 + y1) / 2 - c[1], (x0 + x1) / 2 - c[0]))
    ang = np.degrees(np.arctan2(corners[:, 1], corners[:, 0]))
    ang = mid + (ang - mid + 180.0) % 360.0 - 180.0
    lo, hi = float(ang.min()), float(ang.max())
    if t2 - t1 < 360.0:  # an arc: its part within [lo, hi], the arc shifted by whole turns
        shift = 360.0 * math.floor((lo - t1) / 360.0)
        a, b = t1 + shift, t2 + shift
        if b < lo:
            a, b = a + 360.0, b + 360.0
        lo, hi = max(lo, a), min(hi, b)
        if lo >= hi:
            return []
    step = math.degrees(2.0 * math.sqrt(2.0 * 1e-7 / r))
    n = min(max(int(math.ceil((hi - lo) / step)), 2), 20000)
    t = np.radians(np.linspace(lo, hi, n + 1))
    pts = c + r * np.stack([np.cos(t), np.sin(t)], axis=-1)
    return _runs(pts, box)


def _flat(p: Panel) -> Panel:
    """A panel whose data coordinates are the paper's (inches from the sheet's corner)."""
    from graphkin.render.scale import Scale

    w, h = p.size
    x0, y0 = p.origin
    return Panel(p.name, p.plane, "", "in", scale=Scale(1.0, "in", 1.0, "in"),
                 view=(0.0, 0.0, x0 + w, y0 + h), origin=(0.0, 0.0))


def _polyline(opts: list[str], pts: np.ndarray) -> str:
    return f"\\path[{', '.join(opts)}] " + " -- ".join(_xy(q) for q in pts) + ";"


def _item(it: Item, p: Panel, highlight: bool) -> list[str]:
    """The TikZ commands of one item of a panel (paper coordinates, inches)."""
    st = _style(it, highlight)
    k = p.k
    xy = np.atleast_2d(np.asarray(it.xy, dtype=float))
    paper = p.to_paper(xy) + np.asarray(p.origin)
    if not np.all(np.isfinite(paper)):
        return []
    out: list[str] = []
    if it.kind in ("marker", "text", "arrow") and np.abs(paper).max() > FAR:
        return []  # far off the panel: clipped away in the SVG too
    if it.kind == "polygon" and np.abs(paper).max() > FAR:
        from shapely.geometry import Polygon, box

        cut = Polygon(paper).intersection(box(*_box(p)))
        parts = getattr(cut, "geoms", [cut])
        return [line for part in parts if isinstance(part, Polygon) and not part.is_empty
                for line in _item(Item("polygon", np.asarray(part.exterior.coords)[:-1],
                                       it.style, overrides=it.overrides), _flat(p), highlight)]
    if it.kind == "path":
        if len(paper) < 2:
            return []
        opts = _stroke(st.get("color", "k"), float(st.get("lw", 1.0)), st.get("ls", "-"))
        if np.abs(paper).max() > FAR:
            out += [_polyline(opts, run) for run in _runs(paper, _box(p))]
        else:
            out.append(_polyline(opts, paper))
    elif it.kind == "marker":
        ms = float(st.get("ms", 3.0))
        mew = float(st.get("mew", 0.5))
        opts = []
        fc = _color(st.get("mfc", "k"))
        ec = _color(st.get("mec", "k"))
        if fc:
            opts.append(f"fill={fc}")
        if ec and mew > 0:
            opts.append(f"draw={ec}, line width={mew:.3f}bp")
        shape = st.get("marker", "o")
        for q in paper:
            if shape == "s":
                h = ms / 2
                out.append(f"\\path[{', '.join(opts)}] ([shift={{(-{h:g}bp,-{h:g}bp)}}]"
                           f"{_xy(q)[1:-1]}) rectangle ([shift={{({h:g}bp,{h:g}bp)}}]"
                           f"{_xy(q)[1:-1]});")
            else:
                out.append(f"\\path[{', '.join(opts)}] {_xy(q)} circle[radius={ms / 2:g}bp];")
    elif it.kind == "polygon":
        lw = float(st.get("lw", 1.0))
        opts = []
        fc = _color(st.get("fc", "none"))
        if fc:
            opts.append(f"fill={fc}")
        if "alpha" in st:
            opts.append(f"fill opacity={float(st['alpha']):g}")
        if "hatch" in st:
            opts.append(f"pattern=north east lines, pattern color={_color(st.get('ec', 'k'))}")
        if lw > 0 and _color(st.get("ec", "k")):
            opts += _stroke(st.get("ec", "k"), lw, st.get("ls", "-"))
        if opts:
            out.append(f"\\path[{', '.join(opts)}] " + " -- ".join(_xy(q) for q in paper)
                       + " -- cycle;")
    elif it.kind in ("circle", "arc"):
        r = it.radius / k
        opts = _stroke(st.get("color", "k"), float(st.get("lw", 0.5)), st.get("ls", "-"))
        c = paper[0]
        if r > FAR or np.abs(c).max() > FAR:
            t1, t2 = (0.0, 360.0) if it.kind == "circle" else (float(it.theta1),
                                                                 float(it.theta2))
            while t2 <= t1:
                t2 += 360.0
            out += [_polyline(opts, run) for run in _visible_arc(c, r, t1, t2, _box(p))]
        elif it.kind == "circle":
            out.append(f"\\path[{', '.join(opts)}] {_xy(c)} circle[radius={_f(r)}];")
        else:
            t1, t2 = float(it.theta1), float(it.theta2)
            while t2 <= t1:
                t2 += 360.0
            start = c + r * np.array([math.cos(math.radians(t1)), math.sin(math.radians(t1))])
            out.append(f"\\path[{', '.join(opts)}] {_xy(start)} arc[start angle={t1:.4f}, "
                       f"end angle={t2:.4f}, radius={_f(r)}];")
    elif it.kind == "arrow":
        tail, tip = paper[0], paper[-1]
        head, half = it.head / k, it.width / k
        d = tip - tail
        n = float(np.hypot(*d))
        u = d / n if n else np.array([1.0, 0.0])
        nrm = np.array([-u[1], u[0]])
        end = tip - u * min(head * 0.7, n)
        color = st.get("color", "k")
        opts = _stroke(color, float(st.get("lw", 1.0)), st.get("ls", "-"))
        out.append(f"\\path[{', '.join(opts)}] {_xy(tail)} -- {_xy(end)};")
        base = tip - u * head
        c = _color(color) or "black"
        out.append(f"\\path[fill={c}, draw={c}, line width=0.3bp] {_xy(tip)} -- "
                   f"{_xy(base + half * nrm)} -- {_xy(base - half * nrm)} -- cycle;")
    elif it.kind == "text":
        out.append(text_node(paper[0][0], paper[0][1], it.text, float(st.get("size", 8.0)),
                             color=st.get("color", "#000000"), ha=it.ha, va=it.va,
                             bold=st.get("weight") == "bold", italic=st.get("style") == "italic"))
    return out


def _rect(r: tuple[float, float, float, float], p: Panel) -> str:
    a = p.to_paper(np.array([r[0], r[1]])) + np.asarray(p.origin)
    b = p.to_paper(np.array([r[2], r[3]])) + np.asarray(p.origin)
    return f"{_xy(a)} rectangle {_xy(b)}"


def _group(g: Group, p: Panel) -> list[str]:
    lines = [f"% {g.gid}"]
    for it in g.items:
        lines += _item(it, p, g.highlight)
    return lines if len(lines) > 1 else []


def _panel(p: Panel) -> list[str]:
    """A panel: its groups in z order, clipped to its view, construction lines to ``inner``."""
    out = [f"% panel {p.prefix}{p.name}", "\\begin{scope}", f"\\clip {_rect(p.view, p)};"]
    texts: list[str] = []
    for g in sorted(p.groups, key=lambda g: g.z):
        frame = g.gid.startswith(f"{p.prefix}title-") or g.gid.startswith(f"{p.prefix}scale-")
        shapes = Group(g.gid, g.z, [it for it in g.items if it.kind != "text"],
                       highlight=g.highlight)
        words = Group(g.gid, g.z, [it for it in g.items if it.kind == "text"],
                      highlight=g.highlight)
        body = _group(shapes, p)
        if body and p.inner is not None and not frame:
            out += ["\\begin{scope}", f"\\clip {_rect(p.inner, p)};", *body, "\\end{scope}"]
        else:
            out += body
        texts += _group(words, p)
    out.append("\\end{scope}")
    return out + texts


def _table(sheet: Any) -> list[str]:
    """The results table, cell by cell where :func:`graphkin.render.table.add_table` puts it."""
    from graphkin.render.results import full_table
    from graphkin.render.table import (
        COL_GAP,
        FOLD_GAP,
        PAD,
        ROW_H,
        _fold_width,
        column_widths,
        table_size,
    )

    t = full_table(sheet.rows)
    if not t.widths:
        t.widths = column_widths(t)
    x, y = sheet.table_origin
    w, h = table_size(t)
    out = ["% results-table"]

    def text(xx: float, yy: float, s: str, style: str, ha: str = "left") -> None:
        st = STYLES[style]
        out.append(text_node(x + xx, y + yy, s, float(st.get("size", 7.0)), ha=ha, va="center",
                             bold=st.get("weight") == "bold", color=st.get("color", "k")))

    yy = h - PAD - ROW_H / 2
    if t.title:
        text(PAD, yy, t.title, t.head_style)
        yy -= 1.25 * ROW_H
    y_head = yy
    fold_w = _fold_width(t)
    lefts = [sum(t.widths[:c]) + COL_GAP * c for c in range(len(t.widths))]
    for f in range(max(t.folds, 1)):
        x0 = PAD + f * (fold_w + FOLD_GAP)
        for c, head in enumerate(t.head):
            right = t.align[c] == "right"
            text(x0 + lefts[c] + (t.widths[c] if right else 0.0), y_head, head, t.head_style,
                 "right" if right else "left")
        ry = y + y_head - ROW_H / 2
        out.append(f"\\draw[line width=0.5bp] {_xy((x + x0, ry))} -- {_xy((x + x0 + fold_w, ry))};")
    per = t.per_fold
    for k, row in enumerate(t.rows):
        f, r = divmod(k, per)
        x0 = PAD + f * (fold_w + FOLD_GAP)
        for c, cell in enumerate(row):
            right = t.align[c] == "right"
            text(x0 + lefts[c] + (t.widths[c] if right else 0.0), y_head - ROW_H * (r + 1),
                 cell, t.style, "right" if right else "left")
    if t.foot:
        text(PAD, y_head - ROW_H * (per + 1.25), t.foot, t.style)
    return out


def _legend(sheet: Any) -> list[str]:
    """The line-style legend in its framed box (as :func:`graphkin.render.legend.draw_legend`)."""
    from graphkin.render.legend import HANDLE_W, LEGEND_PT, LINE_H, _widths

    bx, by, bw, bh = sheet.legend_box
    out = ["% legend", f"\\draw[line width=0.8bp] {_xy((bx, by))} rectangle "
                       f"{_xy((bx + bw, by + bh))};"]
    entries, cols = sheet.legend, sheet.legend_cols
    per = -(-len(entries) // cols)
    widths = _widths(entries)
    colw = [max(widths[c * per:(c + 1) * per], default=0.0) for c in range(cols)]
    for k, e in enumerate(entries):
        c, r = divmod(k, per)
        x = bx + 0.08 + sum(colw[:c]) + 0.12 * c
        y = by + bh - 0.06 - LINE_H * (r + 0.5)
        st = STYLES.get(e.style, {})
        if e.style == "image":
            out.append(f"\\fill[fill={_color(e.fill)}] {_xy((x, y - 0.04))} rectangle "
                       f"{_xy((x + HANDLE_W, y + 0.04))};")
        elif e.style == "link":
            out.append(f"\\path[fill=white, {', '.join(_stroke('k', STYLES['link']['lw']))}] "
                       f"{_xy((x, y - 0.03))} rectangle {_xy((x + HANDLE_W, y + 0.03))};")
        else:
            opts = _stroke(e.color or st.get("color", "k"), float(st.get("lw", 1.0)),
                           st.get("ls", "-"))
            out.append(f"\\path[{', '.join(opts)}] {_xy((x, y))} -- {_xy((x + HANDLE_W, y))};")
        out.append(text_node(x + HANDLE_W + 0.08, y, e.text, LEGEND_PT, ha="left"))
    return out


def sheet_tikz(sheet: Any, extra: list[tuple[float, float, str, float]] = ()  # type: ignore[assignment]
               ) -> str:
    """A laid-out :class:`~graphkin.render.sheet.Sheet` as a standalone LaTeX document.

    Parameters
    ----------
    sheet : Sheet
        Panels placed on paper (``build_sheet``), labels already placed.
    extra : list of (x, y, text, size)
        More lines of text at ``(x, y)`` inches (left, centred vertically): the
        forces drawing's line stating its scales.

    Returns
    -------
    str
        LaTeX source: the page is the sheet's size, the picture's unit one
        inch, its origin the sheet's lower-left corner.

    Raises
    ------
    GraphkinError
        A handout page (``--sheet``): its band is drawn by matplotlib only.
    """
    from graphkin.errors import GraphkinError
    from graphkin.render.style import SMALL_PT

    if sheet.page is not None:
        raise GraphkinError("a handout page (--sheet) is written as SVG, PDF or PNG; "
                            "TikZ holds the drawing without the page's band")
    W, H = sheet.size
    body = [f"\\path[use as bounding box] (0,0) rectangle {_xy((W, H))};"]
    if sheet.title:
        left, top = sheet.title_offset or (0.0, H)
        body.append(text_node(left + 0.12, top - 0.22, sheet.title,
                              float(STYLES["title"]["size"]) + 1, ha="left", bold=True))
    for p in sheet.panels:
        body += _panel(p)
    if sheet.rows:
        body += _table(sheet)
    if sheet.legend:
        body += _legend(sheet)
    for x, y, s, size in extra:
        body.append(text_node(x, y, s, size or SMALL_PT, ha="left"))
    head = (f"% graphkin: {sheet.diagram} ({W:.3f} x {H:.3f} in), one inch = 1 unit of the "
            "picture\n% compile: pdflatex FILE.tex; in a document of your own, copy the "
            "tikzpicture\n% and put in the preamble: \\usepackage{tikz} "
            "\\usetikzlibrary{patterns} \\usepackage{amssymb}\n")
    return (head + "\\RequirePackage{fix-cm}\n\\documentclass{article}\n" + PREAMBLE
            + f"\\usepackage[paperwidth={_f(W)}in,paperheight={_f(H)}in,margin=0pt]"
              "{geometry}\n\\pagestyle{empty}\n\\setlength{\\topskip}{0pt}\n"
              "\\setlength{\\parindent}{0pt}\n\\begin{document}\n"
            + "\\begin{tikzpicture}[x=1in, y=1in, line cap=butt, line join=miter]\n"
            + "\n".join(body) + "\n\\end{tikzpicture}\n\\end{document}\n")


def drawing_tikz(drawing: Any) -> str:
    """The TikZ document of a :class:`~graphkin.render.mpl.Drawing` (from its sheet).

    The forces drawing's scale line (a text of the figure, outside the
    panels) is written too.
    """
    from graphkin.errors import GraphkinError

    sheet = getattr(drawing, "sheet", None)
    if sheet is None:
        raise GraphkinError("this drawing has no sheet to write as TikZ")
    extra = []
    t = getattr(drawing, "texts", {}).get("force-scale")
    if t is not None:  # placed in figure fractions by render.forces
        fx, fy = t.get_position()
        W, H = sheet.size
        extra.append((fx * W, fy * H, t.get_text(), float(t.get_fontsize())))
    return sheet_tikz(sheet, extra)
