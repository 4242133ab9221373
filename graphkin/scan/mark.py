"""Marking the image points read off a worksheet, as ``check --drawing`` marks a drawing.

The points read (:func:`graphkin.scan.read.read_sheet`), in mm on the
sheet, with the printed scale and pole, are marked by
:func:`graphkin.check.drawing.check_polygons` (not turned, within the
drawing tolerance in mm on the sheet, follow-through included).  What a
reading cannot tell apart is then said, not named: a wrong image read
within 2 mm of a place two mistakes share, or where the two readings of
its ink disagree (:func:`_untold`); a polygon read turned as a whole is
marked ``sense`` row by row (:func:`_turned_row`).  :func:`debug_image`
draws what was read, for ``check --scan --show``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (image points measured from the
pole to the scale; the polygon for the reversed sense turned 180°).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from graphkin.check.answers import CheckTolerance
from graphkin.check.compare import fmt
from graphkin.check.diagnose import Diagnoser, Mistake
from graphkin.check.drawing import check_polygons
from graphkin.check.polygon import Polygon
from graphkin.check.report import FOLLOWS, WRONG, Report, Row
from graphkin.scan import need_cv2
from graphkin.scan.read import _SHORT_MM, _UNTOLD_MM, NOT_FOUND, SheetRead, _names, too_short
from graphkin.scan.sheet import PX_PER_MM

__all__ = ["mark_scan", "debug_image"]


def mark_scan(sol: Any, read: SheetRead, name: str, tol: CheckTolerance,
              diag: Diagnoser) -> Report:
    """The report of one page: each image point read, marked as ``check --drawing`` marks it."""
    layout = read.layout
    letter = "V" if layout.diagram == "velocity" else "A"
    poly = Polygon(layout.diagram, tuple(layout.pole),
                   {n.lower(): (float(p[0]), float(p[1])) for n, p in read.points.items()},
                   scale=layout.scale_text, unit="mm")
    if tol.drawing is None:
        tol = dataclasses.replace(tol, drawing=0.5)
    if read.points:
        marked = check_polygons(sol, [poly], name, tolerance=tol, diagnoser=diag)
        rows, title, notes, used = marked.rows, marked.title, marked.notes, marked.tolerance
    else:
        rows, title, notes, used = [], f"{layout.diagram} polygon in {name}", [], tol
    rows, untold = _untold(read, rows, float(used.drawing or 0.0))
    notes += untold
    f = sol.velocity if layout.diagram == "velocity" else sol.acceleration
    for n in read.missing:
        v = np.asarray(f(n), dtype=float)
        rows.append(Row(f"{letter}_{n}", "—", f"{fmt(float(np.hypot(*v)))}", "not found",
                        WRONG, mistake=NOT_FOUND))
    order = {n: i for i, n in enumerate(_names(sol))}
    rows.sort(key=lambda r: order.get(r.key.split("_", 1)[-1], len(order)))
    rep = Report(rows, used, name, title=title.replace("(scale", "(read from the photo; scale"))
    rep.notes += notes + read.notes
    if read.is_turned:
        rep.notes.append("read as a polygon drawn turned 180° about the pole (the input's "
                         "angular velocity taken with the wrong sense): each image was looked "
                         "for at its reversed place first")
    for n in too_short(sol, layout):
        rep.notes.append(f"{letter}_{n} is under {_SHORT_MM:g} mm on the sheet: too short to "
                         "read from a photo, not marked")
    if read.rect.upto is None:
        rep.notes.append("the marker that says how many construction steps were printed was "
                         "not found: read as if none were")
    return rep


def _untold(read: SheetRead, rows: list[Row], drawing_mm: float = 0.0
            ) -> tuple[list[Row], list[str]]:
    """Wrong rows read within 2 mm of the right place: still wrong, but no mistake named.

    Its counterpart for the polygon turned 180° (the reversed sense): a wrong
    row read within 2 mm of its reversed place names no mistake but
    ``sense`` (another one there, such as ``normal-reversed+sense``, cannot
    be told from the reversed sense misread); in a polygon read turned as
    a whole, within ``drawing_mm`` of it, ``sense`` itself (:func:`_turned_row`).

    Where the two readings of an image disagree by more than 2 mm (the pencil
    segments' ends and the lines fitted to its ink, ``read.moved``), a wrong
    row names no mistake but ``sense`` either: either reading may be the
    misread one.

    And a row that follows from the student's own earlier images
    (:mod:`graphkin.check.carry`) from one read within 2 mm of its right
    place: wrong, not following (that one may only be misread).
    """
    out, notes = [], []
    for r in rows:
        name = r.key.split("_", 1)[-1]
        p, at, back = read.points.get(name), read.places.get(name), read.turned.get(name)
        turned = _turned_row(read, r, drawing_mm)
        if turned is not None:
            r, note = turned
            notes.append(note)
        elif (r.verdict == WRONG and r.mistake is not None and p is not None and at
                and float(np.hypot(*(p - at[0]))) < _UNTOLD_MM):
            notes.append(f"{r.key} is read {float(np.hypot(*(p - at[0]))):.1f} mm from its "
                         f"right place, where {r.mistake.code} also puts it: a misread "
                         "cannot be told from that mistake, so none is named")
            r = dataclasses.replace(r, mistake=None)
        elif (r.verdict == WRONG and r.mistake is not None and r.mistake.code != "sense"
              and p is not None and back and float(np.hypot(*(p - back[0]))) < _UNTOLD_MM):
            notes.append(f"{r.key} is read {float(np.hypot(*(p - back[0]))):.1f} mm from its "
                         f"place with the sense reversed, where {r.mistake.code} also puts "
                         "it: a misread cannot be told from that mistake, so none is named")
            r = dataclasses.replace(r, mistake=None)
        elif (r.verdict == WRONG and r.mistake is not None and r.mistake.code != "sense"
              and read.moved.get(name, 0.0) > _UNTOLD_MM):
            notes.append(f"{r.key}: the pencil segments' ends and the lines fitted to its ink "
                         f"put it {read.moved[name]:.1f} mm apart, where {r.mistake.code} "
                         "puts it: a misread cannot be told from that mistake, so none is "
                         "named")
            r = dataclasses.replace(r, mistake=None)
        elif (r.verdict == FOLLOWS and r.mistake is not None and r.mistake.kind == "carried"
              and _near_right(read, r.follows.split("_", 1)[-1])):
            notes.append(f"{r.key} is where drawing it from {r.follows} as read puts it, but "
                         f"{r.follows} is read within {_UNTOLD_MM:g} mm of its right place: a "
                         "misread cannot be told from a mistake there, so it is not marked as "
                         "following")
            r = dataclasses.replace(r, verdict=WRONG, mistake=None, follows="")
        out.append(r)
    return out, notes


def _turned_row(read: SheetRead, r: Row, drawing_mm: float) -> tuple[Row, str] | None:
    """Row ``r`` marked ``sense`` (and a note) when its image is where the turned polygon puts it.

    In a polygon read turned 180° (``read.is_turned``, Sec. 3.4), a row wrong
    with another mistake or none, or following by one carried through the
    whole polygon, read within ``drawing_mm`` of its reversed place (the
    crossed four-bar, Sec. 2.9, may put two images of a four-bar's
    acceleration polygon within the check's tolerance of theirs at once).
    """
    name = r.key.split("_", 1)[-1]
    p, back = read.points.get(name), read.turned.get(name)
    if (not read.is_turned or p is None or not back or r.verdict not in (WRONG, FOLLOWS)
            or (r.mistake is not None and r.mistake.code == "sense")
            or (r.verdict == FOLLOWS and (r.mistake is None or r.mistake.kind == "carried"))):
        return None
    if (off := float(np.hypot(*(p - back[0])))) > drawing_mm:
        return None
    text = f"sense reversed: {r.key} drawn the wrong way round (180° out), with the whole polygon"
    note = (f"{r.key} is read {off:.1f} mm from its place with the sense reversed, in a "
            f"polygon read turned as a whole: marked as the reversed sense, not {r.code}")
    return dataclasses.replace(r, verdict=WRONG, follows="",
                               mistake=Mistake("sense", text, "sense")), note


def _near_right(read: SheetRead, name: str) -> bool:
    """Whether image ``name`` is read within 2 mm of its right place (a misread, perhaps)."""
    p, at = read.points.get(name), read.places.get(name)
    return p is not None and at is not None and bool(at) and float(
        np.hypot(*(p - at[0]))) < _UNTOLD_MM


def debug_image(read: SheetRead) -> np.ndarray:
    """The rectified sheet with the segments (blue), places (grey) and images read (green).

    The places drawn are those of the reading taken: the polygon's, or the
    polygon's turned 180° when it was read turned (``read.is_turned``).
    """
    cv2 = need_cv2()
    img = cv2.cvtColor(read.rect.gray, cv2.COLOR_GRAY2BGR)
    h = read.layout.size[1]

    def px(p: np.ndarray) -> tuple[int, int]:
        return (int(round(p[0] * PX_PER_MM)), int(round((h - p[1]) * PX_PER_MM)))

    x0, y0, x1, y1 = read.layout.polygon_box
    cv2.rectangle(img, px(np.array([x0, y1])), px(np.array([x1, y0])), (200, 200, 0), 1)
    for s in read.segments:
        cv2.line(img, px(s[0]), px(s[1]), (255, 80, 0), 2)
    searched = read.turned if read.is_turned else read.places   # the reading taken
    for name, at in searched.items():
        for c in at + read.carried.get(name, []):
            q = px(c)
            cv2.drawMarker(img, q, (150, 150, 150), cv2.MARKER_CROSS, 8, 1)
        if name in read.points:
            q = px(read.points[name])
            cv2.circle(img, q, 9, (0, 170, 0), 2)
            cv2.putText(img, name.lower(), (q[0] + 10, q[1] - 8), cv2.FONT_HERSHEY_SIMPLEX,
                        0.7, (0, 140, 0), 2)
        else:
            q = px(at[0])
            cv2.drawMarker(img, q, (0, 0, 220), cv2.MARKER_TILTED_CROSS, 14, 2)
            cv2.putText(img, name.lower() + "?", (q[0] + 10, q[1] - 8),
                        cv2.FONT_HERSHEY_SIMPLEX, 0.7, (0, 0, 220), 2)
    return np.asarray(img)
