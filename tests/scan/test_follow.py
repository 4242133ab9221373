"""``check --scan``: follow-through from the student's own images, thin polygons, reversed sense.

A student who draws the crank's image wrong (too long, or turned a few
degrees) and then constructs every later image right from it makes one
mistake: the first image is wrong and the others ``follows``.  The later
images are constructed here by hand geometry in the test (the book's
construction, Sec. 3.4 and 4.3: each image where the lines of its two
vector equations meet, the images of a link similar to it, Sec. 3.5), from
the analytic solver's positions and rates, not by the checker's replay.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

cv2 = pytest.importorskip("cv2")

from hypothesis import HealthCheck, Phase, assume, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402
from scan.photos import exact_images, hand_photo, layout_for, sheet_pixels  # noqa: E402
from strategies import fourbars, slider_cranks  # noqa: E402

import graphkin  # noqa: E402
from graphkin.check import CheckTolerance, Diagnoser, Evaluator  # noqa: E402
from graphkin.check.report import FOLLOWS, OK, WRONG, Report  # noqa: E402
from graphkin.kinematics.analytic import solve_analytic  # noqa: E402
from graphkin.mechanisms import from_dict  # noqa: E402
from graphkin.scan.mark import mark_scan  # noqa: E402
from graphkin.scan.read import read_sheet  # noqa: E402
from graphkin.scan.sheet import Page  # noqa: E402


def _c(p: Any) -> complex:
    return complex(*np.asarray(p, dtype=float)[:2])


def _meet(p: complex, u: complex, q: complex, w: complex) -> complex:
    """Where the line through p along u meets the line through q along w."""
    # p + s u = q + t w: solve for s by the 2-D cross product
    s = ((q - p).real * w.imag - (q - p).imag * w.real) / (u.real * w.imag - u.imag * w.real)
    return p + s * u


def _carried(sol: Any, lay: Any, diagram: str, crank: str, rocker_pivot: str,
             coupler: str, wrong: np.ndarray) -> dict[str, np.ndarray]:
    """A four-bar's images constructed right from the crank image ``wrong`` (sheet mm).

    The four-bar O2-crank-coupler-O4: the coupler's image c from the crank's
    image b: V_C = V_B + V_CB (⊥ CB) = V_CO4 (⊥ CO4) (Sec. 3.4); for the
    acceleration polygon each line drawn from the end of its normal component
    -ω² R (Sec. 4.3), ω3 and ω4 the exact ones (the velocity polygon right).
    Every other point of links 3 and 4 by similarity to the link (Sec. 3.5).
    """
    mech = sol.mechanism
    an = solve_analytic(mech)
    pole = _c(lay.pole)
    pos = {n: _c(an.position(n)) for n in mech.point_names}
    b = _c(wrong) - pole
    cb = pos[coupler] - pos[crank]
    co = pos[coupler] - pos[rocker_pivot]
    if diagram == "velocity":
        c = _meet(b, 1j * cb, 0j, 1j * co)
    else:
        w3 = float(an.links[_link_of(mech, crank, coupler)].omega)
        w4 = float(an.links[_link_of(mech, rocker_pivot, coupler)].omega)
        k = lay.per_mm
        c = _meet(b - w3**2 * cb / k, 1j * cb, -w4**2 * co / k, 1j * co)
    out = {crank: b, coupler: c}
    for lid, base, q in ((_link_of(mech, crank, coupler), b, c),
                         (_link_of(mech, rocker_pivot, coupler), 0j, c)):
        pts = mech.links[lid].points
        p0 = crank if base == b else rocker_pivot
        for n in pts:
            if n not in out and n not in mech.helper_points:
                out[n] = base + (q - base) * (pos[n] - pos[p0]) / (pos[coupler] - pos[p0])
    return {n: np.array([(pole + z).real, (pole + z).imag]) for n, z in out.items()}


def _link_of(mech: Any, p: str, q: str) -> str:
    return next(lid for lid, link in mech.links.items()
                if lid != "1" and p in link.points and q in link.points)


def _mark(sol: Any, lay: Any, photo: np.ndarray, diag: Diagnoser) -> Report:
    read = read_sheet(sol, Page("photo", photo), diag, lay.digest)
    return mark_scan(sol, read, "photo", CheckTolerance(), diag)


def _check_follows(rep: Report, images: dict[str, np.ndarray], exact: dict[str, np.ndarray],
                   root: str, letter: str) -> None:
    got = {r.key: (r.verdict, r.code) for r in rep.rows}
    assert got.pop(f"{letter}_{root}")[0] == WRONG, rep.text()
    for n, p in images.items():
        if n == root or f"{letter}_{n}" not in got:
            continue
        moved = float(np.hypot(*(p - exact[n])))
        v, code = got[f"{letter}_{n}"]
        if moved > 2.0:     # well beyond 0.5 mm and the reading's error: not right
            assert (v, code) == (FOLLOWS, f"follows:{letter}_{root}"), (n, rep.text())
        else:               # near its right place: right, following, or no mistake named
            assert v in (OK, FOLLOWS) or code == "unexplained", (n, rep.text())


@pytest.mark.parametrize("diagram,factor,turn,level", [
    ("velocity", 1.0, 6.0, "phone"), ("acceleration", 0.92, 0.0, "mild")])
def test_later_images_drawn_from_a_wrong_crank_image_follow(diagram: str, factor: float,
                                                            turn: float, level: str) -> None:
    # Examples 3.1 / 4.2: b drawn wrong, c from it (c = meet of ⊥CB through b and ⊥CD
    # through the pole), e on link 3 and f on link 4 by similarity
    sol = graphkin.examples.fourbar().solve()
    lay = layout_for(sol, diagram, "fourbar")
    exact = exact_images(sol, lay)
    pole = np.array(lay.pole)
    t = np.radians(turn)
    rot = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    b = pole + factor * rot @ (exact["B"] - pole)
    images = {n: p for n, p in _carried(sol, lay, diagram, "B", "D", "C", b).items()
              if n in exact}
    diag = Diagnoser(Evaluator(sol))
    rep = _mark(sol, lay, hand_photo(sol, lay, sheet_pixels(sol, lay), images, level, seed=23),
                diag)
    _check_follows(rep, images, exact, "B", diagram[0].upper())
    assert "(in V_B)" in rep.summary() or "(in A_B)" in rep.summary(), rep.text()


def _separated(images: dict[str, np.ndarray], pole: np.ndarray) -> bool:
    pts = list(images.values())
    return all(np.hypot(*(p - pole)) >= 12.0 for p in pts) and all(
        np.hypot(*(p - q)) >= 6.0 for i, p in enumerate(pts) for q in pts[i + 1:])


# the layout's assumptions (inside the box, images apart) leave few random four-bars
@settings(max_examples=3, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate],
          suppress_health_check=[HealthCheck.filter_too_much, HealthCheck.too_slow])
@given(rm=fourbars(other_rates=False), seed=st.integers(0, 2**16),
       factor=st.sampled_from([0.9, 1.1, 1.12, 0.88]),
       diagram=st.sampled_from(["velocity", "acceleration"]))
def test_random_four_bars_follow_through_from_a_wrong_crank_image(
        rm: Any, seed: int, factor: float, diagram: str) -> None:
    """Crank-driven four-bars (O2-A crank, A-B-E coupler, O4-B-F rocker): a drawn 10-12 %
    too long or short, b, e, f constructed from it: a wrong, the rest following, whenever a
    is read where it was drawn."""
    sol = rm.mechanism().solve()
    lay = layout_for(sol, diagram, rm.kind)
    exact = exact_images(sol, lay)
    pole = np.array(lay.pole)
    assume(set(exact) >= {"A", "B"})
    images = _carried(sol, lay, diagram, "A", "O4", "B",
                      pole + factor * (exact["A"] - pole))
    images = {n: p for n, p in images.items() if n in exact}
    box = lay.polygon_box
    assume(all(box[0] + 5 < p[0] < box[2] - 5 and box[1] + 5 < p[1] < box[3] - 5
               for p in images.values()))
    assume(_separated(images, pole) and _separated(exact, pole) and not _thin(images, pole)
           and not _in_band(images))
    diag = Diagnoser(Evaluator(sol))
    photo = hand_photo(sol, lay, sheet_pixels(sol, lay), images, "mild", seed)
    read = read_sheet(sol, Page("photo", photo), diag, lay.digest)
    rep = mark_scan(sol, read, "photo", CheckTolerance(), diag)
    # a wrong length is near none of the places a can be, only within reach of its exact
    # one: when another line end there is taken for it (the reading rate of the follows
    # case in docs/checking.md), where the rest are looked for is not where they were drawn
    assume("A" in read.points and np.hypot(*(read.points["A"] - images["A"])) < 0.5)
    # a 10 % wrong crank image is only 1-2 mm wrong when the crank's image is short; an
    # image read within 2 mm of its right place may be only misread, so nothing is marked
    # as following from it (scan.mark._untold): the follow-through needs a well off it
    assume(np.hypot(*(read.points["A"] - exact["A"])) >= 2.0)
    _check_follows(rep, images, exact, "A", diagram[0].upper())


def _in_band(images: dict[str, np.ndarray]) -> bool:
    """An image within 2 mm of the line between two others: in a band of merged strokes.

    Its arrowhead lies in the band's ink; the reading of such images is the
    benchmark's to measure (docs/scan-reading.md, "an image in the middle of
    a straight band"), not this follow-through test's.  One such photo is
    pinned as a strict xfail below.
    """
    pts = list(images.values())
    for k, e in enumerate(pts):
        others = pts[:k] + pts[k + 1:]
        for i, a in enumerate(others):
            for b in others[i + 1:]:
                ab = b - a
                t = float((e - a) @ ab) / float(ab @ ab)
                if 0.0 < t < 1.0 and float(np.hypot(*(a + t * ab - e))) < 2.0:
                    return True
    return False


def _thin(images: dict[str, np.ndarray], pole: np.ndarray) -> bool:
    """Two images within 8 mm of each other, or within 6° of each other seen from the pole."""
    pts = list(images.values())
    ang = [np.arctan2(*(p - pole)[::-1]) for p in pts]
    return any(np.hypot(*(p - q)) < 8.0 or abs((a - b + np.pi) % (2 * np.pi) - np.pi) < 0.105
               for i, (p, a) in enumerate(zip(pts, ang)) for q, b in zip(pts[i + 1:], ang[i + 1:]))


@settings(max_examples=3, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(rm=st.one_of(fourbars(), slider_cranks()), seed=st.integers(0, 2**16),
       diagram=st.sampled_from(["velocity", "acceleration"]))
def test_thin_polygons_no_vertex_twice_and_no_mistake_named(rm: Any, seed: int,
                                                             diagram: str) -> None:
    """Images close together or nearly in line with the pole, drawn right: no two names are
    read at one vertex (unless their images coincide), and no usual mistake is named."""
    sol = rm.mechanism().solve()
    lay = layout_for(sol, diagram, rm.kind)
    pole = np.array(lay.pole)
    images = {n: p for n, p in exact_images(sol, lay).items() if np.hypot(*(p - pole)) >= 7.0}
    assume(len(images) >= 2 and _thin(images, pole))
    diag = Diagnoser(Evaluator(sol))
    photo = hand_photo(sol, lay, sheet_pixels(sol, lay), images, "mild", seed)
    read = read_sheet(sol, Page("photo", photo), diag, lay.digest)
    got = list(read.points.items())
    for i, (a, pa) in enumerate(got):
        for b, pb in got[i + 1:]:
            assert np.hypot(*(pa - pb)) >= 2.5 or np.hypot(*(images[a] - images[b])) < 2.5
    rep = mark_scan(sol, read, "photo", CheckTolerance(), diag)
    assert all(r.code in ("", "unexplained", "not-found") for r in rep.rows), rep.text()


@settings(max_examples=3, deadline=None, phases=[Phase.explicit, Phase.reuse, Phase.generate])
@given(rm=st.one_of(fourbars(), slider_cranks()), seed=st.integers(0, 2**16),
       diagram=st.sampled_from(["velocity", "acceleration"]),
       level=st.sampled_from(["scan", "mild", "phone"]))
def test_random_reversed_polygons_are_never_right(rm: Any, seed: int, diagram: str,
                                                  level: str) -> None:
    """The polygon turned 180° about the pole (the input's ω taken the wrong way, Sec. 3.4):
    no image is marked right, and no mistake but the reversed sense is named (an image
    misread is "no usual mistake explains it"; the others follow from the first)."""
    sol = rm.mechanism().solve()
    lay = layout_for(sol, diagram, rm.kind)
    pole = np.array(lay.pole)
    images = exact_images(sol, lay)
    assume(images and _separated(images, pole))
    diag = Diagnoser(Evaluator(sol))
    drawn = {n: 2 * pole - p for n, p in images.items()}
    rep = _mark(sol, lay, hand_photo(sol, lay, sheet_pixels(sol, lay), drawn, level, seed), diag)
    assert not any(r.verdict == OK for r in rep.rows), rep.text()
    codes = {r.code for r in rep.rows}
    assert all(c in ("sense", "unexplained", "not-found") or c.startswith("follows:")
               for c in codes), rep.text()
    assert "sense" in codes or not any(c.startswith("follows:") for c in codes), rep.text()


# the four-bar Hypothesis drew for the follow-through test above on 28 Nov 2026 (photo seed
# 15608, mild): a drawn 12 % short, b and e constructed from it; e lies 1.4 mm off the
# line a b, its arrowhead in that line's ink
_BAND_FOURBAR = {
    "title": "random fourbar", "units": {"length": "ft"},
    "links": {"1": {"O2": [25.454107373309824, 8.241001583416223],
                    "O4": [86.9043011242092, 133.13451359319856]},
              "2": {"A": [55.47902084982768, -2.392218652706415],
                    "O2": [32.390385263469945, -2.392218652706415]},
              "3": {"A": [1.058955029021277, -11.000358463323517],
                    "B": [-62.55067876336092, 21.425688622112652],
                    "E": [-20.8704805180145, 1.902018920652364]},
              "4": {"B": [4.732880473623551, -15.800251363760204],
                    "O4": [-57.62968343771533, -18.27961364893916]}},
    "drive": {"link": 2, "angle": 0.0, "omega": "9.676515482197129 rad/s ccw", "alpha": 0.0},
    "assembly": {"A": [48.54274295966756, 8.241001583416223],
                 "B": [55.29597546686867, 79.31862036381416],
                 "E": [52.47356533484029, 33.37902300565568]}}


@pytest.mark.xfail(strict=True, reason="an image whose arrowhead lies in the band of its "
                   "link's line is read where the vector crosses the band (28 Nov 2026)")
def test_an_image_in_the_band_of_its_links_line_follows() -> None:
    sol = from_dict(_BAND_FOURBAR).solve()
    lay = layout_for(sol, "velocity", "fourbar")
    exact = exact_images(sol, lay)
    pole = np.array(lay.pole)
    images = _carried(sol, lay, "velocity", "A", "O4", "B", pole + 0.88 * (exact["A"] - pole))
    images = {n: p for n, p in images.items() if n in exact}
    assert _in_band(images)
    diag = Diagnoser(Evaluator(sol))
    photo = hand_photo(sol, lay, sheet_pixels(sol, lay), images, "mild", 15608)
    read = read_sheet(sol, Page("photo", photo), diag, lay.digest)
    rep = mark_scan(sol, read, "photo", CheckTolerance(), diag)
    assert float(np.hypot(*(read.points["A"] - images["A"]))) < 0.5
    _check_follows(rep, images, exact, "A", "V")
