"""Pure numpy geometry in homogeneous coordinates (points at infinity included).

Two layers, one engine:

* :mod:`graphkin.geometry.ops` works on arrays of shape ``(..., 3)`` and
  broadcasts, so one recorded construction runs on one posture or a sweep; it
  never raises and answers NaN where there is no answer.
* The small frozen values re-exported here (:class:`Point`, :class:`Vector`,
  :class:`Line`, :class:`Circle`) and the functions on them (:func:`join`,
  :func:`meet`, :func:`intersect`, ...) are views onto those functions for the
  public API and the drawings.  They return tuples of 0, 1 or 2 points in a
  documented order and raise :class:`~graphkin.errors.DegenerateError` only for
  true degeneracy (coincident points or lines).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed., Sec. 2.8.
"""

from graphkin.geometry import ops
from graphkin.geometry.circle import Circle, intersect
from graphkin.geometry.line import (
    Line,
    angle_between,
    join,
    meet,
    parallel,
    perpendicular,
    project,
    reflect,
)
from graphkin.geometry.point import Point, Vector, midpoint
from graphkin.geometry.predicates import are_collinear, are_concurrent, is_on, is_parallel

__all__ = [
    "ops",
    "Point",
    "Vector",
    "Line",
    "Circle",
    "join",
    "meet",
    "intersect",
    "parallel",
    "perpendicular",
    "project",
    "reflect",
    "midpoint",
    "angle_between",
    "is_parallel",
    "are_collinear",
    "are_concurrent",
    "is_on",
]
