"""Spur gears as Chapter 7 defines them: tooth geometry, the layout of a pair in mesh, checks.

* :mod:`~graphkin.gears.tooth`: one gear (teeth, module, pressure angle,
  addendum, dedendum, cutter offset) and its tooth thickness at any radius;
* :mod:`~graphkin.gears.involute`: the involute constructed step by step
  (Sec. 7.5, Step 6) and in closed form;
* :mod:`~graphkin.gears.mesh`: a pair in mesh laid out as the book lays it
  out (Figs. 7.8-7.9, 7.17-7.21) and measured on the construction;
* :mod:`~graphkin.gears.profile`: the teeth of both gears as outlines to draw;
* :mod:`~graphkin.gears.file`: the gear file (``docs/formats/gears.md``);
* :mod:`~graphkin.gears.analytic`: the book's equations in closed form, the
  independent check the tests compare the constructions with.

References
----------
Uicker, Pennock & Shigley, 5th ed., Chapter 7.
"""

from __future__ import annotations

from graphkin.gears.mesh import Contact, GearPair, MeshLayout, layout, mesh_construction
from graphkin.gears.tooth import Gear, ToothSystem

__all__ = ["Gear", "GearPair", "ToothSystem", "MeshLayout", "Contact", "layout",
           "mesh_construction"]
