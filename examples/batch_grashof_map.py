"""A Grashof and transmission-angle map of a crank-rocker over two link lengths.

One ``graphkin.batch`` call sweeps 61 x 61 = 3721 designs of the benchmark
four-bar (crank 4 in, frame 10 in) through a full turn of the crank, with
the coupler BC from 6 to 18 in and the rocker DC from 4 to 16 in.  For each
design: does the crank turn all the way round (every posture assembles), and
if so, the worst transmission angle over the turn (the one farthest from
90 degrees, Sec. 1.10).  Grashof's law (Eq. 1.6) draws the boundaries.

Run from the repository's root::

    python examples/batch_grashof_map.py docs/img/batch_map.png
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

import graphkin

HERE = Path(__file__).resolve().parent


def main(out: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    mech = graphkin.load(HERE.parent / "benchmarks" / "bench_fourbar.toml")
    r3 = np.linspace(6.0, 18.0, 61)          # coupler BC
    r4 = np.linspace(4.0, 16.0, 61)          # rocker DC
    g3, g4 = np.meshgrid(r3, r4)              # g3[i, j] = r3[j], g4[i, j] = r4[i]
    zero = np.zeros(g3.size)
    b = graphkin.batch(mech, {"links.3.C": np.stack([g3.ravel(), zero], axis=1),
                              "links.4.C": np.stack([g4.ravel(), zero], axis=1)},
                       count=360, transmission=True)
    gamma = b.columns["transmission_C"]                       # (3721, 360), degrees
    worst = np.nanmax(np.abs(gamma - 90.0), axis=1) + 0.0    # farthest from 90°
    turns = b.always_assembles                               # the crank turns fully
    kinds = np.array([g.kind for g in b.grashof()])
    mu_min = np.where(turns, 90.0 - worst, np.nan).reshape(g3.shape)

    fig, ax = plt.subplots(figsize=(6.4, 5.2), layout="constrained")
    im = ax.pcolormesh(r3, r4, mu_min, cmap="viridis", vmin=0.0, vmax=90.0, shading="nearest")
    fig.colorbar(im, ax=ax, label="worst transmission angle over the turn, 90° − max|γ − 90°|")
    # Grashof's law: s + l = p + q with the crank (4) the shortest link and the frame 10
    code = np.select([kinds == "crank-rocker", kinds == "non-Grashof"], [0, 1], 2)
    ax.contour(r3, r4, code.reshape(g3.shape).astype(float), levels=[0.5],
               colors="crimson", linewidths=1.2, linestyles="--")
    ax.plot([], [], color="crimson", linestyle="--", label="s + l = p + q (Eq. 1.6)")
    ax.plot([12.0], [11.0], marker="*", color="red", markersize=12, label="the file's design")
    ax.set_xlabel("coupler BC (in)")
    ax.set_ylabel("rocker DC (in)")
    ax.set_title("Crank 4 in, frame 10 in: Grashof crank-rockers (inside the dashed line)\n"
                 "and their worst transmission angle; blank where the crank cannot turn fully",
                 fontsize=9)
    ax.legend(loc="lower right", fontsize=8)
    fig.savefig(out, dpi=110)
    print(f"{b.designs} designs x {len(b.values)} postures; "
          f"{int(turns.sum())} let the crank turn fully; wrote {out}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "batch_map.png")
