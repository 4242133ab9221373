"""The report of a synthesis: text and JSON (``graphkin synthesize``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Ch. 9.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.synthesis.linkage import Linkage
from graphkin.synthesis.run import Result
from graphkin.text import fmt

__all__ = ["synthesis_json", "synthesis_text"]


def _xy(z: complex) -> list[float]:
    return [float(z.real), float(z.imag)]


def _linkage(link: Linkage) -> dict[str, Any]:
    na, nb = link.names
    return {"fixed_pivots": {f"O_{na}": _xy(link.o_a), f"O_{nb}": _xy(link.o_b)},
            "moving_pivots": {f"{na}1": _xy(link.a1), f"{nb}1": _xy(link.b1)},
            "lengths": {k: float(v) for k, v in link.lengths.items()},
            "crank_angles_deg": [float(math.degrees(a)) for a in link.crank_angles()],
            "checks": [{"name": c.name, "passed": c.passed, "detail": c.detail}
                       for c in link.checks], "ok": link.ok}


def _half_turn(deg: float) -> float:
    """An angle in (-180°, 180°]: a half turn, -180° within round-off, is written 180°."""
    return 180.0 if deg <= -180.0 + 1e-9 else deg


def synthesis_json(res: Result) -> dict[str, Any]:
    """The result as plain data (floats in the file's length unit, angles in degrees)."""
    out: dict[str, Any] = {"title": res.spec.title, "kind": res.kind, "units": res.spec.units}
    if res.construction is not None:
        ev = res.construction.evaluate({"t": np.array(0.0)} if "t" in res.construction.labels
                                       else None, strict=False)
        out["poles"] = {s.label: _xy(complex(ev[s.label][0] / ev[s.label][2],
                                             ev[s.label][1] / ev[s.label][2]))
                        for s in res.construction if s.label.startswith("P")
                        and s.role == "result" and s.kind == "point"}
        post = res.postures
        if post is not None and res.cognates is None and res.function is None:
            # the rotation angle θij of each pole (Eq. 9.2), in (-180°, 180°]
            out["rotation_angles_deg"] = {
                f"θ{k[1:]}": _half_turn(float(math.degrees(math.remainder(
                    float(post.angles[int(k[2]) - 1] - post.angles[int(k[1]) - 1]), math.tau))))
                for k in out["poles"]}
        out["steps"] = res.construction.to_dict()
    if res.burmester:
        out["burmester_points"] = [{"center": _xy(p.center), "circle": _xy(p.circle)}
                                   for p in res.burmester]
    out["candidates"] = [_linkage(c) for c in res.candidates]
    if res.dwell is not None:
        dw = res.dwell
        slider = dw.kind == "slider"
        out["dwell"] = {"kind": str(dw.kind), "O6": _xy(dw.o6),
                        **({"slot_at_middle": dw.radius, "line_deviation": dw.deviation}
                           if slider else
                           {"D": _xy(dw.d), "link_5": dw.radius,
                            "link_6": float(abs(dw.d - dw.o6)), "arc_deviation": dw.deviation}),
                        "crank_from_deg": float(np.degrees(dw.crank[dw.start]) % 360),
                        "crank_span_deg": float(np.degrees(dw.crank[1] - dw.crank[0])
                                                * (dw.stop - dw.start))}
    if res.crank_rocker is not None:
        cr = res.crank_rocker
        adv = float(np.degrees((cr.theta_b - cr.theta_a) % math.tau))
        out["crank_rocker"] = {
            "O2": _xy(cr.o2), "O4": _xy(cr.o4), "A1": _xy(cr.a1), "B1": _xy(cr.b1),
            "B2": _xy(cr.b2), "lengths": {"r1": float(abs(cr.o4 - cr.o2)), "r2": cr.r2,
                                          "r3": cr.r3, "r4": cr.r4},
            "advance_deg": adv, "return_deg": 360.0 - adv, "Q": cr.q,
            "crank_at_B1_deg": float(np.degrees(cr.theta_a)),
            "crank_at_B2_deg": float(np.degrees(cr.theta_b))}
    if res.overlay is not None:
        ov = res.overlay
        out["overlay"] = {"O2": _xy(ov.o2), "O4": _xy(ov.o4), "A": _xy(ov.a), "B": _xy(ov.b),
                          "P": _xy(ov.p), "residual": ov.residual, "reversed": ov.reversed,
                          "lengths": {"crank": abs(ov.a - ov.o2), "coupler": abs(ov.b - ov.a),
                                      "rocker": abs(ov.b - ov.o4),
                                      "ground": abs(ov.o4 - ov.o2)},
                          "atlas_row": [float(v) for v in ov.dims]}
    if res.cognates is not None:
        z = res.cognates.points
        out["cognates"] = {w: {lab: _xy(z[lab]) for lab in labs}
                           for w, labs in res.cognates.linkages().items()}
    if res.dyads:
        out["dyads"] = {k: (_xy(v) if k.startswith("r") else float(np.degrees(v.real)))
                        for k, v in res.dyads.items()}
    if res.function is not None:
        f = res.function
        out["function"] = {
            "expression": f.spec.expression, "x": f.x.tolist(), "y": f.y.tolist(),
            "phi_deg": np.degrees(f.phi).tolist(), "psi_deg": np.degrees(f.psi).tolist(),
            "K": f.k.tolist(), "lengths": {"r1": f.lengths[0], "r2": f.lengths[1],
                                           "r3": f.lengths[2], "r4": f.lengths[3]},
            "max_structural_error": float(np.nanmax(np.abs(f.error)))}
    return out


def synthesis_text(res: Result) -> str:
    """The result as a text report."""
    lines = [res.spec.title or "Synthesis", f"{res.kind}", ""]
    data = synthesis_json(res)
    if data.get("poles"):
        lines.append("Poles: " + ", ".join(f"{k} = ({fmt(v[0])}, {fmt(v[1])})"
                                            for k, v in data["poles"].items()))
    if data.get("rotation_angles_deg"):
        lines.append("Rotation angles (Eq. 9.2): " + ", ".join(
            f"{k} = {fmt(v)}°" for k, v in data["rotation_angles_deg"].items()))
    if res.burmester:
        lines.append(f"Burmester points: {len(res.burmester)} real")
        for p in res.burmester:
            lines.append(f"  center ({fmt(p.center.real)}, {fmt(p.center.imag)})  "
                         f"circle ({fmt(p.circle.real)}, {fmt(p.circle.imag)})")
    if "dwell" in data and data["dwell"]["kind"] == "slider":
        d = data["dwell"]
        lines.append(f"Dwell with a slider (Sec. 9.13, Fig. 9.44): O6 = ({fmt(d['O6'][0])}, "
                     f"{fmt(d['O6'][1])}) on the line of the straight stretch, O6C = "
                     f"{fmt(d['slot_at_middle'])} at its middle; the coupler point stays "
                     f"within {fmt(d['line_deviation'])} of the line for "
                     f"{fmt(d['crank_span_deg'])}° of crank from {fmt(d['crank_from_deg'])}°")
    elif "dwell" in data:
        d = data["dwell"]
        lines.append(f"Dwell (Sec. 9.13): D = ({fmt(d['D'][0])}, {fmt(d['D'][1])}), "
                     f"O6 = ({fmt(d['O6'][0])}, {fmt(d['O6'][1])}), link 5 = "
                     f"{fmt(d['link_5'])}, link 6 = {fmt(d['link_6'])}; the coupler point "
                     f"stays within {fmt(d['arc_deviation'])} of the arc for "
                     f"{fmt(d['crank_span_deg'])}° of crank from {fmt(d['crank_from_deg'])}°")
    if "crank_rocker" in data:
        c = data["crank_rocker"]
        lines.append("Crank-rocker from the limit postures (Sec. 9.3, Fig. 9.3): " + ", ".join(
            f"{k} = ({fmt(c[k][0])}, {fmt(c[k][1])})" for k in ("O2", "O4", "B1", "B2")))
        lines.append("  " + ", ".join(f"{k} {fmt(v)}" for k, v in c["lengths"].items())
                     + f" {res.spec.units}")
        lines.append(f"  the crank turns {fmt(c['advance_deg'])}° counterclockwise from B1 to "
                     f"B2 and {fmt(c['return_deg'])}° back: Q = {fmt(c['Q'])} (Eq. 9.1)")
    if "overlay" in data:
        o = data["overlay"]
        lines.append("Overlay (Sec. 9.8): the atlas curve of crank 1, coupler "
                     f"{fmt(o['atlas_row'][1])}, rocker {fmt(o['atlas_row'][2])}, frame "
                     f"{fmt(o['atlas_row'][3])}, point ({fmt(o['atlas_row'][4])}, "
                     f"{fmt(o['atlas_row'][5])}) fits the path to {fmt(100 * o['residual'])} % "
                     "of its size (RMS)")
        lines.append("  " + ", ".join(f"{k} = ({fmt(o[k][0])}, {fmt(o[k][1])})"
                                      for k in ("O2", "O4", "A", "B", "P")))
        lines.append("  " + ", ".join(f"{k} {fmt(v)}" for k, v in o["lengths"].items()))
    if "cognates" in data:
        for w, labs in data["cognates"].items():
            lines.append(f"Cognate {w}: " + ", ".join(
                f"{k} = ({fmt(v[0])}, {fmt(v[1])})" for k, v in labs.items()))
    if "dyads" in data:
        lines.append("Dyads (Sec. 9.12): " + ", ".join(
            f"{k} = {fmt(v[0])} {'-' if v[1] < 0 else '+'} j{fmt(abs(v[1]))}"
            if isinstance(v, list) else f"{k} = {fmt(v)}°"
            for k, v in data["dyads"].items()))
    for i, c in enumerate(data["candidates"], 1):
        lines.append(f"Candidate {i}: " + ("passes every check" if c["ok"] else "fails " +
                     ", ".join(k["name"] for k in c["checks"] if not k["passed"])))
        for name, v in {**c["fixed_pivots"], **c["moving_pivots"]}.items():
            lines.append(f"  {name} = ({fmt(v[0])}, {fmt(v[1])}) {res.spec.units}")
        lines.append("  " + ", ".join(f"{k} {fmt(v)}" for k, v in c["lengths"].items()))
        for k in c["checks"]:
            lines.append(f"  [{'ok' if k['passed'] else 'FAIL'}] {k['name']}: {k['detail']}")
    if res.function is not None:
        f = data["function"]
        lines.append(f"y = {f['expression']}; precision points (Chebyshev, Eq. 9.22):")
        for x, y, p, q in zip(f["x"], f["y"], f["phi_deg"], f["psi_deg"]):
            lines.append(f"  x = {fmt(x)}  y = {fmt(y)}  φ = {fmt(p)}°  ψ = {fmt(q)}°")
        lines.append("  K1, K2, K3 = " + ", ".join(fmt(k) for k in f["K"]))
        lines.append("  " + ", ".join(f"{k} = {fmt(v)}" for k, v in f["lengths"].items()))
        lines.append(f"  largest structural error |Δy| = {fmt(f['max_structural_error'])}")
    return "\n".join(lines) + "\n"
