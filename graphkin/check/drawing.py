"""Checking a velocity or acceleration polygon drawn in CAD (DXF or SVG).

A drawing holds lines and text labels: the pole ``O_V`` (or ``O_A``) and the
image points ``b``, ``c``, ``e`` ... (``b'`` is accepted for acceleration
images).  What is read:

* **graphkin's own drawings** (``graphkin draw -d velocity -o v.svg``): only
  the polygon panel (the SVG group ``panel-velocity`` or
  ``panel-acceleration``), its image points where the construction steps put
  them (the ``step-…`` groups), and its scale (``scale-text-…``);
* **drawings made in CAD or by hand**: the vertices are the ends of the
  polygon's long segments (arrowheads, tapered polyline ends and two-line
  arrowheads are too short to count; a polyline's collinear pieces are one
  segment), LEADERs, blocks (INSERT, read as virtual entities), TEXT, MTEXT
  (formatting codes and stacked subscripts such as O with a subscript V) and
  attributes; only the connected polygon that contains the pole is read, and
  each label names the nearest vertex of it.

The drawing's scale comes from ``--scale "1 in = 20 ft/s"`` or a scale note in
the drawing; its axes are then the mechanism's and it is **not** turned to fit
(a polygon drawn for the wrong sense of the input's ω fails).  Without a
scale, the scale and orientation are fitted by least squares over every
labelled image point (with one point only, that point is right by
construction).  Each image point is then read as a vector from the pole and
checked like a measured answer, within 2 % and 2° or within 0.5 mm on the
sheet (``--drawing-tolerance``) when the drawing's paper unit is known.

Limits: a drawing file of at most 20 MB, SVG groups nested at most 200 deep.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon and its
labels: "the line to image point P from image point Q"), Sec. 4.3
(acceleration polygon).
"""

from __future__ import annotations

import dataclasses
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.check.answers import (
    MAX_FILE_BYTES,
    CheckTolerance,
    Given,
    Key,
    SheetScale,
    read_scale,
)
from graphkin.check.compare import fmt
from graphkin.check.diagnose import Diagnoser
from graphkin.check.exact import Evaluator
from graphkin.check.report import FIT, Report, Row, check_given, follow_through, printable
from graphkin.errors import InputError
from graphkin.io.dxf import DrawingData
from graphkin.kinematics.solution import Solution

__all__ = ["read_drawing", "read_svg", "parse_scale", "check_drawing", "Polygon",
           "read_polygons", "find_polygons", "MAX_DEPTH"]

_KIND = {"velocity": "velocity", "acceleration": "acceleration"}
_POLES = {"ov": "velocity", "oa": "acceleration"}
#: deepest nesting of SVG groups read
MAX_DEPTH = 200
#: mm per unit of an SVG length
_SVG_UNITS = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72.0, "pc": 25.4 / 6.0,
              "px": 25.4 / 96.0, "": 25.4 / 96.0}


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
    """

    diagram: str
    pole: tuple[float, float]
    points: dict[str, tuple[float, float]] = field(default_factory=dict)
    scale: str | None = None
    unit: str | None = None
    ignored: list[str] = field(default_factory=list)


def _check_size(path: Path) -> None:
    try:
        st = path.stat()
    except OSError as exc:
        raise InputError(f"cannot read the drawing: {exc.strerror or exc}",
                         file=str(path)) from None
    if not path.is_file():
        raise InputError("cannot read the drawing: not a regular file", file=str(path))
    if st.st_size > MAX_FILE_BYTES:
        raise InputError(f"cannot read the drawing: file too large ({st.st_size} bytes; the "
                         f"limit is {MAX_FILE_BYTES // 1_000_000} MB)", file=str(path))


def read_drawing(path: str | Path) -> DrawingData:
    """Lines and labels of a ``.dxf`` or ``.svg`` drawing."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix not in (".dxf", ".svg"):
        raise InputError("a drawing is a .dxf or .svg file", file=str(path))
    _check_size(path)
    if suffix == ".dxf":
        from graphkin.io.dxf import read_dxf

        return read_dxf(path)
    return read_svg(path)


