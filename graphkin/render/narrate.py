"""Narration: the recorded construction steps told in the book's words, with their numbers.

A teaching page walks through a construction the way Uicker, Pennock &
Shigley work their examples: each step has a title in words ("Velocity of C:
V_C = V_B + V_CB"), the vector equation it solves or uses with ✓/? over
every vector (its left side included), one or two sentences saying what is
drawn and why, and the numbers — the known magnitude computed
(A^n_CB = V_CB²/R_CB = (38.4 ft/s)²/(1.5 ft) = 983 ft/s²), its length on the
drawing at the chosen scale, and the result read off once it is found.

The recorded steps are not renamed (other code keys on their labels); this
module reads them — their operation, inputs, outputs and equation — and the
values of the solved construction, and groups the small preparatory acts
(the posture line a perpendicular is drawn to, a component before it is laid
off) with the step they serve.  Steps that only place helper points (points
that only define a slider's line or a slot) are left out.

Numbers the student is to find are marked ``⟦...⟧`` in the text; the page
shows them behind a "show answers" toggle (:func:`answer_html`), and
:func:`plain` removes the marks.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Table 2.2, the ✓/? marks),
3.3-3.7 (velocity difference, polygons and images, apparent velocity, rolling
contact), 4.3-4.7 (acceleration difference, polygons, Coriolis component,
rolling contact).
"""

from __future__ import annotations

import html
import math
import re
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.construction import Construction, Mark, Step, Term
from graphkin.mechanisms.model import FRAME, Mechanism, Slider, Slot
from graphkin.render.scale import Scale, fmt

__all__ = ["PageStep", "narrate", "helper_steps", "plain", "answer_html", "vector_html",
           "point_name", "image_letter", "PREPARATORY"]

K, U = Mark.KNOWN, Mark.UNKNOWN

PREPARATORY = ("join", "normal_component", "coriolis", "rolling_normal", "apparent_normal")
"""Operations that only prepare the next step (a line to be perpendicular to, a component
to lay off): narrated together with the step that uses them."""

_ANSWER = re.compile(r"⟦(.*?)⟧")
_SUBS = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def plain(text: str) -> str:
    """Text without the answer marks.

    Examples
    --------
    >>> plain("ω3 = ⟦4.6 rad/s⟧ ccw")
    'ω3 = 4.6 rad/s ccw'
    """
    return _ANSWER.sub(r"\1", text)


def answer_html(text: str) -> str:
    """Escape text for HTML and wrap each ``⟦answer⟧`` in ``<span class="answer">``.

    Examples
    --------
    >>> answer_html("V = ⟦3 < 4⟧")
    'V = <span class="answer"><span class="val">3 &lt; 4</span></span>'
    """
    out = []
    pos = 0
    for m in _ANSWER.finditer(text):
        out.append(_sym_html(text[pos:m.start()]))
        out.append(f'<span class="answer"><span class="val">{_sym_html(m.group(1))}'
                   "</span></span>")
        pos = m.end()
    out.append(_sym_html(text[pos:]))
    return "".join(out)


def _sym_html(text: str) -> str:
    """Escape text and write vector names (``A_CB^n``) with sub- and superscripts."""
    esc = html.escape(text)

    def vec(m: re.Match[str]) -> str:
        base, sup1, sub, sup2 = m.groups()
        sup = sup1 or sup2
        return vector_html(f"{base}_{sub}" + (f"^{sup}" if sup else ""))

    esc = re.sub(r"\b([VAR])(?:\^([ntcr]))?_([A-Za-z0-9]+(?:/\d+)?)(?:\^([ntcr]))?", vec, esc)
    esc = re.sub(r"\bO_([VA])\b", r"<i>O</i><sub>\1</sub>", esc)
    return re.sub(r"([ωα])(\d+)", r"\1<sub>\2</sub>", esc)


def vector_html(name: str) -> str:
    """A vector's name in HTML: ``A_CB^n`` -> ``A<sup>n</sup><sub>CB</sub>``.

    Examples
    --------
    >>> vector_html("A_CB^n")
    '<i>A</i><sup>n</sup><sub>CB</sub>'
    """
    base, _, rest = name.partition("_")
    sub, _, sup = rest.partition("^")
    out = f"<i>{html.escape(base)}</i>"
    if sup:
        out += f"<sup>{html.escape(sup)}</sup>"
    if sub:
        out += f"<sub>{html.escape(sub)}</sub>"
    return out


