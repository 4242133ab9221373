"""An image whose vector lies on a longer one from the pole is read at its arrowhead.

A slider-driven slider-crank with the slider at constant speed has A_C = 0,
so the acceleration image of a coupler point D on the rod A-C lies on the
line from the pole to a (Uicker, Pennock & Shigley, 5th ed., Sec. 4.2: the
acceleration image of a link is similar to the link): o_d, o_a and the image
line d-a are one straight stroke, and only o_d's arrowhead, in the middle of
it, marks d (Sec. 3.4: each absolute vector drawn from the pole with its
arrowhead at the image).  Three drawings of the benchmark's fixed sample
(benchmarks/data/scan_sample_65.json, #2, #59, #61) where d was not found or
read 1.1-1.2 mm off (docs/checking.md "How well it reads"): the arrowhead's
barbs at 13-15° (hardly 0.7 mm beside the line), a barb's edge joined by the
letter's ink, and the line broken by the detector beside the tip.
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
from scan.photos import between_pole_and, exact_images, layout_for, read_photo  # noqa: E402

from graphkin.check.report import OK, WRONG  # noqa: E402
from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.arrows import _broken_ends, arrow_tips  # noqa: E402
from graphkin.scan.strokes import apart, segments  # noqa: E402

# Two slider-driven slider-cranks drawn by tests/strategies.py (the fixed sample's #2 and
# #59; #61 is #59's mechanism with the coupler point's link drawn another way)
_SC2 = {
    "title": "random slider-crank, slider-driven", "units": {"length": "ft"},
    "links": {"1": {"O2": [0.0, 11.944811288822905],
                    "L1a": [-32.86816998379555, -99.87946184798281],
                    "L1b": [-14.248105152999258, -101.2540410285941]},
              "2": {"A": [-6.062390989867267, 11.311827363777068],
                    "O2": [22.881070195631533, 31.013378016379768]},
              "3": {"A": [23.1829707844329, -34.94984064256637],
                    "C": [-23.182970784432893, 34.94984064256637], "D": [0.0, 0.0]},
              "4": {"C": [-3.4518253703579553, -5.528535769025845],
                    "G": [-6.003052007510563, 4.831600488835095]}},
    "drive": {"link": 4, "position": 0.0, "velocity": 389.5339973547133, "acceleration": 0.0},
    "assembly": {"A": [-19.622262635615844, -17.052461903193954],
                 "C": [-32.86816998379555, -99.87946184798281],
                 "D": [-26.245216309705697, -58.46596187558838],
                 "G": [-34.64973781116851, -89.35961409661152]},
    "sliders": [{"link": 4, "on": 1, "point": "C", "line": ["L1a", "L1b"]}]}


_SC59 = {
    "title": "random slider-crank, slider-driven", "units": {"length": "mm"},
    "links": {"1": {"O2": [0.00020398508850171313, -2.625515857073206]},
              "2": {"A": [2.1029611323889736, 0.2062847298035208],
                    "O2": [1.2084053295088442, 0.6777499194582601]},
              "3": {"A": [1.1399231925745779, 1.1487707823647266],
                    "C": [-1.9745381325984004, -4.38497145365043],
                    "D": [-0.41750498995242374, -1.6180493867524712]},
              "4": {"C": [2.6512972582101755, 0.18881945462903693],
                    "G": [2.642122381511588, 0.07972900366206948]}},
    "drive": {"link": 4, "position": -2.276496813603253, "velocity": 54.92478105494217},
    "assembly": {"A": [0.7428819541074809, -3.3117657706298753],
                 "C": [-0.8907187740207807, -9.448012273314971],
                 "D": [-0.0741223950451516, -6.3798890219724225],
                 "G": [-0.9829564792573028, -9.506979302978259]},
    "sliders": [{"link": 4, "on": 1, "point": "C",
                 "line": [[0.49190728568485453, -11.256542870614512],
                          [2.1357132057659864, -13.406707249204182]]}]}
_SC61 = {
    "title": "random slider-crank, slider-driven", "units": {"length": "mm"},
    "links": {"1": {"O2": [0.00020398508850171313, -2.625515857073206]},
              "2": {"A": [2.1029611323889736, 0.2062847298035208],
                    "O2": [1.2084053295088442, 0.6777499194582601]},
              "3": {"A": [-0.007509927225993113, -0.8899763572198052],
                    "C": [-0.8271050127978296, -2.346224314065899],
                    "D": [-0.417504989952424, -1.6180493867524726]},
              "4": {"C": [2.6512972582101773, 0.1888194546290356],
                    "G": [2.642122381511589, 0.07972900366206859]}},
    "drive": {"link": 4, "position": -2.276496813603253, "velocity": 54.92478105494217},
    "assembly": {"A": [0.7428819541074809, -3.3117657706298753],
                 "C": [0.3129870256526752, -4.926567481862795],
                 "D": [0.5277305047915763, -4.119166626246336],
                 "G": [0.22074932041615314, -4.985534511526082]},
    "sliders": [{"link": 4, "on": 1, "point": "C",
                 "line": [[1.6956130853583105, -6.735098079162336],
                          [3.339419005439442, -8.885262457752006]]}]}


@pytest.mark.parametrize(("data", "level", "case", "seed"), [
    (_SC2, "scan", "right", 54267),       # barbs at 13-15°: no tip found, d read 1.2 mm off
    (_SC59, "scan", "length", 122),       # a 4.8 % long: a barb's edge joined by the letter
    (_SC61, "phone", "reversed", 0),      # the line broken beside d: d read 1.1 mm off
])
def test_an_image_on_the_line_to_another_is_read_at_its_arrowhead(
        data: dict[str, Any], level: str, case: str, seed: int) -> None:
    sol = from_dict(data).solve()
    lay = layout_for(sol, "acceleration", "slider-crank, slider-driven")
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    # (the drawing is what the test means: d on o-a within 0.01 mm, between o and a)
    assert between_pole_and(pole, images["A"], images["D"])
    drawn = {"right": images, "reversed": {k: 2 * pole - p for k, p in images.items()},
             "length": {**images, "A": pole + 1.048 * (images["A"] - pole)}}[case]
    read, _, rows = read_photo(sol, lay, drawn, level, seed)
    # d read at its arrowhead's tip, where it is drawn (the tip 0.1-0.3 mm off, the line's
    # wobble 0.1 mm across)
    assert "D" in read.points
    assert float(np.hypot(*(read.points["D"] - drawn["D"]))) < 0.5, read.points["D"] - drawn["D"]
    if case == "right":
        assert all(r.verdict == OK for r in rows.values())
    elif case == "reversed":
        assert rows["A_A"].code == "sense" and rows["A_D"].code in ("sense", "follows:A_A")
    else:
        # 4.8 % of o_a (about 70 mm) moves a by 3.4 mm: wrong, no usual mistake; d right
        assert rows["A_A"].verdict == WRONG and rows["A_A"].code == "unexplained"
        assert rows["A_D"].verdict == OK


def _narrow(rng: np.random.Generator, od: float, da: float, barb: float, blur_px: float
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """o_a drawn through d, o_d's arrowhead at d with barbs at ``barb``° (2-2.5 mm).

    Returns the ratio at the rectified 5 px/mm (1 = paper), d and the pole (sheet mm).
    """
    h = 120.0
    img, lay = photos.blank_page(h, 235)
    u, pole, d, a = photos.in_line(rng, od, da)
    grey = int(rng.integers(50, 120))
    photos._stroke(img, lay, pole, a + u * rng.uniform(-0.3, 0.4), rng, grey, gap=False)
    for s in (1.0, -1.0):
        b = math.radians(180.0 + s * (barb + rng.uniform(-1.0, 1.0)))
        rot = np.array([[math.cos(b), -math.sin(b)], [math.sin(b), math.cos(b)]])
        photos._stroke(img, lay, d, d + rot @ u * rng.uniform(2.0, 2.5), rng, grey, gap=False)
    return photos.as_rectified(img, 235, blur_px, 2.0, rng), d, pole


@settings(max_examples=20, deadline=None)
@given(od=st.floats(15.0, 40.0), da=st.floats(15.0, 25.0), barb=st.floats(15.5, 18.0),
       blur=st.floats(0.5, 1.2), seed=st.integers(0, 2**32 - 1))
def test_narrow_barbs_in_the_middle_of_a_line_give_their_tip(
        od: float, da: float, barb: float, blur: float, seed: int) -> None:
    # barbs 2-2.5 mm long at 14.5-19° (photos.py draws 15-25°) reach 0.5-0.8 mm beside the
    # line (its own ink 0.2-0.3 mm each side of its middle): about a fifth of the line's
    # darkness is read beside it, where the detector used to ask for 30 %.  Blurred as the
    # scan and mild levels blur the rectified sheet (0.1-0.24 mm): the tip found, within
    # 0.6 mm of d, and no other.  (Under 14.5° the two barbs' edges can put the tip over
    # 1 mm apart, and none is found: docs/checking.md.)
    # Not every such tip is found (local runs with new examples missed one in about 13:
    # the rate is measured below); a tip found is d's, and there is never another.
    ratio, d, pole = _narrow(np.random.default_rng(seed), od, da, barb, blur)
    segs = apart(segments(ratio, (0, 0), 120.0), ratio, (0, 0), 120.0)
    tips = arrow_tips(segs, ratio, (0, 0), 120.0, pole)
    assert len(tips) <= 1, (tips, d)
    if len(tips):
        assert float(np.hypot(*(tips[0] - d))) < 0.6, (tips[0] - d)


def test_narrow_barbs_in_the_middle_of_a_line_are_found_in_most_drawings() -> None:
    # The same drawings, 120 of them from fixed seeds: 109 found here (91 %; 92.5 % of 200
    # other seeds), none off d, none doubled; at least 85 %, a margin for another OpenCV's
    # pixels (docs/checking.md counts about seven in eight arrowheads found on whole
    # photos, where other strokes cross the barbs).
    rng = np.random.default_rng(5)
    found = 0
    for i in range(120):
        od, da = rng.uniform(15.0, 40.0), rng.uniform(15.0, 25.0)
        barb, blur = rng.uniform(15.5, 18.0), rng.uniform(0.5, 1.2)
        ratio, d, pole = _narrow(np.random.default_rng(i), od, da, barb, blur)
        segs = apart(segments(ratio, (0, 0), 120.0), ratio, (0, 0), 120.0)
        tips = arrow_tips(segs, ratio, (0, 0), 120.0, pole)
        assert len(tips) <= 1 and all(float(np.hypot(*(t - d))) < 0.6 for t in tips)
        found += len(tips)
    assert found >= 0.85 * 120, found


def test_the_ends_of_pieces_of_one_line_are_breaks() -> None:
    # o-a from (0, 0) to (60, 0) broken beside d at x = 30: pieces overlapping 2 mm (28-30
    # and 30-32 mm are each other's), a piece 1° off running on 5 mm past a gap of 1 mm,
    # and a stroke ending on the line at 40° (no break: it is a vertex)
    segs = np.array([[[0.0, 0.0], [32.0, 0.0]], [[28.0, 0.1], [60.0, 0.1]],
                     [[-6.0, 0.0], [-1.0, -5.0 * math.tan(math.radians(1.0))]],
                     [[45.0, 0.0], [45.0 - 10 * math.cos(0.7), 10 * math.sin(0.7)]]])
    broken = _broken_ends(segs)
    # each piece's end inside the other's body; the 1° piece's end (gap 1 mm) runs on into
    # the first, whose start runs on into the 1° piece by 5 mm > 2.5 mm
    assert broken.tolist() == [True, True, True, False, False, True, False, False]
