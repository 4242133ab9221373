"""Placing labels where they collide with nothing: shapely geometric queries on paper.

Every drawn line, arc, outline and marker of a panel becomes a thin shapely
obstacle (in inches of paper, so the clearance is the same at every scale).
Each label then tries a ring of positions around its anchor, nearest first,
and takes the one whose box overlaps the least ink, the fewest labels already
placed and stays inside the panel.  The choice is deterministic.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (lettering a kinematic diagram).
"""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import LineString, Point, box

from graphkin.render.scene import Item, LabelRequest, Panel
from graphkin.render.style import STYLES

__all__ = ["place_labels", "text_size"]

INK_WIDTH = 0.03
"""How wide a drawn line counts when a label covers it, in inches."""
_PRIORITY = {"label": 0, "number": 1, "label-aux": 2, "label-small": 3}
_DIRS = ((1, 1), (-1, 1), (1, -1), (-1, -1), (1, 0), (-1, 0), (0, 1), (0, -1))


def text_size(text: str, size_pt: float) -> tuple[float, float]:
    """An estimate of a label's width and height in inches (DejaVu Sans metrics, roughly).

    Examples
    --------
    >>> [round(v, 2) for v in text_size("B", 9)]   # a 9 pt capital and a little margin
    [0.11, 0.15]
    """
    em = size_pt / 72.0
    width = 0.0
    small = False
    for ch in text:
        if ch in "${}\\":
            continue
        if ch in "_^":
            small = True
            continue
        f = 0.7 if small else 1.0
        if "₀" <= ch <= "₉":
            w = 0.4
        elif ch in "′'":
            w = 0.25
        elif ch == " ":
            w = 0.32
        elif ch.isupper():
            w = 0.7
        elif ch.isdigit():
            w = 0.64
        elif ch in "il.,:;|":
            w = 0.3
        else:
            w = 0.6
        width += w * f * em
        if small and ch.isalnum() and not text.count("{"):
            small = False
    return width + 0.02, em * 1.05 + 0.02


def _obstacles(panel: Panel, it: Item) -> tuple[list[shapely.Geometry], list[shapely.Geometry]]:
    """The ink of an item in paper inches: (lines, areas)."""
    pts = panel.to_paper(it.xy) if len(it.xy) else np.zeros((0, 2))
    lines: list[shapely.Geometry] = []
    areas: list[shapely.Geometry] = []
    if it.kind in ("path", "arrow") and len(pts) >= 2:
        lines.append(LineString(pts))
    elif it.kind == "polygon" and len(pts) >= 3:
        lines.append(LineString(np.vstack([pts, pts[:1]])))
    elif it.kind == "marker" and len(pts):
        ms = float(STYLES.get(it.style, {}).get("ms", 3.0))
        areas.append(Point(pts[0]).buffer(ms / 72 / 2 + 0.012, quad_segs=2))
    elif it.kind in ("circle", "arc") and len(pts):
        r = it.radius / panel.k
        t1, t2 = (0.0, 360.0) if it.kind == "circle" else (it.theta1, it.theta2)
        ts = np.radians(np.linspace(t1, t2, max(int(abs(t2 - t1) / 4), 4)))
        lines.append(LineString(pts[0] + r * np.stack([np.cos(ts), np.sin(ts)], axis=-1)))
    elif it.kind == "text" and len(pts):
        size = float(STYLES.get(it.style, {}).get("size", 8.0))
        w, h = text_size(it.text, size)
        areas.append(box(pts[0][0] - w / 2, pts[0][1] - h / 2, pts[0][0] + w / 2,
                         pts[0][1] + h / 2))
    return lines, areas


def place_labels(panel: Panel) -> None:
    """Place every label request of a panel as a text item of its group.

    The text items are appended to the groups that asked for them, with the
    request's gid, centred on the chosen box.
    """
    line_list: list[shapely.Geometry] = []
    area_list: list[shapely.Geometry] = []
    for g in panel.groups:
        for it in g.items:
            ls, ars = _obstacles(panel, it)
            line_list.extend(ls)
            area_list.extend(ars)
    lines = np.array(line_list, dtype=object)
    areas = np.array(area_list, dtype=object)
    line_tree = shapely.STRtree(lines)
    area_tree = shapely.STRtree(areas)
    pw, ph = panel.size
    frame = box(0.0, 0.0, pw, ph)
    placed: list[shapely.Geometry] = []
    order = sorted(range(len(panel.labels)),
                   key=lambda i: (_PRIORITY.get(panel.labels[i].style, 4), i))
    for i in order:
        req = panel.labels[i]
        size = float(STYLES.get(req.style, {}).get("size", 8.0))
        w, h = text_size(req.text, size)
        a = panel.to_paper(req.anchor)
        best: tuple[float, np.ndarray] | None = None
        for rank, c in enumerate(_candidates(req, a, w, h)):
            b = box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2)
            area = b.area
            over = 0.0
            hit = line_tree.query(b, predicate="intersects")
            if len(hit):
                inked = float(np.sum(shapely.length(shapely.intersection(lines[hit], b))))
                over += inked * INK_WIDTH / area
            hit = area_tree.query(b, predicate="intersects")
            if len(hit):
                over += float(np.sum(shapely.area(shapely.intersection(areas[hit], b)))) / area
            lab = sum(b.intersection(p).area for p in placed if p.intersects(b)) / area
            out = 1.0 - frame.intersection(b).area / area
            score = 4.0 * over + 25.0 * lab + 40.0 * out + 0.04 * rank
            if best is None or score < best[0] - 1e-12:
                best = (score, c)
            if score < 0.04 * (rank + 1) and over == 0 and lab == 0 and out == 0:
                break
        assert best is not None
        c = best[1]
        placed.append(box(c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2))
        x0, y0, _, _ = panel.view
        xy = np.array([[x0 + c[0] * panel.k, y0 + c[1] * panel.k]])
        req.group.items.append(Item("text", xy, req.style, gid=req.gid, text=req.text,
                                    key=req.key))


def _candidates(req: LabelRequest, a: np.ndarray, w: float, h: float) -> list[np.ndarray]:
    dirs = list(_DIRS)
    if req.prefer is not None:
        px, py = req.prefer
        dirs.sort(key=lambda d: -(d[0] * px + d[1] * py) / math.hypot(*d))
    out = [a.copy()] if req.center else []
    for ring in (1.0, 2.2, 3.6):
        for dx, dy in dirs:
            n = math.hypot(dx, dy)
            ux, uy = dx / n, dy / n
            gap = req.gap * ring + (0.03 if ring > 1 else 0.0)
            out.append(a + np.array([ux * gap + dx * w / 2, uy * gap + dy * h / 2]))
    return out
