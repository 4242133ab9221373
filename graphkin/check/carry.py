"""Follow-through from the student's own images: the polygon constructed right from them.

A student who draws one image point wrong (b at a mistaken place: a wrong
length, an image flipped over, a slip) and then constructs every later image
right *from the b on the paper* makes one mistake, not several.  The
whole-solution variants of :class:`graphkin.check.diagnose.Diagnoser` cover
the usual mistakes carried through; this module covers any mistake carried
through: the velocity (or acceleration) construction is replayed step by step
with each image the student drew put in place of the construction's own, so
every later image comes out where the student's correct construction from
those images puts it (Sec. 3.4: "the line to image point P from image point
Q"; Sec. 4.3 for the acceleration polygon, its normal components from the
exact velocities).

:class:`Carry` does the replay; :func:`own_follow_through` marks the answers
that it explains ``follows`` (after the usual-mistake follow-through of
:func:`graphkin.check.report.follow_through`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon, each image
point constructed from earlier ones), Sec. 4.3 (the acceleration polygon).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from graphkin.check.answers import CheckTolerance, Given
from graphkin.check.compare import compare
from graphkin.check.diagnose import Mistake
from graphkin.check.exact import Evaluator, Exact
from graphkin.errors import GraphkinError
from graphkin.geometry import ops as g

__all__ = ["Carry", "carry_for", "own_follow_through"]


class Carry:
    """The polygon of one solved mechanism, replayed from the images a student drew.

    Parameters
    ----------
    sol : Solution
        Solved by the constructions (``sol.method == "construction"``); for
        any other solution nothing is carried (:attr:`order` is empty).

    Examples
    --------
    Example 3.1's four-bar with b drawn 10 % long: c, e and f move with it.

    >>> import graphkin
    >>> sol = graphkin.examples.fourbar().solve()
    >>> carry = Carry(sol)
    >>> carry.order("velocity")
    ['B', 'C', 'E', 'F']
    >>> moved = carry.images("velocity", {"B": 1.1 * sol.velocity("B")})
    >>> bool(np.allclose(moved["B"], 1.1 * sol.velocity("B")))
    True
    >>> bool(np.allclose(moved["C"], sol.velocity("C")))
    False
    """

    def __init__(self, sol: Any) -> None:
        self.sol = sol
        self._built: tuple[Any, ...] | None = None
        self._ok = sol.method == "construction" and sol.has_rates

    def _build(self) -> tuple[Any, ...]:
        if self._built is None:
            from graphkin.kinematics.polygons import build_polygons
            from graphkin.kinematics.posture import build_posture
            from graphkin.kinematics.solve import rate_inputs

            mech = self.sol.mechanism
            pc = build_posture(mech, None, dict(self.sol.branches))
            pol = build_polygons(mech, pc)
            vin, ain = rate_inputs(mech, pol, pc, pc.values)
            vel = pol.velocity.evaluate(vin, values=dict(pc.values)).values
            self._built = (pc, pol, vin, ain, vel)
        return self._built

    def _parts(self, diagram: str) -> tuple[Any, dict[str, str], dict[str, Any], dict[str, Any]]:
        pc, pol, vin, ain, vel = self._build()
        if diagram == "velocity":
            return pol.velocity, dict(pol.velocity_images), vin, dict(pc.values)
        return pol.acceleration, dict(pol.acceleration_images), ain, dict(vel)

    def order(self, diagram: str) -> list[str]:
        """The image points (not at the pole) in the order the construction draws them."""
        if not self._ok:
            return []
        try:
            cx, images, _, _ = self._parts(diagram)
        except (GraphkinError, KeyError, ValueError):
            return []
        pole = "o_v" if diagram == "velocity" else "o_a"
        mech = self.sol.mechanism
        at: dict[str, int] = {}
        for name, lab in images.items():
            if lab == pole or name in mech.helper_points or name not in mech.point_names:
                continue
            try:
                at[name] = cx.step_of(lab).index
            except KeyError:
                continue
        return sorted(at, key=lambda n: (at[n], mech.point_names.index(n)))

    def depends(self, diagram: str, name: str, on: str) -> bool:
        """Whether the construction of image ``name`` reads image ``on`` (directly or not)."""
        cx, images, _, _ = self._parts(diagram)
        target = images.get(on)
        todo = [images[name]]
        seen: set[str] = set()
        while todo:
            lab = todo.pop()
            if lab in seen:
                continue
            seen.add(lab)
            try:
                step = cx.step_of(lab)
            except KeyError:
                continue
            if target in step.inputs:
                return True
            todo += list(step.inputs)
        return False

    def images(self, diagram: str, drawn: Mapping[str, np.ndarray]) -> dict[str, np.ndarray]:
        """Every image point (a vector from the pole) with ``drawn`` put in the construction.

        Parameters
        ----------
        diagram : {"velocity", "acceleration"}
        drawn : mapping
            Point name -> the image the student drew, a vector from the pole
            in the mechanism's units (as :meth:`Solution.velocity` gives).

        Returns
        -------
        dict
            Point name -> its image when every later step is done right from
            ``drawn`` (an image the construction cannot reach from them, such
            as two parallel lines that would meet, is left out).
        """
        order = self.order(diagram)
        if not order:
            return {}
        cx, labels, given, env = self._parts(diagram)
        pole_label = "o_v" if diagram == "velocity" else "o_a"
        put = sorted(((cx.step_of(labels[n]).index, labels[n], np.asarray(v, dtype=float))
                      for n, v in drawn.items() if n in order), key=lambda t: t[0])
        start = 0
        try:
            for idx, lab, v in put:
                if idx >= start:
                    env = cx.upto(idx).evaluate(given, values=env, start=start).values
                pole = g.xy(np.asarray(env[pole_label], dtype=float))
                env[lab] = np.array([pole[0] + v[0], pole[1] + v[1], 1.0])
                start = max(start, idx + 1)
            env = cx.evaluate(given, values=env, start=start).values
        except (GraphkinError, KeyError, ValueError, ArithmeticError):
            return {}
        pole = g.xy(np.asarray(env[pole_label], dtype=float))
        out: dict[str, np.ndarray] = {}
        for n in order:
            xy = g.xy(np.asarray(env[labels[n]], dtype=float)) - pole
            if np.all(np.isfinite(xy)):
                out[n] = np.asarray(xy, dtype=float)
        return out


def carry_for(diag: Any) -> Carry:
    """The :class:`Carry` of a diagnoser's solution (made once, kept on it)."""
    carry = getattr(diag, "_carry", None)
    if carry is None or carry.sol is not diag.sol:
        carry = Carry(diag.sol)
        diag._carry = carry
    return carry


