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
scale, the scale (and the turn, when nothing on the sheet gives the
directions) is fitted robustly (:mod:`graphkin.check.fit`): the images that
agree on one scale fix it, and one or two wrong images are left out of the
fit, each with the reason in the report.  The mechanism drawn on the same
sheet (its joints labelled ``A``, ``B`` ...) gives the directions: the
polygon is then not turned to fit.  A label that stands nearer another line
end than its own is read at the end near it where the polygon puts its image
(within the marking tolerance).  Each image point is then read as a vector
from the pole and checked like a measured answer, within 2 % and 2° or within
0.5 mm on the sheet (``--drawing-tolerance``) when the drawing's paper unit is
known.

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
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.check.answers import (
    CheckTolerance,
    Given,
    Key,
    SheetScale,
    read_scale,
)
from graphkin.check.carry import own_follow_through
from graphkin.check.compare import direction_text, fmt, mm_text
from graphkin.check.diagnose import Diagnoser
from graphkin.check.exact import Evaluator
from graphkin.check.fit import Fit, fit_factor
from graphkin.check.polygon import Polygon, find_polygons, read_polygons
from graphkin.check.report import (
    FIT,
    Report,
    Row,
    check_given,
    follow_through,
    printable,
    sheet_allowance,
)
from graphkin.check.svg import _NUM, MAX_DEPTH, read_drawing, read_svg
from graphkin.errors import InputError
from graphkin.kinematics.solution import Solution

__all__ = ["read_drawing", "read_svg", "parse_scale", "check_drawing", "check_polygons", "Polygon",
           "read_polygons", "find_polygons", "MAX_DEPTH"]

_KIND = {"velocity": "velocity", "acceleration": "acceleration"}


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
        the scale (and the turn, unless the mechanism drawn on the sheet
        gives it) fitted robustly to the images that agree.
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
    polys = read_polygons(path)
    return check_polygons(sol, polys, path, scale=scale, tolerance=tolerance,
                          diagnoser=diagnoser)


