"""Instant centers of velocity: primary centers by inspection, the rest by Kennedy's theorem.

A mechanism of ``n`` links has ``N = n(n-1)/2`` instant centers (Eq. 3.20).
They are found the way the book teaches (Secs. 3.12-3.14):

1. **Primary centers, by inspection.**  A pin is the instant center of the
   links it joins.  A slider (prismatic pair) gives a center at infinity,
   perpendicular to the line of sliding: the two links do not turn relative to
   each other (Fig. 3.26, Eq. 3.21).  A point of rolling contact is the center
   of the two rolling bodies (Fig. 3.25).  A pin in a slot (direct contact
   with slipping, Fig. 3.24) does not give the center, only a **line** through
   it: the common normal at the pin (for a straight slot, the perpendicular to
   the slot through the pin; for a circular slot, the line through the pin and
   the slot's center).  A circle rolling on a line (``[[rolling]]``) touches
   it at the foot of the perpendicular from its center; contacts the file
   cannot state are passed as :class:`KnownCenter` and :class:`KnownLine`.
2. **Secondary centers, by the Aronhold-Kennedy theorem** (Sec. 3.13): the
   three centers of any three links lie on one straight line.  Following the
   *Kennedy circle*, an unknown center ``Iij`` is found as soon as two lines of
   centers through it are known: two triangles ``i, j, k`` with ``Iik`` and
   ``Ijk`` both known, or one triangle and the common normal of a slot.  The
   two lines meet at ``Iij``.
3. **Several degrees of freedom** (Sec. 5.4, Example 5.5): some centers
   cannot be reached by Kennedy's theorem; they depend on the ratio of the
   input speeds.  They are found from the velocities as the point where both
   links have the same velocity, and flagged so.  The same is done, for one
   degree of freedom, at a posture where the lines of centers of a pair
   coincide (the velocities of a unit input speed serve when the file gives
   none).

Points at infinity are handled in homogeneous coordinates with no special
case: the line through a finite center and a center at infinity is the
parallel through the finite one, and two parallel lines meet at infinity.
Two special triangles are named: when ``Iik`` and ``Ijk`` are both at
infinity, links ``i`` and ``j`` do not turn relative to each other, so ``Iij``
is the point at infinity of its other line of centers (the Scotch yoke of
Fig. 3.27); when ``Iik`` and ``Ijk`` coincide, ``Iij`` is that same point.

Every step is recorded in a :class:`~graphkin.construction.Construction`
(``diagram="centers"``) with the book's words, so that the drawings can show
the Kennedy circle and the order of discovery, and ``construction.evaluate()``
replays to the same centers.

The module also gives the velocity analyses that use the centers: the
line-of-centers method (Sec. 3.15), the angular-velocity-ratio theorem
(Sec. 3.16, Eq. 3.22), the first-order kinematic coefficients from instant
centers (Sec. 3.17, Eqs. 3.24 and 3.26) and the mechanical advantage
(Sec. 3.19, Eq. 3.34).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Secs. 3.12-3.17 and 3.19; Sec. 5.4 (Example 5.5).

Examples
--------
The four-bar of Examples 3.1 and 3.13:

>>> import graphkin
>>> sol = graphkin.loads('''
... units = { length = "in" }
... [links.1]
... A = [0, 0]
... D = [10, 0]
... [links.2]
... A = [0, 0]
... B = [4, 0]
... [links.3]
... B = [0, 0]
... C = [18, 0]
... [links.4]
... D = [0, 0]
... C = [11, 0]
... [drive]
... link = 2
... angle = 120
... omega = "900 rev/min"
... [assembly]
... C = [15, 10]
... ''').solve()
>>> ic = instant_centers(sol)
>>> ic.order
['I12', 'I14', 'I23', 'I34', 'I13', 'I24']
>>> print(ic["I13"].note)
I13 lies on the line I12-I23 and on the line I14-I34 (Kennedy).
>>> [round(float(v), 4) for v in ic["I24"].xy]
[-11.0627, 0.0]
>>> round(float(angular_velocity_ratio(sol, "2", "4")), 4)  # ω4/ω2 (Eq. 3.22)
0.5252
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from enum import StrEnum
from itertools import combinations
from typing import Any, Literal

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction import Construction, Role
from graphkin.construction.ops import OPS
from graphkin.errors import DegenerateError, GraphkinError, IdealPointError, InputError
from graphkin.geometry import ops as g
from graphkin.geometry.point import Point
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = [
    "How",
    "Center",
    "InstantCenters",
    "KnownCenter",
    "KnownLine",
    "LineOfCentersVelocity",
    "center_label",
    "pair_key",
    "sort_links",
    "instant_centers",
    "instant_center",
    "angular_velocity_ratio",
    "kinematic_coefficient",
    "mechanical_advantage",
    "line_of_centers_velocity",
    "instant_centers_json",
    "instant_centers_text",
]

Pair = tuple[str, str]
Array = np.ndarray

#: A meet of two lines of centers (or a join of two centers) whose sine, in
#: coordinates scaled by the size of the mechanism, is below this loses more
#: than 6 of 16 digits: another triangle, or the velocities, are used instead.
_WELL_CONDITIONED = 1e-6


# ---------------------------------------------------------------------------
# names
# ---------------------------------------------------------------------------

def _id_key(lid: str) -> tuple[int, int, str]:
    return (0, int(lid), "") if lid.isdigit() else (1, 0, lid)


def sort_links(ids: Iterable[object]) -> list[str]:
    """Link ids in the book's order: numeric ids by number, then named ones.

    Examples
    --------
    >>> sort_links(["10", "2", "1", "crank"])
    ['1', '2', '10', 'crank']
    """
    return sorted((str(i) for i in ids), key=_id_key)


def _triangle(i: str, j: str, k: str) -> tuple[str, str, str]:
    """The links of a Kennedy triangle in the book's order."""
    a, b, c = sort_links([i, j, k])
    return a, b, c


def pair_key(i: object, j: object) -> Pair:
    """The pair of link ids with the lower id first (``I31`` is ``I13``).

    Examples
    --------
    >>> pair_key(3, 1)
    ('1', '3')
    >>> pair_key("13", "2")
    ('2', '13')
    """
    a, b = str(i), str(j)
    if a == b:
        raise InputError(f"an instant center needs two different links, not {a} and {b}")
    return (a, b) if _id_key(a) <= _id_key(b) else (b, a)


def center_label(i: object, j: object) -> str:
    """The book's name of an instant center: ``I13``, or ``I1-13`` for longer ids.

    Examples
    --------
    >>> center_label(3, 1), center_label(1, 13)
    ('I13', 'I1-13')
    """
    a, b = pair_key(i, j)
    return f"I{a}{b}" if len(a) == 1 and len(b) == 1 else f"I{a}-{b}"


def _parse_pair(key: object) -> Pair:
    """``"I13"``, ``"I1-13"``, ``"1-3"``, ``(1, 3)`` -> ``("1", "3")``."""
    if isinstance(key, (tuple, list)) and len(key) == 2:
        return pair_key(*key)
    if isinstance(key, str):
        s = key[1:] if key[:1] in ("I", "i") else key
        if "-" in s:
            a, b = s.split("-", 1)
            return pair_key(a, b)
        if len(s) == 2:
            return pair_key(s[0], s[1])
    raise KeyError(f"not an instant center: {key!r} (write 'I13', 'I1-13', '1-3' or (1, 3))")


