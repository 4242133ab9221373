"""The cam report writes its units as the rest of graphkin's output does.

Defects noticed at the session-8 stop: the report printed ``mm/s^2`` (every
other report prints ``mm/s²``), and the warnings gave the jumps in y' and y''
without a unit.  y' and y'' are derivatives by the cam angle (Sec. 6.8), so
they are in mm/rad and mm/rad² (rad/rad and rad/rad² for an oscillating follower).
"""

from __future__ import annotations

from pathlib import Path

from graphkin.cams.parse import loads_cam
from graphkin.cams.report import cam_text
from graphkin.cli import main

# A harmonic rise of L = 30 mm over β = 180°, then a cycloidal return over 180°.
# Harmonic (Eq. 6.11): y'' = (π²L / 2β²) cos(πθ/β) = ±15 mm/rad² at its ends (β = π);
# cycloidal: y'' = (2πL/β²) sin(2πθ/β) = 0 at its ends.  So y'' jumps from -15 to 0 at
# Θ = 180° and from 0 to 15 at Θ = 0°.
CAM = """units = "mm"
[cam]
prime = 40
speed = "10 rad/s"
[follower]
kind = "roller"
roller = 12
[[segment]]
motion = "harmonic"
lift = 30
angle = 180
[[segment]]
motion = "cycloidal"
lift = -30
angle = 180
"""


def test_rates_are_printed_with_superscript_powers() -> None:
    text = cam_text(loads_cam(CAM))
    rates = text.split("Follower at ω")[1]
    assert "mm/s²" in rates and "mm/s³" in rates
    assert "^" not in text


def test_jumps_in_y1_and_y2_carry_their_unit(tmp_path: Path, capsys) -> None:  # type: ignore[no-untyped-def]
    f = tmp_path / "c.toml"
    f.write_text(CAM, encoding="utf-8")
    assert main(["cam", str(f)]) == 0
    err = capsys.readouterr().err
    assert "y'' (acceleration) jumps from -15 to 0 mm/rad² at Θ = 180°" in err
    assert "y'' (acceleration) jumps from 0 to 15 mm/rad² at Θ = 0°" in err
    assert "jumps from -15 to 0 mm/rad²" in cam_text(loads_cam(CAM))
