"""``graphkin cam``: the report, its JSON, the outputs read back, and one-line errors (exit 2)."""

from __future__ import annotations

import json
import math
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest

from graphkin.cams import profile, stations
from graphkin.cams.parse import load_cam
from graphkin.cli import main

CAMS = Path(__file__).resolve().parents[2] / "examples" / "cams"
GOOD = ["ex6_3_flat_face", "ex6_5_roller", "ex6_6_roller", "ex6_7_oscillating"]


def _run(capsys, *args):
    rc = main(["cam", *map(str, args)])
    out = capsys.readouterr()
    return rc, out.out, out.err


@pytest.mark.parametrize("name", GOOD)
def test_the_examples_report(capsys, name):
    rc, out, err = _run(capsys, CAMS / f"{name}.toml", "--json")
    assert rc == 0 and err == ""
    d = json.loads(out)
    assert d["segments"] and d["pressure_angle"]["max"] >= 0 and d["undercut"] == []


def test_example_6_4_and_6_5_numbers_in_the_report(capsys):
    """Ex 6.4: least R0 for 30° (exact 3.627 in; the book's nomogram 3.9); Ex 6.5: 3.5 in."""
    rc, out, _ = _run(capsys, CAMS / "ex6_5_roller.toml", "--json")
    d = json.loads(out)
    assert abs(d["min_prime_for_pressure_angle"]["prime"] - 3.627) < 1e-3
    assert abs(d["radius_of_curvature"]["min"] - 3.5) < 1e-9
    # 150 rev/min, y'max 1.59155 in/rad in BC (Ex 6.2): 25 in/s ... the largest is in DE
    assert abs(d["rates"]["velocity"]["max"] - 2.834 * 150 * math.pi / 30) < 0.01
    rc, text, _ = _run(capsys, CAMS / "ex6_5_roller.toml")
    assert "least prime circle for |φ| ≤ 30°: R0 = 3.627" in text


def test_example_6_3_face_in_the_report(capsys):
    rc, out, _ = _run(capsys, CAMS / "ex6_3_flat_face.toml", "--json")
    d = json.loads(out)
    assert abs(d["face"]["min_width"] - 4.4255) < 1e-3 and d["face"]["given"] == 4.5
    assert abs(d["min_prime_for_radius"]["prime"] - 1.7443) < 1e-3


def test_the_layout_svg_has_every_element(capsys, tmp_path):
    out = tmp_path / "c.svg"
    rc, _, _ = _run(capsys, CAMS / "ex6_5_roller.toml", "-o", out, "--stations", "8")
    assert rc == 0
    ids = {el.get("id") for el in ET.parse(out).getroot().iter()}
    need = {"profile", "pitch-curve", "prime-circle", "base-circle", "O2", "title", "rotation"}
    need |= {f"name-{g}" for g in ("profile", "pitch-curve", "prime-circle", "base-circle")}
    need |= {f"station-{i}-{w}" for i in range(8) for w in ("roller", "axis", "label", "C")}
    assert need <= ids, need - ids


@pytest.mark.parametrize("name, parts", [("ex6_3_flat_face", ("face", "axis")),
                                         ("ex6_7_oscillating", ("roller", "arm", "O4"))])
def test_every_follower_kind_is_drawn(capsys, tmp_path, name, parts):
    out = tmp_path / "c.svg"
    assert _run(capsys, CAMS / f"{name}.toml", "-o", out)[0] == 0
    ids = {el.get("id") for el in ET.parse(out).getroot().iter()}
    assert {f"station-{i}-{p}" for i in range(12) for p in parts} <= ids


def test_the_displacement_diagram_svg(capsys, tmp_path):
    out = tmp_path / "d.svg"
    assert _run(capsys, CAMS / "ex6_5_roller.toml", "-d", "displacement", "-o", out)[0] == 0
    root = ET.parse(out).getroot()
    ids = {el.get("id") for el in root.iter()}
    assert {"diagram-Y", "diagram-y1", "diagram-y2", "title"} <= ids
    assert {f"boundary-Y-{j}" for j in range(1, 5)} <= ids
    assert {f"segment-label-{j}" for j in range(5)} <= ids
    text = "".join(el.text or "" for el in root.iter("{http://www.w3.org/2000/svg}text"))
    for name in ("AB", "BC", "CD", "DE"):
        assert name in text


