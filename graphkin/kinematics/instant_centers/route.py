"""A Kennedy route for every posture: each center on the best of all its lines, chosen per posture.

:func:`~graphkin.kinematics.instant_centers.instant_centers` finds the centers
of *one* posture: at each center it takes the two lines of centers that meet
best *there* (Secs. 3.13-3.15).  A page that re-solves the posture on every
pointer move needs a route that holds at every posture: two lines that meet
well at the file's posture can be parallel, or one of their centers at
infinity, at another (a cam's follower, a dragged crank).

The route here fixes only the order in which the centers are found: the
search's own order at the given posture wherever two known lines reach the
next center (the search passes over lines that coincide there), else the
first pair, in the order I12, I13, ..., that two known lines reach.  Each
center is then given *every* line of centers that reaches it at that point
of the order (each triangle whose two other centers are known, and the common
normals of a direct contact).  Each center is then one step ``kennedy_center``
(:mod:`graphkin.construction.ops.kennedy`) that meets the best-conditioned
pair of those lines at whatever posture it is evaluated on, by the search's
own measure.  A center no two lines reach (two inputs, Sec. 5.4) is taken
from the velocities as the search takes it (``homogeneous_point``, which the
live page redoes from its velocity polygon).

Where both links of a pair slide on a third (two centers of a triangle at
infinity by inspection, Fig. 3.27) the center is the point at infinity of the
best of its other lines.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 3.12-3.15 (primary centers, the
Aronhold-Kennedy theorem, the Kennedy circle), Sec. 5.4 (centers that depend
on the input speeds).
"""

from __future__ import annotations

from dataclasses import dataclass
from itertools import combinations
from typing import Any

from graphkin.construction import Construction, Role
from graphkin.construction.ops import kennedy  # noqa: F401  (registers kennedy_center)
from graphkin.kinematics.instant_centers.centers import How, InstantCenters
from graphkin.kinematics.instant_centers.kennedy import _MOST_LINES, _Kennedy
from graphkin.kinematics.instant_centers.labels import center_label, pair_key
from graphkin.kinematics.solution import Solution
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["Route", "every_posture_route"]

Pair = tuple[str, str]


@dataclass(frozen=True)
class Route:
    """The centers' construction for every posture, and what the page draws of it.

    Attributes
    ----------
    construction : Construction
        The primary centers and common normals (as the search records them),
        then one ``kennedy_center`` (or ``homogeneous_point``) step per center.
    centers : list of str
        The centers in the order they are found.
    lines : dict
        Center -> the points on each of its candidate lines, in the order of
        the step's ``lines`` (the two centers of a triangle, or the point a
        common normal passes through).
    pairs : dict
        Center -> the step's candidate pairs of lines (indices into ``lines``).
    """

    construction: Construction
    centers: list[str]
    lines: dict[str, list[list[str]]]
    pairs: dict[str, list[list[int]]]


