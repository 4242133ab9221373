"""The cams of a mechanism file at the drive's cam angle (``[[cams]]``, Secs. 4.7, 6.9-6.10).

A cam mechanism is solved as its equivalent linkage through the centers of
curvature (:mod:`graphkin.cams.joint`); this section says what that linkage
stands for: the cam angle Θ, the follower's lift, the contact point, the
common normal and the pressure angle at the contact, and the follower's
velocity and acceleration from its program (y'Θ̇, y''Θ̇² + y'Θ̈, Eqs. 6.9-6.11),
which the polygons of the linkage reproduce.  It reads the mechanism's
``cams`` (plain values) and imports nothing of the cam layer.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING, Any

from graphkin.text import g6

if TYPE_CHECKING:
    from graphkin.kinematics.solution import Solution
    from graphkin.output.units import OutputUnits

__all__ = ["cams_json", "cams_text"]


def _rows(sol: Solution) -> list[dict[str, Any]]:
    mech = sol.mechanism
    out = []
    for j in mech.cams:
        cam = j.cam
        osc = cam.follower.kind.oscillating
        k = cam.program.evaluate([j.theta])
        row: dict[str, Any] = {
            "key": j.key, "cam": j.link, "follower": j.follower,
            "kind": cam.follower.kind.value,
            "coupler": j.coupler or None,
            "theta": math.degrees(j.theta),
            "lift": math.degrees(j.Y) if osc else j.Y,
            "contact": list(j.contact),
            "normal": math.degrees(math.atan2(j.normal[1], j.normal[0])),
            "pressure_angle": math.degrees(j.pressure),
        }
        drive = next((d for d in mech.drives if d.link == j.link), None)
        if drive is not None and drive.rate is not None:
            w = cam.s * drive.rate
            a = cam.s * (drive.rate2 or 0.0)
            f = 1.0 if osc else j.scale
            v = float(k.y1[0]) * w * f
            acc = (float(k.y2[0]) * w * w + float(k.y1[0]) * a) * f
            sig = cam.follower.rise.sign if osc else 1.0
            row["follower_rate"] = sig * v
            row["follower_rate2"] = sig * acc
        out.append(row)
    return out


def cams_json(sol: Solution, units: OutputUnits) -> list[dict[str, Any]] | None:
    """One object per cam (docs/formats/mechanism.md, "Cams"), or None without cams.

    Lengths are in the output's length unit, angles in degrees; ``follower_rate`` and
    ``follower_rate2`` are the follower's velocity and acceleration along its line
    (ω4 and α4 for an oscillating follower) from its program.
    """
    if not sol.mechanism.cams:
        return None
    rows = _rows(sol)
    for r, j in zip(rows, sol.mechanism.cams):
        osc = j.cam.follower.kind.oscillating
        r["contact"] = [c * units.k_length for c in r["contact"]]
        if not osc:
            r["lift"] *= units.k_length
        if "follower_rate" in r:
            r["follower_rate"] *= units.k_omega if osc else units.k_velocity
            r["follower_rate2"] *= units.k_alpha if osc else units.k_acceleration
    return rows


def cams_text(sol: Solution, units: OutputUnits) -> str | None:
    """Per cam: Θ, the lift, the contact, the common normal, φ, and the follower's rates."""
    if not sol.mechanism.cams:
        return None
    lines = []
    for r, j in zip(cams_json(sol, units) or [], sol.mechanism.cams):
        osc = j.cam.follower.kind.oscillating
        lu = units.text("length")
        lift = f"{g6(r['lift'])}°" if osc else f"{g6(r['lift'])} {lu}"
        how = (f"coupler {r['coupler']} through the centers of curvature K{j.follower}-"
               f"T{j.follower}" if r["coupler"] else f"K{j.follower} in a slot parallel "
               "to the face")
        lines.append(f"  {r['key']}: cam {r['cam']}, {r['kind']} follower {r['follower']} "
                     f"at Θ = {g6(r['theta'])}° (equivalent linkage: {how}, Sec. 4.7)")
        lines.append(f"    lift Y = {lift}   contact C = ({g6(r['contact'][0])}, "
                     f"{g6(r['contact'][1])}) {lu}   common normal ∠{r['normal']:.2f}°   "
                     f"pressure angle φ = {r['pressure_angle']:.2f}°")
        if "follower_rate" in r:
            if osc:
                lines.append(f"    from the program: ω{j.follower} = "
                             f"{g6(r['follower_rate'])} {units.text('omega')}, α{j.follower} "
                             f"= {g6(r['follower_rate2'])} {units.text('alpha')} (y'Θ̇, "
                             "y''Θ̇² + y'Θ̈)")
            else:
                lines.append(f"    from the program: V = y'Θ̇ = {g6(r['follower_rate'])} "
                             f"{units.text('velocity')}, A = y''Θ̇² + y'Θ̈ = "
                             f"{g6(r['follower_rate2'])} {units.text('acceleration')} "
                             "along the follower's line")
    return "\n".join(lines)
