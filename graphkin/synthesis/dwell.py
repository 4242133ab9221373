"""A dwell six-bar from a coupler curve's circular arc or straight stretch (Sec. 9.13).

Fig. 9.42a (``DwellKind.ARC``):

Along a stretch of a four-bar's coupler curve that is nearly a circular arc,
a link 5 of the arc's radius pinned at the coupler point C keeps its other
end D (nearly) still: a link 6 pivoted on the frame at O6 and pinned at D
dwells while C runs along the arc.  The arc is found on the coupler curve
(sampled over the crank's turn, vectorised) as the stretch of a given crank
span whose three points C1, C2, C3 (start, middle, end) give the circle the
whole stretch keeps closest to; D, its center, is constructed as the book
does: the bisectors of C1C2 and C2C3 meet at D.  Link 6 is laid
perpendicular to link 5 at the middle of the dwell, as long as link 5, for
a good transmission angle.

Figs. 9.42b and 9.44 (``DwellKind.SLIDER``): along a stretch that is nearly
straight, a slotted link 6 pivoted at O6 on the extension of that line (the
book: "pivot O6 is placed on an extension of this line") carries a block
pinned at C; while C runs the straight stretch the slot keeps its
direction and link 6 dwells.  The stretch of the given crank span whose
points keep closest to the line C1C3 (relative to its length) is found on
the sampled curve; the line is drawn through C1 and C3 and O6 laid off on it
one stretch's length beyond the end the rest of the curve keeps farther
from (the book warns that link 6 turns fast when the block passes near O6).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.13 (Figs. 9.42, 9.44).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import StrEnum

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.errors import InputError
from graphkin.synthesis.postures import DIAGRAM
from graphkin.text import toml_string

__all__ = ["Dwell", "DwellKind", "dwell"]


class DwellKind(StrEnum):
    """Which stretch of the coupler curve makes the dwell (Sec. 9.13)."""

    ARC = "arc"          # link 5 of the arc's radius, link 6 pivoted at O6 (Fig. 9.42a)
    SLIDER = "slider"    # a block at C in a slotted link 6 pivoted on the line (Fig. 9.44)


@dataclass(frozen=True)
class Dwell:
    """A dwell six-bar: the four-bar and the dwelling link 6.

    ARC: the arc's center D, link 5 (C D) and link 6 (O6 D).  SLIDER: the
    slotted link 6 about O6 on the line C1C3 (``d`` is then O6 too, ``radius``
    the distance O6C at the middle of the dwell, ``deviation`` the stretch's
    largest distance from the line).
    """

    o_a: complex
    a_len: float
    o_b: complex
    lengths: tuple[float, float, float]
    coupler_local: complex
    crank: np.ndarray
    c: np.ndarray
    start: int
    stop: int
    d: complex
    radius: float
    deviation: float
    o6: complex
    construction: Construction
    kind: DwellKind = DwellKind.ARC

    def mechanism_toml(self, units: str = "mm", title: str = "") -> str:
        """The six-bar's mechanism file, the crank at the middle of the dwell."""
        mid = (self.start + self.stop) // 2
        theta = float(self.crank[mid])
        crank, coupler, rocker = self.lengths
        a = self.o_a + crank * np.exp(1j * theta)
        cz = complex(self.c[mid])
        b = a + (cz - a) / self.coupler_local * coupler

        def xy(z: complex) -> str:
            return f"[{float(z.real)!r}, {float(z.imag)!r}]"

        slider = self.kind is DwellKind.SLIDER
        name = "Dwell six-bar with a slider (Sec. 9.13)" if slider else "Dwell six-bar (Sec. 9.13)"
        four_bar = [  # the four-bar whose coupler point C dwells, as both forms share it
            f'title = {toml_string(title or name)}', f'units = {{ length = "{units}" }}', "",
            "[links.1]", f"O_A = {xy(self.o_a)}", f"O_B = {xy(self.o_b)}",
            f"O6 = {xy(self.o6)}", "",
            "[links.2]", "O_A = [0.0, 0.0]", f"A = [{crank!r}, 0.0]", "",
            "[links.3]", "A = [0.0, 0.0]", f"B = [{coupler!r}, 0.0]",
            f"C = {xy(self.coupler_local * coupler)}", "",
            "[links.4]", "O_B = [0.0, 0.0]", f"B = [{rocker!r}, 0.0]", ""]
        drive = ["[drive]", "link = 2", f"angle = {math.degrees(theta)!r}", ""]
        if slider:  # C slides in the slotted link 6 about O6
            dyad = ["[links.6]", "O6 = [0.0, 0.0]", f"S = [{self.radius!r}, 0.0]", "",
                    "[[slots]]", "link = 3", "on = 6", 'point = "C"', 'line = ["O6", "S"]', ""]
            assembly = ["[assembly]", f"B = {xy(b)}", f"C = {xy(cz)}", f"S = {xy(cz)}", ""]
        else:       # the dyad C-D, D-O6 of radius R5 from C
            dyad = ["[links.5]", "C = [0.0, 0.0]", f"D = [{self.radius!r}, 0.0]", "",
                    "[links.6]", "O6 = [0.0, 0.0]", f"D = [{abs(self.d - self.o6)!r}, 0.0]", ""]
            assembly = ["[assembly]", f"B = {xy(b)}", f"C = {xy(cz)}", f"D = {xy(self.d)}", ""]
        return "\n".join(four_bar + dyad + drive + assembly)


