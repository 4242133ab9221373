"""One spur gear as the book defines it: teeth, module, pressure angle, addendum and dedendum.

Inside graphkin a gear's lengths are floats in its file's length unit and
its angles are radians (as for mechanisms).  The circles of Fig. 7.2 (pitch,
base, addendum, dedendum) and the tooth's thickness at any radius
(involutometry, Sec. 7.10) are properties and methods of :class:`Gear`.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.1, 7.4 (Table 7.2), 7.10, 7.11.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum
from typing import Any

import numpy as np

from graphkin.errors import InputError

__all__ = ["ToothSystem", "GearKind", "Gear", "ADDENDUM", "DEDENDUM", "involute_angle", "inv"]


class ToothSystem(StrEnum):
    """The standard tooth systems of Table 7.2 (addendum and dedendum in modules, ``1/P``)."""

    FULL_DEPTH = "full depth"
    """Addendum ``1 m``, dedendum ``1.25 m`` (20°, 22½°, 25°)."""
    STUB = "stub"
    """Stub teeth: addendum ``0.8 m``, dedendum ``1 m`` (20°)."""


class GearKind(StrEnum):
    """Where a gear's teeth stand against its pitch circle (Sec. 7.5, Figs. 7.9, 7.11)."""

    EXTERNAL = "external"
    """Teeth outside the pitch circle: the addendum circle is R + a."""
    INTERNAL = "internal"
    """An internal (annular) gear: teeth inside a ring, the addendum circle R − a inside
    the pitch circle and the dedendum circle R + d outside it (Fig. 7.11)."""
    RACK = "rack"
    """A rack: a gear of infinite pitch radius (Sec. 7.5, Fig. 7.10), its teeth straight
    flanks at the pressure angle from the line of centers, its addendum and dedendum lines
    parallel to its pitch line; ``teeth`` is 0 (a rack has no count of teeth)."""


#: Addendum in modules, by tooth system (Table 7.2).
ADDENDUM = {ToothSystem.FULL_DEPTH: 1.0, ToothSystem.STUB: 0.8}
#: Dedendum in modules, by tooth system (Table 7.2).
DEDENDUM = {ToothSystem.FULL_DEPTH: 1.25, ToothSystem.STUB: 1.0}


def inv(phi: Any) -> Any:
    """``inv φ = tan φ − φ`` (Eq. 7.14)."""
    return np.tan(phi) - phi


def involute_angle(base: float, r: Any) -> Any:
    """The involute angle ϕ at radius ``r`` of an involute of base radius ``base``.

    ``cos ϕ = r_b/r`` (Eq. 7.15); NaN inside the base circle.
    """
    with np.errstate(invalid="ignore", divide="ignore"):
        return np.arccos(base / np.asarray(r, dtype=float))


