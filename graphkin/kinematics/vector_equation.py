"""The planar vector equation ``C = A + B``: the four cases of Table 2.2, as constructions.

Any solvable planar vector equation reduces to three terms with two unknowns
(Sec. 2.8, Eq. 2.16), and the kind of the two unknowns decides the
construction (Table 2.2 of the 5th edition; the numbering is pinned in
``docs/glossary.md``):

======  ===========================  =====================  ==========================
case    unknowns                     construction           solutions
======  ===========================  =====================  ==========================
1       magnitude and direction of   vectors tip to tail    one
        one vector (C, θ_C)          (Fig. 2.10)
2       magnitude of one, direction  a line and an arc      two: ``Along.BEHIND``,
        of another (A, θ_B)          (Fig. 2.11)            ``Along.AHEAD``
3       two magnitudes (A, B)        two lines (Fig. 2.12)  one (none if parallel)
4       two directions (θ_A, θ_B)    two arcs (Fig. 2.13)   two: ``Side.LEFT``,
                                                            ``Side.RIGHT``
======  ===========================  =====================  ==========================

:func:`solve_vector_equation` records the construction step by step with
:meth:`graphkin.construction.Construction.add` (every step carries the
equation with its ✓/? marks, its role, its branch and a sentence from the
book) and reads the solutions from it.  The vectors form a triangle with
three named vertices:

* ``O``, the origin of **A** and of **C**;
* ``P``, the terminus of **A**, where **B** starts;
* ``T``, the terminus of **B** and of **C**.

The fully known vector is drawn first, its origin at ``(0, 0)``; the vertex
that is not one of its ends is the one the construction finds.  A second
solution is primed (``P'``, ``A'``) as in the book's figures.  Known angles
enter the construction as inputs (``theta_A``...) and known magnitudes as
constants, so the same construction replays on one set of angles or on
arrays of them (``result.construction.evaluate(...)``).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (graphic solution, Table 2.2, Figs. 2.10-2.13, Eqs. 2.14-2.19) and
Sec. 2.11 (the same four cases in complex polar form, Eqs. 2.42-2.50).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import IntEnum
from typing import Any, NamedTuple

import numpy as np

from graphkin.construction import Along, Construction, Mark, Role, Side, Term, VectorEquation
from graphkin.errors import (
    ConstructionError,
    InputError,
    NoIntersectionError,
    ParallelDirectionsError,
)
from graphkin.geometry import ops as g
from graphkin.geometry.point import Vector
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["VectorEquationCase", "Polar", "VectorTriple", "VectorEquationResult",
           "solve_vector_equation", "vector_construction"]

NAMES = ("A", "B", "C")
# each vector as (origin, terminus) of the triangle O, P, T: C = A + B
_ENDS = {"A": ("O", "P"), "B": ("P", "T"), "C": ("O", "T")}


class VectorEquationCase(IntEnum):
    """The four cases of the planar vector equation ``C = A + B`` (Table 2.2, 5th ed.).

    Each case is named by its two unknowns; the numbering is that of the 5th
    edition's Table 2.2 (see ``docs/glossary.md``; other editions differ).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, Table 2.2; Sec. 2.11,
    Eqs. (2.43)-(2.50).

    Examples
    --------
    >>> VectorEquationCase.CASE_4.unknowns
    'two directions (θ_A, θ_B): two arcs meet'
    >>> VectorEquationCase.of(Polar(5), Polar(4), Polar(8, 0.0))
    <VectorEquationCase.CASE_4: 4>
    """

    CASE_1 = 1
    """Unknowns: the magnitude and the direction of one vector (C, θ_C).

    The other two vectors are known and are added (or subtracted) tip to tail
    (Fig. 2.10, Eq. 2.14).  One solution (Eqs. 2.43-2.44).
    """
    CASE_2 = 2
    """Unknowns: the magnitude of one vector and the direction of another (A, θ_B).

    A line with the known direction of A meets an arc of radius B: a line and
    a circle (Fig. 2.11, Eq. 2.17).  Two solutions, ``Along.BEHIND`` and
    ``Along.AHEAD`` (Eqs. 2.45-2.46), none when the arc misses the line.
    """
    CASE_3 = 3
    """Unknowns: two magnitudes (A, B) with known directions.

    Two lines of known direction meet: a meet of two lines (Fig. 2.12,
    Eq. 2.18).  One solution (Eqs. 2.47-2.48); the magnitudes may be negative.
    Parallel lines give infinite magnitudes, collinear lines indeterminate ones.
    """
    CASE_4 = 4
    """Unknowns: two directions (θ_A, θ_B) with known magnitudes.

    Two arcs meet: an intersection of two circles (Fig. 2.13, Eq. 2.19).  Two
    solutions, ``Side.LEFT`` and ``Side.RIGHT`` (Eqs. 2.49-2.50); a real
    solution needs ``A + B ≥ C`` (and ``|A - B| ≤ C``).
    """

    @property
    def unknowns(self) -> str:
        """The unknowns and the construction, in words."""
        return {
            1: "magnitude and direction of one vector (C, θ_C): add tip to tail",
            2: "magnitude of one vector and direction of another (A, θ_B): a line and an arc",
            3: "two magnitudes (A, B): two lines meet",
            4: "two directions (θ_A, θ_B): two arcs meet",
        }[int(self)]

    @property
    def method(self) -> str:
        """The construction, in a few words."""
        return {1: "the known vectors tip to tail", 2: "a line and an arc", 3: "two lines",
                4: "two arcs"}[int(self)]

    @property
    def figure(self) -> str:
        """The book's figure of the construction."""
        return f"Fig. 2.1{int(self) - 1}"

    @property
    def branches(self) -> tuple[str, ...]:
        """The branch names of the case's solutions, in order (empty for one solution)."""
        return {2: (str(Along.BEHIND), str(Along.AHEAD)),
                4: (str(Side.LEFT), str(Side.RIGHT))}.get(int(self), ())

    @classmethod
    def of(cls, A: Polar, B: Polar, C: Polar) -> VectorEquationCase:
        """The case of ``C = A + B`` with these knowns.

        Raises
        ------
        InputError
            Unless exactly two of the six magnitudes and directions are unknown.
        """
        unknown = _unknowns({"A": A, "B": B, "C": C})
        if len(unknown) != 2:
            listed = ", ".join(f"{n}.{p}" for n, p in unknown) or "none"
            raise InputError(f"C = A + B is solvable for exactly two unknowns (Sec. 2.8); "
                             f"this one has {len(unknown)} ({listed})")
        (n1, p1), (n2, p2) = unknown
        if n1 == n2:
            return cls.CASE_1
        if p1 == p2:
            return cls.CASE_3 if p1 == "magnitude" else cls.CASE_4
        return cls.CASE_2


