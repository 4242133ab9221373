"""The mechanism as described by a mechanism file (``docs/formats/mechanism.md``).

Plain frozen values: links with their points in their own coordinates, pins
(a point name shared by links), sliders, slots, drives and rates.  Inside
graphkin every length is in the file's length unit, every angle in radians,
every time in seconds.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.5-1.7 (links, pairs, mobility).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from graphkin.kinematics.solution import Solution
    from graphkin.kinematics.sweep import Sweep
    from graphkin.kinematics.sweep.batch import Batch
    from graphkin.mechanisms.laws import Law
    from graphkin.mechanisms.loading import Inertia, Load
    from graphkin.tolerance import Tolerance

__all__ = ["FRAME", "Link", "Pin", "Slider", "Slot", "Rolling", "Drive", "Rates", "Mechanism",
           "XY", "Body"]

FRAME = "1"
XY = tuple[float, float]


@dataclass(frozen=True, slots=True)
class Link:
    """A link and its named points in the link's own coordinates.

    The frame (link 1) holds absolute coordinates.  The angle of a link is the
    direction of its own x axis.
    """

    id: str
    points: dict[str, XY] = field(hash=False, compare=False)

    def local(self, name: str) -> XY:
        """The local coordinates of point ``name``."""
        return self.points[name]


@dataclass(frozen=True, slots=True)
class Pin:
    """A revolute pair: the point ``name`` is common to every link in ``links``."""

    name: str
    links: tuple[str, ...]


@dataclass(frozen=True, slots=True)
class Slider:
    """A prismatic pair: ``point`` of ``link`` stays on a line fixed in ``on``.

    ``link`` keeps its angle relative to ``on``: its x axis is parallel to the
    line, from ``p0`` toward ``p1`` (both in ``on``'s coordinates).
    """

    index: int
    link: str
    on: str
    point: str
    p0: XY
    p1: XY
    key: str = "sliders"

    @property
    def direction_angle(self) -> float:
        """Angle of the line in ``on``'s coordinates (rad)."""
        return math.atan2(self.p1[1] - self.p0[1], self.p1[0] - self.p0[0])


@dataclass(frozen=True, slots=True)
class Slot:
    """A pin in a slot: ``point`` of ``link`` moves on a line or circle fixed in ``on``.

    Exactly one of ``line`` (two points) or ``center``/``radius`` is given.
    """

    index: int
    link: str
    on: str
    point: str
    p0: XY | None = None
    p1: XY | None = None
    center: XY | None = None
    radius: float | None = None
    key: str = "slots"

    @property
    def is_line(self) -> bool:
        """True for a straight slot."""
        return self.p0 is not None


@dataclass(frozen=True, slots=True)
class Rolling:
    """Rolling contact without slip: a circle of ``link`` rolls on a line or circle of ``on``.

    ``center`` names the rolling circle's center (a point of ``link``),
    ``radius`` its radius.  The surface of ``on`` is either a line (``p0``,
    ``p1`` in ``on``'s coordinates, with ``side`` the side of the directed line
    p0 → p1 on which the circle lies, ``"left"`` or ``"right"``: the rule of
    :class:`graphkin.construction.Side`) or a circle (``on_center``,
    ``on_radius`` in ``on``'s coordinates, with ``contact`` ``"outside"``: the
    circles touch externally, as gears; or ``"inside"``: the rolling circle
    runs inside, as a planet in a ring gear).  At the file's drive the rolling
    link stands at ``angle`` (rad, absolute; default 0: its own axes as
    written).  For the posture the center runs on the surface offset by the
    radius (the equivalent pin-in-slot, Example 4.7); for the rates the contact
    points have equal velocities (Eq. 3.13) and their accelerations differ by a
    component normal to the surfaces (Eq. 4.19).  When both centers are points
    of one link (gears on fixed centers, a planet on its arm) the distance of
    the centers is already held and only the no-slip condition is a constraint
    (``fixed_centers``); ``on_center_point`` then names the point of ``on`` at
    its circle's center.  ``angle_given`` says whether the file wrote ``angle``
    (a contact that places a slider's travel has no angle to take).
    """

    index: int
    link: str
    on: str
    center: str
    radius: float
    p0: XY | None = None
    p1: XY | None = None
    side: str = "left"
    angle: float = 0.0
    key: str = "rolling"
    on_center: XY | None = None
    on_radius: float | None = None
    contact: str = "outside"
    on_center_point: str | None = None
    fixed_centers: bool = False
    angle_given: bool = False
    contact_name: str = "C"
    """The contact point's name on drawings and in the steps (``C``; another when the file
    has a point ``C`` or a second contact: :func:`graphkin.mechanisms.names.contact_names`)."""

    @property
    def contact_label(self) -> str:
        """The label of the point of contact in the constructions: ``rolling[0]:C``."""
        return f"{self.key}:{self.contact_name}"

    @property
    def slot_key(self) -> str:
        """Key of the equivalent slot of the center."""
        return f"{self.key}:slot"

    @property
    def on_line(self) -> bool:
        """True when the surface of ``on`` is a line."""
        return self.p0 is not None

    @property
    def factor(self) -> float:
        """``R/(R ± r)``: the rolling-contact acceleration is ``factor · ρ ω_rel²`` (1 on a line).

        For a circle of radius r rolling on one of radius R the contact point of
        the rolling circle, seen from ``on``, has the acceleration
        ``ω_rel² r R/(R + r)`` (outside) or ``ω_rel² r R/(R − r)`` (inside)
        toward the rolling circle's center.
        """
        if self.on_radius is None:
            return 1.0
        big = self.on_radius
        return big / (big + self.radius) if self.contact == "outside" else \
            big / (big - self.radius)


@dataclass(frozen=True, slots=True)
class Drive:
    """An input that fixes the posture.

    ``kind`` is one of

    * ``"angle"``: the absolute angle of a link pinned to the frame (rad);
    * ``"position"``: the travel of a slider's point along its line from the
      line's first point;
    * ``"relative"``: the angle θ_{i/j} = θ_i − θ_j of link ``link`` relative
      to link ``relative_to`` (a robot's joint angle, Problems 5.7-5.11; rad);
    * ``"x"`` or ``"y"``: a coordinate of the point ``point`` in the frame
      (the pantograph's x_C, y_C of Problem 5.13); ``link`` is a moving link
      that carries it.

    ``rate`` and ``rate2`` are ω, α (rad/s, rad/s²) of the angle, or the
    first and second derivatives of the travel or coordinate; ``None`` when
    not given.  ``index`` is the drive's place in :attr:`Mechanism.drives`;
    ``key`` the file's key (one ``[[drive]]`` with both ``x`` and ``y`` gives
    two drives with the same key).
    """

    index: int
    link: str
    kind: str
    value: float
    rate: float | None = None
    rate2: float | None = None
    pivot: str | None = None
    slider: Slider | None = None
    key: str = "drive"
    relative_to: str | None = None
    point: str | None = None
    law: Law | None = None
    """The law of an input coupled to the first drive (``follows`` in the file): value =
    f(first), linear (k · first + c) or a table's spline, in internal units (rad or
    length); its rates f' · ω and f'' · ω² + f' · α (:mod:`graphkin.mechanisms.laws`)."""

    @property
    def is_angle(self) -> bool:
        """True for an angle (absolute or relative): values in rad, shown in degrees."""
        return self.kind in ("angle", "relative")

    @property
    def label(self) -> str:
        """The book's name of the input: ``θ2``, ``s4``, ``θ3/2``, ``x_C``, ``y_C``."""
        if self.kind == "angle":
            return f"θ{self.link}"
        if self.kind == "relative":
            return f"θ{self.link}/{self.relative_to}"
        if self.kind in ("x", "y"):
            return f"{self.kind}_{self.point}"
        return f"s{self.link}"

    @property
    def rate_labels(self) -> tuple[str, str]:
        """Names of the input's rates: ``ω2, α2``; ``ω3/2, α3/2``; ``vx_C, ax_C``."""
        if self.kind == "angle":
            return f"ω{self.link}", f"α{self.link}"
        if self.kind == "relative":
            return f"ω{self.link}/{self.relative_to}", f"α{self.link}/{self.relative_to}"
        if self.kind in ("x", "y"):
            return f"v{self.kind}_{self.point}", f"a{self.kind}_{self.point}"
        return f"ds{self.link}", f"dds{self.link}"

    def describe(self, unit: str = "") -> str:
        """The drive in words with its value: ``θ3/2 = -15°``, ``x_C = 300 mm``."""
        if self.is_angle:
            return f"{self.label} = {math.degrees(self.value):.6g}°"
        return f"{self.label} = {self.value:.6g}{' ' + unit if unit else ''}"


@dataclass(frozen=True, slots=True)
class Rates:
    """Known rates that belong to a link other than the drive (``[rates]``).

    For a link: ω and α; for a slider link: velocity and acceleration of its
    point along the line (``kind == "position"``).
    """

    link: str
    kind: str
    rate: float | None
    rate2: float | None


@dataclass(frozen=True, slots=True)
class Body:
    """What a link looks like where its equivalent mechanism does not show it (``[[bodies]]``).

    Drawing only: a body changes no position, velocity or acceleration.  The
    book draws a cam as its disc and a follower with its flat face even when
    it solves them as the equivalent pin-in-slot (Sec. 4.6, Example 4.7,
    Fig. 4.18).  ``kind`` is ``"circle"`` (``center``, ``radius``: a cam
    disc, a wheel, a roller), ``"face"`` (``points``: a straight face from
    the first point to the second) or ``"outline"`` (``points``: a closed
    plate, three or more corners); every coordinate is in the link's own
    coordinates.
    """

    index: int
    link: str
    kind: str
    center: XY | None = None
    radius: float | None = None
    points: tuple[XY, ...] = ()
    key: str = "bodies"


@dataclass(frozen=True)
class Mechanism:
    """A planar mechanism at one posture: what a mechanism file says.

    Use :func:`graphkin.load` to read one from a file.
    """

    links: dict[str, Link]
    pins: tuple[Pin, ...]
    sliders: tuple[Slider, ...] = ()
    slots: tuple[Slot, ...] = ()
    rolling: tuple[Rolling, ...] = ()
    drives: tuple[Drive, ...] = ()
    rates: Rates | None = None
    assembly: dict[str, XY] = field(default_factory=dict)
    title: str = ""
    length_unit: str = "mm"
    source: str = "<mechanism>"
    line_points: frozenset[str] = frozenset()
    """Point names the file uses to define a slider's, slot's or rolling surface's line."""
    force_unit: str = "N"
    """``units.force`` (docs/forces.md): the unit of every force; torques in force × length."""
    loads: tuple[Load, ...] = ()
    """Applied forces and couples (``[[loads]]``, Ch. 11)."""
    inertia: dict[str, Inertia] = field(default_factory=dict)
    """Link id -> mass properties (``[inertia.N]``, Ch. 12)."""
    gravity: XY | None = None
    """The acceleration of gravity (length unit/s²) when ``[gravity]`` is given."""
    friction: dict[str, tuple[float, str | None]] = field(default_factory=dict)
    """Slider or slot key (``sliders[0]``, ``slots[1]``) -> (μ, impending motion
    ``"ahead"``/``"behind"`` or None: from the velocity) for sliders and pins in slots
    with Coulomb friction (Sec. 11.10, an extension of forces.md)."""
    pressure: dict[str, float] = field(default_factory=dict)
    """Rolling pair key (``rolling[0]``) -> pressure angle φ (rad) of gear teeth: the contact
    force acts along the pressure line (Sec. 11.11, Fig. 11.14; an extension of forces.md)."""
    bodies: tuple[Body, ...] = ()
    """What links look like where the equivalent mechanism does not show it
    (``[[bodies]]``: a cam's disc, a follower's face); drawing only."""
    notes: tuple[str, ...] = ()
    """What the file says that the report notes, one line each (a link of zero length:
    :func:`graphkin.mechanisms.checks.zero_length_notes`)."""
    cams: tuple[Any, ...] = ()
    """Disk cams (``[[cams]]``, :class:`graphkin.cams.joint.CamJoint`), each replaced by its
    equivalent linkage through the centers of curvature at the drive (Sec. 4.7)."""

    @property
    def has_forces(self) -> bool:
        """True when the file asks for a force analysis (loads or mass properties)."""
        return bool(self.loads) or bool(self.inertia)

    def _repr_svg_(self) -> str | None:
        """Jupyter: a sketch of the mechanism in the file's posture (its repr is the summary).

        None (Jupyter then shows the one-line repr) when it cannot be assembled.
        """
        from graphkin.errors import GraphkinError

        try:
            sol = self.solve()
        except GraphkinError:
            return None
        return sol._repr_svg_()

    def __repr__(self) -> str:
        """A short summary: title, links, pins, pairs, drives (never raises).

        >>> import graphkin
        >>> graphkin.examples.fourbar()  # doctest: +ELLIPSIS
        <Mechanism 'Four-bar linkage ...': links 1 2 3 4, pins A D B C, drive link 2 at 120°, ...>
        """
        try:
            parts = [f"links {' '.join(self.links)}"]
            if self.pins:
                parts.append(f"pins {' '.join(p.name for p in self.pins)}")
            slots = [s for s in self.slots if not s.key.startswith("rolling")]
            for what, items in (("slider", self.sliders), ("slot", slots),
                                ("rolling contact", self.rolling)):
                if items:
                    parts.append(f"{len(items)} {what}{'s' if len(items) > 1 else ''}")
            for d in self.drives:
                if d.kind in ("relative", "x", "y"):
                    parts.append(f"drive {d.describe(self.length_unit)}")
                    continue
                at = (f"{math.degrees(d.value):.6g}°" if d.kind == "angle"
                      else f"{d.value:.6g} {self.length_unit}")
                parts.append(f"drive link {d.link} at {at}")
            parts.append(f"lengths in {self.length_unit}")
            return f"<Mechanism {self.title or self.source!r}: {', '.join(parts)}>"
        except Exception:  # a repr never raises
            return f"<Mechanism at {id(self):#x}>"

    @cached_property
    def moving(self) -> list[str]:
        """Ids of the moving links, in file order."""
        return [k for k in self.links if k != FRAME]

    @cached_property
    def point_links(self) -> dict[str, list[str]]:
        """Point name -> the links that carry it, in file order."""
        out: dict[str, list[str]] = {}
        for lid, link in self.links.items():
            for name in link.points:
                out.setdefault(name, []).append(lid)
        return out

    @property
    def point_names(self) -> list[str]:
        """Every named point once, in file order."""
        return list(self.point_links)

    @cached_property
    def helper_points(self) -> frozenset[str]:
        """Points that only define a line: drawn as the line or slot, not as points.

        A helper point (``S``, ``T`` of a slider's line, ``S1``, ``S2`` of a
        slot) is named in some ``line = [...]``, belongs to one link only (it is
        no pin), is not the point that runs on a line, and has no assembly hint.
        Drawings, results tables and teaching steps leave such points out.

        Examples
        --------
        >>> import graphkin
        >>> from graphkin.mechanisms import from_dict
        >>> m = from_dict({"links": {
        ...     "1": {"A": [0, 0], "S": [-10, 2], "T": [10, 2]},
        ...     "2": {"A": [0, 0], "B": [3, 0]},
        ...     "3": {"B": [0, 0], "C": [9, 0]},
        ...     "4": {"C": [0, 0]}},
        ...     "sliders": [{"link": 4, "on": 1, "point": "C", "line": ["S", "T"]}],
        ...     "drive": {"link": 2, "angle": 30}, "assembly": {"C": [9, 2]}})
        >>> sorted(m.helper_points)
        ['S', 'T']
        """
        runners = {s.point for s in self.sliders} | {s.point for s in self.slots} \
            | {r.center for r in self.rolling}
        return frozenset(n for n in self.line_points
                         if len(self.point_links.get(n, ())) == 1 and n not in runners
                         and n not in self.assembly)

    @property
    def has_rates(self) -> bool:
        """True when the file gives velocities (a drive rate or ``[rates]``)."""
        if self.rates is not None:
            return self.rates.rate is not None
        return bool(self.drives) and all(d.rate is not None for d in self.drives)

    @property
    def has_accelerations(self) -> bool:
        """True when accelerations can be found too (every second rate given, 0 by default)."""
        return self.has_rates

    @cached_property
    def scale(self) -> float:
        """Size of the mechanism (its largest coordinate), for scale-aware tolerances."""
        xs: list[float] = []
        for link in self.links.values():
            for x, y in link.points.values():
                xs.extend((abs(x), abs(y)))
        big = max(xs, default=0.0)
        return big if big > 0 else 1.0

    @cached_property
    def size(self) -> float:
        """Size of the mechanism itself: its largest link, whatever its offset from the origin.

        The largest distance between two points of one link (each link's own
        coordinates), or the largest radius of a slot or rolling circle.
        Comparisons of positions (assembly hints, branches) are made relative
        to it, so they do not change when a mechanism is moved or scaled.
        """
        sizes = [0.0]
        for link in self.links.values():
            if len(link.points) > 1:
                xs = [p[0] for p in link.points.values()]
                ys = [p[1] for p in link.points.values()]
                sizes.append(math.hypot(max(xs) - min(xs), max(ys) - min(ys)))
        sizes += [abs(s.radius) for s in self.slots if s.radius is not None]
        sizes += [abs(r.radius) for r in self.rolling]
        big = max(sizes)
        return big if big > 0 and math.isfinite(big) else self.scale

    def mobility(self) -> int:
        """Degrees of freedom by Kutzbach's criterion (Eq. 1.3): 3(n-1) - 2 j1 - j2."""
        m = 3 * len(self.moving)
        m -= sum(2 * (len(p.links) - 1) for p in self.pins)
        # a rolling contact's equivalent slot is among the slots (unless the distance of the
        # centers is held by the links already); its no-slip condition is one more
        m -= 2 * len(self.sliders) + len(self.slots) + len(self.rolling)
        return m

    # ---- conveniences (the work is done in graphkin.kinematics) ------
    def solve(self, tol: Tolerance | None = None) -> Solution:
        """Solve at the file's posture; see :func:`graphkin.kinematics.solve.solve`."""
        from graphkin.kinematics.solve import solve

        return solve(self, tol)

    def draw(self, diagram: str = "posture", ax: Any = None, **kw: Any) -> Any:
        """Solve and draw a diagram (into ``ax`` if given); see :func:`graphkin.render.draw`."""
        from graphkin.render import draw

        return draw(self, diagram, ax=ax, **kw)

    def sweep(self, count: int = 360, start: float | None = None, stop: float | None = None,
              **kw: Any) -> Sweep:
        """Solve over many drive values at once; see :func:`graphkin.kinematics.sweep.sweep`."""
        from graphkin.kinematics.sweep import sweep

        return sweep(self, count=count, start=start, stop=stop, **kw)

    def with_dimensions(self, dimensions: Mapping[str, Any]) -> Mechanism:
        """The mechanism with points moved in their links' coordinates (``{"links.3.C": (x, y)}``).

        See :func:`graphkin.kinematics.sweep.batch.with_dimensions`.
        """
        from graphkin.kinematics.sweep.batch import with_dimensions

        return with_dimensions(self, dimensions)

    def batch(self, dimensions: Mapping[str, Any], count: int = 360, start: float | None = None,
              stop: float | None = None, **kw: Any) -> Batch:
        """Sweep many designs at once (dimensions as arrays); see :func:`graphkin.batch`."""
        from graphkin.kinematics.sweep.batch import batch

        return batch(self, dimensions, count=count, start=start, stop=stop, **kw)
