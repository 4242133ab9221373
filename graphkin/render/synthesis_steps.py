"""The constructions of a synthesis step by step, as one web page (``synthesize --steps``).

One frame per drawn step of the recorded construction, in the order the book
draws it (the poles, the pole triangle or the opposite-pole quadrilateral,
the image point, the bisectors, the center and circle points; for four
postures then the chosen center points' circle points), each with the step's
sentence in the book's words and the drawing up to it, the newest element
highlighted; the last frame is the whole drawing (curves and linkage).  The
pager is :mod:`graphkin.render.stepper`'s, as for the gear and force layouts.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.3-9.7, 9.10, 9.13.
"""

from __future__ import annotations

import html
from typing import Any

from graphkin.construction import Construction
from graphkin.construction.step import Step
from graphkin.render.stepper import PAGER_JS, frame_section
from graphkin.render.synthesis import draw_synthesis, hidden, synthesis_sheet
from graphkin.synthesis.run import Result

__all__ = ["teaching_steps", "synthesis_frames", "synthesis_steps_html"]

_DRAWN = ("point", "line", "circle")


def teaching_steps(res: Result) -> list[tuple[Construction, Step]]:
    """The steps a teaching page shows one by one, with their constructions, in order."""
    if res.overlay is not None:
        return []   # a search, not a construction: the page is the result alone
    if res.function is not None:
        order = [res.construction]
    elif res.cognates is not None:
        order = [res.cognates.construction]
    elif res.dwell is not None:
        order = [res.dwell.construction]
    else:
        order = [res.construction, res.selection]
    post = res.postures if res.spec.postures is not None else None
    out: list[tuple[Construction, Step]] = []
    for cx in order:
        if cx is None:
            continue
        skip = hidden(cx, post) if post is not None else set()
        out += [(cx, s) for s in cx if s.kind in _DRAWN and s.outputs[0] not in skip]
    return out


def synthesis_frames(res: Result, max_inches: float = 5.0) -> list[tuple[str, str, str]]:
    """One drawing per step, then the whole drawing: ``(title, note, svg)`` each."""
    from graphkin.render.mpl import render_sheet
    from graphkin.render.svg import to_svg

    frames = []
    for cx, step in teaching_steps(res):
        sheet, _ = synthesis_sheet(res, max_inches=max_inches, stage=(cx, step.index))
        frames.append((step.label, step.note, to_svg(render_sheet(sheet).figure)))
    whole = {"4 postures": "The construction repeated for every circle on the chord gives the "
                           "center-point curve (solid) and the circle-point curve (dash-dot); "
                           "the chosen center points and their circle points make the four-bar "
                           "(Sec. 9.5).",
             "5 postures": "The center-point curves of postures 1234 and 1235 meet at the "
                           "Burmester points (open circles): each pair of them is a four-bar "
                           "through all five postures (Sec. 9.6)."}.get(
        res.kind, "The four-bar found, in its design postures, with its coupler curve.")
    frames.append(("the result", whole, to_svg(draw_synthesis(res, max_inches=max_inches)
                                               .figure)))
    return frames


def synthesis_steps_html(res: Result) -> str:
    """The synthesis step by step as one self-contained HTML page.

    Previous/next buttons and the arrow keys walk through it.
    """
    frames = synthesis_frames(res)
    head = html.escape(res.spec.title or f"Synthesis: {res.kind}")
    n = len(frames)
    parts: list[Any] = [frame_section(k, n, label, f"<p>{html.escape(note)}</p>", svg)
                        for k, (label, note, svg) in enumerate(frames)]
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'>"
            f"<title>Synthesis: {head}</title><style>body{{font-family:sans-serif;margin:1em}}"
            ".fig svg{max-width:100%;height:auto}</style></head>"
            f"<body><h1>Graphical synthesis (Ch. 9): {head}</h1><p><button id='prev'>"
            "◀ previous</button> <button id='next'>next ▶</button> (or the arrow keys)</p>"
            + "".join(parts) + f"<script>{PAGER_JS}</script></body></html>\n")
