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
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from graphkin.construction.ops import OPS, OUTPUT_KIND
from graphkin.construction.step import Role, Step, VectorEquation
from graphkin.errors import ConstructionError, DegenerateError, NoIntersectionError
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
    """

    values: dict[str, np.ndarray]
    valid: np.ndarray
    failed_at: np.ndarray | None = None

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
        """
        tol = tol or DEFAULT_TOL
        env: dict[str, np.ndarray] = dict(values or {})
        env.update({k: np.asarray(v, dtype=float) for k, v in (given or {}).items()})
        valid: np.ndarray | None = None
        failed_at: np.ndarray | None = None
        for step in self.steps[start:]:
            if step.op == "input":
                if step.outputs[0] not in env:
                    raise ConstructionError(f"step {step.label}: the input {step.outputs[0]!r} "
                                            "was not given", step=step.label)
                continue
            try:
                args = [env[i] for i in step.inputs]
            except KeyError as exc:
                raise ConstructionError(f"step {step.label}: input {exc.args[0]!r} is not known",
                                        step=step.label) from None
            with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
                outs = OPS[step.op](*args, tol=tol, **step.params)
            for name, val in zip(step.outputs, outs):
                env[name] = val
            bad = _bad_entries(outs, step.kind)
            if bad is not None and np.any(bad):
                if strict:
                    raise _failure(step, args)
                if valid is None:
                    valid = np.ones(np.shape(bad), dtype=bool)
                    failed_at = np.full(np.shape(bad), -1, dtype=int)
                bad = np.broadcast_to(bad, valid.shape)
                assert failed_at is not None
                failed_at = np.where(bad & valid, step.index, failed_at)
                valid = valid & ~bad
        if valid is None:
            valid = np.array(True)
        return Evaluation(env, valid, failed_at)

    def table(self) -> str:
        """A plain-text table of the steps: index, label, operation, inputs, branch, equation."""
        rows = [("#", "label", "op", "inputs", "role", "branch", "equation")]
        for s in self.steps:
            rows.append((str(s.index), s.label, s.op, ", ".join(s.inputs), str(s.role),
                         s.branch or "", "" if s.equation is None else str(s.equation)))
        widths = [max(len(r[i]) for r in rows) for i in range(len(rows[0]))]
        return "\n".join("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip() for r in rows)

    def to_dict(self) -> list[dict[str, Any]]:
        """The steps as plain data."""
        return [s.to_dict() for s in self.steps]

    def to_json(self) -> str:
        """The steps as JSON text."""
        return json.dumps(self.to_dict(), ensure_ascii=False, indent=1)


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
