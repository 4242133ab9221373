"""A construction: an ordered list of named, replayable steps.

The same construction is evaluated on one posture (arrays of shape ``(3,)``,
to draw and narrate) and on many (shape ``(N, 3)``, to sweep): the inputs
decide, the steps do not change.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8.
"""

from __future__ import annotations

import json
import operator
from collections.abc import Callable, Iterable, Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from graphkin.construction.ops import OPS, OUTPUT_KIND
from graphkin.construction.ops.runtime import (
    KERNELS,
    ORIGINATING,
    CompileInfo,
    Runtime,
    _all_finite,
    generic_kernel,
)
from graphkin.construction.step import Role, Step, VectorEquation
from graphkin.errors import ConstructionError, DegenerateError, NoIntersectionError
from graphkin.geometry.ops import xy as g_xy
from graphkin.text import table
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["Construction", "Evaluation"]

_FAILURE = {
    "intersect_circles": NoIntersectionError,
    "intersect_line_circle": NoIntersectionError,
    "join": DegenerateError,
    "meet": DegenerateError,
}


@dataclass
class Evaluation:
    """The values of a construction's labels after a replay.

    Attributes
    ----------
    values : dict
        Label -> array.
    valid : numpy.ndarray of bool
        For a batch replay, which entries of the leading axis were constructed
        (an entry whose arcs did not meet is False); a 0-d True for one posture.
    failed_at : dict
        For a batch, the first step that failed for each failed entry (step index).
    unit : frozenset of str
        Point labels known to be stored with ``w == 1`` exactly, or all NaN
        (so their first two components are their Cartesian coordinates); set
        by the compiled evaluation, empty when not known.
    """

    values: dict[str, np.ndarray]
    valid: np.ndarray
    failed_at: np.ndarray | None = None
    unit: frozenset[str] = frozenset()

    def __getitem__(self, label: str) -> np.ndarray:
        return self.values[label]

    def __contains__(self, label: object) -> bool:
        return label in self.values


