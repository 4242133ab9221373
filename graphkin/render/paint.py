"""Construction steps into scene items: what a draftsman draws for each recorded act.

The painter is generic over steps: it looks only at a step's kind (point,
line, circle, vector, scalar), its operation, its role and the values of its
inputs and outputs.  The textbook conventions it follows:

* a point of the mechanism is a pin (small circle) or a dot, lettered; a
  construction point is a small grey dot; a point at infinity is an arrow at
  the panel's edge marked ∞;
* a line is drawn thin and only as long as the points on it need (the
  through-point and the points later found on it), with a right-angle mark
  where it was drawn perpendicular to a line of the same panel or to a vector
  laid off there;
* a circle is drawn as short arcs where it is later cut, as the book swings
  its arcs (Fig. 2.14), and in full when nothing cuts it;
* in a polygon, every image is lettered (``b``, ``c`` for velocities; ``b′``
  for accelerations; ``a₄`` for the point of link 4 at A), absolute vectors
  are drawn bold from the pole, relative ones thinner; normal components are
  dashed, tangential ones solid and Coriolis components dash-dotted (Fig. 4.11);
* an angular rate is a curved arrow on its link with its value and sense.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Fig. 2.14), Sec. 3.4 (Fig. 3.5),
Sec. 3.5 (images), Sec. 4.3 (Fig. 4.4), Sec. 4.5 (Fig. 4.11).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Collection

import numpy as np

from graphkin.construction import Construction, Role, Step
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.render.contact_letters import (
    contact_acceleration_letters,
    contact_velocity_letters,
    point_letters,
)
from graphkin.render.paint_rates import paint_scalar
from graphkin.render.scene import (
    Group,
    Item,
    LabelRequest,
    Panel,
    clip_arc,
    clip_segment,
    construction_text,
    far_distance,
    far_reference,
    finite_xy,
    inside_spans,
    point_text,
    safe_id,
)
from graphkin.render.sources import Source, plane_of
from graphkin.render.style import style_for_role
from graphkin.render.text import math_escape, plain

__all__ = ["StepPainter", "image_text", "vector_math", "INTERSECTIONS", "POLES"]

INTERSECTIONS = ("intersect_circles", "intersect_line_circle", "meet")
_LAID_OFF = ("point", "rigid", "translate", "subtract", "add_along", "along_line", "similar",
             "image", "velocity_difference", "acceleration_difference")
POLES = {"velocity": ("o_v", "$O_V$"), "acceleration": ("o_a", "$O_A$")}

ARROW_HEAD = 0.085
"""Arrowhead length in inches."""
ARROW_HALF = 0.028
"""Arrowhead half width in inches."""
ARC_HALF = 0.5
"""Half the length of an arc swung through an intersection, in inches."""


def image_text(label: str) -> str:
    """The letter of an image point: ``v(B)`` -> ``b``, ``a(B)`` -> ``b′``, ``v(A@4)`` -> ``a₄``.

    Examples
    --------
    >>> image_text("v(B)"), image_text("a(C)"), image_text("v(A@4)"), image_text("a(O2)")
    ('b', 'c′', 'a₄', 'o′₂')

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.5 (lowercase image letters) and
    Sec. 4.3 (primed acceleration images).
    """
    prime = label.startswith("a(")
    inner = label[2:-1] if label.endswith(")") else label
    name, _, link = inner.partition("@")
    base = name.split("#")[0].split(":")[-1]
    return plain(point_letters(base, link, prime))


def vector_math(label: str) -> str:
    """A vector's label as mathtext: ``A_CB^n`` -> ``$A^{n}_{CB}$``.

    Examples
    --------
    >>> vector_math("A_CB^n"), vector_math("A_A/4^c"), vector_math("V_B")
    ('$A^{n}_{CB}$', '$A^{c}_{A/4}$', '$V_{B}$')
    """
    base, _, rest = label.partition("_")
    sub, _, sup = rest.rpartition("^") if "^" in rest else (rest, "", "")
    sub = sub.replace("{", "").replace("}", "")
    if not sub:
        return plain(label)
    b, lo, hi = math_escape(base), math_escape(sub), math_escape(sup)
    if b is None or lo is None or hi is None:
        return plain(label)
    return f"${b}^{{{hi}}}_{{{lo}}}$" if hi else f"${b}_{{{lo}}}$"


def vector_style(label: str) -> str:
    """The style of a laid-off vector from its name: normal, tangential, Coriolis."""
    if "^c" in label:
        return "vector-c"
    if "^n" in label:
        return "vector-n"
    if "^t" in label:
        return "vector-t"
    return "vector-rel"


def _unknown_terms(step: Step) -> list[str]:
    """Names of the vectors a step finds: the unknown-magnitude terms of its equation."""
    eq = step.equation
    if eq is None:
        return []
    terms = (*eq.lhs, *eq.rhs)
    return [t.name for t in terms if str(getattr(t.magnitude, "value", t.magnitude)) == "?"
            and str(getattr(t.direction, "value", t.direction)) != "?"]


def _component_names(step: Step) -> dict[str, str]:
    """The normal and tangential components named in a step's equation: ``{"n": "A_CD^n"}``."""
    eq = step.equation
    out: dict[str, str] = {}
    if eq is None:
        return out
    for t in (*eq.lhs, *eq.rhs):
        for sup in ("n", "t", "c"):
            if t.name.endswith("^" + sup):
                out.setdefault(sup, t.name)
    return out