# ---------------------------------------------------------------------------
# values
# ---------------------------------------------------------------------------

class How(StrEnum):
    """How an instant center was found."""

    PRIMARY = "primary"
    """By inspection: a pin, a slider (at infinity) or a point of rolling contact."""
    KENNEDY = "kennedy"
    """By the Aronhold-Kennedy theorem: the meet of two lines of centers."""
    VELOCITIES = "velocities"
    """From the velocities: the point where both links have the same velocity."""


@dataclass(frozen=True)
class KnownCenter:
    """A primary center known by inspection that the mechanism file does not state.

    Use it for rolling contact (the point of contact is the instant center of
    the two bodies, Fig. 3.25) until the file format has it.

    Parameters
    ----------
    links : pair of link ids
    point : (x, y)
        World coordinates at the solution's posture (arrays for a batch).
    source : str
        What it is, for the notes (``"rolling contact"``).
    """

    links: tuple[object, object]
    point: tuple[Any, Any]
    source: str = "rolling contact"


@dataclass(frozen=True)
class KnownLine:
    """A line known to carry an instant center: the common normal at a direct contact.

    Parameters
    ----------
    links : pair of link ids
    through : (x, y)
        A point of the line (the contact point), world coordinates.
    direction : (dx, dy)
        Direction of the common normal.
    source : str
    """

    links: tuple[object, object]
    through: tuple[Any, Any]
    direction: tuple[Any, Any]
    source: str = "direct contact"


@dataclass
class Center:
    """One instant center and how it was found.

    Attributes
    ----------
    pair : (str, str)
        The two links, lower id first.
    label : str
        ``"I13"``.
    point : ndarray, shape (..., 3)
        Homogeneous coordinates: ``(x, y, 1)``, or ``(dx, dy, 0)`` at infinity.
    how : How
        Primary, Kennedy or velocities.
    source : str
        ``"pin B"``, ``"slider 4 on 1"``, ``"Kennedy"``...
    order : int
        Order of discovery (1 = first), as on the Kennedy circle.
    lines : tuple of str
        Labels of the lines of centers it was found on.
    triangles : tuple of (str, str, str)
        The link triangles whose lines of centers were used.
    speed_dependent : bool
        True when it depends on the ratio of the input speeds (several degrees
        of freedom, Sec. 5.4): it was found from the velocities.
    note : str
        One sentence in the book's words.
    """

    pair: Pair
    label: str
    point: Array
    how: How
    source: str
    order: int
    lines: tuple[str, ...] = ()
    triangles: tuple[tuple[str, str, str], ...] = ()
    speed_dependent: bool = False
    note: str = ""

    @property
    def is_ideal(self) -> Any:
        """True where the center is at infinity (an array for a batch)."""
        return g.is_ideal(self.point)

    @property
    def xy(self) -> Array:
        """Finite coordinates.

        Raises
        ------
        IdealPointError
            For one posture whose center is at infinity.
        """
        if self.point.ndim == 1 and self.point[2] == 0.0:
            raise IdealPointError(f"{self.label} is at infinity; ask for .direction",
                                  label=self.label)
        return g.xy(self.point)

    @property
    def direction(self) -> Array:
        """Unit direction of a center at infinity (NaN where finite, for a batch).

        Raises
        ------
        GraphkinError
            For one posture whose center is finite.
        """
        if self.point.ndim == 1 and self.point[2] != 0.0:
            raise GraphkinError(f"{self.label} is a finite point; ask for .xy", label=self.label)
        d = self.point[..., :2]
        return np.where(g.is_ideal(self.point)[..., None], d, np.nan)

    def as_point(self) -> Point:
        """The center as a :class:`~graphkin.geometry.Point` (one posture only)."""
        return Point.from_array(self.point)

    def __repr__(self) -> str:
        if self.point.ndim == 1:
            if self.point[2] == 0.0:
                where = f"at infinity ({self.point[0]:.6g}, {self.point[1]:.6g})"
            else:
                where = f"({self.point[0]:.6g}, {self.point[1]:.6g})"
        else:
            where = f"{self.point.shape[0]} postures"
        return f"<{self.label} {where}, {self.how.value}, #{self.order}>"


@dataclass
class InstantCenters:
    """All instant centers of a solved mechanism and their construction.

    Attributes
    ----------
    solution : Solution
    links : list of str
        Link ids in the book's order (the Kennedy circle's numbers).
    centers : dict
        Pair -> :class:`Center`, in order of discovery.
    construction : Construction
        The recorded steps (``diagram="centers"``).
    values : dict
        Label -> array: every point and line of the construction.
    missing : list of pairs
        Centers that could not be found (several degrees of freedom and no
        velocities in the file).
    notes : list of str
    """

    solution: Solution
    links: list[str]
    centers: dict[Pair, Center]
    construction: Construction
    values: dict[str, Array]
    missing: list[Pair] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)

    def __getitem__(self, key: object) -> Center:
        """``ic["I13"]``, ``ic["1-3"]``, ``ic[1, 3]`` or ``ic[("3", "1")]``."""
        pair = _parse_pair(key)
        if pair not in self.centers:
            if pair in self.missing:
                raise KeyError(f"{center_label(*pair)} was not found: {'; '.join(self.notes)}")
            raise KeyError(f"no links {pair[0]} and {pair[1]} in this mechanism")
        return self.centers[pair]

    def __contains__(self, key: object) -> bool:
        try:
            return _parse_pair(key) in self.centers
        except (KeyError, InputError):
            return False

    def __iter__(self) -> Any:
        return iter(self.centers.values())

    def __len__(self) -> int:
        return len(self.centers)

    def center(self, i: object, j: object) -> Center:
        """The center of links ``i`` and ``j`` (either order)."""
        return self[(i, j)]

    @property
    def order(self) -> list[str]:
        """Labels in order of discovery."""
        return [c.label for c in self.centers.values()]

    @property
    def count(self) -> int:
        """``N = n(n-1)/2`` (Eq. 3.20)."""
        n = len(self.links)
        return n * (n - 1) // 2

    def kennedy_circle(self) -> dict[str, Any]:
        """The Kennedy circle (Fig. 3.22b) as plain data, for drawing.

        Returns
        -------
        dict
            ``links``: ids in order around the circle; ``positions``: id ->
            (x, y) on a unit circle (link 1 at the top, then counterclockwise);
            ``edges``: one per pair, ``{"pair", "label", "order", "how",
            "known"}`` with ``order`` ``None`` and ``known`` False for a
            center not found (a dashed line).
        """
        n = len(self.links)
        pos = {lid: (math.cos(math.pi / 2 + 2 * math.pi * k / n),
                     math.sin(math.pi / 2 + 2 * math.pi * k / n))
               for k, lid in enumerate(self.links)}
        edges = []
        for c in self.centers.values():
            edges.append({"pair": c.pair, "label": c.label, "order": c.order,
                          "how": c.how.value, "known": True})
        for p in self.missing:
            edges.append({"pair": p, "label": center_label(*p), "order": None, "how": None,
                          "known": False})
        return {"links": list(self.links), "positions": pos, "edges": edges}


# ---------------------------------------------------------------------------
# the search
# ---------------------------------------------------------------------------

def _as_float(x: Any) -> Any:
    a = np.asarray(x, dtype=float)
    return float(a) if a.ndim == 0 else a


def _perp(v: Array) -> Array:
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


