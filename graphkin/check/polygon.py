"""Finding the velocity or acceleration polygons in a drawing: pole, image points, scale.

graphkin's own drawings are read by their group ids (the ``panel-…`` and
``step-…`` groups); a drawing made in CAD or by hand by its geometry: the
vertices are the ends of the polygon's long segments (arrowheads are too
short to count; a polyline's collinear pieces are one segment), and each
label names the nearest vertex of the connected polygon that holds the pole
(the other vertices near it are kept as its ``candidates``: the check reads
the label at one of them when that one, not the nearest, is where the
polygon puts the image).  The pole is the vertex near its label where most
lines meet; the labels elsewhere on the sheet are kept too (the mechanism
drawn beside the polygon gives the sheet's directions).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon and its
labels), Sec. 4.3 (acceleration polygon).
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.check.answers import read_scale
from graphkin.check.svg import (
    _children,
    _local,
    _number,
    _paper,
    _parse_svg,
    _svg_data,
    _text_of,
    _unit_scale,
    _walk,
    read_drawing,
)
from graphkin.errors import InputError
from graphkin.io.dxf import DrawingData

_POLES = {"ov": "velocity", "oa": "acceleration"}


@dataclass
class Polygon:
    """A polygon read from a drawing: its pole and labelled image points, on paper.

    Attributes
    ----------
    diagram : str
        ``velocity`` or ``acceleration``.
    pole : (x, y)
    points : dict
        Label as drawn -> its vertex ``(x, y)`` (drawing units, y up).
    scale : str or None
        The scale stated on the sheet.
    unit : str or None
        The paper unit of the coordinates (``mm`` for SVG with a sized root).
    ignored : list of str
        Labels near the polygon that name no vertex.
    turn : float or None
        When the sheet gives the directions (a printed worksheet): the angle
        (radians, counterclockwise) the polygon is drawn turned from the
        mechanism's axes; only the scale is then fitted.  ``None``: found from
        the mechanism drawn on the same sheet, else fitted.
    candidates : dict
        Label -> the other line ends of the polygon near it, nearest first:
        where the label may stand for when its nearest end is not where the
        polygon puts its image (a label standing a little away).
    sheet_labels : list of (str, (x, y))
        The labels elsewhere on the sheet, each at the line end nearest it
        (the mechanism's joints ``A``, ``B`` ... when it is drawn beside the
        polygon: they give the sheet's directions).
    """

    diagram: str
    pole: tuple[float, float]
    points: dict[str, tuple[float, float]] = field(default_factory=dict)
    scale: str | None = None
    unit: str | None = None
    ignored: list[str] = field(default_factory=list)
    turn: float | None = None
    candidates: dict[str, list[tuple[float, float]]] = field(default_factory=dict)
    sheet_labels: list[tuple[str, tuple[float, float]]] = field(default_factory=list)


def _pole_kind(label: str) -> str | None:
    return _POLES.get(re.sub(r"[^0-9A-Za-z]", "", label).lower())


def _graphkin_panels(root: ET.Element, path: Path) -> list[Polygon]:
    """The polygon panels of a graphkin drawing, read by their group ids.

    ``panel-velocity`` / ``panel-acceleration`` hold one group per construction
    step (``step-NN-label``); a step that lays off an image point draws a
    marker there and labels it (``b``, ``c′``, O_V).  The scale is the text of
    ``scale-text-velocity`` (the sheet is drawn to scale, so its paper units
    are real).
    """
    unit_scale, unit = _unit_scale(root)
    out: list[Polygon] = []
    panels: list[tuple[ET.Element, np.ndarray, int, str]] = []
    for el, mat, depth in _walk(root, path, _paper(unit_scale)):
        gid = el.get("id") or ""
        m = re.fullmatch(r"panel-(?:.*?)(velocity|acceleration)", gid)
        if m and _local(el.tag) == "g":
            panels.append((el, mat, depth, m.group(1)))
    for panel, pmat, pdepth, diagram in panels:
        points: dict[str, tuple[float, float]] = {}
        pole: tuple[float, float] | None = None
        scale = None
        for el, mat, depth in _children(panel, path, pmat, pdepth):
            gid = el.get("id") or ""
            if re.match(r"(?:.*-)?scale-text-", gid):       # ids may carry the panel's prefix
                scale = "".join(el.itertext()).strip()
            if not re.match(r"(?:.*-)?step-\d+-", gid) or _local(el.tag) != "g":
                continue
            marks = []
            label = ""
            for sub, smat, _ in _children(el, path, mat, depth):
                tag = _local(sub.tag)
                if tag == "use":
                    p = smat @ np.array([_number(sub, "x", path), _number(sub, "y", path), 1.0])
                    marks.append((float(p[0]), float(p[1])))
                elif tag == "text" and not label:
                    label = _text_of(sub)
            if len(marks) != 1 or not label:
                continue
            if _pole_kind(label):
                pole = marks[0]
            else:
                points.setdefault(label, marks[0])
        if pole is None or not points:
            # the drawing's details changed: read the panel alone as any drawing is read
            data = _svg_data(_children(panel, path, pmat, pdepth), path)
            data.unit = unit
            try:
                found = find_polygons(data, str(path))
            except InputError:
                continue
            for poly in found:
                poly.scale = poly.scale or scale
            out += [p for p in found if p.diagram == diagram]
            continue
        out.append(Polygon(diagram, pole, points, scale, unit))
    return out


# ---- polygons of any drawing ----------------------------------------------------------

def _merge_collinear(pts: list[tuple[float, float]]) -> list[tuple[float, float]]:
    """A polyline's vertices with collinear runs joined (a tapered arrowhead joins its shaft)."""
    out: list[tuple[float, float]] = []
    for p in pts:
        if out and p == out[-1]:
            continue
        if len(out) >= 2:
            a, b = np.array(out[-2]), np.array(out[-1])
            u, v = b - a, np.array(p) - b
            nu, nv = float(np.hypot(*u)), float(np.hypot(*v))
            if nu > 0 and nv > 0 and float(u @ v) > 0 and \
                    abs(float(u[0] * v[1] - u[1] * v[0])) <= math.sin(math.radians(3)) * nu * nv:
                out[-1] = p
                continue
        out.append(p)
    return out


def _to_tips(long: np.ndarray, strokes: np.ndarray, size: float, eps: float) -> np.ndarray:
    """Run each long segment on to the tip of an arrowhead drawn beyond its end.

    A shaft that stops at the base of its arrowhead (a filled triangle, a
    separate tapered polyline) points at the image point: the tip is the end
    of a short stroke straight ahead of the shaft (within about 8° of its
    line, and no farther than an arrowhead's size).  An end that is already a
    tip (short strokes leave it backwards: barbs, an arrowhead's sides) stays.
    """
    if not len(strokes):
        return long
    marks = strokes.reshape(-1, 2)
    # candidates from a grid of cells of the arrowhead's size: linear in the drawing
    cell = _cell_size(np.concatenate([marks, long.reshape(-1, 2)]), 1.02 * max(size, eps))
    grid: dict[tuple[int, int], list[int]] = {}
    for i, q in enumerate(marks.tolist()):
        grid.setdefault(_key(q, cell), []).append(i)
    for seg in long:
        for k in (0, 1):
            p, q = seg[k], seg[1 - k]
            d = p - q
            n = float(np.hypot(*d))
            if n == 0:
                continue
            d = d / n
            cand = np.array(sorted(_near(grid, p, cell)), dtype=int)
            if not len(cand):
                continue
            near = marks[cand]
            at = np.hypot(*(near - p).T) <= eps          # stroke ends at p
            if np.any(at):
                # the other end of each stroke that touches p
                other = marks[cand[at] ^ 1]
                if np.any((other - p) @ d < 0):
                    continue
            rel = near - p
            along = rel @ d
            across = np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0])
            ok = (along > 0) & (along <= size) & (across <= 0.14 * along)
            if np.any(ok):
                j = int(np.argmax(np.where(ok, along, -np.inf)))
                seg[k] = near[j]
    return long


