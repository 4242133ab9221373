"""The force analysis (Chs. 11-12) as a section of the report.

The ``forces`` JSON object of ``docs/formats/json.md`` (docs/forces.md) and
its textbook-style text.

The builders live with the analysis (:mod:`graphkin.forces.report`); this
module hands them the solution and the report's units.  Forces stay in the
file's ``units.force``; lengths (points of action, offsets h) and the length in
a torque's unit follow ``--units`` like every other length of the report.

References
----------
Uicker, Pennock & Shigley, 5th ed., Ch. 11-12.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from graphkin.forces.report import forces_json as _json
from graphkin.forces.report import forces_report
from graphkin.forces.report import forces_text as _text

if TYPE_CHECKING:
    from graphkin.kinematics.solution import Solution
    from graphkin.output.units import OutputUnits

__all__ = ["forces_json", "forces_text"]


def forces_json(sol: Solution, units: OutputUnits) -> dict[str, Any] | None:
    """The ``forces`` object, or None when the file has no loads and no masses."""
    fs = forces_report(sol)
    if fs is None:
        return None
    out = _json(fs)
    k = float(units.k_length)
    if k != 1.0:
        length = units.text("length")
        out["units"]["torque"] = f"{fs.mechanism.force_unit}*{length}"
        for j in out["joints"].values():
            j["point"] = [x * k for x in j["point"]]
        for d in out["drives"].values():
            if "torque" in d:
                d["torque"] *= k
        for f in out.get("inertia", {}).values():
            f["point"] = [x * k for x in f["point"]]
            f["torque"] *= k
            f["offset"] *= k
        for g in out.get("gears", {}).values():   # gear teeth (Sec. 11.11)
            g["point"] = [x * k for x in g["point"]]
            g["torque"] = {lid: m * k for lid, m in g["torque"].items()}
            g["radius"] = {lid: r * k for lid, r in g["radius"].items()}
        if "shaking" in out:
            out["shaking"]["moment"] *= k
    return out


def forces_text(sol: Solution, units: OutputUnits) -> str | None:
    """The force analysis as the book states it, or None."""
    fs = forces_report(sol)
    return None if fs is None else _text(fs).rstrip("\n")
