"""The scene of a drawing: panels of groups of items, in data coordinates, without matplotlib.

A sheet is a few *panels* (the mechanism, a velocity polygon, ...), each
drawn to its own round scale.  A panel holds *groups*: one per construction
step (its id is the step's id, ``step-07-C``) and one per part of the
mechanism (``link-3``, ``frame``).  A group holds *items*: a path, a polygon,
a marker, an arrow, a text.  Labels are placed after everything else is
known, so that they avoid the lines and each other.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (a construction, step by step).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.construction import Step
from graphkin.render.scale import Scale
from graphkin.render.text import plain

__all__ = ["Item", "Group", "LabelRequest", "Panel", "finite_xy", "clip_segment", "safe_id",
           "sub_digits", "point_text", "construction_text", "inside_spans", "clip_arc",
           "far_reference", "far_distance"]

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def safe_id(text: str) -> str:
    """A label made safe for an SVG id, the way :attr:`Step.step_id` does it.

    Examples
    --------
    >>> safe_id("v(B)")
    'v_B_'
    """
    return "".join(ch if ch.isalnum() or ch in "_-" else "_" for ch in text)


def sub_digits(text: str) -> str:
    """Trailing digits as subscripts: ``O2`` -> ``O₂`` (the book's O₂, L₁).

    Examples
    --------
    >>> sub_digits("O2"), sub_digits("B"), sub_digits("12")
    ('O₂', 'B', '12')
    """
    i = len(text)
    while i > 0 and text[i - 1].isdigit():
        i -= 1
    if i == 0 or i == len(text):
        return text
    return text[:i] + text[i:].translate(_SUB)


def point_text(label: str) -> str:
    """How a point's label is printed: construction suffixes dropped, digits subscript.

    Examples
    --------
    >>> point_text("sliders[0]:T"), point_text("O4"), point_text("C'#3")
    ('T', 'O₄', "C'")
    """
    base = label.split("#")[0].split(":")[-1]
    return plain(sub_digits(base))


def construction_text(label: str) -> str:
    """A construction point's label with real subscripts: ``J_B`` -> ``$J_{B}$``, ``A_H3``.

    Plain text when there is nothing to subscript; user letters are escaped.

    Examples
    --------
    >>> construction_text("J_B"), construction_text("Q_Γ"), construction_text("C'")
    ('$J_{B}$', '$Q_{Γ}$', "C'")
    """
    from graphkin.render.text import math_escape

    base = label.split("#")[0].split(":")[-1]
    head, sep, sub = base.partition("_")
    if not sep or not head or not sub:
        return point_text(label)
    h, lo = math_escape(head), math_escape(sub.replace("_", ""))
    if h is None or lo is None:
        return point_text(label)
    prime = ""
    while lo.endswith("'"):
        lo, prime = lo[:-1], prime + "'"
    return f"${h}_{{{lo}}}{prime}$"


def finite_xy(p: Any, tol: float = 1e-12) -> np.ndarray | None:
    """``(x, y)`` of a finite homogeneous point, or None (ideal, NaN or not a point)."""
    a = np.asarray(p, dtype=float)
    if a.shape != (3,) or not np.all(np.isfinite(a)):
        return None
    w = a[2]
    if abs(w) <= tol * max(1.0, abs(a[0]), abs(a[1])):
        return None
    return a[:2] / w


def clip_segment(p0: np.ndarray, p1: np.ndarray,
                 rect: tuple[float, float, float, float]) -> tuple[np.ndarray, np.ndarray] | None:
    """The part of the segment ``p0 p1`` inside ``rect = (x0, y0, x1, y1)`` (Liang-Barsky).

    Examples
    --------
    >>> a, b = clip_segment(np.array([-5.0, 0]), np.array([5.0, 0]), (-1, -1, 1, 1))
    >>> a.tolist(), b.tolist()
    ([-1.0, 0.0], [1.0, 0.0])
    """
    x0, y0, x1, y1 = rect
    d = p1 - p0
    t0, t1 = 0.0, 1.0
    # a component round-off of the other (1e-191 beside 40: an assembly hint's y) is zero:
    # q / p would overflow, and the segment is parallel to that side of the box anyway
    flat = 1e-15 * max(abs(float(d[0])), abs(float(d[1])))
    for p, q in ((-d[0], p0[0] - x0), (d[0], x1 - p0[0]), (-d[1], p0[1] - y0),
                 (d[1], y1 - p0[1])):
        if abs(p) <= flat or p == 0:
            if q < 0:
                return None
            continue
        r = q / p
        if p < 0:
            t0 = max(t0, r)
        else:
            t1 = min(t1, r)
        if t0 > t1:
            return None
    return p0 + t0 * d, p0 + t1 * d

def inside_spans(center: np.ndarray, r: float, box: tuple[float, float, float, float]
                  ) -> list[tuple[float, float]] | None:
    """The arcs (degrees, counterclockwise) of a circle inside ``box``; None if all of it is.

    A circle that runs out of the panel's drawing area (into the title strip
    or the scale bar's) is drawn as the arcs that stay inside, so no
    construction line crosses a panel's title.  The arcs end exactly where
    the circle crosses the box's edges, so a circle of any radius (an
    inflection circle 10⁷ times the panel, whose arc through the panel spans
    a microdegree) keeps its arc.

    Examples
    --------
    >>> inside_spans(np.array([0.0, 0.0]), 1.0, (-2, -2, 2, 2)) is None
    True
    >>> [(round(a), round(b)) for a, b in inside_spans(np.array([0.0, 0.0]), 1.0,
    ...                                                 (0, -2, 2, 2))]
    [(-90, 90)]
    >>> sp = inside_spans(np.array([0.0, -1e7]), 1e7, (-1, -1, 1, 1))
    >>> len(sp) == 1 and 89.99999 < sp[0][0] < 90 < sp[0][1] < 90.00001
    True
    """
    x0, y0, x1, y1 = box
    cx, cy = float(center[0]), float(center[1])
    if cx - r >= x0 and cx + r <= x1 and cy - r >= y0 and cy + r <= y1:
        return None
    # the angles where the circle crosses the box's four edge lines
    cuts: list[float] = []
    for xe in (x0, x1):
        d = (xe - cx) / r
        if abs(d) <= 1.0:
            a = math.acos(d)
            cuts += [a, -a]
    for ye in (y0, y1):
        d = (ye - cy) / r
        if abs(d) <= 1.0:
            a = math.asin(d)
            cuts += [a, math.pi - a]
    ts = sorted({math.remainder(t, 2 * math.pi) for t in cuts})
    if not ts:
        return []  # no crossing: wholly outside the box (the wholly inside case returned above)

    def inside(t: float) -> bool:
        # tested at the arc's middle in the frame of the centre, exact for any radius
        px, py = r * math.cos(t), r * math.sin(t)
        return x0 - cx <= px <= x1 - cx and y0 - cy <= py <= y1 - cy

    spans: list[tuple[float, float]] = []
    for i, t in enumerate(ts):
        t2 = ts[i + 1] if i + 1 < len(ts) else ts[0] + 2 * math.pi
        if t2 - t > 0 and inside((t + t2) / 2):
            spans.append((math.degrees(t), math.degrees(t2)))
    # join arcs that meet at a corner crossing
    joined: list[tuple[float, float]] = []
    for a, b in spans:
        if joined and abs(a - joined[-1][1]) <= 1e-12 * 360:
            joined[-1] = (joined[-1][0], b)
        else:
            joined.append((a, b))
    if len(joined) > 1 and abs(joined[-1][1] - (joined[0][0] + 360.0)) <= 1e-12 * 360:
        joined = [(joined[-1][0], joined[0][1] + 360.0)] + joined[1:-1]
    return joined


def clip_arc(t1: float, t2: float, spans: list[tuple[float, float]] | None
             ) -> list[tuple[float, float]]:
    """The parts of the arc ``t1..t2`` (degrees, ccw) inside ``spans`` (of :func:`inside_spans`).

    Examples
    --------
    >>> clip_arc(-10, 10, None), clip_arc(-10.0, 10.0, [(0.0, 90.0)])
    ([(-10, 10)], [(0.0, 10.0)])
    >>> clip_arc(350.0, 370.0, [(-90.0, 5.0)])     # the span -90..5 is 270..365 too
    [(350.0, 365.0)]
    """
    if spans is None:
        return [(t1, t2)]
    out: list[tuple[float, float]] = []
    for a, b in spans:
        for k in (-360.0, 0.0, 360.0):
            lo, hi = max(t1, a + k), min(t2, b + k)
            if hi > lo:
                out.append((lo, hi))
    return out


def far_distance(dist: float) -> str:
    """A far point's distance in a label: three figures, a power of ten past five digits.

    A point 10⁷ times the figure away (a pole of a link that nearly
    translates) reads ``4.47·10⁷``, not a nine-digit integer.

    Examples
    --------
    >>> far_distance(254.31), far_distance(44666961.0), far_distance(98765.0)
    ('254', '4.47·10⁷', '98765')
    """
    if not math.isfinite(dist) or dist < 1e5:
        from graphkin.text import fmt

        return fmt(dist, 3)
    e = math.floor(math.log10(dist))
    m = dist / 10.0**e
    if round(m, 2) >= 10.0:
        m, e = m / 10.0, e + 1
    return f"{m:.2f}·10{str(e).translate(_SUP)}"


_SUP = str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻")


def far_reference(panel: Panel, label: str, xy: np.ndarray,
                  value: Callable[[str], np.ndarray | None], mech: Any, sol: Any
                  ) -> tuple[str, np.ndarray]:
    """The point an off-panel point's distance is given from: the pole, else the nearest pin.

    The velocity pole P (Sec. 4.14), or I (Figs. 4.37-4.39), when the panel
    shows it; else the nearest named point of the mechanism in the panel.
    ``value(name)`` gives a construction point's finite coordinates.  Returns
    ``("", centre of the panel)`` when no named point is in the panel.
    """
    x0, y0, x1, y1 = panel.inner or panel.view

    def inside(q: np.ndarray) -> bool:
        return bool(x0 <= q[0] <= x1 and y0 <= q[1] <= y1)

    if panel.plane == "posture":
        # the velocity pole, I (Figs. 4.37-4.39; P in Sec. 4.14): "I*" when the file has a
        # point I of its own; a point of the file called P is not the pole (the pantograph's pen)
        named = set(mech.point_names) if mech is not None else set()
        for name in ("I", "I*", "I**", "P"):
            if name in named:
                continue
            pole = value(name) if label != name else None
            if pole is not None and inside(pole):
                return name, pole
        if mech is not None and sol is not None:
            best: tuple[float, str, np.ndarray] | None = None
            for n in mech.point_names:
                if n in mech.helper_points:
                    continue
                q = np.asarray(sol.position(n), dtype=float)
                d = float(np.hypot(*(xy - q)))
                if inside(q) and (best is None or d < best[0]):
                    best = (d, n, q)
            if best is not None:
                return best[1], best[2]
    return "", np.array([(x0 + x1) / 2, (y0 + y1) / 2])


@dataclass
class Item:
    """One drawable thing, in data coordinates.

    ``kind`` is ``path`` (a polyline), ``polygon``, ``marker`` (one point),
    ``arrow`` (``xy = [tail, tip]``), ``circle`` (``xy = [center]``, ``radius``),
    ``arc`` (also ``theta1``, ``theta2`` in degrees) or ``text``.
    """

    kind: str
    xy: np.ndarray
    style: str
    gid: str | None = None
    text: str = ""
    key: str | None = None
    radius: float = 0.0
    theta1: float = 0.0
    theta2: float = 360.0
    ha: str = "center"
    va: str = "center"
    head: float = 0.0
    """Arrowhead length (data units) for arrows."""
    width: float = 0.0
    """Arrowhead half width (data units)."""
    overrides: dict[str, Any] = field(default_factory=dict)
    aliases: list[str] = field(default_factory=list)
    """Other keys under which :func:`~graphkin.render.draw` returns this item's artist."""


