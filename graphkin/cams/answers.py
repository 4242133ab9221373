"""Marking a student's cam answers: ``graphkin check CAMFILE ANSWERS`` (Secs. 6.9-6.12).

The answers file of ``graphkin check`` (the contract of docs/formats/answers.md:
keys in the book's notation, numbers in the cam file's units or strings with
units, an optional ``tolerance = { relative = 0.02, angle = 2.0 }``), with
keys of its own for a cam file:

=================  ===================================================================
``phi_max``        the largest pressure angle |φ| over the turn (degrees)
``phi_max_at``     the cam angle Θ where it occurs (degrees)
``rho_min``        the least radius of curvature of the profile where convex (length)
``rho_pitch_min``  the same of the pitch curve (roller and knife edge)
``face_width``     a flat face's least width, y'max − y'min (Eq. 6.29)
``R0_phi``         the least prime circle for ``[limits] pressure_angle`` (Ex 6.4)
``R0_rho``         the least prime circle for ``[limits] radius`` (Ex 6.3)
``omega_jump``     the cam speed at which the follower jumps (``[dynamics]``, Ex 6.8)
``Y_<Θ>``          the lift at cam angle Θ (degrees): length, or degrees for an arm
``phi_<Θ>``        the pressure angle at Θ (degrees)
``rho_<Θ>``        the profile's radius of curvature at Θ (convex positive)
``C_<Θ>``          the contact point ``[u, v]`` in the cam's frame (Ex 6.6, 6.7)
=================  ===================================================================

Θ is whole degrees (``phi_30``), or quoted with a fraction (``"phi_22.5"``).

A radius of curvature is positive where the profile is convex (the book's
Eqs. 6.37-6.38 give a counterclockwise cam's convex profile a negative one):
a radius given with the other sign is marked wrong and said so.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.9-6.12, Examples 6.3-6.8.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.cams.analytic import profile
from graphkin.cams.parse import CamFile
from graphkin.cams.report import cam_json
from graphkin.errors import InputError
from graphkin.files import parse_toml
from graphkin.text import g6, table
from graphkin.units import parse_quantity

__all__ = ["CamRow", "check_cam", "KEYS"]

KEYS = {"phi_max": "angle", "phi_max_at": "angle", "rho_min": "length",
        "rho_pitch_min": "length", "face_width": "length", "R0_phi": "length",
        "R0_rho": "length", "omega_jump": "omega"}
"""The cam answers' keys and their kinds (``Y_Θ``, ``phi_Θ``, ``rho_Θ``, ``C_Θ`` besides)."""

_AT = re.compile(r"^(Y|phi|rho|C)_(\d+(?:\.\d+)?)$")
#: Factors a wrong answer is tried against (the likely mistake), with their words.
_FACTORS = ((12.0, "inches and feet mixed up (12 in = 1 ft)"),
            (25.4, "inches and millimetres mixed up (25.4 mm = 1 in)"),
            (1000.0, "metres and millimetres mixed up"),
            (180 / math.pi, "radians and degrees mixed up"),
            (30 / math.pi, "rad/s and rev/min mixed up"))


@dataclass(frozen=True)
class CamRow:
    """One answer marked: key, the value given and the exact one (as text), the error."""

    key: str
    given: str
    exact: str
    error: str
    ok: bool
    rule: str
    mistake: str = ""


