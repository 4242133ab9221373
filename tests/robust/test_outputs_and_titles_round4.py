"""Round four of issue 25: the commands added since, under the same two classes.

* **Nothing the user gave may be lost**: an output option (``-o``, ``--csv``,
  ``--gif``, ``--draw``) equal to an input, or a link to it, and ``--frames``
  into a folder holding an input named like a frame, are refused in one line
  before any work by every command (the check is in the CLI, so a new
  command has it too): ``live -o`` and ``synthesize -o`` replaced the input.
* **A hostile title through the design commands** (``live``, ``cam``,
  ``gears``, ``steps`` of a gear pair, ``synthesize``): every command ends
  cleanly and the mechanism file ``synthesize -o`` writes reads back with the
  very title (it was written unquoted: an invalid TOML file).
"""

from __future__ import annotations

import json
import os
import re
import sys
import tomllib
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
from test_hostile_corpus import assert_clean, run  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
FOURBAR = ROOT / "examples" / "fourbar.toml"
CAM = ROOT / "examples" / "cams" / "ex6_5_roller.toml"
GEARS = ROOT / "examples" / "gears" / "ex7_1.toml"
SYNTH = """title = "Two postures"
units = "in"
[[postures]]
point = [0, 0]
angle = 0
[[postures]]
point = [1, 0.5]
angle = 30
[pivots]
circle_points = [[0.5, -1], [1.5, -1]]
center_points = [[0, -3], [3, -3]]
"""
TITLE = ('x² ﬁ "q" \'s\' \\ b\nnew __import__("os").system("x") \u202eRTL\u202c \u200f '
         '<!--<script> </script> ]]> {{}} %s ${x} \x7f')


def _files(tmp: Path) -> dict[str, Path]:
    out = {"m": tmp / "m.toml", "c": tmp / "c.toml", "g": tmp / "g.toml", "s": tmp / "s.toml"}
    out["m"].write_text(FOURBAR.read_text(encoding="utf-8"), encoding="utf-8")
    out["c"].write_text(CAM.read_text(encoding="utf-8"), encoding="utf-8")
    out["g"].write_text(GEARS.read_text(encoding="utf-8"), encoding="utf-8")
    out["s"].write_text(SYNTH, encoding="utf-8")
    return out


@pytest.mark.parametrize("argv,option", [
    (["live", "{m}", "-o", "{m}"], "--output"),
    (["live", "{m}", "-o", "{link}"], "--output"),
    (["synthesize", "{s}", "-o", "{s}"], "--output"),
    (["synthesize", "{s}", "--draw", "{s}"], "--draw"),
    (["cam", "{c}", "-o", "{c}"], "--output"),
    (["plot", "{m}", "--count", "4", "-o", "{link}"], "--output"),
    (["sweep", "{m}", "--count", "4", "--csv", "{link}"], "--csv"),
    (["steps", "{g}", "-o", "{g}"], "--output"),
    (["animate", "{m}", "--count", "3", "--gif", "{link}"], "--gif"),
])
def test_an_output_that_is_an_input_is_refused_by_every_command(argv: list[str], option: str,
                                                                  tmp_path: Path) -> None:
    f = _files(tmp_path)
    link = tmp_path / "same.html"
    link.symlink_to(f["m"])
    before = {k: p.read_bytes() for k, p in f.items()}
    rc, out, err = run([a.format(link=link, **f) for a in argv])
    assert_clean(rc, out, err)
    assert rc == 2 and option in err and "input file" in err, err
    assert {k: p.read_bytes() for k, p in f.items()} == before


@pytest.mark.parametrize("cmd,name", [
    (["steps", "{f}", "--frames", "{d}"], "step-00.svg"),
    (["steps", "{f}", "-d", "forces", "--frames", "{d}"], "forces-00.svg"),
    (["animate", "{f}", "--count", "3", "--frames", "{d}"], "cycle-000.svg"),
])
def test_frames_never_overwrite_an_input_named_like_a_frame(cmd: list[str], name: str,
                                                            tmp_path: Path) -> None:
    f = tmp_path / name
    text = FOURBAR.read_text(encoding="utf-8")
    f.write_text(text, encoding="utf-8")
    rc, out, err = run([a.format(f=f, d=tmp_path) for a in cmd])
    assert_clean(rc, out, err)
    assert rc == 2 and "--frames" in err, err
    assert f.read_text(encoding="utf-8") == text


