"""The units of a sweep's CSV columns (``docs/formats/sweep-csv.md``); columns in other units.

The column names of ``docs/formats/sweep-csv.md`` stay as they are (``omega_3``, not
``omega_3 [rad/s]``) so that every reader of the CSV keeps working; the
units go in an optional second line (``graphkin sweep --units-row``), which
``pandas.read_csv(f, header=[0, 1])`` or a spreadsheet reads as a second
header line.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.11 (units).
"""

from __future__ import annotations

import re

import numpy as np

from graphkin.output.units import OutputUnits

__all__ = ["column_unit", "convert_columns"]

# column name -> the quantity it measures (the first pattern that matches)
_KINDS = (
    (r"angle_|transmission_", "angle"),
    (r"omega_", "omega"),
    (r"alpha_", "alpha"),
    (r"vx_|vy_", "velocity"),
    (r"ax_|ay_", "acceleration"),
    (r"dx_|dy_", "direction"),
    (r"x_|y_|jx_|jy_|gx_|gy_|cx_|cy_|rho_|inflection_diameter_", "length"),
    (r"torque_", "torque"),
    (r"force_|F_", "force"),
)


def _kind(name: str, slider_drive: bool) -> str | None:
    if name == "drive":
        return "length" if slider_drive else "angle"
    for pattern, kind in _KINDS:
        if re.match(pattern, name):
            return kind
    return None


def column_unit(name: str, units: OutputUnits, slider_drive: bool = False,
                force_unit: str = "N") -> str:
    """The unit of a sweep column: ``deg``, a length, velocity, ... or ``""`` (a direction).

    Forces (``torque_2``, ``force_4``, ``F_3-4``: ``graphkin sweep --torque``) stay
    in the file's force unit; a torque is that force times the report's length.

    Examples
    --------
    >>> u = OutputUnits.of("in")
    >>> [column_unit(n, u) for n in ("drive", "omega_3", "vx_E", "ax_E", "x_I13", "dx_I24")]
    ['deg', 'rad/s', 'in/s', 'in/s^2', 'in', '']
    >>> column_unit("torque_2", OutputUnits.of("in", "ft"), force_unit="lbf")
    'lbf*ft'
    """
    kind = _kind(name, slider_drive)
    if kind == "angle":
        return "deg"
    if kind is None or kind == "direction":
        return ""
    if kind == "force":
        return force_unit
    if kind == "torque":
        return f"{force_unit}*{units.length}"
    return str(getattr(units, kind))


def convert_columns(columns: dict[str, np.ndarray], units: OutputUnits,
                    slider_drive: bool = False) -> dict[str, np.ndarray]:
    """The columns in ``units`` (the internal ones are the file's length unit, s and rad/s).

    Raises
    ------
    KeyError
        A column whose quantity is not known, when units other than the
        file's are asked for (it would be left in the wrong unit).

    Examples
    --------
    >>> u = OutputUnits.of("in", "ft")
    >>> convert_columns({"x_B": np.array([12.0]), "angle_2": np.array([30.0])}, u)
    {'x_B': array([1.]), 'angle_2': array([30.])}
    """
    out: dict[str, np.ndarray] = {}
    for name, col in columns.items():
        kind = _kind(name, slider_drive)
        if kind is None:
            raise KeyError(name)
        # forces stay in the file's force unit; a torque (force x length) follows the length
        k = (1.0 if kind in ("angle", "direction", "force") else float(units.k_length)
             if kind == "torque" else float(getattr(units, f"k_{kind}")))
        out[name] = col if k == 1.0 else col * k
    return out
