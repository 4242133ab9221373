"""Drawings of function generation, cognates and dwell linkages, in the house style.

* function generation (Secs. 9.7, 9.11): (a) Chebyshev spacing constructed
  as in Fig. 9.27, (b) the four-bar in its three precision postures
  (Fig. 9.40), (c) the structural error over the range (Fig. 9.28), a graph
  with its own axes in inches;
* cognates (Sec. 9.10): Cayley's diagram, the three four-bars (Fig. 9.38)
  and the one coupler curve they trace (graphkin's sweep of the first);
* dwell (Sec. 9.13): the coupler curve, its circular arc, the arc's center
  D constructed from three of its points, links 5 and 6 (Fig. 9.42a);
* the overlay method (Sec. 9.8): the desired path, the atlas curve laid on
  it and the four-bar that traces it (Fig. 9.29);
* the crank-rocker of two limit postures (Sec. 9.3): the construction of
  Fig. 9.3a and the linkage in both limit postures (Fig. 9.3b).

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 9.27, 9.28, 9.38, 9.40, 9.42.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.render.labels import text_size
from graphkin.render.scene import Item, Panel
from graphkin.render.synthesis import Pen, _c, paint_construction, paint_linkage, panel
from graphkin.synthesis.run import Result
from graphkin.text import fmt

__all__ = ["function_panels", "cognates_panel", "dwell_panel", "overlay_panel",
           "crank_rocker_panel"]

_COGNATE_STYLES = {"1": "result-line", "2": "vector-n", "3": "vector-c"}
"""Each cognate its own line (solid, dashed, dash-dotted): the drawing stays black."""


def _box(zs: list[complex], pad: float = 0.06) -> tuple[np.ndarray, np.ndarray]:
    arr = np.array([[z.real, z.imag] for z in zs if np.isfinite(z)])
    lo, hi = arr.min(axis=0), arr.max(axis=0)
    m = pad * float(max(hi - lo))
    return lo - m, hi + m


def _staged(pen: Pen, cx: Any, stage: tuple[Any, int] | None) -> bool:
    """Set a teaching frame on the pen; True when the frame is one (draw nothing else)."""
    if stage is None:
        return False
    pen.stage = stage
    return True


def function_panels(res: Result, max_inches: float, skip: frozenset[str],
                    stage: tuple[Any, int] | None = None) -> list[tuple[Panel, Pen]]:
    """Chebyshev spacing, the linkage in its precision postures, the structural error.

    ``stage``: a teaching frame, Chebyshev's construction up to a step (panel (a) only).
    """
    f = res.function
    assert f is not None and res.construction is not None
    x0, x1 = f.spec.x_range
    half = (x1 - x0) / 2
    lo = np.array([x0 - 0.05 * half, -1.05 * half])
    hi = np.array([x1 + 0.05 * half, 1.05 * half])
    a = panel("chebyshev", "(a) Chebyshev spacing (Fig. 9.27)", "", lo, hi, 0.55 * max_inches)
    pen_a = Pen(a, skip)
    framed = _staged(pen_a, res.construction, stage)
    mid = np.array([(x0 + x1) / 2, 0.0])
    paint_construction(pen_a, res.construction, set(), mid, 3 * half + 1e-300,
                       optional={"C", "X0", "X1"})
    out = [(a, pen_a)]
    if framed:
        return out
    link = res.chosen
    if link is not None:
        pa, pb = link.pivots
        lo2, hi2 = _box([link.o_a, link.o_b, *pa, *pb])
        b = panel("linkage", "(b) the four-bar at the precision points (Fig. 9.40)",
                  res.spec.units, lo2, hi2, 0.55 * max_inches)
        pen_b = Pen(b, skip)
        paint_linkage(pen_b, link)
        out.append((b, pen_b))
    out.append(_error_panel(res, max_inches, skip))
    return out


def _error_panel(res: Result, max_inches: float, skip: frozenset[str]) -> tuple[Panel, Pen]:
    """The structural error y_generated − y over the range, drawn as a graph (Fig. 9.28)."""
    f = res.function
    assert f is not None
    w, h = 0.75 * max_inches, 0.4 * max_inches
    left, bottom = 0.75, 0.55
    p = Panel("error", "plot", "(c) the structural error (Sec. 9.7)", "", scale=None,
              prefix="error-")
    p.view = (0.0, 0.0, left + w + 0.3, bottom + h + 0.45)
    p.inner = (0.0, 0.0, p.view[2], p.view[3] - 0.3)
    pen = Pen(p, skip)
    xs, err = np.asarray(f.error_x, float), np.asarray(f.error, float)
    x0, x1 = f.spec.x_range
    big = float(np.nanmax(np.abs(err))) if np.any(np.isfinite(err)) else 1.0
    big = big if big > 0 else 1.0
    top = _nice(big)

    def to(x: Any, y: Any) -> np.ndarray:
        return np.stack([left + (np.asarray(x) - x0) / (x1 - x0) * w,
                         bottom + (np.asarray(y) + top) / (2 * top) * h], axis=-1)

    g = pen.group("error-axes", 1.0, key="axes")
    box = to([x0, x1, x1, x0, x0], [-top, -top, top, top, -top])
    g.items.append(Item("path", box, "aux-line"))
    g.items.append(Item("path", to([x0, x1], [0.0, 0.0]), "datum"))
    for x in np.linspace(x0, x1, 5):
        q = to(x, -top)
        g.items.append(Item("path", np.array([q, q - [0, 0.05]]), "aux-line"))
        g.items.append(Item("text", np.array([q - [0, 0.15]]), "label-small", text=fmt(x, 4),
                            va="top", gid=f"{p.prefix}tick-x-{fmt(x, 4)}"))
    for y in (-top, 0.0, top):
        q = to(x0, y)
        g.items.append(Item("path", np.array([q, q - [0.05, 0]]), "aux-line"))
        g.items.append(Item("text", np.array([q - [0.08, 0]]), "label-small", text=fmt(y, 3),
                            ha="right", gid=f"{p.prefix}tick-y-{fmt(y, 3)}"))
    g.items.append(Item("text", np.array([[left + w / 2, 0.08]]), "label-small",
                        text=f"x (y = {f.spec.expression})", gid=f"{p.prefix}x-name"))
    name = "Δy"
    g.items.append(Item("text", np.array([[left - text_size(name, 7.0)[0] - 0.45,
                                           bottom + h / 2]]), "label-small", text=name,
                        gid=f"{p.prefix}y-name"))
    g2 = pen.group("structural-error", 3.0, key="structural error")
    pts = to(xs, err)
    ok = np.all(np.isfinite(pts), axis=1)
    g2.items.append(Item("path", pts[ok], "result-line", key="structural-error"))
    g3 = pen.group("precision-points", 4.0, key="precision points")
    for j, x in enumerate(f.x, 1):
        pen.point(g3, f"x{j}", to(x, 0.0), "point", text=f"x{_sub(j)}")
    return p, pen


def _sub(j: int) -> str:
    return str(j).translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))


def _nice(v: float) -> float:
    """The round number at or above ``v`` (1, 2, 2.5, 5 × 10^k)."""
    e = math.floor(math.log10(v))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10 ** e >= v * (1 - 1e-12):
            return m * 10 ** e
    return 10.0 ** (e + 1)


def cognates_panel(res: Result, max_inches: float, skip: frozenset[str],
                   stage: tuple[Any, int] | None = None) -> tuple[Panel, Pen]:
    """Cayley's diagram: the three cognates and their one coupler curve (Fig. 9.38)."""
    from graphkin.mechanisms import loads

    cg = res.cognates
    assert cg is not None
    z = cg.points
    curve = np.array([], dtype=complex)
    try:   # the coupler curve, traced by graphkin's sweep of the first cognate
        sw = loads(cg.mechanism_toml("1")).sweep(count=360)
        curve = np.asarray(sw.columns["x_P"]) + 1j * np.asarray(sw.columns["y_P"])
    except Exception:  # noqa: BLE001 - a linkage that does not sweep is drawn without it
        pass
    lo, hi = _box([*z.values(), *curve[np.isfinite(curve)]])
    p = panel("cognates", "Cayley's diagram: three four-bars, one coupler curve (Fig. 9.38)",
              res.spec.units, lo, hi, max_inches)
    pen = Pen(p, skip)
    mid = (lo + hi) / 2
    joins = {s.label for s in cg.construction if s.op == "join"}
    if _staged(pen, cg.construction, stage):
        paint_construction(pen, cg.construction, set(), mid, 4 * float(max(hi - lo)))
        return p, pen
    for w, (o1, p1, p2, o2) in cg.linkages().items():
        g = pen.group(f"cognate-{w}", 4.0, key=f"cognate {w}")
        chain = [z[o1], z[p1], z[p2], z[o2]]
        for a, b in zip(chain[:-1], chain[1:]):
            pen.segment(g, _c(a), _c(b), _COGNATE_STYLES[w])
        gc = pen.group(f"cognate-{w}-coupler", 3.5, key=f"cognate {w} coupler")
        g_tri = [z[p1], z[p2], z["P"]]
        gc.items.append(Item("polygon", np.array([_c(q) for q in g_tri]), "plate"))
    g = pen.group("cayley-triangle", 2.0, key="pivot triangle")
    for u, v in (("O_A", "O_B"), ("O_B", "O_C"), ("O_C", "O_A")):
        pen.segment(g, _c(z[u]), _c(z[v]), "ref-line")
    if curve.size:
        gcc = pen.group("coupler-curve", 0.5, key="coupler curve")
        pen.polyline(gcc, curve, "datum", key="coupler-curve",
                     jump=0.25 * float(max(hi - lo)))
    paint_construction(pen, cg.construction, joins, mid, 4 * float(max(hi - lo)))
    return p, pen


