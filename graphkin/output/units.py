"""The units results are reported in: the file's by default, or those asked for (``--units``).

Inside graphkin lengths are in the mechanism file's length unit, angles in
radians and times in seconds (:mod:`graphkin.units`).  A report converts at
the last moment: positions and lengths, velocities, accelerations, angular
velocities and angular accelerations each get a unit and a factor.  The
default factors are exactly 1, so a report in the file's units is the
values themselves.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.11 (units): the book's examples
give dimensions in inches and answer in ft/s, or in mm and answer in m/s.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from graphkin.errors import InputError

__all__ = ["OutputUnits", "parse_units"]

# pint dimensionality -> the kind of quantity it measures
_KINDS = {
    "[length]": "length",
    "[length] / [time]": "velocity",
    "[length] / [time] ** 2": "acceleration",
    "1 / [time]": "omega",
    "1 / [time] ** 2": "alpha",
}
_INTERNAL = {"velocity": "{L}/s", "acceleration": "{L}/s^2", "length": "{L}",
             "omega": "rad/s", "alpha": "rad/s^2"}


@dataclass(frozen=True)
class OutputUnits:
    """The unit and the factor (internal value × factor = reported value) of each quantity.

    Examples
    --------
    >>> u = OutputUnits.of("in", "ft, ft/s, ft/s^2")
    >>> u.length, u.velocity, round(u.k_velocity, 12)
    ('ft', 'ft/s', 0.083333333333)
    >>> OutputUnits.of("mm").acceleration
    'mm/s^2'
    """

    length: str
    velocity: str
    acceleration: str
    omega: str = "rad/s"
    alpha: str = "rad/s^2"
    k_length: float = 1.0
    k_velocity: float = 1.0
    k_acceleration: float = 1.0
    k_omega: float = 1.0
    k_alpha: float = 1.0

    @classmethod
    def of(cls, length_unit: str, spec: str | None = None) -> OutputUnits:
        """The file's units (``length_unit``), changed by ``spec`` (see :func:`parse_units`)."""
        units: dict[str, Any] = {"length": length_unit, "velocity": f"{length_unit}/s",
                                 "acceleration": f"{length_unit}/s^2"}
        if spec:
            units.update(parse_units(spec, length_unit))
        return cls(**units)

    def json(self) -> dict[str, str]:
        """The ``units`` object of the JSON: docs/formats/json.md's keys, then one a quantity."""
        return {"length": self.length, "time": "s", "angle": "deg",
                "position": self.length, "velocity": self.velocity,
                "acceleration": self.acceleration, "omega": self.omega, "alpha": self.alpha}

    def text(self, kind: str) -> str:
        """The unit of ``kind`` as a report writes it (``in/s²``)."""
        from graphkin.text import unit_text

        return unit_text(str(getattr(self, kind)))


def parse_units(spec: str, length_unit: str) -> dict[str, Any]:
    """Read ``"ft, ft/s, ft/s^2"``: each unit is recognised by what it measures.

    A length unit alone also sets the velocity and acceleration units
    (``ft`` gives ``ft/s`` and ``ft/s^2``) unless they are given too;
    ``rev/min`` or ``rad/s`` sets the angular velocities, ``rad/s^2`` the
    angular accelerations.  Angles are always reported in degrees.

    Raises
    ------
    InputError
        An unknown unit, one that is not a length, velocity, acceleration or
        angular rate, or two units for the same quantity.

    Examples
    --------
    >>> sorted(parse_units("m, rev/min", "mm").items())  # doctest: +NORMALIZE_WHITESPACE
    [('acceleration', 'm/s^2'), ('k_acceleration', 0.001), ('k_length', 0.001),
     ('k_omega', 9.549296585513721), ('k_velocity', 0.001), ('length', 'm'),
     ('omega', 'rev/min'), ('velocity', 'm/s')]
    """
    from graphkin.units import check_unit, registry

    ureg = registry()
    out: dict[str, Any] = {}
    given: set[str] = set()
    for item in (s.strip() for s in spec.split(",")):
        if not item:
            continue
        try:
            check_unit(item)  # never arithmetic for pint to evaluate
            q = ureg.Quantity(1.0, item.replace("^", "**"))
        except Exception:
            raise InputError(f"unknown unit {item!r}", key="--units") from None
        kind = _KINDS.get(str(q.dimensionality))
        if kind is None:
            raise InputError(f"{item!r} is not a length, velocity, acceleration or angular "
                             "rate unit (angles are always in degrees)", key="--units")
        if kind in given:
            raise InputError(f"two units for the {kind}: {out[kind]!r} and {item!r}",
                             key="--units")
        given.add(kind)
        out[kind] = item
        out[f"k_{kind}"] = _factor(ureg, _INTERNAL[kind].format(L=length_unit), item)
        if kind == "length":
            for k, u in (("velocity", f"{item}/s"), ("acceleration", f"{item}/s^2")):
                if k not in given:
                    out[k] = u
                    out[f"k_{k}"] = _factor(ureg, _INTERNAL[k].format(L=length_unit), u)
    return out


def _factor(ureg: Any, internal: str, unit: str) -> float:
    return float(ureg.Quantity(1.0, internal.replace("^", "**")).to(unit.replace("^", "**"))
                 .magnitude)
