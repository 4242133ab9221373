"""Gear trains, parallel-axis and epicyclic (Secs. 7.12-7.16): the book's two methods and a check.

A train is its members (gears and arms, each with a name), the meshes between
gears (external or internal contact, and the member that carries both axes:
the frame for fixed axes, the arm for a sun and its planet), the members
joined on one shaft, and the given motions (as many as the train has
degrees of freedom).

* :func:`solve` writes one equation per mesh, seen from its carrier,
  ``N_j (ω_j − ω_A) = ∓ N_i (ω_i − ω_A)`` (− external, + internal; Eq. 7.25
  for one pair), and the given motions, and solves them together: the
  independent check.
* :func:`tabular` is the book's table (Sec. 7.16): every gear locked to the
  arm, then the arm held and one gear B turned, then the sum; the two given
  motions fix ``ω_A`` and ``ω_B/A``.
* :func:`formula` is Eq. (7.25): the train value ``θ'_LF/A`` from the product
  of the driving over the driven tooth numbers (Eq. 7.24) along the meshes
  from the first gear F to the last L, and ``ω_L = ω_A + θ'_LF/A (ω_F − ω_A)``.

Angular velocities (or, for a "turns" question such as Ferguson's paradox,
angular displacements) are counterclockwise positive.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.12-7.16, Eqs. (7.22)-(7.26),
Examples 7.4-7.11.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import StrEnum
from fractions import Fraction

import numpy as np

from graphkin.errors import InputError

__all__ = ["Contact", "Mesh", "Train", "TrainSolution", "TableRow", "Table", "solve", "tabular",
           "formula", "FRAME"]

FRAME = "frame"
"""The name of the fixed member (speed 0), the carrier of gears on fixed axes."""


class Contact(StrEnum):
    """The contact of a mesh: the sign of its train value (Sec. 7.12)."""

    EXTERNAL = "external"
    """The gears turn in opposite senses: ``−N_i/N_j``."""
    INTERNAL = "internal"
    """A gear inside a ring: the same sense, ``+N_i/N_j``."""


@dataclass(frozen=True)
class Mesh:
    """Gear ``driver`` in mesh with ``driven``, both axes carried by ``arm`` (Sec. 7.15)."""

    driver: str
    driven: str
    contact: Contact = Contact.EXTERNAL
    arm: str = FRAME

    def ratio(self, size: dict[str, Fraction]) -> Fraction:
        """``(ω_driven − ω_A)/(ω_driver − ω_A) = ∓ N_driver / N_driven`` (Eqs. 7.24-7.25)."""
        r = size[self.driver] / size[self.driven]
        return -r if self.contact == Contact.EXTERNAL else r

    def factor(self, size: dict[str, Fraction]) -> str:
        """The book's factor, ``(-40/20)`` or ``(20/80)``."""
        sign = "-" if self.contact == Contact.EXTERNAL else ""
        return f"({sign}{_num(size[self.driver])}/{_num(size[self.driven])})"


def _num(x: Fraction) -> str:
    return str(x.numerator) if x.denominator == 1 else f"{float(x):g}"


