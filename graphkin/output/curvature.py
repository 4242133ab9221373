"""Curvature and path curvature in the JSON and in the text report (``docs/formats/json.md``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.kinematics.curvature import curvature, path_curvatures
from graphkin.kinematics.solution import Solution
from graphkin.output.centers import is_batch
from graphkin.output.solution import rate_floors
from graphkin.output.units import OutputUnits
from graphkin.text import clean, direction_degrees, fmt_angle, g6, xy

__all__ = ["curvature_json", "paths_json", "curvature_text"]

Array = np.ndarray


def _num(x: float | None, k: float = 1.0) -> float | None:
    if x is None or not math.isfinite(x):
        return None
    return float(x) * k + 0.0


def _pair(p: Array | None, k: float = 1.0) -> list[float] | None:
    if p is None or not np.all(np.isfinite(p)):
        return None
    return [float(p[0]) * k + 0.0, float(p[1]) * k + 0.0]


def _angle(degrees: float) -> str:
    """``∠90.00°``; a direction at round-off of the x axis prints ``∠0.00°``, never ``∠-0.00°``."""
    return fmt_angle(math.radians(degrees))


def _units(sol: Solution, units: OutputUnits | None) -> OutputUnits:
    return units if units is not None else OutputUnits.of(sol.mechanism.length_unit)


def curvature_json(sol: Solution, units: OutputUnits | None = None) -> dict[str, Any] | None:
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
    The crank of Example 4.2 turns about its pivot A, which is its velocity pole:

    >>> import graphkin
    >>> k2 = curvature_json(graphkin.examples.fourbar().solve())["2"]
    >>> k2["velocity_pole"], k2["method"]
    ([0.0, 0.0], 'pivot')
    """
    if is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    u = _units(sol, units)
    kl = u.k_length
    out: dict[str, Any] = {}
    for lid, k in curvature(sol).items():
        e: dict[str, Any] = {
            "velocity_pole": _pair(k.velocity_pole, kl),
            "inflection_pole": _pair(k.inflection_pole, kl),
            "inflection_diameter": _num(k.inflection_diameter, kl),
            "acceleration_center": _pair(k.acceleration_center, kl),
            "bresse_diameter": _num(k.bresse_diameter, kl),
        }
        if k.cubic is not None:
            e["cubic"] = {"tangent": _pair(k.cubic.tangent), "M": _num(k.cubic.M, kl),
                          "N": _num(k.cubic.N, kl)}
            e["ball_point"] = _pair(k.ball_point, kl)
        e.update({
            "normal": _pair(k.normal),
            "tangent": _pair(k.tangent),
            "pole_velocity": _pair(k.pole_velocity, u.k_velocity),
            "pole_acceleration": _pair(k.pole_acceleration, u.k_acceleration),
            "bresse_pole": _pair(k.bresse_pole, kl),
            "gamma": _num(math.degrees(k.gamma)),
            "method": k.method,
        })
        for key, cen in (("moving_centrode", k.moving_centrode),
                         ("fixed_centrode", k.fixed_centrode)):
            if cen is not None:
                e[key] = {"radius": _num(abs(cen[0]), kl), "R_IO": _num(cen[0], kl),
                          "center": _pair(cen[1], kl)}
        out[lid] = e
    return out