@dataclass(frozen=True, slots=True)
class Polar:
    """A vector in polar notation ``R∠θ``, either part possibly unknown (``None``).

    Parameters
    ----------
    magnitude : float or None
        ``R``; ``None`` when unknown.  May be negative (the vector then points
        along ``θ + 180°``), as the book allows for case 3.
    angle : float or None
        ``θ`` in radians, counterclockwise from +x; ``None`` when unknown.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.10 (polar notation, Eq. 2.35)
    and Sec. 2.8 (the ✓/? marks).

    Examples
    --------
    >>> Polar.deg(10, 30)
    Polar(magnitude=10.0, angle=0.5235987755982988)
    >>> str(Polar.deg(10, 30)), str(Polar(4)), str(Polar(angle=0.0))
    ('10∠30°', '4∠?', '?∠0°')
    >>> Polar(4).marks
    (<Mark.KNOWN: '✓'>, <Mark.UNKNOWN: '?'>)
    """

    magnitude: float | None = None
    angle: float | None = None

    def __post_init__(self) -> None:
        for part in ("magnitude", "angle"):
            x = getattr(self, part)
            if isinstance(x, (int, float, np.floating, np.integer)) and not isinstance(x, bool):
                object.__setattr__(self, part, float(x))

    @classmethod
    def deg(cls, magnitude: float | None = None, angle: float | None = None) -> Polar:
        """Like the constructor, with the angle in degrees."""
        return cls(magnitude, None if angle is None else math.radians(angle))

    @property
    def marks(self) -> tuple[Mark, Mark]:
        """The book's marks for the magnitude and the direction (✓ known, ? unknown)."""
        return (Mark.UNKNOWN if self.magnitude is None else Mark.KNOWN,
                Mark.UNKNOWN if self.angle is None else Mark.KNOWN)

    @property
    def is_known(self) -> bool:
        """True when both the magnitude and the direction are known."""
        return self.magnitude is not None and self.angle is not None

    @property
    def vector(self) -> Vector:
        """The vector ``R∠θ``; raises ``InputError`` unless both parts are known."""
        if self.magnitude is None or self.angle is None:
            raise InputError(f"{self} is not fully known")
        return Vector.polar(self.magnitude, self.angle)

    def __str__(self) -> str:
        m = "?" if self.magnitude is None else f"{self.magnitude:.6g}"
        a = "?" if self.angle is None else f"{math.degrees(self.angle):.6g}°"
        return f"{m}∠{a}"


