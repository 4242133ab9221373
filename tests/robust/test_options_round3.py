"""Options checked before the work, in the user's words (issue 25, item 1 and the limits).

Each test is a class of option, not one value: drive ranges the floats cannot
resolve, suffixes an item does not take, items the file cannot give.
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.errors import InputError

sys.path.insert(0, str(Path(__file__).parent))
from test_hostile_corpus import assert_clean, run  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
FOURBAR = ROOT / "graphkin" / "examples" / "data" / "fourbar.toml"
LOADED = ROOT / "tests" / "data" / "forces" / "ex11_1_static_fourbar.toml"


@pytest.mark.parametrize("args,option", [
    (["--from", "1e300"], "--from"), (["--from", "1e17"], "--from"),
    (["--from", "-1e12"], "--from"), (["--from", "0", "--to", "1e-300"], "--to"),
    (["--from", "5", "--to", "5"], "--to"), (["--to", "1e200"], "--to"),
])
def test_ranges_the_floats_cannot_resolve_are_refused(args: list[str], option: str) -> None:
    rc, out, err = run(["sweep", str(FOURBAR), "--count", "4", *args])
    assert_clean(rc, out, err)
    assert rc == 2 and option in err, err


@pytest.mark.parametrize("start", [math.nan, math.inf, -math.inf, "10"])
def test_python_ranges_must_be_finite_numbers(start: object) -> None:
    with pytest.raises(InputError, match="finite numbers"):
        graphkin.examples.fourbar().sweep(count=3, start=start)  # type: ignore[arg-type]


def test_drive_values_are_the_round_values_asked_for() -> None:
    """0 to 360 in 360 steps gives 0, 1, ..., 359 exactly (not 48.00000000000001)."""
    sw = graphkin.examples.crank_rocker().sweep(count=360, start=0, stop=360)
    assert np.array_equal(sw.columns["drive"], np.arange(360.0))
    sw = graphkin.examples.crank_rocker().sweep(count=7, start=-90, stop=90)
    # k·180/7 rounded once: the nearest floats to -90 + 180 k / 7
    want = [-90 + (180 * k) / 7 for k in range(7)]
    assert list(sw.columns["drive"]) == want


@pytest.mark.parametrize("what,words", [
    ("torque:99", "torque needs forces"), ("transmission:Q", "takes no suffix"),
    ("angle:9", "no link '9'"), ("omega:99", "no link '99'"), ("velocity:Z", "no point 'Z'"),
    ("centrode:1", "no moving link '1'"), ("path:", "needs a point"), ("xx", "cannot plot"),
])
def test_plot_items_and_suffixes_are_checked(what: str, words: str, tmp_path: Path) -> None:
    rc, out, err = run(["plot", str(FOURBAR), "--what", what, "--count", "4", "-o",
                        str(tmp_path / "p.svg")])
    assert_clean(rc, out, err)
    assert rc == 2 and f"{FOURBAR}: --what: " in err and words in err, err
    assert not (tmp_path / "p.svg").exists()


def test_plot_torque_of_an_undriven_link(tmp_path: Path) -> None:
    rc, out, err = run(["plot", str(LOADED), "--what", "torque:3", "--count", "4", "-o",
                        str(tmp_path / "p.svg")])
    assert_clean(rc, out, err)
    assert rc == 2 and "link '3' is not driven" in err, err


@pytest.mark.parametrize("what", ["omega", "alpha", "velocity:C", "acceleration:E"])
def test_plot_without_rates_names_the_file_and_the_option(what: str, tmp_path: Path) -> None:
    text = FOURBAR.read_text(encoding="utf-8")
    f = tmp_path / "still.toml"
    f.write_text("\n".join(ln for ln in text.splitlines()
                           if not ln.startswith(("omega", "alpha"))), encoding="utf-8")
    rc, out, err = run(["plot", str(f), "--what", what, "-o", str(tmp_path / "p.svg")])
    assert_clean(rc, out, err)
    assert rc == 2 and f"{f}: --what: " in err and "needs rates" in err, err


def _q_line(path: Path) -> str:
    rc, out, err = run(["sweep", str(path), "--count", "360", "--singular"])
    assert rc == 0, err
    lines = [ln for ln in err.splitlines() if "time ratio" in ln]
    assert len(lines) == 1, err
    return lines[0]


def test_time_ratio_of_a_crank_rocker() -> None:
    """Sec. 1.7: crank 100, coupler 250, rocker 300, frame 200 (Fig. 2.25).  The rocker's
    limits are where crank and coupler are in line: extended, |AC| = 350 and
    cos φe = (200² + 350² − 300²)/(2·200·350); folded, |AC| = 150, the crank opposite:
    cos φf = (200² + 150² − 300²)/(2·200·150).  α = 180° + φf − φe, Q = α/(360° − α)."""
    fe = math.degrees(math.acos((200**2 + 350**2 - 300**2) / (2 * 200 * 350)))
    ff = math.degrees(math.acos((200**2 + 150**2 - 300**2) / (2 * 200 * 150)))
    alpha = 180 + ff - fe
    line = _q_line(ROOT / "graphkin" / "examples" / "data" / "crank_rocker.toml")
    assert f"{alpha:.2f}°/{360 - alpha:.2f}° = {alpha / (360 - alpha):.3f}" in line, line


def test_time_ratio_of_a_whitworth_quick_return() -> None:
    """Crank 3 about O2, O4 1 above it; the ram is at its ends when link 4 lies along the
    ram's line: O4A horizontal, 3 sin θ2 = 1, θ2 = asin(1/3) or 180° − asin(1/3).  The crank
    turns 180° + 2 asin(1/3) for one stroke and 180° − 2 asin(1/3) for the other."""
    a = math.degrees(math.asin(1 / 3))
    alpha, beta = 180 + 2 * a, 180 - 2 * a
    line = _q_line(ROOT / "tests" / "data" / "whitworth.toml")
    assert "slider 6's strokes" in line and f"{alpha:.2f}°/{beta:.2f}°" in line, line
    assert f"= {alpha / beta:.3f}" in line
