"""The recorder of a link's curvature construction and the helpers its sections share."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction import Construction, Role
from graphkin.errors import ConstructionError, GraphkinError
from graphkin.geometry import ops as g
from graphkin.kinematics.curvature.conjugates import known_conjugates
from graphkin.kinematics.curvature.inflection import acceleration_center, inflection_pole
from graphkin.kinematics.solution import Solution, perp
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import VERDICT_REL, Tolerance

Array = np.ndarray

# Conditioning of the drawings (which construction to draw), not tolerances of
# geometric decisions (those come from a Tolerance):
_FAR = 0.05
"""A point nearer than this fraction of the figure to a center makes poor rays from it."""

_USABLE = 1e-6
"""Relative size below which a known point is taken as at I, or two rays from I as one."""

_RAY_FROM_N = 0.1
"""Fig. 4.30 is drawn for rays at least ~6° (cos ψ > 0.1) away from the centrode normal ..."""

_FROM_CIRCLE = 0.05
"""... and for points not within 5 % of the inflection circle or of J; Hartmann otherwise."""

_RAYS = 0.02
"""Bobillier's construction is chosen when its two rays cross at more than ~1° at I."""

_AGREE = 1e-6
"""The construction through W is kept when it agrees with the closed form to this (relative)."""

# ---------------------------------------------------------------------------
# the construction of one link
# ---------------------------------------------------------------------------

_Section = Callable[[], None]


class _Build:
    """Record and evaluate the curvature construction of one link, section by section."""

    def __init__(self, sol: Solution, lid: str, tol: Tolerance) -> None:
        self.sol, self.mech, self.lid, self.tol = sol, sol.mechanism, lid, tol
        st = sol.links[lid]
        self.st = st
        self.w = float(st.omega)  # type: ignore[arg-type]
        self.a = float(st.alpha)  # type: ignore[arg-type]
        self.sgn = 1.0 if self.w > 0 else -1.0
        # α is zero when it is round-off of the mechanism's accelerations (ω² + |α| per length)
        ref = max(float(s.omega or 0.0) ** 2 + abs(float(s.alpha or 0.0))
                  for s in sol.links.values())
        self.a_zero = abs(self.a) <= tol.angle * ref
        self.L = _figure_size(sol)
        self.local = dict(self.mech.links[lid].points)
        self.names = list(self.local)
        self.reserved = set(self.mech.point_names)
        self.cx = Construction(title=f"{self.mech.title or self.mech.source}: curvature of the "
                                     f"motion {lid}/1")
        self.env: dict[str, Array] = {}
        self.made: dict[str, str] = {}  # cache key -> label
        self.notes: list[str] = []
        self.sections: dict[str, str] = {}
        c, s = math.cos(float(st.angle)), math.sin(float(st.angle))
        self._rot = np.array([[c, -s], [s, c]])
        self.origin = np.asarray(st.origin, dtype=float)

    # -- world data of body points --
    def to_local(self, p: Array) -> Array:
        return self._rot.T @ (np.asarray(p, dtype=float) - self.origin)

    def pos(self, loc: ArrayLike) -> Array:
        return np.asarray(self.st.position(loc), dtype=float)

    def vel(self, loc: ArrayLike) -> Array:
        return np.asarray(self.st.velocity(loc), dtype=float)

    def acc(self, loc: ArrayLike) -> Array:
        return np.asarray(self.st.acceleration(loc), dtype=float)

    # -- labels and steps --
    def lab(self, x: str) -> str:
        """A construction label that does not clash with a named point of the file."""
        while x in self.reserved:
            x += "*"
        return x

    def add(self, op_name: str, inputs: tuple[str, ...], out: str, note: str,
            role: Role = Role.AUXILIARY, **params: Any) -> str:
        if self.has(out):
            raise ConstructionError(f"the label {out!r} is taken", step=out)
        self.cx.add(op_name, inputs, (out,), role=role, note=note, diagram="curvature", **params)
        return out

    def has(self, label: str) -> bool:
        if label in self.env:
            return True
        # the outputs made so far, kept up to date as steps are added (a scan of every step on
        # every call made 300 coupler points quadratic); rebuilt when the steps changed otherwise
        steps = self.cx.steps
        seen = getattr(self, "_made_outputs", None)
        if seen is None or seen[0] is not self.cx or seen[1] > len(steps) or (
                seen[1] and steps[seen[1] - 1] is not seen[2]):
            seen = (self.cx, 0, None, set())
        outs: set[str] = seen[3]
        for st in steps[seen[1]:]:
            outs.update(st.outputs)
        self._made_outputs = (self.cx, len(steps), steps[-1] if steps else None, outs)
        return label in outs

    def given(self, label: str, xy: Array, note: str) -> str:
        if not self.has(label):
            self.add("point", (), label, note, Role.GIVEN,
                     xy=(float(xy[0]) + 0.0, float(xy[1]) + 0.0))
        return label

    def given_h(self, label: str, h: Array, note: str) -> str:
        if not self.has(label):
            if h[2] == 0.0:
                self.add("ideal_point", (), label, note, Role.GIVEN,
                         direction=(float(h[0]), float(h[1])))
            else:
                self.add("point", (), label, note, Role.GIVEN,
                         xy=(float(h[0] / h[2]), float(h[1] / h[2])))
        return label

    def line(self, p: str, q: str, note: str) -> str:
        key = f"join:{p}:{q}"
        if key not in self.made:
            self.made[key] = self.add("join", (p, q), self.lab(f"{p}{q}"), note)
        return self.made[key]

    def section(self, fn: _Section) -> bool:
        """Record a group of steps and evaluate it; undo it if it has no answer.

        Each step's first output is filed under the section's name in
        :attr:`sections` (``circle``, ``bresse``, ``hartmann``, ``hain``...), so
        that a drawing can show one idea per figure.
        """
        n0, made = len(self.cx.steps), dict(self.made)
        try:
            fn()
            ev = self.cx.evaluate(values=self.env, start=n0, tol=self.tol)
        except GraphkinError:
            del self.cx.steps[n0:]
            self.made = made
            return False
        self.env = dict(ev.values)
        name = _section_name(fn)
        for st in self.cx.steps[n0:]:
            self.sections.setdefault(st.outputs[0], name)
        return True

    def val(self, label: str) -> Array:
        return np.asarray(self.env[label], dtype=float)

    def pt(self, label: str) -> Array:
        return g.xy(self.val(label))