class VectorTriple(NamedTuple):
    """One solution of ``C = A + B``: the three vectors."""

    A: Vector
    B: Vector
    C: Vector


@dataclass(frozen=True)
class VectorEquationResult:
    """The solutions of ``C = A + B`` and the construction that found them.

    Attributes
    ----------
    case : VectorEquationCase
    equation : VectorEquation
        ``C = A + B`` with its ✓/? marks.
    knowns : dict
        ``"A"``, ``"B"``, ``"C"`` -> :class:`Polar` as given.
    solutions : tuple of VectorTriple
        Every solution, in branch order (``behind, ahead`` or ``left, right``).
    branches : tuple of (str or None)
        The branch of each solution (``None`` for cases 1 and 3).
    construction : Construction
        The recorded steps.
    inputs : dict
        The given values that replay the construction
        (``construction.evaluate(inputs)``): each known angle, in radians.
    """

    case: VectorEquationCase
    equation: VectorEquation
    knowns: Mapping[str, Polar]
    solutions: tuple[VectorTriple, ...]
    branches: tuple[str | None, ...]
    construction: Construction = field(repr=False)
    inputs: Mapping[str, float] = field(default_factory=dict)

    @property
    def unknowns(self) -> tuple[str, ...]:
        """The two unknowns in the book's notation: ``"A"`` a magnitude, ``"θ_B"`` a direction.

        Examples
        --------
        >>> solve_vector_equation(Polar(angle=0.5), Polar(4.0), Polar(5.0, 0.0)).unknowns
        ('A', 'θ_B')
        """
        return tuple(n if part == "magnitude" else f"θ_{n}" for n, part in _unknowns(self.knowns))

    def solution(self, branch: Side | Along | str) -> VectorTriple:
        """The solution of the named branch.

        Raises
        ------
        KeyError
            When no solution has that branch (the message lists the branches).
        """
        for b, s in zip(self.branches, self.solutions):
            if b == str(branch):
                return s
        raise KeyError(f"no branch {str(branch)!r}; branches: "
                       f"{', '.join(str(b) for b in self.branches)}")

    def polar(self, k: int = 0) -> tuple[Polar, Polar, Polar]:
        """Solution ``k`` in polar form, the textbook way.

        A known direction is kept and its unknown magnitude is signed (it may
        be negative, Sec. 2.8 case 3); a known magnitude is kept and the
        direction found is reported for it; a vector found whole (case 1) has
        a positive magnitude (Eq. 2.43).  Angles found are in (-π, π].
        """
        out = []
        for name, v in zip(NAMES, self.solutions[k]):
            given = self.knowns[name]
            if given.magnitude is not None and given.angle is not None:
                out.append(given)
            elif given.angle is not None:
                out.append(Polar(v.dot(Vector.polar(1.0, given.angle)), given.angle))
            elif given.magnitude is not None:
                theta = v.angle if given.magnitude >= 0 else _wrap(v.angle + math.pi)
                out.append(Polar(given.magnitude, theta))
            else:
                out.append(Polar(v.magnitude, v.angle))
        return (out[0], out[1], out[2])


def _wrap(angle: float) -> float:
    """An angle in (-π, π]."""
    a = math.remainder(angle, math.tau)
    return math.pi if a == -math.pi else a


