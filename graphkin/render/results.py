"""The results table of a sheet: each value read off the construction beside the analytic one.

A drawing proves itself on its face: every angle, angular rate, velocity
and acceleration the construction found is listed with the value of the
independent analytic solver (Newton-Raphson on the loop-closure equations,
:func:`graphkin.kinematics.analytic.solve_analytic`) and their relative
difference.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.9-2.11, 3.9 and 4.9 (the analytic
solutions the graphic ones are checked against).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from graphkin.errors import GraphkinError
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME
from graphkin.render.paint import _is_joint_or_named_point
from graphkin.render.scale import fmt, fmt_angle
from graphkin.render.scene import finite_xy, sub_digits
from graphkin.render.sources import Source
from graphkin.render.table import Table
from graphkin.text import degrees_text
from graphkin.tolerance import VERDICT_REL

__all__ = ["Row", "result_rows", "analytic_solution", "AGREE", "ROUND_OFF", "diff_text"]

AGREE = 1e-6
"""Relative difference below which a value is marked as agreeing (✓)."""

ROUND_OFF = 1e-9
"""Relative differences below this are floating-point round-off and print as 0.

The construction and the analytic solver reach the same number by different
arithmetic; their last bits differ from one machine (BLAS, libm, CPU) to
another.  Printing that round-off would make a drawing differ between
machines, so the tables print it as 0.
"""


def diff_text(diff: float | None) -> str:
    """A relative difference as printed in a results table (round-off as ``0``).

    >>> diff_text(5.8e-13), diff_text(2.5e-4), diff_text(None)
    ('0', '2.5e-04', '—')
    """
    if diff is None:
        return "—"
    return "0" if diff < ROUND_OFF else f"{diff:.1e}"


@dataclass(frozen=True)
class Row:
    """One line of the results table.

    Attributes
    ----------
    key : str
        ``theta3``, ``omega3``, ``V_C``...: a stable id for the row.
    quantity : str
        As printed (``ω₃``, ``V_C``).
    unit : str
    drawn, exact : str
        The construction's value and the analytic one, formatted.
    diff : float or None
        Relative difference (None when there is no analytic value).
    """

    key: str
    quantity: str
    unit: str
    drawn: str
    exact: str
    diff: float | None
    drawn_value: tuple[float, ...] = ()
    exact_value: tuple[float, ...] = ()


def analytic_solution(sol: Solution, unit_rates: bool = False) -> Solution | None:
    """The analytic solution on the construction's branch (None when it cannot be had).

    Newton's method starts from the construction's posture, so both describe
    the same assembly; the values are then computed independently.  With
    ``unit_rates`` every drive gets a unit rate when the file gives none (the
    instant centers of one degree of freedom do not depend on the input speed).
    """
    try:
        from graphkin.kinematics.analytic import solve_analytic
    except ImportError:  # pragma: no cover - the solver ships with graphkin
        return None
    guess = {lid: (float(st.origin[0]), float(st.origin[1]), float(st.angle))
             for lid, st in sol.links.items() if lid != FRAME}
    mech = sol.mechanism
    if unit_rates and not mech.has_rates:
        mech = replace(mech, rates=None,
                       drives=tuple(replace(d, rate=1.0, rate2=0.0) for d in mech.drives))
    try:
        return solve_analytic(mech, guess=guess)
    except (GraphkinError, ValueError, ArithmeticError):
        return None


def _rel(d: np.ndarray | float, e: np.ndarray | float, scale: float) -> float:
    """|d - e| relative to |e|, or to ``scale`` (a thousandth of the diagram's size) if larger."""
    diff = float(np.hypot(*np.atleast_1d(np.asarray(d) - np.asarray(e))[:2])) \
        if np.ndim(d) else abs(float(d) - float(e))
    size = float(np.hypot(*np.atleast_1d(e)[:2])) if np.ndim(e) else abs(float(e))
    return diff / max(size, scale, 1e-300)


def result_rows(src: Source, diagrams: list[str], exact: Solution | None = None) -> list[Row]:
    """The rows for the given diagrams (posture, velocity, acceleration).

    Parameters
    ----------
    src : Source
    diagrams : list of str
    exact : Solution, optional
        The analytic solution (computed when not given).
    """
    sol = src.solution
    if sol is None:
        return []
    mech = sol.mechanism
    if exact is None:
        exact = analytic_solution(sol)
    unit = mech.length_unit
    rows: list[Row] = []
    names = [n for n in mech.point_names
             if FRAME not in mech.point_links[n] and _is_joint_or_named_point(mech, n)]
    for d in diagrams:
        vals = src.values.get(d, {})
        if d == "posture":
            for lid in mech.moving:
                lab = f"θ{lid}"
                v = vals.get(lab)
                th = float(v) if v is not None else float(sol.angle_rad(lid))
                e = None if exact is None else float(exact.angle_rad(lid))
                diff = None if e is None else abs(math.remainder(th - e, 2 * math.pi))
                rows.append(Row(f"theta{lid}", "θ" + sub_digits("x" + lid)[1:], "deg",
                                degrees_text(th), "—" if e is None else degrees_text(e),
                                diff, (th,), () if e is None else (e,)))
            for n in names:
                p = finite_xy(vals[n]) if n in vals else np.asarray(sol.position(n))
                if p is None:
                    continue
                ep = None if exact is None else np.asarray(exact.position(n), dtype=float)
                # a coordinate below a millionth of the mechanism's size is 0 on any drawing
                # (as the curvature rows): its digits would be the last digits of a solve
                tiny = 1e-6 * mech.scale
                rows.append(Row(f"R_{n}", f"R_{n}", unit, _pair(p, tiny),
                                "—" if ep is None else _pair(ep, tiny),
                                None if ep is None else _rel(p, ep, 1e-3 * mech.scale),
                                tuple(map(float, p)), () if ep is None else tuple(map(float, ep))))
        elif d in ("velocity", "acceleration"):
            sym, img, pole = ("ω", "v", "o_v") if d == "velocity" else ("α", "a", "o_a")
            qunit = "rad/s" if d == "velocity" else "rad/s²"
            vunit = f"{unit}/s" if d == "velocity" else f"{unit}/s²"
            tiny = 1e-9 * max([1.0, *(abs(float(vals[f"{sym}{x}"])) for x in mech.moving
                                      if f"{sym}{x}" in vals)])
            for lid in mech.moving:
                v = vals.get(f"{sym}{lid}")
                if v is None:
                    continue
                w = float(v)
                e = None
                if exact is not None:
                    e = float(exact.omega(lid) if d == "velocity" else exact.alpha(lid))
                rows.append(Row(f"{'omega' if d == 'velocity' else 'alpha'}{lid}",
                                sym + sub_digits("x" + lid)[1:], qunit, _rate(w, tiny),
                                "—" if e is None else _rate(e, tiny),
                                # both print as 0: any difference is round-off, shown as 0
                                None if e is None else 0.0 if max(abs(w), abs(e)) <= tiny
                                else _rel(np.float64(w), np.float64(e), tiny * 1e6),
                                (w,), () if e is None else (e,)))
            o = finite_xy(vals[pole]) if pole in vals else None
            sizes = [float(np.hypot(*(finite_xy(vals[f"{img}({n})"]) - o))) for n in names
                     if o is not None and f"{img}({n})" in vals
                     and finite_xy(vals[f"{img}({n})"]) is not None]
            vscale = 1e-3 * max([0.0, *sizes])
            for n in names:
                lab = f"{img}({n})"
                if lab not in vals or o is None:
                    continue
                p = finite_xy(vals[lab])
                if p is None:
                    continue
                vec = p - o
                evec = None
                if exact is not None:
                    evec = np.asarray(exact.velocity(n) if d == "velocity"
                                      else exact.acceleration(n), dtype=float)
                rows.append(Row(f"{'V' if d == 'velocity' else 'A'}_{n}",
                                f"{'V' if d == 'velocity' else 'A'}_{n}", vunit,
                                _polar(vec, vscale * 1e-6),
                                "—" if evec is None else _polar(evec, vscale * 1e-6),
                                None if evec is None else _rel(vec, evec, vscale),
                                tuple(map(float, vec)),
                                () if evec is None else tuple(map(float, evec))))
        elif d == "centers":
            rows.extend(_center_rows(src, exact, unit))
        elif d == "curvature":
            rows.extend(_curvature_rows(src, exact, unit))
    return rows


def _body(exact: Solution, lid: str, world: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Velocity and acceleration of the point of link ``lid`` at ``world`` (Eqs. 3.4, 4.5)."""
    st = exact.links[lid]
    c, s = math.cos(float(st.angle)), math.sin(float(st.angle))
    d = np.asarray(world, dtype=float) - np.asarray(st.origin, dtype=float)
    local = np.array([c * d[0] + s * d[1], -s * d[0] + c * d[1]])
    return np.asarray(st.velocity(local), dtype=float), np.asarray(st.acceleration(local),
                                                                   dtype=float)


def equal_velocity_point(exact: Solution, i: str, j: str) -> np.ndarray | None:
    """Where links ``i`` and ``j`` have the same velocity: their instant center, homogeneous.

    From ``V_i(X) = V_j(X)`` with ``V(X) = V(0) + ω k × X`` (Eq. 3.4):
    ``k × X = -(V_i(0) - V_j(0))/(ω_i - ω_j)``; when ``ω_i = ω_j`` the center
    is at infinity, perpendicular to the difference of velocities.  None when
    the two have no relative motion at this posture (a block at the end of its
    travel on a link turning with it): every point has the same velocity on
    both, and a direction taken from a difference of velocities that is
    round-off would be any direction.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.12 (the definition of an instant center).
    """
    vi, _ = _body(exact, i, np.zeros(2))
    vj, _ = _body(exact, j, np.zeros(2))
    dv = vi - vj
    dw = float(exact.omega(i)) - float(exact.omega(j))
    # the speeds of the two links: at the origin, and turning about it over the mechanism
    size = max(float(np.hypot(*vi)), float(np.hypot(*vj)), 1e-300,
               abs(float(exact.omega(i))) * exact.mechanism.scale,
               abs(float(exact.omega(j))) * exact.mechanism.scale)
    if abs(dw) * exact.mechanism.scale <= 1e-12 * size:
        if float(np.hypot(*dv)) <= VERDICT_REL * size:
            return None
        return np.array([-dv[1], dv[0], 0.0]) / max(float(np.hypot(*dv)), 1e-300)
    w = -dv / dw
    return np.array([w[1], -w[0], 1.0])


def _center_rows(src: Source, exact: Solution | None, unit: str) -> list[Row]:
    ic = src.extras.get("centers")
    vals = src.values.get("centers", {})
    rows: list[Row] = []
    if ic is None:
        return rows
    sol = src.solution
    assert sol is not None  # result_rows returns early without a solution
    scale = 1e-3 * sol.mechanism.scale
    if exact is not None and not exact.has_rates:
        exact = analytic_solution(sol, unit_rates=True)
    for c in getattr(ic, "centers", {}).values():
        lab = c.label
        if lab not in vals:
            continue
        p = np.asarray(vals[lab], dtype=float)
        e = None
        if exact is not None and exact.has_rates:
            from graphkin.kinematics.instant_centers.primary import far_as_ideal

            q = equal_velocity_point(exact, *c.pair)
            e = None if q is None else far_as_ideal(q, sol.mechanism)
        rows.append(Row(f"center-{lab}", lab, unit, _homog(p, scale * 1e-6),
                        "—" if e is None else _homog(e, scale * 1e-6),
                        None if e is None else _homog_diff(p, e, scale),
                        tuple(map(float, p)), () if e is None else tuple(map(float, e))))
    return rows


def _curvature_rows(src: Source, exact: Solution | None, unit: str) -> list[Row]:
    lc = src.extras.get("curvature")
    vals = src.values.get("curvature", {})
    if lc is None or exact is None or not exact.has_accelerations:
        return []
    lid = lc.link
    mech = exact.mechanism
    scale = 1e-3 * mech.scale
    w = float(exact.omega(lid))
    al = float(exact.alpha(lid))
    st = exact.links[lid]
    rows: list[Row] = []
    ie = equal_velocity_point(exact, lid, FRAME)
    if ie is None or abs(ie[2]) < 1e-12:
        return rows
    i_xy = ie[:2] / ie[2]
    a_i = _body(exact, lid, i_xy)[1]
    j_xy = i_xy + a_i / w**2  # Eq. 4.46: A_I = ω² R_JI, from I toward J
    a0 = _body(exact, lid, np.zeros(2))[1]
    m = np.array([[-w**2, -al], [al, -w**2]])
    gamma = np.linalg.solve(m, -a0)  # A(X) = A(0) + α k × X - ω² X = 0
    expected: dict[str, np.ndarray] = {"I": i_xy, "J": j_xy, "Γ": gamma}
    for n in mech.links[lid].points:
        v, a = st.velocity(mech.links[lid].points[n]), st.acceleration(mech.links[lid].points[n])
        v, a = np.asarray(v, dtype=float), np.asarray(a, dtype=float)
        cr = float(v[0] * a[1] - v[1] * a[0])
        sp = float(np.hypot(*v))
        if sp == 0 or abs(cr) <= 1e-12 * sp * float(np.hypot(*a)) + 1e-300:
            continue
        rho = sp**3 / cr  # signed: the center is to the left of V when positive
        nrm = np.array([-v[1], v[0]]) / sp
        expected[f"{n}'"] = np.asarray(exact.position(n, lid), dtype=float) + rho * nrm
    for lab, e in expected.items():
        if lab not in vals:
            continue
        p = finite_xy(vals[lab])
        if p is None:
            continue
        rows.append(Row(f"curvature-{safe_label(lab)}", lab, unit, _pair(p, scale * 1e-6),
                        _pair(e, scale * 1e-6),
                        _rel(p, e, scale), tuple(map(float, p)), tuple(map(float, e))))
    if "I" in vals and "J" in vals:
        p_i, p_j = finite_xy(vals["I"]), finite_xy(vals["J"])
        if p_i is not None and p_j is not None:
            d = float(np.hypot(*(p_j - p_i)))
            de = float(np.hypot(*(j_xy - i_xy)))
            rows.append(Row("curvature-inflection-diameter", "|IJ|", unit, fmt(d, 6), fmt(de, 6),
                            abs(d - de) / max(de, scale), (d,), (de,)))
    return rows


def safe_label(text: str) -> str:
    """A label as a row id."""
    return "".join(ch if ch.isalnum() else "_" for ch in text)


def _homog(p: np.ndarray, tiny: float = 0.0) -> str:
    q = finite_xy(p)
    if q is not None:
        return _pair(q, tiny)
    d = np.asarray(p[:2], dtype=float)
    n = float(np.hypot(*d))
    if n == 0:
        return "—"
    d = d / n
    # a component at round-off of the unit direction is none (a direction (±1e-11, 1)
    # printed with its sense decided by the last digits read "(0, 1)" or "(0, -1)")
    d = np.where(np.abs(d) < VERDICT_REL, 0.0, d)
    if d[0] < 0 or (d[0] == 0 and d[1] < 0):
        d = -d
    return f"∞ along ({fmt(d[0], 4)}, {fmt(d[1], 4)})"


def _homog_diff(p: np.ndarray, e: np.ndarray, scale: float) -> float:
    a, b = finite_xy(p), finite_xy(e)
    if a is not None and b is not None:
        return _rel(a, b, scale)
    if a is None and b is None:
        u, v = np.asarray(p[:2], dtype=float), np.asarray(e[:2], dtype=float)
        nu, nv = float(np.hypot(*u)), float(np.hypot(*v))
        if nu == 0.0 or nv == 0.0:  # a direction not known ("—") is no direction
            return 0.0 if nu == nv else math.inf
        u, v = u / nu, v / nv
        return abs(float(u[0] * v[1] - u[1] * v[0]))
    return math.inf


def _g6(x: float) -> str:
    """Six significant figures at every scale: ``25.3828``, ``3.14159e-5``, ``2.5e9``.

    :func:`fmt` shortens a number it writes with an exponent (a drawing's
    label); a results table keeps the same figures at a nanometre's scale as
    at a metre's.
    """
    x = float(x)
    if x == 0 or not math.isfinite(x) or 1e-4 <= abs(x) < 1e9:
        return fmt(x, 6)
    mantissa, _, exp = f"{x:.6g}".partition("e")
    return f"{mantissa}e{int(exp)}"


def _pair(p: np.ndarray, tiny: float = 0.0) -> str:
    x, y = (0.0 if abs(float(c)) <= tiny else float(c) for c in p[:2])
    return f"({_g6(x)}, {_g6(y)})"


def _rate(w: float, tiny: float = 0.0) -> str:
    if abs(w) <= tiny:
        return "0"
    return f"{_g6(abs(w))} {'ccw' if w > 0 else 'cw'}"


def _polar(v: np.ndarray, tiny: float = 0.0) -> str:
    m = float(np.hypot(*v))
    if m <= tiny:
        return "0"
    return f"{_g6(m)} {fmt_angle(math.atan2(v[1], v[0]))}"


ROW_DIAGRAM = (("theta", "posture"), ("R_", "posture"), ("omega", "velocity"),
               ("V_", "velocity"), ("alpha", "acceleration"), ("A_", "acceleration"),
               ("center-", "centers"), ("curvature-", "curvature"))
"""Row key prefix -> the diagram the row's value is read off."""


def row_diagram(key: str) -> str:
    """The diagram a row belongs to (``V_B`` -> ``velocity``).

    >>> row_diagram("V_B"), row_diagram("center-I13"), row_diagram("theta3")
    ('velocity', 'centers', 'posture')
    """
    for prefix, d in ROW_DIAGRAM:
        if key.startswith(prefix):
            return d
    return ""


def scale_factor(file_unit: str, shown: str) -> float:
    """File units -> the unit a scale bar is written in (``in/s`` -> ``ft/s``: 1/12), by pint.

    >>> round(scale_factor("in/s", "ft/s"), 12), scale_factor("mm/s²", "m/s²")
    (0.083333333333, 0.001)
    """
    if file_unit == shown:
        return 1.0
    from graphkin.units import registry

    ureg = registry()

    def q(u: str) -> Any:
        return ureg.Quantity(1.0, u.replace("²", "**2").replace("^2", "**2"))

    return float(q(file_unit).to(q(shown).units).magnitude)


def _short(x: float) -> str:
    """A value read off a drawing: four significant figures (``31.42``, ``1819``, ``10.00``)."""
    if x == 0 or not math.isfinite(x):
        return fmt(x)
    r = float(f"{x:.4g}")  # 9.99995 rounds to 10.00, not 10.000
    return fmt(r, 4, trim=False) if abs(r) >= 1e-3 else fmt(r, 3)


def _dir(rad: float) -> str:
    return f"∠{degrees_text(rad, 1)}°"


def quantity_text(row: Row) -> str:
    """A row's quantity as a table prints it, subscripts as subscripts (``V_B`` -> ``$V_{B}$``)."""
    from graphkin.render.text import math_escape, plain

    for prefix, letter in (("V_", "V"), ("A_", "A"), ("R_", "R")):
        if row.key.startswith(prefix):
            esc = math_escape(row.key[len(prefix):])
            if esc:
                return f"${letter}_{{{esc}}}$"
    if row.key.startswith("center-") and row.quantity[:1] == "I" and row.quantity[1:].isdigit():
        return "I" + row.quantity[1:].translate(str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉"))
    return plain(row.quantity)


def compact_cells(row: Row, units: dict[str, tuple[str, float]],
                  tiny: float = 0.0) -> tuple[str, str, str, str]:
    """A handout's row: quantity, value, direction or sense, unit, in the scale bar's units.

    Parameters
    ----------
    row : Row
    units : dict
        Diagram (``velocity``) -> (the unit its scale bar is written in, the
        factor from the file's unit to it).  A diagram not listed keeps the
        row's own unit.
    tiny : float
        Magnitudes at or below this (in the row's file units) print as 0.
    """
    unit, k = units.get(row_diagram(row.key), (row.unit, 1.0))
    v = row.drawn_value
    q = quantity_text(row)
    if row.key.startswith("theta") and v:
        return q, degrees_text(v[0], 2), "", "deg"
    if row.key.startswith(("omega", "alpha")) and v:
        w = v[0]
        if abs(w) <= tiny:
            return q, "0", "", row.unit
        return q, _short(abs(w)), "ccw" if w > 0 else "cw", row.unit
    if row.key.startswith(("V_", "A_")) and len(v) >= 2:
        m = math.hypot(v[0], v[1])
        if m <= tiny:
            return q, "0", "", unit
        return q, _short(m * k), _dir(math.atan2(v[1], v[0])), unit
    if len(v) == 3 and abs(v[2]) <= 1e-12 * max(abs(v[0]), abs(v[1]), 1e-300):
        return q, "∞", _homog(np.asarray(v))[2:], ""
    if len(v) >= 2:
        xy = np.asarray(v[:2], dtype=float) / (v[2] if len(v) == 3 else 1.0)
        x, y = (0.0 if abs(c) <= tiny else float(c) * k for c in xy)
        return q, f"({_short(x)}, {_short(y)})", "", unit
    if len(v) == 1:
        return q, _short(v[0] * k), "", unit
    return q, row.drawn, "", row.unit


def full_table(rows: list[Row]) -> Table:
    """A drawing sheet's results table: drawn value, analytic value, relative difference.

    The footnote says how well the drawing agrees with the analytic solution.
    """
    from graphkin.render.text import plain

    worst = max((r.diff for r in rows if r.diff is not None), default=0.0)
    if all(r.diff is None for r in rows) and all(not r.exact.strip("—") for r in rows):
        foot = "The analytic solver gave no answer here."
    elif worst < ROUND_OFF:
        foot = ("The drawing agrees with the analytic solution to round-off "
                f"(relative differences below {ROUND_OFF:.0e}).")
    elif worst < AGREE:
        foot = (f"Largest relative difference {worst:.1e}: the drawing agrees with the "
                "analytic solution.")
    else:
        foot = f"Largest relative difference {worst:.1e}."
    cells = [(quantity_text(r), plain(r.drawn), plain(r.exact), diff_text(r.diff), r.unit)
             for r in rows]
    return Table(("quantity", "drawn", "analytic", "rel. diff.", "unit"), cells,
                 [r.key for r in rows], ("left", "right", "right", "right", "left"),
                 title="Results: read off the construction, and the analytic solution",
                 foot=foot)
