"""Columns a sweep adds on request: transmission angles, instant centers and curvature.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.10 (transmission angle), Sec. 3.13 (instant centers),
Secs. 4.14-4.15 (radius of curvature, Eq. 4.49; inflection circle).
"""

from __future__ import annotations

import numpy as np

from graphkin.errors import InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.polygons import build_polygons
from graphkin.kinematics.solution import Solution
from graphkin.kinematics.sweep.columns import _concat_solutions, _solution_of_block
from graphkin.kinematics.sweep.engine import _Block, _dyads
from graphkin.kinematics.sweep.four_bar import fourbar, transmission_angle
from graphkin.kinematics.sweep.report import Sweep
from graphkin.mechanisms.model import FRAME

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


def _center_columns(sw: Sweep) -> dict[str, Array]:
    try:
        from graphkin.kinematics.instant_centers import instant_centers
    except ImportError:
        return {}
    sol = sw.solution
    if not sol.has_rates:
        sol = _with_unit_rates(sw)
    ic = instant_centers(sol)
    out: dict[str, Array] = {}
    n = len(sw)
    for c in ic:
        p = np.asarray(c.point, dtype=float)
        p = np.broadcast_to(p, (n, 3)) if p.ndim == 1 else p
        ideal = p[:, 2] == 0.0
        with np.errstate(invalid="ignore", divide="ignore"):
            xy = g.xy(p)
        name = c.label
        x, y = xy[:, 0].copy(), xy[:, 1].copy()
        x[~sw.assembled] = np.nan
        y[~sw.assembled] = np.nan
        out[f"x_{name}"], out[f"y_{name}"] = x, y
        if ideal.any():
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
    try:
        from graphkin.kinematics.curvature import inflection_pole, path_curvature
    except ImportError:
        return {}
    mech = sw.mechanism
    if not mech.has_rates:
        return {}
    sol = sw.solution
    out: dict[str, Array] = {}
    n = len(sw)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        for lid in mech.moving:
            st = sol.links[lid]
            w = np.broadcast_to(np.asarray(st.omega, dtype=float), (n,))
            # the velocity pole: V_O + ω k × (I - O) = 0, so I = O + k × V_O / ω
            vo = np.asarray(st.origin_velocity, dtype=float)
            pole = np.asarray(st.origin) + np.stack([-vo[:, 1], vo[:, 0]], axis=-1) / w[:, None]
            c, s = np.cos(st.angle), np.sin(st.angle)
            r = pole - st.origin
            local = np.stack([c * r[:, 0] + s * r[:, 1], -s * r[:, 0] + c * r[:, 1]], axis=-1)
            a_pole = st.acceleration(local)
            j = inflection_pole(pole, a_pole, w)
            dia = np.hypot(*(j - pole).T)
            bad = ~sw.valid | (w == 0.0)
            for arr in (j[:, 0], j[:, 1], dia):
                arr[bad | ~np.isfinite(arr)] = np.nan
            out[f"jx_{lid}"], out[f"jy_{lid}"] = j[:, 0], j[:, 1]
            out[f"inflection_diameter_{lid}"] = dia
        for name in mech.point_names:
            if sol.owner(name) == FRAME:
                continue
            rho, center = path_curvature(sol.position(name), sol.velocity(name),
                                         sol.acceleration(name))
            rho = np.array(np.broadcast_to(rho, (n,)), dtype=float)
            center = np.array(np.broadcast_to(center, (n, 2)), dtype=float)
            bad = ~sw.valid | ~np.isfinite(rho)
            rho[bad] = np.nan
            center[bad | ~np.isfinite(center).all(axis=-1)] = np.nan
            out[f"rho_{name}"] = rho
            out[f"cx_{name}"], out[f"cy_{name}"] = center[:, 0], center[:, 1]
    return out
