"""The live page of a vector file: drag what is given of ``C = A + B`` and the construction redraws.

``graphkin live case4.toml -o page.html`` on a vector file (docs/formats/vector.md)
writes one self-contained HTML file (no network) with the construction of
Sec. 2.8 that ``graphkin vector`` records (Table 2.2, Figs. 2.10-2.13): the
given vector drawn to scale, the line(s) of known direction, the arc(s) of
known magnitude and their intersections, both solutions named as
``graphkin vector`` names them (``behind``/``ahead``, ``left``/``right``), the
chosen one in ink and the other in grey.  The user drags what is given:

* a vector known whole: its tip (the end its step lays off), which sets its
  magnitude and direction;
* a vector of known direction only: the knob on its line (the direction from
  the line's point toward the knob);
* a vector of known magnitude only: the knob on its arc (the radius).

The construction is the recorded one
(:func:`graphkin.kinematics.vector_equation.vector_construction`), written out
as one JavaScript function by :func:`graphkin.construction.jsgen.generate_js`
from the one table of operations (``point``, ``rigid``, ``line_at_angle``,
``circle``, ``intersect_circles``, ``intersect_line_circle``, ``meet``,
``vector``), its magnitudes parameters (``K``) and its known angles inputs
(``I``), and written ``soft``: where the arcs miss the line (or each other, or
the lines are parallel) the intersections are ``null`` and the page says
"no solution" with the reason ``graphkin vector`` gives, never a number.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (Table 2.2, Figs. 2.10-2.13: the four cases and their constructions)
and Sec. 2.11 (the same cases in closed form, Eqs. 2.42-2.50).
"""

from __future__ import annotations

import html
from typing import Any

from graphkin.construction.codegen import Unsupported
from graphkin.construction.jsgen import RUNTIME, generate_js, js_string
from graphkin.errors import InputError
from graphkin.kinematics.vector_equation import NAMES, VectorEquationResult, vector_construction
from graphkin.kinematics.vector_file import VectorFile
from graphkin.render.live import script_json
from graphkin.render.live_toml_js import TOML_JS
from graphkin.render.live_vector_js import VECTOR_APP_JS, VECTOR_CSS
from graphkin.render.style import HIGHLIGHT, STYLES
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["vector_live_data", "vector_live_html"]

# each vector as (origin, terminus) of the triangle O, P, T: C = A + B
# (graphkin.kinematics.vector_equation)
_ENDS = {"A": ("O", "P"), "B": ("P", "T"), "C": ("O", "T")}
_INTERSECTIONS = ("intersect_circles", "intersect_line_circle", "meet")
_STYLE_KEYS = ("vector-abs", "result-line", "vector-aux", "aux-line", "arc", "point",
               "aux-point")


def _record(vf: VectorFile) -> VectorEquationResult:
    try:
        return vector_construction(*(vf.knowns[n] for n in NAMES), branch=vf.branch)
    except InputError as exc:
        raise InputError(exc.message, key=exc.info.get("key"), file=vf.source) from None