def dwell_panel(res: Result, max_inches: float, skip: frozenset[str],
                stage: tuple[Any, int] | None = None) -> tuple[Panel, Pen]:
    """The dwell six-bar (Fig. 9.42a): the coupler curve, its arc, D, links 5 and 6."""
    dw = res.dwell
    assert dw is not None
    curve = dw.c
    k = (dw.start + dw.stop) // 2 % len(curve)
    cz = complex(curve[k])
    az = dw.o_a + dw.lengths[0] * np.exp(1j * float(dw.crank[k]))
    bz = az + (cz - az) / dw.coupler_local
    slider = dw.kind == "slider"
    lo, hi = _box([dw.o_a, dw.o_b, dw.o6, dw.d, az, bz, *curve])
    p = panel("dwell", "The dwell six-bar with a slider (Fig. 9.44)" if slider else
              "The dwell six-bar (Fig. 9.42a)", res.spec.units, lo, hi, max_inches)
    pen = Pen(p, skip)
    g = pen.group("coupler-curve", 0.5, key="coupler curve")
    pen.polyline(g, np.append(curve, curve[:1]), "datum", key="coupler-curve")
    if _staged(pen, dw.construction, stage):
        paint_construction(pen, dw.construction, set(), (lo + hi) / 2, 4 * float(max(hi - lo)))
        return p, pen
    g = pen.group("dwell-arc", 1.0, key="dwell stretch" if slider else "dwell arc")
    pen.polyline(g, curve[np.arange(dw.start, dw.stop + 1) % len(curve)], "vector-abs",
                 key="dwell-arc")
    paint_construction(pen, dw.construction, set(), (lo + hi) / 2, 4 * float(max(hi - lo)))
    g = pen.group("linkage-1", 4.0, key="linkage")
    for a, b in ((dw.o_a, az), (az, bz), (bz, dw.o_b)):
        pen.segment(g, _c(a), _c(b), "result-line")
    g.items.append(Item("polygon", np.array([_c(az), _c(bz), _c(cz)]), "plate"))
    pen.point(g, "A", _c(az), "pin")
    pen.point(g, "B", _c(bz), "pin")
    pen.point(g, "C", _c(cz), "pin")
    if slider:   # the slotted link 6 from O6 past C, the block at C (Fig. 9.44)
        g = pen.group("link-6", 4.2, key="link 6")
        far = max(float(np.max(np.abs(curve - dw.o6))), abs(cz - dw.o6))
        pen.segment(g, _c(dw.o6), _c(dw.o6 + far * (cz - dw.o6) / abs(cz - dw.o6)),
                    "result-line")
        u = (cz - dw.o6) / abs(cz - dw.o6) * 0.025 * float(max(hi - lo))
        g.items.append(Item("polygon", np.array([_c(cz + k * u) for k in
                                                 (1.6 + 1j, -1.6 + 1j, -1.6 - 1j, 1.6 - 1j)]),
                            "block"))
        pen.point(g, "C", _c(cz), "pin")
    else:
        g = pen.group("link-5", 4.2, key="link 5")
        pen.segment(g, _c(cz), _c(dw.d), "result-line")
        g = pen.group("link-6", 4.2, key="link 6")
        pen.segment(g, _c(dw.o6), _c(dw.d), "result-line")
    g = pen.group("fixed-pivots", 5.5, key="fixed pivots")
    for name, zz in (("O_A", dw.o_a), ("O_B", dw.o_b), ("O6", dw.o6)):
        pen.point(g, name, _c(zz), "pin")
    return p, pen


