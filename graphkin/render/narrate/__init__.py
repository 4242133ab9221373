"""Narration: the recorded construction steps told in the book's words, with their numbers.

A teaching page walks through a construction the way Uicker, Pennock &
Shigley work their examples: each step has a title in words ("Velocity of C:
V_C = V_B + V_CB"), the vector equation it solves or uses with ✓/? over
every vector (its left side included), one or two sentences saying what is
drawn and why, and the numbers — the known magnitude computed
(A^n_CB = V_CB²/R_CB = (38.4 ft/s)²/(1.5 ft) = 983 ft/s²), its length on the
drawing at the chosen scale, and the result read off once it is found.

The recorded steps are not renamed (other code keys on their labels); this
module reads them — their operation, inputs, outputs and equation — and the
values of the solved construction, and groups the small preparatory acts
(the posture line a perpendicular is drawn to, a component before it is laid
off) with the step they serve.  Steps that only place helper points (points
that only define a slider's line or a slot) are left out.

Numbers the student is to find are marked ``⟦...⟧`` in the text; the page
shows them behind a "show answers" toggle (:func:`answer_html`), and
:func:`plain` removes the marks.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (Table 2.2, the ✓/? marks),
3.3-3.7 (velocity difference, polygons and images, apparent velocity, rolling
contact), 4.3-4.7 (acceleration difference, polygons, Coriolis component,
rolling contact).
"""

from typing import Any

from graphkin.render.narrate.polygons import _Teller
from graphkin.render.narrate.words import (
    PREPARATORY,
    PageStep,
    answer_html,
    image_letter,
    plain,
    point_name,
    vector_html,
)
from graphkin.render.scale import Scale

__all__ = ["PageStep", "narrate", "helper_steps", "plain", "answer_html", "vector_html",
           "point_name", "image_letter", "PREPARATORY"]


def helper_steps(src: Any, diagram: str) -> set[int]:
    """Indices of the steps that only place the images of helper points (left off the page).

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.render.sources import as_source
    >>> src = as_source(graphkin.examples.coriolis_block().solve())
    >>> [src.constructions["velocity"][i].label for i in sorted(helper_steps(src, "velocity"))]
    ['v(X)']
    """
    t = _Teller(src, diagram, None)
    return {s.index for s in t.cx.steps if t.helper(s)}


def narrate(src: Any, diagram: str, scale: Scale | None = None) -> list[PageStep]:
    """The steps of a construction told in the book's words, with their numbers.

    Parameters
    ----------
    src : Source
        The solved mechanism and its evaluated constructions
        (:func:`graphkin.render.sources.as_source`).
    diagram : str
        ``velocity``, ``acceleration`` (told in full), or ``posture``,
        ``centers``, ``curvature`` (told from the steps' notes).
    scale : Scale, optional
        The scale the polygon is drawn at (lengths on the drawing are given at it).

    Returns
    -------
    list of PageStep
        In order; helper points' steps left out, preparatory steps grouped.

    Examples
    --------
    >>> import graphkin
    >>> from graphkin.render.sources import as_source
    >>> src = as_source(graphkin.examples.fourbar().solve())
    >>> steps = narrate(src, "velocity")
    >>> [s.title for s in steps][:2]
    ['The velocity pole O_V and the scale; the input', 'Velocity of B: V_B = V_A + V_BA']
    >>> steps[4].equation_text()
    'V_C(??) = V_B(✓✓) + V_CB(?✓) = V_D(✓✓) + V_CD(?✓)'

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (Example 3.1, Fig. 3.7) and
    Sec. 4.4 (Example 4.2, Fig. 4.8).
    """
    return _Teller(src, diagram, scale).tell()
