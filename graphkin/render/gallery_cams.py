"""The gallery's cam files (``gallery/cams/``): Examples 6.1-6.8 drawn and compared with the book.

Read by :mod:`graphkin.render.gallery` (its ``CHAPTERS`` table): each cam file
(docs/formats/cam.md) with a ``[gallery]`` table gives its drawings (``diagrams``:
``layout``, ``displacement``, ``design``; default ``layout``) and the numbers its
``[[gallery.book]]`` rows name, looked up in the dict :func:`solution` builds:

* everything ``graphkin cam FILE --json`` reports (:func:`graphkin.cams.report.cam_json`):
  ``pressure_angle.max``, ``radius_of_curvature.min``, ``face.min_width``,
  ``min_prime_for_pressure_angle.prime``, ``min_prime_for_radius.prime``,
  ``rates.velocity.max``, ``jump.omega``...;
* ``segments.<k>``: segment k (from 0) as reported (``angle``, ``lift``...) and
  ``pressure_max``, its largest |φ| (degrees);
* ``coefficients.y1_max``, ``y1_min``, ``y2_max``, ``y2_min``, ``y3_max``: the
  kinematic coefficients' extremes over the turn;
* ``at.<Θ>`` for every whole degree Θ: ``Y``, ``y1``, ``y2``, ``y3``, ``contact``
  ([u, v] in the cam's frame), ``pitch`` ([u, v], roller and knife edge), ``rho``
  and ``rho_pitch`` (positive where convex), ``pressure`` (degrees), and with the
  cam's speed ``velocity`` and ``acceleration`` (Eq. 6.11).

References
----------
Uicker, Pennock & Shigley, 5th ed., Examples 6.1-6.8.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.design import GRID
from graphkin.cams.layout import stations
from graphkin.cams.model import Cam
from graphkin.cams.parse import CamFile, load_cam
from graphkin.cams.report import cam_json
from graphkin.errors import GraphkinError, InputError

__all__ = ["render_entry", "solution", "DIAGRAMS"]

DIAGRAMS = ("layout", "displacement", "design")
"""The drawings a cam's gallery file may ask for (``[gallery] diagrams``)."""


def _num(x: Any) -> float | None:
    v = float(x)
    return v if math.isfinite(v) else None


def solution(cf: CamFile) -> dict[str, Any]:
    """The numbers a cam gallery file's ``[[gallery.book]]`` paths are looked up in.

    Examples
    --------
    Ex 6.6 at Θ = 30°: the contact point (23.473, 29.139) mm, ρ = 60.757 mm (convex),
    φ = 28.68°.

    >>> from graphkin.cams.parse import load_cam
    >>> d = solution(load_cam("examples/cams/ex6_6_roller.toml"))
    >>> [round(c, 3) for c in d["at"]["30"]["contact"]], round(d["at"]["30"]["pressure"], 2)
    ([23.473, 29.139], 28.68)
    """
    cam = cf.cam
    out = cam_json(cf)
    ang = cam.follower.kind.oscillating
    deg = np.arange(360.0)
    th = np.radians(deg)
    k = cam.program.evaluate(th)
    pr = profile(cam, th)
    sc = math.degrees(1.0) if ang else 1.0        # an oscillating follower's lift in degrees
    at: dict[str, Any] = {}
    for i in range(360):
        row: dict[str, Any] = {"Y": float(k.Y[i]) * sc, "y1": float(k.y1[i]) * sc,
                               "y2": float(k.y2[i]) * sc, "y3": float(k.y3[i]) * sc,
                               "contact": [_num(pr.contact[i].real), _num(pr.contact[i].imag)],
                               "rho": _num(pr.rho[i]),
                               "pressure": _num(math.degrees(float(pr.pressure[i])))}
        if pr.pitch is not None and pr.rho_pitch is not None:
            row["pitch"] = [_num(pr.pitch[i].real), _num(pr.pitch[i].imag)]
            row["rho_pitch"] = _num(pr.rho_pitch[i])
        if cam.omega is not None:         # at the cam's speed (Eq. 6.11)
            row["velocity"] = row["y1"] * cam.omega
            row["acceleration"] = row["y2"] * cam.omega**2
        at[str(i)] = row
    out["at"] = at
    fine = stations(GRID)
    kf = cam.program.evaluate(fine)
    out["coefficients"] = {"y1_max": float(kf.y1.max()) * sc, "y1_min": float(kf.y1.min()) * sc,
                           "y2_max": float(kf.y2.max()) * sc, "y2_min": float(kf.y2.min()) * sc,
                           "y3_max": float(np.abs(kf.y3).max()) * sc}
    phi = np.abs(profile(cam, fine).pressure)
    for j, seg in enumerate(out["segments"]):
        inside = kf.segment == j
        seg["pressure_max"] = float(np.degrees(np.nanmax(phi[inside]))) if inside.any() \
            else None
    out["segments"] = {str(j): seg for j, seg in enumerate(out["segments"])}  # by index
    return out


def render_entry(entry: Any) -> tuple[dict[str, bytes], dict[str, Any]]:
    """The drawings of a cam gallery file (name -> compact SVG bytes) and its numbers.

    Raises
    ------
    InputError
        An unknown diagram, or a cam the design checks refuse (one line naming the file).
    """
    from graphkin.render.cams import design_figure, displacement_figure, layout_figure
    from graphkin.render.gallery import compact_svg
    from graphkin.render.style import rc_context
    from graphkin.render.svg import to_bytes

    draw: dict[str, Callable[[Cam], Any]] = {"layout": layout_figure,
                                             "displacement": displacement_figure,
                                             "design": design_figure}
    cf = load_cam(entry.path)
    wanted = [str(d) for d in entry.meta.get("diagrams", ["layout"])]
    drawings = {}
    for d in wanted:
        if d not in DIAGRAMS:
            raise InputError(f"a cam is drawn as {', '.join(DIAGRAMS)}, not {d!r}",
                             key="gallery.diagrams", file=str(entry.path))
        try:
            with rc_context():
                fig = draw[d](cf.cam)
            data = to_bytes(fig)
        except GraphkinError as exc:
            raise InputError(f"cannot draw the {d}: {exc}", file=str(entry.path)) from None
        drawings[f"{entry.stem}-{d}.svg"] = compact_svg(data)
    return drawings, {"title": cf.cam.title, "solution": solution(cf), "method": "analytic",
                      "has_rates": cf.cam.omega is not None}