def point_name(label: str) -> str:
    """The letter of a point as the book prints it: ``rolling[0]:C`` -> ``C``."""
    return label.split("#")[0].split(":")[-1]


def image_letter(label: str) -> str:
    """The letter of an image: ``v(B)`` -> ``b``, ``a(C)`` -> ``c′``, ``v(A@4)`` -> ``a₄``.

    Examples
    --------
    >>> image_letter("v(B)"), image_letter("a(A@4)"), image_letter("o_v"), image_letter("o_a")
    ('b', 'a′₄', 'O_V', 'O_A')
    """
    if label == "o_v":
        return "O_V"
    if label == "o_a":
        return "O_A"
    prime = label.startswith("a(")
    inner = label[2:-1] if label.endswith(")") else label
    name, _, link = inner.partition("@")
    base = point_name(name)
    i = len(base)
    while i > 0 and base[i - 1].isdigit():
        i -= 1
    letters, digits = (base[:i] or base), (base[i:] if i else "")
    return letters.lower() + ("′" if prime else "") + (digits + link).translate(_SUBS)


def _image_point(label: str) -> tuple[str, str]:
    """``v(A@4)`` -> (``A``, ``4``); ``a(C)`` -> (``C``, ``""``)."""
    inner = label[2:-1] if label.endswith(")") and label[1:2] == "(" else label
    name, _, link = inner.partition("@")
    return name, link


@dataclass
class PageStep:
    """One step of a teaching page: one or more construction steps, told as one act.

    Attributes
    ----------
    title : str
        In words, with the vector equation or formula it is about.
    sides : list of tuple of Term, or None
        The vector equation as sides joined by ``=`` (three sides where two
        lines meet: V_C = V_B + V_CB = V_D + V_CD), each vector with its marks.
    case : int or None
        The case of Table 2.2.
    formula : str
        A scalar relation shown in place of a vector equation (ω3 = V_CB/R_CB).
    text : str
        What is drawn and why, in one or two sentences (answers marked ⟦⟧).
    numbers : list of str
        The numbers: given values, the computed magnitude, its length on the
        drawing, the result read off (answers marked ⟦⟧).
    refs : str
        Section, equation and figure of the book.
    steps : tuple of int
        The construction steps it covers.
    main : int
        The construction step it draws up to (its last).
    vector : bool
        The step finds or uses a vector (it then always has an equation).
    answers : list of str
        Labels of scalars found here whose values the drawing prints (ω3), for
        the answers toggle.
    """

    title: str
    sides: list[tuple[Term, ...]] | None = None
    case: int | None = None
    formula: str = ""
    text: str = ""
    numbers: list[str] = field(default_factory=list)
    refs: str = ""
    steps: tuple[int, ...] = ()
    main: int = 0
    vector: bool = False
    answers: list[str] = field(default_factory=list)

    def equation_text(self) -> str:
        """The equation as plain text with marks: ``V_C(??) = V_B(✓✓) + V_CB(?✓)``."""
        if not self.sides:
            return self.formula

        def side(ts: tuple[Term, ...]) -> str:
            out = ""
            for i, t in enumerate(ts):
                op = ("−" if t.sign < 0 else "") if i == 0 else (" − " if t.sign < 0 else " + ")
                out += op + str(t)
            return out

        return " = ".join(side(s) for s in self.sides)


# ---------------------------------------------------------------------------------------------


