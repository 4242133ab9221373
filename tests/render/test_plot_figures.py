"""Plots a handout can use: toggles clipped and marked, dead zones shaded, paths named."""

from __future__ import annotations

import io
import xml.etree.ElementTree as ET

import numpy as np
import pytest
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
    # C runs on the frame's line: its path is the slider's position, never a "coupler curve";
    # D is a point of the coupler 3 only (no frame pivot on its link): a coupler curve
    assert titles[0] == "path of C: position of slider 4"
    assert titles[1] == "path of D: coupler curve"
    assert "position of slider 4 (C)" in [t.get_text() for t in fig.axes[0].get_legend().texts]


def _svg_ids(fig) -> set[str]:
    buf = io.BytesIO()
    fig.savefig(buf, format="svg")
    return {el.get("id") for el in ET.fromstring(buf.getvalue()).iter() if el.get("id")}


def test_a_coupler_curve_is_framed_around_it_with_the_mechanism_faint_and_a_legend():
    mech = graphkin.examples.crank_rocker()
    sw = mech.sweep(count=180)
    fig = sweep_figure(sw, "path:P")
    ids = _svg_ids(fig)
    assert {"path-P", "path-P-start", "frame-pivots"} <= ids
    assert all(f"mechanism-link-{lid}" in ids for lid in mech.moving)  # the faint mechanism
    ax = fig.axes[0]
    legend = [t.get_text() for t in ax.get_legend().texts]
    assert legend[0] == "coupler curve (P)" and any(t.startswith("mechanism") for t in legend)
    # the frame: the curve and the mechanism at the file's posture (from the solver), with a
    # margin of at most a quarter of that extent -- not every point's reach nor Ball's point
    sol = mech.solve()
    pts = np.array([sol.position(n) for n in mech.point_names], dtype=float)
    px, py = (np.asarray(sw.columns[k], dtype=float) for k in ("x_P", "y_P"))
    xs, ys = np.concatenate([px, pts[:, 0]]), np.concatenate([py, pts[:, 1]])
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert x0 <= xs.min() and xs.max() <= x1 and y0 <= ys.min() and ys.max() <= y1
    span = max(np.ptp(xs), np.ptp(ys))
    assert max(x1 - x0, y1 - y0) <= 1.25 * span + 0.05 * mech.size


@pytest.mark.parametrize("item", ["omega", "alpha"])
def test_toggle_and_dead_zone_read_back_from_the_svg(item):
    # Example 3.1 (not Grashof, Sec. 1.10): the drive cannot pass two limit postures; near them
    # ω and α run away -- clipped and marked, and the dead zone shaded and named in the legend
    sw = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml").sweep(count=721)
    fig = sweep_figure(sw, item)
    ids = _svg_ids(fig)
    assert any(i.startswith("toggle-") for i in ids)
    assert any(i.startswith("unassembled-") for i in ids)
    legend = [t.get_text() for t in fig.axes[0].get_legend().texts]
    assert "cannot be assembled" in legend and "near a toggle (clipped)" in legend
    y = np.array([sw.columns[f"{item}_{k}"] for k in ("2", "3", "4")], dtype=float)
    lo, hi = fig.axes[0].get_ylim()
    assert np.isfinite([lo, hi]).all() and max(hi, -lo) < np.nanmax(np.abs(y))


def test_the_toggles_are_marked_where_crank_and_coupler_line_up():
    # Example 3.2 (slider-driven, crank 50, coupler 140, slide 20 mm below the crank pivot):
    # the toggles are where crank and coupler line up, |O2 C| = 140 - 50 or 140 + 50, so the
    # slider is at x = sqrt(90² - 20²) = 87.75 mm or sqrt(190² - 20²) = 188.94 mm; α runs
    # away there and the plot marks both.
    sw = graphkin.load(EXAMPLES / "ex3_2_slider_driven.toml").sweep(count=721)
    fig = sweep_figure(sw, "alpha")
    marks = sorted(float(i[len("toggle-"):]) for i in _svg_ids(fig) if i.startswith("toggle-"))
    toggles = (np.sqrt(90.0**2 - 20.0**2), np.sqrt(190.0**2 - 20.0**2))
    assert marks and all(min(abs(m - t) for t in toggles) < 4.0 for m in marks), marks
    assert all(any(abs(m - t) < 4.0 for m in marks) for t in toggles), marks


def test_the_dead_zone_is_where_the_law_of_cosines_says():
    # Example 3.1 (ground 10, crank 4, coupler 18, rocker 11 in): B is at least 18 - 11 = 7 in
    # from D only while 4² + 10² - 2·4·10 cos θ2 >= 7², i.e. outside |θ2| < arccos(67/80) =
    # 33.12°: no assembly from 326.88° to 393.12°, one shaded span.
    sw = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml").sweep(count=720)
    fig = sweep_figure(sw, "omega")
    spans = [p for p in fig.axes[0].patches if (p.get_gid() or "").startswith("unassembled-")]
    assert len(spans) == 1
    xs = spans[0].get_path().transformed(spans[0].get_patch_transform()).vertices[:, 0]
    half = np.degrees(np.arccos(67.0 / 80.0))
    step = 360.0 / 720
    x0 = float(np.asarray(sw.drive_values)[0])
    lo, hi = 360.0 - half, 360.0 + half
    # the sweep may start anywhere: compare modulo a turn from its first angle
    wrap = lambda v: x0 + (v - x0) % 360.0  # noqa: E731
    assert wrap(min(xs)) == pytest.approx(wrap(lo), abs=2 * step)
    assert max(xs) - min(xs) == pytest.approx(hi - lo, abs=3 * step)
