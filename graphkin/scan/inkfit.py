"""Image points refined by lines fitted to the pencil's ink along their whole length.

The reader (:mod:`graphkin.scan.read`) finds each image point where the
pencil segments it found end or cross.  Where two strokes meet at a narrow
angle (6-21°) the crossing of two short fitted segments is badly
conditioned: a line 0.1 mm off moves it 0.3-1 mm along them.  Here the
expected figure gives the lines: at an image point ``p`` the student drew
the vector from the pole and a line to each other image of the same link
(Sec. 3.5), from neighbours already read.  Each such line is fitted to the
ink of the light-flattened sheet (the reader's ``ratio`` image) along its
length (the 20 mm nearest the image), and the image is taken where the
fitted lines and the ink's ends along them agree best:

1. **The band.**  The sheet is sampled across the hypothesised line (±1.2 mm)
   every 0.2 mm along it, leaving out the cross-sections where another
   expected stroke's ink merges with this one's (a stroke within 0.8 mm and
   not on it: the other lines through each end, the arrowhead's barbs at
   ``p``): there the ink is shared and would pull the line toward the other.
   In each cross-section the pencil line nearest the hypothesised one (its
   darkest sample within 0.7 mm) gives the line's middle there (the
   darkness-weighted centre of the ink within 0.45 mm of it), when it is
   dark enough and no wider than a pencil line (a letter, a crossing stroke
   or a smudge is wider).
2. **The line.**  A straight line is fitted to those middles, weighted by
   their darkness, robustly (middles farther than 3 robust σ and 0.15 mm
   from it are dropped, in turn), within 20 mm of the middle nearest ``p``
   (the hand's wobble wanders: far ink does not predict the line at ``p``);
   the vector from the pole is held through the pole.  The band is then
   centred on the new line and the fit repeated.  Its uncertainty across
   itself at ``p`` is that of the fit, with the wobble counted as one
   independent sample every 2 mm, and its wander from the last middle fitted
   to ``p``.  A line whose ink covers under 60 % of what is left of it, or
   under 5 mm (3 mm for the vector held through the pole: the pole is its
   other point), or that is fitted no better than 0.15 mm (σ), is not used.
   A line that shares its ink with another expected stroke under 2° from it
   passing ``p`` within 0.8 mm (not one of ``p``'s own lines) is known
   across only to 0.4 mm: the two are one band, its middle between them.
3. **The end.**  Along each fitted line the ink is walked outward from inside
   the stroke to where its darkness falls through half of the stroke's own
   (the stroke's tip, as :mod:`graphkin.scan.strokes` reads it); the image is
   taken half a pencil line's width inside it, or more where the walk runs
   on over another expected stroke's ink (a line going on through ``p``);
   an end run on more than 1.5 mm is not used, nor is one where the walk
   is still on ink when it stops (:data:`MOVE_MAX_MM` and 1.5 mm past
   ``p``: no end found).  A line going on through ``p`` is also looked for
   with this image's other lines drawn to where this line passes ``p``
   (the point read may be off along it by 1-4 mm where segments meet at a
   narrow angle, and a link's line nearly straight on from the vector
   then lies on the walk only from there).  A walk that stepped over paper
   onto another line crossing it, and ended on that line's far side (an
   image about 1 mm beside another line of the polygon), ends before the
   paper; one that ends on such a line's ink with no paper between gives
   no end (:func:`_band_gap_cut`).
4. **The point.**  Each line holds the image across itself (σ from its
   fit), each end along its line (σ 0.3 mm: ends overshot or stopped short
   by up to 0.4 mm); an end farther from the lines' crossing than the two
   can differ by (2.5 σ) is left out, and where every end found is, the
   lines are not the ones drawn: nothing is decided (a lone end past the
   crossing taken as run on over other ink, and left out, read a sample
   drawn afresh worse: docs/checking.md).  Lines well apart fix the point
   by their crossing; along lines nearly parallel, the ends decide.

The point so found replaces the one read only when it is well determined
(σ under :data:`SIGMA_MAX_MM` in every direction, or under
:data:`LOOSE_SIGMA_MAX_MM` where the point read lies more than 2 σ off it
along its vector from the pole: :func:`read_off`) and within
:data:`MOVE_MAX_MM` of it; one moved farther than the drawing tolerance is
said so in a note.  Measured in docs/checking.md ("How well it reads") and
docs/scan-reading.md.

Before the image points are read, :func:`graphkin.scan.crossings.past_crossings` cuts back a
segment's tip that the detector carried over paper, past a line it
crosses, to the student's letter written straight on along it.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the polygon: straight vectors
from the pole to each image point), Sec. 3.5 (the images of a link's points
joined: the velocity image).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.scan import need_cv2
from graphkin.scan.sheet import PX_PER_MM

__all__ = ["FitLine", "Refined", "Sheet", "fit_line", "ink_along", "ink_end",
           "refine_point", "refine_points", "refine_read", "read_off",
           "SIGMA_MAX_MM", "LOOSE_SIGMA_MAX_MM", "MOVE_MAX_MM"]

SIGMA_MAX_MM = 0.35
"""A refined point is used only when known to this (σ, mm) in every direction."""
MOVE_MAX_MM = 4.5
"""A refined point farther than this from the one read is not used (another vertex).

