"""Damped Newton-Raphson and the deterministic search for a posture (Sec. 2.7)."""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping

import numpy as np

from graphkin.errors import AssemblyError
from graphkin.kinematics.analytic.constraints import _Poses, _wrap_array
from graphkin.kinematics.analytic.system import _System
from graphkin.mechanisms.model import FRAME, Drive

Guess = Mapping[str, tuple[float, float, float]]

#: Scaled residual below which Levenberg-Marquardt hands over to plain Newton.
_LM_DONE = 1e-8

#: Iteration limits of the two stages.
_LM_ITER = 200

_NEWTON_ITER = 12

#: Every this many iterations, a residual that fell by less than _STALL_RATIO while
#: still above _STALL_FAR (scaled) means a local minimum of |Φ|: that start fails.
_STALL_EVERY = 10

_STALL_RATIO = 0.9

_STALL_FAR = 1e-3

#: Number of deterministic pseudo-random restarts when no guess is given.
_RESTARTS = 40

#: Seed of those restarts: the search is deterministic.
_SEED = 20240611

#: Two converged postures are the same when every scaled coordinate agrees to this.
_SAME_POSTURE = 1e-6

#: A hint score within this fraction of the size² of the best is a tie (and a
#: score this small means the hints are met exactly).
_TIE = 1e-12

# ---------------------------------------------------------------------------
# Newton-Raphson with damping
# ---------------------------------------------------------------------------


def _converge(eqs: _System, q0: np.ndarray, values: np.ndarray,
              max_iter: int = _LM_ITER) -> np.ndarray | None:
    """Solve Φ(q) = 0 from ``q0``: Levenberg-Marquardt, then Newton polishing.

    Returns the converged ``q`` (angles wrapped to (-π, π]) or None.
    """
    accept = eqs.tol.length_rel * 1e-2
    with np.errstate(all="ignore"):
        q = np.array(q0, dtype=float)
        cs = eqs.col_scale
        try:
            r, J = eqs.scaled(q, values)
        except (ValueError, OverflowError):
            return None
        f = float(r @ r)
        A = J.T @ J
        mu = 1e-3 * max(float(np.max(np.diag(A))), 1e-12)
        nu = 2.0
        f_before = f
        for it in range(max_iter):
            if not math.isfinite(f):
                return None
            if math.sqrt(f) < _LM_DONE:
                break
            if it and it % _STALL_EVERY == 0:
                # stalled far from any solution: a local minimum of |Φ|, give up
                if f > _STALL_RATIO * f_before and f > _STALL_FAR**2:
                    return None
                f_before = f
            g = J.T @ r
            try:
                step = np.linalg.solve(A + mu * np.eye(eqs.n), -g)
            except np.linalg.LinAlgError:
                mu *= nu
                nu *= 2.0
                continue
            big = float(np.max(np.abs(step)))
            if big > 1.0:  # a trust region of one size (or one radian) per step
                step /= big
            q_new = q + step * cs
            try:
                r_new, J_new = eqs.scaled(q_new, values)
            except (ValueError, OverflowError):
                return None
            f_new = float(r_new @ r_new)
            predicted = float(step @ (mu * step - g))
            rho = (f - f_new) / predicted if predicted > 0 else -1.0
            if math.isfinite(f_new) and rho > 0:
                q, r, J, f = q_new, r_new, J_new, f_new
                A = J.T @ J
                mu *= max(1.0 / 3.0, 1.0 - (2.0 * rho - 1.0) ** 3)
                nu = 2.0
            else:
                mu *= nu
                nu *= 2.0
                if mu > 1e16:
                    return None
        else:
            if math.sqrt(f) >= _LM_DONE:
                return None
        # Newton polishing (quadratic convergence at a regular solution)
        for _ in range(_NEWTON_ITER):
            try:
                step = np.linalg.lstsq(J, -r, rcond=None)[0]
            except np.linalg.LinAlgError:
                break
            q_new = q + step * cs
            try:
                r_new, J_new = eqs.scaled(q_new, values)
            except (ValueError, OverflowError):
                break
            f_new = float(r_new @ r_new)
            if not (math.isfinite(f_new) and f_new < f):
                break
            q, r, J, f = q_new, r_new, J_new, f_new
            if f == 0.0:
                break
        if not math.isfinite(f) or float(np.max(np.abs(r), initial=0.0)) > accept:
            return None
    out = q.copy()
    out[2::3] = _wrap_array(out[2::3])
    return out

# ---------------------------------------------------------------------------
# Starting guesses and the choice among branches
# ---------------------------------------------------------------------------