class _Kennedy:
    """Finds the centers one at a time and records each step."""

    def __init__(self, sol: Solution, tol: Tolerance, contacts: Sequence[object]) -> None:
        self.sol = sol
        self.mech: Mechanism = sol.mechanism
        self.tol = tol
        self.links = sort_links(self.mech.links)
        self.cx = Construction(title=f"Instant centers: {self.mech.title}".rstrip(": "))
        self.env: dict[str, Array] = {}
        self.centers: dict[Pair, Center] = {}
        self.normals: dict[Pair, list[tuple[str, str]]] = {}  # pair -> [(line label, source)]
        self.failed: set[Pair] = set()
        self.notes: list[str] = []
        self.contacts = list(contacts)
        self.several = len(self.mech.drives) > 1 or self.mech.mobility() > 1
        self._unit: Solution | Literal[False] | None = None  # False: tried, none
        shape = np.shape(sol.links[FRAME].angle)
        # a batch's postures that could not be assembled are NaN throughout: ignored
        self.valid = np.broadcast_to(np.asarray(sol.valid, dtype=bool), shape)

    # ---- recording ----------------------------------------------------
    def add(self, op_name: str, inputs: tuple[str, ...], output: str, *,
            role: Role = Role.AUXILIARY, note: str = "", **params: Any) -> Array:
        step = self.cx.add(op_name, inputs, (output,), role=role, note=note, diagram="centers",
                           **params)
        args = [self.env[i] for i in inputs]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            (out,) = OPS[op_name](*args, tol=self.tol, **step.params)
        self.env[output] = np.asarray(out, dtype=float)
        return self.env[output]

    def found(self, pair: Pair, how: How, source: str, note: str, *, lines: tuple[str, ...] = (),
              triangles: tuple[tuple[str, str, str], ...] = (), speed: bool = False) -> None:
        lab = center_label(*pair)
        self.centers[pair] = Center(pair, lab, self.env[lab], how, source, len(self.centers) + 1,
                                    lines, triangles, speed, note)

    def fresh(self, label: str) -> str:
        if label not in self.env:
            return label
        k = 2
        while f"{label}#{k}" in self.env:
            k += 1
        return f"{label}#{k}"

    # ---- primary centers and lines --------------------------------------
    def primary(self) -> None:
        sol, mech = self.sol, self.mech
        found: dict[Pair, tuple[str, Any, str, str]] = {}
        for pin in mech.pins:
            p = sol.position(pin.name)
            for a, b in combinations(pin.links, 2):
                pair = pair_key(a, b)
                if pair in found:
                    continue
                lab = center_label(*pair)
                found[pair] = ("point", (_as_float(p[..., 0]), _as_float(p[..., 1])),
                               f"pin {pin.name}",
                               f"{lab} is the pin {pin.name}: a point common to links "
                               f"{pair[0]} and {pair[1]} (primary, by inspection).")
        for s in mech.sliders:
            pair = pair_key(s.link, s.on)
            if pair in found:
                continue
            lab = center_label(*pair)
            th = np.asarray(sol.links[s.on].angle, dtype=float) + s.direction_angle
            n = np.stack([-np.sin(th), np.cos(th)], axis=-1)
            found[pair] = ("ideal_point", (_as_float(n[..., 0]), _as_float(n[..., 1])),
                           f"slider {s.link} on {s.on}",
                           f"{lab} is at infinity, perpendicular to the line on which {s.link} "
                           f"slides on {s.on}: the two links do not turn relative to each other "
                           "(primary, Eq. 3.21).")
        for r in getattr(mech, "rolling", ()):
            pair = pair_key(r.link, r.on)
            if pair in found:
                continue
            lab = center_label(*pair)
            found[pair] = ("rolling", r, f"rolling contact of {r.link} on {r.on}",
                           f"{lab} is the point of rolling contact of {r.link} on {r.on}: the "
                           "foot of the perpendicular from the center of the circle to the line "
                           "it rolls on; no slip, so the velocities are equal there (primary, "
                           "Fig. 3.25).")
        for c in self.contacts:
            if not isinstance(c, KnownCenter):
                continue
            pair = pair_key(*c.links)
            if pair in found:
                continue
            lab = center_label(*pair)
            found[pair] = ("point", (_as_float(c.point[0]), _as_float(c.point[1])), c.source,
                           f"{lab} is the point of {c.source} of links {pair[0]} and {pair[1]}: "
                           "no slip, so their velocities are equal there (primary).")
        for pair in sorted(found, key=lambda p: (_id_key(p[0]), _id_key(p[1]))):
            kind, arg, source, note = found[pair]
            lab = center_label(*pair)
            if kind == "point":
                self.add("point", (), lab, role=Role.GIVEN, note=note, xy=arg)
            elif kind == "rolling":
                self.rolling_contact(arg, lab, note)
            else:
                self.add("ideal_point", (), lab, role=Role.GIVEN, note=note, direction=arg)
            self.found(pair, How.PRIMARY, source, note)
        self.slot_normals()

    def rolling_contact(self, r: Any, lab: str, note: str) -> None:
        """The contact point of a rolling circle (a primary center).

        On a line it is the foot of the perpendicular from the circle's center;
        on a circle, the point of the line of centers at the circle's radius.
        """
        sol = self.sol
        on = sol.links[r.on]
        center = self.fresh(r.center)
        c = sol.position(r.center, r.link)
        self.add("point", (), center, role=Role.GIVEN,
                 note=f"The center {r.center} of the rolling circle of link {r.link}.",
                 xy=(_as_float(c[..., 0]), _as_float(c[..., 1])))
        stem = r.key
        if not r.on_line:
            # circles touch on their line of centers, R from the center of on's circle
            o = on.position(r.on_center)
            self.add("point", (), f"{stem}:O", role=Role.GIVEN,
                     note=f"The center of link {r.on}'s circle.",
                     xy=(_as_float(o[..., 0]), _as_float(o[..., 1])))
            self.add("along_ray", (f"{stem}:O", center), lab, role=Role.GIVEN, note=note,
                     distance=r.on_radius)
            return
        for k, loc in enumerate((r.p0, r.p1)):
            q = on.position(loc)
            self.add("point", (), f"{stem}:L{k}", role=Role.GIVEN,
                     xy=(_as_float(q[..., 0]), _as_float(q[..., 1])))
        self.add("join", (f"{stem}:L0", f"{stem}:L1"), f"{stem}:line",
                 note=f"The line of link {r.on} on which link {r.link} rolls.")
        self.add("perpendicular", (f"{stem}:line", center), f"{stem}:normal",
                 note=f"The common normal: through {r.center}, perpendicular to the line.")
        self.add("meet", (f"{stem}:line", f"{stem}:normal"), lab, role=Role.GIVEN, note=note)

    def slot_normals(self) -> None:
        sol = self.sol
        for s in self.mech.slots:
            pair = pair_key(s.link, s.on)
            if pair in self.centers:
                continue
            lab = center_label(*pair)
            pin = self.fresh(s.point)
            p = sol.position(s.point, s.link)
            self.add("point", (), pin, role=Role.GIVEN,
                     note=f"The pin {s.point} of link {s.link} in the slot of link {s.on}.",
                     xy=(_as_float(p[..., 0]), _as_float(p[..., 1])))
            on = sol.links[s.on]
            stem = f"slots[{s.index}]"
            normal = self.fresh(f"n({s.point}):{lab}")
            if s.is_line:
                assert s.p0 is not None and s.p1 is not None
                q0, q1 = on.position(s.p0), on.position(s.p1)
                self.add("point", (), f"{stem}:L0", role=Role.GIVEN,
                         xy=(_as_float(q0[..., 0]), _as_float(q0[..., 1])))
                self.add("point", (), f"{stem}:L1", role=Role.GIVEN,
                         xy=(_as_float(q1[..., 0]), _as_float(q1[..., 1])))
                self.add("join", (f"{stem}:L0", f"{stem}:L1"), f"{stem}:line",
                         note=f"The slot of link {s.on}: the path of {s.point} on it.")
                self.add("perpendicular", (f"{stem}:line", pin), normal,
                         note=f"{lab} lies on the common normal at {s.point}: the perpendicular "
                              "to the slot through the pin (direct contact, Sec. 3.14).")
            else:
                assert s.center is not None
                k = on.position(s.center)
                self.add("point", (), f"{stem}:center", role=Role.GIVEN,
                         note=f"The center of the circular slot of link {s.on}.",
                         xy=(_as_float(k[..., 0]), _as_float(k[..., 1])))
                self.add("join", (f"{stem}:center", pin), normal,
                         note=f"{lab} lies on the common normal at {s.point}: the line through "
                              "the pin and the center of the circular slot (direct contact, "
                              "Sec. 3.14).")
            self.normals.setdefault(pair, []).append(
                (normal, f"common normal at {s.point} (slot of link {s.on})"))
        for c in self.contacts:
            if not isinstance(c, KnownLine):
                continue
            pair = pair_key(*c.links)
            if pair in self.centers:
                continue
            lab = center_label(*pair)
            through = self.fresh(f"contact:{lab}")
            self.add("point", (), through, role=Role.GIVEN, note=f"The point of {c.source}.",
                     xy=(_as_float(c.through[0]), _as_float(c.through[1])))
            d = self.fresh(f"normal∞:{lab}")
            self.add("ideal_point", (), d, role=Role.GIVEN,
                     direction=(_as_float(c.direction[0]), _as_float(c.direction[1])))
            normal = self.fresh(f"n:{lab}")
            self.add("join", (through, d), normal,
                     note=f"{lab} lies on the common normal at the {c.source} (Sec. 3.14).")
            self.normals.setdefault(pair, []).append((normal, f"common normal ({c.source})"))

    # ---- Kennedy --------------------------------------------------------
    def triangles(self, pair: Pair) -> list[str]:
        i, j = pair
        return [k for k in self.links if k not in pair
                and pair_key(i, k) in self.centers and pair_key(j, k) in self.centers]

    def every(self, flags: Array) -> bool:
        """True when ``flags`` holds at every posture that could be assembled."""
        return bool(np.all(np.broadcast_to(flags, self.valid.shape)[self.valid]))

    def same(self, p: Array, q: Array) -> bool:
        pi, qi = g.is_ideal(p), g.is_ideal(q)
        if self.every(pi) and self.every(qi):
            return self.every(np.abs(g.cross2(p, q)) <= self.tol.angle)
        if not (self.every(~pi) and self.every(~qi)):
            return False
        with np.errstate(invalid="ignore"):
            d = g.distance(p, q)
        return self.every(d <= self.tol.length(self.mech.scale))

    def tri_line(self, pair: Pair, k: str) -> tuple[str, str, str]:
        """The two centers of triangle (i, j, k) that carry Iij, lower label first."""
        a, b = sorted([pair_key(pair[0], k), pair_key(pair[1], k)],
                      key=lambda p: (_id_key(p[0]), _id_key(p[1])))
        la, lb = center_label(*a), center_label(*b)
        return la, lb, f"{la}-{lb}"

    def make_line(self, pair: Pair, opt: tuple[str, str, Array, float]) -> str:
        kind, ref = opt[0], opt[1]
        if kind == "normal":
            return ref
        la, lb, name = self.tri_line(pair, ref)
        if name not in self.env:
            i, j = pair
            self.add("join", (la, lb), name,
                     note=f"The line of centers {name}: {center_label(i, j)} lies on it "
                          f"(links {', '.join(sort_links([i, j, ref]))}: three centers on one "
                          "straight line).")
        return name

    def describe(self, pair: Pair, opt: tuple[str, str, Array, float]) -> str:
        kind, ref = opt[0], opt[1]
        if kind == "normal":
            src = dict(self.normals[pair])[ref]
            return "the " + src
        return "the line " + self.tri_line(pair, ref)[2]

    def point_hat(self, p: Array) -> Array:
        q = np.asarray(p, dtype=float) * np.array([1.0 / self.mech.scale] * 2 + [1.0])
        return q / np.linalg.norm(q, axis=-1, keepdims=True)

    def line_hat(self, line: Array) -> Array:
        q = np.asarray(line, dtype=float) * np.array([1.0, 1.0, 1.0 / self.mech.scale])
        return q / np.linalg.norm(q, axis=-1, keepdims=True)

    def quality(self, u: Array, v: Array) -> float:
        """Sine of the angle between two unit homogeneous vectors (worst entry of a batch).

        For two points (lengths over the figure's size) it says how far apart
        they are, for two lines how far from coincident: the join or meet
        loses about ``-log10(quality)`` digits.
        """
        with np.errstate(invalid="ignore"):
            s = np.linalg.norm(np.cross(u, v), axis=-1)
        s = np.where(np.isfinite(s), s, 0.0)[self.valid]
        return float(np.min(s)) if s.size else 0.0

    def ok(self, a: Array) -> bool:
        """True when ``a`` has an answer at every posture that could be assembled."""
        return self.every(np.all(np.isfinite(a), axis=-1))

    def try_pair(self, pair: Pair, enough: float) -> bool:
        """Find ``Iij`` by Kennedy's theorem if two lines of centers meet well enough."""
        i, j = pair
        lab = center_label(*pair)
        tris = self.triangles(pair)
        for k in tris:
            la, lb, _ = self.tri_line(pair, k)
            if self.same(self.env[la], self.env[lb]):
                note = (f"{lab} coincides with {la} and {lb}: where links {i}, {j} and {k} all "
                        "have the same velocity (Kennedy).")
                self.add("same_point", (la, lb), lab, role=Role.RESULT, note=note)
                self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la, lb),
                           triangles=(_triangle(i, j, k),))
                return True
        # (kind, ref, line, quality of the line)
        opts: list[tuple[str, str, Array, float]] = []
        for name, _src in self.normals.get(pair, []):
            opts.append(("normal", name, self.env[name], 1.0))
        parallel_to: list[str] = []
        for k in tris:
            la, lb, name = self.tri_line(pair, k)
            p, q = self.env[la], self.env[lb]
            if self.every(g.is_ideal(p)) and self.every(g.is_ideal(q)):
                parallel_to.append(k)
                continue
            with np.errstate(invalid="ignore", divide="ignore"):
                line = g.join(p, q, self.tol)
            if self.ok(line):
                opts.append(("tri", k, line, self.quality(self.point_hat(p), self.point_hat(q))))
        best: tuple[float, int, int] | None = None
        for (ia, a), (ib, b) in combinations(enumerate(opts), 2):
            with np.errstate(invalid="ignore", divide="ignore"):
                pt = g.meet(a[2], b[2], self.tol)
            if not self.ok(pt):
                continue
            qual = min(a[3], b[3], self.quality(self.line_hat(a[2]), self.line_hat(b[2])))
            if qual >= enough and (best is None or qual > best[0]):
                best = (qual, ia, ib)
        if best is not None:
            a, b = opts[best[1]], opts[best[2]]
            la, lb = self.make_line(pair, a), self.make_line(pair, b)
            note = (f"{lab} lies on {self.describe(pair, a)} and on {self.describe(pair, b)} "
                    "(Kennedy).")
            self.add("meet", (la, lb), lab, role=Role.RESULT, note=note)
            tri = tuple(_triangle(i, j, o[1]) for o in (a, b) if o[0] == "tri")
            self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la, lb), triangles=tri)
            return True
        good = [o for o in opts if o[3] >= enough]
        if parallel_to and good:
            k = parallel_to[0]
            a = max(good, key=lambda o: o[3])
            la = self.make_line(pair, a)
            ca, cb, _ = self.tri_line(pair, k)
            note = (f"{lab} lies on {self.describe(pair, a)}; {ca} and {cb} are both at "
                    f"infinity, so links {i} and {j} do not turn relative to each other and "
                    f"{lab} is at infinity on that line (Kennedy, Fig. 3.27).")
            self.add("at_infinity_on", (la,), lab, role=Role.RESULT, note=note)
            tris_ij = [_triangle(i, j, k)]
            if a[0] == "tri":
                tris_ij.insert(0, _triangle(i, j, a[1]))
            self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la,),
                       triangles=tuple(tris_ij))
            return True
        return False

    def known_lines(self, pair: Pair) -> int:
        return len(self.normals.get(pair, [])) + len(self.triangles(pair))

    # ---- from the velocities (several degrees of freedom) --------------
    def velocities(self) -> Solution | None:
        """A solution with velocities, or None.

        The given one; or, for one degree of freedom and no rates in the file,
        the same posture at a unit input speed (the centers of a
        one-degree-of-freedom mechanism do not depend on the speed, Sec. 3.14).
        """
        if self.sol.has_rates:
            return self.sol
        if self._unit is not None:
            return self._unit or None
        self._unit = False
        if len(self.mech.drives) != 1 or _is_batch(self.sol):
            return None
        from dataclasses import replace

        from graphkin.kinematics.analytic import solve_analytic

        drive = replace(self.mech.drives[0], rate=1.0, rate2=0.0)
        mech = replace(self.mech, drives=(drive,), rates=None)
        guess = {lid: (float(st.origin[0]), float(st.origin[1]), float(st.angle))
                 for lid, st in self.sol.links.items() if lid != FRAME}
        try:
            self._unit = solve_analytic(mech, guess=guess, tol=self.tol)
        except GraphkinError:
            return None
        return self._unit

    def by_velocities(self, unknown: list[Pair]) -> bool:
        sol = self.velocities()
        if sol is None:
            return False
        drives = {d.link for d in self.mech.drives}
        cands = [p for p in unknown if p not in self.failed]
        if not cands:
            return False
        cands.sort(key=lambda p: (0 if set(p) <= drives else 1, -self.known_lines(p),
                                  _id_key(p[0]), _id_key(p[1])))
        for pair in cands:
            h = _equal_velocity_point(sol, pair[0], pair[1], self.mech.scale, self.tol)
            if not self.ok(h):
                self.failed.add(pair)
                continue
            i, j = pair
            lab = center_label(*pair)
            on = ""
            tris = self.triangles(pair)
            if tris:
                _, _, name = self.tri_line(pair, tris[0])
                on = f" It lies on the line {name}, where ω{i}/ω{j} sets its place (Eq. 3.22)."
            if self.several:
                note = (f"{lab} cannot be found by Kennedy's theorem alone: it is the point "
                        f"where links {i} and {j} have equal velocities, and it depends on the "
                        f"ratio of the input speeds (several degrees of freedom, Sec. 5.4).{on}")
            else:
                unit = "" if sol is self.sol else (
                    " (for a unit input speed: with one degree of freedom the place does not "
                    "depend on the speed)")
                note = (f"{lab} cannot be found by Kennedy's theorem here (its lines of centers "
                        "coincide or meet at too small an angle): it is the point where links "
                        f"{i} and {j} have equal velocities{unit} (Sec. 3.12).{on}")
            self.add("homogeneous_point", (), lab, role=Role.RESULT, note=note,
                     h=_as_float(h) if np.ndim(h) > 1 else tuple(float(v) for v in h))
            self.found(pair, How.VELOCITIES, "velocities", note, speed=self.several)
            return True
        return False

    # ---- driver -------------------------------------------------------
    def run(self) -> InstantCenters:
        self.primary()
        pairs = [pair_key(a, b) for a, b in combinations(self.links, 2)]
        while True:
            unknown = [p for p in pairs if p not in self.centers]
            if not unknown:
                break
            if any(self.try_pair(p, _WELL_CONDITIONED) for p in unknown):
                continue
            if self.by_velocities(unknown):
                continue
            # no velocities to fall back on: take a poorly conditioned meet rather than none
            if not any(self.try_pair(p, self.tol.angle) for p in unknown):
                break
        missing = [p for p in pairs if p not in self.centers]
        if missing:
            names = ", ".join(center_label(*p) for p in missing)
            if self.velocities() is None and self.several:
                self.notes.append(f"{names}: not found by Kennedy's theorem; they depend on the "
                                  "input speeds, which the file does not give (Sec. 5.4)")
            else:
                self.notes.append(f"{names}: not found (the two links have no relative motion "
                                  "here, or their lines of centers coincide)")
        return InstantCenters(self.sol, self.links, self.centers, self.cx, self.env, missing,
                              self.notes)


