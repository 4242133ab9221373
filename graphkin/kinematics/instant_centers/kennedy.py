"""Primary centers by inspection and the rest by the Aronhold-Kennedy theorem (Secs. 3.12-3.14)."""

from __future__ import annotations

from collections.abc import Sequence
from itertools import combinations
from typing import Any, Literal

import numpy as np

from graphkin.construction import Construction, Role
from graphkin.construction.ops import OPS
from graphkin.errors import GraphkinError, InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.instant_centers.centers import (
    Center,
    How,
    InstantCenters,
    KnownCenter,
    KnownLine,
    _as_float,
)
from graphkin.kinematics.instant_centers.labels import (
    _id_key,
    _triangle,
    center_label,
    pair_key,
    sort_links,
)
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["instant_centers", "instant_center", "FAR_AS_INFINITY"]

Pair = tuple[str, str]

Array = np.ndarray

#: A meet of two lines of centers (or a join of two centers) whose sine, in
#: coordinates scaled by the size of the mechanism, is below this loses more
#: than 6 of 16 digits: another triangle, or the velocities, are used instead.
_WELL_CONDITIONED = 1e-6

#: A center farther from the origin than this many sizes of the mechanism is
#: at infinity: its two lines of centers are parallel but for the round-off
#: of the file's numbers (an angle below 1e-6 rad, far finer than any drawing).
#: The center is then recorded as the point at infinity in that direction, so
#: that the report, JSON and drawings print a direction, never a huge coordinate.
FAR_AS_INFINITY = 1e6


def _far_as_ideal(p: Array, far: float) -> Array:
    """A finite point farther than ``far`` from the origin as the point at infinity there.

    Examples
    --------
    >>> _far_as_ideal(np.array([-2.5e8, 0.0, 1.0]), 5e6).tolist()
    [-1.0, 0.0, 0.0]
    >>> _far_as_ideal(np.array([3.0, 4.0, 1.0]), 5e6).tolist()
    [3.0, 4.0, 1.0]
    """
    p = np.asarray(p, dtype=float)
    if p.shape[-1:] != (3,):
        return p
    w = p[..., 2]
    r = np.hypot(p[..., 0], p[..., 1])
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        far_away = (w != 0) & np.isfinite(r) & (r > far * np.abs(w))
        ideal = np.stack([p[..., 0] / r, p[..., 1] / r, np.zeros_like(w)], axis=-1)
    return np.where(far_away[..., None], ideal, p)


def _perp(v: Array) -> Array:
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _is_batch(sol: Solution) -> bool:
    return np.ndim(sol.links[FRAME].angle) > 0


