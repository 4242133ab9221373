"""The joints that carry forces, and their geometry at a solved posture.

Each pair of links in contact is one joint, keyed ``"i-j"`` with the lower id
first (``"i-j@P"`` when the pair shares two joints); its force is the book's
F_ij, exerted BY link i ON link j (docs/forces.md).  Frictionless joints
(Sec. 11.5): a pin transmits a force through its center (two unknowns); a
slider a force normal to its line, anywhere along it (two unknowns: size and
place); a pin in a slot a force through the pin normal to the slot (one
unknown).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.5 (free-body diagrams), Fig. 11.4.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.kinematics.solution import Solution, perp
from graphkin.mechanisms.model import FRAME, Mechanism, Rolling, Slider, Slot

__all__ = ["Joint", "joints_of", "id_order", "Geometry", "geometry", "contact_name",
           "contact_point"]

PIN, SLIDE, SLOT = "pin", "slide", "slot"
UNKNOWNS = {PIN: 2, SLIDE: 2, SLOT: 1}
"""Scalar unknowns a frictionless joint's force has."""


def contact_name(r: Rolling) -> str:
    """The name of a rolling pair's point of contact: ``P_24`` (the pitch point)."""
    lo, hi = sorted((r.link, r.on), key=id_order)
    return f"P_{lo}{hi}"


def contact_point(sol: Solution, r: Rolling) -> np.ndarray:
    """The world point of contact of a rolling pair at a solved posture.

    On a line: the foot of the rolling circle's center on the line; on a
    circle: on the line of centers, the other circle's radius from its center.
    """
    c = np.asarray(sol.position(r.center, r.link), dtype=float)
    guide = sol.links[r.on]
    if r.on_line:
        assert r.p0 is not None and r.p1 is not None
        b = np.asarray(guide.position(r.p0), dtype=float)
        d = np.asarray(guide._r(np.subtract(r.p1, r.p0)), dtype=float)
        u = d / np.hypot(d[..., 0], d[..., 1])[..., None]  # one posture or a sweep's (N, 2)
        return b + np.sum((c - b) * u, axis=-1)[..., None] * u
    assert r.on_center is not None and r.on_radius is not None
    o = np.asarray(guide.position(r.on_center), dtype=float)
    e = (c - o) / np.hypot(c[..., 0] - o[..., 0], c[..., 1] - o[..., 1])[..., None]
    return o + r.on_radius * e


def id_order(lid: str) -> tuple[int, int, str]:
    """Sort key of link ids: numeric ids in numeric order, then names."""
    return (0, int(lid), "") if lid.isdigit() else (1, 0, lid)


@dataclass(frozen=True)
class Joint:
    """A joint between links ``lo`` and ``hi`` (``lo`` first in id order).

    Attributes
    ----------
    key : str
        ``"3-4"`` (or ``"3-4@B"``).
    lo, hi : str
        The links; the joint's force is F_lo,hi, exerted by ``lo`` on ``hi``.
    kind : str
        ``"pin"``, ``"slide"`` or ``"slot"``.
    point : str
        The pin, the slider's point or the pin in the slot.
    source : Slider or Slot or None
        The slider or slot (None for a pin).
    """

    key: str
    lo: str
    hi: str
    kind: str
    point: str
    source: Slider | Slot | Rolling | None = None

    def other(self, lid: str) -> str:
        """The link on the other side of the joint from ``lid``."""
        return self.hi if lid == self.lo else self.lo

    def label(self, on: str, suffix: str = "") -> str:
        """The book's name of the force ON link ``on``: ``F_34`` on 4, ``F_43`` on 3."""
        by = self.other(on)
        at = self.key.partition("@")[2]
        return f"F_{by}{on}{suffix}" + (f"@{at}" if at else "")

    @property
    def unknowns(self) -> int:
        """Scalar unknowns of its force (2 for a pin or slider, 1 for a slot)."""
        return UNKNOWNS[self.kind]


