"""The graphic layout of a cam profile by kinematic inversion (Sec. 6.4, Figs. 6.8-6.11).

The cam is held still and the follower is drawn in its inverted postures:
turned about O2 by −Θ (against the cam's rotation).  Every station is the
same recorded list of ruler-and-compass steps (:class:`Construction`),
evaluated on an array of cam angles at once:

* translating followers (Figs. 6.8-6.10): the centerline tangent to the
  offset circle at F, the station A where it crosses the prime circle, the
  trace point T laid off ``Y`` beyond A along the centerline;
* oscillating followers (Fig. 6.11): the pivot O4 turned about O2 onto its
  station, the arm laid off at ``θ4 = θ4₀ + σY`` from it;
* the profile, "a smooth curve tangent to all the roller locations" (or to
  all the face lines): its point of tangency at each station is where the
  common normal meets the roller (or the face).  The common normal passes
  through the instant center I24 of cam and follower (Sec. 6.10, Fig. 6.27):
  at ``y'`` from O2 square to a translating follower's motion, or on the
  line of centers O2 O4 where ``ω2·I24O2 = ω4·I24O4`` for an oscillating one.

The inputs per station are read off the displacement diagram: ``Y`` and its
slope ``y'`` (the book transfers ``Y − Y0`` distances with dividers).
:mod:`graphkin.cams.analytic` computes the same profile from Eqs. (6.26)-(6.39)
with no construction step; the tests hold one to the other to 1e-9.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 6.4 (Figs. 6.8-6.11), 6.9 (Fig. 6.26,
Eq. 6.26: the face's contact at ``y'``), 6.10 (Fig. 6.27: I24).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from graphkin.cams import ops as _ops  # noqa: F401  (registers ratio_point)
from graphkin.cams.model import Cam, FollowerKind
from graphkin.cams.program import TWO_PI, Kinematics
from graphkin.construction import Construction
from graphkin.construction.protocol import Evaluation
from graphkin.construction.step import Role

__all__ = ["Layout", "layout", "stations"]

Array = np.ndarray


@dataclass
class Layout:
    """The recorded layout of a cam and its evaluation at cam angles.

    Attributes
    ----------
    cam : Cam
    construction : Construction
        The steps of one station (evaluated on arrays of stations).
    """

    cam: Cam
    construction: Construction

    def given(self, theta: Array) -> tuple[dict[str, Array], Kinematics]:
        """The inputs of the stations at cam angles Θ: the inversion angle −sΘ, Y and y'."""
        th = np.asarray(theta, dtype=float)
        k = self.cam.program.evaluate(th)
        return {"phi": -self.cam.s * th, "Y": k.Y, "y1": k.y1}, k

    def evaluate(self, theta: Array | list[float]) -> Evaluation:
        """Every step's values at the stations Θ (rad), one array per label."""
        given, _ = self.given(np.atleast_1d(np.asarray(theta, dtype=float)))
        return self.construction.evaluate(given, strict=False)

    def contact(self, theta: Array | list[float]) -> Array:
        """The profile: the contact points C at cam angles Θ, complex ``u + iv`` (cam frame)."""
        c = self.evaluate(theta)["C"]
        with np.errstate(divide="ignore", invalid="ignore"):
            return c[..., 0] / c[..., 2] + 1j * c[..., 1] / c[..., 2]


def stations(n: int) -> Array:
    """``n`` equal cam angles over one turn, from 0 (the book's stations 0, 1, 2, ...)."""
    return np.arange(n) * (TWO_PI / n)


def layout(cam: Cam) -> Layout:
    """Record the graphic layout of ``cam``'s profile (Sec. 6.4).

    Examples
    --------
    The radial flat-face follower: the contact lies ``y'`` along the face
    (Eq. 6.26), so at Θ = 0 of a cycloidal rise it is at the centerline.

    >>> from graphkin.cams.examples import example_6_6
    >>> lay = layout(example_6_6())
    >>> [s.label for s in lay.construction][:6]
    ['O2', 'k0', 'kb', 'phi', 'Y', 'y1']
    >>> c = lay.contact([0.0])[0]          # at Θ = 0: straight below the roller, R0 − Rr up
    >>> round(float(c.real), 12) + 0.0, round(float(c.imag), 12)
    (0.0, 28.0)
    """
    f = cam.follower
    cx = Construction(title=f"cam layout ({f.kind.value} follower)")
    add = cx.add
    add("point", (), ("O2",), xy=(0.0, 0.0), role=Role.GIVEN, note="the cam shaft O2")
    add("circle", ("O2",), ("k0",), radius=cam.prime, role=Role.GIVEN,
        note="the prime circle, radius R0")
    if f.kind.roller:
        add("circle", ("O2",), ("kb",), radius=cam.base, role=Role.GIVEN,
            note="the base circle, R0 − Rr")
    for name, note in (("phi", "the station's angle −Θ: the follower turned against the cam"),
                       ("Y", "the displacement Y − Y0 at the station (displacement diagram)"),
                       ("y1", "the slope y' of the displacement diagram at the station")):
        add("input", (), (name,), name=name, role=Role.GIVEN, note=note)
    if f.kind.oscillating:
        _oscillating(cam, cx)
    else:
        _translating(cam, cx)
    return Layout(cam, cx)