def check_polygons(sol: Solution, polys: list[Polygon], source: str | Path, *,
                   scale: str | None = None, tolerance: CheckTolerance | None = None,
                   diagnoser: Diagnoser | None = None) -> Report:
    """Check polygons already read (a pole and labelled image points each) against the exact ones.

    The marking behind :func:`check_drawing`, for polygons read from anything
    (a CAD file, a scanned worksheet): each image point is a vector from the
    pole, the scale and turn are the stated ones or fitted robustly
    (:func:`graphkin.check.fit.fit_factor`), and each vector is checked like a
    measured answer, with the usual mistakes named and follow-through.

    Parameters
    ----------
    sol : Solution
    polys : list of Polygon
        ``Polygon(diagram, pole, points, scale=..., unit=..., turn=...)``:
        coordinates on paper (y up) in ``unit`` (``"mm"``, ``"in"``...; ``None``
        when unknown: then the drawing tolerance does not apply); ``turn`` the
        angle the sheet is drawn turned by, when the sheet gives it.
    source : str or Path
        The file named in the report and in errors.
    scale, tolerance, diagnoser
        As for :func:`check_drawing`.

    Returns
    -------
    Report

    Raises
    ------
    InputError
        No polygon, no image point named, no scale and no image point to fit.
    """
    path_s = str(source)
    tol = tolerance or CheckTolerance()
    if tol.drawing is None:
        tol = dataclasses.replace(tol, drawing=0.5)
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
    label_of: dict[str, str] = {}
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
        if name is not None and name not in drawn:
            drawn[name] = np.array(xy) - pole
            label_of[name] = lab
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
    mm_per_unit = _MM_PER.get(poly.unit or "")
    order = [n for n in mech.point_names if n in drawn] + [n for n in drawn if n in on_link]
    if stated:
        try:
            per, unit, factor = parse_scale(stated, kind, lu, poly.unit)
        except InputError as exc:
            if scale:  # --scale
                raise
            # the scale noted in the drawing: the drawing's file
            raise InputError(f"its noted scale: {exc.message}", file=path_s) from None
        how = f"scale {stated}, not turned"
        turn = complex(per, 0.0)
        if mm_per_unit is None:
            m = re.match(rf"\s*{_NUM}\s*([A-Za-z]+)", stated.split("=", 1)[0])
            if m and m.group(1) in ("mm", "cm", "in"):
                mm_per_unit = _MM_PER[m.group(1)]
        sheet_du = float(tol.drawing or 0.0) / mm_per_unit if mm_per_unit else 0.0
        notes += _rematch(poly, label_of, drawn, exact_of, turn, tol, sheet_du)
    else:
        names = [n for n in order if float(np.hypot(*exact_of(n))) > ev.floor(kind)
                 and float(np.hypot(*drawn[n])) > 0]
        if not names:
            raise InputError("give the drawing's scale (--scale \"1 in = 20 ft/s\") or label "
                             "image points away from the pole, to fit it", file=path_s)
        sheet_du = float(tol.drawing or 0.0) / mm_per_unit if mm_per_unit else 0.0
        given_turn, whose = (poly.turn, "the sheet") if poly.turn is not None else \
            _sheet_turn(poly, sol, notes)
        fixed = None if given_turn is None else complex(math.cos(given_turn),
                                                        -math.sin(given_turn))
        drive_links = {d.link for d in mech.drives} | ({mech.rates.link} if mech.rates else set())
        prefer = [n for n in names if (on_link[n][1] in drive_links if n in on_link else
                                       set(mech.point_links.get(n, ())) & drive_links)]

        name_of = {label_of[n]: n for n in names}
        inlier = _inlier(tol)

        def fit_now() -> Fit:
            # fitted by the labels as drawn, so that its reasons name them so
            f = fit_factor([label_of[n] for n in names], [complex(*drawn[n]) for n in names],
                           [complex(*np.asarray(exact_of(n), dtype=float)) for n in names],
                           relative=inlier, sheet=sheet_du, turn=fixed,
                           prefer=[label_of[n] for n in prefer])
            f.used = [name_of[t] for t in f.used]
            f.left_out = {name_of[t]: why for t, why in f.left_out.items()}
            return f

        fit = fit_now()
        moved = _rematch(poly, label_of, drawn, exact_of, fit.factor, tol, sheet_du)
        if moved:
            notes += moved
            fit = fit_now()
        turn = fit.factor
        if not (math.isfinite(abs(turn)) and abs(turn) > 0.0):
            raise InputError("the drawing's scale cannot be fitted: its sizes are out of range "
                             "(give --scale)", file=path_s)
        unit, factor = _default(kind, lu), 1.0
        # the drawing's own length when it gives one (an SVG sized in mm, a DXF's $INSUNITS)
        du = poly.unit if poly.unit in _MM_PER else "drawing unit"
        deg = math.degrees(math.atan2(turn.imag, turn.real))
        turned = direction_text(deg)          # in (-180, 180]: never "-180.00°"
        turned = turned if turned.startswith("-") else "+" + turned
        used = ", ".join(label_of[n] for n in fit.used)
        out = f" ({', '.join(label_of[n] for n in fit.left_out)} left out)" if fit.left_out \
            else ""
        if fixed is None:
            if len(fit.used) == 1:
                fitted = fit.used[0]
            how = (f"scale and turn fitted to {used}{out}: 1 {du} = {abs(turn):.4g} "
                   f"{unit}, turned {turned}")
            if abs(deg) > 150.0:
                notes.append("the polygon is turned about 180° to fit: nothing on the sheet "
                             "gives the directions (neither a scale nor the mechanism drawn "
                             "beside it), so a polygon drawn for the reversed sense of the "
                             "input's ω would fit as well; give --scale or draw the mechanism "
                             "on the sheet to have the sense checked")
        else:
            how = (f"scale fitted to {used}{out}: 1 {du} = {abs(turn):.4g} {unit}, "
                   + (f"turned {turned}" if abs(deg) >= 0.005 else "not turned")
                   + f": {whose} gives the directions")
        for n, why in fit.left_out.items():
            notes.append(f"{label_of[n]} left out of the fit: {why}")
        if not fit.agreed and len(names) > 1:
            one = fit.used[0]
            notes.append(f"no two image points agree on one scale: it was taken from "
                         f"{label_of[one]}" + (", the image of the input link"
                                               if one in prefer else ""))
        if fixed is not None and len(names) == 1:
            notes.append(f"{label_of[names[0]]} alone sets the scale: only its direction "
                         "is marked")
    if mm_per_unit is not None:
        per_mm = abs(turn) / mm_per_unit
        sheet = SheetScale(kind, per_mm, stated or f"1 mm = {per_mm:.4g} {unit}, fitted")
        tol = dataclasses.replace(tol, scales=(sheet,) + tuple(
            s for s in tol.scales if s.quantity != kind))
    rows: list[Row] = []
    givens: list[Given] = []
    letter = "V" if diagram == "velocity" else "A"
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
                row.error += f"; {mm_text(mm)} mm on the drawing"
            else:
                row.error += f"; {dist / factor:.3g} {unit} from exact"
        rows.append(row)
        givens.append(given)
    checked = [i for i, r in enumerate(rows) if r.verdict != FIT]
    sub = [rows[i] for i in checked]
    sub_given = [givens[i] for i in checked]
    follow_through(sub, sub_given, ev, diag, tol)
    own_follow_through(sub, sub_given, diag, tol, diagram,
                       [sheet_allowance(ev, gv, tol) for gv in sub_given])
    ignored = [t for t in ignored if len(re.sub(r"[^0-9A-Za-z]", "", t)) <= 3]  # not titles
    if ignored:
        notes.append("labels that name no image point, ignored: "
                     + ", ".join(printable(t) for t in sorted(set(ignored))))
    title = f"{diagram} polygon in {path_s} ({how})"
    return rows, title, notes, tol


