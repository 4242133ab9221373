"""What a new user meets first: shipped examples, ``python -m graphkin``, short reprs, help."""

from __future__ import annotations

import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest

import graphkin
from graphkin.cli import build_parser, main


def test_example_list_names_every_shipped_example(capsys):
    assert main(["example", "list"]) == 0
    out = capsys.readouterr().out.splitlines()
    assert [line.split()[0] for line in out] == graphkin.examples.names()
    assert any("Examples 3.1" in line for line in out)


def test_example_prints_a_file_that_loads_and_solves(tmp_path, capsys):
    assert main(["example", "fourbar"]) == 0
    text = capsys.readouterr().out
    path = tmp_path / "fourbar.toml"
    path.write_text(text, encoding="utf-8")
    sol = graphkin.load(path).solve()
    # Example 3.1 (Sec. 3.4): θ3 = 20.92° in the book
    assert float(sol.angle(3)) == pytest.approx(20.92, abs=0.01)
    assert main(["example", "slider_crank", "-o", str(tmp_path / "sc.toml")]) == 0
    assert (tmp_path / "sc.toml").read_text(encoding="utf-8") == \
        graphkin.examples.text("slider_crank")


def test_unknown_example_is_one_line_with_a_suggestion(capsys):
    assert main(["example", "fourbr"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "did you mean 'fourbar'?" in err[0]


def test_python_dash_m_graphkin():
    run = subprocess.run([sys.executable, "-m", "graphkin", "--help"], capture_output=True,
                         text=True, timeout=120)
    assert run.returncode == 0
    assert "usage: graphkin" in run.stdout and "example" in run.stdout


def test_gallery_is_a_maintainer_command_hidden_from_help(capsys):
    parser = build_parser()
    assert " gallery " not in parser.format_help()
    # ... and it still runs (CI runs `graphkin gallery --check`)
    assert main(["gallery", "--dir", "no-such-folder"]) == 2
    assert "not a gallery folder" in capsys.readouterr().err


def test_reprs_are_short_and_readable():
    mech = graphkin.examples.fourbar()
    sol = mech.solve()
    for obj in (mech, sol, sol.constructions["velocity"], sol.constructions["acceleration"]):
        text = repr(obj)
        assert len(text) < 400 and "\n" not in text, text
    assert repr(mech).startswith("<Mechanism 'Four-bar linkage")
    assert "pins A D B C" in repr(mech) and "drive link 2 at 120°" in repr(mech)
    # Example 3.1: θ3 = 20.92° (the book)
    assert "θ3 = 20.92°" in repr(sol)
    assert "steps (" in repr(sol.constructions["velocity"])
    for name in graphkin.examples.names():
        assert repr(graphkin.examples.load(name)).startswith("<Mechanism ")


def test_draw_displays_in_jupyter():
    # Jupyter shows an object by its _repr_svg_: the drawing of sol.draw("velocity")
    sol = graphkin.examples.fourbar().solve()
    drawing = sol.draw("velocity")
    assert repr(drawing).startswith("<Drawing ") and len(repr(drawing)) < 200
    svg = drawing._repr_svg_()
    root = ET.fromstring(svg)
    ids = {el.get("id") for el in root.iter()}
    assert any(i and i.startswith("step-") for i in ids)
    # drawn into the user's own axes, the user's figure shows itself: no second copy
    from matplotlib.figure import Figure

    ax = Figure().add_subplot()
    assert sol.draw("velocity", ax=ax)._repr_svg_() is None