def test_dxf_is_the_profile_to_true_scale(capsys, tmp_path):
    import ezdxf

    out = tmp_path / "p.dxf"
    assert _run(capsys, CAMS / "ex6_6_roller.toml", "-o", out, "--points", "720")[0] == 0
    doc = ezdxf.readfile(out)
    assert doc.header["$INSUNITS"] == 4            # mm
    poly = [e for e in doc.modelspace() if e.dxftype() == "LWPOLYLINE"]
    assert len(poly) == 1 and poly[0].closed
    pts = np.array([(p[0], p[1]) for p in poly[0].get_points()])
    exact = profile(load_cam(CAMS / "ex6_6_roller.toml").cam, stations(720)).contact
    assert np.allclose(pts[:, 0] + 1j * pts[:, 1], exact, atol=1e-9)


def test_csv_is_the_table_of_coordinates(capsys, tmp_path):
    out = tmp_path / "p.csv"
    assert _run(capsys, CAMS / "ex6_6_roller.toml", "-o", out, "--points", "36")[0] == 0
    rows = out.read_text().splitlines()
    assert rows[0] == "theta_deg,u_mm,v_mm,R_mm,psi_deg,rho_mm" and len(rows) == 37
    th, u, v = (float(x) for x in rows[4].split(",")[:3])      # Θ = 30°, Ex 6.6
    assert th == 30 and abs(u - 23.473) < 5e-4 and abs(v - 29.139) < 5e-4


BASE = """units = "mm"
[cam]
prime = 40
[follower]
kind = "roller"
roller = 12
"""
SEGS = """[[segment]]
motion = "cycloidal"
lift = 30
angle = 180
[[segment]]
motion = "cycloidal"
lift = -30
angle = 180
"""


@pytest.mark.parametrize("text, words", [
    (BASE + SEGS.replace("angle = 180\n[[", "angle = 170\n[["),
     ["segment[1].angle", "cover 350°, 10° short of 360°", "segment 2"]),
    (BASE + SEGS.replace("lift = -30", "lift = -20"),
     ["segment[0]", "segment 1 (cycloidal rise): the displacement jumps from 10 to 0"]),
    (BASE.replace("prime = 40", "prime = -4") + SEGS,
     ["cam.prime", "must be positive"]),
    # a 45 mm roller on a 40 mm prime circle is bigger than it, not "as big as" (audit9)
    (BASE.replace("roller = 12", "roller = 45") + SEGS,
     ["follower.roller", "the roller (radius 45) is bigger than the prime circle (40)",
      "the follower cannot follow"]),
    (BASE.replace("roller = 12", "roller = 40") + SEGS,
     ["follower.roller", "the roller (radius 40) is as big as the prime circle (40)"]),
    (BASE.replace("prime = 40", "prime = 40\nrotaton = \"cw\"") + SEGS,
     ["cam.rotaton", "did you mean 'rotation'"]),
    (BASE + SEGS.replace("cycloidal", "cycloidel", 1),
     ["segment[0].motion", "did you mean 'cycloidal'"]),
    (BASE + SEGS.replace("cycloidal", "half-cycloidal", 1),
     ["segment[0].rest", "missing"]),
    (BASE.replace("roller = 12", "roller = 12\npivot = [1, 2]") + SEGS,
     ["follower.pivot", "a roller follower has no pivot"]),
    (BASE.replace("prime = 40", "prime = 12").replace("roller = 12", "roller = 10")
     + SEGS.replace("angle = 180\n[[", "angle = 60\n[[").replace("angle = 180\n", "angle = 300\n"),
     ["segment[0]", "segment 1 (cycloidal rise): the profile is undercut", "cannot follow",
      "would do"]),
])
def test_bad_files_are_one_line_naming_the_key(capsys, tmp_path, text, words):
    f = tmp_path / "c.toml"
    f.write_text(text)
    rc, out, err = _run(capsys, f)
    assert rc == 2 and out == ""
    assert err.count("\n") == 1 and str(f) in err, err
    for w in words:
        assert w in err, (w, err)