def _exact(cf: CamFile, key: str, src: str) -> tuple[Any, str]:
    """The exact value of ``key`` and its kind (``length``, ``angle``, ``omega``, ``point``)."""
    cam = cf.cam
    m = _AT.match(key)
    if m:
        what, th = m.group(1), math.radians(float(m.group(2)))
        pr = profile(cam, np.array([th]))
        if what == "Y":
            y = float(cam.program.evaluate([th]).Y[0])
            return (math.degrees(y), "angle") if cam.follower.kind.oscillating else \
                (y, "length")
        if what == "phi":
            return math.degrees(float(pr.pressure[0])), "angle"
        if what == "rho":
            return float(pr.rho[0]), "length"
        c = complex(pr.contact[0])
        return (c.real, c.imag), "point"
    if key not in KEYS:
        from graphkin.keys import nearest

        guess = nearest(key, [*KEYS, "Y_30", "phi_30", "rho_30", "C_30"])
        hint = f"; did you mean {guess!r}?" if guess else ""
        raise InputError(f"unknown answer {key!r} for a cam (keys: {', '.join(KEYS)}, and "
                         f"Y_Θ, phi_Θ, rho_Θ, C_Θ with Θ in degrees){hint}", key=key, file=src)
    d = cam_json(cf)
    need = {"face_width": ("face", "a flat face's width: this cam has no flat face"),
            "rho_pitch_min": ("pitch_radius_of_curvature", "the pitch curve's radius: this "
                              "cam has a flat face"),
            "R0_phi": ("min_prime_for_pressure_angle", "the cam file gives no [limits] "
                       "pressure_angle"),
            "R0_rho": ("min_prime_for_radius", "the cam file gives no [limits] radius"),
            "omega_jump": ("jump", "the cam file gives no [dynamics]")}
    if key in need and d.get(need[key][0]) is None:
        raise InputError(need[key][1], key=key, file=src)
    value = {"phi_max": lambda: d["pressure_angle"]["max"],
             "phi_max_at": lambda: d["pressure_angle"]["at"],
             "rho_min": lambda: (d["radius_of_curvature"] or {}).get("min", math.inf),
             "rho_pitch_min": lambda: d["pitch_radius_of_curvature"]["min"],
             "face_width": lambda: d["face"]["min_width"],
             "R0_phi": lambda: d["min_prime_for_pressure_angle"]["prime"],
             "R0_rho": lambda: d["min_prime_for_radius"]["prime"],
             "omega_jump": lambda: d["jump"]["omega"]}[key]()
    if value is None or not math.isfinite(value):
        raise InputError("graphkin finds no such value for this cam (said by graphkin cam)",
                         key=key, file=src)
    return float(value), KEYS[key]


def _given(value: Any, kind: str, unit: str, key: str, src: str) -> Any:
    try:
        if kind == "point":
            if not (isinstance(value, list) and len(value) == 2):
                raise ValueError(f"a point is [u, v], not {value!r}")
            return tuple(parse_quantity(v, "length", unit)[0] for v in value)
        v, sense = parse_quantity(value, kind, unit)
    except ValueError as exc:
        raise InputError(str(exc)[:200], key=key, file=src) from None
    if sense == "cw":
        v = -abs(v)
    return v


def _tolerance(data: Mapping[str, Any], src: str) -> tuple[float, float]:
    t = data.get("tolerance", {})
    if not isinstance(t, Mapping) or set(t) - {"relative", "angle"}:
        raise InputError("tolerance = { relative = 0.02, angle = 2.0 }", key="tolerance",
                         file=src)
    rel, ang = t.get("relative", 0.02), t.get("angle", 2.0)
    if isinstance(rel, str) and rel.strip().endswith("%"):
        try:
            rel = float(rel.strip()[:-1]) / 100
        except ValueError:
            raise InputError(f"not a fraction: {rel!r}", key="tolerance.relative",
                             file=src) from None
    for name, v in (("relative", rel), ("angle", ang)):
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 < v < 1e6:
            raise InputError(f"a positive number, not {v!r}", key=f"tolerance.{name}", file=src)
    return float(rel), float(ang)


def _mistake(key: str, given: Any, exact: Any, rel: float, cf: CamFile) -> str:
    if isinstance(exact, tuple):
        return ""
    words = []
    if exact and abs(given + exact) <= rel * abs(exact):
        words.append("sign reversed" + (" (the book's Eqs. 6.37-6.38 make a counterclockwise "
                                        "cam's convex radius negative; here convex is "
                                        "positive)" if key.startswith("rho") else ""))
    for f, why in _FACTORS:
        for k, big in ((f, "large"), (1 / f, "small")):
            if exact and abs(given - k * exact) <= rel * abs(k * exact):
                words.append(f"too {big} by a factor of {g6(f)}: {why}")
    rr = cf.cam.follower.roller if cf.cam.follower.kind.roller else 0.0
    if rr and exact and key.startswith(("rho", "R0")):
        for k, word in ((rr, "the roller's radius too much"), (-rr, "the roller's radius too "
                                                                     "little")):
            if abs(given - (exact + k)) <= rel * abs(exact):
                words.append(f"off by {word}: the pitch curve (or prime circle) and the "
                             "profile (or base circle) differ by R_r")
    return "; ".join(words)


