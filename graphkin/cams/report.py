"""The report of a cam: text with units, and the same as JSON (``graphkin cam``).

Also the one check the command makes before drawing: a follower that cannot
follow (an undercut profile, Figs. 6.25 and 6.29) is one line naming the
segment and the cam angles, with the least prime circle that would do.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.3-6.10.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.cams import design
from graphkin.cams.analytic import profile
from graphkin.cams.layout import layout, stations
from graphkin.cams.model import FollowerKind
from graphkin.cams.parse import CamFile
from graphkin.errors import InputError
from graphkin.text import g6, table, unit_text
from graphkin.tolerance import first_largest
from graphkin.units import length_factor

__all__ = ["refuse_undercut", "cam_json", "cam_text", "profile_table", "profile_csv",
           "steps_text"]


def _deg(rad: float) -> float:
    return math.degrees(rad)


def refuse_undercut(cf: CamFile) -> None:
    """Raise an :class:`InputError` when the follower cannot follow the profile.

    Raises
    ------
    InputError
        ``segment 1 (cycloidal rise): the profile is undercut from Θ = 47.3° to 62.1° ...``
    """
    cam = cf.cam
    cuts = design.undercuts(cam)
    if not cuts:
        return
    c = cuts[0]
    what = {FollowerKind.FLAT_FACE: "ρ = R0 + Y + y'' < 0, Eq. 6.27",
            FollowerKind.OSCILLATING_FLAT_FACE: "the face's envelope folds back on itself",
            FollowerKind.KNIFE_EDGE: "the pitch curve has no point there",
            }.get(cam.follower.kind,
                  "the roller is larger than the pitch curve's radius of curvature, Fig. 6.29")
    need = _safe(lambda: design.min_prime_for_curvature(cam, 0.0))
    more = f"; a prime circle of at least {g6(need)} {cam.unit} would do" if need else ""
    raise InputError(f"{cam.program.label(c.segment)}: the profile is undercut from "
                     f"Θ = {_deg(c.start):.4g}° to {_deg(c.end):.4g}° ({what}): the follower "
                     f"cannot follow{more} (or --allow-undercut to draw it)",
                     key=f"segment[{c.segment}]", file=cam.source or None)


def _safe(f: Any) -> float | None:
    try:
        v = float(f())
    except (ValueError, InputError):
        return None
    return v if math.isfinite(v) else None


def cam_json(cf: CamFile) -> dict[str, Any]:
    """The report as plain data (lengths in the file's unit, angles in degrees)."""
    cam = cf.cam
    prog = cam.program
    starts = prog.starts
    angular = cam.follower.kind.oscillating
    segs = [{"name": s.name or f"{k + 1}", "motion": s.motion.value, "kind": s.kind,
             "lift": _deg(s.lift) if angular else s.lift, "angle": _deg(s.angle),
             "start": _deg(float(starts[k])), "rest": None if s.rest is None else s.rest.value,
             "equation": s.equation}
            for k, s in enumerate(prog.segments)]
    chk = design.check(cam)
    out: dict[str, Any] = {
        "title": cam.title, "unit": cam.unit,
        "cam": {"prime": cam.prime, "base": cam.base, "rotation": cam.sense.value,
                "speed": cam.omega},
        "follower": {"kind": cam.follower.kind.value, "offset": cam.follower.offset,
                     "roller": cam.follower.roller if cam.follower.kind.roller else None},
        "segments": segs,
        "warnings": prog.warnings("rad" if angular else cam.unit),
        "pressure_angle": {"max": _deg(chk.pressure.value), "at": _deg(chk.pressure.theta)},
        "radius_of_curvature": None if chk.rho is None else
        {"min": chk.rho.value, "at": _deg(chk.rho.theta)},
        "pitch_radius_of_curvature": None if chk.rho_pitch is None else
        {"min": chk.rho_pitch.value, "at": _deg(chk.rho_pitch.theta)},
        "undercut": [{"segment": prog.label(u.segment), "from": _deg(u.start),
                      "to": _deg(u.end)} for u in chk.undercut],
    }
    if chk.face is not None:
        left, right = chk.face
        out["face"] = {"left": left, "right": right, "min_width": left + right,
                       "given": cam.follower.face}
    if cf.pressure_angle is not None:
        out["min_prime_for_pressure_angle"] = {
            "pressure_angle": _deg(cf.pressure_angle),
            "prime": _safe(lambda: design.min_prime_for_pressure(cam, cf.pressure_angle))}
    if cf.radius is not None:
        out["min_prime_for_radius"] = {
            "radius": cf.radius,
            "prime": _safe(lambda: design.min_prime_for_curvature(cam, cf.radius))}
    if cf.dynamics is not None:
        spring, preload, mass = cf.dynamics
        f = length_factor(cam.unit)       # the program's lengths in metres: SI throughout
        jump = design.jump_speed(prog, spring * f, preload, mass * f)
        ok = math.isfinite(jump.value)
        out["jump"] = {"omega": jump.value if ok else None,
                       "rev_per_min": jump.value * 30 / math.pi if ok else None,
                       "at": _deg(jump.theta)}
    if cam.omega is not None:
        k = prog.evaluate(stations(design.GRID))
        v, a, j = k.rates(cam.omega)
        out["rates"] = {"omega": cam.omega, **{
            # of equal maxima (a symmetric program) the first in cam angle, not round-off's
            name: {"max": float(np.max(np.abs(x))),
                   "at": _deg(float(k.theta[first_largest(np.abs(x), periodic=True)]))}
            for name, x in (("velocity", v), ("acceleration", a), ("jerk", j))}}
    return out


def cam_text(cf: CamFile) -> str:
    """The report as text with units (what ``graphkin cam FILE`` prints)."""
    d = cam_json(cf)
    cam = cf.cam
    u = cam.unit
    ang = cam.follower.kind.oscillating
    lines = [f"Cam{': ' + cam.title if cam.title else ''}",
             f"  follower: {cam.follower.kind.value}"
             + (f", offset ε = {g6(cam.follower.offset)} {u}" if cam.follower.offset else "")
             + (f", roller R_r = {g6(cam.follower.roller)} {u}" if cam.follower.kind.roller
                else ""),
             f"  prime circle R0 = {g6(cam.prime)} {u}, base circle {g6(cam.base)} {u}, "
             f"turning {cam.sense.value}"
             + (f" at {g6(cam.omega)} rad/s" if cam.omega else ""),
             "", "Program (Sec. 6.3)"]
    rows = [("#", "name", "motion", "lift", "β", "from Θ", "book")]
    for k, s in enumerate(d["segments"]):
        motion = s["motion"] + (f" ({s['rest']})" if s["rest"] else "")
        lift = f"{g6(s['lift'])}{'°' if ang else ' ' + u}"
        rows.append((str(k + 1), s["name"], motion, lift, f"{g6(s['angle'])}°",
                     f"{g6(s['start'])}°", s["equation"]))
    lines += table(rows, "  ")
    lines += ["", "Matching of derivatives (Sec. 6.8)"]
    lines += [f"  {w}" for w in d["warnings"]] or ["  y, y' and y'' are continuous at every joint"]
    lines += ["", "Design checks (Secs. 6.9-6.10)"]
    p = d["pressure_angle"]
    if cam.follower.kind is FollowerKind.FLAT_FACE:
        lines.append("  pressure angle: 0° throughout (the face is square to its motion)")
    else:
        lines.append(f"  pressure angle: largest |φ| = {g6(p['max'])}° at Θ = {g6(p['at'])}°")
    r = d["radius_of_curvature"]
    lines.append("  radius of curvature of the profile: " +
                 ("nowhere convex" if r is None else
                  f"least {g6(r['min'])} {u} at Θ = {g6(r['at'])}° (convex)"))
    if d["pitch_radius_of_curvature"] is not None:
        q = d["pitch_radius_of_curvature"]
        lines.append(f"  radius of curvature of the pitch curve: least {g6(q['min'])} {u} at "
                     f"Θ = {g6(q['at'])}° (convex)")
    for c in d["undercut"]:
        lines.append(f"  UNDERCUT: {c['segment']}, Θ = {g6(c['from'])}° to {g6(c['to'])}°")
    if not d["undercut"]:
        lines.append("  no undercutting")
    if "face" in d:
        f = d["face"]
        lines.append(f"  face: contact from {g6(f['left'])} {u} left to {g6(f['right'])} {u} "
                     f"right: width at least {g6(f['min_width'])} {u} (Eq. 6.29)"
                     + ("" if f["given"] is None else
                        f"; given {g6(f['given'])} {u}"
                        + (" — TOO NARROW" if f["given"] < f["min_width"] else "")))
    if "min_prime_for_pressure_angle" in d:
        m = d["min_prime_for_pressure_angle"]
        lines.append(f"  least prime circle for |φ| ≤ {g6(m['pressure_angle'])}°: "
                     f"R0 = {'—' if m['prime'] is None else g6(m['prime'])} {u}")
    if "min_prime_for_radius" in d:
        m = d["min_prime_for_radius"]
        lines.append(f"  least prime circle for a radius of curvature ≥ {g6(m['radius'])} {u}: "
                     f"R0 = {'—' if m['prime'] is None else g6(m['prime'])} {u}")
    if "jump" in d:
        j = d["jump"]
        lines.append("  jump (Sec. 6.12): " + ("the spring holds the follower at any speed"
                                               if j["omega"] is None else
                                               f"the follower leaves the cam above ω = "
                                               f"{g6(j['omega'])} rad/s = "
                                               f"{g6(j['rev_per_min'])} rev/min, at Θ = "
                                               f"{g6(j['at'])}°"))
    if "rates" in d:
        lines += ["", f"Follower at ω = {g6(cam.omega or 0)} rad/s (Eq. 6.11)"]
        lu = "rad" if ang else u
        for name, unit in (("velocity", unit_text(f"{lu}/s")),
                           ("acceleration", unit_text(f"{lu}/s^2")),
                           ("jerk", unit_text(f"{lu}/s^3"))):
            x = d["rates"][name]
            lines.append(f"  largest |{name}| = {g6(x['max'] if not ang else x['max'])} {unit}"
                         f" at Θ = {g6(x['at'])}°")
    return "\n".join(lines) + "\n"


def profile_table(cf: CamFile, n: int = 360) -> list[tuple[float, ...]]:
    """The profile's coordinates at ``n`` equal cam angles: Θ (deg), u, v, R, ψ (deg), ρ.

    ``u, v`` are the contact point in the cam's frame (Eq. 6.30 or 6.36), R and
    ψ its polar coordinates (Eq. 6.31), ρ the profile's radius of curvature.
    """
    th = stations(n)
    pr = profile(cf.cam, th)
    c = pr.contact
    return [(float(_deg(t)), float(z.real), float(z.imag), float(abs(z)),
             float(np.degrees(np.angle(z))), float(rho))
            for t, z, rho in zip(th, c, pr.rho)]


def profile_csv(cf: CamFile, n: int = 360) -> str:
    """:func:`profile_table` as CSV text with a header naming the units."""
    u = cf.cam.unit
    head = f"theta_deg,u_{u},v_{u},R_{u},psi_deg,rho_{u}"
    return "\n".join([head] + [",".join(f"{x:.12g}" for x in row)
                               for row in profile_table(cf, n)]) + "\n"


def steps_text(cf: CamFile) -> str:
    """The recorded steps of one station of the layout, in order, with what each one draws.

    The same steps are evaluated at every station (Sec. 6.4): this is the
    list a student follows with ruler, compass and dividers.
    """
    cx = layout(cf.cam).construction
    rows = [("#", "label", "operation", "from", "what it is")]
    for s in cx:
        rows.append((str(s.index + 1), s.label, s.op, ", ".join(s.inputs), s.note))
    head = [f"The layout by inversion, one station (Sec. 6.4): {cx.title}",
            "The given inputs phi, Y, y1 are read off the displacement diagram at the station.",
            ""]
    return "\n".join(head + table(rows, "  ")) + "\n"
