"""The curvature of a link's motion: the construction evaluated with its closed forms beside it."""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass, field
from functools import partial
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.errors import ConstructionError, GraphkinError
from graphkin.geometry import ops as g
from graphkin.kinematics.curvature._vec import _dot, _sin_angle, _unit
from graphkin.kinematics.curvature.bobillier import _BobillierSteps
from graphkin.kinematics.curvature.bresse import _BresseSteps, bresse_pole
from graphkin.kinematics.curvature.centrodes import centrode_radii
from graphkin.kinematics.curvature.conjugates import _frame_pins
from graphkin.kinematics.curvature.construction import (
    _AGREE,
    _FROM_CIRCLE,
    _RAY_FROM_N,
    _RAYS,
    _USABLE,
    _CurvatureBase,
)
from graphkin.kinematics.curvature.cubic import (
    Cubic,
    _HainSteps,
    ball_point,
    stationary_curvature_cubic,
)
from graphkin.kinematics.curvature.euler_savary import euler_savary
from graphkin.kinematics.curvature.hartmann import _HartmannSteps
from graphkin.kinematics.curvature.inflection import pole_velocity
from graphkin.kinematics.curvature.inflection_circle import _InflectionCircleSteps
from graphkin.kinematics.curvature.paths import PathCurvature, path_curvature
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["LinkCurvature", "link_curvature", "curvature", "curvature_constructions",
           "path_curvatures"]

Array = np.ndarray


class _Curvature(_InflectionCircleSteps, _BobillierSteps, _HartmannSteps, _BresseSteps,
                 _HainSteps, _CurvatureBase):
    """The sections of Secs. 4.12-4.17 for one link, each idea's steps from its own module."""


@dataclass
class LinkCurvature:
    """The curvature theory of one link's motion relative to the frame.

    Attributes
    ----------
    link : str
    omega, alpha : float
    velocity_pole : ndarray, shape (2,)
        ``I`` (the instant center ``I1k``).
    inflection_pole : ndarray, shape (2,)
        ``J``.
    inflection_diameter : float
        ``R_JI``, the inflection circle's diameter.
    normal, tangent : ndarray or None
        Unit positive centrode normal (from ``I`` toward ``J``) and tangent
        (90° clockwise from ``N``); ``None`` when ``J = I``.
    pole_velocity : ndarray
        ``v = ω k × R_JI`` (Eq. 4.47).
    pole_acceleration : ndarray
        ``A_I = ω² R_JI``, the acceleration of the point of the link at ``I``
        (Eq. 4.46), directed from ``I`` toward ``J``.
    acceleration_center : ndarray
        ``Γ``.
    gamma : float
        ``γ = tan⁻¹(α/ω²)`` (Eq. 4.44): ``R_ΓI`` is ``N`` turned by ``γ``.
    bresse_pole : ndarray or None
        The far end of the Bresse circle's diameter from ``I`` (``None`` when ``α = 0``).
    bresse_diameter : float or None
        ``|b| = R_JI ω²/|α|`` (Eq. 4.48); ``None`` when ``α = 0`` (to round-off:
        ``|α| ≤ tol.angle`` times the largest ``ω² + |α|`` of the mechanism).
    conjugates : dict
        Point name -> its conjugate (center of curvature), homogeneous ``(3,)``:
        at infinity for a straight path, NaN for a point at rest.
    conjugate_methods : dict
        Point name -> how its conjugate was found: ``"inspection"`` (given),
        ``"bobillier"`` (Fig. 4.30), ``"hartmann"`` (Fig. 4.25),
        ``"euler-savary"`` (closed form, Eq. 4.42) or ``"pivot"``.
    known : dict
        Point name -> why its conjugate is known by inspection.
    cubic : Cubic or None
    ball_point : ndarray or None
    moving_centrode, fixed_centrode : tuple or None
        ``(R_IO, O)``: signed radius (``I - O`` along ``N``; ``inf`` if straight)
        and center (``None`` if straight).
    method : str
        How ``J`` was found: ``"bobillier"``, ``"euler-savary"`` (Eq. 4.43
        lay-off), ``"accelerations"``, ``"pivot"`` (the link turns about a
        frame pivot) or ``"closed form"``.
    construction : Construction or None
        The recorded steps (``diagram="curvature"``).
    values : dict
        Label -> value after evaluating ``construction``.
    notes : list of str
    """

    link: str
    omega: float
    alpha: float
    velocity_pole: Array
    inflection_pole: Array
    inflection_diameter: float
    normal: Array | None
    tangent: Array | None
    pole_velocity: Array
    pole_acceleration: Array
    acceleration_center: Array
    gamma: float
    bresse_pole: Array | None
    bresse_diameter: float | None
    conjugates: dict[str, Array]
    conjugate_methods: dict[str, str]
    known: dict[str, str]
    cubic: Cubic | None
    ball_point: Array | None
    moving_centrode: tuple[float, Array | None] | None
    fixed_centrode: tuple[float, Array | None] | None
    method: str
    construction: Construction | None
    values: dict[str, Array] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    sections: dict[str, str] = field(default_factory=dict)
    """Step output label -> the section that drew it (``circle``, ``hartmann``, ``hain``...)."""


