"""No key is silently ignored: every table of every file kind rejects what it does not know.

A misspelt key used to be dropped without a word (``alfa = 50`` left α = 0,
``units.time = "min"`` was ignored).  Now each ends with exit status 2 and
one line naming the file, the dotted key and the nearest valid key.
"""

from __future__ import annotations

import copy
import textwrap
import tomllib
from pathlib import Path

import pytest
from spec_data import EXAMPLES, inline

import graphkin
from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.keys import MECHANISM, VECTOR, check_keys

ROOT = Path(__file__).resolve().parents[2]

FOURBAR = inline("unknown_keys-fourbar.toml")

FORCES = FOURBAR.replace('units = { length = "in" }', 'units = { length = "in", force = "lbf" }') \
    + textwrap.dedent("""
    [[loads]]
    link = 4
    point = "C"
    force = "120 lbf at 220 deg"
    [[loads]]
    link = 3
    torque = "35 lbf*in cw"
    [inertia.3]
    center = "E"
    mass = "1.5 kg"
    moment = "0.012 kg*m^2"
    [inertia.4]
    center = "C"
    weight = "7.13 lbf"
    moment = "0.625 lbf*in*s^2"
    [gravity]
    acceleration = "9.80665 m/s^2 at -90 deg"
    """)

SLOT_CIRCLE = FOURBAR.split("[drive]")[0] + textwrap.dedent("""
    [[slots]]
    link = 3
    on = 1
    point = "E"
    circle = { center = [0, 0], radius = 4 }
    [drive]
    link = 2
    angle = 120
""")


def _data(name: str) -> dict:
    files = {
        "fourbar": FOURBAR, "forces": FORCES, "slot_circle": SLOT_CIRCLE,
    }
    if name in files:
        return tomllib.loads(files[name])
    return tomllib.loads((ROOT / name).read_text(encoding="utf-8"))


# (file, the table to put a key into, a misspelling there, the key it should suggest)
TABLES = [
    ("fourbar", "", "titel", "title"),
    ("fourbar", "units", "lenght", "length"),
    ("fourbar", "links", None, None),          # link ids are the user's: nothing is unknown
    ("fourbar", "links.2", None, None),        # point names are the user's
    ("fourbar", "drive", "alfa", "alpha"),
    ("fourbar", "drive", "omgea", "omega"),
    ("fourbar", "drive", "Omega", "omega"),
    ("fourbar", "assembly", None, None),
    ("tests/data/spec/ex3_2_slider_driven.toml", "sliders[0]", "piont", "point"),
    ("tests/data/spec/ex4_7_cam_follower.toml", "slots[0]", "lines", "line"),
    ("slot_circle", "slots[0].circle", "raduis", "radius"),
    ("examples/ex3_9_rolling_wheel.toml", "rolling[0]", "sied", "side"),
    ("examples/ex3_9_rolling_wheel.toml", "rolling[0].circle", "centre", "center"),
    ("examples/planetary_outside.toml", "rolling[0]", "contakt", "contact"),
    ("examples/planetary_outside.toml", "rolling[0].on_circle", "radus", "radius"),
    ("tests/data/spec/ex5_4_fivebar.toml", "drive[1]", "angel", "angle"),
    ("examples/fivebar_coupled.toml", "drive[1].follows", "ration", "ratio"),
    ("tests/data/spec/ex4_14_inflection_bresse.toml", "rates", "omeag", "omega"),
    ("forces", "loads[1]", "torqe", "torque"),
    ("forces", "inertia", None, None),         # link ids
    ("forces", "inertia.3", "moment_of_inertia", "moment"),
    ("forces", "gravity", "acceleraton", "acceleration"),
    ("gallery/mechanisms/fig3_7_fourbar.toml", "gallery", "figuer", "figure"),
    ("gallery/mechanisms/fig3_7_fourbar.toml", "gallery.book[0]", "quanity", "quantity"),
    ("gallery/mechanisms/fig4_18_cam_follower.toml", "bodies[1]", "fase", "face"),
    ("gallery/mechanisms/fig4_18_cam_follower.toml", "bodies[0].circle", "raduis", "radius"),
    ("examples/cams/cam_mechanism.toml", "cams[0]", "folower", "follower"),
]


def _table(data: dict, path: str) -> dict:
    table = data
    for part in path.split(".") if path else []:
        name, _, index = part.partition("[")
        table = table[name]
        if index:
            table = table[int(index[:-1])]
    return table


def _schema_tables(schema, path=""):
    """Every table path the schema knows ('*' for a user's name)."""
    yield path
    for key, sub in schema.items():
        if isinstance(sub, dict):
            yield from _schema_tables(sub, f"{path}.{key}" if path else key)


