"""The analytic solution at many drive values: :func:`solve_analytic_many`."""

from __future__ import annotations

import math

import numpy as np

from graphkin.errors import AssemblyError, ConstructionError
from graphkin.kinematics.analytic.constraints import _wrap
from graphkin.kinematics.analytic.newton import _RESTARTS, Guess, _converge, _Search
from graphkin.kinematics.analytic.posture import _guess_vector
from graphkin.kinematics.analytic.rates import _check_regular, _rates, _solution
from graphkin.kinematics.analytic.system import _System
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["solve_analytic_many"]

#: Iteration limit when continuing from the previous posture of a sweep.
_SWEEP_ITER = 60

#: Restarts at the later postures of a sweep whose first postures do not assemble.
_SWEEP_RESTARTS = 6

#: Largest drive step (rad, and fraction of the size) when a sweep of a mechanism
#: with rolling contact is continued from the file's posture to its first value.
_MARCH_ANGLE = math.radians(2.0)

_MARCH_LENGTH = 0.02


def solve_analytic_many(mech: Mechanism, drive_values: np.ndarray,
                        start: Solution | Guess | None = None, *,
                        tol: Tolerance | None = None) -> Solution:
    """Solve a mechanism at many drive values, each posture continuing the one before.

    Parameters
    ----------
    mech : Mechanism
        The mechanism; its drives' rates (or ``[rates]``) apply at every posture.
    drive_values : ndarray, shape (N, n_drives) or (N,)
        Drive values in file order: angles in radians, slider travels in the
        file's length unit.
    start : Solution or dict, optional
        Where the first posture starts (a solved posture, or link id ->
        ``(x, y, θ)``).  Default: the posture :func:`solve_analytic` chooses
        at the first drive value (nearest the assembly hints).  With rolling
        contact: a posture at the file's own drive values (the reference of
        the no-slip condition, see Notes); default the one
        :func:`solve_analytic` chooses there.
    tol : Tolerance, optional
        As for :func:`solve_analytic`.

    Returns
    -------
    Solution
        Arrays of leading shape ``(N,)``.  Postures that cannot be assembled
        (or are singular) are NaN, and False in ``valid``.

    Raises
    ------
    AssemblyError
        With rolling contact only: the file's own posture, the reference of
        the no-slip condition, cannot be assembled.

    See Also
    --------
    solve_analytic : one posture.

    Notes
    -----
    Branch continuity: each posture starts from the previous valid one,
    advanced by the first-order kinematic coefficients ``dq/dd = -Φ_q⁻¹ Φ_d``
    (Sec. 3.11) times the change of the drive.  A Python loop over postures:
    this is the oracle, not the fast path.

    Rolling contact (``[[rolling]]``): the file gives the rolling link's
    angle only at the file's own drive values, so over a sweep the posture
    row of each contact is the integrated no-slip condition (Sec. 2.19)

        ``(θ_l - θ_o) - (θ_l - θ_o)_ref = -σ (s - s_ref) / ρ``,

    ``s`` the travel of the circle's center along the line in ``on``'s
    coordinates, ``σ = +1`` for a circle on the left of the line, and
    ``ref`` the posture at the file's drive values (rolling links at their
    file angles, as :func:`solve_analytic` finds it).  On a circle it is

        ``(θ_l - θ_o) - (θ_l - θ_o)_ref = ±(R ± r)/r · (φ - φ_ref)``

    (``+(R + r)/r`` outside, ``-(R - r)/r`` inside), ``φ`` the angle of the
    line of centers in ``on``'s axes, counted continuously from posture to
    posture (the ratio need not be an integer, so ``φ`` is not taken modulo
    2π).  The sweep continues
    that posture to the first drive value in steps of at most 2° (or 2 % of
    the mechanism's size), then on as above; the rates are the same as
    :func:`solve_analytic`'s.  After a gap that cannot be assembled the
    search picks the posture nearest the hints among those that satisfy the
    integrated condition.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 2.9, 2.19, 3.9, 3.11, 4.9.
    """
    tol = tol or DEFAULT_TOL
    eqs = _System(mech, tol)
    dv = np.asarray(drive_values, dtype=float)
    if dv.ndim == 1:
        dv = dv[:, None]
    if dv.ndim != 2 or dv.shape[1] != len(mech.drives):
        raise ValueError(f"drive_values must have shape (N, {len(mech.drives)}), "
                         f"not {np.shape(drive_values)}")
    N = dv.shape[0]
    Q = np.full((N, eqs.n), np.nan)
    rated = eqs.rate_functions is not None
    QD = np.full((N, eqs.n), np.nan) if rated else None
    QDD = np.full((N, eqs.n), np.nan) if rated else None
    valid = np.zeros(N, dtype=bool)
    prev: np.ndarray | None = None
    prev_values: np.ndarray | None = None
    prev_index = -2
    if mech.rolling and N:
        # the integrated no-slip condition through the file's posture, reached from
        # there by continuation (a search could find the circle rolled elsewhere)
        ref = _reference_posture(eqs, start)
        eqs = eqs.integrated(ref)
        prev = _march(eqs, ref, eqs.values, dv[0])
    elif start is not None:
        prev = _guess_vector(eqs, start, dv[0] if N else eqs.values)
    search = _Search(eqs)
    for i in range(N):
        values = dv[i]
        if prev is None:
            # the first posture gets the full search; while none assembles, fewer restarts
            try:
                q0 = search.solve(values, _RESTARTS if i == 0 else _SWEEP_RESTARTS,
                                  explain=False)
            except AssemblyError:
                continue
        else:
            q0 = prev
            if prev_values is not None and prev_index == i - 1:  # a step, not a gap
                q0 = prev + _sensitivity(eqs, prev, prev_values) @ _delta(eqs, values,
                                                                          prev_values)
        q = _converge(eqs, q0, values, _SWEEP_ITER)
        if q is None and prev is not None and q0 is not prev:
            q = _converge(eqs, prev, values, _SWEEP_ITER)
        if q is None:
            continue
        try:
            _check_regular(eqs, q, values)
            if rated:
                qd, qdd = _rates(eqs, q)
                assert QD is not None and QDD is not None
                QD[i], QDD[i] = qd, qdd
        except ConstructionError:
            continue
        Q[i] = q
        valid[i] = True
        prev, prev_values, prev_index = q, values, i
        eqs.follow(q)
    notes = ["analytic: Newton-Raphson, each posture from the one before"]
    return _solution(eqs, Q, QD, QDD, valid, notes)


