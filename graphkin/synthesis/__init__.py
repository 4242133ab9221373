"""Graphical synthesis of linkages (Ch. 9): poles, pole triangles, Burmester curves.

Motion generation (body guidance) through two to five finitely separated
postures by the book's constructions, each recorded as named steps (P12, the
pole triangle, bisectors, circle points and center points), with the
complex-number synthesis of Sec. 9.12 as the independent check
(:mod:`graphkin.synthesis.analytic`); function generation by Chebyshev
spacing and Freudenstein's equation (Secs. 9.7, 9.11).  The result of a
synthesis is a mechanism file graphkin analyses as it is.

References
----------
Uicker, Pennock & Shigley, 5th ed., Ch. 9.

Examples
--------
Example 9.7: y = 1/x over 1 <= x <= 2 by Freudenstein's equation.

>>> from graphkin.synthesis import loads_spec, synthesize
>>> text = "[function]", 'expression = "1/x"', "range = [1, 2]"
>>> res = synthesize(loads_spec(chr(10).join(text)))
>>> [round(float(x), 3) for x in res.function.x]
[1.067, 1.5, 1.933]
>>> res.mechanism_toml().splitlines()[3:6]
['[links.1]', 'O2 = [0.0, 0.0]', 'O4 = [1.0, 0.0]']
"""

from __future__ import annotations

from graphkin.synthesis import analytic
from graphkin.synthesis.cognates import Cognates, cayley
from graphkin.synthesis.dwell import Dwell, dwell
from graphkin.synthesis.five import BurmesterPoint, burmester_points, five_construction
from graphkin.synthesis.four import Curves, burmester_construction, curves
from graphkin.synthesis.limits import CrankRocker, crank_rocker
from graphkin.synthesis.postures import Postures
from graphkin.synthesis.run import Result, synthesize
from graphkin.synthesis.spec import Spec, load_spec, loads_spec
from graphkin.synthesis.three import (
    center_from_circle_point,
    circle_point_from_center,
    pole_triangle,
    straight_line_locus,
)

__all__ = ["analytic", "Postures", "pole_triangle", "center_from_circle_point",
           "circle_point_from_center", "straight_line_locus", "burmester_construction",
           "curves", "Curves", "five_construction", "burmester_points", "BurmesterPoint",
           "synthesize", "Result", "Spec", "load_spec", "loads_spec", "cayley", "Cognates",
           "dwell", "Dwell", "crank_rocker", "CrankRocker"]