def _titled(path: Path) -> None:
    text = path.read_text(encoding="utf-8")
    line = "title = " + json.dumps(TITLE).replace("\\u007f", "\\u007f")
    if re.search(r"^title = .*$", text, flags=re.M):
        text = re.sub(r"^title = .*$", lambda _m: line, text, flags=re.M)
    else:
        text = line + "\n" + text
    path.write_text(text, encoding="utf-8")


def test_a_hostile_title_through_the_design_commands(tmp_path: Path) -> None:
    f = _files(tmp_path)
    for p in f.values():
        _titled(p)
    t = tmp_path
    for argv in (["live", "{m}", "-o", "{t}/l.html"], ["live", "{c}", "-o", "{t}/lc.html"],
                 ["cam", "{c}"], ["cam", "{c}", "--json"],
                 ["cam", "{c}", "-o", "{t}/c.svg"], ["gears", "{g}"], ["gears", "{g}", "--json"],
                 ["steps", "{g}", "-o", "{t}/g.html"],
                 ["synthesize", "{s}", "--json"],
                 ["synthesize", "{s}", "-o", "{t}/out.toml", "--draw", "{t}/s.svg"]):
        rc, out, err = run([a.format(t=t, **f) for a in argv])
        assert_clean(rc, out, err)
        assert rc == 0, (argv, err)
    for page in ("l.html", "lc.html", "g.html"):
        html = (t / page).read_text(encoding="utf-8")
        assert "<!--<script>" not in html and "</script> ]]>" not in html
    # the mechanism file synthesize writes is TOML again, with the very title
    written = tomllib.loads((t / "out.toml").read_text(encoding="utf-8"))
    assert written["title"] == TITLE
    rc, out, err = run(["solve", str(t / "out.toml")])
    assert_clean(rc, out, err)
    assert rc == 0, err


def test_the_output_check_is_in_the_cli_for_every_command() -> None:
    """Every verb's output options are among those the CLI checks (a new verb too)."""
    from graphkin.cli import build_parser
    from graphkin.files import OUTPUT_OPTIONS

    parser = build_parser()
    sub = next(a for a in parser._actions if a.dest == "command" or a.choices)
    writers = set()
    for p in sub.choices.values():  # type: ignore[union-attr]
        for act in p._actions:
            if act.dest in ("output", "csv", "gif", "draw", "frames", "marks") or \
                    (act.metavar or "").upper().startswith("OUT"):
                writers.add(act.dest)
    assert writers <= set(OUTPUT_OPTIONS) | {"frames"}, writers
    assert os.path.exists(FOURBAR)


DESIGN = sorted((ROOT / "tests" / "data" / "hostile" / "design").glob("*.toml"))
DESIGN_COMMANDS = {"cam": [["cam"], ["cam", "--json"], ["cam", "-o", "{t}/c.svg"],
                           ["live", "-o", "{t}/l.html"]],   # its cam mechanism's page
                   "gears": [["gears"], ["gears", "--json"]],  # steps: in the title test
                   "synthesis": [["synthesize"], ["synthesize", "--json"],
                                 ["synthesize", "-o", "{t}/m.toml", "--draw", "{t}/s.svg"]]}


@pytest.mark.parametrize("path", DESIGN, ids=[p.stem for p in DESIGN])
def test_every_hostile_design_file_ends_cleanly(path: Path, tmp_path: Path) -> None:
    """The design chapters' corpus (tests/data/hostile/design, named by file kind)."""
    for cmd in DESIGN_COMMANDS[path.stem.split("_")[0]]:
        rc, out, err = run([cmd[0], str(path), *(a.format(t=tmp_path) for a in cmd[1:])])
        assert_clean(rc, out, err)
        assert "cannot handle" not in err, err
        if "not_table" in path.stem or "singular" in path.stem:
            assert rc == 2 and f"{path}: function: " in err, err
