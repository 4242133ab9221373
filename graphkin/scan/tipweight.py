"""How much an arrowhead's tip counts as a vertex beside the segments ending there.

An image point is where its absolute vector, drawn from the pole, has its
arrowhead (Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), and where the
lines of its link's image end with it (Secs. 3.5, 4.2: images of a link).
The names are given to vertices (:func:`graphkin.scan.read._match`): a
segment end counts nearer for each other segment ending with it.  An
arrowhead's tip found where its own vector ends, with the image's lines
ending there too, is as sure a vertex: it counts as much nearer, so a
cluster of ends beside it, whose lines' crossing is pulled off the image
by a band of merged strokes, does not take its name.

A tip is found where the head's ink ends along the vector's axis
(:func:`graphkin.scan.arrows.head_at`).  A line running on past the tip
within 8° of that axis carries the ink on, and the tip is then found up
to 0.8 mm along it (a thin polygon, all its lines near the vector's
direction): such a tip counts no nearer than before.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4, Sec. 3.5, Sec. 4.2.
"""

from __future__ import annotations

import numpy as np

__all__ = ["tip_strength"]

_ON_OWN_MM = 0.5
"""A tip lies on its own vector's line: within this of it (a tip is found to 0.1-0.3 mm)."""


def tip_strength(segs: np.ndarray, tips: np.ndarray, pole: np.ndarray, same_mm: float,
                 strong_mm: float, ray_mm: float, past_mm: float) -> np.ndarray:
    """How much nearer each arrowhead's tip counts as a vertex (mm, (k,)).

    Parameters
    ----------
    segs : ndarray (n, 2, 2)
        The pencil segments (sheet mm).
    tips : ndarray (k, 2)
        The arrowheads' tips the names may take (sheet mm).
    pole : ndarray (2,)
        The printed pole (sheet mm).
    same_mm : float
        Segments ending within this of a tip end there (one vertex).
    strong_mm : float
        How much nearer a tip counts for each segment ending there.
    ray_mm : float
        A segment whose line passes within this of the pole is a vector from it.
    past_mm : float
        A tip farther than this beyond the end of another segment ending
        there, along that segment, is not where that segment ends.

    Returns
    -------
    ndarray (k,)
        ``strong_mm`` for each segment ending within ``same_mm`` of the tip,
        at most twice that, when one of them is the tip's own vector (its
        line through the pole within ``ray_mm``, the tip within 0.5 mm of it)
        and the tip is no farther than ``past_mm`` beyond any other one's end
        along it; 0 otherwise (Sec. 3.4: each vector's arrowhead at its
        image; Secs. 3.5, 4.2: the image's lines end there too).
    """
    tips = np.asarray(tips, dtype=float).reshape(-1, 2)
    out = np.zeros(len(tips))
    if not len(tips) or not len(segs):
        return out
    a, b = segs[:, 0], segs[:, 1]
    d = b - a
    length = np.hypot(*d.T)
    u = d / np.maximum(length, 1e-12)[:, None]

    def off(p: np.ndarray) -> np.ndarray:
        """Each segment's line's distance from ``p`` (mm)."""
        w = p - a
        return np.asarray(np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]))

    ray = (length > 0) & (off(pole) <= ray_mm)
    for i, t in enumerate(tips):
        end = np.minimum(np.hypot(*(a - t).T), np.hypot(*(b - t).T)) < same_mm
        end &= length > 0
        own = end & ray & (off(t) <= _ON_OWN_MM)
        if not own.any():
            continue
        k = int(np.flatnonzero(own)[0])
        # each other line ending there, walked to its end nearer the tip: its end is the
        # vertex's to the hand's 0.3 mm; a tip farther beyond it is read on other ink
        near_b = np.hypot(*(b - t).T) <= np.hypot(*(a - t).T)
        end_pt = np.where(near_b[:, None], b, a)
        w = np.where(near_b[:, None], u, -u)
        beyond = np.einsum("ij,ij->i", t - end_pt, w)
        others = end & (np.arange(len(segs)) != k)
        if np.any(beyond[others] > past_mm):
            continue
        out[i] = strong_mm * min(int(end.sum()), 2)
    return out