_SECTIONS = ("pivot", "bobillier", "collineation_axis", "accelerations", "circle", "bresse",
             "four_circles", "hartmann", "bobillier_conjugate", "hain", "ball", "ball_at_j")


def _section_name(fn: Any) -> str:
    """The name of a section: its method's name (through a ``partial`` or a ``lambda``)."""
    from functools import partial

    if isinstance(fn, partial):
        fn = fn.func
    name = getattr(fn, "__name__", "")
    if name == "<lambda>":
        called = getattr(getattr(fn, "__code__", None), "co_names", ())
        name = next((n for n in called if n in _SECTIONS), name)
        if name == "bobillier" and fn.__code__.co_consts and True in fn.__code__.co_consts:
            name = "euler_savary"  # bobillier(..., layoff=True): J laid off by Eq. 4.43
    return name


def _figure_size(sol: Solution) -> float:
    """The size of the drawing: the largest distance between two named points."""
    got = sol.__dict__.get("_figure_size")  # the same for every link: found once
    if got is not None:
        return float(got)
    pts = np.array([sol.position(n) for n in sol.mechanism.point_names], dtype=float)
    if len(pts) < 2:
        return float(sol.mechanism.scale)
    ext = pts.max(axis=0) - pts.min(axis=0)
    size = float(np.hypot(*ext))
    size = size if size > 0.0 else float(sol.mechanism.scale)
    sol.__dict__["_figure_size"] = size
    return size


