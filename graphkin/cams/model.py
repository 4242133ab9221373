"""A disk cam and its follower: the data of a cam file (Secs. 6.2, 6.4, 6.9-6.10).

Coordinates: the cam shaft O2 is the origin of the frame; a translating
follower moves along the y axis, its centerline offset ``ε`` to the right
(Fig. 6.27); an oscillating follower turns about its pivot O4 (Fig. 6.35).
Θ is the cam's angle turned in its own sense of rotation (``Sense``); the
cam's own coordinates ``u, v`` coincide with ``x, y`` at Θ = 0 (Sec. 6.9).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.2, 6.4 (trace point, pitch curve,
prime and base circles), 6.9-6.10 (Figs. 6.26, 6.27, 6.35).
"""

from __future__ import annotations

import cmath
import enum
import math
from dataclasses import dataclass

from graphkin.cams.program import Program
from graphkin.errors import InputError

__all__ = ["FollowerKind", "Sense", "Follower", "Cam"]


class FollowerKind(enum.Enum):
    """The followers of Fig. 6.2 the layout handles (Figs. 6.8-6.11)."""

    KNIFE_EDGE = "knife-edge"
    ROLLER = "roller"
    FLAT_FACE = "flat-face"
    OSCILLATING_ROLLER = "oscillating-roller"
    OSCILLATING_FLAT_FACE = "oscillating-flat-face"

    @property
    def oscillating(self) -> bool:
        """The follower turns about a pivot (Fig. 6.11)."""
        return self in (FollowerKind.OSCILLATING_ROLLER, FollowerKind.OSCILLATING_FLAT_FACE)

    @property
    def flat(self) -> bool:
        """The follower touches the cam with a flat face (Fig. 6.10)."""
        return self in (FollowerKind.FLAT_FACE, FollowerKind.OSCILLATING_FLAT_FACE)

    @property
    def roller(self) -> bool:
        """The follower touches the cam with a roller (Figs. 6.8, 6.9, 6.11)."""
        return self in (FollowerKind.ROLLER, FollowerKind.OSCILLATING_ROLLER)


class Sense(enum.Enum):
    """A sense of rotation: of the cam, or of an oscillating follower as it rises."""

    CCW = "ccw"
    CW = "cw"

    @property
    def sign(self) -> float:
        """+1 counterclockwise, −1 clockwise."""
        return 1.0 if self is Sense.CCW else -1.0


@dataclass(frozen=True)
class Follower:
    """The follower (Fig. 6.2).

    Parameters
    ----------
    kind : FollowerKind
    offset : float
        ``ε``: a translating follower's centerline to the right of O2 (Fig. 6.27).
    roller : float
        ``R_r``, the roller's radius (roller followers).
    face : float or None
        The flat face's width, if given (checked against Eq. 6.29).
    pivot : tuple of float
        O4, the oscillating follower's fixed pivot (relative to O2).
    arm : float
        ``r4``: O4 to the roller's center (oscillating roller follower).
    face_offset : float
        Oscillating flat face: its distance from the pivot's line, toward the cam.
    rise : Sense
        Oscillating followers: the arm's sense of rotation as the follower rises.
    """

    kind: FollowerKind
    offset: float = 0.0
    roller: float = 0.0
    face: float | None = None
    pivot: tuple[float, float] = (0.0, 0.0)
    arm: float = 0.0
    face_offset: float = 0.0
    rise: Sense = Sense.CCW


@dataclass(frozen=True)
class Cam:
    """A plate cam, its program and its follower.

    Parameters
    ----------
    program : Program
    prime : float
        ``R0``: the prime circle's radius (Sec. 6.4; for a flat face or a
        knife edge also the base circle).
    follower : Follower
    sense : Sense
        The cam's sense of rotation.
    omega : float or None
        The cam's speed (rad/s), for velocities, accelerations and jerks.
    unit : str
        The length unit of the file.
    title, source : str
    """

    program: Program
    prime: float
    follower: Follower
    sense: Sense = Sense.CCW
    omega: float | None = None
    unit: str = "mm"
    title: str = ""
    source: str = ""

    def __post_init__(self) -> None:
        src = self.source or None
        f = self.follower
        if not (self.prime > 0 and math.isfinite(self.prime)):
            raise InputError(f"the prime circle's radius must be positive, not {self.prime:g}",
                             key="cam.prime", file=src)
        if f.kind.roller and not (f.roller > 0):
            raise InputError("a roller follower needs its roller's radius (> 0)",
                             key="follower.roller", file=src)
        if f.kind.roller and f.roller >= self.prime:
            size = "as big as" if f.roller == self.prime else "bigger than"
            raise InputError(f"the roller (radius {f.roller:g}) is {size} the prime circle "
                             f"({self.prime:g}): no base circle is left, the follower cannot "
                             "follow", key="follower.roller", file=src)
        if f.kind in (FollowerKind.KNIFE_EDGE, FollowerKind.ROLLER) and \
                abs(f.offset) >= self.prime:
            raise InputError(f"the offset {f.offset:g} must be smaller than the prime circle's "
                             f"radius {self.prime:g} (Eq. 6.32)", key="follower.offset", file=src)
        if f.kind.oscillating:
            d = math.hypot(*f.pivot)
            if d <= self.prime:
                raise InputError("the pivot must lie outside the prime circle",
                                 key="follower.pivot", file=src)
            if f.kind is FollowerKind.OSCILLATING_ROLLER:
                if not (f.arm > 0) or not (abs(d - f.arm) < self.prime < d + f.arm):
                    raise InputError(f"an arm of {f.arm:g} from the pivot cannot reach the prime "
                                     f"circle (radius {self.prime:g}, pivot {d:g} away)",
                                     key="follower.arm", file=src)
            elif f.face_offset + self.prime >= d:
                raise InputError("the face cannot touch the prime circle: the pivot is too "
                                 "close", key="follower.face_offset", file=src)

    @property
    def s(self) -> float:
        """The cam's sense, +1 counterclockwise."""
        return self.sense.sign

    @property
    def base(self) -> float:
        """The base circle's radius: the prime circle less the roller (Sec. 6.4)."""
        return self.prime - (self.follower.roller if self.follower.kind.roller else 0.0)

    @property
    def y0(self) -> float:
        """The trace point's height above O2 at zero lift (Eq. b of Sec. 6.10)."""
        f = self.follower
        if f.kind.flat:
            return self.prime
        return math.sqrt(self.prime**2 - f.offset**2)

    @property
    def arm0(self) -> float:
        """θ4 at zero lift: the oscillating follower's arm angle (Ex 6.7: 150°).

        The roller's center lies on the prime circle (or the face touches it),
        on the branch where a rise moves the follower away from O2; the flat
        face's arm points from the pivot toward the cam.
        """
        f = self.follower
        px, py = f.pivot
        d, delta = abs(complex(px, py)), cmath.phase(complex(px, py))
        sigma = f.rise.sign
        if f.kind is FollowerKind.OSCILLATING_ROLLER:
            c = (self.prime**2 - d * d - f.arm**2) / (2 * d * f.arm)
            return delta - sigma * math.acos(max(-1.0, min(1.0, c)))
        sn = -sigma * (f.face_offset + self.prime) / d
        return delta + math.pi - math.asin(sn)
