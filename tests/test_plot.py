"""``graphkin plot``: curves over a sweep, as artists and as deterministic SVG."""

from __future__ import annotations

import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.errors import InputError
from graphkin.render.plots import parse_what, save_figure, sweep_figure

FOURBAR = """
title = "crank-rocker"
[links.1]
A = [0, 0]
D = [10, 0]
[links.2]
A = [0, 0]
B = [4, 0]
[links.3]
B = [0, 0]
C = [12, 0]
E = [6, -3]
[links.4]
D = [0, 0]
C = [11, 0]
[drive]
link = 2
angle = 120
omega = 10
[assembly]
C = [9, 11]
"""

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
    (line,) = fig.axes[0].get_lines()
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
