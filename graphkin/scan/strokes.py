"""The pencil line segments in a rectified worksheet's polygon area, in mm on the sheet.

1. The light is flattened: the paper's brightness is estimated by a grey
   closing (a dilation then an erosion, 4 mm across, which wipes out lines
   thinner than that) and the page divided by it; ink is where the ratio is
   below :data:`INK_RATIO`.
2. Everything the worksheet printed is masked out (its ink drawn again and
   grown by 1 mm) and everything outside the polygon area.
3. OpenCV's line segment detector finds straight pieces along each stroke's
   edges; pieces on one line (within 3° and 1.3 mm, with gaps up to 3 mm)
   are merged into one segment, and segments shorter than :data:`MIN_MM`
   (arrowheads, letters, dots) are dropped.
4. Each segment's line is refitted to the ink's middle, and each end is
   the stroke's tip: where the darkness along its middle line falls through
   half the stroke's own (:func:`_tip`), not where the detector stopped.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the polygon's vectors are
straight lines between image points).
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from graphkin.scan import need_cv2
from graphkin.scan.sheet import PX_PER_MM

__all__ = ["INK_RATIO", "MIN_MM", "pencil", "segments", "merge", "apart", "ends", "vertex_at"]

INK_RATIO = 0.84
"""A pixel darker than this fraction of the paper around it is pencil."""
MIN_MM = 5.0
"""Shorter segments are arrowheads, letters or dots."""
_ANGLE = math.radians(3.0)
_ACROSS_MM = 1.3
_GAP_MM = 3.0
_SPREAD_SIN = math.sin(math.radians(8.0))
"""Lines meeting at a vertex at more than 8° give it as their meeting point."""
_RUN_MM = 4.0
"""A tip is looked for at most this far past the detector's end: the detector stops up to
3.5 mm short of it where arrowhead barbs or another stroke join the line's edges."""
_MISS_MM = 0.6
"""A line passing farther than this from the others' meeting point is not one of them."""
_TIP_GAP_MM = _GAP_MM
"""A gap in a stroke shorter than this is stepped over when its tip is looked for (as
the pieces of one stroke are joined over it)."""
_HALF_MM = 0.3
"""Half a pencil line's width (to half its darkness), blurred by the photo."""
_COVER_MM = 2.0
_LONG_MM = 20.0
"""A line at least this long is looked for where a stroke ending near the vertex crosses it
(shorter ones may be pieces of merged strokes, off their lines)."""
"""At most this far does a tip run on over another stroke's ink (lines under 8.6° apart)."""
_GROW = int(round(2.2 * PX_PER_MM)) | 1
"""The printed ink is masked grown to this many pixels across (2.2 mm)."""
_BANDS = (0.9, 0.5)
"""The ink within these distances (mm) of the line, refitted in turn: the stroke's middle."""
_KEEP_MM = 2.0
"""A line refitted apart from the others (:func:`apart`) keeps at least this much of itself."""
_OFF_TIP_MM = 3.0
"""Of crossings as many lines agree on, the one nearest the strokes' tips is taken (each
tip counted at most this far: a tip run on over other ink is up to 3 mm past)."""
_SIGMA_LINE = 0.1
"""How far (σ, mm) a refitted line passes from the image point it was drawn through."""
_SIGMA_END = 0.4
"""How far (σ, mm) a stroke's tip is from its image point along its line (overshot or short)."""

