"""The drive's torque over a whole cycle: the force construction replayed on a sweep.

The force construction is built once, at the file's posture (the order of
two- and three-force members is a property of the mechanism, not of the
posture), and evaluated on the arrays of a sweep: the pin positions, the
sliders' directions, the accelerations of the centers of mass and the angular
accelerations of every posture at once, with no loop over postures.  This is
the input-torque curve a designer sizes a motor with.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 12.5 (superposition), Sec. 12.8
(the forces over a cycle of the input angle).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.forces.batch import tilt_many
from graphkin.forces.joints import geometry, joints_of
from graphkin.forces.solve import solve_forces

__all__ = ["force_columns"]


def force_columns(sw: Any, joints: bool = False) -> dict[str, np.ndarray]:
    """CSV columns of a sweep: each drive's torque (``torque_2``) or force (``force_4``).

    Parameters
    ----------
    sw : Sweep
        A sweep of a mechanism with loads or mass properties.
    joints : bool
        Also the magnitude of every joint force (``F_3-4``).

    Returns
    -------
    dict
        Column name -> array of length N (NaN where the posture does not assemble
        or cannot be held: a dead center for these loads, a self-locking posture).

    Raises
    ------
    InputError
        The file has no loads and no mass properties, or the graphic method
        finds no order for it (the matrix method is not swept).
    """
    mech = sw.mechanism
    if not mech.has_forces:
        raise InputError("no forces to sweep: the file has no [[loads]] and no [inertia.N]",
                         key="loads", file=mech.source)
    try:
        fs = solve_forces(mech.solve())
    except InputError:
        if not mech.friction:
            raise
        # the file's own posture is self-locking, or its slider at rest with no impending
        # sense: the construction's order is that of the frictionless mechanism, and the
        # rough joints' lines are leant at every posture below (NaN where they cannot be)
        fs = solve_forces(dataclasses.replace(mech, friction={}).solve())
    if fs.built is None:
        raise InputError("the drive's torque is swept by the graphic construction, which "
                         "finds no order for this mechanism", key="loads", file=mech.source)
    sol = sw.solution
    jts = joints_of(mech)
    geo = geometry(sol, jts)
    n = len(sw)
    # the rough joints' and gear teeth's lines of action lean as at one posture (solve does
    # it there): their senses are found at every posture by the stacked matrix method
    rough_ok = tilt_many(sol, jts, geo, fs.dynamic, n) if (mech.friction or mech.pressure) \
        else np.ones(n, dtype=bool)
    given: dict[str, np.ndarray] = {}
    for name, xy in geo.points.items():
        xy = np.broadcast_to(np.asarray(xy, dtype=float), (n, 2))
        given[name] = np.concatenate([xy, np.ones((n, 1))], axis=-1)
    for key, v in geo.normal.items():
        given[f"n_{key}"] = np.broadcast_to(v, (n, 2))
    for key, v in geo.along.items():
        given[f"u_{key}"] = np.broadcast_to(v, (n, 2))
    if fs.dynamic:
        for lid, inr in mech.inertia.items():
            given[f"A_{inr.center}"] = np.broadcast_to(
                np.asarray(sol.acceleration(inr.center, lid), dtype=float), (n, 2))
            given[f"α{lid}"] = np.broadcast_to(np.asarray(sol.alpha(lid), dtype=float), (n,))
    ev = fs.built.construction.replay(given, strict=False)
    ok = np.asarray(ev.valid, dtype=bool) & np.asarray(sw.assembled, dtype=bool) & rough_ok
    out: dict[str, np.ndarray] = {}
    for d in mech.drives:
        label = fs.built.drives[d.link]
        col = np.array(np.broadcast_to(ev.values[label], (n,)), dtype=float)
        col[~ok] = np.nan
        out[("torque_" if d.kind == "angle" else "force_") + d.link] = col
    if joints:
        for key, label in fs.built.forces.items():
            w = np.broadcast_to(ev.values[label], (n, 3))
            col = np.hypot(w[:, 0], w[:, 1])
            col[~ok] = np.nan
            out[f"F_{key}"] = col
    return out
