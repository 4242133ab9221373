"""The report of a gear train: every member's motion, the formula method and the book's table.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 7.12-7.16 (Eq. 7.25, Tables 7.3-7.5).
"""

from __future__ import annotations

import re
from fractions import Fraction
from typing import Any

from graphkin.errors import InputError
from graphkin.gears.train import FRAME, Table, Train, TrainSolution, formula, solve, tabular
from graphkin.text import clean, g6, table

__all__ = ["train_json", "train_text", "member_order", "mechanism_train_json",
           "mechanism_train_text", "gear_train_json", "gear_train_text"]


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
        "notes": train.coaxial_notes(),
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
        # a size and its sense, as solve prints ω (ω3 = 91.9764 rad/s cw): never a sign too
        rows.append((m, d["kind"], "" if d["size"] is None else g6(d["size"]),
                     f"{g6(abs(d['omega']))} {u} {d['sense']}".rstrip(), given.strip()))
    lines += table(rows, "  ")
    lines.append(f"\n  {data['freedom']} degree(s) of freedom; counterclockwise positive.")
    lines += [f"  {n}" for n in data["notes"]]
    if data["formula"]:
        lines.append("\nFormula method, Eq. (7.25): θ'_LF/A = (ω_L − ω_A)/(ω_F − ω_A)")
        for f in data["formula"]:
            arm = "frame" if f["arm"] == FRAME else _arm(f["arm"])
            exact = f["fraction"]
            value = "" if "/" not in exact else f" ({g6(f['train_value'])})"
            lines.append(f"  θ'_{_pair(f['last'], f['first'])}/{f['arm']} = {exact}{value}, "
                         f"seen from the {arm}: "
                         f"{w}{f['last']} = {g6(f['omega_last'])} {u}")
    tab = data["table"]
    if tab is not None:
        lines.append(f"\nTabular analysis (Sec. 7.16): {_arm(tab['arm'])}, gear {tab['turned']} "
                     "turned with the arm held")
        head = ["Step"] + [("Arm " if m == tab["arm"] else "Gear ") + m
                           for m in tab["columns"]]
        body = [[r["step"], *r["cells"]] for r in tab["rows"]]
        lines += table([head, *body], "  ")
        lines.append(f"  {w}{tab['arm']} = {g6(clean(tab['omega_arm']))} {u}, "
                     f"{w}{tab['turned']}/{tab['arm']} = "
                     f"{g6(clean(tab['omega_turned_relative']))} {u}")
    return "\n".join(lines) + "\n"


def _omega_unit(units: Any) -> tuple[float, str]:
    """The factor from rad/s to the report's angular-velocity unit, and its name."""
    if units is None:
        return 1.0, "rad/s"
    return float(units.k_omega), str(units.text("omega"))


def mechanism_train_json(sol: Any, units: Any = None) -> dict[str, Any] | None:
    """The train of a solved mechanism's rolling gears, checked against its rolling kinematics.

    The drives' angular velocities are the train's given motions (a fixed gear
    of the frame is given at rest); the train's answer (the mesh equations,
    the formula method and the book's table, Secs. 7.15-7.16) is set beside
    each link's ω from the rolling constructions (``kinematics``), with their
    difference.  None when the mechanism is not a gear train
    (:func:`graphkin.gears.mechanism_train.train_of`) or has no rates, or none at
    this posture (a dead point: the report says so).
    Angular velocities in the report's unit (``units``, an
    :class:`~graphkin.output.units.OutputUnits`; rad/s without one).
    """
    from graphkin.gears.mechanism_train import train_of

    mech = sol.mechanism
    if not mech.has_rates:
        return None
    if any(sol.links[d.link].omega is None for d in mech.drives):
        return None      # no rates at this posture (a dead point: said by the report)
    k, unit = _omega_unit(units)
    given = {d.link: float(sol.links[d.link].omega) * k for d in mech.drives}
    train = train_of(mech, given, unit)
    if train is None:
        return None
    try:
        data = train_json(train)
    except InputError:   # a train the mesh equations do not fix (more inputs than gears)
        return None
    scale = k * max(1.0, *(abs(float(s.omega)) for s in sol.links.values()
                           if s.omega is not None))
    check = {}
    for m, d in data["members"].items():
        lid = m.rstrip("'")
        if lid not in sol.links or sol.links[lid].omega is None:
            continue
        w = float(sol.links[lid].omega) * k
        check[m] = {"rolling": clean(w, 1e-12 * scale), "train": d["omega"],
                    "difference": clean(d["omega"] - w, 1e-12 * scale)}
    data["check"] = check
    return data


def mechanism_train_text(sol: Any, units: Any = None) -> str | None:
    """:func:`mechanism_train_json` as text: the train report and the check."""
    from graphkin.gears.mechanism_train import train_of

    data = mechanism_train_json(sol, units)
    if data is None:
        return None
    mech = sol.mechanism
    k, unit = _omega_unit(units)
    train = train_of(mech, {d.link: float(sol.links[d.link].omega) * k for d in mech.drives},
                     unit)
    assert train is not None
    lines = [train_text(train).rstrip("\n"), "",
             "Check against the rolling-contact kinematics (Sec. 3.7; solved by the "
             f"{'graphic constructions' if sol.method == 'construction' else 'analytic solver'}):"]
    rows = [("member", "ω (rolling)", "ω (train)", "difference")]
    for m, c in data["check"].items():
        rows.append((m, f"{g6(c['rolling'])} {unit}", f"{g6(c['train'])} {unit}",
                     f"{g6(c['difference'])} {unit}"))
    lines += table(rows, "  ")
    worst = max((abs(c["difference"]) for c in data["check"].values()), default=0.0)
    lines.append("  they agree" if worst == 0.0 else f"  largest difference {g6(worst)} {unit}")
    return "\n".join(lines) + "\n"


def gear_train_json(sol: Any, units: Any = None) -> dict[str, Any] | None:
    """The ``gear_train`` section of ``graphkin solve --json`` (:mod:`graphkin.output.sections`).

    :func:`mechanism_train_json` for a mechanism whose rolling contacts form
    a gear train (Secs. 7.15-7.16), else None; angular velocities in the
    report's unit (``--units``; rad/s by default).  A mechanism with no
    rolling contact is passed over at once.
    """
    if not sol.mechanism.rolling:
        return None
    try:
        return mechanism_train_json(sol, units)
    except InputError:   # not a train the book's methods read: `graphkin gears` says why
        return None


def gear_train_text(sol: Any, units: Any = None) -> str | None:
    """The gear-train part of ``graphkin solve``'s text: the book's table and formula method."""
    if gear_train_json(sol, units) is None:
        return None
    return mechanism_train_text(sol, units)


def _pair(last: str, first: str) -> str:
    """The subscript ``LF`` of a train value (Eq. 7.25): ``62`` as the book writes it.

    Names of more than one character are written ``ring,sun``: run together they
    would be ambiguous.
    """
    if len(last) == 1 and len(first) == 1:
        return f"{last}{first}"
    return f"{last},{first}"


def _arm(name: str) -> str:
    """``arm 3``, or ``the arm`` itself when the user named it ``arm`` (not "arm arm")."""
    return name if name.lower().startswith("arm") else f"arm {name}"