def pencil(gray: np.ndarray, printed: np.ndarray, box_px: tuple[int, int, int, int]
           ) -> np.ndarray:
    """The light-flattened page in the polygon area, 1.0 = paper, printed ink set to paper."""
    cv2 = need_cv2()
    x0, y0, x1, y1 = box_px
    g = gray[y0:y1, x0:x1].astype(np.float32)
    g = cv2.medianBlur(g.astype(np.uint8), 3).astype(np.float32)
    k = int(round(4 * PX_PER_MM)) | 1
    kernel = cv2.getStructuringElement(cv2.MORPH_RECT, (k, k))
    paper = cv2.morphologyEx(g, cv2.MORPH_CLOSE, kernel)
    paper = cv2.GaussianBlur(paper, (0, 0), 2 * PX_PER_MM)
    grown = cv2.dilate(printed[y0:y1, x0:x1].astype(np.uint8),
                       cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (_GROW, _GROW))).astype(bool)
    # The closing is the brightest grey near each pixel: with noise it is the paper plus
    # two or three noise σ (3 % of the paper at the harsh level, where the light falls and
    # the same sensor noise is a larger part of it).  The paper is then the mean of the
    # pixels that are paper (not pencil, not printed, 0.6 mm clear of both) around each
    # pixel, a Gaussian 2 mm across weighted by them (a normalised convolution: the noise
    # averages out); where almost none are, the closing stays.
    clear = ~grown & (g >= INK_RATIO * paper)
    clear = cv2.erode(clear.astype(np.uint8), np.ones((7, 7), np.uint8)).astype(np.float32)
    num = cv2.GaussianBlur(g * clear, (0, 0), 2 * PX_PER_MM)
    den = cv2.GaussianBlur(clear, (0, 0), 2 * PX_PER_MM)
    paper = np.where(den > 0.05, num / np.maximum(den, 1e-6), paper)
    ratio = np.clip(g / np.maximum(paper, 1.0), 0.0, 1.0)
    ratio[grown] = 1.0
    edge = int(round(1.5 * PX_PER_MM))
    ratio[:edge, :] = ratio[-edge:, :] = 1.0
    ratio[:, :edge] = ratio[:, -edge:] = 1.0
    return ratio


def segments(ratio: np.ndarray, origin_px: tuple[int, int], sheet_h_mm: float) -> np.ndarray:
    """The merged pencil segments, shape (n, 2, 2), in sheet mm (y up)."""
    cv2 = need_cv2()
    ink = ratio < INK_RATIO
    # the strokes, cleaned of specks, as a smooth dark-on-light picture for the detector
    clean = cv2.morphologyEx(ink.astype(np.uint8), cv2.MORPH_OPEN,
                             np.ones((2, 2), np.uint8))
    img = (255 - 255 * clean).astype(np.uint8)
    img = cv2.GaussianBlur(img, (0, 0), 0.8)
    lsd = cv2.createLineSegmentDetector(cv2.LSD_REFINE_STD)
    found = lsd.detect(img)[0]
    if found is None or not len(merge(found.reshape(-1, 2, 2) / PX_PER_MM)):
        return np.zeros((0, 2, 2))
    px = merge(found.reshape(-1, 2, 2).astype(float) / PX_PER_MM) * PX_PER_MM
    px = np.array([_refine(sg, ratio, ink) for sg in px]).reshape(-1, 2, 2)
    x0, y0 = origin_px
    mm = np.empty_like(px)
    # pixel centres are whole numbers: pixel j spans j - 0.5 ... j + 0.5, i.e. mm j/PX ... (j+1)/PX
    mm[..., 0] = (px[..., 0] + x0 + 0.5) / PX_PER_MM
    mm[..., 1] = sheet_h_mm - (px[..., 1] + y0 + 0.5) / PX_PER_MM
    return mm


