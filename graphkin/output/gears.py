"""The report of a gear pair in mesh: every quantity of Secs. 7.1-7.11 with its unit.

Lengths are in the gear file's length unit, angles in degrees (and the
angles of approach and recess in radians as well, as Eqs. 7.7-7.8 give
them).  Each measured quantity of the layout stands beside the book's closed
form (:mod:`graphkin.gears.analytic`), so a reader sees the construction
and the equation agree.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.1-7.11.
"""

from __future__ import annotations

import math
from typing import Any

from graphkin.gears import analytic
from graphkin.gears.mesh import Contact, GearPair, MeshLayout
from graphkin.gears.profile import ring_overlap
from graphkin.gears.tooth import Gear
from graphkin.text import g6, table

__all__ = ["gears_json", "gears_text", "undercut_offset"]


def undercut_offset(g: Gear) -> float:
    """The least offset of the rack cutter that cuts ``g`` without undercut (Eq. 7.21).

    The cutter's addendum is the gear's dedendum less the clearance.
    """
    return analytic.offset_for_no_undercut(g.dedendum - g.clearance, g.pitch_radius,
                                           g.pressure_angle)


def _gear(g: Gear, outside: float, operating: float, pair: GearPair) -> dict[str, Any]:
    tol = pair.tol.length(g.pitch_radius)
    k = (g.dedendum - g.clearance) / g.module
    pointed = g.pointed_radius()
    need = undercut_offset(g)
    return {
        "name": g.name, "link": g.link, "teeth": g.teeth,
        "module": g.module, "diametral_pitch": 1.0 / g.module,
        "pressure_angle": math.degrees(g.pressure_angle),
        "pitch_radius": g.pitch_radius, "operating_pitch_radius": operating,
        "base_radius": g.base_radius, "addendum": g.addendum, "dedendum": g.dedendum,
        "offset": g.offset, "outside_radius": outside, "root_radius": g.root_radius,
        "circular_pitch": g.circular_pitch, "base_pitch": g.base_pitch,
        "thickness_pitch": g.thickness,
        # inside a ring the base circle lies in the tooth space, not in a tooth
        "thickness_base": None if g.internal else float(g.thickness_at(g.base_radius)),
        "thickness_outside": float(g.thickness_at(outside)),
        "thickness_operating_pitch": float(g.thickness_at(operating)),
        "involute_angle_outside": math.degrees(math.acos(g.base_radius / outside)),
        "kind": str(g.kind),
        "pointed_radius": None if g.internal else pointed,
        "pointed": bool(outside > pointed + tol),
        "undercut_by_rack": bool(g.offset < need - tol) if not g.internal else False,
        "offset_for_no_undercut": need if not g.internal else None,
        "minimum_teeth_rack": math.ceil(analytic.minimum_teeth_rack(k, g.pressure_angle)
                                        - 1e-9),
    }


def _rack(g: Gear) -> dict[str, Any]:
    """A rack's entry: its radii are infinite (null), its pitches and thickness those of a gear."""
    none = ("teeth", "pitch_radius", "operating_pitch_radius", "base_radius", "outside_radius",
            "root_radius", "thickness_base", "thickness_outside", "thickness_operating_pitch",
            "involute_angle_outside", "pointed_radius", "offset_for_no_undercut",
            "minimum_teeth_rack")
    return {
        **dict.fromkeys(none), "name": g.name, "link": g.link, "module": g.module,
        "diametral_pitch": 1.0 / g.module, "pressure_angle": math.degrees(g.pressure_angle),
        "addendum": g.addendum, "dedendum": g.dedendum, "offset": 0.0,
        "circular_pitch": g.circular_pitch, "base_pitch": g.base_pitch,
        "thickness_pitch": g.thickness, "kind": str(g.kind), "pointed": False,
        "undercut_by_rack": False,
    }