Three strokes meeting at 5-11° have their segments cross up to 4 mm short of the
image (docs/checking.md); images are at least 5 mm apart where they can be read."""
_BAND_MM = 1.2
"""Half the band sampled across a hypothesised line (mm)."""
_STEP_MM = 0.2
"""Cross-sections every this far along the line, samples every half of it across."""
_HALF_MM = 0.3
"""Half a pencil line's width (to half its darkness), blurred by the photo."""
_WIDE_MM = 0.25
"""A cross-section whose ink spreads wider than this (σ, mm) is not one pencil line."""
_SEEK_MM = 0.7
"""The pencil line is looked for this far (mm) either side of the line hypothesised."""
_WINDOW_MM = 0.45
"""Its middle is the darkness-weighted centre of the ink this far either side of its darkest."""
_MERGE_MM = 0.8
"""Another stroke nearer than this (mm) to a cross-section's centre merges with its ink."""
_SAME_SIN = math.sin(math.radians(2.0))
"""Another stroke within 2° of the line and on it is the same ink (drawn twice)."""
_OWN_END_MM = 1.5
"""A stroke ending this near (mm) the point read is one of that image's own lines."""
_FLOOR = 0.04
"""Darkness below this (paper's noise after the light is flattened) counts as none."""
_CLEAR_MM = 2.5
"""The stretch at each end of a line left out of its fit (other strokes join there)."""
_ARROW_MM = 3.5
"""The stretch before an image left out of the fit of its vector from the pole (barbs)."""
_WOBBLE_MM = 2.0
"""The hand's wobble: one independent sample of a line's middle every this far."""
_LOCAL_MM = 20.0
"""A line is fitted to its ink within this far (mm) of the ink nearest its end."""
_WALK_MM = 0.04
"""The hand's wobble wanders by about this (σ, mm) every :data:`_WOBBLE_MM`."""
_SIGMA_FLOOR_MM = 0.04
"""A fitted line is not trusted to better than this across itself (σ, mm)."""
_LINE_SIGMA_MAX_MM = 0.15
"""A line fitted no better than this across (σ, mm) shares its band with other ink: unused."""
_SIGMA_END_MM = 0.3
"""How far (σ, mm) a stroke's end is from its image point along its line."""
_COVER_MAX_MM = 1.5
"""An end run on over another stroke's ink farther than this is not used."""
_MIN_COVER = 0.6
_MIN_INK_MM = 5.0
_MIN_HELD_MM = 3.0
"""The least ink (mm) of a vector held through the pole: the pole is its other point."""
_BARB_DEG = (15.0, 20.0, 25.0)
_BARB_MM = 3.0
_CROSSED_MM = 20.0
"""A line at least this long is one a stroke may end on (shorter: pieces, letters, barbs)."""
_CROSS_SIN = math.sin(math.radians(8.0))
"""Lines under 8° apart are not looked at as crossing (their ink is one)."""
_LETTER_MM = 3.0
"""Ink beyond a stretch of paper past a crossing, shorter than this, is a letter or a barb."""
_PAPER_MM = 0.5
"""A stretch of paper at least this long along a stroke's line parts two inks."""
_LIFT_MM = 3.0
"""A pencil lifted leaves paper under this along a stroke (as :mod:`strokes` joins pieces)."""
_BAND_PAPER_MM = 0.2
"""Paper at least this long between a stroke's tip and a line past it parts them (a dip of
the blurred ink under half its darkness over less is a saddle between the two inks)."""
_TOLD_MM = 0.5
"""A point moved farther than this (the default drawing tolerance) is said so in a note."""
_SPREAD_SIN = math.sin(math.radians(3.0))
"""Lines under 3° apart are one direction: the ends decide along it."""
LOOSE_SIGMA_MAX_MM = 0.6
"""A refined point known only to this (σ, mm) is used where the point read lies far off it."""
_OFF_SIGMAS = 2.0
"""The point read lies off a refined point by more than this many σ (its Mahalanobis distance)."""
_ON_RAY_MM = 0.15
"""A point read this near (mm) the vector from the pole through the refined point lies on it."""


@dataclass(frozen=True)
class FitLine:
    """A line fitted to the ink: ``point + t·direction``, sheet mm.

    Attributes
    ----------
    point : ndarray
        The line's point nearest the image point it ends at.
    direction : ndarray
        Unit vector, pointing toward the image point (from its neighbour).
    sigma : float
        Uncertainty across the line at ``point`` (σ, mm).
    ink_mm : float
        Length of the line along which one pencil line was found.
    darkness : float
        The stroke's darkness (1 - ratio), the median along its middle.
    """

    point: np.ndarray
    direction: np.ndarray
    sigma: float
    ink_mm: float
    darkness: float


