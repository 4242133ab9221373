"""Strokes past crossed lines, and other images' vectors, before the image points are read.

A stroke drawn to an image on a long line runs on over that line, and the
detector carries its tip on to the student's letter (:func:`past_crossings`);
another image's vector from the pole passing a vertex is none of its lines
(:func:`other_ray`).  Split from :mod:`graphkin.scan.inkfit`, whose sampling
of the ink they use.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the polygon: straight vectors
from the pole to each image point).
"""

from __future__ import annotations

import numpy as np

from graphkin.scan.inkfit import _CROSS_SIN, _CROSSED_MM, _LETTER_MM, _PAPER_MM, Sheet, ink_along

__all__ = ["other_ray", "past_crossings"]


def past_crossings(segs: np.ndarray, sheet: Sheet) -> np.ndarray:
    """The segments with each tip run on past a crossing over paper to a letter cut back (mm).

    A stroke drawn to an image on a long line (a link's line to an image in
    the middle of a straight line from the pole) ends on that line's ink;
    the student's letter is written just past the image, often straight on
    along the stroke.  The detector joins the letter's stroke to the line
    over the paper between them (gaps under 3 mm are a pencil lifted), and
    the tip is then walked on through the letter's ink, up to 5 mm past the
    image (:mod:`graphkin.scan.strokes`), out of reach of the places it can
    be.  Here, where a segment crosses a line at least
    :data:`_CROSSED_MM` long (over 8° apart) 1-6 mm before its tip, and
    along its middle past the crossing the ink stops, paper follows for at
    least :data:`_PAPER_MM`, and the ink after it runs under
    :data:`_LETTER_MM` to the tip, the tip is put where the ink past the
    crossing stops (half the stroke's darkness): a stroke's own piece after a
    pencil gap is longer, and a line crossed in its middle goes on.
    """
    out = np.array(segs, dtype=float, copy=True)
    if len(segs) < 2:
        return out
    d = segs[:, 1] - segs[:, 0]
    length = np.hypot(d[:, 0], d[:, 1])
    step = 0.05
    for i in range(len(segs)):
        if length[i] == 0.0:
            continue
        mid = segs[i, 0] + np.outer(np.linspace(0.15, 0.85, 25), d[i])
        half = 0.5 * float(np.median(sheet.darkness(mid)))
        for k in (0, 1):
            tip, far = segs[i, k], segs[i, 1 - k]
            w = (tip - far) / length[i]
            nrm = np.array([-w[1], w[0]])
            cut = None
            for j in np.flatnonzero(length >= _CROSSED_MM).tolist():
                if j == i:
                    continue
                v = d[j] / length[j]
                if abs(float(w[0] * v[1] - w[1] * v[0])) < _CROSS_SIN:
                    continue
                A = np.array([nrm, [-v[1], v[0]]])
                x = np.linalg.solve(A, np.array([float(nrm @ far), float(A[1] @ segs[j, 0])]))
                back = float((tip - x) @ w)
                along = float((x - segs[j, 0]) @ v)
                if not (1.0 < back < _LETTER_MM + 3.0 and 0.0 < along < length[j]):
                    continue
                s = np.arange(0.0, back + 1e-9, step)
                prof = ink_along(sheet, x, w, s)
                dark = prof >= half
                if not dark[0] or np.all(dark):
                    continue
                stop = int(np.argmin(dark))                 # the first paper past the crossing
                again = np.flatnonzero(dark[stop:])
                if not len(again) or s[stop + int(again[0])] - s[stop] < _PAPER_MM:
                    continue
                if back - float(s[stop + int(again[0])]) >= _LETTER_MM:
                    continue
                frac = (prof[stop - 1] - half) / max(float(prof[stop - 1] - prof[stop]), 1e-12)
                at = x + (float(s[stop - 1]) + min(max(float(frac), 0.0), 1.0) * step) * w
                if cut is None or float((at - far) @ w) < float((cut - far) @ w):
                    cut = at
            if cut is not None:
                out[i, k] = cut
    return out


def other_ray(seg: np.ndarray, p: np.ndarray, pole: np.ndarray, line_mm: float,
              start_mm: float) -> bool:
    """Whether segment ``seg`` is a vector from the pole passing ``p`` by 1 mm or more.

    A vector from the pole: its line within ``line_mm`` of the pole, its end
    nearer the pole within ``start_mm`` of it (mm on the sheet, Sec. 3.4).
    Where two vectors from the pole run a few degrees apart (a four-bar's
    o a and o f, 5°), the other one crosses the links' lines near the
    vertex, and :func:`graphkin.scan.strokes.vertex_at` would take that
    crossing as the vertex.
    """
    a, b = sorted(np.asarray(seg, dtype=float), key=lambda e: float(np.hypot(*(e - pole))))
    u = (b - a) / max(float(np.hypot(*(b - a))), 1e-12)
    off = abs(float(u[0] * (pole - a)[1] - u[1] * (pole - a)[0]))
    return (off < line_mm and float(np.hypot(*(a - pole))) < start_mm
            and abs(float(u[0] * (p - a)[1] - u[1] * (p - a)[0])) >= 1.0)
