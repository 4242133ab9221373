"""Pure numpy geometry in homogeneous coordinates (points at infinity included)."""

from graphkin.geometry import ops
from graphkin.geometry.ops import (
    intersect_circles,
    intersect_line_circle,
    join,
    meet,
    parallel,
    perpendicular,
)

__all__ = ["ops", "join", "meet", "parallel", "perpendicular", "intersect_circles",
           "intersect_line_circle"]