@dataclass
class Train:
    """A gear train (Secs. 7.12-7.16).

    Attributes
    ----------
    size : dict
        Gear name -> its teeth (or its pitch radius: only ratios count).
    meshes : list of Mesh
    joined : list of tuple
        Members fixed together on one shaft (a compound gear, a gear and an arm).
    given : dict
        Member name -> its given angular velocity (or displacement).
    unit : str
        The unit of the given motions and of the results (``rev/min``, ``rad/s``, ``rev``).
    title : str
    source : str or None
    """

    size: dict[str, Fraction]
    meshes: list[Mesh]
    joined: list[tuple[str, ...]] = field(default_factory=list)
    given: dict[str, float] = field(default_factory=dict)
    unit: str = "rad/s"
    title: str = ""
    source: str | None = None
    turns: bool = False
    """The given motions are turns (angular displacements), not angular velocities."""
    by_teeth: bool = True
    """The sizes are teeth (else pitch radii)."""
    length_unit: str = "mm"
    """The unit of the pitch radii and of the module (the file's ``units``)."""
    module: float | None = None
    """The module the file gives with ``[teeth]`` (m = 1/P), in ``length_unit``; None: none."""

    @property
    def members(self) -> list[str]:
        """Every member, in the order of the file: gears, then arms not already named."""
        out = list(self.size)
        for m in self.meshes:
            if m.arm not in out and m.arm != FRAME:
                out.append(m.arm)
        for group in self.joined:
            out += [g for g in group if g not in out and g != FRAME]
        return out

    @property
    def arms(self) -> list[str]:
        """The members that carry the axes of a mesh (not the frame)."""
        return list(dict.fromkeys(m.arm for m in self.meshes if m.arm != FRAME))

    def coaxial_notes(self) -> list[str]:
        """A sun and a ring that mesh one planet on one arm but cannot share an axis.

        The sun's axis and the ring's are both the arm's: the planet's centre
        lies (N_sun + N_planet)/2 module from it through the sun and
        (N_ring − N_planet)/2 through the ring, so standard teeth of one module
        need ``N_ring = N_sun + 2 N_planet`` (pitch radii alike; Fig. 7.40,
        Sec. 7.14).  Otherwise the speeds still follow from the tooth numbers
        (Eq. 7.25), as with the profile-shifted teeth of Ferguson's paradox
        (Example 7.10, all external: not flagged), so this is a note, not a refusal.
        """
        notes: list[str] = []
        word = "N" if self.by_teeth else "R"
        for ring_mesh in self.meshes:
            if ring_mesh.contact != Contact.INTERNAL or ring_mesh.arm == FRAME:
                continue
            pair = (ring_mesh.driver, ring_mesh.driven)
            ring, planet = sorted(pair, key=lambda g: self.size[g], reverse=True)
            for m in self.meshes:
                if m.contact != Contact.EXTERNAL or m.arm != ring_mesh.arm \
                        or planet not in (m.driver, m.driven):
                    continue
                sun = m.driven if m.driver == planet else m.driver
                need = self.size[sun] + 2 * self.size[planet]
                if self.size[ring] != need:
                    what = ("standard teeth of one module" if self.by_teeth
                            else "their pitch radii")
                    notes.append(
                        f"note: ring gear {ring} and sun gear {sun} share arm "
                        f"{ring_mesh.arm}'s axis around planet {planet}: {what} need "
                        f"{word}_{ring} = {word}_{sun} + 2 {word}_{planet} = {_num(need)}, "
                        f"not {_num(self.size[ring])}"
                        + (" (else profile-shifted teeth, Sec. 7.11)" if self.by_teeth
                           else " (Fig. 7.40)"))
        return notes

    def shaft(self) -> dict[str, str]:
        """Each member -> the first member of its shaft (joined members move as one)."""
        rep = {m: m for m in [*self.members, FRAME]}

        def find(a: str) -> str:
            while rep[a] != a:
                a = rep[a]
            return a

        for group in self.joined:
            for other in group[1:]:
                rep[find(other)] = find(group[0])
        return {m: find(m) for m in rep}


@dataclass
class TrainSolution:
    """Every member's angular velocity (or displacement), counterclockwise positive."""

    train: Train
    omega: dict[str, float]
    freedom: int


def solve(train: Train) -> TrainSolution:
    """Solve the mesh equations and the given motions together (the independent check).

    Raises
    ------
    InputError
        Given motions that do not fix the train (fewer than its degrees of
        freedom) or contradict each other.
    """
    shaft = train.shaft()
    unknowns = list(dict.fromkeys(shaft[m] for m in train.members))
    frame = shaft[FRAME]
    col = {u: i for i, u in enumerate(unknowns)}
    rows: list[np.ndarray] = []
    rhs: list[float] = []

    def row() -> np.ndarray:
        return np.zeros(len(unknowns))

    for m in train.meshes:
        # N_j (ω_j − ω_A) − r N_j (ω_i − ω_A) = 0 with r the mesh's ratio, scaled by N_j
        r = float(m.ratio(train.size))
        coeff = {shaft[m.driven]: 1.0, shaft[m.driver]: -r, shaft[m.arm]: r - 1.0}
        a = row()
        for member, c in coeff.items():
            if member != frame:
                a[col[member]] += c
        rows.append(a)
        rhs.append(0.0)
    for member, value in train.given.items():
        s = shaft[member]
        if s == frame:
            if value != 0.0:
                raise InputError(f"{member} is joined to the frame: its motion is 0",
                                 key=f"speeds.{member}", file=train.source)
            continue
        a = row()
        a[col[s]] = 1.0
        rows.append(a)
        rhs.append(value)
    mesh_rank = np.linalg.matrix_rank(np.array(rows[: len(train.meshes)]).reshape(
        len(train.meshes), len(unknowns))) if train.meshes else 0
    freedom = len(unknowns) - int(mesh_rank)
    a_mat, b = np.array(rows).reshape(len(rows), len(unknowns)), np.array(rhs)
    rank = np.linalg.matrix_rank(a_mat) if len(rows) else 0
    if rank < len(unknowns):
        raise InputError(f"the train has {freedom} degree(s) of freedom: give the motion of "
                         f"{freedom} member(s) (gears or arm) in [speeds]", key="speeds",
                         file=train.source)
    x, *_ = np.linalg.lstsq(a_mat, b, rcond=None)
    scale = max(1.0, *(abs(v) for v in train.given.values()))
    if not np.allclose(a_mat @ x, b, rtol=0.0, atol=1e-9 * scale):
        raise InputError("the given motions contradict the meshes: give only as many as "
                         f"the train's {freedom} degree(s) of freedom", key="speeds",
                         file=train.source)
    omega = {m: (0.0 if shaft[m] == frame else float(x[col[shaft[m]]])) for m in train.members}
    return TrainSolution(train, omega, freedom)


