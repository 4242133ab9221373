"""DXF in and out, with ezdxf (imported only when a DXF is read or written).

:func:`write_dxf` writes a construction (the posture, or the velocity or
acceleration polygon, whole or up to a step) as a drawing a student can go on
with in CAD; :func:`read_dxf` reads back the lines and the text labels of a
drawing, for ``graphkin check --drawing``.

Polygons are written at a round scale (``1 in = 200 in/s``) chosen so the
polygon is about the size of the mechanism; the scale is stated in a note on
the drawing and in the header variable ``graphkin_scale``.  Every image point of
a named point is the end of a line from the pole and is labelled at that end:
``O_V`` (``O_A``) at the pole, then ``b``, ``c``, ``e`` ... (Sec. 3.4's labels).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (velocity polygon, image labels),
Sec. 4.3 (acceleration polygon).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from graphkin.errors import InputError
from graphkin.files import check_file

if TYPE_CHECKING:
    from graphkin.kinematics.solution import Solution

__all__ = ["write_dxf", "read_dxf", "DrawingData", "INSUNITS", "nice_scale", "require_ezdxf"]

#: DXF ``$INSUNITS`` codes of the length units graphkin files use
INSUNITS = {"in": 1, "inch": 1, "ft": 2, "foot": 2, "mm": 4, "millimeter": 4, "cm": 5,
            "centimeter": 5, "m": 6, "meter": 6}
_UNIT_OF_CODE = {1: "in", 2: "ft", 4: "mm", 5: "cm", 6: "m"}

_POLE = {"velocity": "O_V", "acceleration": "O_A"}
_POLE_LABEL = {"velocity": "o_v", "acceleration": "o_a"}
_IMAGE = {"velocity": "v", "acceleration": "a"}
_RATE_UNIT = {"velocity": "{L}/s", "acceleration": "{L}/s^2"}
_LAYERS = {"LINKS": 7, "GIVEN": 5, "AUXILIARY": 8, "RESULT": 1, "LABELS": 3, "NOTES": 2}


def require_ezdxf() -> Any:
    """Import ezdxf, or raise an InputError saying how to install it."""
    try:
        import ezdxf
    except ImportError:
        raise InputError("DXF needs ezdxf, a dependency of graphkin: pip install ezdxf") \
            from None
    return ezdxf


@dataclass
class DrawingData:
    """What a drawing holds: straight segments, text labels and its units.

    Attributes
    ----------
    segments : list of ((x0, y0), (x1, y1))
    labels : list of (text, (x, y))
    strokes : list of list of (x, y)
        Polylines, paths and leaders as drawn (their collinear pieces are one
        segment of a polygon: a tapered arrowhead continues its shaft).
    unit : str or None
        The drawing's length unit, when it says.
    scale : str or None
        A scale stated in the drawing (``"1 in = 200 in/s"``).
    """

    segments: list[tuple[tuple[float, float], tuple[float, float]]] = field(default_factory=list)
    labels: list[tuple[str, tuple[float, float]]] = field(default_factory=list)
    strokes: list[list[tuple[float, float]]] = field(default_factory=list)
    unit: str | None = None
    scale: str | None = None


def nice_scale(x: float) -> float:
    """The round number (1, 2, 2.5 or 5 times a power of ten) at or above ``x``.

    Examples
    --------
    >>> nice_scale(37.7), nice_scale(200.0), nice_scale(0.0012)
    (50.0, 200.0, 0.002)
    """
    if not (x > 0 and math.isfinite(x)):
        return 1.0
    e = math.floor(math.log10(x))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        v = m * 10.0**e
        if v >= x * (1 - 1e-12):
            return float(f"{v:.12g}")
    return 10.0 ** (e + 1)  # pragma: no cover


def _xy(v: np.ndarray) -> tuple[float, float] | None:
    v = np.asarray(v, dtype=float)
    if v.ndim != 1:
        return None
    if v.shape[-1] == 3:
        if abs(float(v[2])) < 1e-12 or not np.all(np.isfinite(v)):
            return None
        return float(v[0] / v[2]), float(v[1] / v[2])
    if v.shape[-1] == 2 and np.all(np.isfinite(v)):
        return float(v[0]), float(v[1])
    return None


def write_dxf(solution: Solution, diagram: str, path: str | Path,
              upto: int | None = None) -> Path:
    """Write a construction of a solved mechanism to a DXF drawing.

    Parameters
    ----------
    solution : Solution
        From :func:`graphkin.solve` (by the constructions).
    diagram : {"posture", "velocity", "acceleration"}
    path : str or Path
    upto : int, optional
        Write steps ``0..upto`` only: a started drawing to hand out.

    Returns
    -------
    Path

    Raises
    ------
    InputError
        ezdxf is missing, the diagram does not exist, or the file cannot be written.

    Examples
    --------
    >>> import graphkin, tempfile, os
    >>> mech = graphkin.examples.fourbar()
    >>> out = os.path.join(tempfile.mkdtemp(), "v.dxf")
    >>> data = read_dxf(write_dxf(mech.solve(), "velocity", out))
    >>> sorted(t for t, _ in data.labels if len(t) < 4), data.scale
    (['O_V', 'b', 'c', 'e', 'f'], '1 in = 50 in/s')
    """
    ezdxf = require_ezdxf()
    from ezdxf.enums import TextEntityAlignment

    if diagram not in solution.constructions:
        raise InputError(f"no {diagram} construction; this solution has "
                         f"{', '.join(solution.constructions) or 'none'}")
    mech = solution.mechanism
    cx = solution.constructions[diagram]
    values = solution.values.get(diagram, {})
    steps = cx.steps if upto is None else cx.steps[: upto + 1]
    lu = mech.length_unit

    # scale: drawing units (the file's length unit) per unit of the quantity
    if diagram == "posture":
        k, note = 1.0, None
    else:
        pts = [_xy(values[o]) for s in cx.steps for o in s.outputs
               if s.kind == "point" and o in values]
        ext = max([float(np.hypot(*p)) for p in pts if p is not None] + [0.0])
        k = nice_scale(ext / float(mech.scale)) if ext > 0 else 1.0
        note = f"1 {lu} = {k:g} {_RATE_UNIT[diagram].format(L=lu)}"

    # no setup=True: its standard styles are created in an order that depends on Python's
    # hash seed, which made two runs differ; the drawing uses the default style only
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = INSUNITS.get(lu, 0)
    if note:
        doc.header.custom_vars.append("graphkin_scale", note)
    for layer_name, color in _LAYERS.items():
        doc.layers.add(layer_name, color=color)
    msp = doc.modelspace()
    size = 0.025 * float(mech.scale)

    def P(label: str) -> tuple[float, float] | None:
        if label not in values:
            return None
        p = _xy(values[label])
        return None if p is None else (p[0] / k, p[1] / k)

    def text(s: str, at: tuple[float, float], layer: str = "LABELS") -> None:
        t = msp.add_text(s, height=size, dxfattribs={"layer": layer})
        t.set_placement(at, align=TextEntityAlignment.BOTTOM_LEFT)

    # the points that every segment may end at: finite points made so far
    known = {o: P(o) for s in steps if s.kind == "point" for o in s.outputs if o in values}
    finite = [p for p in known.values() if p is not None]
    if finite:
        arr = np.array(finite)
        lo, hi = arr.min(axis=0), arr.max(axis=0)
        pad = 0.15 * max(float(np.max(hi - lo)), size * 10)
        lo, hi = lo - pad, hi + pad
    else:  # pragma: no cover - a construction always starts with a point
        lo, hi = np.array([-1.0, -1.0]), np.array([1.0, 1.0])

    role_layer = {"given": "GIVEN", "auxiliary": "AUXILIARY", "result": "RESULT"}
    if diagram == "posture":
        for lid, link in mech.links.items():
            names = [n for n in link.points if known.get(n) is not None]
            if lid == "1" or len(names) < 2:
                continue
            ring = list(zip(names, names[1:])) + ([(names[-1], names[0])] if len(names) > 2
                                                  else [])
            for a, b in ring:
                msp.add_line(known[a], known[b], dxfattribs={"layer": "LINKS"})
    for step in steps:
        layer = role_layer.get(str(step.role), "AUXILIARY")
        for o in step.outputs:
            if o not in values:
                continue
            if step.kind == "line":
                seg = _clip_line(np.asarray(values[o], dtype=float), lo, hi)
                if seg is not None:
                    msp.add_line(seg[0], seg[1], dxfattribs={"layer": layer})
            elif step.kind == "circle" and diagram == "posture":
                c = np.asarray(values[o], dtype=float)
                if np.all(np.isfinite(c)) and c[-1] > 0:
                    msp.add_circle((float(c[0]), float(c[1])), float(c[-1]),
                                   dxfattribs={"layer": layer})
            elif step.kind == "point":
                p = known.get(o)
                if p is None:
                    continue
                msp.add_point(p, dxfattribs={"layer": layer})
                if step.op in ("translate", "subtract", "add_along") and step.inputs:
                    q = known.get(step.inputs[0])
                    if q is not None and q != p:
                        msp.add_line(q, p, dxfattribs={"layer": "AUXILIARY"})
                name = _point_name(o, diagram, mech.point_names)
                if diagram == "posture":
                    if name:
                        text(name, p)
                elif o == _POLE_LABEL[diagram]:
                    text(_POLE[diagram], p)
                elif name:
                    pole = known.get(_POLE_LABEL[diagram])
                    if pole is not None and pole != p:
                        msp.add_line(pole, p, dxfattribs={"layer": layer})
                    text(name.lower(), p)
    if note:
        text(f"Scale: {note}", (float(lo[0]), float(lo[1]) - 3 * size), layer="NOTES")
    path = Path(path)
    # byte-identical output for the same input, like every other format: ezdxf's fixed
    # header dates ($TDCREATE, $TDUPDATE ...) and constant GUIDs instead of the clock's
    from ezdxf.document import CONST_MARKER_STRING, CREATED_BY_EZDXF

    doc.ezdxf_metadata()[CREATED_BY_EZDXF] = CONST_MARKER_STRING
    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    try:
        doc.saveas(path)
    except OSError as exc:
        raise InputError(f"cannot write the drawing: {exc.strerror or exc}",
                         file=str(path)) from None
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed
    return path


def _point_name(label: str, diagram: str, names: list[str]) -> str | None:
    """The mechanism point an output label stands for (``v(B)`` -> ``B``), if any."""
    if diagram == "posture":
        return label if label in names else None
    pre = _IMAGE[diagram] + "("
    if label.startswith(pre) and label.endswith(")"):
        inner = label[len(pre):-1]
        if inner in names:
            return inner
        # the point of link k at P (a slider's or a slot's coincident point, ``v(A@4)``):
        # labelled ``a4`` as docs/checking.md reads it, not left without a label
        point, at, link = inner.partition("@")
        if at and point in names and link and ":" not in link:
            return f"{point}{link}"
    return None


def _clip_line(line: np.ndarray, lo: np.ndarray, hi: np.ndarray
               ) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """The part of the line ``ax + by + c = 0`` inside the box [lo, hi]."""
    a, b, c = (float(x) for x in line[:3])
    n = math.hypot(a, b)
    if n == 0 or not math.isfinite(n):
        return None
    a, b, c = a / n, b / n, c / n
    # point on the line nearest the box centre, and the direction
    m = (lo + hi) / 2
    d = np.array([-b, a])
    p0 = m - (a * m[0] + b * m[1] + c) * np.array([a, b])
    ts = []
    for i in (0, 1):
        if abs(d[i]) > 1e-15:
            ts += [(lo[i] - p0[i]) / d[i], (hi[i] - p0[i]) / d[i]]
    ts.sort()
    if len(ts) < 2:
        return None
    inside = [t for t in ts if np.all(p0 + t * d >= lo - 1e-9) and np.all(p0 + t * d <= hi + 1e-9)]
    if len(inside) < 2:
        return None
    p, q = p0 + inside[0] * d, p0 + inside[-1] * d
    return (float(p[0]), float(p[1])), (float(q[0]), float(q[1]))


def read_dxf(path: str | Path) -> DrawingData:
    """Read the straight segments and text labels of a DXF drawing's model space.

    LINE, LWPOLYLINE, POLYLINE and LEADER give segments; TEXT, MTEXT (with its
    formatting codes and stacked sub- and superscripts read as plain letters:
    O with a subscript V is ``OV``) and block attributes give labels at their
    anchor point; blocks (INSERT) are read as the entities they place.  A
    header variable ``graphkin_scale`` or a text ``Scale: 1 in = 20 ft/s``
    gives the drawing's scale.

    Raises
    ------
    InputError
        ezdxf is missing, or the file is not a readable DXF (truncated,
        binary garbage, a coordinate that is not finite).
    """
    ezdxf = require_ezdxf()
    path = Path(path)
    check_file(path)  # a regular file of at most 20 MB
    try:
        doc = ezdxf.readfile(str(path))
    except OSError as exc:
        raise InputError(f"cannot read the drawing: {exc.strerror or exc}",
                         file=str(path)) from None
    except Exception as exc:  # ezdxf raises DXFError, struct.error, ValueError... on bad files
        raise InputError(f"not a readable DXF file: {type(exc).__name__}: {exc}"[:300],
                         file=str(path)) from None
    data = DrawingData()
    try:
        data.unit = _UNIT_OF_CODE.get(int(doc.header.get("$INSUNITS", 0) or 0))
        if doc.header.custom_vars.has_tag("graphkin_scale"):
            data.scale = doc.header.custom_vars.get("graphkin_scale")
        total = _expanded_count(doc)
        if total > MAX_ENTITIES:
            raise InputError(f"the drawing places more than {MAX_ENTITIES} entities through "
                             "its blocks (a polygon drawing has a few dozen)", file=str(path))
        count = [0]
        for e in doc.modelspace():
            _read_entity(e, data, 0, count)
    except InputError:
        raise
    except Exception as exc:  # malformed entities
        raise InputError(f"not a readable DXF file: {type(exc).__name__}: {exc}"[:300],
                         file=str(path)) from None
    for seg in data.segments:
        if not all(math.isfinite(c) for p in seg for c in p):
            raise InputError("not a readable DXF file: a coordinate is not finite",
                             file=str(path))
    return data


#: most entities read from one drawing (blocks included), and deepest block nesting
MAX_ENTITIES = 100_000
MAX_BLOCK_DEPTH = 16


def _expanded_count(doc: Any) -> int:
    """The entities the model space places, its blocks expanded, counted before reading.

    Each block's count is found once (memoized by block and depth), so a small
    file of nested blocks that expands to millions of entities is refused in
    time linear in its size (it ran half a minute before the limit was met).
    """
    memo: dict[tuple[str, int], int] = {}

    def count(entities: Any, depth: int) -> int:
        n = 0
        for e in entities:
            n += 1
            if e.dxftype() == "INSERT" and depth < MAX_BLOCK_DEPTH:
                name = str(e.dxf.name)
                key = (name, depth + 1)
                if key not in memo:
                    memo[key] = 0  # a block that inserts itself counts once per depth
                    block = doc.blocks.get(name)
                    memo[key] = count(block, depth + 1) if block is not None else 0
                n += memo[key]
            if n > MAX_ENTITIES:
                return n
        return n

    return count(doc.modelspace(), 0)


def _mtext_plain(raw: str) -> str:
    r"""MTEXT without its formatting codes; a stack (``\\S^V;``) becomes its plain letters."""
    import re

    from ezdxf.tools.text import plain_mtext

    raw = re.sub(r"\\S([^;]*);", lambda m: re.sub(r"[\^/#]", "", m.group(1)), raw)
    return str(plain_mtext(raw))


def _read_entity(e: Any, data: DrawingData, depth: int, count: list[int]) -> None:
    count[0] += 1
    if count[0] > MAX_ENTITIES:
        raise InputError(f"the drawing has more than {MAX_ENTITIES} entities (a polygon "
                         "drawing has a few dozen)")
    t = e.dxftype()
    if t == "LINE":
        s, f = e.dxf.start, e.dxf.end
        data.segments.append(((float(s.x), float(s.y)), (float(f.x), float(f.y))))
    elif t == "LWPOLYLINE":
        pts = [(float(p[0]), float(p[1])) for p in e.get_points("xy")]
        if e.closed and len(pts) > 2:
            pts.append(pts[0])
        data.strokes.append(pts)
    elif t == "POLYLINE":
        pts = [(float(v.dxf.location.x), float(v.dxf.location.y)) for v in e.vertices]
        if e.is_closed and len(pts) > 2:
            pts.append(pts[0])
        data.strokes.append(pts)
    elif t == "LEADER":
        data.strokes.append([(float(v[0]), float(v[1])) for v in e.vertices])
    elif t == "INSERT":
        if depth >= MAX_BLOCK_DEPTH:
            return
        for sub in e.virtual_entities():
            _read_entity(sub, data, depth + 1, count)
        for att in e.attribs:
            _label(att.dxf.text, att.dxf.insert, data)
    elif t in ("TEXT", "ATTRIB"):
        halign, valign = e.dxf.get("halign", 0), e.dxf.get("valign", 0)
        at = e.dxf.align_point if (halign or valign) and e.dxf.hasattr("align_point") \
            else e.dxf.insert
        _label(e.dxf.text, at, data)
    elif t == "MTEXT":
        _label(_mtext_plain(e.text), e.dxf.insert, data)


def _label(text: str, at: Any, data: DrawingData) -> None:
    s = str(text).strip()
    if s.lower().startswith("scale:"):
        data.scale = data.scale or s.split(":", 1)[1].strip()
    elif s:
        data.labels.append((s, (float(at.x), float(at.y))))
