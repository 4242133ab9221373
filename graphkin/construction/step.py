"""Named construction steps, their roles, branches and vector equations.

A :class:`Step` is one ruler-and-compass act (draw a circle, intersect two
arcs, draw a perpendicular, lay off a vector), recorded with its inputs and
outputs by label, so that a construction can be replayed, narrated and drawn.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (the ✓/? marks over the vectors
of a planar vector equation, Eq. 2.16 and Table 2.2).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum
from typing import Any

__all__ = ["Role", "Side", "Along", "Mark", "Term", "VectorEquation", "Step", "fresh_label"]


class Role(StrEnum):
    """What a step's output is in the drawing."""

    GIVEN = "given"
    """Known before the construction starts (frame points, the input crank)."""
    AUXILIARY = "auxiliary"
    """A construction line or arc: drawn thin."""
    RESULT = "result"
    """A sought point or vector: drawn bold."""


class Side(StrEnum):
    """Branch of a circle-circle intersection (case 4).

    The rule: ``LEFT`` is the point to the left of the directed line from the
    first circle's center to the second's, i.e. where the cross product
    ``(c2 - c1) × (P - c1)`` is positive; ``RIGHT`` where it is negative.
    """

    LEFT = "left"
    RIGHT = "right"


class Along(StrEnum):
    """Branch of a line-circle intersection (case 2).

    The two points are ordered along the line's direction (for a slider line,
    from its first point toward its second): ``BEHIND`` comes first,
    ``AHEAD`` second.
    """

    BEHIND = "behind"
    AHEAD = "ahead"


class Mark(StrEnum):
    """The state of a vector's magnitude or direction (Sec. 2.8)."""

    KNOWN = "✓"
    UNKNOWN = "?"
    INPUT = "I"
    """Known because it is the given input (the book's "I")."""
    CONSTRAINED = "C"
    """Known from a constraint such as a constant angle (the book's "C")."""


@dataclass(frozen=True, slots=True)
class Term:
    """One vector of a planar vector equation with its two marks.

    Parameters
    ----------
    name : str
        The vector in the book's notation, e.g. ``"R_CB"``, ``"V_CB"``, ``"A_CB^n"``.
    magnitude, direction : Mark
        What is known of it.
    sign : int
        +1 or -1 (a vector subtracted).

    Examples
    --------
    >>> str(Term("V_CB", Mark.UNKNOWN, Mark.KNOWN))
    'V_CB(?✓)'
    """

    name: str
    magnitude: Mark = Mark.KNOWN
    direction: Mark = Mark.KNOWN
    sign: int = 1

    def __str__(self) -> str:
        return f"{self.name}({self.magnitude}{self.direction})"

    @property
    def unknowns(self) -> int:
        """How many of the two properties are unknown."""
        return (self.magnitude == Mark.UNKNOWN) + (self.direction == Mark.UNKNOWN)


@dataclass(frozen=True, slots=True)
class VectorEquation:
    """A planar vector equation ``lhs = rhs`` with ✓/? marks, and its Table 2.2 case.

    Examples
    --------
    >>> eq = VectorEquation((Term("R_C"),), (Term("R_B"), Term("R_CB", Mark.KNOWN, Mark.UNKNOWN)))
    >>> str(eq)
    'R_C(✓✓) = R_B(✓✓) + R_CB(✓?)'
    """

    lhs: tuple[Term, ...]
    rhs: tuple[Term, ...]
    case: int | None = None

    def __str__(self) -> str:
        def side(terms: tuple[Term, ...]) -> str:
            out = ""
            for i, t in enumerate(terms):
                op = ("- " if t.sign < 0 else "") if i == 0 else (" - " if t.sign < 0 else " + ")
                out += op + str(t)
            return out

        return f"{side(self.lhs)} = {side(self.rhs)}"

    @property
    def unknowns(self) -> int:
        """Number of unknown magnitudes and directions (a solvable equation has two)."""
        return sum(t.unknowns for t in (*self.lhs, *self.rhs))

    def to_dict(self) -> dict[str, Any]:
        """Plain-data form, for JSON."""
        return {"text": str(self), "case": self.case,
                "terms": [{"name": t.name, "magnitude": str(t.magnitude),
                           "direction": str(t.direction), "sign": t.sign,
                           "side": "lhs" if t in self.lhs else "rhs"}
                          for t in (*self.lhs, *self.rhs)]}


@dataclass(frozen=True, slots=True)
class Step:
    """One recorded construction step.

    Parameters
    ----------
    index : int
        Position in the construction (0-based).
    label : str
        Name of the step, usually its main output (``"C"``, ``"k_C"``, ``"c'"``).
    op : str
        The operation (a key of :data:`graphkin.construction.ops.OPS`).
    inputs : tuple of str
        Labels of the values it reads.
    outputs : tuple of str
        Labels of the values it makes.
    params : dict
        Constants of the step (a radius, local coordinates).
    role : Role
        Given, auxiliary or result.
    branch : str or None
        The chosen branch of a two-way step (a :class:`Side` or :class:`Along`).
    equation : VectorEquation or None
        The vector equation the step solves, with ✓/? marks.
    note : str
        One sentence in the book's words.
    diagram : str
        Which diagram it belongs to: ``posture``, ``velocity``, ``acceleration``, ...
    kind : str
        The kind of the main output: ``point``, ``line``, ``circle``, ``vector``, ``scalar``.
    """

    index: int
    label: str
    op: str
    inputs: tuple[str, ...]
    outputs: tuple[str, ...]
    params: dict[str, Any] = field(default_factory=dict, hash=False, compare=False)
    role: Role = Role.AUXILIARY
    branch: str | None = None
    equation: VectorEquation | None = None
    note: str = ""
    diagram: str = "posture"
    kind: str = "point"

    @property
    def step_id(self) -> str:
        """Stable id used as the SVG group id: ``step-07-C``."""
        safe = "".join(ch if ch.isalnum() or ch in "_-" else "_" for ch in self.label)
        return f"step-{self.index:02d}-{safe}"

    def to_dict(self) -> dict[str, Any]:
        """Plain-data form, for JSON."""
        return {
            "index": self.index, "id": self.step_id, "label": self.label, "op": self.op,
            "inputs": list(self.inputs), "outputs": list(self.outputs),
            "role": str(self.role), "branch": self.branch, "diagram": self.diagram,
            "kind": self.kind, "note": self.note,
            "equation": None if self.equation is None else self.equation.to_dict(),
        }


def fresh_label(label: str, taken: Any) -> str:
    """``label``, or ``label#2``, ``label#3``... the first not in ``taken``.

    A construction that draws the same element twice (the same line of
    centers found again, a force drawn for a second load) keeps both, the
    later ones numbered; ``#`` is never part of a point's name.

    >>> fresh_label("I13", {"I13": 0, "I13#2": 0})
    'I13#3'
    """
    if label not in taken:
        return label
    k = 2
    while f"{label}#{k}" in taken:
        k += 1
    return f"{label}#{k}"
