"""The posture and its rates: the JSON object of ``docs/formats/json.md`` and the text report.

References
----------
Uicker, Pennock & Shigley, 5th ed.: results are stated as the book states them,
``θ3 = 20.92°``, ``ω3 = 25.38 rad/s ccw``, ``V_E = 27.8 ft/s ∠165.3°``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME
from graphkin.output.sections import SECTIONS
from graphkin.output.units import OutputUnits
from graphkin.text import clean, g6, polar, sense, wrap_degrees
from graphkin.tolerance import VERDICT_REL

__all__ = ["solution_to_dict", "text_report", "finite", "RateFloors", "rate_floors"]


def finite(x: Any) -> Any:
    """A JSON-safe copy: numpy to Python numbers, non-finite floats to None, -0.0 to 0.0.

    Examples
    --------
    >>> finite({"a": np.float64("nan"), "b": [np.int64(2), -0.0]})
    {'a': None, 'b': [2, 0.0]}
    """
    if isinstance(x, dict):
        return {k: finite(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [finite(v) for v in x]
    if isinstance(x, np.ndarray):
        return finite(x.tolist())
    if isinstance(x, (int, np.integer)) and not isinstance(x, (bool, np.bool_)):
        return int(x)
    if isinstance(x, (float, np.floating)):
        f = float(x)
        if not math.isfinite(f):
            return None
        return f + 0.0
    return x


def solution_to_dict(sol: Solution, units: OutputUnits | None = None) -> dict[str, Any]:
    """The ``graphkin solve --json`` object of ``docs/formats/json.md`` (and a few extra keys).

    ``units`` (default: the file's length unit, seconds, radians per second)
    converts every length, velocity, acceleration and angular rate, and is
    stated in the ``units`` object.

    Examples
    --------
    >>> import graphkin
    >>> d = solution_to_dict(graphkin.examples.fourbar().solve())
    >>> round(d["links"]["3"]["angle"], 2), d["units"]["velocity"]  # Example 3.1: θ3 = 20.92°
    (20.92, 'in/s')
    """
    mech = sol.mechanism
    u = units if units is not None else OutputUnits.of(mech.length_unit)
    links: dict[str, Any] = {}
    for lid, st in sol.links.items():
        entry: dict[str, Any] = {"angle": wrap_degrees(float(st.angle))}
        if st.omega is not None:
            entry["omega"] = float(st.omega) * u.k_omega
        elif mech.has_rates:  # rates given, undetermined here (a toggle; see the notes)
            entry["omega"] = None
        if st.alpha is not None:
            entry["alpha"] = float(st.alpha) * u.k_alpha
        elif mech.has_rates:
            entry["alpha"] = None
        links[lid] = entry
    points: dict[str, Any] = {}
    for name in mech.point_names:
        entry = {"position": (sol.position(name) * u.k_length).tolist()}
        if sol.has_rates:
            entry["velocity"] = (sol.velocity(name) * u.k_velocity).tolist()
        elif mech.has_rates:  # undetermined at a toggle or dead center (see the notes)
            entry["velocity"] = None
        if sol.has_accelerations:
            entry["acceleration"] = (sol.acceleration(name) * u.k_acceleration).tolist()
        elif mech.has_accelerations:
            entry["acceleration"] = None
        entry["links"] = list(mech.point_links[name])
        points[name] = entry
    out: dict[str, Any] = {
        "title": mech.title,
        "units": u.json(),
        "method": sol.method,
        "links": links,
        "points": points,
    }
    for s in SECTIONS:
        section = s.json(sol, u)
        if section is not None:
            out[s.key] = section
    if sol.branches:
        out["branches"] = dict(sol.branches)
    if sol.notes:
        out["notes"] = list(sol.notes)
    # the instant centers of a large mechanism come as plain finite floats already
    # (graphkin.output.centers): hundreds of thousands of them need no second pass
    centers = out.get("instant_centers")
    if centers is not None and len(centers) > 20000:
        clean = finite({k: v for k, v in out.items() if k != "instant_centers"})
        return {k: (centers if k == "instant_centers" else clean[k]) for k in out}
    return finite(out)


@dataclass(frozen=True)
class RateFloors:
    """What is round-off of each kind of rate at one posture (below it: 0, no sense).

    Each is :data:`graphkin.tolerance.VERDICT_REL` of the size of its kind, which
    counts every quantity of the same dimension: ω with ``|V|/size``, α with ω² and
    ``|A|/size``, a velocity with ``|ω| size``, so that a posture whose every α is
    round-off (a crank at constant ω moving a link in pure translation) prints 0,
    never a sense, on every machine.
    """

    omega: float
    alpha: float
    velocity: float
    acceleration: float


def rate_floors(sol: Solution) -> RateFloors:
    """The round-off floors of ω, α, V and A of a one-posture solution (0 without rates)."""
    if not sol.has_rates:
        return RateFloors(0.0, 0.0, 0.0, 0.0)
    mech = sol.mechanism
    size = mech.size or 1.0
    moving = [st for lid, st in sol.links.items() if lid != FRAME]

    def big(values: list[float]) -> float:
        return max([0.0, *(abs(v) for v in values if math.isfinite(v))])

    ws = big([float(st.omega) for st in moving if st.omega is not None])
    als = big([float(st.alpha) for st in moving if st.alpha is not None])
    vs = big([float(np.hypot(*sol.velocity(n))) for n in mech.point_names])
    accs = (big([float(np.hypot(*sol.acceleration(n))) for n in mech.point_names])
            if sol.has_accelerations else 0.0)
    w_scale = max(ws, vs / size)
    a_scale = max(als, w_scale**2, accs / size)
    return RateFloors(VERDICT_REL * w_scale, VERDICT_REL * a_scale,
                      VERDICT_REL * max(vs, w_scale * size),
                      VERDICT_REL * max(accs, a_scale * size))


def text_report(sol: Solution, units: OutputUnits | None = None) -> str:
    """A readable, textbook-style report of a solved posture.

    Examples
    --------
    >>> import graphkin
    >>> print(text_report(graphkin.examples.fourbar().solve()).splitlines()[5])
      θ2 = 120.0000°   ω2 = 94.2478 rad/s ccw   α2 = 0 rad/s²
    """
    mech = sol.mechanism
    ou = units if units is not None else OutputUnits.of(mech.length_unit)
    u = ou.text("length")
    lines = [mech.title or mech.source, ""]
    how = ("by the graphic constructions" if sol.method == "construction"
           else "by the analytic solver")
    lines.append(f"Solved {how}.")
    for n in sol.notes:
        lines.append(f"  note: {n}")
    lines.append("")
    # what is left of a zero is round-off: below 1e-9 of the largest value of its kind
    # (1e-12 of the mechanism's size for positions) it prints as 0 on every machine
    names = mech.point_names

    floors = rate_floors(sol)
    tw, ta = floors.omega, floors.alpha
    tv = floors.velocity * ou.k_velocity
    tacc = floors.acceleration * ou.k_acceleration
    tl = 1e-12 * mech.scale * ou.k_length
    lines.append("Links")
    for lid, st in sol.links.items():
        if lid == FRAME:
            continue
        row = f"  θ{lid} = {clean(round(wrap_degrees(float(st.angle)), 4)):.4f}°"
        if st.omega is not None:
            w = clean(float(st.omega), tw)
            row += f"   ω{lid} = {g6(abs(w) * ou.k_omega)} {ou.text('omega')} {sense(w)}".rstrip()
        if st.alpha is not None:
            a = clean(float(st.alpha), ta)
            row += f"   α{lid} = {g6(abs(a) * ou.k_alpha)} {ou.text('alpha')} {sense(a)}".rstrip()
        lines.append(row)
    lines.append("")
    lines.append("Points")
    for name in names:
        x, y = sol.position(name) * ou.k_length
        row = f"  R_{name} = ({g6(clean(x, tl))}, {g6(clean(y, tl))}) {u}"
        if sol.has_rates:
            v = sol.velocity(name) * ou.k_velocity
            row += f"   V_{name} = {polar(v, ou.text('velocity'), tv)}"
        if sol.has_accelerations:
            acc = sol.acceleration(name) * ou.k_acceleration
            row += f"   A_{name} = {polar(acc, ou.text('acceleration'), tacc)}"
        lines.append(row)
    for s in SECTIONS:
        text = s.text(sol, ou)
        if text:
            lines += ["", s.title, text]
    return "\n".join(lines) + "\n"
