"""Plots a handout can use: toggles clipped and marked, dead zones shaded, paths named."""

from __future__ import annotations

import numpy as np
from spec_data import EXAMPLES

import graphkin
from graphkin.render.plots import sweep_figure


def _gids(ax) -> list[str]:
    return [a.get_gid() or "" for a in ax.get_children()]


def test_dead_zone_is_shaded_and_toggles_clipped():
    # Example 3.1's four-bar is not a Grashof crank-rocker (4 + 18 > 10 + 11, Sec. 1.10):
    # the crank cannot turn all the way round, and ω runs away at the two limit postures.
    sw = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml").sweep(count=721)
    fig = sweep_figure(sw, "omega")
    ax = fig.axes[0]
    gids = _gids(ax)
    assert any(g.startswith("unassembled-") for g in gids)
    assert any(g.startswith("toggle-") for g in gids)
    w = np.array([sw.columns[f"omega_{k}"] for k in ("2", "3", "4")], dtype=float)
    lo, hi = ax.get_ylim()
    assert max(hi, -lo) < np.nanmax(np.abs(w))  # the spike is clipped, the rest keeps its scale


def test_a_slider_path_is_named_by_its_slider():
    sw = graphkin.load(EXAMPLES / "ex3_2_slider_driven.toml").sweep(count=37)
    fig = sweep_figure(sw, "path:C,path:D")
    titles = [ax.get_title() for ax in fig.axes]
    assert titles[0] == "path of C (slider 4)"
    assert titles[1] == "path of D (coupler curve)"
