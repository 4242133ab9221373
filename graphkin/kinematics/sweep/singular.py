"""The special postures a sweep meets: ranges that cannot assemble, dead centers, limits.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.10 (toggle and dead-center postures).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from graphkin.construction import Construction
from graphkin.kinematics.polygons import build_polygons
from graphkin.kinematics.sweep.columns import wrap_degrees
from graphkin.kinematics.sweep.drive_range import _assembles, _bisect
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import DEFAULT_TOL

if TYPE_CHECKING:
    from graphkin.kinematics.sweep.report import Sweep

Array = np.ndarray


@dataclass(frozen=True)
class SingularPosture:
    """A special posture met by a sweep, located to the drive value.

    Attributes
    ----------
    kind : str
        ``"cannot-assemble"`` (a range: ``drive`` to ``end``), ``"dead-center"``
        (the two branches of ``label`` meet: the arcs are tangent, the
        transmission angle is 0° or 180°), or ``"limit"`` (a link pinned to the
        frame stops and turns back: ``ω = 0``; for a crank-rocker driven by its
        crank this is the toggle posture of Sec. 1.10, crank and coupler in line).
    drive : float
        The drive value (degrees, or the slider's travel).
    end : float or None
        The end of a range.
    label : str
        The construction step (``"C"``) or the link (``"4"``).
    note : str
        One line for the report.
    change_point : bool
        A dead center inside an assembled range: the branches touch without a
        gap, and beyond it the named branch need not be the continuous motion.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.10 (toggle and dead-center postures).
    """

    kind: str
    drive: float
    end: float | None
    label: str
    note: str
    change_point: bool = False


def _fmt(eng: _Engine, v: float) -> str:
    """A drive value as the reports write it: an angle in [0, 360), or a slider's travel.

    The sweep runs on past 360° from the file's angle; the notes say the
    angle as the rest of the output does.
    """
    if eng.drive.is_angle:
        text = f"{v % 360.0:.2f}"
        return ("0.00" if text in ("360.00", "-0.00") else text) + "°"
    return f"{v:.4g}"


def _to_user(eng: _Engine, x: float) -> float:
    return math.degrees(x) if eng.drive.is_angle else float(x)


def _runs(mask: Array) -> list[tuple[int, int]]:
    """Maximal runs of True as (first, last) indices."""
    if not mask.any():
        return []
    m = np.concatenate([[False], mask, [False]]).astype(int)
    d = np.diff(m)
    starts = np.flatnonzero(d == 1)
    ends = np.flatnonzero(d == -1) - 1
    return list(zip(starts.tolist(), ends.tolist()))


def _singular(sw: Sweep) -> list[SingularPosture]:
    eng = sw._engine
    assert eng is not None
    out: list[SingularPosture] = []
    dv = sw.values
    n = len(dv)
    if n == 0:
        return out
    period = 2 * math.pi if sw._cyclic else None
    bad = ~sw.assembled
    if bad.all():
        a, b = _to_user(eng, dv[0]), _to_user(eng, dv[-1])
        out.append(SingularPosture("cannot-assemble", a, b, "",
                                   f"cannot assemble for drive {_fmt(eng, a)} to {_fmt(eng, b)}"))
        return out

    def value(i: int) -> float:
        """Drive value of sample i, continued past either end of a full turn."""
        if i < 0:
            assert period is not None  # only a full turn continues past its ends
            return float(dv[i + n]) - period
        if i >= n:
            assert period is not None
            return float(dv[i - n]) + period
        return float(dv[i])

    # ---- ranges that cannot be assembled --------------------------------
    runs = _runs(bad)
    if period is not None and len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == n - 1:
        first = runs.pop(0)
        last = runs.pop()
        runs.append((last[0], first[1] + n))
    goods: list[float] = []
    bads: list[float] = []
    where: list[tuple[str, int]] = []
    for k, (i0, i1) in enumerate(runs):
        if i0 > 0 or period is not None:
            goods.append(value(i0 - 1))
            bads.append(value(i0))
            where.append(("start", k))
        if i1 < n - 1 or period is not None:
            goods.append(value(i1 + 1))
            bads.append(value(i1))
            where.append(("end", k))
    refined: dict[tuple[str, int], float] = {}
    if goods:
        gd: list[float] | Array
        if eng.method == "analytic":
            gd = _refine_analytic(sw, goods, bads)
        else:
            gd, _ = _bisect(_assembles(eng), np.array(goods), np.array(bads))
        refined = {key: float(v) for key, v in zip(where, gd)}
    failing = _failing_labels(sw)
    for k, (i0, i1) in enumerate(runs):
        a = refined.get(("start", k), value(i0))
        b = refined.get(("end", k), value(i1))
        ua, ub = _to_user(eng, a), _to_user(eng, b)
        lab = failing.get(i0 % n, "")
        out.append(SingularPosture("cannot-assemble", ua, ub, lab,
                                   f"cannot assemble for drive {_fmt(eng, ua)} to {_fmt(eng, ub)}"))
        if lab and eng.pc is not None and _is_branch(eng.pc.construction, lab):
            for key, v in ((("start", k), a), (("end", k), b)):
                if key in refined:
                    u = _to_user(eng, v)
                    out.append(SingularPosture(
                        "dead-center", u, None, lab,
                        f"dead center at {lab}: its two branches meet at drive {_fmt(eng, u)} "
                        "(an end of a range where it cannot be assembled)"))
    if eng.pc is not None:
        # ---- change points: the branches touch inside an assembled range -----
        out.extend(_change_points(sw, eng))
        # ---- limit positions of the links pinned to the frame ----------------
        out.extend(_limits(sw, eng))
        # ---- sliders: where a slider on the frame stops and turns back (Sec. 1.10),
        #      and a slider drive's dead centers at the ends of its travel ------------
        out.extend(_slider_limits(sw, eng))
        out.extend(_travel_ends(sw, eng))
    else:
        out.extend(_travel_limits(sw, eng))
    out.sort(key=lambda s: (s.drive, s.kind))
    return out


def _refine_analytic(sw: Sweep, goods: list[float], bads: list[float],
                     steps: int = 24) -> list[float]:
    """Bisection of assembly boundaries with Newton's method started from the assembled side."""
    from graphkin.kinematics.analytic import solve_analytic_many

    mech = sw.mechanism
    sol = sw.solution
    dv = sw.values
    period = 2 * math.pi if sw._cyclic else 0.0
    out = []
    for good, bad in zip(goods, bads):
        # the sample nearest the assembled side seeds Newton's method
        gap = dv - good
        if period:
            gap = np.remainder(gap + period / 2, period) - period / 2
        i = int(np.argmin(np.abs(gap)))
        guess = {lid: (float(sol.links[lid].origin[i, 0]), float(sol.links[lid].origin[i, 1]),
                       float(sol.links[lid].angle[i])) for lid in mech.moving}
        for _ in range(steps):
            mid = 0.5 * (good + bad)
            full = np.array([[mid if k == 0 else d.value for k, d in enumerate(mech.drives)]])
            s = solve_analytic_many(mech, full, guess)
            if bool(np.asarray(s.valid).reshape(-1)[0]):
                good = mid
                guess = {lid: (float(np.reshape(s.links[lid].origin, (-1, 2))[0, 0]),
                               float(np.reshape(s.links[lid].origin, (-1, 2))[0, 1]),
                               float(np.reshape(s.links[lid].angle, (-1,))[0]))
                         for lid in mech.moving}
            else:
                bad = mid
        out.append(good)
    return out


def _failing_labels(sw: Sweep) -> dict[int, str]:
    eng = sw._engine
    out: dict[int, str] = {}
    if eng is None or eng.pc is None:
        return out
    cx = eng.combined if eng.combined is not None else eng.pc.construction
    off = 0
    for blk in sw._blocks:
        assert blk.ev is not None  # eng.pc is set: every block has its posture replay
        fa = blk.ev.failed_at
        if fa is not None:
            fa = np.broadcast_to(fa, (len(blk.dv),))
            for i in np.flatnonzero(fa >= 0):
                out[off + int(i)] = cx[int(fa[i])].label
        off += len(blk.dv)
    return out


def _is_branch(cx: Construction, label: str) -> bool:
    try:
        return cx.step_of(label).branch is not None
    except KeyError:
        return False


def _separations(cx: Construction, values: dict[str, Array]) -> dict[str, Array]:
    """For every two-way step: the half-distance between its two answers over the figure size.

    Zero where the branches meet (tangent arcs, a tangent line).
    """
    out: dict[str, Array] = {}
    for s in cx.steps:
        if s.branch is None or any(i not in values for i in s.inputs):
            continue
        with np.errstate(invalid="ignore", divide="ignore"):
            if s.op == "intersect_circles":
                c1, c2 = (np.asarray(values[i], dtype=float) for i in s.inputs)
                d = c2[..., :2] - c1[..., :2]
                dist = np.hypot(d[..., 0], d[..., 1])
                r1, r2 = c1[..., 2], c2[..., 2]
                a = (dist**2 + r1**2 - r2**2) / (2 * dist)
                h = np.sqrt(np.maximum(r1**2 - a**2, 0.0))
                out[s.label] = h / np.maximum(r1, r2)
            elif s.op == "intersect_line_circle":
                line, c = (np.asarray(values[i], dtype=float) for i in s.inputs)
                dd = line[..., 0] * c[..., 0] + line[..., 1] * c[..., 1] + line[..., 2]
                r = c[..., 2]
                out[s.label] = np.sqrt(np.maximum(r**2 - dd**2, 0.0)) / r
    return out


def _change_points(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    assert eng.pc is not None
    cx = eng.pc.construction
    seps: dict[str, list[Array]] = {}
    for blk in sw._blocks:
        full = eng.posture(blk.dv)
        for k, v in _separations(cx, full.values).items():
            seps.setdefault(k, []).append(np.broadcast_to(v, (len(blk.dv),)))
    out: list[SingularPosture] = []
    dv = sw.values
    n = len(dv)
    for lab, parts in seps.items():
        sep = np.concatenate(parts)
        sep = np.where(sw.assembled, sep, np.inf)
        idx = [i for i in range(1, n - 1)
               if sep[i] <= sep[i - 1] and sep[i] <= sep[i + 1] and sep[i] < 0.05]
        for i in idx:
            lo, hi = dv[i - 1], dv[i + 1]

            def f(x: Array, lab: str = lab) -> Array:
                ev = eng.posture(np.atleast_1d(x))
                s = _separations(cx, ev.values).get(lab)
                if s is None:
                    return np.full(np.shape(x), np.inf)
                return np.where(np.broadcast_to(ev.valid, np.shape(s)), s, np.inf)

            gr = (math.sqrt(5) - 1) / 2
            for _ in range(60):
                m1 = hi - gr * (hi - lo)
                m2 = lo + gr * (hi - lo)
                v = f(np.array([m1, m2]))
                if v[0] <= v[1]:
                    hi = m2
                else:
                    lo = m1
            x = 0.5 * (lo + hi)
            if float(f(np.array([x]))[0]) < 1e-6:
                u = _to_user(eng, x)
                br = eng.pc.branches.get(lab, "")
                out.append(SingularPosture(
                    "dead-center", u, None, lab,
                    f"dead center at {lab}: its two branches meet at drive {_fmt(eng, u)} "
                    f"(change point); the sweep keeps the branch named {br!r}, which need not "
                    "be the continuous motion beyond it (--follow goes on with the motion)",
                    change_point=True))
    return out


def _reversals(dv: Array, speed: Array, ok: Array, speed_at: Callable[[Array], Array],
               scale: float = 0.0) -> list[tuple[float, float | None]]:
    """Where an output stops and turns back: its speed changes sense (Sec. 1.10).

    ``speed`` is sampled at the drive values ``dv`` (valid where ``ok``), and
    ``speed_at(x)`` gives it at other drive values.  A speed within round-off
    of zero (``DEFAULT_TOL.length_rel`` of the largest, or of ``scale``, the
    speed's natural size per unit drive rate, whichever is larger) is zero,
    not a sense: a follower at rest through a dwell has ω or V of 1e-17 of
    either sign, and an output at rest over the whole sweep has nothing but.
    The sense is compared between consecutive samples that move, across any
    samples at rest between them (no invalid sample between), so

    * a sense that flips between two samples is one limit position, located
      by bisection to round-off (``(x, None)``);
    * a dwell between two strokes of opposite sense is one limit position held
      over a range (``(start, end)``, each end bisected);
    * a dwell inside one stroke (a pause between two rises) is no limit;
    * a rest shorter than half the sampling step is not resolved: one posture,
      at its middle.

    Returns
    -------
    list of (float, float or None)
        The limit positions in the order of ``dv``.
    """
    v = np.asarray(speed, dtype=float)
    moving = ok & np.isfinite(v)
    if not moving.any():
        return []
    tol = DEFAULT_TOL.length_rel * max(float(np.max(np.abs(v[moving]))), scale)
    if not tol > 0.0:
        return []

    def sense(x: Array) -> Array:
        x = np.asarray(x, dtype=float)
        return np.where(np.abs(x) <= tol, 0.0, np.sign(x))   # NaN -> NaN: no sense

    sg = sense(v)
    nz = np.flatnonzero(moving & (sg != 0))
    if nz.size < 2:
        return []
    i, j = nz[:-1], nz[1:]
    bad = np.concatenate([[0], np.cumsum(~ok)])
    keep = (bad[j] - bad[i + 1] == 0) & (sg[i] != sg[j])
    i, j = i[keep], j[keep]
    if i.size == 0:
        return []
    d = np.asarray(dv, dtype=float)
    # start: where the sense of sample i ends, within [dv[i], dv[i+1]];
    # end: where the sense of sample j begins, within [dv[j-1], dv[j]]
    lo = np.concatenate([d[i], d[j]])
    hi = np.concatenate([d[i + 1], d[j - 1]])
    want = np.concatenate([sg[i], sg[j]])
    for _ in range(48):                       # to round-off of the drive
        mid = 0.5 * (lo + hi)
        same = sense(speed_at(mid)) == want
        lo = np.where(same, mid, lo)
        hi = np.where(same, hi, mid)
    edge = 0.5 * (lo + hi)
    a, b = edge[:i.size], edge[i.size:]
    step = float(np.max(np.abs(np.diff(d)))) if d.size > 1 else 1.0
    out: list[tuple[float, float | None]] = []
    for ai, bi in zip(a.tolist(), b.tolist()):
        # a sense flipping at one drive value (its zone of round-off speed is
        # 2 tol/|v'| wide), or a rest shorter than the sampling resolves
        if abs(bi - ai) <= 0.5 * step:
            out.append((0.5 * (ai + bi), None))
        else:
            out.append((ai, bi))
    return out


def _limits(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    """Where a link pinned to the frame stops and turns back (``ω = 0``)."""
    assert eng.pc is not None
    mech = eng.mech
    frame_pts = set(mech.links[FRAME].points)
    slid = {s.link for s in mech.sliders}
    cands = [lid for lid in mech.moving
             if lid != eng.drive.link and lid not in slid
             and frame_pts & set(mech.links[lid].points)
             and any(lid in p.links and FRAME in p.links for p in mech.pins)]
    if not cands:
        return []
    if eng.pol is None:
        eng.pol = build_polygons(mech, eng.pc)
    out: list[SingularPosture] = []
    dv = sw.values

    def omegas(x: Array) -> tuple[dict[str, Array], Array]:
        ev = eng.posture(np.atleast_1d(x))
        evv, _ = eng.rates(ev, unit=True)
        ok = np.broadcast_to(ev.valid & evv.valid, np.shape(x))
        return {lid: np.broadcast_to(np.asarray(evv[f"ω{lid}"]), np.shape(x)) for lid in cands}, ok

    w_all, ok_all = omegas(dv)
    for lid in cands:
        def w_at(mid: Array, lid: str = lid) -> Array:
            return omegas(mid)[0][lid]

        # ω per unit drive rate: rad/rad for a crank, rad per length for a slider drive
        unit = 1.0 if eng.drive.is_angle else 1.0 / mech.size
        found = _reversals(dv, w_all[lid], ok_all, w_at, unit)
        if not found:
            continue
        x = np.array([f[0] for f in found])
        ev = eng.posture(x)
        th = np.broadcast_to(np.asarray(ev.values[eng.pc.angles[lid]]), x.shape)
        for (xi, xe), ti in zip(found, th):
            u = _to_user(eng, float(xi))
            ue = None if xe is None else _to_user(eng, float(xe))
            at = f"at drive {_fmt(eng, u)}" if ue is None else \
                f"held from drive {_fmt(eng, u)} to {_fmt(eng, ue)} (a dwell)"
            out.append(SingularPosture(
                "limit", u, ue, lid,
                f"limit position of link {lid} (ω{lid} = 0) {at}, "
                f"θ{lid} = {float(wrap_degrees(np.array([ti]))[0]):.2f}°"))
    return out


def _slider_limits(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    """Where a slider on the frame stops and turns back (its velocity along the line is 0).

    For a slider-crank driven by its crank these are the slider's two limit
    positions, with crank and connecting rod in line (the dead-center
    postures of Sec. 1.10); for a quick-return mechanism, the ends of the
    ram's stroke.
    """
    assert eng.pc is not None
    mech = eng.mech
    sliders = [s for s in mech.sliders if s.on == FRAME and s.link != eng.drive.link]
    if not sliders:
        return []
    if eng.pol is None:
        eng.pol = build_polygons(mech, eng.pc)
    dv = sw.values

    def along(x: Array) -> tuple[dict[int, Array], dict[int, Array], Array]:
        """Per slider: velocity along its line (unit drive speed) and travel; and validity."""
        ev = eng.posture(np.atleast_1d(x))
        evv, _ = eng.rates(ev, unit=True)
        ok = np.broadcast_to(ev.valid & evv.valid, np.shape(x))
        speed, travel = {}, {}
        for s in sliders:
            if f"v({s.point})" not in evv.values or s.point not in ev.values:
                continue
            u = np.subtract(s.p1, s.p0) / math.hypot(s.p1[0] - s.p0[0], s.p1[1] - s.p0[1])
            v = np.asarray(evv[f"v({s.point})"], dtype=float)
            o = np.asarray(evv["o_v"], dtype=float)
            vel = v[..., :2] / v[..., 2:3] - o[..., :2] / o[..., 2:3]
            p = np.asarray(ev[s.point], dtype=float)
            pos = p[..., :2] / p[..., 2:3] - np.asarray(s.p0)
            speed[s.index] = np.broadcast_to(vel @ u, np.shape(x))
            travel[s.index] = np.broadcast_to(pos @ u, np.shape(x))
        return speed, travel, ok

    out: list[SingularPosture] = []
    speed_all, _, ok_all = along(dv)
    for s in sliders:
        if s.index not in speed_all:
            continue

        def v_at(mid: Array, k: int = s.index) -> Array:
            return along(mid)[0][k]

        # V per unit drive rate: length per rad for a crank, length per length for a slider
        unit = mech.size if eng.drive.is_angle else 1.0
        found = _reversals(dv, speed_all[s.index], ok_all, v_at, unit)
        if not found:
            continue
        _s, trav, _ok = along(np.array([f[0] for f in found]))
        for (xi, xe), ti in zip(found, trav[s.index]):
            u = _to_user(eng, float(xi))
            ue = None if xe is None else _to_user(eng, float(xe))
            at = f"at drive {_fmt(eng, u)}" if ue is None else \
                f"held from drive {_fmt(eng, u)} to {_fmt(eng, ue)} (a dwell)"
            out.append(SingularPosture(
                "limit", u, ue, s.link,
                f"limit position of slider {s.link} (V_{s.point} = 0) {at}, "
                f"{s.point} at {float(ti):.4g} {mech.length_unit} along its line"))
    return out


def _travel_ends(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    """Dead centers at the ends of a slider drive's travel.

    A slider drive's default range is the travel over which the mechanism
    assembles; where it ends, two arcs of the posture become tangent: the
    crank and connecting rod of a slider-crank driven by its slider are in
    line, and the slider cannot turn the crank on (Sec. 1.10).
    """
    assert eng.pc is not None
    dv = sw.values
    if eng.drive.kind != "position" or sw._cyclic or len(dv) < 2:
        return []
    step = float(dv[1] - dv[0])
    ends = (float(dv[0]), float(dv[0]) + step * len(dv))
    ok = _assembles(eng)
    gap = 1e-6 * eng.mech.scale
    out: list[SingularPosture] = []
    for end, outward in ((ends[0], -gap), (ends[1], gap)):
        if bool(ok(np.array([end + outward]))[0]):
            continue  # it assembles beyond this end: the range was cut short by the user
        # the end found by bisection, or within round-off of it on the assembled side
        x = np.array([end])
        if not bool(ok(x)[0]):
            x = np.array([end - 1e-3 * outward])
            if not bool(ok(x)[0]):
                continue
        ev = eng.posture(x)
        for lab, sep in _separations(eng.pc.construction, ev.values).items():
            if float(np.reshape(sep, (-1,))[0]) < 1e-3:
                u = _to_user(eng, end)
                out.append(SingularPosture(
                    "dead-center", u, None, lab,
                    f"dead center at {lab}: its two branches meet at drive {_fmt(eng, u)} "
                    "(an end of the travel over which it assembles)"))
    return out


def _travel_limits(sw: Sweep, eng: _Engine) -> list[SingularPosture]:
    """Dead centers at the ends of a travel drive's range, for the analytic solver.

    The limit positions :func:`_travel` found by bisection (Sec. 1.10) that are
    an end of this sweep (within ``VERDICT_REL`` of the size of the
    mechanism): there the rates are left empty (:meth:`_Engine.at_limit`).
    There is no construction to name the point where the branches meet.
    """
    dv = sw.values
    if eng.drive.is_angle or sw._cyclic or len(dv) < 2:
        return []
    step = float(dv[1] - dv[0])
    ends = np.array([float(dv[0]), float(dv[0]) + step * len(dv)])
    out: list[SingularPosture] = []
    for end, near in zip(ends, eng.at_limit(ends)):
        if near:
            u = _to_user(eng, float(end))
            out.append(SingularPosture(
                "dead-center", u, None, "",
                f"dead center: the two branches of the posture meet at drive {_fmt(eng, u)} "
                "(an end of the travel over which it assembles; the rates are not "
                "determined there)"))
    return out


def time_ratios(sw: Sweep) -> list[str]:
    """The time ratio of each output that swings between two limit positions (Sec. 1.7).

    Over one whole turn of a crank turning at constant speed, a link (or a
    slider) with exactly two limit positions, at drive angles θa and θb, makes
    one stroke while the crank turns through α = θb − θa and the other while
    it turns through β = 360° − α; the advance-to-return time ratio is
    Q = α/β (Eq. 1.5), written with the longer stroke first (Q ≥ 1).

    Returns
    -------
    list of str
        One line per such output; none when the sweep is not one assembled turn
        of a revolute drive (the ratio is that of a constant crank speed, whatever
        α the file gives at its posture).
    """
    eng = sw._engine
    if eng is None:
        return []
    d = eng.drive
    if not (sw._cyclic and d.is_angle) or any(s.kind == "cannot-assemble"
                                              for s in sw.singular):
        return []
    # Q is a property of the geometry at a constant crank speed (Eq. 1.5), said so in
    # the line; a file's α (the crank's acceleration at its one posture) does not
    # take it away
    out = []
    by: dict[str, list[float]] = {}
    dwells = set()
    for s in sw.singular:
        if s.kind == "limit":
            by.setdefault(s.label, []).append(s.drive)
            if s.end is not None:
                dwells.add(s.label)
    for lid, us in by.items():
        if len(us) != 2 or lid in dwells:   # a dwell at a limit: the strokes' times are not α, β
            continue
        a = (us[1] - us[0]) % 360.0
        alpha, beta = max(a, 360.0 - a), min(a, 360.0 - a)
        if beta <= 0.0:
            continue
        what = f"slider {lid}" if any(sl.link == lid for sl in sw.mechanism.sliders) \
            else f"link {lid}"
        out.append(f"time ratio of {what}'s strokes at a constant crank speed: Q = "
                   f"α/β = {alpha:.2f}°/{beta:.2f}° = {alpha / beta:.3f} (Sec. 1.7, Eq. 1.5)")
    return out
