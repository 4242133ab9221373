"""An image read at the ends' vertex or at its arrowhead's tip, whichever its ink allows.

An image point is where its absolute vector, drawn from the pole, has its
arrowhead (Uicker, Pennock & Shigley, 5th ed., Sec. 3.4), and where the
lines of its link's image end with it (Secs. 3.5, 4.2: images of a link).
Where segments end near an image, it is read where their lines meet
(:func:`graphkin.scan.read._vertex`); in a band of merged strokes crossing
the vector at 20° that crossing slides along the vector, past its tip.
The arrowhead found there (:func:`graphkin.scan.arrows.head_at`) is read
where the head's ink ends along the vector's axis: other ink through the
tip (a link line running on past it at 5-20°) can only carry that end
farther from the pole, never nearer.  So a tip behind the ends' vertex,
along its own vector, is the image; a tip ahead of it may be run-on ink
(up to 0.9 mm ahead in a thin polygon), and the vertex stays.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4, Sec. 3.5, Sec. 4.2.
"""

from __future__ import annotations

import numpy as np

__all__ = ["tip_behind"]

_ON_OWN_MM = 0.5
"""A point lies on a vector's line: within this of it (a tip is found to 0.1-0.3 mm)."""
_AHEAD_MM = 1.5
"""The ends' vertex slides past the tip along a band by up to this (0.97 mm in sample
20261202 #18); a tip 2.4-2.5 mm behind it is a false one, where a link line run on past
the image crosses the vector (20261130 #49 at mild, 20261129 #35 at scan)."""


def tip_behind(segs: np.ndarray, tips: np.ndarray, v: np.ndarray, pole: np.ndarray,
               same_mm: float, ray_mm: float, past_mm: float, narrow_sin: float
               ) -> np.ndarray:
    """The image: the vertex ``v``, or the arrowhead's tip it lies ahead of (mm).

    Parameters
    ----------
    segs : ndarray (n, 2, 2)
        The pencil segments (sheet mm).
    tips : ndarray (k, 2)
        The arrowheads' tips found at the places images can be (sheet mm).
    v : ndarray (2,)
        The vertex read where the segments ending there meet (sheet mm).
    pole : ndarray (2,)
        The printed pole (sheet mm).
    same_mm : float
        A tip within this of ``v``, and a segment ending within it of the
        tip, are at one vertex.
    ray_mm : float
        A segment whose line passes within this of the pole is a vector from it.
    past_mm : float
        Another segment, a link line of the image, ends within this of the tip.
    narrow_sin : float
        The sine of the angle over which that line crosses the vector's axis.

    Returns
    -------
    ndarray (2,)
        The nearest tip within ``same_mm`` of ``v`` when a segment ending
        within ``same_mm`` of it is its own vector (its line through the
        pole within ``ray_mm``, the tip within 0.5 mm of it), another segment
        crossing its axis at over the narrow angle ends within ``past_mm`` of
        the tip (Secs. 3.5, 4.2: the image's lines
        end there too; a tip found where a line merging with the vector's ink
        leaves it has none), and ``v`` lies
        on that vector's line (within 0.5 mm) 0.5-1.5 mm beyond the tip,
        away from the pole (Sec. 3.4: the vector ends at its arrowhead);
        ``v`` otherwise.
    """
    v = np.asarray(v, dtype=float)
    tips = np.asarray(tips, dtype=float).reshape(-1, 2)
    if not len(tips) or not len(segs):
        return v
    dist = np.hypot(*(tips - v).T)
    i = int(np.argmin(dist))
    t = tips[i]
    if float(dist[i]) >= same_mm:
        return v
    a, b = segs[:, 0], segs[:, 1]
    d = b - a
    length = np.hypot(*d.T)
    u = d / np.maximum(length, 1e-12)[:, None]

    def off(p: np.ndarray) -> np.ndarray:
        """Each segment's line's distance from ``p`` (mm)."""
        w = p - a
        return np.asarray(np.abs(u[:, 0] * w[:, 1] - u[:, 1] * w[:, 0]))

    end = np.minimum(np.hypot(*(a - t).T), np.hypot(*(b - t).T)) < same_mm
    own = end & (length > 0) & (off(pole) <= ray_mm) & (off(t) <= _ON_OWN_MM)
    if not own.any():
        return v
    k = int(np.flatnonzero(own)[0])
    # a link line of the image crossing the vector ends at the tip (within past_mm of it):
    # the tip is at the image's vertex, not where a line merging with the vector's ink
    # leaves it
    reach = float(np.hypot(*(t - pole)))
    axis = (t - pole) / max(reach, 1e-12)
    near = np.minimum(np.hypot(*(a - t).T), np.hypot(*(b - t).T)) <= past_mm
    near &= np.abs(u[:, 0] * axis[1] - u[:, 1] * axis[0]) > narrow_sin
    near[k] = False
    if not near.any():
        return v
    ahead = float((v - t) @ axis)
    if _ON_OWN_MM < ahead <= _AHEAD_MM and float(off(v)[k]) <= _ON_OWN_MM:
        return t.copy()
    return v
