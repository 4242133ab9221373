"""What graphkin reports: the JSON of ``docs/formats/json.md`` and the textbook-style text report.

One layer builds every report from the result objects, with one formatter
(:mod:`graphkin.text`) and one choice of units (:class:`OutputUnits`):

- :mod:`graphkin.output.solution`: the posture and its rates, and the
  whole report (:func:`solution_to_dict`, :func:`text_report`);
- :mod:`graphkin.output.centers`: the instant centers;
- :mod:`graphkin.output.curvature`: curvature of the links' motions and of
  the points' paths;
- :mod:`graphkin.output.sections`: the list of sections beyond the posture
  (where a new kind of result, such as forces, is added);
- :mod:`graphkin.output.units`: the units of the report (``--units``);
- :mod:`graphkin.output.csv`: the units of a sweep's CSV columns;
- :mod:`graphkin.output.vector`: the report of ``graphkin vector`` (``C = A + B``).

References
----------
Uicker, Pennock & Shigley, 5th ed.: results are stated as the book states them,
``θ3 = 20.92°``, ``ω3 = 25.38 rad/s ccw``, ``V_E = 27.8 ft/s ∠165.3°``.
"""

from __future__ import annotations

from graphkin.output.solution import finite, solution_to_dict, text_report
from graphkin.output.units import OutputUnits, parse_units
from graphkin.text import wrap_degrees

__all__ = ["solution_to_dict", "text_report", "wrap_degrees", "finite", "OutputUnits",
           "parse_units"]
