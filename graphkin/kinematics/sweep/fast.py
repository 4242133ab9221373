"""A sweep's columns from one generated function: the constructions written out once per mechanism.

The posture, velocity and acceleration constructions of a mechanism
(:class:`~graphkin.kinematics.sweep.engine._Engine`) are written out by
:func:`graphkin.construction.codegen.generate` as one Python function of the
drive values that returns exactly the arrays the CSV columns need
(``docs/formats/sweep-csv.md``): no step-by-step replay, no evaluation
record, no value nobody reads.  It is built from the recorded steps, so any
mechanism the sweep constructs gets one; the held drives and the given rates
are written in as constants.  When some posture is not clean (it does not
assemble, a dead center, a value at infinity) the function says so and the
sweep replays the constructions as before, which marks those postures.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 2.8 (posture), Secs. 3.4-3.6 and 4.2-4.6 (polygons).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.construction.codegen import Generated, Unsupported, generate
from graphkin.kinematics.sweep.columns import _recipe
from graphkin.kinematics.sweep.engine import _Engine
from graphkin.text import wrap_degrees

Array = np.ndarray

_ZERO, _VALUE, _ANGLE = 0, 1, 2

#: After this many calls that were not clean and more of those than clean ones, a mechanism's
#: sweeps go straight to the replay (a mechanism that is never clean over its range).
_GIVE_UP = 3


@dataclass
class _Fast:
    """The generated function of an engine and where each column comes from."""

    generated: Generated
    layout: tuple[tuple[str, int], ...]
    clean: int = 0
    unclean: int = 0


def _layout(eng: _Engine) -> tuple[tuple[tuple[str, int], ...],
                                  tuple[tuple[str, str], ...]] | None:
    """Where each column comes from, and what the generated function returns; or None."""
    if eng.method != "construction" or eng.pc is None:
        return None
    if eng.pol is not None and eng.combined is None:
        return None  # [rates] of another link: the ratio is found posture by posture
    recipe = _recipe(eng)
    if recipe is None:
        return None
    layout: list[tuple[str, int]] = []
    requests: list[tuple[str, str]] = []
    for name, kind, _phase, label, comp in recipe:
        if kind == "zero":
            layout.append((name, _ZERO))
            continue
        layout.append((name, _ANGLE if kind == "angle" else _VALUE))
        requests.append((label, ("x", "y")[comp] if kind == "row" else "value"))
    return tuple(layout), tuple(requests)


def _constants(eng: _Engine) -> dict[str, Any]:
    """The inputs that stay fixed over a sweep: the held drives and the given rates."""
    constants: dict[str, Any] = dict(eng.held)
    if eng.combined is not None:
        constants.update(eng.rate_given)
    return constants


def _build(eng: _Engine) -> _Fast | None:
    """The engine's constructions written out, with the column layout; None if they cannot be."""
    plan = _layout(eng)
    if plan is None:
        return None
    layout, requests = plan
    cx = eng.combined if eng.combined is not None else eng.pc.construction  # type: ignore[union-attr]
    try:
        gen = generate(cx.steps, varying=eng.varying, constants=_constants(eng),
                       requests=requests, tol=eng.tol, name="sweep")
    except Unsupported:
        return None
    return _Fast(gen, layout)


def _fill(out: tuple[Any, ...], layout: tuple[tuple[str, int], ...], shape: tuple[int, ...],
          cols: dict[str, Array]) -> dict[str, Array]:
    """The columns (arrays of ``shape``) from what the generated function returned."""
    zero = np.zeros(shape)
    values = iter(out)
    seen: set[int] = set()
    for name, kind in layout:
        if kind == _ZERO:
            cols[name] = zero
            continue
        v = next(values)
        if type(v) is not np.ndarray or v.shape != shape:
            if np.ndim(v) == 0:  # a constant (a frame point, a given rate)
                if v == 0.0:
                    cols[name] = zero
                    continue
                c = np.empty(shape)
                c.fill(v)
                v = c
            else:
                v = np.array(np.broadcast_to(v, shape), dtype=float)
        elif id(v) in seen:
            v = v.copy()  # two columns with the same values are still two arrays
        seen.add(id(v))
        cols[name] = wrap_degrees(v) if kind == _ANGLE else v
    return cols


def fast_columns(eng: _Engine, dv: Array, user: Array) -> dict[str, Array] | None:
    """The columns of a block of drive values, or None when some posture is not clean.

    Every posture is then constructed: ``valid`` and ``assembled`` are True throughout.
    """
    fast = eng.fast
    if fast is False:
        fast = eng.fast = _build(eng)
    if fast is None:
        return None
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        inputs = eng.inputs_at(dv)
        out = fast.generated.fn(*(inputs[lab] for lab in fast.generated.varying))
    if out is None:
        fast.unclean += 1
        if fast.unclean >= _GIVE_UP and fast.unclean > fast.clean:
            eng.fast = None
        return None
    fast.clean += 1
    return _fill(out, fast.layout, (len(dv),), {"drive": user})