def vector_live_data(vf: VectorFile, file_data: dict[str, Any]) -> tuple[dict[str, Any], str]:
    """What the page needs: its data (JSON-able) and the JavaScript of the construction.

    Parameters
    ----------
    vf : VectorFile
        The loaded vector file.
    file_data : dict
        Its parsed TOML (the page saves it back with the edits).

    Returns
    -------
    (dict, str)
        The page's data and the construction written out as the JavaScript
        function ``vectorConstruction(I, K)``.

    Raises
    ------
    InputError
        The file's knowns are not a case of Table 2.2 (as ``graphkin vector``
        says), or its branch is not one of the case's.
    """
    rec = _record(vf)
    steps = rec.construction.steps
    made = [o for s in steps for o in s.outputs if s.op != "input"]
    try:
        fn = generate_js(steps, requests=made, tol=DEFAULT_TOL, name="vectorConstruction",
                         soft=True)
    except Unsupported as exc:  # every operation of Sec. 2.8 has its template: a bug
        raise InputError(f"no live page: {exc}", file=vf.source) from None
    slots = [n for n, _ in fn.slots]
    handles: list[dict[str, Any]] = []
    lines: dict[str, dict[str, str]] = {}
    arcs: dict[str, dict[str, str]] = {}
    results: list[dict[str, Any]] = []
    for s in steps:
        if s.op == "rigid":  # a vector known whole, laid off from `start` to `end` (either sense)
            name = s.inputs[1][len("theta_"):]
            start, end = s.inputs[0], s.outputs[0]
            handles.append({"kind": "vector", "name": name, "start": start, "end": end,
                            "sign": 1.0 if _ENDS[name] == (start, end) else -1.0,
                            "slot": slots.index(f"{end}.0"), "theta": s.inputs[1]})
        elif s.op == "line_at_angle":  # a vector of known direction: its line
            name = s.outputs[0][len("l_"):]
            lines[s.outputs[0]] = {"name": name, "anchor": s.inputs[0]}
            handles.append({"kind": "direction", "name": name, "line": s.outputs[0],
                            "anchor": s.inputs[0], "theta": s.inputs[1]})
        elif s.op == "circle":  # a vector of known magnitude: its arc
            name = s.outputs[0][len("k_"):]
            arcs[s.outputs[0]] = {"name": name, "anchor": s.inputs[0]}
            handles.append({"kind": "magnitude", "name": name, "arc": s.outputs[0],
                            "anchor": s.inputs[0], "slot": slots.index(f"{s.outputs[0]}.0")})
        elif s.op in _INTERSECTIONS:
            results.append({"vertex": s.outputs[0], "op": s.op, "inputs": list(s.inputs),
                            "branch": s.params.get("branch")})
    if not results:  # case 1: the unknown vector closes the triangle of the known ones
        results.append({"vertex": "", "op": "vector", "inputs": [], "branch": None})
    branches = [str(b) for b in rec.branches if b]
    chosen = branches.index(vf.branch) if vf.branch in branches else 0
    known = {n: {"magnitude": vf.knowns[n].magnitude, "angle": vf.knowns[n].angle}
             for n in NAMES}
    case = rec.case
    sizes = [abs(k.magnitude) for k in vf.knowns.values() if k.magnitude is not None]
    data = {
        "title": vf.title or vf.source,
        "unit": vf.units or "",
        "case": int(case),
        "heading": (f"case {int(case)} of Table 2.2 ({case.figure}, {case.method}): "
                    f"unknowns {' and '.join(rec.unknowns)}"),
        "equation": str(rec.equation),
        "known": known,
        # the vertex the construction finds (O, P or T; primed for the second solution)
        "found": results[0]["vertex"].rstrip("'"),
        "handles": handles,
        "lines": lines,
        "arcs": arcs,
        "results": results,
        "branches": branches,
        "chosen": chosen,
        "fileBranch": vf.branch in branches,
        "inputs": dict(rec.inputs),
        "K": fn.values,
        "size": max(sizes, default=1.0) or 1.0,
        "tol": {"abs": DEFAULT_TOL.length_abs, "rel": DEFAULT_TOL.length_rel,
                "angle": DEFAULT_TOL.angle},
        "steps": [f"{s.label}: {s.note}" for s in steps if s.op != "input"],
        "file": file_data,
        "style": {k: STYLES[k] for k in _STYLE_KEYS},
        "highlight": HIGHLIGHT,
    }
    # a vector found whole (case 1) has no vertex of its own: its ends are known points
    data["unknownVector"] = next((n for n in NAMES if not vf.knowns[n].is_known), "") \
        if case == 1 else ""
    return data, RUNTIME + fn.source


def vector_live_html(vf: VectorFile, file_data: dict[str, Any]) -> str:
    r"""The whole page of a vector file, self-contained (one file, no network).

    Examples
    --------
    >>> from graphkin.kinematics.vector_file import loads
    >>> text = '[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n[C]\nmagnitude = 5\nangle = 0\n'
    >>> page = vector_live_html(loads(text), {})
    >>> "vectorConstruction" in page, "<script src" in page, "<link" in page
    (True, False, False)
    """
    data, js = vector_live_data(vf, file_data)
    title = html.escape(str(data["title"]))
    heading = html.escape(str(data["heading"]))
    # the status is under the drawing: a message that comes and goes while a handle is
    # dragged must not move the drawing under the pointer
    equation = html.escape(str(data["equation"]))
    return f"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title} (live)</title>
<style>{VECTOR_CSS}</style></head>
<body>
<header><h1>{title}</h1>
<p class="gk-case">{heading}<br><span class="gk-eq">{equation}</span></p>
<p class="hint">Drag what is given (shaded handles): the tip of a vector known whole, the knob
on a line of known direction, the knob on an arc of known magnitude. The construction of
Sec. 2.8 is re-solved in the page on every move.</p>
<div class="controls"><label>solution <select id="gk-solution"></select></label>
<button id="gk-undo" type="button">Undo</button>
<button id="gk-reset" type="button">Reset</button>
<button id="gk-save" type="button">Save the edited file</button></div></header>
<main><figure><figcaption>Construction ({html.escape(_figure(int(data["case"])))})</figcaption>
<svg id="gk-vector"></svg>
<p id="gk-status" role="status"></p></figure>
<div><table id="gk-table"></table>
<ol id="gk-steps"></ol></div></main>
<script id="gk-data" type="application/json">
{script_json(data)}</script>
<script>
{js}
{TOML_JS}
{VECTOR_APP_JS}
window.graphkinLive = gkVectorApp(document,
  JSON.parse(document.getElementById("gk-data").textContent), {js_string(vf.source)});
</script>
</body></html>
"""


def _figure(case: int) -> str:
    """The book's figure of a case (Fig. 2.10 for case 1 ... Fig. 2.13 for case 4)."""
    return f"Fig. 2.1{case - 1}"
