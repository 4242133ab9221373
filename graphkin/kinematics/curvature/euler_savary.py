"""The Euler-Savary equation (Sec. 4.16, Eqs. 4.41-4.43) and its construction operation."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction.codegen import Gen, NeedGeneric, template
from graphkin.construction.ops import OPS, op
from graphkin.construction.step import Step
from graphkin.geometry import ops as g
from graphkin.kinematics.curvature._vec import _dot, _xy
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["euler_savary", "inflection_points_on_ray", "radius_of_curvature"]

Array = np.ndarray

# ---------------------------------------------------------------------------
# the one construction operation that is curvature's own
# ---------------------------------------------------------------------------

def _register() -> None:
    if "euler_savary_inflection" not in OPS:
        @op("euler_savary_inflection")
        def _es_inflection(i: Array, a: Array, a_conj: Array, *,
                           tol: Tolerance) -> tuple[Array]:
            """Lay off ``R_AJ_A = R_AI²/R_AA'`` from A along the ray (Eq. 4.43): J_A."""
            return (inflection_points_on_ray(i, a, a_conj),)

_register()


@template("euler_savary_inflection")
def _es_inflection_template(gen: Gen, step: Step) -> None:
    """The template of the lay-off (one table for both writers: the live page's curvature).

    The arithmetic of :func:`inflection_points_on_ray`, on one posture or rows
    of postures: ``u`` the unit ray from I through A, ``x_A = |A - I|``,
    ``x_A' = (A' - I)·u`` and ``J_A = I + u x_A x_A'/(x_A' - x_A)`` (Eq. 4.43);
    ``J_A = A`` when A' is at infinity (the JavaScript writer's center of
    curvature normal to a slider's line, given as ``[x, y, 0]``).  A ray of no
    length or ``A' = A`` (the general function divides by zero) is not clean.
    """
    i, a, c = step.inputs
    if getattr(gen, "homogeneous", False):
        raise NeedGeneric(c)  # the centers' writer: no curvature there
    ax, ay = gen.pt(a)
    cv = gen.val(c)
    if cv.form == "rows" and cv.kind == "point":
        gen.bail_unless(f"{cv.ex[2]} == 0.0")
        gen.put_point(step.outputs[0], ax, ay)
        return
    ix, iy = gen.pt(i)
    cx, cy = gen.pt(c)
    wx, wy = gen.let(gen.sub(ax, ix), "dx"), gen.let(gen.sub(ay, iy), "dy")
    xa = gen.let(f"_sqrt({gen.add(gen.mul(wx, wx), gen.mul(wy, wy))})", "n")
    gen.bail_unless(f"_min({xa}, None) > 0.0")
    ux, uy = gen.let(f"{wx} / {xa}", "c"), gen.let(f"{wy} / {xa}", "s")
    xc = gen.add(gen.mul(gen.sub(cx, ix), ux), gen.mul(gen.sub(cy, iy), uy))
    den = gen.let(gen.sub(xc, xa), "d")
    gen.bail_unless(f"_min(_abs({den}), None) > 0.0")
    xj = gen.let(f"{xa} * {xc} / {den}", "k")
    gen.put_point(step.outputs[0], gen.add(ix, gen.mul(xj, ux)), gen.add(iy, gen.mul(xj, uy)))


