"""Static and dynamic force analysis by the graphic method (Ch. 11-12), as named steps.

The construction works the way the book does, and records every act as a
:class:`~graphkin.construction.Step` of diagram ``"forces"``:

1. The applied forces of each link: loads P (Sec. 11.4), couples, d'Alembert
   inertia forces ``-m A_G`` offset by ``h`` (Eq. 12.18) and weights.
2. One analysis per loaded link (superposition, Sec. 12.5, Ex 12.5): with the
   other links unloaded, look for

   * two-force members (Sec. 11.6): an unloaded link with two joints; its
     forces act along the line its two joints define (the pins' line; a pin
     and a slider's normal; ...), and where two such lines cross at one joint
     its force is zero;
   * three-force members (Sec. 11.7, Fig. 11.5e): the known resultant R of the
     link's known forces (its loads combined first, Sec. 11.8), one force on a
     known line and one through a pin: the concurrency point X of R and the
     known line fixes the third line, the force polygon (Fig. 11.5f) closes;
   * a slider's normal force of known direction but unknown place (Ex 11.2);
   * the drive link last: the frame's force balances ΣF and the drive's
     torque T_12 balances ΣM about the pivot (Ex 11.1 step 7), or the input
     force along a slider's line (Ex 12.3);

   solving link by link in the order the search finds.
3. The vector sums of the partial analyses: every joint force and the drive's
   torque.

When no such order exists (a link with four unknowns and no neighbour to
help), :class:`NotDecomposable` is raised and the caller falls back to the
analytic matrix method (:mod:`graphkin.forces.analytic`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 11.5-11.8, 12.4-12.5, Figs. 11.5,
11.8, 12.8; Examples 11.1, 11.2, 12.3, 12.5.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

import graphkin.forces.ops  # noqa: F401  (registers the force operations)
from graphkin.construction import Construction
from graphkin.construction.ops import OPS
from graphkin.construction.step import Mark, Role, Term, VectorEquation, fresh_label
from graphkin.errors import ConstructionError, GraphkinError
from graphkin.forces.joints import PIN, SLIDE, SLOT, Geometry, Joint
from graphkin.forces.ops import line_of, moment_about
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["NotDecomposable", "Partial", "build_forces", "applied_labels"]

_ZERO = "0"
_PRIMES = ["′", "″", "‴"]


class NotDecomposable(GraphkinError, ValueError):
    """No link-by-link graphic order solves this mechanism's forces."""


@dataclass
class Partial:
    """One analysis of the superposition (Sec. 12.5): the loads of one link alone.

    Attributes
    ----------
    link : str
        The loaded link.
    suffix : str
        The book's prime: ``′`` for the first partial, ``″`` for the second ("" alone).
    forces : dict
        Joint key -> label of its force F_lo,hi in this analysis.
    drives : dict
        Drive link -> label of its torque (or input force) in this analysis.
    order : list of str
        What was found, link by link, in order (``"link 3: two-force member"``).
    """

    link: str
    suffix: str
    forces: dict[str, str] = field(default_factory=dict)
    drives: dict[str, str] = field(default_factory=dict)
    order: list[str] = field(default_factory=list)


@dataclass
class BuiltForces:
    """What :func:`build_forces` makes: the construction, its values and the labels."""

    construction: Construction
    values: dict[str, np.ndarray]
    partials: list[Partial]
    forces: dict[str, str]
    drives: dict[str, str]
    drive_forces: dict[str, str]
    applied: dict[str, list[str]]


def _prime(k: int, n: int) -> str:
    if n <= 1:
        return ""
    return _PRIMES[k] if k < len(_PRIMES) else f"⁽{k + 1}⁾"


