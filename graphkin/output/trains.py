"""The report of a gear train: every member's motion, the formula method and the book's table.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.12-7.16 (Eq. 7.25, Tables 7.3-7.5).
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Any

from graphkin.gears.train import FRAME, Table, Train, TrainSolution, formula, solve, tabular
from graphkin.text import clean, g6, table

__all__ = ["train_json", "train_text", "member_order"]


def member_order(train: Train) -> list[str]:
    """The members as the book's tables order them: numbers first, by value, then names."""
    def key(m: str) -> tuple[int, float, str]:
        return (0, float(m), m) if re.fullmatch(r"\d+", m) else (1, 0.0, m)

    return sorted(train.members, key=key)


def _sense(w: float, tiny: float) -> str:
    return "" if abs(w) <= tiny else ("ccw" if w > 0 else "cw")


def _fraction(f: Fraction) -> str:
    return str(f.numerator) if f.denominator == 1 else f"{f.numerator}/{f.denominator}"


def _formulas(train: Train, sol: TrainSolution) -> list[dict[str, Any]]:
    """Eq. (7.25) for each arm: from its first gear F to each other gear L it carries.

    A speed at round-off of the train's largest is printed as 0 (Example 7.4's
    fixed gear 6 came out 6.7e-13 rev/min).
    """
    out = []
    tiny = 1e-9 * max(1.0, *(abs(v) for v in sol.omega.values()))
    carriers = list(dict.fromkeys(m.arm for m in train.meshes))
    for arm in carriers:
        gears = list(dict.fromkeys(g for m in train.meshes if m.arm == arm
                                   for g in (m.driver, m.driven)))
        first = gears[0]
        for last in gears[1:]:
            found = formula(train, first, last)
            if found is None:
                continue
            value, _ = found
            out.append({"arm": arm, "first": first, "last": last,
                        "train_value": float(value), "fraction": _fraction(value),
                        "omega_last": clean(sol.omega[last] if last in sol.omega else 0.0,
                                            tiny)})
    return out


def train_json(train: Train) -> dict[str, Any]:
    """The report as plain data (``graphkin gears TRAINFILE --json``)."""
    sol = solve(train)
    tab = tabular(train)
    tiny = 1e-9 * max(1.0, *(abs(v) for v in sol.omega.values()))
    members = {}
    for m in member_order(train):
        w = sol.omega[m]
        w = 0.0 if abs(w) <= tiny else w
        members[m] = {"kind": "gear" if m in train.size else "arm",
                      "size": float(train.size[m]) if m in train.size else None,
                      "omega": w, "sense": _sense(w, tiny)}
    data: dict[str, Any] = {
        "title": train.title, "unit": train.unit,
        "quantity": "turn" if train.turns else "angular velocity",
        "size": "teeth" if train.by_teeth else "radius",
        "freedom": sol.freedom, "members": members,
        "formula": _formulas(train, sol),
        "table": None if tab is None else _table_json(train, tab),
    }
    return data


def _table_json(train: Train, tab: Table) -> dict[str, Any]:
    return {"arm": tab.arm, "turned": tab.turned, "omega_arm": tab.omega_arm,
            "omega_turned_relative": tab.omega_turned,
            "columns": member_order(train),
            "rows": [{"step": r.name, "cells": [r.cells[m] for m in member_order(train)]}
                     for r in tab.rows]}


def train_text(train: Train) -> str:
    """The report as text (``graphkin gears TRAINFILE``)."""
    data = train_json(train)
    u = data["unit"]
    w = "Δθ" if train.turns else "ω"
    lines = [data["title"] or "Gear train", ""]
    rows = [("member", "", "teeth" if data["size"] == "teeth" else "radius", w, "")]
    for m, d in data["members"].items():
        given = " (given)" if m in train.given else ""
        rows.append((m, d["kind"], "" if d["size"] is None else g6(d["size"]),
                     f"{g6(d['omega'])} {u} {d['sense']}".rstrip(), given.strip()))
    lines += table(rows, "  ")
    lines.append(f"\n  {data['freedom']} degree(s) of freedom; counterclockwise positive.")
    if data["formula"]:
        lines.append("\nFormula method, Eq. (7.25): θ'_LF/A = (ω_L − ω_A)/(ω_F − ω_A)")
        for f in data["formula"]:
            arm = "frame" if f["arm"] == FRAME else f"arm {f['arm']}"
            exact = f["fraction"]
            value = "" if "/" not in exact else f" ({g6(f['train_value'])})"
            lines.append(f"  θ'_{f['last']}{f['first']}/{f['arm']} = {exact}{value}, "
                         f"seen from the {arm}: "
                         f"{w}{f['last']} = {g6(f['omega_last'])} {u}")
    tab = data["table"]
    if tab is not None:
        lines.append(f"\nTabular analysis (Sec. 7.16): arm {tab['arm']}, gear {tab['turned']} "
                     "turned with the arm held")
        head = ["Step"] + [("Arm " if m == tab["arm"] else "Gear ") + m
                           for m in tab["columns"]]
        body = [[r["step"], *r["cells"]] for r in tab["rows"]]
        lines += table([head, *body], "  ")
        lines.append(f"  {w}{tab['arm']} = {g6(clean(tab['omega_arm']))} {u}, "
                     f"{w}{tab['turned']}/{tab['arm']} = "
                     f"{g6(clean(tab['omega_turned_relative']))} {u}")
    return "\n".join(lines) + "\n"
