"""A vector's end not read on the student's letter past the line it ends on.

An image drawn in the middle of a link's line (a coupler point ``e`` 1 mm
off the straight line ``a b``): the vector from the pole ends on that line's
ink, and the student's letter stands just past it, straight on along the
vector.  The walk along the vector's fitted line
(:func:`graphkin.scan.inkfit.ink_end`) steps over the paper between them
when it is under 1 mm (a pencil lifted) and ends on the letter, 2-4 mm
past the image; with no other line across it there, nothing else held the
point, and ``e`` of a right drawing was read 4.4 mm off and marked wrong.
:func:`graphkin.scan.inkfit._letter_cut` reads that walk as
:func:`graphkin.scan.crossings.past_crossings` reads a segment's tip: the ink
stops past the crossed line and the ink after the paper is a letter; where
it stops on the crossed line's own ink, the walk gives no end.

The raster tests draw the strokes themselves (where the ink stops is known
from the drawing); the photo test draws the mechanism Hypothesis found,
each image where the analytic solver puts it (``exact_images``), and
expects every row marked right.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scan.photos import exact_images, layout_for, read_photo  # noqa: E402
from scan.rasters import pencil_sheet, unit  # noqa: E402

from graphkin.check.report import OK  # noqa: E402
from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.inkfit import FitLine, Sheet, _letter_cut, ink_end  # noqa: E402


def _crossing(phi: float, cross: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """x, the stroke's direction w, its far end f (25 mm back) and a long line through x."""
    x, w, v = np.array([40.0, 40.0]), unit(phi), unit(phi + cross)
    return x, w, x - 25.0 * w, np.array([x - 20.0 * v, x + 20.0 * v])


def _walk(sheet: Sheet, f: np.ndarray, x: np.ndarray, w: np.ndarray,
          others: list[np.ndarray]) -> tuple[float | None, float | None]:
    """The walk's end along the stroke f -> x, before and after the letter's cut."""
    mid = f + np.outer(np.linspace(0.2, 0.8, 25), x - f)
    fl = FitLine(x, w, 0.05, 25.0, float(np.median(sheet.darkness(mid))))
    end = ink_end(sheet, fl, inside_mm=4.0, beyond_mm=12.0)   # reach past every stroke drawn
    return end, (None if end is None else _letter_cut(sheet, fl, end, others))


@settings(max_examples=25, deadline=None)
@given(phi=st.floats(0.0, 360.0), cross=st.floats(35.0, 145.0), gap=st.floats(0.75, 0.95),
       letter=st.floats(0.8, 2.2), blur=st.floats(0.5, 1.0))
def test_a_walk_over_a_line_and_paper_onto_a_letter_gives_no_end(
        phi: float, cross: float, gap: float, letter: float, blur: float) -> None:
    # a stroke from f ending at x on a long line through x; past the line's ink (0.45 mm
    # of its blurred half width over sin of their angle), 0.75-0.95 mm of paper (0.5-1 mm
    # to half darkness, blurred: the walk steps over gaps under 1 mm), then a letter's
    # stroke straight on, 0.8-2.2 mm long.  Where the walk ends on the letter, cut, its
    # ink stops on the long line: no end; where it stopped, it is by the line's ink
    x, w, f, line = _crossing(phi, cross)
    ink = 0.45 / math.sin(math.radians(min(cross, 180.0 - cross)))
    start = x + (ink + gap) * w
    sheet = pencil_sheet([(line[0], line[1]), (f, x), (start, start + letter * w)], blur)
    end, cut = _walk(sheet, f, x, w, [line])
    assert end is not None
    if end > ink + gap:                                   # the walk ran on to the letter
        assert cut is None, cut
    else:
        assert cut is not None and cut < ink + 0.35, (cut, ink)
    # the decision does not move with the input 1e-12 of its size off
    _e, again = _walk(sheet, f, x + 1e-12 * 40.0, w, [line])
    assert (again is None) == (cut is None)


