"""A crank-rocker from the rocker's two limit postures and the time ratio Q (Sec. 9.3, Fig. 9.3).

The book's construction: the rocker O4B is drawn in its two limit postures
O4B1 and O4B2, ``φ`` apart; through B1 any line X is drawn, through B2 the
line Y at the angle ``α`` to X, where ``Q = (180° + α) / (180° − α)``
(Eq. 9.1); X and Y meet at the crank pivot O2.  At the limit postures the
crank and the coupler lie on one line: O2B1 = r3 + r2 (extended),
O2B2 = r3 − r2 (folded).  The arc about O2 through B2 meets O2B1 at C, so
B1C = 2 r2; the bisector of B1C gives its midpoint M, r2 = CM and
r3 = O2B1 − r2 (Fig. 9.3a).  The crank turns counterclockwise, through
180° + α from the extended to the folded posture (the advance stroke, B1 to
B2) and 180° − α back.

The direction of line X is the designer's free choice; a choice that puts
O2 where the linkage would not be a crank-rocker with these limits (O2 on
the wrong side, the crank not the shortest link) is refused in one line.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.3 (Figs. 9.2-9.3, Eq. 9.1), Sec. 1.7.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.errors import InputError
from graphkin.synthesis.postures import DIAGRAM
from graphkin.text import toml_string

__all__ = ["CrankRocker", "crank_rocker", "alpha_of"]


def alpha_of(q: float) -> float:
    """The angle α (rad) of a time ratio Q: Eq. 9.1 solved, ``α = 180° (Q − 1)/(Q + 1)``."""
    return math.pi * (q - 1.0) / (q + 1.0)


@dataclass(frozen=True)
class CrankRocker:
    """The crank-rocker found: pivots, lengths, the limit postures and the construction.

    Attributes
    ----------
    o2, o4, b1, b2 : complex
        The crank pivot, the rocker pivot and the rocker pin at the two limits.
    r2, r3, r4 : float
        Crank, coupler and rocker lengths (r1 = |O4 − O2|).
    theta_a, theta_b : float
        The crank's angle (rad) at the extended limit (B1) and at the folded one (B2).
    construction : Construction
        Fig. 9.3a, step by step.
    """

    o2: complex
    o4: complex
    b1: complex
    b2: complex
    r2: float
    r3: float
    r4: float
    theta_a: float
    theta_b: float
    construction: Construction

    @property
    def a1(self) -> complex:
        """The crank pin in the extended limit posture (on O2B1)."""
        return self.o2 + self.r2 * np.exp(1j * self.theta_a)

    @property
    def q(self) -> float:
        """The advance-to-return ratio of the linkage (crank counterclockwise, Eq. 9.1)."""
        adv = (self.theta_b - self.theta_a) % math.tau
        return adv / (math.tau - adv)

    def mechanism_toml(self, units: str = "mm", title: str = "") -> str:
        """The four-bar's mechanism file, assembled in the first limit posture (B at B1)."""
        def xy(z: complex) -> str:
            return f"[{float(z.real)!r}, {float(z.imag)!r}]"

        return "\n".join([
            f'title = {toml_string(title or "Crank-rocker from its limit postures (Sec. 9.3)")}',
            f'units = {{ length = "{units}" }}', "",
            "[links.1]", f"O2 = {xy(self.o2)}", f"O4 = {xy(self.o4)}", "",
            "[links.2]", "O2 = [0.0, 0.0]", f"A = [{self.r2!r}, 0.0]", "",
            "[links.3]", "A = [0.0, 0.0]", f"B = [{self.r3!r}, 0.0]", "",
            "[links.4]", "O4 = [0.0, 0.0]", f"B = [{self.r4!r}, 0.0]", "",
            "[drive]", "link = 2", f"angle = {math.degrees(self.theta_a)!r}", "",
            "[assembly]", f"B = {xy(self.b1)}", ""])


def _side(p: complex, q: complex, r: complex) -> float:
    """The sign of R's side of the directed line PQ (+1 left, −1 right, 0 on it)."""
    u, v = q - p, r - p
    cr = u.real * v.imag - u.imag * v.real
    return 0.0 if abs(cr) <= 1e-9 * abs(u) * abs(v) else math.copysign(1.0, cr)


def _z(v: np.ndarray) -> complex:
    return complex(v[0] / v[2], v[1] / v[2])


