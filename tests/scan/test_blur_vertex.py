"""A vertex where two strokes meet at a narrow angle, their lines pulled together by the blur.

Two strokes drawn from one side to an image point V (a thin polygon's
vector from the pole and a link's line, Uicker, Pennock & Shigley, 5th ed.,
Sec. 3.4-3.5) share their blurred ink near V, and the lines fitted to that
ink are pulled toward each other there.  The test draws the geometry
itself: each segment's tip is half a pencil line's width (0.3 mm) past V
along its own direction, as a stroke's ink reaches past the point it was
drawn to, and each line is moved ``pull`` mm toward the other.  Two lines
``θ`` apart, each moved ``pull`` toward the other, cross ``pull / sin(θ/2)``
from V along the bisector (``2 pull / θ`` for small θ: 2.5 mm for 0.22 mm
at 10°); the tips still say V.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

pytest.importorskip("cv2")

from hypothesis import example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from graphkin.scan.strokes import line_sigma, vertex_at  # noqa: E402

V = np.array([100.0, 120.0])
HALF = 0.3
"""Half a pencil line's width: how far a stroke's ink reaches past the point it ends at."""
HARSH = 0.44
"""The harsh level's blur on the sheet (σ, mm; docs/checking.md, "The blur")."""


def _pair(theta_deg: float, pull: float, turn_deg: float = 0.0, length: float = 20.0,
          over: tuple[float, float] = (0.0, 0.0)) -> np.ndarray:
    """Two segments leaving V ``theta_deg`` apart, each moved ``pull`` mm toward the other.

    ``over``: how far (mm) each stroke overshoots V (negative: stops short).
    """
    half = math.radians(theta_deg) / 2
    turn = math.radians(turn_deg)
    segs = []
    for s, extra in zip((1.0, -1.0), over, strict=True):
        a = turn + s * half
        d = np.array([math.cos(a), math.sin(a)])                # from V outward
        toward = s * np.array([d[1], -d[0]])                     # toward the other stroke
        tip = V - (HALF + extra) * d
        segs.append(np.array([tip + pull * toward, V + length * d + pull * toward]))
    return np.array(segs)


def test_line_sigma_is_the_wobble_and_half_the_blur() -> None:
    # √(0.1² + (b/2)²): 0.1 sharp, √(0.01 + 0.0484) = 0.2417 at 0.44 mm
    assert line_sigma(0.0) == pytest.approx(0.1)
    assert line_sigma(HARSH) == pytest.approx(math.sqrt(0.01 + 0.22**2))
    assert line_sigma(-1.0) == pytest.approx(0.1)       # not measured: sharp


@settings(max_examples=40, deadline=None)
@given(theta=st.floats(9.0, 20.0), pull_part=st.floats(0.0, 1.0), turn=st.floats(0.0, 360.0),
       over=st.tuples(st.floats(-0.2, 0.2), st.floats(-0.2, 0.2)))
@example(theta=10.0, pull_part=1.0, turn=0.0, over=(0.0, 0.0))
def test_lines_pulled_by_the_blur_do_not_move_the_vertex(theta: float, pull_part: float,
                                                         turn: float,
                                                         over: tuple[float, float]) -> None:
    # lines pulled together by up to half the harsh blur (0.22 mm) cross up to
    # 0.22 / sin(4.5°) = 2.8 mm from V; read at that blur, the tips decide: V to within
    # the tips' own overshoot (≤ 0.2 mm) and a part of the pull
    segs = _pair(theta, pull_part * HARSH / 2, turn, over=over)
    got = vertex_at(segs, [0, 1], segs[0, 0], None, HARSH)
    assert float(np.hypot(*(got - V))) < 0.45


def test_a_sharp_photo_still_trusts_its_lines() -> None:
    # The same strokes pulled 0.22 mm at 10°, read as if the photo were sharp (σ 0.1 mm a
    # line): their crossing, 0.22 / sin 5° = 2.5 mm along, disagrees with the tips by more
    # than 2.5 σ, so the tips were left out and the crossing taken (what harsh photos read
    # before the blur counted); a sharp photo's lines are not pulled so.
    segs = _pair(10.0, 0.22)
    sharp = vertex_at(segs, [0, 1], segs[0, 0], None, 0.0)
    assert float(np.hypot(*(sharp - V))) == pytest.approx(0.22 / math.sin(math.radians(5.0)),
                                                          abs=0.1)
    blurred = vertex_at(segs, [0, 1], segs[0, 0], None, HARSH)
    assert float(np.hypot(*(blurred - V))) < 0.1


@settings(max_examples=30, deadline=None)
@given(theta=st.floats(40.0, 140.0), turn=st.floats(0.0, 360.0), blur=st.floats(0.0, HARSH),
       over=st.tuples(st.floats(-0.3, 0.4), st.floats(-0.3, 0.4)))
def test_lines_at_a_wide_angle_fix_the_vertex_at_any_blur(theta: float, turn: float,
                                                          blur: float,
                                                          over: tuple[float, float]) -> None:
    # unpulled lines through V at 40-140°: their crossing is V.  The tips, overshot or
    # short by o1, o2 beyond the ink's half width, pull it off: their mean m along the
    # bisector, where the lines hold V with b = σ_line / (√2 sin θ/2) and the two tips with
    # t = 0.4 / (√2 cos θ/2), each o along its line o / cos θ/2 along it, so least squares
    # moves V (m / cos θ/2) b² / (b² + t²) (0.13 mm for o = 0.4 at 40° sharp, 0.31 blurred
    # 0.44 mm: the price of trusting a blurred photo's lines less; 0.03 and 0.15 at 90°);
    # half their difference across it likewise, sin and cos swapped.
    segs = _pair(theta, 0.0, turn, over=over)
    got = vertex_at(segs, [0, 1], segs[0, 0], None, blur)
    half = math.radians(theta) / 2
    sl, c, sn = line_sigma(blur), math.cos(half), math.sin(half)
    along = (sl / (math.sqrt(2) * sn)) ** 2, (0.4 / (math.sqrt(2) * c)) ** 2
    across = (sl / (math.sqrt(2) * c)) ** 2, (0.4 / (math.sqrt(2) * sn)) ** 2
    m, d = abs(over[0] + over[1]) / 2, abs(over[0] - over[1]) / 2
    bound = (m / c * along[0] / sum(along) + d / sn * across[0] / sum(across)) + 0.01
    assert float(np.hypot(*(got - V))) < bound
