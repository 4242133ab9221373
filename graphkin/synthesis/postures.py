"""Postures of a moving body and the poles of its finite displacements (Secs. 9.3-9.5).

A posture is the body's reference point and its angle (or two of its
points).  The pole P_ij is constructed as the book does it: the
perpendicular bisectors of D_iD_j and E_iE_j, for two points D and E of the
body, meet at the pole (Figs. 9.5, 9.7).  Every step is recorded in a
:class:`~graphkin.construction.Construction` with the book's names.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.3 (pole of a finite displacement,
Eq. 9.2), Sec. 9.4 (Fig. 9.7, the pole triangle), Sec. 9.5 (six poles).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from itertools import combinations

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.errors import InputError
from graphkin.synthesis import analytic as an
from graphkin.synthesis import ops as _ops  # noqa: F401  (registers the operations)
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["Postures", "pole_label", "add_postures", "add_poles", "evaluate_points",
           "DIAGRAM"]

DIAGRAM = "synthesis"
"""The diagram name of every synthesis step."""


def pole_label(i: int, j: int) -> str:
    """``P12``: the book's name of the pole of postures i and j (1-based, as given)."""
    return f"P{i}{j}"


@dataclass(frozen=True)
class Postures:
    """N finitely separated postures of a rigid body.

    Parameters
    ----------
    points : ndarray, shape (N, 2)
        The body's reference point (``names[0]``) in each posture.
    angles : ndarray, shape (N,)
        The body's angle in each posture (rad, counterclockwise).
    names : tuple of str
        The names of the body's two marked points (the book's D and E of
        Fig. 9.7 unless the file names them).
    second : tuple of float
        The second point in the body's own coordinates (reference point at the
        origin, the body's x axis at its angle).
    source : str
        The file, for the messages.
    second_given : bool
        Whether the second point is the user's (two points of the body given).
        When the postures were given as a point and an angle, the second point
        is only the construction's (the bisectors of E_iE_j find the poles): it
        is drawn without a letter and not written in the mechanism file.
    """

    points: np.ndarray
    angles: np.ndarray
    names: tuple[str, str] = ("D", "E")
    second: tuple[float, float] = (1.0, 0.0)
    source: str = "<synthesis>"
    key: str = "postures"
    tol: Tolerance = field(default=DEFAULT_TOL)
    second_given: bool = True

    @property
    def n(self) -> int:
        """The number of postures."""
        return len(self.angles)

    @property
    def scale(self) -> float:
        """The size of the figure: the spread of the reference points and the body's length."""
        spread = float(np.max(np.ptp(self.points, axis=0))) if self.n > 1 else 0.0
        return max(spread, math.hypot(*self.second), 1e-300)

    def motion(self) -> an.Motion:
        """The displacements from posture 1 (complex form, :mod:`.analytic`)."""
        return an.motion(self.points[:, 0] + 1j * self.points[:, 1], self.angles)

    def positions(self, local: tuple[float, float] | np.ndarray) -> np.ndarray:
        """The positions ``(N, 2)`` of the body point with body coordinates ``local``."""
        u = np.asarray(local, dtype=float)
        c, s = np.cos(self.angles), np.sin(self.angles)
        return self.points + np.stack([c * u[0] - s * u[1], s * u[0] + c * u[1]], axis=-1)

    def local(self, xy: np.ndarray, k: int = 0) -> tuple[float, float]:
        """Body coordinates of the point that is at ``xy`` in posture ``k`` (0-based)."""
        d = np.asarray(xy, dtype=float) - self.points[k]
        c, s = math.cos(self.angles[k]), math.sin(self.angles[k])
        return (float(c * d[0] + s * d[1]), float(-s * d[0] + c * d[1]))

    def check(self) -> None:
        """Refuse coincident postures and pure translations (a pole at infinity).

        Raises
        ------
        InputError
            Naming the file, the postures' key and the two postures.
        """
        eps = self.tol.length(self.scale)
        for i, j in combinations(range(self.n), 2):
            dth = math.remainder(float(self.angles[j] - self.angles[i]), math.tau)
            moved = float(np.hypot(*(self.points[j] - self.points[i])))
            if abs(dth) <= self.tol.angle and moved <= eps:
                raise InputError(f"postures {i + 1} and {j + 1} coincide (a pole needs two "
                                 "different postures)", key=self.key, file=self.source)
            # the pole lies |moved| / (2 sin(dth/2)) from the points: at infinity when the
            # body only translates (within round-off of the figure's size)
            if abs(2 * math.sin(dth / 2)) * self.scale * 1e6 <= moved:
                raise InputError(
                    f"postures {i + 1} and {j + 1} differ by a translation only: the pole "
                    f"P{i + 1}{j + 1} is at infinity (turn the body between them)",
                    key=self.key, file=self.source)


