"""graphkin: the graphic constructions of planar mechanism kinematics, exact and drawn.

The polygon methods of Uicker, Pennock & Shigley, *Theory of Machines and
Mechanisms* (5th ed.), Chapters 2-5: posture by the four cases of the planar
vector equation, velocity and acceleration polygons and images, instant
centers, curvature.  Importing graphkin does not import matplotlib.

Examples
--------
>>> import graphkin
>>> mech = graphkin.examples.fourbar()
>>> sol = mech.solve()
>>> round(float(sol.angle("3")), 2)  # θ3 in degrees; Example 3.1: the book gives 20.92°
20.92
"""

from graphkin import examples
from graphkin.construction import Construction, Step
from graphkin.errors import (
    AssemblyError,
    ConstructionError,
    DegenerateError,
    GraphkinError,
    IdealPointError,
    InputError,
    NoIntersectionError,
    ParallelDirectionsError,
)
from graphkin.kinematics.solution import LinkState, Solution
from graphkin.kinematics.solve import solve
from graphkin.kinematics.sweep.batch import Batch, batch
from graphkin.mechanisms import Mechanism, from_dict, load, loads
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__version__ = "0.1.0"  # the one source of the version (pyproject.toml reads it)

__all__ = [
    "examples",
    "load", "loads", "from_dict", "solve", "Mechanism", "Solution", "LinkState",
    "Construction", "Step", "Tolerance", "DEFAULT_TOL", "GraphkinError", "InputError",
    "ConstructionError", "NoIntersectionError", "ParallelDirectionsError", "DegenerateError",
    "IdealPointError", "AssemblyError", "batch", "Batch", "__version__", "live",
]


def live(mechanism: Mechanism | str) -> object:
    """The live page of a mechanism as a notebook widget (anywidget; ``graphkin[jupyter]``).

    Drag the crank or a pivot in the cell's output; ``widget.mechanism`` is
    the edited mechanism.  See :func:`graphkin.render.live_widget.live`.
    """
    from graphkin.render.live_widget import live as _live

    return _live(mechanism)