def _is_batch(sol: Solution) -> bool:
    return np.ndim(sol.links[FRAME].angle) > 0


def _turning(sol: Solution, lid: str, tol: Tolerance) -> bool:
    """True when the link turns at this instant: ``|ω| L`` beyond round-off of the speeds."""
    st = sol.links[lid]
    if st.omega is None:
        return False
    w = abs(float(st.omega))
    if w * w < np.finfo(float).tiny:
        # ω = 0, or so small that ω² underflows: the construction divides by ω² (J = I + A_I/ω²)
        return False
    mech = sol.mechanism
    # the largest speed of the posture: the same for every link, so found once per solution
    ref = sol.__dict__.get("_largest_speed")
    if ref is None:
        speeds = [float(np.hypot(*sol.velocity(n))) for n in mech.point_names]
        ref = max(speeds + [abs(float(s.omega or 0.0)) * mech.scale
                            for s in sol.links.values()])
        sol.__dict__["_largest_speed"] = ref
    return w * mech.scale > tol.angle * max(ref, 1e-300)


def _finite_or_none(h: Array) -> Array | None:
    if not np.all(np.isfinite(h)) or h[2] == 0.0:
        return None
    return np.asarray(h[:2] / h[2], dtype=float)


def link_curvature(sol: Solution, link: str, *, tol: Tolerance | None = None,
                   method: str = "auto") -> LinkCurvature:
    """The curvature theory of the motion of ``link`` relative to the frame, at one posture.

    Parameters
    ----------
    sol : Solution
        One solved posture with rates.
    link : str
        A moving link whose angular velocity is not zero.
    tol : Tolerance, optional
    method : {"auto", "bobillier", "euler-savary", "accelerations"}
        How to find the inflection pole: ``"auto"`` uses Bobillier's
        construction (Fig. 4.29) when two pairs of conjugate points are known
        by inspection -- or, when it degenerates, the Eq. 4.43 lay-off of
        Examples 4.14 and 4.16 -- and the accelerations otherwise.

    Returns
    -------
    LinkCurvature

    Raises
    ------
    ConstructionError
        A batch solution, a solution without rates, a link that does not turn,
        or a ``method`` that does not apply.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    tol = tol or DEFAULT_TOL
    if _is_batch(sol):
        raise ConstructionError("the curvature constructions are drawn for one posture, "
                                "not a sweep", step="curvature")
    if not sol.has_rates or not sol.has_accelerations:
        raise ConstructionError("curvature needs the rates (the file gives none)",
                                step="curvature")
    if link == FRAME or link not in sol.links:
        raise ConstructionError(f"no moving link {link!r}; valid: "
                                f"{', '.join(sol.mechanism.moving)}", step="curvature")
    if not _turning(sol, link, tol):
        raise ConstructionError(f"link {link} does not turn at this instant (ω = 0): its "
                                "velocity pole is at infinity", step="curvature")
    if method not in ("auto", "bobillier", "euler-savary", "accelerations"):
        raise ConstructionError(f"unknown method {method!r}; valid: auto, bobillier, "
                                "euler-savary, accelerations", step="curvature")
    b = _Curvature(sol, link, tol)
    mech = sol.mechanism
    pins = _frame_pins(mech, link)
    if len(pins) > 1:
        raise ConstructionError(f"link {link} is pinned to the frame twice", step="curvature")
    pivot = pins[0] if pins else None

    # the two points of constant path curvature (by inspection), not on one ray from I
    pair: tuple[str, str] | None = None
    crossing = 0.0
    known = [n for n in b.known
             if float(np.hypot(*(b.pos(b.local[n]) - b.I0))) > _USABLE * b.L]
    for x in range(len(known)):
        for y in range(x + 1, len(known)):
            pa, pb = b.pos(b.local[known[x]]), b.pos(b.local[known[y]])
            sa = _sin_angle(pa - b.I0, pb - b.I0)
            if sa > _USABLE and sa > crossing:
                pair, crossing = (known[x], known[y]), sa
    # in "auto", rays that cross at less than ~1° locate I poorly: use the accelerations
    rays_ok = method != "auto" or crossing > _RAYS
    if method in ("bobillier", "euler-savary") and (pair is None or pivot is not None):
        raise ConstructionError(f"link {link} does not carry two points whose conjugates are "
                                "known by inspection", step="curvature")

    core = False
    if pivot is not None:
        core = b.section(lambda: b.pivot(pivot))
    else:
        if pair is not None and rays_ok and method in ("auto", "bobillier"):
            core = b.section(lambda: b.bobillier(pair[0], pair[1], layoff=False))
            if core:
                # the W construction is ill-conditioned when W runs far away: check it
                jj = b.pt(b.J_label or "J")
                ref = b.L + float(np.hypot(*(b.J0 - b.I0)))
                if float(np.hypot(*(jj - b.J0))) > _AGREE * ref:
                    b.notes.append("Bobillier's construction through W was ill-conditioned; "
                                   "J laid off by Eq. 4.43 instead.")
                    b.cx = Construction(title=b.cx.title)
                    b.env, b.made = {}, {}
                    core = False
        if not core and pair is not None and rays_ok and method in ("auto", "bobillier",
                                                                     "euler-savary"):
            core = b.section(lambda: b.bobillier(pair[0], pair[1], layoff=True))
            if core:
                b.section(lambda: b.collineation_axis(pair[0], pair[1]))
        if not core and method in ("auto", "accelerations"):
            core = b.section(b.accelerations)
    if not core:
        b.notes.append("the construction has no answer here; the values are closed-form")
        b.method = "closed form"

    # values (construction first, closed form otherwise)
    big_i = b.pt(b.I_label) if core and b.I_label else b.I0
    if pivot is not None:
        big_i = np.asarray(mech.links[FRAME].points[pivot], dtype=float)
        big_j = big_i.copy()
    else:
        big_j = b.pt(b.J_label) if core and b.J_label else b.J0
    d = float(np.hypot(*(big_j - big_i)))
    has_axes = pivot is None and d > tol.length(b.L)
    circle_ok = core and has_axes and b.section(b.circle)
    normal = _unit(big_j - big_i) if has_axes else None
    tangent = np.array([normal[1], -normal[0]]) if normal is not None else None
    v_pole = pole_velocity(big_i, big_j, b.w)
    a_pole = b.w**2 * (big_j - big_i)

    # Bresse circle and Γ
    gamma = math.atan2(b.a, b.w**2)
    if pivot is not None:
        big_g = big_i.copy()
    elif circle_ok and b.section(b.bresse):
        big_g = b.pt(b.lab("Γ"))
    else:
        big_g = b.G0
    if pivot is None and not b.a_zero:
        b.section(b.four_circles)
    if b.a_zero:
        e_pole, bd = None, None
    else:
        e_pole = b.pt(b.lab("E")) if b.has(b.lab("E")) else bresse_pole(big_i, big_j, b.w, b.a)
        bd = d * b.w**2 / abs(b.a)  # inf (not a warning) when α is tiny: null in the JSON
        if not np.all(np.isfinite(e_pole)):
            e_pole = None

    # conjugates of every named point
    conj: dict[str, Array] = {}
    conj_how: dict[str, str] = {}
    for n, loc in b.local.items():
        p = b.pos(loc)
        if pivot is not None:
            conj[n] = (g.point(*big_i) if float(np.hypot(*(p - big_i))) > tol.length(b.L)
                       else np.full(3, np.nan))
            conj_how[n] = "pivot"
            continue
        if n in b.known and b.has(b.lab(f"{n}'")) and pair is not None and n in pair:
            conj[n] = b.val(b.lab(f"{n}'"))
            conj_how[n] = "inspection"
            continue
        closed = euler_savary(big_i, big_j, p, tol, scale=b.L)
        conj_how[n] = "euler-savary"
        rp = float(np.hypot(*(p - big_i)))
        if not circle_ok or not np.all(np.isfinite(closed)) or closed[2] == 0.0:
            conj[n] = closed  # at rest or straight (decided relative to the figure's size)
            continue
        w_hat = (p - big_i) / rp
        cos_psi = abs(float(_dot(w_hat, tangent)))  # type: ignore[arg-type]
        q = float(_dot(big_j - big_i, p - big_i))
        well = (b.method in ("bobillier", "euler-savary") and cos_psi > _RAY_FROM_N
                and abs(q - rp * rp) > _FROM_CIRCLE * rp * rp
                and float(np.hypot(*(p - big_j))) > _FROM_CIRCLE * d)
        ok = well and b.section(partial(b.bobillier_conjugate, n))
        how = "bobillier"
        if not ok:
            ok = b.section(partial(b.hartmann, n))
            how = "hartmann"
        h = b.val(b.lab(f"{n}'")) if ok else closed
        if ok and h[2] != 0.0:
            conj[n], conj_how[n] = h, how
        else:
            conj[n] = closed

    # the cubic of stationary curvature (Hain), Ball's point, the centrodes
    cubic = None
    ball = None
    mc = fc = None
    if pair is not None and pivot is None and normal is not None and tangent is not None:
        m_val = n_val = None
        gn = gt = None
        if circle_ok and b.section(lambda: b.hain(pair[0], pair[1])):
            gn_h, gt_h = b.val(b.lab("G_N")), b.val(b.lab("G_T"))
            m_val = math.inf if gn_h[2] == 0.0 else float(_dot(g.xy(gn_h) - big_i, normal))
            n_val = math.inf if gt_h[2] == 0.0 else -float(_dot(g.xy(gt_h) - big_i, tangent))
            gn, gt = _finite_or_none(gn_h), _finite_or_none(gt_h)
        if m_val is None or n_val is None:
            try:
                m_val, n_val = stationary_curvature_cubic(
                    big_i, tangent, b.pos(b.local[pair[0]]), b.pos(b.local[pair[1]]),
                    scale=b.L, tol=tol)
            except GraphkinError:
                m_val = n_val = None
        if m_val is not None and n_val is not None:
            cubic = Cubic(big_i, tangent, normal, m_val, n_val, gn, gt)
            closed_u = ball_point(big_i, big_j, tangent, m_val, n_val, tol)
            if closed_u is None:
                ball = None  # the cubic contains the inflection circle, or touches it at I
            elif math.isinf(n_val):
                if circle_ok and b.section(partial(b.ball_at_j, pair[0], pair[1])):
                    ball = b.pt(b.lab("U"))
                else:
                    ball = closed_u
            elif closed_u is not None and circle_ok and b.has(b.lab("G")) \
                    and b.section(b.ball):
                ball = b.pt(b.lab("U"))
            else:
                ball = closed_u
            rm, rf = centrode_radii(d, m_val)
            mc = (rm, None if math.isinf(rm) else big_i - rm * normal)
            fc = (rf, None if math.isinf(rf) else big_i - rf * normal)

    return LinkCurvature(
        link=link, omega=b.w, alpha=b.a, velocity_pole=big_i, inflection_pole=big_j,
        inflection_diameter=d, normal=normal, tangent=tangent, pole_velocity=v_pole,
        pole_acceleration=a_pole, acceleration_center=big_g, gamma=gamma,
        bresse_pole=e_pole, bresse_diameter=bd, conjugates=conj, conjugate_methods=conj_how,
        known={n: why for n, (_, why) in b.known.items()}, cubic=cubic, ball_point=ball,
        moving_centrode=mc, fixed_centrode=fc, method=b.method,
        construction=b.cx if len(b.cx) else None, values=dict(b.env), notes=b.notes,
        sections=dict(b.sections))

# ---------------------------------------------------------------------------
# every link, every path
# ---------------------------------------------------------------------------

_CACHE: dict[int, tuple[Any, Tolerance, dict[str, LinkCurvature]]] = {}


def curvature(sol: Solution, *, tol: Tolerance | None = None) -> dict[str, LinkCurvature]:
    """:func:`link_curvature` of every moving link that turns at this instant.

    Empty for a batch or a solution without rates.  The result is cached per
    solution object.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.17.
    """
    tol = tol or DEFAULT_TOL
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return {}
    hit = _CACHE.get(id(sol))
    if hit is not None and hit[0]() is sol and hit[1] == tol:
        return hit[2]
    out = {lid: link_curvature(sol, lid, tol=tol) for lid in sol.mechanism.moving
           if _turning(sol, lid, tol)}
    key = id(sol)

    def forget(_ref: Any) -> None:
        _CACHE.pop(key, None)

    _CACHE[key] = (weakref.ref(sol, forget), tol, out)
    return out


def curvature_constructions(sol: Solution, *,
                            tol: Tolerance | None = None) -> dict[str, Construction]:
    """Link id -> its recorded curvature construction (``diagram="curvature"``)."""
    return {lid: k.construction for lid, k in curvature(sol, tol=tol).items()
            if k.construction is not None}


def path_curvatures(sol: Solution, *, tol: Tolerance | None = None) -> dict[str, PathCurvature]:
    """Radius and center of curvature of the absolute path of every named point of a moving link.

    A point shared by several moving links is one world point with one path:
    it is taken from the first of them that turns (its conjugate point by the
    constructions of Secs. 4.12-4.13); when none turns, from the point's
    velocity and acceleration (Eq. 4.49).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 4.12-4.13 and 4.16.
    """
    tol = tol or DEFAULT_TOL
    if _is_batch(sol) or not sol.has_rates or not sol.has_accelerations:
        return {}
    curv = curvature(sol, tol=tol)
    mech = sol.mechanism
    out: dict[str, PathCurvature] = {}
    for name in mech.point_names:
        carriers = [lid for lid in mech.point_links[name] if lid != FRAME]
        if not carriers:
            continue
        p = np.asarray(sol.position(name), dtype=float)
        if FRAME in mech.point_links[name]:
            out[name] = PathCurvature(name, carriers[0], None, None, "at rest")
            continue
        turning = [lid for lid in carriers if lid in curv]
        if turning:
            k = curv[turning[0]]
            h = k.conjugates[name]
            how = k.conjugate_methods.get(name, "euler-savary")
            if not np.all(np.isfinite(h)):
                out[name] = PathCurvature(name, k.link, None, None, "at rest")
            elif h[2] == 0.0:
                out[name] = PathCurvature(name, k.link, None, None, "straight")
            else:
                c = h[:2] / h[2]
                out[name] = PathCurvature(name, k.link, float(np.hypot(*(p - c))), c, how)
            continue
        rho, c = path_curvature(p, sol.velocity(name), sol.acceleration(name), tol)
        rho_f = float(rho)
        if math.isnan(rho_f):
            out[name] = PathCurvature(name, None, None, None, "at rest")
        elif math.isinf(rho_f):
            out[name] = PathCurvature(name, None, None, None, "straight")
        else:
            out[name] = PathCurvature(name, None, rho_f, np.asarray(c, dtype=float),
                                      "velocity-acceleration")
    return out