def _why_not(o2: complex, o4: complex, b1: complex, b2: complex, alpha: float,
             r2: float, scale: float) -> str | None:
    """Why the crank pivot ``o2`` gives no crank-rocker with these limits (None: it does)."""
    # O2 must see B1B2 under +α (the advance stroke 180° + α, crank counterclockwise)
    seen = math.remainder(float(np.angle((b2 - o2) / (b1 - o2))), math.tau)
    r3 = abs(b1 - o2) - r2
    r1 = abs(o4 - o2)
    r4 = abs(b1 - o4)
    lengths = sorted((r1, r2, r3, r4))
    tiny = 1e-9 * scale
    if abs(seen - alpha) > 1e-6 or abs(b1 - o2) - abs(b2 - o2) <= tiny:
        return "O2 does not see B1B2 under +α with O2B1 > O2B2 (swap the sense of φ or " \
               "turn line X)"
    if _side(o2, o4, b1) * _side(o2, o4, b2) < 0:
        return "B1 and B2 fall either side of O2O4: the rocker reaches them on two " \
               "different branches"
    if not (r2 <= lengths[0] + tiny and lengths[0] + lengths[3] < lengths[1] + lengths[2]
            - tiny):
        return (f"r1 = {r1:.6g}, r2 = {r2:.6g}, r3 = {r3:.6g}, r4 = {r4:.6g} is not a "
                "crank-rocker (the crank must be the shortest link, s + l < p + q)")
    return None


def _admissible(o4: complex, b1: complex, b2: complex, alpha: float, scale: float) -> str:
    """The directions of line X (whole degrees, mod 180°) that do give a crank-rocker.

    X through B1 at x and Y through B2 at x + α meet at O2 (Fig. 9.3a); the
    crank is half of O2B1 − O2B2.  Said in the refusal, so that the designer
    need not search the free choice blindly.
    """
    good = []
    for deg in range(180):
        x = math.radians(deg)
        u, w = complex(math.cos(x), math.sin(x)), complex(math.cos(x + alpha),
                                                          math.sin(x + alpha))
        den = u.real * w.imag - u.imag * w.real
        if abs(den) < 1e-12:
            continue
        d = b2 - b1
        t = (d.real * w.imag - d.imag * w.real) / den
        o2 = b1 + t * u
        if abs(o2 - o4) > 1e4 * scale:
            continue
        r2 = (abs(b1 - o2) - abs(b2 - o2)) / 2
        good.append(_why_not(o2, o4, b1, b2, alpha, r2, scale) is None)
    if not any(good):
        return "no direction of X does with this swing: give φ the other sense"
    runs, start = [], None
    for deg, ok in enumerate([*good, False]):
        if ok and start is None:
            start = deg
        elif not ok and start is not None:
            runs.append(f"{start}° to {deg - 1}°" if deg - 1 > start else f"{start}°")
            start = None
    return "x_angle " + ", ".join(runs) + " (or 180° more) gives one"


