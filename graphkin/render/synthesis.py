"""Drawings of a synthesis, after Figs. 9.5-9.26: postures, poles, pole triangle, curves, linkage.

Every element carries a gid (``posture-2``, ``pole-P12``, ``side-s1``,
``center-point-curve``, ``circle-point-curve``, ``burmester-1``,
``linkage-3``...), so a test reads the SVG back by id.  A function generator
is drawn as its structural error over the range (Sec. 9.7).

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

from graphkin.render.svg import save
from graphkin.synthesis.run import Result

__all__ = ["synthesis_figure", "save_synthesis"]


def _z(ev: Any, lab: str) -> complex:
    v = np.asarray(ev[lab], dtype=float)
    return complex(v[0] / v[2], v[1] / v[2]) if v[2] != 0 else complex(np.nan, np.nan)


def _polyline(ax: Any, z: np.ndarray, gid: str, window: tuple[complex, float],
              **kw: Any) -> None:
    """A sampled curve, broken where it leaves the window or jumps (no line across gaps)."""
    mid, size = window
    z = np.where(np.abs(z - mid) <= size, z, np.nan)
    gap = np.abs(np.diff(z)) > 0.2 * size
    z = z.copy()
    z[1:][gap] = np.nan
    (line,) = ax.plot(z.real, z.imag, **kw)
    line.set_gid(gid)


def synthesis_figure(res: Result) -> Figure:
    """The figure of a synthesis result (a matplotlib Figure, no pyplot state)."""
    fig = Figure(figsize=(7.5, 6.0))
    ax = fig.add_subplot(1, 1, 1)
    ax.set_title(res.spec.title or f"Synthesis: {res.kind}")
    if res.function is not None:
        f = res.function
        (line,) = ax.plot(f.error_x, f.error, color="k")
        line.set_gid("structural-error")
        pts = ax.plot(f.x, np.zeros_like(f.x), "o", color="C3")[0]
        pts.set_gid("precision-points")
        ax.axhline(0.0, color="0.6", lw=0.6)
        ax.set_xlabel("x")
        ax.set_ylabel("structural error Δy (Sec. 9.7)")
        return fig
    post = res.spec.postures
    assert post is not None
    dpos = post.positions((0.0, 0.0))
    epos = post.positions(post.second)
    mid = complex(*dpos.mean(axis=0))
    size = 4.0 * post.scale
    for j in range(post.n):
        (body,) = ax.plot([dpos[j, 0], epos[j, 0]], [dpos[j, 1], epos[j, 1]], color="k", lw=2.2)
        body.set_gid(f"posture-{j + 1}")
        t = ax.text(dpos[j, 0], dpos[j, 1], f" {post.names[0]}{j + 1}", fontsize=8)
        t.set_gid(f"label-posture-{j + 1}")
    if res.construction is not None:
        cx = res.construction
        given = {"t": np.array(0.0)} if "t" in cx.labels else None
        ev = cx.evaluate(given, strict=False)
        for s in cx:
            if s.kind == "point" and s.label.startswith("P") and len(s.label) == 3 \
                    and s.role == "result":
                z = _z(ev, s.label)
                if np.isfinite(z):
                    (m,) = ax.plot(z.real, z.imag, "s", color="C0", ms=5)
                    m.set_gid(f"pole-{s.label}")
                    ax.text(z.real, z.imag, f" {s.label}", color="C0", fontsize=8)
            if s.op == "join" and s.label in ("s1", "s2", "s3"):
                p, q = (_z(ev, i) for i in s.inputs)
                (ln,) = ax.plot([p.real, q.real], [p.imag, q.imag], color="C0", lw=0.8)
                ln.set_gid(f"side-{s.label}")
    if res.curves is not None:
        for b in range(2):
            _polyline(ax, res.curves.center[b], f"center-point-curve-{b + 1}", (mid, size),
                      color="C2", lw=1.0)
            _polyline(ax, res.curves.circle[b], f"circle-point-curve-{b + 1}", (mid, size),
                      color="C4", lw=1.0, ls="--")
    for k, bp in enumerate(res.burmester, 1):
        (mk,) = ax.plot([bp.center.real, bp.circle.real], [bp.center.imag, bp.circle.imag],
                        "o", color="C3", ms=6)
        mk.set_gid(f"burmester-{k}")
    link = res.chosen
    if link is not None:
        pa, pb = link.pivots
        for j in range(post.n):
            xs = [link.o_a.real, pa[j].real, pb[j].real, link.o_b.real]
            ys = [link.o_a.imag, pa[j].imag, pb[j].imag, link.o_b.imag]
            (ln,) = ax.plot(xs, ys, color="C1", lw=1.4 if j == 0 else 0.7,
                            alpha=1.0 if j == 0 else 0.6)
            ln.set_gid(f"linkage-{j + 1}")
        (fx,) = ax.plot([link.o_a.real, link.o_b.real], [link.o_a.imag, link.o_b.imag], "^",
                        color="C1", ms=9)
        fx.set_gid("fixed-pivots")
    ax.set_aspect("equal", adjustable="box")
    ax.set_xlim(mid.real - size, mid.real + size)
    ax.set_ylim(mid.imag - size, mid.imag + size)
    return fig


def save_synthesis(res: Result, path: str | os.PathLike[str]) -> Path:
    """Draw the result and write it (SVG, PDF or PNG by the suffix)."""
    return save(synthesis_figure(res), path)
