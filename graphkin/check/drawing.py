"""Checking a velocity or acceleration polygon drawn in CAD (DXF or SVG).

The drawing holds lines and text labels: the pole ``O_V`` (or ``O_A``) and the
image points ``b``, ``c``, ``e`` ... (``b'`` is accepted for acceleration
images).  Each label is snapped to the nearest line end.  The drawing's scale
comes from ``--scale "1 in = 20 ft/s"`` or a ``Scale: ...`` note in the
drawing, its axes then being the mechanism's; otherwise scale *and*
orientation are fitted to the first known vector, the image of the input
crank's point (``V_B = ω2 × R_BA`` in Example 3.1), which is then right by
construction.  Every other image point is read as a vector from the pole and
checked like a measured answer: magnitude, direction, distance from the exact
image point, and the likely mistake.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon and its
labels: "the line to image point P from image point Q"), Sec. 4.3
(acceleration polygon).
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from graphkin.check.answers import CheckTolerance, Given, Key
from graphkin.check.compare import fmt
from graphkin.check.diagnose import Diagnoser
from graphkin.check.exact import Evaluator
from graphkin.check.report import FIT, Report, Row, check_given
from graphkin.errors import InputError
from graphkin.io.dxf import DrawingData
from graphkin.kinematics.solution import Solution
from graphkin.units import parse_quantity, registry

__all__ = ["read_drawing", "read_svg", "parse_scale", "check_drawing"]

_KIND = {"velocity": "velocity", "acceleration": "acceleration"}
_POLES = {"ov": "velocity", "oa": "acceleration"}


def read_drawing(path: str | Path) -> DrawingData:
    """Lines and labels of a ``.dxf`` or ``.svg`` drawing."""
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".dxf":
        from graphkin.io.dxf import read_dxf

        return read_dxf(path)
    if suffix == ".svg":
        return read_svg(path)
    raise InputError("a drawing is a .dxf or .svg file", file=str(path))


# ---- SVG ----------------------------------------------------------------------

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"


def _floats(text: str | None) -> list[float]:
    return [float(x) for x in re.findall(_NUM, text or "")]


def _transform(text: str | None) -> np.ndarray:
    """The 3×3 matrix of an SVG ``transform`` attribute."""
    m = np.eye(3)
    for name, args in re.findall(r"(\w+)\s*\(([^)]*)\)", text or ""):
        a = _floats(args)
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


def read_svg(path: str | Path) -> DrawingData:
    """Read lines, polylines, paths and texts of an SVG drawing.

    The y axis is turned up (SVG's points down); a root ``width`` in mm, cm or
    in with a ``viewBox`` gives the drawing's unit, else coordinates are in
    the unit of the stated scale.

    Raises
    ------
    InputError
        The file cannot be read or is not SVG.
    """
    path = Path(path)
    try:
        root = ET.parse(path).getroot()
    except OSError as exc:
        raise InputError(f"cannot read the drawing: {exc.strerror or exc}",
                         file=str(path)) from None
    except ET.ParseError as exc:
        raise InputError(f"not a readable SVG file: {exc}", file=str(path)) from None
    data = DrawingData()
    unit_scale = 1.0
    m = re.fullmatch(rf"\s*({_NUM})\s*(mm|cm|in)\s*", root.get("width", ""))
    vb = _floats(root.get("viewBox"))
    if m and len(vb) == 4 and vb[2] > 0:
        unit_scale = float(m.group(1)) / vb[2]
        data.unit = m.group(2)

    def local(tag: str) -> str:
        return tag.rsplit("}", 1)[-1]

    def put(mat: np.ndarray, x: float, y: float) -> tuple[float, float]:
        p = mat @ np.array([x, y, 1.0])
        return float(p[0] * unit_scale), float(-p[1] * unit_scale)

    def walk(el: ET.Element, mat: np.ndarray) -> None:
        mat = mat @ _transform(el.get("transform"))
        tag = local(el.tag)
        if tag == "line":
            a = [float(el.get(k, "0") or 0) for k in ("x1", "y1", "x2", "y2")]
            data.segments.append((put(mat, a[0], a[1]), put(mat, a[2], a[3])))
        elif tag in ("polyline", "polygon"):
            v = _floats(el.get("points"))
            pts = [put(mat, v[i], v[i + 1]) for i in range(0, len(v) - 1, 2)]
            if tag == "polygon" and len(pts) > 2:
                pts.append(pts[0])
            data.segments += list(zip(pts, pts[1:]))
        elif tag == "path":
            for sub in _path_points(el.get("d", "")):
                pts = [put(mat, x, y) for x, y in sub]
                data.segments += [(p, q) for p, q in zip(pts, pts[1:]) if p != q]
        elif tag == "text":
            text = "".join(el.itertext()).strip()
            xs, ys = _floats(el.get("x")), _floats(el.get("y"))
            if not xs:
                for child in el:
                    if local(child.tag) == "tspan" and child.get("x") is not None:
                        xs, ys = _floats(child.get("x")), _floats(child.get("y"))
                        break
            at = put(mat, xs[0] if xs else 0.0, ys[0] if ys else 0.0)
            if text.lower().startswith("scale:"):
                data.scale = text.split(":", 1)[1].strip()
            elif text:
                data.labels.append((text, at))
            return
        for child in el:
            walk(child, mat)

    walk(root, np.eye(3))
    return data


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
    if "=" not in text:
        raise InputError(f"a scale reads like \"1 in = 20 ft/s\", not {text!r}", key="--scale")
    left, right = (s.strip() for s in text.split("=", 1))
    ureg = registry()
    try:
        ql = ureg.Quantity(left)
        if not hasattr(ql, "dimensionality") or ql.dimensionless:
            raise ValueError
        du = drawing_unit or str(ql.units)
        paper = float(ql.to(du).magnitude)
    except Exception:  # pint raises several unrelated types
        raise InputError(f"the left side of the scale, {left!r}, is not a length on paper",
                         key="--scale") from None
    try:
        value, _ = parse_quantity(right, kind, length_unit)
    except ValueError as exc:
        raise InputError(str(exc), key="--scale") from None
    if not (paper > 0 and value > 0):
        raise InputError("both sides of the scale must be positive", key="--scale")
    m = re.match(rf"\s*{_NUM}\s*(.*)$", right)
    unit = m.group(1).strip() if m and m.group(1).strip() else ""
    factor = parse_quantity(f"1 {unit}", kind, length_unit)[0] if unit else 1.0
    return value / paper, unit or _default(kind, length_unit), factor


def _default(kind: str, lu: str) -> str:
    return f"{lu}/s" if kind == "velocity" else f"{lu}/s^2"


# ---- the check ------------------------------------------------------------------

def _snap(data: DrawingData, path: str) -> dict[str, tuple[float, float]]:
    """Each label snapped to the nearest end of a line (shapely)."""
    import shapely

    ends = sorted({p for seg in data.segments for p in seg})
    if not ends:
        raise InputError("the drawing has no lines", file=path)
    pts = shapely.points(np.array(ends))
    tree = shapely.STRtree(pts)
    out: dict[str, tuple[float, float]] = {}
    for text, at in data.labels:
        i = int(tree.nearest(shapely.Point(at)))
        out.setdefault(text, ends[i])
    return out


def _pole_kind(label: str) -> str | None:
    return _POLES.get(re.sub(r"[\s_]", "", label).lower())


def check_drawing(sol: Solution, path: str | Path, *, scale: str | None = None,
                  tolerance: CheckTolerance | None = None) -> Report:
    """Check a drawn velocity or acceleration polygon against the exact one.

    Parameters
    ----------
    sol : Solution
    path : str or Path
        ``.dxf`` (needs ezdxf) or ``.svg``.
    scale : str, optional
        ``"1 in = 20 ft/s"``; default: the drawing's own ``Scale:`` note,
        else fitted to the input crank's image.
    tolerance : CheckTolerance, optional

    Returns
    -------
    Report
        One row per labelled image point.

    Raises
    ------
    InputError
        Unreadable drawing, no pole label, no scale and no crank image to fit.
    """
    import shapely

    path_s = str(path)
    tol = tolerance or CheckTolerance()
    data = read_drawing(path)
    at = _snap(data, path_s)
    poles: dict[str, str] = {}
    for lab in at:
        pk = _pole_kind(lab)
        if pk:
            poles[lab] = pk
    kinds = set(poles.values())
    if len(kinds) != 1:
        raise InputError("label the pole of the polygon O_V (velocity) or O_A (acceleration), "
                         "and draw one polygon per drawing", file=path_s)
    diagram = kinds.pop()
    kind = _KIND[diagram]
    pole = np.array(at[next(iter(poles))])
    mech = sol.mechanism
    if not sol.has_rates or (diagram == "acceleration" and not sol.has_accelerations):
        raise InputError(f"the mechanism file gives no rates, so its {diagram} polygon cannot "
                         "be checked", file=path_s)
    upper = {n.upper(): n for n in mech.point_names}
    drawn: dict[str, np.ndarray] = {}
    ignored = []
    for lab, xy in at.items():
        if lab in poles:
            continue
        name = upper.get(lab.strip().rstrip("'′").upper())
        if name is None:
            ignored.append(lab)
        else:
            drawn[name] = np.array(xy) - pole
    if not drawn:
        raise InputError("no image points labelled with the mechanism's point names "
                         f"({', '.join(n.lower() for n in mech.point_names)})", file=path_s)
    ev = Evaluator(sol)
    exact_of = sol.velocity if diagram == "velocity" else sol.acceleration
    stated = scale or data.scale
    lu = mech.length_unit
    fitted: str | None = None
    if stated:
        per, unit, factor = parse_scale(stated, kind, lu, data.unit)
        how = f"scale {stated}"
        turn = complex(per, 0.0)
    else:
        first = _first_known(sol, diagram, drawn)
        if first is None:
            raise InputError("give the drawing's scale (--scale \"1 in = 20 ft/s\") or label "
                             "the image of the input crank's point, to fit it", file=path_s)
        e = exact_of(first)
        z_ex, z_dr = complex(*e), complex(*drawn[first])
        if abs(z_dr) == 0 or abs(z_ex) == 0:
            raise InputError(f"the image of {first} is at the pole; give --scale", file=path_s)
        turn = z_ex / z_dr
        unit, factor = _default(kind, lu), 1.0
        fitted = first
        how = (f"fitted to {first.lower()}: 1 drawing unit = {abs(turn):.4g} {unit}, "
               f"turned {math.degrees(math.atan2(turn.imag, turn.real)):+.2f}°")
    rows: list[Row] = []
    diag = Diagnoser(ev)
    letter = "V" if diagram == "velocity" else "A"
    for name in mech.point_names:
        if name not in drawn:
            continue
        z = complex(*drawn[name]) * turn
        vec = np.array([z.real, z.imag])
        key = Key(f"{letter}_{name}", letter, (name,))
        mag = float(np.hypot(*vec))
        direction = math.degrees(math.atan2(vec[1], vec[0])) if mag > 0 else None
        raw = f"{fmt(mag / factor)} {unit}" + (f" at {direction:.2f}°" if direction is not None
                                                 else "")
        given = Given(key, raw, value=mag, direction=direction, unit=unit, factor=factor,
                      vector=vec)
        exact = np.asarray(exact_of(name), dtype=float)
        dist = float(shapely.Point(vec).distance(shapely.Point(exact)))
        if name == fitted:
            row = Row(key.text, raw, raw, "—", FIT,
                      note="used to fit the drawing's scale and orientation")
        else:
            row = check_given(ev, diag, given, tol)
            row.error += f"; {dist / factor:.3g} {unit} from exact"
        rows.append(row)
    rep = Report(rows, tol, path_s, title=f"{diagram} polygon in {path_s} ({how})")
    if ignored:
        rep.notes.append(f"labels that name no point, ignored: {', '.join(sorted(ignored))}")
    return rep


def _first_known(sol: Solution, diagram: str, drawn: dict[str, np.ndarray]) -> str | None:
    """The first image point the construction finds from the given data (the crank's)."""
    cx = sol.constructions.get(diagram)
    pre = "v(" if diagram == "velocity" else "a("
    if cx is not None:
        for step in cx.steps:
            for o in step.outputs:
                if o.startswith(pre) and o.endswith(")"):
                    name = o[2:-1]
                    if name in sol.mechanism.point_names:
                        return name if name in drawn else None
    for d in sol.mechanism.drives:
        for name in sol.mechanism.links[d.link].points:
            if name in drawn and np.hypot(*sol.velocity(name)) > 0:
                return name
    return None
