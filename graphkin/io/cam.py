"""A cam's profile to true scale for manufacture: a closed polyline in DXF (ezdxf).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 6.9 (Eqs. 6.30-6.31: "a table of numeric
rectangular coordinate data from which the cam can be machined").
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.layout import layout, stations
from graphkin.cams.model import Cam
from graphkin.errors import InputError
from graphkin.io.dxf import INSUNITS, require_ezdxf

__all__ = ["write_profile_dxf", "chordal_deviation"]


def chordal_deviation(cam: Cam, n: int) -> float:
    """The largest distance between the true profile and the polyline of ``n`` points.

    Each chord of length c on an arc of radius ρ stands off it by ``c²/8|ρ|``.
    """
    th = stations(n)
    c = profile(cam, th)
    chord = np.abs(np.diff(np.append(c.contact, c.contact[:1])))
    with np.errstate(divide="ignore"):
        dev = chord**2 / (8 * np.abs(c.rho))
    return float(np.max(np.where(np.isfinite(dev), dev, 0.0)))


def write_profile_dxf(cam: Cam, path: str | Path, n: int = 360) -> Path:
    """Write the profile (layer PROFILE), the base circle and the shaft's center, to true scale.

    The profile is the graphic layout's contact points at ``n`` equal cam
    angles (:func:`graphkin.cams.layout.layout`), in the cam's own frame, as
    one closed LWPOLYLINE; ``$INSUNITS`` says the file's length unit and the
    header variable ``graphkin_chordal_deviation`` the polyline's largest
    distance from the true profile.
    """
    ezdxf = require_ezdxf()
    pts = layout(cam).contact(stations(n))
    if not np.all(np.isfinite(pts)):
        raise InputError("the profile could not be laid out at every point", file=cam.source)
    doc = ezdxf.new("R2010")
    doc.header["$INSUNITS"] = INSUNITS.get(cam.unit, 0)
    doc.header.custom_vars.append("graphkin_chordal_deviation",
                                  f"{chordal_deviation(cam, n):.3g} {cam.unit}")
    for name, color in (("PROFILE", 7), ("BASE", 5), ("CENTER", 1)):
        doc.layers.add(name, color=color)
    msp = doc.modelspace()
    msp.add_lwpolyline([(float(z.real), float(z.imag)) for z in pts], close=True,
                       dxfattribs={"layer": "PROFILE"})
    msp.add_circle((0.0, 0.0), cam.base, dxfattribs={"layer": "BASE"})
    msp.add_point((0.0, 0.0), dxfattribs={"layer": "CENTER"})
    from ezdxf.document import CONST_MARKER_STRING, CREATED_BY_EZDXF

    doc.ezdxf_metadata()[CREATED_BY_EZDXF] = CONST_MARKER_STRING
    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True
    out = Path(path)
    try:
        doc.saveas(out)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed
    return out
