"""Solve a mechanism: the graphic constructions, with the analytic solver as fallback.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (posture), 3.4-3.6 (velocity
polygons), 4.2-4.6 (acceleration polygons), 5.4 (several inputs).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.errors import ConstructionError, DegenerateError, InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.assembly_words import parallel_meet, toggle_words
from graphkin.kinematics.polygons import Polygons, build_polygons
from graphkin.kinematics.posture import NotDecomposable, PostureConstruction, build_posture
from graphkin.kinematics.solution import LinkState, Solution, perp
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["solve", "link_states", "rate_inputs", "superposition"]


def link_states(mech: Mechanism, pc: PostureConstruction, values: Mapping[str, np.ndarray],
                vel: Mapping[str, np.ndarray] | None = None,
                acc: Mapping[str, np.ndarray] | None = None,
                pol: Polygons | None = None) -> dict[str, LinkState]:
    """Read every link's pose (and rates) from evaluated constructions.

    Works on one posture or on arrays of postures alike.
    """
    shape = np.shape(values[next(iter(pc.inputs))]) if pc.inputs else ()
    zero = np.zeros(shape)
    states: dict[str, LinkState] = {}
    for lid in mech.links:
        if lid == FRAME:
            z2 = np.zeros((*shape, 2))
            states[lid] = LinkState(zero.copy(), z2.copy(),
                                    None if vel is None else zero.copy(),
                                    None if acc is None else zero.copy(),
                                    None if vel is None else z2.copy(),
                                    None if acc is None else z2.copy())
            continue
        theta = np.asarray(values[pc.angles[lid]], dtype=float) + zero
        anchor, aloc = pc.anchors[lid]
        pa = g.xy(values[anchor])
        c, s = np.cos(theta), np.sin(theta)
        r = np.stack([c * aloc[0] - s * aloc[1], s * aloc[0] + c * aloc[1]], axis=-1)
        origin = pa - r
        st = LinkState(theta, origin)
        if vel is not None:
            w = np.asarray(vel[f"ω{lid}"], dtype=float) + zero
            assert pol is not None
            va = g.xy(vel[pol.velocity_images[anchor]])
            st.omega = w
            st.origin_velocity = va + w[..., None] * perp(-r)
            if acc is not None:
                al = np.asarray(acc[f"α{lid}"], dtype=float) + zero
                aa = g.xy(acc[pol.acceleration_images[anchor]])
                st.alpha = al
                st.origin_acceleration = aa + al[..., None] * perp(-r) + w[..., None] ** 2 * r
        states[lid] = st
    return states


def rate_inputs(mech: Mechanism, pol: Polygons, pc: PostureConstruction,
                values: Mapping[str, np.ndarray],
                tol: Tolerance | None = None) -> tuple[dict[str, float], dict[str, float]]:
    """The given rates as construction inputs (velocity inputs, acceleration inputs).

    When ``[rates]`` names another link, the polygons are linear in the input
    speed and affine in the input acceleration, so the construction is run for
    a unit input and scaled (superposition, Sec. 5.4).
    """
    vin: dict[str, float] = {}
    ain: dict[str, float] = {}
    for d in mech.drives:
        w, a = pol.rate_inputs[d.index]
        vin[w] = 0.0 if d.rate is None else d.rate
        ain[a] = 0.0 if d.rate2 is None else d.rate2
    if mech.rates is None:
        return vin, ain
    (d,) = mech.drives
    w, a = pol.rate_inputs[d.index]
    target = mech.rates
    slider = next((sl for sl in mech.sliders if sl.link == target.link), None)

    def measure(vel: Mapping[str, np.ndarray], acc: Mapping[str, np.ndarray] | None,
                kind: str) -> float:
        if target.kind == "angle":
            env = vel if kind == "v" else acc
            assert env is not None
            return float(env[("ω" if kind == "v" else "α") + target.link])
        # a slider's rate: its point's motion along the line, relative to the guide
        assert slider is not None
        st = link_states(mech, pc, values, vel, acc, pol)
        guide, body = st[slider.on], st[slider.link]
        loc = mech.links[slider.link].points[slider.point]
        pos = body.position(loc)
        gloc = _local_of(guide, pos)
        u = guide._r(np.subtract(slider.p1, slider.p0))
        u = u / np.hypot(*u)
        if kind == "v":
            return float((body.velocity(loc) - guide.velocity(gloc)) @ u)
        # apparent acceleration along the line: A_P − A_P(guide) − 2ω × V_rel (Table 4.1)
        vrel = body.velocity(loc) - guide.velocity(gloc)
        cor = 2 * float(np.asarray(guide.omega)) * np.array([-vrel[1], vrel[0]])
        return float((body.acceleration(loc) - guide.acceleration(gloc) - cor) @ u)

    tol = tol or DEFAULT_TOL
    ev = pol.velocity.evaluate({w: 1.0}, values=dict(values))
    k = measure(ev.values, None, "v")
    # k is ω_target (or the slider's speed) per unit input speed: dimensionless, or a length
    small = tol.angle if target.kind == "angle" else tol.length(mech.scale)
    if abs(k) <= small or target.rate is None:
        raise InputError(f"link {target.link} does not move when the drive moves, so its rate "
                         "cannot set the drive's", key="rates.link", file=mech.source)
    vin[w] = target.rate / k
    ev = pol.velocity.evaluate(vin, values=dict(values))
    a0 = measure(ev.values, pol.acceleration.evaluate({a: 0.0}, values=ev.values).values, "a")
    want = 0.0 if target.rate2 is None else target.rate2
    # the target's acceleration is k times the input's plus the terms in ω² (Eqs. 4.5-4.7):
    # its coefficient is the velocity ratio k itself, exactly; a difference of two
    # evaluations would lose it in the ω² terms' round-off (ω = 1e8: a division by zero)
    ain[a] = (want - a0) / k
    if not (math.isfinite(vin[w]) and math.isfinite(ain[a])):
        raise InputError("the rates are too large for this mechanism: its accelerations "
                         "overflow", key="rates", file=mech.source)
    return vin, ain


def _local_of(state: LinkState, world: np.ndarray) -> np.ndarray:
    """Local coordinates, in a link, of a world point (one posture)."""
    d = np.asarray(world) - state.origin
    c, s = np.cos(state.angle), np.sin(state.angle)
    return np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])


#: Below this sine of the angle between its two lines, a velocity-polygon meet is taken as
#: a meet of parallel lines: a toggle or dead-center posture.  A posture found exactly at
#: a toggle has its tangent arcs' meet only to about √ε of the figure's size (1.5e-8), so
#: the lines' directions carry errors of that order; 1e-7 stays above them.
SINGULAR_SINE = 1e-7


def singular_step(cx: Construction, values: Mapping[str, np.ndarray]) -> str | None:
    """Why a velocity polygon meets two parallel lines (a singular posture), or None.

    The words name the posture's points in line and the quantity the polygon
    cannot find (:func:`graphkin.kinematics.assembly_words.toggle_words`),
    never a step of the construction.
    """
    if parallel_meet(cx, values, SINGULAR_SINE) is None:
        return None
    return toggle_words(cx, values, SINGULAR_SINE)


def _posture_words(mech: Mechanism, pc: PostureConstruction) -> str:
    """The posture in the file's words: its drives and the branches taken (``B behind``)."""
    where = ", ".join(d.describe(mech.length_unit) for d in mech.drives)
    if pc.branches:
        where += " (branch: " + ", ".join(f"{p} {b}" for p, b in sorted(pc.branches.items())) + ")"
    return where


