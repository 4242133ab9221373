"""The Bresse circle and the center of acceleration Γ (Secs. 4.14-4.15, Eq. 4.48)."""

from __future__ import annotations

import numpy as np
from numpy.typing import ArrayLike

from graphkin.construction import Role
from graphkin.kinematics.curvature._vec import _xy
from graphkin.kinematics.curvature.construction import _CurvatureBase
from graphkin.kinematics.solution import perp

__all__ = ["bresse_pole"]

Array = np.ndarray


def bresse_pole(pole: ArrayLike, inflection_pole: ArrayLike, omega: ArrayLike,
                alpha: ArrayLike) -> Array:
    """The far end ``E`` of the Bresse circle's diameter through ``I``.

    The Bresse circle (the points with no tangential acceleration) has the
    diameter ``b = R_JI ω²/α`` (Eq. 4.48) along the centrode tangent:
    ``E = I + (ω²/α) k × R_JI``, on the negative side of ``T`` when ``α > 0``.
    NaN (no circle: it becomes the centrode normal) when ``α = 0``.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 4.15, Eq. 4.48, Fig. 4.34.

    Examples
    --------
    >>> bresse_pole([0, 0], [0, 2], 1.0, 0.5)
    array([-4.,  0.])
    """
    w, al = np.asarray(omega, dtype=float), np.asarray(alpha, dtype=float)
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        k = np.where(al == 0.0, np.nan, w**2 / np.where(al == 0.0, 1.0, al))
        out = _xy(pole) + k[..., None] * perp(_xy(inflection_pole) - _xy(pole))
    return np.where(np.isfinite(out), out, np.nan)


class _BresseSteps(_CurvatureBase):
    """The steps of the Bresse circle and of Γ by the four circles (Fig. 4.33)."""

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