def gears_json(lay: MeshLayout) -> dict[str, Any]:
    """The report as plain data (``graphkin gears --json``; keys in ``docs/formats/gears.md``)."""
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    ra2, ra3 = pair.outside_radii
    r2p, r3p = pair.operating_pitch_radii
    phi = lay.operating_pressure_angle
    phi_op = analytic.operating_pressure_angle(pair.standard_center_distance, pair.center,
                                               g2.pressure_angle)
    if g3.rack:
        return _rack_json(lay)
    if g3.internal:
        cp, pd = analytic.approach_recess_internal(ra2, ra3, g2.base_radius, g3.base_radius,
                                                   r2p, r3p, phi_op)
        least = analytic.minimum_teeth_internal(g3.addendum / g3.module, g2.pressure_angle,
                                                g3.teeth)
    else:
        cp, pd = analytic.approach_recess(ra2, ra3, g2.base_radius, g3.base_radius,
                                          pair.center, phi_op)
        k3 = (g3.dedendum - g3.clearance) / g3.module
        least = analytic.minimum_teeth(k3, g2.pressure_angle, g3.teeth)
    pitch_op = 2.0 * math.pi * r2p / g2.teeth
    backlash = pitch_op - float(g2.thickness_at(r2p)) - float(g3.thickness_at(r3p))
    if backlash < pair.tol.length(pair.center):   # round-off of the thicknesses' sum
        backlash = 0.0
    return {
        "title": pair.title,
        "units": {"length": pair.units, "angle": "deg"},
        "gears": {g.name: _gear(g, ra, rp, pair)
                  for g, ra, rp in ((g2, ra2, r2p), (g3, ra3, r3p))},
        "mesh": {
            "driver": g2.name, "driven": g3.name,
            "ratio": g3.teeth / g2.teeth,
            "standard_center_distance": pair.standard_center_distance,
            "tight_center_distance": pair.tight_center_distance,
            "center_distance": pair.center,
            "operating_pressure_angle": math.degrees(phi),
            "backlash": backlash,
            "points": {k: list(v) for k, v in lay.points.items()},
            "approach_CP": lay.approach, "recess_PD": lay.recess, "path_CD": lay.path,
            "contact_ratio": lay.contact_ratio,
            "contact_ratio_eq_7_9": analytic.contact_ratio(cp, pd, g2.base_pitch),
            "approach_angles": {"alpha2": math.degrees(lay.approach_angles[0]),
                                "alpha3": math.degrees(lay.approach_angles[1])},
            "recess_angles": {"beta2": math.degrees(lay.recess_angles[0]),
                              "beta3": math.degrees(lay.recess_angles[1])},
            "interference": lay.interference,
            "start": str(lay.start), "end": str(lay.end),
            "AC": max(lay.beyond_a, 0.0), "BD": max(lay.beyond_b, 0.0),
            "involute_contact_ratio": lay.involute_contact_ratio,
            "kind": str(g3.kind),
            "minimum_driver_teeth": None if math.isnan(least) else math.ceil(least - 1e-9),
            **_fouling(lay),
        },
    }


#: A pinion tooth entering a ring tooth by less than this many modules touches it (round-off).
FOULING_FLOOR = 1e-6


def _fouling(lay: MeshLayout) -> dict[str, Any]:
    """``tip_overlap`` and ``tip_interference`` of a ring (null for external gears)."""
    if not lay.pair.driven.internal:
        return {"tip_overlap": None, "tip_interference": None}
    depth = ring_overlap(lay.pair, lay.points)
    return {"tip_overlap": depth,
            "tip_interference": bool(depth > FOULING_FLOOR * lay.pair.driver.module)}


def _rack_json(lay: MeshLayout) -> dict[str, Any]:
    """:func:`gears_json` for a pinion and a rack: no center distance, the rack's radii null."""
    pair = lay.pair
    g2, g3 = pair.driver, pair.driven
    ra2 = pair.outside_radii[0]
    phi = g2.pressure_angle
    cp, pd = analytic.approach_recess_rack(ra2, g2.base_radius, g2.pitch_radius, g3.addendum,
                                           phi)
    cos = math.cos(lay.operating_pressure_angle)
    return {
        "title": pair.title,
        "units": {"length": pair.units, "angle": "deg"},
        "gears": {g2.name: _gear(g2, ra2, g2.pitch_radius, pair), g3.name: _rack(g3)},
        "mesh": {
            "driver": g2.name, "driven": g3.name, "ratio": None,
            "standard_center_distance": None, "tight_center_distance": None,
            "center_distance": None,
            "operating_pressure_angle": math.degrees(lay.operating_pressure_angle),
            "backlash": 0.0,
            "points": {k: list(v) for k, v in lay.points.items()},
            "approach_CP": lay.approach, "recess_PD": lay.recess, "path_CD": lay.path,
            "contact_ratio": lay.contact_ratio,
            "contact_ratio_eq_7_9": analytic.contact_ratio(cp, pd, g2.base_pitch),
            "approach_angles": {"alpha2": math.degrees(lay.approach_angles[0]),
                                "alpha3": None},
            "recess_angles": {"beta2": math.degrees(lay.recess_angles[0]), "beta3": None},
            # the rack moves R2 per radian of 2, the contact r2 = R2 cos φ along AB
            "rack_approach": lay.approach / cos, "rack_recess": lay.recess / cos,
            "interference": lay.interference,
            "start": str(lay.start), "end": str(lay.end),
            "AC": max(lay.beyond_a, 0.0), "BD": 0.0,
            "involute_contact_ratio": lay.involute_contact_ratio,
            "kind": str(g3.kind),
            "minimum_driver_teeth": math.ceil(analytic.minimum_teeth_rack(
                g3.addendum / g3.module, phi) - 1e-9),
            "tip_overlap": None, "tip_interference": None,
        },
    }