def _cell_size(points: np.ndarray, eps: float) -> float:
    """A grid cell of at least ``eps``, coarse enough that cell numbers stay whole numbers."""
    far = float(np.max(np.abs(points))) if points.size else 0.0
    return max(eps, far / 2.0**40, 1e-300)


def _key(p: Any, cell: float) -> tuple[int, int]:
    return int(math.floor(p[0] / cell)), int(math.floor(p[1] / cell))


def _near(grid: dict[tuple[int, int], list[int]], p: Any, cell: float) -> list[int]:
    """Indices in the 3 × 3 cells around ``p``: every point within a cell of it is there."""
    a, b = _key(p, cell)
    out: list[int] = []
    for da in (-1, 0, 1):
        for db in (-1, 0, 1):
            out += grid.get((a + da, b + db), [])
    return out


def _any_within(points: np.ndarray, others: np.ndarray, eps: float) -> np.ndarray:
    """For each point, whether some point of ``others`` lies within ``eps`` (linear time)."""
    cell = _cell_size(np.concatenate([points, others]), eps)
    grid: dict[tuple[int, int], list[int]] = {}
    for i, q in enumerate(others.tolist()):
        grid.setdefault(_key(q, cell), []).append(i)
    out = np.zeros(len(points), dtype=bool)
    for i, p in enumerate(points.tolist()):
        cand = _near(grid, p, cell)
        if cand:
            d = np.hypot(*(others[cand] - p).T)
            out[i] = bool(np.any(d <= eps))
    return out


