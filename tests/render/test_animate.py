"""``graphkin animate``: the cycle's data equal the sweep's; the page is light and offline."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
from spec_data import EXAMPLES

import graphkin
from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.render.animate import animate_html, cycle_data


def _decode(series, q):
    return np.array([np.nan if v is None else v * q for v in series])


@pytest.mark.parametrize("name", ["fourbar", "slider_crank", "inverted_slider_crank", "fivebar"])
def test_cycle_data_are_the_sweeps_values(name):
    mech = getattr(graphkin.examples, name)()
    data = cycle_data(mech, count=72)
    sw = mech.sweep(count=72)
    assert data["n"] == 72 and len(data["valid"]) == 72
    assert data["valid"] == "".join("1" if v else "0" for v in sw.assembled)
    for p, s in data["points"].items():
        for key, q in (("x", "L"), ("y", "L"), ("vx", "V"), ("vy", "V"), ("ax", "A"),
                       ("ay", "A")):
            got, want = _decode(s[key], data["q"][q]), sw.columns[f"{key}_{p}"]
            assert np.array_equal(np.isnan(got), np.isnan(want))
            # stored as integers of the quantum: within half a quantum of the sweep
            assert np.nanmax(np.abs(got - want), initial=0) <= 0.5 * data["q"][q] * (1 + 1e-9)
    # helper points (a slider's line) are not drawn as points
    assert not set(data["points"]) & mech.helper_points


def test_page_is_light_and_offline():
    text = animate_html(graphkin.examples.fivebar(), count=360, centers=True)
    assert len(text.encode("utf-8")) < 2 * 1024 * 1024
    assert not re.search(r'\b(src|href)="(https?:)?//', text)
    assert "<script src" not in text and "<link " not in text
    blob = re.search(r'<script type="application/json" id="cycle-data">(.*?)</script>', text,
                     re.S).group(1)
    data = json.loads(blob.replace("<\\/", "</"))
    assert data["n"] == 360 and "I13" in data["centers"]
    # two inputs (Example 5.4): the page says which is swept and which is held
    assert data["held"].startswith("θ2 is swept; θ3 held")


def test_unassemblable_range_and_toggles_are_in_the_data():
    """Example 3.1's four-bar cannot be assembled for part of the crank's turn."""
    data = cycle_data(graphkin.load(EXAMPLES / "ex3_1_fourbar.toml"), count=360)
    assert "0" in data["valid"]
    kinds = {e["kind"] for e in data["events"]}
    assert "cannot-assemble" in kinds and "limit" in kinds


def test_cli_animate(tmp_path, capsys):
    out = tmp_path / "cycle.html"
    assert main(["animate", str(EXAMPLES / "ex3_1_fourbar.toml"), "-o", str(out),
                 "--count", "36", "--inflection"]) == 0
    assert "graphkinCycle" in out.read_text(encoding="utf-8")
    assert "wrote" in capsys.readouterr().err


def test_cli_animate_sizes_polygons_per_posture_when_asked(tmp_path):
    out = tmp_path / "cycle.html"
    fit = re.compile(r'<input type="checkbox" id="fit"( checked)?>')
    for how, checked in (("cycle", None), ("posture", " checked")):
        assert main(["animate", str(EXAMPLES / "ex3_1_fourbar.toml"), "-o", str(out),
                     "--count", "12", "--polygons", how]) == 0
        m = fit.search(out.read_text(encoding="utf-8"))
        assert m is not None and m.group(1) == checked
    with pytest.raises(InputError, match="posture"):
        animate_html(graphkin.examples.fourbar(), count=12, polygons="each")


@pytest.mark.parametrize("args, words", [
    (["--count", "1"], "--count"),
    (["--inflection"], "needs rates"),
])
def test_cli_animate_mistakes_are_one_line(tmp_path, capsys, args, words):
    src = EXAMPLES / ("ex2_5_open.toml" if "--inflection" in args else "ex3_1_fourbar.toml")
    assert main(["animate", str(src), "-o", str(tmp_path / "x.html"), *args]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and len(err.splitlines()) == 1 and "Traceback" not in err


def test_frames_and_gif_for_slides(tmp_path):
    import xml.etree.ElementTree as ET

    out = tmp_path / "frames"
    assert main(["animate", str(EXAMPLES / "ex3_1_fourbar.toml"), "--count", "6",
                 "--frames", str(out), "--gif", str(tmp_path / "c.gif")]) == 0
    files = sorted(out.glob("cycle-*.svg"))
    assert [p.name for p in files] == [f"cycle-{i:03d}.svg" for i in range(6)]
    texts = {t.text for t in ET.parse(files[0]).getroot().iter("{http://www.w3.org/2000/svg}text")}
    assert any(t and "θ2 = 120.00°" in t for t in texts)  # the file's drive comes first
    gif = (tmp_path / "c.gif").read_bytes()
    assert gif[:6] in (b"GIF87a", b"GIF89a")


def test_cli_animate_without_an_output_writes_beside_the_user(tmp_path, capsys, monkeypatch):
    """Issue 31: no -o writes FILE-STEM-cycle.html in the current directory and says so."""
    monkeypatch.chdir(tmp_path)
    assert main(["animate", str(EXAMPLES / "ex3_1_fourbar.toml"), "--count", "4"]) == 0
    assert (tmp_path / "ex3_1_fourbar-cycle.html").is_file()
    assert "wrote ex3_1_fourbar-cycle.html" in capsys.readouterr().err


@pytest.mark.parametrize("name", ["inverted_slider_crank", "coriolis_block"])
def test_apparent_velocity_runs_along_the_slide(name):
    """V_P − V_Pk (the apparent velocity V_P/k, Eq. 3.6) lies along the slide of link k."""
    mech = getattr(graphkin.examples, name)()
    data = cycle_data(mech, count=36)
    sw = mech.sweep(count=36)
    (cp,) = data["coincident"]
    (sl,) = [s for s in mech.sliders if s.point == cp["point"]]
    theta = np.radians(sw.columns[f"angle_{sl.on}"])
    u0 = np.subtract(sl.p1, sl.p0) / np.hypot(*np.subtract(sl.p1, sl.p0))
    # the slide's direction in the world: link k's angle turns its own direction u0
    u = np.stack([np.cos(theta) * u0[0] - np.sin(theta) * u0[1],
                  np.sin(theta) * u0[0] + np.cos(theta) * u0[1]], axis=-1)
    vk = np.stack([_decode(cp["vx"], data["q"]["V"]), _decode(cp["vy"], data["q"]["V"])], -1)
    vp = np.stack([sw.columns[f"vx_{cp['point']}"], sw.columns[f"vy_{cp['point']}"]], -1)
    rel = vp - vk
    cross = rel[:, 0] * u[:, 1] - rel[:, 1] * u[:, 0]
    ok = np.isfinite(cross)
    assert ok.sum() > 10
    assert np.max(np.abs(cross[ok])) <= 1e-3 * np.nanmax(np.abs(vp))
    if name == "coriolis_block":
        # Example 4.4: the block slides on the rod at 30 m/s = 30000 mm/s (given)
        assert np.allclose(np.hypot(*rel[ok].T), 30000.0, rtol=1e-4)
