"""A wrong-by-a-power-of-ten hint fits the file's units (audit9, item 10).

``check`` explained an inch answer 100 times too small as "centimetres and
metres mixed up": in a file of inches a factor of 100 is a decimal point two
places off; in millimetres the metric causes stay.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from graphkin.check.diagnose import UNIT_FACTORS, unit_factors
from graphkin.cli import main

DATA = Path(__file__).resolve().parents[1] / "data" / "check_units"


def _why(unit: str, factor: float) -> str:
    return next(why for f, _, why in unit_factors(unit) if f == factor)


@pytest.mark.parametrize("unit", ["in", "ft", "inch", "thou"])
def test_powers_of_ten_in_imperial_files_are_a_decimal_point(unit):
    assert "decimal point 2 places off" in _why(unit, 100.0)
    assert "decimal point 3 places off" in _why(unit, 1000.0)
    assert "metres" not in _why(unit, 100.0) + _why(unit, 10.0) + _why(unit, 1000.0)
    assert _why(unit, 25.4) == "millimetres and inches mixed up (1 in = 25.4 mm)"


@pytest.mark.parametrize("unit", ["mm", "cm", "m", "um"])
def test_metric_files_keep_the_metric_causes(unit):
    assert unit_factors(unit) == UNIT_FACTORS
    assert _why(unit, 100.0) == "centimetres and metres mixed up"


def test_the_audit_inch_answer(capsys):
    main(["check", str(DATA / "fb_q3.toml"), str(DATA / "v_ba_small.toml")])
    out = capsys.readouterr().out
    (hint,) = [ln for ln in out.splitlines() if "likely mistake" in ln]
    assert "factor of 100" in hint and "decimal point 2 places off" in hint
    assert "centimetres" not in out
