"""The gallery's Chapter 9 folder: synthesis files drawn, their numbers beside the book's.

Every file of ``gallery/synthesis/`` is a synthesis file (``docs/formats/synthesis.md``)
with a ``[gallery]`` table; :func:`render_entry` synthesizes it, draws it in
the house style (:func:`graphkin.render.synthesis.draw_synthesis`) and, when
the synthesis ends in a four-bar, hands the written mechanism file to
graphkin's analysis as it is: solved in every design posture (how far the
body's point lands from where it was asked to be), drawn in its first
posture, and swept between the first and the last (the transmission angle).
The ``[[gallery.book]]`` rows read their values from the solution this
returns (paths such as ``sides.P12P23``, ``candidates.0.lengths.crank``,
``analysis.transmission_min_deg``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Examples 9.1-9.8.
"""

from __future__ import annotations

import math
from itertools import combinations
from typing import Any

import numpy as np

__all__ = ["render_entry", "solution"]


def _z(v: Any) -> complex:
    v = np.asarray(v, dtype=float)
    return complex(v[0] / v[2], v[1] / v[2]) if v.shape == (3,) and v[2] != 0 else complex(
        math.nan, math.nan)


def solution(res: Any) -> dict[str, Any]:
    """The numbers a gallery row may ask for: the JSON report, every point, sides and radii.

    ``points``: every point of the constructions (t = 0 for the curves' own);
    ``sides``: the distance between every two poles (``P12P23``);
    ``radii``: the radius of every circle of the constructions (``k_A``);
    ``list`` values are indexed by position (``candidates.0``).
    """
    from graphkin.output.synthesis import synthesis_json

    data = synthesis_json(res)
    data.pop("steps", None)
    points: dict[str, list[float]] = {}
    radii: dict[str, float] = {}
    for cx in (res.construction, res.selection):
        if cx is None:
            continue
        ev = cx.evaluate({"t": np.array(0.0)} if "t" in cx.labels else None, strict=False)
        for s in cx:
            lab = s.outputs[0]
            if lab not in ev:
                continue
            if s.kind == "point":
                z = _z(ev[lab])
                if np.isfinite(z):
                    points[lab] = [z.real, z.imag]
            elif s.kind == "circle":
                r = float(np.asarray(ev[lab], dtype=float)[2])
                if math.isfinite(r):
                    radii[lab] = r
    poles = {k: complex(*v) for k, v in data.get("poles", {}).items()}
    data["points"] = points
    data["radii"] = radii
    data["sides"] = {f"{a}{b}": abs(poles[a] - poles[b]) for a, b in combinations(poles, 2)}
    data["candidates"] = {str(i): c for i, c in enumerate(data.get("candidates", []))}
    f = data.get("function")
    if f is not None:   # the lists by number: function.x.1, function.K.3
        for key in ("x", "y", "phi_deg", "psi_deg", "K"):
            f[key] = {str(i + 1): v for i, v in enumerate(f[key])}
    return data


def _analysis(res: Any) -> tuple[dict[str, Any], Any]:
    """The written mechanism analysed by graphkin: the postures reached, the transmission angle.

    ``reached``: the body's point where graphkin's solution of the written file puts it
    in each design posture (``reached.1`` ...); ``posture_error``: the largest distance
    from where it was asked to be; ``transmission_min_deg``: the least transmission
    angle (measured from a toggle, at most 90°) over the crank's travel from the first
    posture to the last; ``off_line_max``: how far the point leaves the straight line
    through its first and last positions over that travel.
    """
    import graphkin

    link = res.chosen
    if res.function is not None:
        return _function_analysis(res)
    post = link.post
    d = post.names[0]
    reached: dict[str, list[float]] = {}
    miss = []
    for k in range(post.n):
        sol = graphkin.loads(link.mechanism_toml(k, res.spec.title, res.spec.units)).solve()
        xy = np.asarray(sol.position(d), dtype=float)
        reached[str(k + 1)] = [float(xy[0]), float(xy[1])]
        miss.append(float(np.hypot(*(xy - post.points[k]))))
    mech = graphkin.loads(res.mechanism_toml())
    sense, travel = link.travel()
    start = math.degrees(float(link.crank_angles()[0]))
    sw = mech.sweep(count=181, start=start, stop=start + sense * math.degrees(travel),
                    transmission=True)
    raw = np.asarray(sw.columns[f"transmission_{link.names[1]}"], dtype=float)
    path = np.asarray(sw.columns[f"x_{d}"]) + 1j * np.asarray(sw.columns[f"y_{d}"])
    p0, p1 = complex(*post.points[0]), complex(*post.points[-1])
    u = (p1 - p0) / abs(p1 - p0) if abs(p1 - p0) > 0 else 1.0
    off = np.abs(((path - p0) * np.conj(u)).imag)
    sol0 = mech.solve()
    out = {"reached": reached, "posture_error": max(miss),
           "assembled": bool(np.all(sw.assembled)),
           "transmission_min_deg": float(np.nanmin(np.minimum(raw, 180.0 - raw))),
           "transmission_from_deg": float(np.nanmin(raw)),
           "transmission_to_deg": float(np.nanmax(raw)),
           "off_line_max": float(np.nanmax(off)), "method": sol0.method}
    return out, sol0


def _function_analysis(res: Any) -> tuple[dict[str, Any], Any]:
    """A function generator's written file solved at each precision point's crank angle.

    ``psi_deg.j``: the rocker angle ψ graphkin's solution gives there (Freudenstein's
    r4 runs from C to O4, so ψ is θ4 + 180°); ``psi_error_deg``: the largest difference
    from the ψ the synthesis asked for.
    """
    import graphkin

    f = res.function
    psi, err = {}, []
    sol = None
    for j in range(len(f.x)):
        sol = graphkin.loads(f.mechanism_toml(res.spec.title, res.spec.units, j=j)).solve()
        got = math.radians(float(sol.angle("4"))) + math.pi
        psi[str(j + 1)] = math.degrees(got) % 360.0
        err.append(abs(math.degrees(math.remainder(got - float(f.psi[j]), math.tau))))
    sol0 = graphkin.loads(res.mechanism_toml()).solve()
    return {"psi_deg": psi, "psi_error_deg": max(err), "method": sol0.method}, sol0


def render_entry(entry: Any) -> tuple[dict[str, bytes], dict[str, Any]]:
    """The drawings of a synthesis file (name -> compact SVG bytes) and its solution."""
    from graphkin.errors import GraphkinError, InputError
    from graphkin.render.gallery import compact_svg
    from graphkin.render.mpl import draw
    from graphkin.render.svg import to_bytes
    from graphkin.render.synthesis import draw_synthesis
    from graphkin.synthesis import load_spec, synthesize

    res = synthesize(load_spec(entry.path))
    data = solution(res)
    drawings = {f"{entry.stem}-synthesis.svg":
                compact_svg(to_bytes(draw_synthesis(res).figure))}
    if res.candidates and res.cognates is None and res.dwell is None:
        try:
            data["analysis"], sol = _analysis(res)
        except GraphkinError as exc:
            raise InputError(f"graphkin cannot analyse the linkage it wrote: {exc}",
                             file=str(entry.path)) from None
        if "posture" in [str(d) for d in entry.meta.get("diagrams", [])]:
            drawings[f"{entry.stem}-posture.svg"] = compact_svg(
                to_bytes(draw(sol, "posture").figure))
    return drawings, {"title": res.spec.title, "solution": data}
