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
    the distance from the point to its conjugate, ρ = R_EE′ (Sec. 4.12).
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
        out.append(f"The radius of curvature of the path of {base}: ρ_{base} = R_{base}{base}′ "
                   f"= ⟦{fmt(_round(rho), 4)} {unit}⟧.")
    return out


_WHY: list[tuple[str, str, str, str]] = [
    # (section, operation, pattern of the output's label, why: {o} output, {a} {b} inputs)
    ("euler_savary", "join", r"[^']+", "The line through the two points of the link; the line "
     "through their conjugates is drawn next, and the two lines meet at Q (Fig. 4.29a)."),
    ("euler_savary", "join", r".*'.*'", "The line through the conjugate points, the centers of "
     "curvature of their paths (Fig. 4.29a)."),
    ("euler_savary", "meet", r"Q", "The straight line drawn through I and Q is the collineation "
     "axis; it belongs to the two rays (Fig. 4.29a)."),
    ("euler_savary", "parallel", r"I∥.*", "Fig. 4.29b: the point W where this line meets the "
     "line of the two points starts the search for two more points of the inflection circle."),
    ("euler_savary", "meet", r"W", "Through W a line parallel to the collineation axis is drawn "
     "next (Fig. 4.29b)."),
    ("euler_savary", "parallel", r"W∥.*", "This line intersects the two rays at two additional "
     "points of the inflection circle (Fig. 4.29b)."),
    ("euler_savary", "meet", r"J_.+", "{o} lies on the inflection circle: its conjugate point "
     "is at infinity, and its path has an inflection (Fig. 4.29b)."),
    ("euler_savary", "perpendicular", r"⊥.*", "A triangle inscribed in a semicircle is a right "
     "triangle having the diameter as its hypotenuse: the perpendicular erected at {b} passes "
     "through the inflection pole J, the end of the diameter IJ (Fig. 4.29c)."),
    ("accelerations", "join", r".*", "The velocity of the point, from the velocity polygon; "
     "the velocity pole lies on the perpendicular to it through the point (Sec. 3.13)."),
    ("accelerations", "perpendicular", r".*", "Every point of the link moves perpendicular to "
     "its line to the velocity pole I, so I lies on this perpendicular (Sec. 3.13)."),
    ("accelerations", "meet", r".*", "The velocity pole is the point of the link with no "
     "velocity at this instant: the instant center of the link and the frame (Sec. 4.12)."),
    ("accelerations", "*", r"A_.*", "The absolute acceleration of the point, from the "
     "acceleration polygon; it locates the inflection circle (the points with no normal "
     "acceleration, Sec. 4.15)."),
    ("collineation_axis", "join", r"[^']+", "The line through the two pins; the line through "
     "their frame pivots, their conjugate points, meets it at Q (Fig. 4.31)."),
    ("collineation_axis", "join", r".*'.*'", "The line through the frame pivots, the "
     "conjugate points of the pins: it meets the line of the pins at Q (Fig. 4.31)."),
    ("circle", "join", r"N", "The centrode normal is normal to both centrodes at the velocity "
     "pole; the diameter IJ of the inflection circle lies on it (Sec. 4.12)."),
    ("four_circles", "point", r"A_.*", "The absolute acceleration of the point, laid off from it "
     "(Fig. 4.33)."),
    ("four_circles", "point", r".*", "Fig. 4.33 starts from two points of the link and their "
     "absolute accelerations; any two points will do."),
    ("four_circles", "join", r".*", "We extend the two accelerations until they intersect "
     "(Fig. 4.33)."),
    ("four_circles", "meet", r".*", "Then we construct a circle through the two points and "
     "{o} (Fig. 4.33)."),
    ("four_circles", "circumcircle", r".*", "The four-circle method draws two circles through "
     "{c}; their second intersection is Γ (Fig. 4.33)."),
    ("bobillier_conjugate", "point", r".*", "The point whose conjugate, the center of curvature "
     "of its path, is wanted (Fig. 4.30)."),
    ("bobillier_conjugate", "join", r"I.*", "This ray serves as one of the two rays that locate "
     "the collineation axis; the centrode normal, with J and its conjugate J′ at infinity, is "
     "the other (Fig. 4.30)."),
    ("bobillier_conjugate", "second_on_circle", r".*", "The point of intersection of the ray "
     "{b} with the inflection circle (Fig. 4.30)."),
    ("bobillier_conjugate", "join", r"J_.*", "For the ray through {a} and the centrode normal, "
     "the collineation axis is a line through I parallel to this line (Fig. 4.29c)."),
    ("bobillier_conjugate", "join", r"J[^_].*", "The point Q is located by the intersection of "
     "a line through J and {b} with the collineation axis (Fig. 4.30)."),
    ("bobillier_conjugate", "meet", r".*", "A line through {o} and J′ at infinity (parallel to "
     "the centrode normal) intersects the ray at the conjugate point (Fig. 4.30)."),
    ("hartmann", "point", r".*", "The point whose conjugate, the center of curvature of its "
     "path, is wanted (Fig. 4.25)."),
    ("hartmann", "join", r"I.*", "The conjugate point lies on this line through the velocity "
     "pole (Fig. 4.25)."),
    ("hartmann", "perpendicular", r"v∥.*", "It cuts off u, the component of the pole velocity v "
     "parallel to the velocity of the point (Fig. 4.25)."),
    ("hartmann", "meet", r"u_.*", "u is the component of the pole velocity parallel to the "
     "velocity of the point, perpendicular to the line to I (Fig. 4.25)."),
    ("hartmann", "join", r".*", "The intersection of the line through I and a line connecting "
     "the termini of the two velocities gives the conjugate point (Fig. 4.25)."),
    ("hain", "join", r"I.*", "{b} lies on the cubic of stationary curvature: its path has "
     "stationary curvature (Fig. 4.38)."),
    ("hain", "perpendicular", r".*", "This line intersects the centrode normal and the centrode "
     "tangent at two corners of a rectangle on I (Fig. 4.38)."),
    ("hain", "meet", r".*_[NT]", "A corner of the rectangle on I (Fig. 4.38)."),
    ("hain", "parallelogram", r".*", "The fourth corner {o} of the rectangle is a point of the "
     "auxiliary line G (Fig. 4.38)."),
    ("ball", "meet", r"U_G", "U_G is the corner on G of the rectangle of Ball's point U, whose "
     "corner on the centrode normal is J (Fig. 4.38)."),
    ("ball", "parallel", r"U_G∥.*", "The rectangle's side from U_G to the centrode tangent."),
    ("ball", "meet", r"U_T", "U_T and U_N = J are where the line through U perpendicular to IU "
     "meets T and N."),
    ("ball", "join", r".*", "U lies on this line, and IU is perpendicular to it (Fig. 4.38)."),
    ("ball", "perpendicular", r".*", "Its foot on the line U_TJ is Ball's point U."),
]
"""Why a step of a curvature figure is drawn, for the steps whose note says only what
(the book's words, Secs. 4.12-4.17); the first match of section, operation and label wins."""


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
