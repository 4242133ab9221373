"""Primary centers by inspection: pins, sliders, rolling contact, slot normals (Sec. 3.12)."""

from __future__ import annotations

from collections.abc import Sequence
from itertools import combinations
from typing import Any, Literal

import numpy as np

from graphkin.construction import Construction, Role
from graphkin.construction.ops import OPS
from graphkin.construction.step import fresh_label
from graphkin.kinematics.instant_centers.centers import (
    Center,
    How,
    KnownCenter,
    KnownLine,
    _as_float,
)
from graphkin.kinematics.instant_centers.labels import _id_key, center_label, pair_key, sort_links
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import Tolerance

Pair = tuple[str, str]

Array = np.ndarray

#: A center farther from the mechanism than this many sizes of the mechanism is
#: at infinity: its two lines of centers are parallel but for the round-off
#: of the file's numbers (an angle below 1e-6 rad, far finer than any drawing).
#: The center is then recorded as the point at infinity in that direction, so
#: that the report, JSON and drawings print a direction, never a huge coordinate.
FAR_AS_INFINITY = 1e6


def _far_as_ideal(p: Array, far: float, origin: tuple[float, float] = (0.0, 0.0)) -> Array:
    """A finite point farther than ``far`` from ``origin`` as the point at infinity there.

    The distance is measured from the mechanism (``origin``: the middle of its
    frame points), so a mechanism drawn far from the file's origin keeps its
    finite centers.

    Examples
    --------
    >>> _far_as_ideal(np.array([-2.5e8, 0.0, 1.0]), 5e6).tolist()
    [-1.0, 0.0, 0.0]
    >>> _far_as_ideal(np.array([3.0, 4.0, 1.0]), 5e6).tolist()
    [3.0, 4.0, 1.0]
    >>> _far_as_ideal(np.array([1e9 + 3.0, 4.0, 1.0]), 5e6, origin=(1e9, 0.0)).tolist()
    [1000000003.0, 4.0, 1.0]
    """
    p = np.asarray(p, dtype=float)
    if p.shape[-1:] != (3,):
        return p
    w = p[..., 2]
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        dx = p[..., 0] - origin[0] * w
        dy = p[..., 1] - origin[1] * w
        r = np.hypot(dx, dy)
        far_away = (w != 0) & np.isfinite(r) & (r > far * np.abs(w))
        ideal = np.stack([dx / r * np.sign(w), dy / r * np.sign(w), np.zeros_like(w)], axis=-1)
    return np.where(far_away[..., None], ideal, p)


def far_as_ideal(p: Array, mech: Mechanism) -> Array:
    """An instant center beyond :data:`FAR_AS_INFINITY` sizes of ``mech`` as a point at infinity.

    Distances are measured from the middle of the frame's points and in sizes
    of the mechanism (:attr:`Mechanism.scale`), so the decision does not
    depend on the file's unit or on where the mechanism is drawn.
    """
    frame = list(mech.links[FRAME].points.values()) or [(0.0, 0.0)]
    origin = (float(np.mean([q[0] for q in frame])), float(np.mean([q[1] for q in frame])))
    return _far_as_ideal(p, FAR_AS_INFINITY * mech.scale, origin)


class _Recorder:
    """The state of the search for a mechanism's centers, and the recording of its steps."""

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
        self.env[lab] = far_as_ideal(self.env[lab], self.mech)
        self.centers[pair] = Center(pair, lab, self.env[lab], how, source, len(self.centers) + 1,
                                    lines, triangles, speed, note)
        # a new center changes the lines of centers of the pairs of its links only
        stamp = self.__dict__.setdefault("_stamp", {})
        for lid in pair:
            stamp[lid] = stamp.get(lid, 0) + 1

    def fresh(self, label: str) -> str:
        return fresh_label(label, self.env)


class _PrimaryCenters(_Recorder):
    """The centers and lines of centers found by inspection, before Kennedy's theorem."""

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
