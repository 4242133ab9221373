"""A misspelt length unit is refused with the name meant (audit9, item 7).

Pint reads plurals loosely ('inchs' and 'inchess' are inches) and its 'mil'
is a milliradian; a file's unit is printed as written, so 'inchs' must not
get through, and 'mil' (a thousandth of an inch to a machinist) is told apart.
"""

from __future__ import annotations

import pytest

from graphkin.cli import main
from graphkin.units import length_factor

FOURBAR = """title = "t"
units = "{unit}"
[links.1]
O2 = [0, 0]
O4 = [4, 0]
[links.2]
O2 = [0, 0]
A = [1, 0]
[links.3]
A = [0, 0]
B = [4, 0]
[links.4]
O4 = [0, 0]
B = [3, 0]
[drive]
link = 2
angle = 60
"""


@pytest.mark.parametrize("unit,meant", [("inchs", "inch"), ("inchess", "inches"),
                                        ("metrs", "metre"), ("milimeter", "millimeter")])
def test_a_misspelt_name_is_refused_with_the_nearest_name(unit, meant):
    with pytest.raises(ValueError) as info:
        length_factor(unit)
    if meant is not None:
        assert f"did you mean {meant!r}?" in str(info.value)


@pytest.mark.parametrize("unit,metres", [
    ("inch", 0.0254), ("inches", 0.0254), ("in", 0.0254), ("feet", 0.3048), ("foot", 0.3048),
    ("metre", 1.0), ("metres", 1.0), ("meters", 1.0), ("millimeters", 0.001),
    ("millimetres", 0.001), ("centimeters", 0.01), ("um", 1e-6), ("µm", 1e-6),
    ("thou", 0.0254e-3), ("yards", 0.9144), ("miles", 1609.344)])
def test_names_symbols_and_plurals_are_read(unit, metres):
    # the international inch is 25.4 mm exactly; the foot 12 in, the yard 36 in, the mile 5280 ft
    assert length_factor(unit) == pytest.approx(metres, rel=1e-12)


@pytest.mark.parametrize("unit", ["mil", "mils"])
def test_mil_is_told_apart_from_thou(unit):
    with pytest.raises(ValueError) as info:
        length_factor(unit)
    assert "angle" in str(info.value) and "'thou'" in str(info.value)


def test_the_file_error_is_one_line_naming_the_key(tmp_path, capsys):
    p = tmp_path / "m.toml"
    p.write_text(FOURBAR.format(unit="inchs"), encoding="utf-8")
    assert main(["solve", str(p)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "units" in err and "did you mean 'inch'?" in err