# ---- SVG ----------------------------------------------------------------------

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def _floats(text: str | None) -> list[float]:
    return [float(x) for x in re.findall(_NUM, text or "")]


def _transform(text: str | None) -> np.ndarray:
    """The 3×3 matrix of an SVG ``transform`` attribute."""
    m = np.eye(3)
    for name, args in re.findall(r"(\w+)\s*\(([^)]*)\)", text or ""):
        a = _floats(args)
        if not all(math.isfinite(x) for x in a):
            return np.full((3, 3), np.nan)
        t = np.eye(3)
        if name == "matrix" and len(a) == 6:
            t = np.array([[a[0], a[2], a[4]], [a[1], a[3], a[5]], [0, 0, 1]])
        elif name == "translate" and a:
            t[0, 2], t[1, 2] = a[0], (a[1] if len(a) > 1 else 0.0)
        elif name == "scale" and a:
            t[0, 0], t[1, 1] = a[0], (a[1] if len(a) > 1 else a[0])
        elif name == "rotate" and a:
            c, s = math.cos(math.radians(a[0])), math.sin(math.radians(a[0]))
            r = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
            if len(a) == 3:
                sh = np.array([[1, 0, a[1]], [0, 1, a[2]], [0, 0, 1]])
                back = np.array([[1, 0, -a[1]], [0, 1, -a[2]], [0, 0, 1]])
                r = sh @ r @ back
            t = r
        m = m @ t
    return m


def _path_points(d: str) -> list[list[tuple[float, float]]]:
    """Vertices of the sub-paths of an SVG path (curves replaced by their chords)."""
    tokens = re.findall(rf"[MmLlHhVvZzCcSsQqTtAa]|{_NUM}", d)
    subs: list[list[tuple[float, float]]] = []
    cur = (0.0, 0.0)
    start = cur
    cmd = ""
    i = 0
    sizes = {"M": 2, "L": 2, "H": 1, "V": 1, "C": 6, "S": 4, "Q": 4, "T": 2, "A": 7, "Z": 0}
    while i < len(tokens):
        t = tokens[i]
        if re.fullmatch(r"[A-Za-z]", t):
            cmd = t
            i += 1
            if cmd in "Zz":
                if subs:
                    subs[-1].append(start)
                cur = start
                continue
        if not cmd:
            break
        n = sizes[cmd.upper()]
        args = [float(x) for x in tokens[i:i + n]]
        if len(args) < n:
            break
        i += n
        rel = cmd.islower()
        up = cmd.upper()
        if up == "H":
            pt = (cur[0] * rel + args[0], cur[1])
        elif up == "V":
            pt = (cur[0], cur[1] * rel + args[0])
        else:
            pt = (args[-2] + cur[0] * rel, args[-1] + cur[1] * rel)
        if up == "M":
            subs.append([pt])
            start = pt
            cmd = "l" if rel else "L"
        elif subs:
            subs[-1].append(pt)
        else:
            subs.append([cur, pt])
        cur = pt
    return subs


