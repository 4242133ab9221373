"""``ball_point``: Ball's point U of any posture, continuous through N = ∞.

The cubic of stationary curvature (Sec. 4.17, Eq. 4.57) is, in coordinates
``x`` along the centrode tangent ``T`` and ``y`` along the normal ``N`` from
the velocity pole ``I``,

    ``(x² + y²)(x/M - y/N) = xy``,

linear in ``1/M`` and ``1/N``.  Measured in units of the inflection
diameter ``d = R_JI`` (``x̂ = x/d``, ``ŷ = y/d``) each point of constant
path curvature of the link (a pin to a link turning about a frame pivot, a
point held on a frame-fixed line: two of them, ``A`` and ``B``) gives one
homogeneous linear equation in ``(d/M, d/N, 1)``:

    ``ŝ x̂ · (d/M) - ŝ ŷ · (d/N) - x̂ ŷ · 1 = 0``,   ``ŝ = x̂² + ŷ²``,

so ``(μ, ν, κ) = row_A × row_B`` is proportional to ``(d/M, d/N, 1)``.
``N = ∞`` is ``ν = 0`` and ``M = ∞`` is ``μ = 0``: finite numbers, no test.
On the inflection circle ``x̂² + ŷ² = ŷ`` Eq. 4.57 becomes the line through
``I``

    ``x̂ (d/M - 1) = (d/N) ŷ``,  direction ``(ν, μ - κ)`` in ``(T, N)``,

and Ball's point ``U`` is where that line meets the circle again: the
projection of ``R_JI`` on it (Thales: ``IU ⊥ JU``),

    ``U = I + q (p t + q u) / (p² + q²)``,  ``p = ν``, ``q = μ - κ``,

``u = J - I`` and ``t = (u_y, -u_x)`` (``T`` to the length ``d``: the
positive centrode tangent is ``N`` turned 90° clockwise).  At ``N = ∞``
(``p = 0``) it is ``U = I + u = J`` by the formula itself (Example 4.16);
near it ``U`` moves continuously.  The result does not depend on the sense
of ``T`` nor on the scale of ``(μ, ν, κ)``.

``U`` is none (NaN; the written-out function's ``null``) where the formula
has no answer, each decided on a value clearly above round-off of its own
scale (:class:`~graphkin.tolerance.Tolerance`):

* ``J`` at ``I`` (``d`` within the length tolerance of the figure around
  ``I``): a link turning about a frame pivot, whose inflection circle is a
  point;
* ``A`` and ``B`` do not determine the cubic (``row_A × row_B`` round-off of
  ``|row_A| |row_B|``);
* the cubic contains the whole inflection circle (``d/M = 1``, ``d/N = 0``:
  ``p² + q²`` round-off of ``|(μ, ν, κ)|²``);
* the line touches the circle at ``I`` (``|q|`` round-off of ``√(p² + q²)``):
  the cubic meets it only at ``I``, no finite Ball's point off ``I``.

The operation is an entry of the table both writers read
(``@template("ball_point")``): the JavaScript writer (the live page's
curvature panel) and the Python writer write the template; the replay calls
the numpy function.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 4.17 (Eqs. 4.55-4.57, Ball's point,
Fig. 4.38, Example 4.16).
"""

from __future__ import annotations

import numpy as np

from graphkin.construction.codegen import Gen, lit, template
from graphkin.construction.ops.registry import op
from graphkin.construction.step import Step
from graphkin.geometry.ops import xy as _xy
from graphkin.tolerance import Tolerance

__all__: list[str] = []

Array = np.ndarray


def _row(r: Array, t: Array, u: Array, dd: Array) -> Array:
    """``(ŝ x̂, -ŝ ŷ, -x̂ ŷ)`` of a point ``I + r`` (Eq. 4.57 in units of ``d``)."""
    x = (r[..., 0] * t[..., 0] + r[..., 1] * t[..., 1]) / dd
    y = (r[..., 0] * u[..., 0] + r[..., 1] * u[..., 1]) / dd
    s = x * x + y * y
    return np.stack([s * x, -s * y, -x * y], axis=-1)


