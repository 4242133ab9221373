"""The words of a teaching page: answer marks, vector names in HTML, point and image letters.

:class:`PageStep` (one act of the page) and the small helpers the tellers
(:mod:`graphkin.render.narrate.reader`, :mod:`~graphkin.render.narrate.polygons`)
write their sentences with.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Table 2.2, the ✓/? marks), 3.4 (image
letters of the velocity polygon), 4.4 (primed letters of the acceleration polygon).
"""

from __future__ import annotations

import html
import math
import re
from dataclasses import dataclass, field

import numpy as np

from graphkin.construction import Mark, Term

K, U = Mark.KNOWN, Mark.UNKNOWN

PREPARATORY = ("join", "normal_component", "coriolis", "rolling_normal", "apparent_normal")
"""Operations that only prepare the next step (a line to be perpendicular to, a component
to lay off): narrated together with the step that uses them."""

_ANSWER = re.compile(r"⟦(.*?)⟧")
_SUBS = {ord(d): ord("₀") + int(d) for d in "0123456789"}  # digits as subscripts


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
    # the other points with subscripts (J_B, C_N, Q_Γ, U_T; Figs. 4.29, 4.33, 4.38)
    # (written together as the book writes a rectangle: IC_NC_GC_T is I C_N C_G C_T)
    esc = re.sub(r"(?<![a-z0-9_])([A-Z])_([A-Z]\d?|Γ)", r"\1<sub>\2</sub>", esc)
    esc = re.sub(r"ρ_([A-Z]\d?)", r"ρ<sub>\1</sub>", esc)  # a path's radius of curvature
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

        return " = ".join("".join(_sign(i, t.sign) + str(t) for i, t in enumerate(side))
                          for side in self.sides)


_PLURAL = {"velocity": "velocities", "acceleration": "accelerations"}

_OP_WORDS = {
    "point": "point", "circle": "arc", "intersect_circles": "two arcs meet at",
    "intersect_line_circle": "a line and an arc meet at", "join": "line",
    "meet": "two lines meet at", "perpendicular": "perpendicular", "parallel": "parallel",
    "input": "the input", "rigid": "point of the link", "similar": "image",
}

_REFS = {"posture": "Sec. 2.8, Fig. 2.14", "centers": "Sec. 3.13-3.14",
         "curvature": "Sec. 4.12-4.15",
         # the figures of the curvature sheet
         "inflection": "Sec. 4.12, 4.14-4.15, Figs. 4.29c, 4.33, 4.34",
         "bobillier": "Sec. 4.13, Figs. 4.28, 4.29",
         "hartmann": "Sec. 4.12-4.13, Figs. 4.25, 4.30",
         "cubic": "Sec. 4.17, Fig. 4.38"}


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


def _sign(i: int, sign: int) -> str:
    """The sign before the ``i``-th term of a side: ``−`` first, then `` − `` or `` + ``."""
    if i == 0:
        return "−" if sign < 0 else ""
    return " − " if sign < 0 else " + "


def _side_words(side: tuple[Term, ...]) -> str:
    return "".join(_sign(i, t.sign) + _pretty(t.name) for i, t in enumerate(side))


def _path_words(line: str) -> str:
    return "the slot" if line.startswith("slots") else "the slide"
