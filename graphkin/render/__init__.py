"""Drawings of the constructions, as the textbook's draftsman makes them (the only matplotlib user).

* :func:`draw` — a diagram of a mechanism, a solution or a construction,
  returning ``{label: Artist}``;
* :func:`save` / :func:`to_svg` — deterministic SVG (real ``<text>``, one
  ``<g id="step-NN-...">`` per step), vector PDF, PNG;
* :func:`repr_svg` — for Jupyter's ``_repr_svg_``;
* :func:`steps_html` — the teaching page, one frame per step
  (:mod:`graphkin.render.teach`).

Importing :mod:`graphkin` does not import this package.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8, 3.4-3.6, 4.2-4.6.
"""

from __future__ import annotations

from graphkin.render.mpl import Drawing, StepGroup, Vector, draw, render_sheet
from graphkin.render.sheet import Sheet, build_sheet
from graphkin.render.sources import DIAGRAMS, DiagramUnavailable, Source, as_source
from graphkin.render.svg import repr_svg, save, to_bytes, to_svg

__all__ = ["draw", "save", "to_svg", "to_bytes", "repr_svg", "render_sheet", "build_sheet",
           "Sheet", "Drawing", "StepGroup", "Vector", "DIAGRAMS", "DiagramUnavailable",
           "Source", "as_source", "steps_html"]


def steps_html(obj: object, diagram: str = "posture", *, link: str | None = None,
               title: str | None = None) -> str:
    """The teaching page of a diagram; see :func:`graphkin.render.teach.steps_html`."""
    from graphkin.render.teach import steps_html as _steps_html

    return _steps_html(obj, diagram, link=link, title=title)
