"""The exact value of every answer key, read from a solved mechanism.

Angles, rates, velocities and accelerations come from the
:class:`~graphkin.kinematics.solution.Solution` of the book's constructions.
Instant centers come from :mod:`graphkin.kinematics.instant_centers` when that
module is there, else from the velocities (the one point at which the two links
have the same velocity, Sec. 3.13).  Radii of curvature come from
:mod:`graphkin.kinematics.curvature` when it is there, else from
``ρ = |V|³ / |V × A|`` (Sec. 4.14).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.13 (instant center of velocity),
Sec. 4.3 (normal and tangential components), Sec. 4.5 (Coriolis component),
Sec. 4.14 (radius of curvature of a point path).
"""

from __future__ import annotations

import dataclasses
import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.check.answers import Key
from graphkin.errors import GraphkinError, InputError
from graphkin.kinematics.solution import Solution, perp
from graphkin.mechanisms.model import FRAME

__all__ = ["Exact", "Evaluator", "wrap180"]

# relative size below which a magnitude counts as zero (numerical noise of the constructions)
_ZERO = 1e-9


def wrap180(deg: float) -> float:
    """An angle in degrees wrapped to (-180, 180].

    Examples
    --------
    >>> wrap180(190.0), wrap180(-180.0), wrap180(360.0)
    (-170.0, 180.0, 0.0)
    """
    d = math.fmod(deg, 360.0)
    if d > 180.0:
        d -= 360.0
    elif d <= -180.0:
        d += 360.0
    return d + 0.0


@dataclass(frozen=True)
class Exact:
    """An exact value: a scalar (``value``) or a vector or position (``xy``).

    ``ideal`` marks an instant center at infinity, ``xy`` then being its unit
    direction.  ``value`` may be ``inf`` for the radius of a straight path.
    """

    value: float | None = None
    xy: np.ndarray | None = None
    ideal: bool = False

    @property
    def magnitude(self) -> float:
        """``|xy|`` or ``|value|``."""
        if self.xy is not None:
            return float(np.hypot(*self.xy))
        return abs(float(self.value if self.value is not None else 0.0))

    @property
    def direction(self) -> float | None:
        """Direction of ``xy`` in degrees, or None for a zero vector."""
        if self.xy is None or not np.any(self.xy):
            return None
        return math.degrees(math.atan2(self.xy[1], self.xy[0]))

    def scaled(self, f: float) -> Exact:
        """The value times ``f`` (a unit mistake or a reversed sense)."""
        if self.xy is not None:
            return Exact(None, self.xy * f, self.ideal)
        return Exact(None if self.value is None else self.value * f)


