"""Function generation: Chebyshev spacing, Freudenstein's equation, structural error.

The precision points are spaced by Eq. 9.22, mapped linearly to crank angles
φ and rocker angles ψ, and Freudenstein's equation (9.24) written at the
three of them gives K1, K2, K3 and the link lengths (Eqs. 9.25-9.27).  The
structural error (Sec. 9.7) is the generated y minus f(x) over the range, the
linkage solved in closed form on the branch of the first precision point.

In Freudenstein's loop (Fig. 9.39) ``r4`` runs from the coupler pin C to the
rocker's pivot O4, so the rocker's own angle (O4 → C) is ``θ4 + 180°``.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.7 (Eq. 9.22), 9.11 (Eqs.
9.24-9.27, Example 9.7, Table 9.2).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.synthesis import analytic as an
from graphkin.synthesis.postures import DIAGRAM
from graphkin.synthesis.spec import FunctionSpec
from graphkin.text import toml_string

__all__ = ["FunctionDesign", "design", "chebyshev_construction"]


@dataclass(frozen=True)
class FunctionDesign:
    """The synthesized function generator."""

    spec: FunctionSpec
    x: np.ndarray
    y: np.ndarray
    phi: np.ndarray
    psi: np.ndarray
    k: np.ndarray
    lengths: tuple[float, float, float, float]
    branch: float
    error_x: np.ndarray
    error: np.ndarray

    def mechanism_toml(self, title: str = "", units: str = "mm", j: int = 0) -> str:
        """The mechanism file, the crank at precision point ``j`` (0-based)."""
        r1, r2, r3, r4 = self.lengths
        phi = float(self.phi[j])
        c = complex(r1, 0.0) - r4 * np.exp(1j * float(self.psi[j]))
        return "\n".join([
            f'title = {toml_string(title or "Function generator by Freudenstein")}',
            f'units = {{ length = "{units}" }}', "",
            "[links.1]", "O2 = [0.0, 0.0]", f"O4 = [{r1!r}, 0.0]", "",
            "[links.2]", "O2 = [0.0, 0.0]", f"B = [{r2!r}, 0.0]", "",
            "[links.3]", "B = [0.0, 0.0]", f"C = [{r3!r}, 0.0]", "",
            "[links.4]", "O4 = [0.0, 0.0]", f"C = [{r4!r}, 0.0]", "",
            "[drive]", "link = 2", f"angle = {math.degrees(phi)!r}", "",
            "[assembly]", f"C = [{float(c.real)!r}, {float(c.imag)!r}]", ""])


def chebyshev_construction(x0: float, x1: float, n: int) -> Construction:
    """Chebyshev spacing drawn as in Fig. 9.27.

    A circle on the range as diameter, a regular polygon of 2n sides in it
    with its first side perpendicular to the x axis, and the perpendiculars
    from its vertices to the diameter.  The feet (labels ``x_1`` ... ``x_n``)
    are the precision points of Eq. 9.22: vertex j stands at the angle
    ``π − (2j − 1)π / 2n`` about the circle's center, so its foot is
    ``(x0 + x1)/2 − (x1 − x0)/2 · cos((2j − 1)π / 2n)``.
    """
    cx = Construction(title="Chebyshev spacing (Fig. 9.27)")
    half = (x1 - x0) / 2
    cx.add("point", (), ("X0",), xy=(x0, 0.0), role=Role.GIVEN, diagram=DIAGRAM,
           note="X0: the start of the range on the x axis.")
    cx.add("point", (), ("X1",), xy=(x1, 0.0), role=Role.GIVEN, diagram=DIAGRAM,
           note="X1: the end of the range.")
    cx.add("circle_on_diameter", ("X0", "X1"), ("k",), diagram=DIAGRAM,
           note="the circle whose diameter is the range Δx (Eq. c).")
    cx.add("join", ("X0", "X1"), ("diameter",), diagram=DIAGRAM, note="the diameter X0X1.")
    cx.add("scalar", (), ("θ0",), value=0.0, diagram=DIAGRAM, note="the x axis's direction.")
    cx.add("rigid", ("X0", "θ0"), ("C",), local_p=(0.0, 0.0), local_q=(half, 0.0),
           diagram=DIAGRAM, note="C: the circle's center.")
    for j in range(1, n + 1):
        ang = math.pi - (2 * j - 1) * math.pi / (2 * n)
        cx.add("scalar", (), (f"∠V{j}",), value=ang, diagram=DIAGRAM,
               note=f"vertex {j} of the regular {2 * n}-gon, {math.degrees(ang):.6g}° about C.")
        cx.add("rigid", ("C", f"∠V{j}"), (f"V{j}",), local_p=(0.0, 0.0), local_q=(half, 0.0),
               diagram=DIAGRAM, note=f"V{j}: a vertex of the {2 * n}-gon inscribed in the "
                                     f"circle, its first side perpendicular to the x axis.")
        cx.add("perpendicular", ("diameter", f"V{j}"), (f"n{j}",), diagram=DIAGRAM,
               note=f"the perpendicular dropped from V{j} to the diameter.")
        cx.add("meet", ("diameter", f"n{j}"), (f"x_{j}",), role=Role.RESULT, diagram=DIAGRAM,
               note=f"x_{j}: precision point {j} (Eq. 9.22).")
    return cx


def _rocker(phi: np.ndarray, lengths: tuple[float, float, float, float],
            branch: float) -> tuple[np.ndarray, np.ndarray]:
    """θ4 of Freudenstein's loop at crank angles φ on one branch, and the closure margin.

    The loop is ``r2 e^{iφ} + r3 e^{iθ3} + r4 e^{iθ4} = r1`` (Fig. 9.39); the
    lengths of Eqs. 9.25-9.27 carry signs, so θ4 is the angle of ``(O4 − C)/r4``.
    """
    r1, r2, r3, r4 = lengths
    b = r2 * np.exp(1j * phi)
    o4 = complex(r1, 0.0)
    d = o4 - b
    dist = np.abs(d)
    along = (dist ** 2 + r3 ** 2 - r4 ** 2) / (2 * dist)
    h2 = r3 ** 2 - along ** 2
    u = d / dist
    c = b + along * u + branch * np.sqrt(np.maximum(h2, 0.0)) * 1j * u
    # r4 e^{iθ4} = O4 − C: a negative r4 (Eq. 9.25 with K1 < 0) turns the
    # vector O4 − C half a turn away from θ4, so divide by r4, not by |r4|
    return np.angle((o4 - c) / r4), h2


def design(fs: FunctionSpec, samples: int = 201) -> FunctionDesign:
    """Synthesize the function generator of ``fs`` and its structural error."""
    x0, x1 = fs.x_range
    x = an.chebyshev(x0, x1, fs.points)
    y = fs.f(x)
    ya, yb = fs.f(np.array([x0, x1]))
    phi = fs.input_start + fs.input_span * (x - x0) / (x1 - x0)
    psi = fs.output_start + fs.output_span * (y - ya) / (yb - ya)
    k = an.freudenstein(phi, psi)
    lengths = an.freudenstein_lengths(k, fs.ground)
    r1, r2, r3, r4 = lengths
    b = r2 * np.exp(1j * phi[0])
    c = complex(r1, 0.0) - r4 * np.exp(1j * psi[0])
    u, v = complex(r1, 0.0) - b, c - b
    branch = float(np.sign(u.real * v.imag - u.imag * v.real)) or 1.0
    ex = np.linspace(x0, x1, samples)
    th, h2 = _rocker(fs.input_start + fs.input_span * (ex - x0) / (x1 - x0), lengths, branch)
    # the generated y: the rocker's angle mapped back (θ4 near the ψ range, mod 360°)
    ref = fs.output_start + fs.output_span / 2
    th = ref + np.mod(th - ref + math.pi, math.tau) - math.pi
    gen = ya + (th - fs.output_start) * (yb - ya) / fs.output_span
    err = np.where(h2 >= 0, gen - fs.f(ex), np.nan)
    return FunctionDesign(fs, x, y, phi, psi, k, lengths, branch, ex, err)
