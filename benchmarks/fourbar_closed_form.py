"""A closed-form, vectorized numpy four-bar: the yardstick of ``graphkin sweep``.

Nothing here uses graphkin's constructions.  The posture comes from
Freudenstein's equation as the textbook writes it in Example 2.5(d)
(Uicker, Pennock & Shigley, 5th ed., Sec. 2.12): with the loop
``R_BA + R_CB = R_DA + R_CD`` (crank r2 from A, coupler r3 from B, rocker
r4 from D, frame r1 from A to D at angle θ1), squaring and adding the
components eliminates θ3::

    P cos θ4 + Q sin θ4 = S,
    P = 2 r1 r4 cos θ1 - 2 r4 r2 cos θ2,
    Q = 2 r1 r4 sin θ1 - 2 r4 r2 sin θ2,
    S = r3² - r1² - r4² - r2² + 2 r1 r2 cos(θ2 - θ1),

so ``θ4 = atan2(Q, P) ± acos(S / √(P² + Q²))`` and θ3 follows from the loop.
Velocities and accelerations are the loop-closure derivatives of Secs. 3.9
and 4.9 (the loop differentiated once and twice, then dotted with the
normals of the unknown directions)::

    ω3 = r2 ω2 sin(θ4 - θ2) / (r3 sin(θ3 - θ4)),
    ω4 = r2 ω2 sin(θ3 - θ2) / (r4 sin(θ3 - θ4)),
    α3 = (Kx cos θ4 + Ky sin θ4) / (r3 sin(θ3 - θ4)) ... (see the code),

and every point of a link follows from Eqs. 3.4 and 4.5:
``V_P = V_O + ω × R_PO``, ``A_P = A_O + α × R_PO - ω² R_PO``.

It produces the same columns as ``graphkin sweep`` (``docs/formats/sweep-csv.md``) so that
both do the same work when they are timed against each other.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

__all__ = ["FourBar", "fourbar_from_mechanism", "fourbar_batch", "wrap_deg"]


def wrap_deg(rad: np.ndarray) -> np.ndarray:
    """Angles in degrees in (-180, 180]."""
    d = np.degrees(rad)
    d -= 360.0 * np.ceil((d - 180.0) * (1.0 / 360.0))
    return d


class FourBar:
    """A four-bar A-B-C-D (A, D on the frame) with any further points on its links.

    Parameters
    ----------
    A, D : (x, y)
        The frame pivots.
    links : dict
        Link id -> {point name: local (x, y)}, for the frame ``"1"``, crank
        ``"2"`` (A, B, ...), coupler ``"3"`` (B, C, ...) and rocker ``"4"``
        (D, C, ...), as in a mechanism file.
    sign : float
        +1 or -1: which root of Freudenstein's equation (the posture).
    """

    def __init__(self, links: dict[str, dict[str, tuple[float, float]]], sign: float,
                 names: tuple[str, str, str, str] = ("A", "B", "C", "D"),
                 ids: tuple[str, str, str, str] = ("1", "2", "3", "4")) -> None:
        a, b, c, d = names
        self.names = names
        self.ids = ids
        self.links = links
        f, k2, k3, k4 = ids
        self.A = links[f][a]
        self.D = links[f][d]
        v = (self.D[0] - self.A[0], self.D[1] - self.A[1])
        self.r1 = np.hypot(*v)
        self.t1 = np.arctan2(v[1], v[0])

        def seg(lid: str, p: str, q: str) -> tuple[Any, Any]:
            dx = links[lid][q][0] - links[lid][p][0]
            dy = links[lid][q][1] - links[lid][p][1]
            return np.hypot(dx, dy), np.arctan2(dy, dx)

        # link lengths and where each link's own x axis stands from its line
        self.r2, self.phi2 = seg(k2, a, b)
        self.r3, self.phi3 = seg(k3, b, c)
        self.r4, self.phi4 = seg(k4, d, c)
        self.sign = sign

    def solve(self, theta2: np.ndarray, omega2: float, alpha2: float,
              crank_angle: bool = True) -> dict[str, np.ndarray]:
        """Every column of ``graphkin sweep`` for the crank's x-axis angles ``theta2`` (rad)."""
        r1, r2, r3, r4, t1 = self.r1, self.r2, self.r3, self.r4, self.t1
        # direction of the crank line AB (the link's x axis plus the line's local angle)
        q2 = theta2 + self.phi2
        c2, s2 = np.cos(q2), np.sin(q2)
        c1, s1 = np.cos(t1), np.sin(t1)
        # Freudenstein's equation P cos θ4 + Q sin θ4 = S (Example 2.5, Eqs. 4-5)
        P = (2 * r1 * r4 * c1) - (2 * r4 * r2) * c2
        Q = (2 * r1 * r4 * s1) - (2 * r4 * r2) * s2
        S = (r3 * r3 - r1 * r1 - r4 * r4 - r2 * r2) + (2 * r1 * r2) * (c2 * c1 + s2 * s1)
        with np.errstate(invalid="ignore", divide="ignore"):
            q4 = np.arctan2(Q, P) + self.sign * np.arccos(S / np.sqrt(P * P + Q * Q))
            c4, s4 = np.cos(q4), np.sin(q4)
            # θ3 from the loop: r3 e^{iθ3} = r1 e^{iθ1} + r4 e^{iθ4} - r2 e^{iθ2}
            X = (r1 * c1) + r4 * c4 - r2 * c2
            Y = (r1 * s1) + r4 * s4 - r2 * s2
            q3 = np.arctan2(Y, X)
            c3, s3 = X / r3, Y / r3            # |R_CB| = r3
            # velocities: ω3, ω4 from the differentiated loop (Sec. 3.9)
            s34 = s3 * c4 - c3 * s4                    # sin(θ3 - θ4)
            w3 = (r2 * omega2) * (s4 * c2 - c4 * s2) / (r3 * s34)
            w4 = (r2 * omega2) * (s3 * c2 - c3 * s2) / (r4 * s34)
            # accelerations (Sec. 4.9): r3 α3 e^{iθ3} - r4 α4 e^{iθ4} = -K with
            # K = r2 α2 e^{iθ2} + i (r2 ω2² e^{iθ2} + r3 ω3² e^{iθ3} - r4 ω4² e^{iθ4})
            n2, n3, n4 = r2 * omega2 * omega2, r3 * w3 * w3, r4 * w4 * w4
            Kx = (r2 * alpha2) * c2 - (n2 * s2 + n3 * s3 - n4 * s4)
            Ky = (r2 * alpha2) * s2 + (n2 * c2 + n3 * c3 - n4 * c4)
            a3 = -(Ky * c4 - Kx * s4) / (r3 * s34)
            a4 = -(Ky * c3 - Kx * s3) / (r4 * s34)
        f, k2, k3, k4 = self.ids
        a, b, c, d = self.names
        ax, ay = self.A
        dx, dy = self.D
        # one design: shape (N,); a batch of designs (lengths of shape (M, 1)): (M, N)
        zero = np.zeros(np.broadcast_shapes(np.shape(theta2), np.shape(r2), np.shape(r3),
                                            np.shape(r4), np.shape(r1)))
        # link poses: (x-axis angle, cos, sin of the line, anchor point, anchor local,
        # anchor position/velocity/acceleration, ω, α)
        t3 = q3 - self.phi3
        t4 = q4 - self.phi4
        ab = (ax + r2 * c2, ay + r2 * s2)
        vb = (-(r2 * omega2) * s2, (r2 * omega2) * c2)
        abx = -(r2 * alpha2) * s2 - n2 * c2
        aby = (r2 * alpha2) * c2 - n2 * s2
        poses = {
            k2: (theta2, q2, c2, s2, a, (ax, ay), (0.0, 0.0), (0.0, 0.0), omega2, alpha2),
            k3: (t3, q3, c3, s3, b, ab, vb, (abx, aby), w3, a3),
            k4: (t4, q4, c4, s4, d, (dx, dy), (0.0, 0.0), (0.0, 0.0), w4, a4),
        }
        cols: dict[str, np.ndarray] = {"drive": np.degrees(theta2) + zero}
        cols[f"angle_{f}"] = zero
        cols[f"omega_{f}"] = zero
        cols[f"alpha_{f}"] = zero
        for lid in (k2, k3, k4):
            t, _, _, _, _, _, _, _, w, al = poses[lid]
            cols[f"angle_{lid}"] = wrap_deg(t + zero)
            cols[f"omega_{lid}"] = w + zero
            cols[f"alpha_{lid}"] = al + zero
        done: set[str] = set()
        for lid in (f, k2, k3, k4):
            for name, loc in self.links[lid].items():
                if name in done:
                    continue
                done.add(name)
                if lid == f:
                    x, y = loc
                    cols[f"x_{name}"] = zero + x
                    cols[f"y_{name}"] = zero + y
                    for k in ("vx_", "vy_", "ax_", "ay_"):
                        cols[k + name] = zero
                    continue
                _, q, cq, sq, anchor, (px, py), (vx, vy), (qx, qy), w, al = poses[lid]
                lp = self.links[lid][anchor]
                # R_PO in the link's own frame, turned by the line's angle
                ux, uy = loc[0] - lp[0], loc[1] - lp[1]
                phi = {k2: self.phi2, k3: self.phi3, k4: self.phi4}[lid]
                cp, sp = np.cos(-phi), np.sin(-phi)
                ux, uy = cp * ux - sp * uy, sp * ux + cp * uy
                rx = cq * ux - sq * uy
                ry = sq * ux + cq * uy
                cols[f"x_{name}"] = px + rx
                cols[f"y_{name}"] = py + ry
                cols[f"vx_{name}"] = vx - w * ry
                cols[f"vy_{name}"] = vy + w * rx
                ww = w * w
                cols[f"ax_{name}"] = qx - al * ry - ww * rx
                cols[f"ay_{name}"] = qy + al * rx - ww * ry
        return cols


