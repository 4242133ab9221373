"""A link's tip run on past the vector from the pole to its image, cut back to that vector.

Every vector of a velocity or acceleration polygon starts at the pole
(Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), and the places where each
image can be are known from the expected figure, so the line each short
vector lies on is known even where its ink yields no pencil segment: where
it runs under the printed pole and its label (masked as print), or the
pole's dot and the arrowhead take it.  A link's line drawn to such an image
(Sec. 3.5) then runs on past it over a barb of the image's own arrowhead, or
on to another stroke near it, and the detector's tip is taken for the image
(:mod:`graphkin.scan.read`).  :func:`pole_ray_cuts` cuts such a tip back to
the ray from the pole, before :func:`graphkin.scan.crossings.past_crossings`
cuts tips carried over paper to a letter.
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.scan import need_cv2
from graphkin.scan.inkfit import _CROSS_SIN, _FLOOR, _PAPER_MM, Sheet, ink_along
from graphkin.scan.strokes import _GROW

__all__ = ["pole_ray_cuts", "printed_sheet"]

_RAY_NEAR_MM = 12.0
"""Images nearer the pole than this (mm) are looked for on the ray from the pole to them."""
_RAY_MIN_MM = 1.0
"""A tip past a ray by less than this (mm) is left: ends scatter along their lines so far."""
_RAY_RUN_MM = 4.0
"""A tip run on past a ray farther than this (mm) is a line going on, not a barb's run-on."""
_RAY_BACK_MM = 6.0
"""Tips farther than this (mm) past a ray are not looked at (past_crossings' reach)."""
_RAY_FREE_MM = 1.0
"""The least length (mm) of a ray not masked as print on which its ink is looked for."""
_RAY_COVER = 0.7
"""The least part of that length on ink: a vector drawn from the pole along the ray."""
_RAY_END_MM = 1.5
"""Past a vector's end along its ray the ink may run this far (mm): its tip, a link's edge."""


def printed_sheet(printed: np.ndarray, box_px: tuple[int, int, int, int],
                  sheet_h_mm: float) -> Sheet:
    """The print masked in the polygon area, as a :class:`Sheet` (darkness 1 where masked).

    ``printed`` is the sheet's template ink (:func:`graphkin.scan.sheet.template_ink`),
    grown as :func:`graphkin.scan.strokes.pencil` grows it before setting it to paper.
    """
    cv2 = need_cv2()
    x0, y0, x1, y1 = box_px
    grown = cv2.dilate(np.asarray(printed[y0:y1, x0:x1], dtype=np.uint8),
                       cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (_GROW, _GROW)))
    return Sheet(1.0 - (grown > 0).astype(np.float32), (x0, y0), sheet_h_mm)


def _paper_by(dark: np.ndarray, by_mm: float, step: float) -> bool:
    """Whether paper :data:`_PAPER_MM` long starts within ``by_mm`` of a profile's start."""
    need = int(round(_PAPER_MM / step))
    for k in range(min(int(round(by_mm / step)) + 1, len(dark))):
        if not dark[k:k + need].any() and k + need <= len(dark):
            return True
    return False


