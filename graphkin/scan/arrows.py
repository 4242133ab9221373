"""Arrowheads in the middle of a stroke from the pole: the images no segment ends at.

An image in line with the pole and another image lies in the middle of one
straight pencil stroke; only its vector's arrowhead marks it (Uicker,
Pennock & Shigley, 5th ed., Sec. 3.4: each absolute vector is drawn from the
pole with its arrowhead at the image).  :func:`arrow_tips` finds such
arrowheads by their two barbs beside the line; the segments and the page's
darkness come from :mod:`graphkin.scan.strokes`.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.scan.sheet import PX_PER_MM
from graphkin.scan.strokes import _ANGLE, _MISS_MM, _sample, _through

__all__ = ["arrow_tips", "broken_by_tips", "head_at"]


_BARB_DEG = np.arange(10.0, 36.0, 1.0)
"""The angles (degrees) an arrowhead's barbs are looked for at, from the vector's line."""
_BARB_O = np.arange(0.6, 1.45, 0.1)
"""How far beside the line (mm) a barb's ink is read: clear of the line's own, blurred."""
_BARB_DARK = 0.15
"""Both barbs' ink, above the line's own beside it, at least this part of the line's darkness
(barbs at 15° give 0.2-0.25 of it; their edges then decide, :func:`_barbs_meet`)."""


def arrow_tips(segs: np.ndarray, ratio: np.ndarray, origin_px: tuple[int, int],
               sheet_h_mm: float, pole: np.ndarray) -> np.ndarray:
    """The tips of arrowheads in the middle of a line from the pole (mm, (k, 2)).

    An image in line with the pole and another image (a slider-crank at a
    dead centre: the crank's image, the coupler point's and the pole in one
    line) is in the middle of one straight stroke: no segment ends there, and
    only its vector's arrowhead marks it (Uicker, Pennock & Shigley, 5th ed.,
    Sec. 3.4: each absolute vector drawn from the pole with its arrowhead at
    the image).  Along each segment on a line through the pole (within
    1.5 mm), the page's darkness beside the line, less the line's own there
    (the median along it at that distance), is matched with two barbs leaving
    the line backward (toward the pole), one on each side, at 10-35°: the
    darkness along each barb's line 0.6-1.4 mm beside the line, the weaker
    of the two the score, at least 30 % of the line's darkness.  That finds
    an arrowhead to a millimetre or so (a barb 2 mm long at 15° is hardly
    0.5 mm clear of the line); where the tip is, the barbs' outer edges say
    (:func:`_barbs_meet`).  Tips within 2.5 mm of a segment's end (an
    arrowhead at an end: the end is read) are left out, and the weaker of
    any two within 3 mm; not the end of a piece of one straight stroke that
    another piece runs on past (:func:`_broken_ends`: the detector breaks a
    line where the barbs widen it, so the line from the pole through an
    image in its middle often ends and starts again beside the tip).
    """
    if not len(segs):
        return np.zeros((0, 2))
    x0, y0 = origin_px
    step = 0.1 * PX_PER_MM
    tans = np.tan(np.radians(_BARB_DEG))
    found: list[tuple[float, np.ndarray]] = []
    for sg in segs:
        if not _through(sg, pole):
            continue
        near, far = sorted(sg, key=lambda e: float(np.hypot(*(e - pole))))
        a, b = ((np.array([e[0], sheet_h_mm - e[1]]) * PX_PER_MM - np.array([x0, y0]) - 0.5)
                for e in (near, far))
        length = float(np.hypot(*(b - a)))
        if length < 8 * PX_PER_MM:
            continue
        u = (b - a) / length
        n = np.array([-u[1], u[0]])
        t = np.arange(0.0, length + step / 2, step)
        o = np.arange(-1.6, 1.65, 0.1) * PX_PER_MM
        grid = a + t[:, None, None] * u + o[None, :, None] * n
        dark = _sample(ratio, grid)
        line = float(np.median(dark[:, len(o) // 2]))
        if line <= 0.05:
            continue
        res = np.clip(dark - np.median(dark, axis=0), 0.0, None)
        scores: list[np.ndarray] = []
        for side in (1.0, -1.0):
            cols = [int(np.argmin(np.abs(o - side * k * PX_PER_MM))) for k in _BARB_O]
            # along a barb at angle α, the ink |o| beside the line is |o| / tan α behind the tip
            back = np.rint(np.outer(1.0 / tans, _BARB_O) * 10.0).astype(int)   # (angles, o)
            sc = np.zeros((len(tans), len(t)))
            for ia in range(len(tans)):
                acc = np.zeros(len(t))
                for k, c in enumerate(cols):
                    sh = back[ia, k]
                    acc[sh:] += res[: len(t) - sh, c] if sh else res[:, c]
                sc[ia] = acc / len(cols)
            scores.append(sc.max(axis=0))
        both = np.minimum(*scores)
        lo, hi = int(2.5 * 10), len(t) - int(2.5 * 10)
        if hi <= lo:
            continue
        for k in range(lo, hi):
            if both[k] < _BARB_DARK * line or both[k] < both[k - 1] or both[k] < both[k + 1]:
                continue
            at = _barbs_meet(dark, t, o, t[k], line)
            if at is None:
                continue
            tip_px = a + at * u
            mm = np.array([(tip_px[0] + x0 + 0.5) / PX_PER_MM,
                           sheet_h_mm - (tip_px[1] + y0 + 0.5) / PX_PER_MM])
            found.append((float(both[k] / line), mm))
    ends_mm = segs.reshape(-1, 2)[~_broken_ends(segs)]
    out: list[np.ndarray] = []
    for _score, p in sorted(found, key=lambda f: -f[0]):
        if float(np.min(np.hypot(*(ends_mm - p).T))) < 2.5:
            continue
        if any(float(np.hypot(*(p - q))) < 3.0 for q in out):
            continue
        out.append(p)
    return np.array(out).reshape(-1, 2)


def broken_by_tips(segs: np.ndarray, tips: np.ndarray, near_mm: float = 2.5) -> np.ndarray:
    """Which segment ends (2n) are a straight stroke broken beside an arrowhead's tip.

    The detector breaks the stroke from the pole through an image in its
    middle where the arrowhead's barbs widen it (:func:`_broken_ends`: another
    piece of the line runs on past the end); :func:`arrow_tips` keeps a tip
    beside such ends for that reason.  Such an end is no vertex of its own:
    the image is at the tip (Uicker, Pennock & Shigley, 5th ed., Sec. 3.4,
    each vector's arrowhead at its image point).  ``tips``: from
    :func:`arrow_tips` (mm, (k, 2)); an end within ``near_mm`` of one counts.
    """
    out = np.zeros(2 * len(segs), bool)
    tips = np.asarray(tips, dtype=float).reshape(-1, 2)
    if not len(segs) or not len(tips):
        return out
    pts = segs.reshape(-1, 2)
    near = np.min(np.hypot(pts[:, None, 0] - tips[None, :, 0],
                           pts[:, None, 1] - tips[None, :, 1]), axis=1) < near_mm
    return np.asarray(near & _broken_ends(segs))


def _broken_ends(segs: np.ndarray) -> np.ndarray:
    """Which segment ends (2n) are where one straight stroke is broken, not where it ends.

    Another segment within 3°, its line within 0.6 mm of the end, runs on
    past it by over 2.5 mm (pieces of one line overlapping or leaving a gap).
    """
    out = np.zeros(2 * len(segs), bool)
    for i, sg in enumerate(segs):
        u = (sg[1] - sg[0]) / max(float(np.hypot(*(sg[1] - sg[0]))), 1e-12)
        for k in (0, 1):
            e, back = sg[k], (-u if k == 1 else u)        # back: into its own segment
            for j, other in enumerate(segs):
                if j == i:
                    continue
                w = (other[1] - other[0]) / max(float(np.hypot(*(other[1] - other[0]))), 1e-12)
                if abs(float(u[0] * w[1] - u[1] * w[0])) > math.sin(_ANGLE):
                    continue
                if abs(float((e - other[0]) @ np.array([-w[1], w[0]]))) > _MISS_MM:
                    continue
                if max(float((other[0] - e) @ -back), float((other[1] - e) @ -back)) > 2.5:
                    out[2 * i + k] = True
                    break
    return out


def _edge(prof: np.ndarray, o: np.ndarray, level: float) -> float:
    """The farthest ``o`` (px, increasing) out to which ``prof`` stays at ``level`` or darker."""
    k = 0
    while k + 1 < len(prof) and prof[k + 1] >= level:
        k += 1
    if k + 1 >= len(prof) or prof[k] <= prof[k + 1]:
        return float(o[k])
    return float(o[k] + (prof[k] - level) / (prof[k] - prof[k + 1]) * (o[k + 1] - o[k]))


def _barbs_meet(dark: np.ndarray, t: np.ndarray, o: np.ndarray, t0: float,
                line: float) -> float | None:
    """Where the two barbs found near ``t0`` leave the line (px along it), or None.

    On each side, the ink's edge (where the darkness falls through half the
    line's) is the line's own, ``h`` off its middle, ahead of the tip, and
    behind it the barb's outer edge, ``(t* - t) tan α + h / cos α`` off: a
    straight line is fitted to that edge where it stands over 0.2 mm clear of
    the line's own (from the tip back to the barb's widest), and the tip
    ``t*`` solved from it.  Each barb must leave at 8-40°; the two tips must
    agree within 1 mm.  Failing that, once more without the edge where the
    ink runs on to the sampled band's border (other ink joining the barb's:
    a letter, a stroke) and refitted without samples over 0.1 mm off.
    """
    for clean in (False, True):
        at = _barbs_fit(dark, t, o, t0, line, clean)
        if at is not None:
            return at
    return None


def _barbs_fit(dark: np.ndarray, t: np.ndarray, o: np.ndarray, t0: float, line: float,
               clean: bool) -> float | None:
    """:func:`_barbs_meet` once; ``clean``: other ink at the barbs' edges left out."""
    mid = len(o) // 2
    meets = []
    for side in (1.0, -1.0):
        cols = np.arange(mid, len(o)) if side > 0 else np.arange(mid, -1, -1)
        oo = np.abs(o[cols])
        ahead = np.flatnonzero((t > t0 + 0.6 * PX_PER_MM) & (t < t0 + 2.5 * PX_PER_MM))
        behind = np.flatnonzero((t > t0 - 3.5 * PX_PER_MM) & (t < t0 + 1.0 * PX_PER_MM))
        if not len(ahead) or len(behind) < 5:
            return None
        h = float(np.median([_edge(dark[k, cols], oo, 0.5 * line) for k in ahead]))
        e = np.array([_edge(dark[k, cols], oo, 0.5 * line) for k in behind])
        # clean: an edge out at the grid's border is other ink joining the barb's
        out = (e > h + 0.2 * PX_PER_MM) & ((e < float(oo[-1]) - 1e-9) | (not clean))
        if np.count_nonzero(out) < 4:
            return None
        # from the first clear sample back to the widest (the barb's end is rounded)
        far = int(np.argmax(np.where(out, e, -np.inf)))
        near = int(np.flatnonzero(out)[-1])
        idx = np.arange(far + 1, near + 1) if near > far else np.array([], int)
        idx = idx[out[idx]] if len(idx) else idx
        if len(idx) < 3:
            return None
        slope, icpt = np.polyfit(t[behind][idx], e[idx], 1)
        # once more without the samples over 0.1 mm off (ink joining the barb's edge)
        fit = np.abs(e[idx] - (slope * t[behind][idx] + icpt)) < 0.1 * PX_PER_MM
        if clean and 3 <= np.count_nonzero(fit) < len(idx):
            slope, icpt = np.polyfit(t[behind][idx][fit], e[idx][fit], 1)
        tan = -float(slope)
        if not math.tan(math.radians(8.0)) <= tan <= math.tan(math.radians(40.0)):
            return None
        cos = 1.0 / math.hypot(1.0, tan)
        meets.append((float(icpt) - h / cos) / tan)
    if abs(meets[0] - meets[1]) > 1.0 * PX_PER_MM or abs(np.mean(meets) - t0) > 2.5 * PX_PER_MM:
        return None
    return float(np.mean(meets))