def overlay_panel(res: Result, max_inches: float, skip: frozenset[str],
                  stage: tuple[Any, int] | None = None) -> tuple[Panel, Pen]:
    """The overlay (Sec. 9.8, Fig. 9.29): the path, the atlas curve laid on it, its four-bar.

    The four-bar is drawn where the fitting stretch starts.
    """
    ov = res.overlay
    assert ov is not None
    path = ov.path
    lo, hi = _box([*path, ov.o2, ov.o4, ov.a, ov.b, ov.p, *ov.curve])
    p = panel("overlay", "The overlay: the desired path and the atlas curve that fits it "
              "(Fig. 9.29)", res.spec.units, lo, hi, max_inches)
    pen = Pen(p, skip)
    g = pen.group("coupler-curve", 1.0, key="coupler curve")
    pen.polyline(g, np.append(ov.curve, ov.curve[:1]), "cubic", key="coupler-curve")
    g = pen.group("desired-path", 2.0, key="desired path")
    closed = res.spec.closed
    pen.polyline(g, np.append(path, path[:1]) if closed else path, "vector-abs",
                 key="desired-path")
    for z in path:
        g.items.append(Item("marker", np.array([_c(z)]), "image-point"))
    g = pen.group("linkage-1", 4.0, key="linkage")
    for a, b in ((ov.o2, ov.a), (ov.a, ov.b), (ov.b, ov.o4)):
        pen.segment(g, _c(a), _c(b), "result-line")
    g.items.append(Item("polygon", np.array([_c(ov.a), _c(ov.b), _c(ov.p)]), "plate"))
    pen.point(g, "A", _c(ov.a), "pin")
    pen.point(g, "B", _c(ov.b), "pin")
    pen.point(g, "P", _c(ov.p), "point")
    g = pen.group("fixed-pivots", 5.5, key="fixed pivots")
    pen.point(g, "O2", _c(ov.o2), "pin")
    pen.point(g, "O4", _c(ov.o4), "pin")
    return p, pen


