"""A pair of gears in mesh, laid out as the book lays it out (Sec. 7.5, Figs. 7.8-7.9, 7.17-7.21).

:class:`GearPair` holds the two gears and the center distance;
:func:`mesh_construction` records the layout as construction steps in the
book's order: the centers O2 and O3, the pitch point P and the pitch circles
(Step 1), the common tangent (Step 2), the base circles and the line of
action tangent to them at A and B (Step 3), the addendum circles and the
ends of the path of contact, C on the driven gear's addendum circle and D on
the driver's (Step 4), and the dedendum circles (Step 5).  :func:`layout`
evaluates it and measures, on the constructed points, the path of contact,
the angles of approach and recess (Eqs. 7.7-7.8), the contact ratio
(Eq. 7.9) and the interference (Eq. 7.12, Fig. 7.18).

The layout is the book's: the driver 2 (the pinion) above, turning
clockwise; the driven gear 3 below, counterclockwise; the line of centers
vertical and P at the origin.  At a center distance larger than standard
(Sec. 7.9, Fig. 7.21b) the base circles do not change: the pitch point
divides the line of centers in the ratio of the teeth, and the line of
action is the tangent from it to the base circles, at the larger operating
pressure angle.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.5, 7.7-7.9, 7.11.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from enum import StrEnum

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Along, Side
from graphkin.errors import InputError, NoIntersectionError
from graphkin.gears.tooth import Gear, inv
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["GearPair", "MeshLayout", "Contact", "mesh_construction", "layout"]


class Contact(StrEnum):
    """Where an end of the path of contact lies against the interference point (Sec. 7.7)."""

    INSIDE = "inside"
    """Between the pitch point and the point of tangency: involute on involute."""
    INTERFERENCE = "interference"
    """Beyond the point of tangency: the tip digs into the flank (Fig. 7.18)."""


@dataclass(frozen=True)
class GearPair:
    """Two spur gears in mesh at a center distance (Secs. 7.4-7.11).

    Parameters
    ----------
    driver, driven : Gear
        Gear 2 (the driver, usually the pinion) and gear 3.
    center_distance : float or None
        The operating center distance; None mounts the gears where their
        teeth touch on both flanks (the standard ``R2 + R3`` for standard
        teeth, Eqs. 7.18-7.20 for teeth cut with offsets).
    units : str
        The length unit of every length.
    title : str
    source : str
        The file it came from, for messages.

    Raises
    ------
    InputError
        Gears that cannot mesh: different modules or pressure angles, a
        center distance at which the teeth jam (less than where they touch
        on both flanks) or do not reach each other.
    """

    driver: Gear
    driven: Gear
    center_distance: float | None = None
    units: str = "mm"
    title: str = ""
    source: str | None = None
    tol: Tolerance = field(default=DEFAULT_TOL, repr=False)

    def __post_init__(self) -> None:
        g2, g3 = self.driver, self.driven
        if not math.isclose(g2.module, g3.module, rel_tol=1e-9):
            raise InputError(f"gears {g2.name!r} and {g3.name!r} cannot mesh: their modules "
                             f"differ ({g2.module:g} and {g3.module:g} {self.units})",
                             key=f"gears.{g3.name}", file=self.source)
        if not math.isclose(g2.pressure_angle, g3.pressure_angle, rel_tol=1e-9):
            raise InputError(f"gears {g2.name!r} and {g3.name!r} cannot mesh: their pressure "
                             "angles differ", key=f"gears.{g3.name}", file=self.source)
        if g2.internal:
            raise InputError(f"the driver {g2.name!r} is the pinion: only the second gear may be "
                             "internal (kind = \"internal\")", key=f"gears.{g2.name}.kind",
                             file=self.source)
        if g3.rack:
            if g2.offset != 0.0:
                raise InputError("a pinion cut with an offset is not modelled in mesh with a "
                                 "rack: leave offset out", key=f"gears.{g2.name}.offset",
                                 file=self.source)
            if self.center_distance is not None:
                raise InputError("a pinion and a rack have no center distance",
                                 key="center_distance", file=self.source)
            if g2.standard_outside_radius <= g2.base_radius:
                raise InputError(f"the addendum circle of {g2.name!r} lies inside its base "
                                 "circle: its teeth do not reach the line of action",
                                 key=f"gears.{g2.name}.addendum", file=self.source)
            return
        if g3.internal and g3.teeth <= g2.teeth:
            raise InputError(f"a pinion of {g2.teeth} teeth cannot mesh inside an internal gear "
                             f"of {g3.teeth}: the ring needs more teeth than the pinion",
                             key=f"gears.{g3.name}.teeth", file=self.source)
        c0 = self.tight_center_distance
        c = self.center
        if c < c0 - self.tol.length(c0):
            raise InputError(f"the gears cannot mesh at a center distance of {c:g} {self.units}: "
                             f"their teeth jam below {c0:.6g} {self.units}, where they touch on "
                             "both flanks", key="center_distance", file=self.source)
        ra2, ra3 = self.outside_radii
        if g3.internal and ra3 <= g3.base_radius * (1 + 1e-12):
            raise InputError(f"the addendum circle of the internal gear {g3.name!r} ({ra3:g} "
                             f"{self.units}) lies inside its base circle ({g3.base_radius:.6g}): "
                             "its tips would not be involute", key=f"gears.{g3.name}.addendum",
                             file=self.source)
        reach = ra2 + ra3 if not g3.internal else math.inf   # inside: the path decides
        if c >= reach or ra2 <= g2.base_radius or ra3 <= g3.base_radius:
            raise InputError(f"the gears cannot mesh at a center distance of {c:g} {self.units}: "
                             "their addendum circles do not reach the line of action",
                             key="center_distance", file=self.source)

    @property
    def tight_angle(self) -> float:
        """The pressure angle at which the teeth touch on both flanks (no backlash, Eq. 7.18).

        Found by bisection on the sum of the thicknesses on the two pitch
        circles, ``t_2(R'_2) + t_3(R'_3) = 2π R'_2 / N_2`` (Eq. 7.18's
        condition c), with ``R'_i = r_i / cos φ'``; the standard φ when the
        teeth are standard.
        """
        g2, g3 = self.driver, self.driven
        phi = g2.pressure_angle
        if g2.offset == 0.0 and g3.offset == 0.0:
            return phi
        if g3.internal:
            raise InputError("teeth cut with an offset are not modelled inside an internal gear",
                             key=f"gears.{g3.name}.offset", file=self.source)

        def gap(x: float) -> float:   # backlash / (2 R'_2), decreasing in x
            b2 = g2.thickness / (2 * g2.pitch_radius) + float(inv(phi)) - float(inv(x))
            b3 = g3.thickness / (2 * g3.pitch_radius) + float(inv(phi)) - float(inv(x))
            return math.pi / g2.teeth - b2 - b3 * g3.teeth / g2.teeth

        lo, hi = 1e-9, math.pi / 2 - 1e-9
        if gap(lo) > 0 or gap(hi) < 0:
            raise InputError("the gears cannot mesh: their teeth are too thin or too thick "
                             "for any center distance", key="gears", file=self.source)
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if gap(mid) > 0:
                hi = mid
            else:
                lo = mid
        return 0.5 * (lo + hi)

    @property
    def tight_center_distance(self) -> float:
        """Where the teeth touch on both flanks: ``(r_2 + r_3) / cos φ'`` (Eqs. 7.19-7.20)."""
        r2, r3 = self.driver.base_radius, self.driven.base_radius
        if self.driven.rack:
            return math.inf
        return (r3 - r2 if self.driven.internal else r2 + r3) / math.cos(self.tight_angle)

    @property
    def center(self) -> float:
        """The operating center distance."""
        return self.tight_center_distance if self.center_distance is None else \
            self.center_distance

    @property
    def scale(self) -> float:
        """The length the tolerances scale with: the center distance, or ``R_2`` with a rack."""
        return self.driver.pitch_radius if self.driven.rack else self.center

    @property
    def standard_center_distance(self) -> float:
        """``R_2 + R_3``: the standard pitch circles tangent (Step 1); ``R_3 − R_2`` inside."""
        if self.driven.internal:
            return self.driven.pitch_radius - self.driver.pitch_radius
        return self.driver.pitch_radius + self.driven.pitch_radius

    @property
    def outside_radii(self) -> tuple[float, float]:
        """The addendum circles as cut (Example 7.3's rule).

        Each blank is cut so that the clearance at the other gear's root is
        standard when the pair is mounted with no backlash:
        ``R_a2 = C_0 − (root radius of 3) − (d_3 − a_2)``; for standard teeth
        this is ``R + a``, and for equal and opposite offsets (the
        long-and-short-addendum system) ``R + a + e``.
        """
        g2, g3 = self.driver, self.driven
        if g3.rack:   # the rack's addendum line at a above its pitch line: "radius" infinite
            return g2.standard_outside_radius, math.inf
        if g3.internal:   # no offsets inside a ring: each blank as cut alone
            return g2.standard_outside_radius, g3.standard_outside_radius
        c0 = self.tight_center_distance
        return (c0 - g3.root_radius - (g3.dedendum - g2.addendum),
                c0 - g2.root_radius - (g2.dedendum - g3.addendum))

    @property
    def operating_pitch_radii(self) -> tuple[float, float]:
        """``R'_2, R'_3``: the pitch point divides the center distance as the teeth (Eq. 7.5)."""
        n2, n3 = self.driver.teeth, self.driven.teeth
        if self.driven.rack:   # the pitch circle of 2 rolls on the rack's pitch line
            return self.driver.pitch_radius, math.inf
        if self.driven.internal:   # both centers on one side of P: R'_3 − R'_2 = C
            return self.center * n2 / (n3 - n2), self.center * n3 / (n3 - n2)
        return self.center * n2 / (n2 + n3), self.center * n3 / (n2 + n3)


