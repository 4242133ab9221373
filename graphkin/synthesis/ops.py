"""Bisectors, mirrors and circles on a chord: the steps of the synthesis constructions.

The poles of finite displacements, the pole triangle's image points and the
center-point curve (Ch. 9) are drawn with three more compass-and-straightedge
acts (registered in :data:`graphkin.construction.ops.OPS` when
:mod:`graphkin.synthesis` is imported, as the force operations are): the
perpendicular bisector of a segment, the mirror image of a point in
a line, and a circle drawn on a given chord with its center on the chord's
bisector (Fig. 9.20).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.3-9.5 (Figs. 9.5, 9.10, 9.20).
"""

from __future__ import annotations

import numpy as np

from graphkin.construction.ops import OPS, op
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray

_NEW = ("bisector", "reflect", "circle_on_chord", "circle_through")
_TAKEN = [name for name in _NEW if name in OPS]
if _TAKEN:  # pragma: no cover - two packages registering one name is a merge mistake
    raise ImportError(f"construction operations {_TAKEN} are registered twice")


@op("bisector", kind="line")
def _bisector(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The perpendicular bisector of PQ, directed 90° counterclockwise from P → Q.

    Every point of it is as far from P as from Q (the pole P12 lies on the
    bisector of A1A2, Sec. 9.3).  Coincident P and Q give NaN.
    """
    return (g.perpendicular(g.join(p, q, tol), g.midpoint(p, q)),)


@op("reflect")
def _reflect(p: Array, line: Array, *, tol: Tolerance) -> tuple[Array]:
    """The mirror image of P in a line (an image point across a side, Sec. 9.4)."""
    return (g.reflect(p, line),)


@op("circle_on_chord", kind="circle")
def _circle_on_chord(p: Array, q: Array, t: Array, *, tol: Tolerance) -> tuple[Array]:
    """The circle through P and Q whose center stands ``t`` half-chords right of the chord.

    The center is ``M + t (c/2) n`` where M is the chord's midpoint, ``c = |PQ|``
    and n the unit normal to the right of P → Q ("standing at P looking toward
    Q, the center to our right", Sec. 9.5); the radius is ``(c/2) √(1 + t²)``.
    Every point of the circle sees PQ under the same directed angle (mod 180°),
    whose cotangent is ``t``; two chords drawn with the same ``t`` have radii in
    the ratio of the chords (Eq. 9.19).
    """
    a, b = g.xy(p), g.xy(q)
    t = np.asarray(t, dtype=float)
    half = (b - a) / 2.0
    mid = a + half
    right = np.stack([half[..., 1], -half[..., 0]], axis=-1)
    center = mid + t[..., None] * right
    radius = np.hypot(half[..., 0], half[..., 1]) * np.sqrt(1.0 + t * t)
    return (np.concatenate([center, radius[..., None]], axis=-1),)


@op("circle_through", kind="circle")
def _circle_through(c: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """The circle about C through P (the circle the circle point runs on)."""
    return (g.circle(c, g.distance(c, p)),)
