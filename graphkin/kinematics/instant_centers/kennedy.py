"""The secondary centers by the Aronhold-Kennedy theorem, and the search (Secs. 3.12-3.14)."""

from __future__ import annotations

from collections.abc import Sequence
from itertools import combinations

import numpy as np

from graphkin.construction import Role
from graphkin.errors import GraphkinError, InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.instant_centers.centers import (
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
from graphkin.kinematics.instant_centers.primary import FAR_AS_INFINITY, _PrimaryCenters
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["instant_centers", "instant_center", "FAR_AS_INFINITY"]

Pair = tuple[str, str]

Array = np.ndarray

#: A meet of two lines of centers (or a join of two centers) whose sine, in
#: coordinates scaled by the size of the mechanism, is below this loses more
#: than 6 of 16 digits: another triangle, or the velocities, are used instead.
_WELL_CONDITIONED = 1e-6


#: At most this many lines of centers are offered to :meth:`_Kennedy.best_meet` for one
#: center (the best-conditioned ones): a mechanism of up to 10 links never has more.
_MOST_LINES = 8


def _perp(v: Array) -> Array:
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _is_batch(sol: Solution) -> bool:
    return np.ndim(sol.links[FRAME].angle) > 0


class _Kennedy(_PrimaryCenters):
    """Finds the centers one at a time and records each step: the search of Kennedy's theorem."""

    # ---- Kennedy --------------------------------------------------------
    def triangles(self, pair: Pair) -> list[str]:
        """The links k (in order) whose centers with both links of ``pair`` are known."""
        adj = self.adjacency()
        i, j = pair
        common = adj[i] & adj[j]
        if not common:
            return []
        order = self.__dict__.setdefault("_order", {k: n for n, k in enumerate(self.links)})
        return sorted(common - {i, j}, key=order.__getitem__)

    def adjacency(self) -> dict[str, set[str]]:
        """Link -> the links whose center with it is known (kept up to date as centers come)."""
        adj: dict[str, set[str]] = self.__dict__.setdefault(
            "_adjacency", {k: set() for k in self.links})
        seen = self.__dict__.get("_adjacency_seen", 0)
        if seen != len(self.centers):
            for a, b in list(self.centers)[seen:]:
                adj[a].add(b)
                adj[b].add(a)
            self.__dict__["_adjacency_seen"] = len(self.centers)
        return adj

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
        cache = self.__dict__.setdefault("_tri_lines", {})
        got = cache.get((pair, k))
        if got is None:
            got = cache[(pair, k)] = self._tri_line(pair, k)
        return got  # type: ignore[no-any-return]

    def _tri_line(self, pair: Pair, k: str) -> tuple[str, str, str]:
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

    def best_meet(self, opts: list[tuple[str, str, Array, float]],
                  enough: float) -> tuple[float, int, int] | None:
        """The best-conditioned pair of lines among ``opts`` (every pair at once).

        Returns ``(quality, index, index)`` of the first pair (in the order of
        :func:`itertools.combinations`) of the highest quality that is at
        least ``enough`` and meets at every posture, or None.
        """
        m = len(opts)
        if m < 2:
            return None
        shape = np.broadcast_shapes(*(np.shape(o[2]) for o in opts))
        lines = np.stack([np.broadcast_to(np.asarray(o[2], dtype=float), shape) for o in opts])
        ia, ib = np.triu_indices(m, 1)
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            pts = g.meet(lines[ia], lines[ib], self.tol)
            hats = self.line_hat(lines)
            sines = np.linalg.norm(np.cross(hats[ia], hats[ib]), axis=-1)
        n = len(ia)
        valid = np.broadcast_to(self.valid, pts.shape[1:-1])
        meets = np.all(np.isfinite(pts), axis=-1)
        ok = np.all(np.where(valid, meets, True).reshape(n, -1), axis=1)
        sines = np.where(np.isfinite(sines), sines, 0.0)
        if valid.any():
            qline = np.min(np.where(valid, sines, np.inf).reshape(n, -1), axis=1)
        else:
            qline = np.zeros(n)
        q = np.array([o[3] for o in opts])
        qual = np.minimum(np.minimum(q[ia], q[ib]), qline)
        cand = ok & (qual >= enough)
        if not cand.any():
            return None
        k = int(np.argmax(np.where(cand, qual, -np.inf)))
        return float(qual[k]), int(ia[k]), int(ib[k])

    def try_pair(self, pair: Pair, enough: float) -> bool:
        """Find ``Iij`` by Kennedy's theorem if two lines of centers meet well enough.

        A pair that failed is not tried again until it has a new triangle (a
        link k whose centers with both links are known): only that changes
        its lines of centers.
        """
        failed = self.__dict__.setdefault("_failed_at", {})
        now = len(self.triangles(pair))
        if failed.get((pair, enough)) == now:
            return False
        if self._try_pair(pair, enough):
            return True
        failed[(pair, enough)] = now
        return False

    def every_of(self, flags: Array) -> Array:
        """:meth:`every` of each row of ``flags`` (shape ``(m, *postures)``) at once."""
        m = flags.shape[0]
        valid = np.broadcast_to(self.valid, flags.shape[1:])
        return np.all(np.where(valid, flags, True).reshape(m, -1), axis=1)

    def _try_pair(self, pair: Pair, enough: float) -> bool:
        i, j = pair
        lab = center_label(*pair)
        tris = self.triangles(pair)
        # the lines of centers of every triangle at once: one numpy call for all of them
        # (the centers are joined, compared and rated row by row, as one at a time would)
        names = [self.tri_line(pair, k) for k in tris]
        if tris:
            P, Q = (_stack([self.env[t[c]] for t in names]) for c in (0, 1))
            if P.shape[1:] != Q.shape[1:]:
                shape = np.broadcast_shapes(P.shape[1:], Q.shape[1:])
                P = np.broadcast_to(P, (len(names), *shape))
                Q = np.broadcast_to(Q, (len(names), *shape))
            pi, qi = g.is_ideal(P), g.is_ideal(Q)
            both_ideal = self.every_of(pi) & self.every_of(qi)
            finite = self.every_of(~pi) & self.every_of(~qi)
            with np.errstate(invalid="ignore"):
                same_ideal = self.every_of(np.abs(g.cross2(P, Q)) <= self.tol.angle)
                same_finite = self.every_of(g.distance(P, Q) <= self.tol.length(self.mech.scale))
            same = np.where(both_ideal, same_ideal, finite & same_finite)
            for n, k in enumerate(tris):
                if same[n]:
                    la, lb, _ = names[n]
                    note = (f"{lab} coincides with {la} and {lb}: where links {i}, {j} and {k} "
                            "all have the same velocity (Kennedy).")
                    self.add("same_point", (la, lb), lab, role=Role.RESULT, note=note)
                    self.found(pair, How.KENNEDY, "Kennedy", note, lines=(la, lb),
                               triangles=(_triangle(i, j, k),))
                    return True
            with np.errstate(invalid="ignore", divide="ignore"):
                lines = g.join(P, Q, self.tol)
                cr = np.linalg.norm(np.cross(self.point_hat(P), self.point_hat(Q)), axis=-1)
            usable = self.every_of(np.all(np.isfinite(lines), axis=-1))
            cr = np.where(np.isfinite(cr), cr, 0.0)
            valid = np.broadcast_to(self.valid, cr.shape[1:])
            quality = (np.min(np.where(valid, cr, np.inf).reshape(len(tris), -1), axis=1)
                       if valid.any() else np.zeros(len(tris)))
        # (kind, ref, line, quality of the line)
        opts: list[tuple[str, str, Array, float]] = []
        for name, _src in self.normals.get(pair, []):
            opts.append(("normal", name, self.env[name], 1.0))
        parallel_to: list[str] = []
        for n, k in enumerate(tris):
            if both_ideal[n]:
                parallel_to.append(k)
                continue
            if usable[n]:
                opts.append(("tri", k, lines[n], float(quality[n])))
        if len(opts) > _MOST_LINES:
            # a large mechanism: the best-conditioned lines of centers are enough to choose
            # from (every pair of them is tried, so the work would grow with their square)
            keep = sorted(range(len(opts)), key=lambda n: -opts[n][3])[:_MOST_LINES]
            opts = [opts[n] for n in sorted(keep)]
        best = self.best_meet(opts, enough)
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


def _stack(arrays: list[Array]) -> Array:
    """Points (or lines) of one shape stacked on a new first axis; else broadcast first."""
    arrs = [np.asarray(a, dtype=float) for a in arrays]
    shape = arrs[0].shape
    if all(a.shape == shape for a in arrs):
        return np.array(arrs)
    shape = np.broadcast_shapes(*(a.shape for a in arrs))
    return np.stack([np.broadcast_to(a, shape) for a in arrs])


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
    The inverted slider-crank of Example 3.3: the block 3 slides on the rod 4,
    so I34 is at infinity, perpendicular to the rod.

    >>> import graphkin
    >>> sol = graphkin.examples.inverted_slider_crank().solve()
    >>> ic = instant_centers(sol)
    >>> ic["I34"].how.value, bool(ic["I34"].is_ideal)
    ('primary', True)
    >>> [round(float(v), 4) for v in ic["I13"].xy]  # on EA (30°) and ⊥ the slide through D
    [15.1508, 8.7473]
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
    >>> sol = graphkin.examples.fourbar().solve()
    >>> instant_center(sol, 2, 1)
    array([0., 0., 1.])
    """
    ic = _centers(sol)
    return ic[(i, j)].point


def _centers(obj: Solution | InstantCenters) -> InstantCenters:
    return obj if isinstance(obj, InstantCenters) else instant_centers(obj)
