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

Array = np.ndarray


def _count(count: object, mech: Mechanism) -> int:
    """The number of postures asked for, as an int (a one-line error otherwise)."""
    if mech.cams:  # its equivalent linkage holds at the file's cam angle only (Sec. 4.7)
        raise InputError("a cam mechanism is solved at the file's cam angle (its equivalent "
                         "linkage, Sec. 4.7): sweeping it is not supported yet (change "
                         "[drive] angle, or graphkin cam for the follower's motion)",
                         key="cams", file=mech.source)
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
    _resolvable(eng, a, b, count, "--to" if stop is not None else "--from")
    # (b - a) k is exact for whole numbers, so 0 to 360 in 360 steps gives 48.0, not
    # 48.00000000000001
    user = a + ((b - a) * np.arange(count, dtype=float)) / count
    return user, (np.radians(user) if eng.drive.is_angle else user), cyclic


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
    out = []
    for sign in (-1.0, 1.0):
        xs = d.value + sign * reach * np.linspace(0.0, 1.0, 401)
        good = ok(xs)
        if not good[0]:
            raise AssemblyError(f"cannot assemble at the file's travel {d.value:g}",
                                key="drive", file=mech.source)
        bad = np.flatnonzero(~good)
        if bad.size == 0:
            out.append(float(xs[-1]))
            continue
        k = int(bad[0])
        lo, hi = _bisect(ok, np.array([xs[k - 1]]), np.array([xs[k]]))
        out.append(float(lo[0]))
    return min(out), max(out)


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
