"""The ``forces`` object of ``graphkin solve --json`` and the textbook-style force report.

References
----------
Uicker, Pennock & Shigley, 5th ed., Ex 11.1 (F₃₄ = 33.09 lb, link 3 in
compression, T₁₂ = 183.3 in·lb cw), Ex 12.4.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.forces.gear_teeth import tooth_forces, tooth_forces_json
from graphkin.forces.joints import id_order
from graphkin.forces.solve import ForceSolution
from graphkin.tolerance import VERDICT_REL, is_zero, sign

__all__ = ["forces_json", "forces_text", "forces_section", "forces_report"]

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _deg(v: np.ndarray) -> float:
    d = math.degrees(math.atan2(float(v[1]), float(v[0]))) % 360.0
    if d > 180.0:
        d -= 360.0
    if d <= -179.995:  # prints as 180.00, never -180.00 (round-off of a half turn)
        d = 180.0
    return 0.0 if abs(d) < 0.005 else d  # prints 0.00, never -0.00 (a sign at round-off)


def _units(fs: ForceSolution) -> dict[str, str]:
    mech = fs.mechanism
    return {"force": mech.force_unit, "torque": f"{mech.force_unit}*{mech.length_unit}"}


def forces_json(fs: ForceSolution) -> dict[str, Any]:
    """The ``forces`` object of docs/formats/json.md (plus ``method``, ``shaking``, ``notes``)."""
    joints = {}
    tiny = VERDICT_REL * fs.scale  # round-off of the forces: 0 on every machine
    for j in fs.joints:
        f = fs.forces[j.key][:2]
        f = np.where(np.abs(f) <= tiny, 0.0, f) + 0.0
        joints[j.key] = {"force": f.tolist(),
                         "point": fs.point(j.key).tolist()}
    drives = {lid: {kind: value} for lid, (kind, value) in fs.drives.items()}
    out: dict[str, Any] = {"units": _units(fs), "method": fs.method, "joints": joints,
                           "drives": drives}
    if fs.inertia:
        out["inertia"] = {lid: {"force": f.force.tolist(), "point": f.point.tolist(),
                                "torque": f.torque, "offset": f.offset}
                          for lid, f in fs.inertia.items()}
    sh = fs.shaking
    if sh is not None:
        out["shaking"] = {"force": sh[0].tolist(), "moment": sh[1]}
    gears = tooth_forces_json(fs)   # gear teeth: transmitted and radial (Sec. 11.11)
    if gears:
        out["gears"] = gears
    if fs.notes:
        out["notes"] = list(fs.notes)
    return out


def _name(i: str, j: str) -> str:
    return f"F{i}{j}".translate(_SUB) if (i + j).isdigit() else f"F_{i}{j}"


def _num(x: float, digits: int = 4) -> str:
    """``x`` to ``digits`` significant figures, without an exponent for everyday sizes.

    >>> _num(33754.69), _num(5.877149), _num(0.000123456)
    ('33750', '5.877', '0.0001235')
    """
    ax = abs(x)
    if ax == 0 or not math.isfinite(x):
        return "0" if ax == 0 else str(x)
    if ax >= 1e9 or ax < 1e-6:
        return f"{x:.{digits}g}"
    r = float(f"{x:.{digits}g}")  # rounded to the significant figures
    places = max(0, digits - 1 - int(math.floor(math.log10(abs(r)))))
    return f"{r:.{places}f}"


def _mag(v: np.ndarray, unit: str, scale: float) -> str:
    """``|v| unit ∠θ``, or ``0 unit`` for a vector at round-off of ``scale`` (no direction)."""
    m = float(np.hypot(v[0], v[1]))
    if is_zero(m, scale):
        return f"0 {unit}"
    return f"{_num(m)} {unit} ∠{_deg(v):.2f}°"


def _two_force_state(fs: ForceSolution, lid: str) -> str | None:
    """"in compression" or "in tension" for a two-pin link carrying opposite pin forces."""
    if lid in fs.drives or fs.applied.get(lid):
        return None
    js = [j for j in fs.joints if lid in (j.lo, j.hi)]
    if len(js) != 2 or any(j.kind != "pin" for j in js):
        return None
    p = [fs.geometry.points[j.point] for j in js]
    f = [fs.force(j.other(lid), lid) for j in js]  # forces ON the link
    axis = p[1] - p[0]
    n = float(np.hypot(*axis))
    if n == 0:
        return None
    # the force on the first pin pointing toward the second pin pushes the link together
    push = float(f[0] @ axis) / n
    scale = fs.scale
    if not is_zero(float(np.hypot(*(f[0] + f[1]))), scale):
        return None
    s = sign(push, scale)
    if s == 0:
        return None
    return "in compression" if s > 0 else "in tension"


def forces_text(fs: ForceSolution) -> str:
    """The force analysis as the book states it (one block of lines)."""
    mech = fs.mechanism
    u = _units(fs)
    fu, tu = u["force"], u["torque"].replace("*", "·")
    how = ("by the graphic method (free bodies and force polygons)" if fs.method ==
           "construction" else "by the matrix method")
    kind = "Dynamic" if fs.dynamic else "Static"
    lines = [f"{kind} force analysis {how}"]
    fscale = fs.scale
    for n in fs.notes:
        lines.append(f"  note: {n}")
    if fs.inertia:
        lines.append("  inertia forces (d'Alembert, offset by h, Eq. 12.18)")
        for lid, f in fs.inertia.items():
            g = mech.inertia[lid].center
            sense = fs.sense(f.torque)
            lines.append(f"    -m{lid}A_{g} = {_mag(f.force, fu, fscale)}   -I_G{lid}α{lid} = "
                         f"{_num(abs(f.torque))} {tu} {sense}   h{lid} = {_num(f.offset)} "
                         f"{mech.length_unit}".rstrip())
    lines.append("  joint forces (F_ij: by link i on link j)")
    for j in sorted(fs.joints, key=lambda j: (id_order(j.lo), id_order(j.hi), j.key)):
        v = fs.forces[j.key][:2]
        row = f"    {_name(j.lo, j.hi)} = {_mag(v, fu, fscale)}"
        at = j.key.partition("@")[2]
        if at:
            row += f"  at {at}"
        lines.append(row)
    lines += _teeth_lines(fs, fu, tu)
    for lid in mech.moving:
        state = _two_force_state(fs, lid)
        if state:
            lines.append(f"    link {lid} is a two-force member {state}")
    for lid, (kind_, value) in fs.drives.items():
        if kind_ == "torque":
            sense = fs.sense(value)
            value = 0.0 if not sense else value
            name = f"T{1}{lid}".translate(_SUB) if lid.isdigit() else f"T_1{lid}"
            lines.append(f"  drive: {name} = {_num(abs(value), 6)} {tu} {sense}".rstrip())
        else:
            value = 0.0 if is_zero(value, fscale) else value
            lines.append(f"  drive: input force on link {lid} = {_num(value, 6)} {fu} "
                         "(along the slider's line)")
    sh = fs.shaking
    if sh is not None:
        lines.append(f"  shaking force F_s = {_mag(sh[0], fu, fscale)}, shaking moment M_s = "
                     f"{_num(sh[1], 6)} {tu} about the origin (Eqs. 12.23-12.24)")
    if fs.partials and len(fs.partials) > 1:
        lines.append("  superposition (Sec. 12.5): one analysis per loaded link")
        for p in fs.partials:
            lines.append(f"    {p.suffix} loads of link {p.link}: " + "; ".join(p.order))
    elif fs.partials:
        lines.append("  order: " + "; ".join(fs.partials[0].order))
    return "\n".join(lines) + "\n"


def _teeth_lines(fs: ForceSolution, fu: str, tu: str) -> list[str]:
    """Each gear pair's tooth force as Fig. 11.14b resolves it (Sec. 11.11)."""
    lines = []
    lu = fs.mechanism.length_unit
    for t in tooth_forces(fs):
        name = _name(t.mate, t.gear)
        toward = "toward" if t.radial >= 0 else "away from"
        lines.append(f"  gear teeth {t.key} (φ = {math.degrees(t.pressure_angle):g}°): "
                     f"{name} = {_num(t.force)} {fu} = transmitted {name}^t "
                     f"{_num(t.tangential)} {fu} + radial {name}^r {_num(abs(t.radial))} {fu} "
                     f"{toward} the center of {t.gear}")
        for lid, m in t.torque.items():
            lines.append(f"    its moment on {lid}: F^t R = {_num(abs(m))} {tu} {fs.sense(m)} "
                         f"(R = {_num(t.radius[lid])} {lu}, Eq. 11.12)".rstrip())
    return lines


def forces_section(sol: Any) -> dict[str, Any] | None:
    """The ``forces`` JSON section of a kinematic solution, or None (no loads, no masses)."""
    fs = forces_report(sol)
    return None if fs is None else forces_json(fs)


def forces_report(sol: Any) -> ForceSolution | None:
    """The force solution of a one-posture solution whose file has loads or masses."""
    mech = sol.mechanism
    if not getattr(mech, "has_forces", False):
        return None
    cached = getattr(sol, "_forces", None)
    if cached is None:
        from graphkin.forces.solve import solve_forces

        cached = solve_forces(sol)
        try:
            sol._forces = cached
        except AttributeError:  # pragma: no cover - a slotted solution
            pass
    return cached
