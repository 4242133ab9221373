"""The JSON and text report of curvature results."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.kinematics.curvature.link import _is_batch, curvature, path_curvatures
from graphkin.kinematics.solution import Solution

__all__ = ["curvature_json", "paths_json", "curvature_text"]

Array = np.ndarray

_TEXT_ZERO = 1e-12
"""Coordinates below this fraction of the figure print as 0 in the text report."""

# ---------------------------------------------------------------------------
# output (docs/formats/json.md)
# ---------------------------------------------------------------------------

def _num(x: float | None) -> float | None:
    if x is None or not math.isfinite(x):
        return None
    return float(x) + 0.0


def _pair(p: Array | None) -> list[float] | None:
    if p is None or not np.all(np.isfinite(p)):
        return None
    return [float(p[0]) + 0.0, float(p[1]) + 0.0]


def curvature_json(sol: Solution) -> dict[str, Any] | None:
    """The ``curvature`` section of ``graphkin solve --json`` (``docs/formats/json.md``).

    Keyed by link id, for every moving link that turns: ``velocity_pole``,
    ``inflection_pole``, ``inflection_diameter``, ``acceleration_center``,
    ``bresse_diameter`` (``null`` when ``α = 0``) and, for a link that carries
    two points of constant path curvature, ``cubic`` (``tangent``, ``M``,
    ``N``; ``null`` where infinite) and ``ball_point``.  Extra keys:
    ``normal``, ``pole_velocity``, ``pole_acceleration``, ``bresse_pole``,
    ``gamma`` (degrees), ``moving_centrode`` / ``fixed_centrode``
    (``radius``, signed ``R_IO`` along ``N``, and ``center``), ``method``.
    ``None`` for a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 0
    ... omega = 2
    ... alpha = 1
    ... ''').solve()
    >>> curvature_json(sol)["2"]["velocity_pole"], curvature_json(sol)["2"]["bresse_diameter"]
    ([0.0, 0.0], 0.0)
    """
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    out: dict[str, Any] = {}
    for lid, k in curvature(sol).items():
        e: dict[str, Any] = {
            "velocity_pole": _pair(k.velocity_pole),
            "inflection_pole": _pair(k.inflection_pole),
            "inflection_diameter": _num(k.inflection_diameter),
            "acceleration_center": _pair(k.acceleration_center),
            "bresse_diameter": _num(k.bresse_diameter),
        }
        if k.cubic is not None:
            e["cubic"] = {"tangent": _pair(k.cubic.tangent), "M": _num(k.cubic.M),
                          "N": _num(k.cubic.N)}
            e["ball_point"] = _pair(k.ball_point)
        e.update({
            "normal": _pair(k.normal),
            "tangent": _pair(k.tangent),
            "pole_velocity": _pair(k.pole_velocity),
            "pole_acceleration": _pair(k.pole_acceleration),
            "bresse_pole": _pair(k.bresse_pole),
            "gamma": _num(math.degrees(k.gamma)),
            "method": k.method,
        })
        for key, cen in (("moving_centrode", k.moving_centrode),
                         ("fixed_centrode", k.fixed_centrode)):
            if cen is not None:
                e[key] = {"radius": _num(abs(cen[0])), "R_IO": _num(cen[0]),
                          "center": _pair(cen[1])}
        out[lid] = e
    return out


def paths_json(sol: Solution) -> dict[str, Any] | None:
    """The ``paths`` section of ``graphkin solve --json`` (``docs/formats/json.md``).

    For every named point of a moving link: ``radius_of_curvature`` (a
    magnitude) and ``center_of_curvature`` of its absolute path, both
    ``null`` where the path is straight here or the point is at rest; plus
    ``how`` it was found and the ``link`` whose motion gave it.  ``None`` for
    a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.13, 4.16.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 0
    ... omega = 2
    ... ''').solve()
    >>> paths_json(sol)["B"]["radius_of_curvature"], paths_json(sol)["A"]["how"]
    (5.0, 'at rest')
    """
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    out: dict[str, Any] = {}
    for name, pc in path_curvatures(sol).items():
        out[name] = {"radius_of_curvature": _num(pc.radius),
                     "center_of_curvature": _pair(pc.center), "how": pc.how, "link": pc.link}
    return out


def _fmt(p: Array | None, unit: str, scale: float = 1.0) -> str:
    if p is None or not np.all(np.isfinite(p)):
        return "—"
    x, y = (0.0 if abs(float(c)) < _TEXT_ZERO * scale else float(c) for c in p[:2])
    return f"({x:.6g}, {y:.6g}) {unit}"


def _deg(v: Array) -> float:
    return math.degrees(math.atan2(float(v[1]), float(v[0])))


def curvature_text(sol: Solution) -> str | None:
    """The curvature part of the text report: per link, then the paths of the named points.

    ``None`` for a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    u = sol.mechanism.length_unit
    sc = float(sol.mechanism.scale)
    lines: list[str] = []
    how = {"bobillier": "Bobillier's construction (Fig. 4.29)",
           "euler-savary": "the Euler-Savary lay-off R_AJ_A = R_AI²/R_AA' (Eq. 4.43)",
           "accelerations": "the acceleration of the point at I (A_I = ω² R_JI, Eq. 4.46)",
           "pivot": "inspection (the link turns about a frame pivot)",
           "closed form": "the closed forms"}
    for lid, k in curvature(sol).items():
        lines.append(f"  Motion {lid}/1: ω{lid} = {k.omega:.6g} rad/s, α{lid} = {k.alpha:.6g} "
                     f"rad/s²; J by {how[k.method]}")
        lines.append(f"    velocity pole I = {_fmt(k.velocity_pole, u, sc)}, inflection pole "
                     f"J = {_fmt(k.inflection_pole, u, sc)}, "
                     f"R_JI = {k.inflection_diameter:.6g} {u}")
        if k.tangent is not None:
            lines.append(f"    centrode tangent T ∠{_deg(k.tangent):.2f}°, normal N "
                         f"∠{_deg(k.normal):.2f}°; pole velocity "  # type: ignore[arg-type]
                         f"v = {float(np.hypot(*k.pole_velocity)):.6g} {u}/s, "
                         f"A_I = {float(np.hypot(*k.pole_acceleration)):.6g} {u}/s²")
        b = "∞ (α = 0)" if k.bresse_diameter is None else f"{k.bresse_diameter:.6g} {u}"
        lines.append(f"    Γ = {_fmt(k.acceleration_center, u, sc)}, Bresse diameter b = {b}, "
                     f"γ = {math.degrees(k.gamma):.2f}°")
        if k.cubic is not None:
            m = "∞" if math.isinf(k.cubic.M) else f"{k.cubic.M:.6g} {u}"
            n = "∞" if math.isinf(k.cubic.N) else f"{k.cubic.N:.6g} {u}"
            lines.append(f"    cubic of stationary curvature (Hain): M = {m}, N = {n}; "
                         f"Ball's point U = {_fmt(k.ball_point, u, sc)}")
        if k.moving_centrode is not None and k.fixed_centrode is not None:
            rm, rf = k.moving_centrode[0], k.fixed_centrode[0]
            lines.append(f"    centrodes: R_IO_M = {'∞' if math.isinf(rm) else f'{rm:.6g}'}, "
                         f"R_IO_F = {'∞' if math.isinf(rf) else f'{rf:.6g}'} {u}")
        for note in k.notes:
            lines.append(f"    note: {note}")
    paths = path_curvatures(sol)
    if paths:
        lines.append("  Paths (radius and center of curvature)")
        for name, pc in paths.items():
            if pc.radius is None:
                lines.append(f"    {name}: {pc.how}")
            else:
                lines.append(f"    {name}: ρ = {pc.radius:.6g} {u}, center "
                             f"{_fmt(pc.center, u, sc)}")
    return "\n".join(lines) if lines else None