class _Teller:
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
        for s in self.cx.steps:
            if self.helper(s):
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
        return out

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
        return out

    def tell_group(self, group: list[Step]) -> PageStep:
        polygon = self.diagram in ("velocity", "acceleration")
        lead = group[-1]
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
        text = " ".join(notes)
        if notes and text.startswith(title):
            text = text[len(title):].lstrip(".;: ")
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
                numbers.append(f"Given: the slider {link} moves along its line at "
                               f"{'s̈' if kind == 'A' else 'ṡ'} = {self.q(v, kind, False)}.")
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

    # a point of a link from another point of it (case 1)
    def tell_velocity_difference(self, s: Step) -> PageStep:
        img, w, a, x = s.inputs
        name, link = _image_point(s.outputs[0])
        P, A = point_name(x), point_name(a)
        Pk = f"{P}{link}"
        r = self.dist(a, x)
        wv = self.scalar(w)
        rate, given = self.rate(w)
        vrel = abs(wv) * r
        sides = self.sides_of(s)
        who = (f"Velocity of {Pk}, the point of link {link} at {P}" if link
               else f"Velocity of {P}")
        sense = "counterclockwise" if wv > 0 else "clockwise"
        text = (f"V_{P}{A} = ω{w[1:]} × R_{P}{A} is perpendicular to {A}{P}, R_{P}{A} turned 90° "
                f"{sense} (the sense of ω{w[1:]}). Lay it off from {image_letter(img)}: its tip "
                f"is {image_letter(s.outputs[0])}, the tip of V_{Pk}.")
        numbers = [f"{rate}{' (given)' if given else ''}.",
                   f"V_{P}{A} = ω{w[1:]} R_{P}{A} = ({_wtext(rate)})({self.length(a, x)}) = "
                   f"{self.q(vrel, 'V')}; at {self.scale_text()} lay off {self.paper(vrel)}.",
                   f"V_{Pk} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{who}: V_{Pk} = V_{A} + V_{P}{A}", sides, 1, text=text,
                        numbers=numbers, refs="Sec. 3.3, Eq. 3.4; Sec. 3.4", vector=True)

    def tell_acceleration_difference(self, s: Step) -> PageStep:
        img, w, al, a, x = s.inputs
        name, link = _image_point(s.outputs[0])
        P, A = point_name(x), point_name(a)
        Pk = f"{P}{link}"
        r = self.dist(a, x)
        wv, av = self.scalar(w), self.scalar(al)
        wt, _ = self.rate(w)
        at, _ = self.rate(al)
        an, atn = wv * wv * r, abs(av) * r
        who = (f"Acceleration of {Pk}, the point of link {link} at {P}" if link
               else f"Acceleration of {P}")
        text = (f"A^n_{P}{A} = ω² R points from {P} toward {A}; A^t_{P}{A} = α × R is "
                f"perpendicular to {A}{P}. Lay off A^n_{P}{A} from {image_letter(img)}, then "
                f"A^t_{P}{A} from its tip: the end is {image_letter(s.outputs[0])}.")
        numbers = [f"{wt}, {at}.",
                   f"A^n_{P}{A} = ω{w[1:]}² R_{P}{A} = ({_wtext(wt)})²({self.length(a, x)}) = "
                   f"{self.q(an, 'A')}; lay off {self.paper(an)} (at {self.scale_text()}).",
                   f"A^t_{P}{A} = α{al[1:]} R_{P}{A} = ({_wtext(at)})({self.length(a, x)}) = "
                   f"{self.q(atn, 'A')}; lay off {self.paper(atn)}.",
                   f"A_{Pk} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{who}: A_{Pk} = A_{A} + A^n_{P}{A} + A^t_{P}{A}", self.sides_of(s), 1,
                        text=text, numbers=numbers,
                        refs="Sec. 4.3, Eqs. 4.6, 4.7, 4.11; Sec. 4.4", vector=True)

    # a direction line through a known image
    def _line(self, s: Step, kind: str) -> PageStep:
        ds = self.downstream(s.outputs[0])
        through = s.inputs[1]
        ref = s.inputs[0]
        sides: list[tuple[Term, ...]] | None = None
        unknown = None
        if ds is not None:
            meet, i = ds
            full = self.sides_of(meet)
            if full is not None and len(full) == 3:
                side = full[1 + min(i, 1)]
                sides = [full[0], side]
                unknown = next((t for t in side if t.magnitude == U), None)
        vname = unknown.name if unknown is not None else ("A^t" if self.accel else "V")
        vname = self.book(vname)
        letter = image_letter(through)
        if through in ("o_v", "o_a"):
            fixed = self._fixed_name(ref)
            if fixed:
                letter = f"{letter} (the image of {fixed})"
        tip = letter
        m = self.makers.get(through)
        if m is not None and m.op in ("translate", "subtract") and len(m.inputs) > 1:
            tip = f"the tip of {_pretty(self.book(m.inputs[1]))}" if m.op == "translate" \
                else f"the tail of {_pretty(self.book(m.inputs[1]))}"
        if kind == "perpendicular":
            p, q = self._posture_pair(ref)
            why = (f"{_pretty(vname)} is perpendicular to {p}{q}" if p else
                   f"{_pretty(vname)} has a known direction")
            if self.accel and unknown is not None and unknown.name.endswith("^t"):
                why += " (its size, α × R, is not known yet)"
            else:
                why += " but its size is not known yet"
            text = (f"{why}. Through {tip} draw a line perpendicular to {p}{q}: the sought "
                    "image lies on it.")
            title = f"Direction of {_pretty(vname)}: perpendicular to {p}{q}"
        else:
            path = _path_words(ref)
            text = (f"{_pretty(vname)} is along {path}, its size unknown. Through {tip} draw a "
                    f"line parallel to {path}: the sought image lies on it.")
            title = f"Direction of {_pretty(vname)}: along {path}"
        numbers = []
        ln = self.raw(ref, "posture")
        if ln is None:
            ln = self.raw(ref)
        if ln is not None and ln.shape == (3,) and np.all(np.isfinite(ln[:2])):
            d = np.array([ln[1], -ln[0]])  # the direction of the line (a, b, c)
            if kind == "perpendicular":
                p, q = self._posture_pair(ref)
                numbers.append(f"{p}{q} lies at {_deg_line(d)} on the mechanism; the line "
                               f"through {letter if tip == letter else 'the tip'} is at "
                               f"{_deg_line(np.array([-d[1], d[0]]))}.")
            else:
                numbers.append(f"The {_path_words(ref)[4:]} lies at {_deg_line(d)}: so does the "
                               "line.")
        refs = "Sec. 4.4" if self.accel else "Sec. 3.4"
        if kind == "parallel":
            refs = "Sec. 4.5, Eq. 4.17" if self.accel else "Sec. 3.5, Eq. 3.6"
        return PageStep(title, sides, None, text=text, numbers=numbers, refs=refs, vector=True)

    def tell_perpendicular(self, s: Step) -> PageStep:
        return self._line(s, "perpendicular")

    def tell_parallel(self, s: Step) -> PageStep:
        return self._line(s, "parallel")

    def _posture_pair(self, line: str) -> tuple[str, str]:
        m = self.makers.get(line)
        if m is None:
            for cx in self.src.constructions.values():
                m = next((st for st in cx.steps if line in st.outputs), None)
                if m is not None:
                    break
        if m is None or m.op != "join":
            return "", ""
        return point_name(m.inputs[0]), point_name(m.inputs[1])

    def _fixed_name(self, ref: str) -> str:
        """The point whose image the pole is, for a line drawn through the pole."""
        p, _ = self._posture_pair(ref)
        return p

    # a known component laid off
    def tell_normal_component(self, s: Step, lay: Step) -> PageStep:
        p, c, vp, vc = s.inputs
        P, C = point_name(p), point_name(c)
        vrel = self.between(vp, vc, "velocity")
        v = float(np.hypot(*vrel)) if vrel is not None else math.nan
        r = self.dist(p, c)
        an = v * v / r if r > 0 else math.nan
        vec = self.raw(s.outputs[0])
        if vec is not None and vec.shape == (2,):
            an = float(np.hypot(*vec))
        name = s.outputs[0]
        ds = self.downstream(lay.outputs[0])
        sides = None
        if ds is not None:
            full = self.sides_of(ds[0])
            if full is not None and len(full) == 3:
                sides = [full[0], full[1 + min(ds[1], 1)]]
        _, link = _image_point(vc)
        vname = f"V_{C}{link}{P}" if link else f"V_{C}{P}"
        text = (f"The normal component {_pretty(name)} = V²/R is known from the velocity "
                f"polygon. It is parallel to {C}{P}, directed from {C} toward {P}. Lay it off "
                f"from {image_letter(lay.inputs[0])}.")
        numbers = [f"{_pretty(name)} = {vname}²/R_{C}{P} = ({self.q(v, 'V')})²/"
                   f"({self.length(p, c)}) = {self.q(an, 'A')}.",
                   f"At {self.scale_text()}: lay off {self.paper(an)} from "
                   f"{image_letter(lay.inputs[0])}, parallel to {C}{P}, toward {P}."]
        return PageStep(f"Normal component {_pretty(name)} = {vname}²/R_{C}{P}", sides, None,
                        text=text, numbers=numbers, refs="Sec. 4.3, Eq. 4.6; Sec. 4.4",
                        vector=True)

    def tell_coriolis(self, s: Step, lay: Step) -> PageStep:
        w, vp, vpk = s.inputs
        k = w[1:]
        P, _ = _image_point(vp)
        P = point_name(P)
        rel = self.book(f"V_{P}/{k}")
        vrel = self.between(vpk, vp, "velocity")
        v = float(np.hypot(*vrel)) if vrel is not None else math.nan
        wv = self.scalar(w)
        wt, _ = self.rate(w)
        ac = 2 * abs(wv) * v
        name = self.book(f"A_{P}/{k}^c")
        sense = "counterclockwise" if wv > 0 else "clockwise"
        sub = lay.op == "subtract"
        text = (f"{P} moves along a path that is fixed in link {k}, and the path turns with "
                f"link {k}: the Coriolis component uses ω{k}, the angular velocity of the link "
                f"that carries the path. It is {rel} turned 90° {sense} (the sense of ω{k}). "
                + ("It is subtracted: lay it off backward, ending at "
                   f"{image_letter(lay.inputs[0])}." if sub
                   else f"Lay it off from {image_letter(lay.inputs[0])}."))
        maker = self.src.constructions.get("velocity")
        given = False
        if maker is not None:
            vs = next((st for st in maker.steps if vp in st.outputs), None)
            given = vs is not None and vs.op == "add_along" and vs.inputs[3] in self.given_rates
        vt = self.q(v, "V", answer=not given)
        numbers = [f"{wt}; {rel} = {vt} "
                   f"({'given' if given else 'from the velocity polygon'}).",
                   f"{_pretty(name)} = 2 ω{k} {rel} = 2({_wtext(wt)})({vt}) = "
                   f"{self.q(ac, 'A')}; lay off {self.paper(ac)}."]
        ds = self.downstream(lay.outputs[0])
        sides = None
        if ds is not None:
            full = self.sides_of(ds[0])
            if full is not None:
                sides = [full[0], full[1 + min(ds[1], len(full) - 2)]] if len(full) == 3 \
                    else full
        return PageStep(f"Coriolis component {_pretty(name)} = 2ω{k} × {rel}", sides, None,
                        text=text, numbers=numbers, refs="Sec. 4.5, Eqs. 4.16, 4.17",
                        vector=True)

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

    def tell_apparent_normal(self, s: Step, lay: Step) -> PageStep:
        x, o, vx, vxk = s.inputs
        X = point_name(x)
        vec = self.raw(s.outputs[0])
        a = float(np.hypot(*vec)) if vec is not None and vec.shape == (2,) else math.nan
        rho = self.dist(o, x)
        text = (f"{X} moves on a curved path of radius ρ = {self.length(o, x)}: the apparent "
                "acceleration has a normal component V²/ρ toward the path's center of "
                f"curvature. Lay it off from {image_letter(lay.inputs[0])}.")
        vrel = self.between(vxk, vx, "velocity")
        v = float(np.hypot(*vrel)) if vrel is not None else math.nan
        numbers = [f"{_pretty(s.outputs[0])} = V²/ρ = ({self.q(v, 'V')})²/"
                   f"({self.q(rho, 'L', False)}) = {self.q(a, 'A')}; lay off {self.paper(a)}."]
        return PageStep(f"Apparent normal component {_pretty(s.outputs[0])} = V²/ρ", None, None,
                        text=text, numbers=numbers, refs="Sec. 4.5, Eq. 4.14", vector=True)

    def tell_rolling_normal(self, s: Step, lay: Step) -> PageStep:
        vec = self.raw(s.outputs[0])
        a = float(np.hypot(*vec)) if vec is not None and vec.shape == (2,) else math.nan
        name = s.outputs[0]
        sides = [lay.equation.lhs, lay.equation.rhs] if lay.equation is not None else None
        lhs = lay.equation.lhs[0].name if lay.equation is not None else "A_C"
        text = ("The wheel rolls without slip: the contact points have the same velocity, but "
                f"not the same acceleration. {_pretty(name)} is normal to the surfaces at the "
                "contact, toward the center of the rolling wheel. Lay it off from "
                f"{image_letter(lay.inputs[0])}: its tip is the image of the wheel's contact "
                "point.")
        numbers = [f"{_pretty(name)} = {self.q(a, 'A')}; lay off {self.paper(a)}.",
                   f"{_pretty(lhs)} = {self.vq(self.vec(lay.outputs[0]))}."]
        return PageStep(f"Rolling contact: {_pretty(lhs)} = {_pretty(lhs[:-1] + '1')} + "
                        f"{_pretty(name)}", sides, 1, text=text, numbers=numbers,
                        refs="Sec. 4.7, Eq. 4.19, Fig. 4.19", vector=True)

    # two lines meet
    def tell_meet(self, s: Step) -> PageStep:
        sides = self.sides_of(s)
        lhs = self.lhs_of(s)
        what = "Acceleration" if self.accel else "Velocity"
        name, link = _image_point(s.outputs[0])
        P = point_name(name)
        who = f"{what} of {P}{link}" + (f", the point of link {link} at {P}" if link else "")
        letter = image_letter(s.outputs[0])
        eq_words = " = ".join(_side_words(side) for side in (sides or []))
        title = f"{who}: {eq_words}" if sides else who
        numbers = []
        here = self.xy(s.outputs[0])
        for i, line in enumerate(s.inputs[:2]):
            if sides is None:
                break
            side = sides[1 + i]
            unk = next((t for t in side if t.magnitude == U), None)
            m = self.makers.get(line)
            thr = None
            if m is not None:
                thr = next((self.xy(x) for x in reversed(m.inputs)
                            if self.xy(x) is not None), None)
            if unk is None or thr is None or here is None:
                continue
            v = (here - thr) * unk.sign
            mag = float(np.hypot(*v))
            numbers.append(f"{_pretty(unk.name)} = {self.paper(mag)} on the drawing = "
                           f"{self.vq(v)}.")
        numbers.append(f"{_pretty(lhs.name)} = {self.vq(self.vec(s.outputs[0]))}.")
        text = (f"The two lines meet at {letter}: the only point that satisfies both sides of "
                f"the equation (case 3). Measure the vectors on the drawing and multiply by "
                f"the scale, {self.scale_text()}.")
        return PageStep(title, sides, 3, text=text, numbers=numbers,
                        refs=("Sec. 4.4, Fig. 4.8" if self.accel else "Sec. 3.4, Fig. 3.7")
                        + ("; Sec. 4.5" if self.accel and link else
                           "; Sec. 3.5" if link else ""), vector=True)

    def tell_angular_rate(self, s: Step) -> PageStep:
        a, b, ia, ib = s.inputs
        lab = s.outputs[0]
        k = lab[1:]
        A, B, Bn = point_name(a), point_name(b) + _image_point(ib)[1], point_name(b)
        r = self.dist(a, b)
        val = self.scalar(lab)
        t, _ = self.rate(lab)
        if self.accel:
            at = abs(val) * r
            formula = f"α{k} = A^t_{B}{A}/R_{Bn}{A}"
            numbers = [f"A^t_{B}{A} = {self.q(at, 'A')} (the tangential component, read off).",
                       f"α{k} = ({self.q(at, 'A')})/({self.length(a, b)}) = "
                       f"{t.split(' = ', 1)[1]}."]
            text = (f"The tangential component A^t_{B}{A} = α{k} × R_{Bn}{A} gives α{k}; its "
                    f"sense is the sense in which A^t_{B}{A}, drawn at {B}, turns {B} about {A}.")
            title = f"Angular acceleration of link {k}: {formula}"
            refs = "Sec. 4.3, Eq. 4.7"
        else:
            v = abs(val) * r
            formula = f"ω{k} = V_{B}{A}/R_{Bn}{A}"
            numbers = [f"V_{B}{A} = {self.q(v, 'V')} (read off the polygon).",
                       f"ω{k} = ({self.q(v, 'V')})/({self.length(a, b)}) = "
                       f"{t.split(' = ', 1)[1]}."]
            text = (f"V_{B}{A} = ω{k} × R_{Bn}{A}: its size divided by the length {A}{B} gives "
                    f"ω{k}; its sense is the sense in which V_{B}{A}, drawn at {B}, turns {B} "
                    f"about {A}.")
            if "rolling" in a or "rolling" in b:
                text = (f"No slip: the wheel's contact point has the velocity of the surface "
                        f"it rolls on, so the wheel turns about it for now. {text}")
            title = f"Angular velocity of link {k}: {formula}"
            refs = "Sec. 3.3, Eq. 3.3"
        return PageStep(title, None, None, formula=formula, text=text, numbers=numbers,
                        refs=refs, vector=True, answers=[lab])

    def tell_add_angle(self, s: Step) -> PageStep:
        lab = s.outputs[0]
        src_ = s.inputs[0]
        k, j = lab[1:], src_[1:]
        t, _ = self.rate(lab)
        sym = lab[:1]
        formula = f"{sym}{k} = {sym}{j}"
        what = "velocity" if sym == "ω" else "acceleration"
        text = (f"The slider {k} cannot turn relative to its guide {j}: it has the angular "
                f"{what} of the guide.")
        return PageStep(f"Angular {what} of link {k}: {formula}", None, None, formula=formula,
                        text=text, numbers=[f"{t}."],
                        refs="Sec. 3.6, Eq. 3.11" if sym == "ω" else "Sec. 4.6, Eq. 4.18",
                        answers=[lab])

    def tell_similar(self, s: Step) -> PageStep:
        a, b = s.inputs[:2]
        name, _ = _image_point(s.outputs[0])
        P = point_name(name)
        A, B = _image_point(a)[0] if a not in ("o_v", "o_a") else "", _image_point(b)[0]
        if not A:
            A = self._fixed_of_image(s) or "the pivot"
        sym = "A" if self.accel else "V"
        what = "acceleration" if self.accel else "velocity"
        la, lb, lp = image_letter(a), image_letter(b), image_letter(s.outputs[0])
        if a in ("o_v", "o_a"):
            la = point_name(A).lower() + ("′" if self.accel else "")
            at = f" ({la} is at {image_letter(a)})"
        else:
            at = ""
        sides = [(Term(f"{sym}_{P}", U, U),), (Term(f"{sym}_{point_name(A)}"),
                                                Term(f"{sym}_{P}{point_name(A)}"))]
        text = (f"The {what} image of a link is similar to the link (Sec. "
                f"{'4.4' if self.accel else '3.4'}): draw the triangle {la}{lb}{lp} similar to "
                f"{point_name(A)}{point_name(B)}{P}{at}, lettered in the same order and sense. "
                f"{lp} is the tip of {sym}_{P}.")
        numbers = [f"{sym}_{P} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{what.capitalize()} of {P} from the {what} image: "
                        f"{sym}_{P} = {sym}_{point_name(A)} + {sym}_{P}{point_name(A)}", sides, 1,
                        text=text, numbers=numbers,
                        refs="Sec. 4.4" if self.accel else "Sec. 3.4, Fig. 3.6", vector=True)

    def _fixed_of_image(self, s: Step) -> str:
        mech = self.mech
        if mech is None:
            return ""
        name, _ = _image_point(s.outputs[0])
        for lid in mech.point_links.get(name, []):
            for n in mech.links[lid].points:
                if n in mech.links[FRAME].points:
                    return n
        return ""

    def tell_add_along(self, s: Step) -> PageStep:
        sides = self.sides_of(s)
        base = s.inputs[0]
        rate = s.inputs[3]
        v = self.scalar(rate)
        name, _ = _image_point(s.outputs[0])
        P = point_name(name)
        sym = "A" if self.accel else "V"
        kind = "A" if self.accel else "V"
        what = "Acceleration" if self.accel else "Velocity"
        words = " + ".join(_pretty(t.name) for t in sides[1]) if sides else ""
        text = (f"{P} slides along its line at the given "
                f"{'acceleration' if self.accel else 'speed'}: lay it off along the slide from "
                f"{image_letter(base) if ':' not in base else 'the tip of the last vector'}; "
                f"the end is {image_letter(s.outputs[0])}.")
        numbers = [f"Given: {self.q(abs(v), kind, False)} along the slide; at "
                   f"{self.scale_text()} lay off {self.paper(abs(v), False)}.",
                   f"{sym}_{P} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{what} of {P}: {sym}_{P} = {words}", sides, 1, text=text,
                        numbers=numbers,
                        refs="Sec. 4.5, Eq. 4.17" if self.accel else "Sec. 3.5, Eq. 3.6",
                        vector=True)

    def tell_translate(self, s: Step) -> PageStep:
        return self.tell_generic([s])


