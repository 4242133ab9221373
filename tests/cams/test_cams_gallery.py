"""The gallery's cam files (gallery/cams/, Examples 6.1-6.8), the cam file's [dynamics], and
the layout's speed.

The book's numbers live in each file's [[gallery.book]] rows; a row where graphkin differs
must say why (with the evidence), and a row that agrees must not need to.
"""

from __future__ import annotations

import math
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from graphkin.cams.layout import layout, stations
from graphkin.cams.parse import load_cam, loads_cam
from graphkin.cams.report import cam_json
from graphkin.errors import InputError
from graphkin.render import gallery as G
from graphkin.render.gallery_cams import render_entry, solution

ROOT = Path(__file__).resolve().parents[2]
ENTRIES = [e for e in G.discover(ROOT / "gallery") if e.folder == "cams"]


def test_every_example_of_chapter_6_is_in_the_gallery():
    found = {str(e.meta.get("examples")) for e in ENTRIES}
    assert {f"Example 6.{k}" for k in range(1, 9)} <= found


@pytest.mark.parametrize("entry", ENTRIES, ids=lambda e: e.path.stem)
def test_the_book_rows_agree_or_say_why(entry):
    rows = G._rows(entry, solution(load_cam(entry.path)))
    assert rows, "a gallery file compares at least one number with the book's"
    for r in rows:
        assert r["graphkin"] != "—", f"{r['quantity']}: path not found"
        if r["verdict"] != "agrees":
            assert r["why"], f"{r['quantity']}: differs without saying why"


def test_the_drawings_are_svg_with_the_named_diagrams():
    entry = next(e for e in ENTRIES if e.path.stem == "ex6_3_flat_face")
    drawings, info = render_entry(entry)
    assert sorted(drawings) == ["cams-ex6_3_flat_face-design.svg",
                                "cams-ex6_3_flat_face-layout.svg"]
    for data in drawings.values():
        assert ET.fromstring(data).tag.endswith("svg")
    assert info["title"].startswith("Example 6.3")


def test_an_unknown_diagram_is_one_line(tmp_path):
    p = tmp_path / "c.toml"
    p.write_text((ROOT / "gallery" / "cams" / "ex6_1_parabolic.toml").read_text()
                 .replace('diagrams = ["displacement"]', 'diagrams = ["profile"]'))
    with pytest.raises(InputError, match="not 'profile'"):
        render_entry(G.Entry(p, "cams", {"diagrams": ["profile"]}))


def test_the_solution_at_a_station_is_the_book_s_example_6_6():
    """Ex 6.6 at Θ = 30°: u = (R0 + Y) sin Θ + R_r (v'/w') (the book's Eqs. 3a, 4b, 6 and its
    Ans.), by hand from Y = 7.5, y' = 25.981: 47.5 sin 30° + 12(−1.250/54.141) = 23.473."""
    d = solution(load_cam(ROOT / "examples" / "cams" / "ex6_6_roller.toml"))
    u1 = 25.98076211 * math.sin(math.radians(30)) + 47.5 * math.cos(math.radians(30))
    v1 = 25.98076211 * math.cos(math.radians(30)) - 47.5 * math.sin(math.radians(30))
    w1 = math.hypot(u1, v1)
    u = 47.5 * math.sin(math.radians(30)) + 12 * v1 / w1
    assert abs(d["at"]["30"]["contact"][0] - u) < 1e-9
    assert d["segments"]["0"]["motion"] == "harmonic"


DYN = """units = "mm"
[cam]
prime = 50
[follower]
kind = "flat-face"
[[segment]]
motion = "parabolic"
lift = 40
angle = 120
[[segment]]
motion = "dwell"
angle = 30
[[segment]]
motion = "parabolic"
lift = -40
angle = 210
[dynamics]
spring = "5 kN/m"
preload = 35
mass = "18 kg"
"""


def test_example_6_8_jump_speed_from_the_cam_file():
    """Ex 6.8: ω = √((kY + P)/(m·4L/β²)) at Θ = 60° with Y = 0.020 m, L = 0.040 m,
    β = 2π/3: √(135/(18·0.0365)) = 14.3 rad/s (137 rev/min)."""
    d = cam_json(loads_cam(DYN))
    exact = math.sqrt(135 / (18 * 4 * 0.040 / (2 * math.pi / 3) ** 2))
    assert abs(d["jump"]["omega"] - exact) < 1e-6
    assert abs(d["jump"]["at"] - 60) < 1e-6
    assert round(d["jump"]["rev_per_min"]) == 137


@pytest.mark.parametrize("old, new, key", [
    ("mass = \"18 kg\"", "mass = 0", "dynamics.mass"),
    ("mass = \"18 kg\"", "mass = \"18 m\"", "dynamics.mass"),
    ("preload = 35", "", "dynamics.preload"),
    ("preload = 35", "preload = 35\nspeed = 2", "dynamics.speed"),
])
def test_bad_dynamics_are_one_line_naming_the_key(old, new, key):
    with pytest.raises(InputError) as err:
        loads_cam(DYN.replace(old, new), "c.toml")
    line = err.value.one_line()
    assert "\n" not in line and key in line, line


def test_laying_out_3600_points_takes_less_than_50_ms():
    """The acceptance benchmark of issue 27: the layout recorded and evaluated on 3600
    stations at once (best of five; numpy only, nothing compiled)."""
    cam = load_cam(ROOT / "examples" / "cams" / "ex6_5_roller.toml").cam
    th = stations(3600)
    best = math.inf
    for _ in range(5):
        t0 = time.perf_counter()
        c = layout(cam).contact(th)
        best = min(best, time.perf_counter() - t0)
    assert c.shape == (3600,) and np.all(np.isfinite(c))
    assert best < 0.050, f"{best * 1e3:.1f} ms"
