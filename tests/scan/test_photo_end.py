"""The photo end of ``check --scan``: the perspective undone, the blur measured, the paper's light.

Each expected value comes from the test's own photo, not from the reader:
the perspective ``photos.photograph`` applied (its matrix, taken as it is
made), the blur it applied (σ px of the photo over the photo's px per mm at
the markers), and a blank page of known grey and noise (Uicker, Pennock &
Shigley, 5th ed., Sec. 3.4: the polygon is read in the sheet's millimetres, so
the sheet must be where the markers say).
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
from scan.photos import Degradation, layout_for, sheet_pixels  # noqa: E402

import graphkin  # noqa: E402
from graphkin.errors import InputError  # noqa: E402
from graphkin.scan.sheet import PX_PER_MM, Page, _edge_corners, homography, rectify  # noqa: E402
from graphkin.scan.strokes import pencil, segments  # noqa: E402

_SHEET: dict[str, Any] = {}


def _sheet() -> tuple[Any, np.ndarray]:
    """The textbook four-bar's velocity worksheet (Example 3.1) and its printed pixels."""
    if not _SHEET:
        sol = graphkin.examples.fourbar().solve()
        lay = layout_for(sol, "velocity", "fourbar")
        _SHEET["v"] = (lay, sheet_pixels(sol, lay))
    return _SHEET["v"]


def _photo(img: np.ndarray, deg: Degradation, seed: int) -> tuple[np.ndarray, np.ndarray]:
    """The photo and the perspective matrix (printed px -> photo px) it was taken with."""
    taken: list[np.ndarray] = []
    real = cv2.getPerspectiveTransform

    def keep(a: Any, b: Any, *more: Any) -> Any:
        taken.append(real(a, b, *more))
        return taken[-1]

    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(photos.cv2, "getPerspectiveTransform", keep)
        photo = photos.photograph(img, deg, np.random.default_rng(seed))
    return photo, taken[-1]


_DEGRADATIONS = st.builds(
    Degradation, tilt=st.floats(0.0, 0.12), turn_deg=st.floats(0.0, 25.0),
    light=st.floats(0.45, 1.0), blur=st.floats(0.5, 2.2), noise=st.floats(2.0, 9.0),
    jpeg=st.integers(55, 92), width=st.integers(1400, 1800))


@settings(max_examples=12, deadline=None)
@given(deg=_DEGRADATIONS, seed=st.integers(0, 2**16))
def test_the_sheet_is_where_the_photo_put_it(deg: Degradation, seed: int) -> None:
    # Over the polygon area, the homography read from the markers puts every point within
    # 0.05 mm of where the photo's own perspective put it (a quarter of a rectified pixel;
    # a corner detector on the blurred corners was 0.1-0.3 mm off at the harsh level, which
    # is 2-3 % of a 10 mm vector).  And the blur measured across the markers' edges is the
    # photo's σ over its px per mm, with the print's and the resampling's own blur
    # (pixels of 1/6 and 1/5 mm, σ about 0.1 mm) added in quadrature, within 0.06 mm.
    lay, img = _sheet()
    photo, M = _photo(img, deg, seed)
    H, (diagram, paper, _), _, _, blur = homography(Page("photo", photo))
    assert (diagram, paper) == ("velocity", "a4")
    w, h = lay.size
    x0, y0, x1, y1 = lay.polygon_box
    gx, gy = np.meshgrid(np.linspace(x0, x1, 7), np.linspace(y0, y1, 7))
    mm = np.stack([gx.ravel(), gy.ravel()], axis=1)
    printed = np.stack([mm[:, 0] * photos.PX - 0.5, (h - mm[:, 1]) * photos.PX - 0.5], axis=1)
    in_photo = cv2.perspectiveTransform(printed.reshape(-1, 1, 2), M)
    got = cv2.perspectiveTransform(in_photo, H).reshape(-1, 2)
    got_mm = np.stack([(got[:, 0] + 0.5) / PX_PER_MM, h - (got[:, 1] + 0.5) / PX_PER_MM], 1)
    assert float(np.max(np.hypot(*(got_mm - mm).T))) < 0.05
    # the photo's px per mm at the top-left marker: the perspective's scale there
    m = np.array([[15.0, h - 15.0], [16.0, h - 15.0], [15.0, h - 16.0]])
    q = cv2.perspectiveTransform(np.stack([m[:, 0] * photos.PX, (h - m[:, 1]) * photos.PX],
                                          1).reshape(-1, 1, 2), M).reshape(-1, 2)
    a, b = q[1] - q[0], q[2] - q[0]
    per_mm = math.sqrt(abs(float(a[0] * b[1] - a[1] * b[0])))
    expect = math.hypot(deg.blur / per_mm, 0.1)
    assert abs(blur - expect) < 0.06