@settings(max_examples=20, deadline=None)
@given(phi=st.floats(0.0, 360.0), cross=st.floats(35.0, 145.0), past=st.floats(1.5, 2.0),
       gap=st.floats(0.55, 0.8), letter=st.floats(0.8, 1.4))
def test_a_tip_past_a_line_keeps_its_end_before_the_letter(
        phi: float, cross: float, past: float, gap: float, letter: float) -> None:
    # the stroke crosses the long line and goes on 1.5-2 mm to its own tip, then paper
    # and a letter (its far end under 5 mm past x: within the walk's reach): the end is
    # the stroke's tip (within the blurred half width, 0.35 mm)
    x, w, f, line = _crossing(phi, cross)
    tip = x + past * w
    start = tip + (0.6 + gap) * w     # 0.6: the strokes' round ends, blurred, to half dark
    sheet = pencil_sheet([(line[0], line[1]), (f, tip), (start, start + letter * w)], 0.8)
    _end, cut = _walk(sheet, f, x, w, [line])
    assert cut is not None and abs(cut - past) < 0.35, (cut, past)


@settings(max_examples=15, deadline=None)
@given(phi=st.floats(0.0, 360.0), cross=st.floats(35.0, 145.0), gap=st.floats(0.6, 0.9),
       rest=st.floats(3.5, 6.0))
def test_a_stroke_going_on_past_a_gap_keeps_its_end(
        phi: float, cross: float, gap: float, rest: float) -> None:
    # past the line a pencil gap, then the stroke's own ink for 3.5-6 mm (longer than a
    # letter): the walk's end is left where it is, at that ink's end
    x, w, f, line = _crossing(phi, cross)
    ink = 0.45 / math.sin(math.radians(min(cross, 180.0 - cross)))
    start = x + (ink + gap) * w
    sheet = pencil_sheet([(line[0], line[1]), (f, x), (start, start + rest * w)], 0.8)
    end, cut = _walk(sheet, f, x, w, [line])
    assert end is not None and cut == end


# the four-bar on which the walk ran onto ``e``'s letter (found by Hypothesis in
# tests/scan/test_inkfit.py: velocity, phone, photo seed 3112)
_FOURBAR = {
    "title": "random fourbar", "units": {"length": "ft"},
    "links": {"1": {"O2": [0.0, 0.0], "O4": [0.5404983641280698, -1.5997787407557362]},
              "2": {"A": [-3.5199907758729987, -1.0785259957922917],
                    "O2": [-3.0854377929279666, 1.2153405170619482]},
              "3": {"A": [0.26960425436540136, 2.428427500844093],
                    "B": [0.9420261862394619, 4.798409755335343],
                    "E": [0.5584155752126068, 3.626867066727199]},
              "4": {"B": [0.5832347924771206, -1.2218740373452275],
                    "O4": [0.17658934243098673, -2.8130868475377016]}},
    "drive": {"link": 2, "angle": 0.0, "omega": 4.914881428687878,
              "alpha": 283.1673536778658},
    "assembly": {"A": [-0.434552982945032, -2.29386651285424],
                 "B": [2.028974394834372, -2.29386651285424],
                 "E": [0.7972107059446701, -2.244595965298652]}}


def test_a_right_drawing_reads_e_by_the_line_not_on_its_letter() -> None:
    sol = from_dict(_FOURBAR).solve()
    lay = layout_for(sol, "velocity", "fourbar")
    images = exact_images(sol, lay)
    # e is 1.05 mm off the line a b on the sheet (the setting of the cause)
    a, b, e = images["A"], images["B"], images["E"]
    u = (b - a) / float(np.hypot(*(b - a)))
    assert 0.5 < abs(float(u[0] * (e - a)[1] - u[1] * (e - a)[0])) < 1.5
    read, _rep, rows = read_photo(sol, lay, images, "phone", 3112)
    assert float(np.hypot(*(read.points["E"] - e))) < 0.5, read.points["E"]
    assert all(r.verdict == OK for r in rows.values()), [(k, r.code) for k, r in rows.items()]