def test_an_undercut_cam_is_drawn_when_allowed(capsys, tmp_path):
    out = tmp_path / "u.svg"
    rc, text, _ = _run(capsys, CAMS / "fig6_25_undercut.toml", "--allow-undercut", "-o", out)
    assert rc == 0 and "UNDERCUT: segment 1" in text
    ids = {el.get("id") for el in ET.parse(out).getroot().iter()}
    assert {"profile", "undercut-0", "station-0-face"} <= ids


def test_a_jump_in_acceleration_is_a_warning_on_stderr(capsys, tmp_path):
    f = tmp_path / "c.toml"
    f.write_text(BASE + SEGS.replace("cycloidal", "harmonic", 1))   # then a cycloidal return
    rc, out, err = _run(capsys, f)
    assert rc == 0
    assert "warning: segment 2 (cycloidal return): y'' (acceleration) jumps" in err
    assert "at Θ = 180°" in err and err.count("warning") == 2


def test_steps_lists_one_station_of_the_layout(capsys):
    rc, out, _ = _run(capsys, CAMS / "ex6_5_roller.toml", "--steps")
    assert rc == 0
    steps = out.split("The layout by inversion")[1]
    for label in ("O2", "k0", "kb", "A", "axis", "T", "I24", "roller", "n", "C"):
        assert f"  {label} " in steps, label


def test_a_face_that_turns_with_the_cam_cannot_follow(capsys, tmp_path):
    """An oscillating face whose arm turns as fast as the cam (ω4 = ω2) has no envelope point."""
    f = tmp_path / "c.toml"
    f.write_text("""units = "in"
[cam]
prime = 1.5
[follower]
kind = "oscillating-flat-face"
pivot = [3.0, 0.0]
rise = "ccw"
[[segment]]
motion = "harmonic"
lift = "1 rad"
angle = 90
[[segment]]
motion = "harmonic"
lift = "-1 rad"
angle = 270
""")
    rc, out, err = _run(capsys, f)
    assert rc == 2 and "cannot follow" in err and err.count("\n") == 1


def test_the_equivalent_linkage_is_a_mechanism_file_graphkin_solves(capsys, tmp_path):
    """Ex 6.6 at 30°: the written linkage solves; its follower moves at y'ω = 25.981 mm/s."""
    out = tmp_path / "eq.toml"
    assert _run(capsys, CAMS / "ex6_6_roller.toml", "--equivalent", "30", "-o", out)[0] == 0
    rc = main(["solve", str(out), "--json"])
    d = json.loads(capsys.readouterr().out)
    assert rc == 0
    assert abs(d["points"]["T"]["velocity"][1] - 25.981) < 1e-3
    rc = main(["draw", str(out), "-d", "velocity", "-o", str(tmp_path / "v.svg")])
    assert rc == 0 and (tmp_path / "v.svg").exists()


def test_the_tutorial_shows_what_graphkin_prints(capsys, tmp_path):
    """docs/tutorial/cam.md: its file is examples/cams/ex6_5_roller.toml and its report block
    is what graphkin cam prints for it."""
    import re

    page = (CAMS.parents[1] / "docs" / "tutorial" / "cam.md").read_text(encoding="utf-8")
    toml = re.search(r"```toml\n(.*?)```", page, re.DOTALL).group(1)
    f = tmp_path / "cam.toml"
    f.write_text(toml)
    assert load_cam(f).cam.program.segments == load_cam(CAMS / "ex6_5_roller.toml").cam \
        .program.segments
    rc, out, _ = _run(capsys, f)
    shown = re.search(r"```text\n(.*?)```", page, re.DOTALL).group(1)
    for line in shown.splitlines():
        assert line in out, line