def _curve(o_a: complex, a: complex, b: complex, o_b: complex, c: complex,
           samples: int) -> tuple[tuple[float, float, float], complex, np.ndarray, np.ndarray]:
    """The lengths, C in the coupler's frame, the crank angles and C's curve over a turn."""
    crank, coupler, rocker = abs(a - o_a), abs(b - a), abs(b - o_b)
    local = (c - a) / (b - a)
    u, v = o_b - a, b - a
    side = 1.0 if u.real * v.imag - u.imag * v.real > 0 else -1.0
    theta0 = float(np.angle(a - o_a))
    theta = theta0 + np.arange(samples) * (math.tau / samples)
    pa = o_a + crank * np.exp(1j * theta)
    d = o_b - pa
    dist = np.abs(d)
    along = (dist ** 2 + coupler ** 2 - rocker ** 2) / (2 * dist)
    h2 = coupler ** 2 - along ** 2
    if np.any(h2 < 0):
        raise InputError("the crank does not turn fully: a dwell needs the whole coupler "
                         "curve (a Grashof crank)", key="dwell")
    pb = pa + (along + side * np.sqrt(h2) * 1j) * d / dist
    return (crank, coupler, rocker), local, theta, pa + local * (pb - pa)


def dwell(o_a: complex, a: complex, b: complex, o_b: complex, c: complex,
          span: float = math.radians(60.0), samples: int = 720,
          kind: DwellKind = DwellKind.ARC) -> Dwell:
    """Design the dwell six-bar of the four-bar O_A A B O_B with coupler point C.

    Parameters
    ----------
    o_a, a, b, o_b, c : complex
        The four-bar and its coupler point in one posture (its branch is kept).
    span : float
        The crank's turn over which link 6 is to dwell (rad).
    samples : int
        Crank angles over a turn.
    kind : DwellKind
        A circular arc and link 5 (Fig. 9.42a) or a straight stretch and a
        slider (Fig. 9.44).

    Raises
    ------
    InputError
        The crank does not turn fully, or no stretch of the curve is an arc.
    """
    (crank, coupler, rocker), local, theta, curve = _curve(o_a, a, b, o_b, c, samples)
    if kind is DwellKind.SLIDER:
        return _slider(o_a, o_b, (crank, coupler, rocker), local, theta, curve, span)
    w = max(2, int(round(span / math.tau * samples)))
    w += w % 2
    starts = np.arange(samples)
    idx = (starts[:, None] + np.arange(w + 1)[None, :]) % samples
    pts = curve[idx]
    c1, c2, c3 = pts[:, 0], pts[:, w // 2], pts[:, w]
    # circumcenter of C1 C2 C3 (closed form here: the construction below draws it)
    d1, d2 = c2 - c1, c3 - c1
    den = 2 * (d1.real * d2.imag - d1.imag * d2.real)
    with np.errstate(divide="ignore", invalid="ignore"):
        ux = (d2.imag * np.abs(d1) ** 2 - d1.imag * np.abs(d2) ** 2) / den
        uy = (d1.real * np.abs(d2) ** 2 - d2.real * np.abs(d1) ** 2) / den
    center = c1 + ux + 1j * uy
    radius = np.abs(c1 - center)
    dev = np.max(np.abs(np.abs(pts - center[:, None]) - radius[:, None]), axis=1)
    size = max(abs(o_b - o_a), crank, coupler, rocker)
    dev = np.where(np.isfinite(dev) & (radius < 20 * size), dev, np.inf)
    best = int(np.argmin(dev))
    if not np.isfinite(dev[best]):
        raise InputError("no stretch of the coupler curve is a circular arc of a drawable "
                         "radius", key="dwell")
    k1, k2, k3 = (int(idx[best, 0]), int(idx[best, w // 2]), int(idx[best, w]))
    cx = Construction(title="dwell: the center of the coupler curve's arc")
    for name, k in (("C1", k1), ("C2", k2), ("C3", k3)):
        z = complex(curve[k])
        cx.add("point", (), (name,), xy=(z.real, z.imag), role=Role.GIVEN, diagram=DIAGRAM,
               note=f"{name}: the coupler point at θ2 = {math.degrees(theta[k]) % 360:.6g}°.")
    cx.add("bisector", ("C1", "C2"), ("b_C12",), diagram=DIAGRAM,
           note="the bisector of C1C2.")
    cx.add("bisector", ("C2", "C3"), ("b_C23",), diagram=DIAGRAM,
           note="the bisector of C2C3.")
    cx.add("meet", ("b_C12", "b_C23"), ("D",), role=Role.RESULT, diagram=DIAGRAM,
           note="D: the center of the arc C1C2C3; link 5 (C D) keeps D still (Fig. 9.42a).")
    cx.add("circle_through", ("D", "C1"), ("k_D",), diagram=DIAGRAM,
           note="the circular arc of the coupler curve.")
    ev = cx.evaluate()
    dz = complex(ev["D"][0] / ev["D"][2], ev["D"][1] / ev["D"][2])
    r5 = abs(complex(curve[k2]) - dz)
    # link 6 perpendicular to link 5 at the middle of the dwell, as long as link 5
    o6 = dz + r5 * 1j * (dz - complex(curve[k2])) / r5
    return Dwell(o_a, crank, o_b, (crank, coupler, rocker), local, theta, curve, best,
                 best + w, dz, r5, float(dev[best]), o6, cx)


def _slider(o_a: complex, o_b: complex, lengths: tuple[float, float, float], local: complex,
            theta: np.ndarray, curve: np.ndarray, span: float) -> Dwell:
    """The slider dwell of Fig. 9.44: the straightest stretch, O6 on its line extended."""
    samples = len(curve)
    w = max(2, int(round(span / math.tau * samples)))
    w += w % 2
    idx = (np.arange(samples)[:, None] + np.arange(w + 1)[None, :]) % samples
    pts = curve[idx]
    c1, c3 = pts[:, 0], pts[:, w]
    chord = np.abs(c3 - c1)
    size = max(abs(o_b - o_a), *lengths)
    with np.errstate(divide="ignore", invalid="ignore"):
        unit = (c3 - c1) / chord
        off = np.abs(((pts - c1[:, None]) * np.conj(unit)[:, None]).imag)
        dev = np.max(off, axis=1)
        score = np.where(chord > 0.05 * size, dev / chord, np.inf)
    best = int(np.argmin(score))
    if not np.isfinite(score[best]):
        raise InputError("no stretch of the coupler curve over this crank span is long "
                         "enough to slide along", key="dwell")
    k1, k2, k3 = (int(idx[best, 0]), int(idx[best, w // 2]), int(idx[best, w]))
    z1, z3, length = complex(curve[k1]), complex(curve[k3]), float(chord[best])
    # O6 one stretch's length beyond one end of it: the end the whole curve keeps farther
    # from (link 6 turns fast where the block passes near O6, Sec. 9.13)
    ends = [(z3, z1), (z1, z3)]    # (from, through): O6 beyond `through`
    clear = [float(np.min(np.abs(curve - (2 * q - p)))) for p, q in ends]
    start, through = ends[int(np.argmax(clear))]
    cx = Construction(title="dwell: a slider on the coupler curve's straight stretch")
    for name, k in (("C1", k1), ("C2", k2), ("C3", k3)):
        z = complex(curve[k])
        cx.add("point", (), (name,), xy=(z.real, z.imag), role=Role.GIVEN, diagram=DIAGRAM,
               note=f"{name}: the coupler point at θ2 = {math.degrees(theta[k]) % 360:.6g}°.")
    cx.add("join", ("C1", "C3"), ("s_C13",), diagram=DIAGRAM,
           note="the line of the coupler curve's nearly straight stretch C1C2C3.")
    p_lab, q_lab = ("C3", "C1") if start == z3 else ("C1", "C3")
    cx.add("along_ray", (p_lab, q_lab), ("O6",), distance=2 * length, role=Role.RESULT,
           diagram=DIAGRAM, note=f"O6: on the line extended, a stretch's length beyond "
                                 f"{q_lab} (Fig. 9.44): while C runs C1C3 the slot keeps "
                                 "its direction and link 6 dwells.")
    ev = cx.evaluate()
    o6 = complex(ev["O6"][0] / ev["O6"][2], ev["O6"][1] / ev["O6"][2])
    if float(np.min(np.abs(curve - o6))) <= 1e-3 * size:
        raise InputError("the coupler curve passes through O6 on its line: no slider dwell "
                         "here (choose another span)", key="dwell")
    mid_c = complex(curve[k2])
    return Dwell(o_a, lengths[0], o_b, lengths, local, theta, curve, best, best + w, o6,
                 abs(mid_c - o6), float(dev[best]), o6, cx, DwellKind.SLIDER)