def applied_labels(mech: Any, dynamic: bool) -> dict[str, list[tuple[str, str, Any]]]:
    """Per link, the applied forces as (label, kind, source) in the book's names.

    ``P_4`` for a load on link 4 (``P_4a``, ``P_4b`` for several), ``M_3`` for a
    couple, ``-m3A_G3`` for an inertia force, ``W_3`` for a weight.
    """
    out: dict[str, list[tuple[str, str, Any]]] = {}
    per: dict[str, list[Any]] = {}
    for ld in mech.loads:
        per.setdefault(ld.link, []).append(ld)
    for lid, lds in per.items():
        forces = [ld for ld in lds if ld.force is not None]
        couples = [ld for ld in lds if ld.force is None]
        for k, ld in enumerate(forces):
            tag = "" if len(forces) == 1 else "abcdefghijklmnopqrstuvwxyz"[k % 26]
            out.setdefault(lid, []).append((f"P_{lid}{tag}", "load", ld))
        for k, ld in enumerate(couples):
            tag = "" if len(couples) == 1 else "abcdefghijklmnopqrstuvwxyz"[k % 26]
            out.setdefault(lid, []).append((f"M_{lid}{tag}", "couple", ld))
    for lid, inr in mech.inertia.items():
        if dynamic:
            out.setdefault(lid, []).append((f"-m{lid}A_{inr.center}", "inertia", inr))
        if mech.gravity is not None:
            out.setdefault(lid, []).append((f"W_{lid}", "weight", inr))
    return out