class _Kennedy:
    """Finds the centers one at a time and records each step."""

    def __init__(self, sol: Solution, tol: Tolerance, contacts: Sequence[object]) -> None:
        self.sol = sol
        self.mech: Mechanism = sol.mechanism
        self.tol = tol
        self.links = sort_links(self.mech.links)
        self.cx = Construction(title=f"Instant centers: {self.mech.title}".rstrip(": "))
        self.env: dict[str, Array] = {}
        self.centers: dict[Pair, Center] = {}
        self.normals: dict[Pair, list[tuple[str, str]]] = {}  # pair -> [(line label, source)]
        self.failed: set[Pair] = set()
        self.notes: list[str] = []
        self.contacts = list(contacts)
        self.several = len(self.mech.drives) > 1 or self.mech.mobility() > 1
        self._unit: Solution | Literal[False] | None = None  # False: tried, none
        shape = np.shape(sol.links[FRAME].angle)
        # a batch's postures that could not be assembled are NaN throughout: ignored
        self.valid = np.broadcast_to(np.asarray(sol.valid, dtype=bool), shape)

    # ---- recording ----------------------------------------------------
    def add(self, op_name: str, inputs: tuple[str, ...], output: str, *,
            role: Role = Role.AUXILIARY, note: str = "", **params: Any) -> Array:
        step = self.cx.add(op_name, inputs, (output,), role=role, note=note, diagram="centers",
                           **params)
        args = [self.env[i] for i in inputs]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            (out,) = OPS[op_name](*args, tol=self.tol, **step.params)
        self.env[output] = np.asarray(out, dtype=float)
        return self.env[output]

    def found(self, pair: Pair, how: How, source: str, note: str, *, lines: tuple[str, ...] = (),
              triangles: tuple[tuple[str, str, str], ...] = (), speed: bool = False) -> None:
        lab = center_label(*pair)
        self.env[lab] = _far_as_ideal(self.env[lab], FAR_AS_INFINITY * self.mech.scale)
        self.centers[pair] = Center(pair, lab, self.env[lab], how, source, len(self.centers) + 1,
                                    lines, triangles, speed, note)

    def fresh(self, label: str) -> str:
        if label not in self.env:
            return label
        k = 2
        while f"{label}#{k}" in self.env:
            k += 1
        return f"{label}#{k}"

    # ---- primary centers and lines --------------------------------------
    def primary(self) -> None:
        sol, mech = self.sol, self.mech
        found: dict[Pair, tuple[str, Any, str, str]] = {}
        for pin in mech.pins:
            p = sol.position(pin.name)
            for a, b in combinations(pin.links, 2):
                pair = pair_key(a, b)
                if pair in found:
                    continue
                lab = center_label(*pair)
                found[pair] = ("point", (_as_float(p[..., 0]), _as_float(p[..., 1])),
                               f"pin {pin.name}",
                               f"{lab} is the pin {pin.name}: a point common to links "
                               f"{pair[0]} and {pair[1]} (primary, by inspection).")
        for s in mech.sliders:
            pair = pair_key(s.link, s.on)
            if pair in found:
                continue
            lab = center_label(*pair)
            th = np.asarray(sol.links[s.on].angle, dtype=float) + s.direction_angle
            n = np.stack([-np.sin(th), np.cos(th)], axis=-1)
            found[pair] = ("ideal_point", (_as_float(n[..., 0]), _as_float(n[..., 1])),
                           f"slider {s.link} on {s.on}",
                           f"{lab} is at infinity, perpendicular to the line on which {s.link} "
                           f"slides on {s.on}: the two links do not turn relative to each other "
                           "(primary, Eq. 3.21).")
        for r in getattr(mech, "rolling", ()):
            pair = pair_key(r.link, r.on)
            if pair in found:
                continue
            lab = center_label(*pair)
            found[pair] = ("rolling", r, f"rolling contact of {r.link} on {r.on}",
                           f"{lab} is the point of rolling contact of {r.link} on {r.on}: the "
                           "foot of the perpendicular from the center of the circle to the line "
                           "it rolls on; no slip, so the velocities are equal there (primary, "
                           "Fig. 3.25).")
        for c in self.contacts:
            if not isinstance(c, KnownCenter):
                continue
            pair = pair_key(*c.links)
            if pair in found:
                continue
            lab = center_label(*pair)
            found[pair] = ("point", (_as_float(c.point[0]), _as_float(c.point[1])), c.source,
                           f"{lab} is the point of {c.source} of links {pair[0]} and {pair[1]}: "
                           "no slip, so their velocities are equal there (primary).")
        for pair in sorted(found, key=lambda p: (_id_key(p[0]), _id_key(p[1]))):
            kind, arg, source, note = found[pair]
            lab = center_label(*pair)
            if kind == "point":
                self.add("point", (), lab, role=Role.GIVEN, note=note, xy=arg)
            elif kind == "rolling":
                self.rolling_contact(arg, lab, note)
            else:
                self.add("ideal_point", (), lab, role=Role.GIVEN, note=note, direction=arg)
            self.found(pair, How.PRIMARY, source, note)
        self.slot_normals()

    def rolling_contact(self, r: Any, lab: str, note: str) -> None:
        """The contact point of a rolling circle (a primary center).

        On a line it is the foot of the perpendicular from the circle's center;
        on a circle, the point of the line of centers at the circle's radius.
        """
        sol = self.sol
        on = sol.links[r.on]
        center = self.fresh(r.center)
        c = sol.position(r.center, r.link)
        self.add("point", (), center, role=Role.GIVEN,
                 note=f"The center {r.center} of the rolling circle of link {r.link}.",
                 xy=(_as_float(c[..., 0]), _as_float(c[..., 1])))
        stem = r.key
        if not r.on_line:
            # circles touch on their line of centers, R from the center of on's circle
            o = on.position(r.on_center)
            self.add("point", (), f"{stem}:O", role=Role.GIVEN,
                     note=f"The center of link {r.on}'s circle.",
                     xy=(_as_float(o[..., 0]), _as_float(o[..., 1])))
            self.add("along_ray", (f"{stem}:O", center), lab, role=Role.GIVEN, note=note,
                     distance=r.on_radius)
            return
        for k, loc in enumerate((r.p0, r.p1)):
            q = on.position(loc)
            self.add("point", (), f"{stem}:L{k}", role=Role.GIVEN,
                     xy=(_as_float(q[..., 0]), _as_float(q[..., 1])))
        self.add("join", (f"{stem}:L0", f"{stem}:L1"), f"{stem}:line",
                 note=f"The line of link {r.on} on which link {r.link} rolls.")
        self.add("perpendicular", (f"{stem}:line", center), f"{stem}:normal",
                 note=f"The common normal: through {r.center}, perpendicular to the line.")
        self.add("meet", (f"{stem}:line", f"{stem}:normal"), lab, role=Role.GIVEN, note=note)

    def slot_normals(self) -> None:
        sol = self.sol
        for s in self.mech.slots:
            pair = pair_key(s.link, s.on)
            if pair in self.centers:
                continue
            lab = center_label(*pair)
            pin = self.fresh(s.point)
            p = sol.position(s.point, s.link)
            self.add("point", (), pin, role=Role.GIVEN,
                     note=f"The pin {s.point} of link {s.link} in the slot of link {s.on}.",
                     xy=(_as_float(p[..., 0]), _as_float(p[..., 1])))
            on = sol.links[s.on]
            stem = f"slots[{s.index}]"
            normal = self.fresh(f"n({s.point}):{lab}")
            if s.is_line:
                assert s.p0 is not None and s.p1 is not None
                q0, q1 = on.position(s.p0), on.position(s.p1)
                self.add("point", (), f"{stem}:L0", role=Role.GIVEN,
                         xy=(_as_float(q0[..., 0]), _as_float(q0[..., 1])))
                self.add("point", (), f"{stem}:L1", role=Role.GIVEN,
                         xy=(_as_float(q1[..., 0]), _as_float(q1[..., 1])))
                self.add("join", (f"{stem}:L0", f"{stem}:L1"), f"{stem}:line",
                         note=f"The slot of link {s.on}: the path of {s.point} on it.")
                self.add("perpendicular", (f"{stem}:line", pin), normal,
                         note=f"{lab} lies on the common normal at {s.point}: the perpendicular "
                              "to the slot through the pin (direct contact, Sec. 3.14).")
            else:
                assert s.center is not None
                k = on.position(s.center)
                self.add("point", (), f"{stem}:center", role=Role.GIVEN,
                         note=f"The center of the circular slot of link {s.on}.",
                         xy=(_as_float(k[..., 0]), _as_float(k[..., 1])))
                self.add("join", (f"{stem}:center", pin), normal,
                         note=f"{lab} lies on the common normal at {s.point}: the line through "
                              "the pin and the center of the circular slot (direct contact, "
                              "Sec. 3.14).")
            self.normals.setdefault(pair, []).append(
                (normal, f"common normal at {s.point} (slot of link {s.on})"))
        for c in self.contacts:
            if not isinstance(c, KnownLine):
                continue
            pair = pair_key(*c.links)
            if pair in self.centers:
                continue
            lab = center_label(*pair)
            through = self.fresh(f"contact:{lab}")
            self.add("point", (), through, role=Role.GIVEN, note=f"The point of {c.source}.",
                     xy=(_as_float(c.through[0]), _as_float(c.through[1])))
            d = self.fresh(f"normal∞:{lab}")
            self.add("ideal_point", (), d, role=Role.GIVEN,
                     direction=(_as_float(c.direction[0]), _as_float(c.direction[1])))
            normal = self.fresh(f"n:{lab}")
            self.add("join", (through, d), normal,
                     note=f"{lab} lies on the common normal at the {c.source} (Sec. 3.14).")
            self.normals.setdefault(pair, []).append((normal, f"common normal ({c.source})"))

    # ---- Kennedy --------------------------------------------------------
    def triangles(self, pair: Pair) -> list[str]:
        i, j = pair
        return [k for k in self.links if k not in pair
                and pair_key(i, k) in self.centers and pair_key(j, k) in self.centers]

    def every(self, flags: Array) -> bool:
        """True when ``flags`` holds at every posture that could be assembled."""
        return bool(np.all(np.broadcast_to(flags, self.valid.shape)[self.valid]))

    def same(self, p: Array, q: Array) -> bool:
        pi, qi = g.is_ideal(p), g.is_ideal(q)
        if self.every(pi) and self.every(qi):
            return self.every(np.abs(g.cross2(p, q)) <= self.tol.angle)
        if not (self.every(~pi) and self.every(~qi)):
            return False
        with np.errstate(invalid="ignore"):
            d = g.distance(p, q)
        return self.every(d <= self.tol.length(self.mech.scale))

    def tri_line(self, pair: Pair, k: str) -> tuple[str, str, str]:
        """The two centers of triangle (i, j, k) that carry Iij, lower label first."""
        a, b = sorted([pair_key(pair[0], k), pair_key(pair[1], k)],
                      key=lambda p: (_id_key(p[0]), _id_key(p[1])))
        la, lb = center_label(*a), center_label(*b)
        return la, lb, f"{la}-{lb}"

    def make_line(self, pair: Pair, opt: tuple[str, str, Array, float]) -> str:
        kind, ref = opt[0], opt[1]
        if kind == "normal":
            return ref
        la, lb, name = self.tri_line(pair, ref)
        if name not in self.env:
            i, j = pair
            self.add("join", (la, lb), name,
                     note=f"The line of centers {name}: {center_label(i, j)} lies on it "
                          f"(links {', '.join(sort_links([i, j, ref]))}: three centers on one "
                          "straight line).")
        return name

    def describe(self, pair: Pair, opt: tuple[str, str, Array, float]) -> str:
        kind, ref = opt[0], opt[1]
        if kind == "normal":
            src = dict(self.normals[pair])[ref]
            return "the " + src
        return "the line " + self.tri_line(pair, ref)[2]

    def point_hat(self, p: Array) -> Array:
        q = np.asarray(p, dtype=float) * np.array([1.0 / self.mech.scale] * 2 + [1.0])
        return q / np.linalg.norm(q, axis=-1, keepdims=True)

    def line_hat(self, line: Array) -> Array:
        q = np.asarray(line, dtype=float) * np.array([1.0, 1.0, 1.0 / self.mech.scale])
        return q / np.linalg.norm(q, axis=-1, keepdims=True)

    def quality(self, u: Array, v: Array) -> float:
        """Sine of the angle between two unit homogeneous vectors (worst entry of a batch).

        For two points (lengths over the figure's size) it says how far apart
        they are, for two lines how far from coincident: the join or meet
        loses about ``-log10(quality)`` digits.
        """
        with np.errstate(invalid="ignore"):
            s = np.linalg.norm(np.cross(u, v), axis=-1)
        s = np.where(np.isfinite(s), s, 0.0)[self.valid]
        return float(np.min(s)) if s.size else 0.0

    def ok(self, a: Array) -> bool:
        """True when ``a`` has an answer at every posture that could be assembled."""
        return self.every(np.all(np.isfinite(a), axis=-1))

    def try_pair(self, pair: Pair, enough: float) -> bool:
        """Find ``Iij`` by Kennedy's theorem if two lines of centers meet well enough."""
        i, j = pair
        lab = center_label(*pair)
        tris = self.triangles(pair)
        for k in tris:
            la, lb, _ = self.tri_line(pair, k)
            if self.same(self.env[la], self.env[lb]):
                note = (f"{lab} coincides with {la} and {lb}: where links {i}, {j} and {k} all "
                        "have the same velocity (Kennedy).")
                self.add("same_point", (la, lb), lab, role=Role.RESULT, note=note)
                self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la, lb),
                           triangles=(_triangle(i, j, k),))
                return True
        # (kind, ref, line, quality of the line)
        opts: list[tuple[str, str, Array, float]] = []
        for name, _src in self.normals.get(pair, []):
            opts.append(("normal", name, self.env[name], 1.0))
        parallel_to: list[str] = []
        for k in tris:
            la, lb, name = self.tri_line(pair, k)
            p, q = self.env[la], self.env[lb]
            if self.every(g.is_ideal(p)) and self.every(g.is_ideal(q)):
                parallel_to.append(k)
                continue
            with np.errstate(invalid="ignore", divide="ignore"):
                line = g.join(p, q, self.tol)
            if self.ok(line):
                opts.append(("tri", k, line, self.quality(self.point_hat(p), self.point_hat(q))))
        best: tuple[float, int, int] | None = None
        for (ia, a), (ib, b) in combinations(enumerate(opts), 2):
            with np.errstate(invalid="ignore", divide="ignore"):
                pt = g.meet(a[2], b[2], self.tol)
            if not self.ok(pt):
                continue
            qual = min(a[3], b[3], self.quality(self.line_hat(a[2]), self.line_hat(b[2])))
            if qual >= enough and (best is None or qual > best[0]):
                best = (qual, ia, ib)
        if best is not None:
            a, b = opts[best[1]], opts[best[2]]
            la, lb = self.make_line(pair, a), self.make_line(pair, b)
            note = (f"{lab} lies on {self.describe(pair, a)} and on {self.describe(pair, b)} "
                    "(Kennedy).")
            self.add("meet", (la, lb), lab, role=Role.RESULT, note=note)
            tri = tuple(_triangle(i, j, o[1]) for o in (a, b) if o[0] == "tri")
            self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la, lb), triangles=tri)
            return True
        good = [o for o in opts if o[3] >= enough]
        if parallel_to and good:
            k = parallel_to[0]
            a = max(good, key=lambda o: o[3])
            la = self.make_line(pair, a)
            ca, cb, _ = self.tri_line(pair, k)
            note = (f"{lab} lies on {self.describe(pair, a)}; {ca} and {cb} are both at "
                    f"infinity, so links {i} and {j} do not turn relative to each other and "
                    f"{lab} is at infinity on that line (Kennedy, Fig. 3.27).")
            self.add("at_infinity_on", (la,), lab, role=Role.RESULT, note=note)
            tris_ij = [_triangle(i, j, k)]
            if a[0] == "tri":
                tris_ij.insert(0, _triangle(i, j, a[1]))
            self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la,),
                       triangles=tuple(tris_ij))
            return True
        return False

    def known_lines(self, pair: Pair) -> int:
        return len(self.normals.get(pair, [])) + len(self.triangles(pair))

    # ---- from the velocities (several degrees of freedom) --------------
    def velocities(self) -> Solution | None:
        """A solution with velocities, or None.

        The given one; or, for one degree of freedom and no rates in the file,
        the same posture at a unit input speed (the centers of a
        one-degree-of-freedom mechanism do not depend on the speed, Sec. 3.14).
        """
        if self.sol.has_rates:
            return self.sol
        if self._unit is not None:
            return self._unit or None
        self._unit = False
        if len(self.mech.drives) != 1 or _is_batch(self.sol):
            return None
        from dataclasses import replace

        from graphkin.kinematics.analytic import solve_analytic

        drive = replace(self.mech.drives[0], rate=1.0, rate2=0.0)
        mech = replace(self.mech, drives=(drive,), rates=None)
        guess = {lid: (float(st.origin[0]), float(st.origin[1]), float(st.angle))
                 for lid, st in self.sol.links.items() if lid != FRAME}
        try:
            self._unit = solve_analytic(mech, guess=guess, tol=self.tol)
        except GraphkinError:
            return None
        return self._unit

    def by_velocities(self, unknown: list[Pair]) -> bool:
        sol = self.velocities()
        if sol is None:
            return False
        drives = {d.link for d in self.mech.drives}
        cands = [p for p in unknown if p not in self.failed]
        if not cands:
            return False
        cands.sort(key=lambda p: (0 if set(p) <= drives else 1, -self.known_lines(p),
                                  _id_key(p[0]), _id_key(p[1])))
        for pair in cands:
            h = _equal_velocity_point(sol, pair[0], pair[1], self.mech.scale, self.tol)
            if not self.ok(h):
                self.failed.add(pair)
                continue
            i, j = pair
            lab = center_label(*pair)
            on = ""
            tris = self.triangles(pair)
            if tris:
                _, _, name = self.tri_line(pair, tris[0])
                on = f" It lies on the line {name}, where ω{i}/ω{j} sets its place (Eq. 3.22)."
            if self.several:
                note = (f"{lab} cannot be found by Kennedy's theorem alone: it is the point "
                        f"where links {i} and {j} have equal velocities, and it depends on the "
                        f"ratio of the input speeds (several degrees of freedom, Sec. 5.4).{on}")
            else:
                unit = "" if sol is self.sol else (
                    " (for a unit input speed: with one degree of freedom the place does not "
                    "depend on the speed)")
                note = (f"{lab} cannot be found by Kennedy's theorem here (its lines of centers "
                        "coincide or meet at too small an angle): it is the point where links "
                        f"{i} and {j} have equal velocities{unit} (Sec. 3.12).{on}")
            self.add("homogeneous_point", (), lab, role=Role.RESULT, note=note,
                     h=_as_float(h) if np.ndim(h) > 1 else tuple(float(v) for v in h))
            self.found(pair, How.VELOCITIES, "velocities", note, speed=self.several)
            return True
        return False

    # ---- driver -------------------------------------------------------
    def run(self) -> InstantCenters:
        self.primary()
        pairs = [pair_key(a, b) for a, b in combinations(self.links, 2)]
        while True:
            unknown = [p for p in pairs if p not in self.centers]
            if not unknown:
                break
            if any(self.try_pair(p, _WELL_CONDITIONED) for p in unknown):
                continue
            if self.by_velocities(unknown):
                continue
            # no velocities to fall back on: take a poorly conditioned meet rather than none
            if not any(self.try_pair(p, self.tol.angle) for p in unknown):
                break
        missing = [p for p in pairs if p not in self.centers]
        if missing:
            names = ", ".join(center_label(*p) for p in missing)
            if self.velocities() is None and self.several:
                self.notes.append(f"{names}: not found by Kennedy's theorem; they depend on the "
                                  "input speeds, which the file does not give (Sec. 5.4)")
            else:
                self.notes.append(f"{names}: not found (the two links have no relative motion "
                                  "here, or their lines of centers coincide)")
        return InstantCenters(self.sol, self.links, self.centers, self.cx, self.env, missing,
                              self.notes)


