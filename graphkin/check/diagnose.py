"""The usual mistakes of the graphic method, and which one explains a wrong answer.

For an answer outside tolerance, each usual mistake is made on purpose, the
value it would give is compared with the answer, and the first mistake that
brings the answer within tolerance is named:

* the sense reversed (an angular rate, a direction, a difference the wrong way);
* a unit factor (12 in/ft, 1000 mm/m, 2π/60 rev/min to rad/s, 25.4 mm/in,
  0.3048 m/ft ...);
* a velocity difference given for an absolute velocity, or the other way; the
  angular velocity (or acceleration) of a link relative to another given for
  its absolute one (ω6/4 = ω6 − ω4 for ω6);
* a velocity or acceleration image flipped over (the mirror image of the
  link's shape, Sec. 3.5 and the footnote to Example 4.2);
* a normal component drawn away from the center instead of toward it
  (``A_wrong = A − 2 A^n``, and the acceleration polygon redrawn with it);
* the Coriolis component with the wrong sense, the wrong ω, without the 2,
  or left out (Sec. 4.5);
* the other assembly branch (the crossed instead of the open four-bar, Sec. 2.5).

A hint is given only when the mistaken value matches within tolerance.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.5 (velocity images: "Care must be
taken not to allow the triangle to be flipped over"), Sec. 4.3 (the normal
component is directed toward the center), Sec. 4.5 (Coriolis component
2ω × V of the link that carries the path).
"""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

import numpy as np

from graphkin.check.answers import CheckTolerance, Given, Key
from graphkin.check.compare import compare
from graphkin.check.exact import Evaluator, Exact
from graphkin.errors import GraphkinError
from graphkin.geometry import ops as g
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME

__all__ = ["Mistake", "Diagnoser", "UNIT_FACTORS", "OTHER_BRANCH", "unit_factors"]

#: (factor, how it reads, the usual cause)
UNIT_FACTORS: tuple[tuple[float, str, str], ...] = (
    (12.0, "12", "inches and feet mixed up (12 in = 1 ft)"),
    (1000.0, "1000", "millimetres and metres mixed up (1000 mm = 1 m)"),
    (60.0 / (2.0 * math.pi), "60/2π", "rev/min and rad/s mixed up (1 rev/min = 2π/60 rad/s)"),
    (25.4, "25.4", "millimetres and inches mixed up (1 in = 25.4 mm)"),
    (1.0 / 0.3048, "1/0.3048", "feet and metres mixed up (1 ft = 0.3048 m)"),
    (2.0 * math.pi, "2π", "revolutions and radians mixed up (1 rev = 2π rad)"),
    (60.0, "60", "minutes and seconds mixed up"),
    (180.0 / math.pi, "180/π", "degrees and radians mixed up"),
    (10.0, "10", "millimetres and centimetres mixed up"),
    (100.0, "100", "centimetres and metres mixed up"),
)

_METRIC_ONLY = {1000.0, 10.0, 100.0}
"""The factors whose usual cause (mm, cm, m) only fits a file in metric lengths."""


def unit_factors(length_unit: str) -> tuple[tuple[float, str, str], ...]:
    """:data:`UNIT_FACTORS` with causes that fit a file whose lengths are in ``length_unit``.

    An inch answer 100 times too small is not centimetres and metres mixed up:
    in a file of inches or feet a power of ten is a decimal point in the wrong place.
    """
    from graphkin.units import length_factor

    try:
        metres = length_factor(length_unit)
    except ValueError:
        return UNIT_FACTORS
    metric = any(abs(metres / 10.0 ** k - 1.0) < 1e-12 for k in range(-9, 4))
    if metric:
        return UNIT_FACTORS
    return tuple((f, label, f"the decimal point {round(math.log10(f))} places off "
                            f"(the file's lengths are in '{length_unit}', not metric)")
                 if f in _METRIC_ONLY else (f, label, why) for f, label, why in UNIT_FACTORS)


#: the other branch of each two-way construction (Side and Along names)
OTHER_BRANCH = {"left": "right", "right": "left", "behind": "ahead", "ahead": "behind"}

_MAX_BRANCHES = 4  # 2**4 - 1 alternative postures at most

_Redo = Callable[[dict[str, np.ndarray], tuple[str, ...]], np.ndarray]
"""A construction step done wrongly: its values so far and its inputs -> its (wrong) result."""