def crank_rocker(o4: complex, b1: complex, swing: float, q: float, x_angle: float,
                 source: str = "<synthesis>", key: str = "crank_rocker") -> CrankRocker:
    """Construct the crank-rocker of Fig. 9.3.

    Parameters
    ----------
    o4, b1 : complex
        The rocker's pivot and its pin in the first limit posture (r4 = |B1 − O4|).
    swing : float
        φ, the rocker's turn from B1 to B2 (rad, counterclockwise positive).
    q : float
        The advance-to-return ratio Q > 1 (Eq. 9.1).
    x_angle : float
        The direction of line X through B1 (rad): the free choice.

    Raises
    ------
    InputError
        A swing or Q out of range, or a line X whose O2 gives no crank-rocker
        with these limit postures (naming ``key``).
    """
    r4 = abs(b1 - o4)
    if not 0.0 < abs(swing) < math.pi:
        raise InputError("the rocker's swing φ must be between 0° and 180° either way",
                         key=f"{key}.swing", file=source)
    if not 1.0 + 1e-9 < q < 1e6:
        raise InputError(f"Q = {q!r}: the construction needs an advance-to-return ratio "
                         "above 1 (Eq. 9.1; at Q = 1 lines X and Y are parallel)",
                         key=f"{key}.Q", file=source)
    alpha = alpha_of(q)
    th1 = math.atan2(b1.imag - o4.imag, b1.real - o4.real)
    cx = Construction(title="crank-rocker from two limit postures (Fig. 9.3)")
    cx.add("point", (), ("O4",), xy=(o4.real, o4.imag), note="O4: the rocker's pivot, "
           "chosen anywhere (Fig. 9.3a).", role=Role.GIVEN, diagram=DIAGRAM)
    cx.add("point", (), ("B1",), xy=(b1.real, b1.imag), note="B1: the rocker's pin in its "
           "first limit posture; O4B1 = r4 sets the scale.", role=Role.GIVEN, diagram=DIAGRAM)
    cx.add("scalar", (), ("theta_4_2",), value=th1 + swing, diagram=DIAGRAM,
           note=f"the rocker's second limit posture, φ = {math.degrees(swing):.6g}° from "
                "the first.")
    cx.add("rigid", ("O4", "theta_4_2"), ("B2",), local_p=(0.0, 0.0), local_q=(r4, 0.0),
           role=Role.RESULT, diagram=DIAGRAM,
           note="B2: the rocker's pin in its second limit posture.")
    cx.add("scalar", (), ("x",), value=x_angle, diagram=DIAGRAM,
           note=f"the direction of line X, any ({math.degrees(x_angle):.6g}° here).")
    cx.add("line_at_angle", ("B1", "x"), ("X",), diagram=DIAGRAM,
           note="line X through B1, drawn in any direction.")
    cx.add("line_at_angle", ("B2", "x"), ("Y",), offset=alpha, diagram=DIAGRAM,
           note=f"line Y through B2 at α = {math.degrees(alpha):.6g}° to X, "
                f"Q = (180° + α)/(180° − α) = {q:.6g} (Eq. 9.1).")
    cx.add("meet", ("X", "Y"), ("O2",), role=Role.RESULT, diagram=DIAGRAM,
           note="O2: the crank pivot, where X and Y meet.")
    cx.add("join", ("O2", "B1"), ("O2B1",), diagram=DIAGRAM,
           note="the line O2B1: crank and coupler extended in line at the first limit.")
    cx.add("circle_through", ("O2", "B2"), ("k_O2",), diagram=DIAGRAM,
           note="the arc about O2 through B2 (O2B2 = r3 − r2, folded).")
    cx.add("intersect_line_circle", ("O2B1", "k_O2"), ("C",), branch="ahead",
           diagram=DIAGRAM, note="C: the arc meets O2B1; B1C = 2 r2.")
    cx.add("bisector", ("C", "B1"), ("b_CB1",), diagram=DIAGRAM,
           note="the bisector of CB1.")
    cx.add("meet", ("O2B1", "b_CB1"), ("M",), diagram=DIAGRAM,
           note="M: the middle of CB1; the crank's length r2 = CM = MB1.")
    with np.errstate(all="ignore"):   # X parallel to Y: O2 at infinity, refused below
        ev = cx.evaluate(strict=False)
        o2, b2, c, m = (_z(np.asarray(ev[k], dtype=float)) for k in ("O2", "B2", "C", "M"))
    scale = max(r4, abs(b2 - b1))
    if not (np.isfinite(o2) and abs(o2 - o4) < 1e4 * scale):
        raise InputError("lines X and Y are parallel for this direction of X: choose "
                         "another x_angle", key=f"{key}.x_angle", file=source)
    r2 = abs(m - c)
    why = _why_not(o2, o4, b1, b2, alpha, r2, scale)
    if why is not None:
        raise InputError(f"line X at {math.degrees(x_angle):.6g}°: {why}; "
                         + _admissible(o4, b1, b2, alpha, scale),
                         key=f"{key}.x_angle", file=source)
    r3 = abs(b1 - o2) - r2
    cx.add("along_ray", ("O2", "B1"), ("A1",), distance=r2, role=Role.RESULT,
           diagram=DIAGRAM, note="A1: the crank pin, r2 (the compass set to CM) from O2 "
                                 "toward B1: crank and coupler in line (Fig. 9.3b).")
    theta_a = float(np.angle(b1 - o2))
    theta_b = float(np.angle(o2 - b2))
    return CrankRocker(o2, o4, b1, b2, r2, r3, r4, theta_a, theta_b, cx)
