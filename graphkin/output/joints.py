"""Joint angles θ_{i/j} = θ_i − θ_j of the pins between moving links (Problems 5.7-5.11).

A robot's joint motor turns one link relative to the next: the file drives
such an angle with ``[[drive]] link = 3, relative_to = 2``, and the answers
the book asks for are joint angles too (θ5/4 and ω5/4 of the second robot
of Problem 5.7).  When a file has a relative drive, the report gives the
joint angle, its rate ``ω_{i/j} = ω_i − ω_j`` and ``α_{i/j} = α_i − α_j``
at every pin between two moving links, and at every relative drive.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from graphkin.mechanisms.model import FRAME
from graphkin.text import clean, g6, sense, wrap_degrees

if TYPE_CHECKING:
    from graphkin.kinematics.solution import Solution
    from graphkin.output.units import OutputUnits

__all__ = ["joint_angles_json", "joint_angles_text", "joint_pairs"]


def joint_pairs(sol: Solution) -> list[tuple[str, str]]:
    """(i, j) for each relative drive and each pin between two moving links, once each."""
    mech = sol.mechanism
    if not any(d.kind == "relative" for d in mech.drives):
        return []
    out: list[tuple[str, str]] = []
    for d in mech.drives:
        if d.kind == "relative" and d.relative_to is not None:
            out.append((d.link, d.relative_to))
    for pin in mech.pins:
        moving = [k for k in pin.links if k != FRAME]
        for a in range(len(moving)):
            for b in range(a + 1, len(moving)):
                # the later link relative to the earlier one: θ3/2, θ5/4
                i, j = moving[b], moving[a]
                if (i, j) not in out and (j, i) not in out:
                    out.append((i, j))
    return out


def _values(sol: Solution, i: str, j: str) -> tuple[float, float | None, float | None]:
    a, b = sol.links[i], sol.links[j]
    angle = wrap_degrees(float(a.angle) - float(b.angle))
    w = None if a.omega is None or b.omega is None else float(a.omega) - float(b.omega)
    al = None if a.alpha is None or b.alpha is None else float(a.alpha) - float(b.alpha)
    return angle, w, al


def joint_angles_json(sol: Solution, units: OutputUnits) -> dict[str, Any] | None:
    """``{"3/2": {"angle": deg, "omega": ..., "alpha": ...}}``, or None without a relative drive."""
    pairs = joint_pairs(sol)
    if not pairs:
        return None
    out: dict[str, Any] = {}
    for i, j in pairs:
        angle, w, al = _values(sol, i, j)
        entry: dict[str, Any] = {"angle": angle}
        if sol.mechanism.has_rates:
            entry["omega"] = None if w is None else w * units.k_omega
            entry["alpha"] = None if al is None else al * units.k_alpha
        out[f"{i}/{j}"] = entry
    return out


def joint_angles_text(sol: Solution, units: OutputUnits) -> str | None:
    """``θ3/2 = -15.0000°   ω3/2 = 15 rad/s ccw   α3/2 = 0 rad/s²`` per joint."""
    pairs = joint_pairs(sol)
    if not pairs:
        return None
    from graphkin.output.solution import rate_floors

    floors = rate_floors(sol)
    rows = []
    for i, j in pairs:
        angle, w, al = _values(sol, i, j)
        row = f"  θ{i}/{j} = {clean(round(angle, 4)):.4f}°"
        if w is not None:
            w = clean(w, floors.omega)
            row += (f"   ω{i}/{j} = {g6(abs(w) * units.k_omega)} {units.text('omega')} "
                    f"{sense(w)}").rstrip()
        if al is not None:
            al = clean(al, floors.alpha)
            row += (f"   α{i}/{j} = {g6(abs(al) * units.k_alpha)} {units.text('alpha')} "
                    f"{sense(al)}").rstrip()
        rows.append(row)
    return "\n".join(rows)
