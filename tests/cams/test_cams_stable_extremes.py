"""Of two equal extremes the cam report names the first in cam angle, on every machine.

Defect noticed at the session-8 stop: the largest |acceleration| of a
symmetric program was picked between equal maxima by round-off (``np.argmax``),
so a perturbation of 1e-12 of the inputs, or another CPU, moved the reported angle.

Example 6.6's program, Y = 15(1 - cos 2Θ) mm (four harmonic segments of 90°), at
ω = 10 rad/s (Eq. 6.11):  y' = 30 sin 2Θ, y'' = 60 cos 2Θ, y''' = -120 sin 2Θ, so
|V| = 300 mm/s at Θ = 45°, 135°, ...; |A| = 6000 mm/s² at Θ = 0°, 90°, 180°, 270°;
|jerk| = 120000 mm/s³ at 45°, ...  The pressure angle (radial roller, R0 = 40,
Eq. 6.33) tan φ = 30 sin 2Θ / (55 - 15 cos 2Θ) is largest in size where
cos 2Θ = 3/11: Θ = ½ acos(3/11) = 37.087°, and again at 142.9°, 217.1°, 322.9°.
The radius of curvature is least where the follower is highest, Θ = 90° and 270°.
"""

from __future__ import annotations

import math
import random
from pathlib import Path

import pytest

from graphkin.cams.parse import loads_cam
from graphkin.cams.report import cam_json
from graphkin.tolerance import first_largest

EX66 = (Path(__file__).resolve().parents[2] / "examples" / "cams" / "ex6_6_roller.toml"
        ).read_text(encoding="utf-8").replace('rotation = "ccw"',
                                              'rotation = "ccw"\nspeed = "10 rad/s"')


def _perturbed(seed: int) -> str:
    """Example 6.6 with each lift and the prime circle changed by up to 1e-12 of its size."""
    r = random.Random(seed)
    out = []
    for line in EX66.splitlines():
        key, sep, val = line.partition(" = ")
        if sep and key in ("lift", "prime"):
            line = f"{key} = {float(val) * (1 + r.uniform(-1e-12, 1e-12))!r}"
        out.append(line)
    return "\n".join(out) + "\n"


@pytest.mark.parametrize("seed", range(10))
def test_equal_extremes_are_reported_at_the_first_cam_angle(seed: int) -> None:
    d = cam_json(loads_cam(_perturbed(seed)))
    rates = d["rates"]
    assert rates["acceleration"]["max"] == pytest.approx(6000.0, rel=1e-9)
    assert rates["acceleration"]["at"] == pytest.approx(0.0, abs=1e-9)
    assert rates["velocity"]["max"] == pytest.approx(300.0, rel=1e-9)
    assert rates["velocity"]["at"] == pytest.approx(45.0, abs=1e-9)
    assert rates["jerk"]["at"] == pytest.approx(45.0, abs=1e-9)
    first = 0.5 * math.degrees(math.acos(3 / 11))
    assert d["pressure_angle"]["at"] == pytest.approx(first, abs=1e-3)
    assert d["radius_of_curvature"]["at"] == pytest.approx(90.0, abs=1e-3)


def test_first_largest_ignores_round_off_and_non_finite_values() -> None:
    assert first_largest([2.0, 5.0 - 5e-15, 5.0, 1.0]) == 1   # equal within round-off
    assert first_largest([2.0, 5.0 - 1e-6, 5.0]) == 2          # a real difference counts
    assert first_largest([float("-inf"), float("nan"), -3.0, -3.0]) == 2


def test_a_least_value_held_over_a_dwell_is_reported_at_the_dwells_start() -> None:
    # Example 6.5's program: rises and a return over 85.184 + 45 + 32.058 + 107.758 = 270°,
    # then a dwell at the base circle to 360°.  There the profile's radius of curvature is
    # R0 - R_r = 4 - 0.5 = 3.5 in and the pitch curve's R0 = 4 in, the least of each, over
    # the whole dwell: the report gives its start, Θ = 270°, on every machine (not wherever
    # round-off puts the least of equal values, nor 0°, the dwell's end)
    text = (Path(__file__).resolve().parents[2] / "examples" / "cams" / "ex6_5_roller.toml"
            ).read_text(encoding="utf-8")
    for seed in range(3):
        r = random.Random(seed)
        nudged = text.replace("prime = 4.000",
                              f"prime = {4 * (1 + r.uniform(-1e-12, 1e-12))!r}")
        d = cam_json(loads_cam(nudged))
        assert d["radius_of_curvature"]["min"] == pytest.approx(3.5, rel=1e-9)
        assert d["radius_of_curvature"]["at"] == pytest.approx(270.0, abs=1e-9)
        assert d["pitch_radius_of_curvature"]["min"] == pytest.approx(4.0, rel=1e-9)
        assert d["pitch_radius_of_curvature"]["at"] == pytest.approx(270.0, abs=1e-9)
    assert first_largest([3.0, 1.0, 2.0, 3.0, 3.0], periodic=True) == 3