def _unknowns(knowns: Mapping[str, Polar]) -> list[tuple[str, str]]:
    return [(n, part) for n in NAMES for part in ("magnitude", "angle")
            if getattr(knowns[n], part) is None]


def _check(name: str, value: Any) -> Polar:
    if not isinstance(value, Polar):
        raise InputError(f"{name} must be a Polar (magnitude and angle, None where unknown), "
                         f"not {value!r}", key=name)
    for part in ("magnitude", "angle"):
        x = getattr(value, part)
        if x is None:
            continue
        if isinstance(x, bool) or not isinstance(x, (int, float)) or not math.isfinite(x):
            raise InputError(f"expected a finite number or None, not {x!r}",
                             key=f"{name}.{part}")
    return value


def _branch_names(case: VectorEquationCase, branch: Side | Along | str | None) -> tuple[str, ...]:
    valid = case.branches
    if branch is None:
        return valid or ("",)
    if not valid:
        raise InputError(f"case {int(case)} has one solution, so it takes no branch "
                         f"(got {str(branch)!r})", key="branch")
    if str(branch) not in valid:
        raise InputError(f"case {int(case)} has the branches {', '.join(valid)}, "
                         f"not {str(branch)!r}", key="branch")
    return (str(branch),)


class _Builder:
    """Records the steps of one case, all carrying the same marked equation."""

    def __init__(self, case: VectorEquationCase, knowns: Mapping[str, Polar]) -> None:
        self.case = case
        self.knowns = knowns
        terms = {n: Term(n, *knowns[n].marks) for n in NAMES}
        self.equation = VectorEquation((terms["C"],), (terms["A"], terms["B"]), case=int(case))
        self.cx = Construction(title=f"Case {int(case)} of Table 2.2: {self.equation}")
        self.inputs: dict[str, float] = {}
        self.found = ""  # the vertex the construction finds (O, P or T); "" in case 1
        self.unknown = [n for n in NAMES if not knowns[n].is_known]

    def add(self, op: str, inputs: tuple[str, ...], outputs: tuple[str, ...], note: str,
            role: Role = Role.AUXILIARY, **params: Any) -> None:
        self.cx.add(op, inputs, outputs, role=role, equation=self.equation, note=note,
                    diagram="vector", **params)

    def angle(self, name: str) -> str:
        """The input step of a known angle; returns its label."""
        label = f"theta_{name}"
        if label not in self.inputs:
            theta = self.knowns[name].angle
            assert theta is not None
            self.inputs[label] = float(theta)
            self.add("input", (), (label,), f"The direction of {name} is known.",
                     role=Role.GIVEN, name=label)
        return label

    def origin(self, point: str, name: str) -> None:
        self.add("point", (), (point,), f"Choose a convenient scale factor; {point} is the "
                 f"origin of {name}.", role=Role.GIVEN, xy=(0.0, 0.0))

    def lay_off(self, name: str, start: str, end: str, note: str) -> None:
        """Draw the known vector ``name`` from ``start`` to ``end`` (either sense)."""
        m = self.knowns[name].magnitude
        assert m is not None
        sign = 1.0 if _ENDS[name] == (start, end) else -1.0
        theta = self.angle(name)
        self.add("rigid", (start, theta), (end,), note, role=Role.GIVEN,
                 local_p=(0.0, 0.0), local_q=(sign * float(m), 0.0))

    def vector(self, name: str, prime: str) -> None:
        tail, tip = (p + prime if p == self.found else p for p in _ENDS[name])
        self.add("vector", (tail, tip), (name + prime,),
                 f"{name}{prime} is the vector from {tail} to {tip}.", role=Role.RESULT)


def _where(point: str, name: str) -> str:
    return "origin" if _ENDS[name][0] == point else "terminus"