def _refine(seg: np.ndarray, ratio: np.ndarray, ink: np.ndarray,
            others: np.ndarray | None = None) -> np.ndarray:
    """A merged segment (px) fitted to its pencil stroke.

    Its line goes through the ink's middle; its ends are the stroke's tips
    (:func:`_tip`: through an arrowhead to its tip, over gaps under 3 mm).
    ``ink`` is unused (kept for callers).

    The line is the weighted principal axis of the dark pixels within 0.9 mm of
    it, leaving out 2.5 mm at each end (where other lines join); so the two
    edges the detector saw give the stroke's centre to a fraction of a pixel.
    ``others`` (px, (m, 2, 2)): the other strokes' lines; the stretches of
    this line along which one of them lies within the band it is fitted in
    (and half a line's width more) are left out, across the whole band, as
    its ends are (see :func:`apart`); a segment that keeps less than
    :data:`MIN_MM` of its length so is returned as it was given.
    """
    p, q = seg
    length = float(np.hypot(*(q - p)))
    u = (q - p) / length
    pad = 2.0 * PX_PER_MM
    h, w = ratio.shape
    xa = int(max(min(p[0], q[0]) - pad, 0))
    xb = int(min(max(p[0], q[0]) + pad, w - 1)) + 1
    ya = int(max(min(p[1], q[1]) - pad, 0))
    yb = int(min(max(p[1], q[1]) + pad, h - 1)) + 1
    yy, xx = np.mgrid[ya:yb, xa:xb]
    # each pixel weighs by how dark it is, in proportion to how much of it the stroke covers
    # (no threshold: a threshold would pull the line toward the edge row covered more)
    wgt = np.clip(1.0 - ratio[ya:yb, xa:xb], 0.0, None)
    trim = 2.5 * PX_PER_MM if length > 8 * PX_PER_MM else 0.2 * length
    c = p.astype(float)
    for band in _BANDS:
        rel = np.stack([xx - c[0], yy - c[1]], axis=-1).astype(float)
        t = rel @ u - float((p - c) @ u)
        o = rel @ np.array([-u[1], u[0]])
        sel = (np.abs(o) < band * PX_PER_MM) & (t > trim) & (t < length - trim) & (wgt > 0)
        if others is not None:
            spans = _shared(p, u, others, (_BANDS[0] + _HALF_MM) * PX_PER_MM)
            for lo, hi in spans:
                sel &= (t < lo) | (t > hi)
            if _kept(trim, length - trim, spans) < _KEEP_MM * PX_PER_MM:
                return np.asarray(seg, dtype=float)
        if np.count_nonzero(sel) < 6:
            break
        wv = wgt[sel]
        pts = np.stack([xx[sel], yy[sel]], axis=-1).astype(float)
        c = (pts * wv[:, None]).sum(axis=0) / wv.sum()
        d = pts - c
        cov = (d * wv[:, None]).T @ d
        vals, vecs = np.linalg.eigh(cov)
        v = vecs[:, 1]
        u = v if float(v @ u) > 0 else -v
        a, b = float((p - c) @ u), float((q - c) @ u)
        p, q = c + a * u, c + b * u
    dark = _darkness(ratio, p, q)
    if others is not None:
        # the ends given are tips already: walked again along the new line from 2.5 mm
        # inside them, at most 1.5 mm past them
        k = 2.5 * PX_PER_MM * (q - p) / float(np.hypot(*(q - p)))
        p, q = p + k, q - k
    return np.array([_tip(q, p, ratio, dark), _tip(p, q, ratio, dark)])


def _shared(p: np.ndarray, u: np.ndarray, others: np.ndarray, reach: float
            ) -> list[tuple[float, float]]:
    """The stretches of a line that another segment comes within ``reach`` of (px).

    ``t`` from ``p`` along ``u``, px; each other segment sampled every 0.1 mm.
    """
    n = np.array([-u[1], u[0]])
    spans = []
    for a, b in others:
        k = max(int(np.hypot(*(b - a)) / (0.1 * PX_PER_MM)), 2)
        pts = a + np.outer(np.linspace(0.0, 1.0, k + 1), b - a)
        near = np.abs((pts - p) @ n) < reach
        if np.any(near):
            t = (pts[near] - p) @ u
            pad = _HALF_MM * PX_PER_MM                  # the other line's rounded end
            spans.append((float(t.min()) - pad, float(t.max()) + pad))
    return spans


def _kept(lo: float, hi: float, spans: list[tuple[float, float]]) -> float:
    """How much of [lo, hi] the spans leave."""
    left = hi - lo
    cover: list[tuple[float, float]] = []
    for a, b in sorted(spans):
        a, b = max(a, lo), min(b, hi)
        if b <= a:
            continue
        if cover and a <= cover[-1][1]:
            cover[-1] = (cover[-1][0], max(cover[-1][1], b))
        else:
            cover.append((a, b))
    return left - sum(b - a for a, b in cover)


