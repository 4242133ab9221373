"""Columns a sweep adds on request: transmission angles, instant centers and curvature.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.10 (transmission angle), Sec. 3.13 (instant centers),
Secs. 4.14-4.15 (radius of curvature, Eq. 4.49; inflection circle).
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.errors import InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.polygons import build_polygons
from graphkin.kinematics.solution import LinkState, Solution
from graphkin.kinematics.sweep.columns import _concat_solutions, _solution_of_block
from graphkin.kinematics.sweep.engine import _Block, _dyads
from graphkin.kinematics.sweep.four_bar import fourbar, transmission_angle
from graphkin.kinematics.sweep.report import Sweep
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import DEFAULT_TOL

Array = np.ndarray


def _angle_at(p: Array, a: Array, b: Array) -> Array:
    """The angle APB in degrees, 0-180."""
    u = g.xy(a) - g.xy(p)
    v = g.xy(b) - g.xy(p)
    return np.degrees(np.arctan2(np.abs(g.cross2(u, v)), g.dot2(u, v)))


def _transmission_columns(sw: Sweep) -> dict[str, Array]:
    eng = sw._engine
    out: dict[str, Array] = {}
    if eng is None or eng.pc is None:
        try:
            fb = fourbar(sw.mechanism)
        except InputError:
            return out
        out[f"transmission_{fb.pins[2]}"] = transmission_angle(sw)
        return out
    for pin, c1, c2 in _dyads(eng.pc):
        parts = []
        for blk in sw._blocks:
            assert blk.ev is not None  # eng.pc is set: every block has its posture replay
            v = blk.ev.values
            m = len(blk.dv)
            parts.append(np.broadcast_to(_angle_at(v[pin], v[c1], v[c2]), (m,)))
        col = np.concatenate(parts).astype(float)
        col[~sw.assembled] = np.nan
        out[f"transmission_{pin}"] = col
    return out


#: Postures the Kennedy search is resolved on (evenly spaced over the sweep's assembled ones).
KENNEDY_SAMPLE = 64


def _take(sol: Solution, idx: Array) -> Solution:
    """The postures ``idx`` of a swept solution."""
    def cut(a: Any) -> Any:
        return None if a is None else np.asarray(a)[idx]

    links = {lid: LinkState(cut(st.angle), cut(st.origin), cut(st.omega), cut(st.alpha),
                            cut(st.origin_velocity), cut(st.origin_acceleration))
             for lid, st in sol.links.items()}
    return dataclasses.replace(sol, links=links, valid=np.ones(len(idx), dtype=bool),
                               values={})


def _kennedy_replay(sw: Sweep, sol: Solution) -> tuple[Construction, list[str]] | None:
    """The Kennedy search of a sweep, resolved once: the steps after the primary centers.

    The search (which lines of centers meet at each center) is run on a
    sample of the sweep's postures and kept on the engine; the sweep then
    replays its steps on the whole arrays.  Returns the steps to replay and
    the centers' labels in order of discovery (None when nothing assembles).
    """
    from graphkin.kinematics.instant_centers.kennedy import _Kennedy, instant_centers

    eng = sw._engine
    key = ("kennedy", float(sw.values[0]), float(sw.values[-1]), len(sw))
    cache = eng.extras if eng is not None else {}
    hit = cache.get(key)
    if hit is not None:
        return hit
    ok = np.flatnonzero(sw.valid if sol.has_rates else sw.assembled)
    if ok.size == 0:
        return None
    idx = ok[np.unique(np.linspace(0, ok.size - 1, min(KENNEDY_SAMPLE, ok.size)).astype(int))]
    sample = _take(sol, idx)
    head = _Kennedy(sample, DEFAULT_TOL, ())
    head.primary()  # the search records these steps first, then its own
    ic = instant_centers(sample)
    steps = Construction(title=ic.construction.title)
    for s in ic.construction.steps[len(head.cx):]:
        if s.op == "homogeneous_point":  # found from the velocities: given per posture
            steps.add("input", (), s.outputs, name=s.outputs[0], diagram=s.diagram)
        else:
            steps.steps.append(dataclasses.replace(s, index=len(steps.steps)))
    hit = (steps, [c.label for c in ic.centers.values()])
    cache[key] = hit
    return hit


def _primary_from_columns(sw: Sweep) -> dict[str, Array] | None:
    """The primary centers of pins and sliders, straight from the swept columns.

    A pin is the center of every pair of links it joins; a slider's center is
    at infinity, perpendicular to its line (Eq. 3.21): the points and ideal
    points that :func:`~graphkin.kinematics.instant_centers.instant_centers`
    starts from, without building the sweep's link states.  None when the
    mechanism has slots or rolling contact (their common normals need the
    link states).
    """
    from itertools import combinations

    from graphkin.construction.ops import OPS
    from graphkin.kinematics.instant_centers.labels import center_label, pair_key

    mech = sw.mechanism
    if mech.slots or mech.rolling:
        return None
    cols = sw.columns
    env: dict[str, Array] = {}
    found: set[tuple[str, str]] = set()
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for pin in mech.pins:
            for a, b in combinations(pin.links, 2):
                pair = pair_key(a, b)
                if pair in found:
                    continue
                found.add(pair)
                (env[center_label(*pair)],) = OPS["point"](
                    tol=DEFAULT_TOL, xy=(cols[f"x_{pin.name}"], cols[f"y_{pin.name}"]))
        for s in mech.sliders:
            pair = pair_key(s.link, s.on)
            if pair in found:
                continue
            found.add(pair)
            th = np.radians(cols[f"angle_{s.on}"]) + s.direction_angle
            (env[center_label(*pair)],) = OPS["ideal_point"](
                tol=DEFAULT_TOL, direction=(-np.sin(th), np.cos(th)))
    return env


def _center_columns(sw: Sweep) -> dict[str, Array]:
    """Every instant center over the sweep: the Kennedy search resolved once, replayed on arrays.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14 (Kennedy's theorem).
    """
    try:
        from graphkin.kinematics.instant_centers.kennedy import _equal_velocity_point, _Kennedy
        from graphkin.kinematics.instant_centers.labels import _parse_pair
    except ImportError:
        return {}
    solved: list[Solution] = []

    def solution() -> Solution:
        if not solved:
            sol = sw.solution
            solved.append(sol if sol.has_rates else _with_unit_rates(sw))
        return solved[0]

    eng = sw._engine
    key = ("kennedy", float(sw.values[0]), float(sw.values[-1]), len(sw))
    plan = eng.extras.get(key) if eng is not None else None
    if plan is None:
        plan = _kennedy_replay(sw, solution())
    if plan is None:
        return {}
    steps, labels = plan
    # the primary centers (pins, sliders, contacts, slot normals) on the whole arrays
    env = _primary_from_columns(sw)
    if env is None:
        kn = _Kennedy(solution(), DEFAULT_TOL, ())
        kn.primary()
        env = dict(kn.env)
    given: dict[str, Any] = {}
    for s in steps:
        if s.op == "input":
            i, j = _parse_pair(s.outputs[0])
            given[s.outputs[0]] = _equal_velocity_point(solution(), i, j, sw.mechanism.scale,
                                                        DEFAULT_TOL)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        ev = steps.evaluate(given, values=env, strict=False)
    out: dict[str, Array] = {}
    n = len(sw)
    everywhere = bool(sw.assembled.all())
    for name in labels:
        if name not in ev.values:
            continue
        p = np.asarray(ev.values[name], dtype=float)
        p = np.broadcast_to(p, (n, 3)) if p.ndim == 1 else p
        if name in ev.unit:  # stored with w = 1: its rows are its coordinates, none ideal
            x, y = p[:, 0].copy(), p[:, 1].copy()
            ideal = None
        else:
            ideal = p[:, 2] == 0.0
            with np.errstate(invalid="ignore", divide="ignore"):
                xy = g.xy(p)
            x, y = xy[:, 0].copy(), xy[:, 1].copy()
        if not everywhere:
            x[~sw.assembled] = np.nan
            y[~sw.assembled] = np.nan
        out[f"x_{name}"], out[f"y_{name}"] = x, y
        if ideal is not None and ideal.any():
            d = np.where(ideal[:, None], p[:, :2], np.nan)
            out[f"dx_{name}"], out[f"dy_{name}"] = d[:, 0].copy(), d[:, 1].copy()
    return out


def _with_unit_rates(sw: Sweep) -> Solution:
    """The sweep's solution with the unit input speed (for centers of a posture-only file)."""
    eng = sw._engine
    assert eng is not None
    if eng.pc is None:
        return sw.solution
    if eng.pol is None:
        eng.pol = build_polygons(eng.mech, eng.pc)
    blocks = []
    for blk in sw._blocks:
        assert blk.ev is not None  # eng.pc is set: every block has its posture replay
        evv, eva = eng.rates(blk.ev, unit=True)
        blocks.append(_Block(blk.dv, blk.ev, evv, eva))
    sols = [_solution_of_block(eng, b) for b in blocks]
    return sols[0] if len(sols) == 1 else _concat_solutions(sols)


def _curvature_columns(sw: Sweep) -> dict[str, Array]:
    """Curvature of every moving point's path and every moving link's inflection circle and Γ.

    Read from the swept columns (positions, velocities and accelerations of
    the named points, ω and α of the links: the polygons' results), one
    component at a time, with no second pass through the link states.  Per
    link, from any point ``P`` of it: the velocity pole ``I = P + k × V_P / ω``
    (Sec. 3.13); the acceleration of the link's point at ``I``,
    ``A_I = A_P + α k × R_IP - ω² R_IP`` (Eq. 4.5); the inflection pole
    ``J = I + A_I / ω²`` and the inflection circle's diameter ``|A_I| / ω²``
    (Eqs. 4.46-4.47, as :func:`~graphkin.kinematics.curvature.inflection_pole`);
    the center of acceleration ``Γ = P + (ω² A_P + α k × A_P) / (ω⁴ + α²)``
    (Eqs. 4.44-4.45, as :func:`~graphkin.kinematics.curvature.acceleration_center`).
    Per moving point: ``ρ = V² / A^n`` with the center on the side ``A^n``
    points to (Eq. 4.49, as :func:`~graphkin.kinematics.curvature.path_curvature`):
    empty where the path is straight here or the point is at rest.
    """
    mech = sw.mechanism
    if not mech.has_rates:
        return {}
    cols = sw.columns
    out: dict[str, Array] = {}
    invalid = ~sw.valid
    straight_tol = DEFAULT_TOL.angle

    def clean(arr: Array, bad: Array) -> Array:
        arr = np.array(arr, dtype=float)
        arr[bad | ~np.isfinite(arr)] = np.nan
        return arr

    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for lid in mech.moving:
            name = next(iter(mech.links[lid].points))
            px, py = cols[f"x_{name}"], cols[f"y_{name}"]
            vx, vy = cols[f"vx_{name}"], cols[f"vy_{name}"]
            ax, ay = cols[f"ax_{name}"], cols[f"ay_{name}"]
            w, al = cols[f"omega_{lid}"], cols[f"alpha_{lid}"]
            w2 = w * w
            rx, ry = -vy / w, vx / w                      # R_IP = k × V_P / ω
            aix = ax - w2 * rx - al * ry                   # A_I (Eq. 4.5)
            aiy = ay - w2 * ry + al * rx
            bad = invalid | (w == 0.0)
            out[f"jx_{lid}"] = clean(px + rx + aix / w2, bad)
            out[f"jy_{lid}"] = clean(py + ry + aiy / w2, bad)
            out[f"inflection_diameter_{lid}"] = clean(np.hypot(aix, aiy) / w2, bad)
            den = w2 * w2 + al * al
            bad_g = invalid | ((w == 0.0) & (al == 0.0))
            out[f"gx_{lid}"] = clean(px + (w2 * ax - al * ay) / den, bad_g)
            out[f"gy_{lid}"] = clean(py + (w2 * ay + al * ax) / den, bad_g)
        for name in mech.point_names:
            if FRAME in mech.point_links[name]:
                continue
            vx, vy = cols[f"vx_{name}"], cols[f"vy_{name}"]
            ax, ay = cols[f"ax_{name}"], cols[f"ay_{name}"]
            v2 = vx * vx + vy * vy
            c = vx * ay - vy * ax                          # V × A
            k = v2 / c
            speed = np.sqrt(v2)
            bad = invalid | (v2 == 0.0) | (np.abs(c) <= straight_tol * speed * np.hypot(ax, ay))
            out[f"rho_{name}"] = clean(np.abs(k) * speed, bad)
            out[f"cx_{name}"] = clean(cols[f"x_{name}"] - k * vy, bad)
            out[f"cy_{name}"] = clean(cols[f"y_{name}"] + k * vx, bad)
    return out