def _world_origin_velocity(sol: Solution, lid: str) -> tuple[Array, Array]:
    """``(u, ω)``: velocity of the point of link ``lid`` at the world origin, and ω."""
    st = sol.links[lid]
    if st.omega is None or st.origin_velocity is None:
        raise InputError("the velocities are not known (the file gives no rates)")
    w = np.asarray(st.omega, dtype=float)
    u = np.asarray(st.origin_velocity, dtype=float) - w[..., None] * _perp(
        np.asarray(st.origin, dtype=float))
    return u, w


def _equal_velocity_point(sol: Solution, i: str, j: str, scale: float,
                          tol: Tolerance) -> Array:
    """Homogeneous point where links ``i`` and ``j`` have the same velocity (Sec. 3.12).

    With ``V_k(P) = u_k + ω_k k × P``, equal velocities give
    ``(ω_i - ω_j) k × P = u_j - u_i``, so ``P = k × (u_i - u_j) / (ω_i - ω_j)``
    (Eq. 3.18 for the relative motion).  Equal ω: at infinity, perpendicular
    to the relative velocity.  No relative motion at all: NaN.
    """
    ui, wi = _world_origin_velocity(sol, i)
    uj, wj = _world_origin_velocity(sol, j)
    du = ui - uj
    h = np.concatenate([_perp(du) / scale, (wi - wj)[..., None]], axis=-1)
    p = g.normalize_point(h, tol)
    return np.where(g.is_ideal(p)[..., None], p, p * np.array([scale, scale, 1.0]))