def _fit_pose(pairs: list[tuple[tuple[float, float], tuple[float, float]]],
              angle: float | None) -> tuple[float, float, float]:
    """Rigid pose taking local points onto world points (least squares, Procrustes)."""
    n = len(pairs)
    lx = sum(p[0][0] for p in pairs) / n
    ly = sum(p[0][1] for p in pairs) / n
    wx = sum(p[1][0] for p in pairs) / n
    wy = sum(p[1][1] for p in pairs) / n
    if angle is None:
        sc = sum((p[0][0] - lx) * (p[1][1] - wy) - (p[0][1] - ly) * (p[1][0] - wx)
                 for p in pairs)
        cc = sum((p[0][0] - lx) * (p[1][0] - wx) + (p[0][1] - ly) * (p[1][1] - wy)
                 for p in pairs)
        angle = math.atan2(sc, cc) if (sc or cc) else 0.0
    c, s = math.cos(angle), math.sin(angle)
    return (wx - (c * lx - s * ly), wy - (s * lx + c * ly), angle)


class _Search:
    """Starting guesses (from the assembly hints and the frame), restarts, and the choice."""

    def __init__(self, eqs: _System) -> None:
        self.eqs = eqs
        mech = eqs.mech
        self.frame_pts = dict(mech.links[FRAME].points)
        self.hints = dict(mech.assembly)
        pts = list(self.frame_pts.values()) + list(self.hints.values())
        if pts:
            self.center = (sum(p[0] for p in pts) / len(pts), sum(p[1] for p in pts) / len(pts))
        else:
            self.center = (0.0, 0.0)

    def heuristic(self, values: np.ndarray, rng: np.random.Generator | None,
                  fixed: Guess | None = None) -> np.ndarray:
        """Place links one by one from what is known: frame points, hints, drive angles.

        With ``rng`` the links that nothing places get random angles and the
        hinted positions are jittered; without, they get angle 0.
        """
        eqs, mech = self.eqs, self.eqs.mech
        size = eqs.size
        known: dict[str, tuple[float, float]] = {}
        for name, xy in self.hints.items():
            if rng is not None:
                xy = (xy[0] + 0.05 * size * rng.standard_normal(),
                      xy[1] + 0.05 * size * rng.standard_normal())
            known[name] = xy
        known.update(self.frame_pts)
        poses: dict[str, tuple[float, float, float]] = {FRAME: (0.0, 0.0, 0.0)}
        if fixed:
            for lid, pose in fixed.items():
                if lid in eqs.index and lid != FRAME:
                    poses[lid] = tuple(float(v) for v in pose)  # type: ignore[assignment]
        angles: dict[str, float] = {}
        for d, v in zip(mech.drives, values):
            if d.kind == "angle":
                angles[d.link] = float(v)
        # at the file's drive each rolling contact places a link at its angle (its phase)
        for ph in eqs.phases:
            if ph.kind == "angle":
                angles.setdefault(ph.link, float(ph.value))

        def learn(lid: str) -> None:
            x, y, t = poses[lid]
            c, s = math.cos(t), math.sin(t)
            for name, p in mech.links[lid].points.items():
                if name not in known:
                    known[name] = (x + c * p[0] - s * p[1], y + s * p[0] + c * p[1])

        for lid in list(poses):
            learn(lid)
        todo = [lid for lid in eqs.ids if lid not in poses]
        while todo:
            progress = False
            for lid in list(todo):
                angle = angles.get(lid)
                if angle is None:
                    for sl in mech.sliders:
                        if sl.link == lid and sl.on in poses:
                            angle = poses[sl.on][2] + sl.direction_angle
                        elif sl.on == lid and sl.link in poses:
                            angle = poses[sl.link][2] - sl.direction_angle
                pairs = [(p, known[name]) for name, p in mech.links[lid].points.items()
                         if name in known]
                if len(pairs) >= 2 or (pairs and angle is not None):
                    poses[lid] = _fit_pose(pairs, angle)
                    learn(lid)
                    todo.remove(lid)
                    progress = True
            if progress:
                continue
            # nothing can be placed for sure: place the best-known link with a guessed angle
            lid = max(todo, key=lambda k: sum(n in known for n in mech.links[k].points))
            pairs = [(p, known[name]) for name, p in mech.links[lid].points.items()
                     if name in known]
            angle = angles.get(lid)
            if angle is None:
                angle = float(rng.uniform(-math.pi, math.pi)) if rng is not None else 0.0
            if pairs:
                poses[lid] = _fit_pose(pairs[:1], angle)
            else:
                poses[lid] = (self.center[0], self.center[1], angle)
            learn(lid)
            todo.remove(lid)
        q = np.zeros(eqs.n)
        for lid in eqs.ids:
            k = eqs.index[lid]
            q[3 * k:3 * k + 3] = poses[lid]
        return q

    def random(self, values: np.ndarray, rng: np.random.Generator) -> np.ndarray:
        """Every link anywhere near the frame, at any angle (drive angles kept)."""
        eqs = self.eqs
        q = np.zeros(eqs.n)
        for k in range(eqs.nlinks):
            q[3 * k] = self.center[0] + eqs.size * rng.uniform(-1.0, 1.0)
            q[3 * k + 1] = self.center[1] + eqs.size * rng.uniform(-1.0, 1.0)
            q[3 * k + 2] = rng.uniform(-math.pi, math.pi)
        for d, v in zip(eqs.mech.drives, values):
            if d.kind == "angle":
                q[3 * eqs.index[d.link] + 2] = v
        for ph in eqs.phases:
            if ph.kind == "angle":
                q[3 * eqs.index[ph.link] + 2] = ph.value
        return q

    def score(self, q: np.ndarray) -> tuple[float, float]:
        """(distance² to the hints, distance² to the file's own layout)."""
        eqs, mech = self.eqs, self.eqs.mech
        st = _Poses(q, eqs.nlinks)
        hint = 0.0
        for name, (hx, hy) in self.hints.items():
            owners = mech.point_links[name]
            lid = next((o for o in owners if o != FRAME), owners[0])
            px, py = st.world(eqs.index[lid], mech.links[lid].points[name])
            hint += (px - hx) ** 2 + (py - hy) ** 2
        layout = 0.0
        for lid in eqs.ids:
            k = eqs.index[lid]
            for p in mech.links[lid].points.values():
                px, py = st.world(k, p)
                layout += (px - p[0]) ** 2 + (py - p[1]) ** 2
        return hint, layout

    def same(self, q1: np.ndarray, q2: np.ndarray) -> bool:
        d = (q1 - q2) / self.eqs.col_scale
        d[2::3] = _wrap_array(d[2::3])
        return bool(np.max(np.abs(d), initial=0.0) < _SAME_POSTURE)

    def solve(self, values: np.ndarray, restarts: int = _RESTARTS,
              explain: bool = True) -> np.ndarray:
        """Every start, every converged posture; return the one nearest the hints.

        Raises AssemblyError when nothing converges; with ``explain`` its
        message names the constraint that stays open at the best compromise.
        """
        eqs = self.eqs
        rng = np.random.default_rng(_SEED)
        found: list[np.ndarray] = []
        starts: list[Callable[[], np.ndarray]] = [lambda: self.heuristic(values, None)]
        for i in range(restarts):
            if i % 2 == 0:
                starts.append(lambda: self.heuristic(values, rng))
            else:
                starts.append(lambda: self.random(values, rng))
        exact = _TIE * eqs.size**2
        for make in starts:
            q = _converge(eqs, make(), values)
            if q is None or any(self.same(q, f) for f in found):
                continue
            found.append(q)
            if self.hints and self.score(q)[0] <= exact:
                break  # the hints are met exactly: no posture can be nearer
        if not found:
            if not explain:
                raise AssemblyError("cannot assemble the mechanism", key="drive",
                                    file=eqs.mech.source)
            raise _assembly_error(eqs, values, self.best_attempt(values))
        scores = [self.score(q) for q in found]
        best_hint = min(s[0] for s in scores)
        tie = best_hint + _TIE * eqs.size**2 * max(1, len(self.hints))
        candidates = [(s[1], i) for i, s in enumerate(scores) if s[0] <= tie]
        return found[min(candidates)[1]]

    def best_attempt(self, values: np.ndarray) -> np.ndarray:
        """The least-squares compromise of the unsolvable equations (for the message)."""
        q = self.heuristic(values, None)
        with np.errstate(all="ignore"):
            for _ in range(_LM_ITER):
                r, J = self.eqs.scaled(q, values)
                try:
                    step = np.linalg.lstsq(J, -r, rcond=None)[0]
                except np.linalg.LinAlgError:
                    break
                big = float(np.max(np.abs(step), initial=0.0))
                if not math.isfinite(big):
                    break
                q = q + step * self.eqs.col_scale * min(1.0, 0.5 / max(big, 1e-300))
        return q