def euler_savary(pole: ArrayLike, inflection_pole: ArrayLike, point: ArrayLike,
                 tol: Tolerance | None = None, scale: float = 0.0) -> Array:
    """The conjugate point (center of curvature of the path) of a point, by Euler-Savary.

    With positions measured from the velocity pole ``I`` along the ray
    through the point ``A``, Eq. 4.42 reads ``1/x_A - 1/x_A' = 1/x_J`` where
    ``x_J = R_JI sin ψ`` (Eq. 4.41) is where the ray meets the inflection
    circle again.  Writing ``r² = |A - I|²`` and ``q = (J - I)·(A - I)``, this is
    ``A' = I + q (A - I)/(q - r²)`` and ``ρ = R_AA' = r³/|r² - q|`` (Eq. 4.43).

    Parameters
    ----------
    pole, inflection_pole, point : array_like, shape (..., 2) or (..., 3)
        ``I``, ``J`` and ``A`` (finite points).
    tol : Tolerance, optional
    scale : float
        Size of the figure.  The path is taken as straight when
        ``ρ ≥ s/tol.angle`` with ``s = max(scale, R_AI, R_JI)``, and ``A`` as at
        rest when ``R_AI ≤ tol.length(s)``.

    Returns
    -------
    ndarray, shape (..., 3)
        ``A'`` in homogeneous coordinates: finite; at infinity along the ray
        when ``A`` is on the inflection circle (its path is straight here);
        NaN when ``A`` is at ``I`` (it is at rest).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.12, Eqs. 4.41-4.43.

    Examples
    --------
    A wheel of radius 1 rolling on the x axis: ``I`` is the contact point and
    ``J`` the wheel's center.  The top of the wheel has its center of
    curvature 4 radii below it (the cycloid's apex); the center moves straight.

    >>> euler_savary([0, 0], [0, 1], [0, 2])
    array([ 0., -2.,  1.])
    >>> euler_savary([0, 0], [0, 1], [0, 1])
    array([0., 1., 0.])
    """
    tol = tol or DEFAULT_TOL
    i, j, a = _xy(pole), _xy(inflection_pole), _xy(point)
    w = a - i
    r2 = _dot(w, w)
    r = np.sqrt(r2)
    q = _dot(j - i, w)
    s = np.maximum(np.maximum(r, np.hypot(*np.moveaxis(j - i, -1, 0))), scale)
    rest = r <= tol.length(s)
    den = q - r2
    straight = ~rest & (np.abs(den) * s <= tol.angle * r2 * r)
    with np.errstate(invalid="ignore", divide="ignore"):
        f = q / np.where(straight | rest, 1.0, den)
        fin = i + f[..., None] * w
        ray = w / np.where(rest, 1.0, r)[..., None]
    out = np.concatenate([fin, np.ones_like(r)[..., None]], axis=-1)
    ideal = g.ideal_point(ray[..., 0], ray[..., 1])
    out = np.where(straight[..., None], ideal, out)
    return np.where(rest[..., None], np.nan, out) + 0.0


def inflection_points_on_ray(pole: ArrayLike, point: ArrayLike, conjugate: ArrayLike) -> Array:
    """The inflection point ``J_A`` on the ray ``IA`` from a pair of conjugate points ``A, A'``.

    Eq. 4.43 laid off from ``A``: ``R_AJ_A = R_AI²/R_AA'``.  When ``A'`` is at
    infinity (``A`` moves on a straight line), ``J_A = A``.

    Parameters
    ----------
    pole : array_like, shape (..., 2) or (..., 3)
        The velocity pole ``I``.
    point : array_like
        ``A``.
    conjugate : array_like, shape (..., 3)
        ``A'``, finite or at infinity (homogeneous).

    Returns
    -------
    ndarray, shape (..., 3)

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Eq. 4.43 and Examples 4.12, 4.14, 4.16.

    Examples
    --------
    Example 4.16: ``R_AI = 2`` in, ``A' = O_2`` 1 in from ``A``; ``J_A`` is 4 in from ``A``.

    >>> inflection_points_on_ray([0, -1], [0, 1], [0, 0, 1])
    array([ 0., -3.,  1.])
    """
    i, a = _xy(pole), _xy(point)
    c = np.asarray(conjugate, dtype=float)
    w = a - i
    xa = np.hypot(w[..., 0], w[..., 1])
    with np.errstate(invalid="ignore", divide="ignore"):
        u = w / xa[..., None]
        xc = _dot(_xy(c) - i, u)
        xj = xa * xc / (xc - xa)
    fin = i + xj[..., None] * u
    out = np.where(g.is_ideal(c)[..., None], a, fin)
    return g.point(out[..., 0], out[..., 1])


def radius_of_curvature(point: ArrayLike, conjugate: ArrayLike) -> Array:
    """``ρ = R_AA'``, the distance from a point to its conjugate (Eq. 4.43); ``inf`` if ideal.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.12, Eq. 4.43.

    Examples
    --------
    >>> radius_of_curvature([0, 2], euler_savary([0, 0], [0, 1], [0, 2]))
    array(4.)
    >>> radius_of_curvature([0, 1], euler_savary([0, 0], [0, 1], [0, 1]))
    array(inf)
    """
    c = np.asarray(conjugate, dtype=float)
    with np.errstate(invalid="ignore"):
        d = g.distance(g.point(*np.moveaxis(_xy(point), -1, 0)), c)
    return np.where(g.is_ideal(c), np.inf, d)
