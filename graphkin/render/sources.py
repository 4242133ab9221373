"""What a drawing is made from: a solved mechanism, or a bare construction, and its values.

The renderer is generic over construction steps; this module only finds the
construction of a diagram and the values of its labels.  The posture,
velocity and acceleration constructions come with every solved mechanism; the
instant-center and curvature constructions come from their own modules
(:mod:`graphkin.kinematics.instant_centers`, :mod:`graphkin.kinematics.curvature`)
when they are installed.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (posture), 3.4-3.6 (velocity
polygons), 3.13-3.15 (instant centers), 4.2-4.6 (acceleration polygons),
4.12-4.17 (curvature).
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.errors import GraphkinError
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME, Mechanism

__all__ = ["DIAGRAMS", "Source", "DiagramUnavailable", "as_source", "plane_of",
           "optional_modules"]

DIAGRAMS = ("posture", "velocity", "acceleration", "centers", "curvature")
"""The diagrams graphkin draws, in the order of the book."""

#: diagram -> the module that builds its construction from a Solution
optional_modules: dict[str, str] = {
    "centers": "graphkin.kinematics.instant_centers",
    "curvature": "graphkin.kinematics.curvature",
}

_TITLES = {"posture": "Posture", "velocity": "Velocity polygon",
           "acceleration": "Acceleration polygon", "centers": "Instant centers",
           "curvature": "Curvature",
           "inflection": "(a) Inflection and Bresse circles",
           "bobillier": "(b) Bobillier's construction",
           "hartmann": "(c) Conjugate points",
           "cubic": "(d) Cubic of stationary curvature"}

CURVATURE_PANELS: dict[str, tuple[str, ...]] = {
    "inflection": ("pivot", "accelerations", "circle", "bresse", "four_circles"),
    "bobillier": ("bobillier", "euler_savary", "collineation_axis"),
    "hartmann": ("hartmann", "bobillier_conjugate"),
    "cubic": ("hain", "ball", "ball_at_j"),
}
"""The curvature sheet, one idea per figure as the book draws it (Figs. 4.25-4.39): panel ->
the sections of the curvature construction it shows."""


class StepSubset:
    """Some steps of a construction (a panel of the curvature sheet), in their order.

    It holds the panel's own steps and, for context, the steps that made the
    points, lines and circles they use (drawn as given); ``own`` is the set of
    the indices of its own steps.
    """

    def __init__(self, cx: Construction, keep: set[int], title: str) -> None:
        own = [s for s in cx.steps if s.index in keep]
        self.own = frozenset(s.index for s in own)
        used = {i for s in own for i in s.inputs}
        self.steps = [s for s in cx.steps if s.index in keep or set(s.outputs) & used]
        self.title = title

    def __iter__(self) -> Any:
        return iter(self.steps)

    def __len__(self) -> int:
        return len(self.steps)


def split_curvature(src: Source) -> list[str]:
    """Register one sub-construction per curvature panel that has steps; their names.

    Returns ``[]`` when the curvature construction has no sections (a link
    turning about a frame pivot: one panel with a sentence).
    """
    lc = src.extras.get("curvature")
    cx = src.constructions.get("curvature")
    sections: dict[str, str] = dict(getattr(lc, "sections", {}) or {})
    if cx is None or not sections or set(sections.values()) <= {"pivot"}:
        return []
    out = []
    placed: set[int] = set()
    for name, wanted in CURVATURE_PANELS.items():
        keep = {s.index for s in cx.steps if sections.get(s.outputs[0]) in wanted}
        if name == "inflection":  # anything unfiled goes to the first panel
            keep |= {s.index for s in cx.steps if s.outputs[0] not in sections}
        keep -= placed
        if name == "hartmann":
            keep = _few_conjugates(src, cx, keep, sections)
        if not keep:
            continue
        placed |= keep
        src.constructions[name] = StepSubset(cx, keep, title_of(name))  # type: ignore[assignment]
        src.values[name] = src.values["curvature"]
        src.extras[name] = lc
        out.append(name)
    return out


CONJUGATES_DRAWN = 6
"""At most this many points of a link have their conjugates constructed on figure (c): a
coupler carrying 300 lettered points would bury the construction (the rest are in the
report and the results table)."""


def _few_conjugates(src: Source, cx: Construction, keep: set[int],
                    sections: dict[str, str]) -> set[int]:
    """The steps of figure (c) for the first :data:`CONJUGATES_DRAWN` points of the link.

    Each point's construction begins with the step that places the point (no
    inputs); the names of the points left out go to ``src.extras``
    (``"conjugates_omitted"``) for the sheet's note.
    """
    groups: list[tuple[str, set[int]]] = []
    for st in cx.steps:
        if st.index not in keep:
            continue
        if not st.inputs or not groups:
            groups.append((st.outputs[0], set()))
        groups[-1][1].add(st.index)
    if len(groups) <= CONJUGATES_DRAWN:
        return keep
    src.extras["conjugates_omitted"] = [n for n, _ in groups[CONJUGATES_DRAWN:]]
    return set().union(*(g for _, g in groups[:CONJUGATES_DRAWN]))


class DiagramUnavailable(GraphkinError, LookupError):
    """The diagram cannot be drawn for this object (no rates, or its module is not installed)."""


def plane_of(diagram: str) -> str:
    """The plane a diagram's points live in: ``velocity``, ``acceleration`` or ``posture``.

    Instant centers and curvature constructions are drawn on the mechanism
    itself, in the posture's plane and units.

    Examples
    --------
    >>> plane_of("velocity"), plane_of("centers")
    ('velocity', 'posture')
    """
    return diagram if diagram in ("velocity", "acceleration") else "posture"


def title_of(diagram: str) -> str:
    """The panel title of a diagram."""
    return _TITLES.get(diagram, diagram.capitalize())


@dataclass
class Source:
    """Everything a drawing reads.

    Attributes
    ----------
    solution : Solution or None
        The solved mechanism (None when drawing a bare construction).
    constructions : dict
        Diagram -> Construction.
    values : dict
        Diagram -> {label: array} of the evaluated construction.
    """

    solution: Solution | None
    constructions: dict[str, Construction] = field(default_factory=dict)
    values: dict[str, dict[str, np.ndarray]] = field(default_factory=dict)
    extras: dict[str, Any] = field(default_factory=dict)
    """Diagram -> the object that made its construction (InstantCenters, LinkCurvature)."""

    @property
    def mechanism(self) -> Mechanism | None:
        """The mechanism, when there is one."""
        return None if self.solution is None else self.solution.mechanism

    @property
    def length_unit(self) -> str:
        """The file's length unit (``"mm"`` for a bare construction)."""
        m = self.mechanism
        return "mm" if m is None else m.length_unit

    def available(self) -> list[str]:
        """The diagrams that can be drawn, in book order."""
        out = [d for d in DIAGRAMS if d in self.constructions]
        if self.solution is not None and "posture" not in out:
            out.insert(0, "posture")
        return out

    def construction(self, diagram: str) -> Construction | None:
        """The construction of a diagram (None for a posture solved analytically)."""
        if diagram in self.constructions:
            return self.constructions[diagram]
        if diagram == "posture" and self.solution is not None:
            return None
        raise DiagramUnavailable(self.why_not(diagram), diagram=diagram)

    def why_not(self, diagram: str) -> str:
        """Why a diagram is not available, in one line."""
        if diagram not in DIAGRAMS:
            return f"unknown diagram {diagram!r}; valid: {', '.join((*DIAGRAMS, 'all'))}"
        if diagram in ("velocity", "acceleration"):
            if self.solution is not None and not self.solution.mechanism.has_rates:
                return (f"no {diagram} polygon: the file gives no rates (add omega to [drive] "
                        "or a [rates] table)")
            sol = self.solution
            if sol is not None and sol.method != "construction" and "posture" in \
                    sol.constructions:
                return (f"no {diagram} polygon: it cannot be drawn one step at a time at "
                        "this posture, and the rates are the analytic solver's (see the notes "
                        "of graphkin solve)")
            if sol is not None and sol.method != "construction":
                return (f"no {diagram} polygon: the mechanism was solved analytically "
                        "(it cannot be constructed one group at a time)")
            if sol is not None and any(n.startswith("toggle or dead-center") for n in sol.notes):
                return (f"no {diagram} polygon: the posture is a toggle or dead center, where "
                        "the velocities and accelerations are undetermined (Sec. 3.5)")
            return f"no {diagram} construction in this object"
        if diagram in optional_modules:
            module = optional_modules[diagram]
            if importlib.util.find_spec(module) is None:
                return (f"the {diagram} diagram is not available yet ({module} is not "
                        "installed in this graphkin)")
            if diagram == "curvature" and self.solution is not None \
                    and not self.solution.mechanism.has_rates:
                return ("no curvature construction: the file gives no rates (the inflection "
                        "circle needs the angular velocity and acceleration)")
            return f"the {diagram} diagram is not available for this mechanism"
        return f"no {diagram} construction in this object"

    def value(self, diagram: str, label: str) -> np.ndarray | None:
        """The value of a label in a diagram's evaluation (or any other's)."""
        vals = self.values.get(diagram, {})
        if label in vals:
            return vals[label]
        for d in self.values.values():
            if label in d:
                return d[label]
        return None