@dataclass
class MeshLayout:
    """The evaluated layout of a pair in mesh, every value measured on the construction.

    Attributes
    ----------
    pair : GearPair
    construction : Construction
    points : dict
        ``O2, O3, P, A, B, C, D`` -> ``(x, y)``.
    operating_pressure_angle : float
        The angle between the line of action and the common tangent (radians).
    approach, recess : float
        CP and PD, signed along the direction from C toward D.
    path : float
        CD, the path of contact.
    contact_ratio : float
        ``CD / p_b`` (Eq. 7.9).
    approach_angles, recess_angles : (float, float)
        α2, α3 and β2, β3 (Eqs. 7.7, 7.8), radians.
    start, end : Contact
        C against A, D against B.
    beyond_a, beyond_b : float
        AC and BD when positive (the interference), else negative.
    involute_path : float
        The part of CD between A and B (where involute meets involute).
    """

    pair: GearPair
    construction: Construction
    points: dict[str, tuple[float, float]]
    operating_pressure_angle: float
    approach: float
    recess: float
    path: float
    contact_ratio: float
    approach_angles: tuple[float, float]
    recess_angles: tuple[float, float]
    start: Contact
    end: Contact
    beyond_a: float
    beyond_b: float
    involute_path: float

    @property
    def interference(self) -> bool:
        """Contact begins before A or ends after B (Sec. 7.7)."""
        return Contact.INTERFERENCE in (self.start, self.end)

    @property
    def involute_contact_ratio(self) -> float:
        """The contact ratio of the involute part of the path, ``max(C, A)`` to ``min(D, B)``."""
        return self.involute_path / self.pair.driver.base_pitch