@dataclass(frozen=True)
class Refined:
    """An image point refined from its lines' ink (sheet mm) and its covariance (mm²)."""

    point: np.ndarray
    cov: np.ndarray
    lines: int
    ends: int

    @property
    def sigma(self) -> float:
        """The largest σ of the point (mm)."""
        return float(math.sqrt(max(float(np.linalg.eigvalsh(self.cov)[-1]), 0.0)))


class Sheet:
    """The reader's ``ratio`` image (1.0 paper) sampled in sheet mm (y up)."""

    def __init__(self, ratio: np.ndarray, origin_px: tuple[int, int], sheet_h_mm: float):
        self.ratio = np.ascontiguousarray(ratio, dtype=np.float32)
        self.x0, self.y0 = origin_px
        self.h = sheet_h_mm

    def darkness(self, pts: np.ndarray) -> np.ndarray:
        """Darkness (1 - ratio, ≥ 0) at points (…, 2) in sheet mm, bilinear; paper outside."""
        cv2 = need_cv2()
        pts = np.asarray(pts, dtype=float)
        shape = pts.shape[:-1]
        flat = pts.reshape(-1, 2)
        mx = (flat[:, 0] * PX_PER_MM - self.x0 - 0.5).astype(np.float32).reshape(-1, 1)
        my = ((self.h - flat[:, 1]) * PX_PER_MM - self.y0 - 0.5).astype(np.float32).reshape(-1, 1)
        r = cv2.remap(self.ratio, mx, my, cv2.INTER_LINEAR, borderMode=cv2.BORDER_CONSTANT,
                      borderValue=1.0)
        return np.clip(1.0 - np.asarray(r, dtype=float).reshape(shape), 0.0, None)