def _rack_text(lay: MeshLayout, data: dict[str, Any]) -> list[str]:
    """The pair's lines of :func:`gears_text` for a pinion and a rack."""
    u = data["units"]["length"]
    m = data["mesh"]
    c2, c3 = lay.pair.driver.name, lay.pair.driven.name
    rows = [
        ("pressure angle φ", g6(m["operating_pressure_angle"]), "°"),
        ("approach CP = a/sin φ (Eq. 7.10, R3 → ∞)", g6(m["approach_CP"]), u),
        ("recess PD (Eq. 7.11)", g6(m["recess_PD"]), u),
        ("path of contact CD", g6(m["path_CD"]), u),
        ("contact ratio CD/p_b, construction", g6(m["contact_ratio"]), ""),
        ("contact ratio, Eq. (7.9)", g6(m["contact_ratio_eq_7_9"]), ""),
        (f"angles of approach α2, recess β2 ({c2})",
         f"{g6(m['approach_angles']['alpha2'])}, {g6(m['recess_angles']['beta2'])}", "°"),
        (f"travel of {c3} in approach, in recess",
         f"{g6(m['rack_approach'])}, {g6(m['rack_recess'])}", u),
    ]
    lines = table(rows, "  ") + [""]
    if lay.interference:
        lines.append(f"  Interference (Sec. 7.7, Eq. 7.12): contact begins at C, {g6(m['AC'])} "
                     f"{u} before the interference point A: the rack's addendum line passes "
                     f"beyond A and its tip digs into the flank of {c2}.")
    else:
        lines.append("  No interference: C lies between A and P (Eq. 7.12); the rack's B lies "
                     "at infinity and does not bound the recess.")
    lines.append(f"  The fewest teeth on {c2} that mesh with this rack without interference "
                 f"(N ≥ 2a/(m sin² φ)): {m['minimum_driver_teeth']}"
                 + _shifted(c2, data["gears"][c2], u))
    if m["contact_ratio"] < 1.0:
        lines.append("  The contact ratio is below 1: at times no pair of teeth is in contact.")
    return lines


