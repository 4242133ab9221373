"""``graphkin plot``: curves over a sweep, as artists and as deterministic SVG."""

from __future__ import annotations

import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from spec_data import EXAMPLES, inline

import graphkin
from graphkin.errors import InputError
from graphkin.render.plots import parse_what, save_figure, sweep_figure

FOURBAR = inline("plot-fourbar.toml")

NON_GRASHOF = FOURBAR.replace("B = [4, 0]", "B = [6, 0]").replace("C = [12, 0]", "C = [5, 0]") \
    .replace("C = [11, 0]", "C = [7, 0]").replace("C = [9, 11]", "C = [8, 6]") \
    .replace("angle = 120", "angle = 60")


@pytest.fixture(scope="module")
def sw():
    return graphkin.loads(FOURBAR).sweep(count=120)


def test_parse_what() -> None:
    assert parse_what("angle,omega:3, path:E") == [("angle", None), ("omega", "3"),
                                                   ("path", "E")]
    for bad in ("speed", "path", "", "velocity"):
        with pytest.raises(InputError):
            parse_what(bad)


def test_curves_are_the_sweep_columns(sw) -> None:
    fig = sweep_figure(sw, "omega,alpha:4,path:E,transmission")
    gids = [a.get_gid() for a in fig.axes]
    assert gids == ["plot-omega", "plot-alpha-4", "plot-path-E", "plot-transmission"]
    lines = {ln.get_gid(): ln for ax in fig.axes for ln in ax.get_lines()}
    # one ω curve per moving link, plotted against the drive (degrees)
    for lid in ("2", "3", "4"):
        x, y = lines[f"curve-omega-{lid}"].get_data()
        np.testing.assert_array_equal(x, sw.columns["drive"])
        np.testing.assert_array_equal(y, sw.columns[f"omega_{lid}"])
    assert "curve-alpha-2" not in lines and "curve-alpha-4" in lines
    # the coupler curve of E is (x_E, y_E)
    x, y = lines["path-E"].get_data()
    np.testing.assert_array_equal(x, sw.columns["x_E"])
    np.testing.assert_array_equal(y, sw.columns["y_E"])
    # transmission angle at C: γ = angle BCD (law of cosines on |BD|, Sec. 1.10)
    _, g = lines["transmission-C"].get_data()
    bd2 = (sw.columns["x_B"] - 10) ** 2 + sw.columns["y_B"] ** 2
    want = np.degrees(np.arccos((12**2 + 11**2 - bd2) / (2 * 12 * 11)))
    np.testing.assert_allclose(g, want, atol=1e-9)
    assert {"guide-45", "guide-135"} <= set(lines)


def test_angles_are_drawn_continuous(sw) -> None:
    fig = sweep_figure(sw, "angle:2")
    (line,) = [ln for ln in fig.axes[0].get_lines() if ln.get_gid() == "curve-angle-2"]
    _, y = line.get_data()
    # the crank is the drive: one straight line through a whole turn, no jump at ±180°
    assert np.all(np.diff(y) > 0) and abs(y[-1] - y[0] - 357.0) < 1e-9


def test_gaps_where_the_linkage_cannot_be_assembled() -> None:
    sw = graphkin.loads(NON_GRASHOF).sweep(count=72)
    fig = sweep_figure(sw, "omega:4")
    # the curve (the dotted lines beside it mark the limit and dead-center postures)
    (line,) = [ln for ln in fig.axes[0].get_lines() if ln.get_gid() == "curve-omega-4"]
    _, y = line.get_data()
    # 93.82° < θ2 < 266.18° cannot be assembled (|BD| > 5 + 7; see test_sweep)
    d = sw.columns["drive"] % 360
    np.testing.assert_array_equal(np.isnan(y), (d > 93.83) & (d < 266.17))
    assert np.isnan(y).any() and not np.isnan(y).all()


def test_svg_is_deterministic_and_structured(sw, tmp_path: Path) -> None:
    fig = sweep_figure(sw, "omega,path:E")
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    save_figure(fig, a)
    save_figure(sweep_figure(sw, "omega,path:E"), b)
    assert a.read_bytes() == b.read_bytes()
    root = ET.fromstring(a.read_bytes())
    ids = {el.get("id") for el in root.iter()}
    for gid in ("plot-omega", "plot-path-E", "curve-omega-3", "path-E", "path-E-start"):
        assert gid in ids, gid
    texts = "".join(el.text or "" for el in root.iter() if el.tag.endswith("text"))
    assert "ω" in texts  # text stays text (svg.fonttype = none)
    assert b"<dc:date>" not in a.read_bytes()


