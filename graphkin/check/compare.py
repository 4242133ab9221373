"""Comparing a measured value with the exact one, as a drawing's accuracy allows.

A magnitude is right within a fraction of itself (2 % by default); a
direction or a link angle within an angle (2° by default); a position (an
instant center) within the fraction of the size of the mechanism.  The sense of
an angular rate is checked when one was given.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (graphic solutions read to about
three significant figures: compare Example 3.1's ω3 = 25.6 with the analytic
25.38 rad/s).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.check.answers import CheckTolerance, Given
from graphkin.check.exact import Exact, wrap180
from graphkin.text import fmt as text_fmt

__all__ = ["Comparison", "compare", "show_given", "show_exact", "fmt", "direction_text"]


@dataclass(frozen=True)
class Comparison:
    """The outcome of one comparison.

    Attributes
    ----------
    ok : bool
        Within tolerance.
    error : str
        The error in words and numbers (``"+0.9 %"``, ``"-0.6 %, +0.05°"``).
    rule : str
        Which rule decided the verdict (``"within 2 %"``, ``"end 0.3 mm from
        exact on the drawing (tolerance 0.5 mm)"``, ``"sense reversed"``).
    """

    ok: bool
    error: str
    rule: str = ""


def _pct(x: float) -> str:
    """A relative error in percent; beyond a million percent, its order only.

    >>> _pct(0.0123), _pct(4e306), _pct(-2e7)
    ('+1.23 %', 'over +1e+06 %', 'over -1e+06 %')
    """
    v = x * 100
    if not abs(v) < 1e6:  # an answer of 1e308: no '+inf %'
        return f"over {'-' if x < 0 else '+'}1e+06 %"
    return f"{v if abs(v) >= 0.005 else 0.0:+.2f} %"


def direction_text(deg: float, digits: int = 2) -> str:
    """A direction in degrees as printed: in (-180, 180], never ``-180.00°`` nor ``-0.00°``.

    A direction a hair below the half turn rounds to the half turn and is
    printed as the given ``180 deg`` would be.

    Examples
    --------
    >>> direction_text(-179.9999), direction_text(180.0), direction_text(-1e-9, 1)
    ('180.00°', '180.00°', '0.0°')
    >>> direction_text(-90.0), direction_text(540.0)
    ('-90.00°', '180.00°')
    """
    d = round(wrap180(deg), digits)
    if d <= -180.0:
        d += 360.0
    return f"{d + 0.0:.{digits}f}°"


def _deg(d: float) -> str:
    return f"{d if abs(d) >= 0.005 else 0.0:+.2f}°"


def compare(given: Given, exact: Exact, tol: CheckTolerance, *, floor: float = 0.0,
            reference: float | None = None, sheet: float | None = None) -> Comparison:
    """Compare a measured value with the exact one.

    Parameters
    ----------
    given : Given
    exact : Exact
    tol : CheckTolerance
    floor : float
        Magnitudes below this count as zero (no direction, no sense).
    reference : float, optional
        The length a position error is measured against (default: the exact
        point's distance from the origin, at least 1).
    sheet : float, optional
        The drawing tolerance in the quantity's own units (``tol.drawing``
        millimetres times the drawing's scale, divided by the link's length
        for ω and α): the answer is right too when it is this close, so a
        small vector in a large polygon is judged by where its end is on the
        paper (issue: drawing accuracy is a length on the sheet).

    Examples
    --------
    >>> from graphkin.check.answers import Key
    >>> g = Given(Key("omega3", "omega", ("3",)), "25.6 rad/s ccw", value=25.6, signed=True)
    >>> compare(g, Exact(25.38), CheckTolerance())
    Comparison(ok=True, error='+0.87 %', rule='within 2 %')
    >>> compare(g, Exact(-25.38), CheckTolerance()).rule
    'sense reversed'
    """
    shape = given.key.shape
    if shape == "angle":
        assert given.value is not None and exact.value is not None
        d = wrap180(given.value - exact.value)
        ok = abs(d) <= tol.angle
        return Comparison(ok, _deg(d), f"{'within' if ok else 'outside'} {tol.angle:g}°")
    if shape in ("scalar", "magnitude"):
        c = _scalar(given, exact, tol, floor)
    elif shape == "point":
        c = _point(given, exact, tol, reference)
    else:
        c = _vector(given, exact, tol, floor)
    if sheet is not None and sheet > 0 and tol.drawing:
        c = _on_sheet(c, given, exact, tol, sheet)
    return c


def _on_sheet(c: Comparison, given: Given, exact: Exact, tol: CheckTolerance,
              sheet: float) -> Comparison:
    """Apply the drawing rule: right when the drawn end is within ``tol.drawing`` mm."""
    mm = float(tol.drawing or 0.0)
    shape = given.key.shape
    if shape in ("scalar", "magnitude"):
        g = float(given.value or 0.0)
        e = float(exact.value or 0.0)
        if math.isinf(g) or math.isinf(e):
            return c
        signed = given.signed and shape == "scalar"
        dist = abs(g - e) if signed else abs(abs(g) - abs(e))
    elif shape == "point":
        if exact.ideal or given.ideal or given.point is None or exact.xy is None:
            return c
        dist = float(np.hypot(*(given.point - exact.xy)))
    else:
        if exact.xy is None:
            return c
        gv = given.components()
        if gv is None:
            dist = abs(float(given.value or 0.0) - exact.magnitude)
        else:
            dist = float(np.hypot(*(gv - exact.xy)))
    on_paper = dist / sheet * mm
    if on_paper <= mm:
        if c.ok:
            return c
        return Comparison(True, c.error, f"within {mm:g} mm on the drawing ({mm_text(on_paper)} mm "
                                         f"off; {c.rule})")
    if c.ok:
        return c
    return Comparison(False, c.error, f"{c.rule}, and {mm_text(on_paper)} mm off on the drawing "
                                      f"(more than {mm:g} mm)")


def _scalar(given: Given, exact: Exact, tol: CheckTolerance, floor: float) -> Comparison:
    g = float(given.value if given.value is not None else 0.0)
    e = float(exact.value if exact.value is not None else 0.0)
    if math.isinf(e) or math.isinf(g):
        ok = math.isinf(e) and math.isinf(g)
        return Comparison(ok, "" if ok else "straight path" if math.isinf(e) else "not straight",
                          "infinite radius" if ok else "straight or not")
    signed = given.signed and given.key.shape == "scalar"
    diff = (g - e) if signed else (abs(g) - abs(e))
    ok = abs(diff) <= tol.relative * abs(e) + floor
    if abs(e) <= floor:
        text = f"{diff / given.factor:+.4g} {given.unit}"
    else:
        text = _pct((abs(g) - abs(e)) / abs(e))
    rule = f"{'within' if ok else 'outside'} {tol.relative * 100:g} %"
    if abs(e) <= floor:
        rule = "zero within round-off" if ok else "not zero"
    if signed and abs(g) > floor and abs(e) > floor and (g > 0) != (e > 0):
        text += ", sense"
        # the sense alone, or the sense and the size too (never "sense reversed" alone
        # for an answer whose magnitude is wrong as well)
        size_ok = abs(abs(g) - abs(e)) <= tol.relative * abs(e) + floor
        rule = "sense reversed" if size_ok else \
            f"sense reversed and size outside {tol.relative * 100:g} %"
    elif not signed and given.key.shape == "scalar":
        rule += " (magnitude only)"
    return Comparison(ok, text, rule)


def _vector(given: Given, exact: Exact, tol: CheckTolerance, floor: float) -> Comparison:
    assert exact.xy is not None
    mag = exact.magnitude
    g = float(given.value if given.value is not None else 0.0)
    ok_mag = abs(g - mag) <= tol.relative * mag + floor
    parts = [_pct((g - mag) / mag) if mag > floor
             else f"{(g - mag) / given.factor:+.4g} {given.unit}"]
    rules = [f"magnitude {'within' if ok_mag else 'outside'} {tol.relative * 100:g} %"
             if mag > floor else ("zero within round-off" if ok_mag else "not zero")]
    ok = ok_mag
    ed = exact.direction
    if given.direction is not None and mag > floor and g > floor and ed is not None:
        d = wrap180(given.direction - ed)
        ok_dir = abs(d) <= tol.angle
        ok = ok and ok_dir
        parts.append(_deg(d))
        rules.append(f"direction {'within' if ok_dir else 'outside'} {tol.angle:g}°")
        if abs(d) > 180.0 - tol.angle:
            rules[-1] = "sense reversed"
    elif given.direction is None:
        rules[-1] += " (magnitude only)"
    if ok:
        rule = "within " + " and ".join(r.split(" within ")[-1] for r in rules)
    else:
        rule = ", ".join(r for r in rules if "within" not in r)
    return Comparison(ok, ", ".join(parts), rule)


def _point(given: Given, exact: Exact, tol: CheckTolerance,
           reference: float | None) -> Comparison:
    assert exact.xy is not None
    if exact.ideal or given.ideal:
        if not (exact.ideal and given.ideal):
            return Comparison(False, "at infinity" if exact.ideal else "not at infinity",
                              "at infinity or not")
        assert given.direction is not None and exact.direction is not None
        d = wrap180(given.direction - exact.direction)
        d = d - 180.0 if d > 90.0 else d + 180.0 if d <= -90.0 else d  # either sense
        ok = abs(d) <= tol.angle
        return Comparison(ok, _deg(d), f"direction {'within' if ok else 'outside'} "
                                       f"{tol.angle:g}°")
    assert given.point is not None
    dist = float(np.hypot(*(given.point - exact.xy)))
    ref = reference if reference is not None else max(1.0, float(np.hypot(*exact.xy)))
    ok = dist <= tol.relative * ref
    return Comparison(ok, f"{dist / given.factor:.4g} {given.unit} ({dist / ref * 100:.2f} %)",
                      f"{'within' if ok else 'outside'} {tol.relative * 100:g} % of the "
                      "mechanism's size")


def mm_text(x: float) -> str:
    """A distance on the drawing in mm, two significant figures, never an exponent.

    >>> mm_text(131.7), mm_text(4.93), mm_text(0.0123), mm_text(2e-4)
    ('130', '4.9', '0.012', '0')
    """
    return f"{float(f'{x if x >= 5e-4 else 0.0:.2g}'):g}"


def _sense_word(x: float) -> str:
    return "ccw" if x > 0 else "cw" if x < 0 else ""


def fmt(x: float) -> str:
    """Four significant figures, without an exponent for everyday sizes.

    Examples
    --------
    >>> fmt(35530.6), fmt(25.3828), fmt(0.054321), fmt(0.0)
    ('35531', '25.38', '0.05432', '0')
    """
    return text_fmt(x, 4, trim=False)


def show_given(given: Given) -> str:
    """The measured value as written (strings) or with its unit (numbers)."""
    if isinstance(given.raw, str):
        return given.raw
    if isinstance(given.raw, list) and given.point is not None:
        return f"({', '.join(fmt(v / given.factor) for v in given.point)}) {given.unit}"
    if isinstance(given.raw, list) and given.vector is not None:
        return f"[{', '.join(fmt(v / given.factor) for v in given.vector)}] {given.unit}"
    return show_exact(given, Exact(given.value) if given.vector is None
                      else Exact(None, given.vector), plain=True)


def show_exact(given: Given, exact: Exact, *, plain: bool = False) -> str:
    """An exact value in the unit the answer was given in.

    ``plain`` shows a given value (no sense unless one was written).
    """
    shape = given.key.shape
    f = given.factor or 1.0
    if shape == "angle":
        assert exact.value is not None
        return direction_text(exact.value) if given.unit == "deg" else \
            f"{fmt(exact.value / f)} {given.unit}"
    if shape == "scalar":
        v = float(exact.value or 0.0)
        sense = "" if plain and not given.signed else " " + _sense_word(v)
        return f"{fmt(abs(v) / f)} {given.unit}{sense}".rstrip()
    if shape == "magnitude":
        v = float(exact.value or 0.0)
        return "∞ (straight)" if math.isinf(v) else f"{fmt(v / f)} {given.unit}"
    if shape == "point":
        assert exact.xy is not None
        if exact.ideal:
            return f"∞ at {direction_text(exact.direction or 0.0, 1)}"
        return f"({fmt(exact.xy[0] / f)}, {fmt(exact.xy[1] / f)}) {given.unit}"
    if exact.xy is None:
        return f"{fmt(float(exact.value or 0.0) / f)} {given.unit}"
    text = f"{fmt(exact.magnitude / f)} {given.unit}"
    d = exact.direction
    if d is not None:
        text += f" at {direction_text(d)}"
    return text
