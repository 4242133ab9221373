"""``graphkin draw``: formats by suffix, one-line errors and exit status 2."""

from __future__ import annotations

import xml.etree.ElementTree as ET

from spec_data import EXAMPLES

from graphkin.cli import main


def test_draw_writes_an_svg_with_the_steps(tmp_path, gk):
    out = tmp_path / "v.svg"
    assert main(["draw", str(EXAMPLES / "ex3_1_fourbar.toml"), "--diagram", "velocity",
                 "-o", str(out)]) == 0
    ids = {el.get("id") for el in ET.parse(out).getroot().iter()}
    assert {s.step_id for s in gk.solved("ex3_1_fourbar").constructions["velocity"]} <= ids


def test_draw_refuses_a_velocity_polygon_without_rates(tmp_path, capsys, gk):
    rc = main(["draw", str(EXAMPLES / "ex2_5_open.toml"), "--diagram", "velocity",
               "-o", str(tmp_path / "v.svg")])
    err = capsys.readouterr().err
    assert rc == 2
    assert "no rates" in err and err.count("\n") == 1
    assert not (tmp_path / "v.svg").exists()


def test_draw_refuses_an_unknown_format(tmp_path, capsys, gk):
    rc = main(["draw", str(EXAMPLES / "ex2_5_open.toml"), "-o", str(tmp_path / "v.jpg")])
    assert rc == 2
    assert ".svg" in capsys.readouterr().err