def paths_json(sol: Solution, units: OutputUnits | None = None) -> dict[str, Any] | None:
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
    C turns about D on the rocker of Example 4.2 (|CD| = 11 in); A is at rest:

    >>> import graphkin
    >>> paths = paths_json(graphkin.examples.fourbar().solve())
    >>> paths["C"]["radius_of_curvature"], paths["C"]["center_of_curvature"], paths["A"]["how"]
    (11.0, [10.0, 0.0], 'at rest')
    """
    if is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    kl = _units(sol, units).k_length
    out: dict[str, Any] = {}
    for name, pc in path_curvatures(sol).items():
        out[name] = {"radius_of_curvature": _num(pc.radius, kl),
                     "center_of_curvature": _pair(pc.center, kl), "how": pc.how,
                     "link": pc.link}
    return out


_HOW = {"bobillier": "Bobillier's construction (Fig. 4.29)",
        "euler-savary": "the Euler-Savary lay-off R_AJ_A = R_AI²/R_AA' (Eq. 4.43)",
        "accelerations": "the acceleration of the point at I (A_I = ω² R_JI, Eq. 4.46)",
        "pivot": "inspection (the link turns about a frame pivot)",
        "closed form": "the closed forms"}


def curvature_text(sol: Solution, units: OutputUnits | None = None) -> str | None:
    """The curvature part of the text report: per link, then the paths of the named points.

    ``None`` for a batch or a solution without rates.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    if is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return None
    ou = _units(sol, units)
    kl = ou.k_length
    u = ou.text("length")
    sc = float(sol.mechanism.scale) * kl
    lines: list[str] = []

    def at(p: Array | None) -> str:
        return xy(None if p is None else np.asarray(p, dtype=float)[:2] * kl, u, sc)

    def length(x: float) -> str:
        return "∞" if math.isinf(x) else f"{g6(x * kl)}"

    # what the arithmetic left of a zero rate prints 0, as in the links table (a crank at
    # constant ω printed α2 = -1.47911e-31 rad/s² and γ = -0.00°), on every machine
    floors = rate_floors(sol)
    for lid, k in curvature(sol).items():
        alpha = clean(k.alpha, floors.alpha)
        gamma = 0.0 if alpha == 0.0 else math.degrees(k.gamma)
        lines.append(f"  Motion {lid}/1: ω{lid} = {g6(clean(k.omega, floors.omega) * ou.k_omega)} "
                     f"{ou.text('omega')}, α{lid} = {g6(alpha * ou.k_alpha)} {ou.text('alpha')}; "
                     f"J by {_HOW[k.method]}")
        lines.append(f"    velocity pole I = {at(k.velocity_pole)}, inflection pole "
                     f"J = {at(k.inflection_pole)}, "
                     f"R_JI = {g6(k.inflection_diameter * kl)} {u}")
        if k.tangent is not None:
            lines.append(f"    centrode tangent T {_angle(direction_degrees(k.tangent))}, normal N "
                         f"{_angle(direction_degrees(k.normal))}; pole velocity "
                         f"v = {g6(float(np.hypot(*k.pole_velocity)) * ou.k_velocity)} "
                         f"{ou.text('velocity')}, A_I = "
                         f"{g6(float(np.hypot(*k.pole_acceleration)) * ou.k_acceleration)} "
                         f"{ou.text('acceleration')}")
        b = "∞ (α = 0)" if k.bresse_diameter is None else f"{g6(k.bresse_diameter * kl)} {u}"
        lines.append(f"    Γ = {at(k.acceleration_center)}, Bresse diameter b = {b}, "
                     f"γ = {gamma:.2f}°")
        if k.cubic is not None:
            m = "∞" if math.isinf(k.cubic.M) else f"{length(k.cubic.M)} {u}"
            n = "∞" if math.isinf(k.cubic.N) else f"{length(k.cubic.N)} {u}"
            lines.append(f"    cubic of stationary curvature (Hain): M = {m}, N = {n}; "
                         f"Ball's point U = {at(k.ball_point)}")
        if k.moving_centrode is not None and k.fixed_centrode is not None:
            rm, rf = k.moving_centrode[0], k.fixed_centrode[0]
            lines.append(f"    centrodes: R_IO_M = {length(rm)}, R_IO_F = {length(rf)} {u}")
        for note in k.notes:
            lines.append(f"    note: {note}")
    paths = path_curvatures(sol)
    if paths:
        lines.append("  Paths (radius and center of curvature)")
        for name, pc in paths.items():
            if pc.radius is None:
                lines.append(f"    {name}: {pc.how}")
            else:
                lines.append(f"    {name}: ρ = {g6(pc.radius * kl)} {u}, center {at(pc.center)}")
    return "\n".join(lines) if lines else None