@dataclass(frozen=True)
class Mistake:
    """A mistake that explains a wrong answer.

    Attributes
    ----------
    kind : str
        ``sense``, ``unit``, ``relative``, ``flipped``, ``normal``,
        ``coriolis``, ``branch``, ``inertia`` (forces), or ``combined`` (two mistakes at
        once).
    text : str
        The mistake in words.
    code : str
        A short code to sort and filter marks by: ``sense``, ``unit:12``,
        ``image-flipped``, ``normal-reversed``, ``coriolis-omega``,
        ``coriolis-sense``, ``branch``, ``difference-for-absolute``..., two
        mistakes joined by ``+``.
    variant : int or None
        The whole solution redrawn with this mistake (an index into
        :meth:`Diagnoser.variants`), when the mistake carries through to
        later answers (follow-through marking).
    """

    kind: str
    text: str
    code: str = ""
    variant: int | None = field(default=None, compare=False)

    def __post_init__(self) -> None:
        if not self.code:
            object.__setattr__(self, "code", self.kind)


def _lower(name: str) -> str:
    return name.lower()


def _mirror(p: tuple[float, float], q: tuple[float, float],
            r: tuple[float, float]) -> np.ndarray | None:
    """Mirror image of local point p about the line qr (None if p lies on it)."""
    P, Q, R = (np.asarray(x, dtype=float) for x in (p, q, r))
    d = R - Q
    n = float(np.hypot(*d))
    if n == 0.0:
        return None
    d /= n
    w = P - Q
    off = w - float(w @ d) * d
    if float(np.hypot(*off)) <= 1e-9 * max(n, float(np.hypot(*w))):
        return None
    return P - 2.0 * off


