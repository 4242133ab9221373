"""Velocity and acceleration polygons, built from the posture construction's groups.

Each group of the posture construction has its polygon counterpart, exactly
as the book pairs them:

* two arcs (case 4 in the posture) become two perpendiculars (case 3):
  ``V_C = V_B + V_CB = V_D + V_CD`` with ``V_CB ⊥ R_CB`` and ``V_CD ⊥ R_CD``
  (Sec. 3.4, Fig. 3.5); for accelerations the normal components
  ``A^n = V²/R`` are laid off first and the tangential ones drawn ⊥ (Sec. 4.3);
* a line locus (a slider) becomes a parallel to the slide through the image
  of the coincident point: the apparent velocity (Sec. 3.6) and, for
  accelerations, the Coriolis component ``2ω × V_rel`` and, on a curved path,
  the apparent normal component ``V_rel²/ρ`` (Sec. 4.5-4.6, Eq. 4.15);
* every other point of a link comes from its image (Mehmke's theorem: the
  image is similar to the link, Sec. 3.5, Eq. 4.12).

Images are points of the polygon's plane: the velocity image ``v(B)`` is the
tip of ``V_B`` drawn from the pole ``O_V``; ``a(B)`` likewise from ``O_A``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.3-3.6 (Tables 3.1), 4.2-4.6 (Table 4.1).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from graphkin.construction import Construction, Mark, Role, Term, VectorEquation
from graphkin.errors import ConstructionError
from graphkin.kinematics.polygon_rolling import RollingRules
from graphkin.kinematics.posture import PostureConstruction, _n
from graphkin.mechanisms.model import FRAME, Drive, Mechanism, Rolling, Slider, Slot

__all__ = ["Polygons", "build_polygons", "vimg", "aimg"]

K, U = Mark.KNOWN, Mark.UNKNOWN


def vimg(label: str) -> str:
    """Label of the velocity image of a point: ``v(B)``."""
    return f"v({label})"


def aimg(label: str) -> str:
    """Label of the acceleration image of a point: ``a(B)``."""
    return f"a({label})"


@dataclass
class Polygons:
    """The velocity and acceleration constructions and their input labels.

    Attributes
    ----------
    velocity, acceleration : Construction
    rate_inputs : dict
        Drive index -> (velocity input label, acceleration input label).
    velocity_images, acceleration_images : dict
        Point label -> label of its image (fixed points share the pole ``o_v``/``o_a``).
    """

    velocity: Construction
    acceleration: Construction
    rate_inputs: dict[int, tuple[str, str]]
    velocity_images: dict[str, str]
    acceleration_images: dict[str, str]


class _Poly(RollingRules):
    def __init__(self, mech: Mechanism, pc: PostureConstruction) -> None:
        self.mech = mech
        self.pc = pc
        self.v = Construction(title=f"{mech.title}: velocity polygon")
        self.a = Construction(title=f"{mech.title}: acceleration polygon")
        self.vimg: dict[str, str] = {}
        self.aimg: dict[str, str] = {}
        self.omega: dict[str, str] = {}
        self.alpha: dict[str, str] = {}
        self.anchor: dict[str, str] = {}
        self.rate_inputs: dict[int, tuple[str, str]] = {}
        self.lines: set[str] = set()

    # ---- helpers ------------------------------------------------------
    def V(self, op: str, inputs: tuple[str, ...], out: str, **kw: Any) -> str:
        kw.setdefault("diagram", "velocity")
        self.v.add(op, inputs, (out,), **kw)
        return out

    def A(self, op: str, inputs: tuple[str, ...], out: str, **kw: Any) -> str:
        kw.setdefault("diagram", "acceleration")
        self.a.add(op, inputs, (out,), **kw)
        return out

    def posture_line(self, p: str, q: str, which: Construction) -> str:
        """The line PQ of the posture (a direction to draw perpendiculars to)."""
        lab = f"R_{_n(q)}{_n(p)}:{p}>{q}"
        if lab not in {o for s in which.steps for o in s.outputs}:
            which.add("join", (p, q), (lab,), diagram="posture",
                      note=f"The line {_n(p)}{_n(q)} of the posture, for its direction.")
        return lab

    def coincident(self, k: str, x: str) -> tuple[str, str]:
        """Images (velocity, acceleration) of the point of link k that coincides with X."""
        if k == FRAME:
            return "o_v", "o_a"
        vl, al = vimg(f"{x}@{k}"), aimg(f"{x}@{k}")
        anc = self.anchor[k]
        if vl not in {o for s in self.v.steps for o in s.outputs}:
            self.V("velocity_difference", (self.vimg[anc], self.omega[k], anc, x), vl,
                   note=f"The velocity of the point {_n(x)}{k} of link {k} that coincides "
                        f"with {_n(x)}.",
                   equation=VectorEquation((Term(f"V_{_n(x)}{k}", U, U),),
                                           (Term(f"V_{_n(anc)}"), Term(f"V_{_n(x)}{_n(anc)}")),
                                           case=1))
            self.A("acceleration_difference",
                   (self.aimg[anc], self.omega[k], self.alpha[k], anc, x), al,
                   note=f"The acceleration of the coincident point {_n(x)}{k} of link {k}.",
                   equation=VectorEquation((Term(f"A_{_n(x)}{k}", U, U),),
                                           (Term(f"A_{_n(anc)}"),
                                            Term(f"A_{_n(x)}{_n(anc)}^n"),
                                            Term(f"A_{_n(x)}{_n(anc)}^t")), case=1))
        return vl, al

    # ---- events -------------------------------------------------------
    def frame(self) -> None:
        self.V("point", (), "o_v", xy=(0.0, 0.0), role=Role.GIVEN,
               note="Choose the velocity pole O_V: the image of every fixed point.")
        self.A("point", (), "o_a", xy=(0.0, 0.0), role=Role.GIVEN,
               note="Choose the acceleration pole O_A: the image of every fixed point.")
        self.V("scalar", (), "ω1", value=0.0, role=Role.GIVEN, note="The frame does not turn.")
        self.A("scalar", (), "α1", value=0.0, role=Role.GIVEN, note="The frame does not turn.")
        self.omega[FRAME], self.alpha[FRAME] = "ω1", "α1"
        for name in self.mech.links[FRAME].points:
            self.vimg[name], self.aimg[name] = "o_v", "o_a"

    def run(self) -> None:
        self.frame()
        # an event whose rates are not known yet (a point of a rolling link whose surface's
        # link is found later) waits, and is taken up as soon as they are; when something
        # waits, the rolling rules (polygon_rolling.py) may give the rates it waits for
        pending: list[tuple[object, ...]] = []
        for ev in self.pc.events:
            if self._take(ev):
                pending = [e for e in pending if not self._take(e)]
            else:
                pending.append(ev)
            while pending and self.unstick():
                pending = [e for e in pending if not self._take(e)]
        while self.unstick():
            pending = [e for e in pending if not self._take(e)]
        pending = [e for e in pending if not self._take(e)]
        missing = [k for k in self.mech.links if k not in self.omega or k not in self.alpha]
        if pending or missing:
            what = (f"waiting: {_event_text(pending[0])}" if pending
                    else f"the rates of link {missing[0]} are not found")
            raise ConstructionError("the velocity polygon cannot be drawn one step at a time "
                                    f"here ({what})",
                                    step=str(pending[0][0]) if pending else missing[0])

    def _take(self, ev: tuple[object, ...]) -> bool:
        """Carry out one posture event's polygon steps; False when its rates are not known yet."""
        try:
            getattr(self, f"ev_{ev[0]}")(*ev[1:])
        except _NotYet:
            return False
        return True

    # ---- rolling contact (Sec. 3.7, 4.7): polygon_rolling.py -------------------
    def ev_roll_angle(self, r: Rolling, lid: str) -> None:
        """The ω and α of a link the rolling places come from no slip once its images allow."""

    def ev_roll_travel(self, r: Rolling, s: Slider) -> None:
        """A slider the rolling moves (a rack under a driven pinion): its point from no slip.

        ``V_C(k) = V_C(other)`` (Eq. 3.13), and the slider turns with its guide
        (ω_k known), so ``V_P = V_C(k) + ω_k × R_PC``; likewise for accelerations
        with ``A_C(k) = A_C(other) ∓ A^r`` (Eq. 4.19).
        """
        k, p, c = s.link, s.point, r.contact_label
        other = r.link if k == r.on else r.on
        if (p in self.vimg or c not in self.pc.values or not self.ready(other)
                or k not in self.omega or k not in self.alpha):
            if p in self.vimg:
                return
            raise _NotYet(p)
        vc, _ = self.coincident(other, c)
        ac = self.contact_on(r) if k == r.on else self.contact_images(r)[1]
        self.vimg[p] = self.V(
            "velocity_difference", (vc, self.omega[k], c, p), vimg(p), role=Role.RESULT,
            note=f"No slip: the contact point of link {k} has the velocity of link {other}'s; "
                 f"V_{p} = V_{r.contact_name} + ω{k} × R_{p}{r.contact_name} (case 1).")
        self.aimg[p] = self.A(
            "acceleration_difference", (ac, self.omega[k], self.alpha[k], c, p), aimg(p),
            role=Role.RESULT, note=f"A_{p} = A_{r.contact_name}{k} + A^n + A^t (case 1).")

    def ev_contact(self, r: Rolling) -> None:
        """The contact point is placed: nothing to draw until its images are needed."""

    def ev_input(self, d: Drive) -> None:
        lid, kind, idx = d.link, d.kind, d.index
        if kind in ("relative", "x", "y"):
            w, al = d.rate_labels
            what = (f"the joint's speed {w}" if kind == "relative"
                    else f"the rate of {d.label}")
            self.V("input", (), w, name=w, role=Role.GIVEN, note=f"The input: {what}.")
            self.A("input", (), al, name=al, role=Role.GIVEN,
                   note=f"The input: {'its acceleration' if kind == 'relative' else 'its'} "
                        f"{al}.")
        elif kind == "angle":
            w, al = f"ω{lid}", f"α{lid}"
            self.V("input", (), w, name=w, role=Role.GIVEN, note=f"The input speed ω{lid}.")
            self.A("input", (), al, name=al, role=Role.GIVEN,
                   note=f"The input acceleration α{lid}.")
            self.omega[lid], self.alpha[lid] = w, al
        else:
            w, al = f"ds{lid}", f"dds{lid}"
            self.V("input", (), w, name=w, role=Role.GIVEN,
                   note=f"The input: the slider {lid}'s speed along its line.")
            self.A("input", (), al, name=al, role=Role.GIVEN,
                   note=f"The input: the slider {lid}'s acceleration along its line.")
        self.rate_inputs[idx] = (w, al)

    # ---- joint-angle and coordinate drives (P5.7-5.13) ----------------------
    def ev_relative_angle(self, d: Drive, forward: bool) -> None:
        """``ω3 = ω2 + ω3/2`` and ``α3 = α2 + α3/2`` (or back from link 3 to link 2)."""
        i, j = d.link, d.relative_to
        assert j is not None
        known, new, sign = (j, i, 1.0) if forward else (i, j, -1.0)
        if known not in self.omega or known not in self.alpha:
            raise _NotYet(new)
        w, al = self.rate_inputs[d.index]
        op = "+" if forward else "−"
        self.omega[new] = self.V("add_angles", (self.omega[known], w), f"ω{new}", sign=sign,
                                 role=Role.RESULT,
                                 note=f"The joint turns link {new} with link {known}: "
                                      f"ω{new} = ω{known} {op} {w}.")
        self.alpha[new] = self.A("add_angles", (self.alpha[known], al), f"α{new}", sign=sign,
                                 role=Role.RESULT,
                                 note=f"In plane motion the angular accelerations add too: "
                                      f"α{new} = α{known} {op} {al}.")

    def ev_point_drive(self, x: Drive, y: Drive) -> None:
        """The images of a point whose coordinates are given: its rates laid off from the poles."""
        p = x.point
        assert p is not None
        (vx, ax), (vy, ay) = self.rate_inputs[x.index], self.rate_inputs[y.index]
        eq = VectorEquation((Term(f"V_{p}", U, U),), (Term(vx, K, K), Term(vy, K, K)), case=1)
        self.vimg[p] = self.V("point_xy", (vx, vy), vimg(p), role=Role.RESULT, equation=eq,
                              note=f"From O_V lay off the given components ({vx}, {vy}) of "
                                   f"V_{p}: the image of {p}.")
        eq = VectorEquation((Term(f"A_{p}", U, U),), (Term(ax, K, K), Term(ay, K, K)), case=1)
        self.aimg[p] = self.A("point_xy", (ax, ay), aimg(p), role=Role.RESULT, equation=eq,
                              note=f"From O_A lay off the given components ({ax}, {ay}) of "
                                   f"A_{p}: its acceleration image.")

    def ev_coordinate(self, d: Drive, lid: str, p: str) -> None:
        """A point with one given coordinate on a link turning about P (case 3 in the polygons)."""
        x = d.point
        assert x is not None
        w, al = self.rate_inputs[d.index]
        lv1, la1, tv1, ta1 = self.motion_lines(("rot", lid, p), x)
        lv2 = self.V("coordinate_line", (w,), f"{d.kind}={w}:v", axis=d.kind,
                     note=f"Draw the line {d.kind} = {w} in the polygon: the given component of "
                          f"V_{x} puts its image on it.")
        self.vimg[x] = self.V("meet", (lv1, lv2), vimg(x), role=Role.RESULT,
                              equation=VectorEquation(tv1, (Term(w, K, K),
                                                            Term(f"V_{x}", U, K)), case=3),
                              note=f"They meet at the image of {x} (case 3).")
        la2 = self.A("coordinate_line", (al,), f"{d.kind}={al}:a", axis=d.kind,
                     note=f"Draw the line {d.kind} = {al}: the given component of A_{x}.")
        self.aimg[x] = self.A("meet", (la1, la2), aimg(x), role=Role.RESULT,
                              equation=VectorEquation(ta1, (Term(al, K, K),
                                                            Term(f"A_{x}", U, K)), case=3),
                              note=f"They meet at the acceleration image of {x} (case 3).")

    def ev_placed(self, lid: str, anchor: str) -> None:
        self.anchor[lid] = anchor

    def ev_link_angle(self, lid: str, a: str, b: str) -> None:
        if lid in self.omega:
            return
        if a not in self.vimg or b not in self.vimg:
            return  # the group that placed the link gives its ω
        w, al = f"ω{lid}", f"α{lid}"
        self.V("angular_rate", (a, b, self.vimg[a], self.vimg[b]), w, role=Role.RESULT,
               note=f"ω{lid} = V_{_n(b)}{_n(a)}/R_{_n(b)}{_n(a)}, its sense from the image.")
        self.A("angular_rate", (a, b, self.aimg[a], self.aimg[b]), al, role=Role.RESULT,
               note=f"α{lid} = A_{_n(b)}{_n(a)}^t/R_{_n(b)}{_n(a)}, its sense from the image.")
        self.omega[lid], self.alpha[lid] = w, al

    def ev_same_angle(self, a: str, b: str) -> None:
        self.V("add_angle", (self.omega[b],), f"ω{a}", offset=0.0,
               note=f"The slider turns with its guide: ω{a} = ω{b}.")
        self.A("add_angle", (self.alpha[b],), f"α{a}", offset=0.0,
               note=f"The slider turns with its guide: α{a} = α{b}.")
        self.omega[a], self.alpha[a] = f"ω{a}", f"α{a}"

    def ev_point(self, lid: str, name: str, anchor: str) -> None:
        if name in self.vimg and name in self.aimg:
            return  # drawn already (from two known images of its link)
        if anchor not in self.vimg or anchor not in self.aimg:
            raise _NotYet(name)
        for r in self.mech.rolling:
            if r.link == lid and (lid not in self.omega or lid not in self.alpha):
                if not self.surface_ready(r) or self.point_with_image(lid, r.contact_label) is None:
                    raise _NotYet(name)
                self.ensure_omega(r)
                self.rolling_rates(r)
        if lid not in self.omega or lid not in self.alpha:
            raise _NotYet(name)
        # the image triangle needs a base of two points apart (Mehmke): another pair, or
        # the velocity difference from the anchor alone
        others = [p for p in self.mech.links[lid].points
                  if p != anchor and p in self.vimg and p in self.aimg and self.apart(anchor, p)]
        loc = self.mech.links[lid].points
        if others and anchor in loc:
            b = others[0]
            kw = dict(local_a=loc[anchor], local_b=loc[b], local_p=loc[name])
            self.vimg[name] = self.V(
                "similar", (self.vimg[anchor], self.vimg[b]), vimg(name), role=Role.RESULT,
                note=f"Velocity image: the triangle {_n(anchor).lower()}{_n(b).lower()}"
                     f"{name.lower()} is similar to {_n(anchor)}{_n(b)}{name} (Mehmke).", **kw)
            self.aimg[name] = self.A(
                "similar", (self.aimg[anchor], self.aimg[b]), aimg(name), role=Role.RESULT,
                note=f"Acceleration image: {_n(anchor).lower()}'{_n(b).lower()}'"
                     f"{name.lower()}' is similar to {_n(anchor)}{_n(b)}{name} (Eq. 4.12).", **kw)
            return
        eqv = VectorEquation((Term(f"V_{name}", U, U),),
                             (Term(f"V_{_n(anchor)}"), Term(f"V_{name}{_n(anchor)}")), case=1)
        self.vimg[name] = self.V(
            "velocity_difference", (self.vimg[anchor], self.omega[lid], anchor, name),
            vimg(name), role=Role.RESULT, equation=eqv,
            note=f"V_{name} = V_{_n(anchor)} + ω{lid} × R_{name}{_n(anchor)} (case 1).")
        eqa = VectorEquation((Term(f"A_{name}", U, U),),
                             (Term(f"A_{_n(anchor)}"), Term(f"A_{name}{_n(anchor)}^n"),
                              Term(f"A_{name}{_n(anchor)}^t")), case=1)
        self.aimg[name] = self.A(
            "acceleration_difference",
            (self.aimg[anchor], self.omega[lid], self.alpha[lid], anchor, name),
            aimg(name), role=Role.RESULT, equation=eqa,
            note=f"A_{name} = A_{_n(anchor)} + A^n + A^t (case 1).")

    def ev_slider_drive(self, d: Drive) -> None:
        s = d.slider
        assert s is not None
        p, k = s.point, s.on
        w, al = self.rate_inputs[d.index]
        vk, ak = self.coincident(k, p)
        l0, l1 = f"{s.key}:L0", f"{s.key}:L1"
        eq = VectorEquation((Term(f"V_{p}", U, U),), (Term(f"V_{p}{k}"), Term(f"V_{p}/{k}")),
                            case=1)
        self.vimg[p] = self.V("add_along", (vk, l0, l1, w), vimg(p), role=Role.RESULT,
                              equation=eq,
                              note=f"Lay off the slider's speed along its line from the image "
                                   f"of {p}{k}.")
        if k == FRAME:
            tip = ak
        else:
            cor = self.A("coriolis", (self.omega[k], self.vimg[p], vk), f"A_{p}^c",
                         note=f"The Coriolis component 2ω{k} × V_{p}/{k}.")
            tip = self.A("translate", (ak, cor), f"{aimg(p)}:c", note="Lay it off.")
        self.aimg[p] = self.A("add_along", (tip, l0, l1, al), aimg(p), role=Role.RESULT,
                              note="Lay off the slider's acceleration along its line.")

    def motion_lines(self, motion: tuple[str, ...],
                     c: str) -> tuple[str, str, tuple[Term, ...], tuple[Term, ...]]:
        """Velocity and acceleration lines of point C for one locus; and the terms."""
        kind = motion[0]
        if kind == "rot":
            _, lid, p = motion
            line = self.posture_line(p, c, self.v)
            lv = self.V("perpendicular", (line, self.vimg[p]), f"⊥{_n(c)}{_n(p)}:v",
                        note=f"Through {_n(p).lower()} draw a line perpendicular to "
                             f"{_n(c)}{_n(p)}: the direction of V_{_n(c)}{_n(p)}.")
            line_a = self.posture_line(p, c, self.a)
            an = self.A("normal_component", (p, c, self.vimg[p], vimg(c)),
                        f"A_{_n(c)}{_n(p)}^n",
                        note=f"A_{_n(c)}{_n(p)}^n = V_{_n(c)}{_n(p)}²/R_{_n(c)}{_n(p)}, "
                             f"directed from {_n(c)} toward {_n(p)}.")
            tip = self.A("translate", (self.aimg[p], an), f"{aimg(c)}:n{_n(p)}",
                         note=f"Lay off A_{_n(c)}{_n(p)}^n from the image of {_n(p)}.")
            la = self.A("perpendicular", (line_a, tip), f"⊥{_n(c)}{_n(p)}:a",
                        note=f"Through its tip draw a line perpendicular to {_n(c)}{_n(p)}: "
                             f"the direction of A_{_n(c)}{_n(p)}^t.")
            pc, cc = _n(p), _n(c)
            return lv, la, (Term(f"V_{pc}"), Term(f"V_{cc}{pc}", U, K)), \
                (Term(f"A_{pc}"), Term(f"A_{cc}{pc}^n"), Term(f"A_{cc}{pc}^t", U, K))
        if kind == "roll":
            _, lid, key = motion
            r = self.rolling(key)
            cp, n = r.contact_label, r.contact_name
            vj, _ = self.coincident(r.on, cp)
            line = self.posture_line(cp, c, self.v)
            lv = self.V("perpendicular", (line, vj), f"⊥{_n(c)}{n}:v",
                        note=f"Link {lid} turns about the contact point {n} for now: through "
                             f"the image of {n} draw a line perpendicular to {_n(c)}{n}.")
            _, ac = self.contact_images(r)
            line_a = self.posture_line(cp, c, self.a)
            an = self.A("normal_component", (cp, c, vj, vimg(c)), f"A_{_n(c)}{n}^n",
                        note=f"A_{_n(c)}{n}^n = V²/R toward {n}.")
            tip = self.A("translate", (ac, an), f"{aimg(c)}:n{n}", note="Lay it off.")
            la = self.A("perpendicular", (line_a, tip), f"⊥{_n(c)}{n}:a",
                        note=f"Through its tip draw a line perpendicular to {_n(c)}{n}.")
            cc = _n(c)
            return lv, la, (Term(f"V_{n}"), Term(f"V_{cc}{n}", U, K)), \
                (Term(f"A_{n}"), Term(f"A_{cc}{n}^n"), Term(f"A_{cc}{n}^t", U, K))
        if kind == "slot_pin":
            return self.slot_pin_lines(motion, c)
        _, lid, k, line = motion
        vk, ak = self.coincident(k, c)
        lv = self.V("parallel", (line, vk), f"∥{_n(c)}/{k}:v",
                    note=f"Through the image of {_n(c)}{k} draw a line parallel to the slide: "
                         f"the apparent velocity V_{_n(c)}/{k}.")
        if k == FRAME:
            tip = ak
        else:
            cor = self.A("coriolis", (self.omega[k], vimg(c), vk), f"A_{_n(c)}/{k}^c",
                         note=f"The Coriolis component 2ω{k} × V_{_n(c)}/{k}.")
            tip = self.A("translate", (ak, cor), f"{aimg(c)}:c{k}", note="Lay it off.")
        la = self.A("parallel", (line, tip), f"∥{_n(c)}/{k}:a",
                    note="Through its tip draw a line parallel to the slide: the apparent "
                         "tangential acceleration.")
        cc = _n(c)
        return lv, la, (Term(f"V_{cc}{k}"), Term(f"V_{cc}/{k}", U, K)), \
            (Term(f"A_{cc}{k}"), Term(f"A_{cc}/{k}^c"), Term(f"A_{cc}/{k}^t", U, K))

    def slot_pin_lines(self, motion: tuple[str, ...],
                       c: str) -> tuple[str, str, tuple[Term, ...], tuple[Term, ...]]:
        """Lines of point C of a link L that carries a straight slot with a placed pin P.

        ``V_P = V_P@L + V_P/L`` with ``V_P/L`` along the slot, and C on L:
        ``V_C = V_P + ω_L × R_CP − V_P/L`` — through the image of P moved by
        ``ω_L × R_CP``, a line parallel to the slot.  Likewise
        ``A_C = A_P + α_L × R_CP − ω_L² R_CP − 2ω_L × V_P/L − A_P/L^t``
        (Eq. 4.15, the slot straight: no apparent normal).  The cam's center
        of curvature K in the translating flat face's slot (Sec. 4.7).
        """
        _, lid, key, line = motion
        s = next(t for t in self.mech.slots if t.key == key)
        p, pc, cc = s.point, _n(s.point), _n(c)
        if lid not in self.omega or lid not in self.alpha or p not in self.vimg \
                or p not in self.aimg:
            raise _NotYet(c)
        base_v = self.V("velocity_difference", (self.vimg[p], self.omega[lid], p, c),
                        f"{vimg(c)}:{pc}/{lid}",
                        note=f"From the image of {pc} lay off ω{lid} × R_{cc}{pc}.")
        lv = self.V("parallel", (line, base_v), f"∥{cc}/{key}:v",
                    note=f"Through its tip draw a line parallel to the slot: the apparent "
                         f"velocity V_{pc}/{lid}.")
        base_a = self.A("acceleration_difference",
                        (self.aimg[p], self.omega[lid], self.alpha[lid], p, c),
                        f"{aimg(c)}:{pc}/{lid}",
                        note=f"From the acceleration image of {pc} lay off α{lid} × R_{cc}{pc} "
                             f"− ω{lid}² R_{cc}{pc}.")
        cor = self.A("coriolis", (self.omega[lid], vimg(c), base_v), f"A_{pc}/{lid}^c:{cc}",
                     note=f"The Coriolis component −2ω{lid} × V_{pc}/{lid}.")
        tip = self.A("translate", (base_a, cor), f"{aimg(c)}:c{key}", note="Lay it off.")
        la = self.A("parallel", (line, tip), f"∥{cc}/{key}:a",
                    note="Through its tip draw a line parallel to the slot: the apparent "
                         "tangential acceleration.")
        return lv, la, (Term(f"V_{pc}"), Term(f"V_{cc}{pc}"), Term(f"V_{pc}/{lid}", U, K)), \
            (Term(f"A_{pc}"), Term(f"A_{cc}{pc}"), Term(f"A_{pc}/{lid}^c"),
             Term(f"A_{pc}/{lid}^t", U, K))

    def ev_dyad(self, c: str, ma: tuple[str, ...], mb: tuple[str, ...]) -> None:
        lv1, la1, tv1, ta1 = self.motion_lines(ma, c)
        # the second locus needs the first's images only for the velocity, so build velocity
        # lines of both before meeting; acceleration lines use v(C) once it exists.
        lv2, la2, tv2, ta2 = self.motion_lines(mb, c)
        eqv = VectorEquation(tv1, tv2, case=3)
        self.vimg[c] = self.V("meet", (lv1, lv2), vimg(c), role=Role.RESULT, equation=eqv,
                              note=f"The two lines meet at the image of {c} (case 3).")
        for m in (ma, mb):
            if m[0] == "roll":
                self.ensure_omega(self.rolling(m[2]), via=c)
        self.aimg[c] = self.A("meet", (la1, la2), aimg(c), role=Role.RESULT,
                              equation=VectorEquation(ta1, ta2, case=3),
                              note=f"The two lines meet at the acceleration image of {c} "
                                   "(case 3).")

    def ev_pin_in_slot(self, s: Slot, lid: str, p: str) -> None:
        x, k = s.point, s.on
        lv1, la1, tv1, ta1 = self.motion_lines(("rot", lid, p), x)
        vk, ak = self.coincident(k, x)
        # velocity: the tangent through v(X@k)
        key = s.key
        is_line = s.is_line
        if is_line:
            lv2 = self.V("parallel", (f"{key}:line", vk), f"∥{key}:v",
                         note=f"Through the image of {x}{k} draw a line along the slot: "
                              f"V_{x}/{k}.")
        else:
            rv = self.posture_line(f"{key}:O", x, self.v)
            lv2 = self.V("perpendicular", (rv, vk), f"∥{key}:v",
                         note=f"Through the image of {x}{k} draw the slot's tangent: V_{x}/{k}.")
        self.vimg[x] = self.V("meet", (lv1, lv2), vimg(x), role=Role.RESULT,
                              equation=VectorEquation(
                                  tv1, (Term(f"V_{x}{k}"), Term(f"V_{x}/{k}", U, K)), case=3),
                              note=f"They meet at the image of {x} (case 3).")
        tip = ak
        if k != FRAME:
            cor = self.A("coriolis", (self.omega[k], vimg(x), vk), f"A_{x}/{k}^c",
                         note=f"The Coriolis component 2ω{k} × V_{x}/{k}.")
            tip = self.A("translate", (tip, cor), f"{aimg(x)}:c", note="Lay it off.")
        if not is_line:
            an = self.A("apparent_normal", (x, f"{key}:O", vimg(x), vk), f"A_{x}/{k}^n",
                        note=f"The apparent normal component V_{x}/{k}²/ρ toward the slot's "
                             "center.")
            tip = self.A("translate", (tip, an), f"{aimg(x)}:n/{k}", note="Lay it off.")
        if is_line:
            la2 = self.A("parallel", (f"{key}:line", tip), f"∥{key}:a",
                         note="Through its tip draw a line along the slot: A^t apparent.")
        else:
            ra = self.posture_line(f"{key}:O", x, self.a)
            la2 = self.A("perpendicular", (ra, tip), f"∥{key}:a",
                         note="Through its tip draw the slot's tangent: A^t apparent.")
        self.aimg[x] = self.A("meet", (la1, la2), aimg(x), role=Role.RESULT,
                              equation=VectorEquation(
                                  ta1, (Term(f"A_{x}{k}"), Term(f"A_{x}/{k}^c"),
                                        Term(f"A_{x}/{k}^n"), Term(f"A_{x}/{k}^t", U, K)),
                                  case=3),
                              note=f"They meet at the acceleration image of {x} (case 3).")

    def ev_relative(self, s: Slider | Slot, lid: str, p: str, x: str) -> None:
        """A link turning about P whose path passes through the known point X."""
        key = s.key
        is_line = getattr(s, "p0", None) is not None
        vx_i, ax_i = vimg(f"{x}@{lid}"), aimg(f"{x}@{lid}")
        line = self.posture_line(p, x, self.v)
        lv1 = self.V("perpendicular", (line, self.vimg[p]), f"⊥{_n(x)}{_n(p)}:v",
                     note=f"Through {_n(p).lower()} draw a line perpendicular to "
                          f"{_n(x)}{_n(p)}: V_{_n(x)}{lid} − V_{_n(p)} lies on it.")
        if is_line:
            lv2 = self.V("parallel", (f"{key}:line", self.vimg[x]), f"∥{key}:v",
                         note=f"Through the image of {_n(x)} draw a line along the path: "
                              f"V_{_n(x)}/{lid}.")
        else:
            rv = self.posture_line(f"{key}:O", x, self.v)
            lv2 = self.V("perpendicular", (rv, self.vimg[x]), f"∥{key}:v",
                         note=f"Through the image of {_n(x)} draw the path's tangent.")
        self.V("meet", (lv1, lv2), vx_i, role=Role.RESULT,
               equation=VectorEquation(
                   (Term(f"V_{_n(p)}"), Term(f"V_{_n(x)}{lid}{_n(p)}", U, K)),
                   (Term(f"V_{_n(x)}"), Term(f"V_{_n(x)}/{lid}", U, K, -1)), case=3),
               note=f"They meet at the image of {_n(x)}{lid}, the point of link {lid} at "
                    f"{_n(x)} (case 3).")
        w, al = f"ω{lid}", f"α{lid}"
        self.V("angular_rate", (p, x, self.vimg[p], vx_i), w, role=Role.RESULT,
               note=f"ω{lid} from V_{_n(x)}{lid}{_n(p)}/R_{_n(x)}{_n(p)}.")
        self.omega[lid] = w
        # accelerations: A_X = A_X@i + 2ω_i × V_rel + A_rel^n + A_rel^t
        line_a = self.posture_line(p, x, self.a)
        an = self.A("normal_component", (p, x, self.vimg[p], vx_i), f"A_{_n(x)}{lid}{_n(p)}^n",
                    note=f"A_{_n(x)}{lid}{_n(p)}^n = ω{lid}² R toward {_n(p)}.")
        tip1 = self.A("translate", (self.aimg[p], an), f"{ax_i}:n", note="Lay it off.")
        la1 = self.A("perpendicular", (line_a, tip1), f"⊥{_n(x)}{_n(p)}:a",
                     note=f"Through its tip draw a line perpendicular to {_n(x)}{_n(p)}.")
        cor = self.A("coriolis", (w, self.vimg[x], vx_i), f"A_{_n(x)}/{lid}^c",
                     note=f"The Coriolis component 2ω{lid} × V_{_n(x)}/{lid}.")
        tip2 = self.A("subtract", (self.aimg[x], cor), f"{ax_i}:c",
                      note="Subtract it from the image of the known point.")
        if is_line:
            la2 = self.A("parallel", (f"{key}:line", tip2), f"∥{key}:a",
                         note="Through its tip draw a line along the path.")
        else:
            apn = self.A("apparent_normal", (x, f"{key}:O", self.vimg[x], vx_i),
                         f"A_{_n(x)}/{lid}^n",
                         note="The apparent normal component V_rel²/ρ toward the path's center.")
            tip2 = self.A("subtract", (tip2, apn), f"{ax_i}:cn", note="Subtract it too.")
            ra = self.posture_line(f"{key}:O", x, self.a)
            la2 = self.A("perpendicular", (ra, tip2), f"∥{key}:a",
                         note="Through its tip draw the path's tangent.")
        self.A("meet", (la1, la2), ax_i, role=Role.RESULT,
               equation=VectorEquation(
                   (Term(f"A_{_n(p)}"), Term(f"A_{_n(x)}{lid}{_n(p)}^n"),
                    Term(f"A_{_n(x)}{lid}{_n(p)}^t", U, K)),
                   (Term(f"A_{_n(x)}"), Term(f"A_{_n(x)}/{lid}^c", sign=-1),
                    Term(f"A_{_n(x)}/{lid}^t", U, K, -1)), case=3),
               note=f"They meet at the acceleration image of {_n(x)}{lid} (case 3).")
        self.A("angular_rate", (p, x, self.aimg[p], ax_i), al, role=Role.RESULT,
               note=f"α{lid} = A^t/R, its sense from the image.")
        self.alpha[lid] = al


def _event_text(ev: tuple[object, ...]) -> str:
    """A posture event in words: its kind and the names in it (links, points, keys)."""
    parts = [str(getattr(x, "key", x)) for x in ev[1:]
             if isinstance(x, str) or hasattr(x, "key")]
    return " ".join([str(ev[0]), *parts])


class _NotYet(Exception):
    """A polygon step whose rates are not known yet (it waits for them)."""


def build_polygons(mech: Mechanism, pc: PostureConstruction) -> Polygons:
    """Build the velocity and acceleration constructions that follow the posture's groups.

    Parameters
    ----------
    mech : Mechanism
    pc : PostureConstruction
        From :func:`graphkin.kinematics.posture.build_posture`.

    Returns
    -------
    Polygons
    """
    p = _Poly(mech, pc)
    p.run()
    return Polygons(p.v, p.a, p.rate_inputs, p.vimg, p.aimg)
