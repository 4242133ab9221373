"""Operations on points, vectors and scalars: given points, rigid bodies, sums (Sec. 2.8)."""

from __future__ import annotations

from typing import Any

import numpy as np

from graphkin.construction.ops.registry import op
from graphkin.geometry import ops as g
from graphkin.tolerance import Tolerance

Array = np.ndarray


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


@op("input", kind="scalar")
def _input(*, tol: Tolerance, name: str) -> tuple[Array]:  # pragma: no cover - never called
    """A given input (a drive angle or travel): its value is supplied at evaluation."""
    raise KeyError(name)


@op("scalar", kind="scalar")
def _scalar(*, tol: Tolerance, value: float) -> tuple[Array]:
    """A constant (the frame's angle)."""
    return (np.asarray(float(value)),)


@op("along_line")
def _along_line(p0: Array, p1: Array, s: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off the travel ``s`` from P0 toward P1 (a slider's given position)."""
    a, b = g.xy(p0), g.xy(p1)
    d = b - a
    n = np.hypot(d[..., 0], d[..., 1])
    q = a + d * (np.asarray(s) / n)[..., None]
    return (g.point(q[..., 0], q[..., 1]),)


@op("add_along")
def _add_along(p: Array, p0: Array, p1: Array, s: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known amount ``s`` along the direction P0 → P1 from a point."""
    d = g.xy(p1) - g.xy(p0)
    n = np.hypot(d[..., 0], d[..., 1])
    return (g.translate(p, d * (np.asarray(s) / n)[..., None]),)


@op("subtract")
def _subtract(p: Array, v: Array, *, tol: Tolerance) -> tuple[Array]:
    """Lay off a known vector backward from a point (vector subtraction)."""
    return (g.translate(p, -np.asarray(v)),)

# ---- instant centers and curvature ------------------------------------------------

@op("at_infinity_on")
def _at_infinity_on(line: Array, *, tol: Tolerance) -> tuple[Array]:
    """The point at infinity of a line (where it meets every parallel to it)."""
    d = g.direction(line)
    return (g.ideal_point(d[..., 0], d[..., 1]),)


@op("same_point")
def _same_point(p: Array, q: Array, *, tol: Tolerance) -> tuple[Array]:
    """Two centers that coincide: a third center is that same point (Kennedy)."""
    return (np.asarray(p, dtype=float).copy(),)


@op("copy_point")
def _copy_point(p: Array, *, tol: Tolerance) -> tuple[Array]:
    """A point that coincides with a known one."""
    return (np.asarray(p, dtype=float).copy(),)


@op("homogeneous_point")
def _homogeneous_point(*, tol: Tolerance, h: Any) -> tuple[Array]:
    """A point given by homogeneous coordinates ``(x, y, w)``, finite or at infinity."""
    return (g.normalize_point(np.asarray(h, dtype=float), tol),)


@op("parallelogram")
def _parallelogram(p: Array, a: Array, b: Array, *, tol: Tolerance) -> tuple[Array]:
    """Complete the parallelogram P, A, G, B: ``G = A + B - P``.

    A vertex at infinity makes the opposite vertex that same point at infinity
    (the two sides through it are parallel to it).
    """
    p, a, b = (np.asarray(x, dtype=float) for x in (p, a, b))
    fin = g.point(*np.moveaxis(g.xy(a) + g.xy(b) - g.xy(p), -1, 0))
    out = np.where(g.is_ideal(b)[..., None], b, fin)
    return (np.where(g.is_ideal(a)[..., None], a, out),)


@op("along_ray")
def _along_ray(o: Array, x: Array, *, tol: Tolerance, distance: float) -> tuple[Array]:
    """The point at a known distance from O toward X (a contact point on the line of centers)."""
    a, b = g.xy(o), g.xy(x)
    d = b - a
    n = np.hypot(d[..., 0], d[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        q = a + d * (distance / n)[..., None]
    return (g.point(q[..., 0], q[..., 1]),)
