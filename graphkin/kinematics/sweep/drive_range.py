"""The drive range of a sweep and the drive values where the mechanism stops assembling.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.10 (dead-center postures), Sec. 2.8 (posture).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from graphkin.errors import AssemblyError, InputError
from graphkin.kinematics.sweep.columns import _assembled_of
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.mechanisms.model import Mechanism
from graphkin.tolerance import VERDICT_REL

Array = np.ndarray


def _count(count: object, mech: Mechanism) -> int:
    """The number of postures asked for, as an int (a one-line error otherwise)."""
    if mech.cams:  # a sweep replaces them first (for_sweep): what is left takes designs
        raise InputError("a batch of designs of a cam mechanism is not supported (sweep, plot "
                         "and animate turn its cam)", key="cams", file=mech.source)
    try:
        ok = int(count) == count and int(count) >= 1  # type: ignore[call-overload]
    except (TypeError, ValueError):
        ok = False
    if not ok:
        raise InputError(f"the number of postures must be a whole number of at least 1, not "
                         f"{count!r}", key="count", file=mech.source)
    return int(count)  # type: ignore[call-overload]


def _drive_values(eng: _Engine, count: int, start: float | None,
                  stop: float | None) -> tuple[Array, Array, bool]:
    """The drive values as written (degrees or travel), in internal units, and one turn or not.

    ``start + (stop - start) k / count``, ``k = 0 .. count - 1``.
    """
    for name, v in (("start", start), ("stop", stop)):
        if v is not None and not (isinstance(v, (int, float)) and math.isfinite(v)):
            raise InputError(f"the drive range must be finite numbers, not {name} = {v!r}",
                             key=f"--{'from' if name == 'start' else 'to'}",
                             file=eng.mech.source)
    a, b, cyclic = _drive_range(eng, start, stop)
    a, b, cyclic = _within_tables(eng, start, stop, a, b, cyclic, count)
    _resolvable(eng, a, b, count, "--to" if stop is not None else "--from")
    # (b - a) k is exact for whole numbers, so 0 to 360 in 360 steps gives 48.0, not
    # 48.00000000000001
    user = a + ((b - a) * np.arange(count, dtype=float)) / count
    places = _decimals(a, b, count)
    if places is not None:  # 0.1 to 0.4 in 3 steps: 0.3, not 0.30000000000000004
        user = np.round(user, places) + 0.0  # + 0.0: no -0.0
    return user, (np.radians(user) if eng.drive.is_angle else user), cyclic


def _within_tables(eng: _Engine, start: float | None, stop: float | None, a: float, b: float,
                   cyclic: bool, count: int) -> tuple[float, float, bool]:
    """The range within the rows of a table law that does not cover a whole turn.

    By default such a sweep runs over the table's rows (first to last); a
    ``--from`` or ``--to`` outside them is refused naming the table.
    """
    f = 180.0 / math.pi if eng.drive.is_angle else 1.0
    for d in eng.mech.drives:
        dom = None if d.law is None else d.law.domain
        if dom is None:
            continue
        lo, hi = round(dom[0] * f, 10), round(dom[1] * f, 10)
        a = lo if start is None else a
        b = hi if stop is None else b
        cyclic = False
        last = a + (b - a) * (count - 1) / count  # the end itself is not swept
        for v, opt in ((a, "--from"), (last, "--to")):
            if not lo - 1e-9 * max(1.0, abs(lo)) <= v <= hi + 1e-9 * max(1.0, abs(hi)):
                raise InputError(f"{d.key}.follows.table covers the first drive from {lo:g} "
                                 f"to {hi:g} only, not {v:g}", key=opt, file=eng.mech.source)
    return a, b, cyclic


def _decimals(a: float, b: float, count: int) -> int | None:
    """The decimals of the drive values when ``a`` and the step are short decimals.

    ``--from 0.1 --to 0.4 --count 3`` steps by 0.1: every value has one decimal,
    and rounding to it gives the float nearest the decimal the user means.  None
    when a value needs more than 12 decimals (a step of 1/7, a limit position).
    """
    from fractions import Fraction

    try:
        fa, fb = Fraction(repr(float(a))), Fraction(repr(float(b)))
    except (ValueError, OverflowError):
        return None
    step = (fb - fa) / count
    for places in range(13):
        scale = 10**places
        if (fa * scale).denominator == 1 and (step * scale).denominator == 1:
            big = max(abs(fa), abs(fb)) * scale
            return places if big < 2**52 else None
    return None


#: The largest drive value a sweep takes: degrees, or a travel in sizes of the mechanism.
MAX_DRIVE = 1e9


def _resolvable(eng: _Engine, a: float, b: float, count: int, narrow: str = "--to") -> None:
    """Refuse a range whose postures the floats cannot tell apart (``--from 1e17``).

    Near 1e17 the spacing of floats is 16, so steps of a degree land on the
    same or wrong values; the drive values must stay within :data:`MAX_DRIVE`
    (degrees, or sizes of the mechanism for a slider) and each step must be
    far above the rounding of the values.
    """
    d = eng.drive
    unit = 1.0 if d.is_angle else eng.mech.scale
    what = "degrees" if d.is_angle else f"{eng.mech.length_unit} of travel"
    far = max(abs(a), abs(b))
    if far > MAX_DRIVE * unit:
        key = "--from" if abs(a) > MAX_DRIVE * unit else narrow
        raise InputError(f"a drive value of {far:g} {what} is beyond the ±{MAX_DRIVE * unit:g} "
                         "a sweep takes", key=key, file=eng.mech.source)
    if count > 1 and abs(b - a) / count <= 1e-9 * max(far, unit * 1e-6):
        raise InputError(f"the range {a:g} to {b:g} is too narrow for {count} postures (steps "
                         f"of {abs(b - a) / count:.3g} {what})", key=narrow,
                         file=eng.mech.source)


def _drive_range(eng: _Engine, start: float | None, stop: float | None) -> tuple[float, float,
                                                                                 bool]:
    """Start and stop as the user writes them (degrees or travel), and whether it is one turn."""
    d = eng.drive
    if d.is_angle:
        # the file's angle as written (degrees), free of the round trip through radians
        a = round(math.degrees(d.value), 10) if start is None else float(start)
        b = a + 360.0 if stop is None else float(stop)
        return a, b, math.isclose(abs(b - a), 360.0, rel_tol=1e-12)
    if start is not None and stop is not None:
        return float(start), float(stop), False
    # the search depends only on the mechanism: found once, for every later sweep of it
    key = ("travel", d.value)
    travel = eng.extras.get(key)
    if travel is None:
        travel = eng.extras[key] = _travel(eng)
    lo, hi = travel
    return (lo if start is None else float(start)), (hi if stop is None else float(stop)), False


def _travel(eng: _Engine) -> tuple[float, float]:
    """The travel of a slider drive over which the mechanism assembles, around the file's value.

    Searched outward up to four times the size of the mechanism, then
    refined by bisection.
    """
    d, mech = eng.drive, eng.mech
    reach = 4.0 * mech.scale
    ok = _assembles(eng)
    ends: list[float] = []
    good: list[float] = []
    bad: list[float] = []
    for sign in (-1.0, 1.0):
        xs = d.value + sign * reach * np.linspace(0.0, 1.0, 401)
        fine = ok(xs)
        if not fine[0]:
            raise AssemblyError(f"cannot assemble at the file's travel {d.value:g}",
                                key="drive", file=mech.source)
        where = np.flatnonzero(~fine)
        if where.size == 0:
            ends.append(float(xs[-1]))
            continue
        k = int(where[0])
        good.append(float(xs[k - 1]))
        bad.append(float(xs[k]))
    if good:
        # both ends at once; the analytic solver continues every call from the file's
        # posture, so it gets few calls of many postures instead of 48 halvings
        if eng.method == "analytic":  # one bracket per call: each call is a continuation
            lo = np.array([_narrow(ok, np.array([g]), np.array([b]))[0]
                           for g, b in zip(good, bad, strict=True)])
        else:
            lo, _ = _bisect(ok, np.array(good), np.array(bad))
        limits = [_clean_end(ok, float(x), mech.scale) for x in lo]
        ends += limits
        # the limit positions (dead centers, Sec. 1.10), not the ends of the search: at a
        # drive value within round-off of one the rates are not determined (_Engine.at_limit)
        eng.extras[("limits", d.value)] = limits
    return min(ends), max(ends)


def _clean_end(ok: Callable[[Array], Array], x: float, scale: float) -> float:
    """An end of the travel written cleanly: ``-60`` rather than ``-59.9999999999266``.

    The end found by bisection lies within round-off of the limit position; the
    nearest value with six significant digits of the mechanism's size is taken
    when it is within round-off of it (1e-9 of the size, ``VERDICT_REL``) and
    still assembles: a limit at 188.94443627691183 stays there, it is not
    188.9444.
    """
    q = 10.0 ** (math.floor(math.log10(scale)) - 6) if scale > 0 else 0.0
    if not q:
        return x
    r = round(x / q) * q
    r = float(f"{r:.12g}")
    if r == x or abs(r - x) > VERDICT_REL * scale or not bool(ok(np.array([r]))[0]):
        return x
    return r


def _assembles(eng: _Engine) -> Callable[[Array], Array]:
    """Drive values (internal units) -> whether the posture assembles there."""
    if eng.method == "analytic":
        def ok_analytic(x: Array) -> Array:
            blk = eng.solve(np.atleast_1d(np.asarray(x, dtype=float)))
            return _assembled_of(blk)
        return ok_analytic

    def ok(x: Array) -> Array:
        x = np.atleast_1d(np.asarray(x, dtype=float))
        ev = eng.posture(x)
        return np.broadcast_to(np.asarray(ev.valid), x.shape).copy()

    return ok


def _narrow(ok: Callable[[Array], Array], good: Array, bad: Array, parts: int = 40,
            rounds: int = 6) -> Array:
    """Like :func:`_bisect` in a few calls: each cuts every bracket into ``parts``.

    Six rounds of 40 leave 2.4e-10 of the first bracket (one call per round).
    """
    good, bad = good.astype(float).copy(), bad.astype(float).copy()
    t = np.linspace(0.0, 1.0, parts + 1)[1:-1]
    for _ in range(rounds):
        grid = good[:, None] + (bad - good)[:, None] * t[None, :]
        fine = np.asarray(ok(grid.ravel())).reshape(grid.shape)
        # the first posture that fails in each bracket (the brackets stay ordered)
        first = np.where(fine.all(axis=1), parts - 1, np.argmin(fine, axis=1))
        idx = np.arange(len(good))
        new_bad = np.where(fine.all(axis=1), bad, grid[idx, np.minimum(first, parts - 2)])
        new_good = np.where(first == 0, good, grid[idx, np.maximum(first - 1, 0)])
        good, bad = new_good, new_bad
    return good


def _bisect(ok: Callable[[Array], Array], good: Array, bad: Array,
            steps: int = 48) -> tuple[Array, Array]:
    """Narrow pairs (good, bad) of drive values around the boundaries of ``ok``."""
    good, bad = good.astype(float).copy(), bad.astype(float).copy()
    for _ in range(steps):
        mid = 0.5 * (good + bad)
        m = ok(mid)
        good = np.where(m, mid, good)
        bad = np.where(m, bad, mid)
    return good, bad


def turn_range(eng: _Engine, count: int, start: float | None, stop: float | None
               ) -> tuple[float, float]:
    """``--turn``: the drive from 0° to 360°, or from one limit position to the other.

    A drive that turns fully is swept over one turn from 0° (not from the
    file's angle, the contract's default).  One that cannot -- a rocker, or a
    crank whose mechanism does not assemble over part of the turn -- is swept
    over the arc around the file's angle where it assembles, from its first
    limit position to the other, **both included** (the last posture is the
    second limit, Sec. 1.7).

    Returns
    -------
    start, stop : float
        Degrees, as ``--from``/``--to`` (``stop`` excluded, so that with a
        limited range the last posture lands on the second limit).

    Raises
    ------
    InputError
        With ``--from`` or ``--to``, or a drive that is not an angle.
    """
    d, mech = eng.drive, eng.mech
    if start is not None or stop is not None:
        raise InputError("--turn sets the range: leave out --from and --to", key="--turn",
                         file=mech.source)
    if not d.is_angle:
        raise InputError(f"--turn sweeps an angle; {d.label} is a travel, swept over the range "
                         "where it assembles by default", key="--turn", file=mech.source)
    for x in mech.drives:  # a table law over part of a turn: its rows are the whole motion
        dom = None if x.law is None else x.law.domain
        if dom is not None:
            lo, hi = round(math.degrees(dom[0]), 10), round(math.degrees(dom[1]), 10)
            return lo, (hi if count < 2 else lo + (hi - lo) * count / (count - 1))
    ok = _assembles(eng)
    x0 = math.radians(round(math.degrees(d.value), 10))
    xs = x0 + np.linspace(0.0, 2.0 * math.pi, 721)[:-1]  # once round, x0 + 2π is x0
    fine = np.asarray(ok(xs), dtype=bool)
    if fine.all():
        return 0.0, 360.0
    if not fine[0]:
        raise AssemblyError("cannot assemble at the file's drive angle", key="drive",
                            file=mech.source)
    bad = np.flatnonzero(~fine)
    kf, kb = int(bad[0]), int(bad[-1])
    after = xs[kb + 1] if kb + 1 < len(xs) else xs[0] + 2.0 * math.pi
    good = np.array([xs[kf - 1], after - 2.0 * math.pi])
    out = np.array([xs[kf], xs[kb] - 2.0 * math.pi])
    if eng.method == "analytic":
        ends = np.array([_narrow(ok, good[i:i + 1], out[i:i + 1])[0] for i in range(2)])
    else:
        ends, _ = _bisect(ok, good, out)
    hi, lo = (float(math.degrees(v)) for v in ends)
    # a hair inside the limits found (far below the tangency tolerance, ~1e-7°), so that the
    # round-off of the drive values cannot step past them
    lo, hi = lo + 1e-9, hi - 1e-9
    if count < 2:
        return lo, hi
    return lo, lo + (hi - lo) * count / (count - 1)