def fourbar_from_mechanism(mech: Any) -> FourBar:
    """The closed form for a graphkin four-bar (links 1-4, pins A, B, C, D as in the file).

    The root of Freudenstein's equation is the one whose C is nearer the
    file's ``[assembly]`` hint at the file's drive angle.
    """
    links = {lid: dict(link.points) for lid, link in mech.links.items()}
    drive = mech.drives[0]
    best = None
    for sign in (1.0, -1.0):
        fb = FourBar(links, sign)
        cols = fb.solve(np.array([drive.value]), 0.0, 0.0)
        hint = mech.assembly.get("C")
        if hint is None:
            return fb
        dist = math.hypot(cols["x_C"][0] - hint[0], cols["y_C"][0] - hint[1])
        if best is None or dist < best[0]:
            best = (dist, fb)
    assert best is not None
    return best[1]


def fourbar_batch(mech: Any, dimensions: dict[str, Any]) -> FourBar:
    """The closed form for many designs at once: ``"links.<k>.<P>"`` -> ``(M, 2)`` arrays.

    Every varied coordinate becomes an ``(M, 1)`` column, so the lengths, and
    every column :meth:`FourBar.solve` returns, have the shape ``(M, N)``.
    The root of Freudenstein's equation is the file's design's.
    """
    base = fourbar_from_mechanism(mech)
    links: dict[str, dict[str, Any]] = {lid: dict(link.points) for lid, link in mech.links.items()}
    for key, value in dimensions.items():
        _, lid, name = key.split(".")
        a = np.asarray(value, dtype=float)
        links[lid][name] = (a[:, 0:1], a[:, 1:2])
    return FourBar(links, base.sign)
