"""Static and dynamic force analysis by the graphic method (Ch. 11-12).

Free-body diagrams, two- and three-force members, concurrency points, force
polygons and superposition, recorded as named construction steps; checked
against the matrix method (:mod:`graphkin.forces.analytic`).  Reads the
kinematic solution; nothing below it imports this package.

References
----------
Uicker, Pennock & Shigley, 5th ed., Ch. 11-12.
"""

from __future__ import annotations

from graphkin.forces.analytic import power_balance, solve_matrix
from graphkin.forces.graphic import NotDecomposable, Partial
from graphkin.forces.joints import Joint, joints_of
from graphkin.forces.solve import ForceSolution, InertiaForce, solve_forces

__all__ = ["solve_forces", "ForceSolution", "InertiaForce", "Joint", "joints_of", "Partial",
           "NotDecomposable", "solve_matrix", "power_balance"]
