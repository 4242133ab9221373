"""The tooth force of each gear pair resolved as Sec. 11.11 resolves it: transmitted and radial.

A pair of gear teeth (a ``[[rolling]]`` contact with ``pressure_angle``)
carries one force through the pitch point along the pressure line
(:mod:`graphkin.forces.joints`).  Fig. 11.14b resolves it on each gear into
the *transmitted* force, tangent to the pitch circle, and the *radial* force,
toward the gear's center::

    F^t = T / R           (Eq. 11.12)
    F^r = F^t tan φ,      F = F^t / cos φ

:func:`tooth_forces` reads them off a solved force analysis (nothing is
assumed: the components are projections of the joint force found by the
graphic or the matrix method, and the tests hold them to the equations above
worked by hand).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.11, Fig. 11.14, Eqs. (11.12)-(11.13),
Example 11.7.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.forces.joints import SLOT, contact_point
from graphkin.forces.solve import ForceSolution
from graphkin.mechanisms.model import Rolling
from graphkin.tolerance import VERDICT_REL

__all__ = ["ToothForce", "tooth_forces", "tooth_forces_json"]


@dataclass(frozen=True)
class ToothForce:
    """The tooth force of one gear pair (Sec. 11.11).

    Attributes
    ----------
    key : str
        The ``[[rolling]]`` entry (``rolling[0]``).
    joint : str
        The force joint's key (``2-3``).
    gear : str
        The rolling gear (the entry's ``link``): the components are given on it.
    mate : str
        The gear (or rack) it meshes with (the entry's ``on``).
    point : numpy.ndarray
        The pitch point, where the force acts.
    pressure_angle : float
        φ, radians.
    force : float
        F, the size of the tooth force.
    tangential : float
        F^t, the transmitted force (a size).
    radial : float
        F^r, signed: positive toward the center of the gear it acts on (the
        teeth push the gears apart).
    torque : dict
        Link -> the moment of the tooth force on that gear about its center
        (ccw positive, force unit × length unit); a rack has none.
    radius : dict
        Link -> its pitch radius.
    """

    key: str
    joint: str
    gear: str
    mate: str
    point: np.ndarray
    pressure_angle: float
    force: float
    tangential: float
    radial: float
    torque: dict[str, float]
    radius: dict[str, float]


def _cross(a: np.ndarray, b: np.ndarray) -> float:
    return float(a[0] * b[1] - a[1] * b[0])


def tooth_forces(fs: ForceSolution) -> list[ToothForce]:
    """Every gear pair's tooth force, resolved on its rolling gear (one posture)."""
    mech = fs.mechanism
    sol = fs.solution
    out = []
    for j in fs.joints:
        r = j.source
        if j.kind != SLOT or not isinstance(r, Rolling) or r.key not in mech.pressure:
            continue
        p = np.asarray(contact_point(sol, r), dtype=float)
        c = np.asarray(sol.position(r.center, r.link), dtype=float)
        f = np.asarray(fs.forces[j.key][:2], dtype=float)
        on_gear = f if r.link == j.hi else -f                # the force ON the rolling gear
        e = (c - p) / float(np.hypot(*(c - p)))              # toward the rolling gear's center
        radial = float(on_gear @ e)
        tangential = abs(_cross(e, on_gear))
        torque = {r.link: _cross(p - c, on_gear)}
        radius = {r.link: float(r.radius)}
        if not r.on_line:
            assert r.on_center is not None and r.on_radius is not None
            o = np.asarray(sol.links[r.on].position(r.on_center), dtype=float)
            torque[r.on] = _cross(p - o, -on_gear)
            radius[r.on] = float(r.on_radius)
        tiny = VERDICT_REL * fs.scale
        clean = {k: (0.0 if abs(v) <= tiny * max(radius.values()) else v)
                 for k, v in torque.items()}
        out.append(ToothForce(r.key, j.key, r.link, r.on, p, mech.pressure[r.key],
                              float(np.hypot(*f)), 0.0 if tangential <= tiny else tangential,
                              0.0 if abs(radial) <= tiny else radial, clean, radius))
    return out


def tooth_forces_json(fs: ForceSolution) -> dict[str, Any]:
    """The ``forces.gears`` object: rolling key -> the components (docs/forces.md)."""
    return {t.key: {"joint": t.joint, "gear": t.gear, "mate": t.mate,
                    "point": t.point.tolist(),
                    "pressure_angle": math.degrees(t.pressure_angle),
                    "force": t.force, "tangential": t.tangential, "radial": t.radial,
                    "torque": dict(t.torque), "radius": dict(t.radius)}
            for t in tooth_forces(fs)}
