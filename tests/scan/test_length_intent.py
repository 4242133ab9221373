"""The fixed-sample benchmark's intent for a wrong length: the drawing tolerance's own rule.

docs/checking.md "Tolerances": with a drawing tolerance an answer is also
right when the end of its vector lies within that distance of the exact end
on the paper; ``mark_scan`` uses 0.5 mm when none is given.  So an image
3-10 % too long is intended ``WRONG`` only when that moves its end 0.5 mm or
more (values below worked by hand).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "benchmarks"))

from scan_fixed_sample import _intended, planted_wrong, read_right  # noqa: E402

from graphkin.check.report import OK, WRONG, Row  # noqa: E402


def test_under_the_tolerance_is_intended_right() -> None:
    pole = np.array([100.0, 50.0])
    # 3.7 % short of an 11.2 mm vector: 0.037 * 11.2 = 0.414 mm < 0.5 mm
    assert planted_wrong("c", pole + [11.2, 0.0], pole, 0.963) is None
    # 3.3 % long of a 17.1 mm vector: 0.033 * 17.1 = 0.564 mm >= 0.5 mm
    assert planted_wrong("e", pole + [0.0, 17.1], pole, 1.033) == "e"
    # at a slant: |(3, 4)| * 10 = 50 mm, 1.2 % -> 0.6 mm
    assert planted_wrong("b", pole + [30.0, 40.0], pole, 0.988) == "b"


def test_intended_rows() -> None:
    rows = [Row("V_A", "1", "1", "0", OK), Row("V_C", "1", "1", "0", OK)]
    assert _intended("length", rows, None)          # moved under 0.5 mm: all right
    assert not _intended("length", rows, "C")       # moved 0.5 mm or more: C must be WRONG
    rows[1] = Row("V_C", "1", "1", "0", WRONG)
    assert _intended("length", rows, "C")
    assert not _intended("length", rows, None)


def test_a_reversed_drawing_is_intended_reversed_whatever_its_wrong_length() -> None:
    # the draw's wrong length moves its image under 0.5 mm (``wrong`` None): that is the
    # wrong-length drawing's matter; its reversed drawing is still intended `sense` (the
    # rest following), not all right (before, such reversed photos could never count)
    from graphkin.check.diagnose import Mistake
    from graphkin.check.report import FOLLOWS

    sense = Mistake("sense", "the polygon drawn for the other sense", "sense")
    rows = [Row("V_A", "1", "1", "0", WRONG, mistake=sense),
            Row("V_C", "1", "1", "0", FOLLOWS, follows="V_A")]
    assert _intended("reversed", rows, None)
    assert _intended("reversed", rows, "C")
    assert not _intended("reversed", [Row("V_A", "1", "1", "0", OK)], None)


def test_read_right_counts_a_verdict_on_the_tolerance_edge_apart() -> None:
    drawn = {"A": np.array([10.0, 20.0]), "B": np.array([40.0, 0.0])}
    # read 0.2 mm and 0.15 mm from where drawn: both within 0.25 mm
    near = {"A": np.array([10.12, 20.16]), "B": np.array([40.0, -0.15])}
    assert read_right(near, drawn)
    # B read 0.3 mm off (3-4-5: 0.18, 0.24): a misread, not an edge verdict
    assert not read_right({**near, "B": np.array([40.18, 0.24])}, drawn)
    # B not found at all
    assert not read_right({"A": near["A"]}, drawn)
