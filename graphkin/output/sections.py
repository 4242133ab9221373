"""The sections a report has beyond the posture and its rates, in the order they are printed.

Each section is built from the result objects of one part of the analysis
and gives its JSON object (a key of ``docs/formats/json.md``) and its part of the
text report.  A new kind of result adds a module to :mod:`graphkin.output`
(``graphkin/output/forces.py`` for the force analysis of Chs. 11-12: a
``forces_json(sol, units)`` and a ``forces_text(sol, units)``) and one
:class:`Section` line below; nothing else changes.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from graphkin.kinematics.solution import Solution
    from graphkin.output.units import OutputUnits

__all__ = ["Section", "SECTIONS"]


@dataclass(frozen=True)
class Section:
    """One part of the report: its JSON key, its text title, and the functions that build them.

    The functions are named ``"module:function"`` and imported when first
    called, so that loading the output layer does not load every analysis.
    """

    key: str
    title: str
    json_fn: str
    text_fn: str | None = None

    def json(self, sol: Solution, units: OutputUnits) -> Any:
        """The section's JSON object, or None when it does not apply to ``sol``."""
        return _load(self.json_fn)(sol, units)

    def text(self, sol: Solution, units: OutputUnits) -> str | None:
        """The section's part of the text report, or None (no text, or not for ``sol``)."""
        return None if self.text_fn is None else _load(self.text_fn)(sol, units)


def _load(name: str) -> Callable[..., Any]:
    import importlib

    module, _, fn = name.partition(":")
    return getattr(importlib.import_module(module), fn)  # type: ignore[no-any-return]


SECTIONS: tuple[Section, ...] = (
    Section("cams", "Cams", "graphkin.output.cams:cams_json", "graphkin.output.cams:cams_text"),
    Section("joint_angles", "Joint angles", "graphkin.output.joints:joint_angles_json",
            "graphkin.output.joints:joint_angles_text"),
    Section("instant_centers", "Instant centers", "graphkin.output.centers:instant_centers_json",
            "graphkin.output.centers:instant_centers_text"),
    Section("curvature", "Curvature", "graphkin.output.curvature:curvature_json",
            "graphkin.output.curvature:curvature_text"),
    Section("paths", "", "graphkin.output.curvature:paths_json"),
    Section("forces", "Forces", "graphkin.output.forces:forces_json",
            "graphkin.output.forces:forces_text"),
    Section("gear_train", "Gear train (Secs. 7.15-7.16)",
            "graphkin.output.trains:gear_train_json", "graphkin.output.trains:gear_train_text"),
)
"""The sections, in the order of the JSON keys and of the text report."""
