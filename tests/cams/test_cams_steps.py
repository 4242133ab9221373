"""``graphkin steps CAMFILE -d cam``: the layout by inversion, one frame per step (Sec. 6.4)."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from pathlib import Path

from graphkin.cams.examples import example_6_6
from graphkin.cli import main
from graphkin.render.cam_steps import cam_frames

ROOT = Path(__file__).resolve().parents[2]


def _ids(svg: str) -> set[str]:
    return {el.get("id", "") for el in ET.fromstring(svg.encode()).iter()}


def test_the_frames_teach_the_book_s_order():
    """The circles first; then station i adds the follower at station i only; the profile
    (and the pitch curve) last, as the curve tangent to every roller (Sec. 6.4, Fig. 6.8)."""
    n = 4
    frames = cam_frames(example_6_6(), n)
    assert [t for t, _, _ in frames] == ["circles", "station 0", "station 1", "station 2",
                                         "station 3", "the profile"]
    for k, (_, _, svg) in enumerate(frames):
        ids = _ids(svg)
        assert "prime-circle" in ids and "base-circle" in ids
        drawn = {i for i in range(n) if f"station-{i}-roller" in ids}
        assert drawn == set(range(min(k, n))), (k, drawn)
        assert ("profile" in ids) == (k == n + 1) == ("pitch-curve" in ids)
    # station 1 of Ex 6.6 (Θ = 90°): Y = 15(1 − cos 180°) = 30 mm, the note says so
    assert "Y = 30 mm" in frames[2][1] and "inversion" in frames[2][1]


def test_steps_d_cam_writes_the_page(tmp_path, capsys):
    out = tmp_path / "cam.html"
    assert main(["steps", str(ROOT / "examples" / "cams" / "ex6_7_oscillating.toml"),
                 "-d", "cam", "-o", str(out)]) == 0
    page = out.read_text(encoding="utf-8")
    assert page.count("<section class='frame'") == 14          # circles, 12 stations, profile
    assert "swing the arm about O4" in page


def test_steps_d_cam_on_a_mechanism_file_is_one_line(tmp_path, capsys):
    """A mechanism file is not a cam file: one line naming the file and the key."""
    rc = main(["steps", str(ROOT / "examples" / "cams" / "cam_mechanism.toml"), "-d", "cam",
               "-o", str(tmp_path / "x.html")])
    err = capsys.readouterr().err
    assert rc == 2 and err.count("\n") == 1 and "cam_mechanism.toml" in err, err