def _translating(cam: Cam, cx: Construction) -> None:
    f = cam.follower
    add = cx.add
    if f.offset != 0:
        add("circle", ("O2",), ("ke",), radius=abs(f.offset), role=Role.GIVEN,
            note="the offset circle, radius ε (Fig. 6.9)")
    add("rigid", ("O2", "phi"), ("F",), local_p=(0.0, 0.0), local_q=(f.offset, 0.0),
        note="the centerline's foot F on the offset circle, turned to the station")
    add("rigid", ("O2", "phi"), ("A",), local_p=(0.0, 0.0), local_q=(f.offset, cam.y0),
        note="station A: where the centerline crosses the prime circle (Fig. 6.8)")
    add("join", ("F", "A"), ("axis",), note="the follower's centerline at the station")
    add("add_along", ("A", "F", "A", "Y"), ("T",), role=Role.RESULT,
        note="the trace point T: Y − Y0 laid off outward from A along the centerline")
    add("rigid", ("O2", "phi"), ("U",), local_p=(0.0, 0.0), local_q=(cam.s, 0.0),
        note="the direction square to the follower's motion, on the side of the cam's motion")
    add("along_line", ("O2", "U", "y1"), ("I24",),
        note="I24: y' from O2 square to the motion (V = ω·O2I24, Sec. 6.10)")
    _contact(cam, cx)


def _oscillating(cam: Cam, cx: Construction) -> None:
    f = cam.follower
    add = cx.add
    add("circle", ("O2",), ("kp",), radius=float(np.hypot(*f.pivot)), role=Role.GIVEN,
        note="the circle through the pivot about O2 (Fig. 6.11)")
    add("rigid", ("O2", "phi"), ("O4",), local_p=(0.0, 0.0), local_q=tuple(f.pivot),
        note="the pivot O4 turned to the station")
    add("add_angles", ("phi", "Y"), ("th",), sign=f.rise.sign,
        note="the arm turned by the station's angle and by the follower's swing Y")
    add("add_angle", ("th",), ("th4",), offset=cam.arm0,
        note="the arm's angle θ4₀ + σY at the station")
    if f.kind is FollowerKind.OSCILLATING_ROLLER:
        add("circle", ("O4",), ("arc",), radius=f.arm,
            note="the arc of the roller's center about the pivot (Fig. 6.11)")
        add("rigid", ("O4", "th4"), ("T",), local_p=(0.0, 0.0), local_q=(f.arm, 0.0),
            role=Role.RESULT, note="the trace point T: the roller's center on the arm")
    else:
        e = -f.rise.sign * f.face_offset
        add("rigid", ("O4", "th4"), ("T",), local_p=(0.0, 0.0), local_q=(0.0, e),
            role=Role.RESULT, note="the face's point square to the arm at the pivot")
    add("ratio_point", ("O2", "O4", "y1"), ("I24",), factor=f.rise.sign * cam.s,
        note="I24 on the line of centers: ω2·I24O2 = ω4·I24O4 (Sec. 3.17)")
    _contact(cam, cx)


def _contact(cam: Cam, cx: Construction) -> None:
    f = cam.follower
    add = cx.add
    if f.kind is FollowerKind.KNIFE_EDGE:
        add("copy_point", ("T",), ("C",), role=Role.RESULT,
            note="the knife edge touches the cam at the trace point: the profile is the pitch "
                 "curve")
    elif f.kind.roller:
        add("circle", ("T",), ("roller",), radius=f.roller,
            note="the roller drawn at the station")
        add("join", ("T", "I24"), ("n",), note="the common normal through I24")
        add("along_normal", ("T", "I24"), ("C",), distance=f.roller, role=Role.RESULT,
            note="C: where the profile touches the roller, on the common normal")
    else:
        if f.kind is FollowerKind.FLAT_FACE:
            add("perpendicular", ("axis", "T"), ("face",),
                note="the face square to the centerline through T (Fig. 6.10)")
        else:
            add("line_at_angle", ("T", "th4"), ("face",),
                note="the face along the arm, through its point at the pivot")
        add("perpendicular", ("face", "I24"), ("n",),
            note="the common normal: from I24 square to the face")
        add("meet", ("face", "n"), ("C",), role=Role.RESULT,
            note="C: where the profile touches the face (Eq. 6.26: y' along it)")
