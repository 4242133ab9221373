"""``sweep --turn`` and clean drive values (issue 25 follow-up; docs/formats/sweep-csv.md).

The contract starts a sweep at the file's angle; ``--turn`` sweeps from 0° to
360° instead, or, for a drive that cannot turn fully, from one limit position
to the other, both included.  Drive values that are short decimals are
written as such (0.3, not 0.30000000000000004).
"""

from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

import graphkin
from graphkin.errors import InputError

sys.path.insert(0, str(Path(__file__).parent / "robust"))
from test_hostile_corpus import assert_clean, run  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
FOURBAR = ROOT / "examples" / "fourbar.toml"


def test_a_crank_turns_from_zero() -> None:
    sw = graphkin.examples.crank_rocker().sweep(count=360, turn=True)
    assert np.array_equal(sw.columns["drive"], np.arange(360.0))
    assert np.all(sw.assembled)


def test_a_drive_that_cannot_turn_runs_between_its_limits() -> None:
    """Example 3.1's four-bar (r1 = 10, r2 = 4, r3 = 18, r4 = 11) cannot turn its crank fully:
    r3 + r4 = 29 > r1 + r2, but r3 − r4 = 7 > r1 − r2 = 6, so the crank stops where coupler
    and rocker fold, |DB| = 7: cos θ2 = (10² + 4² − 7²)/(2·10·4) = 67/80, θ2 = ±33.12°; the
    file's 120° lies on the arc from 33.12° to 326.88°."""
    limit = math.degrees(math.acos(67 / 80))
    sw = graphkin.load(FOURBAR).sweep(count=101, turn=True)
    drive = np.asarray(sw.columns["drive"])
    # at a limit the two arcs touch: a tangency within the construction's length tolerance
    # (1e-12 of the size) still assembles, which moves the limit by about its square root
    assert drive[0] == pytest.approx(limit, abs=1e-6)
    assert drive[-1] == pytest.approx(360 - limit, abs=1e-6)
    assert np.all(sw.assembled)
    rc, out, err = run(["sweep", str(FOURBAR), "--turn", "--count", "5"])
    assert_clean(rc, out, err)
    assert rc == 0 and out.splitlines()[1].startswith(f"{limit:.6f}"[:6])


@pytest.mark.parametrize("argv,words", [
    (["--turn", "--from", "10"], "leave out --from and --to"),
    (["--turn", "--to", "10"], "leave out --from and --to"),
])
def test_turn_with_a_range_is_refused(argv: list[str], words: str) -> None:
    rc, out, err = run(["sweep", str(FOURBAR), "--count", "4", *argv])
    assert_clean(rc, out, err)
    assert rc == 2 and "--turn" in err and words in err, err


def test_turn_of_a_slider_is_refused() -> None:
    with pytest.raises(InputError, match="is a travel") as info:
        graphkin.examples.slider_crank().sweep(count=4, turn=True)
    assert info.value.key == "--turn"


def test_plot_takes_turn(tmp_path: Path) -> None:
    rc, out, err = run(["plot", str(FOURBAR), "--turn", "--count", "12", "-o",
                        str(tmp_path / "p.svg")])
    assert_clean(rc, out, err)
    assert rc == 0, err


@pytest.mark.parametrize("start,stop,count,want", [
    (0.1, 0.4, 3, [0.1, 0.2, 0.3]),
    (10.05, 12.3, 9, [10.05 + 0.25 * k for k in range(9)]),
    (-0.7, 0.2, 9, [-0.7, -0.6, -0.5, -0.4, -0.3, -0.2, -0.1, 0.0, 0.1]),
])
def test_drive_values_are_the_decimals_meant(start: float, stop: float, count: int,
                                              want: list[float]) -> None:
    """Each value is the float nearest the decimal a + k·step (written by hand above)."""
    sw = graphkin.examples.crank_rocker().sweep(count=count, start=start, stop=stop)
    got = [repr(float(v)) for v in sw.columns["drive"]]
    assert got == [repr(round(w, 10)) for w in want]


def test_turn_of_a_partial_table_law_is_its_rows() -> None:
    """A follower given by a table over 30°-360° of θ2 moves only there: --turn runs over the
    rows, both ends included (found by the fuzzer: an index past the turn's last posture)."""
    text = (ROOT / "examples" / "fivebar_table.toml").read_text(encoding="utf-8")
    mech = graphkin.loads(text.replace("[0, -315.0000], ", ""))
    sw = mech.sweep(count=5, turn=True)
    assert list(sw.columns["drive"]) == [30.0, 112.5, 195.0, 277.5, 360.0]