def _assembly_error(eqs: _System, values: np.ndarray, q: np.ndarray) -> AssemblyError:
    """Name the constraint that stays open at the best compromise."""
    mech = eqs.mech
    what = ", ".join(_drive_text(d, v) for d, v in zip(mech.drives, values))
    reason = "the loop-closure equations have no real solution"
    with np.errstate(all="ignore"):
        r, _ = eqs.residual(q, values, jac=False)
    if np.all(np.isfinite(r)) and r.size:
        row = 0
        worst, worst_label = 0.0, ""
        for c in [*eqs.cons, *eqs.drives]:
            for j, kind in enumerate(c.kinds):
                v = abs(float(r[row + j])) * (1.0 / eqs.size if kind == "L" else 1.0)
                if v > worst:
                    worst, worst_label = v, c.label
            row += len(c.kinds)
        if worst_label:
            reason += f" ({worst_label} cannot be closed)"
    return AssemblyError(f"cannot assemble the mechanism at {what}: {reason}",
                         key="drive", file=mech.source)


def _drive_text(d: Drive, v: float) -> str:
    if d.kind in ("relative", "x", "y"):
        return d.describe() if v == d.value else f"{d.label} = " + (
            f"{math.degrees(v):.6g}°" if d.is_angle else f"{v:.6g}")
    if d.kind == "angle":
        return f"link {d.link} angle {math.degrees(v):.6g}°"
    return f"link {d.link} position {v:.6g}"