@op("ball_point")
def _ball_point(i: Array, j: Array, a: Array, b: Array, *, tol: Tolerance) -> tuple[Array]:
    """Ball's point U from I, J and two points of the cubic (module docstring); NaN if none."""
    pi, pj, pa, pb = _xy(i), _xy(j), _xy(a), _xy(b)
    u = pj - pi
    t = np.stack([u[..., 1], -u[..., 0]], axis=-1)
    ra, rb = pa - pi, pb - pi
    dd = u[..., 0] ** 2 + u[..., 1] ** 2
    size = np.sqrt(np.maximum(dd, np.maximum(ra[..., 0] ** 2 + ra[..., 1] ** 2,
                                              rb[..., 0] ** 2 + rb[..., 1] ** 2)))
    lt = tol.length(size)
    ok = dd - lt * lt > 0.0
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        safe = np.where(ok, dd, 1.0)
        row_a, row_b = _row(ra, t, u, safe), _row(rb, t, u, safe)
        mu, nu, ka = np.moveaxis(np.cross(row_a, row_b), -1, 0)
        na = np.sum(row_a * row_a, axis=-1)
        nb = np.sum(row_b * row_b, axis=-1)
        q3 = mu * mu + nu * nu + ka * ka
        p, q = nu, mu - ka
        h2 = p * p + q * q
        ang2 = tol.angle * tol.angle
        ok = ok & (q3 - ang2 * na * nb > 0.0) & (h2 - ang2 * q3 > 0.0) & (q * q - ang2 * h2 > 0.0)
        k = np.where(ok, q / np.where(ok, h2, 1.0), np.nan)
        ux = k * (p * t[..., 0] + q * u[..., 0])
        uy = k * (p * t[..., 1] + q * u[..., 1])
    g = pi + np.stack([ux, uy], axis=-1)
    return (np.concatenate([g, np.ones((*g.shape[:-1], 1))], axis=-1),)


def _row_js(gen: Gen, rx: str, ry: str, tx: str, ty: str, ux: str, uy: str,
            dd: str) -> tuple[str, str, str, str]:
    """The row of Eq. 4.57 of a point ``I + (rx, ry)`` and its squared length."""
    x = gen.let(f"({rx} * {tx} + {ry} * {ty}) / {dd}", "x")
    y = gen.let(f"({rx} * {ux} + {ry} * {uy}) / {dd}", "y")
    s = gen.let(f"{x} * {x} + {y} * {y}", "s")
    r0, r1, r2 = (gen.let(e, "r") for e in (f"{s} * {x}", f"-{s} * {y}", f"-{x} * {y}"))
    return r0, r1, r2, gen.let(f"{r0} * {r0} + {r1} * {r1} + {r2} * {r2}", "n")


@template("ball_point")
def _ball_point_js(gen: Gen, step: Step) -> None:
    tol = gen.tol
    ix, iy = gen.pt(step.inputs[0])
    jx, jy = gen.pt(step.inputs[1])
    ax, ay = gen.pt(step.inputs[2])
    bx, by = gen.pt(step.inputs[3])
    ux, uy = gen.let(gen.sub(jx, ix), "dx"), gen.let(gen.sub(jy, iy), "dy")
    tx, ty = uy, gen.neg(ux)  # T to the length d: N turned 90° clockwise
    rax, ray = gen.let(gen.sub(ax, ix), "dx"), gen.let(gen.sub(ay, iy), "dy")
    rbx, rby = gen.let(gen.sub(bx, ix), "dx"), gen.let(gen.sub(by, iy), "dy")
    dd = gen.let(f"{ux} * {ux} + {uy} * {uy}", "dd")
    size = gen.let(f"_sqrt(_maximum({dd}, _maximum({rax} * {rax} + {ray} * {ray}, "
                   f"{rbx} * {rbx} + {rby} * {rby})))", "L")
    lt = gen.let(f"{lit(tol.length_abs)} + {lit(tol.length_rel)} * {size}", "e")
    # J not at I (not a link turning about a frame pivot)
    gen.bail_unless(f"_min({dd} - {lt} * {lt}, None) > 0.0")
    a0, a1, a2, na = _row_js(gen, rax, ray, tx, ty, ux, uy, dd)
    b0, b1, b2, nb = _row_js(gen, rbx, rby, tx, ty, ux, uy, dd)
    mu = gen.let(f"{a1} * {b2} - {a2} * {b1}", "m")
    nu = gen.let(f"{a2} * {b0} - {a0} * {b2}", "m")
    ka = gen.let(f"{a0} * {b1} - {a1} * {b0}", "m")
    q3 = gen.let(f"{mu} * {mu} + {nu} * {nu} + {ka} * {ka}", "n")
    ang2 = lit(tol.angle * tol.angle)
    # A and B determine the cubic; it does not contain the whole circle; U is not I
    gen.bail_unless(f"_min({q3} - {ang2} * {na} * {nb}, None) > 0.0")
    q = gen.let(f"{mu} - {ka}", "q")
    h2 = gen.let(f"{nu} * {nu} + {q} * {q}", "h")
    gen.bail_unless(f"_min({h2} - {ang2} * {q3}, None) > 0.0")
    gen.bail_unless(f"_min({q} * {q} - {ang2} * {h2}, None) > 0.0")
    k = gen.let(f"{q} / {h2}", "k")
    gen.put_point(step.outputs[0], f"{ix} + {k} * ({nu} * {tx} + {q} * {ux})",
                  f"{iy} + {k} * ({nu} * {ty} + {q} * {uy})")