def _optional(sol: Solution, diagram: str,
              link: str | None = None) -> tuple[Construction, dict[str, np.ndarray], Any] | None:
    """Build the instant-center or curvature construction (None when it cannot be had).

    The curvature construction belongs to one link's motion: ``link``, or by
    default the first coupler (a moving link not pinned to the frame) that
    turns, as the book's examples do.
    """
    module_name = optional_modules[diagram]
    if importlib.util.find_spec(module_name) is None:
        return None
    module = importlib.import_module(module_name)
    if diagram == "centers":
        fn = getattr(module, "instant_centers", None)
        return None if fn is None else _unpack(fn(sol), sol)
    fn = getattr(module, "curvature", None)
    if fn is None:
        return None
    links = {k: v for k, v in fn(sol).items() if getattr(v, "construction", None) is not None}
    if not links:
        return None
    if link is not None:
        if str(link) not in links:
            raise DiagramUnavailable(
                f"no curvature construction for link {link}; links with one: "
                f"{', '.join(links)}", diagram=diagram)
        return _unpack(links[str(link)], sol)
    frame_points = set(sol.mechanism.links[FRAME].points)
    couplers = [k for k in links if not frame_points & set(sol.mechanism.links[k].points)]
    return _unpack(links[(couplers or list(links))[0]], sol)