def solve_vector_equation(A: Polar, B: Polar, C: Polar, *,
                          branch: Side | Along | str | None = None,
                          tol: Tolerance | None = None) -> VectorEquationResult:
    """Solve ``C = A + B`` for its two unknowns by the graphic construction of Sec. 2.8.

    Parameters
    ----------
    A, B, C : Polar
        What is known of each vector: ``Polar(magnitude, angle)`` with
        ``None`` for an unknown part (angles in radians).  Exactly two of the
        six parts must be unknown.
    branch : Side, Along, str, optional
        Keep only this branch: ``"left"``/``"right"`` (case 4) or
        ``"behind"``/``"ahead"`` (case 2).  By default every solution is
        constructed.
    tol : Tolerance, optional
        Decides tangency and parallel directions.

    Returns
    -------
    VectorEquationResult
        The case, the marked equation, every solution (in branch order) and
        the recorded construction.

    Raises
    ------
    InputError
        Not exactly two unknowns, a part that is not a finite number, a zero
        magnitude for a vector of unknown direction, or a branch the case
        does not have (the ``key`` names it: ``"A.magnitude"``, ``"branch"``).
    NoIntersectionError
        Case 4 when the arcs do not meet (``|A| + |B| < |C|`` or
        ``||A| - |B|| > |C|``); case 2 when the arc misses the line.  The message
        says why in the book's words; the error's ``step`` names the step.
    ParallelDirectionsError
        Case 3 when the two known directions are parallel: the magnitudes are
        infinite (distinct lines) or indeterminate (collinear lines).  It
        carries ``directions`` (the two unit vectors) and ``vectors`` (their names).

    See Also
    --------
    VectorEquationCase : the four cases.
    graphkin.geometry.intersect : the branch order of two arcs and of a line and an arc.

    Notes
    -----
    Branches, as in :func:`graphkin.geometry.intersect`:

    * case 4: the arcs are drawn about the origin and the terminus of the
      known vector; ``left`` is the solution whose free vertex lies to the left
      of the known vector (positive cross product), ``right`` the other;
    * case 2: the line through an end of the known vector has the known
      direction of the vector of unknown magnitude; ``behind`` is the
      intersection that comes first along that direction, ``ahead`` the other.

    Tangent arcs (``|A| + |B| = |C|``) give the same solution twice.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, Table 2.2 and Figs. 2.10-2.13;
    Sec. 2.11, Eqs. (2.42)-(2.50) for the closed forms.

    Examples
    --------
    Case 4 (Fig. 2.13) with a 3-4-5 triangle: C = 5∠0°, A = 3, B = 4.

    >>> import math
    >>> r = solve_vector_equation(Polar(3), Polar(4), Polar(5, 0.0))
    >>> r.case, r.branches
    (<VectorEquationCase.CASE_4: 4>, ('left', 'right'))
    >>> str(r.equation)
    'C(✓✓) = A(✓?) + B(✓?)'
    >>> [str(p) for p in r.polar(0)]
    ['3∠53.1301°', '4∠-36.8699°', '5∠0°']
    >>> [str(p) for p in r.polar(1)]
    ['3∠-53.1301°', '4∠36.8699°', '5∠0°']

    Case 2 (Fig. 2.11): C = 8∠0°, the direction of A is 30°, B = 5.

    >>> r = solve_vector_equation(Polar.deg(None, 30), Polar(5), Polar.deg(8, 0))
    >>> [round(p[0].magnitude, 4) for p in map(r.polar, range(2))]
    [3.9282, 9.9282]
    >>> print(r.construction.table())  # doctest: +NORMALIZE_WHITESPACE
    #  label    op                     inputs        role       branch  equation
    0  O        point                                given              C(✓✓) = A(?✓) + B(✓?)
    1  theta_C  input                                given              C(✓✓) = A(?✓) + B(✓?)
    2  T        rigid                  O, theta_C    given              C(✓✓) = A(?✓) + B(✓?)
    3  theta_A  input                                given              C(✓✓) = A(?✓) + B(✓?)
    4  l_A      line_at_angle          O, theta_A    auxiliary          C(✓✓) = A(?✓) + B(✓?)
    5  k_B      circle                 T             auxiliary          C(✓✓) = A(?✓) + B(✓?)
    6  P        intersect_line_circle  l_A, k_B      result     behind  C(✓✓) = A(?✓) + B(✓?)
    7  A        vector                 O, P          result             C(✓✓) = A(?✓) + B(✓?)
    8  B        vector                 P, T          result             C(✓✓) = A(?✓) + B(✓?)
    9  P'       intersect_line_circle  l_A, k_B      result     ahead   C(✓✓) = A(?✓) + B(✓?)
    10 A'       vector                 O, P'         result             C(✓✓) = A(?✓) + B(✓?)
    11 B'       vector                 P', T         result             C(✓✓) = A(?✓) + B(✓?)
    """
    knowns = {n: _check(n, v) for n, v in zip(NAMES, (A, B, C))}
    case = VectorEquationCase.of(*knowns.values())
    wanted = _branch_names(case, branch)
    tol = tol or DEFAULT_TOL
    b = _record(knowns, case, wanted, tol, check=True)
    return _finish(b, case, wanted, tol)