@dataclass
class Group:
    """A group of items with a stable id: a construction step or a part of the mechanism."""

    gid: str
    z: float
    items: list[Item] = field(default_factory=list)
    step: Step | None = None
    diagram: str | None = None
    highlight: bool = False
    key: str | None = None


@dataclass
class LabelRequest:
    """A label to place near ``anchor`` (data coordinates) avoiding everything else."""

    text: str
    anchor: np.ndarray
    style: str
    gid: str
    group: Group
    key: str | None = None
    gap: float = 0.045
    """Clearance from the anchor, in inches."""
    prefer: tuple[float, float] | None = None
    """A preferred direction away from the anchor (unit vector), if any."""
    center: bool = False
    """Allow the label to sit on the anchor itself (a link number inside a plate)."""
    fallback: tuple[str, ...] = ()
    """Other texts to try, in turn, when ``text`` finds no clean place (a far point's name
    and distance on two lines)."""
    aliases: list[str] = field(default_factory=list)
    """Other keys the placed text answers to (far points listed in one label)."""
    slides: list[np.ndarray] = field(default_factory=list)
    """Other anchors (data coordinates) the label and its ``arrow`` may move to together
    (a far point's arrow slid back along its ray, where the edge has no room)."""
    arrow: Item | None = None
    """The arrow that moves with the label to a slid anchor."""
    parts: list[LabelRequest] = field(default_factory=list)
    """The labels this one lists (far points that lie the same way): placed one by one,
    each near the anchor, when the list as a whole finds no clean place."""

    short: list[str] = field(default_factory=list)
    """A far point's name and distance without the point they are measured from."""
    ref: str = ""
    """What a far point's distance is measured from (``from I``)."""

    def list_also(self, text: str, gid: str, group: Group, key: str,
                  fallback: tuple[str, ...] = (), short: str = "") -> None:
        """Add a line to this label for another far point that lies the same way.

        A list too wide for its place says once what the distances are from
        (``U_T, 395 in`` ... ``(from I)``).  The lines are also kept as
        :attr:`parts`, each with its own gid and group, to be placed one by
        one if the list finds no room at all.
        """
        if not self.parts:
            self.parts.append(LabelRequest(self.text, self.anchor, self.style, self.gid,
                                           self.group, key=self.key, gap=self.gap,
                                           prefer=self.prefer, fallback=self.fallback))
        self.parts.append(LabelRequest(text, self.anchor, self.style, gid, group, key=key,
                                       gap=self.gap, prefer=self.prefer, fallback=fallback))
        self.text += "\n" + text
        self.short.append(short)
        self.fallback = ("\n".join([*self.short, f"({self.ref})"]),) \
            if self.ref and all(self.short) else ()
        self.aliases.append(key)