def _unpack(out: Any, sol: Solution) -> tuple[Construction, dict[str, np.ndarray], Any] | None:
    """Accept a Construction, (Construction, values) or an object with ``.construction``."""
    values: Mapping[str, Any] | None = None
    cx: Any = out
    if isinstance(out, tuple) and len(out) == 2:
        cx, values = out
    elif not isinstance(out, Construction) and hasattr(out, "construction"):
        cx = out.construction
        values = getattr(out, "values", None)
    if not isinstance(cx, Construction):
        return None
    if not values:
        given: dict[str, np.ndarray] = {}
        for d in sol.values.values():
            given.update(d)
        values = cx.evaluate(values=given).values
    return cx, {k: np.asarray(v, dtype=float) for k, v in values.items()}, out


def as_source(obj: Any, values: Mapping[str, Any] | None = None,
              diagrams: tuple[str, ...] = (), link: str | None = None) -> Source:
    """A :class:`Source` from a Mechanism, a Solution or a Construction.

    Parameters
    ----------
    obj : Mechanism, Solution or Construction
    values : mapping, optional
        For a bare construction whose steps read given inputs: their values
        (a drive angle), or every label's value.
    diagrams : tuple of str
        Optional diagrams (``centers``, ``curvature``) to build when their
        modules are installed.
    link : str, optional
        The link whose curvature construction is drawn (default: the first
        coupler that turns).

    Raises
    ------
    DiagramUnavailable
        A bare construction that cannot be evaluated without more values.
    """
    if isinstance(obj, Mechanism):
        obj = obj.solve()
    if isinstance(obj, Solution):
        src = Source(obj, dict(obj.constructions),
                     {k: dict(v) for k, v in obj.values.items()})
        for d in diagrams:
            if d in optional_modules and d not in src.constructions:
                try:
                    built = _optional(obj, d, link)
                except DiagramUnavailable:
                    raise
                except (GraphkinError, ValueError, ArithmeticError):
                    built = None
                if built is not None:
                    src.constructions[d], src.values[d], src.extras[d] = built
        return src
    if isinstance(obj, Construction):
        given = {k: np.asarray(v, dtype=float) for k, v in (values or {}).items()}
        try:
            ev = obj.evaluate(values=given)
        except GraphkinError as exc:
            raise DiagramUnavailable(f"cannot evaluate the construction by itself ({exc}); "
                                     "draw the solved mechanism instead, or pass values=",
                                     diagram="construction") from None
        diagram = _main_diagram(obj)
        return Source(None, {diagram: obj}, {diagram: dict(ev.values)})
    raise TypeError(f"cannot draw a {type(obj).__name__}; expected a Mechanism, a Solution or "
                    "a Construction")


def _main_diagram(cx: Construction) -> str:
    """The diagram a construction belongs to: that of its last step (posture by default)."""
    for s in reversed(cx.steps):
        if s.diagram:
            return s.diagram
    return "posture"
