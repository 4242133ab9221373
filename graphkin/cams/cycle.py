"""A cam mechanism over the cycle: its follower driven by the cam's program (``sweep``, ``plot``).

The equivalent linkage through the centers of curvature (Sec. 4.7,
:mod:`graphkin.cams.joint`) holds at one cam angle only: its coupler's
length and its pins move along the cam's surface as the cam turns.  Over a
sweep the follower's motion is instead known in closed form: it is the
program's, the displacement diagram's ``Y(Θ)`` and its derivatives (Secs.
6.3, 6.7-6.8),

    position ``Y``,   velocity ``y' Θ̇``,   acceleration ``y'' Θ̇² + y' Θ̈``   (Eqs. 6.1-6.3)

evaluated on a whole array of cam angles at once.  So for a sweep the cam's
contact is replaced by a **second drive that follows the first by a law**
(``follows``, :mod:`graphkin.mechanisms.laws`): the follower's travel along
its guide (a translating follower) or its arm's angle about its pivot (an
oscillating one) is the program's, ``f(θ2)``, with ``f'`` and ``f''`` the
program's ``y'`` and ``y''`` (chain rule through Θ = s(θ2 − (axis − 90°))).
The rest of the mechanism -- links driven off the follower -- is then
swept by the constructions as with any coupled input.

A cam whose link the first drive does not turn itself follows its link: a
second drive's law (or its held value), or the angle the linkage gives the
link (a four-bar's rocker, :mod:`graphkin.cams.linkage`), its kinematic
coefficients θ', θ'' with respect to the swept input evaluated on the whole
array of drive values (:class:`LinkCamLaw`, the chain rule).

The swept mechanism keeps every point, body and joint of the file's but the
equivalent linkage's own: no coupler ``K-T``, no center of curvature
``K<f>`` on the cam and no slot ``F<f>a-F<f>b`` of a flat face (they stand
for the contact at the file's angle only).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.7, 6.3 (Eqs. 6.1-6.3), 6.9-6.10.
"""

from __future__ import annotations

import copy
import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.cams.joint import CamJoint
from graphkin.cams.model import Cam
from graphkin.errors import InputError
from graphkin.mechanisms.laws import Law
from graphkin.mechanisms.model import Mechanism

__all__ = ["CamLaw", "LinkCamLaw", "cam_law", "swept_mechanism"]

Array = np.ndarray


@dataclass(frozen=True, eq=False)
class CamLaw(Law):
    """The follower's drive as a function of the cam link's angle θ2 (rad): the cam's program.

    ``f(θ2) = base + gain · Y(Θ)``, Θ = s (θ2 − shift), so ``f' = gain · s · y'(Θ)``
    and ``f'' = gain · y''(Θ)`` (s² = 1).

    Attributes
    ----------
    cam : Cam
        The cam (its program in its own length unit).
    shift : float
        ``axis − 90°`` (rad): the cam file's frame turned into the mechanism's.
    gain : float
        Mechanism length units per cam-file unit (a translating follower), or
        σ, the arm's sense of rise (an oscillating follower: +1 counterclockwise).
    base : float
        The drive's value at zero lift: the trace point's travel ``y0`` from
        the guide's first point (scaled), or the arm's angle θ4 (rad).
    """

    cam: Cam | None = field(default=None, repr=False)
    shift: float = 0.0
    gain: float = 1.0
    base: float = 0.0

    @property
    def linear(self) -> bool:
        """Never: the follower's rates change with the posture."""
        return False

    @property
    def domain(self) -> tuple[float, float] | None:
        """None: the program covers every cam angle (it repeats every turn)."""
        return None

    def _eval(self, x: Any, order: int) -> Any:
        assert self.cam is not None
        scalar = np.ndim(x) == 0
        xa = np.asarray(x, dtype=float)
        k = self.cam.program.evaluate(self.cam.s * (xa.ravel() - self.shift))
        if order == 0:
            out = self.base + self.gain * k.Y
        elif order == 1:
            out = self.gain * self.cam.s * k.y1
        else:
            out = self.gain * k.y2
        out = np.asarray(out, dtype=float).reshape(xa.shape)
        return float(out) if scalar else out


