"""A cam of a mechanism file turned to any angle: its program and center of curvature as steps.

The equivalent linkage of a ``[[cams]]`` joint (Sec. 4.7,
:mod:`graphkin.cams.joint`) holds at one cam angle: its pin ``K<f>`` on the
cam is the pitch curve's center of curvature there and its coupler ``|ρ|``
long.  At another angle Θ the linkage is another one, with the cam's own
numbers: this module writes, for a knife-edge or roller follower
(translating or oscillating) and a flat face (either), the two
construction steps that give them from the cam link's angle θ2
(:mod:`graphkin.construction.ops.cam_program`):

* ``cam_program``: Θ, the lift ``Y`` and ``y'``, ``y''`` (Secs. 6.3-6.8);
* ``cam_center``: ``K<f>`` in the cam link's coordinates, ``|ρ|``, the trace
  point ``T<f>`` and the contact point in the mechanism's frame, and the
  pitch curve's signed radius of curvature (Secs. 6.9-6.10).

Both operations' templates are written out as Python and as JavaScript (the
live page turns the cam with them, :mod:`graphkin.render.live_cams`); the
check is :func:`graphkin.cams.analytic.profile` and
:func:`graphkin.cams.equivalent.equivalent_linkage`, which share no code with
them.

An oscillating flat face turns too: ``cam_center`` then gives the center of
curvature of the *profile* (the face's envelope) and, in place of ``|ρ|``, the
offset ``y`` of the slot in the follower's own coordinates (Example 4.7).

A table of displacements (``motion = "table"``) is its natural cubic spline,
one ``poly`` row of ``cam_program`` per interval between its points.

A translating flat face turns too: ``cam_center`` gives the profile's center
of curvature and the slot's offset ``−ρ`` along the follower's guide (Eq. 6.27).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.7, 6.3-6.10 (Eqs. 6.12-6.25, 6.37).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.cams.joint import CamJoint
from graphkin.cams.model import Cam, FollowerKind
from graphkin.cams.motions import _P8, Motion, Rest, piece_rows
from graphkin.cams.program import Segment
from graphkin.construction.step import Step

__all__ = ["NotTurned", "TurnSteps", "turn_steps", "program_params"]


class NotTurned(Exception):
    """The cam cannot be turned by the steps here (the message says why, in the user's words)."""


@dataclass(frozen=True)
class TurnSteps:
    """The steps that turn one cam, and the labels of what they make.

    Attributes
    ----------
    steps : list of Step
        ``input`` θ2, ``cam_program``, ``cam_center``.
    theta, lift, center, length, trace, contact, rho : str
        The labels of Θ, Y, ``K<f>`` (cam link's coordinates), ``|ρ|``,
        ``T<f>`` and the contact point (mechanism frame) and the pitch curve's ρ.
    """

    steps: list[Step]
    theta: str
    lift: str
    center: str
    length: str
    trace: str
    contact: str
    rho: str


_HALF = {Motion.HALF_HARMONIC: "half_harmonic", Motion.HALF_CYCLOIDAL: "half_cycloidal"}
_PLAIN = {Motion.DWELL: "dwell", Motion.UNIFORM: "uniform", Motion.PARABOLIC: "parabolic",
          Motion.HARMONIC: "harmonic", Motion.CYCLOIDAL: "cycloidal"}


def _poly8_return() -> list[float]:
    """Eq. (6.17): the rise run backward, ``1 − f(1 − u)``, as coefficients of u⁰ … u⁸."""
    back = np.polynomial.Polynomial(_P8)(np.polynomial.Polynomial([1.0, -1.0]))
    return [float(c) for c in (1.0 - back).coef]


def _table_rows(seg: Segment, start: float) -> list[tuple[Any, ...]]:
    """A table's natural cubic spline as one ``poly`` row per interval between its points.

    On each interval the spline is a cubic in the interval's own ``u``; it is the
    Hermite cubic of its ends' values and slopes (``f(0)``, ``f(1)``, ``f'(0)``,
    ``f'(1)`` of :func:`graphkin.cams.motions.table_shape`, the slopes times the
    interval's share of the segment), exactly.
    """
    assert seg.table is not None
    f, y0, h = seg.unit_shape()
    x = np.asarray(seg.table[0], dtype=float) / float(seg.table[0][-1])
    rows: list[tuple[Any, ...]] = []
    for a, b in zip(x[:-1], x[1:]):
        w = float(b - a)
        v, d, _, _ = f(np.array([a, b]))
        f0, f1, s0, s1 = float(v[0]), float(v[1]), float(d[0]) * w, float(d[1]) * w
        # Hermite: p(u) = f0 + s0 u + (3(f1 − f0) − 2s0 − s1) u² + (2(f0 − f1) + s0 + s1) u³
        coef = (f0, s0, 3 * (f1 - f0) - 2 * s0 - s1, 2 * (f0 - f1) + s0 + s1)
        rows.append(("poly", start + float(a) * seg.angle, w * seg.angle, float(y0), float(h),
                     coef))
    return rows


def program_params(cam: Cam, shift: float) -> dict[str, Any]:
    """The ``cam_program`` step's params for ``cam`` (``shift``: θ2 at Θ = 0, rad).

    Raises
    ------
    NotTurned
        A segment whose motion has no expression in the operation.
    """
    prog = cam.program
    starts, bases = prog.starts, prog.bases
    rows: list[tuple[Any, ...]] = []
    for k, seg in enumerate(prog.segments):
        coef: list[float] = []
        if seg.motion in _PLAIN:
            kind = _PLAIN[seg.motion]
        elif seg.motion in _HALF:
            kind = _HALF[seg.motion] + ("_end" if seg.rest is Rest.END else "_start")
        elif seg.motion is Motion.POLYNOMIAL8:
            kind, coef = "poly", (list(map(float, _P8)) if seg.lift >= 0 else _poly8_return())
        elif seg.motion is Motion.POLYNOMIAL345:
            kind, coef = "poly", [0.0, 0.0, 0.0, 10.0, -15.0, 6.0]
        elif seg.motion is Motion.MODIFIED_TRAPEZOID:
            kind, coef = "pieces", [v for row in piece_rows(seg.motion) for v in row]
        elif seg.motion is Motion.TABLE and seg.table is not None:
            rows += _table_rows(seg, float(starts[k]))
            continue
        else:
            raise NotTurned(f"{prog.label(k)}: the live page has no expression of the "
                            f"{seg.motion.value} motion")
        rows.append((kind, float(starts[k]), float(seg.angle), float(bases[k]),
                     float(seg.lift), tuple(coef)))
    return {"s": float(cam.s), "shift": float(shift), "segments": tuple(rows)}


def turn_steps(joint: CamJoint, drive: str) -> TurnSteps:
    """The steps that turn ``joint``'s cam from the drive's angle ``drive`` (its label, θ2).

    Raises
    ------
    NotTurned
        A motion with no expression here.

    Examples
    --------
    Ex 6.6's cam at Θ = 30° (Eq. 6.37: |ρ| = 72.757 mm, the coupler of its linkage):

    >>> import math
    >>> from graphkin.construction.codegen import generate
    >>> from graphkin.mechanisms import from_dict
    >>> m = from_dict({"links": {"1": {"O2": [0, 0]}},
    ...     "cams": {"link": 2, "follower": 4, "file": "examples/cams/ex6_6_roller.toml"},
    ...     "drive": {"link": 2, "angle": 30}})
    >>> t = turn_steps(m.cams[0], "θ2")
    >>> fn = generate(t.steps, varying=["θ2"], requests=[(t.length, "value")])
    >>> import numpy as np
    >>> round(float(fn.fn(np.array([math.radians(30)]))[0][0]), 3)
    72.757
    """
    cam = joint.cam
    f = cam.follower
    shift = joint.axis - math.pi / 2
    fl = joint.follower
    names = [f"Θ{fl}", f"Y{fl}", f"y'{fl}", f"y''{fl}"]
    out = [f"K{fl}", f"|ρ|{fl}", f"T{fl}", f"C{fl}", f"ρ{fl}"]
    size = cam.prime + abs(cam.program.lift) + math.hypot(*f.pivot) + f.arm
    center: dict[str, Any] = {
        "s": float(cam.s), "scale": float(joint.scale), "size": float(size),
        "roller": float(f.roller) if f.kind.roller else 0.0,
        "rot": (math.cos(shift), math.sin(shift)), "o2": tuple(map(float, joint.center))}
    if f.kind is FollowerKind.FLAT_FACE:
        center.update(follower="translating_flat", offset=float(f.offset), y0=float(cam.y0))
    elif f.kind is FollowerKind.OSCILLATING_FLAT_FACE:
        center.update(follower="oscillating_flat", sig=float(f.rise.sign),
                      arm0=float(cam.arm0), pivot=tuple(map(float, f.pivot)),
                      face_offset=float(f.face_offset))
    elif f.kind.oscillating:
        center.update(follower="oscillating", sig=float(f.rise.sign), arm=float(f.arm),
                      arm0=float(cam.arm0), pivot=tuple(map(float, f.pivot)))
    else:
        center.update(follower="translating", offset=float(f.offset), y0=float(cam.y0))
    steps = [Step(0, drive, "input", (), (drive,), {"name": drive}),
             Step(1, names[0], "cam_program", (drive,), tuple(names),
                  program_params(cam, shift)),
             Step(2, out[0], "cam_center", tuple(names), tuple(out), center)]
    return TurnSteps(steps, names[0], names[1], out[0], out[1], out[2], out[3], out[4])