def crank_rocker_panel(res: Result, max_inches: float, skip: frozenset[str],
                       stage: tuple[Any, int] | None = None) -> tuple[Panel, Pen]:
    """Fig. 9.3: lines X and Y meeting at O2, the arc through B2, C and M.

    The linkage is drawn in its two limit postures (extended at B1, folded at B2).
    """
    cr = res.crank_rocker
    assert cr is not None
    u = (cr.o2 - cr.b2) / abs(cr.o2 - cr.b2)
    a2 = cr.o2 + cr.r2 * u
    lo, hi = _box([cr.o2, cr.o4, cr.b1, cr.b2, cr.a1, a2,
                   cr.o2 + abs(cr.b2 - cr.o2) * (cr.b1 - cr.o2) / abs(cr.b1 - cr.o2)])
    p = panel("limits", "A crank-rocker from its limit postures (Fig. 9.3)",
              res.spec.units, lo, hi, max_inches)
    pen = Pen(p, skip)
    reach = 4 * float(max(hi - lo))
    if _staged(pen, cr.construction, stage):
        paint_construction(pen, cr.construction, set(), (lo + hi) / 2, reach)
        return p, pen
    g = pen.group("rocker-swing", 1.0, key="rocker's swing")
    t1 = math.atan2(cr.b1.imag - cr.o4.imag, cr.b1.real - cr.o4.real)
    t2 = math.atan2(cr.b2.imag - cr.o4.imag, cr.b2.real - cr.o4.real)
    t = t1 + np.linspace(0.0, 1.0, 41) * math.remainder(t2 - t1, math.tau)
    pen.polyline(g, cr.o4 + cr.r4 * np.exp(1j * t), "datum", key="rocker-swing")
    paint_construction(pen, cr.construction, set(), (lo + hi) / 2, reach)
    for j, (a, b) in enumerate(((cr.a1, cr.b1), (a2, cr.b2))):
        g = pen.group(f"linkage-{j + 1}", 4.0 - 0.1 * j, key=f"limit posture {j + 1}")
        style = "result-line" if j == 0 else "aux-line"
        for q1, q2 in ((cr.o2, a), (a, b), (b, cr.o4)):
            pen.segment(g, _c(q1), _c(q2), style)
        pen.point(g, f"A{j + 1}", _c(a), "pin")
        pen.point(g, f"B{j + 1}", _c(b), "pin")
    g = pen.group("fixed-pivots", 5.5, key="fixed pivots")
    pen.point(g, "O2", _c(cr.o2), "pin")
    pen.point(g, "O4", _c(cr.o4), "pin")
    return p, pen