def gears_text(lay: MeshLayout) -> str:
    """The report as text (``graphkin gears FILE``)."""
    data = gears_json(lay)
    u = data["units"]["length"]
    m = data["mesh"]
    g2, g3 = (data["gears"][lay.pair.driver.name], data["gears"][lay.pair.driven.name])
    lines = [data["title"] or (f"Gears {g2['teeth']} and {g3['teeth']} teeth in mesh"
                               if g3["teeth"] is not None else
                               f"A pinion of {g2['teeth']} teeth and a rack"), ""]
    rows = [("", f"{g2['name']} ({g2['link']}, driver)", f"{g3['name']} ({g3['link']})", "")]
    spec = [
        ("teeth N", "teeth", ""), ("module m", "module", u),
        ("diametral pitch P", "diametral_pitch", f"teeth/{u}"),
        ("pressure angle φ", "pressure_angle", "°"),
        ("pitch radius R", "pitch_radius", u), ("base radius r", "base_radius", u),
        ("addendum a", "addendum", u), ("dedendum d", "dedendum", u),
        ("cutter offset e", "offset", u), ("outside radius", "outside_radius", u),
        ("root radius", "root_radius", u), ("circular pitch p", "circular_pitch", u),
        ("base pitch p_b", "base_pitch", u),
        ("thickness at R (Eq. 7.17)", "thickness_pitch", u),
        ("thickness at r (Eq. 7.16)", "thickness_base", u),
        ("thickness at outside", "thickness_outside", u),
        ("operating pitch radius R'", "operating_pitch_radius", u),
    ]
    for name, key, unit in spec:
        rows.append((name, *("—" if g[key] is None else g6(g[key]) for g in (g2, g3)), unit))
    rows.append(("undercut by a rack cutter", _yes(g2["undercut_by_rack"]),
                 _yes(g3["undercut_by_rack"]), ""))
    rows.append(("pointed teeth", _yes(g2["pointed"]), _yes(g3["pointed"]), ""))
    lines += table(rows, "  ")
    lines.append("")
    if lay.pair.driven.rack:
        return "\n".join(lines + _rack_text(lay, data)) + "\n"
    c2, c3 = g2["name"], g3["name"]
    pair_rows = [
        ("speed ratio ω2/ω3 = N3/N2", g6(m["ratio"]), ""),
        ("standard center distance R3 − R2" if m["kind"] == "internal" else
         "standard center distance R2 + R3", g6(m["standard_center_distance"]), u),
        ("center distance", g6(m["center_distance"]), u),
        ("operating pressure angle φ'", g6(m["operating_pressure_angle"]), "°"),
        ("backlash on the pitch circles", g6(m["backlash"]), u),
        ("approach CP (Eq. 7.10)", g6(m["approach_CP"]), u),
        ("recess PD (Eq. 7.11)", g6(m["recess_PD"]), u),
        ("path of contact CD", g6(m["path_CD"]), u),
        ("contact ratio CD/p_b, construction", g6(m["contact_ratio"]), ""),
        ("contact ratio, Eq. (7.9)", g6(m["contact_ratio_eq_7_9"]), ""),
        (f"angles of approach α2 ({c2}), α3 ({c3})",
         f"{g6(m['approach_angles']['alpha2'])}, {g6(m['approach_angles']['alpha3'])}", "°"),
        (f"angles of recess β2 ({c2}), β3 ({c3})",
         f"{g6(m['recess_angles']['beta2'])}, {g6(m['recess_angles']['beta3'])}", "°"),
    ]
    lines += table(pair_rows, "  ")
    lines.append("")
    if lay.interference:
        where = []
        if lay.start == Contact.INTERFERENCE:
            where.append(f"contact begins at C, {g6(m['AC'])} {u} before the interference "
                         f"point A: the tip of {c3} digs into the flank of {c2}")
        if lay.end == Contact.INTERFERENCE:
            where.append(f"contact ends at D, {g6(m['BD'])} {u} after the interference point "
                         f"B: the tip of {c2} digs into the flank of {c3}")
        lines.append("  Interference (Sec. 7.7, Eq. 7.12): " + "; ".join(where) + ".")
        lines.append(f"  The involute action (from A or C to D or B) has a contact ratio of "
                     f"{g6(m['involute_contact_ratio'])}.")
    elif m["kind"] == "internal":
        lines.append(f"  No interference: C lies between A and P (Eq. 7.12); inside "
                     f"{c3} the point B lies beyond A and does not bound the recess (Fig. 7.11).")
    else:
        lines.append("  No interference: C and D lie between the interference points A and B "
                     "(Eq. 7.12).")
    if m["tip_interference"]:
        lines.append(f"  Tip interference (fouling): away from the path of contact the teeth of "
                     f"{c2} enter those of {c3} by up to {g6(m['tip_overlap'])} {u} as they "
                     "turn; the ring needs more teeth, or stub teeth.")
    elif m["kind"] == "internal":
        lines.append(f"  No tip interference: the teeth of {c2} clear those of {c3} through a "
                     "whole pitch of the motion.")
    least = m["minimum_driver_teeth"]
    lines.append(f"  The fewest teeth on {c2} that mesh with {g3['teeth']} teeth without "
                 f"interference: {least if least is not None else 'none (no pinion fits)'}"
                 + _shifted(c2, g2, u))
    if m["contact_ratio"] < 1.0:
        lines.append("  The contact ratio is below 1: at times no pair of teeth is in contact "
                     "(Sec. 7.9).")
    return "\n".join(lines) + "\n"


def _shifted(name: str, gear: dict, unit: str) -> str:
    """The end of the fewest-teeth sentence: for standard teeth, and the driver's offset.

    The fewest teeth are those of standard teeth, cut with the rack cutter's
    pitch line on the pitch circle; a pinion cut with the cutter offset (Sec.
    7.11: a profile shift, Eq. 7.21 for the offset that avoids undercut) can
    have fewer, as this one may.
    """
    off = float(gear.get("offset") or 0.0)
    if off == 0.0:
        return "."
    return (f" for standard teeth; {name} is cut with the cutter offset e = {g6(off)} {unit} "
            "(a profile shift, Sec. 7.11), which that count does not take into account: the "
            "interference above is that of its shifted teeth.")


def _yes(flag: bool) -> str:
    return "yes" if flag else "no"