class _Builder:
    def __init__(self, sol: Solution, joints: list[Joint], geo: Geometry,
                 tol: Tolerance) -> None:
        self.sol = sol
        self.mech = sol.mechanism
        self.joints = joints
        self.geo = geo
        self.tol = tol
        self.cx = Construction(title=f"Force analysis: {self.mech.title or self.mech.source}")
        self.env: dict[str, np.ndarray] = {}
        self.scale = self.mech.scale

    # ---- recording -------------------------------------------------------
    def given(self, label: str, value: Any) -> str:
        self.env[label] = np.asarray(value, dtype=float)
        return label

    def emit(self, op: str, inputs: tuple[str, ...], outputs: tuple[str, ...], note: str,
             role: Role = Role.AUXILIARY, equation: VectorEquation | None = None,
             **params: Any) -> None:
        step = self.cx.add(op, inputs, outputs, role=role, note=note, diagram="forces",
                           equation=equation, **params)
        args = [self.env[i] for i in inputs]
        with np.errstate(invalid="ignore", divide="ignore"):
            outs = OPS[op](*args, tol=self.tol, **params)
        for name, val in zip(outputs, outs):
            v = np.asarray(val, dtype=float)
            if not np.all(np.isfinite(v)):
                raise ConstructionError(
                    f"{note}: this has no finite answer, so equilibrium cannot be held at "
                    "this posture", step=step.label)
            self.env[name] = v

    def fresh(self, label: str) -> str:
        return fresh_label(label, self.env)

    # ---- geometry tests (generic decisions, made once) --------------------
    def on_line(self, point: str, line: str) -> bool:
        ln = self.env[line]
        p = self.env[point]
        return bool(abs(ln[0] * p[0] + ln[1] * p[1] + ln[2] * p[2])
                    <= self.tol.length(self.scale))

    def parallel(self, d1: np.ndarray, d2: np.ndarray) -> bool:
        c = abs(float(d1[0] * d2[1] - d1[1] * d2[0]))
        return c <= math.sin(self.tol.angle)

    def same_line(self, l1: str, l2: str) -> bool:
        a, b = self.env[l1], self.env[l2]
        return self.parallel(a[:2], b[:2]) and abs(abs(float(a[2])) - abs(float(b[2]))) \
            <= self.tol.length(self.scale) and bool(np.dot(a[:2], b[:2]) * a[2] * b[2] >= 0
                                                   or abs(float(a[2])) <= self.tol.length(
                                                       self.scale))

    # ---- the analysis -----------------------------------------------------
    def build(self, dynamic: bool) -> BuiltForces:
        mech, sol = self.mech, self.sol
        for name, xy in self.geo.points.items():
            self.given(name, [xy[0], xy[1], 1.0])
        for key, n in self.geo.normal.items():
            self.given(f"n_{key}", n)
        for key, u in self.geo.along.items():
            self.given(f"u_{key}", u)
        applied = applied_labels(mech, dynamic)
        comps: dict[str, list[str]] = {}
        for lid, items in applied.items():
            for label, kind, src in items:
                if kind == "load":
                    fx, fy = src.force
                    self.emit("force_load", (src.point,), (label,),
                              f"the applied force {label} on link {lid} through {src.point}",
                              role=Role.GIVEN, force=(fx, fy))
                elif kind == "couple":
                    self.emit("force_couple", (), (label,),
                              f"the applied couple {label} on link {lid}", role=Role.GIVEN,
                              torque=src.torque)
                elif kind == "inertia":
                    g = src.center
                    self.given(f"A_{g}", np.asarray(sol.acceleration(g, lid), dtype=float))
                    self.given(f"α{lid}", np.asarray(sol.alpha(lid), dtype=float))
                    self.emit("force_inertia", (g, f"A_{g}", f"α{lid}"), (label,),
                              f"the inertia force -m{lid}A_{g} of link {lid}, offset from {g} "
                              f"by h{lid} = I_G{lid}α{lid}/(m{lid}A_{g}) so that its moment "
                              f"about {g} is -I_G{lid}α{lid} (Eq. 12.18)", role=Role.GIVEN,
                              mass=src.mass, moment=src.moment)
                else:
                    assert mech.gravity is not None
                    self.emit("force_weight", (src.center,), (label,),
                              f"the weight {label} of link {lid} through {src.center}",
                              role=Role.GIVEN, mass=src.mass, gravity=tuple(mech.gravity))
                comps.setdefault(lid, []).append(label)
        # the slots' lines of action: through the pin, normal to the slot
        self.slot_lines: dict[str, str] = {}
        for j in self.joints:
            if j.kind == SLOT:
                lab = f"l_{j.key}"
                why = (f"the gear teeth at the pitch point {j.point}: their force acts along "
                       "the pressure line (Sec. 11.11, Fig. 11.14)"
                       if j.source is not None and j.source.key.startswith("rolling") else
                       f"the pin {j.point} in the slot: its force acts through {j.point} "
                       "normal to the slot")
                self.emit("force_line", (j.point, f"n_{j.key}"), (lab,), why)
                self.slot_lines[j.key] = lab
        loaded = [lid for lid in mech.moving if comps.get(lid)]
        partials = []
        for k, lid in enumerate(loaded):
            p = Partial(lid, _prime(k, len(loaded)))
            self.partial(p, comps[lid])
            partials.append(p)
        forces, drives, drive_forces = self.superpose(partials)
        return BuiltForces(self.cx, self.env, partials, forces, drives, drive_forces,
                           {lid: list(v) for lid, v in comps.items()})

    def partial(self, p: Partial, comps: list[str]) -> None:
        """One loaded link alone: find every joint force link by link."""
        lines: dict[str, tuple[str, str] | None] = {}
        for j in self.joints:
            lines[j.key] = (self.slot_lines[j.key], "slot") if j.kind == SLOT else None
        pending = {d.link: d for d in self.mech.drives}
        known, drives = self.analyse(p, p.suffix, {p.link: comps}, set(), lines, pending, 0)
        for j in self.joints:
            lab = known[j.key]
            if lab == _ZERO:
                lab = j.label(j.hi, p.suffix)
                self.emit("force_zero", (), (lab,), f"{lab} = 0 in this analysis")
            p.forces[j.key] = lab
        p.drives.update(drives)

    def analyse(self, p: Partial, sfx: str, loads_by_link: dict[str, list[str]],
                done: set[str], lines: dict[str, tuple[str, str] | None],
                pending: dict[str, Any], depth: int) -> tuple[dict[str, str], dict[str, str]]:
        """Find the joint forces not in ``done`` under the given loads, link by link.

        When no link can be solved alone but several links carry known forces,
        the rest is solved once per such link and the results added
        (superposition again, Sec. 12.5).  Returns joint key -> label of F_lo,hi
        (or ``"0"``) and drive link -> label of its torque or force.
        """
        mech = self.mech
        known: dict[str, str] = {}
        drives_out: dict[str, str] = {}
        lines = dict(lines)
        pending = dict(pending)
        at_link = {lid: [j for j in self.joints if lid in (j.lo, j.hi) and j.key not in done]
                   for lid in mech.moving}
        todo = [j for j in self.joints if j.key not in done]

        def kind_of(j: Joint) -> str:
            return "line" if lines[j.key] is not None else j.kind

        def set_known(j: Joint, on: str, label: str) -> None:
            """Record the force found on link ``on``; keep the canonical F_lo,hi."""
            canon = j.label(j.hi, sfx)
            if on != j.hi and label != _ZERO:
                self.emit("force_reverse", (label,), (canon,),
                          f"action and reaction: {canon} = -{label}")
            known[j.key] = _ZERO if label == _ZERO else canon

        def on_label(j: Joint, on: str) -> str:
            canon = known[j.key]
            if on == j.hi or canon == _ZERO:
                return canon
            lab = j.label(on, sfx)
            if lab not in self.env:
                self.emit("force_reverse", (canon,), (lab,),
                          f"action and reaction: {lab} = -{canon}")
            return lab

        def resultant(lid: str, items: list[str]) -> str:
            if len(items) == 1:
                return items[0]
            lab = self.fresh(f"R_{lid}{sfx}")
            self.emit("force_resultant", tuple(items), (lab,),
                      f"combine the known forces on link {lid} into their resultant "
                      f"{lab} (Sec. 11.8): {' + '.join(items)}",
                      equation=VectorEquation((Term(lab, Mark.UNKNOWN, Mark.UNKNOWN),),
                                              tuple(Term(i) for i in items)))
            return lab

        def two_force(lid: str, j1: Joint, j2: Joint) -> bool:
            """An unloaded link with two joints (Sec. 11.6)."""
            k1, k2 = kind_of(j1), kind_of(j2)
            if k1 == "line" and k2 == "line":
                l1, l2 = lines[j1.key], lines[j2.key]
                assert l1 is not None and l2 is not None
                if l1[1] == lid and l2[1] == lid:
                    return False
                if self.same_line(l1[0], l2[0]):
                    return False
                zero(lid, (j1, j2), "their lines of action differ")
                return True
            if k1 == "line" or k2 == "line":
                (jl, jo) = (j1, j2) if k1 == "line" else (j2, j1)
                ll = lines[jl.key]
                assert ll is not None
                if jo.kind == PIN:
                    if self.on_line(jo.point, ll[0]):
                        lines[jo.key] = (ll[0], lid)
                        p.order.append(f"link {lid}: two-force member along {ll[0]}")
                        return True
                elif self.parallel(self.env[f"n_{jo.key}"], _dir(self.env[ll[0]])):
                    lines[jo.key] = (ll[0], lid)
                    p.order.append(f"link {lid}: two-force member along {ll[0]}")
                    return True
                zero(lid, (j1, j2), f"the pin or slider cannot act along {ll[0]}")
                return True
            if k1 == SLIDE and k2 == SLIDE:
                if self.parallel(self.env[f"n_{j1.key}"], self.env[f"n_{j2.key}"]):
                    return False
                zero(lid, (j1, j2), "two sliders' normals cross")
                return True
            lab = self.fresh(f"l_{lid}{sfx}")
            if k1 == PIN and k2 == PIN:
                self.emit("join", (j1.point, j2.point), (lab,),
                          f"link {lid} is a two-force member: {j1.label(lid, sfx)} and "
                          f"{j2.label(lid, sfx)} act along the line {j1.point}{j2.point} "
                          "(Sec. 11.6)")
            else:
                jp, js = (j1, j2) if k1 == PIN else (j2, j1)
                self.emit("force_line", (jp.point, f"n_{js.key}"), (lab,),
                          f"link {lid} is a two-force member: its forces act through "
                          f"{jp.point} normal to the sliding line (Sec. 11.6)")
            lines[j1.key] = (lab, lid)
            lines[j2.key] = (lab, lid)
            p.order.append(f"link {lid}: two-force member along {lab}")
            return True

        def zero(lid: str, js: tuple[Joint, ...], why: str) -> None:
            for j in js:
                known[j.key] = _ZERO
            names = " and ".join(j.label(lid, sfx) for j in js)
            p.order.append(f"link {lid}: {names} are zero ({why})")

        progress = True
        while progress:
            progress = False
            for lid in mech.moving:
                unknown = [j for j in at_link[lid] if j.key not in known]
                drive = pending.get(lid)
                if not unknown and drive is None:
                    continue
                loads = loads_by_link.get(lid, [])
                knowns = [j for j in at_link[lid] if j.key in known and known[j.key] != _ZERO]
                rzero = not loads and not knowns
                if drive is not None:
                    progress |= self.drive_step(sfx, p.order, drives_out, lid, drive, unknown,
                                                loads, knowns, on_label, set_known, resultant,
                                                rzero, pending)
                    continue
                if rzero and len(unknown) == 2:
                    progress |= two_force(lid, *unknown)
                    continue
                if rzero and len(unknown) == 1:
                    zero(lid, (unknown[0],), "nothing else acts on the link")
                    progress = True
                    continue
                if rzero:
                    continue
                count = sum(1 if kind_of(j) == "line" else j.unknowns for j in unknown)
                if len(unknown) == 1 and count <= 2:
                    (j,) = unknown
                    r = resultant(lid, [*loads, *(on_label(k, lid) for k in knowns)])
                    lab = j.label(lid, sfx)
                    self.emit("force_balance", (r,), (lab,),
                              f"link {lid}: {lab} = -{r}, the one unknown force balances "
                              "the others (Σ F = 0)", role=Role.RESULT)
                    set_known(j, lid, lab)
                    p.order.append(f"link {lid}: {lab} balances the known forces")
                    progress = True
                    continue
                if len(unknown) == 3 and count == 3:
                    # a four-force member (Sec. 11.8): three forces on known lines
                    lns = [lines[j.key] for j in unknown]
                    dirs = [_dir(self.env[ln[0]]) for ln in lns if ln is not None]
                    if len(dirs) != 3:
                        continue
                    # q where the two most crossing lines meet; the third is found first
                    pairs = [(0, 1, 2), (0, 2, 1), (1, 2, 0)]
                    i, k, m = max(pairs, key=lambda t: abs(float(
                        dirs[t[0]][0] * dirs[t[1]][1] - dirs[t[0]][1] * dirs[t[1]][0])))
                    order = [unknown[i], unknown[k], unknown[m]]
                    r = resultant(lid, [*loads, *(on_label(kk, lid) for kk in knowns)])
                    labs = [j.label(lid, sfx) for j in order]
                    q = self.fresh(f"q_{lid}{sfx}")
                    eq = VectorEquation((Term(r),), tuple(
                        Term(x, Mark.UNKNOWN, Mark.KNOWN, -1) for x in labs), case=None)
                    ins = tuple(lines[j.key][0] for j in order)  # type: ignore[index]
                    self.emit("force_four", (r, *ins), (*labs, q),
                              f"link {lid} is a four-force member (Sec. 11.8): the lines of "
                              f"{labs[0]} and {labs[1]} meet at {q}; Σ M_{q} = 0 gives "
                              f"{labs[2]}; {r} + {labs[2]} acts along the line to {q}, and "
                              f"the force polygon gives {labs[0]} and {labs[1]}",
                              role=Role.RESULT, equation=eq)
                    for j, lab in zip(order, labs):
                        set_known(j, lid, lab)
                    p.order.append(f"link {lid}: four-force member, moments about {q}")
                    progress = True
                    continue
                if len(unknown) == 2 and count == 3:
                    j1, j2 = unknown
                    if kind_of(j2) == "line":
                        j1, j2 = j2, j1
                    if kind_of(j1) != "line":
                        continue
                    r = resultant(lid, [*loads, *(on_label(k, lid) for k in knowns)])
                    line1 = lines[j1.key]
                    assert line1 is not None
                    f1, f2 = j1.label(lid, sfx), j2.label(lid, sfx)
                    x = self.fresh(f"X_{lid}{sfx}")
                    eq = VectorEquation((Term(r),), (
                        Term(f1, Mark.UNKNOWN, Mark.KNOWN, -1),
                        Term(f2, Mark.UNKNOWN, Mark.KNOWN, -1)), case=3)
                    if kind_of(j2) == PIN:
                        ln = self.env[line1[0]]
                        pp = self.env[j2.point]
                        if abs(float(ln @ pp)) <= self.tol.length(self.scale):
                            raise ConstructionError(
                                f"link {lid}: the line of action of {f1} passes through the "
                                f"pin {j2.point}, so no force at {j2.point} can balance "
                                f"{r}'s moment: equilibrium cannot be held at this posture "
                                "(a dead center)", step=f1)
                        self.emit("force_three", (r, line1[0], j2.point), (f1, f2, x),
                                  f"link {lid} is a three-force member: the lines of {r} and "
                                  f"{f1} meet at the concurrency point {x}; {f2} acts along "
                                  f"{j2.point}{x}; the force polygon {r} + {f1} + {f2} = 0 "
                                  "closes (Fig. 11.5e-f)", role=Role.RESULT, equation=eq)
                        p.order.append(f"link {lid}: three-force member, concurrency point "
                                       f"{x}")
                    else:
                        if self.parallel(_dir(self.env[line1[0]]), self.env[f"n_{j2.key}"]):
                            raise ConstructionError(
                                f"link {lid}: {f1} and {f2} are parallel, so the force "
                                "polygon cannot close: equilibrium cannot be held at this "
                                "posture", step=f1)
                        self.emit("force_slide_three", (r, line1[0], f"n_{j2.key}"),
                                  (f1, f2, x),
                                  f"link {lid}: the force polygon {r} + {f1} + {f2} = 0 with "
                                  f"{f2} normal to the sliding line gives both sizes; {f2} "
                                  f"acts through the concurrency point {x} (Ex 11.2)",
                                  role=Role.RESULT, equation=eq)
                        p.order.append(f"link {lid}: slider's normal force through {x}")
                    set_known(j1, lid, f1)
                    set_known(j2, lid, f2)
                    progress = True
            finished = len(known) == len(todo) and not pending
            if finished:
                break
            if not progress:
                return self.split(p, sfx, loads_by_link, done, known, lines, pending, depth,
                                  drives_out, on_label, resultant, at_link)
        return known, drives_out

    def split(self, p: Partial, sfx: str, loads_by_link: dict[str, list[str]], done: set[str],
              known: dict[str, str], lines: dict[str, tuple[str, str] | None],
              pending: dict[str, Any], depth: int, drives_out: dict[str, str],
              on_label: Callable[..., str], resultant: Callable[..., str],
              at_link: dict[str, list[Joint]]) -> tuple[dict[str, str], dict[str, str]]:
        """Stuck with several loaded links: one analysis per loaded link, then add."""
        left = [j.key for j in self.joints if j.key not in done and j.key not in known]
        loaded: dict[str, list[str]] = {}
        for lid in self.mech.moving:
            if not any(j.key not in known for j in at_link[lid]):
                continue
            items = [*loads_by_link.get(lid, []),
                     *(on_label(j, lid) for j in at_link[lid]
                       if j.key in known and known[j.key] != _ZERO)]
            if items:
                loaded[lid] = [resultant(lid, items)]
        if len(loaded) < 2 or depth >= 3:
            raise NotDecomposable(
                "the graphic method finds no two- or three-force member to go on with "
                f"(joints left: {', '.join(left) or 'none'}; drives left: "
                f"{', '.join(pending) or 'none'})")
        p.order.append("superpose again, one analysis per loaded link: "
                       + ", ".join(f"{lid} ({v[0]})" for lid, v in loaded.items()))
        now_done = done | set(known)
        subs = []
        for k, (lid, items) in enumerate(loaded.items()):
            tag = sfx + "abcdefghijklmnopqrstuvwxyz"[k % 26]
            subs.append(self.analyse(p, tag, {lid: items}, now_done, lines, pending,
                                     depth + 1))
        for key in left:
            j = next(jt for jt in self.joints if jt.key == key)
            parts = [sub[0][key] for sub in subs if sub[0][key] != _ZERO]
            if not parts:
                known[key] = _ZERO
                continue
            canon = j.label(j.hi, sfx)
            self.emit("force_resultant", tuple(parts), (canon,),
                      f"superposition (Sec. 12.5): {canon} = {' + '.join(parts)}")
            known[key] = canon
        for lid in pending:
            parts = [sub[1][lid] for sub in subs]
            lab = f"T_{FRAME}{lid}{sfx}" if pending[lid].kind == "angle" else \
                f"F_{pending[lid].slider.point}{sfx}·u"
            self.emit("force_add_torques", tuple(parts), (lab,),
                      f"superposition (Sec. 12.5): {lab} = {' + '.join(parts)}")
            drives_out[lid] = lab
        return known, drives_out

    def drive_step(self, sfx: str, order: list[str], drives_out: dict[str, str], lid: str,
                   drive: Any, unknown: list[Joint],
                   loads: list[str], knowns: list[Joint], on_label: Callable[..., str],
                   set_known: Callable[..., None], resultant: Callable[..., str],
                   rzero: bool, pending: dict[str, Any]) -> bool:
        """The drive link, when only its frame's force is left (Ex 11.1 step 7, Ex 12.3)."""

        def found(out: str, words: str) -> bool:
            drives_out[lid] = out
            order.append(f"link {lid}: {words}")
            del pending[lid]
            return True

        if drive.kind == "angle":
            frame = [j for j in unknown if j.kind == PIN and j.point == drive.pivot
                     and FRAME in (j.lo, j.hi)]
            if len(unknown) != 1 or not frame:
                return False
            (j,) = frame
            t = f"T_{FRAME}{lid}{sfx}"
            if rzero:
                self.emit("scalar", (), (t,), f"{t} = 0: nothing loads link {lid}", value=0.0)
                set_known(j, lid, _ZERO)
            else:
                r = resultant(lid, [*loads, *(on_label(k, lid) for k in knowns)])
                lab = j.label(lid, sfx)
                self.emit("force_drive_reaction", (r, drive.pivot), (lab,),
                          f"link {lid}: the frame's force {lab} = -{r} acts at {drive.pivot}",
                          role=Role.RESULT)
                self.emit("force_drive_torque", (r, drive.pivot), (t,),
                          f"the drive's torque {t} = -(arm of {r} about {drive.pivot}) × "
                          f"|{r}| holds link {lid} (Σ M_{drive.pivot} = 0)", role=Role.RESULT)
                set_known(j, lid, lab)
            return found(t, f"the drive's torque {t}")
        slider = drive.slider
        if slider is None or slider.on != FRAME:
            return False
        match = [j for j in unknown if j.kind == SLIDE and j.source is slider]
        if len(unknown) != 1 or not match:
            return False
        (j,) = match
        fa = f"F_{slider.point}{sfx}"
        amount = f"{fa}·u"
        if rzero:
            self.emit("scalar", (), (amount,), f"{fa} = 0: nothing loads link {lid}", value=0.0)
            self.emit("force_zero", (), (fa,), f"{fa} = 0")
            set_known(j, lid, _ZERO)
        else:
            r = resultant(lid, [*loads, *(on_label(k, lid) for k in knowns)])
            lab = j.label(lid, sfx)
            eq = VectorEquation((Term(r),), (Term(fa, Mark.UNKNOWN, Mark.KNOWN, -1),
                                             Term(lab, Mark.UNKNOWN, Mark.KNOWN, -1)), case=3)
            self.emit("force_drive_force", (r, slider.point, f"u_{j.key}", f"n_{j.key}"),
                      (fa, lab), f"link {lid}: the input force {fa} along the slider's line and "
                      f"the frame's normal force {lab} close the polygon {r} + {fa} + {lab} = 0",
                      role=Role.RESULT, equation=eq)
            self.emit("force_along", (fa, f"u_{j.key}"), (amount,),
                      f"the input force {fa}, signed along the slider's line", role=Role.RESULT)
            set_known(j, lid, lab)
        return found(amount, f"the input force {fa}")

    def superpose(self, partials: list[Partial]) -> tuple[dict[str, str], dict[str, str],
                                                          dict[str, str]]:
        """The vector sums of the partial analyses (Sec. 12.5, Ex 12.5)."""
        forces: dict[str, str] = {}
        drives: dict[str, str] = {}
        drive_forces: dict[str, str] = {}
        for j in self.joints:
            final = j.label(j.hi)
            parts = [p.forces[j.key] for p in partials]
            if len(parts) == 1 and parts[0] == final:
                forces[j.key] = final
                continue
            if not parts:
                self.emit("force_zero", (), (final,), f"{final} = 0: nothing is loaded")
            else:
                self.emit("force_resultant", tuple(parts), (final,),
                          f"superposition (Sec. 12.5): {final} = {' + '.join(parts)}",
                          role=Role.RESULT)
            forces[j.key] = final
        for d in self.mech.drives:
            parts = [p.drives[d.link] for p in partials]
            if d.kind == "angle":
                final = f"T_{FRAME}{d.link}"
            else:
                assert d.slider is not None
                final = f"F_{d.slider.point}·u"
                drive_forces[d.link] = f"F_{d.slider.point}"
            if len(parts) == 1 and parts[0] == final:
                drives[d.link] = final
                continue
            if not parts:
                self.emit("scalar", (), (final,), f"{final} = 0: nothing is loaded", value=0.0)
            else:
                self.emit("force_add_torques", tuple(parts), (final,),
                          f"superposition (Sec. 12.5): {final} = {' + '.join(parts)}",
                          role=Role.RESULT)
            drives[d.link] = final
        return forces, drives, drive_forces


def _dir(line: np.ndarray) -> np.ndarray:
    """The direction ``(b, -a)`` of a line ``(a, b, c)``."""
    return np.array([line[1], -line[0]])


def build_forces(sol: Solution, joints: list[Joint], geo: Geometry, dynamic: bool,
                 tol: Tolerance | None = None) -> BuiltForces:
    """Build and evaluate the force construction of a solved posture.

    Raises
    ------
    NotDecomposable
        The graphic method finds no order (the caller falls back to the matrix method).
    ConstructionError
        A step has no finite answer: equilibrium cannot be held at this posture.
    """
    return _Builder(sol, joints, geo, tol or DEFAULT_TOL).build(dynamic)


# keep the helpers importable for the report and the drawing
__all__ += ["BuiltForces", "line_of", "moment_about"]
