"""The matching of ``check --scan`` on segments laid out by hand (no photo): which vertex is whose.

The segments (sheet mm) and each image's places are made here; the cases are
the ones a nearest-first reading gets wrong: an image whose only vertex is
also the nearest of another image that has a second one; a vector's start
near the pole (the printed pole hides its first millimetres) taken for a
short mistaken image; two images whose vertices could be swapped.
"""

from __future__ import annotations

from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

pytest.importorskip("cv2")

from graphkin.scan.read import SheetRead, _match  # noqa: E402

POLE = np.array([100.0, 100.0])


def _read(segs: list[tuple[tuple[float, float], tuple[float, float]]],
          places: dict[str, list[tuple[float, float]]]) -> SheetRead:
    layout = SimpleNamespace(pole=tuple(POLE), polygon_box=(0.0, 0.0, 200.0, 200.0))
    return SheetRead(None, layout, np.array(segs, dtype=float),  # type: ignore[arg-type]
                     places={n: [np.array(p, dtype=float) for p in at]
                             for n, at in places.items()})


def _ray(p: tuple[float, float]) -> tuple[tuple[float, float], tuple[float, float]]:
    """A vector drawn from the pole to p (its start hidden 3 mm, as under the printed pole)."""
    d = np.array(p) - POLE
    s = POLE + 3.0 * d / np.hypot(*d)
    return (float(s[0]), float(s[1])), p


def test_an_image_gives_way_to_one_that_has_no_other_vertex() -> None:
    # vertices v1 (130, 104) and v2 (137, 100); b's exact place (131, 104.5) is 1.1 mm from
    # v1, and b has a mistaken place (136, 100.5) 1.1 mm from v2 (costing 1.1 + 1.5 mm);
    # c's exact place (128, 106.5) reaches only v1 (3.2 mm).  Nearest-first gives b v1 and
    # leaves c without a vertex (a cost of its reach and more: 6.5 mm), 1.1 + 6.5 in all;
    # the least total is b at v2 and c at v1, 2.6 + 3.2
    v1, v2 = (130.0, 104.0), (137.0, 100.0)
    read = _read([_ray(v1), _ray(v2)], {"B": [(131.0, 104.5), (136.0, 100.5)],
                                        "C": [(128.0, 106.5)]})
    _match(read)
    # which vertex each name takes (v1 and v2 are 8 mm apart); where on it the point is read
    # is the strokes' business: a segment's end is its stroke's tip, half a line's width
    # (0.3 mm) past where the pencil stopped, and that is taken off, so these rays, which
    # end exactly at v1 and v2, are read 0.3 mm short (test_vertex.py: a real tip is read
    # at its point)
    assert np.hypot(*(read.points["C"] - v1)) < 1.0
    assert np.hypot(*(read.points["B"] - v2)) < 1.0
    assert read.missing == []


def test_the_start_of_a_vector_near_the_pole_is_no_image() -> None:
    # a vector from the pole to b = (60, 77) whose stroke starts 7 mm out (under the
    # printed label): its start (94.3, 96.5) lies 0.5 mm from a mistaken place of b (a unit
    # slip); b's own end is 4.7 mm from its exact place (drawn 10 % long), within reach
    b = np.array([60.0, 77.0])
    start = POLE + 7.0 * (b - POLE) / np.hypot(*(b - POLE))
    segs = [((float(start[0]), float(start[1])), (60.0, 77.0)), ((60.0, 77.0), (40.0, 130.0))]
    exact = POLE + (b - POLE) / 1.1
    read = _read(segs, {"B": [tuple(exact), tuple(start + 0.5)]})
    read.layout.polygon_box = (0.0, 0.0, 200.0, 200.0)
    _match(read)
    assert np.hypot(*(read.points["B"] - b)) < 0.2


def test_two_images_that_can_be_swapped_are_noted() -> None:
    # b's and e's places 3 mm apart, the two vertices on their perpendicular bisector, 2.5 mm
    # apart: each vertex is 1.95 mm from both places, so either way round costs the same
    segs = [_ray((131.5, 101.25)), _ray((131.5, 98.75))]
    read = _read(segs, {"B": [(130.0, 100.0)], "E": [(133.0, 100.0)]})
    _match(read)
    assert set(read.points) == {"B", "E"}
    assert any("b and e cannot be told apart" in n for n in read.notes), read.notes
    # moved 1.5 mm toward b's place, the vertices are b's and e's without doubt
    segs = [_ray((130.0, 101.25)), _ray((133.0, 98.75))]
    read = _read(segs, {"B": [(130.0, 100.0)], "E": [(133.0, 100.0)]})
    _match(read)
    assert read.notes == []


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(40, 160), st.floats(40, 160)), min_size=2, max_size=6),
       st.lists(st.tuples(st.floats(-3, 3), st.floats(-3, 3)), min_size=6, max_size=6))
def test_names_never_share_a_vertex_and_each_takes_the_least_total(
        images: list[tuple[float, float]], off: list[tuple[float, float]]) -> None:
    """Whatever the layout, no two names take one vertex, and no other assignment of the
    vertices read (each within reach of its place) costs less in total."""
    from itertools import permutations

    pts = [np.array(p) for p in images]
    if any(np.hypot(*(p - POLE)) < 12.0 for p in pts):
        return
    drawn = [p + np.array(o) for p, o in zip(pts, off)]
    if any(np.hypot(*(p - q)) < 2.5 for i, p in enumerate(drawn) for q in drawn[i + 1:]):
        return        # ends of one vertex: one candidate each (the nearest)
    segs = [_ray((float(q[0]), float(q[1]))) for q in drawn]
    names = [chr(ord("B") + i) for i in range(len(pts))]
    read = _read(segs, {n: [(float(p[0]), float(p[1]))] for n, p in zip(names, pts)})
    _match(read)
    got = list(read.points.items())
    for i, (a, pa) in enumerate(got):
        for b, pb in got[i + 1:]:
            assert np.hypot(*(pa - pb)) >= 2.5 or np.hypot(
                *(read.places[a][0] - read.places[b][0])) < 2.5, (a, b)

    def reach(n: str) -> float:
        return max(4.0, 0.12 * float(np.hypot(*(read.places[n][0] - POLE))))

    def total(assign: dict[str, np.ndarray]) -> float:
        return sum(float(np.hypot(*(q - read.places[n][0]))) for n, q in assign.items()) + sum(
            reach(n) + 2.5 for n in names if n not in assign)

    # brute force over the drawn ends (the ends of the rays) for small cases
    mine = total({n: min(drawn, key=lambda q: float(np.hypot(*(q - p))))
                  for n, p in read.points.items()})
    ends = drawn
    for k in range(len(names) + 1):
        if len(names) > 4:
            break
        for who in permutations(names, k):
            for where in permutations(range(len(ends)), k):
                assign = {n: ends[j] for n, j in zip(who, where)}
                if any(float(np.hypot(*(q - read.places[n][0]))) > reach(n)
                       for n, q in assign.items()):
                    continue
                if any(np.hypot(*(ends[a] - ends[b])) < 2.5 for a in where for b in where
                       if a < b):
                    continue
                assert total(assign) >= mine - 1e-6
