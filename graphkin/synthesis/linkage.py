"""The synthesized four-bar: its mechanism file and its checks (Secs. 1.10, 9.6, 9.7).

Two dyads (a center point and its circle point each) make a four-bar
O_A A B O_B with the body as its coupler.  It is written as a graphkin
mechanism file assembled in a design posture (with assembly hints for the
branch), and checked: the postures reached in order by turning the crank one
way, on one branch with no toggle between them (the branch and order defects
of Sec. 9.7), the Grashof class (Eq. 1.6) and the transmission angle over
the motion.  The checks use their own closed-form four-bar (vectorised over
crank angles), not the kinematics package.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.10 (Grashof's law, Eq. 1.6),
Sec. 9.6 (intermediate limiting postures), Sec. 9.7 (branch and order defects).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphkin.construction.step import Side
from graphkin.synthesis.postures import Postures
from graphkin.text import fmt, toml_string

__all__ = ["Linkage", "Check", "MIN_TRANSMISSION", "grashof_class"]

MIN_TRANSMISSION = math.radians(40.0)
"""The transmission angle the checks ask for at least (and 180° minus it at most)."""

SAMPLES = 720
"""Crank angles sampled over the whole travel from the first posture to the last."""


@dataclass(frozen=True)
class Check:
    """One verdict on a linkage: its name, passed or not, and why, in words."""

    name: str
    passed: bool
    detail: str


def grashof_class(lengths: dict[str, float], rel: float = 1e-9) -> tuple[str, bool]:
    """The Grashof class of a four-bar from its lengths (Eq. 1.6), and whether it is Grashof.

    ``lengths``: ground, crank, coupler, rocker.  ``s + l`` is compared with
    ``p + q`` to ``rel`` of the longest link, so that a change-point linkage
    is called one whatever the round-off.
    """
    items = sorted(lengths.items(), key=lambda kv: kv[1])
    s, l_ = items[0][1], items[-1][1]
    p_q = items[1][1] + items[2][1]
    eps = rel * l_
    if abs(s + l_ - p_q) <= eps:
        return "change-point (s + l = p + q)", True
    if s + l_ > p_q:
        return "non-Grashof (triple-rocker): no link turns fully", False
    shortest = items[0][0]
    return {"ground": "Grashof double-crank (drag link)",
            "crank": "Grashof crank-rocker",
            "coupler": "Grashof double-rocker",
            "rocker": "Grashof rocker-crank"}[shortest], True


@dataclass
class Linkage:
    """A four-bar made of two dyads guiding the body through the postures.

    Parameters
    ----------
    post : Postures
    o_a, o_b : complex
        The center points (fixed pivots).
    a1, b1 : complex
        Their circle points (moving pivots) in posture 1.
    names : tuple of str
        The moving pivots' names (A and B unless the body's points use them).
    """

    post: Postures
    o_a: complex
    o_b: complex
    a1: complex
    b1: complex
    names: tuple[str, str] = ("A", "B")
    checks: list[Check] = field(default_factory=list)

    # ---- geometry ----------------------------------------------------------
    @property
    def pivots(self) -> tuple[np.ndarray, np.ndarray]:
        """A_j and B_j, complex arrays (N,)."""
        mo = self.post.motion()
        return mo.apply(self.a1), mo.apply(self.b1)

    @property
    def lengths(self) -> dict[str, float]:
        """The lengths: ground O_AO_B, crank O_AA, coupler AB, rocker O_BB."""
        return {"ground": abs(self.o_b - self.o_a), "crank": abs(self.a1 - self.o_a),
                "coupler": abs(self.b1 - self.a1), "rocker": abs(self.b1 - self.o_b)}

    def crank_angles(self) -> np.ndarray:
        """θ2 at each design posture (rad)."""
        a, _ = self.pivots
        return np.angle(a - self.o_a)

    def _branch(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Which side of A → O_B the pin B is: +1 left, −1 right (the assembly branch)."""
        u, v = self.o_b - a, b - a
        return np.sign(u.real * v.imag - u.imag * v.real)

    def _solve(self, psi: np.ndarray, side: float) -> tuple[np.ndarray, np.ndarray]:
        """B and the closure margin h² at crank angles ``psi`` on one branch (closed form)."""
        lg = self.lengths
        a = self.o_a + lg["crank"] * np.exp(1j * psi)
        d = self.o_b - a
        dist = np.abs(d)
        along = (dist ** 2 + lg["coupler"] ** 2 - lg["rocker"] ** 2) / (2 * dist)
        h2 = lg["coupler"] ** 2 - along ** 2
        h = np.sqrt(np.maximum(h2, 0.0))
        u = d / dist
        return a + along * u + side * h * 1j * u, h2 / self.post.scale ** 2

    def travel(self) -> tuple[float, float]:
        """The crank's sense (+1 ccw, −1 cw) and its travel from the first posture to the last."""
        psi = self.crank_angles()
        ccw = float(np.sum(np.mod(np.diff(psi), math.tau)))
        cw = float(np.sum(np.mod(-np.diff(psi), math.tau)))
        return (1.0, ccw) if ccw <= cw else (-1.0, cw)

    def coupler_path(self, count: int = SAMPLES) -> np.ndarray:
        """The body's reference point over the crank's travel, on the first posture's branch.

        Complex; NaN where the linkage cannot assemble.
        """
        a, b = self.pivots
        side = float(self._branch(a[:1], b[:1])[0]) or 1.0
        sense, travel = self.travel()
        track = float(self.crank_angles()[0]) + sense * np.linspace(0.0, travel, count)
        bb, h2 = self._solve(track, side)
        aa = self.o_a + self.lengths["crank"] * np.exp(1j * track)
        d_local = (complex(*self.post.points[0]) - a[0]) / (b[0] - a[0])
        return np.where(h2 >= 0, aa + (bb - aa) * d_local, np.nan)

    # ---- the checks ----------------------------------------------------------
    def check(self) -> list[Check]:
        """Run every check and keep the verdicts in :attr:`checks`."""
        out: list[Check] = []
        lg = self.lengths
        scale = self.post.scale
        small = [k for k, v in lg.items() if v <= 1e-9 * scale]
        if small:
            out.append(Check("links", False, f"the {small[0]} has no length"))
            self.checks = out
            return out
        a, b = self.pivots
        sides = self._branch(a, b)
        one = bool(np.all(sides == sides[0]) and sides[0] != 0)
        na, nb = self.names
        side = Side.LEFT if sides[0] > 0 else Side.RIGHT
        out.append(Check("branch", one, f"every posture on one branch ({nb} {side} of "
                                        f"{na} → O_{nb})" if one else
                         "posture(s) " + ", ".join(str(k + 1) for k in np.nonzero(
                             sides != sides[0])[0]) + " on the other branch (branch defect)"))
        psi = self.crank_angles()
        sense, travel = self.travel()
        ordered = travel < math.tau
        out.append(Check("order", ordered,
                         f"postures in order turning the crank {'ccw' if sense > 0 else 'cw'} "
                         f"through {fmt(math.degrees(travel))}°" if ordered else
                         "the crank passes a later posture before an earlier one (order defect)"))
        grashof, _ = grashof_class(lg)
        out.append(Check("grashof", True, grashof))
        track = psi[0] + sense * np.linspace(0.0, travel, SAMPLES)
        _, h2 = self._solve(track, float(sides[0]))
        margin = float(np.min(h2))
        free = margin > 1e-12
        out.append(Check("toggle", free, "no toggle between the postures" if free else
                         "the linkage reaches a toggle (dead) posture between the postures"))
        bb, _ = self._solve(track, float(sides[0]))
        aa = self.o_a + lg["crank"] * np.exp(1j * track)
        cos_mu = np.real(np.conj(aa - bb) * (self.o_b - bb)) / (lg["coupler"] * lg["rocker"])
        mu = np.degrees(np.arccos(np.clip(cos_mu, -1.0, 1.0)))
        worst = float(np.min(np.minimum(mu, 180.0 - mu)))
        good = free and worst >= math.degrees(MIN_TRANSMISSION)
        out.append(Check("transmission", good,
                         f"transmission angle μ from {fmt(float(np.min(mu)))}° to "
                         f"{fmt(float(np.max(mu)))}° over the motion (at least "
                         f"{fmt(math.degrees(MIN_TRANSMISSION))}° from a toggle asked)"))
        self.checks = out
        return out

    @property
    def ok(self) -> bool:
        """Whether every check passed (run :meth:`check` first)."""
        return bool(self.checks) and all(c.passed for c in self.checks)

    # ---- the mechanism file -----------------------------------------------------
    def mechanism_toml(self, k: int = 0, title: str = "", units: str = "mm") -> str:
        """The graphkin mechanism file of the linkage assembled in design posture ``k``.

        Links: 1 the frame (O_A, O_B), 2 the crank, 3 the coupler (the body,
        with its reference point, and its second point when the postures gave
        it), 4 the rocker; the drive is the crank at
        its angle in posture ``k``; the assembly hints place B and the body's
        points where they are in that posture, so graphkin takes the design's
        branch.
        """
        na, nb = self.names
        d, e = self.post.names
        a, b = self.pivots
        lg = {k: float(v) for k, v in self.lengths.items()}
        rot = np.exp(-1j * np.angle(b[0] - a[0]))
        dpos = self.post.positions((0.0, 0.0))
        epos = self.post.positions(self.post.second)
        dl = (complex(*dpos[0]) - a[0]) * rot
        el = (complex(*epos[0]) - a[0]) * rot

        drive = math.degrees(float(np.angle(a[k] - self.o_a)))

        def xy(z: complex) -> str:
            return f"[{float(z.real)!r}, {float(z.imag)!r}]"

        # the body's second point only when the user gave it (two points per posture);
        # with a point and an angle it was the construction's alone
        second = self.post.second_given
        lines = [f'title = {toml_string(title or "Four-bar by synthesis")}',
                 f'units = {{ length = "{units}" }}', "",
                 "[links.1]", f"O_{na} = {xy(self.o_a)}", f"O_{nb} = {xy(self.o_b)}", "",
                 "[links.2]", f"O_{na} = [0.0, 0.0]", f"{na} = [{lg['crank']!r}, 0.0]", "",
                 "[links.3]", f"{na} = [0.0, 0.0]", f"{nb} = [{lg['coupler']!r}, 0.0]",
                 f"{d} = {xy(dl)}", *([f"{e} = {xy(el)}"] if second else []), "",
                 "[links.4]", f"O_{nb} = [0.0, 0.0]", f"{nb} = [{lg['rocker']!r}, 0.0]", "",
                 "[drive]", "link = 2", f"angle = {drive!r}",
                 "", "[assembly]", f"{nb} = {xy(b[k])}", f"{d} = {xy(complex(*dpos[k]))}",
                 *([f"{e} = {xy(complex(*epos[k]))}"] if second else []), ""]
        return "\n".join(lines)