def _cluster(ends: np.ndarray, eps: float) -> tuple[list[np.ndarray], np.ndarray]:
    """Ends closer than ``eps`` to a vertex are that vertex (the first such, in order).

    A grid of cells of side ``eps`` finds the candidates, so a drawing of
    thousands of chained lines is read in linear time (it took a minute
    comparing every end with every vertex).
    """
    cell = _cell_size(ends, eps)
    verts: list[np.ndarray] = []
    grid: dict[tuple[int, int], list[int]] = {}
    index = np.empty(len(ends), dtype=int)
    for i, e in enumerate(ends):
        for j in sorted(_near(grid, e, cell)):
            if float(np.hypot(*(e - verts[j]))) <= eps:
                index[i] = j
                break
        else:
            index[i] = len(verts)
            grid.setdefault(_key(e, cell), []).append(len(verts))
            verts.append(e)
    return verts, index


def find_polygons(data: DrawingData, path: str) -> list[Polygon]:
    """The polygons of a drawing made in CAD or by hand: one per labelled pole.

    Vertices are the ends of the long segments (a segment shorter than 8 % of
    the longest is an arrowhead or a tick; a shaft that stops at its
    arrowhead's base runs on to the tip); ends closer than 1 % of the
    longest segment are one vertex; the polygon is the connected set of
    segments that holds the pole, and each label names its nearest vertex.
    """
    segs = list(data.segments)
    for stroke in data.strokes:
        pts = _merge_collinear(stroke)
        segs += list(zip(pts, pts[1:]))
    segs = [(a, b) for a, b in segs if a != b]
    if not segs:
        raise InputError("the drawing has no lines", file=path)
    arr = np.array(segs, dtype=float)  # (n, 2, 2)
    if not np.all(np.isfinite(arr)):
        raise InputError("the drawing has a coordinate that is not finite", file=path)
    lengths = np.hypot(*(arr[:, 1] - arr[:, 0]).T)
    longest = float(lengths.max())
    short = lengths < 0.08 * longest
    marks = arr[short].reshape(-1, 2)
    eps = 0.01 * longest
    keep = _to_tips(arr[~short].copy(), arr[short], 0.08 * longest, eps)
    # cluster the ends into vertices
    ends = keep.reshape(-1, 2)
    # an end that an arrowhead's strokes touch, or that was run on to a tip, is an arrow's tip
    tip = np.zeros(len(ends), dtype=bool)
    original = arr[~short].reshape(-1, 2)
    tip |= np.any(ends != original, axis=1)
    if len(marks):
        tip |= _any_within(ends, marks, eps)
    verts, index = _cluster(ends, eps)
    parent = list(range(len(verts)))

    def find(i: int) -> int:
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for k in range(len(keep)):
        a, b = find(int(index[2 * k])), find(int(index[2 * k + 1]))
        parent[a] = b
    V = np.array(verts)
    root_of_end = np.array([find(int(i)) for i in index])

    def nearest(at: tuple[float, float], among: list[int] | None = None) -> tuple[int, float]:
        ids = among if among is not None else list(range(len(V)))
        d = np.hypot(*(V[ids] - np.asarray(at)).T)
        k = int(np.argmin(d))
        return ids[k], float(d[k])

    def nearest_end(at: tuple[float, float], root: int) -> tuple[np.ndarray, float]:
        """The segment end nearest a label, among the ends of one polygon (exact, unclustered)."""
        sel = root_of_end == root
        mine, tips = ends[sel], tip[sel]
        d = np.hypot(*(mine - np.asarray(at)).T)
        k = int(np.argmin(d))
        # a label beside an arrow's tip names the tip, though a bare line end be nearer
        close = (d <= d[k] + 0.02 * longest) & tips
        if np.any(close) and not tips[k]:
            k = int(np.argmin(np.where(close, d, np.inf)))
        return mine[k], float(d[k])

    degree = np.bincount(index, minlength=len(V))   # how many segments meet at each vertex
    out: list[Polygon] = []
    bare = _bare_pole_kind(data)
    for text, at in data.labels:
        kind = _pole_kind(text) or (bare if re.sub(r"[^A-Za-z]", "", text) in ("O", "o")
                                    else None)
        if not kind:
            continue
        vi, _ = nearest(at)
        root = find(vi)
        comp = [i for i in range(len(V)) if find(i) == root]
        cv = V[comp]
        size = float(np.hypot(*(cv.max(axis=0) - cv.min(axis=0)))) or longest
        pxy = _pole_vertex(V, comp, degree, at, 0.03 * size)
        poly = Polygon(kind, (float(pxy[0]), float(pxy[1])), scale=data.scale,
                       unit=data.unit)
        best: dict[str, tuple[float, tuple[float, float]]] = {}
        lo, hi = cv.min(axis=0) - 0.1 * size, cv.max(axis=0) + 0.1 * size
        others = [i for i in range(len(V)) if find(i) != root]
        for t2, at2 in data.labels:
            if _pole_kind(t2):
                continue
            exy, d = nearest_end(at2, root)
            if d > 0.12 * size:
                if np.all(np.asarray(at2) >= lo) and np.all(np.asarray(at2) <= hi):
                    poly.ignored.append(t2)
                elif others:
                    oi, _ = nearest(at2, others)
                    poly.sheet_labels.append((t2, (float(V[oi][0]), float(V[oi][1]))))
                continue
            if t2 not in best or d < best[t2][0]:
                best[t2] = (d, (float(exy[0]), float(exy[1])))
                dl = np.hypot(*(cv - np.asarray(at2)).T)
                ok = (np.hypot(*(cv - exy).T) > eps) & (dl <= 0.12 * size)
                order = np.flatnonzero(ok)[np.argsort(dl[ok], kind="stable")]
                poly.candidates[t2] = [(float(cv[i][0]), float(cv[i][1])) for i in order]
        poly.points = {t2: xy for t2, (_, xy) in best.items()}
        out.append(poly)
    return out


