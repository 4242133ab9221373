"""A sweep that follows the motion: the branch changes where the named one would turn back.

A sweep keeps the named branch of every two-way choice of the file's posture
(B *left* of A→C, Sec. 2.8).  Through a stretched or folded posture, or where
the two centers of a pair of arcs pass each other, the named branch is not the
continuous motion: the mechanism goes on along the other one while the named
branch jumps (the five-bar of Fig. 5.5 with θ3 = 3 θ2 − 315°, past θ2 = 395°).
:func:`follow` sweeps the mechanism on every combination of the branches of its
constructions (the same recorded steps, each two-way choice taken both ways),
and at each posture takes the combination whose points lie nearest those of the
posture before -- the motion a real mechanism makes -- naming every drive value
where it changes the branch of a step.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (the two branches of a posture),
Sec. 1.10 (dead-center postures, where branches meet).
"""

from __future__ import annotations

import copy
import dataclasses
import itertools
from typing import Any

import numpy as np

from graphkin.construction import Construction
from graphkin.kinematics.solution import LinkState, Solution
from graphkin.kinematics.sweep.drive_range import _count
from graphkin.kinematics.sweep.engine import _Engine, _engine
from graphkin.kinematics.sweep.report import Sweep
from graphkin.kinematics.sweep.run import _run
from graphkin.mechanisms.cam_joint import for_sweep
from graphkin.mechanisms.model import Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["follow", "MAX_BRANCHES"]

#: The most two-way choices followed (2**4 sweeps at most).
MAX_BRANCHES = 4

_OTHER = {"left": "right", "right": "left", "ahead": "behind", "behind": "ahead"}


def _flipped_cx(cx: Construction, flips: set[str]) -> Construction:
    steps = []
    for s in cx.steps:
        b = s.params.get("branch")
        if s.label in flips and b in _OTHER:
            s = dataclasses.replace(s, params={**s.params, "branch": _OTHER[b]},
                                    branch=_OTHER[b])
        steps.append(s)
    return Construction(steps, cx.title)


def _flipped(eng: _Engine, flips: set[str]) -> _Engine:
    """A copy of the engine with the branch of each step in ``flips`` taken the other way."""
    assert eng.pc is not None
    new = copy.copy(eng)
    new.pc = dataclasses.replace(
        eng.pc, construction=_flipped_cx(eng.pc.construction, flips),
        branches={k: (_OTHER.get(v, v) if k in flips else v) for k, v in eng.pc.branches.items()})
    if eng.combined is not None:
        new.combined = _flipped_cx(eng.combined, flips)
    new.fast = False
    new.extras = {}
    new.const_rows = {}
    return new


def _state(sw: Sweep) -> np.ndarray:
    """Every named point's position at every posture, ``(N, 2P)`` (NaN where not assembled)."""
    mech = sw.mechanism
    cols = [np.asarray(sw.columns[f"{a}_{p}"], dtype=float) for p in mech.point_names
            for a in ("x", "y")]
    return np.stack(cols, axis=-1)


def _choose(states: list[np.ndarray], ok: list[np.ndarray]) -> np.ndarray:
    """Per posture, the sweep whose points continue those of the posture before.

    Sequential by nature (each choice depends on the last); per posture it is one
    comparison of a few short vectors.  A posture after one that does not assemble
    starts again on the file's branches where they assemble.
    """
    n = len(states[0])
    sel = np.zeros(n, dtype=int)
    oks = np.stack(ok)                      # (C, N)
    st = np.stack(states)                   # (C, N, 2P)
    prev, prev_c, before, before_c = -1, 0, -1, 0
    for k in range(n):
        good = np.flatnonzero(oks[:, k])
        if not len(good):
            prev = before = -1
            continue
        if prev < 0:
            c = 0 if oks[0, k] else int(good[0])
        else:
            # where the motion is heading: on from the two postures before (through a
            # stretched posture both branches are equally near the last one, and the
            # motion goes on across, not back)
            last = st[prev_c, k - 1]
            if before >= 0:
                last = 2 * last - st[before_c, k - 2]
            d = np.nansum((st[good, k] - last) ** 2, axis=-1)
            c = int(good[int(np.argmin(d))])
            # stay on the branch taken unless another is clearly nearer
            if oks[prev_c, k]:
                here = float(np.nansum((st[prev_c, k] - last) ** 2))
                if here <= float(np.min(d)) * (1 + 1e-9) + 1e-300:
                    c = prev_c
        sel[k] = c
        before, before_c = prev, prev_c
        prev, prev_c = k, c
    return sel