def apart(segs: np.ndarray, ratio: np.ndarray, origin_px: tuple[int, int],
          sheet_h_mm: float) -> np.ndarray:
    """Each segment's line refitted to its own ink, the other strokes' ink left out (mm).

    Two strokes that meet at a vertex at a narrow angle share ink for
    0.9 mm / sin of their angle from it (more than the 2.5 mm at each end
    the fit of :func:`_refine` leaves out when they meet at under 21°): the
    fit of each is pulled toward the other there, so the two lines come
    together before the vertex and their crossing slides along them toward
    where they come from (measured: lines 0.3-0.4 mm off the image near it,
    crossings 1-4 mm short of it).  Here each line is fitted again leaving
    out, as its ends are, the stretches along which another segment lies
    within its band (0.9 mm and half a line's width): across the whole band,
    so what is left of it is still symmetric about its middle (leaving out
    only the pixels near the other line would leave the far half of the
    stroke there and push the line away).  Twice, each time from the lines
    fitted before; the ends are walked out to the tips again along the new
    line (:func:`_tip`).  A segment no other comes near, or that would keep
    less than 5 mm, is kept as it was.
    """
    if len(segs) < 2:
        return segs
    x0, y0 = origin_px
    px = np.empty_like(segs)
    px[..., 0] = segs[..., 0] * PX_PER_MM - x0 - 0.5
    px[..., 1] = (sheet_h_mm - segs[..., 1]) * PX_PER_MM - y0 - 0.5
    cur = px.copy()
    for _ in range(2):
        nxt = cur.copy()
        for i, sg in enumerate(cur):
            others = np.delete(cur, i, axis=0)
            if _shares(sg, others):
                nxt[i] = _refine(px[i], ratio, ratio < INK_RATIO, others)
        cur = nxt
    mm = np.empty_like(cur)
    mm[..., 0] = (cur[..., 0] + x0 + 0.5) / PX_PER_MM
    mm[..., 1] = sheet_h_mm - (cur[..., 1] + y0 + 0.5) / PX_PER_MM
    return mm


def _shares(sg: np.ndarray, others: np.ndarray) -> bool:
    """Whether another segment (px) lies within the band the line of ``sg`` is fitted in."""
    p, q = sg
    length = float(np.hypot(*(q - p)))
    if length < 8 * PX_PER_MM:
        return False
    u = (q - p) / length
    trim = 2.5 * PX_PER_MM
    spans = _shared(p, u, others, (_BANDS[0] + _HALF_MM) * PX_PER_MM)
    return _kept(trim, length - trim, spans) < length - 2 * trim
def _sample(ratio: np.ndarray, pts: np.ndarray) -> np.ndarray:
    """The page's darkness (1 - ratio) at sub-pixel points (bilinear; paper outside)."""
    h, w = ratio.shape
    x, y = pts[..., 0], pts[..., 1]
    x0, y0 = np.floor(x).astype(int), np.floor(y).astype(int)
    fx, fy = x - x0, y - y0
    out = np.zeros(x.shape)
    for dy, wy in ((0, 1 - fy), (1, fy)):
        for dx, wx in ((0, 1 - fx), (1, fx)):
            i, j = y0 + dy, x0 + dx
            inside = (i >= 0) & (i < h) & (j >= 0) & (j < w)
            val = np.where(inside, 1.0 - ratio[np.clip(i, 0, h - 1), np.clip(j, 0, w - 1)], 0.0)
            out += wx * wy * val
    return out


def _darkness(ratio: np.ndarray, p: np.ndarray, q: np.ndarray) -> float:
    """The stroke's own darkness: the median along its middle line (px ends p, q)."""
    n = max(int(np.hypot(*(q - p)) / 0.5), 2)
    t = np.linspace(0.15, 0.85, n)
    return float(np.median(_sample(ratio, p + np.outer(t, q - p))))