def _pole_vertex(V: np.ndarray, comp: list[int], degree: np.ndarray, at: tuple[float, float],
                 slack: float) -> np.ndarray:
    """The pole: of the vertices about as near its label as the nearest, where most lines meet.

    The vectors of a polygon start at its pole, so a label that stands a
    little away, nearer an arrow's tip than the pole, still names the pole.
    """
    d = np.hypot(*(V[comp] - np.asarray(at)).T)
    near = np.flatnonzero(d <= float(d.min()) + slack)
    k = max(near.tolist(), key=lambda j: (int(degree[comp[j]]), -float(d[j])))
    return np.asarray(V[comp[k]])


def _bare_pole_kind(data: DrawingData) -> str | None:
    """The polygon a pole labelled just ``O`` belongs to, told by the sheet's scale.

    Only when no label says ``O_V`` or ``O_A`` and the stated scale's right
    side is a velocity or an acceleration.
    """
    if any(_pole_kind(t) for t, _ in data.labels) or not data.scale:
        return None
    try:
        return read_scale(data.scale, "mm", kinds=("velocity", "acceleration")).quantity
    except InputError:
        return None


def read_polygons(path: str | Path) -> list[Polygon]:
    """The polygons of a drawing: graphkin's own panels by their ids, else by geometry."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".svg":
        root = _parse_svg(path)
        own = _graphkin_panels(root, path)
        if own:
            return own
    data = read_drawing(path)
    return find_polygons(data, str(path))


# ---- scale --------------------------------------------------------------------