def _reference_posture(eqs: _System, start: Solution | Guess | None) -> np.ndarray:
    """The posture at the file's drive values (rolling links at their file angles).

    From ``start`` when given and Newton converges from it, else the posture
    :func:`solve_analytic` chooses.  ``eqs`` has the file-angle rolling rows.
    """
    values = eqs.values
    if start is not None:
        q = _converge(eqs, _guess_vector(eqs, start, values), values)
        if q is not None:
            return q
    return _Search(eqs).solve(values)


def _march(eqs: _System, q: np.ndarray, v_from: np.ndarray,
           v_to: np.ndarray) -> np.ndarray | None:
    """Continue posture ``q`` at drive ``v_from`` to ``v_to`` in small steps (None: lost)."""
    d = _delta(eqs, v_to, v_from)
    steps = 1
    for i, drv in enumerate(eqs.mech.drives):
        unit = _MARCH_ANGLE if drv.kind == "angle" else _MARCH_LENGTH * eqs.size
        steps = max(steps, math.ceil(abs(float(d[i])) / unit))
    here = np.array(v_from, dtype=float)
    for k in range(1, steps + 1):
        there = v_from + d * (k / steps)
        q_new = _converge(eqs, q + _sensitivity(eqs, q, here) @ (there - here), there,
                          _SWEEP_ITER)
        if q_new is None:
            return None
        q, here = q_new, there
        eqs.follow(q)
    return q


def _delta(eqs: _System, values: np.ndarray, before: np.ndarray) -> np.ndarray:
    d = values - before
    for i, drv in enumerate(eqs.mech.drives):
        if drv.kind == "angle":
            d[i] = _wrap(float(d[i]))
    return d


def _sensitivity(eqs: _System, q: np.ndarray, values: np.ndarray) -> np.ndarray:
    """``dq/dd``: the first-order kinematic coefficients (Sec. 3.11), shape (n, n_drives)."""
    _, J = eqs.residual(q, values)
    assert J is not None
    rhs = np.zeros((eqs.m, len(eqs.drives)))
    rhs[eqs.ncons:, :] = np.eye(len(eqs.drives))
    try:
        return np.linalg.solve(J, rhs)
    except np.linalg.LinAlgError:
        return np.zeros((eqs.n, len(eqs.drives)))