@dataclass(frozen=True, eq=False)
class LinkCamLaw(CamLaw):
    """A cam on a link the linkage moves: its program at the link's angle θ(x) (Secs. 3.11, 6.3).

    ``f(x) = base + gain · Y(Θ)``, ``Θ = s (θ(x) − shift)``, ``x`` the first
    drive's value; by the chain rule ``f' = gain · s · y' θ'`` and
    ``f'' = gain · (y'' θ'² + s y' θ'')`` (s² = 1), where θ, θ' and θ'' are the
    link's angle and kinematic coefficients in the linkage without the cams
    (:func:`graphkin.cams.linkage.link_turning`, on whole arrays of ``x``).
    """

    turning: Any = field(default=None, repr=False)

    def _eval(self, x: Any, order: int) -> Any:
        assert self.cam is not None and self.turning is not None
        scalar = np.ndim(x) == 0
        xa = np.asarray(x, dtype=float).ravel()
        th, th1, th2 = self.turning(xa)
        k = self.cam.program.evaluate(self.cam.s * (np.asarray(th) - self.shift))
        if order == 0:
            out = self.base + self.gain * k.Y
        elif order == 1:
            out = self.gain * self.cam.s * k.y1 * th1
        else:
            out = self.gain * (k.y2 * th1 * th1 + self.cam.s * k.y1 * th2)
        out = np.asarray(out, dtype=float).reshape(np.shape(x))
        return float(out) if scalar else out


def cam_law(joint: CamJoint) -> CamLaw:
    """The law of ``joint``'s follower over the cycle (see :class:`CamLaw`).

    Examples
    --------
    Ex 6.6 (Y = 15(1 − cos 2Θ) mm, prime circle 40 mm, radial roller) with its
    follower rising up (axis 90°): at θ2 = 30° the roller's center stands
    40 + 7.5 mm above O2, rising at y' = 30 sin 60° = 25.981 mm/rad.

    >>> from graphkin.mechanisms import from_dict
    >>> m = from_dict({"links": {"1": {"O2": [0, 0]}},
    ...     "cams": {"link": 2, "follower": 4, "file": "examples/cams/ex6_6_roller.toml"},
    ...     "drive": {"link": 2, "angle": 30}})
    >>> law = cam_law(m.cams[0])
    >>> import math
    >>> round(law.value(math.radians(30)), 6), round(law.slope(math.radians(30)), 3)
    (47.5, 25.981)
    """
    cam = joint.cam
    shift = joint.axis - math.pi / 2
    if cam.follower.kind.oscillating:
        return CamLaw(cam=cam, shift=shift, gain=float(cam.follower.rise.sign),
                      base=cam.arm0 + shift)
    return CamLaw(cam=cam, shift=shift, gain=joint.scale, base=cam.y0 * joint.scale)


def _fail(mech: Mechanism, key: str, message: str) -> InputError:
    return InputError(message, key=key, file=mech.source)


def swept_mechanism(mech: Mechanism) -> Mechanism:
    """``mech``'s cams replaced by their followers driven by the cams' programs, for a sweep.

    A sweep turns the first drive, and each follower follows as a second
    drive by its :class:`CamLaw`: of the first drive's angle when the cam is
    on its link, else of the cam link's angle as its own drive or the linkage
    moves it (:class:`LinkCamLaw`).  The result has no cams; its other points,
    bodies and joints are ``mech``'s.

    Raises
    ------
    InputError
        One line naming ``cams[i].link``, when the linkage without the cams'
        followers does not move the cam's link from the first drive.
    """
    joints: tuple[CamJoint, ...] = mech.cams
    written = joints[0].data
    assert written is not None
    first = mech.drives[0]
    if mech.has_rates and (mech.rolling or mech.rates is not None):
        # the analytic solver that sweeps these takes each drive's rates as constants
        raise _fail(mech, "cams", "a cam mechanism with rolling contact or [rates] is swept "
                    "without its rates only (its followers' rates change with the posture, "
                    "which the solver of rolling contact takes as constants): leave out the "
                    "drive's omega and alpha to sweep its posture")
    from graphkin.cams.joint import expand
    from graphkin.mechanisms import from_dict

    data, _ = expand(copy.deepcopy(dict(written)), mech.source)
    moved = [i for i, j in enumerate(joints) if j.link != first.link or first.kind != "angle"]
    # a cam its link's own drive does not turn with the sweep: its link's angle the linkage's
    # (a cam on an earlier cam's oscillating follower turns with that follower's law)
    by_follower = {j.follower: i for i, j in enumerate(joints)}
    chained = {i: by_follower[joints[i].link] for i in moved
               if by_follower.get(joints[i].link, i) < i
               and joints[by_follower[joints[i].link]].cam.follower.kind.oscillating}
    turning = {i: _turning(mech, data, i) for i in moved if i not in chained}
    links = data["links"]
    for j in joints:
        fl = j.follower
        if j.coupler:
            links.pop(j.coupler, None)
        links[j.link].pop(f"K{fl}", None)
        for n in (f"F{fl}a", f"F{fl}b"):
            links[fl].pop(n, None)
        for n in (f"K{fl}", f"F{fl}a"):
            data["assembly"].pop(n, None)
        if "slots" in data:
            data["slots"] = [s for s in data["slots"] if s.get("point") != f"K{fl}"]
            if not data["slots"]:
                del data["slots"]
    raw = data["drive"]
    drives = [dict(raw)] if isinstance(raw, Mapping) else [dict(d) for d in raw]
    drives += [{"link": j.follower, "follows": {"link": drives[0].get("link")}}
               for j in joints]
    data["drive"] = drives
    twin = from_dict(data, mech.source)
    out = list(twin.drives)
    lead = out[0]
    laws: list[CamLaw] = []
    for k, j in enumerate(joints):
        i = len(out) - len(joints) + k
        law = cam_law(j)
        if k in chained:        # the link's angle is the earlier follower's: its law's
            prev = laws[chained[k]]
            turning[k] = lambda x, p=prev: (p.value(x), p.slope(x), p.curve(x))
        if k in turning:
            law = LinkCamLaw(cam=law.cam, shift=law.shift, gain=law.gain, base=law.base,
                             turning=turning[k])
        laws.append(law)
        w, a = (None, None) if lead.rate is None else law.rates(lead.value, lead.rate,
                                                                  lead.rate2 or 0.0)
        out[i] = dataclasses.replace(out[i], value=law.value(lead.value), rate=w, rate2=a,
                                     law=law)
    return dataclasses.replace(twin, drives=tuple(out))


