"""A design chapter's file given where a mechanism file goes is named for what it is.

`graphkin live ex6_1.toml` used to say "cam: unknown key 'cam' (did you mean
'cams'?)", which sends the user to rename a key of a file that is right. Every
cam, gear, synthesis and vector file the gallery carries (its own copies, in
the repository) must instead be refused in one line that names the command
reading it (docs/formats/cam.md, gears.md, synthesis.md, vector.md).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from graphkin.cli import main
from graphkin.files import parse_toml, read_text
from graphkin.keys import design_file

GALLERY = Path(__file__).resolve().parents[2] / "gallery"
#: folder -> the command of docs/formats that reads its files
KINDS = {"cams": "cam", "synthesis": "synthesize", "vector": "vector"}
FILES = sorted(p for d in KINDS for p in (GALLERY / d).glob("*.toml"))
GEAR_FILES = sorted((GALLERY / "gears").glob("*.toml"))


def test_the_gallery_has_design_files() -> None:
    assert len(FILES) >= 15 and len(GEAR_FILES) >= 5


@pytest.mark.parametrize("path", FILES, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_a_design_file_is_refused_naming_its_command(path: Path, tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    verb = KINDS[path.parent.name]
    # a cam file's live page is its cam mechanism's, a synthesis file's its first linkage's,
    # a vector file's its construction of C = A + B (tests/render/test_live_cam_files.py,
    # test_live_synthesis_files.py, test_live_vector.py)
    live = [] if verb in ("cam", "synthesize", "vector") else \
        [["live", str(path), "-o", str(tmp_path / "p.html")]]
    for argv in (*live, ["draw", str(path), "-o", str(tmp_path / "d.png")],
                 ["sweep", str(path), "--csv", str(tmp_path / "s.csv")]):
        assert main(argv) == 2
        err = capsys.readouterr().err.strip()
        assert len(err.splitlines()) == 1, err
        assert f"'graphkin {verb} {path}' reads it" in err
        assert "unknown key" not in err and "did you mean" not in err


@pytest.mark.parametrize("path", GEAR_FILES, ids=lambda p: p.name)
def test_a_gear_file_is_named_or_is_a_mechanism(path: Path) -> None:
    # the gears folder holds pair and train files and mechanisms with rolling
    # gears ([links.N]): only the former are gear files
    data = parse_toml(read_text(path), str(path))
    kind = design_file(data)
    if "links" in data:
        assert kind is None
    else:
        assert kind is not None and kind[1] == "gears"


def test_a_case_1_vector_file_without_its_unknown_vectors_table_is_named() -> None:
    # case 1 (Fig. 2.10): C unknown, so the file may give [A] and [B] only
    kind = design_file({"A": {"magnitude": 3, "angle": 0}, "B": {"magnitude": 4, "angle": 90}})
    assert kind is not None and kind[1] == "vector"


def test_a_mechanism_file_with_a_cam_link_is_not_a_design_file() -> None:
    assert design_file({"links": {"1": {}}, "cams": [{}]}) is None
    assert design_file({"title": "no links at all"}) is None