def solve(mech: Mechanism, tol: Tolerance | None = None,
          branches: dict[str, str] | None = None) -> Solution:
    """Solve a mechanism at the file's posture by the book's constructions.

    Parameters
    ----------
    mech : Mechanism
    tol : Tolerance, optional
    branches : dict, optional
        Step label -> branch, to force a branch (see :func:`build_posture`).

    Returns
    -------
    Solution
        With ``method == "construction"``; or ``"analytic"`` (and a note)
        when the mechanism cannot be solved one group at a time.

    Raises
    ------
    AssemblyError
        The mechanism cannot be assembled at the file's drive.
    """
    sol = _solve(mech, tol, branches)
    if mech.notes:              # what the file says that the report notes (a zero length)
        sol.notes = [*mech.notes, *sol.notes]
    return sol


def _solve(mech: Mechanism, tol: Tolerance | None,
           branches: dict[str, str] | None) -> Solution:
    try:
        pc = build_posture(mech, tol, branches)
    except NotDecomposable as exc:
        from graphkin.kinematics.analytic import solve_analytic

        sol = solve_analytic(mech, tol=tol)
        sol.notes.append(f"solved by the analytic solver: {exc}")
        return sol
    values = dict(pc.values)
    constructions = {"posture": pc.construction}
    if not mech.has_rates:
        states = link_states(mech, pc, values)
        return Solution(mech, states, "construction", constructions, notes=list(pc.notes),
                        branches=dict(pc.branches), values={"posture": values})
    pol: Polygons | None = None
    vin: Mapping[str, Any] = {}
    ain: Mapping[str, Any] = {}
    try:
        pol = build_polygons(mech, pc)
        vin, ain = rate_inputs(mech, pol, pc, values, tol)
        ev = pol.velocity.evaluate(vin, values=values, tol=tol)
        singular = singular_step(pol.velocity, ev.values)
        if singular is None:
            ea = pol.acceleration.evaluate(ain, values=ev.values, tol=tol)
    except (ConstructionError, DegenerateError) as exc:
        singular = _failure_words(pol, vin, ain, values, tol, exc)
    if singular is not None:
        states = link_states(mech, pc, values)
        exact = _rates_by_analytic(mech, states, tol)
        if exact is not None:
            # the posture is regular: the polygon met two coincident images or parallel
            # lines of its own making, not a toggle; the analytic solver gives the rates
            exact.notes = [*pc.notes, f"the posture is regular but {singular}: the rates "
                           "are the analytic solver's (Secs. 3.9, 4.9)"]
            exact.branches = dict(pc.branches)
            exact.constructions = dict(constructions)  # the posture is still constructed
            exact.values = {"posture": values}
            return exact
        note = (f"toggle or dead-center posture at {_posture_words(mech, pc)}: the "
                f"velocities and accelerations are undetermined here ({singular}; Sec. 3.5)")
        return Solution(mech, states, "construction", constructions,
                        notes=[*pc.notes, note], branches=dict(pc.branches),
                        values={"posture": values})
    assert pol is not None  # built, or the polygons' failure was returned above
    states = link_states(mech, pc, values, ev.values, ea.values, pol)
    constructions["velocity"] = pol.velocity
    constructions["acceleration"] = pol.acceleration
    return Solution(mech, states, "construction", constructions, notes=list(pc.notes),
                    branches=dict(pc.branches),
                    values={"posture": values, "velocity": ev.values,
                            "acceleration": ea.values})