def check_cam(cf: CamFile, text: str, source: str = "", *, relative: float | None = None,
              angle: float | None = None) -> tuple[list[CamRow], str]:
    r"""Mark the answers ``text`` (TOML) against the cam ``cf``; the rows and the report.

    ``relative`` and ``angle`` (degrees), when given, override the file's tolerance
    (``--relative``, ``--angle``).

    Examples
    --------
    Ex 6.6 at Θ = 30°: the book's φ = 28.68° and u_cam = 23.413 mm (a slip: 23.473).

    >>> from graphkin.cams.parse import load_cam
    >>> cf = load_cam("examples/cams/ex6_6_roller.toml")
    >>> rows, _ = check_cam(cf, 'phi_30 = 28.68\nC_30 = [23.413, 29.139]\nrho_30 = -60.775')
    >>> [(r.key, r.ok) for r in rows]
    [('phi_30', True), ('C_30', True), ('rho_30', False)]
    >>> rows[2].mistake.split(" (")[0]
    'sign reversed'
    """
    data = parse_toml(text, source or "<answers>")
    rel, ang = _tolerance(data, source)
    rel, ang = relative or rel, angle or ang
    cam = cf.cam
    size = cam.prime + abs(cam.program.lift) * (1.0 if not cam.follower.kind.oscillating
                                                  else max(cam.follower.arm, 1.0))
    rows = []
    for key, value in data.items():
        if key in ("tolerance", "student", "name", "title", "comment", "notes"):
            continue
        exact, kind = _exact(cf, str(key), source)
        got = _given(value, kind, cam.unit, str(key), source)
        unit = {"length": f" {cam.unit}", "angle": "°", "omega": " rad/s", "point":
                f" {cam.unit}"}[kind]
        if kind == "point":
            err = math.hypot(got[0] - exact[0], got[1] - exact[1])
            ok = err <= rel * max(math.hypot(*exact), 1e-9 * size)
            gtxt, etxt = (f"({g6(got[0])}, {g6(got[1])}){unit}",
                          f"({g6(exact[0])}, {g6(exact[1])}){unit}")
            etext, rule = f"{g6(err)}{unit}", f"within {g6(100 * rel)} % of |C|"
        elif kind == "angle":
            err = got - exact
            ok = abs(err) <= ang
            gtxt, etxt = f"{g6(got)}{unit}", f"{g6(exact)}{unit}"
            etext, rule = f"{err:+.2f}°", f"within {g6(ang)}°"
        else:
            err = got - exact
            ok = abs(err) <= rel * max(abs(exact), 1e-9 * size)
            gtxt, etxt = f"{g6(got)}{unit}", f"{g6(exact)}{unit}"
            etext = f"{100 * err / exact:+.2f} %" if exact else g6(err)
            rule = f"within {g6(100 * rel)} %"
        rows.append(CamRow(str(key), gtxt, etxt, etext, ok, rule if ok else "outside" +
                           rule[6:], "" if ok else _mistake(str(key), got, exact, rel, cf)))
    if not rows:
        raise InputError("no answers to mark", file=source or None)
    lines = [f"tolerance: {g6(100 * rel)} % of magnitude, {g6(ang)}° of angle"]
    body = [("answer", "given", "exact", "error", "verdict", "decided by")]
    body += [(r.key, r.given, r.exact, r.error, "ok" if r.ok else "WRONG", r.rule)
             for r in rows]
    for line, r in zip(table(body, ""), [None, *rows]):
        lines.append(line)
        if r is not None and r.mistake:
            lines.append(f"    likely mistake: {r.mistake}")
    wrong = [r.key for r in rows if not r.ok]
    lines.append(f"{len(rows) - len(wrong)} of {len(rows)} within tolerance"
                 + (f", {len(wrong)} wrong ({', '.join(wrong)})." if wrong else "."))
    return rows, "\n".join(lines) + "\n"