_PLURAL = {"velocity": "velocities", "acceleration": "accelerations"}

_OP_WORDS = {
    "point": "point", "circle": "arc", "intersect_circles": "two arcs meet at",
    "intersect_line_circle": "a line and an arc meet at", "join": "line",
    "meet": "two lines meet at", "perpendicular": "perpendicular", "parallel": "parallel",
    "input": "the input", "rigid": "point of the link", "similar": "image",
}

_REFS = {"posture": "Sec. 2.8, Fig. 2.14", "centers": "Sec. 3.13-3.14",
         "curvature": "Sec. 4.12-4.15"}


def plane(diagram: str) -> str:
    """The plane of a diagram (``velocity``, ``acceleration`` or ``posture``)."""
    return diagram if diagram in ("velocity", "acceleration") else "posture"


def _round(x: float) -> float:
    """A number rid of round-off noise (for printing)."""
    return 0.0 if abs(x) < 1e-12 else x


def _deg(v: np.ndarray) -> str:
    d = math.degrees(math.atan2(float(v[1]), float(v[0]))) % 360.0
    if d > 180.0:
        d -= 360.0
    return f"{d:.1f}°"


def _first_sentence(note: str) -> str:
    """The first sentence of a note, as a title (without its final period)."""
    m = re.match(r"(.+?(?<!\bEq)(?<!\bEqs)(?<!\bFig)(?<!\bFigs)(?<!\bSec)[.;])(\s|$)", note)
    first = (m.group(1) if m else note).rstrip(".;")
    head, colon, _ = first.partition(": ")
    if colon and len(head.split()) >= 3 and head.count("(") == head.count(")"):
        first = head
    if len(first) > 80 and " (" in first:  # the parenthesis stays in the text
        first = first[:first.index(" (")]
    return first[0].upper() + first[1:] if first else note


