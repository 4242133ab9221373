"""A cam file as the mechanism its designer means: the cam turning on O2, its follower moved.

A cam file (docs/formats/cam.md) describes one disk cam and its follower; the
mechanism it stands for is the cam (link 2) pinned to the frame at its center
O2 and driven at the file's speed in the file's sense, and the follower (link 4)
on its guide (translating, at the file's offset) or about its pivot O4
(oscillating), joined to the cam by a ``[[cams]]`` entry
(docs/formats/mechanism.md#cams).  ``graphkin live CAMFILE`` opens that
mechanism's turning cam page (Sec. 4.7: the equivalent linkage through the
centers of curvature at the dragged cam angle).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 4.7, 6.2, 6.9-6.10.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

from graphkin.cams.model import Cam, Sense

__all__ = ["START_ANGLE", "cam_mechanism"]

START_ANGLE = 30.0
"""Θ (degrees) at which the page first stands: off the start of the program, where the
pitch curve of the book's examples has a finite center of curvature (Ex 6.6 at 30°)."""


def cam_mechanism(cam: Cam, path: str | Path) -> dict[str, Any]:
    """The mechanism file (as a dict) of the cam file at ``path``: cam 2, follower 4.

    Parameters
    ----------
    cam : Cam
        The cam file's cam (:func:`graphkin.cams.parse.load_cam`).
    path : str or Path
        The cam file; written as the ``[[cams]] file`` key, absolute, so that the
        mechanism (and the page's saved TOML) reads it wherever it is saved.

    Returns
    -------
    dict
        ``[links.1] O2 = [0, 0]`` (and ``O4`` at the file's pivot for an oscillating
        follower), an empty follower ``[links.4]`` (graphkin names its trace point
        ``T4``), one ``[[cams]]`` entry with the default axis (the cam file's +y up),
        and ``[drive]``: the cam at Θ = 30° with ω = the file's speed (1 rad/s when
        it gives none), positive counterclockwise, so negative for a clockwise cam.

    Examples
    --------
    >>> from graphkin.cams.examples import example_6_6
    >>> d = cam_mechanism(example_6_6(), "ex6_6.toml")
    >>> d["drive"]["angle"], d["links"]["1"]
    (30.0, {'O2': [0.0, 0.0]})
    """
    f = cam.follower
    src = str(path)
    sign = 1.0 if cam.sense is Sense.CCW else -1.0
    omega = cam.omega if cam.omega is not None else 1.0
    frame: dict[str, list[float]] = {"O2": [0.0, 0.0]}
    entry: dict[str, Any] = {"link": 2, "follower": 4, "file": str(Path(src).resolve())}
    if f.kind.oscillating:
        frame["O4"] = [float(f.pivot[0]), float(f.pivot[1])]
    title = cam.title or Path(src).stem
    return {"title": title, "units": cam.unit, "links": {"1": frame, "4": {}},
            "cams": [entry],
            # Θ is the cam link's angle turned in the file's sense (axis 90°: no turn)
            "drive": {"link": 2, "angle": sign * START_ANGLE,
                      "omega": sign * math.fabs(omega)}}
