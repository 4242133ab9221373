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
from graphkin.mechanisms.model import FRAME, Mechanism, Slider, Slot

__all__ = ["Joint", "joints_of", "id_order", "Geometry", "geometry"]

PIN, SLIDE, SLOT = "pin", "slide", "slot"
UNKNOWNS = {PIN: 2, SLIDE: 2, SLOT: 1}
"""Scalar unknowns a frictionless joint's force has."""


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
    source: Slider | Slot | None = None

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

    Raises
    ------
    InputError
        Rolling contact (its tangential force is not yet modelled).
    """
    if mech.rolling:
        r = mech.rolling[0]
        raise InputError("force analysis of rolling contact is not supported yet "
                         "(remove the loads or the rolling pair)", key=r.key, file=mech.source)
    raw: list[tuple[str, str, str, str, Slider | Slot | None]] = []
    for p in mech.pins:
        hub = FRAME if FRAME in p.links else p.links[0]
        for other in p.links:
            if other != hub:
                raw.append((hub, other, PIN, p.name, None))
    for s in mech.sliders:
        raw.append((s.link, s.on, SLIDE, s.point, s))
    for t in mech.slots:
        raw.append((t.link, t.on, SLOT, t.point, t))
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
