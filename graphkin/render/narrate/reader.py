"""The reader of a construction: its values, its steps grouped into the acts of a page.

:class:`_Reader` reads one recorded construction and the values of its solved
labels, groups the preparatory steps with the step they serve, names the
vectors as the book does, and tells the steps that need no polygon words:
the start of a polygon (the pole and the scale), the posture (Sec. 2.8,
Table 2.2) and any step told from its own note (instant centers, curvature).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Table 2.2, Fig. 2.14), 3.4, 4.4.
"""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np

from graphkin.construction import Construction, Step, Term
from graphkin.mechanisms.model import FRAME, Mechanism, Slider, Slot
from graphkin.render.narrate.curvature import PANEL_INTRO, curvature_numbers, given_step, why
from graphkin.render.narrate.words import (
    _OP_WORDS,
    _PLURAL,
    _REFS,
    PREPARATORY,
    PageStep,
    U,
    _deg,
    _deg_line,
    _first_sentence,
    _image_point,
    _round,
    plane,
    point_name,
)
from graphkin.render.scale import Scale, fmt


class _Reader:
    """Reads one construction and its values; tells each group of steps."""

    def __init__(self, src: Any, diagram: str, scale: Scale | None) -> None:
        self.src = src
        self.diagram = diagram
        self.cx: Construction = src.constructions[diagram]
        self.mech: Mechanism | None = src.mechanism
        self.scale = scale
        self.makers = {o: s for s in self.cx.steps for o in s.outputs}
        self.consumers: dict[str, list[Step]] = {}
        for s in self.cx.steps:
            for i in s.inputs:
                self.consumers.setdefault(i, []).append(s)
        self.accel = diagram == "acceleration"
        # a figure of the curvature sheet: its own steps (the others were made before it)
        own = getattr(self.cx, "own", None)
        self.own: frozenset[int] | None = own if isinstance(own, frozenset) else None
        #: output label -> the section of the curvature construction that made it
        self.sections: dict[str, str] = dict(getattr(src.extras.get(diagram), "sections", None)
                                             or {})
        unit = src.length_unit
        # numbers are written in the unit the polygon's scale is written in (in/s as ft/s)
        self.f = scale.factor if scale is not None and plane(diagram) != "posture" else 1.0
        big = scale.unit.partition("/")[0] if scale is not None and self.f != 1.0 else unit
        self.L = big
        self.unit_file = unit
        self.given_rates = set()
        if self.mech is not None:
            for d in self.mech.drives:
                self.given_rates |= set(d.rate_labels)
        self.given_rates |= {"ω1", "α1"}

    # ---- values ---------------------------------------------------------
    def raw(self, label: str, diagram: str | None = None) -> np.ndarray | None:
        v = self.src.value(diagram or self.diagram, label)
        return None if v is None else np.asarray(v, dtype=float)

    def xy(self, label: str, diagram: str | None = None) -> np.ndarray | None:
        v = self.raw(label, diagram)
        if v is None or v.shape != (3,) or abs(v[2]) < 1e-300:
            return None
        return v[:2] / v[2]

    def pos(self, name: str) -> np.ndarray | None:
        return self.xy(name, "posture")

    def dist(self, a: str, b: str) -> float:
        pa, pb = self.pos(a), self.pos(b)
        if pa is None or pb is None:
            return math.nan
        return float(np.hypot(*(pb - pa)))

    def scalar(self, label: str, diagram: str | None = None) -> float:
        v = self.raw(label, diagram)
        return math.nan if v is None or v.shape != () else float(v)

    # ---- numbers --------------------------------------------------------
    def q(self, x: float, kind: str, answer: bool = True) -> str:
        """A quantity in the page's units: kind ``L``, ``V``, ``A``, ``w``, ``a``."""
        if not math.isfinite(x):
            return "—"
        unit = {"L": self.L, "V": f"{self.L}/s", "A": f"{self.L}/s²", "w": "rad/s",
                "a": "rad/s²"}[kind]
        val = x / self.f if kind in ("L", "V", "A") else x
        s = f"{fmt(_round(val), 4)} {unit}"
        return f"⟦{s}⟧" if answer else s

    def length(self, a: str, b: str) -> str:
        """A link length as the book writes it in the page's unit (``4/12 ft``)."""
        r = self.dist(a, b)
        if self.f == 12.0 and self.unit_file in ("in", "inch") and math.isfinite(r) \
                and abs(r - round(r, 3)) < 1e-9:
            return f"{fmt(r, 5)}/12 ft"
        return self.q(r, "L", answer=False)

    def paper(self, magnitude: float, answer: bool = True) -> str:
        """The length of a vector on the drawing at the polygon's scale."""
        if self.scale is None or not math.isfinite(magnitude):
            return ""
        n = magnitude / (self.scale.value * self.scale.factor)
        s = f"{fmt(_round(n), 3)} {self.scale.paper}"
        return f"⟦{s}⟧" if answer else s

    def scale_text(self) -> str:
        return "" if self.scale is None else self.scale.text

    def rate(self, label: str) -> tuple[str, bool]:
        """(ω3 = 4.6 rad/s ccw, given?) of an angular rate label."""
        v = self.scalar(label)
        given = label in self.given_rates
        kind = "w" if label.startswith("ω") else "a"
        if not math.isfinite(v):
            return f"{label} = —", given
        sense = "" if abs(v) < 1e-12 * (1 + abs(v)) else (" ccw" if v > 0 else " cw")
        s = f"{fmt(_round(abs(v)), 4)} {'rad/s' if kind == 'w' else 'rad/s²'}{sense}"
        return (f"{label} = {s}" if given else f"{label} = ⟦{s}⟧"), given

    def vec(self, label: str) -> np.ndarray | None:
        """A vector of the plane: the image minus the pole, or a vector value."""
        v = self.raw(label)
        if v is None:
            return None
        if v.shape == (2,):
            return v
        p = self.xy(label)
        pole = self.xy("o_a" if self.accel else "o_v")
        if p is None or pole is None:
            return None
        return p - pole

    def between(self, a: str, b: str, diagram: str | None = None) -> np.ndarray | None:
        pa, pb = self.xy(a, diagram), self.xy(b, diagram)
        if pa is None or pb is None:
            return None
        return pb - pa

    def vq(self, v: np.ndarray | None, answer: bool = True) -> str:
        """A vector's size and direction: ``31.4 ft/s ∠210.0°``."""
        if v is None:
            return "—"
        m = float(np.hypot(*v))
        s = f"{fmt(_round(m / self.f), 4)} {self.L}/s{'²' if self.accel else ''}"
        tiny = 1e-9 * (self.scale.value * self.scale.factor if self.scale is not None else 1.0)
        if m > tiny:
            s += f" ∠{_deg(v)}"
        return f"⟦{s}⟧" if answer else s

    # ---- structure --------------------------------------------------------
    def helper(self, step: Step) -> bool:
        """A step that only places the image of a helper point."""
        if self.mech is None:
            return False
        helpers = self.mech.helper_points
        if not helpers:
            return False
        for o in step.outputs:
            name, _ = _image_point(o)
            if o.startswith(("v(", "a(")) and name in helpers:
                used = [c for c in self.consumers.get(o, [])
                        if not all(_image_point(x)[0] in helpers for x in c.outputs)]
                return not used
        return False

    def groups(self) -> list[list[Step]]:
        """The construction steps grouped into the acts of the page."""
        out: list[list[Step]] = []
        pending: list[Step] = []
        start: list[Step] = []
        polygon = self.diagram in ("velocity", "acceleration")
        given = [s for s in self.cx.steps if self.own is not None and s.index not in self.own]
        for s in self.cx.steps:
            if self.helper(s) or s in given:
                continue
            if s.op in ("point", "scalar", "input") and s.role.value == "given" and not out \
                    and not pending and (polygon or s.op != "input"):
                start.append(s)
                continue
            if start:
                out.append(start)
                start = []
            if polygon and s.op in PREPARATORY:
                pending.append(s)
                continue
            out.append([*pending, s])
            pending = []
        if start:
            out.append(start)
        if pending:
            if out:
                out[-1].extend(pending)
            else:
                out.append(pending)
        return [given, *out] if given else out

    def downstream(self, label: str) -> tuple[Step, int] | None:
        """The step with an equation that ``label`` leads to, and through which input."""
        seen = {label}
        frontier = [label]
        while frontier:
            lab = frontier.pop(0)
            for c in self.consumers.get(lab, []):
                if c.op == "meet" and c.equation is not None:
                    return c, c.inputs.index(lab)
                if c.op in ("add_along",) and c.diagram == self.diagram:
                    return c, 0
                for o in c.outputs:
                    if o not in seen:
                        seen.add(o)
                        frontier.append(o)
        return None

    def lhs_of(self, step: Step) -> Term:
        """The vector a result step finds: ``v(C)`` -> V_C(??)."""
        name, link = _image_point(step.outputs[0])
        sym = "A" if self.accel else "V"
        return Term(f"{sym}_{point_name(name)}{link}", U, U)

    def book(self, name: str) -> str:
        """An apparent vector named as the book does (Eqs. 3.6, 4.16).

        ``V_A/4`` -> ``V_A3/4``, ``A_A/4^c`` -> ``A_A3A4^c``.
        """
        m = re.fullmatch(r"([VA])_([A-Z][A-Za-z]*)(\d*)/(\w+)(?:\^([ct]))?", name)
        if m is None:
            return name
        sym, P, digits, k, sup = m.groups()
        own = "" if digits else self._own_link(P, k)
        if sup == "c":
            return f"A_{P}{digits or own}{P}{k}^c"
        return f"{sym}_{P}{digits or own}/{k}" + (f"^{sup}" if sup else "")

    def sides_of(self, step: Step) -> list[tuple[Term, ...]] | None:
        """The equation of a result step, its left side included.

        Apparent vectors are named as the book does.
        """
        out = self._sides_of(step)
        if out is None:
            return None
        return [tuple(Term(self.book(t.name), t.magnitude, t.direction, t.sign) for t in side)
                for side in out]

    def _sides_of(self, step: Step) -> list[tuple[Term, ...]] | None:
        eq = step.equation
        if step.op == "meet" and eq is not None:
            return [(self.lhs_of(step),), eq.lhs, eq.rhs]
        if step.op == "add_along" and eq is None and self.accel:
            return self.accel_along_sides(step)
        if eq is None:
            return None
        return [eq.lhs, eq.rhs]

    def accel_along_sides(self, step: Step) -> list[tuple[Term, ...]] | None:
        """A_P = A_Pk + A^c + A_P/k (the slider's input), from the velocity step's equation."""
        vcx = self.src.constructions.get("velocity")
        if vcx is None:
            return None
        vl = "v(" + step.outputs[0][2:]
        vs = next((s for s in vcx.steps if vl in s.outputs), None)
        if vs is None or vs.equation is None or len(vs.equation.rhs) < 2:
            return None
        lhs = tuple(Term("A" + t.name[1:], t.magnitude, t.direction, t.sign)
                    for t in vs.equation.lhs)
        base, rel = vs.equation.rhs[0], vs.equation.rhs[1]
        rhs = [Term("A" + base.name[1:])]
        chain = self.makers.get(step.inputs[0])
        if chain is not None and any(self.makers.get(i) is not None
                                     and self.makers[i].op == "coriolis"
                                     for i in chain.inputs):
            rhs.append(Term("A" + rel.name[1:] + "^c"))
        rhs.append(Term("A" + rel.name[1:] + "^t"))
        return [lhs, tuple(rhs)]

    # ---- telling ------------------------------------------------------------
    def tell(self) -> list[PageStep]:
        out = []
        for group in self.groups():
            ps = self.tell_group(group)
            ps.steps = tuple(s.index for s in group)
            ps.main = group[-1].index
            out.append(ps)
        if self.own is not None and out and out[0].steps[0] in self.own:
            # a figure that starts from nothing given: what it is for, before its first step
            out[0].text = f"{PANEL_INTRO.get(self.diagram, '')} {out[0].text}".strip()
        return out

    def tell_group(self, group: list[Step]) -> PageStep:
        polygon = self.diagram in ("velocity", "acceleration")
        lead = group[-1]
        if self.own is not None and group[0].index not in self.own:
            return given_step(group, self.diagram)
        if not polygon:
            if self.diagram == "posture" and lead.op in ("rigid", "intersect_circles"):
                ps = self.tell_generic(group)
                getattr(self, f"posture_{lead.op}")(lead, ps)
                return ps
            if len(group) > 1 and all(s.op in ("point", "scalar") for s in group):
                names = [point_name(o) for s in group if s.op == "point" for o in s.outputs]
                ps = self.tell_generic(group)
                what = "fixed points" if self.diagram == "posture" else "points"
                ps.title = f"The {what} {', '.join(names)}" if names else ps.title
                return ps
            return self.tell_generic(group)
        prep = [s for s in group if s.op in PREPARATORY and s.op != "join"]
        if lead.op in ("point", "scalar", "input") and all(
                s.op in ("point", "scalar", "input") for s in group):
            return self.tell_start(group)
        if prep:
            fn = getattr(self, f"tell_{prep[-1].op}")
            return fn(prep[-1], lead)
        fn = getattr(self, f"tell_{lead.op}", None)
        if fn is None:
            return self.tell_generic(group)
        return fn(lead)

    def tell_generic(self, group: list[Step]) -> PageStep:
        """A step told from its own note (posture, instant centers, curvature)."""
        lead = group[-1]
        notes = [s.note for s in group if s.note]
        title = _first_sentence(notes[-1]) if notes else \
            _OP_WORDS.get(lead.op, lead.op.replace("_", " ")).capitalize()
        if lead.op == "circle_on_diameter" and len(lead.inputs) == 2 \
                and re.fullmatch(r"[A-Za-z ]+", lead.outputs[0]):
            # name the diameter by its own end points (the Bresse circle's is I and E*, not
            # the coupler point E)
            a, b = (point_name(x) for x in lead.inputs)
            title = f"Draw the {lead.outputs[0]} on the diameter {a}{b}"
            notes = [re.sub(r"^Draw the [^:]*? on the diameter \w+(?=[:.]|\s\()", title, n)
                     for n in notes]
        sides = None
        if lead.equation is not None:
            sides = [lead.equation.lhs, lead.equation.rhs]
        numbers = []
        for s in group:
            numbers.extend(self.posture_numbers(s))
            if self.own is not None or self.diagram == "curvature":
                numbers.extend(curvature_numbers(s, lambda lab: self.xy(lab, "posture"),
                                                 self.unit_file))
        text = " ".join(notes)
        if notes and text.startswith(title):
            text = text[len(title):].lstrip(".;: ")
        if not text and self.sections:
            text = why(lead, self.sections.get(lead.outputs[0]) if lead.outputs else None)
        if self.sections and "a" <= text[:1] <= "z":  # a curvature note's rest, a sentence
            text = text[0].upper() + text[1:]
        return PageStep(title, sides, None if lead.equation is None else lead.equation.case,
                        text=text, numbers=numbers, refs=_REFS.get(self.diagram, ""),
                        vector=sides is not None)

    def posture_rigid(self, s: Step, ps: PageStep) -> None:
        """A point of a link laid off from a known point at the link's angle (case 1)."""
        a, th = s.inputs[0], s.inputs[1]
        b = s.outputs[0]
        A, B = point_name(a), point_name(b)
        link = th[1:] if th.startswith("θ") else ""
        r = self.dist(a, b)
        ps.title = f"Position of {B}: R_{B} = R_{A} + R_{B}{A}"
        ps.text = (f"{B} is a point of link {link}: lay off {A}{B} from {A} at the link's angle "
                   f"(case 1: R_{B}{A} is known in size and direction).")
        ps.numbers.insert(0, f"R_{B}{A} = {fmt(_round(r), 4)} {self.unit_file} at {th}.")
        ps.refs = "Sec. 2.8, Table 2.2 (case 1)"

    def posture_intersect_circles(self, s: Step, ps: PageStep) -> None:
        """Two arcs meet (case 4)."""
        c = s.outputs[0]
        C = point_name(c)
        centers = []
        for k in s.inputs:
            m = self.makers.get(k)
            if m is not None and m.inputs:
                centers.append((point_name(m.inputs[0]), float(m.params.get("radius", math.nan))))
        if len(centers) == 2:
            (P, rp), (Q, rq) = centers
            ps.title = f"Position of {C}: R_{C} = R_{P} + R_{C}{P} = R_{Q} + R_{C}{Q}"
            ps.text = (f"{C} is {P}{C} = {fmt(rp, 4)} {self.unit_file} from {P} and {Q}{C} = "
                       f"{fmt(rq, 4)} {self.unit_file} from {Q}: where the two arcs cross (case 4, "
                       "both directions unknown). Of the two crossings the "
                       f"{s.branch or 'chosen'} one is the linkage as assembled.")
            eq = s.equation
            if eq is not None and len(eq.lhs) == 1 and len(eq.rhs) == 1:
                ps.sides = [(Term(f"R_{C}", U, U),), (Term(f"R_{P}"), eq.lhs[0]),
                            (Term(f"R_{Q}"), eq.rhs[0])]
                ps.case = 4
        ps.refs = "Sec. 2.8, Fig. 2.14, Table 2.2 (case 4)"

    def posture_numbers(self, s: Step) -> list[str]:
        """The numbers of a step drawn on the mechanism: a point found, an angle measured."""
        out: list[str] = []
        if s.role.value == "given" or plane(s.diagram) != "posture":
            return out
        for o in s.outputs:
            v = self.raw(o)
            if v is None:
                continue
            if s.kind == "point" and v.shape == (3,):
                if abs(v[2]) > 1e-12:
                    xy = v[:2] / v[2]
                    out.append(f"{point_name(o)} = ⟦({fmt(_round(xy[0]), 4)}, "
                               f"{fmt(_round(xy[1]), 4)}) {self.unit_file}⟧.")
                elif np.all(np.isfinite(v[:2])):
                    out.append(f"{point_name(o)} is at infinity, in the direction "
                               f"⟦{_deg_line(v[:2])}⟧.")
            elif s.kind == "scalar" and v.shape == () and o.startswith("θ"):
                d = math.degrees(float(v)) % 360.0
                out.append(f"{o} = ⟦{d:.2f}°⟧.")
            elif s.kind == "circle" and v.shape == (3,):
                r = f"{fmt(_round(float(v[2])), 4)} {self.unit_file}"
                known = "radius" in s.params
                out.append(f"Radius {r}." if known else f"Radius ⟦{r}⟧.")
        return out

    def tell_start(self, group: list[Step]) -> PageStep:
        pole = "O_A" if self.accel else "O_V"
        fixed = []
        if self.mech is not None:
            fixed = [n for n in self.mech.links[FRAME].points
                     if n not in self.mech.helper_points]
        what = "acceleration" if self.accel else "velocity"
        text = (f"Choose a point {pole}, the pole of the {what} polygon: it is the image of "
                f"every fixed point ({', '.join(fixed) or 'the frame'}), whose {what} is zero. "
                f"Choose a scale for the {_PLURAL[what]}")
        text += f": {self.scale_text()}." if self.scale is not None else "."
        numbers = []
        for s in group:
            if s.op != "input":
                continue
            lab = s.outputs[0]
            if lab[:1] in ("ω", "α"):
                t, _ = self.rate(lab)
                extra = ""
                d = self._drive_of(lab)
                if d is not None and lab.startswith("ω") and d.rate is not None:
                    extra = f" ({fmt(abs(d.rate) * 60 / (2 * math.pi), 4)} rev/min)"
                numbers.append(f"Given: {t}{extra}.")
            else:
                v = self.scalar(lab)
                kind = "A" if lab.startswith("dds") else "V"
                link = lab.lstrip("ds")
                # the book gives a slider's point velocity, V_C = -10 î m/s (Example 3.2),
                # relative to the link it slides on when that link moves (V_A3/2, Sec. 3.5)
                sl = next((x for x in self.mech.sliders if x.link == link), None) \
                    if self.mech is not None else None
                sym = "ṡ" if sl is None else \
                    f"{kind}_{sl.point}" + ("" if sl.on == FRAME else f"{link}/{sl.on}")
                numbers.append(f"Given: {sym} = {self.q(v, kind, False)} along the line of "
                               f"slider {link} (positive from its first point to its second).")
        title = f"The {what} pole {pole} and the scale"
        if numbers:
            title += "; the input"
        return PageStep(title, text=text, numbers=numbers,
                        refs="Sec. 4.4" if self.accel else "Sec. 3.4")

    def _drive_of(self, label: str) -> Any:
        if self.mech is None:
            return None
        for d in self.mech.drives:
            if label[1:] == d.link and d.kind == "angle":
                return d
        return None

    def _own_link(self, P: str, k: str) -> str:
        mech = self.mech
        if mech is None:
            return ""
        lined: list[Slider | Slot] = [*mech.sliders, *mech.slots]
        for sl in lined:
            if sl.point == P and sl.on == k:
                return sl.link
        for sl in lined:
            if sl.on == k and P in mech.links[sl.link].points:
                return sl.link
        links = [lid for lid in mech.point_links.get(P, []) if lid not in (k, FRAME)]
        return links[0] if links else ""