def vector_construction(A: Polar, B: Polar, C: Polar, *,
                        branch: Side | Along | str | None = None) -> VectorEquationResult:
    """The construction of ``C = A + B`` with every branch recorded, not evaluated.

    What :func:`solve_vector_equation` records, for the live page
    (:mod:`graphkin.render.live_vector`), which evaluates it itself, and so
    also when it has no solution (arcs that miss, parallel lines): the result's
    ``solutions`` is empty and ``branches`` names every branch the case has.

    ``branch`` is only checked (a branch the case has, as
    :func:`solve_vector_equation` checks it): every branch is recorded.

    Raises
    ------
    InputError
        As :func:`solve_vector_equation` for the knowns and the branch.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, Table 2.2 and Figs. 2.10-2.13.

    Examples
    --------
    >>> r = vector_construction(Polar(3), Polar(4), Polar(9, 0.0))  # the arcs miss
    >>> r.case, r.branches, r.solutions
    (<VectorEquationCase.CASE_4: 4>, ('left', 'right'), ())
    """
    knowns = {n: _check(n, v) for n, v in zip(NAMES, (A, B, C))}
    case = VectorEquationCase.of(*knowns.values())
    _branch_names(case, branch)
    wanted = _branch_names(case, None)
    b = _record(knowns, case, wanted, DEFAULT_TOL, check=False)
    return VectorEquationResult(
        case=case, equation=b.equation, knowns=dict(b.knowns), solutions=(),
        branches=tuple(w or None for w in wanted), construction=b.cx, inputs=dict(b.inputs))


def _record(knowns: Mapping[str, Polar], case: VectorEquationCase, wanted: tuple[str, ...],
            tol: Tolerance, check: bool) -> _Builder:
    """Record the steps of ``case`` for the ``wanted`` branches (``check``: refuse parallels)."""
    for n, k in knowns.items():
        if k.angle is None and k.magnitude is not None and k.magnitude == 0.0 and \
                case != VectorEquationCase.CASE_1:
            raise InputError(f"{n} has an unknown direction, so its magnitude must not be "
                             "zero (its arc would have no radius)", key=f"{n}.magnitude")
    b = _Builder(case, knowns)
    if case == VectorEquationCase.CASE_1:
        _build_case_1(b)
        return b
    (z,) = [n for n in NAMES if knowns[n].is_known]
    x, y = [n for n in NAMES if n != z]
    tail, tip = _ENDS[z]
    (free,) = {"O", "P", "T"} - {tail, tip}
    b.found = free
    b.origin(tail, z)
    b.lay_off(z, tail, tip, f"Draw vector {z} to scale from its origin {tail} to its "
                            f"terminus {tip}.")
    anchor = {n: next(p for p in _ENDS[n] if p != free) for n in (x, y)}
    # x is the unknown that touches the origin of z (its arc or line comes first)
    if anchor[x] != tail:
        x, y = y, x
    if case == VectorEquationCase.CASE_4:
        for n in (x, y):
            m = knowns[n].magnitude
            assert m is not None
            b.add("circle", (anchor[n],), (f"k_{n}",),
                  f"Construct a circular arc of radius {n} centered at the "
                  f"{_where(anchor[n], z)} of {z}.", radius=abs(float(m)))
        for i, side in enumerate(wanted):
            prime = "'" * i
            b.add("intersect_circles", (f"k_{x}", f"k_{y}"), (free + prime,),
                  f"The intersection of the arcs to the {side} of {z} defines one set of "
                  f"solutions, the directions of {x}{prime} and {y}{prime}.",
                  role=Role.RESULT, branch=side)
            b.vector(x, prime)
            b.vector(y, prime)
    elif case == VectorEquationCase.CASE_3:
        for n, first in ((x, True), (y, False)):
            theta = b.angle(n)
            b.add("line_at_angle", (anchor[n], theta), (f"l_{n}",),
                  f"Construct {'a' if first else 'another'} line through the "
                  f"{_where(anchor[n], z)} of {z} parallel to the direction of {n}.")
        b.add("meet", (f"l_{x}", f"l_{y}"), (free,),
              f"The intersection of these two lines defines both magnitudes, {x} and {y}, "
              "each of which may be either positive or negative.", role=Role.RESULT)
        b.vector(x, "")
        b.vector(y, "")
        if check:
            _check_parallel(b, z, x, y, anchor, free, tol)
    else:  # case 2: the magnitude of one is unknown (a line), the direction of the other (an arc)
        line_n, arc_n = (x, y) if knowns[x].magnitude is None else (y, x)
        theta = b.angle(line_n)
        b.add("line_at_angle", (anchor[line_n], theta), (f"l_{line_n}",),
              f"Construct a line through the {_where(anchor[line_n], z)} of {z} parallel to "
              f"the direction of {line_n}.")
        m = knowns[arc_n].magnitude
        assert m is not None
        b.add("circle", (anchor[arc_n],), (f"k_{arc_n}",),
              f"Adjust a compass to the scaled magnitude {arc_n} and construct a circular arc "
              f"with the center at the {_where(anchor[arc_n], z)} of {z}.",
              radius=abs(float(m)))
        for i, along in enumerate(wanted):
            prime = "'" * i
            b.add("intersect_line_circle", (f"l_{line_n}", f"k_{arc_n}"), (free + prime,),
                  f"Of the two intersections of the line and the arc, the one {along} along "
                  f"the direction of {line_n} defines one set of solutions, {line_n}{prime} "
                  f"and the direction of {arc_n}{prime}.", role=Role.RESULT, branch=along)
            b.vector(x, prime)
            b.vector(y, prime)
    return b


