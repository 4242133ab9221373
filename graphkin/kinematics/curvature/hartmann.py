"""The Hartmann construction of a conjugate point from the pole velocity (Sec. 4.13, Fig. 4.25)."""

from __future__ import annotations

import numpy as np

from graphkin.construction import Role
from graphkin.kinematics.curvature.construction import _CurvatureBase

Array = np.ndarray


class _HartmannSteps(_CurvatureBase):
    """The steps of the Hartmann construction."""

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
