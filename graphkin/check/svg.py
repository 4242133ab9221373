"""Reading a drawing file: the lines and labels of an SVG (or, through ezdxf, a DXF).

The SVG reader follows transforms and nested groups (at most
:data:`MAX_DEPTH` deep), turns paths, lines and polylines into segments and
texts into labels, all on paper in the drawing's unit (mm when the root is
sized), y up.  :func:`read_drawing` picks the reader by the file's suffix and
refuses a file over 20 MB.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (a polygon drawn to scale).
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.check.answers import MAX_FILE_BYTES
from graphkin.errors import InputError
from graphkin.io.dxf import DrawingData

#: deepest nesting of SVG groups read
MAX_DEPTH = 200
#: The most elements read from one drawing (a polygon drawing has a few dozen): the check's
#: work grows with them, so a larger file is refused before it starts.
MAX_ELEMENTS = 50_000
#: elements whose content is not drawn where it stands (markers, symbols, clip paths...)
_NOT_DRAWN = frozenset({"defs", "marker", "symbol", "clipPath", "mask", "pattern", "metadata",
                        "title", "desc"})
#: mm per unit of an SVG length
_SVG_UNITS = {"mm": 1.0, "cm": 10.0, "in": 25.4, "pt": 25.4 / 72.0, "pc": 25.4 / 6.0,
              "px": 25.4 / 96.0, "": 25.4 / 96.0}


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
    seen = 0
    while stack:
        el, mat, depth = stack.pop()
        seen += 1
        if seen > MAX_ELEMENTS:
            raise InputError(f"the drawing has more than {MAX_ELEMENTS} elements (a polygon "
                             "drawing has a few dozen)", file=str(path))
        if depth > MAX_DEPTH:
            raise InputError(f"not a readable SVG file: elements nested more than {MAX_DEPTH} "
                             "deep", file=str(path))
        with np.errstate(over="ignore", invalid="ignore"):
            mat = mat @ _transform(el.get("transform"))
        if not np.all(np.isfinite(mat)):
            raise InputError("not a readable SVG file: a transform is not finite",
                             file=str(path))
        if depth and _local(el.tag) in _NOT_DRAWN:
            continue                     # definitions (Inkscape's arrow markers) draw nothing here
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
