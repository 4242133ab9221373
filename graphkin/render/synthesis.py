"""Drawings of a synthesis, after Figs. 9.5-9.26: postures, poles, bisectors, curves, linkage.

Every recorded step of the construction is drawn with its step id as gid
(``step-07-P12``: the pole P12; ``step-12-b_A12``: a bisector), as the
other drawings of graphkin are: points as dots with their names, lines
(bisectors, sides of the pole triangle, the lines turned about a pole) as
thin lines across the figure, circles (the circle of a circle point's
positions, the straight-line circles of Example 9.4) as circles.  The curves
and the linkage carry names of their own (``center-point-curve-1``,
``circle-point-curve-1``, ``burmester-1``, ``linkage-1``, ``fixed-pivots``).
A function generator is drawn as its structural error over the range.

References
----------
Uicker, Pennock & Shigley, 5th ed., Figs. 9.5-9.26, Sec. 9.7.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle

from graphkin.construction import Construction
from graphkin.render.svg import save
from graphkin.synthesis.run import Result

__all__ = ["synthesis_figure", "save_synthesis"]

_LINE_OPS = {"bisector", "join", "line_at_angle", "perpendicular"}
_CIRCLE_OPS = {"circle_through", "circle_on_diameter"}


def _z(v: Any) -> complex:
    v = np.asarray(v, dtype=float)
    if v.shape != (3,) or v[2] == 0:
        return complex(np.nan, np.nan)
    return complex(v[0] / v[2], v[1] / v[2])


def _after_t(cx: Construction) -> set[str]:
    """The labels that depend on the input t (the curves' steps, drawn as curves instead)."""
    out = {"t"}
    for s in cx:
        if any(i in out for i in s.inputs):
            out.update(s.outputs)
    return out


def _paint_steps(ax: Any, cx: Construction, window: tuple[complex, float],
                 skip: set[str]) -> None:
    """Draw every step of a construction not in ``skip``; the gid of each is its step id."""
    mid, size = window
    ev = cx.evaluate({"t": np.array(0.0)} if "t" in cx.labels else None, strict=False)
    for s in cx:
        if s.label in skip or s.outputs[0] in skip or s.outputs[0] not in ev:
            continue
        v = np.asarray(ev[s.outputs[0]], dtype=float)
        result = str(s.role) == "result"
        if s.kind == "point":
            z = _z(v)
            if not np.isfinite(z) or abs(z - mid) > 3 * size:
                continue
            color = "C0" if s.label.startswith("P") and len(s.label) == 3 else (
                "C3" if result else "0.2")
            (m,) = ax.plot(z.real, z.imag, "s" if color == "C0" else "o", color=color,
                           ms=4.5 if result or color == "C0" else 3.0)
            m.set_gid(s.step_id)
            t = ax.text(z.real, z.imag, f" {s.label}", color=color, fontsize=7, clip_on=True)
            t.set_gid(f"{s.step_id}-label")
        elif s.kind == "line" and s.op in _LINE_OPS and v.shape == (3,):
            a, b, c = v
            if not np.all(np.isfinite(v)) or a == b == 0:
                continue
            side = s.op == "join" and all(i.startswith("P") for i in s.inputs)
            if s.op == "join":   # a side between two points (the pole triangle, the quadrilateral)
                p, q = (_z(ev[i]) for i in s.inputs)
                foot, d = (p + q) / 2, (q - p) / 2
            else:      # a bisector or a line turned about a pole: across the figure
                off = a * mid.real + b * mid.imag + c
                foot = mid - off * complex(a, b)
                d = complex(-b, a) * 3 * size
            (ln,) = ax.plot([(foot - d).real, (foot + d).real], [(foot - d).imag, (foot + d).imag],
                            color="C0" if side else "0.55", lw=0.9 if side else 0.5,
                            ls="-" if side else (0, (4, 3)))
            ln.set_gid(s.step_id)
        elif s.kind == "circle" and s.op in _CIRCLE_OPS and v.shape == (3,):
            if not np.all(np.isfinite(v)) or v[2] > 3 * size:
                continue
            circ = Circle((v[0], v[1]), v[2], fill=False, lw=0.6,
                          color="C2" if result else "0.45")
            circ.set_gid(s.step_id)
            ax.add_patch(circ)


def synthesis_figure(res: Result) -> Figure:
    """The figure of a synthesis result (a matplotlib Figure, no pyplot state)."""
    fig = Figure(figsize=(7.5, 6.5) if res.function is None else (10.0, 4.5))
    if res.function is not None:
        f = res.function
        ax = fig.add_subplot(1, 2, 1)
        x0, x1 = f.spec.x_range
        half = (x1 - x0) / 2
        if res.construction is not None:
            _paint_steps(ax, res.construction, (complex(x0 + half, 0.0), 1.2 * half), set())
        ax.set_xlim(x0 - 0.2 * half, x1 + 0.2 * half)
        ax.set_ylim(-1.2 * half, 1.2 * half)
        ax.set_aspect("equal", adjustable="box")
        ax.set_title("Chebyshev spacing (Fig. 9.27)", fontsize=10)
        ax = fig.add_subplot(1, 2, 2)
        ax.set_title(res.spec.title or f"Synthesis: {res.kind}", fontsize=10)
        (line,) = ax.plot(f.error_x, f.error, color="k")
        line.set_gid("structural-error")
        marks = ax.plot(f.x, np.zeros_like(f.x), "o", color="C3")[0]
        marks.set_gid("precision-points")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xlabel("x")
        ax.set_ylabel(f"structural error of y = {f.spec.expression} (Sec. 9.7)")
        fig.subplots_adjust(wspace=0.4)
        return fig
    ax = fig.add_subplot(1, 1, 1)
    ax.set_title(res.spec.title or f"Synthesis: {res.kind}", fontsize=10)
    if res.cognates is not None:
        _cognates(ax, res)
        return fig
    if res.dwell is not None:
        _dwell(ax, res)
        return fig
    post = res.postures
    assert post is not None
    dpos = post.positions((0.0, 0.0))
    epos = post.positions(post.second)
    pts = [complex(*p) for p in np.vstack([dpos, epos])]
    link = res.chosen
    if link is not None:   # the linkage too, when its pivots are not far off
        pts += [z for z in (link.o_a, link.o_b) if abs(z - pts[0]) < 10 * post.scale]
    lo = complex(min(z.real for z in pts), min(z.imag for z in pts))
    hi = complex(max(z.real for z in pts), max(z.imag for z in pts))
    mid = (lo + hi) / 2
    size = max(0.7 * max((hi - lo).real, (hi - lo).imag), 1.5 * post.scale)
    window = (mid, size)
    # the marked points and the bisectors that found the poles are the pole construction of
    # Fig. 9.7: left out here, where the postures are drawn as bars
    marked = {f"{n}{j + 1}" for n in post.names for j in range(post.n)}
    for cx in (res.construction, res.selection):
        if cx is not None:
            pole_bisectors = {s.label for s in cx if s.op == "bisector"
                              and set(s.inputs) <= marked | {lab for t in cx if t.op == "rigid"
                                                             for lab in t.outputs}}
            _paint_steps(ax, cx, window, _after_t(cx) | marked | pole_bisectors)
    for j in range(post.n):
        (body,) = ax.plot([dpos[j, 0], epos[j, 0]], [dpos[j, 1], epos[j, 1]], color="k", lw=2.4)
        body.set_gid(f"posture-{j + 1}")
        t = ax.text(dpos[j, 0], dpos[j, 1], f"{post.names[0]}{j + 1} ", fontsize=8,
                    ha="right", va="top", clip_on=True)
        t.set_gid(f"posture-{j + 1}-label")
    if res.curves is not None:
        for b in range(2):
            for z, gid, style in ((res.curves.center[b], "center-point-curve", "-"),
                                  (res.curves.circle[b], "circle-point-curve", "--")):
                z = np.where(np.abs(z - mid) <= 2 * size, z, np.nan)
                z[1:][np.abs(np.diff(z)) > 0.2 * size] = np.nan
                (ln,) = ax.plot(z.real, z.imag, color="C2" if style == "-" else "C4",
                                lw=1.0, ls=style)
                ln.set_gid(f"{gid}-{b + 1}")
    for k, bp in enumerate(res.burmester, 1):
        (mk,) = ax.plot([bp.center.real, bp.circle.real], [bp.center.imag, bp.circle.imag],
                        "o", color="C3", ms=6, mfc="none")
        mk.set_gid(f"burmester-{k}")
    if link is not None:
        pa, pb = link.pivots
        for j in range(post.n):
            xs = [link.o_a.real, pa[j].real, pb[j].real, link.o_b.real]
            ys = [link.o_a.imag, pa[j].imag, pb[j].imag, link.o_b.imag]
            (ln,) = ax.plot(xs, ys, color="C1", lw=1.6 if j == 0 else 0.8,
                            alpha=1.0 if j == 0 else 0.55)
            ln.set_gid(f"linkage-{j + 1}")
        for j in range(post.n):   # the coupler: the body carried by the pins
            tri = [pa[j], pb[j], complex(*dpos[j]), pa[j]]
            (cp,) = ax.plot([z.real for z in tri], [z.imag for z in tri], color="C1",
                            lw=0.6, alpha=0.6)
            cp.set_gid(f"coupler-{j + 1}")
        path = link.coupler_path()
        (cc,) = ax.plot(path.real, path.imag, color="C5", lw=0.9)
        cc.set_gid("coupler-curve")
        (fx,) = ax.plot([link.o_a.real, link.o_b.real], [link.o_a.imag, link.o_b.imag], "^",
                        color="C1", ms=9)
        fx.set_gid("fixed-pivots")
    ax.set_xlim(mid.real - size, mid.real + size)
    ax.set_ylim(mid.imag - size, mid.imag + size)
    ax.set_aspect("equal", adjustable="box")
    ax.tick_params(labelsize=7)
    ax.set_xlabel(f"x ({res.spec.units})", fontsize=8)
    return fig


def _cognates(ax: Any, res: Result) -> None:
    """The three cognates of Cayley's diagram (Fig. 9.38) and their one coupler curve."""
    from graphkin.mechanisms import loads

    cg = res.cognates
    assert cg is not None
    z = cg.points
    pts = list(z.values())
    mid = complex(np.mean([p.real for p in pts]), np.mean([p.imag for p in pts]))
    size = 0.75 * max(max(abs(p - mid) for p in pts), 1e-9)
    _paint_steps(ax, cg.construction, (mid, 3 * size), {s.label for s in cg.construction
                                                         if s.op == "join"})
    for k, (w, (o1, p1, p2, o2)) in enumerate(cg.linkages().items()):
        quad = [z[o1], z[p1], z[p2], z[o2]]
        (ln,) = ax.plot([q.real for q in quad], [q.imag for q in quad], color=f"C{k + 1}",
                        lw=1.6)
        ln.set_gid(f"cognate-{w}")
        tri = [z[p1], z[p2], z["P"], z[p1]]
        (cp,) = ax.plot([q.real for q in tri], [q.imag for q in tri], color=f"C{k + 1}",
                        lw=0.7)
        cp.set_gid(f"cognate-{w}-coupler")
    try:   # the coupler curve, traced by graphkin's sweep of the first cognate
        sw = loads(cg.mechanism_toml("1")).sweep(count=360)
        (cc,) = ax.plot(sw.columns["x_P"], sw.columns["y_P"], color="C5", lw=0.9)
        cc.set_gid("coupler-curve")
    except Exception:  # noqa: BLE001 - a linkage that does not sweep is drawn without it
        pass
    ax.set_xlim(mid.real - 1.6 * size, mid.real + 1.6 * size)
    ax.set_ylim(mid.imag - 1.6 * size, mid.imag + 1.6 * size)
    ax.set_aspect("equal", adjustable="box")
    ax.tick_params(labelsize=7)


def _dwell(ax: Any, res: Result) -> None:
    """The dwell six-bar (Fig. 9.42a): the coupler curve, its arc, D, links 5 and 6."""
    dw = res.dwell
    assert dw is not None
    curve = dw.c
    (cc,) = ax.plot(curve.real, curve.imag, color="C5", lw=0.9)
    cc.set_gid("coupler-curve")
    arc = curve[np.arange(dw.start, dw.stop + 1) % len(curve)]
    (ac,) = ax.plot(arc.real, arc.imag, color="C3", lw=2.2)
    ac.set_gid("dwell-arc")
    pts = [dw.o_a, dw.o_b, dw.o6, dw.d, *curve[:: max(1, len(curve) // 12)]]
    mid = complex(np.mean([p.real for p in pts]), np.mean([p.imag for p in pts]))
    size = max(abs(p - mid) for p in pts)
    _paint_steps(ax, dw.construction, (mid, 2 * size), set())
    k = (dw.start + dw.stop) // 2 % len(curve)
    cz = complex(curve[k])
    az = dw.o_a + dw.lengths[0] * np.exp(1j * float(dw.crank[k]))
    bz = az + (cz - az) / dw.coupler_local
    for gid, chain in {"linkage-1": (dw.o_a, az, bz, dw.o_b), "coupler-1": (az, bz, cz, az)
                       }.items():
        (ln,) = ax.plot([z.real for z in chain], [z.imag for z in chain], color="C0",
                        lw=1.4 if gid == "linkage-1" else 0.7)
        ln.set_gid(gid)
    for gid, (p, q) in {"link-5": (cz, dw.d), "link-6": (dw.o6, dw.d)}.items():
        (ln,) = ax.plot([p.real, q.real], [p.imag, q.imag], color="C1", lw=1.8)
        ln.set_gid(gid)
    (fx,) = ax.plot([dw.o_a.real, dw.o_b.real, dw.o6.real], [dw.o_a.imag, dw.o_b.imag,
                    dw.o6.imag], "^", color="C1", ms=9)
    fx.set_gid("fixed-pivots")
    ax.set_xlim(mid.real - 1.2 * size, mid.real + 1.2 * size)
    ax.set_ylim(mid.imag - 1.2 * size, mid.imag + 1.2 * size)
    ax.set_aspect("equal", adjustable="box")
    ax.tick_params(labelsize=7)


def save_synthesis(res: Result, path: str | os.PathLike[str]) -> Path:
    """Draw the result and write it (SVG, PDF or PNG by the suffix)."""
    return save(synthesis_figure(res), path)
