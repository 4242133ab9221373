"""A plot's legend covers none of its curves (issue 24), read back from the SVG by gid."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from hypothesis import Phase, given, settings
from hypothesis import strategies as st
from shapely import LineString, box
from strategies import examples, fourbars, six_bars, slider_cranks
from strategies_quick import quick_returns

import graphkin
from graphkin.render import plots
from graphkin.render.labels import _PAD, text_size
from graphkin.render.plots import save_figure, sweep_figure

SVG = "{http://www.w3.org/2000/svg}"
DATA = Path(__file__).resolve().parents[1] / "data" / "figures"
_NUM = re.compile(r"-?\d+\.?\d*(?:[eE][-+]?\d+)?")


def _runs(d: str) -> list[np.ndarray]:
    """The polylines of an SVG path of M and L commands (a gap starts a new M)."""
    out = []
    for part in re.split(r"(?=M)", d):
        nums = [float(v) for v in _NUM.findall(part)]
        if len(nums) >= 2:
            out.append(np.array(nums[: len(nums) // 2 * 2]).reshape(-1, 2))
    return out


def legend_box(g: ET.Element) -> tuple[float, float, float, float]:
    """The box of a legend group: its handles' paths and its texts' glyph boxes (pt)."""
    xs, ys = [], []
    for p in g.iter(f"{SVG}path"):
        for run in _runs(p.get("d", "")):
            xs += list(run[:, 0])
            ys += list(run[:, 1])
    for t in g.iter(f"{SVG}text"):
        size = float(re.search(r"font-size:\s*([0-9.]+)px", t.get("style", "")).group(1))
        w = (text_size("".join(t.itertext()), size)[0] - 2 * _PAD) * 72
        x, y = float(t.get("x")), float(t.get("y"))
        xs += [x, x + w]
        ys += [y - 0.93 * size, y + 0.24 * size]
    return min(xs), min(ys), max(xs), max(ys)


def covered(svg: bytes, slack: float = 0.5) -> list[str]:
    """The curves (gid ``curve-…``) that cross their legend; the legend on the page."""
    root = ET.fromstring(svg)
    w, h = [float(v) for v in root.get("viewBox").split()[2:]]
    bad = []
    for ax in root.iter(f"{SVG}g"):
        if not (ax.get("id") or "").startswith("plot-"):
            continue
        legends = [g for g in ax.iter(f"{SVG}g") if (g.get("id") or "").startswith("legend")]
        assert len(legends) == 1, ax.get("id")
        x0, y0, x1, y1 = legend_box(legends[0])
        assert 0 <= x0 and x1 <= w and 0 <= y0 and y1 <= h, ("legend off the page", x1, w)
        frame = box(x0 + slack, y0 + slack, x1 - slack, y1 - slack)
        curves = [g for g in ax.iter(f"{SVG}g") if (g.get("id") or "").startswith("curve-")]
        assert curves, ax.get("id")
        for g in curves:
            for p in g.iter(f"{SVG}path"):
                if any(len(r) >= 2 and LineString(r).intersects(frame)
                       for r in _runs(p.get("d", ""))):
                    bad.append(g.get("id"))
    return bad


def _svg(fig) -> bytes:
    import io

    from graphkin.render.style import rc_context

    buf = io.BytesIO()
    with rc_context():  # real text, as graphkin saves
        fig.savefig(buf, format="svg")
    return buf.getvalue()


@given(rm=st.one_of(fourbars(), slider_cranks(), quick_returns(), six_bars()))
@settings(examples(4), phases=[Phase.explicit, Phase.reuse, Phase.generate])
def test_the_omega_legend_covers_no_curve(rm):
    sw = rm.mechanism().sweep(count=90)
    assert not covered(_svg(sweep_figure(sw, "omega")))


def test_a_legend_over_the_curves_is_seen_and_moved_out(tmp_path, monkeypatch):
    # The Watt I six-bar's five ω curves leave no corner of the axes free: matplotlib's
    # "best" corner crosses a curve (the check sees it), and the plot moves the legend out.
    sw = graphkin.load(DATA / "watt1_sixbar.toml").sweep(count=120)
    monkeypatch.setattr(plots, "_legends_off_the_curves", lambda fig, axes: None)
    fig = sweep_figure(sw, "omega")
    fig.axes[0].get_legend().set_gid("legend-omega")
    assert covered(_svg(fig))
    monkeypatch.undo()
    out = save_figure(sweep_figure(sw, "omega"), tmp_path / "w.svg")
    assert not covered(out.read_bytes())


@pytest.mark.parametrize("name,what", [("watt1_sixbar", "omega,transmission"),
                                       ("whitworth_quick_return", "alpha")])
def test_every_plot_over_the_drive_keeps_its_legend_off_its_curves(name, what, tmp_path):
    sw = graphkin.load(DATA / f"{name}.toml").sweep(count=120)
    out = save_figure(sweep_figure(sw, what), tmp_path / "q.svg")
    root = ET.fromstring(out.read_bytes())
    if "transmission" in what:  # its curves have their own gids: renamed for the check
        for g in root.iter(f"{SVG}g"):
            if (g.get("id") or "").startswith("transmission-"):
                g.set("id", "curve-" + g.get("id"))
    assert not covered(ET.tostring(root))