class _CurvatureBase(_Build):
    """The state of one link's curvature construction and the helpers its sections share."""

    def __init__(self, sol: Solution, lid: str, tol: Tolerance) -> None:
        super().__init__(sol, lid, tol)
        o_v = np.asarray(self.st.origin_velocity, dtype=float)
        o_a = np.asarray(self.st.origin_acceleration, dtype=float)
        # closed-form references (Eq. 3.4 and Secs. 4.14-4.15)
        self.I0 = self.origin + perp(o_v) / self.w
        self.AI0 = self.acc(self.to_local(self.I0))
        self.J0 = inflection_pole(self.I0, self.AI0, self.w)
        self.G0 = acceleration_center(self.origin, o_a, self.w, self.a)
        self.known = known_conjugates(self.mech, lid)
        self.method = "closed form"
        self.I_label = self.J_label = None  # type: str | None

    # -- candidate points for the acceleration route and the four-circle method --
    def candidates(self, center: Array, prefix: str) -> list[tuple[str, Array, bool]]:
        """The named points of the link, and auxiliary body points around ``center``."""
        out = [(n, np.asarray(loc, dtype=float), True) for n, loc in self.local.items()]
        for k, t in enumerate((0.0, 0.5 * math.pi, 0.25 * math.pi, 0.75 * math.pi), start=1):
            p = center + self.L * np.array([math.cos(t), math.sin(t)])
            out.append((self.lab(f"{prefix}{k}"), self.to_local(p), False))
        return out

    def pick_pair(self, center: Array, prefix: str) -> tuple[tuple[str, Array, bool],
                                                            tuple[str, Array, bool]]:
        """Two body points seen from ``center`` at a good angle: lines through them cross well.

        Named points are preferred when they make at least 30° at ``center``;
        auxiliary ones are labelled ``prefix`` + a number.
        """
        cands = self.candidates(center, prefix)
        # every pair at once (300 coupler points are 46 000 pairs); the first best pair in
        # the order (i, j), i < j, as a loop over them would keep it
        rel = self.pos(np.array([c[1] for c in cands])) - center
        d = np.hypot(rel[:, 0], rel[:, 1])
        cross = np.abs(rel[:, None, 0] * rel[None, :, 1] - rel[:, None, 1] * rel[None, :, 0])
        nn = d[:, None] * d[None, :]
        with np.errstate(divide="ignore", invalid="ignore"):
            s = np.where(nn > 0.0, cross / np.where(nn > 0.0, nn, 1.0), 0.0)
        s = np.where(np.minimum(d[:, None], d[None, :]) > _FAR * self.L, s, 0.0)
        named = np.array([c[2] for c in cands])
        # 30° is sin = 0.5: a named pair at 30° within round-off is a named pair at 30°
        s = np.where(named[:, None] & named[None, :] & (s >= 0.5 - VERDICT_REL), s + 0.5, s)
        s[np.tril_indices(len(cands))] = -1.0
        # the first pair in the order (i, j) whose score is the best but for round-off: two
        # equally good pairs (Example 3.3's H1/H2 and H3/H4) are not chosen between by the
        # last digits of the arithmetic, which differ on another CPU
        flat = s.ravel()
        first = int(np.flatnonzero(flat >= float(flat.max()) - VERDICT_REL)[0])
        i, j = divmod(first, len(cands))
        return cands[i], cands[j]

    def point_given(self, name: str, loc: Array, named: bool) -> str:
        if named:
            return self.given(name, self.pos(loc), f"{name}: a point of link {self.lid}.")
        return self.given(name, self.pos(loc),
                          f"{name}: an auxiliary point of link {self.lid} (any point will do).")

    def vtip(self, name: str, loc: Array) -> str:
        tip = self.pos(loc) + self.vel(loc) / abs(self.w)
        return self.given(self.lab(f"V_{name}"), tip,
                          f"V_{name}, drawn from {name} to the scale 1/|ω{self.lid}| "
                          f"(from the velocity polygon).")

    def atip(self, name: str, loc: Array) -> str:
        tip = self.pos(loc) + self.acc(loc) / self.w**2
        return self.given(self.lab(f"A_{name}"), tip,
                          f"A_{name}, drawn from {name} to the scale 1/ω{self.lid}² "
                          f"(from the acceleration polygon).")

    # -- velocity pole and inflection pole --
    def pivot(self, o: str) -> None:
        xy = self.mech.links[FRAME].points[o]
        self.I_label = self.given(self.lab("I"), np.asarray(xy, dtype=float),
                                  f"Link {self.lid} turns about the frame pivot {o}: {o} is its "
                                  f"velocity pole I (the instant center I1{self.lid}); the "
                                  f"path of every point is a circle about {o}, so the "
                                  f"inflection circle shrinks to the point {o}.")
        self.method = "pivot"
