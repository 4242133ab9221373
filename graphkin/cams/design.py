"""Design checks of a plate cam (Secs. 6.9-6.12): pressure angle, curvature, undercutting, sizes.

Every extreme is found on a fine grid of cam angles (arrays, no loop over
angles) and then refined by golden-section search in the grid cell around
it, so that the numbers do not depend on the grid.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 6.9 (Eqs. 6.27-6.29, Ex 6.3), 6.10
(Eqs. 6.32-6.34, Ex 6.4-6.5, Fig. 6.29), 6.12 (jump, Ex 6.8).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.model import Cam, FollowerKind
from graphkin.cams.motions import Motion
from graphkin.cams.program import TWO_PI, Program
from graphkin.tolerance import VERDICT_REL, first_largest

__all__ = ["Extreme", "Undercut", "Checks", "check", "extreme", "joints", "min_prime_for_pressure",
           "min_prime_for_curvature", "face_width", "undercuts", "jump_speed", "GRID"]

Array = np.ndarray
GRID = 7200
"""Cam angles of the search grid over one turn (0.05° apart)."""
_GOLDEN = (math.sqrt(5) - 1) / 2


@dataclass(frozen=True)
class Extreme:
    """An extreme value over the cycle and the cam angle Θ (rad) where it occurs."""

    value: float
    theta: float


@dataclass(frozen=True)
class Undercut:
    """A stretch of cam angles (rad) where the profile is undercut (Figs. 6.25, 6.29)."""

    start: float
    end: float
    segment: int


@dataclass(frozen=True)
class Checks:
    """The design numbers of a cam (all lengths in the cam's unit, angles in rad).

    ``pressure`` is the largest |φ|; ``rho`` the smallest radius of curvature
    of the profile where it is convex (None if it is nowhere convex), ``rho_pitch``
    the same of the pitch curve (roller and knife edge); ``face`` the flat
    face's least extents ``(left, right)`` of the point of contact, and their
    sum the least width (Eq. 6.29).
    """

    pressure: Extreme
    rho: Extreme | None
    rho_pitch: Extreme | None
    undercut: list[Undercut]
    face: tuple[float, float] | None


def _grid() -> Array:
    return np.arange(GRID) * (TWO_PI / GRID)


def joints(program: Program) -> Array:
    """The cam angles at either side of every joint: where an extreme may sit on a jump.

    At a joint where y'' (say) jumps, the extreme of a quantity built on it is
    a one-sided limit, which neither the grid nor a search between grid points
    reaches; the angle just before the joint (1e-12 rad: the end of the
    segment before) and the joint itself (the start of the next) do.  Inside a
    segment, parabolic motion's y'' jumps at its midpoint too (Eq. 6.5 to 6.6,
    Fig. 6.12: +4L/β² to −4L/β²); it is a joint in this sense.
    """
    st = np.asarray(program.starts, dtype=float)
    mid = np.array([a + 0.5 * s.angle for a, s in zip(st, program.segments, strict=True)
                    if s.motion is Motion.PARABOLIC], dtype=float)
    at = np.concatenate([st, mid])
    return np.mod(np.concatenate([at, at - 1e-12]), TWO_PI)


def extreme(fun: Callable[[Array], Array], *, maximum: bool = True,
            mask: Callable[[Array], Array] | None = None,
            candidates: Array | None = None) -> Extreme | None:
    """The largest (or smallest) value of ``fun`` over one turn, refined (golden section).

    ``fun`` takes an array of cam angles; ``mask``, if given, says where it
    counts; ``candidates`` are angles also tried as they are (the joints, see
    :func:`joints`).
    """
    th = _grid()
    v = np.asarray(fun(th), dtype=float)
    sign = 1.0 if maximum else -1.0
    ok = np.isfinite(v) if mask is None else np.isfinite(v) & mask(th)
    if not np.any(ok):
        return None
    # of equal extremes (a symmetric program) the first in cam angle, not round-off's pick
    i = first_largest(np.where(ok, sign * v, -np.inf), periodic=True)
    scale = abs(float(v[i]))  # the extreme's own size: round-off is relative to it
    h = TWO_PI / GRID
    a, b = th[i] - h, th[i] + h

    def g(x: float) -> float:
        y = float(np.asarray(fun(np.array([x])))[0])
        if mask is not None and not bool(mask(np.array([x]))[0]):
            return -math.inf
        return sign * y if math.isfinite(y) else -math.inf

    c, d = b - _GOLDEN * (b - a), a + _GOLDEN * (b - a)
    gc, gd = g(c), g(d)
    for _ in range(60):       # refines one extreme, not a loop over cam angles
        if gc > gd:
            b, d, gd = d, c, gc
            c = b - _GOLDEN * (b - a)
            gc = g(c)
        else:
            a, c, gc = c, d, gd
            d = a + _GOLDEN * (b - a)
            gd = g(d)
    x = (a + b) / 2
    # the refined extreme only when clearly beyond the grid's (a dwell's constant value
    # stays at the grid's first angle, not wherever round-off puts it)
    best = (g(x), x) if g(x) > sign * v[i] + VERDICT_REL * scale else (sign * v[i], th[i])
    if candidates is not None and len(candidates):
        cv = np.asarray(fun(candidates), dtype=float)
        cok = np.isfinite(cv) if mask is None else np.isfinite(cv) & mask(candidates)
        if np.any(cok):
            j = first_largest(np.where(cok, sign * cv, -np.inf))
            if sign * cv[j] > best[0] + VERDICT_REL * scale:  # clearly beyond the grid's
                best = (sign * cv[j], float(candidates[j]))
    return Extreme(sign * best[0], float(np.mod(best[1], TWO_PI)))


def undercuts(cam: Cam) -> list[Undercut]:
    """Where the profile is undercut (Figs. 6.25, 6.29).

    A flat face's ρ < 0 (Eq. 6.27), or a roller larger than the convex pitch
    curve's radius of curvature.
    """
    th = _grid()
    pr = profile(cam, th)
    lost = ~np.isfinite(pr.contact)          # no envelope point: the face turns with the cam
    if cam.follower.kind.flat:
        bad = (pr.rho < 0) | lost
    elif cam.follower.kind.roller:
        assert pr.rho_pitch is not None
        bad = ((pr.rho_pitch > 0) & (pr.rho_pitch < cam.follower.roller)) | lost
    else:
        bad = lost
    out: list[Undercut] = []
    if not np.any(bad):
        return out
    seg = cam.program.evaluate(th).segment
    edges = np.flatnonzero(np.diff(np.concatenate([[False], bad, [False]]).astype(int)))
    for a, b in zip(edges[::2], edges[1::2]):
        out.append(Undercut(float(th[a]), float(th[b - 1]), int(seg[a])))
    if len(out) > 1 and out[0].start == 0.0 and out[-1].end == th[-1]:   # across 360° → 0°
        out[0] = Undercut(out[-1].start, out[0].end, out[-1].segment)
        out.pop()
    return out


def face_width(cam: Cam) -> tuple[float, float] | None:
    """A flat face's least extents ``(left, right)`` of the contact from its reference (Eq. 6.29).

    Translating face: ``−y'_min`` to the left and ``y'_max`` to the right of the
    cam's center (Eq. 6.26: the contact is ``y'`` along the face).
    """
    if not cam.follower.kind.flat:
        return None

    def along(t: Array) -> Array:
        a = profile(cam, t).face
        assert a is not None
        return a

    hi = extreme(along, candidates=joints(cam.program))
    lo = extreme(along, maximum=False, candidates=joints(cam.program))
    assert hi is not None and lo is not None
    return (max(0.0, -lo.value), max(0.0, hi.value))


def check(cam: Cam) -> Checks:
    """The design numbers of ``cam`` (Secs. 6.9-6.10).

    Examples
    --------
    Ex 6.6's roller cam: tan φ = 30 sin 2Θ/(55 − 15 cos 2Θ) (Eq. 6.33) is
    largest where cos 2Θ = 3/11, tan φ = 30√112/560, φ = 29.55°.

    >>> import math
    >>> from graphkin.cams.examples import example_6_6
    >>> c = check(example_6_6())
    >>> round(math.degrees(c.pressure.value), 2), c.undercut
    (29.55, [])
    """
    jt = joints(cam.program)
    pressure = extreme(lambda t: np.abs(profile(cam, t).pressure), candidates=jt)
    assert pressure is not None
    pitch = None
    if not cam.follower.kind.flat:
        pitch = extreme(lambda t: profile(cam, t).rho_pitch, maximum=False,   # type: ignore
                        mask=lambda t: profile(cam, t).rho_pitch > 0,          # type: ignore
                        candidates=jt)
    if cam.follower.kind.flat:     # a flat face's profile is convex unless undercut
        rho = extreme(lambda t: profile(cam, t).rho, maximum=False, candidates=jt)
    else:                           # where the pitch curve is convex (concave parts are fine)
        rho = extreme(lambda t: profile(cam, t).rho, maximum=False,
                      mask=lambda t: profile(cam, t).rho_pitch > 0,  # type: ignore
                      candidates=jt)
    return Checks(pressure, rho, pitch, undercuts(cam), face_width(cam))


def _bisect(ok: Callable[[float], bool], lo: float, hi: float, rel: float = 1e-10) -> float:
    """The least value in ``[lo, hi]`` for which ``ok`` holds (``ok(hi)`` must hold)."""
    while hi - lo > rel * hi:
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if ok(mid) else (mid, hi)
    return hi


def min_prime_for_pressure(cam: Cam, phi_max: float) -> float:
    """The least prime-circle radius R0 for which |φ| ≤ φ_max over the whole cycle (Ex 6.4).

    Translating roller or knife edge: from Eq. (6.32),
    ``√(R0² − ε²) ≥ max(|y' − ε|/tan φ_max − Y)``; oscillating followers by
    bisection on R0.  A translating flat face has φ = 0 for any R0.
    """
    f = cam.follower
    if f.kind is FollowerKind.FLAT_FACE:
        return 0.0
    if not f.kind.oscillating:
        t = math.tan(phi_max)
        need = extreme(lambda th: np.abs(_kin(cam.program, th)[1] - f.offset) / t
                       - _kin(cam.program, th)[0], candidates=joints(cam.program))
        assert need is not None
        return math.hypot(max(need.value, 0.0), f.offset)

    def ok(r0: float) -> bool:
        try:
            c = dataclasses.replace(cam, prime=r0)
        except Exception:
            return False
        p = np.abs(profile(c, _grid()).pressure)
        return bool(np.all(np.nan_to_num(p, nan=math.pi) <= phi_max))

    hi = max(cam.prime, 1e-3)
    lo = f.roller if f.kind.roller else 0.0
    return _bisect(ok, lo, _grow(ok, hi))


def _kin(program: Program, th: Array) -> tuple[Array, Array, Array]:
    k = program.evaluate(th)
    return k.Y, k.y1, k.y2


def _grow(ok: Callable[[float], bool], hi: float) -> float:
    for _ in range(60):
        if ok(hi):
            return hi
        hi *= 2
    raise ValueError("no prime circle up to 2^60 times the given one will do")


def min_prime_for_curvature(cam: Cam, rho_min: float) -> float:
    """The least R0 for which the profile's convex radius of curvature is ≥ ρ_min everywhere.

    Flat face: Eq. (6.28) made exact, ``R0 ≥ ρ_min − min(Y + y'')`` (the
    book takes Y at the posture of y''_min); roller and knife edge: by
    bisection on R0, requiring ``ρ_pitch ≥ ρ_min + R_r`` wherever the pitch
    curve is convex (Eq. c of Sec. 6.10).
    """
    f = cam.follower
    if f.kind is FollowerKind.FLAT_FACE:
        low = extreme(lambda th: _kin(cam.program, th)[0] + _kin(cam.program, th)[2],
                      maximum=False, candidates=joints(cam.program))
        assert low is not None
        return rho_min - low.value
    rr = f.roller if f.kind.roller else 0.0

    def ok(r0: float) -> bool:
        try:
            c = dataclasses.replace(cam, prime=r0)
        except Exception:
            return False
        pr = profile(c, _grid())
        rho = pr.rho if f.kind.flat else pr.rho_pitch
        assert rho is not None
        convex = rho > 0
        good = rho[convex] >= rho_min + (0.0 if f.kind.flat else rr)
        return bool(np.all(np.isfinite(rho)) and np.all(good))

    return _bisect(ok, max(rr, abs(f.offset)) * (1 + 1e-9), _grow(ok, max(cam.prime, 1e-3)))


def jump_speed(program: Program, k: float, preload: float, mass: float) -> Extreme:
    """The cam speed at which the follower first leaves the cam (Sec. 6.12, Ex 6.8).

    The contact force ``F = kY + P + m y'' ω²`` (Eq. 1 of Ex 6.8) first
    reaches zero where ``(kY + P)/(−m y'')`` is least over the postures with
    ``y'' < 0``; ω is its square root.  Consistent units (N/m, N, kg, m) give rad/s.
    """

    def omega2(th: Array) -> Array:
        Y, _, y2 = _kin(program, th)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(y2 < 0, (k * Y + preload) / (-mass * y2), np.inf)

    low = extreme(omega2, maximum=False, mask=lambda th: _kin(program, th)[2] < 0,
                  candidates=joints(program))
    if low is None:
        return Extreme(math.inf, 0.0)
    return Extreme(math.sqrt(low.value), low.theta)