def _world_origin_velocity(sol: Solution, lid: str) -> tuple[Array, Array]:
    """``(u, ω)``: velocity of the point of link ``lid`` at the world origin, and ω."""
    st = sol.links[lid]
    if st.omega is None or st.origin_velocity is None:
        raise InputError("the velocities are not known (the file gives no rates)")
    w = np.asarray(st.omega, dtype=float)
    u = np.asarray(st.origin_velocity, dtype=float) - w[..., None] * _perp(
        np.asarray(st.origin, dtype=float))
    return u, w


def _equal_velocity_point(sol: Solution, i: str, j: str, scale: float,
                          tol: Tolerance) -> Array:
    """Homogeneous point where links ``i`` and ``j`` have the same velocity (Sec. 3.12).

    With ``V_k(P) = u_k + ω_k k × P``, equal velocities give
    ``(ω_i - ω_j) k × P = u_j - u_i``, so ``P = k × (u_i - u_j) / (ω_i - ω_j)``
    (Eq. 3.18 for the relative motion).  Equal ω: at infinity, perpendicular
    to the relative velocity.  No relative motion at all: NaN.
    """
    ui, wi = _world_origin_velocity(sol, i)
    uj, wj = _world_origin_velocity(sol, j)
    du = ui - uj
    h = np.concatenate([_perp(du) / scale, (wi - wj)[..., None]], axis=-1)
    p = g.normalize_point(h, tol)
    return np.where(g.is_ideal(p)[..., None], p, p * np.array([scale, scale, 1.0]))

