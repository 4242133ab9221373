"""The book's graphic constructions of the parabolic, harmonic and cycloidal diagrams.

Fig. 6.5b (parabolic motion): in the rectangle of the first half (β/2 by
L/2), the abscissa and the far ordinate are divided into the same number of
equal parts; point k of the parabola is where the ordinate through
abscissa division k meets the line from the origin O to division k of the
far ordinate.  The second half is the same from the top corner B.

Fig. 6.6 (simple harmonic motion): a semicircle on the lift L as diameter
and the abscissa β are divided into the same number of equal parts; each
point of the semicircle is projected horizontally onto the ordinate through
the division of the same number.

Fig. 6.7 (cycloidal motion): a circle of radius L/2π about the origin O is
divided into equal parts; each point is projected horizontally onto the
ordinate, and from there parallel to the diagonal OB (B = (β, L)) onto the
ordinate through the division of the same number.

Both are recorded steps (:class:`~graphkin.construction.Construction`),
evaluated on the array of division numbers at once; the points land on
Eqs. (6.12a) and (6.13a) (tested).  The abscissa is drawn ``width`` long for β.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 6.3, Figs. 6.5b, 6.6 and 6.7.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.protocol import Evaluation
from graphkin.construction.step import Role

__all__ = ["DiagramConstruction", "harmonic_diagram", "cycloidal_diagram", "parabolic_diagram"]

Array = np.ndarray


@dataclass
class DiagramConstruction:
    """A displacement diagram's recorded construction and its divisions.

    Attributes
    ----------
    construction : Construction
    divisions : int
        The number of equal parts of the circle (and of the abscissa).
    lift, width : float
        L, and the drawn length of the abscissa for β.
    """

    construction: Construction
    divisions: int
    lift: float
    width: float

    def given(self) -> dict[str, Array]:
        """The inputs: for division k = 0..n, its angle on the circle and its abscissa."""
        k = np.arange(self.divisions + 1, dtype=float)
        if self.construction.title.startswith("parabolic"):
            t = k / self.divisions
            half = self.width / 2
            return {"x": half * t, "q": self.lift / 2 * t,
                    "x2": self.width - half * t, "q2": self.lift - self.lift / 2 * t}
        step = math.pi if self.construction.title.startswith("harmonic") else 2 * math.pi
        sign = 1.0 if self.construction.title.startswith("harmonic") else -1.0
        return {"angle": sign * step * k / self.divisions, "x": self.width * k / self.divisions}

    def evaluate(self) -> Evaluation:
        """Every step at every division."""
        return self.construction.evaluate(self.given(), strict=False)

    def points(self) -> Array:
        """The diagram's points ``(x, y)``, one per division, shape ``(n + 1, 2)``.

        For the parabolic construction, both halves: ``(2n + 2, 2)``, in order of x.
        """
        ev = self.evaluate()
        d = ev["D"]
        pts = d[..., :2] / d[..., 2:3]
        if "D2" in ev:
            e = ev["D2"]
            pts = np.concatenate([pts, (e[..., :2] / e[..., 2:3])[::-1]])
        return pts


def harmonic_diagram(lift: float, width: float, divisions: int = 6) -> DiagramConstruction:
    """Fig. 6.6: the simple harmonic rise drawn from a semicircle on the lift.

    Examples
    --------
    >>> d = harmonic_diagram(2.0, 6.0, divisions=6)
    >>> [round(float(y), 9) for y in d.points()[:, 1]]     # Eq. (6.12a): (L/2)(1 − cos πk/6)
    [0.0, 0.133974596, 0.5, 1.0, 1.5, 1.866025404, 2.0]
    """
    cx = Construction(title="harmonic displacement diagram (Fig. 6.6)")
    r = lift / 2
    cx.add("point", (), ("O",), xy=(0.0, 0.0), role=Role.GIVEN, note="the origin O")
    cx.add("point", (), ("M",), xy=(-r, r), role=Role.GIVEN,
           note="the semicircle's center, on the lift L as diameter, left of the ordinate")
    cx.add("circle", ("M",), ("k",), radius=r, note="the semicircle of diameter L")
    cx.add("input", (), ("angle",), name="angle", role=Role.GIVEN,
           note="the semicircle divided into equal parts: division k at πk/n")
    cx.add("input", (), ("x",), name="x", role=Role.GIVEN,
           note="the abscissa β divided into the same number of parts")
    cx.add("rigid", ("M", "angle"), ("P",), local_p=(0.0, 0.0), local_q=(0.0, -r),
           note="point k of the semicircle, numbered from the bottom")
    cx.add("scalar", (), ("zero",), value=0.0, note="horizontal")
    cx.add("line_at_angle", ("P", "zero"), ("h",), note="projected horizontally")
    cx.add("coordinate_line", ("x",), ("v",), axis="x", note="the ordinate through division k")
    cx.add("meet", ("h", "v"), ("D",), role=Role.RESULT, note="point k of the diagram")
    return DiagramConstruction(cx, divisions, lift, width)


def cycloidal_diagram(lift: float, width: float, divisions: int = 6) -> DiagramConstruction:
    """Fig. 6.7: the cycloidal rise drawn from a circle of radius L/2π about O.

    Examples
    --------
    >>> d = cycloidal_diagram(2.0, 6.0, divisions=4)
    >>> [round(float(y), 9) for y in d.points()[:, 1]]     # Eq. (6.13a): L(k/4 − sin(πk/2)/2π)
    [0.0, 0.181690114, 1.0, 1.818309886, 2.0]
    """
    cx = Construction(title="cycloidal displacement diagram (Fig. 6.7)")
    r = lift / (2 * math.pi)
    cx.add("point", (), ("O",), xy=(0.0, 0.0), role=Role.GIVEN, note="the origin O")
    cx.add("point", (), ("B",), xy=(width, lift), role=Role.GIVEN,
           note="B: the end of the rise (β, L)")
    cx.add("join", ("O", "B"), ("OB",), note="the diagonal OB")
    cx.add("circle", ("O",), ("k",), radius=r, note="the circle of radius L/2π about O")
    cx.add("input", (), ("angle",), name="angle", role=Role.GIVEN,
           note="the circle divided into equal parts, numbered clockwise")
    cx.add("input", (), ("x",), name="x", role=Role.GIVEN,
           note="the abscissa β divided into the same number of parts")
    cx.add("rigid", ("O", "angle"), ("P",), local_p=(0.0, 0.0), local_q=(r, 0.0),
           note="point k of the circle")
    cx.add("coordinate_line", ("x",), ("v",), axis="x", note="the ordinate through division k")
    cx.add("scalar", (), ("zero",), value=0.0, note="the ordinate's abscissa")
    cx.add("coordinate_line", ("zero",), ("axis",), axis="x", note="the ordinate through O")
    cx.add("scalar", (), ("flat",), value=0.0, note="horizontal")
    cx.add("line_at_angle", ("P", "flat"), ("h",), note="projected horizontally")
    cx.add("meet", ("h", "axis"), ("Q",), note="onto the ordinate")
    cx.add("parallel", ("OB", "Q"), ("g",), note="from the ordinate, parallel to OB")
    cx.add("meet", ("g", "v"), ("D",), role=Role.RESULT, note="point k of the diagram")
    return DiagramConstruction(cx, divisions, lift, width)


def parabolic_diagram(lift: float, width: float, divisions: int = 4) -> DiagramConstruction:
    """Fig. 6.5b: the parabolic rise (Eqs. 6.5a, 6.6a) drawn in two rectangles.

    Examples
    --------
    >>> d = parabolic_diagram(2.0, 4.0, divisions=2)
    >>> [round(float(y), 12) for y in d.points()[:, 1]]    # 2L(θ/β)², L(1 − 2(1 − θ/β)²)
    [0.0, 0.25, 1.0, 1.0, 1.75, 2.0]
    """
    cx = Construction(title="parabolic displacement diagram (Fig. 6.5b)")
    cx.add("point", (), ("O",), xy=(0.0, 0.0), role=Role.GIVEN, note="the origin O")
    cx.add("point", (), ("B",), xy=(width, lift), role=Role.GIVEN, note="B: the end of the rise")
    cx.add("scalar", (), ("mid",), value=width / 2, note="the midpoint of β, where the "
           "parabolas meet")
    cx.add("coordinate_line", ("mid",), ("m",), axis="x", note="the far ordinate of each "
           "rectangle")
    for tag, corner in (("", "O"), ("2", "B")):
        cx.add("input", (), (f"x{tag}",), name=f"x{tag}", role=Role.GIVEN,
               note="the abscissa of the half divided into equal parts")
        cx.add("input", (), (f"q{tag}",), name=f"q{tag}", role=Role.GIVEN,
               note="the far ordinate divided into the same number of parts")
        cx.add("coordinate_line", (f"q{tag}",), (f"hq{tag}",), axis="y",
               note="the height of division k on the far ordinate")
        cx.add("meet", ("m", f"hq{tag}"), (f"Q{tag}",), note="division k of the far ordinate")
        cx.add("join", (corner, f"Q{tag}"), (f"r{tag}",),
               note=f"the line from {corner} to division k of the far ordinate")
        cx.add("coordinate_line", (f"x{tag}",), (f"v{tag}",), axis="x",
               note="the ordinate through abscissa division k")
        cx.add("meet", (f"r{tag}", f"v{tag}"), (f"D{tag}",), role=Role.RESULT,
               note="point k of the parabola")
    return DiagramConstruction(cx, divisions, lift, width)
