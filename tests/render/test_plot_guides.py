"""Plots over the drive answer a user's questions (issue 24, item 4).

A ram's velocity is plotted signed, along its guide, so that the cutting and
return strokes read apart; the limit positions (the ram at rest, Sec. 1.10)
are marked on every plot over the drive.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

import graphkin
from graphkin.render.plots import sweep_figure

DATA = Path(__file__).resolve().parents[1] / "data" / "figures"


def _lines(ax, prefix):
    return [a for a in ax.get_lines() if (a.get_gid() or "").startswith(prefix)]


def test_a_ram_velocity_is_signed_along_its_guide_and_its_limits_are_marked():
    mech = graphkin.load(DATA / "whitworth_quick_return.toml")
    sw = mech.sweep(count=361)
    fig = sweep_figure(sw, "velocity:D,omega")
    ax_v, ax_w = fig.axes
    (curve,) = _lines(ax_v, "curve-velocity-D")
    x, y = (np.asarray(a, dtype=float) for a in curve.get_data())
    # the ram runs both ways: one stroke positive along R1 -> R2 (+x), the other negative
    assert y.max() > 0 > y.min()
    # at the file's posture (the first drive value) the single-posture solution gives V_D;
    # its x component is the signed value (the guide R1-R2 is the +x axis)
    v0 = np.asarray(mech.solve().velocity("D"), dtype=float)
    assert abs(v0[1]) <= 1e-9 * abs(v0[0])
    assert np.isclose(y[0], v0[0], rtol=1e-9)
    # the limit positions: V_D = 0 where the sweep says the ram stops; marked on both plots
    for ax in (ax_v, ax_w):
        marks = _lines(ax, "limit-")
        assert len(marks) == 2, [m.get_gid() for m in marks]
    big = float(np.abs(y).max())
    for m in _lines(ax_v, "limit-"):
        at = float(m.get_xdata()[0])
        assert abs(np.interp(at, x, y)) < 0.02 * big, at


def test_a_point_off_any_guide_keeps_its_speed():
    mech = graphkin.load(DATA / "whitworth_quick_return.toml")
    fig = sweep_figure(mech.sweep(count=90), "velocity:C")
    (curve,) = _lines(fig.axes[0], "curve-velocity-C")
    assert np.all(np.asarray(curve.get_ydata(), dtype=float) >= 0.0)
