"""The velocity and inflection poles from two points' motion; the inflection circle (Sec. 4.15)."""

from __future__ import annotations

import numpy as np

from graphkin.construction import Role
from graphkin.kinematics.curvature.construction import _CurvatureBase

Array = np.ndarray


class _InflectionCircleSteps(_CurvatureBase):
    """The steps that find I and J from velocities and accelerations, and draw the circle."""

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