@dataclass
class TableRow:
    """One row of the book's table: each member's entry as printed, and its value."""

    name: str
    cells: dict[str, str]


@dataclass
class Table:
    """The tabular analysis of Sec. 7.16 (Tables 7.3-7.5) and its answer."""

    arm: str
    turned: str
    coefficients: dict[str, Fraction]
    rows: list[TableRow]
    omega_arm: float
    omega_turned: float
    omega: dict[str, float]


def _paths(train: Train, start: str) -> dict[str, tuple[Fraction, list[str]]]:
    """From ``start`` with the arm held: each member's multiple of ω_B/A and its factors."""
    shaft = train.shaft()
    out: dict[str, tuple[Fraction, list[str]]] = {start: (Fraction(1), [])}
    todo = [start]
    while todo:
        here = todo.pop(0)
        coef, factors = out[here]
        for other in train.members:   # joined on one shaft: the same turn
            if other not in out and shaft[other] == shaft[here]:
                out[other] = (coef, factors)
                todo.append(other)
        for m in train.meshes:
            for a, b, r, f in ((m.driver, m.driven, m.ratio(train.size), m.factor(train.size)),
                               (m.driven, m.driver, 1 / m.ratio(train.size),
                                Mesh(m.driven, m.driver, m.contact).factor(train.size))):
                if a == here and b not in out:
                    out[b] = (coef * r, [f, *factors])
                    todo.append(b)
    return out


def tabular(train: Train) -> Table | None:
    """The book's three-step table (Sec. 7.16), for a train with one arm; None otherwise.

    Step 1 locks every gear to the arm (each turns ``ω_A``); step 2 holds the
    arm and turns the first gear B by ``ω_B/A`` (the others by their train
    values from B); step 3 adds them.  The two given motions then fix
    ``ω_A`` and ``ω_B/A``.
    """
    if len(train.arms) != 1 or len(train.given) != 2:
        return None
    arm = train.arms[0]
    shaft = train.shaft()
    gears = [g for g in train.size if shaft[g] != shaft[arm]]
    if not gears:
        return None
    turned = gears[0]
    paths = _paths(train, turned)
    if any(g not in paths for g in gears):
        return None
    coef = {m: (Fraction(0) if shaft[m] == shaft[arm] else paths[m][0]) for m in train.members}
    w_a, w_b = f"ω{arm}", f"ω{turned}/{arm}"
    if train.turns:
        w_a, w_b = f"Δθ{arm}", f"Δθ{turned}/{arm}"
    step1 = TableRow("1. Gears fixed to arm", {m: w_a for m in train.members})
    cells2, cells3 = {}, {}
    for m in train.members:
        if shaft[m] == shaft[arm]:
            cells2[m], cells3[m] = "0", w_a
        else:
            f = "".join(paths[m][1])
            cells2[m] = f"{f}{w_b}"
            cells3[m] = f"{w_a} + {f}{w_b}"
    # the given motions: ω_X = ω_A + c_X ω_B/A
    (m1, v1), (m2, v2) = train.given.items()
    a = np.array([[1.0, float(coef.get(m1, 0))], [1.0, float(coef.get(m2, 0))]])
    if m1 == FRAME or m2 == FRAME:
        return None
    if abs(np.linalg.det(a)) < 1e-12:
        return None
    omega_a, omega_b = np.linalg.solve(a, np.array([v1, v2]))
    omega = {m: float(omega_a + float(coef[m]) * omega_b) for m in train.members}
    return Table(arm, turned, coef,
                 [step1, TableRow("2. Arm fixed", cells2), TableRow("3. Total", cells3)],
                 float(omega_a), float(omega_b), omega)


def formula(train: Train, first: str, last: str) -> tuple[Fraction, str] | None:
    """Eq. (7.25): the train value ``θ'_LF/A`` from F to L seen from the arm, and the arm.

    The product of the meshes' train values (Eq. 7.24) along the meshes from
    F to L, all carried by the same member A; None when F and L are not so
    connected.
    """
    carriers = {m.arm for m in train.meshes}
    for arm in carriers:
        sub = Train(train.size, [m for m in train.meshes if m.arm == arm], train.joined)
        if first not in sub.members or last not in sub.members:
            continue
        paths = _paths(sub, first)
        if last in paths:
            return paths[last][0], arm
    return None
