"""A negative value with a sense word is refused (audit9, item 9).

``omega = "-120 rev/min cw"`` was read as 120 rev/min ccw: the minus sign and
``cw`` both say negative, and their product silently turned the crank the other
way.  A double negative is a mistake: one line naming the key, exit 2.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from graphkin.cli import main
from graphkin.units import parse_quantity

DATA = Path(__file__).parent / "data" / "bad"


@pytest.mark.parametrize("text", ["-120 rev/min cw", "-120 rev/min ccw", "-3 rad/s^2 cw",
                                  "-5 in/s cw"])
def test_a_sign_and_a_sense_word_together_are_refused(text):
    kind = "velocity" if "in/s" in text else ("alpha" if "^2" in text else "omega")
    with pytest.raises(ValueError, match="both a minus sign"):
        parse_quantity(text, kind, "in")


def test_one_sign_is_read():
    # 120 rev/min = 120 · 2π/60 = 4π rad/s; cw means negative
    assert parse_quantity("120 rev/min cw", "omega", "mm")[0] == pytest.approx(-4 * math.pi)
    assert parse_quantity("-120 rev/min", "omega", "mm")[0] == pytest.approx(-4 * math.pi)
    assert parse_quantity("0 rad/s cw", "omega", "mm")[0] == 0.0


def test_the_file_error_names_the_key(capsys):
    assert main(["solve", str(DATA / "m15_negcw.toml")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "drive.omega" in err and "'120 rev/min cw'" in err
