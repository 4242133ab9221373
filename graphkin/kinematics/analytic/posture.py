"""The analytic solution at the file's posture: :func:`solve_analytic`."""

from __future__ import annotations

import numpy as np

from graphkin.errors import AssemblyError
from graphkin.kinematics.analytic.newton import Guess, _converge, _drive_text, _Search
from graphkin.kinematics.analytic.rates import _check_regular, _rates, _solution
from graphkin.kinematics.analytic.system import _System
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["solve_analytic"]


def _guess_vector(eqs: _System, guess: Guess | Solution, values: np.ndarray) -> np.ndarray:
    if isinstance(guess, Solution):
        g: dict[str, tuple[float, float, float]] = {}
        for lid in eqs.ids:
            s = guess.links[lid]
            ang = np.asarray(s.angle, dtype=float).reshape(-1)
            org = np.asarray(s.origin, dtype=float).reshape(-1, 2)
            i = 0
            if ang.size > 1:
                ok = np.flatnonzero(np.asarray(guess.valid).reshape(-1))
                i = int(ok[-1]) if ok.size else 0
            g[lid] = (float(org[i, 0]), float(org[i, 1]), float(ang[i]))
        guess = g
    return _Search(eqs).heuristic(values, None, fixed=guess)


def _drive_values(mech: Mechanism) -> np.ndarray:
    return np.array([d.value for d in mech.drives], dtype=float)


def solve_analytic(mech: Mechanism, *, guess: Guess | Solution | None = None,
                   tol: Tolerance | None = None) -> Solution:
    """Solve a mechanism at its posture by Newton-Raphson on the loop-closure equations.

    Parameters
    ----------
    mech : Mechanism
        The mechanism, as read from a mechanism file.
    guess : dict or Solution, optional
        Link id -> ``(x, y, θ)``: the start of the iteration (origin of the
        link's local frame and its angle, rad), or a solved posture of the
        same mechanism.  Newton's method then stays on
        the branch of the guess.  Without a guess the solver starts from the
        assembly hints (``[assembly]``), the frame and the drives, plus
        deterministic pseudo-random restarts, and returns the converged posture
        whose points are nearest the hints (without hints: nearest the file's
        own layout, every link as written).
    tol : Tolerance, optional
        Convergence and singularity tolerances (default
        :data:`~graphkin.tolerance.DEFAULT_TOL`).

    Returns
    -------
    Solution
        ``method="analytic"``; a :class:`LinkState` for every link, the frame
        included.  Rates are present when the file gives them (a missing
        second rate means zero).

    Raises
    ------
    AssemblyError
        No posture satisfies the constraints at the given drive.
    ConstructionError
        The posture is singular (a toggle posture: the Jacobian is rank
        deficient), or the given rates cannot fix the velocities there.

    See Also
    --------
    solve_analytic_many : the same over many drive values, with branch continuity.

    Notes
    -----
    Rolling contact (``[[rolling]]``): the circle's center runs on the line
    offset by the radius, or on the circle of radius ``R + r`` (outside) or
    ``R - r`` (inside) about the center of ``on``'s circle (the equivalent
    slot; none when one link already holds both centers), and at the file's
    drive the rolling link stands at the file's ``angle`` (absolute).  The
    rates obey no slip and its derivative (Eq. 3.13 and 4.19): on a line
    ``ω_l - ω_o = -σ ṡ/ρ`` (``ṡ`` the center's apparent speed along the line
    seen from ``on``, ``σ = +1`` for a circle on the left of the line); on a
    circle ``ω_l - ω_o = (R + r)/r · φ̇`` (outside) or ``-(R - r)/r · φ̇``
    (inside), ``φ`` the angle of the line of centers in ``on``'s axes.  The
    singularity check uses these rows.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.7 (loop-closure equations),
    Secs. 2.9-2.11 (algebraic posture analysis), Sec. 2.19 (rolling
    constraint), Sec. 3.7 (rolling contact), Sec. 3.9 (algebraic velocity
    analysis), Sec. 4.9 (algebraic acceleration analysis), Sec. 4.5
    (Coriolis), Sec. 4.7 (rolling contact acceleration).

    Examples
    --------
    Example 3.1 of the textbook: crank 4 in at 120°, 900 rev/min.

    >>> import graphkin
    >>> mech = graphkin.examples.fourbar()
    >>> sol = solve_analytic(mech)
    >>> import math
    >>> round(math.degrees(float(sol.angle_rad("3"))), 4), round(float(sol.omega("4")), 3)
    (20.9187, 49.501)
    """
    tol = tol or DEFAULT_TOL
    eqs = _System(mech, tol)
    values = _drive_values(mech)
    if guess is not None:
        q = _converge(eqs, _guess_vector(eqs, guess, values), values)
        if q is None:
            raise AssemblyError(
                "cannot assemble the mechanism at "
                + ", ".join(_drive_text(d, v) for d, v in zip(mech.drives, values))
                + ": Newton's method does not converge from the given guess",
                key="drive", file=mech.source)
        notes = ["analytic: Newton-Raphson from the given guess"]
    else:
        q = _Search(eqs).solve(values)
        notes = ["analytic: Newton-Raphson from the assembly hints, nearest posture chosen"]
    # rolling contact: from here on the no-slip rows (the true constraint Jacobian)
    eqs = eqs.integrated(q)
    _check_regular(eqs, q, values)
    qd = qdd = None
    if eqs.rate_functions is not None:
        qd, qdd = _rates(eqs, q)
    return _solution(eqs, q, qd, qdd, np.array(True), notes)