def mesh_construction(pair: GearPair) -> Construction:
    """Record the layout of Figs. 7.8-7.9 (and 7.21b at an increased center distance).

    Returns
    -------
    Construction
        Labels: ``O2``, ``O3``, ``O2O3`` (the line of centers), ``P``,
        ``pitch2``, ``pitch3``, ``tangent`` (the common tangent), ``base2``,
        ``base3``, ``A``, ``B``, ``AB`` (the line of action, directed from A
        to B), ``addendum2``, ``addendum3``, ``C``, ``D``, ``dedendum2``,
        ``dedendum3``.
    """
    g2, g3 = pair.driver, pair.driven
    if g3.rack:
        return _rack_construction(pair)
    c = pair.center
    r2p, r3p = pair.operating_pitch_radii
    ra2, ra3 = pair.outside_radii
    cx = Construction(title=f"gears {g2.teeth} and {g3.teeth} teeth in mesh")

    def add(op: str, inputs: tuple[str, ...], out: str, note: str, **kw: object) -> None:
        cx.add(op, inputs, (out,), note=note, diagram="gears", **kw)  # type: ignore[arg-type]

    # Step 1: the centers, the pitch point and the pitch circles
    add("point", (), "O2", "O2, the center of the driver 2", xy=(0.0, r2p), role="given")
    inside = g3.internal
    if inside:   # Fig. 7.11: both centers on the same side of P
        add("point", (), "O3", f"O3, the center of the internal gear 3, {c:g} from O2 on the "
            "same side of the pitch point", xy=(0.0, r2p + c), role="given")
    else:
        add("point", (), "O3", f"O3, the center of gear 3, {c:g} from O2", xy=(0.0, r2p - c),
            role="given")
    add("join", ("O2", "O3"), "O2O3", "the line of centers O2 O3")
    if inside:
        add("along_ray", ("O2", "O3"), "P", "the pitch point P on the line of centers beyond "
            f"O2, away from O3, O2P/O3P = {g2.teeth}/{g3.teeth} (Eq. 7.5)", distance=-r2p,
            role="result")
    else:
        add("along_ray", ("O2", "O3"), "P", "the pitch point P divides the line of centers in "
            f"the ratio of the teeth, O2P/O3P = {g2.teeth}/{g3.teeth} (Eq. 7.5)", distance=r2p,
            role="result")
    add("circle", ("O2",), "pitch2", "the pitch circle of 2, about O2 through P", radius=r2p)
    add("circle", ("O3",), "pitch3", "the pitch circle of 3, about O3 through P", radius=r3p)
    # Step 2: the common tangent
    add("perpendicular", ("O2O3", "P"), "tangent", "the common tangent to the pitch circles "
        "through P, perpendicular to the line of centers")
    # Step 3: the base circles and the line of action tangent to them
    add("circle", ("O2",), "base2", "the base circle of 2", radius=g2.base_radius)
    add("circle", ("O3",), "base3", "the base circle of 3", radius=g3.base_radius)
    add("tangent_foot", ("O2", "P"), "A", "A, where the line of action through P touches the "
        "base circle of 2: the foot of the perpendicular from O2 (the interference point)",
        offset=g2.base_radius, branch=Side.LEFT, role="result")
    add("tangent_foot", ("O3", "P"), "B", "B, where the line of action touches the base "
        "circle of 3: the foot of the perpendicular from O3" + (
            " (on the same side of P as A: the internal gear's interference point lies "
            "beyond A)" if inside else ""), offset=g3.base_radius,
        branch=Side.LEFT, role="result")
    add("join", ("A", "B"), "AB", "the line of action AB, through P at the pressure angle "
        "from the common tangent")
    # Step 4: the addendum circles and the ends of the path of contact
    add("circle", ("O2",), "addendum2", "the addendum circle of 2", radius=ra2)
    add("circle", ("O3",), "addendum3", "the addendum circle of 3", radius=ra3)
    add("intersect_line_circle", ("AB", "addendum3"), "C", "C, first contact: where the "
        "addendum circle of the driven gear 3 crosses the line of action" + (
            " (of its two crossings, the one nearer P)" if inside else ""),
        branch=Along.BEHIND, role="result")
    add("intersect_line_circle", ("AB", "addendum2"), "D", "D, last contact: where the "
        "addendum circle of the driver 2 crosses the line of action",
        branch=Along.BEHIND if inside else Along.AHEAD, role="result")
    # Step 5: the dedendum circles
    add("circle", ("O2",), "dedendum2", "the dedendum circle of 2", radius=g2.root_radius)
    add("circle", ("O3",), "dedendum3", "the dedendum circle of 3", radius=g3.root_radius)
    return cx