def _build_case_1(b: _Builder) -> None:
    (u,) = [n for n in NAMES if not b.knowns[n].is_known]
    known = [n for n in NAMES if n != u]
    b.origin("O", "A" if "A" in known else "C")
    placed = {"O"}
    while len(placed) < 3:
        for n in known:
            tail, tip = _ENDS[n]
            if tail in placed and tip not in placed:
                note = (f"Draw {n} tip to tail from {tail}." if tail != "O" else
                        f"Draw the known vector {n} to scale from its origin {tail}.")
                b.lay_off(n, tail, tip, note)
                placed.add(tip)
            elif tip in placed and tail not in placed:
                b.lay_off(n, tip, tail, f"Draw {n} tip to tip, ending at {tip} "
                                        "(graphic subtraction, Fig. 2.10b).")
                placed.add(tail)
    tail, tip = _ENDS[u]
    b.add("vector", (tail, tip), (u,),
          f"The vector from {tail} to {tip} closes the triangle: it is {u}, magnitude and "
          "direction (Fig. 2.10).", role=Role.RESULT)


def _check_parallel(b: _Builder, z: str, x: str, y: str, anchor: Mapping[str, str], free: str,
                    tol: Tolerance) -> None:
    """Case 3: refuse parallel directions by angle, before any replay."""
    tx, ty = b.knowns[x].angle, b.knowns[y].angle
    assert tx is not None and ty is not None
    ux, uy = Vector.polar(1.0, tx), Vector.polar(1.0, ty)
    if abs(ux.cross(uy)) > tol.angle:
        return
    zv = b.knowns[z].vector
    offset = abs(zv.cross(ux))  # distance between the two parallel lines
    if offset <= tol.length(abs(zv)):
        what = (f"the lines coincide, so the magnitudes {x} and {y} are indeterminate "
                "(Sec. 2.8)")
    else:
        what = (f"the lines are parallel but distinct, so the magnitudes {x} and {y} are "
                "infinite (Sec. 2.8)")
    raise _parallel_error(b, x, y, free, what, ux, uy)


