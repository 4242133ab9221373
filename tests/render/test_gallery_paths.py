"""A gallery row whose path is misspelt is the file's mistake, said in one line.

Acceptance input: a toggle press whose [[gallery.book]] row read
``forces.drive.torque`` (the JSON has ``forces.drives.2.torque``); the index
showed "—" and "**differs**", as if graphkin disagreed with the book.
The right path gives graphkin's torque, 32641.7 N·mm by virtual work
(T12 ω2 + F·V_Q = 0: 5000 N × 195.85 mm/s / 30 rad/s).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from graphkin.cli import main

SRC = Path(__file__).resolve().parents[1] / "data" / "audit7" / "gallery" / "toggle.toml"


def _gallery(tmp_path: Path, path: str) -> Path:
    root = tmp_path / "g"
    (root / "mechanisms").mkdir(parents=True)
    text = SRC.read_text(encoding="utf-8").replace('path = "forces.drives.2.torque"',
                                                   f'path = "{path}"')
    (root / "mechanisms" / "toggle.toml").write_text(text, encoding="utf-8")
    return root


def test_the_right_path_agrees_with_virtual_work(tmp_path: Path) -> None:
    root = _gallery(tmp_path, "forces.drives.2.torque")
    assert main(["gallery", "--dir", str(root)]) == 0
    readme = (root / "README.md").read_text(encoding="utf-8")
    row = next(ln for ln in readme.splitlines() if ln.startswith("| T12 |"))
    assert "agrees" in row and "32642" in row


@pytest.mark.parametrize("path", ["forces.drive.torque", "links.9.omega", "forces.drives.2.x"])
def test_a_misspelt_path_is_one_line_naming_the_row(tmp_path: Path, path: str,
                                                    capsys: pytest.CaptureFixture[str]) -> None:
    root = _gallery(tmp_path, path)
    assert main(["gallery", "--dir", str(root)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "toggle.toml" in err[0] and "gallery.book[0].path" in err[0]
    assert "(there: " in err[0]
    shutil.rmtree(root)
