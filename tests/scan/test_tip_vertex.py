"""An arrowhead's tip where its own vector and its image's lines end counts as their ends.

Every absolute vector is drawn from the pole with its arrowhead at its image
(Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), and the lines of its link's
image end there too (Secs. 3.5, 4.2).  A tip found there
(:func:`graphkin.scan.arrows.head_at`) counts 0.5 mm nearer for each
segment ending with it, at most 1 mm, as a segment end does
(:func:`graphkin.scan.tipweight.tip_strength`), unless a link line ending
there stops more than 1 mm short of it (the tip was read on other ink: a
thin polygon's line through it within the barbs' angles).

The photos are two four-bar acceleration polygons of the sample seeded
20261202 (benchmarks/data/scan_sample_20261202.json, #18 and #55; their
mechanisms in tests/scan/data/tip_vertex.json), misread at scan before
scan23 (docs/scan-reading.md, 28 Nov 2026, third round): `a` was read
1.1-1.2 mm off, at the crossing of strokes ending beside its arrowhead.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from scan.photos import exact_images, layout_for, read_photo  # noqa: E402

from graphkin.check.report import OK  # noqa: E402
from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.read import _PAST_MM, _RAY_LINE_MM, _SAME_MM, _STRONG_MM  # noqa: E402
from graphkin.scan.tipweight import tip_strength  # noqa: E402

_DATA = json.loads((Path(__file__).parent / "data" / "tip_vertex.json").read_text())

# pole at the origin, the tip 50 mm out along (0.6, 0.8); the link line at right angles,
# along (0.8, -0.6)
_POLE = np.zeros(2)
_AXIS = np.array([0.6, 0.8])
_ACROSS = np.array([0.8, -0.6])
_TIP = 50.0 * _AXIS
# the own vector from 2 mm out (the printed pole hides its start) to 2 mm past the tip (a
# stroke run on over a barb's ink)
_OWN = np.array([2.0 * _AXIS, 52.0 * _AXIS])


def _link(past: float) -> np.ndarray:
    """A 20 mm link line toward the tip, ending ``past`` mm beyond it (negative: short)."""
    return np.array([_TIP - 20.0 * _ACROSS, _TIP + past * _ACROSS])


def _strength(segs: np.ndarray, tips: np.ndarray, pole: np.ndarray) -> np.ndarray:
    return tip_strength(segs, tips, pole, _SAME_MM, _STRONG_MM, _RAY_LINE_MM, _PAST_MM)


def _cases() -> list[tuple[np.ndarray, np.ndarray, float]]:
    """(segments, tip, the strength by hand)."""
    off_pole = _OWN + 2.0 * _ACROSS           # its line 2 mm from the pole: no vector from it
    return [
        # own vector and a link line overshot 0.3 mm: two segments end there, 2 x 0.5 mm
        (np.array([_OWN, _link(0.3)]), _TIP, 1.0),
        # a third line ending there: still at most 1 mm
        (np.array([_OWN, _link(0.3), _link(-0.2)[::-1]]), _TIP, 1.0),
        # the own vector alone: one segment, 0.5 mm
        (np.array([_OWN]), _TIP, 0.5),
        # the link line stops 1.4 mm short of the tip (over 1 mm: the tip is on other ink)
        (np.array([_OWN, _link(-1.4)]), _TIP, 0.0),
        # the link line stops 0.6 mm short (the hand's 0.3 mm and a rounded end): counted
        (np.array([_OWN, _link(-0.6)]), _TIP, 1.0),
        # no vector from the pole ends there
        (np.array([off_pole, _link(0.3)]), _TIP, 0.0),
        # the tip 0.8 mm beside its vector's line (over 0.5 mm): not on its own vector
        (np.array([_OWN, _link(0.3)]), _TIP + 0.8 * _ACROSS, 0.0),
    ]


def test_a_tip_counts_as_the_segments_ending_there_on_its_own_vector() -> None:
    for segs, tip, want in _cases():
        got = _strength(segs, tip[None, :], _POLE)
        assert got.shape == (1,)
        assert got[0] == pytest.approx(want)


def test_the_strength_does_not_move_with_round_off() -> None:
    rng = np.random.default_rng(5)
    for segs, tip, want in _cases():
        for _ in range(5):
            scale = 1e-12 * 60.0                  # the drawing's size, 60 mm
            got = _strength(segs + rng.uniform(-scale, scale, segs.shape),
                            (tip + rng.uniform(-scale, scale, 2))[None, :],
                            _POLE + rng.uniform(-scale, scale, 2))
            assert got[0] == pytest.approx(want)


def test_no_tips_no_segments() -> None:
    assert _strength(np.array([_OWN]), np.zeros((0, 2)), _POLE).shape == (0,)
    assert list(_strength(np.zeros((0, 2, 2)), _TIP[None, :], _POLE)) == [0.0]


@pytest.mark.parametrize("case", _DATA, ids=lambda c: f"n{c['number']}")
def test_an_image_beside_a_cluster_of_ends_is_read_at_its_arrowhead(case: dict) -> None:
    # before scan23: A_A unexplained, a read 1.1-1.2 mm off at the ends' crossing
    sol = from_dict(case["data"]).solve()
    lay = layout_for(sol, case["diagram"], case["kind"])
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    # (what the test means: `a`'s link lines b a, a e ending with o a, 10-25 mm from the pole)
    assert 10.0 < float(np.hypot(*(images["A"] - pole))) < 45.0
    read, rep, rows = read_photo(sol, lay, images, "scan", case["seed"])
    # the tip is found to 0.1-0.3 mm; the drawing tolerance is 0.5 mm on the sheet
    assert float(np.hypot(*(read.points["A"] - images["A"]))) < 0.5, rep.text()
    assert all(r.verdict == OK for r in rows.values()), rep.text()