def _rack_construction(pair: GearPair) -> Construction:
    """The layout of a pinion and a rack (Sec. 7.5, Fig. 7.10; Sec. 7.7).

    The rack is a gear of infinite radius: its pitch circle is the pitch line,
    tangent to the pinion's pitch circle at P; its base circle and B lie at
    infinity, so the line of action runs from A through P without end; its
    addendum and dedendum circles are lines parallel to the pitch line, ``a``
    toward the pinion and ``d`` away from it.  First contact C is where the
    rack's addendum line crosses the line of action (CP = a / sin φ), last
    contact D where the pinion's addendum circle does.

    Labels: ``O2``, ``P``, ``O2P`` (the line of centers), ``pitch2``,
    ``tangent`` (the rack's pitch line), ``base2``, ``A``, ``AB`` (the line of
    action from A through P), ``addendum2``, ``E3`` and ``addendum3`` (the
    rack's addendum line), ``C``, ``D``, ``dedendum2``, ``F3`` and
    ``dedendum3`` (the rack's dedendum line).
    """
    g2, g3 = pair.driver, pair.driven
    r2p = g2.pitch_radius
    ra2 = pair.outside_radii[0]
    cx = Construction(title=f"a pinion of {g2.teeth} teeth and a rack in mesh")

    def add(op: str, inputs: tuple[str, ...], out: str, note: str, **kw: object) -> None:
        cx.add(op, inputs, (out,), note=note, diagram="gears", **kw)  # type: ignore[arg-type]

    # Step 1: the center, the pitch point, the pitch circle and the rack's pitch line
    add("point", (), "O2", "O2, the center of the pinion 2", xy=(0.0, r2p), role="given")
    add("point", (), "P", f"the pitch point P, {r2p:g} (the pitch radius R2) below O2",
        xy=(0.0, 0.0), role="given")
    add("join", ("O2", "P"), "O2P", "the line of centers through O2 and P, perpendicular to "
        "the rack")
    add("circle", ("O2",), "pitch2", "the pitch circle of 2, about O2 through P", radius=r2p)
    # Step 2: the rack's pitch line is the common tangent
    add("perpendicular", ("O2P", "P"), "tangent", "the pitch line of the rack 3: the tangent "
        "to the pitch circle of 2 at P (a rack is a gear of infinite radius, Sec. 7.5)")
    # Step 3: the base circle and the line of action
    add("circle", ("O2",), "base2", "the base circle of 2", radius=g2.base_radius)
    add("tangent_foot", ("O2", "P"), "A", "A, where the line of action through P touches the "
        "base circle of 2: the foot of the perpendicular from O2 (the interference point)",
        offset=g2.base_radius, branch=Side.LEFT, role="result")
    add("join", ("A", "P"), "AB", "the line of action from A through P, at the pressure "
        "angle from the pitch line, normal to the rack's straight flanks; the rack's base "
        "circle, and B, lie at infinity")
    # Step 4: the addendum circle and line, and the ends of the path of contact
    add("circle", ("O2",), "addendum2", "the addendum circle of 2", radius=ra2)
    add("along_ray", ("O2", "P"), "E3", f"E3 on the line of centers, the rack's addendum "
        f"{g3.addendum:g} above P", distance=r2p - g3.addendum)
    add("parallel", ("tangent", "E3"), "addendum3", "the addendum line of the rack, parallel "
        "to its pitch line through E3")
    add("meet", ("AB", "addendum3"), "C", "C, first contact: where the addendum line of the "
        "rack crosses the line of action", role="result")
    add("intersect_line_circle", ("AB", "addendum2"), "D", "D, last contact: where the "
        "addendum circle of the pinion 2 crosses the line of action", branch=Along.AHEAD,
        role="result")
    # Step 5: the dedendum circle and line
    add("circle", ("O2",), "dedendum2", "the dedendum circle of 2", radius=g2.root_radius)
    add("along_ray", ("O2", "P"), "F3", f"F3 on the line of centers, the rack's dedendum "
        f"{g3.dedendum:g} below P", distance=r2p + g3.dedendum)
    add("parallel", ("tangent", "F3"), "dedendum3", "the dedendum line of the rack, parallel "
        "to its pitch line through F3")
    return cx