def _deg_line(d: np.ndarray) -> str:
    """The angle of a line (not a vector) in [0°, 180°): ``20.9°``."""
    a = math.degrees(math.atan2(float(d[1]), float(d[0]))) % 180.0
    return f"{0.0 if a > 179.95 else a:.1f}° from the x axis"


def _wtext(rate: str) -> str:
    """``ω2 = 94.2 rad/s ccw`` -> ``94.2 rad/s`` (answer marks kept)."""
    value = rate.split(" = ", 1)[1] if " = " in rate else rate
    return value.replace(" ccw", "").replace(" cw", "")


def _pretty(name: str) -> str:
    """A vector name as text: ``A_CB^n`` -> ``A^n_CB`` (the book's order)."""
    base, _, rest = name.partition("_")
    sub, _, sup = rest.partition("^")
    if sup and sub:
        return f"{base}^{sup}_{sub}"
    return name


def _side_words(side: tuple[Term, ...]) -> str:
    out = ""
    for i, t in enumerate(side):
        op = ("−" if t.sign < 0 else "") if i == 0 else (" − " if t.sign < 0 else " + ")
        out += op + _pretty(t.name)
    return out


def _path_words(line: str) -> str:
    return "the slot" if line.startswith("slots") else "the slide"


def helper_steps(src: Any, diagram: str) -> set[int]:
    """Indices of the steps that only place the images of helper points (left off the page).

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.render.sources import as_source
    >>> src = as_source(graphkin.examples.coriolis_block().solve())
    >>> [src.constructions["velocity"][i].label for i in sorted(helper_steps(src, "velocity"))]
    ['v(X)']
    """
    t = _Teller(src, diagram, None)
    return {s.index for s in t.cx.steps if t.helper(s)}


