"""What a curvature sheet says in words: the link it shows, the figures it leaves out and why.

The curvature sheet draws one idea per figure (Figs. 4.25-4.39): (a) the
inflection and Bresse circles, (b) Bobillier's construction, (c) conjugate
points, (d) the cubic of stationary curvature.  A figure has no steps for
some links (no point whose center of curvature must be found; no two points
whose conjugates are known by inspection); the sheet then says so in one
sentence instead of leaving the reader to guess, and names the link whose
motion it shows.  A link that nearly translates has its poles far off the
paper: the sheet says so, and why the figure is drawn with arrows.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.13-4.17.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from graphkin.render.scene import far_distance
from graphkin.text import fmt

__all__ = ["link_title", "missing_reasons", "sheet_note", "FAR_POLE"]

FAR_POLE = 20.0
"""A link whose velocity pole I lies farther than this many mechanism sizes away "nearly
translates" (its poles are shown by arrows, and the sheet says why)."""

LETTERS = {"inflection": "(a)", "bobillier": "(b)", "hartmann": "(c)", "cubic": "(d)"}


def link_title(title: str, link: str) -> str:
    """A sheet's title naming the link whose curvature its figures show.

    Examples
    --------
    >>> link_title("Watt I six-bar", "5")
    'Watt I six-bar: curvature of link 5'
    """
    return f"{title}: curvature of link {link}"


def missing_reasons(lc: Any, shown: list[str]) -> dict[str, str]:
    """Why each curvature figure not in ``shown`` has no steps, in the book's words.

    Parameters
    ----------
    lc : LinkCurvature
        The link's curvature (:func:`graphkin.kinematics.curvature.link_curvature`).
    shown : list of str
        The figures the sheet draws (``inflection``, ``bobillier``, ``hartmann``, ``cubic``).

    Returns
    -------
    dict
        Figure name -> one sentence.
    """
    link = str(lc.link)
    known = sorted(lc.known)
    pins = ", ".join(known) if known else "none"
    out: dict[str, str] = {}
    if "bobillier" not in shown:
        if len(known) < 2:
            out["bobillier"] = (f"(b) Bobillier's construction needs two points of link {link} "
                                f"whose centers of curvature are known by inspection (known: "
                                f"{pins}); J was found from the accelerations (Eq. 4.46)")
        else:
            out["bobillier"] = ("(b) Bobillier's construction is not drawn: the rays from I to "
                                f"{pins} cross too flatly to locate J; J was found from the "
                                "accelerations (Eq. 4.46)")
    if "hartmann" not in shown:
        found = [n for n, how in lc.conjugate_methods.items() if how in ("bobillier", "hartmann")]
        if not found:
            out["hartmann"] = (f"(c) Conjugate points: every point of link {link} ({pins}) has "
                               "its center of curvature known by inspection; name a coupler "
                               "point on the link to see its conjugate constructed")
        else:
            out["hartmann"] = ("(c) Conjugate points: none could be constructed here; their "
                               "values are in the report (Euler-Savary, Eq. 4.43)")
    if "cubic" not in shown:
        if len(known) < 2:
            out["cubic"] = (f"(d) The cubic of stationary curvature needs two points of link "
                            f"{link} whose conjugates are known by inspection (Sec. 4.17)")
        else:
            out["cubic"] = ("(d) The cubic of stationary curvature could not be constructed "
                            "in this posture (Sec. 4.17)")
    return {k: out[k] for k in LETTERS if k in out}


def sheet_note(lc: Any, shown: list[str], extent: list[np.ndarray],
               unit: str, whole: bool, omitted: list[str] | None = None) -> str:
    """The sentences under a curvature sheet's first figure ('' when there is nothing to say).

    ``whole`` is True for the full sheet (``-d curvature``): only then are the
    figures left out listed.  ``extent`` is the mechanism's points (to judge
    how far the poles are).
    """
    parts: list[str] = []
    size = 0.0
    if len(extent) > 1:
        arr = np.asarray(extent, dtype=float)
        size = float(np.max(np.ptp(arr, axis=0)))
        centre = (arr.min(axis=0) + arr.max(axis=0)) / 2
        ip = np.asarray(lc.velocity_pole, dtype=float)[:2]
        jp = np.asarray(lc.inflection_pole, dtype=float)[:2]
        if size > 0 and np.all(np.isfinite(ip)) and \
                float(np.hypot(*(ip - centre))) > FAR_POLE * size:
            u = f" {unit}" if unit else ""
            dj = float(np.hypot(*(jp - ip))) if np.all(np.isfinite(jp)) else math.inf
            parts.append(
                f"Link {lc.link} nearly translates (ω{lc.link} = {fmt(lc.omega, 3)} rad/s): its "
                f"velocity pole I is {far_distance(float(np.hypot(*(ip - centre))))}{u} away"
                + (f" and J {far_distance(dj)}{u} beyond it" if math.isfinite(dj) else "")
                + ", so they and the points found from them are shown by arrows")
    if whole:
        parts.extend(missing_reasons(lc, shown).values())
    if omitted and "hartmann" in shown:
        parts.append(f"(c) constructs the conjugates of the first points only; those of "
                     f"{len(omitted)} more ({', '.join(omitted[:3])}, ...) are in the report "
                     "(graphkin solve)")
    return ". ".join(parts) + ("." if parts else "")