def layout(pair: GearPair) -> MeshLayout:
    """Evaluate :func:`mesh_construction` and measure the path of contact on it.

    Raises
    ------
    InputError
        An addendum circle that does not meet the line of action.
    """
    cx = mesh_construction(pair)
    try:
        ev = cx.evaluate()
    except NoIntersectionError as exc:
        raise InputError(f"the gears cannot mesh: {exc}", key="center_distance",
                         file=pair.source) from None
    g2, g3 = pair.driver, pair.driven
    names = ("O2", "P", "A", "C", "D") if g3.rack else ("O2", "O3", "P", "A", "B", "C", "D")
    pts = {k: (float(ev[k][0] / ev[k][2]), float(ev[k][1] / ev[k][2])) for k in names}
    p = np.array(pts["P"])
    u = p - np.array(pts["A"])
    u = u / float(np.hypot(*u))                 # along the line of action, A toward P
    tan = np.asarray(ev["tangent"])
    v = np.array([tan[1], -tan[0]])
    phi = math.atan2(abs(float(u[0] * v[1] - u[1] * v[0])), abs(float(u @ v)))

    def along(label: str) -> float:
        return float((np.array(pts[label]) - p) @ u)

    t_a, t_c, t_d = along("A"), along("C"), along("D")
    t_b = math.inf if g3.rack else along("B")   # a rack's base circle is at infinity
    cp, pd = -t_c, t_d
    path = t_d - t_c
    tol = pair.tol.length(pair.scale)
    if path <= tol:
        raise InputError(f"the gears cannot mesh at a center distance of {pair.center:g} "
                         f"{pair.units}: the addendum circles cross the line of action with no "
                         "path of contact between them", key="center_distance",
                         file=pair.source)
    beyond_a = t_a - t_c
    # inside a ring B lies behind A: the recess is not bounded by it (Fig. 7.11)
    beyond_b = t_d - t_b if not g3.internal else -abs(t_d - t_b)
    start = Contact.INTERFERENCE if beyond_a > tol else Contact.INSIDE
    end = Contact.INTERFERENCE if beyond_b > tol else Contact.INSIDE
    involute_path = (t_d if g3.internal else min(t_d, t_b)) - max(t_c, t_a)
    return MeshLayout(
        pair=pair, construction=cx, points=pts, operating_pressure_angle=phi,
        approach=cp, recess=pd, path=path, contact_ratio=path / g2.base_pitch,
        approach_angles=(cp / g2.base_radius, cp / g3.base_radius),
        recess_angles=(pd / g2.base_radius, pd / g3.base_radius),
        start=start, end=end, beyond_a=beyond_a, beyond_b=beyond_b,
        involute_path=involute_path)