def _middle_off(sheet: Sheet, a: np.ndarray, u: np.ndarray, s: np.ndarray,
                half: float) -> tuple[np.ndarray, np.ndarray]:
    """Where the pencil line's middle is across the line ``a + s·u`` (mm; + to its left).

    The darkness-weighted centre of the ink within 0.4 mm of the line, at
    each ``s`` where the line's middle is on ink (half the stroke's darkness);
    returns those ``s`` and their offsets.
    """
    n = np.array([-u[1], u[0]])
    c = np.arange(-0.4, 0.4 + 1e-9, 0.05)
    pts = a + np.outer(s, u)[:, None, :] + c[None, :, None] * n
    d = sheet.darkness(pts)
    on = d[:, len(c) // 2] >= half
    wsum = d.sum(axis=1)
    off = (d * c).sum(axis=1) / np.maximum(wsum, 1e-12)
    return s[on], off[on]


def _cut_at(sheet: Sheet, pole: np.ndarray, u: np.ndarray, far: np.ndarray, w: np.ndarray,
            x: np.ndarray, r: float, half: float, free: np.ndarray) -> np.ndarray:
    """The crossing of the ray and the link's line, each moved onto its ink's middle.

    The link's line is taken on its ink 1-4 mm before the crossing (clear of
    the barbs and of the run-on tip), the ray's on its ink not masked as
    print, held through the pole (its start); each is shifted and turned to
    the least-squares line through the middles.  Where either has under
    1 mm of ink so read, it is left as it was.
    """
    s, o = _middle_off(sheet, x, -w, np.arange(1.0, 4.0 + 1e-9, 0.1), half)
    n_w = np.array([w[1], -w[0]])                  # left of -w is right of w
    a, b = far, w
    if len(s) >= 10:
        slope, icpt = np.polyfit(s, o, 1)
        p0 = x + icpt * n_w
        d = -w + slope * n_w
        a, b = p0, d / float(np.hypot(*d))
    sr = np.arange(0.0, r - 1.5 + 1e-9, 0.1)
    keep = free[: len(sr)]
    s2, o2 = _middle_off(sheet, pole, u, sr[keep], half)
    v = u
    if len(s2) >= 10:
        c = float((s2 * o2).sum() / max(float((s2 * s2).sum()), 1e-12))
        v = u + c * np.array([-u[1], u[0]])
        v = v / float(np.hypot(*v))
    m = np.array([[b[0], -v[0]], [b[1], -v[1]]])
    if abs(float(np.linalg.det(m))) < _CROSS_SIN:
        return x
    t = np.linalg.solve(m, pole - a)
    y = pole + float(t[1]) * v
    return y if float(np.hypot(*(y - x))) < 1.0 else x


def pole_ray_cuts(segs: np.ndarray, sheet: Sheet, pole: np.ndarray,
                   places: list[np.ndarray], printed: Sheet | None = None) -> np.ndarray:
    """The segments with each tip run on past the vector from the pole to an image cut back.

    Every vector of the polygon starts at the pole (Sec. 3.4), so the line
    it lies on is known even where its ink is not found: a short vector
    (under :data:`_RAY_NEAR_MM`) gives no segment where its ink runs under
    the printed pole and its label (masked as print) or the pole's dot and
    the arrowhead take it.  A link's line drawn to that image then runs on
    over a barb of the image's own arrowhead (the barb lies 8-18° off the
    link's prolongation) or on to another stroke near it, and its tip is
    taken for the image.  Here the ray from the pole through each place an
    image can be near the pole (its exact place and its usual mistakes',
    turned as well) is a line the tip may have run on past: where a segment
    crosses it (over 8° apart) :data:`_RAY_MIN_MM` to :data:`_RAY_BACK_MM`
    before its tip, and

    - the ray from the pole to the crossing is on ink (half the stroke's
      darkness) over at least :data:`_RAY_COVER` of its length not masked as
      print, which is at least :data:`_RAY_FREE_MM` long (the vector drawn to
      the crossing);
    - past the crossing along the ray, paper at least :data:`_PAPER_MM` long
      starts within :data:`_RAY_END_MM` (the vector ends there: a vector
      crossed in its middle goes on);
    - past the crossing along the segment, its ink runs under
      :data:`_RAY_RUN_MM` (a barb) or paper parts it from the rest (another
      stroke the detector joined it to);
    - past the tip, from 1 mm on to 2 mm, the segment's own line is under a
      third on ink (the link's stroke stops at its tip: not one broken by
      the detector and going on);

    the tip is put at the crossing, with the ray and the link's line each
    moved onto the middle of its ink (:func:`_cut_at`).  Of several such
    rays the one most on ink is taken (the first of equals).  The decisions
    are on millimetres of ink at half the stroke's own darkness, none on a
    value at round-off.
    """
    out = np.array(segs, dtype=float, copy=True)
    rays: list[np.ndarray] = []
    for q in places:
        r = float(np.hypot(*(np.asarray(q, dtype=float) - pole)))
        if 1.0 < r < _RAY_NEAR_MM:
            u = (np.asarray(q, dtype=float) - pole) / r
            if not any(float(u @ v) > math.cos(math.radians(0.5)) for v in rays):
                rays.append(u)
    if not rays:
        return out
    step = 0.1
    for i, seg in enumerate(segs):
        length = float(np.hypot(*(seg[1] - seg[0])))
        if length < _RAY_RUN_MM:
            continue
        mid = seg[0] + np.outer(np.linspace(0.15, 0.85, 25), seg[1] - seg[0])
        half = 0.5 * float(np.median(sheet.darkness(mid)))
        if half <= _FLOOR:
            continue
        for k in (0, 1):
            tip, far = seg[k], seg[1 - k]
            if float(np.hypot(*(tip - pole))) > _RAY_NEAR_MM + _RAY_BACK_MM:
                continue
            w = (tip - far) / length
            best: tuple[float, np.ndarray] | None = None
            for u in rays:
                cross = float(w[0] * u[1] - w[1] * u[0])
                if abs(cross) < _CROSS_SIN:
                    continue
                # far + a·w = pole + r·u
                a_r = np.linalg.solve(np.array([[w[0], -u[0]], [w[1], -u[1]]]), pole - far)
                back, r = length - float(a_r[0]), float(a_r[1])
                if not (_RAY_MIN_MM < back < _RAY_BACK_MM and 1.0 < r < _RAY_NEAR_MM):
                    continue
                x = pole + r * u
                s = np.arange(0.0, r - 0.3 + 1e-9, step)
                dark = ink_along(sheet, pole, u, s) >= half
                free = (np.ones(len(s), bool) if printed is None
                        else printed.darkness(pole + np.outer(s, u)) < 0.5)
                if float(free.sum()) * step < _RAY_FREE_MM:
                    continue
                cover = float((dark & free).sum()) / float(free.sum())
                if cover < _RAY_COVER:
                    continue
                on = np.arange(0.0, _RAY_END_MM + _PAPER_MM + 1e-9, step)
                if not _paper_by(ink_along(sheet, x, u, on) >= half, _RAY_END_MM, step):
                    continue                     # the ray's ink goes on: crossed in its middle
                on = np.arange(0.0, back + 1e-9, step)
                if back > _RAY_RUN_MM and not _paper_by(ink_along(sheet, x, w, on) >= half,
                                                        _RAY_RUN_MM, step):
                    continue                     # the link's ink goes on past the ray
                after = np.arange(1.0, 2.0 + 1e-9, step)
                if float(np.mean(ink_along(sheet, tip, w, after) >= half)) > 1.0 / 3.0:
                    continue                     # the segment's own line goes on past its tip
                if best is None or cover > best[0]:
                    best = (cover, _cut_at(sheet, pole, u, far, w, x, r, half, free))
            if best is not None:
                out[i, k] = best[1]
    return out