class Diagnoser:
    """Finds the mistake that explains each wrong answer for one solved mechanism.

    Parameters
    ----------
    ev : Evaluator
        The exact values.

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.check.answers import loads_answers
    >>> ev = Evaluator(graphkin.solve(mech := graphkin.examples.fourbar()))
    >>> ans = loads_answers('omega2 = "900 rev/min cw"', mech)  # the file's ω2 is ccw
    >>> Diagnoser(ev).diagnose(ans.given[0], CheckTolerance()).kind
    'sense'
    """

    def __init__(self, ev: Evaluator) -> None:
        self.ev = ev
        self.sol = ev.sol
        self.mech = ev.mech
        self._factors = unit_factors(self.mech.length_unit)
        self._variants: list[tuple[Mistake, Evaluator]] | None = None

    # ---- the search -----------------------------------------------------
    def diagnose(self, given: Given, tol: CheckTolerance,
                 sheet: float | None = None) -> Mistake | None:
        """The first usual mistake (or pair of them) whose value matches ``given``."""
        try:
            exact = self.ev.value(given.key)
        except GraphkinError:
            return None
        floor = self.ev.floor(given.key.quantity)
        ref = self._reference(given, exact)
        for mistake, cand in self.candidates(given, exact):
            if self._matches(given, cand, tol, floor, ref, sheet):
                return mistake
        return None

    def _reference(self, given: Given, exact: Exact) -> float | None:
        if given.key.shape == "point" and exact.xy is not None and not exact.ideal:
            return self.ev.reference_length(exact.xy)
        return None

    @staticmethod
    def _matches(given: Given, cand: Exact, tol: CheckTolerance, floor: float,
                 ref: float | None, sheet: float | None) -> bool:
        if cand.xy is not None and not np.all(np.isfinite(cand.xy)):
            return False
        if cand.value is not None and not math.isfinite(cand.value):
            return False
        try:
            return compare(given, cand, tol, floor=floor, reference=ref, sheet=sheet).ok
        except (AssertionError, TypeError, ValueError):
            return False

    def explains(self, index: int, given: Given, tol: CheckTolerance,
                 sheet: float | None = None) -> bool:
        """Whether whole-solution variant ``index`` gives ``given`` within tolerance.

        Follow-through marking: an answer that is wrong only because an earlier
        answer's mistake was carried through the rest of the construction.
        """
        both = self._variant_and_exact(index, given)
        if both is None:
            return False
        cand, exact = both
        floor = self.ev.floor(given.key.quantity)
        if not self._matches(given, cand, tol, floor, self._reference(given, exact), sheet):
            return False
        # the variant must differ from the exact value here, or there is nothing to follow
        return not self._matches(given, exact, tol, floor, self._reference(given, exact), sheet)

    def agrees(self, index: int, given: Given, tol: CheckTolerance,
               sheet: float | None = None) -> bool:
        """Whether whole-solution variant ``index`` gives ``given`` within tolerance too.

        An answer given right that the variant would have made wrong shows the
        student did not make that mistake (it is not carried through).
        """
        both = self._variant_and_exact(index, given)
        if both is None:
            return True
        cand, exact = both
        floor = self.ev.floor(given.key.quantity)
        return self._matches(given, cand, tol, floor, self._reference(given, exact), sheet)

    def _variant_and_exact(self, index: int, given: Given) -> tuple[Exact, Exact] | None:
        """The value of ``given``'s key in variant ``index`` and the exact one (None: neither)."""
        try:
            return self.variants()[index][1].value(given.key), self.ev.value(given.key)
        except GraphkinError:
            return None

    def candidates(self, given: Given, exact: Exact) -> Iterator[tuple[Mistake, Exact]]:
        """Every mistaken value worth testing for ``given``, most likely first.

        Single mistakes first; then each polygon mistake combined with a
        reversed sense or a unit factor (two usual mistakes at once).
        """
        key = given.key
        yield from self._sense(given, exact)
        yield from self._units(given, exact, with_sense=False)
        polygon: list[tuple[Mistake, Exact]] = []
        for item in itertools.chain(self._relative(key), self._flipped(key), self._normal(key),
                                    self._forces(key)):
            polygon.append(item)
            yield item
        for i, (mistake, ev) in enumerate(self.variants()):
            try:
                value = ev.value(key)
            except GraphkinError:
                continue
            item = (dataclasses.replace(mistake, variant=i), value)
            polygon.append(item)
            yield item
        yield from self._units(given, exact, with_sense=True)
        # two usual mistakes at once: a polygon mistake and a slip of sense or units
        for mistake, value in polygon:
            extras = itertools.chain(
                () if mistake.kind == "sense" else self._sense(given, value),
                () if mistake.kind == "unit" else self._units(given, value, with_sense=False))
            for extra, changed in extras:
                yield (Mistake("combined", f"{mistake.text}; and {extra.text}",
                               f"{mistake.code}+{extra.code}"), changed)

    # ---- simple mistakes on the value itself ------------------------------
    def _sense(self, given: Given, exact: Exact) -> Iterator[tuple[Mistake, Exact]]:
        key = given.key
        shape = key.shape
        if shape == "scalar" and given.signed:
            w = "ccw" if (exact.value or 0.0) > 0 else "cw"
            yield (Mistake("sense", f"sense reversed: {key.pretty()} is {w}"),
                   exact.scaled(-1.0))
        elif shape == "angle":
            assert exact.value is not None
            yield (Mistake("sense", "angle of the link measured from its other end "
                                    "(180° out)"), Exact(exact.value + 180.0))
        elif shape == "vector" and given.direction is not None:
            if key.kind == "F":
                i, j = key.args
                text = (f"action for reaction: F_{j}{i} given for F_{i}{j} (F_{i}{j} is the "
                        f"force exerted BY link {i} ON link {j}; F_{j}{i} = -F_{i}{j})")
            elif len(key.args) == 2 and key.kind in ("V", "A", "R"):
                p, q = key.args
                text = (f"sense reversed: {key.kind}_{q}{p} given for {key.kind}_{p}{q} "
                        f"(the difference {key.kind}_{p}{q} is drawn to {_lower(p)} from "
                        f"{_lower(q)})")
            else:
                text = f"sense reversed: {key.text} drawn the wrong way round (180° out)"
            code = "action-for-reaction" if key.kind == "F" else "sense"
            yield Mistake("sense", text, code), exact.scaled(-1.0)

    def _forces(self, key: Key) -> Iterator[tuple[Mistake, Exact]]:
        """Dynamic force analysis (Sec. 12.4): the inertia force not reversed, h misplaced."""
        if key.kind not in ("F", "T") or not self.ev.forces().dynamic:
            return
        yield (Mistake("inertia", "the inertia force was not reversed: d'Alembert's force is "
                                  "-m A_G, opposite to the acceleration of G (Sec. 12.4)",
                       "inertia-not-reversed"),
               self.ev.force(key, "not-reversed"))
        yield (Mistake("inertia", "h is on the wrong side of G: the offset inertia force must "
                                  "have the moment -I_G α about G, opposite to α (Eq. 12.18)",
                       "inertia-h-side"),
               self.ev.force(key, "h-side"))

    def _units(self, given: Given, exact: Exact,
               with_sense: bool) -> Iterator[tuple[Mistake, Exact]]:
        shape = given.key.shape
        if shape == "angle":
            assert exact.value is not None
            if not with_sense:
                f, label, why = UNIT_FACTORS[7]
                yield (Mistake("unit", f"too small by a factor of {label}: radians written as "
                                       "degrees", f"unit:{label}"), Exact(exact.value / f))
            return
        if with_sense and not (shape == "scalar" and given.signed) \
                and not (shape == "vector" and given.direction is not None):
            return
        sign = -1.0 if with_sense else 1.0
        pre = "sense reversed and " if with_sense else ""
        if shape == "point" and (exact.ideal or given.ideal):
            return
        for f, label, why in self._factors:
            code = ("sense+" if with_sense else "") + f"unit:{label}"
            yield (Mistake("unit", f"{pre}too large by a factor of {label}: {why}", code),
                   exact.scaled(sign * f))
            yield (Mistake("unit", f"{pre}too small by a factor of {label}: {why}", code),
                   exact.scaled(sign / f))

    # ---- mistakes of the polygon --------------------------------------------
    def _vec(self, kind: str, p: str, link: str | None = None) -> np.ndarray:
        f = self.sol.velocity if kind == "V" else self.sol.acceleration
        return np.asarray(f(p, link) if link else f(p), dtype=float)

    def _relative_rate(self, key: Key) -> Iterator[tuple[Mistake, Exact]]:
        """ω (or α) of a link relative to another, ω_i/j = ω_i − ω_j, given for the absolute one.

        The angular velocity of link 6 relative to link 4 (Sec. 3.6, 3.13: the
        rates read off an inversion, or off a joint angle θ6/4) differs from
        ω6 by the rate of the link it is measured from.
        """
        if key.kind not in ("omega", "alpha") or len(key.args) != 1:
            return
        (i,) = key.args
        rate = self.sol.omega if key.kind == "omega" else self.sol.alpha
        sym = "ω" if key.kind == "omega" else "α"
        floor = self.ev.floor(key.quantity)
        try:
            wi = float(rate(i))
            for j in self.mech.links:
                if j in (i, FRAME):
                    continue
                wj = float(rate(j))
                if not math.isfinite(wj) or abs(wj) <= floor:
                    continue  # relative to a link at rest is the absolute value
                yield (Mistake("relative", f"{sym}{i}/{j} = {sym}{i} − {sym}{j} (of link {i} "
                                           f"relative to link {j}) given for the absolute "
                                           f"{sym}{i}", f"relative-{key.kind}"),
                       Exact(wi - wj))
        except (GraphkinError, ValueError, TypeError, KeyError):
            return

    def _relative(self, key: Key) -> Iterator[tuple[Mistake, Exact]]:
        """A difference given for an absolute value, or the other way."""
        yield from self._relative_rate(key)
        if key.kind not in ("V", "A"):
            return
        word = "velocity" if key.kind == "V" else "acceleration"
        k = key.kind
        try:
            if len(key.args) == 1:
                (p,) = key.args
                vp = self._vec(k, p)
                floor = self.ev.floor("velocity" if k == "V" else "acceleration")
                for q in self.mech.point_names:
                    if q == p or q in self.mech.helper_points:
                        continue
                    vq = self._vec(k, q)
                    if float(np.hypot(*vq)) <= floor:
                        continue
                    yield (Mistake("relative", f"the {word} difference {k}_{p}{q} given for "
                                               f"the absolute {word} {k}_{p}",
                                   "difference-for-absolute"),
                           Exact(None, vp - vq))
                if k == "A":
                    yield from self._components_for_absolute(p, floor)
            else:
                p, q = key.args
                yield (Mistake("relative", f"the absolute {word} {k}_{p} given for the "
                                           f"{word} difference {k}_{p}{q}",
                               "absolute-for-difference"),
                       Exact(None, self._vec(k, p)))
                if k == "A":
                    yield from self._components(key, p, q, f"A_{p}{q}", stop=True)
        except (GraphkinError, ValueError):
            return

    def _components_for_absolute(self, p: str, floor: float) -> Iterator[tuple[Mistake, Exact]]:
        """A_P of a point turning about a fixed pivot Q: one component given for the whole."""
        for lid in self.mech.point_links[p]:
            if lid == FRAME:
                continue
            for q in self.mech.links[lid].points:
                if q == p or q in self.mech.helper_points \
                        or float(np.hypot(*self._vec("A", q))) > floor:
                    continue
                yield from self._components(Key(f"A_{p}{q}", "A", (p, q)), p, q, f"A_{p}",
                                            stop=False)

    def _components(self, key: Key, p: str, q: str, whole: str,
                    stop: bool) -> Iterator[tuple[Mistake, Exact]]:
        """A^n_PQ, then A^t_PQ, each given for ``whole`` (``stop``: none after one fails)."""
        for comp, name in (("n", "normal"), ("t", "tangential")):
            try:
                c = self.ev.component(key, p, q, comp)
            except GraphkinError:
                if stop:
                    return
                continue
            yield (Mistake("relative", f"only the {name} component A_{p}{q}^{comp} given for "
                                       f"{whole}", "component-for-whole"), Exact(None, c))

    def _flipped(self, key: Key) -> Iterator[tuple[Mistake, Exact]]:
        """The image triangle of the link drawn mirror-wise."""
        if key.kind not in ("V", "A"):
            return
        p = key.args[0]
        word = "velocity" if key.kind == "V" else "acceleration"
        try:
            base = self._vec(key.kind, key.args[1]) if len(key.args) == 2 else np.zeros(2)
        except (GraphkinError, ValueError):
            return
        for lid in self.mech.point_links[p]:
            if lid == FRAME:
                continue
            pts = self.mech.links[lid].points
            others = [q for q in pts if q != p and q not in self.mech.helper_points]
            st = self.sol.links[lid]
            for q, r in itertools.combinations(others, 2):
                m = _mirror(pts[p], pts[q], pts[r])
                if m is None:
                    continue
                try:
                    v = st.velocity(m) if key.kind == "V" else st.acceleration(m)
                except ValueError:
                    return
                tri = f"{_lower(q)}{_lower(r)}{_lower(p)}"
                yield (Mistake("flipped", f"the {word} image of link {lid} is flipped over: "
                                          f"triangle {tri} drawn mirror-wise about "
                                          f"{_lower(q)}{_lower(r)} (the image keeps the link's "
                                          "shape and the order of its letters)",
                                "image-flipped"),
                       Exact(None, np.asarray(v, dtype=float) - base))

    def _normal(self, key: Key) -> Iterator[tuple[Mistake, Exact]]:
        """``A − 2 A^n``: one normal component drawn away from its center."""
        if key.kind != "A":
            return
        p = key.args[0]
        try:
            a = np.asarray(self.ev.value(key).xy, dtype=float)
        except GraphkinError:
            return
        for lid in self.mech.point_links[p]:
            if lid == FRAME:
                continue
            st = self.sol.links[lid]
            if st.omega is None:
                return
            for q in self.mech.links[lid].points:
                if q == p or q in self.mech.helper_points:
                    continue
                r = self.sol.position(p, lid) - self.sol.position(q, lid)
                an = -float(st.omega) ** 2 * r
                yield (Mistake("normal", f"A_{p}{q}^n drawn away from {q} instead of toward "
                                         f"it (a normal component points to the center)",
                               "normal-reversed"),
                       Exact(None, a - 2.0 * an))

    # ---- whole polygons redrawn with one mistake ------------------------------
    def variants(self) -> list[tuple[Mistake, Evaluator]]:
        """Solutions redrawn with one mistake each (computed once, on first use)."""
        if self._variants is None:
            out: list[tuple[Mistake, Evaluator]] = []
            try:
                out += self._construction_variants()
            except GraphkinError:
                pass
            out += self._branch_variants()
            out += self._rate_variants()
            self._variants = out
        return self._variants

    def _rate_variants(self) -> list[tuple[Mistake, Evaluator]]:
        """The input's rate with the wrong sense or a unit slip, carried through everything."""
        from graphkin.kinematics.solve import solve

        mech = self.mech
        out: list[tuple[Mistake, Evaluator]] = []
        if mech.rates is not None or not self.sol.has_rates:
            return out
        for d in mech.drives:
            if not d.rate:
                continue
            w = f"ω{d.link}"
            changes: list[tuple[float, Mistake]] = [
                (-1.0, Mistake("sense", f"the input {w} taken with the wrong sense", "sense"))]
            for f, label, why in self._factors:
                changes.append((f, Mistake("unit", f"the input {w} too large by a factor of "
                                                   f"{label}: {why}", f"unit:{label}")))
                changes.append((1.0 / f, Mistake("unit", f"the input {w} too small by a factor "
                                                         f"of {label}: {why}", f"unit:{label}")))
            for f, mistake in changes:
                drives = tuple(dataclasses.replace(e, rate=(e.rate or 0.0) * f) if e is d else e
                               for e in mech.drives)
                try:
                    alt = solve(dataclasses.replace(mech, drives=drives),
                                branches=dict(self.sol.branches))
                except (GraphkinError, ValueError, ArithmeticError):
                    continue
                out.append((mistake, Evaluator(alt)))
        return out

    def _construction_variants(self) -> list[tuple[Mistake, Evaluator]]:
        sol = self.sol
        if sol.method != "construction" or not sol.has_accelerations:
            return []
        from graphkin.kinematics.polygons import build_polygons
        from graphkin.kinematics.posture import _n, build_posture
        from graphkin.kinematics.solve import link_states, rate_inputs

        mech = self.mech
        pc = build_posture(mech, None, dict(sol.branches))
        pol = build_polygons(mech, pc)
        vin, ain = rate_inputs(mech, pol, pc, pc.values)
        vel = pol.velocity.evaluate(vin, values=dict(pc.values)).values
        acc_cx = pol.acceleration
        out: list[tuple[Mistake, Evaluator]] = []

        def redo(label: str, fn: _Redo, mistake: Mistake) -> None:
            step = acc_cx.step_of(label)
            try:
                env = acc_cx.upto(step.index).evaluate(ain, values=dict(vel)).values
                new = fn(env, step.inputs)
                if np.allclose(new, env[label], rtol=1e-12, atol=0.0):
                    return
                env[label] = new
                acc = acc_cx.evaluate(ain, values=env, start=step.index + 1).values
                states = link_states(mech, pc, pc.values, vel, acc, pol)
            except (GraphkinError, KeyError, ValueError):
                return
            alt = Solution(mech, states, "construction", sol.constructions,
                           branches=dict(sol.branches),
                           values={"posture": pc.values, "velocity": vel, "acceleration": acc})
            # the student's pencil: every later image point where the polygon put it
            images = {}
            for name, lab in pol.acceleration_images.items():
                if name in mech.point_names and lab in acc:
                    xy = g.xy(np.asarray(acc[lab], dtype=float))
                    if np.all(np.isfinite(xy)):
                        images[name] = np.asarray(xy, dtype=float)
            out.append((mistake, Evaluator(alt, accelerations=images)))

        def own(label: str, change: Callable[[np.ndarray], np.ndarray]) -> _Redo:
            """A redone step whose result is its own result changed by ``change``."""
            return lambda env, ins: change(np.asarray(env[label]))

        omegas = {lid: f"ω{lid}" for lid in mech.moving if f"ω{lid}" in vel}
        for step in acc_cx.steps:
            lab = step.label
            if step.op == "normal_component":
                center = _n(step.inputs[0])
                redo(lab, own(lab, lambda v: -v),
                     Mistake("normal", f"{lab} drawn away from {center} instead of toward it "
                                       "(a normal component points to the center)",
                             "normal-reversed"))
            elif step.op == "apparent_normal":
                redo(lab, own(lab, lambda v: -v),
                     Mistake("normal", f"{lab} drawn away from the center of curvature of the "
                                       "path instead of toward it", "normal-reversed"))
            elif step.op == "acceleration_difference":
                x = _n(step.outputs[0][2:-1].replace("@", ""))
                a = _n(step.inputs[3])

                def reversed_normal(env: dict[str, np.ndarray], ins: tuple[str, ...],
                                    out_label: str = step.outputs[0]) -> np.ndarray:
                    r = g.xy(env[ins[4]]) - g.xy(env[ins[3]])
                    w = float(np.asarray(env[ins[1]]))
                    res = np.array(env[out_label], dtype=float)
                    res[..., :2] += 2.0 * w**2 * r * res[..., 2:3]
                    return res

                redo(step.outputs[0], reversed_normal,
                     Mistake("normal", f"A_{x}{a}^n drawn away from {a} instead of toward it "
                                       "(a normal component points to the center)",
                             "normal-reversed"))
            elif step.op == "coriolis":
                wk = step.inputs[0]
                redo(lab, own(lab, lambda v: -v),
                     Mistake("coriolis", f"the Coriolis component {lab} drawn with the wrong "
                                         f"sense (it is V_rel turned 90° in the sense of {wk})",
                             "coriolis-sense"))
                redo(lab, own(lab, lambda v: 0.5 * v),
                     Mistake("coriolis", f"the Coriolis component {lab} taken as ω × V "
                                         "instead of 2ω × V", "coriolis-no-2"))
                redo(lab, own(lab, lambda v: 0.0 * v),
                     Mistake("coriolis", f"the Coriolis component {lab} left out",
                             "coriolis-missing"))
                for wj in omegas.values():
                    if wj == wk:
                        continue

                    def other_omega(env: dict[str, np.ndarray], ins: tuple[str, ...],
                                    wj: str = wj) -> np.ndarray:
                        v = g.xy(env[ins[1]]) - g.xy(env[ins[2]])
                        w = float(np.asarray(env[wj]))
                        return 2.0 * w * np.stack([-v[..., 1], v[..., 0]], axis=-1)

                    redo(lab, other_omega,
                         Mistake("coriolis", f"the Coriolis component {lab} computed with {wj} "
                                             f"instead of {wk} (use the angular velocity of "
                                             "the link that carries the path)",
                                 "coriolis-omega"))
        return out

    def _branch_variants(self) -> list[tuple[Mistake, Evaluator]]:
        from graphkin.kinematics.solve import solve

        chosen = {k: v for k, v in self.sol.branches.items() if v in OTHER_BRANCH}
        labels = list(chosen)[:_MAX_BRANCHES]
        out: list[tuple[Mistake, Evaluator]] = []
        seen: list[np.ndarray] = []
        for n in range(1, len(labels) + 1):
            for subset in itertools.combinations(labels, n):
                forced = {lab: OTHER_BRANCH[chosen[lab]] for lab in subset}
                try:
                    alt = solve(self.mech, branches=forced)
                except GraphkinError:
                    continue
                pos = np.array([alt.position(p) for p in self.mech.point_names])
                if any(np.allclose(pos, s) for s in [self._positions(), *seen]):
                    continue
                seen.append(pos)
                where = ", ".join(self._branch_words(alt, lab, forced[lab], chosen[lab])
                                  for lab in subset)
                out.append((Mistake("branch", f"the other assembly ({where})", "branch"),
                            Evaluator(alt)))
        return out

    def _branch_words(self, alt: Solution, label: str, forced: str, chosen: str) -> str:
        """What the student drew on the other branch: ``"C below BD"``."""
        cx = self.sol.constructions.get("posture")
        names = self.mech.point_names
        try:
            step = cx.step_of(label) if cx is not None else None
        except (KeyError, GraphkinError):
            step = None
        if step is not None and step.op == "intersect_circles" and label in names:
            centers = []
            for c in step.inputs:
                try:
                    cs = cx.step_of(c) if cx is not None else None
                except (KeyError, GraphkinError):
                    cs = None
                if cs is not None and cs.inputs and cs.inputs[0] in names:
                    centers.append(cs.inputs[0])
            if len(centers) == 2:
                p, q = centers
                a, b, x = (np.asarray(alt.position(n), dtype=float) for n in (p, q, label))
                d = b - a
                side = float(d[0] * (x - a)[1] - d[1] * (x - a)[0])
                if abs(d[0]) >= abs(d[1]):
                    word = "above" if side * (1 if d[0] > 0 else -1) > 0 else "below"
                else:
                    word = "left of" if side * (1 if d[1] > 0 else -1) > 0 else "right of"
                sep = "" if len(p) == len(q) == 1 else "-"
                return f"{label} {word} {p}{sep}{q}"
        helpers = self.mech.helper_points
        moved = [n for n in names if n not in helpers and float(np.hypot(
            *(np.asarray(alt.position(n)) - np.asarray(self.sol.position(n)))))
            > 1e-6 * float(self.mech.scale)]
        if label in names and label not in helpers:
            return f"{label} at the other intersection"
        if moved:
            return f"{', '.join(moved)} at the other intersection"
        return "the other intersection"

    def _positions(self) -> np.ndarray:
        return np.array([self.sol.position(p) for p in self.mech.point_names])
