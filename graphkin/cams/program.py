"""A follower program: rises, dwells and returns over one turn of the cam (Secs. 6.3, 6.5, 6.8).

A :class:`Program` is a list of :class:`Segment` covering 360° of cam angle.
:meth:`Program.evaluate` gives the displacement ``Y`` and the kinematic
coefficients ``y'``, ``y''``, ``y'''`` (Eqs. 6.1-6.4) for any array of cam
angles, and, with the cam's speed, the follower's velocity, acceleration and
jerk (Eqs. 6.8-6.11).  :meth:`Program.joints` checks the matching of the
derivatives at every boundary (Sec. 6.8): a jump in ``y`` is an error, a jump
in ``y'`` or ``y''`` a warning naming the segment and the cam angle.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.3 (Eqs. a-b), 6.5 (Eqs. 6.7-6.11),
6.8 (matching derivatives, Ex 6.2).
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass, field

import numpy as np

from graphkin.cams.motions import HALF_FORMS, Motion, Rest, Shape, shape, table_shape
from graphkin.errors import InputError
from graphkin.text import ROUND_OFF, clean, g6

__all__ = ["Segment", "Program", "Kinematics", "Joint", "Jump", "TWO_PI", "MATCH_REL"]

TWO_PI = 2 * math.pi
MATCH_REL = 1e-4
"""A jump in y' or y'' smaller than this fraction of the program's largest |y'|
(|y''|) is taken as the rounding of the data as written (the book prints five
digits), not a mismatch; far above the arithmetic's round-off (~1e-15)."""
LIFT_REL = 1e-9
"""A jump in y (or an angle sum off 360°) beyond this fraction of the lift (of 360°) is an error."""

Array = np.ndarray


class Jump(enum.Enum):
    """What does not match at a boundary (Sec. 6.8)."""

    DISPLACEMENT = "y"
    VELOCITY = "y'"
    ACCELERATION = "y''"


@dataclass(frozen=True)
class Segment:
    """One segment of the displacement diagram (Sec. 6.3).

    Parameters
    ----------
    motion : Motion
    lift : float
        ``h``: positive for a rise, negative for a return, 0 for a dwell
        (length, or radians for an oscillating follower); for a table, its last
        displacement less its first.
    angle : float
        ``β``, the segment's cam angle (rad), positive.
    rest : Rest, optional
        The half motions' zero-slope end.
    name : str
        How messages name it (``segment 3 (cycloidal return)``).
    table : tuple of arrays, optional
        For ``Motion.TABLE``: the cam angles from the segment's start (rad) and
        the displacements there.
    """

    motion: Motion
    lift: float
    angle: float
    rest: Rest | None = None
    name: str = ""
    table: tuple[tuple[float, ...], tuple[float, ...]] | None = None

    @property
    def kind(self) -> str:
        """``rise``, ``return``, ``dwell`` or ``table``."""
        if self.motion is Motion.TABLE:
            return "table"
        if self.motion is Motion.DWELL or self.lift == 0:
            return "dwell"
        return "rise" if self.lift > 0 else "return"

    @property
    def equation(self) -> str:
        """The book's equation for this segment, when it has one."""
        rise = self.lift > 0
        if self.rest is not None:
            return HALF_FORMS.get((self.motion, rise, self.rest), "")
        return {
            Motion.PARABOLIC: "Eqs. (6.5)-(6.6), Fig. 6.12",
            Motion.HARMONIC: "Eq. (6.12), Fig. 6.14" if rise else "Eq. (6.15), Fig. 6.17",
            Motion.CYCLOIDAL: "Eq. (6.13), Fig. 6.15" if rise else "Eq. (6.16), Fig. 6.18",
            Motion.POLYNOMIAL8: "Eq. (6.14), Fig. 6.16" if rise else "Eq. (6.17), Fig. 6.19",
        }.get(self.motion, "")

    def unit_shape(self) -> tuple[Shape, float, float]:
        """``(f, y0, h)``: the shape, where it starts (tables only) and its scale."""
        if self.motion is Motion.TABLE:
            assert self.table is not None
            return table_shape(np.asarray(self.table[0]), np.asarray(self.table[1]))
        return shape(self.motion, rise=self.lift >= 0, rest=self.rest), 0.0, self.lift


@dataclass(frozen=True)
class Kinematics:
    """The displacement diagram at an array of cam angles (Eqs. 6.1-6.4).

    Attributes
    ----------
    theta : array
        Cam angle Θ (rad, in [0, 2π)).
    Y, y1, y2, y3 : array
        Displacement and the first-, second- and third-order kinematic
        coefficients ``y'``, ``y''``, ``y'''`` (per rad, rad², rad³).
    segment : array of int
        The segment each angle falls in.
    """

    theta: Array
    Y: Array
    y1: Array
    y2: Array
    y3: Array
    segment: Array

    def rates(self, omega: float) -> tuple[Array, Array, Array]:
        """Velocity, acceleration and jerk at constant cam speed ω (Eq. 6.11)."""
        return self.y1 * omega, self.y2 * omega**2, self.y3 * omega**3


