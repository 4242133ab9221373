"""Cognate linkages by the Roberts-Chebyshev theorem, constructed as Cayley's diagram (Sec. 9.10).

A four-bar O_A A B O_B whose coupler point P stands to A and B as in the
triangle ABP has two cognates tracing the same coupler curve.  Cayley's
diagram finds them with parallelograms and similar triangles:

* O_C stands to O_A, O_B as P stands to A, B (the triangle of the pivots is
  similar to the coupler triangle);
* the parallelogram O_A A P A2 gives the second cognate's crank O_A A2, and
  B2 stands to A2, P as P to A, B: its coupler A2 B2 P, its rocker O_C B2;
* the parallelogram O_B B P B3 gives the third cognate's crank O_B B3, and
  A3 stands to B3, P as P to B, A: its coupler B3 A3 P, its rocker O_C A3.

Every link keeps its length (|A2 − O_A| = |AP|, |B2 − A2| = |r| |O_A A|,
|B2 − O_C| = |r| |O_B B| with r = (P − A)/(B − A)), so each cognate is a
four-bar through P; the tests hold all three to one coupler curve, solved
by graphkin.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.10 (Figs. 9.37-9.38).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.synthesis.postures import DIAGRAM
from graphkin.text import toml_string

__all__ = ["Cognates", "cayley"]

_NAMES = ("O_A", "A", "B", "O_B", "P")


@dataclass(frozen=True)
class Cognates:
    """The three cognate four-bars (pivots and pins, complex) and Cayley's construction."""

    construction: Construction
    points: dict[str, complex]

    def linkages(self) -> dict[str, tuple[str, str, str, str]]:
        """Each cognate as (fixed pivot, crank pin, rocker pin, fixed pivot) labels."""
        return {"1": ("O_A", "A", "B", "O_B"), "2": ("O_A", "A2", "B2", "O_C"),
                "3": ("O_B", "B3", "A3", "O_C")}

    def mechanism_toml(self, which: str, units: str = "mm", title: str = "") -> str:
        """The mechanism file of cognate ``which`` ("1", "2" or "3") with its coupler point P.

        Assembled where Cayley's diagram puts it (assembly hints on every pin).
        """
        o1, p1, p2, o2 = self.linkages()[which]
        z = self.points
        rot = np.exp(-1j * np.angle(z[p2] - z[p1]))
        p_local = (z["P"] - z[p1]) * rot

        def xy(c: complex) -> str:
            return f"[{float(c.real)!r}, {float(c.imag)!r}]"

        drive = math.degrees(float(np.angle(z[p1] - z[o1])))
        # pin names of their own per cognate (A_1 would read as an acceleration label)
        n1, n2 = f"{p1}c{which}", f"{p2}c{which}"
        return "\n".join([
            f'title = {toml_string(title or f"Cognate {which} (Roberts-Chebyshev)")}',
            f'units = {{ length = "{units}" }}', "",
            "[links.1]", f"{o1} = {xy(z[o1])}", f"{o2} = {xy(z[o2])}", "",
            "[links.2]", f"{o1} = [0.0, 0.0]", f"{n1} = [{abs(z[p1] - z[o1])!r}, 0.0]", "",
            "[links.3]", f"{n1} = [0.0, 0.0]", f"{n2} = [{abs(z[p2] - z[p1])!r}, 0.0]",
            f"P = {xy(p_local)}", "",
            "[links.4]", f"{o2} = [0.0, 0.0]", f"{n2} = [{abs(z[p2] - z[o2])!r}, 0.0]", "",
            "[drive]", "link = 2", f"angle = {drive!r}", "",
            "[assembly]", f"{n2} = {xy(z[p2])}", f"P = {xy(z['P'])}", ""])


def cayley(o_a: complex, a: complex, b: complex, o_b: complex, p: complex) -> Cognates:
    """Cayley's diagram of the four-bar O_A A B O_B with coupler point P (Sec. 9.10).

    Parameters
    ----------
    o_a, a, b, o_b, p : complex
        The fixed pivots, the pins and the coupler point in one posture.
    """
    cx = Construction(title="Cayley's diagram (Roberts-Chebyshev cognates)")
    given = dict(zip(_NAMES, (o_a, a, b, o_b, p)))
    for name, z in given.items():
        cx.add("point", (), (name,), xy=(float(z.real), float(z.imag)), role=Role.GIVEN,
               diagram=DIAGRAM, note=f"{name}: of the given four-bar.")
    loc = {"A": (0.0, 0.0), "B": (1.0, 0.0)}
    rr = (p - a) / (b - a)
    loc["P"] = (float(rr.real), float(rr.imag))
    cx.add("similar", ("O_A", "O_B"), ("O_C",), local_a=loc["A"], local_b=loc["B"],
           local_p=loc["P"], role=Role.RESULT, diagram=DIAGRAM,
           note="O_C: the third fixed pivot, the triangle O_A O_B O_C similar to A B P.")
    cx.add("parallelogram", ("A", "O_A", "P"), ("A2",), role=Role.RESULT, diagram=DIAGRAM,
           note="A2: the parallelogram O_A A P A2 (the second cognate's crank O_A A2).")
    cx.add("similar", ("A2", "P"), ("B2",), local_a=loc["A"], local_b=loc["B"],
           local_p=loc["P"], role=Role.RESULT, diagram=DIAGRAM,
           note="B2: the triangle A2 P B2 similar to A B P (the second cognate's coupler).")
    cx.add("parallelogram", ("B", "O_B", "P"), ("B3",), role=Role.RESULT, diagram=DIAGRAM,
           note="B3: the parallelogram O_B B P B3 (the third cognate's crank O_B B3).")
    cx.add("similar", ("B3", "P"), ("A3",), local_a=loc["B"], local_b=loc["A"],
           local_p=loc["P"], role=Role.RESULT, diagram=DIAGRAM,
           note="A3: the triangle B3 P A3 similar to B A P (the third cognate's coupler).")
    for lab, (p1, p2) in {"l_O_AA2": ("O_A", "A2"), "l_A2B2": ("A2", "B2"),
                          "l_B2O_C": ("B2", "O_C"), "l_O_BB3": ("O_B", "B3"),
                          "l_B3A3": ("B3", "A3"), "l_A3O_C": ("A3", "O_C")}.items():
        cx.add("join", (p1, p2), (lab,), diagram=DIAGRAM, note=f"the link {p1}{p2}.")
    ev = cx.evaluate()
    pts = {k: complex(v[0] / v[2], v[1] / v[2]) for k, v in ev.values.items()
           if np.shape(v) == (3,) and cx.step_of(k).kind == "point"}
    return Cognates(cx, pts)