def _turning(mech: Mechanism, data: Mapping[str, Any], i: int) -> Any:
    """θ(x), θ'(x), θ''(x) of cam ``i``'s link, moved by the linkage as the first drive turns.

    The linkage is ``data`` (the file, its cams' equivalent linkages in it)
    without every follower's side (:mod:`graphkin.cams.linkage`), its first
    drive at unit speed.  One line naming ``cams[i].link`` where it does not
    place the cam's link.
    """
    from graphkin.cams.linkage import driving_data, follower_side, link_turning
    from graphkin.errors import GraphkinError
    from graphkin.mechanisms import from_dict

    joints = mech.cams
    j = joints[i]
    key = f"cams[{i}].link"
    own = next((d for d in mech.drives if d.link == j.link and d.kind == "angle"), None)
    if own is not None:     # another drive's link: held, or following the first by its law
        law, value = own.law, own.value
        if law is None:
            return lambda x: (np.full(np.shape(x), value), np.zeros(np.shape(x)),
                              np.zeros(np.shape(x)))
        return lambda x: (law.value(x), law.slope(x), law.curve(x))
    if j.link in {x.follower for x in joints}:
        raise _fail(mech, key, f"a sweep turns the first drive; the cam's link {j.link} is "
                    "a translating follower or a later cam's: a cam on it is swept not yet")
    side = follower_side(data, [x.follower for x in joints], [x.link for x in joints])
    side |= {x.coupler for x in joints if x.coupler}
    first = driving_data(data, side)
    raw = data.get("drive")
    lead = raw if isinstance(raw, Mapping) else raw[0] if isinstance(raw, list) and raw else {}
    drives = first.get("drive", [])
    if j.link in side or j.link not in first["links"] or not drives or \
            drives[0].get("link") != lead.get("link"):
        raise _fail(mech, key, f"a sweep turns the first drive; the cam's link {j.link} is not "
                    "its link, and the linkage does not move it from the first drive without "
                    "the cams' followers (a cam driven through another cam's follower is swept "
                    "not yet)")
    rate = "omega" if "angle" in drives[0] else "velocity"
    drives[0] = {**drives[0], rate: 1.0, ("alpha" if rate == "omega" else "acceleration"): 0.0}
    center = next(n for n, xy in mech.links["1"].points.items()
                  if tuple(map(float, xy)) == tuple(map(float, j.center))
                  and n in mech.links[j.link].points)
    try:
        return link_turning(from_dict(first, mech.source), j.link, center)
    except GraphkinError as exc:
        raise _fail(mech, key, f"a sweep moves the cam's link {j.link} by the linkage without "
                    f"the cams, which does not place it: {exc}") from None

