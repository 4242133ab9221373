"""Bobillier's construction of the inflection pole and of conjugates (Sec. 4.13, Fig. 4.29)."""

from __future__ import annotations

import numpy as np

from graphkin.construction import Role
from graphkin.kinematics.curvature.construction import _CurvatureBase

Array = np.ndarray


class _BobillierSteps(_CurvatureBase):
    """The steps of Bobillier's construction (Examples 4.13, 4.14, 4.16)."""

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