@dataclass
class Construction:
    """An ordered, replayable list of :class:`Step` records.

    Examples
    --------
    Case 4 of Table 2.2 (two unknown directions): the arcs about A and D meet at C.

    >>> cx = Construction()
    >>> _ = cx.add("point", (), ("A",), xy=(0.0, 0.0), role="given")
    >>> _ = cx.add("point", (), ("D",), xy=(8.0, 0.0), role="given")
    >>> _ = cx.add("circle", ("A",), ("k_A",), radius=5.0)
    >>> _ = cx.add("circle", ("D",), ("k_D",), radius=5.0)
    >>> _ = cx.add("intersect_circles", ("k_A", "k_D"), ("C",), branch="left", role="result")
    >>> cx.evaluate()["C"]
    array([4., 3., 1.])
    >>> len(cx.upto(2))
    3
    """

    steps: list[Step] = field(default_factory=list)
    title: str = ""

    def __len__(self) -> int:
        return len(self.steps)

    def __repr__(self) -> str:
        """A short summary: the title, the number of steps by role, the results (never raises).

        >>> Construction(title="velocity polygon")
        <Construction 'velocity polygon': 0 steps>
        """
        try:
            head = f"<Construction {self.title!r}: {len(self.steps)} steps"
            if not self.steps:
                return head + ">"
            roles: dict[str, int] = {}
            for s in self.steps:
                roles[str(s.role)] = roles.get(str(s.role), 0) + 1
            counts = ", ".join(f"{n} {r}" for r, n in roles.items())
            results = [o for s in self.steps if str(s.role) == "result" for o in s.outputs]
            more = f"; results {' '.join(results[:12])}{' …' if len(results) > 12 else ''}"
            return f"{head} ({counts}){more if results else ''}>"
        except Exception:  # a repr never raises
            return f"<Construction at {id(self):#x}>"

    def __iter__(self) -> Iterator[Step]:
        return iter(self.steps)

    def __getitem__(self, k: int) -> Step:
        return self.steps[k]

    @property
    def labels(self) -> list[str]:
        """Every output label, in order."""
        return [o for s in self.steps for o in s.outputs]

    def step_of(self, label: str) -> Step:
        """The step that makes ``label``."""
        for s in self.steps:
            if label in s.outputs:
                return s
        raise KeyError(label)

    def add(self, op: str, inputs: tuple[str, ...], outputs: tuple[str, ...], *,
            label: str | None = None, role: Role | str = Role.AUXILIARY,
            branch: str | None = None, equation: VectorEquation | None = None,
            note: str = "", diagram: str = "posture", **params: Any) -> Step:
        """Append a step and return it.

        Parameters
        ----------
        op : str
            An operation of :data:`graphkin.construction.ops.OPS`.
        inputs, outputs : tuple of str
            Labels read and written.
        label, role, branch, equation, note, diagram
            See :class:`Step`.
        **params
            The step's constants.
        """
        if op not in OPS:
            raise ConstructionError(f"unknown operation {op!r}; valid: {', '.join(sorted(OPS))}",
                                    step=label or (outputs[0] if outputs else op))
        if branch is not None:
            params["branch"] = str(branch)
        step = Step(index=len(self.steps), label=label or outputs[0], op=op,
                    inputs=tuple(inputs), outputs=tuple(outputs), params=params,
                    role=Role(role), branch=None if branch is None else str(branch),
                    equation=equation, note=note, diagram=diagram,
                    kind=OUTPUT_KIND[op])
        self.steps.append(step)
        return step

    def upto(self, k: int) -> Construction:
        """The construction made of steps ``0..k`` (inclusive): "step k of n"."""
        return Construction(self.steps[: k + 1], self.title)

    def extend(self, other: Construction) -> None:
        """Append the steps of another construction, renumbered."""
        for s in other.steps:
            self.steps.append(replace(s, index=len(self.steps)))

    def evaluate(self, given: Mapping[str, Any] | None = None, *, tol: Tolerance | None = None,
                 strict: bool = True, start: int = 0,
                 values: dict[str, np.ndarray] | None = None) -> Evaluation:
        """Replay the steps on the given values.

        Parameters
        ----------
        given : mapping
            Values of labels that no step makes (inputs such as drive angles),
            as arrays: a scalar per posture, or ``(..., 3)`` points.
        tol : Tolerance, optional
        strict : bool
            One posture: raise at the first step that has no answer.
            ``False`` (batches): mark the failed entries invalid and go on.
        start, values
            Resume from step ``start`` with the values already computed.

        Raises
        ------
        NoIntersectionError
            Arcs (or a line and an arc) that do not meet, when ``strict``.
        DegenerateError
            A join of coincident points or meet of coincident lines, when ``strict``.

        Notes
        -----
        The steps are compiled once (per tolerance and start) into a flat list
        of kernels with their constants bound (see
        :data:`graphkin.construction.ops.KERNELS`); steps whose inputs are all
        constant are evaluated once.  Only the steps that can turn finite
        inputs into non-finite outputs (and the consumers of non-finite or
        infinite inputs) are checked, which marks exactly the entries the
        step-by-step replay marks.  :meth:`replay` is that step-by-step
        replay through the general operations.
        """
        tol = tol or DEFAULT_TOL
        env: dict[str, np.ndarray] = dict(values or {})
        env.update({k: np.asarray(v, dtype=float) for k, v in (given or {}).items()})
        plan = self._plan(tol, start)
        return plan.run(env, strict)

    def replay(self, given: Mapping[str, Any] | None = None, *, tol: Tolerance | None = None,
               strict: bool = True, start: int = 0,
               values: dict[str, np.ndarray] | None = None) -> Evaluation:
        """Replay the steps one by one through the general operations.

        Same parameters and results as :meth:`evaluate` (up to rounding), with
        no compilation: the reference the compiled kernels are checked against.
        """
        tol = tol or DEFAULT_TOL
        env: dict[str, np.ndarray] = dict(values or {})
        env.update({k: np.asarray(v, dtype=float) for k, v in (given or {}).items()})
        valid: np.ndarray | None = None
        failed_at: np.ndarray | None = None
        for step in self.steps[start:]:
            if step.op == "input":
                if step.outputs[0] not in env:
                    raise _missing_input(step)
                continue
            try:
                args = [env[i] for i in step.inputs]
            except KeyError as exc:
                raise _unknown_input(step, exc.args[0]) from None
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                outs = OPS[step.op](*args, tol=tol, **step.params)
            for name, val in zip(step.outputs, outs):
                env[name] = val
            bad = _bad_entries(outs, step.kind)
            if bad is not None and np.any(bad):
                if strict:
                    raise _failure(step, args)
                valid, failed_at = _mark(valid, failed_at, bad, step.index)
        if valid is None:
            valid = np.array(True)
        return Evaluation(env, valid, failed_at)

    def evaluate_for(self, keep: Iterable[str], given: Mapping[str, Any] | None = None, *,
                     tol: Tolerance | None = None, strict: bool = True, start: int = 0,
                     values: dict[str, np.ndarray] | None = None) -> Evaluation:
        """Replay the steps as :meth:`evaluate` does, keeping only the values of ``keep``.

        Every step is carried out and checked exactly as by :meth:`evaluate`
        (same numbers, same ``valid`` and ``failed_at``), but the value of a
        label that is not in ``keep`` is let go as soon as no later step reads
        it, so that a long batch (a sweep) works in a small, hot piece of memory.
        ``Evaluation.values`` then holds the kept labels and what was given.

        Examples
        --------
        >>> cx = Construction()
        >>> _ = cx.add("point", (), ("A",), xy=(0.0, 0.0))
        >>> _ = cx.add("point", (), ("D",), xy=(8.0, 0.0))
        >>> _ = cx.add("circle", ("A",), ("k_A",), radius=5.0)
        >>> _ = cx.add("circle", ("D",), ("k_D",), radius=5.0)
        >>> _ = cx.add("intersect_circles", ("k_A", "k_D"), ("C",), branch="left")
        >>> sorted(cx.evaluate_for({"C"}).values)
        ['C']
        """
        tol = tol or DEFAULT_TOL
        env: dict[str, np.ndarray] = dict(values or {})
        env.update({k: np.asarray(v, dtype=float) for k, v in (given or {}).items()})
        keep = frozenset(keep)
        keep = keep | frozenset(env)
        return self._plan(tol, start).run(env, strict, keep)

    def _plan(self, tol: Tolerance, start: int) -> _Plan:
        plans: dict[tuple[Tolerance, int], _Plan] = self.__dict__.setdefault("_plans", {})
        plan = plans.get((tol, start))
        steps = self.steps
        if plan is None or len(plan.steps) != len(steps) or \
                not all(map(operator.is_, plan.steps, steps)):
            plan = _Plan(tuple(steps), tol, start)
            plans[(tol, start)] = plan
        return plan

    def __getstate__(self) -> dict[str, Any]:
        state = dict(self.__dict__)
        state.pop("_plans", None)
        return state

    def table(self) -> str:
        """A plain-text table of the steps: index, label, operation, inputs, branch, equation."""
        rows = [("#", "label", "op", "inputs", "role", "branch", "equation")]
        for s in self.steps:
            rows.append((str(s.index), s.label, s.op, ", ".join(s.inputs), str(s.role),
                         s.branch or "", "" if s.equation is None else str(s.equation)))
        return "\n".join(table(rows))

    def to_dict(self) -> list[dict[str, Any]]:
        """The steps as plain data."""
        return [s.to_dict() for s in self.steps]

    def _repr_svg_(self) -> str | None:
        """Jupyter: the construction drawn inline.

        The renderer is imported here, when a notebook asks, never at import time.
        """
        from graphkin.render import repr_svg

        return repr_svg(self)

    def to_json(self) -> str:
        """The steps as JSON text."""
        return json.dumps(self.to_dict(), ensure_ascii=False, indent=1)


