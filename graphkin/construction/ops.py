"""The operations a construction step may perform, by name.

Each operation takes the arrays named by the step's ``inputs`` (any common
leading shape), the step's ``params`` and a tolerance, and returns a tuple of
arrays, one per output.  They are thin wrappers over :mod:`graphkin.geometry.ops`;
none of them loops over postures.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 1-4), 3.4-3.5 and 4.2-4.3
(velocity and acceleration polygons and images).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

__all__ = ["OPS", "op", "OUTPUT_KIND"]

Array = np.ndarray
OPS: dict[str, Callable[..., tuple[Array, ...]]] = {}
OUTPUT_KIND: dict[str, str] = {}


def op(name: str, kind: str = "point") -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Register an operation under ``name``; ``kind`` is the kind of its outputs."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        OPS[name] = f
        OUTPUT_KIND[name] = kind
        return f

    return deco


@op("point")
def _point(*, tol: Tolerance, xy: tuple[float, float]) -> tuple[Array]:
    """A fixed point given by its coordinates (a frame pivot)."""
    return (g.point(*xy),)


@op("ideal_point")
def _ideal(*, tol: Tolerance, direction: tuple[float, float]) -> tuple[Array]:
    """A fixed point at infinity."""
    return (g.ideal_point(*direction),)


@op("rigid")
def _rigid(p: Array, theta: Array, *, tol: Tolerance, local_p: tuple[float, float],
           local_q: tuple[float, float], offset: float = 0.0) -> tuple[Array]:
    """Lay off a link: ``Q = P + R(θ + offset)(q - p)`` (case 1: magnitude and direction known)."""
    d = np.subtract(local_q, local_p)
    v = g.rotate(d, np.asarray(theta) + offset)
    return (g.translate(p, v),)


@op("similar")
def _similar(a: Array, b: Array, *, tol: Tolerance, local_a: tuple[float, float],
             local_b: tuple[float, float], local_p: tuple[float, float]) -> tuple[Array]:
    """The image of a point similar to its link (placement, velocity and acceleration images)."""
    return (g.similar_point(a, b, local_a, local_b, local_p),)


@op("link_angle", kind="scalar")
def _link_angle(a: Array, b: Array, *, tol: Tolerance, local_a: tuple[float, float],
                local_b: tuple[float, float]) -> tuple[Array]:
    """Angle of a link's x axis from two of its placed points."""
    d = g.xy(b) - g.xy(a)
    dl = np.subtract(local_b, local_a)
    return (np.arctan2(d[..., 1], d[..., 0]) - np.arctan2(dl[1], dl[0]),)


@op("add_angle", kind="scalar")
def _add_angle(theta: Array, *, tol: Tolerance, offset: float) -> tuple[Array]:
    """An angle that differs from a known one by a constant (a slider keeps its angle)."""
    return (np.asarray(theta) + offset,)


@op("circle", kind="circle")
def _circle(center: Array, *, tol: Tolerance, radius: float) -> tuple[Array]:
    """Draw a circle of known radius about a point."""
    return (g.circle(center, radius),)


@op("circle_on_diameter", kind="circle")
def _thales(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The circle on the diameter PQ (Thales: every point sees PQ at a right angle)."""
    return (g.circle(g.midpoint(p, q), g.distance(p, q) / 2),)


@op("intersect_circles")
def _cc(c1: Array, c2: Array, *, tol: Tolerance, branch: str) -> tuple[Array]:
    """Intersect two arcs (case 4) and keep the named branch."""
    left, right = g.intersect_circles(c1, c2, tol)
    return (left if branch == "left" else right,)


@op("intersect_line_circle")
def _lc(line: Array, c: Array, *, tol: Tolerance, branch: str) -> tuple[Array]:
    """Intersect a line and an arc (case 2) and keep the named branch."""
    behind, ahead = g.intersect_line_circle(line, c, tol)
    return (behind if branch == "behind" else ahead,)


@op("join", kind="line")
def _join(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """Draw the line through two points."""
    return (g.join(p, q, tol),)


@op("meet")
def _meet(l1: Array, l2: Array, *, tol: Tolerance) -> tuple[Array]:
    """Intersect two lines (case 3); the result may be a point at infinity."""
    return (g.meet(l1, l2, tol),)


@op("line_at_angle", kind="line")
def _line_at_angle(p: Array, theta: Array, *, tol: Tolerance, offset: float = 0.0) -> tuple[Array]:
    """The line through P at the angle θ + offset."""
    t = np.asarray(theta) + offset
    return (g.line_through(p, g.vector(np.cos(t), np.sin(t))),)


@op("parallel", kind="line")
def _parallel(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P draw a line parallel to a given line."""
    return (g.parallel(line, p),)


@op("perpendicular", kind="line")
def _perpendicular(line: Array, p: Array, *, tol: Tolerance) -> tuple[Array]:
    """Through P draw a line perpendicular to a given line."""
    return (g.perpendicular(line, p),)


@op("translate")
def _translate(p: Array, v: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known vector from a point (case 1)."""
    return (g.translate(p, v),)


@op("vector", kind="vector")
def _vector(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """The vector from P to Q."""
    return (g.xy(q) - g.xy(p),)


@op("scale_vector", kind="vector")
def _scale_vector(v: Array, s: Array, *, tol: Tolerance, factor: float = 1.0) -> tuple[Array]:
    """A vector times a scalar (and a constant factor)."""
    return (np.asarray(v) * (np.asarray(s) * factor)[..., None],)