@dataclass(frozen=True, slots=True)
class Gear:
    """A spur gear (Secs. 7.1, 7.4, 7.11).

    Parameters
    ----------
    name : str
        The name in the file (``pinion``, ``gear``).
    link : int
        The book's link number (2 the driver, 3 the driven gear).
    teeth : int
        N.
    module : float
        ``m = 2R/N`` in the length unit (with a diametral pitch P, ``m = 1/P``).
    pressure_angle : float
        φ of the cutter (radians).
    addendum, dedendum : float
        a and d as cut, lengths (Table 7.2 gives them in modules).
    offset : float
        The rack cutter's offset e away from the blank (Sec. 7.11, Fig. 7.24):
        the teeth are thicker by ``2e tan φ`` on the standard pitch circle
        (Eq. 7.17) and the root circle is ``e`` larger.
    clearance : float
        c, the amount by which a dedendum exceeds the mating addendum in the
        standard system (``0.25 m`` full depth, ``0.2 m`` stub).

    Examples
    --------
    Example 7.2: 22 teeth, P = 2 teeth/in (m = 0.5 in), 20° full depth.

    >>> g = Gear("gear", 2, 22, 0.5, math.radians(20), 0.5, 0.625)
    >>> round(g.pitch_radius, 3), round(g.base_radius, 3), round(g.circular_pitch, 3)
    (5.5, 5.168, 1.571)
    >>> round(float(g.thickness_at(g.base_radius)), 3), round(float(g.thickness_at(6.0)), 3)
    (0.892, 0.353)
    """

    name: str
    link: int
    teeth: int
    module: float
    pressure_angle: float
    addendum: float
    dedendum: float
    offset: float = 0.0
    clearance: float = 0.0
    kind: GearKind = GearKind.EXTERNAL

    @property
    def internal(self) -> bool:
        """An internal (annular) gear."""
        return self.kind == GearKind.INTERNAL

    @property
    def rack(self) -> bool:
        """A rack (Sec. 7.5, Fig. 7.10): infinite pitch radius, straight flanks."""
        return self.kind == GearKind.RACK

    def __post_init__(self) -> None:
        if self.rack:
            if not 0.0 < self.pressure_angle < math.pi / 2:
                raise InputError("the pressure angle must lie between 0° and 90°",
                                 key="pressure_angle")
            return
        if self.teeth < 3:
            raise InputError(f"a gear needs at least 3 teeth, not {self.teeth}",
                             key=f"gears.{self.name}.teeth")
        if not 0.0 < self.pressure_angle < math.pi / 2:
            raise InputError("the pressure angle must lie between 0° and 90°",
                             key="pressure_angle")
        if self.internal and self.addendum >= self.pitch_radius:
            raise InputError(f"the addendum {self.addendum:g} reaches the center of an internal "
                             f"gear of pitch radius {self.pitch_radius:g}",
                             key=f"gears.{self.name}.addendum")
        if not self.internal and self.dedendum >= self.pitch_radius - self.offset:
            raise InputError(f"the dedendum {self.dedendum:g} reaches the center of a gear of "
                             f"pitch radius {self.pitch_radius:g}",
                             key=f"gears.{self.name}.dedendum")

    @property
    def pitch_radius(self) -> float:
        """R = N m / 2 (Eqs. 7.1, 7.2): the standard pitch circle; infinite for a rack."""
        if self.rack:
            return math.inf
        return self.teeth * self.module / 2.0

    @property
    def base_radius(self) -> float:
        """The base radius r = R cos φ (Step 3 of Sec. 7.5; Eq. 7.15)."""
        return self.pitch_radius * math.cos(self.pressure_angle)

    @property
    def circular_pitch(self) -> float:
        """The circular pitch p = 2πR/N = π m (Eqs. 7.3, 7.4); on a rack's pitch line too."""
        return math.pi * self.module

    @property
    def base_pitch(self) -> float:
        """p_b = 2π r / N: the pitch measured on the base circle, ``p cos φ`` (Eq. 7.6).

        For a rack, the distance between its parallel flanks along the line of
        action (Fig. 7.10).
        """
        return math.pi * self.module * math.cos(self.pressure_angle)

    @property
    def thickness(self) -> float:
        """The tooth thickness on the standard pitch circle: ``p/2 + 2e tan φ`` (Eq. 7.17)."""
        return self.circular_pitch / 2.0 + 2.0 * self.offset * math.tan(self.pressure_angle)

    @property
    def root_radius(self) -> float:
        """The dedendum circle: ``R − d + e`` (Step 5 of Sec. 7.5; Example 7.3).

        ``R + d`` for an internal gear (outside its pitch circle, Fig. 7.11).
        """
        if self.internal:
            return self.pitch_radius + self.dedendum
        return self.pitch_radius - self.dedendum + self.offset

    @property
    def standard_outside_radius(self) -> float:
        """The addendum circle of the gear cut alone: ``R + a + e`` (``R − a`` inside a ring)."""
        if self.internal:
            return self.pitch_radius - self.addendum
        return self.pitch_radius + self.addendum + self.offset

    def half_angle(self, r: Any) -> Any:
        """β, the angular half-thickness of a tooth at radius ``r`` (Sec. 7.10, Eq. d).

        ``β = β_p + inv φ − inv ϕ`` with ``β_p = t_p / 2R`` and ``cos ϕ = r/r_b``.
        """
        beta_p = self.thickness / (2.0 * self.pitch_radius)
        ext = beta_p + inv(self.pressure_angle) - inv(involute_angle(self.base_radius, r))
        if self.internal:   # the tooth of a ring is the space of the external gear (Fig. 7.11)
            return math.pi / self.teeth - ext
        return ext

    def thickness_at(self, r: Any) -> Any:
        """The tooth thickness (an arc) at radius ``r`` ≥ the base radius (Eq. 7.16)."""
        return 2.0 * np.asarray(r, dtype=float) * self.half_angle(r)

    def pointed_radius(self) -> float:
        """The radius at which the two flanks of a tooth meet (β = 0): the tip of a pointed tooth.

        Solved by bisection on ϕ (β decreases as the radius grows).  An internal
        gear's teeth widen outward and never come to a point: infinity.
        """
        if self.internal:
            return math.inf
        target = self.thickness / (2.0 * self.pitch_radius) + float(inv(self.pressure_angle))
        lo, hi = 0.0, math.pi / 2 - 1e-9
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if float(inv(mid)) < target:
                lo = mid
            else:
                hi = mid
        return self.base_radius / math.cos(0.5 * (lo + hi))