def _parse_svg(path: Path) -> ET.Element:
    _check_size(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise InputError(f"cannot read the drawing: {exc.strerror or exc}",
                         file=str(path)) from None
    try:
        # expat resolves no external entities and stops entity expansion attacks
        return ET.fromstring(raw)
    except ET.ParseError as exc:
        raise InputError(f"not a readable SVG file: {exc}", file=str(path)) from None
    except RecursionError:
        raise InputError("not a readable SVG file: nested too deeply", file=str(path)) from None


def _local(tag: Any) -> str:
    return str(tag).rsplit("}", 1)[-1]


def _number(el: ET.Element, name: str, path: Path) -> float:
    text = el.get(name, "0") or "0"
    m = re.fullmatch(rf"\s*({_NUM})\s*(?:px)?\s*", text)
    v = float(m.group(1)) if m else math.nan
    if not math.isfinite(v):
        raise InputError(f"<{_local(el.tag)}> has {name}={text!r}, not a finite number",
                         file=str(path))
    return v


def _walk(el: ET.Element, path: Path, parent: np.ndarray, depth: int = 0):  # type: ignore[no-untyped-def]
    """(element, matrix to paper units with y up, depth) of ``el`` and all below it.

    Iterative and depth-bounded (a hostile file nests groups thousands deep).
    """
    stack: list[tuple[ET.Element, np.ndarray, int]] = [(el, parent, depth)]
    while stack:
        el, mat, depth = stack.pop()
        if depth > MAX_DEPTH:
            raise InputError(f"not a readable SVG file: elements nested more than {MAX_DEPTH} "
                             "deep", file=str(path))
        with np.errstate(over="ignore", invalid="ignore"):
            mat = mat @ _transform(el.get("transform"))
        if not np.all(np.isfinite(mat)):
            raise InputError("not a readable SVG file: a transform is not finite",
                             file=str(path))
        yield el, mat, depth
        if _local(el.tag) != "text":
            stack.extend((c, mat, depth + 1) for c in reversed(list(el)))


def _children(el: ET.Element, path: Path, mat: np.ndarray, depth: int):  # type: ignore[no-untyped-def]
    for c in el:
        yield from _walk(c, path, mat, depth + 1)


def _paper(unit_scale: float) -> np.ndarray:
    return np.diag([unit_scale, -unit_scale, 1.0])


def _unit_scale(root: ET.Element) -> tuple[float, str | None]:
    """Mm per user unit of the root, from its ``width`` and ``viewBox``."""
    m = re.fullmatch(rf"\s*({_NUM})\s*(mm|cm|in|pt|pc|px|)\s*", root.get("width", ""))
    vb = _floats(root.get("viewBox"))
    if m and m.group(2) and len(vb) == 4 and vb[2] > 0 and math.isfinite(float(m.group(1))):
        return float(m.group(1)) * _SVG_UNITS[m.group(2)] / vb[2], "mm"
    if m and m.group(2) and len(vb) != 4:
        return _SVG_UNITS[m.group(2)], "mm"
    return 1.0, None


def _text_of(el: ET.Element) -> str:
    return re.sub(r"\s+", "", "".join(el.itertext()))


def read_svg(path: str | Path) -> DrawingData:
    """Read lines, polylines, paths and texts of an SVG drawing.

    The y axis is turned up (SVG's points down); a root ``width`` in mm, cm,
    in, pt or px with a ``viewBox`` gives coordinates in millimetres of paper,
    else coordinates are in the unit of the stated scale.

    Raises
    ------
    InputError
        The file cannot be read, is not SVG, is nested too deeply, or has a
        coordinate that is not a finite number.
    """
    path = Path(path)
    root = _parse_svg(path)
    unit_scale, unit = _unit_scale(root)
    data = _svg_data(_walk(root, path, _paper(unit_scale)), path)
    data.unit = unit
    return data


def _svg_data(elements: Any, path: Path) -> DrawingData:
    """Segments, strokes and labels of walked SVG elements (``(element, matrix, depth)``)."""
    data = DrawingData()

    def put(mat: np.ndarray, x: float, y: float) -> tuple[float, float]:
        with np.errstate(over="ignore", invalid="ignore"):
            p = mat @ np.array([x, y, 1.0])
        if not (math.isfinite(p[0]) and math.isfinite(p[1])):
            raise InputError("not a readable SVG file: a coordinate is not finite",
                             file=str(path))
        return float(p[0]), float(p[1])

    for el, mat, _ in elements:
        tag = _local(el.tag)
        if tag == "line":
            a = [_number(el, k, path) for k in ("x1", "y1", "x2", "y2")]
            data.segments.append((put(mat, a[0], a[1]), put(mat, a[2], a[3])))
        elif tag in ("polyline", "polygon"):
            v = _floats(el.get("points"))
            pts = [put(mat, v[i], v[i + 1]) for i in range(0, len(v) - 1, 2)]
            if tag == "polygon" and len(pts) > 2:
                pts.append(pts[0])
            data.strokes.append(pts)
        elif tag == "path":
            try:
                subs = _path_points(el.get("d", ""))
            except (ValueError, IndexError, KeyError):
                raise InputError("not a readable SVG file: bad path data",
                                 file=str(path)) from None
            for sub in subs:
                data.strokes.append([put(mat, x, y) for x, y in sub])
        elif tag == "text":
            text = _text_of(el)
            at = put(mat, *_untransformed_at(el))
            if text.lower().startswith("scale:"):
                data.scale = "".join(el.itertext()).split(":", 1)[1].strip()
            elif text:
                data.labels.append((text, at))
    return data


def _untransformed_at(el: ET.Element) -> tuple[float, float]:
    xs, ys = _floats(el.get("x")), _floats(el.get("y"))
    if not xs:
        for child in el:
            if _local(child.tag) == "tspan" and child.get("x") is not None:
                xs, ys = _floats(child.get("x")), _floats(child.get("y"))
                break
    return (xs[0] if xs else 0.0), (ys[0] if ys else 0.0)


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
    for seg in long:
        for k in (0, 1):
            p, q = seg[k], seg[1 - k]
            d = p - q
            n = float(np.hypot(*d))
            if n == 0:
                continue
            d = d / n
            at_p = np.hypot(*(strokes - p).transpose(2, 0, 1)) <= eps       # (n, 2)
            touching = np.any(at_p, axis=1)
            if np.any(touching):
                other = np.where(at_p[touching][:, :1], strokes[touching][:, 1],
                                 strokes[touching][:, 0])
                if np.any((other - p) @ d < 0):
                    continue
            rel = marks - p
            along = rel @ d
            across = np.abs(rel[:, 0] * d[1] - rel[:, 1] * d[0])
            ok = (along > 0) & (along <= size) & (across <= 0.14 * along)
            if np.any(ok):
                j = int(np.argmax(np.where(ok, along, -np.inf)))
                seg[k] = marks[j]
    return long


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
        near = np.hypot(*(ends[:, None, :] - marks[None, :, :]).transpose(2, 0, 1))
        tip |= np.any(near <= eps, axis=1)
    verts: list[np.ndarray] = []
    index = np.empty(len(ends), dtype=int)
    for i, e in enumerate(ends):
        for j, v in enumerate(verts):
            if float(np.hypot(*(e - v))) <= eps:
                index[i] = j
                break
        else:
            index[i] = len(verts)
            verts.append(e)
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
        pxy, _ = nearest_end(at, root)
        poly = Polygon(kind, (float(pxy[0]), float(pxy[1])), scale=data.scale,
                       unit=data.unit)
        best: dict[str, tuple[float, tuple[float, float]]] = {}
        lo, hi = cv.min(axis=0) - 0.1 * size, cv.max(axis=0) + 0.1 * size
        for t2, at2 in data.labels:
            if _pole_kind(t2):
                continue
            exy, d = nearest_end(at2, root)
            if d > 0.12 * size:
                if np.all(np.asarray(at2) >= lo) and np.all(np.asarray(at2) <= hi):
                    poly.ignored.append(t2)
                continue
            if t2 not in best or d < best[t2][0]:
                best[t2] = (d, (float(exy[0]), float(exy[1])))
        poly.points = {t2: xy for t2, (_, xy) in best.items()}
        out.append(poly)
    return out


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

def parse_scale(text: str, kind: str, length_unit: str,
                drawing_unit: str | None) -> tuple[float, str, float]:
    """Read ``"1 in = 20 ft/s"``.

    Returns
    -------
    per_unit : float
        The quantity (internal units) that one drawing unit stands for.
    unit : str
        The unit on the right (to show values in) and ``factor``, its size.

    Examples
    --------
    >>> per, unit, f = parse_scale("1 in = 20 ft/s", "velocity", "in", "in")
    >>> per, unit, f    # 20 ft/s = 240 in/s per inch of drawing
    (240.0, 'ft/s', 12.0)
    """
    from graphkin.units import parse_quantity

    sc = read_scale(text, length_unit, key="--scale", kinds=(kind,))
    du = drawing_unit
    if du is None:
        m = re.match(rf"\s*{_NUM}\s*([A-Za-z]+)", text.split("=", 1)[0])
        du = m.group(1) if m else "mm"
    try:
        mm_per_unit = parse_quantity(f"1 {du}", "length", "mm")[0]
    except ValueError:
        raise InputError(f"unknown drawing unit {du!r}", key="--scale") from None
    right = text.split("=", 1)[1].strip().replace("²", "^2")
    m = re.match(rf"\s*{_NUM}\s*(.*)$", right)
    unit = m.group(1).strip() if m and m.group(1).strip() else ""
    factor = parse_quantity(f"1 {unit}", kind, length_unit)[0] if unit else 1.0
    return sc.per_mm * mm_per_unit, unit or _default(kind, length_unit), factor


def _default(kind: str, lu: str) -> str:
    return f"{lu}/s" if kind == "velocity" else f"{lu}/s^2"


# ---- the check ------------------------------------------------------------------

def _pole_kind(label: str) -> str | None:
    return _POLES.get(re.sub(r"[^0-9A-Za-z]", "", label).lower())


_SUBSCRIPTS = str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789")


def _point_name(label: str, upper: dict[str, str]) -> str | None:
    text = re.sub(r"[\s'′’\"″_{}]", "", label.translate(_SUBSCRIPTS))
    return upper.get(text.upper())


def _on_link(label: str, mech: Any) -> tuple[str, str] | None:
    """``a′₄`` -> ``("A", "4")``: the image of the coincident point A4 (Sec. 3.6)."""
    from graphkin.check.answers import point_on_link

    text = re.sub(r"[\s'′’\"″_{}]", "", label.translate(_SUBSCRIPTS))
    upper = {n.upper(): n for n in mech.point_names}
    for i in range(len(text) - 1, 0, -1):
        name = upper.get(text[:i].upper())
        if name is not None:
            return point_on_link(name + text[i:], mech)
    return None


def check_drawing(sol: Solution, path: str | Path, *, scale: str | None = None,
                  tolerance: CheckTolerance | None = None,
                  diagnoser: Diagnoser | None = None) -> Report:
    """Check a drawn velocity or acceleration polygon against the exact one.

    Parameters
    ----------
    sol : Solution
    path : str or Path
        ``.dxf`` or ``.svg``.
    scale : str, optional
        ``"1 in = 20 ft/s"``; default: the drawing's own scale note, else
        scale and orientation fitted by least squares.
    tolerance : CheckTolerance, optional
        Its ``drawing`` length (default 0.5 mm) applies when the drawing's
        paper unit is known.
    diagnoser : Diagnoser, optional
        Shared between files.

    Returns
    -------
    Report
        One row per labelled image point (of every polygon in the drawing).

    Raises
    ------
    InputError
        Unreadable drawing, no pole label, no image point, no scale and no
        image point to fit.
    """
    path_s = str(path)
    tol = tolerance or CheckTolerance()
    if tol.drawing is None:
        tol = dataclasses.replace(tol, drawing=0.5)
    polys = read_polygons(path)
    if not polys:
        raise InputError("label the pole of the polygon O_V (velocity) or O_A (acceleration)",
                         file=path_s)
    diag = diagnoser if diagnoser is not None and diagnoser.sol is sol else \
        Diagnoser(Evaluator(sol))
    rows: list[Row] = []
    titles: list[str] = []
    notes: list[str] = []
    scales: list[SheetScale] = []
    for poly in polys:
        r, t, n, tol_used = _check_polygon(sol, poly, path_s, scale, tol, diag)
        rows += r
        titles.append(t)
        notes += n
        scales += [sc for sc in tol_used.scales if sc not in scales]
    rep = Report(rows, dataclasses.replace(tol, scales=tuple(scales)), path_s,
                 title="; ".join(titles))
    rep.notes += notes
    return rep


def _check_polygon(sol: Solution, poly: Polygon, path_s: str, scale: str | None,
                   tol: CheckTolerance, diag: Diagnoser
                   ) -> tuple[list[Row], str, list[str], CheckTolerance]:
    diagram = poly.diagram
    kind = _KIND[diagram]
    mech = sol.mechanism
    if not sol.has_rates or (diagram == "acceleration" and not sol.has_accelerations):
        raise InputError(f"the mechanism file gives no rates, so its {diagram} polygon cannot "
                         "be checked", file=path_s)
    helpers = mech.helper_points
    upper = {n.upper(): n for n in mech.point_names if n not in helpers}
    pole = np.array(poly.pole)
    drawn: dict[str, np.ndarray] = {}
    on_link: dict[str, tuple[str, str]] = {}
    ignored = list(poly.ignored)
    helper_names = {n.upper() for n in helpers}
    for lab, xy in poly.points.items():
        name = _point_name(lab, upper)
        if name is None:
            on = _on_link(lab, mech)
            if on is not None and on[0] not in helpers:
                name = f"{on[0]}{on[1]}"
                on_link[name] = on
            elif _point_name(lab, {h: h for h in helper_names}) is None:
                ignored.append(lab)        # slot-definition points are never named
        if name is not None:
            drawn.setdefault(name, np.array(xy) - pole)
    if not drawn:
        raise InputError("no image points labelled with the mechanism's point names "
                         f"({', '.join(n.lower() for n in upper.values())}) in the {diagram} "
                         "polygon", file=path_s)
    ev = diag.ev
    plain = sol.velocity if diagram == "velocity" else sol.acceleration

    def exact_of(name: str) -> np.ndarray:
        if name in on_link:
            return ev.on_link(*on_link[name], "V" if diagram == "velocity" else "A")
        return np.asarray(plain(name), dtype=float)

    stated = scale or poly.scale
    lu = mech.length_unit
    fitted: str | None = None
    notes: list[str] = []
    mm_per_unit: float | None = None
    if poly.unit is not None:
        mm_per_unit = 25.4 if poly.unit == "in" else {"mm": 1.0, "cm": 10.0, "m": 1000.0,
                                                       "ft": 304.8}.get(poly.unit)
    if stated:
        per, unit, factor = parse_scale(stated, kind, lu, poly.unit)
        how = f"scale {stated}, not turned"
        turn = complex(per, 0.0)
        if mm_per_unit is None:
            m = re.match(rf"\s*{_NUM}\s*([A-Za-z]+)", stated.split("=", 1)[0])
            if m and m.group(1) in ("mm", "cm", "in"):
                mm_per_unit = {"mm": 1.0, "cm": 10.0, "in": 25.4}[m.group(1)]
    else:
        names = [n for n in drawn if float(np.hypot(*exact_of(n))) > ev.floor(kind)
                 and float(np.hypot(*drawn[n])) > 0]
        if not names:
            raise InputError("give the drawing's scale (--scale \"1 in = 20 ft/s\") or label "
                             "image points away from the pole, to fit it", file=path_s)
        turn, used = _fit(names, drawn, exact_of, tol)
        unit, factor = _default(kind, lu), 1.0
        if len(names) == 1:
            fitted = names[0]
        deg = math.degrees(math.atan2(turn.imag, turn.real))
        how = (f"fitted by least squares to {', '.join(n.lower() for n in used)}: 1 drawing "
               f"unit = {abs(turn):.4g} {unit}, turned {deg:+.2f}°")
        if abs(deg) > 150.0:
            notes.append("the polygon is turned about 180° from the mechanism's axes: is the "
                         "sense of the input's angular velocity reversed?")
    if mm_per_unit is not None:
        sheet = SheetScale(kind, abs(turn) / mm_per_unit, stated or "fitted")
        tol = dataclasses.replace(tol, scales=(sheet,) + tuple(
            s for s in tol.scales if s.quantity != kind))
    rows: list[Row] = []
    givens: list[Given] = []
    letter = "V" if diagram == "velocity" else "A"
    order = [n for n in mech.point_names if n in drawn] + [n for n in drawn if n in on_link]
    for name in order:
        z = complex(*drawn[name]) * turn
        vec = np.array([z.real, z.imag])
        if name in on_link:
            key = Key(f"{letter}_{name}", letter, (on_link[name][0],), link=on_link[name][1])
        else:
            key = Key(f"{letter}_{name}", letter, (name,))
        mag = float(np.hypot(*vec))
        direction = math.degrees(math.atan2(vec[1], vec[0])) if mag > 0 else None
        raw = f"{fmt(mag / factor)} {unit}" + (f" at {direction:.2f}°" if direction is not None
                                                 else "")
        given = Given(key, raw, value=mag, direction=direction, unit=unit, factor=factor,
                      vector=vec)
        exact = np.asarray(exact_of(name), dtype=float)
        dist = float(np.hypot(*(vec - exact)))
        if name == fitted:
            row = Row(key.text, raw, raw, "—", FIT,
                      note="used to fit the drawing's scale and orientation")
        else:
            row = check_given(ev, diag, given, tol)
            if mm_per_unit is not None:
                mm = dist / abs(turn) * mm_per_unit
                row.error += f"; {mm if mm >= 5e-4 else 0.0:.2g} mm on the drawing"
            else:
                row.error += f"; {dist / factor:.3g} {unit} from exact"
        rows.append(row)
        givens.append(given)
    checked = [i for i, r in enumerate(rows) if r.verdict != FIT]
    sub = [rows[i] for i in checked]
    follow_through(sub, [givens[i] for i in checked], ev, diag, tol)
    ignored = [t for t in ignored if len(re.sub(r"[^0-9A-Za-z]", "", t)) <= 3]  # not titles
    if ignored:
        notes.append("labels that name no image point, ignored: "
                     + ", ".join(printable(t) for t in sorted(set(ignored))))
    title = f"{diagram} polygon in {path_s} ({how})"
    return rows, title, notes, tol


def _fit(names: list[str], drawn: dict[str, np.ndarray], exact_of: Any,
         tol: CheckTolerance) -> tuple[complex, list[str]]:
    """Scale and turn (one complex factor) by least squares, leaving out gross misfits.

    ``exact ≈ turn × drawn`` over the labelled image points; a point off by
    more than five times the tolerance is left out and the fit redone, so one
    wrong point does not spoil the others (at least two points stay in).
    """
    used = list(names)
    zd = {n: complex(*drawn[n]) for n in names}
    ze = {n: complex(*np.asarray(exact_of(n), dtype=float)) for n in names}
    while True:
        num = sum(zd[n].conjugate() * ze[n] for n in used)
        den = sum(abs(zd[n]) ** 2 for n in used)
        turn = num / den
        if len(used) <= 2:
            return turn, used
        err = {n: abs(zd[n] * turn - ze[n]) / abs(ze[n]) for n in used}
        worst = max(used, key=lambda n: err[n])
        if err[worst] <= 5 * tol.relative:
            return turn, used
        used.remove(worst)