def _pick_solution(sols: list[Solution], sel: np.ndarray) -> Solution:
    """A sweep's solution made of the chosen rows of each combination's."""
    base = sols[0]
    links = {}
    for lid in base.links:
        fields: dict[str, Any] = {}
        for f in ("angle", "origin", "omega", "alpha", "origin_velocity",
                  "origin_acceleration"):
            arrs = [getattr(s.links[lid], f) for s in sols]
            if arrs[0] is None:
                fields[f] = None
                continue
            stack = np.stack([np.broadcast_to(np.asarray(a, dtype=float),
                                              np.shape(arrs[0])) for a in arrs])
            fields[f] = np.take_along_axis(
                stack, sel.reshape((1, -1) + (1,) * (stack.ndim - 2)), axis=0)[0]
        links[lid] = LinkState(**fields)
    valid = np.stack([np.broadcast_to(np.asarray(s.valid), sel.shape) for s in sols])
    return dataclasses.replace(base, links=links, constructions={}, values={},
                               valid=np.take_along_axis(valid, sel[None], axis=0)[0])


def follow(mech: Mechanism, count: int = 360, start: float | None = None,
           stop: float | None = None, *, tol: Tolerance | None = None,
           transmission: bool = False, centers: bool = False,
           curvature: bool = False) -> Sweep:
    """Sweep as :func:`graphkin.kinematics.sweep.sweep`, keeping the motion continuous.

    Returns
    -------
    Sweep
        Its columns (and ``solution``) take, at each posture, the branches that
        continue the posture before; ``notes`` name every drive value where a
        step's branch changes, and ``branches`` hold the file's.  A mechanism
        swept by the analytic solver already follows the motion (Newton goes on
        from each posture to the next), and is returned as it is.
    """
    mech = for_sweep(mech)  # a cam's follower moves by the cam's program (Sec. 6.3)
    count = _count(count, mech)
    tol = tol or DEFAULT_TOL
    base = _engine(mech, tol)
    def run(eng: _Engine) -> Sweep:
        return _run(mech, eng, count, start, stop, transmission=transmission, centers=centers,
                    curvature=curvature)

    sw0 = run(base)
    if base.method == "analytic" or base.pc is None or not base.pc.branches:
        return sw0
    labels = list(base.pc.branches)
    note = ""
    if len(labels) > MAX_BRANCHES:
        note = (f"--follow: {len(labels)} two-way choices; the first {MAX_BRANCHES} "
                f"({', '.join(labels[:MAX_BRANCHES])}) are followed, the others kept as named")
        labels = labels[:MAX_BRANCHES]
    combos = [set(c) for r in range(len(labels) + 1) for c in itertools.combinations(labels, r)]
    sweeps = [sw0] + [run(_flipped(base, flips)) for flips in combos[1:]]
    oks = [np.asarray(s.assembled, dtype=bool) & np.all(np.isfinite(_state(s)), axis=-1)
           for s in sweeps]
    sel = _choose([_state(s) for s in sweeps], oks)
    cols = {}
    for name in sw0.columns:
        stack = np.stack([np.asarray(s.columns[name], dtype=float) for s in sweeps])
        cols[name] = np.take_along_axis(stack, sel[None], axis=0)[0]
    cols["drive"] = sw0.columns["drive"]
    pick = np.arange(count)
    assembled = np.stack([s.assembled for s in sweeps])[sel, pick]
    valid = np.stack([np.broadcast_to(s.valid, (count,)) for s in sweeps])[sel, pick]
    notes = list(sw0.notes) + ([note] if note else [])
    drive = np.asarray(sw0.columns["drive"], dtype=float)
    for k in range(1, count):
        if sel[k] != sel[k - 1] and assembled[k] and assembled[k - 1]:
            changed = sorted(combos[sel[k]] ^ combos[sel[k - 1]])
            where = ", ".join(f"{lab} from {_side(base, lab, combos[sel[k - 1]])} to "
                              f"{_side(base, lab, combos[sel[k]])}" for lab in changed)
            unit = "°" if sw0.drive.is_angle else f" {mech.length_unit}"
            notes.append(f"--follow: the motion goes on along the other branch between drive "
                         f"{drive[k - 1]:.2f}{unit} and {drive[k]:.2f}{unit} ({where}): a "
                         "stretched or folded posture, or two centers passing each other")
    out = Sweep(mech, sw0.drive, sw0.values, cols, valid, assembled, sw0.method, notes,
                dict(sw0.branches), base, sw0._parts, sw0._cyclic, sw0._released)
    if len(set(sel.tolist())) > 1:
        sol = _pick_solution([s.solution for s in sweeps], sel)
        out.__dict__["solution"] = sol
    return out


def _side(eng: _Engine, label: str, flips: set[str]) -> str:
    assert eng.pc is not None
    b = eng.pc.branches[label]
    return str(_OTHER.get(b, b) if label in flips else b).upper()