def _generic(path: str) -> str:
    import re

    path = re.sub(r"\[\d+\]", "", path)
    return re.sub(r"(links|inertia)\.\d+", r"\1.*", path)


def test_every_table_of_the_schema_is_tested():
    tested = {_generic(p) for _, p, _, _ in TABLES}
    assert set(_schema_tables(MECHANISM)) - {"links.*"} <= tested | {"links.*"}
    assert "links.*" in tested


@pytest.mark.parametrize("name", sorted({f for f, *_ in TABLES} - {"slot_circle"}))
def test_the_files_used_are_valid_as_written(name):
    # a file with every forces key, and the repository's files, are accepted as written
    graphkin.from_dict(_data(name), source=name)


@pytest.mark.parametrize("name,path,wrong,right", TABLES,
                         ids=[f"{p or 'top'}:{w}" for _, p, w, _ in TABLES])
def test_unknown_key_in_every_table(name, path, wrong, right):
    data = _data(name)
    bad = copy.deepcopy(data)
    key = wrong or "zz_not_a_key"
    _table(bad, path)[key] = 1
    dotted = f"{path}.{key}" if path else key
    if wrong is None:
        # a table of names the user chooses: any name is a name
        check_keys(bad, MECHANISM, name)
        return
    with pytest.raises(InputError) as info:
        graphkin.from_dict(bad, source=name)
    err = info.value
    assert err.key == dotted and err.file == name
    assert err.suggestion == right
    assert f"did you mean {right!r}?" in err.one_line()
    # a key nothing is near: the message lists the valid ones instead
    far = copy.deepcopy(data)
    _table(far, path)["zz_not_a_key"] = 1
    with pytest.raises(InputError) as info:
        graphkin.from_dict(far, source=name)
    assert "valid keys: " in str(info.value) and right in str(info.value)


@pytest.mark.parametrize("edit,key,expect", [
    (("alpha = 0", "alfa = 50"), "drive.alfa", "did you mean 'alpha'?"),
    (('omega = "900 rev/min cw"', 'omgea = "900 rev/min cw"'), "drive.omgea",
     "did you mean 'omega'?"),
    (("title =", "titel ="), "titel", "did you mean 'title'?"),
    (('units = { length = "in" }', 'units = { length = "in", angle = "rad" }'), "units.angle",
     "angles in a file are always degrees"),
    (('units = { length = "in" }', 'units = { length = "in", time = "min" }'), "units.time",
     "time is always seconds"),
    (("[assembly]", "[assembley]"), "assembley", "did you mean 'assembly'?"),
])
def test_cli_one_line_exit_2(tmp_path, capsys, edit, key, expect):
    path = tmp_path / "mech.toml"
    path.write_text(FOURBAR.replace(*edit), encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in err
    assert lines[0].startswith(f"graphkin: {path}: {key}: unknown key ")
    assert expect in lines[0]


@pytest.mark.parametrize("units", ['"in"', '{ length = "in" }'])
def test_units_written_either_way(units):
    # the same syntax in every file kind: a string is the length unit
    mech = graphkin.loads(FOURBAR.replace('{ length = "in" }', units))
    assert mech.length_unit == "in"
    vec = tomllib.loads(f"units = {units}\n[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n"
                        "[C]\nmagnitude = 5\nangle = 0\n")
    check_keys(vec, VECTOR, "v.toml")
    from graphkin.commands.vector import loads as vloads

    assert vloads(f"units = {units}\n[A]\nmagnitude = 3\n").units == "in"


@pytest.mark.parametrize("units,reason", [
    ("3", "expected units = \"mm\""),
    ('{ length = 3 }', "a unit is a string"),
    ('{ length = "" }', "a unit is a string"),
])
def test_bad_units_value(units, reason):
    with pytest.raises(InputError, match=reason):
        graphkin.loads(FOURBAR.replace('{ length = "in" }', units))


def test_misspelt_pin_names_the_lonely_points(tmp_path, capsys):
    # link 4 says Cc where link 3 says C: no pin at C, so the four-bar has
    # 3(4-1) - 2*3 = 3 degrees of freedom (Kutzbach, Eq. 1.3) for one drive
    path = tmp_path / "mech.toml"
    path.write_text(FOURBAR.replace("C = [11, 0]", "Cc = [11, 0]"), encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "3 degree(s) of freedom" in err
    assert "points named in only one link: C (link 3), E (link 3), Cc (link 4)" in err
    assert "'C' (link 3) and 'Cc' (link 4) look alike" in err


def test_spec_examples_and_shipped_examples_are_accepted():
    for path in sorted(EXAMPLES.glob("*.toml")):
        if path.name != "expected.toml":
            graphkin.load(path)
    for name in graphkin.examples.names():
        graphkin.examples.load(name)