def _seg_dist(pts: np.ndarray, a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Distance of points (n, 2) from segment a-b."""
    d = b - a
    L2 = float(d @ d)
    if L2 == 0.0:
        return np.asarray(np.hypot(*(pts - a).T))
    t = np.clip((pts - a) @ d / L2, 0.0, 1.0)
    return np.asarray(np.hypot(*(pts - a - np.outer(t, d)).T))


def fit_line(sheet: Sheet, start: np.ndarray, end: np.ndarray, others: list[np.ndarray],
             clear_start: float = _CLEAR_MM, clear_end: float = _CLEAR_MM,
             through: np.ndarray | None = None) -> FitLine | None:
    """The pencil line drawn from about ``start`` to about ``end``, fitted to its ink (mm).

    ``others``: the other strokes expected on the sheet (segments (2, 2),
    mm); the stretches of the band they cross are left out.  ``clear_start``,
    ``clear_end``: the stretches at the ends left out.  ``through``: a point
    the line is known to start from (the pole), held to within 0.1 mm.
    Returns None when the ink does not show one line there (see the module).
    """
    length = float(np.hypot(*(end - start)))
    least = _MIN_INK_MM if through is None else _MIN_HELD_MM
    if length < clear_start + clear_end + least:
        return None
    u = (end - start) / length
    t = np.arange(clear_start, length - clear_end + 1e-9, _STEP_MM)
    s = np.arange(-_BAND_MM, _BAND_MM + 1e-9, _STEP_MM / 2)
    line_p, line_u = start.astype(float), u
    fit: tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray] | None = None
    for _ in range(3):
        nn = np.array([-line_u[1], line_u[0]])
        centres = line_p + np.outer(t, line_u)
        # the sections where another expected stroke's ink merges with this one's (nearer
        # than :data:`_MERGE_MM` but not on it: the same ink drawn twice is no harm)
        shared = np.zeros(len(t), bool)
        for a, b in others:
            e = b - a
            el = float(np.hypot(*e))
            if el == 0.0:
                continue
            dist = _seg_dist(centres, a, b)
            same = abs(float(line_u[0] * e[1] - line_u[1] * e[0])) / el < _SAME_SIN
            shared |= (dist < _MERGE_MM) & ~(same & (dist < _HALF_MM))
        grid = centres[:, None, :] + s[None, :, None] * nn[None, None, :]
        dark = np.clip(sheet.darkness(grid) - _FLOOR, 0.0, None)
        # the pencil line nearest the hypothesised one: the darkest sample within
        # :data:`_SEEK_MM` of it, and its ink within :data:`_WINDOW_MM` of that
        near = np.abs(s) <= _SEEK_MM
        k = np.argmax(np.where(near[None, :], dark, -1.0), axis=1)
        win = np.abs(s[None, :] - s[k][:, None]) <= _WINDOW_MM
        dw = np.where(win, dark, 0.0)
        mass = dw.sum(axis=1)
        peak = dark[np.arange(len(t)), k]
        with np.errstate(invalid="ignore", divide="ignore"):
            mid = (dw * s).sum(axis=1) / mass
            spread = np.sqrt((dw * (s - mid[:, None]) ** 2).sum(axis=1) / mass)
        free = ~shared
        if np.count_nonzero(free) * _STEP_MM < least:
            return None
        stroke = float(np.median(peak[free]))
        ok = (free & (peak > 0.5 * max(stroke, 2 * _FLOOR)) & (spread < _WIDE_MM)
              & np.isfinite(mid))
        covered = int(np.count_nonzero(ok)) / max(int(np.count_nonzero(free)), 1)
        if covered < _MIN_COVER or np.count_nonzero(ok) * _STEP_MM < least:
            return None
        # the hand's wobble wanders: only the ink nearest the end predicts the line there
        ok &= t >= float(t[ok].max()) - _LOCAL_MM
        if through is None and np.count_nonzero(ok) * _STEP_MM < _MIN_INK_MM:
            # the ink nearest the end is a dot or a dash: no line to fit (a line held
            # through the pole has the pole as its other point, and is fitted)
            return None
        tt, mm_, w = t[ok], mid[ok], mass[ok]
        keep = np.ones(len(tt), bool)
        for _ in range(4):
            coef = _wls(tt[keep], mm_[keep], w[keep], through, line_p, line_u)
            res = mm_ - (coef[0] + coef[1] * tt)
            mad = 1.4826 * float(np.median(np.abs(res[keep])))
            nxt = np.abs(res) <= max(3.0 * mad, 0.15)
            if np.array_equal(nxt, keep) or np.count_nonzero(nxt) < 10:
                break
            keep = nxt
        coef = _wls(tt[keep], mm_[keep], w[keep], through, line_p, line_u)
        fit = (tt[keep], mm_[keep] - (coef[0] + coef[1] * tt[keep]), w[keep], coef)
        # the new line: offset coef[0] at t = 0, slope coef[1], in the old frame
        p0 = line_p + coef[0] * nn
        p1 = line_p + length * line_u + (coef[0] + coef[1] * length) * nn
        line_u = (p1 - p0) / float(np.hypot(*(p1 - p0)))
        line_p = p0
    assert fit is not None
    tk, res, wk, coef = fit
    sig = _across_sigma(tk, res, wk, length, through is not None)
    # and the wobble's wander over the stretch from the last ink fitted to the end
    sig = math.hypot(sig, _WALK_MM * math.sqrt(max(length - float(tk.max()), 0.0) / _WOBBLE_MM))
    at = line_p + float((end - line_p) @ line_u) * line_u
    stroke_dark = float(np.median([_center_dark(sheet, line_p + x * line_u, line_u)
                                   for x in tk[:: max(len(tk) // 25, 1)]]))
    return FitLine(at, line_u, sig, float(len(tk) * _STEP_MM), stroke_dark)


def _wls(t: np.ndarray, m: np.ndarray, w: np.ndarray, through: np.ndarray | None,
         line_p: np.ndarray, line_u: np.ndarray) -> np.ndarray:
    """Weighted least squares m = a + b t; with ``through``, the line held near that point."""
    A = np.stack([np.ones_like(t), t], axis=1)
    W = w / max(float(w.sum()), 1e-12) * len(w)
    M = A.T @ (A * W[:, None])
    r = A.T @ (W * m)
    if through is not None:
        # the pole as one more middle, as good as 25 sections (held within about 0.1 mm)
        nn = np.array([-line_u[1], line_u[0]])
        tp, mp = float((through - line_p) @ line_u), float((through - line_p) @ nn)
        k = 25.0
        M = M + k * np.array([[1.0, tp], [tp, tp * tp]])
        r = r + k * mp * np.array([1.0, tp])
    return np.asarray(np.linalg.solve(M, r))


def _across_sigma(t: np.ndarray, res: np.ndarray, w: np.ndarray, at: float,
                  anchored: bool) -> float:
    """σ of the fitted line across itself at ``t = at`` (mm), the wobble's samples counted."""
    n = len(t)
    span = float(t.max() - t.min()) if n else 0.0
    n_eff = max(span / _WOBBLE_MM, 2.0)
    s2 = float((w * res**2).sum() / max(w.sum(), 1e-12)) * n / max(n - 2, 1)
    tm = float((w * t).sum() / max(w.sum(), 1e-12))
    var_t = float((w * (t - tm) ** 2).sum() / max(w.sum(), 1e-12))
    lever = (at - tm) ** 2 / max(var_t, 1e-12)
    if anchored:
        lever = min(lever, 1.0)
    sig = math.sqrt(s2 / n_eff * (1.0 + lever))
    return max(sig, _SIGMA_FLOOR_MM)


def _center_dark(sheet: Sheet, p: np.ndarray, u: np.ndarray) -> float:
    """The darkness on a line's middle at p (the best of three samples across it)."""
    n = np.array([-u[1], u[0]])
    return float(sheet.darkness(np.array([p + k * 0.1 * n for k in (-1, 0, 1)])).max())


def ink_along(sheet: Sheet, a: np.ndarray, u: np.ndarray, s: np.ndarray) -> np.ndarray:
    """Darkness on a line's middle at ``a + s·u`` (the mean of three samples 0.12 mm across)."""
    n = np.array([-u[1], u[0]])
    base = a + np.outer(s, u)
    return np.asarray(np.mean([sheet.darkness(base + k * 0.12 * n) for k in (-1, 0, 1)],
                              axis=0))


def ink_end(sheet: Sheet, line: FitLine, inside_mm: float,
            beyond_mm: float = MOVE_MAX_MM + 1.5) -> float | None:
    """Where the stroke's ink ends along a fitted line (mm from ``line.point``, + beyond).

    Walked outward from ``inside_mm`` before ``line.point`` while the
    darkness on the line's middle is at least half the stroke's (gaps under
    1 mm stepped over, and gaps under :data:`_LIFT_MM` where the ink goes on
    again before ``line.point``: the pencil lifted on the way to the point
    the segments reached), up to ``beyond_mm`` past it; the end is where it
    falls through half (interpolated).  None if the walk starts on paper.
    """
    u, p = line.direction, line.point
    s = np.arange(-inside_mm, beyond_mm + 1e-9, 0.05)
    prof = ink_along(sheet, p, u, s)
    half = 0.5 * line.darkness
    dark = prof >= half
    if not np.any(dark[: max(int(1.0 / 0.05), 1)]):
        return None
    last, ended = 0, False
    for k in range(1, len(s)):
        if dark[k]:
            last = k
        elif s[k] - s[last] > 1.0:
            again = np.flatnonzero(dark[k:])
            if (len(again) and s[k + int(again[0])] <= 0.0
                    and s[k + int(again[0])] - s[last] <= _LIFT_MM):
                continue     # the pencil lifted on its way to the point read: ink goes on
            ended = True
            break
    if not ended:
        return None          # still on ink (or in a gap) where the walk stops: no end found
    if last + 1 < len(s) and prof[last] > prof[last + 1]:
        frac = (prof[last] - half) / (prof[last] - prof[last + 1])
        return float(s[last] + min(max(frac, 0.0), 1.0) * 0.05)
    return float(s[last])


def _cover(p: np.ndarray, u: np.ndarray, others: list[np.ndarray]) -> float:
    """How far past ``p`` along ``u`` the walk stays on other expected strokes' ink (mm)."""
    s = np.arange(0.0, 4.0, 0.05)
    pts = p + np.outer(s, u)
    on = np.zeros(len(s), bool)
    for a, b in others:
        on |= _seg_dist(pts, a, b) < _HALF_MM
    if not on[0]:
        return _HALF_MM
    k = int(np.argmin(on)) if not np.all(on) else len(s) - 1
    return max(float(s[k]), _HALF_MM)


def refine_point(sheet: Sheet, p0: np.ndarray, neighbours: list[np.ndarray],
                 pole: np.ndarray | None, strokes: list[np.ndarray]) -> Refined | None:
    """The image point near ``p0`` from its lines' ink (see the module); None if undecided.

    ``neighbours``: the other ends of the lines drawn to it (mm); ``pole``:
    the pole, when its vector ends here (held as the line's start, with the
    arrowhead's barbs left out); ``strokes``: every stroke expected on the
    sheet (segments, mm), its own lines included (they are told by their ends).
    """
    rows: list[tuple[np.ndarray, float, float]] = []      # normal, offset, σ
    tips: list[tuple[np.ndarray, np.ndarray, float]] = []  # point, direction, σ
    fitted: list[FitLine] = []
    starts = ([pole] if pole is not None else []) + list(neighbours)
    own = [np.array([q, p0]) for q in starts]
    barbs = _barbs(pole, p0) if pole is not None else []
    for k, q in enumerate(starts):
        is_pole = pole is not None and k == 0
        others = [sg for sg in strokes + barbs if not _same(sg, own[k])]
        fl = fit_line(sheet, q, p0, others, clear_end=_ARROW_MM if is_pole else _CLEAR_MM,
                      through=q if is_pole else None)
        if fl is None or fl.sigma > _LINE_SIGMA_MAX_MM:
            continue
        fl = _twice_drawn(fl, p0, others)
        fitted.append(fl)
        nrm = np.array([-fl.direction[1], fl.direction[0]])
        rows.append((nrm, float(nrm @ fl.point), fl.sigma))
        end = ink_end(sheet, fl, inside_mm=min(4.0, 0.5 * float(np.hypot(*(p0 - q)))))
        if end is None:
            continue
        end = _letter_cut(sheet, fl, end, others)
        if end is None:
            continue
        end = _band_gap_cut(sheet, fl, end, others, p0)
        if end is None:
            continue
        cover = _cover(fl.point, fl.direction, others)
        # and this image's other lines drawn to where this one passes it (the point read
        # may be off along it, 1-4 mm where segments meet at a narrow angle): a line going
        # on through the image, nearly straight on, is then on the walk past it
        mine = [np.array([starts[j], fl.point]) for j in range(len(starts)) if j != k]
        if max(cover, _cover(fl.point, fl.direction, [sg for sg in others if not any(
                _same(sg, o) for o in own)] + mine)) > _COVER_MAX_MM:
            continue
        tip = fl.point + (end - cover) * fl.direction
        tips.append((tip, fl.direction, max(_SIGMA_END_MM, cover / 2)))
    if not rows:
        return None
    A = np.array([r[0] for r in rows])
    b = np.array([r[1] for r in rows])
    sig = np.array([r[2] for r in rows])
    M = (A.T / sig**2) @ A
    r = (A.T / sig**2) @ b
    spread = max((abs(float(A[i, 0] * A[j, 1] - A[i, 1] * A[j, 0]))
                  for i in range(len(A)) for j in range(i)), default=0.0)
    if spread > _SPREAD_SIN:
        cross = np.linalg.solve(M, r)
        cov = np.linalg.inv(M)
        agree = [(tp, d, sg) for tp, d, sg in tips
                 if abs(float((tp - cross) @ d)) <= 2.5 * math.sqrt(sg**2 + float(d @ cov @ d))]
        if tips and not agree:
            return None          # no end where the lines cross: a line is not the one drawn
        tips = agree
    elif len(tips) > 1:
        # one direction: the ends that agree with their median along it
        d0 = tips[0][1]
        along = np.array([float(tp @ d0) for tp, _d, _s in tips])
        med = float(np.median(along))
        tips = [t_ for t_, a in zip(tips, along, strict=True) if abs(a - med) <= 2.5 * t_[2]]
    for tp, d, sg in tips:
        M = M + np.outer(d, d) / sg**2
        r = r + d * float(d @ tp) / sg**2
    if np.linalg.cond(M) > 1e8:
        return None
    pt = np.linalg.solve(M, r)
    return Refined(np.asarray(pt), np.linalg.inv(M), len(rows), len(tips))


def _letter_cut(sheet: Sheet, fl: FitLine, end: float, others: list[np.ndarray]
                ) -> float | None:
    """The end (mm along ``fl``) put where its ink stops past a crossed line, before a letter.

    :func:`ink_end` steps over gaps under 1 mm (a pencil lifted); past a
    line the walk crosses (at least :data:`_CROSSED_MM` long, over 8°
    apart) the student's letter may lie straight on, over less paper than
    that.  As :func:`past_crossings` reads a segment's tip: where past the
    crossing the ink stops, paper follows for at least :data:`_PAPER_MM`,
    and the ink after it runs under :data:`_LETTER_MM` to the end, the end
    is where the ink stops; None where it stops on the crossed line's ink
    (the stroke's own tip is then anywhere up to that line: no end).
    """
    u, p = fl.direction, fl.point
    nrm = np.array([-u[1], u[0]])
    crossings, crossed = [], []
    for a, b in others:
        v = b - a
        ln = float(np.hypot(*v))
        if ln < _CROSSED_MM or abs(float(u[0] * v[1] - u[1] * v[0])) < _CROSS_SIN * ln:
            continue
        t = float(nrm @ (a - p)) / float(-(nrm @ v)) if abs(float(nrm @ v)) > 0 else -1.0
        at = float((a + t * v - p) @ u)
        if 0.0 <= t <= 1.0 and -1.0 < at < end - _PAPER_MM:
            crossings.append(at)
            crossed.append((a, b))
    if not crossings:
        return end
    s = np.arange(min(crossings), end + 1e-9, 0.05)
    prof = ink_along(sheet, p, u, s)
    dark = prof >= 0.5 * fl.darkness
    if not dark[0] or np.all(dark):
        return end
    stop = int(np.argmin(dark))                      # the first paper past the crossing
    again = np.flatnonzero(dark[stop:])
    if (not len(again) or float(s[stop + int(again[0])] - s[stop]) < _PAPER_MM
            or end - float(s[stop + int(again[0])]) >= _LETTER_MM):
        return end
    q = (p + float(s[stop - 1]) * u)[None, :]
    if any(float(_seg_dist(q, a, b)[0]) < 2 * _HALF_MM for a, b in crossed):
        return None
    return float(s[stop - 1])


def _band_gap_cut(sheet: Sheet, fl: FitLine, end: float, others: list[np.ndarray],
                  p0: np.ndarray) -> float | None:
    """The stroke's own end where the walk ran on onto another line's ink; None if hidden.

    :func:`ink_end` steps over gaps under 1 mm (the pencil lifted).  An image
    about 1 mm beside another line of the polygon (a coupler point beside its
    link's line, Sec. 3.5) has paper between its stroke's tip and that line:
    the walk steps over it, across the other line, and ends on its far side.
    Where the ink after the last stretch of paper (at least
    :data:`_BAND_PAPER_MM`) lies all on one other
    expected stroke crossing this one (over 8° apart, within a pencil line's
    width of it; not one of the image's own lines, which end at ``p0``), that
    ink is the other line's: the end is where the stroke's own ink stopped,
    before the paper.  With no paper between (the two inks merged by the
    blur), an end on the ink of such a line crossing the stroke past ``p0``
    (by a pencil line's width or more) tells nothing of where the stroke
    stopped under it: None.  An image on the line (a coupler point in the middle of
    its link's line) keeps its end: its walk runs on over the line's ink
    only as far as :func:`_cover` takes back.
    """
    u, p = fl.direction, fl.point
    crossing = []
    for a, b in others:
        v = b - a
        ln = float(np.hypot(*v))
        if (ln >= 1.0 and abs(float(u[0] * v[1] - u[1] * v[0])) >= _CROSS_SIN * ln
                and min(float(np.hypot(*(a - p0))), float(np.hypot(*(b - p0)))) > 1.0):
            crossing.append((a, b))
    if not crossing:
        return end
    s = np.arange(0.0, end + 1e-9, 0.05)
    if len(s) >= 4:
        dark = ink_along(sheet, p, u, s) >= 0.5 * fl.darkness
        paper = np.flatnonzero(~dark)
        if len(paper) and dark[0] and paper[-1] < len(s) - 1:
            g0 = g1 = int(paper[-1])                # the last paper before the end
            while g0 > 0 and not dark[g0 - 1]:
                g0 -= 1
            after = p + np.outer(s[g1 + 1:], u)
            if s[g1] - s[g0] + 0.05 >= _BAND_PAPER_MM and any(
                    bool(np.all(_seg_dist(after, a, b) < 2 * _HALF_MM)) for a, b in crossing):
                return float(s[g0])
    def past(a: np.ndarray, b: np.ndarray) -> float:
        # how far past p0 along the stroke the other line crosses it (mm)
        v = b - a
        q = a - np.asarray(p0, dtype=float)
        return float(q[0] * v[1] - q[1] * v[0]) / float(u[0] * v[1] - u[1] * v[0])

    tip = (p + (end - 0.1) * u)[None, :]
    if any(float(_seg_dist(tip, a, b)[0]) < 2 * _HALF_MM and past(a, b) >= 2 * _HALF_MM
           for a, b in crossing):
        return None
    return end


def _twice_drawn(fl: FitLine, p0: np.ndarray, others: list[np.ndarray]) -> FitLine:
    """The line with its σ across at least half the merging distance, when its ink is shared.

    Another expected stroke within 2° of the line passing its image within
    :data:`_MERGE_MM` (and not ending there: not one of this image's own
    lines) is counted as this line's ink by :func:`fit_line` (the same ink
    drawn twice).  But two vectors from the pole 1-2° apart, or a vector and
    a link's line running on along it, are two lines whose ink is one band
    when they are under :data:`_MERGE_MM` apart: the fitted middle lies
    between them, and the line drawn to this image may be anywhere in the
    band (Sec. 3.4: an image 0.5-0.8 mm off another's line).  Its place
    across is then known to half that distance only.
    """
    u = fl.direction
    for a, b in others:
        e = b - a
        el = float(np.hypot(*e))
        if el == 0.0 or abs(float(u[0] * e[1] - u[1] * e[0])) / el >= _SAME_SIN:
            continue
        if min(float(np.hypot(*(a - p0))), float(np.hypot(*(b - p0)))) < _OWN_END_MM:
            continue                                   # one of this image's lines
        if float(_seg_dist(fl.point[None, :], a, b)[0]) < _MERGE_MM:
            return FitLine(fl.point, fl.direction, max(fl.sigma, 0.5 * _MERGE_MM),
                           fl.ink_mm, fl.darkness)
    return fl


def _same(a: np.ndarray, b: np.ndarray) -> bool:
    """Whether two segments are one (their ends within 0.5 mm, either way round)."""
    return bool(min(np.hypot(*(a[0] - b[0])) + np.hypot(*(a[1] - b[1])),
                    np.hypot(*(a[0] - b[1])) + np.hypot(*(a[1] - b[0]))) < 0.5)


def _barbs(pole: np.ndarray, p: np.ndarray) -> list[np.ndarray]:
    """The arrowhead's barbs expected at image ``p`` of the vector from the pole (a fan)."""
    d = p - pole
    length = float(np.hypot(*d))
    if length == 0.0:
        return []
    u = -d / length
    out = []
    for deg in _BARB_DEG:
        for sgn in (1.0, -1.0):
            a = math.radians(sgn * deg)
            r = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
            out.append(np.array([p, p + _BARB_MM * (r @ u)]))
    return out


def refine_points(points: dict[str, np.ndarray], links: list[list[str]], pole: np.ndarray,
                  sheet: Sheet) -> dict[str, Refined]:
    """Each image point read refined from its lines' ink (the names refined, see the module).

    ``links``: the names of each moving link's points (their images are
    joined, Sec. 3.5).  The strokes expected are the vectors from the pole
    to the points read, the lines joining the points read of each link, and
    the arrowheads' barbs at each.
    """
    where: dict[str, list[np.ndarray]] = {n: [p] for n, p in points.items()}
    strokes: list[np.ndarray] = []
    for at in where.values():
        for p in at:
            if float(np.hypot(*(p - pole))) > 1.0:
                strokes.append(np.array([pole, p]))
    for names in links:
        for i, a in enumerate(names):
            for b_ in names[i + 1:]:
                for pa in where.get(a, []):
                    for pb in where.get(b_, []):
                        if float(np.hypot(*(pa - pb))) > 1.0:
                            strokes.append(np.array([pa, pb]))
    for n, at in where.items():
        if n in points:
            strokes += _barbs(pole, at[0])
    out: dict[str, Refined] = {}
    for name, p0 in points.items():
        nb: list[np.ndarray] = []
        for names in links:
            if name not in names:
                continue
            for m in names:
                if m == name or m not in points:
                    continue
                q = points[m]
                if float(np.hypot(*(q - p0))) < 5.0 or float(np.hypot(*(q - pole))) < 2.5:
                    continue
                if not any(float(np.hypot(*(q - x))) < 0.5 for x in nb):
                    nb.append(q)
        ref = refine_point(sheet, p0, nb, pole if float(np.hypot(*(p0 - pole))) > 5.0 else None,
                           strokes)
        if ref is not None:
            out[name] = ref
    return out


def refine_read(read: Any, sol: Any, ratio: np.ndarray, origin_px: tuple[int, int],
                sheet_h_mm: float) -> None:
    """Refine the image points of a :class:`graphkin.scan.read.SheetRead` in place.

    Each point read is replaced by the one its lines' ink gives
    (:func:`refine_points`) when that is known to :data:`SIGMA_MAX_MM` (or
    to :data:`LOOSE_SIGMA_MAX_MM` with the point read far off it along its
    vector: :func:`read_off`) and within :data:`MOVE_MAX_MM`; a point moved by more
    than the default drawing tolerance (0.5 mm, ``check --drawing``) is said
    so in a note.
    ``ratio``: the reader's light-flattened polygon area, its top-left pixel
    at ``origin_px`` of the rectified sheet, ``sheet_h_mm`` high.
    """
    mech = sol.mechanism
    links = [[n for n in link.points if n not in mech.helper_points]
             for lid, link in mech.links.items() if lid != "1"]
    pole = np.array(read.layout.pole, dtype=float)
    found = refine_points(read.points, links, pole, Sheet(ratio, origin_px, sheet_h_mm))
    for name in sorted(found):
        ref, p0 = found[name], read.points[name]
        move = float(np.hypot(*(ref.point - p0)))
        if move > MOVE_MAX_MM or not (ref.sigma <= SIGMA_MAX_MM or read_off(ref, p0, pole)):
            continue
        read.points[name] = ref.point
        read.moved[name] = move
        if move > _TOLD_MM:
            read.notes.append(f"{name.lower()} is read {move:.1f} mm from where the pencil "
                              "segments' ends put it: where its lines, fitted to the ink along "
                              "their length, and their ends agree")


def read_off(ref: Refined, p0: np.ndarray, pole: np.ndarray) -> bool:
    """Whether a loosely refined point is used all the same: its arrowhead's end is far on.

    Where the image lies on (or within about 1 mm of) a link's line through
    another image (Sec. 3.5: the image of a link is similar to the link) and
    the vector from the pole crosses that line at 10-20° (Sec. 3.4), the
    strokes' ink is one band; the point is known across the band to 0.1 mm
    but along it only from the crossing vector's fitted line and its
    arrowhead's end, run on over the band's ink for about 1 mm and known to
    half that run: to 0.35-0.6 mm (σ).  The segments' ends put it 1-2 mm
    short of or past the arrowhead, on the vector.  A refined point known to
    :data:`LOOSE_SIGMA_MAX_MM`, with an end found, is used when the point
    read lies on the vector from the pole through it (within
    :data:`_ON_RAY_MM`: moved along the vector, to its arrowhead) and more
    than :data:`_OFF_SIGMAS` of its σ off it (its Mahalanobis distance under
    the refined point's covariance).  Measured in docs/scan-reading.md
    (28 Nov 2026, scan24).
    """
    if ref.sigma > LOOSE_SIGMA_MAX_MM or ref.ends < 1:
        return False
    ray = ref.point - np.asarray(pole, dtype=float)
    d = np.asarray(p0, dtype=float) - ref.point
    across = abs(float(ray[0] * d[1] - ray[1] * d[0])) / max(float(np.hypot(*ray)), 1e-12)
    return across <= _ON_RAY_MM and float(d @ np.linalg.solve(ref.cov, d)) > _OFF_SIGMAS**2
