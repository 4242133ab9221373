"""Plots over the drive: a dwell at a limit is a band, an instant center keeps its hyphen.

Acceptance inputs: Problem 6.30's cam driving a follower (the follower rests
from 0° to 45° and from 180° to 210° between strokes of opposite sense, Sec.
6.3), and an offset slider-crank numbered 1, 7, 9, 12 whose I7-12 was titled
"I712" (I71-2?).
"""

from __future__ import annotations

from pathlib import Path

import pytest

import graphkin
from graphkin.render.plots import sweep_figure

DATA = Path(__file__).resolve().parents[1] / "data" / "audit7"


def test_a_dwell_at_a_limit_is_drawn_from_its_start_to_its_end() -> None:
    sw = graphkin.load(DATA / "cam_mech.toml").sweep(count=360)
    fig = sweep_figure(sw, "velocity:P")
    ax = fig.axes[0]
    starts = sorted(float(a.get_xdata()[0]) for a in ax.get_lines()
                    if (a.get_gid() or "").startswith("limit-") and
                    not a.get_gid().startswith("limit-end-"))
    ends = sorted(float(a.get_xdata()[0]) for a in ax.get_lines()
                  if (a.get_gid() or "").startswith("limit-end-"))
    # the follower's dwells (drive from the file's 230°): 360°-405° and 540°-570°, to the
    # round-off of their edges (2e-3°, tests/test_singular_dwell.py); the
    # rocker 6 it drives rests with it (both are marked, at the same drive values)
    assert sorted({round(v, 2) for v in ends}) == pytest.approx([405.0, 570.0], abs=1e-2)
    assert 360.0 == pytest.approx(min(starts, key=lambda v: abs(v - 360.0)), abs=2e-3)
    assert 540.0 == pytest.approx(min(starts, key=lambda v: abs(v - 540.0)), abs=2e-3)
    assert len(ax.patches) >= 2                                   # the two bands


def test_an_instant_center_of_a_two_digit_link_keeps_its_hyphen() -> None:
    sw = graphkin.load(DATA / "offset_in.toml").sweep(count=72)
    fig = sweep_figure(sw, "center:I7-12")
    ax = fig.axes[0]
    assert ax.get_title() == "path of the instant center I7-12"
    assert [a.get_label() for a in ax.get_lines() if a.get_gid() == "center-I7-12"] == ["I7-12"]