def _math_or_none(name: str | None) -> str | None:
    return None if not name else vector_math(name)


_CONTACT_IMAGE = re.compile(r"([va])\((rolling\[\d+\]):(\w+)@(\w+)\)(:r)?")


def _contact_text(label: str, mech: Mechanism | None) -> str:
    """An image's letters; a contact's as the book letters it (Fig. 3.14b, Eq. 4.19).

    The one velocity image of the coincident points of a rolling contact
    carries both links' letters, ``c₄ = c₂``; each link's acceleration image
    its own, ``c′₄``, naming the other link when the link is in two contacts
    (a planet 4 meshing with 2 and with 1: ``c′₄ (4/2)``, Sec. 4.7).
    """
    m = _CONTACT_IMAGE.fullmatch(label)
    if m is None or mech is None:
        return image_text(label)
    what, key, name, lid = m.group(1), m.group(2), m.group(3), m.group(4)
    r = next((x for x in mech.rolling if x.key == key), None)
    if r is None:
        return image_text(label)
    if what == "v":
        return plain(contact_velocity_letters(name, (r.link, r.on)))
    shared = sum(lid in (x.link, x.on) for x in mech.rolling) > 1
    return plain(contact_acceleration_letters(name, lid, r.on if lid == r.link else r.link,
                                              shared))


def _is_image(label: str) -> bool:
    """An image point lettered in its polygon: a point's, or a rolling contact point's.

    The point of contact of a rolling link (``v(rolling[0]:C@4)``, lettered
    ``c₄ = c₂``; ``a(rolling[0]:C@2):r``, the other link's, found through the
    rolling component, ``c′₂``) is an image as the book draws it (Sec. 3.7,
    Fig. 3.14b); other internal labels (with ``:``) are construction points.
    """
    if _CONTACT_IMAGE.fullmatch(label):
        return True
    return (label.startswith(("v(", "a(")) and label.endswith(")") and ":" not in label)


def _unit(v: np.ndarray) -> np.ndarray | None:
    n = float(np.hypot(v[0], v[1]))
    if not math.isfinite(n) or n == 0:
        return None
    return v / n