def joints_of(mech: Mechanism) -> list[Joint]:
    """Every force-carrying joint of a mechanism, in file order.

    A pin shared by k links is k − 1 joints between its first link and each
    other one.

    Rolling without slip (Sec. 11.11): the friction holds, so the contact
    transmits a force with two unknown components through the point of
    contact, a pin-like joint at ``P_ij`` (the pitch point); the rolling
    pair's equivalent slot (a kinematic device) carries no force.

    Gear teeth (``pressure_angle`` in ``[[rolling]]``, Sec. 11.11, Fig.
    11.14): one unknown, the force through the pitch point along the pressure
    line (:func:`graphkin.forces.solve.solve_forces` tilts it).

    Raises
    ------
    InputError
        Gears on two fixed centers without a pressure angle (two unknown
        components there would leave the pair statically indeterminate).
    """
    raw: list[tuple[str, str, str, str, Slider | Slot | Rolling | None]] = []
    for r in mech.rolling:
        if r.fixed_centers and r.key not in mech.pressure:
            raise InputError("gears on two fixed centers transmit their force along the "
                             "pressure line (Sec. 11.11, Fig. 11.14): give pressure_angle "
                             "(degrees, e.g. 20)", key=f"{r.key}.pressure_angle",
                             file=mech.source)
    for p in mech.pins:
        hub = FRAME if FRAME in p.links else p.links[0]
        for other in p.links:
            if other != hub:
                raw.append((hub, other, PIN, p.name, None))
    for s in mech.sliders:
        raw.append((s.link, s.on, SLIDE, s.point, s))
    for t in mech.slots:
        if not t.key.endswith(":slot"):  # a rolling pair's equivalent slot carries no force
            raw.append((t.link, t.on, SLOT, t.point, t))
    for r in mech.rolling:  # gear teeth: one unknown along the pressure line
        raw.append((r.link, r.on, SLOT if r.key in mech.pressure else PIN, contact_name(r), r))
    pairs: dict[tuple[str, str], int] = {}
    for a, b, *_ in raw:
        lo, hi = sorted((a, b), key=id_order)
        pairs[(lo, hi)] = pairs.get((lo, hi), 0) + 1
    out = []
    for a, b, kind, point, src in raw:
        lo, hi = sorted((a, b), key=id_order)
        key = f"{lo}-{hi}" + (f"@{point}" if pairs[(lo, hi)] > 1 else "")
        out.append(Joint(key, lo, hi, kind, point, src))
    return out


@dataclass
class Geometry:
    """World geometry of the joints at a solved posture.

    Arrays of leading shape ``()`` or ``(N,)``.

    Attributes
    ----------
    points : dict
        Point name -> world position ``(..., 2)``.
    normal : dict
        Joint key -> unit direction of its force (slider, slot).
    along : dict
        Joint key -> unit direction of a slider's line (from its first point to its second).
    base : dict
        Joint key -> a world point of a slider's line.
    """

    points: dict[str, np.ndarray]
    normal: dict[str, np.ndarray]
    along: dict[str, np.ndarray]
    base: dict[str, np.ndarray]


def geometry(sol: Solution, joints: list[Joint]) -> Geometry:
    """The world geometry the force construction takes as given."""
    mech = sol.mechanism
    points = {n: np.asarray(sol.position(n), dtype=float) for n in mech.point_names}
    normal: dict[str, np.ndarray] = {}
    along: dict[str, np.ndarray] = {}
    base: dict[str, np.ndarray] = {}
    for j in joints:
        src = j.source
        if isinstance(src, Rolling):
            points[j.point] = contact_point(sol, src)
            if j.kind == SLOT:  # gear teeth: first along the common tangent (solve.py tilts)
                c = np.asarray(sol.position(src.center, src.link), dtype=float)
                d = c - points[j.point]
                e = d / np.hypot(d[..., 0], d[..., 1])[..., None]
                normal[j.key] = perp(e)
            continue
        if src is None:
            continue
        guide = sol.links[src.on]
        if isinstance(src, Slot) and not src.is_line:
            assert src.center is not None
            c = guide.position(src.center)
            d = c - points[j.point]
            normal[j.key] = d / np.hypot(d[..., 0], d[..., 1])[..., None]
            continue
        p0: Any = src.p0
        p1: Any = src.p1
        d = guide._r(np.subtract(p1, p0))
        u = d / np.hypot(d[..., 0], d[..., 1])[..., None]
        along[j.key] = u
        normal[j.key] = perp(u)
        base[j.key] = guide.position(p0)
    return Geometry(points, normal, along, base)
