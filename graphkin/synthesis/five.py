"""Five postures: the Burmester points (Sec. 9.6).

The center points of postures 1234 form one cubic and those of 1235 another;
their common points other than the poles P12, P13, P23 are the Burmester
center points (0, 2 or 4 of them real), whose circle points pass through all
five postures on one circle.  By construction: the center-point curve of
1234 is drawn as in Sec. 9.5 (the construction of :mod:`.four`, evaluated on
an array of t); for each of its points, the circle point A1 is carried to
posture 5 by the rotation θ15 about P15 (two mirrors in lines through P15,
φ15 apart), and the center point is a Burmester point where A5 falls on the
circle through A1..A4.  The roots are bracketed along the curve and halved
(every halving one evaluation of the construction on all brackets at once).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 9.6.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from graphkin.construction import Construction
from graphkin.construction.step import Role
from graphkin.synthesis.analytic import REACH
from graphkin.synthesis.four import _cplx, burmester_construction, letters, sample_t
from graphkin.synthesis.postures import DIAGRAM, Postures, add_poles

__all__ = ["BurmesterPoint", "five_construction", "burmester_points"]


@dataclass(frozen=True)
class BurmesterPoint:
    """A Burmester point: a center point and its circle point (posture 1), complex."""

    center: complex
    circle: complex


def five_construction(post: Postures) -> Construction:
    """The four-posture construction of postures 1-4 with the fifth position of each circle point.

    Adds P15 and, for both branches, ``E5``/``F5``: the circle point turned
    θ15 about P15 (mirrored in P15E_C and then in the line through P15 turned
    φ15 from it).
    """
    four_post = Postures(post.points[:4], post.angles[:4], post.names, post.second,
                         post.source, post.key, post.tol, post.second_given)
    cx = burmester_construction(four_post)
    cx.title = "Burmester points (five postures)"
    # posture 5 and its pole with posture 1
    d, e = post.names
    cx.add("point", (), (f"{d}5",), xy=tuple(map(float, post.points[4])), role=Role.GIVEN,
           diagram=DIAGRAM, note=f"{d}5: the body's point {d} in posture 5 (given).")
    cx.add("scalar", (), ("θ5",), value=float(post.angles[4]), role=Role.GIVEN,
           diagram=DIAGRAM, note="θ5: the body's angle in posture 5 (given).")
    cx.add("rigid", (f"{d}5", "θ5"), (f"{e}5",), local_p=(0.0, 0.0),
           local_q=tuple(post.second), role=Role.GIVEN, diagram=DIAGRAM,
           note=f"{e}5: the body's point {e} in posture 5.")
    labels = [(f"{d}{k}", f"{e}{k}", f"θ{k}") for k in range(1, 6)]
    add_poles(cx, post, labels, [(1, 5)])
    phi = math.remainder(float(post.angles[4] - post.angles[0]), math.tau) / 2
    for name in letters(post):
        center = f"{name}_C"
        ang = f"∠P15{center}"
        cx.add("angle_along", ("P15", center), (ang,), local_angle=0.0, sign=1.0,
               diagram=DIAGRAM, note=f"the direction of P15{center}.")
        cx.add("line_at_angle", ("P15", ang), (f"m_{name}15",), diagram=DIAGRAM,
               note=f"the line P15{center}.")
        cx.add("line_at_angle", ("P15", ang), (f"n_{name}15",), offset=phi, diagram=DIAGRAM,
               note=f"the line through P15 turned φ15 = {math.degrees(phi):.6g}° from it.")
        cx.add("reflect", (f"{name}1", f"m_{name}15"), (f"{name}'",), diagram=DIAGRAM,
               note=f"{name}1 mirrored in P15{center}.")
        cx.add("reflect", (f"{name}'", f"n_{name}15"), (f"{name}5",), role=Role.RESULT,
               diagram=DIAGRAM, note=f"{name}5: {name}1 turned θ15 about P15 (two mirrors).")
    return cx


def _defect(ev: dict[str, np.ndarray] | object, branch: str, center: str,
            scale: float) -> np.ndarray:
    m = _cplx(ev[center])  # type: ignore[index]
    a1 = _cplx(ev[f"{branch}1"])  # type: ignore[index]
    a5 = _cplx(ev[f"{branch}5"])  # type: ignore[index]
    return (np.abs(a5 - m) ** 2 - np.abs(a1 - m) ** 2) / scale ** 2


def _bisect(cx: Construction, branch: str, lo: np.ndarray, hi: np.ndarray,
            scale: float) -> np.ndarray:
    """Close the brackets [lo, hi] of t (either order) on one branch; the t's found.

    Regula falsi with the Illinois rule (a bisection where the secant leaves the
    bracket or meets a missing value): each step one evaluation of the
    construction on every bracket at once.
    """
    center = f"{branch}_C"

    def g(t: np.ndarray) -> np.ndarray:
        return np.atleast_1d(_defect(cx.evaluate({"t": t}, strict=False), branch, center,
                                     scale))

    lo, hi = np.atleast_1d(lo).astype(float), np.atleast_1d(hi).astype(float)
    glo, ghi = g(lo), g(hi)
    # a defect that grows a thousandfold past both ends is a jump through infinity (A1 at
    # infinity), not a root: such a bracket is given up (the caller's check refuses it)
    wild = 1e3 * np.maximum(np.abs(glo), np.abs(ghi))
    pole = np.zeros(lo.shape, bool)
    side = np.zeros(lo.shape)
    for _ in range(48):
        with np.errstate(invalid="ignore", divide="ignore"):
            new = hi - ghi * (hi - lo) / (ghi - glo)
        inside = np.isfinite(new) & ((new - lo) * (new - hi) < 0)
        new = np.where(inside, new, 0.5 * (lo + hi))
        gn = g(new)
        stay = np.sign(gn) == np.sign(glo)
        # the Illinois rule: the end kept twice running has its value halved
        ghi = np.where(stay, np.where(side > 0, 0.5 * ghi, ghi), gn)
        glo = np.where(stay, gn, np.where(side < 0, 0.5 * glo, glo))
        lo = np.where(stay, new, lo)
        hi = np.where(stay, hi, new)
        side = np.where(stay, 1.0, -1.0)
        done = np.abs(hi - lo) <= 1e-15 * (1.0 + np.abs(lo))
        # a defect of round-off size (the defect is relative to the figure's size squared)
        # is a root: the secant steps below it only shuffle the last digits of t
        pole |= ~(np.abs(gn) <= wild)
        if np.all(done | pole | (np.abs(gn) <= 1e-15)):
            break
    return np.where(np.abs(glo) < np.abs(ghi), lo, hi)


def _junctions(cx: Construction, t: np.ndarray, exists: np.ndarray) -> tuple[np.ndarray, ...]:
    """Where the two circles stop meeting: the last t on each side, and t at the tangency.

    The two branches of center points join there (the circles touch), so a root of
    the defect may lie on the loop through the junction.
    """
    k_end = np.nonzero(exists[:-1] & ~exists[1:])[0]
    k_start = np.nonzero(~exists[:-1] & exists[1:])[0]
    inner = np.concatenate([t[k_end], t[k_start + 1]])
    outer = np.concatenate([t[k_end + 1], t[k_start]])
    first = inner.copy()
    if inner.size == 0:
        return first, inner
    step = next(s for s in cx if s.op == "intersect_circles")
    head = cx.upto(step.index)   # the steps up to the first center point only
    for _ in range(52):
        mid = 0.5 * (inner + outer)
        fin = np.isfinite(_cplx(head.evaluate({"t": mid}, strict=False)[step.outputs[0]]))
        inner = np.where(fin, mid, inner)
        outer = np.where(fin, outer, mid)
    return first, inner


def burmester_points(post: Postures, count: int = 4001,
                     cx: Construction | None = None) -> tuple[list[BurmesterPoint], Construction]:
    """The real Burmester points of five postures, by construction.

    The defect (A5's distance from the center point minus A1's) changes sign
    along a branch of the 1234 curve, or between the two branches where they
    join (the two circles touch): each change is bracketed and halved.

    Returns the points and the construction.
    """
    cx = cx if cx is not None else five_construction(post)
    scale = post.scale
    middle = complex(*np.mean(post.points, axis=0))
    t = sample_t(count)
    ev = cx.evaluate({"t": t}, strict=False)
    names = letters(post)
    g = {b: _defect(ev, b, f"{b}_C", scale) for b in names}
    brackets: dict[str, list[tuple[float, float]]] = {b: [] for b in names}
    for b in names:
        ok = np.isfinite(g[b][:-1]) & np.isfinite(g[b][1:])
        for k in np.nonzero(ok & (np.sign(g[b][:-1]) * np.sign(g[b][1:]) <= 0))[0]:
            brackets[b].append((float(t[k]), float(t[k + 1])))
    first, touch = _junctions(cx, t, np.isfinite(_cplx(ev[f"{names[0]}_C"])))
    if first.size:
        ev_first = cx.evaluate({"t": first}, strict=False)
        ev_touch = cx.evaluate({"t": touch}, strict=False)
        for b in names:
            g0 = _defect(ev_first, b, f"{b}_C", scale)
            g1 = _defect(ev_touch, b, f"{b}_C", scale)
            for k in np.nonzero(np.sign(g0) * np.sign(g1) < 0)[0]:
                brackets[b].append((float(first[k]), float(touch[k])))
    found: list[BurmesterPoint] = []
    for branch in names:
        if not brackets[branch]:
            continue
        lo, hi = (np.array(v) for v in zip(*brackets[branch]))
        ev2 = cx.evaluate({"t": _bisect(cx, branch, lo, hi, scale)}, strict=False)
        m = np.atleast_1d(_cplx(ev2[f"{branch}_C"]))
        a1 = np.atleast_1d(_cplx(ev2[f"{branch}1"]))
        a5 = np.atleast_1d(_cplx(ev2[f"{branch}5"]))
        miss = np.abs(np.abs(a5 - m) - np.abs(a1 - m)) / scale
        for mi, ai, gap in zip(m, a1, miss):
            # a true root, not a jump of the defect through infinity (A1 at infinity)
            if np.isfinite(gap) and gap <= 1e-7 and abs(ai - mi) <= 1e6 * scale \
                    and abs(mi - middle) <= REACH * scale:
                if all(abs(mi - f.center) > 1e-7 * scale for f in found):
                    found.append(BurmesterPoint(complex(mi), complex(ai)))
    return found, cx