def narrate(src: Any, diagram: str, scale: Scale | None = None) -> list[PageStep]:
    """The steps of a construction told in the book's words, with their numbers.

    Parameters
    ----------
    src : Source
        The solved mechanism and its evaluated constructions
        (:func:`graphkin.render.sources.as_source`).
    diagram : str
        ``velocity``, ``acceleration`` (told in full), or ``posture``,
        ``centers``, ``curvature`` (told from the steps' notes).
    scale : Scale, optional
        The scale the polygon is drawn at (lengths on the drawing are given at it).

    Returns
    -------
    list of PageStep
        In order; helper points' steps left out, preparatory steps grouped.

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.render.sources import as_source
    >>> src = as_source(graphkin.examples.fourbar().solve())
    >>> steps = narrate(src, "velocity")
    >>> [s.title for s in steps][:2]
    ['The velocity pole O_V and the scale; the input', 'Velocity of B: V_B = V_A + V_BA']
    >>> steps[4].equation_text()
    'V_C(??) = V_B(✓✓) + V_CB(?✓) = V_D(✓✓) + V_CD(?✓)'

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (Example 3.1, Fig. 3.7) and
    Sec. 4.4 (Example 4.2, Fig. 4.8).
    """
    return _Teller(src, diagram, scale).tell()
