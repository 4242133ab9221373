"""The curvature construction of a link: Bobillier, Hartmann, four circles, Hain (4.13-4.17)."""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction import Construction, Role
from graphkin.errors import ConstructionError, GraphkinError
from graphkin.geometry import ops as g
from graphkin.kinematics.curvature._vec import _sin_angle
from graphkin.kinematics.curvature.conjugates import known_conjugates
from graphkin.kinematics.curvature.inflection import acceleration_center, inflection_pole
from graphkin.kinematics.solution import Solution, perp
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import Tolerance

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
        return label in self.env or any(label in s.outputs for s in self.cx.steps)

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
    pts = np.array([sol.position(n) for n in sol.mechanism.point_names], dtype=float)
    if len(pts) < 2:
        return float(sol.mechanism.scale)
    ext = pts.max(axis=0) - pts.min(axis=0)
    size = float(np.hypot(*ext))
    return size if size > 0.0 else float(sol.mechanism.scale)


class _Curvature(_Build):
    """The sections of Secs. 4.12-4.17 for one link."""

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
        best, best_s = None, -1.0
        for i in range(len(cands)):
            for j in range(i + 1, len(cands)):
                p, q = self.pos(cands[i][1]), self.pos(cands[j][1])
                far = min(float(np.hypot(*(p - center))), float(np.hypot(*(q - center))))
                s = _sin_angle(p - center, q - center) if far > _FAR * self.L else 0.0
                if cands[i][2] and cands[j][2] and s >= 0.5:
                    s += 0.5
                if s > best_s:
                    best, best_s = (cands[i], cands[j]), s
        assert best is not None
        return best

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

    def bobillier(self, a: str, b: str, layoff: bool) -> None:
        """Fig. 4.29 (Example 4.13), or Eq. 4.43 laid off (Examples 4.14, 4.16)."""
        lab = self.lab
        ha, hb = self.known[a][0], self.known[b][0]
        for n, h in ((a, ha), (b, hb)):
            self.given(n, self.pos(self.local[n]), f"{n}: a point of link {self.lid}.")
            self.given_h(lab(f"{n}'"), h, self.known[n][1] + ".")
        ap, bp = lab(f"{a}'"), lab(f"{b}'")
        raa = self.line(a, ap, f"Draw the ray {a}{a}': the normal to the path of {a}, "
                               f"perpendicular to V_{a}.")
        rbb = self.line(b, bp, f"Draw the ray {b}{b}': the normal to the path of {b}, "
                               f"perpendicular to V_{b}.")
        i = self.add("meet", (raa, rbb), lab("I"),
                     f"Locate the velocity pole I (the instant center I1{self.lid}) at the "
                     f"intersection of {a}{a}' and {b}{b}'.", Role.RESULT)
        self.I_label = i
        ja, jb = lab(f"J_{a}"), lab(f"J_{b}")
        if not layoff:
            rab = self.line(a, b, f"Draw the line {a}{b}.")
            rpp = self.line(ap, bp, f"Draw the line {a}'{b}'.")
            q = self.add("meet", (rab, rpp), lab("Q"),
                         f"Locate Q at the intersection of {a}{b} and {a}'{b}'.")
            ax = self.add("join", (i, q), lab("IQ"),
                          "Line IQ is the collineation axis (Bobillier's theorem: the angle "
                          "from the collineation axis to the first ray equals the angle from "
                          "the second ray to the centrode tangent).")
            par = self.add("parallel", (rpp, i), lab(f"I∥{a}'{b}'"),
                           f"Through I draw a line parallel to {a}'{b}'.")
            w = self.add("meet", (par, rab), lab("W"), f"It meets {a}{b} at W.")
            wq = self.add("parallel", (ax, w), lab("W∥IQ"),
                          "Through W draw a line parallel to the collineation axis IQ.")
            self.add("meet", (wq, raa), ja,
                     f"It locates J_{a} on {a}{a}', a point of the inflection circle.")
            self.add("meet", (wq, rbb), jb,
                     f"It locates J_{b} on {b}{b}', another point of the inflection circle.")
            self.method = "bobillier"
        else:
            self.add("euler_savary_inflection", (i, a, ap), ja,
                     f"Lay off R_{a}J_{a} = R_{a}I²/R_{a}{a}' from {a} along the ray "
                     f"(Eq. 4.43): the inflection point J_{a}.")
            self.add("euler_savary_inflection", (i, b, bp), jb,
                     f"Lay off R_{b}J_{b} = R_{b}I²/R_{b}{b}' from {b} (Eq. 4.43): the "
                     f"inflection point J_{b}.")
            self.method = "euler-savary"
        pa = self.add("perpendicular", (raa, ja), lab(f"⊥{a}{a}'@J_{a}"),
                      f"Through J_{a} draw a perpendicular to {a}{a}'.")
        pb = self.add("perpendicular", (rbb, jb), lab(f"⊥{b}{b}'@J_{b}"),
                      f"Through J_{b} draw a perpendicular to {b}{b}'.")
        self.J_label = self.add("meet", (pa, pb), lab("J"),
                                "The perpendiculars intersect at the inflection pole J "
                                "(a triangle inscribed in a semicircle is a right triangle).",
                                Role.RESULT)

    def collineation_axis(self, a: str, b: str) -> None:
        """Record the collineation axis of the two rays (for Bobillier's theorem and Hain)."""
        lab = self.lab
        ap, bp = lab(f"{a}'"), lab(f"{b}'")
        rab = self.line(a, b, f"Draw the line {a}{b}.")
        rpp = self.line(ap, bp, f"Draw the line {a}'{b}'.")
        q = self.add("meet", (rab, rpp), lab("Q"),
                     f"Locate Q at the intersection of {a}{b} and {a}'{b}' (for pins of two "
                     "links turning about frame pivots, their instant center: I24 of "
                     "Example 4.14).")
        self.add("join", (self.I_label or "I", q), lab("IQ"),
                 "Line IQ is the collineation axis: the angle from it to the first ray equals "
                 "the angle from the second ray to the centrode tangent (Bobillier).")

    def accelerations(self) -> None:
        """I from two velocities; J from the acceleration image of the point at I (Sec. 4.15)."""
        lab = self.lab
        (pn, pl, pnamed), (qn, ql, qnamed) = self.pick_pair(self.I0, "K")
        p, q = self.point_given(pn, pl, pnamed), self.point_given(qn, ql, qnamed)
        vp, vq = self.vtip(pn, pl), self.vtip(qn, ql)
        lp = self.line(p, vp, f"The line of V_{pn}.")
        lq = self.line(q, vq, f"The line of V_{qn}.")
        np_ = self.add("perpendicular", (lp, p), lab(f"⊥V_{pn}"),
                       f"Through {pn} draw a perpendicular to V_{pn}.")
        nq = self.add("perpendicular", (lq, q), lab(f"⊥V_{qn}"),
                      f"Through {qn} draw a perpendicular to V_{qn}.")
        self.I_label = self.add("meet", (np_, nq), lab("I"),
                                f"They meet at the velocity pole I (the instant center "
                                f"I1{self.lid}).", Role.RESULT)
        ap, aq = self.atip(pn, pl), self.atip(qn, ql)
        self.J_label = self.add(
            "image", (p, q, ap, aq, self.I_label), lab("J"),
            f"The acceleration of the point of link {self.lid} at I, from its acceleration "
            f"image (the triangle is similar to {pn}{qn}I), drawn from I to the scale "
            f"1/ω{self.lid}²: since A_I = ω² R_JI is directed from I toward J (Eqs. 4.46-4.47), "
            "its tip is the inflection pole J.", Role.RESULT)
        self.method = "accelerations"

    def circle(self) -> None:
        lab = self.lab
        i, j = self.I_label or "I", self.J_label or "J"
        self.add("circle_on_diameter", (i, j), lab("inflection circle"),
                 "Draw the inflection circle on the diameter IJ (Eq. 4.41): every point of "
                 "the link on it is at an inflection point of its path.", Role.RESULT)
        self.add("join", (i, j), lab("N"),
                 "The centrode normal N through I and J, positive from I toward J.")
        self.add("perpendicular_cw", (lab("N"), i), lab("T"),
                 "The centrode tangent T through I, its positive sense 90° clockwise from N "
                 "(so N is 90° counterclockwise from T, Sec. 4.12; Example 4.16).")
        self.add("similar", (i, j), lab("v"),
                 f"The pole velocity v = ω{self.lid} R_JI (Eq. 4.47), along the centrode "
                 f"tangent, drawn from I to the scale 1/|ω{self.lid}|.",
                 local_a=(0.0, 0.0), local_b=(1.0, 0.0), local_p=(0.0, self.sgn))

    def bresse(self) -> None:
        lab = self.lab
        i, j = self.I_label or "I", self.J_label or "J"
        if self.a_zero:
            self.add("copy_point", (j,), lab("Γ"),
                     f"α{self.lid} = 0: the Bresse circle becomes the centrode normal, and the "
                     "instantaneous center of acceleration Γ coincides with J (Sec. 4.15).",
                     Role.RESULT)
            return
        k = self.w**2 / self.a
        e = self.add("similar", (i, j), lab("E"),
                     f"Lay off the Bresse diameter b = R_JI ω²/α = {k:.6g} R_JI (Eq. 4.48) from "
                     "I along the centrode tangent: on its negative side when α > 0, on its "
                     "positive side when α < 0.",
                     local_a=(0.0, 0.0), local_b=(1.0, 0.0), local_p=(0.0, k))
        self.add("circle_on_diameter", (i, e), lab("Bresse circle"),
                 "Draw the Bresse circle on the diameter IE: the points of the link with no "
                 "tangential acceleration.", Role.RESULT)
        self.add("other_intersection", (lab("inflection circle"), lab("Bresse circle"), i),
                 lab("Γ"),
                 "The inflection and Bresse circles meet at I and at Γ, the instantaneous "
                 "center of acceleration (Fig. 4.34).", Role.RESULT)

    def four_circles(self) -> None:
        lab = self.lab
        (pn, pl, pnamed), (qn, ql, qnamed) = self.pick_pair(self.G0, "H")
        p, q = self.point_given(pn, pl, pnamed), self.point_given(qn, ql, qnamed)
        ap, aq = self.atip(pn, pl), self.atip(qn, ql)
        lp = self.line(p, ap, f"Extend A_{pn}.")
        lq = self.line(q, aq, f"Extend A_{qn}.")
        x = self.add("meet", (lp, lq), lab("Q_Γ"),
                     f"A_{pn} and A_{qn} extended intersect at Q_Γ (Fig. 4.33).")
        c1 = self.add("circumcircle", (p, q, x), lab(f"circle {pn}{qn}Q_Γ"),
                      f"Construct a circle through {pn}, {qn} and Q_Γ.")
        c2 = self.add("circumcircle", (ap, aq, x), lab(f"circle A_{pn}A_{qn}Q_Γ"),
                      f"Draw another circle through the termini of A_{pn} and A_{qn} and Q_Γ.")
        self.add("other_intersection", (c1, c2, x), lab("Γ (four circles)"),
                 "The second intersection of the two circles locates Γ, the instantaneous "
                 "center of acceleration (the four-circle method, Fig. 4.33).", Role.RESULT)

    def hartmann(self, name: str) -> None:
        """Fig. 4.25: the conjugate of a point from the pole velocity."""
        lab = self.lab
        loc = np.asarray(self.local[name], dtype=float)
        c = self.given(name, self.pos(loc), f"{name}: a point of link {self.lid}.")
        vc = self.vtip(name, loc)
        i = self.I_label or "I"
        ray = self.line(i, c, f"Draw the line I{name}.")
        pi = self.add("perpendicular", (ray, i), lab(f"⊥I{name}@I"),
                      f"Through I draw the line perpendicular to I{name}: it carries u, the "
                      f"component of the pole velocity v parallel to V_{name}.")
        pv = self.add("perpendicular", (pi, lab("v")), lab(f"v∥I{name}"),
                      f"Through the terminus of v draw a line parallel to I{name}.")
        u = self.add("meet", (pv, pi), lab(f"u_{name}"),
                     "The terminus of u (u = v sin ψ, Eq. d).")
        tt = self.line(vc, u, f"Connect the termini of V_{name} and u.")
        self.add("meet", (tt, ray), lab(f"{name}'"),
                 f"The line through the termini meets the line {name}I at the conjugate point "
                 f"{name}', the center of curvature of the path of {name} (the Hartmann "
                 "construction, Fig. 4.25).", Role.RESULT)

    def bobillier_conjugate(self, name: str) -> None:
        """Fig. 4.30 (Example 4.13): the conjugate of a point from the inflection circle."""
        lab = self.lab
        loc = np.asarray(self.local[name], dtype=float)
        c = self.given(name, self.pos(loc), f"{name}: a point of link {self.lid}.")
        i, j = self.I_label or "I", self.J_label or "J"
        ray = self.line(i, c, f"Draw the ray I{name}.")
        jc = self.add("second_on_circle", (ray, lab("inflection circle"), i), lab(f"J_{name}"),
                      f"It meets the inflection circle at J_{name}.")
        jj = self.line(jc, j, f"Draw the line J_{name}J.")
        ax = self.add("parallel", (jj, i), lab(f"IQ_{name}"),
                      f"The collineation axis belonging to the rays I{name} and IJ: a line "
                      f"through I parallel to J_{name}J.")
        jcl = self.line(j, c, f"Draw the line J{name}.")
        qc = self.add("meet", (ax, jcl), lab(f"Q_{name}"),
                      f"Q_{name} is the intersection of this collineation axis and J{name}.")
        pn = self.add("parallel", (lab("N"), qc), lab(f"Q_{name}∥N"),
                      f"Through Q_{name} draw a line parallel to the centrode normal (it "
                      "passes through J' at infinity).")
        self.add("meet", (pn, ray), lab(f"{name}'"),
                 f"Its intersection with the ray I{name} is {name}', the center of curvature "
                 f"of the path of {name} (Bobillier, Fig. 4.30).", Role.RESULT)

    def hain(self, a: str, b: str) -> None:
        """Fig. 4.38: the auxiliary line G of Hain's construction."""
        lab = self.lab
        i = self.I_label or "I"
        corners = []
        for n in (a, b):
            self.given(n, self.pos(self.local[n]), f"{n}: a point of link {self.lid}.")
            ray = self.line(i, n, f"Draw the line I{n}.")
            pp = self.add("perpendicular", (ray, n), lab(f"⊥I{n}@{n}"),
                          f"Through {n} draw a line perpendicular to I{n}.")
            xn = self.add("meet", (pp, lab("N")), lab(f"{n}_N"),
                          f"It intersects the centrode normal at {n}_N.")
            xt = self.add("meet", (pp, lab("T")), lab(f"{n}_T"),
                          f"It intersects the centrode tangent at {n}_T.")
            corners.append(self.add("parallelogram", (i, xn, xt), lab(f"{n}_G"),
                                    f"Complete the rectangle I{n}_N{n}_G{n}_T."))
        gl = self.add("join", tuple(corners), lab("G"),
                      f"{a}_G and {b}_G define the auxiliary line G: for every point S of the "
                      "cubic of stationary curvature, S_G lies on G.")
        self.add("meet", (gl, lab("N")), lab("G_N"),
                 "G meets the centrode normal at G_N: IG_N = M, the diameter of the circle "
                 "(centered on N) that osculates the branch of the cubic tangent to T.",
                 Role.RESULT)
        self.add("meet", (gl, lab("T")), lab("G_T"),
                 "G meets the centrode tangent at G_T: IG_T = -N, the diameter of the circle "
                 "(centered on T) that osculates the branch of the cubic tangent to N.",
                 Role.RESULT)

    def ball(self) -> None:
        lab = self.lab
        i, j = self.I_label or "I", self.J_label or "J"
        tj = self.add("parallel", (lab("T"), j), lab("T@J"),
                      "Draw the tangent to the inflection circle at J (parallel to T): the "
                      "S_G of every point of the inflection circle lies on it.")
        ug = self.add("meet", (lab("G"), tj), lab("U_G"), "It meets G at U_G.")
        un = self.add("parallel", (lab("N"), ug), lab("U_G∥N"),
                      "Through U_G draw a ray parallel to N.")
        ut = self.add("meet", (un, lab("T")), lab("U_T"),
                      "It locates U_T on the centrode tangent (U_N is J).")
        tl = self.line(ut, j, "Connect U_T with U_N = J.")
        pl = self.add("perpendicular", (tl, i), lab("⊥U_TJ@I"),
                      "Through I draw a perpendicular to this line.")
        self.add("meet", (pl, tl), lab("U"),
                 "Its foot is Ball's point U: the point of the cubic of stationary curvature "
                 "on the inflection circle, whose path is nearly straight for a long way.",
                 Role.RESULT)

    def ball_at_j(self) -> None:
        self.add("copy_point", (self.J_label or "J",), self.lab("U"),
                 "N is infinite: the cubic contains the centrode normal, so it meets the "
                 "inflection circle at J, and Ball's point U is the inflection pole "
                 "(Example 4.16).", Role.RESULT)
