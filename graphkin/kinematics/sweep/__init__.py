"""Whole cycles at once: the recorded constructions evaluated on arrays of drive values.

A sweep runs the *same* constructions as :func:`graphkin.solve` -- the posture
groups of Sec. 2.8 and the velocity and acceleration polygons of Secs. 3.4-4.6
-- once, on whole arrays of drive values (shape ``(N,)``), with no Python
loop over postures.  The constructions are built once at the file's posture,
where every two-way choice is named (``left``/``right`` of the directed line
of centers, ``behind``/``ahead`` along a line); the sweep keeps those names.

Branch continuity
-----------------
Each posture continues the assembly of the one before because the *named*
branch is kept: the side of C relative to the directed line from the first
circle's center to the second's can only change where the two intersections
coincide (the arcs are tangent: the linkage is at a dead center, its
transmission angle 0° or 180°) or where the two centers coincide.  Away from
those postures, keeping the name is keeping continuity.  Where the branches
meet the sweep reports it (:attr:`Sweep.singular`): at the ends of a range
where the linkage cannot be assembled, and at a change point, where the
branches touch without a gap and the sweep goes on with the same name.

Several drives
--------------
The first drive is swept; every other drive is held at its value in the
file (and its rates, if any, apply at every posture).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.9 (Grashof's law, Eq. 1.6), Sec. 1.10 (transmission angle, toggle and
dead-center postures), Sec. 2.8 (posture), Secs. 3.4-3.6 and 4.2-4.6
(polygons), Sec. 5.4 (several inputs).

Modules
-------
``engine``
    The constructions of one mechanism, built once, replayed on arrays.
``columns``
    The CSV columns of ``docs/formats/sweep-csv.md`` read from an evaluated block.
``run``
    :func:`sweep` itself: drive values, blocks, the :class:`Sweep`.
``drive_range``
    The drive range, a slider's travel, assembly boundaries by bisection.
``report``
    :class:`Sweep`: the result, its report lines and its CSV.
``singular``
    :class:`SingularPosture`: unassemblable ranges, dead centers, limits.
``extra_columns``
    Transmission angle, instant center and curvature columns.
``four_bar``
    :func:`fourbar`, Grashof's law (:func:`grashof`), :func:`transmission_angle`.
"""

from graphkin.kinematics.sweep.columns import (
    _assembled_of,
    _column_order,
    _columns,
    _columns_of_solution,
    _columns_slow,
    _concat_solutions,
    _full,
    _point_columns,
    _recipe,
    _solution_of_block,
    _valid_of,
    _xy_rows,
    wrap_degrees,
)
from graphkin.kinematics.sweep.drive_range import _assembles, _bisect, _drive_range, _travel
from graphkin.kinematics.sweep.engine import _ENGINES, _Block, _dyads, _Engine, _engine
from graphkin.kinematics.sweep.extra_columns import (
    _angle_at,
    _center_columns,
    _curvature_columns,
    _transmission_columns,
    _with_unit_rates,
)
from graphkin.kinematics.sweep.four_bar import (
    FourBar,
    Grashof,
    fourbar,
    grashof,
    transmission_angle,
)
from graphkin.kinematics.sweep.report import Sweep
from graphkin.kinematics.sweep.run import BLOCK, _blank, sweep
from graphkin.kinematics.sweep.singular import (
    SingularPosture,
    _change_points,
    _failing_labels,
    _fmt,
    _is_branch,
    _limits,
    _refine_analytic,
    _runs,
    _separations,
    _singular,
    _to_user,
)

__all__ = [
    "Sweep",
    "SingularPosture",
    "sweep",
    "wrap_degrees",
    "FourBar",
    "fourbar",
    "Grashof",
    "grashof",
    "transmission_angle",
]

# the private helpers stay importable from here, as when this was one module
_PRIVATE = (_assembled_of, _column_order, _columns, _columns_of_solution, _columns_slow,
            _concat_solutions, _full, _point_columns, _recipe, _solution_of_block, _valid_of,
            _xy_rows, _assembles, _bisect, _drive_range, _travel, _ENGINES, _Block, _dyads,
            _Engine, _engine, _angle_at, _center_columns, _curvature_columns,
            _transmission_columns, _with_unit_rates, BLOCK, _blank, _change_points,
            _failing_labels, _fmt, _is_branch, _limits, _refine_analytic, _runs, _separations,
            _singular, _to_user)