class Evaluator:
    """Exact values of answer keys for one solved mechanism.

    Parameters
    ----------
    sol : Solution
    accelerations : dict, optional
        Point name -> acceleration image ``[x, y]`` read off a polygon redrawn
        with a mistake: what the student's pencil gives for every later point.

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.check.answers import parse_key
    >>> mech = graphkin.examples.fourbar()
    >>> ev = Evaluator(graphkin.solve(mech))
    >>> ev.value(parse_key("V_B", mech)).xy.round(4)   # ω2 k × R_BA, 94.25 rad/s × 4 in ∠120°
    array([-326.4839, -188.4956])
    """

    def __init__(self, sol: Solution, *,
                 accelerations: dict[str, np.ndarray] | None = None) -> None:
        self.sol = sol
        self.mech = sol.mechanism
        #: image points read off an acceleration polygon drawn with a mistake (the student's
        #: pencil), used instead of the links' rigid motion
        self.images = dict(accelerations or {})
        self._ic: dict[str, Any] | None = None
        self._paths: dict[str, Any] | None = None

    # ---- scales ---------------------------------------------------------
    def typical(self, quantity: str) -> float:
        """A typical size of a quantity in this mechanism (to tell zero from noise)."""
        sol = self.sol
        vals: list[float] = [0.0]
        if quantity in ("omega", "alpha") and sol.has_rates:
            for lid in self.mech.links:
                st = sol.links[lid]
                x = st.omega if quantity == "omega" else st.alpha
                if x is not None:
                    vals.append(abs(float(x)))
        elif quantity in ("force", "torque"):
            fs = self.forces()
            if quantity == "force":
                vals += [float(np.hypot(*w[:2])) for w in fs.forces.values()]
            else:
                vals += [abs(v) for _, v in fs.drives.values()]
        elif quantity in ("velocity", "acceleration") and sol.has_rates:
            if quantity == "acceleration" and not sol.has_accelerations:
                return 1.0
            f = sol.velocity if quantity == "velocity" else sol.acceleration
            vals += [float(np.hypot(*f(p))) for p in self.mech.point_names]
        else:
            return float(self.mech.scale)
        m = max(vals)
        return m if m > 0 else 1.0

    def floor(self, quantity: str) -> float:
        """Magnitudes below this are zero."""
        return _ZERO * self.typical(quantity)

    def reference_length(self, xy: np.ndarray) -> float:
        """The length a position error is measured against.

        The mechanism's size, or the point's distance from the middle of the
        mechanism when it lies farther out.
        """
        pts = np.array([self.sol.position(p) for p in self.mech.point_names])
        centre = pts.mean(axis=0)
        return max(float(self.mech.scale), float(np.hypot(*(np.asarray(xy) - centre))))

    # ---- values ---------------------------------------------------------
    def _rates(self, key: Key, acc: bool = False) -> None:
        if not self.sol.has_rates or (acc and not self.sol.has_accelerations):
            what = "accelerations" if acc else "velocities"
            raise InputError(f"the mechanism file gives no rates, so {what} cannot be checked",
                             key=key.text)

    def value(self, key: Key) -> Exact:
        """The exact value of ``key``.

        Raises
        ------
        InputError
            The quantity does not exist for this mechanism (no rates, no
            Coriolis component there, a point at rest has no path curvature).
        """
        sol, k, a = self.sol, key.kind, key.args
        if k == "theta":
            return Exact(math.degrees(float(sol.angle_rad(a[0]))))
        if k == "omega":
            self._rates(key)
            return Exact(float(sol.omega(a[0])))
        if k == "alpha":
            self._rates(key, acc=True)
            return Exact(float(sol.alpha(a[0])))
        if k == "R":
            xy = sol.position(a[0]) - (sol.position(a[1]) if len(a) == 2 else 0.0)
            return Exact(None, np.asarray(xy, dtype=float))
        if k in ("V", "A") and key.link is not None:
            self._rates(key, acc=k == "A")
            return Exact(None, self.on_link(a[0], key.link, k))
        if k == "V":
            self._rates(key)
            xy = sol.velocity(a[0]) - (sol.velocity(a[1]) if len(a) == 2 else 0.0)
            return Exact(None, np.asarray(xy, dtype=float))
        if k == "A":
            self._rates(key, acc=True)
            xy = self._acc(a[0]) - (self._acc(a[1]) if len(a) == 2 else 0.0)
            return Exact(None, np.asarray(xy, dtype=float))
        if k in ("An", "At"):
            self._rates(key, acc=True)
            return Exact(None, self.component(key, a[0], a[1], k[-1]))
        if k == "Ac":
            self._rates(key, acc=True)
            return Exact(None, self.coriolis(key, a[0]))
        if k == "I":
            return self.instant_center(key, a[0], a[1])
        if k == "rho":
            return Exact(self.radius(key, a[0]))
        if k in ("F", "T"):  # docs/forces.md
            return self.force(key)
        raise InputError(f"no exact value for {key.text!r}", key=key.text)  # pragma: no cover

    def forces(self, mistake: str | None = None) -> Any:
        """The force analysis (Ch. 11-12) of this posture, or one made with a usual mistake."""
        cache: dict[str | None, Any] = self.__dict__.setdefault("_forces", {})
        if mistake not in cache:
            from graphkin.forces import solve_forces

            cache[mistake] = solve_forces(self.sol, mistake=mistake)
        return cache[mistake]

    def force(self, key: Key, mistake: str | None = None) -> Exact:
        """F_ij (by link i on link j) or the drive's torque T_1k."""
        fs = self.forces(mistake)
        i, j = key.args
        if key.kind == "F":
            try:
                return Exact(None, np.asarray(fs.force(i, j), dtype=float))
            except KeyError:
                raise InputError(f"links {i} and {j} share no joint", key=key.text) from None
        if i != "1" or j not in fs.drives or fs.drives[j][0] != "torque":
            drives = ", ".join(f"T_1{lid}" for lid, (k, _) in fs.drives.items()
                               if k == "torque") or "none"
            raise InputError(f"{key.text} is not a drive's torque (drives: {drives})",
                             key=key.text)
        return Exact(float(fs.drives[j][1]))

    def on_link(self, name: str, lid: str, kind: str) -> np.ndarray:
        """Velocity (``V``) or acceleration (``A``) of the point of link ``lid`` at ``name``.

        ``V = V_O + ω × R`` and ``A = A_O + α × R − ω² R`` of the link's motion
        at the point's place (Eqs. 3.4, 4.5): the coincident point A4 of Sec. 3.6.
        """
        st = self.sol.links[lid]
        r = np.asarray(self.sol.position(name), dtype=float) - np.asarray(st.origin, dtype=float)
        if st.omega is None or st.origin_velocity is None:
            raise InputError("the mechanism file gives no rates", key=f"{kind}_{name}{lid}")
        w = float(st.omega)
        if kind == "V":
            return np.asarray(st.origin_velocity, dtype=float) + w * perp(r)
        if st.alpha is None or st.origin_acceleration is None:
            raise InputError("the mechanism file gives no rates", key=f"{kind}_{name}{lid}")
        return (np.asarray(st.origin_acceleration, dtype=float) + float(st.alpha) * perp(r)
                - w**2 * r)

    def _acc(self, name: str) -> np.ndarray:
        if name in self.images:
            return self.images[name]
        return np.asarray(self.sol.acceleration(name), dtype=float)

    def common_link(self, key: Key, p: str, q: str) -> str:
        """A moving link that carries both points (the frame if only it does)."""
        pl = self.mech.point_links
        common = [lid for lid in pl[p] if lid in pl[q]]
        if not common:
            raise InputError(f"{p} and {q} are not points of one link, so A_{p}{q} has no "
                             "normal and tangential components", key=key.text)
        moving = [c for c in common if c != FRAME]
        return (moving or common)[0]

    def component(self, key: Key, p: str, q: str, which: str) -> np.ndarray:
        """``A_PQ^n = −ω² R_PQ`` or ``A_PQ^t = α × R_PQ`` of the link carrying P and Q (Eq. 4.7)."""
        lid = self.common_link(key, p, q)
        r = self.sol.position(p) - self.sol.position(q)
        if which == "n":
            return -float(self.sol.omega(lid)) ** 2 * r
        return float(self.sol.alpha(lid)) * perp(r)

    def coriolis(self, key: Key, p: str) -> np.ndarray:
        """The Coriolis component laid off for point P in the acceleration construction."""
        cx = self.sol.constructions.get("acceleration")
        env = self.sol.values.get("acceleration", {})
        pat = re.compile(rf"A_{re.escape(p)}(\d*)(/[^^]*)?\^c")
        if cx is not None:
            for step in cx.steps:
                if step.op == "coriolis" and pat.fullmatch(step.label) and step.label in env:
                    return np.asarray(env[step.label], dtype=float)[..., :2]
        raise InputError(f"there is no Coriolis component at {p} in this mechanism's "
                         "acceleration polygon", key=key.text)

    def instant_center(self, key: Key, i: str, j: str) -> Exact:
        """Instant center I_ij: a position, or a direction when at infinity."""
        if self._ic is None:
            self._ic = _optional_instant_centers(self.sol)
        entry = self._ic.get(f"{i}-{j}") if self._ic else None
        if isinstance(entry, dict):
            if entry.get("position") is not None:
                return Exact(None, np.asarray(entry["position"], dtype=float))
            if entry.get("direction") is not None:
                return Exact(None, np.asarray(entry["direction"], dtype=float), ideal=True)
        sol = self.sol
        if not sol.has_rates:
            sol = _with_unit_rate(sol, key)
        return _equal_velocity_point(sol, i, j, key)

    def radius(self, key: Key, p: str) -> float:
        """Radius of curvature of the path of P (``inf`` where the path is straight)."""
        self._rates(key, acc=True)
        if self._paths is None:
            self._paths = _optional_paths(self.sol)
        entry = (self._paths or {}).get(p)
        if isinstance(entry, dict) and entry.get("radius_of_curvature") is not None:
            return float(entry["radius_of_curvature"])
        v = self.sol.velocity(p)
        a = self.sol.acceleration(p)
        speed = float(np.hypot(*v))
        if speed <= self.floor("velocity"):
            raise InputError(f"{p} is at rest, so its path has no radius of curvature here",
                             key=key.text)
        cross = abs(float(v[0] * a[1] - v[1] * a[0]))
        if cross <= _ZERO * speed * max(float(np.hypot(*a)), self.floor("acceleration")):
            return math.inf
        return speed**3 / cross