def test_the_output_never_overwrites_the_input(capsys, tmp_path):
    f = tmp_path / "c.toml"
    f.write_text((CAMS / "ex6_6_roller.toml").read_text())
    for extra in (["--equivalent", "30", "-o", str(f)], ["-o", str(f)]):
        rc, out, err = _run(capsys, f, *extra)
        assert rc == 2 and "--output" in err and "refusing to write over" in err
    assert f.read_text() == (CAMS / "ex6_6_roller.toml").read_text()


@pytest.mark.parametrize("special", ["/dev/zero", "folder"])
def test_files_that_are_not_small_regular_files(capsys, tmp_path, special):
    path = str(tmp_path) if special == "folder" else special
    if not Path(path).exists():
        pytest.skip(f"{path} does not exist here")
    rc, out, err = _run(capsys, path)
    assert rc == 2 and "not a regular file" in err and err.count("\n") == 1


def test_the_design_drawing_marks_the_extremes(capsys, tmp_path):
    """-d design: φ and ρ over the cycle, the largest |φ| and the least ρ marked (Ex 6.4-6.5)."""
    out = tmp_path / "d.svg"
    assert _run(capsys, CAMS / "ex6_5_roller.toml", "-d", "design", "-o", out)[0] == 0
    root = ET.parse(out).getroot()
    ids = {el.get("id") for el in root.iter()}
    assert {"pressure-angle", "pressure-max", "radius-of-curvature", "radius-min",
            "title"} <= ids
    text = "".join(el.text or "" for el in root.iter("{http://www.w3.org/2000/svg}text"))
    assert "28.1558" in text and "3.5 in" in text
    out2 = tmp_path / "u.svg"
    assert _run(capsys, CAMS / "fig6_25_undercut.toml", "--allow-undercut", "-d", "design",
                "-o", out2)[0] == 0
    assert "undercut-0" in {el.get("id") for el in ET.parse(out2).getroot().iter()}


def test_the_displacement_diagram_reads_in_rates_at_the_cam_s_speed(capsys, tmp_path):
    out = tmp_path / "d.svg"
    assert _run(capsys, CAMS / "ex6_5_roller.toml", "-d", "displacement", "-o", out)[0] == 0
    ids = {el.get("id") for el in ET.parse(out).getroot().iter()}
    assert {"rate-axis-y1", "rate-axis-y2"} <= ids


@pytest.mark.parametrize("ext", ["svg", "dxf", "csv"])
def test_writing_a_file_says_so(capsys, tmp_path, ext):
    # every command that writes a file says "wrote OUT" on standard error (audit7: cam -o
    # wrote the file silently, the report alone on standard output)
    out = tmp_path / f"profile.{ext}"
    rc, text, err = _run(capsys, CAMS / "ex6_6_roller.toml", "-o", out)
    assert rc == 0 and out.exists() and f"wrote {out}" in err and f"wrote {out}" not in text


def test_a_table_segment_reports_its_lift(capsys, tmp_path):
    # A table rising from Y = 0 to Y = 20 mm over 180°, then a harmonic return of -20 mm:
    # its lift is 20 - 0 = 20 mm, as the return's -20 mm says (audit9: reported "0 mm").
    f = tmp_path / "t.toml"
    f.write_text('units = "mm"\n[cam]\nprime = 40\n[follower]\nkind = "roller"\nroller = 10\n'
                 '[[segment]]\nmotion = "table"\nangle = 180\n'
                 'points = [[0, 2], [45, 5], [90, 12], [135, 19], [180, 22]]\n'
                 '[[segment]]\nmotion = "harmonic"\nlift = -20\nangle = 180\n')
    assert main(["cam", str(f), "--json"]) == 0
    segs = json.loads(capsys.readouterr().out)["segments"]
    assert [s["lift"] for s in segs] == [20, -20]
    assert main(["cam", str(f)]) == 0
    row = next(r for r in capsys.readouterr().out.splitlines() if " table " in r)
    assert "20 mm" in row and "0 mm" not in row.replace("20 mm", "")
