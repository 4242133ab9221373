"""Placing labels where they collide with nothing, and measuring collisions in a drawing.

Placement works on paper (inches, so the clearance is the same at every
scale).  Every drawn line, arc, outline, marker and fixed text of a panel is
rasterised once into an *ink map* (``RES`` cells per inch) with its summed-area
table, so the ink under any box costs four look-ups; labels already placed go
into a second map.  Each label then tries a ring of positions around its
anchor, nearest first, and takes the one that covers the least ink and no
other label and stays inside the panel.  Label sizes come from matplotlib's
own font metrics.  The cost is linear in the number of labels (300 coupler
points place in well under a second), and the choice is deterministic.

:func:`collisions` measures a finished drawing the same way a reader sees it:
text boxes from the font metrics matplotlib reports
(:meth:`~matplotlib.text.Text.get_window_extent`) against each other and
against every drawn segment of another group.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (lettering a kinematic diagram).
"""

from __future__ import annotations

import math
from dataclasses import replace
from functools import lru_cache
from typing import Any

import numpy as np

from graphkin.render.label_points import PRIORITY, labelled_points, nearer_another
from graphkin.render.scene import Item, LabelRequest, Panel
from graphkin.render.style import STYLES
from graphkin.render.text import shown_size

__all__ = ["place_labels", "text_size", "collisions", "RES"]

RES = 100
"""Cells per inch of the ink map."""
_TIE = 1e-9
"""Two places whose scores differ by less than this score alike: the first in rank is taken."""
_BIAS = 1e-7
"""Cells are counted from a point ``_BIAS`` of a cell past each cell's edge: a line or a box
edge exactly on a cell's edge (a panel's round margin, a point at a round coordinate) falls in
the same cell on every machine, where the last digits of its coordinate would decide it."""

INK_WIDTH = 0.03
"""How wide a drawn line counts when a label covers it, in inches."""
_DIRS = ((1, 1), (-1, 1), (1, -1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))
_SAME_WIDTH = str.maketrans("123456789₁₂₃₄₅₆₇₈₉¹²³⁴⁵⁶⁷⁸⁹", "000000000₀₀₀₀₀₀₀₀₀⁰⁰⁰⁰⁰⁰⁰⁰⁰")
_PAD = 0.012
"""Clearance kept around a label's glyphs, in inches."""
SCORE = {"ink": 4.0, "on_ink": 0.6, "label": 25.0, "out": 40.0, "rank": 0.04,
         "astray": 10.0, "grid": 0.25, "grid_distance": 0.5}
"""The weights of a place's score (lower is better): the share of its box a line covers
(``ink``), any ink at all (``on_ink``), the share another label covers (``label``), the share
off the panel (``out``), each rank down the ring (``rank``), nearer another lettered point
(``astray``); a crowded place's grid adds ``grid`` and ``grid_distance`` per inch from the
anchor.  The live page scores its places with the same numbers
(:mod:`graphkin.render.live_labels_js`)."""
GRID = {"step": 0.04, "reach": 0.5, "clear": 0.02}
"""A crowded place's grid about its anchor (inches): its step, its reach beyond the box's
larger side, and the clearance of the box from the anchor."""


@lru_cache(maxsize=1)
def _renderer() -> Any:
    from matplotlib.backends.backend_agg import RendererAgg

    return RendererAgg(10, 10, 72)


@lru_cache(maxsize=8192)
def _metrics(text: str, size_pt: float, family: str, weight: str, style: str) -> tuple[float,
                                                                                      float]:
    from matplotlib.font_manager import FontProperties

    from graphkin.render.style import rc_context
    from graphkin.render.text import is_math, math_ok

    with rc_context():
        prop = FontProperties(family=family, size=size_pt, weight=weight,
                              style=style)  # type: ignore[arg-type]
        math = is_math(text) and math_ok(text)
        shown = text if math else text.replace(r"\$", "$")
        w, h, _d = _renderer().get_text_width_height_descent(shown, prop,
                                                             ismath=bool(math))
    return w / 72.0, h / 72.0


def text_size(text: str, size_pt: float, style: str = "label") -> tuple[float, float]:
    """A label's width and height in inches, from matplotlib's font metrics, plus a margin.

    Examples
    --------
    >>> w, h = text_size("B", 9)
    >>> 0.08 < w < 0.14 and 0.12 < h < 0.2    # a 9 pt capital and a little margin
    True
    """
    st = STYLES.get(style, {})
    size_pt = shown_size(text, float(size_pt))
    # DejaVu's digits share one advance width (and 0, round, is the tallest): "P₁₂₃" measures
    # as "P₀₀₀" and "$V_{P123}$" as "$V_{P000}$", so 300 lettered points measure a handful of
    # strings, not a thousand
    text = text.translate(_SAME_WIDTH)
    family = "monospace" if st.get("family") == "monospace" else "sans-serif"
    if "\n" in text:  # matplotlib's own layout of the lines (line spacing, mathtext depths)
        w, h = _block_metrics(text, float(size_pt), family, str(st.get("weight", "normal")),
                              str(st.get("style", "normal")))
        return w + 2 * _PAD, h + 2 * _PAD
    w, h = _metrics(text or " ", float(size_pt), family, str(st.get("weight", "normal")),
                    str(st.get("style", "normal")))
    return w + 2 * _PAD, max(h, size_pt / 72.0) + 2 * _PAD


