"""Velocities and accelerations by one linear solve each (Secs. 3.9 and 4.9)."""

from __future__ import annotations

import numpy as np

from graphkin.errors import ConstructionError
from graphkin.kinematics.analytic.constraints import _F
from graphkin.kinematics.analytic.newton import _drive_text
from graphkin.kinematics.analytic.system import _System
from graphkin.kinematics.solution import LinkState, Solution
from graphkin.tolerance import Tolerance


def _check_regular(eqs: _System, q: np.ndarray, values: np.ndarray) -> None:
    """Raise ConstructionError at a singular (toggle, dead-center) posture."""
    _, J = eqs.scaled(q, values)
    if not eqs.n:
        return
    sv = np.linalg.svd(J, compute_uv=False)
    if sv.size < eqs.n or sv[-1] <= _singular_threshold(eqs.tol) * sv[0]:
        what = ", ".join(_drive_text(d, v) for d, v in zip(eqs.mech.drives, values))
        raise ConstructionError(
            f"the posture at {what} is singular (a toggle or dead-center posture: the "
            "Jacobian of the loop-closure equations is rank deficient)",
            key="drive", file=eqs.mech.source)


def _singular_threshold(tol: Tolerance) -> float:
    # a double root found to machine precision leaves σ_min ~ √ε ~ 1e-8; a
    # regular posture this close to a toggle is a singular one for a drawing
    return 100.0 * tol.angle

# ---------------------------------------------------------------------------
# Rates
# ---------------------------------------------------------------------------


def _rates(eqs: _System, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """q̇ and q̈ at a posture (Secs. 3.9 and 4.9)."""
    A, b = eqs.velocity_system(q)
    # dimensionless rows and columns, as for the posture, to judge the rank
    rows = np.concatenate([eqs.row_scale[:eqs.ncons],
                           [1.0 if g.kinds[0] == "A" else 1.0 / eqs.size
                            for g in eqs.rate_functions or []]])
    sv = np.linalg.svd(A * rows[:, None] * eqs.col_scale[None, :], compute_uv=False)
    if A.shape[0] != eqs.n or sv[-1] <= _singular_threshold(eqs.tol) * sv[0]:
        r = eqs.mech.rates
        who = f"the given rate of link {r.link}" if r is not None else "the drive rates"
        raise ConstructionError(f"{who} cannot fix the velocities at this posture (the "
                                "velocity equations are singular)", key="rates",
                                file=eqs.mech.source)
    qd = np.linalg.solve(A, b)
    qdd = np.linalg.solve(A, eqs.acceleration_rhs(q, qd))
    return qd, qdd

# ---------------------------------------------------------------------------
# Building the Solution
# ---------------------------------------------------------------------------


def _solution(eqs: _System, q: np.ndarray, qd: np.ndarray | None, qdd: np.ndarray | None,
              valid: np.ndarray, notes: list[str]) -> Solution:
    """A Solution from stacked coordinates of shape (n,) or (N, n)."""
    lead = q.shape[:-1]
    links: dict[str, LinkState] = {}
    for lid in eqs.mech.links:
        k = eqs.index[lid]
        if k == _F:
            zero = np.zeros(lead)
            zero2 = np.zeros((*lead, 2))
            rated = qd is not None
            links[lid] = LinkState(zero.copy(), zero2.copy(),
                                   zero.copy() if rated else None,
                                   zero.copy() if rated else None,
                                   zero2.copy() if rated else None,
                                   zero2.copy() if rated else None)
            continue
        sl = slice(3 * k, 3 * k + 2)
        th = 3 * k + 2
        links[lid] = LinkState(
            np.array(q[..., th]), np.array(q[..., sl]),
            None if qd is None else np.array(qd[..., th]),
            None if qdd is None else np.array(qdd[..., th]),
            None if qd is None else np.array(qd[..., sl]),
            None if qdd is None else np.array(qdd[..., sl]))
    return Solution(mechanism=eqs.mech, links=links, method="analytic", valid=valid,
                    notes=notes)
