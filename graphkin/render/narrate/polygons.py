"""The velocity and acceleration polygons told in the book's words (Secs. 3.4-3.6, 4.4-4.7).

:class:`_Teller` adds to :class:`~graphkin.render.narrate.reader._Reader` one
method per construction operation of a polygon: a velocity or acceleration
difference, a line laid through a known image, the meet of two lines that
solves a vector equation, normal and Coriolis components, an angular rate
read off, an image by similar triangles, a slider's motion along its line.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.3-3.7 (velocity difference, polygons and
images, apparent velocity, rolling contact), 4.3-4.7 (acceleration difference,
polygons, Coriolis component, rolling contact).
"""

from __future__ import annotations

import math

import numpy as np

from graphkin.construction import Step, Term
from graphkin.mechanisms.model import FRAME
from graphkin.render.narrate.reader import _Reader
from graphkin.render.narrate.words import (
    PageStep,
    U,
    _deg_line,
    _image_point,
    _path_words,
    _pretty,
    _side_words,
    _wtext,
    image_letter,
    point_name,
)


class _Teller(_Reader):
    """Reads one construction and its values; tells each group of steps."""

    # a point of a link from another point of it (case 1)
    def tell_velocity_difference(self, s: Step) -> PageStep:
        img, w, a, x = s.inputs
        name, link = _image_point(s.outputs[0])
        P, A = point_name(x), point_name(a)
        Pk = f"{P}{link}"
        r = self.dist(a, x)
        wv = self.scalar(w)
        rate, given = self.rate(w)
        vrel = abs(wv) * r
        sides = self.sides_of(s)
        who = (f"Velocity of {Pk}, the point of link {link} at {P}" if link
               else f"Velocity of {P}")
        sense = "counterclockwise" if wv > 0 else "clockwise"
        text = (f"V_{P}{A} = ω{w[1:]} × R_{P}{A} is perpendicular to {A}{P}, R_{P}{A} turned 90° "
                f"{sense} (the sense of ω{w[1:]}). Lay it off from {image_letter(img)}: its tip "
                f"is {image_letter(s.outputs[0])}, the tip of V_{Pk}.")
        numbers = [f"{rate}{' (given)' if given else ''}.",
                   f"V_{P}{A} = ω{w[1:]} R_{P}{A} = ({_wtext(rate)})({self.length(a, x)}) = "
                   f"{self.q(vrel, 'V')}; at {self.scale_text()} lay off {self.paper(vrel)}.",
                   f"V_{Pk} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{who}: V_{Pk} = V_{A} + V_{P}{A}", sides, 1, text=text,
                        numbers=numbers, refs="Sec. 3.3, Eq. 3.4; Sec. 3.4", vector=True)

    def tell_acceleration_difference(self, s: Step) -> PageStep:
        img, w, al, a, x = s.inputs
        name, link = _image_point(s.outputs[0])
        P, A = point_name(x), point_name(a)
        Pk = f"{P}{link}"
        r = self.dist(a, x)
        wv, av = self.scalar(w), self.scalar(al)
        wt, _ = self.rate(w)
        at, _ = self.rate(al)
        an, atn = wv * wv * r, abs(av) * r
        who = (f"Acceleration of {Pk}, the point of link {link} at {P}" if link
               else f"Acceleration of {P}")
        text = (f"A^n_{P}{A} = ω² R points from {P} toward {A}; A^t_{P}{A} = α × R is "
                f"perpendicular to {A}{P}. Lay off A^n_{P}{A} from {image_letter(img)}, then "
                f"A^t_{P}{A} from its tip: the end is {image_letter(s.outputs[0])}.")
        numbers = [f"{wt}, {at}.",
                   f"A^n_{P}{A} = ω{w[1:]}² R_{P}{A} = ({_wtext(wt)})²({self.length(a, x)}) = "
                   f"{self.q(an, 'A')}; lay off {self.paper(an)} (at {self.scale_text()}).",
                   f"A^t_{P}{A} = α{al[1:]} R_{P}{A} = ({_wtext(at)})({self.length(a, x)}) = "
                   f"{self.q(atn, 'A')}; lay off {self.paper(atn)}.",
                   f"A_{Pk} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{who}: A_{Pk} = A_{A} + A^n_{P}{A} + A^t_{P}{A}", self.sides_of(s), 1,
                        text=text, numbers=numbers,
                        refs="Sec. 4.3, Eqs. 4.6, 4.7, 4.11; Sec. 4.4", vector=True)

    # a direction line through a known image
    def _line(self, s: Step, kind: str) -> PageStep:
        ds = self.downstream(s.outputs[0])
        through = s.inputs[1]
        ref = s.inputs[0]
        sides: list[tuple[Term, ...]] | None = None
        unknown = None
        if ds is not None:
            meet, i = ds
            full = self.sides_of(meet)
            if full is not None and len(full) == 3:
                side = full[1 + min(i, 1)]
                sides = [full[0], side]
                unknown = next((t for t in side if t.magnitude == U), None)
        vname = unknown.name if unknown is not None else ("A^t" if self.accel else "V")
        vname = self.book(vname)
        letter = image_letter(through)
        if through in ("o_v", "o_a"):
            fixed = self._fixed_name(ref)
            if fixed:
                letter = f"{letter} (the image of {fixed})"
        tip = letter
        m = self.makers.get(through)
        if m is not None and m.op in ("translate", "subtract") and len(m.inputs) > 1:
            tip = f"the tip of {_pretty(self.book(m.inputs[1]))}" if m.op == "translate" \
                else f"the tail of {_pretty(self.book(m.inputs[1]))}"
        if kind == "perpendicular":
            p, q = self._posture_pair(ref)
            why = (f"{_pretty(vname)} is perpendicular to {p}{q}" if p else
                   f"{_pretty(vname)} has a known direction")
            if self.accel and unknown is not None and unknown.name.endswith("^t"):
                why += " (its size, α × R, is not known yet)"
            else:
                why += " but its size is not known yet"
            text = (f"{why}. Through {tip} draw a line perpendicular to {p}{q}: the sought "
                    "image lies on it.")
            title = f"Direction of {_pretty(vname)}: perpendicular to {p}{q}"
        else:
            path = _path_words(ref)
            text = (f"{_pretty(vname)} is along {path}, its size unknown. Through {tip} draw a "
                    f"line parallel to {path}: the sought image lies on it.")
            title = f"Direction of {_pretty(vname)}: along {path}"
        numbers = []
        ln = self.raw(ref, "posture")
        if ln is None:
            ln = self.raw(ref)
        if ln is not None and ln.shape == (3,) and np.all(np.isfinite(ln[:2])):
            d = np.array([ln[1], -ln[0]])  # the direction of the line (a, b, c)
            if kind == "perpendicular":
                p, q = self._posture_pair(ref)
                numbers.append(f"{p}{q} lies at {_deg_line(d)} on the mechanism; the line "
                               f"through {letter if tip == letter else 'the tip'} is at "
                               f"{_deg_line(np.array([-d[1], d[0]]))}.")
            else:
                numbers.append(f"The {_path_words(ref)[4:]} lies at {_deg_line(d)}: so does the "
                               "line.")
        refs = "Sec. 4.4" if self.accel else "Sec. 3.4"
        if kind == "parallel":
            refs = "Sec. 4.5, Eq. 4.17" if self.accel else "Sec. 3.5, Eq. 3.6"
        return PageStep(title, sides, None, text=text, numbers=numbers, refs=refs, vector=True)

    def tell_perpendicular(self, s: Step) -> PageStep:
        return self._line(s, "perpendicular")

    def tell_parallel(self, s: Step) -> PageStep:
        return self._line(s, "parallel")

    def _posture_pair(self, line: str) -> tuple[str, str]:
        m = self.makers.get(line)
        if m is None:
            for cx in self.src.constructions.values():
                m = next((st for st in cx.steps if line in st.outputs), None)
                if m is not None:
                    break
        if m is None or m.op != "join":
            return "", ""
        return point_name(m.inputs[0]), point_name(m.inputs[1])

    def _fixed_name(self, ref: str) -> str:
        """The point whose image the pole is, for a line drawn through the pole."""
        p, _ = self._posture_pair(ref)
        return p

    # a known component laid off
    def tell_normal_component(self, s: Step, lay: Step) -> PageStep:
        p, c, vp, vc = s.inputs
        P, C = point_name(p), point_name(c)
        vrel = self.between(vp, vc, "velocity")
        v = float(np.hypot(*vrel)) if vrel is not None else math.nan
        r = self.dist(p, c)
        an = v * v / r if r > 0 else math.nan
        vec = self.raw(s.outputs[0])
        if vec is not None and vec.shape == (2,):
            an = float(np.hypot(*vec))
        name = s.outputs[0]
        ds = self.downstream(lay.outputs[0])
        sides = None
        if ds is not None:
            full = self.sides_of(ds[0])
            if full is not None and len(full) == 3:
                sides = [full[0], full[1 + min(ds[1], 1)]]
        _, link = _image_point(vc)
        vname = f"V_{C}{link}{P}" if link else f"V_{C}{P}"
        text = (f"The normal component {_pretty(name)} = V²/R is known from the velocity "
                f"polygon. It is parallel to {C}{P}, directed from {C} toward {P}. Lay it off "
                f"from {image_letter(lay.inputs[0])}.")
        numbers = [f"{_pretty(name)} = {vname}²/R_{C}{P} = ({self.q(v, 'V')})²/"
                   f"({self.length(p, c)}) = {self.q(an, 'A')}.",
                   f"At {self.scale_text()}: lay off {self.paper(an)} from "
                   f"{image_letter(lay.inputs[0])}, parallel to {C}{P}, toward {P}."]
        return PageStep(f"Normal component {_pretty(name)} = {vname}²/R_{C}{P}", sides, None,
                        text=text, numbers=numbers, refs="Sec. 4.3, Eq. 4.6; Sec. 4.4",
                        vector=True)

    def tell_coriolis(self, s: Step, lay: Step) -> PageStep:
        w, vp, vpk = s.inputs
        k = w[1:]
        P, _ = _image_point(vp)
        P = point_name(P)
        rel = self.book(f"V_{P}/{k}")
        vrel = self.between(vpk, vp, "velocity")
        v = float(np.hypot(*vrel)) if vrel is not None else math.nan
        wv = self.scalar(w)
        wt, _ = self.rate(w)
        ac = 2 * abs(wv) * v
        name = self.book(f"A_{P}/{k}^c")
        sense = "counterclockwise" if wv > 0 else "clockwise"
        sub = lay.op == "subtract"
        text = (f"{P} moves along a path that is fixed in link {k}, and the path turns with "
                f"link {k}: the Coriolis component uses ω{k}, the angular velocity of the link "
                f"that carries the path. It is {rel} turned 90° {sense} (the sense of ω{k}). "
                + ("It is subtracted: lay it off backward, ending at "
                   f"{image_letter(lay.inputs[0])}." if sub
                   else f"Lay it off from {image_letter(lay.inputs[0])}."))
        maker = self.src.constructions.get("velocity")
        given = False
        if maker is not None:
            vs = next((st for st in maker.steps if vp in st.outputs), None)
            given = vs is not None and vs.op == "add_along" and vs.inputs[3] in self.given_rates
        vt = self.q(v, "V", answer=not given)
        numbers = [f"{wt}; {rel} = {vt} "
                   f"({'given' if given else 'from the velocity polygon'}).",
                   f"{_pretty(name)} = 2 ω{k} {rel} = 2({_wtext(wt)})({vt}) = "
                   f"{self.q(ac, 'A')}; lay off {self.paper(ac)}."]
        ds = self.downstream(lay.outputs[0])
        sides = None
        if ds is not None:
            full = self.sides_of(ds[0])
            if full is not None:
                sides = [full[0], full[1 + min(ds[1], len(full) - 2)]] if len(full) == 3 \
                    else full
        return PageStep(f"Coriolis component {_pretty(name)} = 2ω{k} × {rel}", sides, None,
                        text=text, numbers=numbers, refs="Sec. 4.5, Eqs. 4.16, 4.17",
                        vector=True)

    def tell_apparent_normal(self, s: Step, lay: Step) -> PageStep:
        x, o, vx, vxk = s.inputs
        X = point_name(x)
        vec = self.raw(s.outputs[0])
        a = float(np.hypot(*vec)) if vec is not None and vec.shape == (2,) else math.nan
        rho = self.dist(o, x)
        text = (f"{X} moves on a curved path of radius ρ = {self.length(o, x)}: the apparent "
                "acceleration has a normal component V²/ρ toward the path's center of "
                f"curvature. Lay it off from {image_letter(lay.inputs[0])}.")
        vrel = self.between(vxk, vx, "velocity")
        v = float(np.hypot(*vrel)) if vrel is not None else math.nan
        numbers = [f"{_pretty(s.outputs[0])} = V²/ρ = ({self.q(v, 'V')})²/"
                   f"({self.q(rho, 'L', False)}) = {self.q(a, 'A')}; lay off {self.paper(a)}."]
        return PageStep(f"Apparent normal component {_pretty(s.outputs[0])} = V²/ρ", None, None,
                        text=text, numbers=numbers, refs="Sec. 4.5, Eq. 4.14", vector=True)

    def tell_rolling_normal(self, s: Step, lay: Step) -> PageStep:
        vec = self.raw(s.outputs[0])
        a = float(np.hypot(*vec)) if vec is not None and vec.shape == (2,) else math.nan
        name = s.outputs[0]
        sides = [lay.equation.lhs, lay.equation.rhs] if lay.equation is not None else None
        lhs = lay.equation.lhs[0].name if lay.equation is not None else "A_C"
        text = ("The wheel rolls without slip: the contact points have the same velocity, but "
                f"not the same acceleration. {_pretty(name)} is normal to the surfaces at the "
                "contact, toward the center of the rolling wheel. Lay it off from "
                f"{image_letter(lay.inputs[0])}: its tip is the image of the wheel's contact "
                "point.")
        numbers = [f"{_pretty(name)} = {self.q(a, 'A')}; lay off {self.paper(a)}.",
                   f"{_pretty(lhs)} = {self.vq(self.vec(lay.outputs[0]))}."]
        return PageStep(f"Rolling contact: {_pretty(lhs)} = {_pretty(lhs[:-1] + '1')} + "
                        f"{_pretty(name)}", sides, 1, text=text, numbers=numbers,
                        refs="Sec. 4.7, Eq. 4.19, Fig. 4.19", vector=True)

    # two lines meet
    def tell_meet(self, s: Step) -> PageStep:
        sides = self.sides_of(s)
        lhs = self.lhs_of(s)
        what = "Acceleration" if self.accel else "Velocity"
        name, link = _image_point(s.outputs[0])
        P = point_name(name)
        who = f"{what} of {P}{link}" + (f", the point of link {link} at {P}" if link else "")
        letter = image_letter(s.outputs[0])
        eq_words = " = ".join(_side_words(side) for side in (sides or []))
        title = f"{who}: {eq_words}" if sides else who
        numbers = []
        here = self.xy(s.outputs[0])
        for i, line in enumerate(s.inputs[:2]):
            if sides is None:
                break
            side = sides[1 + i]
            unk = next((t for t in side if t.magnitude == U), None)
            m = self.makers.get(line)
            thr = None
            if m is not None:
                thr = next((self.xy(x) for x in reversed(m.inputs)
                            if self.xy(x) is not None), None)
            if unk is None or thr is None or here is None:
                continue
            v = (here - thr) * unk.sign
            mag = float(np.hypot(*v))
            numbers.append(f"{_pretty(unk.name)} = {self.paper(mag)} on the drawing = "
                           f"{self.vq(v)}.")
        numbers.append(f"{_pretty(lhs.name)} = {self.vq(self.vec(s.outputs[0]))}.")
        text = (f"The two lines meet at {letter}: the only point that satisfies both sides of "
                f"the equation (case 3). Measure the vectors on the drawing and multiply by "
                f"the scale, {self.scale_text()}.")
        return PageStep(title, sides, 3, text=text, numbers=numbers,
                        refs=("Sec. 4.4, Fig. 4.8" if self.accel else "Sec. 3.4, Fig. 3.7")
                        + ("; Sec. 4.5" if self.accel and link else
                           "; Sec. 3.5" if link else ""), vector=True)

    def tell_angular_rate(self, s: Step) -> PageStep:
        a, b, ia, ib = s.inputs
        lab = s.outputs[0]
        k = lab[1:]
        A, B, Bn = point_name(a), point_name(b) + _image_point(ib)[1], point_name(b)
        r = self.dist(a, b)
        val = self.scalar(lab)
        t, _ = self.rate(lab)
        # the relative vector read off (A^t_BA or V_BA) and what it gives (α or ω), Eq. 4.7 / 3.3
        rel, kind, read = ((f"A^t_{B}{A}", "A", "the tangential component, read off")
                           if self.accel else (f"V_{B}{A}", "V", "read off the polygon"))
        sym, size = lab[:1], abs(val) * r
        formula = f"{sym}{k} = {rel}/R_{Bn}{A}"
        numbers = [f"{rel} = {self.q(size, kind)} ({read}).",
                   f"{sym}{k} = ({self.q(size, kind)})/({self.length(a, b)}) = "
                   f"{t.split(' = ', 1)[1]}."]
        turns = f"its sense is the sense in which {rel}, drawn at {B}, turns {B} about {A}."
        if self.accel:
            text = f"The tangential component {rel} = {sym}{k} × R_{Bn}{A} gives {sym}{k}; {turns}"
            title, refs = f"Angular acceleration of link {k}: {formula}", "Sec. 4.3, Eq. 4.7"
        else:
            text = (f"{rel} = {sym}{k} × R_{Bn}{A}: its size divided by the length {A}{B} gives "
                    f"{sym}{k}; {turns}")
            if "rolling" in a or "rolling" in b:
                text = (f"No slip: the wheel's contact point has the velocity of the surface "
                        f"it rolls on, so the wheel turns about it for now. {text}")
            title, refs = f"Angular velocity of link {k}: {formula}", "Sec. 3.3, Eq. 3.3"
        return PageStep(title, None, None, formula=formula, text=text, numbers=numbers,
                        refs=refs, vector=True, answers=[lab])

    def tell_add_angle(self, s: Step) -> PageStep:
        lab = s.outputs[0]
        src_ = s.inputs[0]
        k, j = lab[1:], src_[1:]
        t, _ = self.rate(lab)
        sym = lab[:1]
        formula = f"{sym}{k} = {sym}{j}"
        what = "velocity" if sym == "ω" else "acceleration"
        text = (f"The slider {k} cannot turn relative to its guide {j}: it has the angular "
                f"{what} of the guide.")
        return PageStep(f"Angular {what} of link {k}: {formula}", None, None, formula=formula,
                        text=text, numbers=[f"{t}."],
                        refs="Sec. 3.6, Eq. 3.11" if sym == "ω" else "Sec. 4.6, Eq. 4.18",
                        answers=[lab])

    def tell_similar(self, s: Step) -> PageStep:
        a, b = s.inputs[:2]
        name, _ = _image_point(s.outputs[0])
        P = point_name(name)
        A, B = _image_point(a)[0] if a not in ("o_v", "o_a") else "", _image_point(b)[0]
        if not A:
            A = self._fixed_of_image(s) or "the pivot"
        sym = "A" if self.accel else "V"
        what = "acceleration" if self.accel else "velocity"
        la, lb, lp = image_letter(a), image_letter(b), image_letter(s.outputs[0])
        if a in ("o_v", "o_a"):
            la = point_name(A).lower() + ("′" if self.accel else "")
            at = f" ({la} is at {image_letter(a)})"
        else:
            at = ""
        sides = [(Term(f"{sym}_{P}", U, U),), (Term(f"{sym}_{point_name(A)}"),
                                                Term(f"{sym}_{P}{point_name(A)}"))]
        text = (f"The {what} image of a link is similar to the link (Sec. "
                f"{'4.4' if self.accel else '3.4'}): draw the triangle {la}{lb}{lp} similar to "
                f"{point_name(A)}{point_name(B)}{P}{at}, lettered in the same order and sense. "
                f"{lp} is the tip of {sym}_{P}.")
        numbers = [f"{sym}_{P} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{what.capitalize()} of {P} from the {what} image: "
                        f"{sym}_{P} = {sym}_{point_name(A)} + {sym}_{P}{point_name(A)}", sides, 1,
                        text=text, numbers=numbers,
                        refs="Sec. 4.4" if self.accel else "Sec. 3.4, Fig. 3.6", vector=True)

    def _fixed_of_image(self, s: Step) -> str:
        mech = self.mech
        if mech is None:
            return ""
        name, _ = _image_point(s.outputs[0])
        for lid in mech.point_links.get(name, []):
            for n in mech.links[lid].points:
                if n in mech.links[FRAME].points:
                    return n
        return ""

    def tell_add_along(self, s: Step) -> PageStep:
        sides = self.sides_of(s)
        base = s.inputs[0]
        rate = s.inputs[3]
        v = self.scalar(rate)
        name, _ = _image_point(s.outputs[0])
        P = point_name(name)
        sym = "A" if self.accel else "V"
        kind = "A" if self.accel else "V"
        what = "Acceleration" if self.accel else "Velocity"
        words = " + ".join(_pretty(t.name) for t in sides[1]) if sides else ""
        text = (f"{P} slides along its line at the given "
                f"{'acceleration' if self.accel else 'speed'}: lay it off along the slide from "
                f"{image_letter(base) if ':' not in base else 'the tip of the last vector'}; "
                f"the end is {image_letter(s.outputs[0])}.")
        numbers = [f"Given: {self.q(abs(v), kind, False)} along the slide; at "
                   f"{self.scale_text()} lay off {self.paper(abs(v), False)}.",
                   f"{sym}_{P} = {self.vq(self.vec(s.outputs[0]))}."]
        return PageStep(f"{what} of {P}: {sym}_{P} = {words}", sides, 1, text=text,
                        numbers=numbers,
                        refs="Sec. 4.5, Eq. 4.17" if self.accel else "Sec. 3.5, Eq. 3.6",
                        vector=True)

    def tell_translate(self, s: Step) -> PageStep:
        return self.tell_generic([s])