@lru_cache(maxsize=1024)
def _block_metrics(text: str, size_pt: float, family: str, weight: str,
                   style: str) -> tuple[float, float]:
    """Width and height (inches) of a text of several lines, as matplotlib lays it out."""
    from matplotlib.figure import Figure
    from matplotlib.font_manager import FontProperties

    from graphkin.render.style import rc_context

    with rc_context():
        prop = FontProperties(family=family, size=size_pt, weight=weight,
                              style=style)  # type: ignore[arg-type]
        t = Figure(dpi=72).text(0, 0, text, fontproperties=prop)
        box = t.get_window_extent(renderer=_renderer())
    return box.width / 72.0, box.height / 72.0


@lru_cache(maxsize=64)
def _disc(r: float) -> np.ndarray:
    """The offsets (inches) of a raster disc of radius ``r`` about its centre."""
    n = max(int(r * RES), 1)
    g = np.arange(-n, n + 1) / RES
    xx, yy = np.meshgrid(g, g)
    inside = xx**2 + yy**2 <= r * r
    out = np.stack([xx[inside], yy[inside]], axis=-1)
    out.flags.writeable = False
    return out


class _InkMap:
    """A raster of a panel's ink with a summed-area table: ink under a box in O(1)."""

    def __init__(self, panel: Panel) -> None:
        pw, ph = panel.size
        self.nx, self.ny = max(int(math.ceil(pw * RES)) + 1, 2), max(int(math.ceil(ph * RES)) + 1,
                                                                       2)
        self.ink = np.zeros((self.ny, self.nx), dtype=np.float32)
        self.taken = np.zeros((self.ny, self.nx), dtype=np.uint8)
        self.sat: np.ndarray | None = None
        self.points = np.zeros((0, 2))
        """The panel's lettered points (paper inches): see :func:`.label_points.labelled_points`."""
        self.last: tuple[np.ndarray, tuple[int, int, int, int]] = (
            np.zeros((0, 0), dtype=np.uint8), (0, 0, 0, 0))

    def _cells(self, pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        ij = np.floor(pts * RES + _BIAS).astype(np.int64)
        ok = (ij[:, 0] >= 0) & (ij[:, 0] < self.nx) & (ij[:, 1] >= 0) & (ij[:, 1] < self.ny)
        return ij[ok, 0], ij[ok, 1]

    def polyline(self, pts: np.ndarray, weight: float = 1.0) -> None:
        """Mark the cells along a polyline (paper inches); each cell counts once per segment."""
        if len(pts) < 2:
            return
        seg = np.diff(pts, axis=0)
        lengths = np.hypot(seg[:, 0], seg[:, 1])
        ok = np.isfinite(lengths)
        if not ok.all():
            pts0, seg, lengths = pts[:-1][ok], seg[ok], lengths[ok]
        else:
            pts0 = pts[:-1]
        if not len(seg):
            return
        # every segment sampled at once: k + 1 points each, t = i (1/k) as np.linspace makes
        # them (the last exactly 1), so that a cell is counted once per segment as before
        k = np.maximum((lengths * RES * 2 + _BIAS).astype(np.int64), 1)
        which = np.repeat(np.arange(len(k)), k + 1)
        start = np.cumsum(k + 1) - (k + 1)
        i = np.arange(len(which)) - start[which]
        t = i * (1.0 / k)[which]
        t[start + k] = 1.0
        q = pts0[which] + t[:, None] * seg[which]
        ij = np.floor(q * RES + _BIAS).astype(np.int64)
        inside = (ij[:, 0] >= 0) & (ij[:, 0] < self.nx) & (ij[:, 1] >= 0) & (ij[:, 1] < self.ny)
        cell = ij[inside, 1] * self.nx + ij[inside, 0]
        pair = np.unique(which[inside] * (self.nx * self.ny) + cell)
        np.add.at(self.ink.reshape(-1), pair % (self.nx * self.ny), np.float32(weight))

    def disc(self, c: np.ndarray, r: float) -> None:
        """Mark the cells of a small filled disc (a marker)."""
        xs, ys = self._cells(c + _disc(r))
        self.ink[ys, xs] += 1.0

    def rect(self, x0: float, y0: float, x1: float, y1: float) -> None:
        """Mark a filled box (a fixed text)."""
        i0, j0 = max(int(x0 * RES + _BIAS), 0), max(int(y0 * RES + _BIAS), 0)
        i1, j1 = min(int(x1 * RES + _BIAS) + 1, self.nx), min(int(y1 * RES + _BIAS) + 1, self.ny)
        if i1 > i0 and j1 > j0:
            self.ink[j0:j1, i0:i1] += 1.0

    def finish(self) -> None:
        """Build the summed-area table (after every obstacle is marked)."""
        self.sat = np.zeros((self.ny + 1, self.nx + 1), dtype=np.float64)
        self.sat[1:, 1:] = np.cumsum(np.cumsum(self.ink, axis=0), axis=1)

    def _range(self, b: tuple[float, float, float, float]) -> tuple[int, int, int, int]:
        i0 = min(max(int(math.floor(b[0] * RES + _BIAS)), 0), self.nx)
        j0 = min(max(int(math.floor(b[1] * RES + _BIAS)), 0), self.ny)
        i1 = min(max(int(math.ceil(b[2] * RES - _BIAS)), 0), self.nx)
        j1 = min(max(int(math.ceil(b[3] * RES - _BIAS)), 0), self.ny)
        return i0, j0, i1, j1

    def ink_in(self, b: tuple[float, float, float, float]) -> float:
        """Inked cells under a box (each cell ~ 1/RES inch of line)."""
        assert self.sat is not None
        i0, j0, i1, j1 = self._range(b)
        if i1 <= i0 or j1 <= j0:
            return 0.0
        s = self.sat
        return float(s[j1, i1] - s[j0, i1] - s[j1, i0] + s[j0, i0])

    def _ranges(self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray,
                y1: np.ndarray) -> tuple[np.ndarray, ...]:
        lo = np.floor(np.stack([x0, y0]) * RES + _BIAS).astype(np.int64)
        hi = np.ceil(np.stack([x1, y1]) * RES - _BIAS).astype(np.int64)
        top = np.array([[self.nx], [self.ny]])
        lo = np.minimum(np.maximum(lo, 0), top)
        hi = np.maximum(np.minimum(np.maximum(hi, 0), top), lo)
        return lo[0], lo[1], hi[0], hi[1]

    def ink_many(self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray,
                 y1: np.ndarray) -> np.ndarray:
        """:meth:`ink_in` of many boxes at once."""
        return self.both_many(x0, y0, x1, y1)[0]

    def taken_many(self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray,
                   y1: np.ndarray) -> np.ndarray:
        """:meth:`taken_in` of many boxes at once."""
        return self.both_many(x0, y0, x1, y1)[1]

    def both_many(self, x0: np.ndarray, y0: np.ndarray, x1: np.ndarray,
                  y1: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The ink and the placed labels' cells under many boxes at once."""
        assert self.sat is not None
        i0, j0, i1, j1 = self._ranges(x0, y0, x1, y1)
        s = self.sat
        inked = s[j1, i1] - s[j0, i1] - s[j1, i0] + s[j0, i0]
        # a summed-area table of the window these boxes cover only (the labels change as
        # they are placed)
        wi, wj = int(i0.min()), int(j0.min())
        win = self.taken[wj:int(j1.max()), wi:int(i1.max())]
        t = np.zeros((win.shape[0] + 1, win.shape[1] + 1), dtype=np.int32)
        np.cumsum(win, axis=0, dtype=np.int32, out=t[1:, 1:])
        np.cumsum(t[1:, 1:], axis=1, out=t[1:, 1:])
        i0, i1, j0, j1 = i0 - wi, i1 - wi, j0 - wj, j1 - wj
        return inked, (t[j1, i1] - t[j0, i1] - t[j1, i0] + t[j0, i0]).astype(float)

    def taken_in(self, b: tuple[float, float, float, float]) -> int:
        """Cells of placed labels under a box."""
        i0, j0, i1, j1 = self._range(b)
        if i1 <= i0 or j1 <= j0:
            return 0
        return int(self.taken[j0:j1, i0:i1].sum())

    def take(self, b: tuple[float, float, float, float]) -> None:
        i0, j0, i1, j1 = self._range(b)
        self.last = (self.taken[j0:j1, i0:i1].copy(), (i0, j0, i1, j1))
        self.taken[j0:j1, i0:i1] = 1

    def _line_cells(self, pts: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The cells along a polyline (paper inches), two cells wide."""
        xs, ys = [], []
        for p0, p1 in zip(pts[:-1], pts[1:]):
            n = max(int(float(np.hypot(*(p1 - p0))) * RES * 2 + _BIAS), 1)
            q = p0 + np.linspace(0.0, 1.0, n + 1)[:, None] * (p1 - p0)
            for dx in (-1, 0, 1):
                for dy in (-1, 0, 1):
                    i, j = self._cells(q + np.array([dx, dy]) / RES)
                    xs.append(i)
                    ys.append(j)
        return np.concatenate(xs), np.concatenate(ys)

    def line_taken(self, pts: np.ndarray) -> bool:
        """True when a polyline (paper inches) runs over a placed label."""
        i, j = self._line_cells(pts)
        return bool(self.taken[j, i].any())

    def take_line(self, pts: np.ndarray) -> None:
        """Keep later labels off a polyline drawn after the ink map was made (a slid arrow)."""
        i, j = self._line_cells(pts)
        self.taken[j, i] = 1

    def untake(self) -> None:
        """Give back the box of the last :meth:`take`."""
        old, (i0, j0, i1, j1) = self.last
        self.taken[j0:j1, i0:i1] = old


def _mark(ink: _InkMap, panel: Panel, it: Item) -> None:
    """Rasterise the ink of one item (paper inches)."""
    if not len(it.xy):
        return
    pts = panel.to_paper(it.xy)
    if it.kind in ("path", "arrow") and len(pts) >= 2:
        ink.polyline(pts)
        if it.kind == "arrow":  # the head is a filled triangle: a blob at the tip
            ink.disc(pts[-1], max(it.width / panel.k, 0.02))
    elif it.kind == "polygon" and len(pts) >= 3:
        ink.polyline(np.vstack([pts, pts[:1]]))
    elif it.kind == "marker":
        ms = float(STYLES.get(it.style, {}).get("ms", 3.0))
        ink.disc(pts[0], ms / 72 / 2 + 0.012)
    elif it.kind in ("circle", "arc"):
        r = it.radius / panel.k
        t1, t2 = (0.0, 360.0) if it.kind == "circle" else (it.theta1, it.theta2)
        ts = np.radians(np.linspace(t1, t2, max(int(abs(t2 - t1) / 2 + 1e-6), 8)))
        ink.polyline(pts[0] + r * np.stack([np.cos(ts), np.sin(ts)], axis=-1))
    elif it.kind == "text":
        size = float(STYLES.get(it.style, {}).get("size", 8.0))
        w, h = text_size(it.text, size, it.style)
        x, y = pts[0]
        x0 = x - w / 2 if it.ha == "center" else (x if it.ha == "left" else x - w)
        y0 = y - h / 2 if it.va == "center" else (y if it.va in ("bottom", "baseline") else y - h)
        ink.rect(x0, y0, x0 + w, y0 + h)
        # a fixed text (a panel's title, its scale text) counts as a placed label: no label
        # may sit on it (issue 11: B_B on the "(d) Cubic" title)
        ink.take((x0 - 0.02, y0 - 0.02, x0 + w + 0.02, y0 + h + 0.02))


def place_labels(panel: Panel) -> None:
    """Place every label request of a panel as a text item of its group.

    The text items are appended to the groups that asked for them, with the
    request's gid, centred on the chosen box.  A request with ``fallback``
    texts (a far point's name and distance on two lines) tries them in turn
    when its text finds no clean place; a list of far points (``parts``) that
    finds none is placed item by item.  ``panel.crowded`` counts the labels
    left without a clean place.
    """
    from graphkin.render.style import rc_context

    with rc_context():  # once for every label measured
        _place_all(panel)


def _place_all(panel: Panel) -> None:
    ink = _InkMap(panel)
    for g in panel.groups:
        for it in g.items:
            _mark(ink, panel, it)
    ink.finish()
    ink.points = labelled_points(panel)
    order = sorted(range(len(panel.labels)),
                   key=lambda i: (PRIORITY.get(panel.labels[i].style, 4), i))
    panel.crowded = 0
    for i in order:
        req = panel.labels[i]
        if _place_one(panel, ink, req) or not req.parts:
            continue
        # the list found no clean place: its items one by one, each near the arrow
        req.group.items.pop()
        ink.untake()
        for part in req.parts:
            _place_one(panel, ink, part)


def _place_one(panel: Panel, ink: _InkMap, req: LabelRequest) -> bool:
    """Place one label (its text, else a fallback text); True when its place is clean.

    A far point's label with ``slides`` looks first for a clean place close to
    its arrow at the panel's edge, then with the arrow slid back along its ray;
    only then anywhere near the edge.
    """
    size = float(STYLES.get(req.style, {}).get("size", 8.0))
    if req.slides and req.arrow is not None:
        for k, anchor in enumerate([req.anchor, *req.slides]):
            shift = anchor - req.anchor
            arrow = panel.to_paper(req.arrow.xy + shift)
            if k and ink.line_taken(arrow):
                continue  # the arrow would cross a label already placed
            near = replace(req, anchor=anchor, slides=[])
            for text in (req.text, *req.fallback):
                w, h = text_size(text, size, req.style)
                c = _near_spot(panel, ink, near, w, h)
                if c is not None:
                    if k:
                        req.arrow.xy = req.arrow.xy + shift
                        ink.take_line(arrow)
                    _put(panel, ink, req, text, c, w, h)
                    return True
    best: tuple[float, np.ndarray, bool, str, float, float] | None = None
    for text in (req.text, *req.fallback):
        w, h = text_size(text, size, req.style)
        sc, c, clean = _spot(panel, ink, req, w, h)
        if best is None or (clean and not best[2]) or (clean == best[2] and sc < best[0]):
            best = (sc, c, clean, text, w, h)
        if clean:
            break
    assert best is not None
    _, c, clean, text, w, h = best
    if not clean and req.arrow is not None:
        # a far point's label with no room near its arrow: the nearest clear place anywhere
        # in the panel, with the arrow set beside it
        for text in (req.text, *req.fallback):
            w, h = text_size(text, size, req.style)
            for c in _clear_spots(panel, ink, panel.to_paper(req.anchor), w, h):
                if _arrow_beside(panel, ink, req.arrow, c, w, h):
                    _put(panel, ink, req, text, c, w, h)
                    return True
        # a panel too small for the name and the distance from its reference point: shorter
        # texts (without the reference, then the name alone), by the arrow or beside it
        # anywhere, rather than a label across the construction's lines
        for text in _shorter(req):
            w, h = text_size(text, size, req.style)
            sc, c, clean = _spot(panel, ink, req, w, h)
            if clean:
                _put(panel, ink, req, text, c, w, h)
                return True
            for c in _clear_spots(panel, ink, panel.to_paper(req.anchor), w, h):
                if _arrow_beside(panel, ink, req.arrow, c, w, h):
                    _put(panel, ink, req, text, c, w, h)
                    return True
        _, c, clean, text, w, h = best
    if not clean and req.arrow is None:
        # a far point of a list placed on its own: its distance without the reference, then
        # its name alone, rather than a label across a line
        for short in _shorter(req):
            sw, sh = text_size(short, size, req.style)
            _, sc_, ok = _spot(panel, ink, req, sw, sh)
            if ok:
                _put(panel, ink, req, short, sc_, sw, sh)
                return True
    if not (clean or req.parts):
        panel.crowded += 1
    if req.arrow is not None and clean:
        _arrow_beside(panel, ink, req.arrow, c, w, h)
    _put(panel, ink, req, text, c, w, h)
    return clean


def _shorter(req: LabelRequest) -> list[str]:
    """Shorter texts of a far point's label: its name and distance, then its name alone."""
    if req.parts or len(req.short) > 1:
        return []
    if req.short:
        short = req.short[0]
        out = [f"{short}\n({req.ref})" if req.ref else short, short]
    elif ", " in req.text and "\n" not in req.text and (" from " in req.text
                                                        or "off the figure" in req.text):
        # one far point of a list placed on its own ("C_N, 5182 ft from I")
        short = req.text.rsplit(" from ", 1)[0].replace(" off the figure", "")
        out = [short]
    else:
        return []
    out.append(short.split(",", 1)[0])
    return [t for t in dict.fromkeys(out) if t and t != req.text and t not in req.fallback]


def _clear_spots(panel: Panel, ink: _InkMap, a: np.ndarray, w: float,
                 h: float) -> list[np.ndarray]:
    """Centres (paper inches) of clear ``w`` × ``h`` boxes in the panel, nearest ``a`` first."""
    pw, ph = panel.size
    if w >= pw or h >= ph:
        return []
    xs = np.arange(w / 2, pw - w / 2, 0.05)
    ys = np.arange(h / 2, ph - h / 2, 0.05)
    gx, gy = (v.ravel() for v in np.meshgrid(xs, ys))
    inked, taken = ink.both_many(gx - w / 2, gy - h / 2, gx + w / 2, gy + h / 2)
    ok = (inked == 0) & (taken == 0)
    # nearest first; as near but for round-off: in grid order
    order = np.argsort(np.round(np.hypot(gx[ok] - a[0], gy[ok] - a[1]), 9), kind="stable")[:40]
    return [np.array([gx[ok][i], gy[ok][i]]) for i in order]


def _arrow_beside(panel: Panel, ink: _InkMap, arrow: Item, c: np.ndarray, w: float,
                  h: float) -> bool:
    """Move a far point's arrow beside its label's box (centre ``c``), pointing the same way.

    The point is many sheet-widths away, so an inch along the edge does not
    change where the arrow points; beside its name it cannot be mistaken.
    Left where it is when the moved arrow would leave the panel or cross a
    label (returns False; True when it stands beside the label).
    """
    pts = panel.to_paper(arrow.xy)
    d = pts[-1] - pts[0]
    n = float(np.hypot(*d))
    a = panel.to_paper(np.asarray([arrow.xy[0]]))[0]
    gap_now = math.hypot(max(abs(a[0] - c[0]) - w / 2, 0.0), max(abs(a[1] - c[1]) - h / 2, 0.0))
    if n <= 0:
        return False
    if gap_now <= NEAR:
        return True
    u = d / n
    # where the arrow may start: out of the box along u (its natural place), else beside
    # the middle of a side or at a corner, a little clear of the box
    t = min(w / 2 / abs(u[0]) if abs(u[0]) > 1e-12 else math.inf,
            h / 2 / abs(u[1]) if abs(u[1]) > 1e-12 else math.inf)
    starts = [c + u * (t + 0.04)] + [
        c + np.array([sx * (w / 2 + 0.04), sy * (h / 2 + 0.04)])
        for sx, sy in ((1, 0), (-1, 0), (0, 1), (0, -1), (1, 1), (-1, 1), (1, -1), (-1, -1))]
    lo, hi = (panel.to_paper(np.asarray([q])) for q in ((panel.inner or panel.view)[:2],
                                                        (panel.inner or panel.view)[2:]))
    box = (c[0] - w / 2 - 0.02, c[1] - h / 2 - 0.02, c[0] + w / 2 + 0.02, c[1] + h / 2 + 0.02)
    sides = starts[1:]
    for length in (n, 0.6 * n):
        # the arrow leaving its name, else (crowded) arriving beside it from behind
        ends = [(q, q + u * length) for q in starts] + [(q - u * length, q) for q in sides]
        for tail, tip in ends:
            new = np.array([tail, tip])
            q = tail + np.linspace(0.0, 1.0, 12)[:, None] * (tip - tail)
            if (new < lo).any() or (new > hi).any() or ink.line_taken(new) or bool((
                    (q[:, 0] > box[0]) & (q[:, 0] < box[2]) & (q[:, 1] > box[1])
                    & (q[:, 1] < box[3])).any()):
                continue  # off the drawing, over a label, or through its own name
            x0, y0, _, _ = panel.view
            arrow.xy = np.array([x0, y0]) + new * panel.k
            ink.take_line(new)
            return True
    return False


def _put(panel: Panel, ink: _InkMap, req: LabelRequest, text: str, c: np.ndarray, w: float,
         h: float) -> None:
    """Take the box centred at ``c`` (paper inches) and add the text item to its group."""
    ink.take((c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2))
    x0, y0, _, _ = panel.view
    xy = np.array([[x0 + c[0] * panel.k, y0 + c[1] * panel.k]])
    req.group.items.append(Item("text", xy, req.style, gid=req.gid, text=text,
                                key=req.key, aliases=list(req.aliases)))


NEAR = 0.3
"""How far (inches) a far point's label may stand from its arrow before the arrow slides."""


def _near_spot(panel: Panel, ink: _InkMap, req: LabelRequest, w: float,
               h: float) -> np.ndarray | None:
    """A clean place for a ``w`` × ``h`` box within :data:`NEAR` of the anchor, or None."""
    pw, ph = panel.size
    a = panel.to_paper(req.anchor)
    for c in _candidates(req, a, w, h):
        b = (c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)
        gap = math.hypot(max(b[0] - a[0], a[0] - b[2], 0.0), max(b[1] - a[1], a[1] - b[3], 0.0))
        if gap > NEAR or b[0] < 0 or b[1] < 0 or b[2] > pw or b[3] > ph:
            continue
        if ink.ink_in(b) == 0 and ink.taken_in(b) == 0:
            return c
    return None


def _spot(panel: Panel, ink: _InkMap, req: LabelRequest, w: float,
          h: float) -> tuple[float, np.ndarray, bool]:
    """The best place (paper inches) for a ``w`` × ``h`` box near the request's anchor.

    Returns its score (lower is better), its centre and whether it is clean
    (no ink, no other label, inside the panel).
    """
    pw, ph = panel.size
    a = panel.to_paper(req.anchor)
    area_cells = max(w * h * RES * RES, 1.0)
    # the ring of candidates, in rank order, and (for a crowded place) a fine grid around the
    # anchor: every box scored by one look-up of the ink and one of the labels
    cand = _candidates(req, a, w, h)
    n = len(cand)
    step = GRID["step"]
    rmax = GRID["reach"] + 1.0 * max(w, h)
    gx, gy, dist = _grid(rmax, step)
    keep = (dist <= rmax) & ((np.abs(gx) >= w / 2 + GRID["clear"])
                             | (np.abs(gy) >= h / 2 + GRID["clear"]))
    cxs = np.concatenate([cand[:, 0], a[0] + gx[keep]])
    cys = np.concatenate([cand[:, 1], a[1] + gy[keep]])
    x0, y0, x1, y1 = cxs - w / 2, cys - h / 2, cxs + w / 2, cys + h / 2
    inked_all, lab_all = ink.both_many(x0, y0, x1, y1)
    inked_all, lab_all = inked_all / RES, lab_all / area_cells
    ix = np.clip(np.minimum(x1, pw) - np.maximum(x0, 0.0), 0, None)
    iy = np.clip(np.minimum(y1, ph) - np.maximum(y0, 0.0), 0, None)
    over_all = inked_all * INK_WIDTH / (w * h)
    out_all = 1.0 - ix * iy / (w * h)
    mark = np.where(inked_all > 0, SCORE["on_ink"], 0.0)
    clean_all = (over_all == 0) & (lab_all == 0) & (out_all <= 1e-12)
    # a point's letters nearer another lettered point would be read as that point's; in a
    # crowded place, at least a box nearer its own point than any other (attached to it);
    # else (no clear place is) a clear place still beats one on a line
    astray = nearer_another(ink.points, a, cxs, cys)
    if astray is not None and not bool(np.any(clean_all & ~astray)):
        astray = nearer_another(ink.points, a, cxs, cys, (w / 2, h / 2))
    if astray is not None and bool(np.any(clean_all & ~astray)):
        clean_all &= ~astray
        mark = mark + np.where(astray, SCORE["astray"], 0.0)

    # the ring taken in rank order up to the first clean one: the best score of that prefix
    sc = SCORE["ink"] * over_all[:n] + mark[:n] + SCORE["label"] * lab_all[:n] \
        + SCORE["out"] * out_all[:n] + SCORE["rank"] * np.arange(n)
    first = int(np.argmax(clean_all[:n])) if clean_all[:n].any() else n - 1
    j = 0
    for k in range(1, first + 1):  # the first strictly better score, as the loop kept it
        if sc[k] < sc[j] - _TIE:
            j = k
    best = (float(sc[j]), cand[j].copy(), bool(clean_all[j]))
    if best[2] or len(cxs) == n:
        return best
    # a crowded place: the grid, nearest clean first
    g = SCORE["ink"] * inked_all[n:] * INK_WIDTH / (w * h) + mark[n:] \
        + SCORE["label"] * lab_all[n:] + SCORE["out"] * out_all[n:] + SCORE["grid"] \
        + SCORE["grid_distance"] * dist[keep]
    # the first of the places as good but for round-off (two at the same distance either side
    # of the anchor score alike): np.argmin would pick either as the last digits went
    j = int(np.flatnonzero(g <= g.min() + _TIE)[0])
    if g[j] < best[0] - _TIE:
        best = (float(g[j]), np.array([cxs[n + j], cys[n + j]]), bool(clean_all[n + j]))
    return best


@lru_cache(maxsize=256)
def _grid(rmax: float, step: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """A square grid of offsets (inches) about an anchor and their distances from it."""
    ring = np.arange(-rmax, rmax + 1e-9, step)
    gx, gy = (v.ravel() for v in np.meshgrid(ring, ring))
    dist = np.hypot(gx, gy)
    for v in (gx, gy, dist):
        v.flags.writeable = False
    return gx, gy, dist


_GAPS = np.array([1.0, 1.8, 2.8, 4.0])
_FAR_RINGS = np.array([0.14, 0.22, 0.32, 0.45, 0.6, 0.8])
RING_SPREAD = 0.02
"""Each ring past the first stands this much farther out per unit of its gap (inches)."""


def _candidates(req: LabelRequest, a: np.ndarray, w: float, h: float) -> np.ndarray:
    """Centres (paper inches) a label tries around its anchor ``a``, in rank order."""
    dirs = list(_DIRS)
    if req.prefer is not None:
        px, py = req.prefer
        # two directions as near the preferred one but for round-off (it bisects them) keep
        # their order in _DIRS, on every machine
        n = math.hypot(px, py) or 1.0
        dirs.sort(key=lambda d: round(-(d[0] * px + d[1] * py) / math.hypot(*d) / n, 9))
    d = np.array(dirs, dtype=float)
    u = d / np.hypot(d[:, 0], d[:, 1])[:, None]
    half = d * np.array([w / 2, h / 2])
    # rings close about the anchor, each in the preferred order of directions; then farther
    # out along the preferred directions, for crowded places
    gaps = np.concatenate([req.gap * _GAPS + np.where(_GAPS > 1, RING_SPREAD * _GAPS, 0.0),
                           _FAR_RINGS])
    out = (a + u[None, :, :] * gaps[:, None, None] + half[None, :, :]).reshape(-1, 2)
    return np.vstack([a[None, :], out]) if req.center else out


# ---------------------------------------------------------------------------
# measuring a finished drawing
# ---------------------------------------------------------------------------

def _segments(artist: Any) -> list[np.ndarray]:
    """The drawn polylines of an artist, in display pixels."""
    from matplotlib import patches
    from matplotlib.lines import Line2D

    out: list[np.ndarray] = []
    ax: Any = artist.axes
    if isinstance(artist, Line2D):
        if artist.get_linestyle() in ("None", "none", " ", ""):
            return out
        xy = np.asarray(artist.get_xydata(), dtype=float)
        if len(xy) >= 2:
            out.append(artist.get_transform().transform(xy))
    elif isinstance(artist, patches.Arc):
        c = np.asarray(artist.center, dtype=float)
        r = artist.width / 2
        t1, t2 = artist.theta1, artist.theta2
        ts = np.radians(np.linspace(t1, t2, max(int(abs(t2 - t1) / 2 + 1e-6), 8)))
        pts = c + r * np.stack([np.cos(ts), np.sin(ts)], axis=-1)
        out.append(ax.transData.transform(pts))
    elif isinstance(artist, patches.Patch):
        edge_alpha = float(np.asarray(artist.get_edgecolor(), dtype=float).ravel()[-1])
        if artist.get_linewidth() <= 0 or edge_alpha == 0:
            return out
        path = artist.get_path().transformed(artist.get_patch_transform())
        for poly in path.to_polygons(closed_only=False):
            if len(np.asarray(poly)) >= 2:
                out.append(ax.transData.transform(np.asarray(poly)))
    return out


def collisions(drawing: Any, *, shrink: float = 0.5) -> list[tuple[str, str, str]]:
    """Every label that overlaps another label or a drawn segment of another group.

    Parameters
    ----------
    drawing : Drawing
        What :func:`graphkin.render.draw` returns.
    shrink : float
        Pixels taken off each side of a text box (glyphs that only touch).

    Returns
    -------
    list of (kind, gid, other)
        ``kind`` is ``label`` (two text boxes overlap, or a label overlaps a
        panel's title, scale text or legend) or ``line`` (a text box crosses a
        line, arc or outline of another group).
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.text import Text
    from shapely import STRtree, box
    from shapely.geometry import LineString

    from graphkin.render.style import rc_context

    fig = drawing.figure
    with rc_context():
        canvas = FigureCanvasAgg(fig)
        renderer = canvas.get_renderer()
        boxes: list[tuple[str, str, Any]] = []
        lines: list[Any] = []
        owners: list[str] = []
        fixed: list[tuple[str, Any]] = []
        for gid, grp in drawing.groups.items():
            for a in grp.get_children():
                if isinstance(a, Text):
                    tg = a.get_gid() or ""
                    if not a.get_text().strip():
                        continue
                    bb = a.get_window_extent(renderer)
                    b = box(bb.x0 + shrink, bb.y0 + shrink, bb.x1 - shrink, bb.y1 - shrink)
                    if "title" in tg or "scale-text" in tg or "legend" in tg:
                        fixed.append((tg, b))  # a panel's title, scale text, legend: obstacles
                    else:
                        boxes.append((tg, gid, b))
                    continue
                parts = [a]
                if hasattr(a, "_shaft"):
                    parts = [a._shaft]  # a vector: its shaft (the head is at its tip)
                axbox = None
                if a.axes is not None:  # what the panel shows: its drawing is clipped there
                    ab = a.axes.bbox
                    axbox = box(ab.x0, ab.y0, ab.x1, ab.y1)
                    # the panel less its title strip (mpl._add_group): a rectangle clip
                    # is kept by matplotlib as a clip box
                    e = a.get_clip_box() if a.get_clip_on() else None
                    if e is not None:
                        axbox = axbox.intersection(box(e.x0, e.y0, e.x1, e.y1))
                for part in parts:
                    part.axes = a.axes
                    for seg in _segments(part):
                        ln = LineString(seg)
                        if axbox is not None:
                            ln = ln.intersection(axbox)
                            if ln.is_empty:
                                continue
                        lines.append(ln)
                        owners.append(gid)
    out: list[tuple[str, str, str]] = []
    if boxes:
        btree = STRtree([b for _, _, b in boxes])
        for i, (ga, _grp_a, ba) in enumerate(boxes):
            for j in btree.query(ba, predicate="intersects"):
                if int(j) > i and ba.intersection(boxes[int(j)][2]).area > 0:
                    out.append(("label", ga, boxes[int(j)][0]))
            for gf, bf in fixed:
                if ba.intersection(bf).area > 0:
                    out.append(("label", ga, gf))
    if lines:
        tree = STRtree(lines)
        for ga, grp_a, ba in boxes:
            for j in tree.query(ba, predicate="intersects"):
                if owners[int(j)] != grp_a:
                    out.append(("line", ga, owners[int(j)]))
        for gf, bf in fixed:  # no construction line runs across a panel's title
            for j in tree.query(bf, predicate="intersects"):
                if "title" in gf and "title" not in owners[int(j)]:
                    out.append(("line", gf, owners[int(j)]))
    return out
