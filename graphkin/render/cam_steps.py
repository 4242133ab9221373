"""``graphkin steps CAMFILE -d cam``: the layout of a cam profile by inversion, step by step.

The book's procedure of Sec. 6.4 (Figs. 6.8-6.11), one frame per step: the
prime (and base) circle about the cam's center; then, station by station, the
follower turned against the cam's rotation (the cam held still: kinematic
inversion) and set at its displacement read off the displacement diagram; and
last the profile, the smooth curve tangent to every position of the roller,
the knife edge or the face (their envelope).  Each frame is the layout drawing
(:func:`graphkin.render.cams.layout_figure`) up to that step, the newest
station highlighted; the page is the one pager of every step page
(:mod:`graphkin.render.stepper`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 6.4, Figs. 6.8-6.11.
"""

from __future__ import annotations

import html
import math

from graphkin.cams.model import Cam, FollowerKind
from graphkin.text import g6

__all__ = ["cam_frames", "cam_steps_html"]

_WHAT = {FollowerKind.KNIFE_EDGE: "its knife edge", FollowerKind.ROLLER: "its roller",
         FollowerKind.FLAT_FACE: "its flat face", FollowerKind.OSCILLATING_ROLLER:
         "its arm and roller", FollowerKind.OSCILLATING_FLAT_FACE: "its arm and flat face"}


def _station_note(cam: Cam, i: int, n: int) -> str:
    """What the book does at station ``i`` (Sec. 6.4), with the numbers of this cam."""
    f = cam.follower
    th = 2 * math.pi * i / n
    Y = float(cam.program.evaluate([th]).Y[0])
    sense = "clockwise" if cam.s > 0 else "counterclockwise"
    if f.kind.oscillating:
        where = (f"swing the arm about O4 by the follower's angle Y = "
                 f"{g6(math.degrees(Y))}° from its lowest position")
        turn = "turn the pivot O4 about O2"
    else:
        where = (f"set the trace point Y = {g6(Y)} {cam.unit} above the prime circle along "
                 "the follower's line")
        turn = "turn the follower's line about O2"
    return (f"Station {i}, Θ = {g6(math.degrees(th))}°: the cam is held still, so {turn} "
            f"{g6(math.degrees(th))}° {sense} (against the cam's rotation: kinematic "
            f"inversion); {where} (the displacement diagram at Θ = "
            f"{g6(math.degrees(th))}°), and draw {_WHAT[f.kind]} there.")


def cam_frames(cam: Cam, n: int = 12) -> list[tuple[str, str, str]]:
    """One drawing per step of the layout: ``(title, note, svg)`` each."""
    from graphkin.render.cams import layout_figure
    from graphkin.render.style import rc_context
    from graphkin.render.svg import to_svg

    f = cam.follower
    circles = (f"the prime circle, radius R0 = {g6(cam.prime)} {cam.unit}"
               + (f", and the base circle, R0 − Rr = {g6(cam.base)} {cam.unit}"
                  if f.kind.roller else "")
               + (f", and the circle through the pivot O4 (radius "
                  f"{g6(math.hypot(*f.pivot))} {cam.unit})" if f.kind.oscillating else ""))
    envelope = {FollowerKind.KNIFE_EDGE: "through every position of the knife edge",
                FollowerKind.ROLLER: "tangent to every roller: it touches each where the "
                "common normal through the instant center I24 meets it (Fig. 6.27)",
                FollowerKind.FLAT_FACE: "tangent to every position of the face (their "
                "envelope); the contact lies y' along the face from the center line "
                "(Eq. 6.26)",
                FollowerKind.OSCILLATING_ROLLER: "tangent to every roller (I24 on the line "
                "of centers O2O4)",
                FollowerKind.OSCILLATING_FLAT_FACE: "tangent to every position of the face "
                "(their envelope)"}[f.kind]
    steps: list[tuple[str, str, int]] = [
        ("circles", f"About the cam's center O2 draw {circles} (Sec. 6.4).", 0)]
    steps += [(f"station {i}", _station_note(cam, i, n), i + 1) for i in range(n)]
    steps.append(("the profile", f"Draw the cam's profile as the smooth curve {envelope}. "
                  "graphkin's curve is the analytic profile of Secs. 6.9-6.10, which the "
                  "recorded layout meets to round-off at every station.", n + 1))
    frames = []
    for title, note, upto in steps:
        with rc_context():
            fig = layout_figure(cam, n, upto=upto)
            frames.append((title, note, to_svg(fig)))
    return frames


def cam_steps_html(cam: Cam, n: int = 12) -> str:
    """The layout by inversion step by step as one self-contained HTML page.

    Examples
    --------
    >>> from graphkin.cams.examples import example_6_6
    >>> page = cam_steps_html(example_6_6(), n=4)
    >>> page.count("<section"), "kinematic inversion" in page
    (6, True)
    """
    from graphkin.render.stepper import PAGER_JS, frame_section

    frames = cam_frames(cam, n)
    head = html.escape(cam.title or "cam")
    parts = [frame_section(k, len(frames), label, f"<p>{html.escape(note)}</p>", svg)
             for k, (label, note, svg) in enumerate(frames)]
    return ("<!DOCTYPE html><html><head><meta charset='utf-8'>"
            f"<title>Cam layout: {head}</title><style>body{{font-family:sans-serif;"
            "margin:1em}.fig svg{max-width:100%;height:auto}</style></head>"
            f"<body><h1>The cam profile laid out by inversion (Sec. 6.4): {head}</h1><p>"
            "<button id='prev'>◀ previous</button> <button id='next'>next ▶</button> "
            "(or the arrow keys)</p>" + "".join(parts) + f"<script>{PAGER_JS}</script>"
            "</body></html>\n")