# ---------------------------------------------------------------------------
# the public API
# ---------------------------------------------------------------------------

def instant_centers(sol: Solution, *, tol: Tolerance | None = None,
                    contacts: Sequence[KnownCenter | KnownLine] = ()) -> InstantCenters:
    """Every instant center of a solved mechanism, found the way the book teaches.

    Parameters
    ----------
    sol : Solution
        One posture or a batch (every array then has a leading axis).
    tol : Tolerance, optional
        Decides when two centers coincide and when two lines are parallel.
    contacts : sequence of KnownCenter or KnownLine
        Primary centers (rolling contact) and lines of centers (direct
        contact) that the mechanism file does not state.

    Returns
    -------
    InstantCenters
        ``n(n-1)/2`` centers (Eq. 3.20) in order of discovery, with the
        recorded construction.

    Raises
    ------
    InputError
        A contact names a link that is not in the mechanism.

    See Also
    --------
    angular_velocity_ratio, line_of_centers_velocity, mechanical_advantage

    Notes
    -----
    The search follows the Kennedy circle: primary centers first (pins,
    sliders, rolling contacts), then repeatedly the first unknown pair (in the
    order I12, I13, ...) that two known lines of centers reach.  When none
    can be reached and the velocities are known, one center is found from the
    velocities (preferring the pair of the two input links, as in
    Example 5.5) and the search goes on.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14 (Eq. 3.20, Figs.
    3.22-3.28) and Sec. 5.4 (Example 5.5).

    Examples
    --------
    The inverted slider-crank of Fig. 3.26: the block 3 slides on the rod 4,
    so I34 is at infinity, perpendicular to the rod.

    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... E = [0, 0]
    ... D = [14, 0]
    ... [links.2]
    ... E = [0, 0]
    ... A = [3, 0]
    ... [links.3]
    ... A = [0, 0]
    ... [links.4]
    ... D = [0, 0]
    ... L1 = [0, 0]
    ... L2 = [1, 0]
    ... [[sliders]]
    ... link = 3
    ... on = 4
    ... point = "A"
    ... line = ["L1", "L2"]
    ... [drive]
    ... link = 2
    ... angle = 90
    ... ''').solve()
    >>> ic = instant_centers(sol)
    >>> ic["I34"].how.value, bool(ic["I34"].is_ideal)
    ('primary', True)
    >>> [round(float(v), 4) + 0.0 for v in ic["I13"].xy]  # on x = 0 and ⊥ DA through D
    [0.0, -65.3333]
    """
    mech = sol.mechanism
    for c in contacts:
        for lid in c.links:
            if str(lid) not in mech.links:
                raise InputError(f"the contact {c.source!r} names link {lid}, which is not in "
                                 f"the mechanism (links: {', '.join(sort_links(mech.links))})")
    return _Kennedy(sol, tol or DEFAULT_TOL, contacts).run()


