"""The report of ``graphkin vector``: the case, the marked equation and every solution.

:func:`vector_text` is the textbook-style text, :func:`vector_json` the same
as plain data (what ``--json`` prints); numbers are written by
:mod:`graphkin.text` (six significant digits, the book's ``R∠θ``).

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 and Table 2.2 (the four cases); results are written ``R∠θ`` as in
Sec. 2.10, Example 2.3.
"""

from __future__ import annotations

import math
from typing import Any

from graphkin.kinematics.vector_equation import NAMES, Polar, VectorEquationResult
from graphkin.kinematics.vector_file import VectorFile
from graphkin.text import g6, table

__all__ = ["vector_text", "vector_json"]


def _degrees(rad: float) -> float:
    d = math.degrees(rad)
    return d + 0.0


def _polar_text(p: Polar, units: str | None) -> str:
    assert p.magnitude is not None and p.angle is not None
    unit = f" {units}" if units else ""
    return f"{g6(p.magnitude)}{unit} ∠{g6(_degrees(p.angle))}°"


def vector_text(vf: VectorFile, result: VectorEquationResult, steps: bool = False) -> str:
    r"""The textbook-style report: the case, the marked equation, every solution.

    Examples
    --------
    >>> from graphkin.kinematics.vector_file import loads
    >>> from graphkin.kinematics.vector_equation import solve_vector_equation
    >>> vf = loads('[A]\nmagnitude = 3\n[B]\nmagnitude = 4\n[C]\nmagnitude = 5\nangle = 0')
    >>> r = solve_vector_equation(*vf.knowns.values())
    >>> print(vector_text(vf, r))  # doctest: +NORMALIZE_WHITESPACE
    case 4 of Table 2.2 (Fig. 2.13, two arcs): unknowns θ_A and θ_B
    C(✓✓) = A(✓?) + B(✓?)
    solution 1 (left):   A = 3 ∠53.1301°    B = 4 ∠-36.8699°   C = 5 ∠0°
    solution 2 (right):  A = 3 ∠-53.1301°   B = 4 ∠36.8699°    C = 5 ∠0°
    <BLANKLINE>
    """
    lines = []
    if vf.title:
        lines.append(vf.title)
    case = result.case
    lines.append(f"case {int(case)} of Table 2.2 ({case.figure}, {case.method}): "
                 f"unknowns {' and '.join(result.unknowns)}")
    lines.append(str(result.equation))
    rows = []
    for k, branch in enumerate(result.branches):
        head = f"solution {k + 1}" + (f" ({branch}):" if branch else ":")
        cells = [f"{n} = {_polar_text(p, vf.units)}" for n, p in zip(NAMES, result.polar(k))]
        rows.append([head, *cells])
    lines += table(rows)
    if steps:
        lines.append("")
        lines.append(result.construction.table())
    return "\n".join(lines) + "\n"


def vector_json(vf: VectorFile, result: VectorEquationResult,
                steps: bool = False) -> dict[str, Any]:
    """The report as plain data (what ``--json`` prints)."""

    def polar(p: Polar) -> dict[str, Any]:
        return {"magnitude": p.magnitude,
                "angle_deg": None if p.angle is None else _degrees(p.angle)}

    solutions = []
    for k, branch in enumerate(result.branches):
        entry: dict[str, Any] = {"branch": branch}
        for n, p, v in zip(NAMES, result.polar(k), result.solutions[k]):
            entry[n] = {**polar(p), "x": v.x, "y": v.y}
        solutions.append(entry)
    data: dict[str, Any] = {
        "file": vf.source,
        "title": vf.title,
        "units": vf.units,
        "case": int(result.case),
        "unknowns": list(result.unknowns),
        "figure": result.case.figure,
        "equation": result.equation.to_dict(),
        "knowns": {n: polar(vf.knowns[n]) for n in NAMES},
        "solutions": solutions,
    }
    if steps:
        data["steps"] = result.construction.to_dict()
    return data
