"""What ``graphkin solve`` prints: the JSON of ``spec/output.md`` and a textbook-style report.

References
----------
Uicker, Pennock & Shigley, 5th ed.: results are stated as the book states them,
``θ3 = 20.92°``, ``ω3 = 25.38 rad/s ccw``, ``V_E = 27.8 ft/s ∠165.3°``.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME

__all__ = ["solution_to_dict", "text_report", "wrap_degrees", "finite"]


def wrap_degrees(rad: float) -> float:
    """An angle in degrees in (-180, 180].

    Examples
    --------
    >>> wrap_degrees(math.pi), wrap_degrees(-math.pi), wrap_degrees(-2 * math.pi)
    (180.0, 180.0, 0.0)
    """
    d = math.degrees(rad) % 360.0
    if d > 180.0:
        d -= 360.0
    return 0.0 if d == 0 else d


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


def _sections() -> list[Any]:
    """Optional sections (instant centers, curvature, paths) provided by other modules."""
    out = []
    try:
        from graphkin.kinematics.instant_centers import instant_centers_json
        out.append(("instant_centers", instant_centers_json))
    except ImportError:
        pass
    try:
        from graphkin.kinematics.curvature import curvature_json, paths_json
        out.append(("curvature", curvature_json))
        out.append(("paths", paths_json))
    except ImportError:
        pass
    from graphkin.forces.report import forces_section  # spec/forces.md
    out.append(("forces", forces_section))
    return out


def solution_to_dict(sol: Solution) -> dict[str, Any]:
    """The ``graphkin solve --json`` object of ``spec/output.md`` (and a few extra keys)."""
    mech = sol.mechanism
    links: dict[str, Any] = {}
    for lid, st in sol.links.items():
        entry: dict[str, Any] = {"angle": wrap_degrees(float(st.angle))}
        if st.omega is not None:
            entry["omega"] = float(st.omega)
        if st.alpha is not None:
            entry["alpha"] = float(st.alpha)
        links[lid] = entry
    points: dict[str, Any] = {}
    for name in mech.point_names:
        entry = {"position": sol.position(name).tolist()}
        if sol.has_rates:
            entry["velocity"] = sol.velocity(name).tolist()
        if sol.has_accelerations:
            entry["acceleration"] = sol.acceleration(name).tolist()
        entry["links"] = list(mech.point_links[name])
        points[name] = entry
    out: dict[str, Any] = {
        "title": mech.title,
        "units": {"length": mech.length_unit, "time": "s", "angle": "deg"},
        "method": sol.method,
        "links": links,
        "points": points,
    }
    for key, fn in _sections():
        section = fn(sol)
        if section is not None:
            out[key] = section
    if sol.branches:
        out["branches"] = dict(sol.branches)
    if sol.notes:
        out["notes"] = list(sol.notes)
    return finite(out)


def _sense(w: float) -> str:
    return "ccw" if w > 0 else ("cw" if w < 0 else "")


def _vec(v: np.ndarray, unit: str) -> str:
    mag = float(np.hypot(*v))
    if mag == 0:
        return f"0 {unit}"
    return f"{mag:.6g} {unit} ∠{wrap_degrees(math.atan2(v[1], v[0])):.2f}°"


def text_report(sol: Solution) -> str:
    """A readable, textbook-style report of a solved posture."""
    mech = sol.mechanism
    u = mech.length_unit
    lines = [mech.title or mech.source, ""]
    how = ("by the graphic constructions" if sol.method == "construction"
           else "by the analytic solver")
    lines.append(f"Solved {how}.")
    for n in sol.notes:
        lines.append(f"  note: {n}")
    lines.append("")
    lines.append("Links")
    for lid, st in sol.links.items():
        if lid == FRAME:
            continue
        row = f"  θ{lid} = {wrap_degrees(float(st.angle)):.4f}°"
        if st.omega is not None:
            w = float(st.omega)
            row += f"   ω{lid} = {abs(w):.6g} rad/s {_sense(w)}".rstrip()
        if st.alpha is not None:
            a = float(st.alpha)
            row += f"   α{lid} = {abs(a):.6g} rad/s² {_sense(a)}".rstrip()
        lines.append(row)
    lines.append("")
    lines.append("Points")
    for name in mech.point_names:
        x, y = sol.position(name)
        row = f"  R_{name} = ({x:.6g}, {y:.6g}) {u}"
        if sol.has_rates:
            row += f"   V_{name} = {_vec(sol.velocity(name), u + '/s')}"
        if sol.has_accelerations:
            row += f"   A_{name} = {_vec(sol.acceleration(name), u + '/s²')}"
        lines.append(row)
    for title, fn in (("Instant centers", "instant_centers_text"),
                      ("Curvature", "curvature_text")):
        text = _optional_text(fn, sol)
        if text:
            lines += ["", title, text]
    from graphkin.forces.report import forces_report, forces_text  # spec/forces.md
    fs = forces_report(sol)
    if fs is not None:
        lines += ["", forces_text(fs).rstrip("\n")]
    return "\n".join(lines) + "\n"


def _optional_text(name: str, sol: Solution) -> str | None:
    try:
        if name == "instant_centers_text":
            from graphkin.kinematics.instant_centers import instant_centers_text as fn
        else:
            from graphkin.kinematics.curvature import curvature_text as fn
    except ImportError:
        return None
    return fn(sol)
