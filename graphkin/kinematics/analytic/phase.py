"""Where each rolling contact stands at the file's drive: the link it places (Sec. 2.19).

Rolling without slip is a velocity condition (Eq. 3.13); integrated, it is
``(θ_l - θ_o) + σ s/ρ = c`` on a line or ``(θ_l - θ_o) - k φ = c`` on a
circle (:mod:`graphkin.kinematics.analytic.rolling`), with a constant ``c``
that no equation gives: two gears mesh at any relative angle.  At the file's
drive the file fixes it by placing one link of the mechanism, exactly as a
drive places its link:

* the rolling link, when nothing else fixes its angle (a wheel on the
  ground, a planet on its arm);
* else the link it rolls on (a driven pinion turns the gear it meshes with);
* else the first other link whose angle the drives leave open (the arm of a
  planet that meshes with a driven sun and a fixed ring);
* else the travel of a slider the drives leave open (a rack sliding under a
  driven pinion), as drawn: with its own origin at the origin of the link it
  slides on.

A link placed by its angle stands at the contact's ``angle`` (default 0: its
own axes as written, the link as drawn).

"What else fixes" is decided by rank: the Jacobian of every joint and drive
(without the no-slip rows), at a generic configuration, plus the row of the
candidate coordinate; the candidate is open when the rank grows.  The
singular values of a generic configuration are either of the order of one
(the system is scaled to the mechanism's size) or of round-off, so the test
sits far from both.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.19 (the rolling constraint),
Sec. 3.7 (rolling contact), Example 3.9 (a wheel rolling on the ground).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.errors import InputError
from graphkin.mechanisms.model import FRAME, Mechanism, Slider

__all__ = ["Phase", "rolling_phases"]

#: A singular value below this fraction of the largest counts as zero (generic configuration:
#: the others are of the order of one, round-off of the order of 1e-15).
_RANK_GAP = 1e-8

#: Seed of the generic configuration (deterministic).
_SEED = 7919


@dataclass(frozen=True)
class Phase:
    """The coordinate a rolling contact fixes at the file's drive.

    Attributes
    ----------
    key : str
        The rolling contact (``rolling[0]``).
    link : str
        The link it places.
    kind : str
        ``"angle"`` (the link's angle θ, rad) or ``"travel"`` (the travel of
        ``slider``'s point along its line).
    value : float
        The angle (rad) or the travel at the file's drive.
    slider : Slider or None
        For a travel.
    """

    key: str
    link: str
    kind: str
    value: float
    slider: Slider | None = None

    def describe(self, given: bool) -> str:
        """The phase in words (for a note); ``given``: the file wrote the contact's angle."""
        if self.kind == "angle":
            return (f"{self.key}: at the file's drive the contact places link {self.link} at "
                    f"θ{self.link} = {math.degrees(self.value):.6g}°"
                    + ("" if given else " (as drawn)"))
        return (f"{self.key}: at the file's drive the contact places the slider {self.link} "
                f"as drawn (travel {self.value:.6g})")


def _travel_drawn(mech: Mechanism, s: Slider) -> float:
    """The travel of the slider's point with its link's origin at ``on``'s origin.

    The slider's x axis runs along its line (its angle relative to ``on`` is the
    line's direction), so its point ``p`` is at ``R(φ) p`` in ``on``'s axes.
    """
    p = mech.links[s.link].points[s.point]
    phi = s.direction_angle
    c, sn = math.cos(phi), math.sin(phi)
    px, py = c * p[0] - sn * p[1], sn * p[0] + c * p[1]
    return c * (px - s.p0[0]) + sn * (py - s.p0[1])


def rolling_phases(mech: Mechanism) -> tuple[Phase, ...]:
    """The coordinate each rolling contact fixes at the file's drive (module docstring).

    Parameters
    ----------
    mech : Mechanism

    Returns
    -------
    tuple of Phase
        One per rolling contact, in the file's order.
    """
    if not mech.rolling:
        return ()
    from graphkin.kinematics.analytic.constraints import _OnLine
    from graphkin.kinematics.analytic.rolling import _Rolling, _RollingCircle
    from graphkin.kinematics.analytic.system import _System, _unit
    from graphkin.tolerance import DEFAULT_TOL

    eqs = _System(mech, DEFAULT_TOL, [0.0] * len(mech.rolling))
    rng = np.random.default_rng(_SEED)
    q = np.empty(eqs.n)
    q[0::3] = eqs.size * rng.uniform(-1.0, 1.0, eqs.nlinks)
    q[1::3] = eqs.size * rng.uniform(-1.0, 1.0, eqs.nlinks)
    q[2::3] = rng.uniform(-math.pi, math.pi, eqs.nlinks)
    _, J = eqs.scaled(q, eqs.values)
    keep: list[int] = []
    row = 0
    for c in eqs.cons:
        if not isinstance(c, (_Rolling, _RollingCircle)):
            keep.extend(range(row, row + len(c.kinds)))
        row += len(c.kinds)
    keep.extend(range(eqs.ncons, eqs.m))
    base = J[keep]

    def rank(a: np.ndarray) -> int:
        if a.size == 0:
            return 0
        sv = np.linalg.svd(a, compute_uv=False)
        return int(np.sum(sv > _RANK_GAP * max(float(sv[0]), 1.0)))

    from graphkin.kinematics.analytic.constraints import _Poses

    st = _Poses(q, eqs.nlinks)

    def angle_row(lid: str) -> np.ndarray:
        r = np.zeros(eqs.n)
        r[3 * eqs.index[lid] + 2] = 1.0
        return r

    def travel_row(s: Slider) -> np.ndarray:
        u, _ = _unit(s.p0, s.p1)
        tmp = np.zeros((1, eqs.n))
        _OnLine(eqs.index[s.link], mech.links[s.link].points[s.point], eqs.index[s.on],
                s.p0, u, "").eval(st, tmp, 0)
        return tmp[0] * eqs.col_scale / eqs.size

    out: list[Phase] = []
    have = rank(base)
    for r in mech.rolling:
        cands: list[tuple[str, str, Slider | None]] = []
        for lid in (r.link, r.on):
            if lid != FRAME:
                cands.append(("angle", lid, None))
        cands += [("travel", s.link, s) for s in mech.sliders if s.link in (r.link, r.on)]
        cands += [("angle", lid, None) for lid in mech.moving if lid not in (r.link, r.on)]
        cands += [("travel", s.link, s) for s in mech.sliders if s.link not in (r.link, r.on)]
        chosen: Phase | None = None
        for kind, lid, s in cands:
            cand = angle_row(lid) if s is None else travel_row(s)
            trial = np.vstack([base, cand[None, :]])
            if rank(trial) > have:
                base, have = trial, have + 1
                if kind == "angle":
                    chosen = Phase(r.key, lid, "angle", float(r.angle))
                else:
                    assert s is not None
                    if r.angle_given:
                        raise InputError(f"this contact places the slider {lid} by its travel "
                                         "along its line, not by an angle: leave angle out and "
                                         "draw the slider where it stands at the file's drive "
                                         "(its origin on that of the link it slides on)",
                                         key=f"{r.key}.angle", file=mech.source)
                    chosen = Phase(r.key, lid, "travel", _travel_drawn(mech, s), s)
                break
        # nothing left open (the joints already hold every coordinate): the rolling link's
        # angle, as before; the count of constraints then says what is wrong
        out.append(chosen or Phase(r.key, r.link, "angle", float(r.angle)))
    return tuple(out)