@dataclass(frozen=True)
class Joint:
    """A boundary between two segments and what does not match there (Sec. 6.8).

    ``before`` and ``after`` are segment indices (0-based); ``theta`` the cam
    angle (rad); ``jumps`` maps each :class:`Jump` that occurs to ``(left, right)``.
    """

    before: int
    after: int
    theta: float
    jumps: dict[Jump, tuple[float, float]] = field(default_factory=dict)


@dataclass(frozen=True)
class Program:
    """A follower program covering one turn of the cam (Sec. 6.3).

    Parameters
    ----------
    segments : tuple of Segment
        In order from Θ = 0.
    source : str
        The file it was read from, for messages.

    Raises
    ------
    InputError
        Segments that do not cover 360°, a non-positive angle, or a lift that
        does not come back to the start.

    Examples
    --------
    A cycloidal rise of 2 in 90°, a dwell, a cycloidal return (Fig. 6.15 and 6.18):

    >>> import math
    >>> from graphkin.cams.motions import Motion
    >>> p = Program((Segment(Motion.CYCLOIDAL, 2.0, math.pi / 2),
    ...              Segment(Motion.DWELL, 0.0, math.pi / 2),
    ...              Segment(Motion.CYCLOIDAL, -2.0, math.pi)))
    >>> k = p.evaluate([math.pi / 4])
    >>> round(float(k.Y[0]), 12), round(float(k.y1[0]), 6)   # L/2 and 2L/β at mid-rise
    (1.0, 2.546479)
    """

    segments: tuple[Segment, ...]
    source: str = ""

    def __post_init__(self) -> None:
        self._check()

    # ---- structure -------------------------------------------------------------------
    def label(self, k: int) -> str:
        """How a message names segment ``k``: ``segment 2 (cycloidal rise)``."""
        s = self.segments[k]
        what = s.name or (f"{s.motion.value} {s.kind}" if s.kind not in ("dwell", "table")
                          else s.kind)
        return f"segment {k + 1} ({what})"

    @property
    def starts(self) -> Array:
        """Θ_k: the cam angle where each segment starts (rad)."""
        return np.concatenate([[0.0], np.cumsum([s.angle for s in self.segments])[:-1]])

    @property
    def bases(self) -> Array:
        """Y_k: the displacement where each segment starts."""
        out = [0.0]
        for s in self.segments[:-1]:
            f, y0, h = s.unit_shape()
            end = y0 + h * float(f(np.array(1.0))[0])
            out.append(end if s.motion is Motion.TABLE else out[-1] + end)
        return np.asarray(out)

    @property
    def lift(self) -> float:
        """The largest displacement (the total lift)."""
        k = self.evaluate(np.linspace(0, TWO_PI, 3601)[:-1])
        return float(np.max(k.Y) - np.min(k.Y))

    def _check(self) -> None:
        src = self.source or None
        if not self.segments:
            raise InputError("a cam program needs at least one [[segment]]", key="segment",
                             file=src)
        for k, s in enumerate(self.segments):
            if not (s.angle > 0 and math.isfinite(s.angle)):
                raise InputError(f"{self.label(k)}: the angle must be positive, not "
                                 f"{math.degrees(s.angle):g}°", key=f"segment[{k}].angle",
                                 file=src)
            if s.motion is Motion.DWELL and s.lift != 0:
                raise InputError(f"{self.label(k)}: a dwell has no lift", key=f"segment[{k}].lift",
                                 file=src)
            if s.motion not in (Motion.DWELL, Motion.TABLE) and s.lift == 0:
                raise InputError(f"{self.label(k)}: a {s.motion.value} segment needs a lift "
                                 "(negative for a return); use motion = \"dwell\" for none",
                                 key=f"segment[{k}].lift", file=src)
        total = float(sum(s.angle for s in self.segments))
        if abs(total - TWO_PI) > LIFT_REL * TWO_PI:
            short = "short of" if total < TWO_PI else "beyond"
            raise InputError(f"the segments cover {math.degrees(total):.6g}°, "
                             f"{abs(math.degrees(TWO_PI - total)):.6g}° {short} 360° "
                             f"(the last is {self.label(len(self.segments) - 1)})",
                             key=f"segment[{len(self.segments) - 1}].angle", file=src)
        for j in self.joints(only_errors=True):
            left, right = j.jumps[Jump.DISPLACEMENT]
            raise InputError(f"{self.label(j.after)}: the displacement jumps from {left:.6g} to "
                             f"{right:.6g} at {math.degrees(j.theta):.6g}° "
                             f"(the end of {self.label(j.before)}); a cam cannot lift "
                             "its follower in no time",
                             key=f"segment[{j.after}]", file=src)

    # ---- evaluation ------------------------------------------------------------------
    def evaluate(self, theta: Array | list[float] | float) -> Kinematics:
        """Y, y', y'', y''' at cam angles Θ (rad; taken modulo 2π).

        A boundary angle belongs to the segment that starts there.
        """
        th = np.mod(np.asarray(theta, dtype=float), TWO_PI)
        starts, bases = self.starts, self.bases
        k = np.clip(np.searchsorted(starts, th, side="right") - 1, 0, len(self.segments) - 1)
        Y, y1, y2, y3 = (np.zeros_like(th) for _ in range(4))
        for i, s in enumerate(self.segments):
            m = k == i
            if not np.any(m):
                continue
            u = np.clip((th[m] - starts[i]) / s.angle, 0.0, 1.0)
            f, y0, h = s.unit_shape()
            a, b, c, d = f(u)
            base = y0 if s.motion is Motion.TABLE else bases[i]
            Y[m] = base + h * a
            y1[m] = h * b / s.angle
            y2[m] = h * c / s.angle**2
            y3[m] = h * d / s.angle**3
        return Kinematics(th, Y, y1, y2, y3, k)

    def ends(self, k: int) -> tuple[Array, Array]:
        """Segment ``k``'s (Y, y', y'') at its start and at its end (limits from inside)."""
        s = self.segments[k]
        f, y0, h = s.unit_shape()
        base = y0 if s.motion is Motion.TABLE else self.bases[k]
        a, b, c, _ = f(np.array([0.0, 1.0]))
        return (np.array([base + h * a[0], h * b[0] / s.angle, h * c[0] / s.angle**2]),
                np.array([base + h * a[1], h * b[1] / s.angle, h * c[1] / s.angle**2]))

    def scales(self) -> Array:
        """The program's largest |Y|, |y'|, |y''| (the sizes jumps are judged against)."""
        k = self.evaluate(np.linspace(0.0, TWO_PI, 7201)[:-1])
        ends = np.array([np.abs(e) for i in range(len(self.segments)) for e in self.ends(i)])
        out = np.maximum(ends.max(axis=0), [np.abs(k.Y).max(), np.abs(k.y1).max(),
                                            np.abs(k.y2).max()])
        return np.where(out > 0, out, 1.0)

    def joints(self, *, only_errors: bool = False) -> list[Joint]:
        """The boundaries where y, y' or y'' jump (Sec. 6.8), including 360° → 0°.

        A jump counts when it exceeds :data:`LIFT_REL` (for y) or
        :data:`MATCH_REL` (for y', y'') of the program's largest value of that
        quantity.
        """
        n = len(self.segments)
        scale = self.scales()
        rel = np.array([LIFT_REL, MATCH_REL, MATCH_REL])
        out = []
        starts = self.starts
        for i in range(n):
            before, after = (i - 1) % n, i
            left = self.ends(before)[1]
            right = self.ends(after)[0]
            bad = np.abs(left - right) > rel * scale
            if only_errors:
                bad[1:] = False
            jumps = {j: (float(left[q]), float(right[q]))
                     for q, j in enumerate(Jump) if bad[q]}
            if jumps:
                out.append(Joint(before, after, float(starts[i]), jumps))
        return out

    def warnings(self, unit: str = "") -> list[str]:
        """One line for each jump in y' or y'' (the velocity or the acceleration).

        ``unit`` is the unit of the displacement y (the file's length unit, or
        ``rad`` for an oscillating follower): y' is given in unit/rad and y'' in
        unit/rad² (Sec. 6.8, Eqs. 6.2-6.3, derivatives by the cam angle).

        Examples
        --------
        >>> from graphkin.cams.motions import Motion
        >>> from graphkin.cams.program import Program, Segment
        >>> import math
        >>> p = Program((Segment(Motion.UNIFORM, 1.0, math.pi / 2),
        ...              Segment(Motion.DWELL, 0.0, math.pi / 2),
        ...              Segment(Motion.UNIFORM, -1.0, math.pi / 2),
        ...              Segment(Motion.DWELL, 0.0, math.pi / 2)))
        >>> print(p.warnings("in")[1])  # doctest: +NORMALIZE_WHITESPACE
        segment 2 (dwell): y' (velocity) jumps from 0.63662 to 0 in/rad at Θ = 90°
        (end of segment 1 (uniform rise))

        (on the uniform rise y' = L/β = 1/(π/2) = 0.63662 in/rad)
        """
        lines = []
        names = {Jump.VELOCITY: ("y'", "velocity", f" {unit}/rad" if unit else ""),
                 Jump.ACCELERATION: ("y''", "acceleration", f" {unit}/rad²" if unit else "")}
        joints = self.joints()
        size = self.scales() if joints else np.ones(3)
        for j in joints:
            for kind, (left, right) in j.jumps.items():
                if kind is Jump.DISPLACEMENT:
                    continue
                sym, word, per = names[kind]
                # what the arithmetic left of a zero (sin 2π) is written 0, never "-0"
                tiny = ROUND_OFF * float(size[1 if kind is Jump.VELOCITY else 2])
                a, b = g6(clean(left, tiny)), g6(clean(right, tiny))
                lines.append(f"{self.label(j.after)}: {sym} ({word}) jumps from {a} to {b}{per} "
                             f"at Θ = {g6(math.degrees(j.theta))}° (end of "
                             f"{self.label(j.before)})")
        return lines