def _missing_input(step: Step) -> ConstructionError:
    return ConstructionError(f"step {step.label}: the input {step.outputs[0]!r} was not given",
                             step=step.label)


def _unknown_input(step: Step, label: str) -> ConstructionError:
    return ConstructionError(f"step {step.label}: input {label!r} is not known", step=step.label)


def _mark(valid: np.ndarray | None, failed_at: np.ndarray | None, bad: np.ndarray,
          index: int) -> tuple[np.ndarray, np.ndarray]:
    """Record the entries a step failed for (the first failing step of each entry)."""
    if valid is None:
        valid = np.ones(np.shape(bad), dtype=bool)
        failed_at = np.full(np.shape(bad), -1, dtype=int)
    assert failed_at is not None
    # a step on constants may fail before the batch's shape is known: widen to the batch
    shape = np.broadcast_shapes(np.shape(bad), valid.shape)
    if shape != valid.shape:
        valid = np.broadcast_to(valid, shape).copy()
        failed_at = np.broadcast_to(failed_at, shape).copy()
    bad = np.broadcast_to(bad, shape)
    failed_at = np.where(bad & valid, index, failed_at)
    valid = valid & ~bad
    return valid, failed_at


class _Plan:
    """A construction compiled for one tolerance and start step.

    Each step becomes one kernel bound to its constants (or, when every input
    is constant, its values computed once).  ``externals`` are the labels read
    before any step in range makes them: the given inputs and the resumed values.
    """

    def __init__(self, steps: tuple[Step, ...], tol: Tolerance, start: int) -> None:
        self.steps = steps
        self.tol = tol
        info = CompileInfo()
        made: set[str] = set()
        externals: list[str] = []
        # (run, always checked, inputs, step); run is None for an input step.  A run that
        # returns True has made sure its outputs are finite (when its inputs are).
        self.program: list[tuple[Callable[[Runtime], bool | None] | None, bool,
                                 frozenset[str], Step]] = []
        for step in steps[start:]:
            if step.op == "input":
                for o in step.outputs:
                    info.forget(o)
                    made.discard(o)
                self.program.append((None, False, frozenset(), step))
                continue
            for i in step.inputs:
                if i not in made and i not in externals:
                    externals.append(i)
            if all(i in info.const for i in step.inputs):
                run, always = self._fold(step, info)
            else:
                factory = KERNELS.get(step.op)
                kern = factory(step, tol, info) if factory is not None else None
                always = step.op in ORIGINATING or kern is None
                run = kern if kern is not None else generic_kernel(step, tol)
                for o in step.outputs:
                    info.forget(o)
                if step.op == "circle" and np.ndim(step.params["radius"]) == 0:
                    info.radius[step.outputs[0]] = float(step.params["radius"])
            self.program.append((run, always, frozenset(step.inputs), step))
            made.update(step.outputs)
        self.externals = tuple(externals)

    def _fold(self, step: Step,
              info: CompileInfo) -> tuple[Callable[[Runtime], bool | None], bool]:
        """Evaluate a step whose inputs are all constant once; replaying it copies the values."""
        args = [info.const[i] for i in step.inputs]
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            outs = OPS[step.op](*args, tol=self.tol, **step.params)
        consts: list[tuple[str, np.ndarray, Any, bool, bool]] = []
        for name, val in zip(step.outputs, outs):
            val = np.asarray(val, dtype=float)
            info.forget(name)
            info.const[name] = val
            xy: Any = None
            unit = dirty = False
            if step.kind == "point" and val.shape[-1:] == (3,):
                if bool(np.all(val[..., 2] == 1.0)):
                    xy, unit = _rows2(val), True
                else:
                    xy, dirty = _rows2(g_xy(val)), True
            elif step.kind in ("circle", "vector") and val.ndim >= 1:
                xy = _rows2(val)
                if step.kind == "circle" and val.shape == (3,):
                    info.radius[name] = float(val[2])
            consts.append((name, val, xy, unit, dirty))
        bad = _bad_entries(tuple(c[1] for c in consts), step.kind)
        always = bad is not None and bool(np.any(bad))

        def run(rt: Runtime) -> None:
            for name, val, xy, unit, dirty in consts:
                rt.put(name, val.copy())
                if xy is not None:
                    rt.xy[name] = xy
                if unit:
                    rt.unit.add(name)
                if dirty:
                    rt.dirty.add(name)

        return run, always

    def drops(self, keep: frozenset[str]) -> dict[int, tuple[str, ...]]:
        """Program index -> labels no longer needed after it (neither read later nor kept)."""
        cache: dict[frozenset[str], dict[int, tuple[str, ...]]] = self.__dict__.setdefault(
            "_drops", {})
        hit = cache.get(keep)
        if hit is not None:
            return hit
        last: dict[str, int] = {}
        for k, (_, _, ins, step) in enumerate(self.program):
            for o in step.outputs:
                last.setdefault(o, k)
                last[o] = max(last[o], k)
            for i in ins:
                last[i] = k
        made = {o for _, _, _, st in self.program for o in st.outputs
                if st.op != "input"}
        out: dict[int, list[str]] = {}
        for lab, k in last.items():
            if lab in made and lab not in keep:
                out.setdefault(k, []).append(lab)
        hit = {k: tuple(v) for k, v in out.items()}
        cache[keep] = hit
        return hit

    def run(self, env: dict[str, np.ndarray], strict: bool,
            keep: frozenset[str] | None = None) -> Evaluation:
        rt = Runtime(env)
        dirty = rt.dirty
        for lab in self.externals:
            if lab in env and not _all_finite(env[lab]):
                dirty.add(lab)
        drops = self.drops(keep) if keep is not None else {}
        valid: np.ndarray | None = None
        failed_at: np.ndarray | None = None
        step: Step | None = None
        with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
            try:
                for k, (run, always, ins, step) in enumerate(self.program):
                    if run is None:
                        if step.outputs[0] not in env:
                            raise _missing_input(step)
                        continue
                    sure = run(rt)
                    if (sure is not True and always) or (dirty and not dirty.isdisjoint(ins)):
                        outs = [env[o] for o in step.outputs]
                        if not all(map(_all_finite, outs)):
                            bad = _bad_entries(tuple(outs), step.kind)
                            if bad is not None and np.any(bad):
                                if strict:
                                    raise _failure(step, [env[i] for i in step.inputs])
                                valid, failed_at = _mark(valid, failed_at, bad, step.index)
                    if drops:
                        for lab in drops.get(k, ()):
                            del env[lab]
                            rt.xy.pop(lab, None)
            except KeyError as exc:
                missing = [i for i in step.inputs if i not in env] if step is not None else []
                if missing:
                    raise _unknown_input(step, missing[0]) from None  # type: ignore[arg-type]
                raise exc
        if valid is None:
            valid = np.array(True)
        return Evaluation(env, valid, failed_at, frozenset(rt.unit))


def _rows2(a: np.ndarray) -> tuple[Any, Any]:
    """The first two rows of a constant: floats for one point, arrays otherwise."""
    if a.ndim == 1:
        return float(a[0]), float(a[1])
    return a[..., 0].copy(), a[..., 1].copy()


def _bad_entries(outs: tuple[np.ndarray, ...], kind: str) -> np.ndarray | None:
    bad = None
    for o in outs:
        o = np.asarray(o)
        b = ~np.isfinite(o)
        if kind != "scalar":
            b = b.any(axis=-1)
        bad = b if bad is None else (bad | b)
    return bad


def _failure(step: Step, args: list[np.ndarray]) -> Exception:
    cls = _FAILURE.get(step.op, ConstructionError)
    what = {
        "intersect_circles": "the two arcs do not meet",
        "intersect_line_circle": "the line and the arc do not meet",
        "join": "the two points coincide, so no line joins them",
        "meet": "the two lines coincide",
    }.get(step.op, "the step has no answer")
    objects = {name: np.asarray(a).tolist() for name, a in zip(step.inputs, args)}
    return cls(f"step {step.index} ({step.label}): {what} ({', '.join(step.inputs)})",
               step=step.label, objects=objects)