def _tip(start: np.ndarray, end: np.ndarray, ratio: np.ndarray, dark: float) -> np.ndarray:
    """The stroke's tip beyond ``end``, walking its middle line from ``start``'s side.

    From 2 mm inside ``end`` the line is walked outward while it is at least
    half as dark as the stroke's middle (gaps under :data:`_TIP_GAP_MM`
    stepped over), up to :data:`_RUN_MM` beyond ``end``; the tip is where the
    darkness falls through half of the stroke's (the edge of a blurred line,
    to a fraction of a pixel).
    """
    length = float(np.hypot(*(end - start)))
    u = (end - start) / length
    step = 0.1 * PX_PER_MM
    back = min(2.0 * PX_PER_MM, 0.5 * length)
    s = np.arange(-back, _RUN_MM * PX_PER_MM + step / 2, step)
    prof = _sample(ratio, end + np.outer(s, u))
    n = np.array([-u[1], u[0]])
    off = 0.12 * PX_PER_MM
    prof = (prof + _sample(ratio, end + np.outer(s, u) + off * n)
            + _sample(ratio, end + np.outer(s, u) - off * n)) / 3
    half = 0.5 * dark
    last = 0
    for k in range(1, len(s)):
        if prof[k] >= half:
            last = k
        elif (s[k] - s[last]) > _TIP_GAP_MM * PX_PER_MM:
            break
    if last + 1 < len(s) and prof[last] > prof[last + 1]:
        # the half-darkness crossing between the last dark sample and the next
        frac = (prof[last] - half) / (prof[last] - prof[last + 1])
        return end + (s[last] + min(max(frac, 0.0), 1.0) * step) * u
    return end + s[last] * u


def merge(segs: np.ndarray) -> np.ndarray:
    """Pieces of one straight stroke joined: (n, 2, 2) -> (m, 2, 2), long ones only.

    Two pieces are one when their directions differ by less than 3°, each
    lies within 1.3 mm of the other's line, and they overlap or leave a gap
    under 3 mm.  The merged segment spans the pieces' ends projected on the
    longest piece's line, moved midway between the outermost pieces (the two
    edges of one pencil line give its middle).  Passes repeat until nothing more joins.
    """
    cur = np.asarray(segs, dtype=float).reshape(-1, 2, 2)
    while True:
        nxt = _merge_pass(cur)
        if len(nxt) == len(cur):
            break
        cur = nxt
    keep = np.hypot(*(cur[:, 1] - cur[:, 0]).T) >= MIN_MM if len(cur) else np.zeros(0, bool)
    return cur[keep] if len(cur) else np.zeros((0, 2, 2))


def _merge_pass(segs: np.ndarray) -> np.ndarray:
    items = [s for s in segs if np.hypot(*(s[1] - s[0])) > 0.4]
    items.sort(key=lambda s: -float(np.hypot(*(s[1] - s[0]))))
    groups: list[list[np.ndarray]] = []
    lines: list[tuple[np.ndarray, np.ndarray, float, float]] = []   # point, dir, t0, t1
    for s in items:
        d = s[1] - s[0]
        d = d / np.hypot(*d)
        for gi, (p, u, t0, t1) in enumerate(lines):
            if abs(float(u[0] * d[1] - u[1] * d[0])) > math.sin(_ANGLE):
                continue
            n = np.array([-u[1], u[0]])
            if max(abs(float((s[0] - p) @ n)), abs(float((s[1] - p) @ n))) > _ACROSS_MM:
                continue
            a, b = sorted((float((s[0] - p) @ u), float((s[1] - p) @ u)))
            if a > t1 + _GAP_MM or b < t0 - _GAP_MM:
                continue
            groups[gi].append(s)
            lines[gi] = (p, u, min(t0, a), max(t1, b))
            break
        else:
            groups.append([s])
            lines.append((s[0].copy(), d, 0.0, float(np.hypot(*(s[1] - s[0])))))
    out = []
    for g, (p, u, _t0, _t1) in zip(groups, lines, strict=True):
        pts = np.concatenate(g)
        n = np.array([-u[1], u[0]])
        off = np.array([float((s.mean(axis=0) - p) @ n) for s in g])
        # the two edges of a pencil line: the middle between them is the line
        mid = (float(off.min()) + float(off.max())) / 2
        c = p + mid * n
        t = (pts - c) @ u
        out.append(np.array([c + float(t.min()) * u, c + float(t.max()) * u]))
    return np.array(out) if out else np.zeros((0, 2, 2))


