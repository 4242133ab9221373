"""Image points refined from their lines fitted to the pencil's ink (``graphkin.scan.inkfit``).

The drawn image points are known here: in the raster tests they are the
points the strokes are drawn to (hand geometry in the test); in the photo
tests they come from the analytic solver (``graphkin.kinematics.analytic``)
and a planted mistake is a vector lengthened by hand, as in test_read.py.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import Phase, assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scan.photos import exact_images, hand_photo, layout_for, sheet_pixels  # noqa: E402
from strategies import fourbars, slider_cranks  # noqa: E402

import graphkin.scan.read as scan_read  # noqa: E402
from graphkin.check import CheckTolerance, Diagnoser, Evaluator  # noqa: E402
from graphkin.check.report import OK, WRONG  # noqa: E402
from graphkin.scan.inkfit import Sheet, fit_line, refine_point, refine_points  # noqa: E402
from graphkin.scan.mark import mark_scan  # noqa: E402
from graphkin.scan.sheet import PX_PER_MM, Page  # noqa: E402

_H_MM = 100.0


def _px(p: np.ndarray) -> tuple[int, int]:
    """Sheet mm (y up) -> the raster's pixel, 16ths (cv2's ``shift=4``)."""
    return (int(round((p[0] * PX_PER_MM - 0.5) * 16)),
            int(round(((_H_MM - p[1]) * PX_PER_MM - 0.5) * 16)))


def _raster(strokes: list[tuple[np.ndarray, np.ndarray]], rng: np.random.Generator,
            blur: float, noise: float) -> np.ndarray:
    """A light-flattened page (1.0 paper) with pencil strokes 0.4 mm wide, darkness 0.55."""
    n = int(_H_MM * PX_PER_MM)
    img = np.full((n, n), 255, np.uint8)
    for a, b in strokes:
        cv2.line(img, _px(a), _px(b), 115, 2, cv2.LINE_AA, shift=4)
    out = cv2.GaussianBlur(img.astype(np.float32) / 255.0, (0, 0), blur)
    return np.clip(out + rng.normal(0.0, noise, out.shape).astype(np.float32), 0.0, 1.0)


def _turn(v: np.ndarray, deg: float) -> np.ndarray:
    a = math.radians(deg)
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]]) @ v


@settings(max_examples=30, deadline=None)
@given(phi=st.floats(15.0, 75.0), size=st.floats(35.0, 60.0), angle=st.floats(6.0, 21.0),
       side=st.sampled_from([-1.0, 1.0]), link=st.floats(25.0, 40.0),
       off=st.floats(1.0, 3.0), seed=st.integers(0, 2**16), blur=st.floats(0.5, 1.5))
def test_a_narrow_vertex_is_found_where_the_strokes_meet(
        phi: float, size: float, angle: float, side: float, link: float, off: float,
        seed: int, blur: float) -> None:
    # the vector o-v from the pole and the link's line q-v meet at v at 6-21°; both drawn
    # with their ends overshot or short by up to 0.3 mm, v with two arrowhead barbs, q with
    # its own vector from the pole; v is looked for from a point read 1-3 mm off along the
    # two lines (where a crossing of two short segments at such an angle puts it)
    rng = np.random.default_rng(seed)
    pole = np.array([12.0, 12.0])
    u = np.array([math.cos(math.radians(phi)), math.sin(math.radians(phi))])
    v = pole + size * u
    q = v + link * _turn(-u, side * angle)
    assume(5.0 < q[0] < _H_MM - 5.0 and 5.0 < q[1] < _H_MM - 5.0)
    assume(float(np.hypot(*(q - pole))) > 12.0)

    def drawn(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        d = (b - a) / float(np.hypot(*(b - a)))
        return a - d * rng.uniform(-0.3, 0.3), b + d * rng.uniform(-0.3, 0.3)

    strokes = [drawn(pole, v), drawn(q, v), drawn(pole, q)]
    for p in (v, q):
        back = (pole - p) / float(np.hypot(*(pole - p)))
        strokes += [(p, p + 2.5 * _turn(back, s * 20.0)) for s in (1.0, -1.0)]
    sheet = Sheet(_raster(strokes, rng, blur, 0.02), (0, 0), _H_MM)
    bisector = (_turn(-u, side * angle / 2))
    read = v + off * bisector * rng.choice([-1.0, 1.0])
    got = refine_points({"V": read, "Q": q}, [["V", "Q"]], pole, sheet)
    assert "V" in got
    # within the ends' 0.3 mm and a line's share of the blur (about 0.1 mm across, i.e.
    # 0.1 / sin 6° ≈ 1 mm along the lines were their crossing alone to decide)
    assert float(np.hypot(*(got["V"].point - v))) < 0.45, (got["V"], v)


def test_a_point_read_1e_12_away_is_refined_alike() -> None:
    # the decisions (lines used, ends kept, the point taken) do not rest on round-off
    rng = np.random.default_rng(7)
    pole, v = np.array([12.0, 12.0]), np.array([45.0, 52.0])
    q = v + 30.0 * _turn((pole - v) / float(np.hypot(*(pole - v))), 10.0)
    sheet = Sheet(_raster([(pole, v), (q, v), (pole, q)], rng, 0.8, 0.02), (0, 0), _H_MM)
    read = v + np.array([1.2, 1.5])
    a = refine_points({"V": read, "Q": q}, [["V", "Q"]], pole, sheet)
    b = refine_points({"V": read * (1 + 1e-12), "Q": q}, [["V", "Q"]], pole, sheet)
    assert a.keys() == b.keys() and "V" in a
    assert (a["V"].lines, a["V"].ends) == (b["V"].lines, b["V"].ends)
    assert float(np.hypot(*(a["V"].point - b["V"].point))) < 1e-6


def test_no_ink_no_refinement() -> None:
    # the lines expected are not drawn at all: nothing is refined (the point read stays)
    sheet = Sheet(np.ones((500, 500), np.float32), (0, 0), _H_MM)
    got = refine_points({"V": np.array([50.0, 50.0]), "Q": np.array([80.0, 60.0])},
                        [["V", "Q"]], np.array([12.0, 12.0]), sheet)
    assert got == {}


def _usable(images: dict[str, np.ndarray], pole: np.ndarray) -> bool:
    """As the benchmark: every image over 7 mm from the pole and 5 mm from the others."""
    pts = list(images.values())
    return bool(images) and all(np.hypot(*(p - pole)) >= 7 for p in pts) and all(
        np.hypot(*(p - q)) >= 5 for i, p in enumerate(pts) for q in pts[i + 1:])


@settings(max_examples=4, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(rm=st.one_of(fourbars(), slider_cranks()),
       diagram=st.sampled_from(["velocity", "acceleration"]),
       level=st.sampled_from(["scan", "mild", "phone", "harsh"]),
       seed=st.integers(0, 2**16), factor=st.floats(0.03, 0.10), longer=st.booleans())
def test_random_photos_refined_near_the_drawn_images_and_a_planted_mistake_named(
        rm: Any, diagram: str, level: str, seed: int, factor: float, longer: bool) -> None:
    sol = rm.mechanism().solve()
    lay = layout_for(sol, diagram, rm.kind)
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    assume(_usable(images, pole))
    name = sorted(images)[seed % len(images)]
    wrong = pole + (1 + factor if longer else 1 - factor) * (images[name] - pole)
    # a mistake the reading can tell from a misread (2 mm, docs/checking.md)
    assume(float(np.hypot(*(wrong - images[name]))) >= 2.0)
    _photos_refined_and_marked(rm.mechanism(), rm.kind, diagram, level, seed, factor, longer)


def test_a_coupler_point_read_right_is_not_carried_off_by_the_ink_fit() -> None:
    # The derandomized CI of 28 Nov (examples no longer drawn from the code's constants)
    # drew this slider-crank: D, a coupler point, read 0.12 mm from where it was drawn
    # from the segments' ends, then moved 1.7 mm by its lines' ink (session 15: a strict
    # xfail). D lies 1 mm beside the line c a of its link's image (Sec. 3.5); the walk
    # along o d stepped over the paper between and ended on the far side of c a.  The
    # ink after that paper is c a's: the end is before it (session 16, _band_gap_cut).
    import json
    from pathlib import Path

    from graphkin.mechanisms import from_dict

    data = json.loads((Path(__file__).parent / "data" / "carried_off_d.json").read_text())
    mech = from_dict(data, source="carried_off_d.json")
    _photos_refined_and_marked(mech, "slider-crank, slider-driven", "velocity", "phone", 300,
                               0.07808558494460993, True)


def _photos_refined_and_marked(mech: Any, kind: str, diagram: str, level: str, seed: int,
                               factor: float, longer: bool) -> None:
    """A right photo and one with a planted mistake: points refined near, mistake named."""
    sol = mech.solve()
    lay = layout_for(sol, diagram, kind)
    images = exact_images(sol, lay)
    pole = np.array(lay.pole)
    name = sorted(images)[seed % len(images)]
    f = 1 + factor if longer else 1 - factor
    wrong = pole + f * (images[name] - pole)
    diag, sheet = Diagnoser(Evaluator(sol)), sheet_pixels(sol, lay)
    before: dict[str, np.ndarray] = {}
    refine = scan_read.refine_read

    def spy(read: Any, *args: Any) -> None:
        before.clear()
        before.update({n: p.copy() for n, p in read.points.items()})
        refine(read, *args)

    letter = diagram[0].upper()
    for drawn in (images, {**images, name: wrong}):
        photo = hand_photo(sol, lay, sheet, drawn, level, seed)
        with pytest.MonkeyPatch.context() as mp:
            mp.setattr(scan_read, "refine_read", spy)
            read = scan_read.read_sheet(sol, Page("p", photo), diag, lay.digest)
        rows = mark_scan(sol, read, "p", CheckTolerance(), diag).rows
        for n, p in read.points.items():
            e0 = float(np.hypot(*(before[n] - drawn[n])))
            e1 = float(np.hypot(*(p - drawn[n])))
            if float(np.hypot(*(p - before[n]))) > 0.5:
                # moved by more than the drawing tolerance (a note says so): where the
                # segments' crossing was over 1 mm off, the lines' ink puts it within 0.8 mm
                # (measured on the benchmark's 780 photos: all 23 such within 0.7 mm), and
                # no move puts it 1.5 mm off (of 96 such moves 4 ended 1.1-1.3 mm off)
                if level == "harsh":
                    # past the documented levels (docs/checking.md: strokes at narrow angles
                    # merge into one blot), a move ends within 1.5 mm or nearer than it began:
                    # a slider-crank's D, 2.23 mm off, was moved to 1.72 mm (session 15)
                    assert e1 < max(1.5, e0), (n, e0, e1, level)
                else:
                    assert e1 < (0.8 if e0 > 1.0 else 1.5), (n, e0, e1, level)
        if drawn is images:
            # no usual mistake named where none was drawn
            assert not any(r.verdict != OK and r.code not in ("unexplained", "not-found")
                           for r in rows), [(r.key, r.code) for r in rows]
        else:
            got = {r.key: r.verdict for r in rows}
            assert got[f"{letter}_{name}"] == WRONG, (name, f, level)


def test_a_dot_beyond_a_line_is_no_line() -> None:
    # A photo of the fresh sample (a four-bar's acceleration polygon, phone level)
    # raised numpy's "Singular matrix": the band along a hypothesised line held ink
    # 2.5-20 mm along it, then another stroke's ink merged with it (left out) up to
    # 46.8 mm, then one dot at 47.5 mm. The fit keeps only the ink within 20 mm of
    # the last found (the wobble wanders), which left the dot alone: one middle, and
    # a straight line through one point is no fit. Such a band shows no line: None.
    start, end = np.array([20.0, 20.0]), np.array([75.0, 20.0])
    ratio = _raster([(np.array([22.5, 20.0]), np.array([40.0, 20.0])),
                     (np.array([67.4, 20.0]), np.array([67.6, 20.0]))],
                    np.random.default_rng(0), 0.6, 0.0)
    other = np.array([[41.0, 20.5], [66.0, 20.5]])      # parallel, 0.5 mm off: merged ink
    got = fit_line(Sheet(ratio, (0, 0), _H_MM), start, end, [other], clear_end=2.5)
    assert got is None
    # the same band without the dot is the line along y = 20 fitted to its ink (the control)
    ratio = _raster([(np.array([22.5, 20.0]), np.array([40.0, 20.0]))],
                    np.random.default_rng(0), 0.6, 0.0)
    got = fit_line(Sheet(ratio, (0, 0), _H_MM), start, end, [other], clear_end=2.5)
    assert got is None or abs(float(got.point[1]) - 20.0) < 0.1


@settings(max_examples=40, deadline=None)
@given(phi=st.floats(225.0, 315.0), length=st.floats(25.0, 35.0), gap=st.floats(0.8, 1.4),
       angle=st.floats(15.0, 80.0), side=st.sampled_from([-1.0, 1.0]),
       off=st.floats(-0.3, 0.3), seed=st.integers(0, 2**16), blur=st.floats(0.6, 1.0))
def test_an_image_beside_another_line_is_not_carried_past_it(
        phi: float, length: float, gap: float, angle: float, side: float, off: float,
        seed: int, blur: float) -> None:
    # A vector from the pole ends at p; another line of the polygon (a link's image line,
    # Sec. 3.5) crosses its line `gap` mm past p at `angle`.  The walk along the vector
    # used to step over the paper between (a gap under 1 mm is a pencil lifted), or over
    # the merged ink, and end on the far side of the other line: p refined 1-2.2 mm past
    # where it was drawn (18 of 40 such strokes).  Drawn geometry by hand: the refined
    # point is where the vector ends (0.5 mm, the drawing tolerance), or not refined.
    pole = np.array([50.0, 85.0])
    u = _turn(np.array([1.0, 0.0]), phi)
    p = pole + length * u
    w = _turn(u, side * angle)
    other = np.array([p + gap * u - 12.0 * w, p + gap * u + 12.0 * w])
    ratio = _raster([(pole, p), (other[0], other[1])], np.random.default_rng(seed), blur, 0.02)
    ref = refine_point(Sheet(ratio, (0, 0), _H_MM), p + off * u, [], pole,
                       [np.array([pole, p]), other])
    if ref is not None:
        assert abs(float((ref.point - p) @ u)) < 0.5, (ref.point, p)