_HEAD_DEG = (10.0, 38.0)
"""The angles (degrees) a barb leaves the vector's line at, as its ink's edge shows them
(the hand draws 15-25°; blur rounds the edge)."""
_HEAD_WIDEN_MM = 0.3
"""A free barb's ink stands out at least this far (mm) beyond the line's own edge ahead of
the tip (a barb 2 mm long at 15° stands 0.5 mm out; blur and noise move an edge 0.1 mm)."""
_HEAD_FIT_MM = 0.1
"""A free barb's outer edge is straight to this (mm, root mean square)."""
_HEAD_HALF_MM = 0.15
"""A pencil stroke's ink stands out at least this far (mm) each side of its middle (strokes
are 0.4-0.8 mm wide once blurred): less, and the axis runs along no stroke."""
_HEAD_FROM_POLE_MM = 7.0
"""No tip nearer the pole than this (mm): a shorter vector is not read (read._SHORT_MM), and
the printed pole and its label are there."""
_HEAD_LONG_MM = 1.5
"""A barb (2-3 mm at 15-25°) stands out widest at least this far (mm) behind the tip."""


def head_at(sheet: Any, place: np.ndarray, pole: np.ndarray, reach_mm: float
            ) -> np.ndarray | None:
    """The tip of the arrowhead of a vector from ``pole`` drawn toward ``place``, or None (mm).

    Every absolute vector starts at the printed pole and has its arrowhead
    at its image point (Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), and
    every place an image can be is known; so the arrowhead is looked for
    with its axis fixed along pole → ``place``, its tip within ``reach_mm``
    of ``place`` along that axis, where no segment need end (an image in the
    middle of a band of merged strokes, or a short vector whose ink is one
    band with a link line near the pole).  One barb may lie inside another
    stroke's ink; the other must be free on paper.  On each side of the axis
    the ink's edge (where the darkness falls through half the line's) is
    read along it; a tip at ``t*`` is taken when, on one side (the free
    barb):

    - behind the tip the edge is a straight ramp (within 0.1 mm) leaving
      the line at 10-38° and standing out at least 0.3 mm beyond the edge
      ahead of the tip, and meets that edge within 0.5 mm of ``t*``;
    - the barb ends: 3.3-4.4 mm behind the tip the edge is back within half
      that widening of the edge ahead (two strokes from one point separate
      for good; a barb, 2-3 mm long, stops);

    on the other side the ink is also wider behind the tip than ahead (the
    other barb, or the stroke covering it), and the line's own ink runs
    behind the tip along the axis (over 80 % of 0.5-3 mm behind it as dark as
    half the line).  Of several tips the one nearest the position tried is
    taken.  ``sheet``: :class:`graphkin.scan.inkfit.Sheet`.
    """
    place = np.asarray(place, dtype=float)
    pole = np.asarray(pole, dtype=float)
    length = float(np.hypot(*(place - pole)))
    if length < 1e-9:
        return None
    u = (place - pole) / length
    n = np.array([-u[1], u[0]])
    step = 0.1
    t = np.arange(max(length - reach_mm - 5.0, 1.0), length + reach_mm + 1.5, step)
    o = np.arange(0.0, 2.05, step)
    grid = pole + t[:, None, None] * u + np.concatenate([o, -o[1:]])[None, :, None] * n
    dark = sheet.darkness(grid)
    up, down = dark[:, : len(o)], np.concatenate([dark[:, :1], dark[:, len(o):]], axis=1)
    centre = np.max(np.stack([up[:, :3], down[:, :3]]), axis=(0, 2))
    own = (t > length - reach_mm - 3.0) & (t < length)
    line = float(np.median(centre[own])) if np.any(own) else 0.0
    if line <= 0.05:
        return None
    edges = [_edges(side, o, 0.5 * line) for side in (up, down)]
    inked = centre >= 0.5 * line
    span = (t >= length - reach_mm - 3.0) & (t <= length + reach_mm) & inked
    if np.count_nonzero(span) < 10:
        return None
    w = float(np.percentile(np.minimum(*edges)[span], 25.0))   # the stroke's half-width
    if w < _HEAD_HALF_MM:
        return None                            # no stroke along the axis: not this vector
    tans = (math.tan(math.radians(_HEAD_DEG[0])), math.tan(math.radians(_HEAD_DEG[1])))
    best: tuple[float, float] | None = None
    for t0 in t[(t >= length - reach_mm) & (t <= length + reach_mm)]:
        ramp = (t > t0 - 1.8) & (t < t0 - 0.3)
        behind = (t > t0 - 4.4) & (t < t0 - 3.3)
        shaft = (t > t0 - 3.0) & (t < t0 - 0.5)
        if np.count_nonzero(behind) < 5 or float(np.mean(inked[shaft])) < 0.8:
            continue
        for free, other in ((0, 1), (1, 0)):
            e = edges[free]
            slope, icpt = np.polyfit(t[ramp], e[ramp], 1)
            tan = -float(slope)
            if not tans[0] <= tan <= tans[1]:
                continue
            if float(np.sqrt(np.mean((e[ramp] - (slope * t[ramp] + icpt)) ** 2))) > _HEAD_FIT_MM:
                continue
            widen = float(slope * (t0 - 1.6) + icpt) - w
            if widen < _HEAD_WIDEN_MM:
                continue
            if not _HEAD_HALF_MM <= float(np.median(e[behind])) <= w + 0.5 * widen:
                continue                       # no barb's end (two strokes parting for good),
                                               # or no shaft behind it on the line
            tip = (float(icpt) - w) / tan       # where the barb's outer edge meets the stroke's
            if abs(tip - t0) > 0.5 or tip < _HEAD_FROM_POLE_MM:
                continue
            back = (t > tip - 3.2) & (t < tip)
            if float(t[back][np.argmax(e[back])]) > tip - _HEAD_LONG_MM:
                continue                       # too short for a barb: a letter's curve
            if float(np.median(edges[other][(t > t0 - 1.6) & (t < t0 - 0.6)])) < (
                    w + 0.5 * _HEAD_WIDEN_MM):
                continue                       # the other side bare: no barb there, no cover
            if best is None or abs(tip - t0) < best[0]:
                best = (abs(tip - t0), tip)
    if best is None:
        return None
    return np.asarray(pole + best[1] * u)


def _edges(prof: np.ndarray, o: np.ndarray, level: float) -> np.ndarray:
    """How far the ink runs out from a line, per row of ``prof`` (mm).

    ``prof``: darkness at ``o`` (≥ 0 mm) out from the line; the ink is at
    ``level`` or darker; 0 where the line itself is paper.
    """
    below = prof < level
    k = np.where(below.any(axis=1), np.argmax(below, axis=1), prof.shape[1] - 1)
    rows = np.arange(len(prof))
    last = np.maximum(k - 1, 0)
    a, b = prof[rows, last], prof[rows, k]
    frac = np.where(a > b, (a - level) / np.where(a > b, a - b, 1.0), 0.0)
    out = o[last] + np.clip(frac, 0.0, 1.0) * (o[k] - o[last])
    return np.asarray(np.where(k == 0, 0.0, out))