def ends(segs: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Every segment end (2n, 2) and the index of its segment."""
    return segs.reshape(-1, 2), np.repeat(np.arange(len(segs)), 2)


def vertex_at(segs: np.ndarray, idx: list[int], guess: np.ndarray,
              pole: np.ndarray | None = None) -> np.ndarray:
    """Where the segments ``idx`` that end near ``guess`` meet.

    The segments that pass through ``guess`` (within 1 mm of their line,
    between their ends: an image point in the middle of a straight image,
    where the lines of a link's collinear points merged) count too, and
    the long ones (:data:`_LONG_MM`) that the strokes ending there cross
    within 3 mm of ``guess`` (an end run on over a line's ink is past it).  The
    lines that agree on the vertex are those within 0.6 mm of the crossing
    of two of them (over 8° apart) that most lines agree on (a letter or a
    barb ending nearby is left out); the vertex is then the least-squares
    point of those lines and of the strokes' ends (:func:`_combine`): a line
    overshot or stopped short still points at the vertex, and along lines
    that meet at a narrow angle the ends decide.  ``pole``: the vector from
    it ends here too, found as a segment or not (its direction tells how far
    the other strokes' tips run on over its ink).  With no segment ending
    there (``idx`` empty), ``guess`` is an arrowhead's tip in the middle of a
    line from the pole (:func:`graphkin.scan.arrows.arrow_tips`), put on that line
    (:func:`_on_own_line`).
    """
    if not idx:
        return _on_own_line(segs, np.asarray(guess, dtype=float), pole)
    lines = list(idx)
    # the strokes' own ends there: ``guess`` is one of them, and may be the one run on
    # farthest past the vertex, so a line's crossing is looked for near each
    tips = [min(segs[j], key=lambda e: float(np.hypot(*(e - guess)))) for j in idx] or [guess]
    for i, (p, q) in enumerate(segs):
        if i in lines:
            continue
        length = float(np.hypot(*(q - p)))
        u = (q - p) / length
        n = np.array([-u[1], u[0]])
        # where it passes nearest the end, or crosses the line of a stroke ending there
        # (an end run on over its ink is up to 3 mm past it)
        at = [guess] + ([_cross(p, n, segs[j]) for j in idx] if length >= _LONG_MM else [])
        for x in at:
            if x is None or min(float(np.hypot(*(x - e))) for e in tips) >= 3.0:
                continue
            t = float((x - p) @ u)
            if 1.0 < t < length - 1.0 and abs(float((x - p) @ n)) < 1.0:
                lines.append(i)
                break
    normals, offsets = [], []
    for i in lines:
        p, q = segs[i]
        d = (q - p) / np.hypot(*(q - p))
        n = np.array([-d[1], d[0]])
        normals.append(n)
        offsets.append(float(n @ p))
    A, b = np.array(normals), np.array(offsets)
    end = np.mean([min(segs[i], key=lambda e: float(np.hypot(*(e - guess)))) for i in idx],
                  axis=0)
    # pieces of one stroke (a gap, or the detector stopping where it crosses other ink):
    # their ends there are no stroke's tip
    broken = {lines[i] for i, j in itertools.permutations(range(len(lines)), 2)
              if abs(float(A[i, 0] * A[j, 1] - A[i, 1] * A[j, 0])) < math.sin(_ANGLE)
              and abs(float(A[j] @ segs[lines[i]].mean(axis=0)) - b[j]) < _MISS_MM}
    best: tuple[int, float, float, np.ndarray] | None = None
    for i, j in itertools.combinations(range(len(lines)), 2):
        if abs(float(A[i, 0] * A[j, 1] - A[i, 1] * A[j, 0])) < _SPREAD_SIN:
            continue
        x = np.linalg.solve(A[[i, j]], b[[i, j]])
        if float(np.hypot(*(x - guess))) >= 3.0:
            continue
        miss = np.abs(A @ x - b)
        support = _distinct(A[miss <= _MISS_MM])
        total = float(miss[miss <= _MISS_MM].sum())
        # of crossings as many lines agree on, the one nearest where the strokes end (not
        # counting the ends of a line broken there, by a gap or where it crosses a stroke:
        # passing near the image, it crosses the others away from their tips)
        off_tips = sum(min(float(np.hypot(*(x - e))), _OFF_TIP_MM)
                       for j, e in zip(idx, tips, strict=False) if j not in broken)
        if best is None or (support, -off_tips, -total) > (best[0], -best[1], -best[2]):
            best = (support, off_tips, total, x)
    # the lines that agree on the vertex (a letter or a barb ending nearby does not)
    ok = np.abs(A @ (best[3] if best is not None else end) - b) <= _MISS_MM
    if not np.any(ok):
        return end
    agree = [segs[i] for i, k in zip(lines, ok, strict=True) if k]
    if pole is not None and float(np.hypot(*(guess - pole))) > 2.0 and not any(
            _through(sg, pole) for sg in agree):
        # the vector from the pole ends here too, found or not (a short one often is not);
        # found, it is one of the lines already
        agree.append(np.array([pole, guess], dtype=float))
    return _combine(A[ok], b[ok], agree, [segs[i] for i in idx if ok[lines.index(i)]],
                    guess, end)


def _distinct(normals: np.ndarray) -> int:
    """How many lines of these unit normals there are, two pieces of one line counted once.

    Lines that pass through one point (a crossing's support) and run within
    3° of each other are pieces of one stroke: broken by a gap, or where it
    crosses another, into two segments (both of them then agree on every
    crossing on that stroke, right or not).
    """
    kept: list[np.ndarray] = []
    for a in normals:
        if all(abs(float(a[0] * k[1] - a[1] * k[0])) >= math.sin(_ANGLE) for k in kept):
            kept.append(a)
    return len(kept)


def _on_own_line(segs: np.ndarray, tip: np.ndarray, pole: np.ndarray | None) -> np.ndarray:
    """An arrowhead's tip where no segment ends, on its vector's line.

    The tip is found by :func:`graphkin.scan.arrows.arrow_tips`.

    The barbs place it along the line to 0.1-0.2 mm; across, the line of the
    segment from the pole it lies on does (the nearest within 1 mm).  Other
    lines passing there are not crossed with it: a faint construction line
    or a stroke run on through it a few degrees off would move the point
    along the line by millimetres.
    """
    best, out = 1.0, tip
    for sg in segs:
        if pole is not None and not _through(sg, pole):
            continue
        d = (sg[1] - sg[0]) / np.hypot(*(sg[1] - sg[0]))
        n = np.array([-d[1], d[0]])
        off = float((tip - sg[0]) @ n)
        if abs(off) < best:
            best, out = abs(off), tip - off * n
    return np.asarray(out)


def _through(sg: np.ndarray, pole: np.ndarray) -> bool:
    """Whether a segment lies on a line through the pole (within 1.5 mm): a vector from it."""
    d = (sg[1] - sg[0]) / np.hypot(*(sg[1] - sg[0]))
    return abs(float(d[0] * (pole - sg[0])[1] - d[1] * (pole - sg[0])[0])) < 1.5


def _cross(p: np.ndarray, n: np.ndarray, sg: np.ndarray) -> np.ndarray | None:
    """Where the line through ``p`` with unit normal ``n`` crosses the segment's line (>8°)."""
    d = (sg[1] - sg[0]) / np.hypot(*(sg[1] - sg[0]))
    m = np.array([-d[1], d[0]])
    if abs(float(n[0] * m[1] - n[1] * m[0])) < _SPREAD_SIN:
        return None
    return np.asarray(np.linalg.solve(np.array([n, m]), np.array([n @ p, m @ sg[0]])))


def _covered(d: np.ndarray, at: np.ndarray, others: list[np.ndarray]) -> float:
    """How far past the vertex other strokes' ink lies on a stroke's line (mm).

    A stroke arriving along ``d`` is walked on to where the ink ends
    (:func:`_tip`): over its own rounded end, half a line's width past where
    the pencil stopped (:data:`_HALF_MM`), and past the vertex its line still
    runs over the ink of a stroke whose body lies on that side (one that goes
    through the vertex, or comes from the far side), for :data:`_HALF_MM` / sin
    of their angle.
    """
    cover = _HALF_MM
    for sg in others:
        e = (sg[1] - sg[0]) / np.hypot(*(sg[1] - sg[0]))
        sin = abs(float(d[0] * e[1] - d[1] * e[0]))
        ta, tb = sorted((float((sg[0] - at) @ d), float((sg[1] - at) @ d)))
        # its body reaches past the vertex along d (beyond its own rounded end)
        beyond = tb > 1.0
        c = _HALF_MM / max(sin, _HALF_MM / _COVER_MM) if beyond else _HALF_MM
        cover = max(cover, c)
    return cover


def _combine(A: np.ndarray, b: np.ndarray, agree: list[np.ndarray], ending: list[np.ndarray],
             guess: np.ndarray, end: np.ndarray) -> np.ndarray:
    """The vertex from the lines that meet there (rows of ``A``, ``b``) and the strokes' ends.

    Each line holds the vertex across itself (σ :data:`_SIGMA_LINE`); each
    stroke that ends there holds it along its own line (σ :data:`_SIGMA_END`),
    unless its end is farther from the lines' crossing than the two can
    differ by (2.5 σ of the sum): such an end was run on over another
    stroke's ink, or stopped short where the strokes merge.  Lines that meet
    at a wide angle fix the vertex by themselves; along lines that meet at a
    narrow one, the ends do.  When no two of the lines are over 8° apart
    (:data:`_SPREAD_SIN`, as in :func:`vertex_at`), their crossing is not
    used at all: a line is off by 0.1-0.4 mm at the vertex (a hand's wobble,
    a fit that leaves out the ink it shares with another stroke there), which
    moves a crossing at under 8° by 1-6 mm along them, more than its ends can
    be off; so each line holds the vertex only across their mean direction,
    and the ends decide along it, none left out.
    """
    if len(A) > 1 and max(abs(float(A[i, 0] * A[j, 1] - A[i, 1] * A[j, 0]))
                          for i in range(len(A)) for j in range(i)) < _SPREAD_SIN:
        m = A * np.sign(A @ A[0])[:, None]
        m = m.sum(axis=0) / np.hypot(*m.sum(axis=0))
        # each line's place across the mean direction, where it passes nearest the end
        b = np.array([float(m @ (guess - (a @ guess - c) * a)) for a, c in zip(A, b)])
        A = np.tile(m, (len(A), 1))
    M = A.T @ A / _SIGMA_LINE**2
    r = A.T @ b / _SIGMA_LINE**2
    tips = []
    for sg in ending:
        k = int(np.argmin(np.hypot(*(sg - guess).T)))
        near, far = sg[k], sg[1 - k]
        d = (near - far) / np.hypot(*(near - far))
        cover = _covered(d, guess, [o for o in agree if o is not sg])
        tips.append((near - cover * d, d, max(_SIGMA_END, cover / 2)))
    if np.linalg.cond(M) < 1e6:
        cross = np.linalg.solve(M, r)
        cov = np.linalg.inv(M)
        kept = []
        for near, d, sig in tips:
            spread = math.sqrt(sig**2 + float(d @ cov @ d))
            if abs(float((near - cross) @ d)) <= 2.5 * spread:
                kept.append((near, d, sig))
        tips = kept
    else:
        # one direction only: the ends decide along it
        tips = tips or [(end, np.array([-A[0, 1], A[0, 0]]), _SIGMA_END)]
    for near, d, sig in tips:
        M = M + np.outer(d, d) / sig**2
        r = r + d * float(d @ near) / sig**2
    if np.linalg.cond(M) > 1e6:
        return end
    return np.asarray(np.linalg.solve(M, r))