def every_posture_route(sol: Solution, ic: InstantCenters, *,
                        tol: Tolerance | None = None) -> Route:
    """The Kennedy route of ``sol``'s mechanism that chooses its lines at each posture.

    Parameters
    ----------
    sol : Solution
        One posture (its primary centers are recorded as the search records them).
    ic : InstantCenters
        The search's centers at that posture: a center it found from the
        velocities is found so here too, when no two lines reach it.
    tol : Tolerance, optional

    Returns
    -------
    Route
    """
    k = _Kennedy(sol, tol or DEFAULT_TOL, ())
    k.primary()
    cx = Construction(title=k.cx.title)
    for st in k.cx.steps:
        cx.add(st.op, st.inputs, st.outputs, role=st.role, note=st.note, diagram="centers",
               **st.params)
    # centers at infinity whatever the posture: a slider's, and those found so below
    ideal = {c.label for c in k.centers.values()
             if any(s.op == "ideal_point" and s.outputs == (c.label,) for s in k.cx.steps)}
    known: set[Pair] = set(k.centers)
    order = [c.label for c in k.centers.values()]
    pairs = [pair_key(a, b) for a, b in combinations(k.links, 2)]
    lines: dict[str, list[list[str]]] = {}
    chosen: dict[str, list[list[int]]] = {}
    steps = {s.outputs[0]: s for s in cx.steps if s.outputs}

    def points_on(line: str) -> list[str]:
        st = steps[line]
        return [i for i in st.inputs if steps[i].kind == "point"]

    # the search's own order at that posture where the lines allow it (it passed over lines
    # that coincide there), the centers it found from the velocities found so too
    rank = {c.pair: n for n, c in enumerate(ic.centers.values())}
    by_vel = {c.pair: c for c in ic.centers.values() if c.how is How.VELOCITIES}
    while True:
        ready: list[tuple[int, int, Pair, list[tuple[str, ...]], bool]] = []
        for n, pair in enumerate(p for p in pairs if p not in known):
            if pair in by_vel:
                ready.append((rank[pair], n, pair, [], False))
                continue
            cands, at_infinity = _candidates(k, pair, known, ideal, order)
            if len(cands) >= 2 or (at_infinity and cands):
                ready.append((rank.get(pair, len(pairs)), n, pair, cands, at_infinity))
        if not ready:
            break
        _, _, pair, cands, at_infinity = min(ready, key=lambda r: r[:2])
        if pair in by_vel:
            lab = by_vel[pair].label
            st = next(s for s in ic.construction.steps if s.outputs == (lab,))
            cx.add(st.op, st.inputs, st.outputs, role=st.role, note=st.note, diagram="centers",
                   **st.params)
        else:
            _add(cx, pair, cands, at_infinity, float(k.mech.scale), lines, chosen, points_on)
            if at_infinity:
                ideal.add(center_label(*pair))
        known.add(pair)
        order.append(center_label(*pair))
    return Route(cx, order, lines, chosen)


def _candidates(k: _Kennedy, pair: Pair, known: set[Pair], ideal: set[str],
                order: list[str]) -> tuple[list[tuple[str, ...]], bool]:
    """The lines of centers that reach ``pair``'s center, and whether it is at infinity.

    The common normals of a direct contact (a line each), then each triangle's line
    through its two known centers (the two, in the order found); a triangle whose
    two centers are both at infinity by inspection puts the center at infinity.
    """
    i, j = pair
    cands: list[tuple[str, ...]] = [(n,) for n, _ in k.normals.get(pair, [])]
    at_infinity = False
    for m in k.links:
        if m in pair or pair_key(i, m) not in known or pair_key(j, m) not in known:
            continue
        la, lb = (center_label(*pair_key(x, m)) for x in (i, j))
        if la in ideal and lb in ideal:
            at_infinity = True      # i and j both slide on m: Iij is at infinity
            continue
        cands.append(tuple(sorted((la, lb), key=order.index)))
    return cands[:_MOST_LINES], at_infinity


def _add(cx: Construction, pair: Pair, cands: list[tuple[str, ...]], at_infinity: bool,
         scale: float, lines: dict[str, list[list[str]]], chosen: dict[str, list[list[int]]],
         points_on: Any) -> None:
    """One ``kennedy_center`` step: ``Iij`` on the best pair of ``cands`` at each posture."""
    lab = center_label(*pair)
    ins: list[str] = []
    specs = []
    for c in cands:
        for x in c:
            if x not in ins:
                ins.append(x)
        specs.append(tuple(ins.index(x) for x in c))
    npairs = [[a] for a in range(len(cands))] if at_infinity else \
        [list(p) for p in combinations(range(len(cands)), 2)]
    lines[lab] = [list(c) if len(c) == 2 else points_on(c[0]) for c in cands]
    chosen[lab] = npairs
    names = [" and ".join(c) if len(c) == 2 else c[0] for c in cands]
    if at_infinity:
        note = (f"{lab} is at infinity: links {pair[0]} and {pair[1]} both slide on a third "
                "(Fig. 3.27); its direction is that of the best of its lines of centers "
                f"({'; '.join(names)})")
    else:
        note = (f"{lab} is where two of its lines of centers meet (Kennedy): the pair that "
                f"meets best at this posture, of the lines through {'; '.join(names)}")
    cx.add("kennedy_center", tuple(ins), (lab, f"{lab}|a", f"{lab}|b", f"{lab}|k"),
           role=Role.RESULT, note=note + ".", diagram="centers",
           lines=tuple(specs), pairs=tuple(tuple(p) for p in npairs), scale=scale)