# ---------------------------------------------------------------------------
# the public API
# ---------------------------------------------------------------------------

def instant_centers(sol: Solution, *, tol: Tolerance | None = None,
                    contacts: Sequence[KnownCenter | KnownLine] = ()) -> InstantCenters:
    """Every instant center of a solved mechanism, found the way the book teaches.

    Parameters
    ----------
    sol : Solution
        One posture or a batch (every array then has a leading axis).
    tol : Tolerance, optional
        Decides when two centers coincide and when two lines are parallel.
    contacts : sequence of KnownCenter or KnownLine
        Primary centers (rolling contact) and lines of centers (direct
        contact) that the mechanism file does not state.

    Returns
    -------
    InstantCenters
        ``n(n-1)/2`` centers (Eq. 3.20) in order of discovery, with the
        recorded construction.

    Raises
    ------
    InputError
        A contact names a link that is not in the mechanism.

    See Also
    --------
    angular_velocity_ratio, line_of_centers_velocity, mechanical_advantage

    Notes
    -----
    The search follows the Kennedy circle: primary centers first (pins,
    sliders, rolling contacts), then repeatedly the first unknown pair (in the
    order I12, I13, ...) that two known lines of centers reach.  When none
    can be reached and the velocities are known, one center is found from the
    velocities (preferring the pair of the two input links, as in
    Example 5.5) and the search goes on.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.14 (Eq. 3.20, Figs.
    3.22-3.28) and Sec. 5.4 (Example 5.5).

    Examples
    --------
    The inverted slider-crank of Fig. 3.26: the block 3 slides on the rod 4,
    so I34 is at infinity, perpendicular to the rod.

    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... E = [0, 0]
    ... D = [14, 0]
    ... [links.2]
    ... E = [0, 0]
    ... A = [3, 0]
    ... [links.3]
    ... A = [0, 0]
    ... [links.4]
    ... D = [0, 0]
    ... L1 = [0, 0]
    ... L2 = [1, 0]
    ... [[sliders]]
    ... link = 3
    ... on = 4
    ... point = "A"
    ... line = ["L1", "L2"]
    ... [drive]
    ... link = 2
    ... angle = 90
    ... ''').solve()
    >>> ic = instant_centers(sol)
    >>> ic["I34"].how.value, bool(ic["I34"].is_ideal)
    ('primary', True)
    >>> [round(float(v), 4) + 0.0 for v in ic["I13"].xy]  # on x = 0 and ⊥ DA through D
    [0.0, -65.3333]
    """
    mech = sol.mechanism
    for c in contacts:
        for lid in c.links:
            if str(lid) not in mech.links:
                raise InputError(f"the contact {c.source!r} names link {lid}, which is not in "
                                 f"the mechanism (links: {', '.join(sort_links(mech.links))})")
    return _Kennedy(sol, tol or DEFAULT_TOL, contacts).run()


def instant_center(sol: Solution | InstantCenters, i: object, j: object) -> Array:
    """The instant center ``Iij`` in homogeneous coordinates ``(x, y, w)``.

    ``w = 1`` for a finite center, ``w = 0`` (and a unit direction) at infinity.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links.1]
    ... A = [0, 0]
    ... [links.2]
    ... A = [0, 0]
    ... B = [5, 0]
    ... [drive]
    ... link = 2
    ... angle = 30
    ... ''').solve()
    >>> instant_center(sol, 2, 1)
    array([0., 0., 1.])
    """
    ic = _centers(sol)
    return ic[(i, j)].point


def _centers(obj: Solution | InstantCenters) -> InstantCenters:
    return obj if isinstance(obj, InstantCenters) else instant_centers(obj)