def add_postures(cx: Construction, post: Postures) -> list[tuple[str, str, str]]:
    """Record the given postures: the body's two points D_j, E_j and its angle θ_j.

    Returns the labels ``(D_j, E_j, θ_j)`` of each posture.
    """
    d, e = post.names
    out = []
    for j in range(post.n):
        k = j + 1
        dj, ej, tj = f"{d}{k}", f"{e}{k}", f"θ{k}"
        cx.add("point", (), (dj,), xy=tuple(map(float, post.points[j])), role=Role.GIVEN,
               diagram=DIAGRAM, note=f"{d}{k}: the body's point {d} in posture {k} (given).")
        cx.add("scalar", (), (tj,), value=float(post.angles[j]), role=Role.GIVEN,
               diagram=DIAGRAM, note=f"θ{k}: the body's angle in posture {k} (given).")
        cx.add("rigid", (dj, tj), (ej,), local_p=(0.0, 0.0), local_q=tuple(post.second),
               role=Role.GIVEN, diagram=DIAGRAM,
               note=f"{e}{k}: the body's point {e} in posture {k}; the line {d}{k}{e}{k} "
                    f"marks the body (Fig. 9.7).")
        out.append((dj, ej, tj))
    return out


def add_poles(cx: Construction, post: Postures, labels: list[tuple[str, str, str]],
              pairs: list[tuple[int, int]]) -> list[str]:
    """Record the pole of each pair of postures (1-based): two bisectors meet at P_ij.

    When a marked point does not move between the two postures it is itself
    the pole; when the two bisectors coincide, the bisector of a third point
    of the body is drawn instead.
    """
    out = []
    d, e = post.names
    for i, j in pairs:
        di, ei, ti = labels[i - 1]
        dj, ej, tj = labels[j - 1]
        name = pole_label(i, j)
        rot = post.angles[j - 1] - post.angles[i - 1]
        note = (f"{name}: the bisectors of {d}{i}{d}{j} and {e}{i}{e}{j} meet at the pole, "
                f"the point of the body that does not move from posture {i} to {j}; "
                f"θ{i}{j} = {math.degrees(math.remainder(rot, math.tau)):.6g}° (Eq. 9.2).")
        # a point is the pole itself only where no line joins its two positions (the test of
        # graphkin.geometry.join: within round-off of their distance from the origin); one
        # that moves by more still has an accurate bisector (its direction errs by
        # round-off over the move, at about the move's distance from the pole), while
        # calling it the pole would err by the move
        fixed = [(p, q, loc) for p, q, loc in ((di, dj, (0.0, 0.0)), (ei, ej, post.second))
                 if _no_line(post.positions(loc)[[i - 1, j - 1]], post.tol)]
        if fixed:
            cx.add("rigid", (labels[i - 1][0], ti), (name,), local_p=(0.0, 0.0),
                   local_q=fixed[0][2], role=Role.RESULT, diagram=DIAGRAM,
                   note=f"{name}: {fixed[0][0]} does not move from posture {i} to {j}, so it "
                        f"is the pole (Sec. 9.3).")
            out.append(name)
            continue
        b1, b2 = f"b_{d}{i}{j}", f"b_{e}{i}{j}"
        cx.add("bisector", (di, dj), (b1,), diagram=DIAGRAM,
               note=f"{b1}: the perpendicular bisector of {d}{i}{d}{j}.")
        second = (ei, ej)
        if _same_line(post, i, j):
            # D, E and the pole on one line: their bisectors coincide; use a third point
            f_loc = (-post.second[1], post.second[0])
            fi, fj = f"{d}⊥{e}{i}", f"{d}⊥{e}{j}"
            for lab, th, k in ((fi, ti, i), (fj, tj, j)):
                if lab not in cx.labels:
                    cx.add("rigid", (labels[k - 1][0], th), (lab,), local_p=(0.0, 0.0),
                           local_q=f_loc, diagram=DIAGRAM,
                           note=f"{lab}: a third point of the body in posture {k} (the "
                                f"bisectors of {d} and {e} coincide).")
            second, b2 = (fi, fj), f"b_{d}⊥{e}{i}{j}"
        cx.add("bisector", second, (b2,), diagram=DIAGRAM,
               note=f"{b2}: the perpendicular bisector of {second[0]}{second[1]}.")
        cx.add("meet", (b1, b2), (name,), role=Role.RESULT, diagram=DIAGRAM, note=note)
        out.append(name)
    return out


def _no_line(pq: np.ndarray, tol: Tolerance) -> bool:
    """Whether two positions are too close for a line to join them (as ``join`` decides)."""
    move = float(np.hypot(*(pq[1] - pq[0])))
    return move <= tol.length(float(np.max(np.hypot(pq[:, 0], pq[:, 1]))))


def _same_line(post: Postures, i: int, j: int) -> bool:
    """Whether the bisectors of D_iD_j and E_iE_j coincide (within round-off)."""
    pd = post.positions((0.0, 0.0))[[i - 1, j - 1]]
    pe = post.positions(post.second)[[i - 1, j - 1]]
    ud, ue = pd[1] - pd[0], pe[1] - pe[0]
    md, me = pd.mean(axis=0), pe.mean(axis=0)
    cross = ud[0] * ue[1] - ud[1] * ue[0]
    par = abs(cross) <= post.tol.angle * np.hypot(*ud) * np.hypot(*ue)
    off = abs(np.dot(me - md, ud)) <= post.tol.length(post.scale) * np.hypot(*ud)
    return bool(par and off)


def evaluate_points(cx: Construction, labels: list[str]) -> dict[str, complex]:
    """The values of point labels as complex numbers (NaN for a point at infinity)."""
    ev = cx.evaluate(strict=False)
    out = {}
    for lab in labels:
        v = np.asarray(ev[lab], dtype=float)
        out[lab] = complex(v[0] / v[2], v[1] / v[2]) if v[2] != 0 else complex(np.nan, np.nan)
    return out