def instant_center(sol: Solution | InstantCenters, i: object, j: object) -> Array:
    """The instant center ``Iij`` in homogeneous coordinates ``(x, y, w)``.

    ``w = 1`` for a finite center, ``w = 0`` (and a unit direction) at infinity.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> instant_center(sol, 2, 1)
    array([0., 0., 1.])
    """
    ic = _centers(sol)
    return ic[(i, j)].point


def _centers(obj: Solution | InstantCenters) -> InstantCenters:
    return obj if isinstance(obj, InstantCenters) else instant_centers(obj)


def _ratio_homogeneous(a: Array, b: Array, c: Array) -> Array:
    """Signed ``R_CA / R_CB`` along the line of three collinear centers (homogeneous).

    With coordinates ``t`` along the line and weights ``w``:
    ``(t_c w_a - t_a w_c) w_b / ((t_c w_b - t_b w_c) w_a)``.  This is 1 when
    ``C`` is at infinity, 0 when ``B`` is, and unbounded when ``A`` is.
    """
    # a direction along the line: from any two distinct points of the three
    cands = []
    for p, q in ((a, b), (a, c), (b, c)):
        with np.errstate(invalid="ignore", divide="ignore"):
            cands.append(g.join(p, q))
    line = cands[0]
    for other in cands[1:]:
        line = np.where(np.isfinite(line).all(axis=-1, keepdims=True), line, other)
    u = g.direction(line)

    def t(p: Array) -> Array:
        return g.dot2(p, u)  # = (x·u) for finite (w = 1), ±1 at infinity on the line

    ta, tb, tc = t(a), t(b), t(c)
    wa, wb, wc = a[..., 2], b[..., 2], c[..., 2]
    num = (tc * wa - ta * wc) * wb
    den = (tc * wb - tb * wc) * wa
    with np.errstate(invalid="ignore", divide="ignore"):
        return num / den


def _unbounded(ic: InstantCenters, values: Array) -> bool:
    """True when a result has no finite value at some posture that could be assembled."""
    valid = np.broadcast_to(np.asarray(ic.solution.valid, dtype=bool), np.shape(values))
    return bool(np.any(~np.isfinite(values) & valid))


def angular_velocity_ratio(sol: Solution | InstantCenters, i: object, j: object,
                           reference: object = FRAME) -> Array:
    """``ω_j / ω_i`` (both relative to ``reference``) by the angular-velocity-ratio theorem.

    Eq. 3.22: the ratio is inversely as the segments into which the common
    center ``Iij`` cuts the line of centers,

    ``ω_j / ω_i = R(Iij, I1i) / R(Iij, I1j)``

    (signed distances along the line): positive (the same sense) when ``Iij``
    lies outside ``I1i`` and ``I1j``, negative (opposite senses) when it lies
    between them.  Found from the centers only, not from the solution's ω.

    Parameters
    ----------
    sol : Solution or InstantCenters
    i, j : link ids
    reference : link id
        The third link (the frame by default).

    Returns
    -------
    ndarray
        The ratio (0-d for one posture).

    Raises
    ------
    DegenerateError
        When link ``i`` does not turn relative to the reference (``I1i`` at
        infinity), so the ratio is unbounded.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.16, Eq. 3.22; Example 3.13.

    Examples
    --------
    A parallelogram four-bar: I24 is at infinity (the ratio is 1, the same
    sense), and the coupler translates, so I13 is at infinity and ω3/ω2 = 0.

    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [4, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [2, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [4, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [2, 0]
    ... [drive]
    ... link = 2
    ... angle = 60
    ... [assembly]
    ... C = [5, 1.7]
    ... ''').solve()
    >>> float(angular_velocity_ratio(sol, 2, 4)), float(angular_velocity_ratio(sol, 2, 3))
    (1.0, 0.0)
    """
    ic = _centers(sol)
    r = str(reference)
    a = ic[(r, i)].point
    b = ic[(r, j)].point
    c = ic[(i, j)].point
    with np.errstate(invalid="ignore", divide="ignore"):
        out = _ratio_homogeneous(a, b, c)
    if _unbounded(ic, out):
        raise DegenerateError(
            f"link {i} does not turn relative to link {r} ({center_label(r, i)} is at infinity "
            f"or coincides with {center_label(i, j)}), so ω{j}/ω{i} is unbounded",
            links=(str(i), str(j), r))
    return out


def _slide_direction(ic: InstantCenters, lid: str, reference: str) -> Array:
    """Unit direction of positive travel of a link translating relative to ``reference``.

    From the slider of the file between the two (its line from first to second
    point); otherwise the center at infinity turned -90°, so that positive
    travel is a positive (ccw) turn about it (footnote to Example 3.14).
    """
    sol, mech = ic.solution, ic.solution.mechanism
    for s in mech.sliders:
        if {s.link, s.on} == {lid, reference}:
            th = np.asarray(sol.links[s.on].angle, dtype=float) + s.direction_angle
            u = np.stack([np.cos(th), np.sin(th)], axis=-1)
            return u if s.link == lid else -u
    d = ic[(reference, lid)].point[..., :2]
    return np.stack([d[..., 1], -d[..., 0]], axis=-1)


