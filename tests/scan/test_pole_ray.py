"""A short vector's image read where drawn when a link's tip runs on past it (``scan.poleray``).

A vector from the pole 7.8-9.4 mm long may give no pencil segment of its
own: its ink runs under the printed pole's label (masked as print), or the
pole's dot and the arrowhead take it.  The link line drawn to that image
then runs on 1.4-3 mm past it over one barb of the image's own arrowhead
(8-18° off the link's prolongation), sometimes on to another stroke, and the
image was read at that run-on tip (docs/scan-reading.md, 28 Nov 2026,
scan21).  Every vector starts at the pole (Sec. 3.4), so the tip is cut
back to the ray from the pole through the place the image can be.

The raster tests draw the strokes themselves (the image point they place is
the expected cut); the photo tests draw two mechanisms of the sample
``benchmarks/data/scan_sample_20261129.json`` (#16 and #28, both misread by
the reader before this rule) as the benchmark does, each image where the
analytic solver puts it (``exact_images``), and expect every row right.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scan.photos import exact_images, hand_photo, layout_for, sheet_pixels  # noqa: E402
from scan.rasters import pencil_sheet, unit  # noqa: E402

from graphkin.check import CheckTolerance, Diagnoser, Evaluator  # noqa: E402
from graphkin.check.report import OK  # noqa: E402
from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.inkfit import Sheet  # noqa: E402
from graphkin.scan.mark import mark_scan  # noqa: E402
from graphkin.scan.poleray import pole_ray_cuts  # noqa: E402
from graphkin.scan.read import read_sheet  # noqa: E402
from graphkin.scan.sheet import PX_PER_MM, Page  # noqa: E402

_H_MM = 60.0
_POLE = np.array([30.0, 30.0])


def _sheet(strokes: list[tuple[np.ndarray, np.ndarray]], blur: float) -> Sheet:
    return pencil_sheet(strokes, blur, _H_MM)


_unit = unit


def _arrow(x: np.ndarray, u: np.ndarray) -> list[tuple[np.ndarray, np.ndarray]]:
    """Two barbs at tip ``x`` of a vector along ``u``: 2.5 mm long, 20° either side."""
    ang = math.degrees(math.atan2(u[1], u[0])) + 180.0
    return [(x, x + 2.5 * _unit(ang + s * 20.0)) for s in (-1.0, 1.0)]


def _run_on(phi: float, r: float, side: float, off: float, run: float
            ) -> tuple[np.ndarray, np.ndarray, list[tuple[np.ndarray, np.ndarray]]]:
    """The image ``x``, the link's segment (its tip run on), and the strokes drawn.

    The vector from the pole at ``phi`` (r mm long) with its arrowhead at x;
    the link drawn to x comes from the side where its prolongation past x
    lies ``off`` degrees from one barb (``side`` ±1: which), and the
    detector's segment runs ``run`` mm past x along it, over that barb.
    """
    u = _unit(phi)
    x = _POLE + r * u
    barb = phi + 180.0 + side * 20.0                  # the barb's direction from x
    w = _unit(barb + side * off)                      # the link's prolongation past x
    far = x - 25.0 * w
    strokes = [(_POLE, x), (far, x), *_arrow(x, u)]
    return x, np.array([far, x + run * w]), strokes


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(0.0, 360.0), r=st.floats(7.8, 10.0), side=st.sampled_from([-1.0, 1.0]),
       off=st.floats(8.0, 18.0), run=st.floats(1.4, 3.0), blur=st.floats(0.5, 1.0))
def test_a_link_tip_run_on_over_a_barb_is_cut_back_to_the_ray(
        phi: float, r: float, side: float, off: float, run: float, blur: float) -> None:
    # the link's prolongation is 28-38° from the vector's line (20° barb + 8-18°): the tip,
    # 1.4-3 mm past x, is put where the link's line crosses the ray from the pole through
    # the image's place, i.e. x itself (both lines are drawn through x)
    x, seg, strokes = _run_on(phi, r, side, off, run)
    sheet = _sheet(strokes, blur)
    segs = np.array([seg])
    got = pole_ray_cuts(segs, sheet, _POLE, [x])
    assert float(np.hypot(*(got[0, 1] - x))) < 0.2, (got[0, 1], x)
    assert np.array_equal(got[0, 0], segs[0, 0])


@settings(max_examples=20, deadline=None)
@given(phi=st.floats(0.0, 360.0), r=st.floats(7.8, 10.0), cross=st.floats(30.0, 150.0),
       run=st.floats(1.4, 3.0))
def test_a_link_crossing_a_longer_vector_in_its_middle_is_kept(
        phi: float, r: float, cross: float, run: float) -> None:
    # the vector from the pole goes on 4 mm past x to its own image, and the link's ink
    # goes on 6 mm past x (the detector broke it 1.4-3 mm past): nothing to cut back to
    u = _unit(phi)
    x = _POLE + r * u
    w = _unit(phi + cross)
    far = x - 25.0 * w
    sheet = _sheet([(_POLE, x + 4.0 * u), (far, x + 6.0 * w), *_arrow(x + 4.0 * u, u)], 0.8)
    segs = np.array([[far, x + run * w]])
    assert np.array_equal(pole_ray_cuts(segs, sheet, _POLE, [x]), segs)


def test_a_link_ending_at_its_image_is_kept() -> None:
    # the segment ends at x (0.3 mm overshot): under a millimetre past the ray, not cut
    x, seg, strokes = _run_on(130.0, 8.5, 1.0, 12.0, 0.3)
    sheet = _sheet(strokes, 0.8)
    segs = np.array([seg])
    assert np.array_equal(pole_ray_cuts(segs, sheet, _POLE, [x]), segs)


def test_a_vector_under_a_masked_label_still_gives_its_ray() -> None:
    # the vector's middle 2-6 mm from the pole masked as print (the pole's label): the
    # ink left near the pole and the image still puts the ray, and x is found
    x, seg, strokes = _run_on(-131.7, 7.9, -1.0, 10.0, 3.0)
    sheet = _sheet(strokes, 0.8)
    n = int(_H_MM * PX_PER_MM)
    mask = np.ones((n, n), np.float32)
    u = (x - _POLE) / 7.9
    for s in np.arange(2.0, 6.0, 0.05):
        p = _POLE + s * u
        cv2.circle(mask, (int(p[0] * PX_PER_MM), int((_H_MM - p[1]) * PX_PER_MM)),
                   int(1.2 * PX_PER_MM), 0.0, -1)
    printed = Sheet(mask, (0, 0), _H_MM)
    dimmed = Sheet(np.maximum(sheet.ratio, 1.0 - mask), (0, 0), _H_MM)
    got = pole_ray_cuts(np.array([seg]), dimmed, _POLE, [x], printed)
    assert float(np.hypot(*(got[0, 1] - x))) < 0.2, (got[0, 1], x)


def test_the_cut_moved_1e_12_is_alike() -> None:
    # the decisions (a ray looked at, ink present, the vector ending, the link stopping)
    # do not rest on round-off: inputs moved by 1e-12 of their size cut alike
    x, seg, strokes = _run_on(40.0, 8.8, 1.0, 14.0, 2.2)
    sheet = _sheet(strokes, 0.8)
    segs = np.array([seg])
    a = pole_ray_cuts(segs, sheet, _POLE, [x])
    for k in (1.0 + 1e-12, 1.0 - 1e-12):
        b = pole_ray_cuts(segs * k, sheet, _POLE * k, [x * k])
        assert float(np.abs(a - b).max()) < 1e-6
    assert float(np.hypot(*(a[0, 1] - x))) < 0.2                  # cut (see above)


_FOURBAR = {
    "title": "random fourbar", "units": {"length": "ft"},
    "links": {"1": {"O2": [0.05, 0.39507831815374983], "O4": [0.9268238319927987,
                                                                0.308319586078492]},
              "2": {"A": [-0.21764893512335093, -0.19632627795475807],
                    "O2": [-0.47741883863373835, -0.45208365091814773]},
              "3": {"A": [-0.044611532750085, 0.020139791599188883],
                    "B": [0.205388467249915, 0.020139791599188883],
                    "E": [0.00733620131582291, -0.040279583198377766]},
              "4": {"B": [-0.1376430270484662, -0.184378096171949],
                    "O4": [0.1226452769472185, -0.3153969207025448]}},
    "drive": {"link": 2, "angle": -38.82447780159303, "omega": 15.476999698378025,
              "alpha": -220.35206742544506},
    "assembly": {"A": [0.4127226737717071, 0.4314719786845919],
                 "B": [0.6627226737717071, 0.4314719786845919],
                 "E": [0.46467040783761504, 0.37105260388702527]}}
_SLIDER = {
    "title": "random slider-crank, slider-driven", "units": {"length": "ft"},
    "links": {"1": {"O2": [-2.672682632723949e-42, 25.0],
                    "L1a": [31.670065013555543, 104.6085936105846],
                    "L1b": [1.4951973199265716, 90.37650174355264]},
              "2": {"A": [-50.57569526048285, -11.016515188456394],
                    "O2": [-24.63929908233957, 11.748151595373052]},
              "3": {"A": [-7.447455127841895, 50.460640685299126],
                    "C": [-48.937014890914355, 6.078998766279497],
                    "D": [-41.33606512277576, 8.530900932195191]},
              "4": {"C": [-0.0, 0.0]}},
    "drive": {"link": 4, "position": -5.391760004555554, "velocity": -113.79780042811238,
              "acceleration": 1.5},
    "assembly": {"A": [26.61124167367824, 46.971993925756564],
                 "C": [36.54662642452276, 106.90864246915051],
                 "D": [31.578934049100504, 100.6549800164625]},
    "sliders": [{"link": 4, "on": 1, "point": "C", "line": ["L1a", "L1b"]}]}


@pytest.mark.parametrize("data,kind,level,seed,name", [
    # `o a` (7.9 mm) under the printed pole's label; `a b` runs on 1.5 mm over a barb
    # (A_A unexplained before)
    (_FOURBAR, "fourbar", "phone", 3, "A"),
    # `o d` (9.35 mm) taken by the pole's dot and the arrowhead; `a d` runs on 1.4 mm
    # over a barb (A_D unexplained before, read 0.9 mm off)
    (_SLIDER, "slider-crank, slider-driven", "scan", 2, "D"),
], ids=["under-the-pole-label", "dot-and-arrowhead"])
def test_a_right_drawing_reads_the_short_vector_where_drawn(
        data: dict[str, Any], kind: str, level: str, seed: int, name: str) -> None:
    sol = from_dict(data).solve()
    lay = layout_for(sol, "acceleration", kind)
    images = exact_images(sol, lay)
    assert 7.8 < float(np.hypot(*(images[name] - np.array(lay.pole)))) < 9.4
    diag = Diagnoser(Evaluator(sol))
    photo = hand_photo(sol, lay, sheet_pixels(sol, lay), images, level, seed)
    read = read_sheet(sol, Page("p", photo), diag, lay.digest)
    assert name in read.points
    # within the drawing tolerance's 0.5 mm of where it was drawn
    assert float(np.hypot(*(read.points[name] - images[name]))) < 0.5, read.points[name]
    rows = mark_scan(sol, read, "p", CheckTolerance(), diag).rows
    assert rows and all(r.verdict == OK for r in rows), [(r.key, r.verdict, r.code) for r in rows]