_MM_PER = {"mm": 1.0, "cm": 10.0, "m": 1000.0, "in": 25.4, "ft": 304.8}


def _inlier(tol: CheckTolerance) -> float:
    """How near its exact place (a fraction of its size) an image is right by any rule.

    A circle of this radius lies within both 2 % of magnitude and 2° of
    direction: an image inside it agrees with the fit.
    """
    return min(tol.relative, math.sin(math.radians(min(tol.angle, 90.0))))


def _sheet_turn(poly: Polygon, sol: Solution, notes: list[str]) -> tuple[float | None, str]:
    """The turn of the sheet's directions, from the mechanism drawn beside the polygon.

    The joints labelled with the mechanism's point names (capitals: ``A``,
    ``B``, ``O2``; the images are small letters) are fitted by a similarity
    (scale, turn, shift) to the file's posture; when it fits them closely (1 %
    of their spread), its turn is the polygon's: a student draws both with
    the same axes.  ``None`` when no mechanism is drawn, or it does not fit
    (then a note says so).
    """
    mech = sol.mechanism
    upper = {n.upper(): n for n in mech.point_names if n not in mech.helper_points}
    seen: dict[str, complex] = {}
    for text, xy in poly.sheet_labels:
        if not text[:1].isupper() or re.search(r"['′’\"″]", text):
            continue
        name = _point_name(text, upper)
        if name is not None and name not in seen:
            seen[name] = complex(*xy)
    if len(seen) < 2:
        return None, ""
    w = np.array([complex(*np.asarray(sol.position(n), dtype=float)) for n in seen])
    d = np.array(list(seen.values()))
    wc, dc = w - w.mean(), d - d.mean()
    spread = float(np.sqrt(np.mean(np.abs(dc) ** 2)))
    den = float(np.sum(np.abs(wc) ** 2))
    if den <= (1e-9 * float(np.max(np.abs(w)))) ** 2 or spread == 0.0:
        return None, ""
    a = complex(np.sum(np.conj(wc) * dc) / den)
    miss = float(np.sqrt(np.mean(np.abs(dc - a * wc) ** 2)))
    if not miss <= 0.01 * spread:
        notes.append(f"the mechanism drawn on the sheet ({', '.join(seen)}, each read at the "
                     "line end nearest its label) does not match the file's posture, so it "
                     "does not give the polygon's directions: the turn was fitted")
        return None, ""
    return math.atan2(a.imag, a.real), f"the mechanism drawn on the sheet ({', '.join(seen)})"


def _rematch(poly: Polygon, label_of: dict[str, str], drawn: dict[str, np.ndarray],
             exact_of: Any, k: complex, tol: CheckTolerance, sheet_du: float) -> list[str]:
    """Read a label at another line end near it when its nearest is not where its image is.

    A label standing a little away from its vertex may stand nearer another
    line end (an arrowhead of the next vector); of the ends near it (the
    polygon's ``candidates``), the nearest one that lies within the marking
    tolerance of where the scale puts the image is the vertex it names.
    Changes ``drawn``; returns a note for each label read so.
    """
    notes: list[str] = []
    pole = np.array(poly.pole)
    size = max(float(np.hypot(*v)) for v in drawn.values())

    def taken(v: np.ndarray) -> bool:   # the pole, or a line end another label names
        return float(np.hypot(*v)) <= 1e-9 * size or any(
            float(np.hypot(*(v - w))) <= 1e-9 * size for w in drawn.values())

    for name, lab in label_of.items():
        e = complex(*np.asarray(exact_of(name), dtype=float))
        radius = max(_inlier(tol) * abs(e), sheet_du * abs(k))
        if abs(k * complex(*drawn[name]) - e) <= radius:
            continue
        for xy in poly.candidates.get(lab, ()):
            v = np.array(xy) - pole
            if taken(v) or abs(k * complex(*v) - e) > radius:
                continue
            notes.append(f"{lab} read at the line end where the polygon puts it (its label "
                         "stands nearer another line end)")
            drawn[name] = v
            break
    return notes