def _translates(mech: Mechanism, lid: str) -> bool:
    """True for a link joined to the frame by sliders only (it can never turn)."""
    seen, todo = {FRAME}, [FRAME]
    while todo:
        k = todo.pop()
        for s in mech.sliders:
            for a, b in ((s.link, s.on), (s.on, s.link)):
                if a == k and b not in seen:
                    seen.add(b)
                    todo.append(b)
    return lid in seen and lid != FRAME


def _input_link(mech: Mechanism, given: object) -> object:
    """The input link: the one given, or the single drive's."""
    if given is not None:
        return given
    if len(mech.drives) != 1:
        raise InputError("say which link is the input: the file has "
                         f"{len(mech.drives)} drives", key="drive")
    return mech.drives[0].link


def kinematic_coefficient(sol: Solution | InstantCenters, output: object,
                          input: object | None = None) -> Array:
    """First-order kinematic coefficient of ``output`` for ``input``, from instant centers.

    The speed of the output divided by the speed of the input, both relative
    to the frame.  A link that can turn has speed ω (zero at an instant when
    its absolute center is at infinity); a slider (a link joined to the frame
    by sliders only, its absolute center always at infinity) has speed ṙ
    along its slider's line (from the line's first point to its second):

    * turning input, turning output: ``θ'_j = R(Iij, I1i) / R(Iij, I1j)`` (Eq. 3.24);
    * sliding input, turning output: ``θ'_j = ±1 / R(Iij, I1j)`` (Eq. 3.26), in
      rad per length unit;
    * turning input, sliding output: the velocity of ``Iij`` as a point of the
      input, along the output's line, per unit ω;
    * both sliding: the ratio of the travels whose difference is perpendicular
      to the direction of ``Iij`` at infinity.

    With several degrees of freedom this is the ratio of the speeds at the
    file's input speeds (the centers depend on them, Sec. 5.4).

    Parameters
    ----------
    sol : Solution or InstantCenters
    output : link id
    input : link id, optional
        Default: the drive's link (the file must have one drive).

    Returns
    -------
    ndarray

    Raises
    ------
    InputError
        No input given and the file has several drives.
    DegenerateError
        The input does not move relative to the output's motion (a ratio over zero).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.17, Eqs. 3.23-3.26; Examples 3.13, 3.14.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> float(kinematic_coefficient(sol, 2))
    1.0
    """
    ic = _centers(sol)
    mech = ic.solution.mechanism
    input = _input_link(mech, input)
    i, j = str(input), str(output)
    if i == j:
        return np.ones(np.shape(ic.solution.links[FRAME].angle))
    a = ic[(FRAME, i)].point
    b = ic[(FRAME, j)].point
    c = ic[(i, j)].point
    # a slider's speed is its travel ṙ; a link that can turn has speed ω, even
    # at an instant when it does not turn (its center at infinity, ω = 0)
    shape = np.shape(g.is_ideal(c))
    ia = np.full(shape, _translates(mech, i))
    ib = np.full(shape, _translates(mech, j))
    with np.errstate(invalid="ignore", divide="ignore"):
        rot_rot = _ratio_homogeneous(a, b, c)
        out = rot_rot
        if np.any(ia) or np.any(ib):
            # the velocity of Iij: ω_i k×(C - A) per unit ω_i, or s_i per unit ṙ_i
            ci = g.xy(c)
            s_i = _slide_direction(ic, i, FRAME) if np.any(ia) else np.zeros(c.shape[:-1] + (2,))
            s_j = _slide_direction(ic, j, FRAME) if np.any(ib) else np.zeros(c.shape[:-1] + (2,))
            v_c = np.where(ia[..., None], s_i, _perp(ci - g.xy(a)))
            rb = ci - g.xy(b)
            # turning output: ω_j = v_c · (k × R) / R²; 0 while its center is at infinity
            to_rot = np.where(g.is_ideal(b), 0.0, g.dot2(v_c, _perp(rb)) / g.dot2(rb, rb))
            # sliding output: ṙ_j = v_c · s_j
            to_slide = g.dot2(v_c, s_j)
            # both sliding, Iij at infinity in direction d: (ṙ_j s_j - ṙ_i s_i) ⊥ d
            d = c[..., :2]
            both = g.dot2(s_i, d) / g.dot2(s_j, d)
            mixed = np.where(ib, to_slide, to_rot)
            mixed = np.where(ia & ib & g.is_ideal(c), both, mixed)
            out = np.where(ia | ib, mixed, rot_rot)
    if _unbounded(ic, out):
        raise DegenerateError(f"the speed of link {j} per unit speed of link {i} is unbounded "
                              "here (the input is at a dead point)", links=(i, j))
    return out


def mechanical_advantage(sol: Solution | InstantCenters, output: object,
                         input: object | None = None) -> Array:
    """Mechanical advantage: output torque (force) over input torque (force), Eq. 3.34.

    With no friction or inertia, power in equals power out, so
    ``T_out / T_in = ω_in / ω_out`` (and ``F/T = ω/ṙ`` for a slider): the
    reciprocal of :func:`kinematic_coefficient`, from the instant centers.
    It is infinite in toggle (the output at rest), where this returns ``inf``.

    Parameters
    ----------
    sol : Solution or InstantCenters
    output : link id
    input : link id, optional
        Default: the drive's link.

    Returns
    -------
    ndarray
        Signed: negative when output and input turn opposite ways.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.19, Eqs. 3.34-3.35.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> float(mechanical_advantage(sol, 2))
    1.0
    """
    ic = _centers(sol)
    mech = ic.solution.mechanism
    input = _input_link(mech, input)
    k = kinematic_coefficient(ic, output, input)
    with np.errstate(divide="ignore"):
        return np.where(k == 0.0, np.inf, 1.0 / np.where(k == 0.0, 1.0, k))


@dataclass
class LineOfCentersVelocity:
    """The result of the line-of-centers method (Sec. 3.15).

    Attributes
    ----------
    velocity : ndarray, shape (..., 2)
        Velocity of the point, relative to the reference link.
    omega : ndarray
        ω of the point's link relative to the reference (0 when it translates).
    common : str
        Label of the common center (``I24``), whose velocity carries the motion over.
    common_velocity : ndarray, shape (..., 2)
        Its velocity, found as a point of the given link.
    line : tuple of str
        The three centers on the line of centers.
    """

    velocity: Array
    omega: Array
    common: str
    common_velocity: Array
    line: tuple[str, str, str]