def test_rates_need_a_file_with_rates() -> None:
    sw = graphkin.loads(FOURBAR.replace("omega = 10\n", "")).sweep(count=10)
    with pytest.raises(InputError):
        sweep_figure(sw, "omega")
    sweep_figure(sw, "angle,path:C")  # positions need no rates
    with pytest.raises(InputError):
        sweep_figure(sw, "path:Q")


def test_cli_plot(tmp_path: Path) -> None:
    f = tmp_path / "m.toml"
    f.write_text(FOURBAR, encoding="utf-8")
    out = tmp_path / "o.svg"
    cmd = [sys.executable, "-m", "graphkin.cli", "plot", str(f), "--what", "omega,alpha,path:E",
           "-o", str(out), "--count", "90"]
    r = subprocess.run(cmd, capture_output=True, text=True, check=False)
    assert r.returncode == 0, r.stderr
    assert out.read_bytes().startswith(b"<?xml")
    r = subprocess.run(cmd[:5] + ["--what", "speed", "-o", str(out)], capture_output=True,
                       text=True, check=False)
    assert r.returncode == 2 and "valid" in r.stderr and "Traceback" not in r.stderr


def test_no_pyplot_state() -> None:
    code = ("import sys, graphkin; from graphkin.render.plots import sweep_figure; "
            f"sw = graphkin.loads({FOURBAR!r}).sweep(count=20); sweep_figure(sw, 'omega'); "
            "print('matplotlib.pyplot' in sys.modules)")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert r.stdout.strip() == "False"
    assert math.isfinite(1.0)


def _gid_line(fig, gid):
    for ax in fig.axes:
        for line in ax.get_lines():
            if line.get_gid() == gid:
                return np.asarray(line.get_xydata(), dtype=float)
    raise KeyError(gid)


def test_centrodes_touch_at_the_pole_and_roll_without_slip():
    # Sec. 3.20: the moving centrode rolls on the fixed one without slip, touching at
    # the velocity pole.  For Example 3.1 the pole of the coupler at the file's posture
    # is I13 = (5.42613, -9.39833) (expected.toml).  Rolling without slip: from the
    # contact point the two curves have equal arc lengths to the next contact points.
    from graphkin.render.plots import sweep_figure

    mech = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml")
    sw = mech.sweep(count=720, start=120.0, stop=160.0, centers=True)
    fig = sweep_figure(sw, "centrode:3")
    fixed = _gid_line(fig, "centrode-fixed-3")
    moving = _gid_line(fig, "centrode-moving-3")
    np.testing.assert_allclose(fixed[0], [5.42613, -9.39833], atol=1e-4)
    np.testing.assert_allclose(moving[0], fixed[0], atol=1e-9)
    for m in (60, 180, 360):
        lf = np.sum(np.hypot(*np.diff(fixed[: m + 1], axis=0).T))
        lm = np.sum(np.hypot(*np.diff(moving[: m + 1], axis=0).T))
        assert lm == pytest.approx(lf, rel=2e-3)


def test_coupler_curve_marks_its_osculating_circle_and_balls_point():
    # the osculating circle at the first posture has the radius of curvature of E's path,
    # 4.320695 in for Example 3.1 (expected.toml); Ball's point U lies on its own track
    from graphkin.render.plots import sweep_figure

    mech = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml")
    fig = sweep_figure(mech.sweep(count=72), "path:E")
    (ax,) = fig.axes
    (circ,) = [p for p in ax.patches if p.get_gid() == "path-E-osculating"]
    assert circ.get_radius() == pytest.approx(4.320695, abs=1e-4)
    u = _gid_line(fig, "ball-point-3")[0]
    track = _gid_line(fig, "path-E-ball-point")
    assert np.min(np.hypot(*(track - u).T)) < 1e-9 * mech.scale


def test_path_of_an_instant_center():
    # I24 of a four-bar lies on the frame line A-D (Kennedy: on I12-I14), so its path is
    # on y = 0
    from graphkin.render.plots import sweep_figure

    mech = graphkin.load(EXAMPLES / "ex3_1_fourbar.toml")
    fig = sweep_figure(mech.sweep(count=36, centers=True), "center:I24")
    pts = _gid_line(fig, "center-I24")
    ok = np.isfinite(pts).all(axis=1)
    assert ok.sum() > 10
    np.testing.assert_allclose(pts[ok, 1], 0.0, atol=1e-9)
