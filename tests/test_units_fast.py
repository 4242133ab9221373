"""The common units without pint (issue 25: the first use of a unit string cost ~0.5 s).

``graphkin.units`` reads angles in rad/deg/rev over s or min and lengths in the
file's unit (or its metric or inch family) over s from a small table, before
falling back on pint.  Held here to pint itself, bit for bit, over random
numbers; and the book's usual files load without importing pint at all.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from graphkin.units import _BASE, _common, parse_quantity, quantity

ROOT = Path(__file__).resolve().parents[1]

CASES = [("omega", u) for u in ("rad/s", "deg/s", "rev/min", "rev/s", "rad/min",
                                 "revolution/minute", "degree/second")]
CASES += [("alpha", u) for u in ("rad/s^2", "rad/s**2", "rad/s²", "deg/s^2", "rev/min^2")]
CASES += [("angle", u) for u in ("deg", "rad", "rev", "degrees")]
CASES += [("velocity", u) for u in ("in/s", "ft/s", "yd/s", "in/min")]
CASES += [("acceleration", u) for u in ("in/s^2", "ft/s**2", "in/min^2")]
CASES += [("length", u) for u in ("in", "ft")]
METRIC = [("velocity", u) for u in ("m/s", "mm/s", "cm/s", "km/s")]
METRIC += [("acceleration", u) for u in ("m/s^2", "mm/s²")]


@settings(max_examples=40, deadline=None)
@given(v=st.floats(-1e6, 1e6, allow_nan=False).filter(lambda x: abs(x) > 1e-9),
       case=st.sampled_from([(k, u, "in") for k, u in CASES] +
                            [(k, u, "mm") for k, u in METRIC]))
def test_the_table_gives_pints_values_bit_for_bit(v: float, case: tuple[str, str, str]) -> None:
    kind, unit, length = case
    text = f"{v!r} {unit}"
    fast = _common(text, kind, length)  # type: ignore[arg-type]
    assert fast is not None, text
    target = _BASE[kind].replace("L", f"({length})")
    assert fast == float(quantity(text).to(target).magnitude), text


@pytest.mark.parametrize("text,kind", [("10 mm/s", "velocity"), ("5 lbf", "omega"),
                                       ("3 rad/s", "alpha"), ("2 furlong/s", "velocity"),
                                       ("36", "angle"), ("1 rad/h", "omega")])
def test_anything_else_goes_to_pint(text: str, kind: str) -> None:
    assert _common(text, kind, "in") is None  # type: ignore[arg-type]
    try:
        parse_quantity(text, kind, "in")  # type: ignore[arg-type]
    except ValueError:
        pass  # refused by pint as before (5 lbf is no angular speed)


def test_sense_words_on_the_fast_path() -> None:
    assert parse_quantity("36 rad/s cw", "omega", "in") == (-36.0, "cw")
    assert parse_quantity("900 rev/min ccw", "omega", "in")[0] == pytest.approx(94.24778, 1e-6)


def test_the_usual_files_load_without_pint() -> None:
    files = ["examples/fourbar.toml", "graphkin/examples/data/slider_crank.toml",
             "examples/planetary_outside.toml",
             "gallery/mechanisms/ex11_4_slider_crank_friction.toml"]
    code = ("import sys, graphkin\n"
            f"for f in {[str(ROOT / f) for f in files]!r}:\n"
            "    graphkin.load(f)\n"
            "print('pint' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "False"


@pytest.mark.parametrize("kind, text", [("omega", "12 rad"), ("omega", "2 rev"),
                                        ("alpha", "5 rad"), ("length", "3 rad"),
                                        ("velocity", "4 deg"), ("acceleration", "1 rev")])
def test_an_angle_without_its_time_is_not_a_rate_or_a_length(kind: str, text: str) -> None:
    # A student who writes omega = "12 rad" (forgot the "/s") or module = "3 rad" must be
    # told, not given 12 rad/s or a 3 mm module: pint calls rad dimensionless, but it is a
    # unit the user wrote, not a bare number (audit9).
    with pytest.raises(ValueError, match="is not"):
        parse_quantity(text, kind, "mm")  # type: ignore[arg-type]


def test_a_bare_number_in_a_string_is_still_the_default_unit() -> None:
    assert parse_quantity("10", "omega", "mm") == (10.0, None)
    assert parse_quantity("3", "length", "in") == (3.0, None)
