"""Force analysis of a solved posture: the graphic construction, checked by the matrix method.

References
----------
Uicker, Pennock & Shigley, 5th ed., Ch. 11 (static force analysis), Ch. 12
(dynamic force analysis), Sec. 12.7 (shaking force and moment).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np

from graphkin.construction.ops import OPS
from graphkin.errors import ConstructionError, InputError
from graphkin.forces.analytic import applied_wrenches, solve_matrix
from graphkin.forces.graphic import BuiltForces, NotDecomposable, Partial, build_forces
from graphkin.forces.joints import PIN, SLIDE, SLOT, Geometry, Joint, geometry, joints_of
from graphkin.forces.ops import line_of
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import Rolling, Slider, Slot
from graphkin.tolerance import DEFAULT_TOL, Tolerance, is_zero, sign

if TYPE_CHECKING:
    from graphkin.construction import Construction

__all__ = ["ForceSolution", "InertiaForce", "solve_forces"]


@dataclass
class InertiaForce:
    """d'Alembert's inertia force of a link as one offset force (Eq. 12.18, Fig. 12.7c).

    Attributes
    ----------
    force : ndarray
        ``-m A_G`` (force unit).
    point : ndarray
        A point of its line of action: G moved by ``h`` perpendicular to the force.
    torque : float
        ``-I_G α`` (force unit × length unit), the moment about G of the offset force.
    offset : float
        ``h = I_G α / (m A_G)`` (a magnitude, length unit).
    """

    force: np.ndarray
    point: np.ndarray
    torque: float
    offset: float


@dataclass
class ForceSolution:
    """Every joint force and the drives' torques (or forces) at one posture.

    Attributes
    ----------
    solution : Solution
        The kinematic solution it stands on.
    joints : list of Joint
    forces : dict
        Joint key -> wrench ``(Fx, Fy, M_origin)`` of F_lo,hi, by ``lo`` on ``hi``.
    drives : dict
        Drive link -> ``("torque", T)`` (ccw, about its pivot) or ``("force", F)``
        (signed along the slider line's direction).
    inertia : dict
        Link -> :class:`InertiaForce` (dynamic analysis only).
    dynamic : bool
        True when inertia forces take part (mass properties and rates given).
    method : str
        ``"construction"`` (the graphic method) or ``"analytic"`` (the matrix method,
        when no graphic order exists; ``notes`` says why).
    built : BuiltForces or None
        The construction, its values and partial analyses (graphic method).
    notes : list of str
    geometry : Geometry
    """

    solution: Solution
    joints: list[Joint]
    forces: dict[str, np.ndarray]
    drives: dict[str, tuple[str, float]]
    inertia: dict[str, InertiaForce]
    dynamic: bool
    method: str
    built: BuiltForces | None
    geometry: Geometry
    applied: dict[str, list[tuple[str, np.ndarray]]] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)

    @property
    def mechanism(self) -> Any:
        """The mechanism."""
        return self.solution.mechanism

    @property
    def construction(self) -> Construction | None:
        """The recorded graphic construction (None for the matrix method)."""
        return None if self.built is None else self.built.construction

    @property
    def partials(self) -> list[Partial]:
        """The analyses of the superposition, one per loaded link (Sec. 12.5)."""
        return [] if self.built is None else self.built.partials

    def force(self, i: str | int, j: str | int) -> np.ndarray:
        """F_ij, the force exerted by link i on link j (``force(3, 4)`` is F_34).

        With two joints between the links (``"1-3@B"``, ``"1-3@D"``) their sum;
        :attr:`forces` has each.
        """
        a, b = str(i), str(j)
        total = np.zeros(2)
        found = False
        for jt in self.joints:  # two joints between one pair (F_13@B, F_13@D): their sum
            if (jt.lo, jt.hi) == (a, b):
                total = total + self.forces[jt.key][:2]
                found = True
            elif (jt.lo, jt.hi) == (b, a):
                total = total - self.forces[jt.key][:2]
                found = True
        if not found:
            raise KeyError(f"links {a} and {b} share no joint")
        return total

    def point(self, key: str) -> np.ndarray:
        """A point on the line of action of a joint's force (docs/forces.md).

        The pin for a pin or a pin in a slot; for a slider, where the force's
        line crosses the sliding line.
        """
        jt = next(j for j in self.joints if j.key == key)
        p = self.geometry.points[jt.point]
        if jt.kind != SLIDE:
            return p.copy()
        w = self.forces[key]
        if is_zero(float(np.hypot(w[0], w[1])), self.scale):  # no force, no line of action
            return p.copy()
        base, u = self.geometry.base[key], self.geometry.along[key]
        den = -w[1] * u[0] + w[0] * u[1]
        t = (w[1] * base[0] - w[0] * base[1] - w[2]) / den
        return base + t * u

    @property
    def scale(self) -> float:
        """The size of the forces: the largest load, inertia force, joint force or drive.

        A torque counts as itself over the mechanism's size.  A force within
        :data:`graphkin.tolerance.VERDICT_REL` of it is zero in the reports, and
        no sense is taken from it.
        """
        size = self.mechanism.size or 1.0
        big = force_scale(self.solution, self.dynamic, self.forces)
        for kind, value in self.drives.values():
            big = max(big, abs(value) / size if kind == "torque" else abs(value))
        return big

    def sense(self, torque: float) -> str:
        """``ccw``, ``cw``, or ``""`` for a torque at round-off of the forces' scale.

        >>> import graphkin
        >>> from graphkin.forces import solve_forces
        """
        size = self.mechanism.size or 1.0
        return {1: "ccw", -1: "cw", 0: ""}[sign(torque, self.scale * size)]

    def torque(self, link: str | int) -> float:
        """The drive's torque (or input force) of a drive link."""
        return self.drives[str(link)][1]

    @property
    def shaking(self) -> tuple[np.ndarray, float] | None:
        """The shaking force Σ(-m A_G) and moment about the origin (Eqs. 12.23-12.24)."""
        if not self.dynamic:
            return None
        f = np.zeros(2)
        m = 0.0
        for lid, inr in self.mechanism.inertia.items():
            sol = self.solution
            a = np.asarray(sol.acceleration(inr.center, lid))
            g = np.asarray(sol.position(inr.center, lid))
            fi = -inr.mass * a
            f += fi
            m += float(g[0] * fi[1] - g[1] * fi[0]) - inr.moment * float(sol.alpha(lid))
        return f, m


def _inertia(sol: Solution) -> dict[str, InertiaForce]:
    out = {}
    for lid, inr in sol.mechanism.inertia.items():
        a = np.asarray(sol.acceleration(inr.center, lid), dtype=float)
        g = np.asarray(sol.position(inr.center, lid), dtype=float)
        f = -inr.mass * a
        t = -inr.moment * float(sol.alpha(lid))
        f2 = float(f @ f)
        if f2 > 0:
            pt = g + (t / f2) * np.array([f[1], -f[0]])
            h = abs(t) / float(np.sqrt(f2))
        else:
            pt, h = g.copy(), 0.0
        out[lid] = InertiaForce(f, pt, t, h)
    return out


def solve_forces(sol: Solution, tol: Tolerance | None = None,
                 method: str = "construction", mistake: str | None = None) -> ForceSolution:
    """Find every joint force and the drives' torques of a solved posture.

    Parameters
    ----------
    sol : Solution
        A kinematic solution of a mechanism with loads or mass properties (one posture).
    tol : Tolerance, optional
    method : {"construction", "analytic"}
        The graphic method (falling back to the matrix method when it finds no
        order), or the matrix method alone.
    mistake : str, optional
        Solve with a usual mistake (by the matrix method), to diagnose a
        student's answer: ``"not-reversed"`` (the inertia force taken as
        ``+m A_G``), ``"h-side"`` (h on the wrong side of G).

    Returns
    -------
    ForceSolution

    Raises
    ------
    InputError
        Equilibrium cannot be held at this posture, or the mechanism is not
        statically determinate.

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.forces import solve_forces
    """
    mech = sol.mechanism
    joints = joints_of(mech)
    geo = geometry(sol, joints)
    dynamic = bool(mech.inertia) and sol.has_accelerations
    notes: list[str] = []
    if mech.inertia and not dynamic:
        notes.append("the file gives no rates: a static analysis (inertia forces need "
                     "the accelerations)")
    if mech.pressure:
        _tilt_for_pressure(sol, joints, geo, dynamic, notes)
    if mech.friction:
        _tilt_for_friction(sol, joints, geo, dynamic, notes, tol)
    applied = {lid: [("", w) for w, _ in items]
               for lid, items in applied_wrenches(sol, dynamic).items()}
    inertia = _inertia(sol) if dynamic else {}
    built: BuiltForces | None = None
    if mistake is not None:
        method = "analytic"
    if method == "construction":
        try:
            built = build_forces(sol, joints, geo, dynamic, tol)
        except NotDecomposable as exc:
            notes.append(f"solved by the matrix method: {exc}")
        except ConstructionError as exc:
            raise InputError(str(exc), key="drive", file=mech.source) from None
    if built is not None:
        env = built.values
        forces = {k: np.asarray(env[lab], dtype=float) for k, lab in built.forces.items()}
        drives: dict[str, tuple[str, float]] = {}
        for d in mech.drives:
            kind = "torque" if d.kind == "angle" else "force"
            drives[d.link] = (kind, float(env[built.drives[d.link]]))
        return ForceSolution(sol, joints, forces, drives, inertia, dynamic, "construction",
                             built, geo, applied, notes)
    fw, dv, _ = solve_matrix(sol, joints, geo, dynamic, mistake)
    drives = {d.link: ("torque" if d.kind == "angle" else "force", dv[d.link])
              for d in mech.drives}
    return ForceSolution(sol, joints, fw, drives, inertia, dynamic, "analytic", None, geo,
                         applied, notes)


def _tilt_for_friction(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
                       notes: list[str], tol: Tolerance | None) -> None:
    """Tilt each rough slider's (or pin in a slot's) force by the friction angle (Sec. 11.10).

    Ex 11.4 (a block on the ground), Ex 11.5 (a follower in two sliding bearings,
    each a pin of the frame in the follower's straight slot: its force, through the
    pin, leans from the slot's normal).

    As the book recommends, the problem is first solved without friction to
    find the sense of each normal force; the friction force opposes the
    impending motion of the slider relative to its guide (given, or from the
    velocity); the resultant then leans by φ = atan μ from the normal.
    """
    from graphkin.forces.analytic import solve_matrix

    mech = sol.mechanism
    plain, _, _ = solve_matrix(sol, joints, geo, dynamic)
    fscale = force_scale(sol, dynamic, plain)
    vscale = sol.velocity_scale() if sol.has_rates else 0.0
    rough: list[tuple[Joint, Any, np.ndarray, np.ndarray, float, float, float]] = []
    for j in joints:
        src = j.source
        if j.kind not in (SLIDE, SLOT) or not isinstance(src, (Slider, Slot)) \
                or src.key not in mech.friction:
            continue
        mu, impending = mech.friction[src.key]
        if j.key not in geo.along:
            raise InputError("friction is modelled along a straight line: a pin in a "
                             "circular slot cannot have friction = ...",
                             key=f"{src.key}.friction", file=mech.source)
        n, u = geo.normal[j.key], geo.along[j.key]
        block = "hi" if src.link == j.hi else "lo"
        # the sense of the frictionless normal force on the block (0: none, Sec. 11.10)
        c = float(OPS["force_normal_sense"](plain[j.key], n, fscale, tol=DEFAULT_TOL,
                                            block=block)[0])
        if impending is None:
            if not sol.has_rates:
                raise InputError("say which way the slider's motion is impending: impending = "
                                 "\"ahead\" or \"behind\" (a static file has no velocity)",
                                 key=f"{src.key}.impending", file=mech.source)
            pw = np.asarray(sol.position(src.point, src.link), dtype=float)
            # the block's velocity less the guide's at its point, along u (ops.py: the verdict)
            s = float(OPS["force_impending"](sol.velocity(src.point, src.link),
                                             _velocity_in(sol, src.on, pw), pw, pw, 0.0, u,
                                             vscale, tol=DEFAULT_TOL)[0])
            if s == 0.0:
                raise InputError("the slider is at rest relative to its guide at this posture: "
                                 "say impending = \"ahead\" or \"behind\"",
                                 key=f"{src.key}.impending", file=mech.source)
        else:
            s = 1.0 if impending == "ahead" else -1.0
        if c == 0.0:
            # a load taken directly by a drive leaves the joint forces at round-off of the
            # loads: the normal force is zero, so is friction (no verdict on its sense)
            notes.append(f"{src.key}: no normal force without friction, so no friction")
            continue
        rough.append((j, src, n, u, mu, s, c))
        notes.append(f"{src.key}: friction μ = {mu:g}, the force on link {src.link} leans "
                     f"{np.degrees(np.arctan(mu)):.2f}° from the normal against its impending "
                     f"motion {'ahead' if s > 0 else 'behind'} (Sec. 11.10)")
    _friction_senses(sol, joints, geo, dynamic, rough, fscale)


def _friction_senses(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
                     rough: list[tuple[Joint, Any, np.ndarray, np.ndarray, float, float, float]],
                     fscale: float) -> None:
    """Lean each rough slider's force by φ, and check the normal's sense it was leant from.

    The sense is the frictionless solution's (Sec. 11.10).  Friction can turn
    it over near self-locking: the force found must press the block along the
    leant line, not pull.  A slider whose force turns over is tried with the
    other sense; when neither holds, the posture is self-locking: the force on
    the block lies within the friction angle of the guide's normal and no drive
    moves it.
    """
    from graphkin.forces.analytic import solve_matrix

    senses = {j.key: sign for j, _, _, _, _, _, sign in rough}
    tried: dict[str, int] = {j.key: 1 for j, *_ in rough}
    while True:
        for j, _src, n, u, mu, s, _ in rough:  # the normal leant by φ (one source: ops.py)
            geo.normal[j.key] = OPS["force_friction_normal"](
                n, u, senses[j.key], tol=DEFAULT_TOL, mu=mu, impending=s)[0]
        if not rough:
            return
        fw, _, _ = solve_matrix(sol, joints, geo, dynamic)
        big = float(OPS["force_scale"](fscale, *fw.values(), tol=DEFAULT_TOL, size=1.0,
                                       kinds=("scale",) + ("force",) * len(fw))[0])
        turned = []
        for j, src, *_ in rough:
            block = "hi" if src.link == j.hi else "lo"
            if OPS["force_turned"](fw[j.key], geo.normal[j.key], big, senses[j.key],
                                   tol=DEFAULT_TOL, block=block)[0] > 0:
                turned.append((j, src))
        if not turned:
            return
        for j, src in turned:
            if tried[j.key] >= 2:
                mu = sol.mechanism.friction[src.key][0]
                raise InputError(
                    f"self-locking at this posture: the force on link {src.link} lies within "
                    f"the friction angle φ = {np.degrees(np.arctan(mu)):.2f}° of its guide's "
                    f"normal, so no drive moves it (Sec. 11.10)",
                    key=f"{src.key}.friction", file=sol.mechanism.source)
            tried[j.key] += 1
            senses[j.key] = -senses[j.key]


def _tilt_for_pressure(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
                       notes: list[str]) -> None:
    """Tilt each gear pair's force from the common tangent onto the pressure line (Sec. 11.11).

    Solved first with the force along the common tangent at the pitch point
    (the transmitted force F^t alone) to find its sense; the teeth then also
    push the gears apart, F^r = F^t tan φ from the pitch point toward each
    gear's center (Fig. 11.14b), so the force on the rolling gear leans by φ
    toward its center.
    """
    from graphkin.forces.analytic import solve_matrix

    mech = sol.mechanism
    plain, _, _ = solve_matrix(sol, joints, geo, dynamic)
    fscale = force_scale(sol, dynamic, plain)
    for j in joints:
        src = j.source
        if j.kind != SLOT or not isinstance(src, Rolling):
            continue
        phi = mech.pressure[src.key]
        p = geo.points[j.point]
        c = np.asarray(sol.position(src.center, src.link), dtype=float)
        e = (c - p) / float(np.hypot(*(c - p)))       # radial: toward the gear's center
        t = np.array([-e[1], e[0]])
        on_gear = plain[j.key][:2] if src.link == j.hi else -plain[j.key][:2]
        s = sign(float(on_gear @ t), fscale)
        if s == 0:
            notes.append(f"{src.key}: no transmitted force, so no radial force")
            continue
        d = s * t + np.tan(phi) * e
        geo.normal[j.key] = d / float(np.hypot(*d))
        notes.append(f"{src.key}: gear teeth, the force on link {src.link} along the pressure "
                     f"line at φ = {np.degrees(phi):g}° from the common tangent at "
                     f"{j.point} (Sec. 11.11, Fig. 11.14)")


def force_scale(sol: Solution, dynamic: bool,
                joint_forces: dict[str, np.ndarray] | None = None) -> float:
    """The size of the forces of a posture: the largest load, inertia force or weight.

    A couple counts as its torque over the mechanism's size; the joint forces
    (of the frictionless solution, when given) count too, since near a toggle
    they exceed the loads.  Verdicts on a force's sense (friction, self-locking,
    a gear's transmitted force) are taken relative to it, so a joint force at
    round-off of it (a load taken directly by a drive) has no sense.
    """
    size = sol.mechanism.size or 1.0
    big = 0.0
    for items in applied_wrenches(sol, dynamic).values():
        for w, point in items:
            big = max(big, float(np.hypot(w[0], w[1])) if point else abs(float(w[2])) / size)
    for w in (joint_forces or {}).values():
        big = max(big, float(np.hypot(w[0], w[1])))
    return big


def _velocity_in(sol: Solution, lid: str, world: Any) -> np.ndarray:
    """Velocity of the point of link ``lid`` at a world position."""
    st = sol.links[lid]
    d = np.asarray(world) - np.asarray(st.origin)
    c, s = np.cos(st.angle), np.sin(st.angle)
    return np.asarray(st.velocity(np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])))


def pin_kind(j: Joint) -> bool:
    """True for a pin joint."""
    return j.kind == PIN


__all__ += ["line_of", "pin_kind"]
