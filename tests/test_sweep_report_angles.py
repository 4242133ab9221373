"""``sweep --singular`` writes drive angles in [0, 360) (audit9, item 5).

The sweep starts at the file's angle (300°) and runs one turn, to 660°; the
report said "drive 510.00°".  The slider-crank on a line at 150° through the
crank pivot O (crank 40, rod 120 mm) is at its limit positions when crank and
rod are collinear along the line: the crank at 150° (B at 40 + 120 = 160 mm)
and at 330° (B at 120 − 40 = 80 mm).
"""

from __future__ import annotations

import csv
import io
import re
from pathlib import Path

import numpy as np

from graphkin.cli import main

SC_INCL = Path(__file__).parent / "data" / "worksheet" / "sc_incl.toml"


def test_limit_positions_are_reported_within_one_turn(tmp_path, capsys):
    assert main(["sweep", str(SC_INCL), "--singular", "--csv", str(tmp_path / "s.csv")]) == 0
    err = capsys.readouterr().err
    at = {m[2]: float(m[1]) for m in re.finditer(r"at drive ([-\d.]+)°, B at (\d+) mm", err)}
    assert at == {"80": 330.0, "160": 150.0}, err
    assert all(0 <= float(a) < 360 for a in re.findall(r"([-\d.]+)°", err)), err


def test_the_csv_writes_the_slider_line_angle_as_solve_does(tmp_path):
    # audit9 #6: T = (-86.6025403784, 50) puts the line at 150° to 2.5e-11° (100 cos 150°
    # = -86.60254037844386), far below round-off of the angles' scale (1e-12 × 360° is
    # 3.6e-10°): written 150.0, not 149.99999999998744; x_A = 40 cos 300° = 20 exactly.
    out = tmp_path / "s.csv"
    assert main(["sweep", str(SC_INCL), "--count", "4", "--csv", str(out)]) == 0
    rows = list(csv.DictReader(out.open(encoding="utf-8")))
    assert {r["angle_4"] for r in rows} == {"150.0"}
    assert rows[0]["x_A"] == "20.0" and rows[0]["drive"] == "300.0"


def test_rounding_moves_no_value_beyond_round_off_of_its_scale():
    import graphkin
    from graphkin.text import ROUND_OFF

    sw = graphkin.load(SC_INCL).sweep(count=7)
    rows = list(csv.DictReader(io.StringIO(sw.csv_text())))
    for name, col in sw.columns.items():
        kind_cols = [c for n, c in sw.columns.items() if n.split("_")[0] == name.split("_")[0]]
        scale = max(float(np.nanmax(np.abs(c))) for c in kind_cols)
        if name.startswith("angle"):
            scale = max(scale, 360.0)
        written = np.array([float(r[name]) for r in rows])
        assert np.allclose(written, col, rtol=0, atol=ROUND_OFF * scale), name
