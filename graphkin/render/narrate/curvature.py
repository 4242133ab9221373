"""The figures of the curvature sheet told one at a time (Secs. 4.12-4.17, Figs. 4.25-4.39).

A figure of the curvature sheet (``inflection``, ``bobillier``, ``hartmann``,
``cubic``: :data:`graphkin.render.sources.CURVATURE_PANELS`) draws its own
steps over the points, lines and circles that earlier figures made.  Its page
opens with what the figure is for, in the book's words, and with those given
elements in one act ("Given from the figures before"); each of its own steps
is then told from its note, with the point it finds and, for the center of
curvature of a point's path, the radius of curvature ρ read off.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 4.12 (Euler-Savary equation, the
inflection circle, the Hartmann construction, Fig. 4.25), 4.13 (Bobillier
constructions, Figs. 4.28-4.31), 4.14 (instantaneous center of acceleration,
Fig. 4.33), 4.15 (Bresse circle, Fig. 4.34), 4.17 (cubic of stationary
curvature, Hain's construction and Ball's point, Fig. 4.38).
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.construction import Step
from graphkin.render.narrate.words import _REFS, PageStep, _round, point_name
from graphkin.render.scale import fmt

__all__ = ["PANEL_INTRO", "given_step", "curvature_numbers", "why"]

PANEL_INTRO = {
    "inflection": (
        "The inflection circle is the locus of the points of the moving plane whose paths "
        "have an inflection at this instant: their conjugate points are at infinity, and "
        "they have no normal acceleration. Its diameter IJ lies on the centrode normal N. "
        "The Bresse circle is the locus of the points with no tangential acceleration; the "
        "two circles meet at the velocity pole I and at Γ, the instantaneous center of "
        "acceleration."),
    "bobillier": (
        "Bobillier's theorem: the angle from the collineation axis to the first ray equals "
        "the angle from the second ray to the centrode tangent. From two known pairs of "
        "conjugate points it finds the inflection circle without measuring an angle."),
    "hartmann": (
        "With the inflection circle known, the conjugate point of any point of the moving "
        "plane (the center of curvature of its path) is found by Bobillier's construction, "
        "using the centrode normal, whose conjugate J′ is at infinity, as the second ray, "
        "or by Hartmann's construction from the pole velocity."),
    "cubic": (
        "The cubic of stationary curvature is the locus of the points of the moving plane "
        "whose paths have stationary curvature at this instant. Hain's construction finds "
        "it from two points known to lie on it (the pins, whose paths are circles); where "
        "it meets the inflection circle is Ball's point U, whose path is nearly a straight "
        "line for a long way."),
}
"""What each figure is for, told before its first step (the book's words, Secs. 4.12-4.17)."""


_GIVEN_NAMES = {"N": "the centrode normal N", "T": "the centrode tangent T"}


def given_step(group: list[Step], diagram: str) -> PageStep:
    """The act that lays out what earlier figures made, before a figure's own steps."""
    names = []
    for s in group:
        for o in s.outputs:
            name = point_name(o)
            names.append(_GIVEN_NAMES.get(name) or (
                name if s.kind == "point" or " " not in name else f"the {name}"))
    listed = ", ".join(names) if names else "the points of the link"
    return PageStep(f"Given from the figures before: {listed}",
                    text=PANEL_INTRO.get(diagram, "") + " These elements were constructed "
                    "in the figures before this one and are drawn here as given.",
                    refs=_REFS.get(diagram, ""))


def curvature_numbers(step: Step, xy: Any, unit: str) -> list[str]:
    """ρ of a point's path, where a step finds its center of curvature (``E'`` of ``E``).

    ``xy(label)`` is the point's position (or None); the radius of curvature is
    the distance from the point to its conjugate, ρ = |EE′| (Sec. 4.12).
    """
    out: list[str] = []
    if step.role.value == "given":
        return out
    for o in step.outputs:
        name = point_name(o)
        if not name.endswith("'"):
            continue
        base = name[:-1]
        p, q = xy(base), xy(o)
        if p is None or q is None:
            continue
        rho = float(np.hypot(*(np.asarray(q) - np.asarray(p))))
        out.append(f"The radius of curvature of the path of {base}: ρ_{base} = |{base}{base}′| "
                   f"= ⟦{fmt(_round(rho), 4)} {unit}⟧.")
    return out


def _why_table() -> list[tuple[str, str, str, str]]:
    """The table of ``why.toml``: (section, operation, label pattern, text)."""
    with open(Path(__file__).with_name("why.toml"), "rb") as fh:
        rows = tomllib.load(fh)["why"]
    return [(r["section"], r["op"], r["label"], r["text"]) for r in rows]


_WHY = _why_table()
"""Why a step of a curvature figure is drawn (``why.toml``, the book's words, Secs. 4.12-4.17)."""


def why(step: Step, section: str | None) -> str:
    """Why a curvature step is drawn (``""`` when its note says it already).

    Examples
    --------
    >>> from graphkin.construction import Construction
    >>> cx = Construction()
    >>> _ = cx.add("meet", ("BC", "B'C'"), ("Q",))
    >>> why(cx.steps[0], "euler_savary").split(";")[0]
    'The straight line drawn through I and Q is the collineation axis'
    """
    out = step.outputs[0] if step.outputs else ""
    names = [point_name(i) for i in step.inputs]
    for sec, op, pattern, text in _WHY:
        if sec == section and op in (step.op, "*") and re.fullmatch(pattern, out):
            a = names[0] if names else ""
            b = names[1] if len(names) > 1 else a
            return text.format(o=point_name(out), a=a, b=b, c=", ".join(names))
    return ""
