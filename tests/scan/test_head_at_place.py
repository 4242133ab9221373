"""An arrowhead looked for at each place an image can be, its axis along pole -> place.

Every absolute vector is drawn from the pole with its arrowhead at its image
(Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), so where no segment ends at
an image (a short vector whose ink is one band with a link line near the
pole, or an image in the middle of a band of merged strokes) its
arrowhead's tip still marks it: :func:`graphkin.scan.arrows.head_at`.

The photos are two mechanisms of the sample seeded 20261129
(benchmarks/data/scan_sample_20261129.json, drawn by tests/strategies.py),
misread by the reader before scan22 (docs/scan-reading.md, 28 Nov 2026):
#9, a slider-driven slider-crank's velocity polygon, `a` 7.8 mm from the
pole with the link line `a d` 10.5° from `o a` passing 1.4 mm from the pole
(`V_A` not-found); #36, the same kind's acceleration polygon, `c` 10.2 mm
from the pole in the middle of the straight band pole-c-d (`A_C` read
0.6-3 mm toward the pole, unexplained).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scan import photos  # noqa: E402
from scan.photos import exact_images, layout_for, read_photo  # noqa: E402

from graphkin.check.report import OK  # noqa: E402
from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.arrows import head_at  # noqa: E402
from graphkin.scan.inkfit import Sheet  # noqa: E402

_H = 120.0
_PAPER = 235

# #9 of the 20261129 sample (seed 0)
_SHORT_A: dict[str, Any] = {
    "title": "random slider-crank, slider-driven", "units": {"length": "in"},
    "links": {"1": {"O2": [-9.175552797847659e-194, -1.9516362555387856e-131]},
              "2": {"A": [-5.045630910893523, -12.577449358738019],
                    "O2": [5.045630910893523, -15.190735555305602]},
              "3": {"A": [19.112285880167384, -23.468820816459033],
                    "C": [-0.17226881988637377, 20.029229454369823],
                    "D": [-18.940017060281, 3.439591362089203]},
              "4": {"C": [13.897845360007867, -7.592945436591086]}},
    "drive": {"link": 4, "position": 0.0, "velocity": -531.9317403970456},
    "assembly": {"A": [-10.091261821787047, 2.613286196567583],
                 "C": [-36.83778125466046, 41.965517716137654],
                 "D": [-52.3392306918977, 22.289401956352616]},
    "sliders": [{"link": 4, "on": 1, "point": "C",
                 "line": [[-36.83778125466046, 41.965517716137654],
                          [-11.593125205016158, 55.75673617130845]]}]}

# #36 of the 20261129 sample (seed 20)
_BAND_C: dict[str, Any] = {
    "title": "random slider-crank, slider-driven", "units": {"length": "ft"},
    "links": {"1": {"O2": [4.0888151875955325e-87, 7.779321004516809e-123]},
              "2": {"A": [-188.02815815825213, -539.3568839661089],
                    "O2": [-337.70745498735243, -495.6936563500421]},
              "3": {"A": [261.6482819438089, 551.0760939534363],
                    "C": [-373.19782729545096, -82.49408745909317],
                    "D": [-14.676246146791458, 5.769588557045245]},
              "4": {"C": [0.0, 243.75086997899166]}},
    "drive": {"link": 4, "position": 40.44633774078494, "velocity": -2507.8702451048557,
              "acceleration": 2557.3023074000776},
    "assembly": {"A": [-75.85554358492068, -136.22153226469948],
                 "C": [373.1555819090421, -912.642659214486],
                 "D": [380.05502972032497, -543.4806375043485]},
    "sliders": [{"link": 4, "on": 1, "point": "C",
                 "line": [[332.70924416825716, -912.642659214486],
                          [1085.2360335548296, -912.642659214486]]}]}


def _deg(u: np.ndarray, v: np.ndarray) -> float:
    c = float(u @ v) / float(np.hypot(*u) * np.hypot(*v))
    return float(np.degrees(np.arccos(np.clip(c, -1.0, 1.0))))


def test_a_short_vector_in_one_band_with_a_link_line_is_read_at_its_arrowhead() -> None:
    # before scan22: V_A not-found (no segment end within 4 mm of a, one barb in a d's ink)
    sol = from_dict(_SHORT_A).solve()
    lay = layout_for(sol, "velocity", "slider-crank, slider-driven")
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    o_a = images["A"] - pole
    # (what the test means: a short, the link line a d within 12° of o a)
    assert 7.0 < float(np.hypot(*o_a)) < 9.0
    ad = _deg(o_a, images["D"] - images["A"])
    assert min(ad, 180.0 - ad) < 12.0
    for level in ("scan", "phone"):
        read, rep, rows = read_photo(sol, lay, images, level, 0)
        assert "A" in read.points, rep.text()
        # the tip is found to 0.1-0.3 mm; the drawing tolerance is 0.5 mm on the sheet
        assert float(np.hypot(*(read.points["A"] - images["A"]))) < 0.5, rep.text()
        assert all(r.verdict == OK for r in rows.values()), rep.text()


def test_an_image_in_the_middle_of_a_band_is_read_at_its_arrowhead() -> None:
    # before scan22: A_C unexplained, c read 3.2 mm toward the pole where a c crosses the band
    sol = from_dict(_BAND_C).solve()
    lay = layout_for(sol, "acceleration", "slider-crank, slider-driven")
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    o_c, o_d = images["C"] - pole, images["D"] - pole
    # pole, c and d nearly on one line (o d passes c within 1.5 mm, a stroke's ink and a
    # half): one band
    assert abs(float(o_d[0] * o_c[1] - o_d[1] * o_c[0])) / float(np.hypot(*o_d)) < 1.5
    read, rep, rows = read_photo(sol, lay, images, "scan", 20)
    assert float(np.hypot(*(read.points["C"] - images["C"]))) < 0.5, rep.text()
    assert all(r.verdict == OK for r in rows.values()), rep.text()


def _drawing(rng: np.random.Generator, length: float, beta: float, blur: float,
             barbs: bool) -> tuple[Sheet, np.ndarray, np.ndarray, np.ndarray]:
    """o a (``length`` mm, its arrowhead if ``barbs``) and a link line leaving a backward
    ``beta`` degrees off o a, 15-25 mm long: a thin triangle at the pole (class 1 (a)).

    The hand of photos.py: a wobble of 0.1 mm, ends over- or undershot by -0.3..0.4 mm,
    barbs 2-3 mm at 15-25°.  Returns the sheet, the pole, a and o a's direction.
    """
    img, lay = photos.blank_page(_H, _PAPER)
    ang = rng.uniform(0.0, 2 * math.pi)
    u = np.array([math.cos(ang), math.sin(ang)])
    pole = np.array([60.0, 60.0]) - 0.5 * length * u
    a = pole + length * u

    def turn(deg: float) -> np.ndarray:
        b = math.radians(deg)
        return np.array([[math.cos(b), -math.sin(b)], [math.sin(b), math.cos(b)]]) @ u

    far = a + turn(180.0 + float(rng.choice([-1.0, 1.0])) * beta) * rng.uniform(15.0, 25.0)
    grey = int(rng.integers(50, 120))
    photos._stroke(img, lay, pole + u * rng.uniform(-0.3, 0.3), a + u * rng.uniform(-0.3, 0.4),
                   rng, grey, gap=False)
    back = (a - far) / float(np.hypot(*(a - far)))
    photos._stroke(img, lay, a + back * rng.uniform(-0.3, 0.4), far, rng,
                   grey + int(rng.integers(-15, 15)), gap=False)
    for s in (1.0, -1.0) if barbs else ():
        photos._stroke(img, lay, a, a + turn(180.0 + s * rng.uniform(15.0, 25.0))
                       * rng.uniform(2.0, 3.0), rng, grey, gap=False)
    return Sheet(photos.as_rectified(img, _PAPER, blur, 3.0, rng), (0, 0), _H), pole, a, u


@settings(max_examples=25, deadline=None)
@given(length=st.floats(7.5, 12.0), beta=st.floats(6.0, 12.0), blur=st.floats(0.5, 1.5),
       short=st.floats(0.03, 0.10), seed=st.integers(0, 2**32 - 1))
def test_a_tip_only_at_the_drawn_arrowhead(length: float, beta: float, blur: float,
                                           short: float, seed: int) -> None:
    # a drawn where it is; a place 3-10 % off along o a (a wrong length's exact place, or
    # the drawing's where the student drew it right): the tip found, if any, is the drawn
    # one (within 0.6 mm: a barb 2 mm at 15° stands hardly 0.5 mm clear once blurred),
    # never at the place where nothing is drawn
    sheet, pole, a, _u = _drawing(np.random.default_rng(seed), length, beta, blur, True)
    for f in (1.0, 1.0 - short, 1.0 + short):
        tip = head_at(sheet, pole + f * (a - pole), pole, 1.0)
        if f == 1.0:
            assert tip is not None
        if tip is not None:
            assert float(np.hypot(*(tip - a))) < 0.6, (f, tip - a)


@settings(max_examples=20, deadline=None)
@given(length=st.floats(7.5, 14.0), beta=st.floats(6.0, 35.0), blur=st.floats(0.5, 1.5),
       seed=st.integers(0, 2**32 - 1))
def test_two_strokes_parting_from_a_point_are_no_arrowhead(length: float, beta: float,
                                                           blur: float, seed: int) -> None:
    # o a and the link line without the arrowhead: their inks part for good behind a (a
    # one-sided widening like a barb's, scan18), but no barb ends there
    sheet, pole, a, _u = _drawing(np.random.default_rng(seed), length, beta, blur, False)
    assert head_at(sheet, a, pole, 4.0) is None


def test_a_tip_does_not_move_with_round_off() -> None:
    # the decision rests on millimetres and darkness ratios: a place and pole moved by
    # 1e-12 of their size find the same tip (or none), to far below a pixel
    rng = np.random.default_rng(20261128)
    for _ in range(6):
        sheet, pole, a, _u = _drawing(rng, rng.uniform(7.5, 12.0), rng.uniform(6.0, 12.0),
                                      rng.uniform(0.5, 1.5), bool(rng.integers(0, 2)))
        tip = head_at(sheet, a, pole, 4.0)
        moved = head_at(sheet, a * (1.0 + 1e-12), pole * (1.0 - 1e-12), 4.0)
        assert (tip is None) == (moved is None)
        if tip is not None and moved is not None:
            assert float(np.hypot(*(tip - moved))) < 1e-6
