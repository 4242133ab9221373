"""``sweep --singular`` writes drive angles in [0, 360) (audit9, item 5).

The sweep starts at the file's angle (300°) and runs one turn, to 660°; the
report said "drive 510.00°".  The slider-crank on a line at 150° through the
crank pivot O (crank 40, rod 120 mm) is at its limit positions when crank and
rod are collinear along the line: the crank at 150° (B at 40 + 120 = 160 mm)
and at 330° (B at 120 − 40 = 80 mm).
"""

from __future__ import annotations

import re
from pathlib import Path

from graphkin.cli import main

SC_INCL = Path(__file__).parent / "data" / "worksheet" / "sc_incl.toml"


def test_limit_positions_are_reported_within_one_turn(tmp_path, capsys):
    assert main(["sweep", str(SC_INCL), "--singular", "--csv", str(tmp_path / "s.csv")]) == 0
    err = capsys.readouterr().err
    at = {m[2]: float(m[1]) for m in re.finditer(r"at drive ([-\d.]+)°, B at (\d+) mm", err)}
    assert at == {"80": 330.0, "160": 150.0}, err
    assert all(0 <= float(a) < 360 for a in re.findall(r"([-\d.]+)°", err)), err