def _optional_instant_centers(sol: Solution) -> dict[str, Any]:
    """``instant_centers_json(sol)`` of :mod:`graphkin.output.centers` ({} if it fails)."""
    from graphkin.output.centers import instant_centers_json

    return _section(instant_centers_json, sol)


def _optional_paths(sol: Solution) -> dict[str, Any]:
    """``paths_json(sol)`` of :mod:`graphkin.output.curvature` ({} if it fails)."""
    from graphkin.output.curvature import paths_json

    return _section(paths_json, sol)


def _section(fn: Any, sol: Solution) -> dict[str, Any]:
    try:
        out = fn(sol)
    except (GraphkinError, ArithmeticError, ValueError, KeyError, TypeError):
        return {}
    return out if isinstance(out, dict) else {}


def _with_unit_rate(sol: Solution, key: Key) -> Solution:
    """The same posture solved with the (single) drive turning at a unit rate.

    Instant centers depend on the posture only; their location from the
    velocities does not depend on the rate chosen.
    """
    from graphkin.kinematics.solve import solve

    mech = sol.mechanism
    if len(mech.drives) != 1:
        raise InputError("instant centers of a mechanism with several inputs need the "
                         "inputs' rates in the mechanism file", key=key.text)
    drives = tuple(dataclasses.replace(d, rate=1.0, rate2=0.0) for d in mech.drives)
    return solve(dataclasses.replace(mech, drives=drives), branches=dict(sol.branches))


def _equal_velocity_point(sol: Solution, i: str, j: str, key: Key) -> Exact:
    """The point at which links i and j have equal velocities (Sec. 3.13)."""
    def field_at_origin(lid: str) -> tuple[np.ndarray, float]:
        st = sol.links[lid]
        w = float(st.omega) if st.omega is not None else 0.0
        vo = np.zeros(2) if st.origin_velocity is None else np.asarray(st.origin_velocity)
        # velocity of the body point at the world origin: V_O + ω × (0 − O)
        return vo - w * perp(np.asarray(st.origin, dtype=float)), w

    ci, wi = field_at_origin(i)
    cj, wj = field_at_origin(j)
    dw = wi - wj
    dc = cj - ci
    big = max(abs(wi), abs(wj), 1.0)
    if abs(dw) > _ZERO * big:
        w = dc / dw  # = k × P
        return Exact(None, np.array([w[1], -w[0]]))
    n = float(np.hypot(*dc))
    if n == 0.0:
        raise InputError(f"links {i} and {j} have no relative motion, so I{i}{j} is not "
                         "defined", key=key.text)
    d = perp(dc / n)
    return Exact(None, np.asarray(d, dtype=float), ideal=True)
