"""Reading the student's image points off a rectified worksheet, and marking them.

Each image point of the polygon can only be in a few places: where it truly
is, or where one of the usual mistakes puts it (the polygon turned 180° for
a reversed sense, and each single mistake of
:meth:`graphkin.check.diagnose.Diagnoser.candidates`: an image flipped over,
a relative velocity drawn from the pole, a normal component drawn outward,
the Coriolis component's mistakes, the other branch, the whole polygon redrawn
from a slip in the input's rate ...).  The student's image point is taken as the end of the pencil
segments nearest one of those places (within 4 mm, or 12 % of the vector's
length on the sheet if that is more), two names never sharing one vertex;
where two or more segments end there, where their lines meet.  The points,
in mm on the sheet, with the printed scale and pole, are then marked as
``check --drawing`` marks a drawing with a stated scale (not turned, within
the drawing tolerance in mm on the sheet).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (image points measured from the
pole to the scale), Sec. 3.5 (images flipped over), Secs. 4.3-4.5 (normal and
Coriolis components).
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.check.answers import CheckTolerance, Given, Key
from graphkin.check.compare import fmt
from graphkin.check.diagnose import Diagnoser, Mistake
from graphkin.check.polygon import Polygon
from graphkin.check.report import WRONG, Report, Row
from graphkin.errors import GraphkinError, InputError
from graphkin.scan import need_cv2
from graphkin.scan.sheet import PX_PER_MM, Page, Rectified, rectify, template_ink
from graphkin.scan.strokes import ends, pencil, segments, vertex_at

__all__ = ["SheetRead", "read_sheet", "mark_scan", "places", "NOT_FOUND"]

NOT_FOUND = Mistake("missing", "no pencil line ends near where this image point can be: "
                               "not drawn, or too faint to read", "not-found")
_NEAR_MM = 4.0
_NEAR_FRACTION = 0.12
_POLE_MM = 2.5
_SHORT_MM = 7.0
"""A vector shorter than this on the sheet is not read: the printed pole hides its
first 1.1 mm and a stroke under 5 mm cannot be told from an arrowhead or a letter."""
_SAME_MM = 2.5
_UNTOLD_MM = 2.0
"""A usual mistake is not named for an image read this close to its right place: the
reading is off by up to about 2 mm (docs/checking.md), so a mistake that moves the
image less than that cannot be told from a misread."""
_CLEAR_MM = 6.0
_ALTERNATIVE_MM = 1.5
"""A mistaken place counts as this much farther than it is (the exact one wins a tie)."""


@dataclass
class SheetRead:
    """What was read from one page.

    Attributes
    ----------
    rect : Rectified
    layout : Layout
    segments : ndarray (n, 2, 2)
        Pencil segments, sheet mm.
    points : dict
        Name -> the image point read (sheet mm).
    places : dict
        Name -> the places it can be (sheet mm; the exact one first).
    missing : list of str
    """

    rect: Rectified
    layout: Any
    segments: np.ndarray
    points: dict[str, np.ndarray] = field(default_factory=dict)
    places: dict[str, list[np.ndarray]] = field(default_factory=dict)
    missing: list[str] = field(default_factory=list)


def _names(sol: Any) -> list[str]:
    mech = sol.mechanism
    return [n for n in mech.point_names if n not in mech.helper_points]


def places(sol: Any, layout: Any, diag: Diagnoser) -> dict[str, list[np.ndarray]]:
    """Where each image point can be on the sheet (mm): exact, reversed, each variant.

    Image points less than 7 mm from the pole are left out: at the pole
    (fixed points) nothing can be drawn, and a shorter vector cannot be read
    (see :func:`too_short`).  A mistaken place is kept only
    inside the polygon area, clear of the pole (where every vector starts)
    and of every other image's exact place (a right neighbour is not read
    as this image's mistake).
    """
    letter = "V" if layout.diagram == "velocity" else "A"
    pole = np.array(layout.pole)
    x0, y0, x1, y1 = layout.polygon_box
    f = sol.velocity if layout.diagram == "velocity" else sol.acceleration
    exact: dict[str, np.ndarray] = {}
    for name in _names(sol):
        v = np.asarray(f(name), dtype=float) / layout.per_mm
        if float(np.hypot(*v)) >= _SHORT_MM:
            exact[name] = pole + v
    out: dict[str, list[np.ndarray]] = {}
    for name, e in exact.items():
        at = [e, 2 * pole - e]
        key = Key(f"{letter}_{name}", letter, (name,))
        vec = (e - pole) * layout.per_mm
        given = Given(key, "", value=float(np.hypot(*vec)),
                      direction=math.degrees(math.atan2(vec[1], vec[0])), vector=vec)
        try:
            exact_value = diag.ev.value(key)
            found = [c for m, c in diag.candidates(given, exact_value) if m.kind != "combined"]
        except GraphkinError:
            found = []
        for c in found:
            xy = c.xy
            if xy is not None and not c.ideal and np.all(np.isfinite(xy)):
                at.append(pole + np.asarray(xy, dtype=float) / layout.per_mm)
        keep = [e]
        for c in at[1:]:
            if not (x0 < c[0] < x1 and y0 < c[1] < y1):
                continue
            if float(np.hypot(*(c - pole))) < _CLEAR_MM:
                continue
            if any(float(np.hypot(*(c - q))) < _CLEAR_MM for q in exact.values()):
                continue
            if any(float(np.hypot(*(c - q))) < 0.3 for q in keep):
                continue
            keep.append(c)
        out[name] = keep
    return out


def too_short(sol: Any, layout: Any) -> list[str]:
    """The images away from the pole whose vectors are too short to read (not marked)."""
    f = sol.velocity if layout.diagram == "velocity" else sol.acceleration
    return [n for n in _names(sol)
            if _POLE_MM <= float(np.hypot(*np.asarray(f(n), dtype=float))) / layout.per_mm
            < _SHORT_MM]


def read_sheet(sol: Any, page: Page, diag: Diagnoser, digest: str, title: str = "",
               upto: int | None = None) -> SheetRead:
    """Rectify one page, find its pencil segments and the image points they end at."""
    from graphkin.render.worksheet_layout import worksheet_layout

    if page.identity is not None and page.identity.get("digest") != digest:
        raise InputError(f"this worksheet was printed for another mechanism file (its hash "
                         f"{page.identity.get('digest')}, this file's {digest})",
                         file=page.name, key="--scan")
    rect = rectify(page)
    layout = worksheet_layout(sol, rect.diagram, rect.paper, digest,
                              rect.upto if rect.upto is not None else upto)
    ink = template_ink(sol, layout, title)
    w, h = layout.size
    x0, y0, x1, y1 = layout.polygon_box
    box = (int(x0 * PX_PER_MM), int((h - y1) * PX_PER_MM), int(np.ceil(x1 * PX_PER_MM)),
           int(np.ceil((h - y0) * PX_PER_MM)))
    ratio = pencil(rect.gray, ink, box)
    segs = segments(ratio, (box[0], box[1]), h)
    read = SheetRead(rect, layout, segs, places=places(sol, layout, diag))
    _match(read)
    return read


def _match(read: SheetRead) -> None:
    """Name the vertices: nearest place first, one vertex per name (see the module)."""
    segs = read.segments
    pole = np.array(read.layout.pole)
    pts, seg_of = ends(segs)
    away = np.hypot(*(pts - pole).T) > _POLE_MM if len(pts) else np.zeros(0, bool)
    pairs: list[tuple[float, str, int]] = []
    for name, at in read.places.items():
        reach = max(_NEAR_MM, _NEAR_FRACTION * float(np.hypot(*(at[0] - pole))))
        for jj in np.flatnonzero(away).tolist():
            d = min(float(np.hypot(*(pts[jj] - c))) + (_ALTERNATIVE_MM if i else 0.0)
                    for i, c in enumerate(at))
            if d <= reach:
                pairs.append((d, name, int(jj)))
    pairs.sort()
    taken: list[tuple[np.ndarray, str]] = []
    for _d, name, j in pairs:
        if name in read.points:
            continue
        p = pts[j]
        if any(float(np.hypot(*(p - q))) < _SAME_MM and not _same_image(read, name, other)
               for q, other in taken):
            continue
        near = [int(seg_of[k]) for k in np.flatnonzero(np.hypot(*(pts - p).T) < _SAME_MM)]
        read.points[name] = vertex_at(segs, sorted(set(near)), p, pole)
        taken.append((p, name))
    read.missing = [n for n in read.places if n not in read.points]


def _same_image(read: SheetRead, a: str, b: str) -> bool:
    """Two names whose exact images coincide on the sheet may share a vertex."""
    return float(np.hypot(*(read.places[a][0] - read.places[b][0]))) < _SAME_MM


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
        rows, title, notes, used = _check_polygon(sol, poly, name, tol, diag)
    else:
        rows, title, notes, used = [], f"{layout.diagram} polygon in {name}", [], tol
    rows, untold = _untold(read, rows)
    notes += untold
    f = sol.velocity if layout.diagram == "velocity" else sol.acceleration
    for n in read.missing:
        v = np.asarray(f(n), dtype=float)
        rows.append(Row(f"{letter}_{n}", "—", f"{fmt(float(np.hypot(*v)))}", "not found",
                        WRONG, mistake=NOT_FOUND))
    order = {n: i for i, n in enumerate(_names(sol))}
    rows.sort(key=lambda r: order.get(r.key.split("_", 1)[-1], len(order)))
    rep = Report(rows, used, name, title=title.replace("(scale", "(read from the photo; scale"))
    rep.notes += notes
    for n in too_short(sol, layout):
        rep.notes.append(f"{letter}_{n} is under {_SHORT_MM:g} mm on the sheet: too short to "
                         "read from a photo, not marked")
    if read.rect.upto is None:
        rep.notes.append("the marker that says how many construction steps were printed was "
                         "not found: read as if none were")
    return rep


def _untold(read: SheetRead, rows: list[Row]) -> tuple[list[Row], list[str]]:
    """Wrong rows read within 2 mm of the right place: still wrong, but no mistake named."""
    out, notes = [], []
    for r in rows:
        name = r.key.split("_", 1)[-1]
        p, at = read.points.get(name), read.places.get(name)
        if (r.verdict == WRONG and r.mistake is not None and p is not None and at
                and float(np.hypot(*(p - at[0]))) < _UNTOLD_MM):
            notes.append(f"{r.key} is read {float(np.hypot(*(p - at[0]))):.1f} mm from its "
                         f"right place, where {r.mistake.code} also puts it: a misread "
                         "cannot be told from that mistake, so none is named")
            r = dataclasses.replace(r, mistake=None)
        out.append(r)
    return out, notes


def _check_polygon(sol: Any, poly: Polygon, name: str, tol: CheckTolerance,
                   diag: Diagnoser) -> tuple[list[Row], str, list[str], CheckTolerance]:
    """The marking of ``check --drawing`` for a polygon already read (its one entry point).

    A drawing with a stated scale is marked without turning it, each vertex
    within the drawing tolerance in mm on the sheet.
    """
    from graphkin.check import drawing

    rows, title, notes, used = drawing._check_polygon(sol, poly, name, None, tol, diag)
    return rows, title, notes, used


def debug_image(read: SheetRead) -> np.ndarray:
    """The rectified sheet with the segments (blue), places (grey) and images read (green)."""
    cv2 = need_cv2()
    img = cv2.cvtColor(read.rect.gray, cv2.COLOR_GRAY2BGR)
    h = read.layout.size[1]

    def px(p: np.ndarray) -> tuple[int, int]:
        return (int(round(p[0] * PX_PER_MM)), int(round((h - p[1]) * PX_PER_MM)))

    x0, y0, x1, y1 = read.layout.polygon_box
    cv2.rectangle(img, px(np.array([x0, y1])), px(np.array([x1, y0])), (200, 200, 0), 1)
    for s in read.segments:
        cv2.line(img, px(s[0]), px(s[1]), (255, 80, 0), 2)
    for name, at in read.places.items():
        for c in at:
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