def test_two_opposite_corner_markers_and_the_top_one_are_enough() -> None:
    # the top right and bottom left markers cut off by the frame (painted over here): the
    # three left span a fifth of the sheet and fix its perspective; the two top corners and
    # the top one, in a line, do not
    lay, img = _sheet()
    w, h = lay.size

    def without(*which: tuple[float, float]) -> np.ndarray:
        out = img.copy()
        for mx, my in which:            # the marker's lower left corner, mm
            a = (int((mx - 2) * photos.PX), int((h - my - 20) * photos.PX))
            b = (int((mx + 20) * photos.PX), int((h - my + 2) * photos.PX))
            cv2.rectangle(out, a, b, 255, -1)
        return out

    deg = Degradation(0.06, 12.0, 0.7, 1.2, 4.0, 85, 1600)
    photo, M = _photo(without((w - 28.0, h - 28.0), (10.0, 10.0)), deg, 7)
    H, _, found, _, _ = homography(Page("photo", photo))
    assert len(found) == 3
    p = np.array([[lay.pole[0] * photos.PX - 0.5, (h - lay.pole[1]) * photos.PX - 0.5]])
    got = cv2.perspectiveTransform(cv2.perspectiveTransform(p.reshape(-1, 1, 2), M), H)
    pole = np.array([(got[0, 0, 0] + 0.5) / PX_PER_MM, h - (got[0, 0, 1] + 0.5) / PX_PER_MM])
    assert float(np.hypot(*(pole - np.array(lay.pole)))) < 0.1
    photo, _ = _photo(without((10.0, 10.0), (w - 28.0, 10.0)), deg, 7)
    with pytest.raises(InputError, match="found 2 of the worksheet's 4 corner markers"):
        homography(Page("photo", photo))


@settings(max_examples=10, deadline=None)
@given(noise=st.floats(2.0, 9.0), seed=st.integers(0, 999))
def test_the_paper_is_the_mean_of_a_dim_noisy_page(noise: float, seed: int) -> None:
    # A blank page of grey 90 (light fallen to 35 %) with noise σ 2-9 (2-10 % of it): its
    # brightness is the mean of its pixels, so half of them are brighter (the ratio clipped
    # at 1), where the brightest grey near each (a closing) left 1-3 %; and nothing on it
    # is pencil.
    rng = np.random.default_rng(seed)
    page = np.clip(90.0 + rng.normal(0.0, noise, (200, 300)), 0, 255).astype(np.uint8)
    ratio = pencil(page, np.zeros(page.shape, bool), (0, 0, 300, 200))
    inner = ratio[10:-10, 10:-10]
    assert 0.35 < float(np.mean(inner >= 1.0)) < 0.65
    assert len(segments(ratio, (0, 0), 40.0)) == 0


def _rectified_noise(photo: np.ndarray, lay: Any) -> tuple[float, np.ndarray]:
    """The paper's relative noise in a blank patch of the rectified polygon area, and the
    top-left marker's corners found on the rectified sheet (px)."""
    rect = rectify(Page("photo", photo))
    w, h = lay.size
    x0, _, _, y1 = lay.polygon_box
    r0, c0 = int((h - y1) * PX_PER_MM) + 20, int(x0 * PX_PER_MM) + 20
    patch = rect.gray[r0:r0 + 100, c0:c0 + 100].astype(float)
    high = patch - cv2.GaussianBlur(patch, (0, 0), 5)
    m, s = 10.0, 18.0          # the top-left marker: lower left corner (10, h - 28) mm
    sheet = [(m, h - m), (m + s, h - m), (m + s, h - m - s), (m, h - m - s)]
    want = np.array([(x * PX_PER_MM - 0.5, (h - y) * PX_PER_MM - 0.5) for x, y in sheet])
    got, _ = _edge_corners(rect.gray, want + 1.0)
    return float(high.std() / patch.mean()), got - want


def test_a_fine_photo_is_shrunk_by_area_before_the_warp() -> None:
    # A 4000 px photo has 2.2 times the pixels a millimetre of an 1800 px one; with the same
    # blur on the sheet and the same noise a pixel, each rectified pixel is the mean of about
    # 2.2 x 2.2 of its pixels, so its paper's noise is about 1/2.2 of the other's (sampled
    # bilinearly, four pixels, it was the same).  The sheet stays where it was: the
    # top-left marker's corners on the rectified sheet within 0.05 mm of their place.
    lay, img = _sheet()
    noise = {}
    for width in (1800, 4000):
        deg = Degradation(0.06, 8.0, 0.7, 1.5 * width / 1800, 9.0, 90, width)
        photo, _ = _photo(img, deg, 11)
        noise[width], off = _rectified_noise(photo, lay)
        assert float(np.max(np.hypot(*off.T))) < 0.05 * PX_PER_MM
    assert noise[4000] < 0.6 * noise[1800]
