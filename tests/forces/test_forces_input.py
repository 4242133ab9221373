"""Bad force input ends with one line naming the file, the key and the reason (exit 2)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from graphkin.cli import main
from graphkin.errors import InputError
from graphkin.mechanisms import loads as load_text

DATA = Path(__file__).resolve().parent.parent / "data" / "forces"
BASE = (DATA / "ex11_1_static_fourbar.toml").read_text().split("[[loads]]")[0]
TAIL = "\n[assembly]\nB = [12.4, 11.2]\n"


def _parse(extra: str):
    return load_text(BASE + extra + TAIL, source="m.toml")


BAD = [
    ('[[loads]]\nlink = 9\npoint = "Q"\nforce = "1 lbf at 0 deg"\n', "loads[0].link", "no link"),
    ('[[loads]]\nlink = 4\npoint = "Z"\nforce = "1 lbf at 0 deg"\n', "loads[0].point",
     "no point"),
    ('[[loads]]\nlink = 4\npoint = "Q"\nforce = "120 lbf"\n', "loads[0].force",
     "no direction"),
    ('[[loads]]\nlink = 4\npoint = "Q"\nforce = "120 m at 10 deg"\n', "loads[0].force",
     "'120 m' is not a force (give a unit like lbf)"),
    ('[[loads]]\nlink = 4\npoint = "Q"\nforce = "2*60 lbf at 10 deg"\n', "loads[0].force",
     "arithmetic"),
    ('[[loads]]\nlink = 4\npoint = "Q"\nforce = "1 lbf at 0 deg"\nforse = 2\n',
     "loads[0].forse", "unknown key"),
    ('[[loads]]\nlink = 4\ntorque = "3 lbf cw"\n', "loads[0].torque",
     "is not a torque (give a unit like lbf*in)"),
    ('[[loads]]\nlink = 4\nforce = "3 lbf at 0 deg"\n', "loads[0].point", "point"),
    ('[[loads]]\nlink = 1\ntorque = 3\n', "loads[0].link", "frame"),
    # the value as the user wrote it, not in graphkin's internal N*s^2/mm (audit9)
    ('[inertia.3]\ncenter = "A"\nmass = "-1 kg"\n', "inertia.3.mass",
     "a mass cannot be negative ('-1 kg')"),
    ('[inertia.3]\ncenter = "A"\nweight = "-4 lbf"\n', "inertia.3.weight",
     "a weight cannot be negative ('-4 lbf')"),
    ('[inertia.3]\ncenter = "A"\nmass = "1 kg"\nmoment = "-1 kg*m^2"\n', "inertia.3.moment",
     "negative ('-1 kg*m^2')"),
    ('[inertia.3]\ncenter = "A"\nmass = "1 kg*m"\n', "inertia.3.mass",
     "is not a mass (give a unit like"),
    ('[inertia.3]\ncenter = "A"\nmass = "1 kg"\nmoment = "1 kg"\n', "inertia.3.moment",
     "is not a moment of inertia (give a unit like"),
    ('[inertia.3]\nmass = "1 kg"\n', "inertia.3.center", "center"),
    ('[inertia.3]\ncenter = "A"\nmass = "1 kg"\nweight = "2 lbf"\n', "inertia.3", "either"),
    ('[gravity]\nacceleration = "9.8 m/s^2 at -90 deg"\n', "gravity", "inertia"),
]


@pytest.mark.parametrize("extra,key,words", BAD, ids=[b[1] + ":" + b[2] for b in BAD])
def test_bad_force_input_names_key(extra, key, words):
    with pytest.raises(InputError) as info:
        _parse(extra)
    assert info.value.key == key
    assert words in info.value.message
    assert info.value.one_line().startswith(f"m.toml: {key}: ")


def test_bad_force_unit():
    text = BASE.replace('force = "lbf"', 'force = "in"') + TAIL
    with pytest.raises(InputError) as info:
        load_text(text, source="m.toml")
    assert info.value.key == "units.force"


def test_weight_gives_mass():
    """Ex 12.3: w3 = 2.20 lb gives m3 = 2.20/(32.17·12) = 0.00570 lb·s²/in."""
    m = _parse('[inertia.3]\ncenter = "A"\nweight = "2.20 lbf"\nmoment = '
               '"0.0479 lbf*in*s^2"\n')
    assert m.inertia["3"].mass == pytest.approx(2.20 / (9.80665 / 0.0254), rel=1e-12)
    assert m.inertia["3"].mass == pytest.approx(0.00570, abs=5e-6)
    assert m.inertia["3"].moment == pytest.approx(0.0479, rel=1e-12)


def test_cli_exit_2_one_line(tmp_path, capsys):
    f = tmp_path / "m.toml"
    f.write_text(BASE + '[[loads]]\nlink = 4\npoint = "Q"\nforce = "120 lbf"\n' + TAIL)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1
    assert "loads[0].force" in err and "direction" in err


def test_dead_center_cannot_hold(tmp_path, capsys):
    """A rocker-driven four-bar at the crank's dead center cannot hold a couple on the crank.

    O2 = (0, 0), O4 = (8, 0), crank 2, coupler 7, rocker 5: with O2, A, B in line
    |B| = 9 and |B - O4| = 5 give B = (7.5, √24.75).  Link 3 is a two-force member
    along AB, which passes through O2, so no force on link 2 balances its couple.
    """
    y = math.sqrt(81 - 7.5**2)
    t4 = math.degrees(math.atan2(y, -0.5))
    text = ('units = { length = "in", force = "lbf" }\n'
            '[links.1]\nO2 = [0, 0]\nO4 = [8, 0]\n'
            '[links.2]\nO2 = [0, 0]\nA = [2, 0]\n'
            '[links.3]\nA = [0, 0]\nB = [7, 0]\n'
            '[links.4]\nO4 = [0, 0]\nB = [5, 0]\n'
            f'[drive]\nlink = 4\nangle = {t4!r}\n'
            '[[loads]]\nlink = 2\ntorque = 10\n'
            f'[assembly]\nA = [{2 * 7.5 / 9!r}, {2 * y / 9!r}]\n')
    f = tmp_path / "dead.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert "equilibrium cannot be held" in err and len(err.splitlines()) == 1
    assert "dead.toml: drive: " in err


def test_friction_keys():
    slider = ('units = { length = "in", force = "lbf" }\n[links.1]\nO2 = [0, 0]\n'
              '[links.2]\nO2 = [0, 0]\nA = [6, 0]\n[links.3]\nA = [0, 0]\nB = [18, 0]\n'
              '[links.4]\nB = [0, 0]\n[[sliders]]\nlink = 4\non = 1\npoint = "B"\n'
              'line = [[0, 0], [1, 0]]\nEXTRA\n[drive]\nlink = 2\nangle = 120\n'
              'LOADS[assembly]\nB = [14, 0]\n')

    def fill(extra: str, loads: str) -> str:
        return slider.replace("EXTRA", extra).replace("LOADS", loads)

    load = '[[loads]]\nlink = 4\npoint = "B"\nforce = "100 lbf at 180 deg"\n'
    with pytest.raises(InputError) as info:
        load_text(fill("friction = -1", load), source="m.toml")
    assert info.value.key == "sliders[0].friction"
    with pytest.raises(InputError) as info:
        load_text(fill('friction = 0.2\nimpending = "left"', load),
                  source="m.toml")
    assert info.value.key == "sliders[0].impending"
    with pytest.raises(InputError) as info:
        load_text(fill("friction = 0.2", ""), source="m.toml")
    assert info.value.key == "sliders[0].friction"
    # a static file must say which way the motion is impending
    mech = load_text(fill("friction = 0.2", load), source="m.toml")
    from graphkin.forces import solve_forces
    with pytest.raises(InputError) as info:
        solve_forces(mech.solve())
    assert info.value.key == "sliders[0].impending"