def _failure_words(pol: Polygons | None, vin: Mapping[str, Any],
                   ain: Mapping[str, Any], values: Mapping[str, np.ndarray],
                   tol: Tolerance | None, exc: Exception) -> str:
    """Why the polygons failed, in the book's words: replayed on past the failure to see why."""
    if pol is None or not vin:
        return "the polygons cannot be drawn"
    failed = getattr(exc, "step", None)
    ev = pol.velocity.evaluate(vin, values=dict(values), tol=tol, strict=False)
    cx = pol.velocity
    if bool(np.all(ev.valid)) and parallel_meet(cx, ev.values, SINGULAR_SINE) is None:
        cx = pol.acceleration  # the velocities were found: the acceleration polygon failed
        ev = cx.evaluate(ain, values=dict(ev.values), tol=tol, strict=False)
    return toggle_words(cx, ev.values, SINGULAR_SINE,
                        failed if isinstance(failed, str) else None)


def _rates_by_analytic(mech: Mechanism, states: Mapping[str, LinkState],
                       tol: Tolerance | None) -> Solution | None:
    """The analytic solution at the constructed posture, or None at a real toggle.

    The verdict "toggle" is the analytic solver's: its Jacobian, scaled to the
    mechanism's size, rank deficient (Sec. 3.9); a polygon that fails at a
    regular posture is no verdict.
    """
    from graphkin.kinematics.analytic import solve_analytic

    guess = {lid: (float(s.origin[0]), float(s.origin[1]), float(s.angle))
             for lid, s in states.items() if lid != FRAME}
    try:
        sol = solve_analytic(mech, guess=guess, tol=tol)
    except (ConstructionError, DegenerateError):
        return None
    # the same posture as the construction (Newton from it stays on its branch)
    size = float(mech.scale)
    for lid, s in states.items():
        e = sol.links[lid]
        if float(np.hypot(*(np.asarray(e.origin) - np.asarray(s.origin)))) > \
                1e-6 * size or abs(np.angle(np.exp(1j * (float(e.angle) - float(s.angle))))) > 1e-6:
            return None
    return sol


def superposition(mech: Mechanism, tol: Tolerance | None = None) -> list[tuple[int, Solution]]:
    """Velocities by the method of superposition (Sec. 5.4, Example 5.4).

    For a mechanism with several inputs, solve the velocity polygon once per
    input with every other input frozen; the velocities are linear in the
    inputs, so the cases add up to the full solution.

    Parameters
    ----------
    mech : Mechanism
        With rates given for every drive.
    tol : Tolerance, optional

    Returns
    -------
    list of (int, Solution)
        For each drive (its index in ``mech.drives``) the velocity-only solution
        with that input active and the others frozen.

    Raises
    ------
    InputError
        The file gives no rates.
    """
    if not mech.has_rates or mech.rates is not None:
        raise InputError("superposition needs the rate of every drive", key="drive",
                         file=mech.source)
    pc = build_posture(mech, tol)
    pol = build_polygons(mech, pc)
    vin, _ = rate_inputs(mech, pol, pc, pc.values)
    out = []
    for d in mech.drives:
        active = pol.rate_inputs[d.index][0]
        given = {k: (v if k == active else 0.0) for k, v in vin.items()}
        ev = pol.velocity.evaluate(given, values=dict(pc.values), tol=tol)
        states = link_states(mech, pc, pc.values, ev.values, None, pol)
        out.append((d.index, Solution(mech, states, "construction",
                                      {"posture": pc.construction,
                                       "velocity": pol.velocity},
                                      notes=[f"input {d.key} active, the others frozen"],
                                      values={"posture": dict(pc.values),
                                              "velocity": ev.values})))
    return out