def line_of_centers_velocity(sol: Solution | InstantCenters, point: str | ArrayLike,
                             link: object, *, given: object,
                             reference: object = FRAME) -> LineOfCentersVelocity:
    """Velocity of a point of ``link`` from the known motion of link ``given`` (Sec. 3.15).

    The book's four steps: (1) the three links are ``given``, ``link`` and the
    reference; (2) their three centers lie on the line of centers; (3) the
    common center ``I(given, link)`` gets its velocity as a point of ``given``
    (turning about ``I(ref, given)`` at ω_given, or translating with it);
    (4) as a point of ``link`` it fixes ω_link about ``I(ref, link)``, and so
    the velocity of any point of ``link``.  Only ω_given (and, when ``given``
    translates, the velocity of its points) is read from the solution.

    Parameters
    ----------
    sol : Solution or InstantCenters
    point : str or (x, y)
        A named point of ``link``, or world coordinates of a point of it.
    link : link id
    given : link id
        The link whose motion is known.
    reference : link id
        The frame by default.

    Returns
    -------
    LineOfCentersVelocity

    Raises
    ------
    DegenerateError
        When the common center coincides with ``I(ref, link)`` (the motion
        cannot be carried over), or all three centers are at infinity.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.15, Figs. 3.29-3.31, Example 3.12.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... D = [10, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [4, 0]
    ... [links.3]
    ... B = [0, 0]
    ... C = [18, 0]
    ... [links.4]
    ... D = [0, 0]
    ... C = [11, 0]
    ... [drive]
    ... link = 2
    ... angle = 120
    ... omega = 10
    ... [assembly]
    ... C = [15, 10]
    ... ''').solve()
    >>> r = line_of_centers_velocity(sol, "C", 4, given=2)
    >>> r.common, bool(np.allclose(r.velocity, sol.velocity("C")))
    ('I24', True)
    """
    ic = _centers(sol)
    s = ic.solution
    lid, gid, rid = str(link), str(given), str(reference)
    if isinstance(point, str):
        where = s.position(point, lid)
    else:
        where = np.asarray(point, dtype=float)
    if lid == rid:
        z = np.zeros(np.shape(where))
        return LineOfCentersVelocity(z, np.zeros(z.shape[:-1]), "", z, ("", "", ""))
    if lid == gid:
        raise InputError("the given link and the point's link must differ")
    a = ic[(rid, gid)].point          # the given link's center
    b = ic[(rid, lid)].point          # the point's link's center
    c = ic[(gid, lid)].point          # the common center
    labels = (center_label(rid, gid), center_label(gid, lid), center_label(rid, lid))
    ug, wg = _world_origin_velocity(s, gid)
    ur, wr = _world_origin_velocity(s, rid)
    w_given = wg - wr
    ca, cb, cc = g.is_ideal(a), g.is_ideal(b), g.is_ideal(c)
    with np.errstate(invalid="ignore", divide="ignore"):
        # (3) velocity of the common center as a point of the given link
        cxy = np.where(cc[..., None], 0.0, g.xy(c))
        v_trans = ug - ur  # a translating link: every point moves alike
        v_rot = w_given[..., None] * _perp(cxy - g.xy(a))
        v_c = np.where(ca[..., None], v_trans, v_rot)
        # (4) as a point of the wanted link, about its own center b
        rb = cxy - g.xy(b)
        w_link = g.dot2(v_c, _perp(rb)) / g.dot2(rb, rb)
        # the common center at infinity: the two links turn alike (ω_link = ω_given)
        w_link = np.where(cc, w_given, w_link)
        w_link = np.where(cb, 0.0, w_link)
        v_rot_b = w_link[..., None] * _perp(where - g.xy(b))
        # the wanted link translates: every point has the velocity of the common center
        vel = np.where(cb[..., None], v_c, v_rot_b)
    if _unbounded(ic, vel[..., 0] + vel[..., 1] + w_link):
        raise DegenerateError(
            f"the line-of-centers method fails here: {labels[1]} and {labels[2]} coincide, or "
            "the centers are all at infinity", centers=labels)
    return LineOfCentersVelocity(vel, w_link, labels[1], v_c, labels)


# ---------------------------------------------------------------------------
# output
# ---------------------------------------------------------------------------

def _canonical(d: Array) -> list[float]:
    """A unit direction with its first nonzero component positive (either sense is valid)."""
    dx, dy = float(d[0]), float(d[1])
    n = math.hypot(dx, dy)
    dx, dy = dx / n, dy / n
    if dx < 0 or (dx == 0 and dy < 0):
        dx, dy = -dx, -dy
    return [dx + 0.0, dy + 0.0]


def _is_batch(sol: Solution) -> bool:
    return np.ndim(sol.links[FRAME].angle) > 0


def instant_centers_json(sol: Solution) -> dict[str, Any] | None:
    """The ``instant_centers`` section of ``graphkin solve --json`` (``spec/output.md``).

    Keys ``"i-j"`` (lower id first); ``{"position": [x, y]}``, or
    ``{"direction": [dx, dy]}`` (a unit vector) for a center at infinity; plus
    ``label``, ``how`` (``primary``, ``kennedy``, ``velocities``), ``order`` of
    discovery, ``source``, the ``lines`` it was found on and, for a center that
    depends on the input speeds, ``speed_ratio_dependent: true``.  ``None``
    for a batch.  A center that cannot be found (several degrees of freedom
    and no velocities in the file) is left out.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> instant_centers_json(sol)["1-2"]["position"]
    [0.0, 0.0]
    """
    if _is_batch(sol):
        return None
    ic = instant_centers(sol)
    out: dict[str, Any] = {}
    for c in sorted(ic.centers.values(), key=lambda c: (_id_key(c.pair[0]), _id_key(c.pair[1]))):
        entry: dict[str, Any] = {}
        if c.point[2] == 0.0:
            entry["direction"] = _canonical(c.point[:2])
        else:
            entry["position"] = [float(c.point[0]) + 0.0, float(c.point[1]) + 0.0]
        entry.update({"label": c.label, "how": c.how.value, "order": c.order,
                      "source": c.source})
        if c.lines:
            entry["lines"] = list(c.lines)
        if c.speed_dependent:
            entry["speed_ratio_dependent"] = True
        out[f"{c.pair[0]}-{c.pair[1]}"] = entry
    return out


def instant_centers_text(sol: Solution) -> str | None:
    """A short textbook-style table of the instant centers, for the text report.

    ``None`` for a batch.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> print(instant_centers_text(sol))
      n = 2 links, N = n(n-1)/2 = 1 instant center (Eq. 3.20)
      #  center  found by        location
      1  I12     pin A           (0, 0) mm
    """
    if _is_batch(sol):
        return None
    ic = instant_centers(sol)
    unit = sol.mechanism.length_unit
    n, count = len(ic.links), ic.count
    lines = [f"  n = {n} links, N = n(n-1)/2 = {count} instant "
             f"center{'s' if count != 1 else ''} (Eq. 3.20)"]
    rows = [("#", "center", "found by", "location", "")]
    for c in ic.centers.values():
        if c.point[2] == 0.0:
            dx, dy = _canonical(c.point[:2])
            where = f"at infinity ∠{round(math.degrees(math.atan2(dy, dx)), 2) + 0.0:.2f}°"
        else:
            where = f"({float(c.point[0]) + 0.0:.6g}, {float(c.point[1]) + 0.0:.6g}) {unit}"
        if c.how is How.KENNEDY:
            by = "Kennedy"
            extra = "on " + " and ".join(c.lines)
        elif c.how is How.VELOCITIES:
            by = "velocities"
            extra = "depends on the speed ratio (Sec. 5.4)" if c.speed_dependent else ""
        else:
            by, extra = c.source, ""
        rows.append((str(c.order), c.label, by, where, extra))
    widths = [max(len(r[k]) for r in rows) for k in range(4)]
    for r in rows:
        lines.append(("  " + "  ".join(x.ljust(w) for x, w in zip(r[:4], widths))
                      + ("  " + r[4] if r[4] else "")).rstrip())
    for p in ic.missing:
        lines.append(f"  {center_label(*p)}: not found")
    for note in ic.notes:
        lines.append(f"  note: {note}")
    return "\n".join(lines)
