"""The pencil stroke's line fitted to a fraction of a pixel, and vectors too short to read.

Each expected value is the geometry the test draws itself: a straight band
of ink symmetric about a known line (so its total-least-squares line is that
line), and vectors whose lengths on the sheet are their values over the
printed scale (Uicker, Pennock & Shigley, 5th ed., Sec. 3.4).
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import example, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from graphkin.scan.read import too_short  # noqa: E402
from graphkin.scan.strokes import _refine  # noqa: E402


def _below(c: np.ndarray, a: float, b: float) -> np.ndarray:
    """The part of a unit pixel on the side n·(x - centre) <= c of a line (|n| = 1, exact).

    n·(x - centre) over the pixel is the sum of two uniform variables, of
    widths a = |n_x| and b = |n_y|: its distribution is a trapezoid, and the
    area below ``c`` is that trapezoid's cumulative distribution.
    """
    a, b = max(a, b), max(min(a, b), 1e-12)
    s = np.clip(c + (a + b) / 2, 0.0, a + b)
    return np.where(s <= b, s**2 / (2 * a * b),
                    np.where(s <= a, (2 * s - b) / (2 * a), 1 - (a + b - s) ** 2 / (2 * a * b)))


def _band(p: np.ndarray, q: np.ndarray, shape: tuple[int, int], half: float) -> np.ndarray:
    """The page's ratio (1 = paper) with ink 0.4 within ``half`` px of the line p-q.

    Each pixel's ink is the exact part of it the band covers (as a camera's
    pixel integrates the light over its area), so the band's edges are
    anti-aliased symmetrically about the line at any position and slope.
    """
    h, w = shape
    yy, xx = np.mgrid[0:h, 0:w].astype(float)
    u = (q - p) / np.hypot(*(q - p))
    n = np.array([-u[1], u[0]])
    off = (xx - p[0]) * n[0] + (yy - p[1]) * n[1]
    a, b = abs(float(n[0])), abs(float(n[1]))
    cover = _below(half - off, a, b) - _below(-half - off, a, b)
    return 1.0 - 0.6 * cover


@settings(max_examples=25, deadline=None)
@given(x0=st.floats(15.0, 25.0), y0=st.floats(20.0, 60.0), x1=st.floats(170.0, 185.0),
       y1=st.floats(20.0, 60.0), shift=st.floats(-1.2, 1.2), half=st.floats(0.8, 1.6))
@example(x0=15.0, y0=26.125, x1=170.0, y1=26.25, shift=0.0, half=0.8125)   # 0.106 px, 8 x 8
@example(x0=15.0, y0=26.5, x1=170.0, y1=26.25, shift=0.0, half=0.8125)
def test_refit_finds_the_strokes_middle(x0: float, y0: float, x1: float, y1: float,
                                        shift: float, half: float) -> None:
    # a detector's segment along one edge of the stroke (``shift`` px across it) is moved to
    # the stroke's middle: both true ends lie within 0.1 px (0.02 mm) of the refitted line
    # (weights thresholded at the ink level put them up to 0.19 px off).  Why 0.1 px: a
    # pixel's ink counts at the pixel's centre, not at the middle of the part the band
    # covers; an edge pixel covered a fraction m moves the ink's moment by m(1 - m)/2 px, at
    # most 1/8, so the middle of a band 2 half >= 1.6 px wide is off by at most
    # 1/8 / 1.6 = 0.08 px (it was measured off by at most 0.086 px at the ends, over 300
    # random bands).  (The band sampled 8 x 8 times a pixel put its edges on a 1/8 px grid,
    # up to 1/16 px more: 0.106 px was seen.)
    p, q = np.array([x0, y0]), np.array([x1, y1])
    ratio = _band(p, q, (80, 200), half)
    u = (q - p) / np.hypot(*(q - p))
    n = np.array([-u[1], u[0]])
    seg = np.array([p + shift * n, q + shift * n])
    a, b = _refine(seg, ratio, ratio < 0.84)
    d = (b - a) / np.hypot(*(b - a))
    m = np.array([-d[1], d[0]])
    assert abs(float((p - a) @ m)) < 0.1
    assert abs(float((q - a) @ m)) < 0.1


def test_vectors_under_7_mm_are_not_read() -> None:
    # 1 mm = 10 mm/s: V_A 50 mm/s is 5 mm on the sheet (too short), V_B 100 is 10 mm (read),
    # V_C 20 is 2 mm (at the pole: never marked), the helper point H is never named
    vel = {"A": (30.0, 40.0), "B": (0.0, 100.0), "C": (20.0, 0.0), "H": (60.0, 0.0)}
    sol = SimpleNamespace(mechanism=SimpleNamespace(point_names=["A", "B", "C", "H"],
                                                    helper_points={"H"}),
                          velocity=lambda name: np.array(vel[name]))
    layout = SimpleNamespace(diagram="velocity", per_mm=10.0)
    assert too_short(sol, layout) == ["A"]


def test_no_mistake_named_for_an_image_read_near_its_right_place() -> None:
    # D read 1.0 mm from its right place (under 2 mm): WRONG, its mistake not named;
    # E read 3.0 mm from it: the mistake stays named; an ok row is left alone
    from graphkin.check.diagnose import Mistake
    from graphkin.check.report import OK, WRONG, Row
    from graphkin.scan.mark import _untold
    from graphkin.scan.read import SheetRead

    read = SheetRead(None, None, np.zeros((0, 2, 2)),  # type: ignore[arg-type]
                     points={"D": np.array([11.0, 20.0]), "E": np.array([40.0, 23.0]),
                             "F": np.array([5.0, 5.0])},
                     places={"D": [np.array([10.0, 20.0])], "E": [np.array([40.0, 20.0])],
                             "F": [np.array([5.0, 5.0])]})
    m = Mistake("normal", "the normal component drawn outward", "normal-reversed")
    rows = [Row("A_D", "1", "1", "2 %", WRONG, mistake=m),
            Row("A_E", "1", "1", "9 %", WRONG, mistake=m), Row("A_F", "1", "1", "0 %", OK)]
    out, notes = _untold(read, rows)
    assert [(r.verdict, r.mistake) for r in out] == [(WRONG, None), (WRONG, m), (OK, None)]
    assert len(notes) == 1 and notes[0].startswith("A_D is read 1.0 mm")


def _stub(p: np.ndarray, q: np.ndarray, shape: tuple[int, int], half: float) -> np.ndarray:
    """The page's ratio with ink 0.4 within ``half`` px of the *segment* p-q (flat ends).

    Sampled 8 x 8 times a pixel, so the band's edges and its end are anti-aliased.
    """
    h, w = shape
    s = (np.arange(8) + 0.5) / 8 - 0.5
    yy, xx = np.mgrid[0:h, 0:w].astype(float)
    length = float(np.hypot(*(q - p)))
    u = (q - p) / length
    n = np.array([-u[1], u[0]])
    cover = np.zeros(shape)
    for dy in s:
        for dx in s:
            rx, ry = xx + dx - p[0], yy + dy - p[1]
            t = rx * u[0] + ry * u[1]
            cover += (np.abs(rx * n[0] + ry * n[1]) <= half) & (t >= 0) & (t <= length)
    return 1.0 - 0.6 * cover / 64


@settings(max_examples=20, deadline=None)
@given(x0=st.floats(15.0, 25.0), y0=st.floats(30.0, 50.0), x1=st.floats(120.0, 150.0),
       y1=st.floats(20.0, 60.0), short=st.floats(0.5, 15.0), half=st.floats(1.0, 1.6))
def test_a_segment_end_is_the_strokes_tip(x0: float, y0: float, x1: float, y1: float,
                                          short: float, half: float) -> None:
    # the detector's segment stops ``short`` px (up to 3 mm) before the stroke's flat end q:
    # the end refitted is q, where the ink along the middle falls to half (within 0.5 px,
    # 0.1 mm); the other end p likewise
    p, q = np.array([x0, y0]), np.array([x1, y1])
    ratio = _stub(p, q, (80, 180), half)
    u = (q - p) / np.hypot(*(q - p))
    a, b = _refine(np.array([p + 3 * u, q - short * u]), ratio, ratio < 0.84)
    assert float(np.hypot(*(b - q))) < 0.5
    assert float(np.hypot(*(a - p))) < 0.5


@settings(max_examples=30, deadline=None)
@given(x=st.floats(50.0, 150.0), y=st.floats(50.0, 150.0), turn=st.floats(0.0, 180.0),
       angle=st.floats(40.0, 140.0), run_on=st.floats(1.8, 2.95), over=st.floats(-0.3, 0.4))
def test_a_tip_run_on_over_a_crossing_line_does_not_move_the_vertex(
        x: float, y: float, turn: float, angle: float, run_on: float, over: float) -> None:
    # V is the crossing of a line drawn through it and a stroke ending at it (``angle``
    # apart, 40-140°): the vertex is V (the two lines' crossing, which they give exactly
    # here) even when the stroke's end was read ``run_on`` mm past V along its own line (past
    # the 0.3 mm / sin(angle) a tip runs on over the line's ink by more than it can be off).
    # The reach is under 3 mm (vertex_at's docstring): a local run drew run_on = 3.0 exactly,
    # the boundary, and the crossing 3.0 mm from the tip was out of reach.
    from graphkin.scan.strokes import vertex_at

    v = np.array([x, y])
    a = np.radians(turn)
    d1 = np.array([np.cos(a), np.sin(a)])
    d2 = np.array([np.cos(a + np.radians(angle)), np.sin(a + np.radians(angle))])
    through = np.array([v - 30 * d1, v + 30 * d1])
    ending = np.array([v - 40 * d2, v + run_on * d2])
    other = np.array([v - 25 * d1 - 40 * d2, v - 25 * d1 + over * d2])   # far away
    segs = np.array([through, ending, other])
    got = vertex_at(segs, [1], ending[1], pole=None)
    assert float(np.hypot(*(got - v))) < 0.05
