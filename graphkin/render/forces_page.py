"""The forces drawing on a handout page (``draw -d forces --sheet a4|letter``).

The panels of :func:`~graphkin.render.forces_sheet.build_forces_sheet` (the
book's Fig. 11.5 layout) at the 1-2-5 scales that fit, portrait or landscape
by the larger drawing, above the band every handout page has
(:mod:`graphkin.render.handout`): the compact table of each joint force F_ij
and the drive read off the drawing in the force scale bar's unit (the
torque in that unit times the length bar's: lbf·in, N·m), the legend of the
forces' colours and line styles, and the title block naming the mechanism,
"forces", and the length and force scales.

References
----------
Uicker, Pennock & Shigley, 5th ed., Fig. 11.5 (free bodies and force
polygon), Ex 11.1 step 7 (T₁₂ from the arm of F₃₂), Fig. 12.8 (h).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphkin.render.forces_sheet import (
    _SUB,
    DRIVE,
    GREY_INK,
    INERTIA,
    JOINT,
    LOAD,
    Force,
    ForceSheet,
    build_forces_sheet,
    couples_on,
    label_text,
)
from graphkin.render.scale import Scale, fmt
from graphkin.render.sheet import Sheet
from graphkin.render.table import Table

if TYPE_CHECKING:
    from graphkin.forces.solve import ForceSolution
    from graphkin.render.handout import Page
    from graphkin.render.legend import LegendEntry

__all__ = ["page_table", "page_legend", "paper_forces_sheet", "FORCE_BIGS"]


def page_table(fs: ForceSolution, lscale: Scale, fscale: Scale,
               known: set[str] | None = None) -> Table | None:
    """A handout page's compact table: each F_ij and the drive read off the drawing.

    Magnitudes in the force scale bar's unit (lbf, N, kN), the drive's torque
    in that unit times the length scale bar's (lbf·in), directions as angles
    from the x axis, torques with their sense; no analytic column.  With
    ``known`` (the outputs of the steps drawn, ``--upto``) only the answers
    the construction has reached.
    """
    from graphkin.render.forces import force_name

    mech = fs.mechanism
    fu, ff = fscale.unit, fscale.factor
    tu, tf = f"{fscale.unit}·{lscale.unit}", fscale.factor * lscale.factor
    big = {"mm": ("m", 1000.0), "cm": ("m", 100.0)}.get(lscale.unit)
    if big is not None and any(w == "torque" and abs(t) / tf >= big[1]
                               for w, t in fs.drives.values()):
        tu, tf = f"{fscale.unit}·{big[0]}", tf * big[1]  # 18 260 N·mm written 18.26 N·m

    def reached(*labels: str) -> bool:
        return known is None or any(n in known for n in labels)

    def short(x: float) -> str:
        r = float(f"{x:.4g}")
        return fmt(r, 4, trim=False) if abs(r) >= 1e-3 or r == 0 else fmt(r, 3)

    def angle(v: np.ndarray) -> str:
        d = math.degrees(math.atan2(float(v[1]), float(v[0])))  # (-180, 180]
        d = 180.0 if d <= -179.95 else 0.0 if abs(d) < 0.05 else d  # no "-180.0", "-0.0"
        return f"∠{d:.1f}°"

    cells: list[tuple[str, ...]] = []
    keys: list[str] = []
    for j in fs.joints:
        if not reached(j.label(j.hi), j.label(j.lo)):
            continue
        v = fs.forces[j.key][:2]
        size = float(np.hypot(*v))
        cells.append((force_name(j.label(j.hi)), short(size / ff),
                      angle(v) if size > 0 else "", fu))
        keys.append(f"F_{j.key}")
    for lid, (what, val) in fs.drives.items():
        if what == "torque":
            if not reached(f"T_1{lid}"):
                continue
            cells.append((f"T1{lid}".translate(_SUB), short(abs(val) / tf),
                          fs.sense(val), tu))
            keys.append(f"T_1{lid}")
        else:
            d = next(d for d in mech.drives if d.link == lid)
            if d.slider is None or not reached(f"F_{d.slider.point}·u"):
                continue
            key = next(j.key for j in fs.joints if j.source is d.slider)
            u = fs.geometry.along[key] * (1.0 if val >= 0 else -1.0)
            cells.append((label_text(f"F_{d.slider.point}"), short(abs(val) / ff),
                          angle(u) if val else "", fu))
            keys.append(f"F_drive_{lid}")
    if not cells:
        return None
    return Table(("quantity", "value", "direction", "unit"), cells, keys,
                 ("left", "right", "left", "left"), title="Results read off the construction")


def page_legend(fs: ForceSolution, on: dict[str, list[Force]]) -> list[LegendEntry]:
    """A handout page's legend: the links and the forces' colours and line styles drawn."""
    from graphkin.render.legend import LegendEntry

    mech = fs.mechanism
    colours = {f.color for fl in on.values() for f in fl}
    out = [LegendEntry("legend-link", "link", "link, pin joint"),
           LegendEntry("legend-joint-force", "vector-abs", "joint force $F_{ij}$, by i on j",
                       color=JOINT)]
    if LOAD in colours or any(couples_on(fs, lid) for lid in mech.moving):
        out.append(LegendEntry("legend-load", "vector-abs", "given load (force, couple)",
                               color=LOAD))
    if INERTIA in colours:
        out.append(LegendEntry("legend-inertia", "vector-abs",
                               "inertia force $-mA_{G}$, offset h", color=INERTIA))
    if fs.drives:
        out.append(LegendEntry("legend-drive", "vector-abs", "drive (torque or force)",
                               color=DRIVE))
    if any(f.along is not None for fl in on.values() for f in fl):
        out.append(LegendEntry("legend-components", "vector-n",
                               "normal and friction components", color=GREY_INK))
    out.append(LegendEntry("legend-line-of-action", "datum", "line of action",
                           color="#7a7a7a"))
    if mech.rolling:
        out.append(LegendEntry("legend-result-arc", "result-arc", "pitch circle, wheel"))
    return out


def _unbroken(part: str) -> str:
    """``lengths 1 cm = 50 mm`` with no-break spaces in the scale (never cut before its unit)."""
    what, _, scale = part.partition(" ")
    return f"{what} {scale.replace(' ', chr(0xA0))}"


FORCE_BIGS = (6.0, 5.0, 4.2, 3.8, 3.4, 2.9, 2.4, 2.0, 1.7, 1.4, 1.2, 1.0, 0.8)
"""The largest side of the mechanism panel tried on a handout page, in inches."""


def paper_forces_sheet(fs: ForceSolution, paper: str, *, upto: int | None = None,
                       table: bool = True) -> ForceSheet:
    """The forces drawing on one page of ``paper``, laid out as every other handout page.

    The panels at the 1-2-5 scales that fit, portrait or landscape by the
    larger drawing, above the handout band
    (:func:`graphkin.render.handout.arrange_on_paper`): the compact table of
    the F_ij and the drive read off the drawing in the force scale's unit,
    the legend of the forces' colours, and the title block (mechanism,
    "forces", the length and force scales).

    Raises
    ------
    DiagramUnavailable
        ``paper`` is not a known size.
    """
    from graphkin.render.handout import Page, arrange_on_paper, block_lines, place_on_page

    built: dict[float, ForceSheet] = {}

    def build(big: float) -> Sheet:
        if big not in built:
            built[big] = build_forces_sheet(fs, upto=upto, table=table, paper=paper, big=big)
        return built[big].sheet

    def which(sheet: Sheet) -> ForceSheet:
        return next(f for f in built.values() if f.sheet is sheet)

    def band(sheet: Sheet) -> Page:
        f = which(sheet)
        block = block_lines([
            (sheet.title, "bold", 3),
            ("Diagram: forces (mechanism and loads, free bodies, force polygons)",
             "normal", 2),
            ("Scales: " + "; ".join(_unbroken(part) for part in f.scales.split(";  ")),
             "normal", 3),
            ("Values in the units of the scale bars.", "normal", 1)])
        return Page(paper, table=f.table, legend=list(f.legend), block=block)

    f = which(arrange_on_paper(build, band, paper, FORCE_BIGS))
    # the force polygons one 1-2-5 step larger at a time while the page has room
    big = next(b for b, g in built.items() if g is f)
    grow = 1.0
    for _ in range(4):
        fscale = next(p.scale for p in f.sheet.panels if p.name.startswith("polygon-")
                      and p.scale is not None) if any(
            p.name.startswith("polygon-") for p in f.sheet.panels) else None
        if fscale is None:
            break
        mant = fscale.value / 10 ** math.floor(math.log10(fscale.value) + 1e-9)
        grow *= (2.5 if abs(mant - 5.0) < 1e-6 else 2.0) * (1 + 1e-6)  # 5 -> 2, 2 -> 1, 1 -> .5
        trial = build_forces_sheet(fs, upto=upto, table=table, paper=paper, big=big,
                                   force_grow=grow)
        built[-grow] = trial  # (kept findable by band())
        if place_on_page(trial.sheet, band(trial.sheet), f.sheet.size) is None:
            break
        f = trial
    return f