class StepPainter:
    """Paints the steps of one construction into the panels of a sheet.

    Parameters
    ----------
    src : Source
    diagram : str
        The construction's diagram.
    panels : dict
        ``"length"`` -> the mechanism's panel (or None), ``"polygon"`` -> the
        panel of the diagram's plane (or None).
    prefix : str
        Prepended to every id (for sheets with several constructions).
    kinds, planes : dict
        Label -> kind and plane of every label of the source.
    """

    def __init__(self, src: Source, diagram: str, panels: dict[str, Panel | None], prefix: str,
                 kinds: dict[str, str], planes: dict[str, str]) -> None:
        self.src = src
        self.diagram = diagram
        cx = src.constructions[diagram]
        self.cx: Construction = cx
        self.values = src.values.get(diagram, {})
        self.panels = panels
        self.prefix = prefix
        self.kinds = kinds
        self.planes = planes
        self.consumers: dict[str, list[Step]] = {}
        for s in cx.steps:
            for i in s.inputs:
                self.consumers.setdefault(i, []).append(s)
        self.makers: dict[str, Step] = {o: s for s in cx.steps for o in s.outputs}
        self.drawn_points: set[str] = set()
        self.arrows: dict[str, dict[tuple[float, ...], Item]] = {}
        self.arrow_ends: dict[str, list[tuple[np.ndarray, np.ndarray]]] = {}
        # far points shown per panel: (direction from the reference, the label asked for)
        self.far: dict[str, list[tuple[np.ndarray, LabelRequest]]] = {}
        self._helper_xy: list[np.ndarray] | None = None
        self.quiet_rates = False
        """Leave angular rates off the mechanism (a sheet of every diagram lists them)."""

    # ---- routing ------------------------------------------------------
    def panel_for(self, step: Step) -> Panel | None:
        """The panel a step is drawn in (None: nowhere on this sheet)."""
        plane = plane_of(step.diagram)
        own = plane_of(self.diagram)
        if own == "posture":
            return self.panels.get("length") or self.panels.get("polygon")
        if step.kind == "scalar" or plane == "posture":
            return self.panels.get("length") or self.panels.get("polygon")
        return self.panels.get("polygon")

    def xy(self, label: str) -> np.ndarray | None:
        """Finite coordinates of a point label (this construction's values, then any)."""
        v = self.values.get(label)
        if v is None:
            v = self.src.value(self.diagram, label)
        return None if v is None else finite_xy(v)

    def raw(self, label: str) -> np.ndarray | None:
        """The raw value of a label (homogeneous point, line, circle, vector or scalar)."""
        v = self.values.get(label)
        if v is None:
            v = self.src.value(self.diagram, label)
        return None if v is None else np.asarray(v, dtype=float)

    # ---- entry point --------------------------------------------------
    def paint(self, upto: int | None = None,
              highlight: int | Collection[int] | None = None) -> list[Group]:
        """Paint steps ``0..upto`` (all by default); returns the groups made.

        ``highlight`` is the step (or the steps) drawn in the highlight colour.
        """
        lit = set() if highlight is None else (
            {highlight} if isinstance(highlight, int) else set(highlight))
        groups = []
        for step in self.cx.steps:
            if upto is not None and step.index > upto:  # (a panel's steps keep their numbers)
                break
            panel = self.panel_for(step)
            if panel is None:
                continue
            z = {"line": 2.0, "circle": 2.0, "vector": 3.0, "scalar": 3.5}.get(step.kind, 4.0)
            g = panel.group(self.prefix + step.step_id, z, step=step, diagram=self.diagram,
                            highlight=step.index in lit,
                            key=step.label)
            groups.append(g)
            if step.kind == "scalar":
                self.scalar(step, g, panel)
                continue
            if plane_of(step.diagram) != panel.plane:
                continue
            getattr(self, step.kind if step.kind in ("point", "line", "circle", "vector")
                    else "other")(step, g, panel)
        return groups

    # ---- helpers ------------------------------------------------------
    def label(self, panel: Panel, g: Group, text: str, anchor: np.ndarray, key: str,
              style: str = "label", gap: float = 0.045,
              prefer: tuple[float, float] | None = None,
              fallback: tuple[str, ...] = ()) -> None:
        """Ask for a label near ``anchor`` (placed later, avoiding the ink)."""
        panel.labels.append(LabelRequest(text, np.asarray(anchor, dtype=float), style,
                                         self.prefix + "label-" + safe_id(key), g, key=key,
                                         gap=gap, prefer=prefer, fallback=fallback))

    def arrow(self, panel: Panel, g: Group, tail: np.ndarray, tip: np.ndarray, style: str,
              key: str | None = None, text: str | None = None) -> Item | None:
        """An arrow (deduplicated per panel); returns it, or None when empty or repeated."""
        tail, tip = np.asarray(tail, dtype=float), np.asarray(tip, dtype=float)
        length = float(np.hypot(*(tip - tail)))
        if not math.isfinite(length) or length <= 1e-9 * panel.diag():
            return None
        tol = 1e-7 * panel.diag()
        sig = tuple(np.round(np.concatenate([tail, tip]) / tol).astype(float).tolist())
        seen = self.arrows.setdefault(panel.name, {})
        if sig in seen:
            old = seen[sig]
            if key is not None:
                old.aliases.append(key)
            if style == "vector-abs":
                old.style = style
            return None
        self.arrow_ends.setdefault(panel.name, []).append((tail, tip))
        k = panel.k
        head = min(ARROW_HEAD * k, 0.45 * length)
        it = Item("arrow", np.array([tail, tip]), style, key=key, head=head,
                  width=ARROW_HALF * k * head / (ARROW_HEAD * k))
        g.items.append(it)
        seen[sig] = it
        if text:
            mid = tail + 0.5 * (tip - tail)
            # at point-label size: mathtext sub- and superscripts (0.7 of it) stay above 6 pt
            self.label(panel, g, text, mid, key or text, style="label-vector", gap=0.03)
        return it

    def marker(self, g: Group, xy: np.ndarray, style: str, key: str) -> Item:
        """A point marker."""
        it = Item("marker", np.asarray([xy], dtype=float), style, key=key)
        g.items.append(it)
        return it

    def off_sheet(self, panel: Panel, g: Group, label: str, xy: np.ndarray) -> None:
        """A finite point beyond the panel: an arrow toward it, named, with its distance.

        As a book figure does when a point does not fit (the far Γ of
        Fig. 4.35): the arrow points from the velocity pole I (Figs.
        4.37-4.39) when the panel shows it, else from the
        nearest point of the mechanism in the panel, and reads
        "Γ_T, 254 in from I" -- never raw coordinates.
        """
        name = construction_text(label) if panel.plane == "posture" else image_text(label)
        ref_name, ref = self.reference_for(panel, label, xy)
        dist = float(np.hypot(*(xy - ref)))
        unit = f" {panel.unit}" if panel.unit else ""
        who = construction_text(ref_name) if panel.plane == "posture" else image_text(ref_name)
        text = f"{name}, {far_distance(dist)}{unit} from {who}" if ref_name else \
            f"{name}, {far_distance(dist)}{unit} off the figure"
        # where a crowded edge has no room for one line: the name above its distance
        two = (text.replace(", ", ",\n", 1),)
        d = _unit(xy - ref)
        if d is None:
            return
        shown = self.far.setdefault(panel.name, [])
        for d0, req in shown:
            if float(d @ d0) > math.cos(math.radians(8.0)):
                # one arrow for points that lie the same way, their names and distances in
                # one list beside it (a label of its own could drift an inch from the arrow)
                req.list_also(text, self.prefix + "label-" + safe_id(label), g, label, two,
                              short=f"{name}, {far_distance(dist)}{unit}")
                return
        n = len(panel.labels)
        self.ideal(panel, g, label, np.array([*(xy - ref), 0.0]), text=text, center=ref,
                   fallback=two)
        if len(panel.labels) > n:
            shown.append((d, panel.labels[-1]))
            panel.labels[-1].short = [f"{name}, {far_distance(dist)}{unit}"]
            panel.labels[-1].ref = f"from {who}" if ref_name else "off the figure"

    def later_points(self, label: str, panel: Panel,
                     lies_on: Callable[[np.ndarray], bool]) -> list[np.ndarray]:
        """The points that later steps of this panel construct from ``label`` and that lie on it."""
        out = []
        for s in self.consumers.get(label, []):
            if plane_of(s.diagram) != panel.plane:
                continue
            for o in s.outputs:
                if self.kinds.get(o) == "point":
                    q = self.xy(o)
                    if q is not None and lies_on(q):
                        out.append(q)
        return out

    def reference_for(self, panel: Panel, label: str, xy: np.ndarray
                      ) -> tuple[str, np.ndarray]:
        """The point an off-panel point's distance is given from: see :func:`far_reference`."""
        return far_reference(panel, label, xy, self.xy, self.src.mechanism, self.src.solution)

    def ideal(self, panel: Panel, g: Group, label: str, p: np.ndarray, text: str | None = None,
              center: np.ndarray | None = None, fallback: tuple[str, ...] = ()) -> None:
        """A point at infinity: an arrow at the panel's edge, marked ∞."""
        d = _unit(np.asarray(p[:2], dtype=float))
        if d is None:
            return
        x0, y0, x1, y1 = panel.inner or panel.view  # clear of the title and scale strips
        c = np.array([(x0 + x1) / 2, (y0 + y1) / 2]) if center is None else center
        ts = []
        for i, (lo, hi) in enumerate(((x0, x1), (y0, y1))):
            # a component of round-off (of the unit direction) leaves by the other side
            if d[i] > 1e-12:
                ts.append((hi - c[i]) / d[i])
            elif d[i] < -1e-12:
                ts.append((lo - c[i]) / d[i])
        t = min(ts)
        tip = c + d * (t - 0.12 * panel.k)
        tail = tip - d * 0.4 * panel.k
        arrow = self.arrow(panel, g, tail, tip, "infinity", key=label)
        self.label(panel, g, text or f"{construction_text(label)} ∞", tail, label, style="label",
                   prefer=(-d[0], -d[1]), fallback=fallback)
        room = float((tail - c) @ d)  # how far the arrow may slide back toward the center
        if arrow is not None:
            # the arrow goes with its label (beside a clear place) even where it cannot slide
            # back: its reference point near the panel's edge (I15 of the Watt six-bar, from F)
            req = panel.labels[-1]
            req.arrow = arrow
            if room > 0:
                req.slides = [tail - d * f * room for f in (0.15, 0.3, 0.45, 0.6)]

    # ---- points -------------------------------------------------------
    def point(self, step: Step, g: Group, panel: Panel) -> None:
        """A point: a pin, a dot, a construction point, an image with its vectors."""
        for label in step.outputs:
            p = self.raw(label)
            if p is None or p.shape != (3,):
                continue
            xy = finite_xy(p)
            if xy is None:
                if np.all(np.isfinite(p)):
                    self.ideal(panel, g, label, p)
                continue
            x0, y0, x1, y1 = panel.inner or panel.view  # the title strip is no drawing room
            if not (x0 <= xy[0] <= x1 and y0 <= xy[1] <= y1):
                # a helper point a later line is drawn through (W of Bobillier's
                # construction, Fig. 4.29) is shown too: the reader must find it
                if step.role != Role.AUXILIARY or self.consumers.get(label):
                    self.off_sheet(panel, g, label, xy)
                continue
            if panel.plane == "posture":
                self.posture_point(step, g, panel, label, xy)
            else:
                self.polygon_point(step, g, panel, label, xy)

    def posture_point(self, step: Step, g: Group, panel: Panel, label: str,
                      xy: np.ndarray) -> None:
        """A point of the mechanism's plane: a pin or dot, lettered; or a construction point."""
        mech = self.src.mechanism
        if mech is not None and label in mech.helper_points:
            self.drawn_points.add(label)  # drawn as its line or slot, not as a point
            return
        if mech is not None and label in mech.point_links:
            style = "pin" if len(mech.point_links[label]) >= 2 else "point"
            helper = not _is_joint_or_named_point(mech, label)
            self.marker(g, xy, "aux-point" if helper else style, label)
            self.drawn_points.add(label)
            self.label(panel, g, point_text(label), xy, label,
                       style="label-aux" if helper else "label")
            return
        found = step.role == Role.RESULT or (self.diagram == "centers" and step.role == Role.GIVEN)
        if mech is not None and not found and self._on_helper(xy, panel):
            return  # a copy of a helper point (the slot's S1, S2): drawn as the slot
        internal = "#" in label or ":" in label  # a second copy, a slider line's own point
        if internal and step.role != Role.RESULT:
            return  # drawn as the line it defines or the point it copies: no dot, no name
        shown = step.role != Role.AUXILIARY or step.op not in _LAID_OFF
        self.marker(g, xy, style_for_role(step.role, "point") if shown else "aux-point", label)
        if not internal or ("#" not in label and shown and step.op not in _LAID_OFF):
            # a center or a point the construction finds: black, at point-label size; a point
            # laid off on the way (the pole velocity v, the Bresse diameter's end E) in grey
            text = construction_text(label)
            self.label(panel, g, text, xy, label,
                       style="label" if shown and (found or text.startswith("$"))
                       else "label-aux")

    def _on_helper(self, xy: np.ndarray, panel: Panel) -> bool:
        """True when ``xy`` is where a helper point of the mechanism is."""
        mech, sol = self.src.mechanism, self.src.solution
        if mech is None or sol is None or not mech.helper_points:
            return False
        if self._helper_xy is None:
            self._helper_xy = [np.asarray(sol.position(n), dtype=float)
                               for n in sorted(mech.helper_points)]
        tol = 1e-9 * panel.diag()
        return any(float(np.hypot(*(xy - q))) <= tol for q in self._helper_xy)

    def polygon_point(self, step: Step, g: Group, panel: Panel, label: str,
                      xy: np.ndarray) -> None:
        """A point of a polygon: the pole, an image and the vectors that found it."""
        pole_label, pole_text = POLES.get(panel.plane, (None, ""))
        pole = self.xy(pole_label) if pole_label else None
        if step.op == "point" or label == pole_label:
            self.marker(g, xy, "pole", label)
            self.label(panel, g, pole_text or point_text(label), xy, label)
            return
        image = _is_image(label)
        mech = self.src.mechanism
        if image and mech is not None and label[2:-1] in mech.helper_points:
            return  # a helper point has no image (issue 11: only the line it defines)
        if image:
            self.marker(g, xy, "image-point", label)
            self.label(panel, g, _contact_text(label, mech), xy, label)
        result = step.role == Role.RESULT
        accel = panel.plane == "acceleration"
        ins = step.inputs

        def at_pole(q: np.ndarray | None) -> bool:
            return pole is not None and q is not None and \
                float(np.hypot(*(q - pole))) <= 1e-9 * panel.diag()

        abs_done = False
        if step.op == "velocity_difference":
            ta = self.xy(ins[0])
            if ta is not None:
                st = "vector-abs" if (at_pole(ta) and result) else "vector-rel"
                self.arrow(panel, g, ta, xy, st,
                           key=f"{label}:abs" if at_pole(ta) else f"{label}:{ins[0]}")
                abs_done = at_pole(ta)
        elif step.op == "acceleration_difference":
            ta = self.xy(ins[0])
            w = self.raw(ins[1])
            a, x = self.xy(ins[3]), self.xy(ins[4])
            if ta is not None and w is not None and a is not None and x is not None:
                r = x - a
                mid = ta - float(w) ** 2 * r
                names = _component_names(step)
                self.arrow(panel, g, ta, mid, "vector-n", key=f"{label}:n",
                           text=_math_or_none(names.get("n")))
                self.arrow(panel, g, mid, xy, "vector-t", key=f"{label}:t",
                           text=_math_or_none(names.get("t")))
        elif step.op == "meet":
            unknown = _unknown_terms(step)
            for li, line in enumerate(ins):
                name = unknown[li] if len(unknown) == len(ins) else None
                if not accel and name is not None and "/" not in name:
                    name = None  # a velocity polygon letters only the apparent (slip) vectors
                thr = self.through(line)
                if thr is None or float(np.hypot(*(thr - xy))) <= 1e-9 * panel.diag():
                    continue
                if at_pole(thr):
                    self.arrow(panel, g, thr, xy, "vector-abs" if result else "vector-rel",
                               key=f"{label}:abs")
                    abs_done = True
                else:
                    self.arrow(panel, g, thr, xy, "vector-t" if accel else "vector-rel",
                               key=f"{label}:{line}", text=_math_or_none(name))
        elif step.op in ("translate", "subtract"):
            p = self.xy(ins[0])
            if p is not None:
                tail, tip = (p, xy) if step.op == "translate" else (xy, p)
                st = vector_style(ins[1])
                self.arrow(panel, g, tail, tip, st, key=ins[1], text=vector_math(ins[1]))
        elif step.op == "add_along":
            p = self.xy(ins[0])
            if p is not None:
                self.arrow(panel, g, p, xy, "vector-rel", key=f"{label}:along")
                abs_done = at_pole(p) and result
        if result and pole is not None and not abs_done and image:
            self.arrow(panel, g, pole, xy, "vector-abs", key=f"{label}:abs")

    def through(self, line: str) -> np.ndarray | None:
        """The point a line was drawn through (the tip of the vector it continues)."""
        s = self.makers.get(line)
        if s is None:
            return None
        plane = plane_of(s.diagram)
        for i in reversed(s.inputs):
            if self.kinds.get(i) == "point" and self.planes.get(i) == plane:
                return self.xy(i)
        return None

    # ---- lines --------------------------------------------------------
    def line(self, step: Step, g: Group, panel: Panel) -> None:
        """A line, as long as the points on it need, with its right-angle mark."""
        label = step.outputs[0]
        ln = self.raw(label)
        if ln is None or ln.shape != (3,) or not np.all(np.isfinite(ln)):
            return
        n = ln[:2]
        nn = float(np.hypot(*n))
        if nn == 0:
            return
        n = n / nn
        c = ln[2] / nn
        d = np.array([n[1], -n[0]])
        eps = 1e-7 * panel.diag()
        on: list[np.ndarray] = []
        for i in step.inputs:
            if self.kinds.get(i) == "point" and self.planes.get(i) == panel.plane:
                q = self.xy(i)
                if q is not None and abs(float(n @ q) + c) <= eps:
                    on.append(q)
        through = on[0] if on else None
        foot = None
        rn = n
        if step.op == "perpendicular" and self.planes.get(step.inputs[0]) == panel.plane:
            ref = self.raw(step.inputs[0])
            if ref is not None and through is not None:
                rn = ref[:2] / float(np.hypot(*ref[:2]))
                rc = ref[2] / float(np.hypot(*ref[:2]))
                foot = through - (float(rn @ through) + rc) * rn
                on.append(foot)
        on += self.later_points(label, panel, lambda q: abs(float(n @ q) + c) <= eps * 10)
        k = panel.k
        if on:
            ts = [float(d @ q) for q in on]
            base = on[0] - ts[0] * d
            lo, hi = min(ts), max(ts)
            ext = 0.3 * k if hi - lo > 1e-9 * panel.diag() else 0.9 * k
            p0, p1 = base + (lo - ext) * d, base + (hi + ext) * d
        else:
            x0, y0, x1, y1 = panel.view
            center = np.array([(x0 + x1) / 2, (y0 + y1) / 2])
            base = center - (float(n @ center) + c) * n
            p0, p1 = base - panel.diag() * d, base + panel.diag() * d
        seg = clip_segment(p0, p1, panel.inner or panel.view)
        if seg is None:
            return
        style = ("ref-line" if self.diagram != step.diagram and step.op == "join"
                 else style_for_role(step.role, "line"))
        g.items.append(Item("path", np.array(seg), style, key=label))
        if self.diagram in _CURVATURE and label.split("*")[0] in ("N", "T"):
            # the centrode normal and tangent, lettered at their positive ends
            a, b = np.asarray(seg[0]), np.asarray(seg[1])
            tip = b if float((b - a) @ d) >= 0 else a
            self.label(panel, g, label.split("*")[0], tip - 0.15 * panel.k * d *
                       (1 if tip is b else -1), label, style="label")
        # right-angle marks
        if step.op == "perpendicular" and through is not None:
            if foot is not None:
                away = [q for q in on if float(np.hypot(*(q - foot))) > eps]
                u = _unit(away[0] - foot) if away else d
                ref_dir = np.array([rn[1], -rn[0]])
                if u is not None:
                    self.right_angle(g, panel, foot, u, ref_dir)
                return
            far = [q for q in on if float(np.hypot(*(q - through))) > eps]
            u = _unit(far[-1] - through) if far else d
            if u is None:
                return
            for tail, tip in self.arrow_ends.get(panel.name, []):
                if float(np.hypot(*(tip - through))) <= eps:
                    back = _unit(tail - tip)
                    if back is not None and abs(float(back @ u)) < 1e-6:
                        self.right_angle(g, panel, through, u, back)
                        break

    def right_angle(self, g: Group, panel: Panel, at: np.ndarray, u: np.ndarray,
                    v: np.ndarray) -> None:
        """A right-angle mark at ``at`` between the directions ``u`` and ``v``."""
        s = 0.06 * panel.k
        pts = np.array([at + s * u, at + s * (u + v), at + s * v])
        g.items.append(Item("path", pts, "right-angle"))

    # ---- circles ------------------------------------------------------
    def circle(self, step: Step, g: Group, panel: Panel) -> None:
        """A circle: arcs where it is cut, or the whole circle."""
        label = step.outputs[0]
        c = self.raw(label)
        if c is None or c.shape != (3,) or not np.all(np.isfinite(c)) or c[2] <= 0:
            return
        center, r = c[:2], float(c[2])
        style = style_for_role(step.role, "circle")
        cuts = self.later_points(
            label, panel, lambda q: abs(float(np.hypot(*(q - center))) - r) <= 1e-6 * r)
        if not cuts:
            # no intersection cuts it: mark the later points that lie on it (a tangent's foot)
            for s in (x for x in self.cx.steps if x.index > step.index):
                if plane_of(s.diagram) != panel.plane:
                    continue
                for o in s.outputs:
                    if o in step.inputs or self.kinds.get(o) != "point":
                        continue
                    q = self.xy(o)
                    if q is not None and abs(float(np.hypot(*(q - center))) - r) <= 1e-6 * r:
                        cuts.append(q)
        if not cuts or step.role == Role.RESULT:
            gid = safe_id(self.prefix + label.replace(" ", "-"))
            spans = inside_spans(center, r, panel.inner or panel.view)
            if spans is None:
                g.items.append(Item("circle", np.array([center]), style, key=label, radius=r,
                                    gid=gid))
            else:  # a circle larger than the drawing: the arcs inside it, clear of the title
                for i, (t1, t2) in enumerate(spans):
                    g.items.append(Item("arc", np.array([center]), style,
                                        key=label if i == 0 else f"{label}:{i}", radius=r,
                                        theta1=t1, theta2=t2,
                                        gid=gid if i == 0 else f"{gid}-{i}"))
            if label.split("*")[0] in ("inflection circle", "Bresse circle"):
                top = center + np.array([0.0, r])
                if spans:  # its top is off the drawing: letter it in the middle of its arc
                    t1, t2 = max(spans, key=lambda sp: sp[1] - sp[0])
                    mid = math.radians((t1 + t2) / 2)
                    top = center + r * np.array([math.cos(mid), math.sin(mid)])
                self.label(panel, g, label.split("*")[0].replace(" circle", " circle"), top,
                           label, style="label-small", prefer=(0.0, 1.0))
            return
        # a short arc about each cut: at least 6° of a small circle, never longer than
        # three times the usual arc on paper (6° of a huge circle would cross the panel)
        half = min(max(min(6.0, math.degrees(3 * ARC_HALF * panel.k / r)),
                       math.degrees(ARC_HALF * panel.k / r)), 170.0)
        spans = inside_spans(center, r, panel.inner or panel.view)
        n = 0
        for q in cuts:
            phi = math.degrees(math.atan2(q[1] - center[1], q[0] - center[0]))
            for t1, t2 in clip_arc(phi - half, phi + half, spans):  # kept out of the title
                g.items.append(Item("arc", np.array([center]), style,
                                    key=label if n == 0 else f"{label}:{n}", radius=r,
                                    theta1=t1, theta2=t2))
                n += 1

    # ---- vectors ------------------------------------------------------
    def vector(self, step: Step, g: Group, panel: Panel) -> None:
        """A vector: drawn where it is laid off, else from the pole."""
        label = step.outputs[0]
        if any(s.op in ("translate", "subtract") for s in self.consumers.get(label, [])):
            return  # drawn where it is laid off
        pole_label = POLES.get(panel.plane, (None, ""))[0]
        pole = self.xy(pole_label) if pole_label else None
        v = self.raw(label)
        if pole is None or v is None or v.shape != (2,) or not np.all(np.isfinite(v)):
            return
        self.arrow(panel, g, pole, pole + v, vector_style(label), key=label,
                   text=vector_math(label))

    def other(self, step: Step, g: Group, panel: Panel) -> None:
        """A step of an unknown kind draws nothing (its group still exists)."""

    # ---- scalars: angles and angular rates on the mechanism -------------
    def scalar(self, step: Step, g: Group, panel: Panel) -> None:
        """An input angle or an angular rate, drawn on its link (:mod:`.paint_rates`)."""
        paint_scalar(self, step, g, panel)


def _is_joint_or_named_point(mech: Mechanism, label: str) -> bool:
    """A point worth a letter: a joint, a slider point, or a point of a moving link.

    A helper point (:attr:`Mechanism.helper_points`: ``S``, ``T``, ``L1``...)
    never is: it is drawn as the line or slot it defines.
    """
    if label in mech.helper_points:
        return False
    links = mech.point_links[label]
    if len(links) >= 2:
        return True
    if any(s.point == label for s in mech.sliders) or any(s.point == label for s in mech.slots):
        return True
    return links != [FRAME]


PaintFn = Callable[[Step, Group, Panel], None]

_CURVATURE = ("curvature", "inflection", "bobillier", "hartmann", "cubic")
