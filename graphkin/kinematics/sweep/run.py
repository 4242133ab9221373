"""``sweep``: a mechanism solved over many drive values at once, in blocks.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 2.8 (posture), Secs. 3.4-3.6 and 4.2-4.6 (polygons), Sec. 1.10 (transmission angle).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from graphkin.kinematics.sweep.columns import _assembled_of, _columns, _valid_of
from graphkin.kinematics.sweep.drive_range import _count, _drive_values
from graphkin.kinematics.sweep.engine import _Block, _Engine, _engine
from graphkin.kinematics.sweep.extra_columns import (
    _center_columns,
    _curvature_columns,
    _transmission_columns,
)
from graphkin.kinematics.sweep.fast import fast_columns
from graphkin.kinematics.sweep.report import Sweep
from graphkin.mechanisms.cam_joint import for_sweep
from graphkin.mechanisms.model import Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

Array = np.ndarray


#: Sweeps longer than this are evaluated in blocks of this many postures: few enough that a
#: block's arrays stay in the processor's cache, many enough that the fixed cost of a replay
#: does not count (a progress callback is told after each block).
BLOCK = 8_192


def sweep(mech: Mechanism, count: int = 360, start: float | None = None,
          stop: float | None = None, *, tol: Tolerance | None = None,
          transmission: bool = False, centers: bool = False, curvature: bool = False,
          progress: Callable[[float], None] | None = None, follow: bool = False,
          turn: bool = False) -> Sweep:
    """Solve a mechanism over ``count`` values of its (first) drive, all at once.

    Parameters
    ----------
    mech : Mechanism
    count : int
        Number of postures.
    start, stop : float, optional
        The drive range, as ``--from``/``--to`` of ``graphkin sweep``: degrees
        for a revolute drive, the travel in the file's length unit for a slider.
        Defaults: from the file's drive angle through one full turn (``stop``
        excluded); for a slider, the travel over which the mechanism assembles
        around the file's position.  The drive values are
        ``start + (stop - start) k / count``, ``k = 0 .. count - 1``.
    tol : Tolerance, optional
    transmission : bool
        Add ``transmission_<P>`` columns: the transmission angle (degrees,
        0-180) at each pin found by two arcs (case 4), between the two links'
        lines to their centers (Sec. 1.10).
    centers : bool
        Add the instant centers: ``x_I<i><j>``, ``y_I<i><j>`` (empty at
        infinity) and, for a center that goes to infinity, its direction
        ``dx_I<i><j>``, ``dy_I<i><j>`` (when :mod:`graphkin.kinematics.instant_centers`
        is installed).
    curvature : bool
        Add the radius and center of curvature of every moving point's path,
        ``rho_<P>``, ``cx_<P>``, ``cy_<P>`` (Eq. 4.49), and every moving link's
        inflection pole and inflection-circle diameter, ``jx_<k>``, ``jy_<k>``,
        ``inflection_diameter_<k>`` (Sec. 4.15), and its center of
        acceleration Γ, ``gx_<k>``, ``gy_<k>`` (Sec. 4.14), when the file gives rates.
    progress : callable, optional
        Called with the fraction done, for long sweeps (evaluated in blocks of
        :data:`BLOCK` postures).
    follow : bool
        Keep the motion continuous: where the named branch of a two-way choice
        would jump (a stretched or folded posture, two centers passing each
        other), go on along the other branch, and say where in ``notes``
        (:func:`graphkin.kinematics.sweep.follow.follow`).
    turn : bool
        Sweep from 0° to 360° instead of from the file's angle, or, when the
        drive cannot turn fully, from its first limit position to the other,
        both included (``--turn``; :func:`.drive_range.turn_range`).  Not
        with ``start`` or ``stop``.

    Returns
    -------
    Sweep

    Raises
    ------
    InputError
        A count below 1, or no drive.
    AssemblyError
        The mechanism cannot be assembled at the file's posture (where the
        branches are chosen).

    Notes
    -----
    The constructions are built once per mechanism (branches chosen at the
    file's posture by the assembly hints) and evaluated on whole arrays; the
    named branches are kept through the sweep (see the module notes on
    continuity).  With several drives the first is swept and the others are
    held at the file's values (their rates, if given, apply throughout), except
    those that follow the first by a law (``follows``, ``Drive.law``): they move with
    it, value f(first) and rates f′ · ω and f″ · ω² + f′ · α (f linear, k · first + c,
    or the spline through a table, :mod:`graphkin.mechanisms.laws`).
    A cam mechanism (``[[cams]]``) is swept with each follower as such a drive,
    moved by its cam's program (:func:`graphkin.mechanisms.cam_joint.for_sweep`,
    Sec. 6.3): the returned sweep's ``mechanism`` is that one.
    Mechanisms that cannot be solved one group at a time are solved by
    :func:`graphkin.kinematics.analytic.solve_analytic_many` (Newton-Raphson,
    each posture from the one before), and ``method`` and ``notes`` say so.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (posture), Secs. 3.4-3.6 and
    4.2-4.6 (polygons), Sec. 1.10 (transmission angle).

    Examples
    --------
    A crank-rocker (crank 4, coupler 12, rocker 11, frame 10) through one turn
    of its crank at 10 rad/s:

    >>> import graphkin
    >>> mech = graphkin.examples.crank_rocker()
    >>> sw = sweep(mech, count=3600, start=0)
    >>> sw.columns["omega_3"].shape
    (3600,)
    >>> round(float(sw.columns["angle_4"][0]), 4)  # 180° - acos((100² + 300² - 250²)/(2·100·300))
    128.6822
    """
    mech = for_sweep(mech)  # a cam's follower moves by the cam's program (Sec. 6.3)
    if turn:
        from graphkin.kinematics.sweep.drive_range import turn_range

        start, stop = turn_range(_engine(mech, tol or DEFAULT_TOL), _count(count, mech),
                                 start, stop)
    if follow:
        from graphkin.kinematics.sweep.follow import follow as _follow

        return _follow(mech, count, start, stop, tol=tol, transmission=transmission,
                       centers=centers, curvature=curvature)
    count = _count(count, mech)
    tol = tol or DEFAULT_TOL
    return _run(mech, _engine(mech, tol), count, start, stop, transmission=transmission,
                centers=centers, curvature=curvature, progress=progress)


def _run(mech: Mechanism, eng: _Engine, count: int, start: float | None, stop: float | None,
         *, transmission: bool = False, centers: bool = False, curvature: bool = False,
         progress: Callable[[float], None] | None = None) -> Sweep:
    """The sweep of :func:`sweep` by a given engine (its constructions and branches)."""
    user, dv, cyclic = _drive_values(eng, count, start, stop)
    blocks: list[_Block] = []
    released = False
    # the transmission angles read the replayed constructions: then there is no gain in
    # writing the columns out first
    written = not transmission
    fast = fast_columns(eng, dv, user) if count <= BLOCK and written else None
    if fast is not None:
        # every posture clean: the constructions' values are replayed only if asked for
        cols = fast
        valid, assembled = np.ones(count, dtype=bool), np.ones(count, dtype=bool)
        blocks.append(_Block(dv, None, None, None, user=user))
        released = True
    elif count <= BLOCK:
        blk = eng.solve(dv)
        blk.user = user
        blocks.append(blk)
        cols = _columns(eng, blk)
        valid, assembled = _valid_of(blk), _assembled_of(blk)
    else:
        # blocks small enough to stay in the cache, written straight into the columns; the
        # constructions' values are let go after each block (and replayed if asked for again:
        # Sweep.solution, singular postures, extra columns), so the next block reuses the memory
        cols = {}
        valid = np.empty(count, dtype=bool)
        assembled = np.empty(count, dtype=bool)
        for i in range(0, count, BLOCK):
            part = fast_columns(eng, dv[i:i + BLOCK], user[i:i + BLOCK]) if written else None
            if part is not None:
                blk = _Block(dv[i:i + BLOCK], None, None, None, user=user[i:i + BLOCK])
            else:
                blk = eng.solve(dv[i:i + BLOCK])
                blk.user = user[i:i + BLOCK]
                part = _columns(eng, blk)
            if not cols:
                cols = {k: np.empty(count) for k in part}
            for k, v in part.items():
                cols[k][i:i + BLOCK] = v
            if blk.ev is None and blk.analytic is None:  # written out: every posture clean
                valid[i:i + BLOCK] = True
                assembled[i:i + BLOCK] = True
                released = True
            else:
                valid[i:i + BLOCK] = _valid_of(blk)
                assembled[i:i + BLOCK] = _assembled_of(blk)
            if blk.analytic is None:
                blk = _Block(blk.dv, None, None, None, user=blk.user)
                released = True
            blocks.append(blk)
            if progress is not None:
                progress(min(1.0, (i + BLOCK) / count))
    notes: list[str] = []
    if eng.built_at is not None:
        notes.append(f"the file's drive cannot be assembled; the constructions were laid out "
                     f"at {math.degrees(eng.built_at):.2f}° (branches by the assembly hints there)")
    if eng.method == "analytic":
        notes.append("solved by the analytic solver (Newton-Raphson, each posture from the one "
                     f"before): {eng.reason}")
    if not valid.all():
        _blank(cols, assembled, valid)
    sw = Sweep(mech, eng.drive, dv, cols, valid, assembled, eng.method, notes,
               dict(eng.pc.branches) if eng.pc is not None else {}, eng, blocks, cyclic,
               released)
    if transmission:
        sw.columns.update(_transmission_columns(sw))
    if centers:
        sw.columns.update(_center_columns(sw))
    if curvature:
        sw.columns.update(_curvature_columns(sw))
    return sw


def _blank(cols: dict[str, Array], assembled: Array, valid: Array) -> None:
    """NaN where a posture cannot be assembled (every column but the drive)."""
    for k, c in cols.items():
        if k == "drive":
            continue
        c = np.array(c, dtype=float)
        c[~assembled] = np.nan
        c[~np.isfinite(c)] = np.nan
        if k[:2] in ("vx", "vy", "ax", "ay") or k.startswith(("omega_", "alpha_")):
            c[~valid] = np.nan
        cols[k] = c
