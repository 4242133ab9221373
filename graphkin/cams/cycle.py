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

__all__ = ["CamLaw", "cam_law", "swept_mechanism"]

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

    The first drive must turn every cam (the cam's link, by its angle): a
    sweep turns it, and each follower follows as a second drive by its
    :class:`CamLaw`.  The result has no cams; its other points, bodies and
    joints are ``mech``'s.

    Raises
    ------
    InputError
        One line, when a cam is not on the first drive's link.
    """
    joints: tuple[CamJoint, ...] = mech.cams
    written = joints[0].data
    assert written is not None
    first = mech.drives[0]
    for i, j in enumerate(joints):
        if j.link != first.link or first.kind != "angle":
            raise _fail(mech, f"cams[{i}].link", f"a sweep turns the first drive, which must "
                        f"be the cam's (link {j.link}) by its angle, to move the follower by "
                        "the cam's program: put the cam's [[drive]] first")
    from graphkin.cams.joint import expand
    from graphkin.mechanisms import from_dict

    data, _ = expand(copy.deepcopy(dict(written)), mech.source)
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
    drives += [{"link": j.follower, "follows": {"link": j.link}} for j in joints]
    data["drive"] = drives
    twin = from_dict(data, mech.source)
    out = list(twin.drives)
    lead = out[0]
    for k, j in enumerate(joints):
        i = len(out) - len(joints) + k
        law = cam_law(j)
        w, a = (None, None) if lead.rate is None else law.rates(lead.value, lead.rate,
                                                                  lead.rate2 or 0.0)
        out[i] = dataclasses.replace(out[i], value=law.value(lead.value), rate=w, rate2=a,
                                     law=law)
    return dataclasses.replace(twin, drives=tuple(out))