def _parallel_error(b: _Builder, x: str, y: str, free: str, what: str, ux: Vector,
                    uy: Vector) -> ParallelDirectionsError:
    # the construction's step labels (P, k_A) stay inside: the message is the book's words
    return ParallelDirectionsError(
        f"case 3 has no solution: the directions of {x} "
        f"({math.degrees(ux.angle):.6g}°) and {y} ({math.degrees(uy.angle):.6g}°) are "
        f"parallel; {what}", step=free, directions=(ux, uy), vectors=(x, y))


def _finish(b: _Builder, case: VectorEquationCase, wanted: tuple[str, ...],
            tol: Tolerance) -> VectorEquationResult:
    ev = b.cx.evaluate(b.inputs, tol=tol, strict=False)
    if case == VectorEquationCase.CASE_3:
        meet = np.asarray(ev[b.found])
        if not np.all(np.isfinite(meet)) or bool(g.is_ideal(meet)):
            # nearly parallel: the lines coincide, or meet so far away that it is at infinity
            x, y = b.unknown
            tx, ty = b.knowns[x].angle, b.knowns[y].angle
            assert tx is not None and ty is not None
            what = ("the lines coincide (Sec. 2.8)" if not np.all(np.isfinite(meet)) else
                    "the lines meet at infinity (Sec. 2.8)")
            raise _parallel_error(b, x, y, b.found, what, Vector.polar(1.0, tx),
                                  Vector.polar(1.0, ty))
    if not bool(np.all(ev.valid)):
        assert ev.failed_at is not None
        raise _no_solution(b, int(ev.failed_at), ev.values, tol)
    solutions = []
    for i in range(len(wanted)):
        pts = {p: ev[p + "'" * i if p == b.found else p] for p in ("O", "P", "T")}
        vecs = {n: Vector.from_array(g.xy(pts[_ENDS[n][1]]) - g.xy(pts[_ENDS[n][0]]))
                for n in NAMES}
        solutions.append(VectorTriple(vecs["A"], vecs["B"], vecs["C"]))
    return VectorEquationResult(
        case=case, equation=b.equation, knowns=dict(b.knowns), solutions=tuple(solutions),
        branches=tuple(w or None for w in wanted), construction=b.cx, inputs=dict(b.inputs))


def _no_solution(b: _Builder, index: int, values: Mapping[str, np.ndarray],
                 tol: Tolerance) -> ConstructionError:
    step = b.cx[index]
    head = f"case {int(b.case)} has no solution"   # the book's words, no step labels
    if step.op == "intersect_circles":
        k1, k2 = (np.asarray(values[s]) for s in step.inputs)
        (n1, r1), (n2, r2) = ((s[2:], float(k[2])) for s, k in zip(step.inputs, (k1, k2)))
        d = float(np.hypot(*(k2[:2] - k1[:2])))
        z = next(n for n in NAMES if b.knowns[n].is_known)
        if d <= tol.length(max(r1, r2)):
            why = (f"{z} is zero, so the arcs are concentric and the directions of {n1} and "
                   f"{n2} are indeterminate")
        elif r1 + r2 < d:
            why = (f"the arcs do not meet: |{n1}| + |{n2}| = {r1 + r2:.6g} < |{z}| = {d:.6g} "
                   f"(a real solution needs |{n1}| + |{n2}| ≥ |{z}|, Sec. 2.8)")
        else:
            why = (f"the arcs do not meet: one lies inside the other, "
                   f"||{n1}| - |{n2}|| = {abs(r1 - r2):.6g} > |{z}| = {d:.6g}")
        return NoIntersectionError(f"{head}: {why}", step=step.label, case=int(b.case),
                                   objects={s: values[s].tolist() for s in step.inputs})
    if step.op == "intersect_line_circle":
        line, k = (np.asarray(values[s]) for s in step.inputs)
        n_line, n_arc = step.inputs[0][2:], step.inputs[1][2:]
        dist = abs(float(g.signed_distance(line, g.point(k[0], k[1]))))
        why = (f"the line with the direction of {n_line} passes {dist:.6g} from the center of "
               f"the arc of radius |{n_arc}| = {float(k[2]):.6g}, so they do not meet")
        return NoIntersectionError(f"{head}: {why}", step=step.label, case=int(b.case),
                                   objects={s: values[s].tolist() for s in step.inputs})
    return ConstructionError(f"{head}: the step has no answer", step=step.label,
                             case=int(b.case))
