"""Setting a note of a plain matplotlib figure where it covers no curve and no other note.

The drawings built on the label engine (:mod:`graphkin.render.labels`) place
their letters on paper; the cam and gear figures are drawn with matplotlib
directly (plots against the cam angle, the layout by inversion).  Their few
notes (``|φ|max``, ``ρmin``, a station's number) are set here: the note tries
its places in turn, nearest first, and takes the first whose box (from
matplotlib's font metrics, :meth:`~matplotlib.text.Text.get_window_extent`)
crosses no drawn line, covers no marker and no note already set, and stays
inside its axes; where none is clear, the one covering least.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (lettering a drawing), Secs. 6.4 and 6.9-6.10
(the cam figures lettered here).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator, Sequence
from contextlib import contextmanager
from typing import Any

import numpy as np

__all__ = ["Obstacles", "measuring", "settle", "ring"]

PAD = 1.0
"""Clearance (points) kept around a note's glyphs."""
DPI = 300.0
"""The resolution notes are measured at: Agg's hinted metrics round each glyph's advance to a
pixel, so at 100 dpi a 7.5 pt note of 18 letters measures 69 pt for its 75 (8 % short)."""


@contextmanager
def measuring(fig: Any) -> Iterator[Any]:
    """An Agg renderer for ``fig`` at :data:`DPI`, the figure's dpi restored after."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    dpi = fig.dpi
    fig.set_dpi(DPI)
    try:
        yield FigureCanvasAgg(fig).get_renderer()
    finally:
        fig.set_dpi(dpi)


class Obstacles:
    """What a note must not cover, in display pixels: the drawn lines, markers and notes set.

    Parameters
    ----------
    ax : Axes
        The axes whose lines, patches, markers, texts and leaders are obstacles.
    r : renderer
        What measures the texts (:func:`measuring`).
    skip : callable
        True for the gid of an artist that is no obstacle (the notes being set).
    """

    def __init__(self, ax: Any, r: Any, skip: Callable[[str], bool] = lambda gid: False) -> None:
        from shapely import STRtree, box
        from shapely.geometry import LineString, Point

        self.ax = ax
        ax.apply_aspect()      # an equal-aspect axes takes its drawn size first
        bb = ax.bbox
        self.frame = box(bb.x0, bb.y0, bb.x1, bb.y1)
        geoms: list[Any] = []
        owners: list[str] = []
        self.notes: list[Any] = []
        drawn = [*ax.lines, *ax.patches]
        for t in ax.texts:
            if not t.get_visible() or skip(t.get_gid() or "") or not t.get_text().strip():
                continue
            self.notes.append(_box(t, r))
            arrow = getattr(t, "arrow_patch", None)
            if arrow is not None and arrow.get_visible():
                t.update_positions(r)      # its leader where it is drawn
                drawn.append(arrow)
        for art in drawn:
            if not art.get_visible() or skip(art.get_gid() or ""):
                continue
            for poly in _polylines(art):
                if len(poly) >= 2:
                    ln = LineString(poly)
                    if ln.length > 0:
                        geoms.append(ln)
                        owners.append(art.get_gid() or "")
            if hasattr(art, "get_marker") and art.get_marker() not in (None, "None", "none", ""):
                r = 0.5 * float(art.get_markersize()) * ax.figure.dpi / 72.0
                pts = art.get_transform().transform(np.asarray(art.get_xydata(), float))
                discs = [Point(p).buffer(r) for p in pts if np.all(np.isfinite(p))]
                geoms += discs
                owners += [art.get_gid() or ""] * len(discs)
        self.lines = geoms
        self.owners = owners
        self.tree = STRtree(geoms) if geoms else None

    def cost(self, b: Any, own: frozenset[str] = frozenset()) -> float:
        """How much of the box ``b`` (a shapely box) is covered: 0 when it is clear.

        Lines whose gid is in ``own`` (the line a note names) are no obstacle.
        """
        out = b.area - b.intersection(self.frame).area
        if self.tree is not None:
            for j in self.tree.query(b, predicate="intersects"):
                if self.owners[int(j)] in own:
                    continue
                g = self.lines[int(j)]
                out += 1.0 + g.intersection(b).length + g.intersection(b).area
        for n in self.notes:
            out += 10.0 * b.intersection(n).area
        return float(out)

    def take(self, b: Any) -> None:
        """Mark the box ``b`` as a note set."""
        self.notes.append(b)


def _polylines(art: Any) -> list[np.ndarray]:
    """The drawn polylines of a line or patch, in display pixels (curves flattened)."""
    from matplotlib.lines import Line2D

    if isinstance(art, Line2D):
        if art.get_linestyle() in ("None", "none", " ", ""):
            return []
        xy = np.asarray(art.get_xydata(), dtype=float)
        xy = art.get_transform().transform(xy)
        # a NaN breaks the line (a jump drawn as a jump)
        ok = np.all(np.isfinite(xy), axis=1)
        runs, cur = [], []
        for p, good in zip(xy, ok):
            if good:
                cur.append(p)
            elif cur:
                runs.append(np.array(cur))
                cur = []
        if cur:
            runs.append(np.array(cur))
        return runs
    if art.get_linewidth() <= 0:
        return []   # a shaded span: its edges are not drawn
    from matplotlib.patches import FancyArrowPatch

    if isinstance(art, FancyArrowPatch):   # its path is in display pixels once positioned
        return [np.asarray(p) for p in art.get_path().to_polygons(closed_only=False)]
    path = art.get_path().transformed(art.get_transform())
    return [np.asarray(p) for p in path.to_polygons(closed_only=False)]


def _box(t: Any, r: Any) -> Any:
    from matplotlib.text import Text
    from shapely import box

    if hasattr(t, "update_positions"):
        t.update_positions(r)          # an annotation: its text where it is set
    e = Text.get_window_extent(t, r)   # the text alone (an annotation's includes its leader)
    pad = PAD * r.dpi / 72.0
    return box(e.x0 - pad, e.y0 - pad, e.x1 + pad, e.y1 + pad)


def settle(t: Any, places: Sequence[tuple[Any, ...]], obstacles: Obstacles, r: Any,
           own: frozenset[str] = frozenset(), last: bool = True) -> bool:
    """Set the text ``t`` at the first clear place of ``places``; True when it is clear.

    Each place is ``(x, y, ha, va)``: a position in ``t``'s own coordinates
    (for an annotation, its text's offset) and its alignment; ``own`` the gids
    of the lines it names, which it may cross (a station's number on its own
    center line).  With no clear
    place, ``t`` takes the one covering least (unless ``last`` is False: a
    shorter text is to be tried; ``t`` is left as it was).  Its box is then
    taken.  The text is measured once for each alignment and its box moved
    with the place.
    """
    from shapely import box

    def put(x: float, y: float, ha: str, va: str) -> None:
        t.set_position((x, y))
        t.set_ha(ha)
        t.set_va(va)

    if hasattr(t, "update_positions"):
        t.update_positions(r)
    tr = t.get_transform()
    rel: dict[tuple[str, str], np.ndarray] = {}
    best: tuple[float, int] | None = None
    for k, (x, y, ha, va) in enumerate(places):
        p = np.asarray(tr.transform((x, y)), dtype=float)
        if (ha, va) not in rel:
            put(x, y, ha, va)
            rel[(ha, va)] = np.asarray(_box(t, r).bounds) - np.r_[p, p]
        b = box(*(rel[(ha, va)] + np.r_[p, p]))
        c = obstacles.cost(b, own)
        if c == 0.0:
            put(x, y, ha, va)
            obstacles.take(b)
            return True
        if best is None or c < best[0]:
            best = (c, k)
    assert best is not None
    if last:
        put(*places[best[1]])
        obstacles.take(_box(t, r))
    return False


_DIRS = ((1, 1), (1, -1), (-1, 1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))


_DIRS16 = _DIRS + ((2, 1), (2, -1), (-2, 1), (-2, -1), (1, 2), (1, -2), (-1, 2), (-1, -2))


def ring(dists: Sequence[float] = (5.0, 9.0, 14.0, 21.0, 30.0, 42.0, 58.0, 76.0)
         ) -> list[tuple[Any, ...]]:
    """Places (offsets in points, alignment) around a point, nearest first.

    Eight ways round up to 14 pt, sixteen beyond (a note set farther keeps a leader).

    Examples
    --------
    >>> ring((5.0,))[0]
    (3.5355339059327373, 3.5355339059327373, 'left', 'bottom')
    >>> len(ring())
    104
    """
    out: list[tuple[Any, ...]] = []
    for d in dists:
        for dx, dy in (_DIRS if d <= 14.0 else _DIRS16):
            n = float(np.hypot(dx, dy))
            out.append((d * dx / n, d * dy / n,
                        "left" if dx > 0 else "right" if dx < 0 else "center",
                        "bottom" if dy > 0 else "top" if dy < 0 else "center"))
    return out
