"""The fewest-teeth line names a pinion's cutter offset (audit9, item 11).

The fewest teeth that mesh without interference are those of standard teeth;
a pinion cut with the rack cutter offset (profile shift, Sec. 7.11) may have
fewer.  The audit's pinion: 12 teeth, module 2 mm, φ = 20°, e = 1.5 mm.  By
Eq. (7.21) it is cut without undercut when e ≥ m (1 − N sin²φ / 2) =
2 (1 − 12 · 0.116978 / 2) = 0.596 mm, which 1.5 mm is: the report must not
leave the reader thinking 12 < 15 teeth interfere.
"""

from __future__ import annotations

import math
from pathlib import Path

from graphkin.cli import main

DATA = Path(__file__).parent / "data"


def _report(capsys, path: Path) -> str:
    assert main(["gears", str(path)]) == 0
    return capsys.readouterr().out


def test_the_offset_pinion_is_named_in_the_fewest_teeth_line(capsys):
    out = _report(capsys, DATA / "pinion_offset.toml")
    (line,) = [ln for ln in out.splitlines() if "fewest teeth" in ln]
    assert "for standard teeth" in line and "e = 1.5 mm" in line and "Sec. 7.11" in line
    # Eq. 7.21 by hand: the offset that avoids undercut, below the pinion's 1.5 mm
    need = 2 * (1 - 12 * math.sin(math.radians(20)) ** 2 / 2)
    assert abs(need - 0.596) < 1e-3 and 1.5 > need
    (undercut,) = [ln for ln in out.splitlines() if "undercut by a rack cutter" in ln]
    assert undercut.split()[-2:] == ["no", "no"]


def test_standard_teeth_keep_the_plain_line(tmp_path, capsys):
    p = tmp_path / "std.toml"
    p.write_text((DATA / "pinion_offset.toml").read_text().replace("offset = 1.5\n", ""))
    out = _report(capsys, p)
    (line,) = [ln for ln in out.splitlines() if "fewest teeth" in ln]
    # 20° full-depth teeth: 14 pinion teeth mesh with at most 26, 15 with at most 45 (the
    # interference limit N_G ≤ (N_P² sin²φ − 4k²)/(4k − 2 N_P sin²φ), k = 1): 15 for 40
    assert line.endswith(": 15.") and "offset" not in line