@dataclass
class Panel:
    """One diagram of a sheet, drawn to its own scale.

    Attributes
    ----------
    name : str
        ``posture``, ``velocity``, ``acceleration``, ``centers``, ``curvature`` or
        ``results``.
    plane : str
        The plane of its points (``posture``, ``velocity``, ``acceleration``).
    title : str
    unit : str
        The data unit (``in/s``).
    bbox : tuple
        Content extent in data units ``(x0, y0, x1, y1)``.
    scale : Scale or None
        ``None`` for the results table.
    view : tuple
        The data rectangle the panel shows (content plus margins).
    """

    name: str
    plane: str
    title: str
    unit: str
    bbox: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)
    scale: Scale | None = None
    view: tuple[float, float, float, float] = (0.0, 0.0, 1.0, 1.0)
    groups: list[Group] = field(default_factory=list)
    labels: list[LabelRequest] = field(default_factory=list)
    prefix: str = ""
    mechanism: bool = False
    pole: str | None = None
    origin: tuple[float, float] = (0.0, 0.0)
    """Where the panel sits on the sheet: its lower-left corner in inches."""
    inner: tuple[float, float, float, float] | None = None
    """The view less the title and scale-bar strips: where construction lines may run."""
    crowded: int = 0
    """How many of its labels found no place clear of every line and label (set by
    :func:`~graphkin.render.labels.place_labels`)."""

    @property
    def k(self) -> float:
        """Data units per inch of paper."""
        return 1.0 if self.scale is None else self.scale.per_inch

    @property
    def size(self) -> tuple[float, float]:
        """Width and height in inches."""
        x0, y0, x1, y1 = self.view
        return (x1 - x0) / self.k, (y1 - y0) / self.k

    def group(self, gid: str, z: float, **kw: Any) -> Group:
        """A new group, appended."""
        g = Group(gid, z, **kw)
        self.groups.append(g)
        return g

    def to_paper(self, xy: np.ndarray) -> np.ndarray:
        """Data coordinates to inches from the panel's lower-left corner."""
        x0, y0, _, _ = self.view
        a = np.asarray(xy, dtype=float)
        return (a - np.array([x0, y0])) / self.k

    def diag(self) -> float:
        """The diagonal of the view, in data units."""
        x0, y0, x1, y1 = self.view
        return math.hypot(x1 - x0, y1 - y0)