def own_follow_through(rows: list[Any], given: Sequence[Given], diag: Any,
                       tol: CheckTolerance, diagram: str,
                       sheet: Sequence[float | None]) -> None:
    """Mark image points that are wrong only because they were drawn from wrong ones.

    In the order of the construction, each image point still ``WRONG``
    (not explained by a usual mistake carried through) is compared with
    where the construction puts it when done right from every image the
    student drew before it (:meth:`Carry.images`).  When it lies there
    within tolerance it is marked ``follows``, from the first wrong image
    it is constructed from; otherwise it stays wrong and is carried on
    itself.  An image that others already follow (the first of a usual
    mistake carried through) stays the root of its own.

    Parameters
    ----------
    rows, given : list
        The rows of a drawn polygon and the vectors read (same order);
        changed in place.
    diag : Diagnoser
    tol : CheckTolerance
    diagram : {"velocity", "acceleration"}
    sheet : sequence
        Each row's drawing allowance (:func:`graphkin.check.report.sheet_allowance`).
    """
    from graphkin.check.report import FOLLOWS, OK, WRONG

    letter = "V" if diagram == "velocity" else "A"
    if not any(r.verdict == WRONG for r in rows):
        return
    carry = carry_for(diag)
    order = carry.order(diagram)
    if not order:
        return
    index: dict[str, int] = {}
    for i, gv in enumerate(given):
        k = gv.key
        if k.kind == letter and len(k.args) == 1 and k.link is None and k.args[0] in order \
                and gv.vector is not None:
            index[k.args[0]] = i
    drawn: dict[str, np.ndarray] = {}
    wrong: list[str] = []
    ev: Evaluator = diag.ev
    floor = ev.floor(diagram)
    for name in order:
        if name not in index:
            continue
        i = index[name]
        row = rows[i]
        vec = np.asarray(given[i].vector, dtype=float)
        if row.verdict == WRONG and wrong and not any(r.follows == row.key for r in rows):
            roots = [w for w in wrong if carry.depends(diagram, name, w)]
            there = carry.images(diagram, drawn).get(name) if roots else None
            if there is not None:
                try:
                    c = compare(given[i], Exact(None, there), tol, floor=floor, sheet=sheet[i])
                except (AssertionError, TypeError, ValueError):
                    c = None
                if c is not None and c.ok:
                    first = rows[index[roots[0]]]
                    row.verdict = FOLLOWS
                    row.follows = first.follows if first.verdict == FOLLOWS else first.key
                    row.mistake = Mistake(
                        "carried", f"{name.lower()} constructed right from the wrong "
                                   f"image{'s' if len(roots) > 1 else ''} "
                                   f"{', '.join(r.lower() for r in roots)} as drawn", "carried")
        if row.verdict in (WRONG, FOLLOWS):
            wrong.append(name)
        if row.verdict != OK:
            drawn[name] = vec
