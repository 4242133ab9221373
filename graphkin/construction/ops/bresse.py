"""``bresse_circle`` and ``acceleration_center``: the Bresse circle and Γ of any posture.

The Bresse circle of a moving link (the points with no tangential
acceleration) passes through the velocity pole ``I`` with its diameter
``b = R_JI ω²/α`` laid off along the centrode tangent (Eq. 4.48):
``E = I + (ω²/α) k × R_JI``.  It meets the inflection circle (diameter
``IJ``) at ``I`` and at the instantaneous center of acceleration ``Γ``
(Sec. 4.15, Fig. 4.34).  ``Γ`` sees both ``IJ`` and ``IE`` at a right
angle, so it is the foot of the perpendicular from ``I`` on ``JE``; with
``u = R_JI`` that is

    ``Γ = I + (ω⁴ u + ω² α k × u) / (ω⁴ + α²)``

(``R_ΓI`` is ``N`` turned by ``γ = tan⁻¹(α/ω²)``, Eq. 4.44, of length
``|u| cos γ``), which holds whatever ``α`` is: at ``α = 0`` the Bresse
circle becomes the centrode normal and ``Γ = J``.

The recorded curvature construction lays off ``E`` with the file's ratio
``ω²/α`` (a ``similar`` step) or, where ``α = 0`` in the file, copies ``J``
to ``Γ``; either holds at the file's posture only.  These two operations
take ``ω``, ``α`` and the mechanism's scale of accelerations ``ref``
(``max ω² + |α|`` over its links, rad/s²) as parameters and decide at each
posture they are evaluated on, as the construction does
(:mod:`graphkin.kinematics.curvature.construction`): ``α`` is zero when
``|α| <= tol.angle · ref``.  There the circle is none (NaN; the
written-out function's ``null``) and ``Γ`` is ``J`` itself.

The operations are entries of the table both writers read
(``@template(..., python=False)``): the JavaScript writer writes the
templates; the Python writer and the replay call the numpy functions, which
the templates are tested against (tests/render/test_live_bresse.py).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.13-4.15 (the inflection circle,
Eq. 4.44; the Bresse circle, Eq. 4.48, Fig. 4.34).
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


def _alpha_zero(alpha: float, ref: float, tol: Tolerance) -> bool:
    """α is round-off of the mechanism's accelerations (as the curvature construction says)."""
    return abs(float(alpha)) <= tol.angle * float(ref)


@op("bresse_circle", kind="circle")
def _bresse_circle(i: Array, j: Array, *, tol: Tolerance, omega: float, alpha: float,
                   ref: float) -> tuple[Array]:
    """The Bresse circle on ``IE``, ``E = I + (ω²/α) k × R_JI`` (Eq. 4.48); NaN at α = 0."""
    pi, pj = _xy(i), _xy(j)
    if _alpha_zero(alpha, ref, tol):
        return (np.full((*np.broadcast_shapes(pi.shape, pj.shape)[:-1], 3), np.nan),)
    k = float(omega) ** 2 / float(alpha)
    u = pj - pi
    half = 0.5 * k * np.stack([-u[..., 1], u[..., 0]], axis=-1)
    r = 0.5 * abs(k) * np.hypot(u[..., 0], u[..., 1])
    return (np.concatenate([pi + half, r[..., None]], axis=-1),)


@op("acceleration_center")
def _acceleration_center(i: Array, j: Array, *, tol: Tolerance, omega: float, alpha: float,
                         ref: float) -> tuple[Array]:
    """Γ, the second meet of the inflection and Bresse circles (module docstring); J at α = 0."""
    pi, pj = _xy(i), _xy(j)
    u = pj - pi
    if _alpha_zero(alpha, ref, tol):
        g = pj
    else:
        w2, a = float(omega) ** 2, float(alpha)
        d = w2 * w2 + a * a
        g = pi + (w2 * w2 * u + w2 * a * np.stack([-u[..., 1], u[..., 0]], axis=-1)) / d
    return (np.concatenate([g, np.ones((*g.shape[:-1], 1))], axis=-1),)


def _rates(gen: Gen, step: Step) -> tuple[str, str, str]:
    """ω, α and ``ref`` (entries of ``K`` the page sets per posture) and whether α is not zero."""
    w = gen.num(step.params["omega"])
    a = gen.num(step.params["alpha"])
    ref = gen.num(step.params["ref"])
    some = gen.let(f"_abs({a}) > {lit(gen.tol.angle)} * {ref}", "ok")
    return w, a, some


@template("bresse_circle", python=False)
def _bresse_circle_js(gen: Gen, step: Step) -> None:
    w, a, some = _rates(gen, step)
    ix, iy = gen.pt(step.inputs[0])
    jx, jy = gen.pt(step.inputs[1])
    gen.bail_unless(some)
    k = gen.let(f"{w} * {w} / {a}", "k")
    ux, uy = gen.let(gen.sub(jx, ix), "dx"), gen.let(gen.sub(jy, iy), "dy")
    # the center I + (k/2) k × u, the radius |k| |u| / 2
    gen.put_rows(step.outputs[0], "circle", gen.sub(ix, f"0.5 * {k} * {uy}"),
                 gen.add(iy, f"0.5 * {k} * {ux}"),
                 f"0.5 * _abs({k}) * _sqrt({ux} * {ux} + {uy} * {uy})")


@template("acceleration_center", python=False)
def _acceleration_center_js(gen: Gen, step: Step) -> None:
    w, a, some = _rates(gen, step)
    ix, iy = gen.pt(step.inputs[0])
    jx, jy = gen.pt(step.inputs[1])
    ux, uy = gen.let(gen.sub(jx, ix), "dx"), gen.let(gen.sub(jy, iy), "dy")
    w2 = gen.let(f"{w} * {w}", "w")
    # α taken as 0 where it is round-off: Γ = J exactly (the construction's copy of J)
    az = gen.let(gen.where(some, a, "0.0"), "a")
    d = gen.let(f"{w2} * {w2} + {az} * {az}", "d")
    gen.bail_unless(f"{d} > 0.0")
    gx = gen.where(some, f"{ix} + ({w2} * {w2} * {ux} - {w2} * {az} * {uy}) / {d}", jx)
    gy = gen.where(some, f"{iy} + ({w2} * {w2} * {uy} + {w2} * {az} * {ux}) / {d}", jy)
    gen.put_point(step.outputs[0], gx, gy)
