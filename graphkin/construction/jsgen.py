"""A construction written out as one JavaScript function, from the Python writer's templates.

The Python writer (:mod:`graphkin.construction.codegen`) walks the recorded
steps and lets each operation's *template*
(:mod:`graphkin.construction.ops.templates`, the one table of operations)
write its arithmetic through a :class:`~graphkin.construction.codegen.Gen`.
A template writes only expressions both languages read alike (``+ - * /``,
``**``, parentheses, calls of ``_sqrt``, ``_atan2``, ``_cos``, ``_sin``,
``_min(x, None)``, ``_abs``, ``_maximum``, ``max``, ``float``) and asks the
generator for the few forms that differ (:meth:`Gen.where`,
:meth:`Gen.every`, :meth:`Gen.helper`).  :class:`JSGen` is the same
generator writing JavaScript: one posture, JavaScript numbers only, so the
runtime names above are one-line shims over ``Math``.

Two differences from the Python writer:

* **The mechanism's dimensions are parameters.**  Every number a step
  carries (a frame pivot's coordinates, a link's local coordinates, an
  arc's radius) is read from the array ``K`` the function takes, not written
  in as a literal, and no step is folded; :attr:`JSFunction.slots` names each
  entry and gives its recorded value.  A frame point ``A`` (a ``point``
  step) has the slots ``"A.0"`` and ``"A.1"`` (its x and y); the branch of a
  two-way step making ``C`` is the sign ``"C.branch"`` (+1 the recorded
  ``left``/``ahead``, -1 the other), so the page can switch it.
* **No general function to fall back on.**  An operation without a template
  cannot be written (:class:`~graphkin.construction.codegen.Unsupported`).

As in Python, the function computes the clean case only and returns ``null``
where the compiled kernel would take its exact branch (arcs that do not meet
or barely touch, coincident points, parallel lines): a posture that cannot be
assembled, or is too near a dead center to be constructed cleanly.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (the posture constructions), Secs. 3.4-3.6 and 4.2-4.6 (the
velocity and acceleration polygons).
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from graphkin.construction.codegen import (
    TEMPLATES,
    Gen,
    NeedGeneric,
    Unsupported,
    _live,
    _num,
    _params_key,
    lit,
)
from graphkin.construction.step import Step
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["JSFunction", "JSGen", "generate_js", "js_string", "RUNTIME"]

RUNTIME = """\
const _sqrt = Math.sqrt, _atan2 = Math.atan2, _cos = Math.cos, _sin = Math.sin;
const _abs = Math.abs, _maximum = Math.max, max = Math.max, None = null;
const _min = (x, _axis) => x, _max = (x, _axis) => x, float = (x) => x;
const _fin = (x) => Number.isFinite(x);
"""
"""The names the templates' expressions call, for one posture of JavaScript numbers."""


def _helpers_js(tol: Tolerance) -> dict[str, str]:
    """The JavaScript of :data:`graphkin.construction.codegen.HELPERS` (same arithmetic)."""
    a, r = lit(tol.length_abs), lit(tol.length_rel)
    return {
        # (h/d)² of two arcs; a round-off below the length tolerance is a tangency
        "tangent_cc": (
            "function _tangent_cc(q2, dd, r1, r2) {\n"
            "  const dist = Math.sqrt(dd);\n"
            "  const scale = Math.max(Math.max(r1, r2), dist);\n"
            f"  const eps = {a} + {r} * Math.abs(scale);\n"
            "  return (q2 < 0 && q2 * dd > -2 * eps * scale) ? 0.0 : q2;\n}\n"),
        # h² of a line and an arc; a round-off below the length tolerance is zero
        "tangent_lc": (
            "function _tangent_lc(h2, s, r) {\n"
            f"  const eps = {a} + {r} * Math.abs(Math.max(r, Math.abs(s)));\n"
            "  return (h2 < 0 && h2 > -2 * eps * Math.max(r, 1e-300)) ? 0.0 : h2;\n}\n"),
        # entry by entry in Python (np.where); one posture here
        "select": "function _select(c, a, b) { return c ? a : b; }\n",
        # a declaration, not a const: a page holds several functions that each bring it
        "floor": "function _floor(x) { return Math.floor(x); }\n",
    }


def js_string(text: str) -> str:
    """``text`` as a JavaScript string literal safe inside an HTML ``<script>``."""
    return (json.dumps(text).replace("<", "\\u003c").replace(">", "\\u003e")
            .replace("&", "\\u0026").replace("\u2028", "\\u2028").replace("\u2029", "\\u2029"))


@dataclass
class JSFunction:
    """A construction written out as JavaScript.

    Attributes
    ----------
    source : str
        The source of ``function <name>(I, K)``: ``I`` maps each input's label
        to a number, ``K`` is the array of the construction's numbers; it
        returns an object, label -> number (a scalar) or array (a point's
        ``[x, y]``, a vector's two rows, a line's or circle's three), or
        ``null`` when the posture is not clean.
    name : str
        The function's name.
    inputs : tuple of str
        The labels ``I`` must give.
    slots : tuple of (str, float)
        ``K``'s entries: a name (the label of the step that reads it and a
        count) and the value the construction recorded.
    requests : tuple of str
        The labels the returned object holds.
    """

    source: str
    name: str
    inputs: tuple[str, ...]
    slots: tuple[tuple[str, float], ...]
    requests: tuple[str, ...]

    @property
    def values(self) -> list[float]:
        """The recorded value of every slot, in order (the ``K`` of the drawn mechanism)."""
        return [v for _, v in self.slots]


class JSGen(Gen):
    """The generator of :mod:`graphkin.construction.codegen`, writing JavaScript."""

    def __init__(self, tol: Tolerance, homogeneous: bool = False) -> None:
        super().__init__(tol)
        #: points as homogeneous rows ``(x, y, w)``, at infinity too (the instant centers)
        self.homogeneous = homogeneous
        self.slots: list[tuple[str, float]] = []
        self.owner = "K"
        self.count = 0
        self.helpers: set[str] = set()
        #: soft: a step with no clean answer makes its own outputs (and what reads them) null,
        #: not the whole function; ``conds`` collects the current step's conditions
        self.soft = False
        self.conds: list[str] | None = None
        self.flags: dict[str, str] = {}
        self.cse_flags: dict[Any, str] = {}

    # the forms that differ from Python
    def let(self, expr: str, hint: str = "t") -> str:
        """``expr`` as a ``const`` (a name or literal is returned as it is)."""
        if expr.isidentifier() or _num(expr) is not None:
            return expr
        name = self.memo.get(expr)
        if name is None:
            name = self.memo[expr] = self.tmp(hint)
            self.lines.append(f"  const {name} = {expr};")
        return name

    def bail_unless(self, cond: str) -> None:
        """Return ``null`` (not clean) unless ``cond`` holds (soft: the step's outputs only)."""
        if self.soft and self.conds is not None:
            if cond not in self.conds:
                self.conds.append(cond)
            return
        line = f"  if (!({cond})) return null;"
        if line not in self.memo:
            self.memo[line] = ""
            self.lines.append(line)

    def where(self, cond: str, a: str, b: str) -> str:
        """``cond ? a : b``."""
        return f"(({cond}) ? {a} : {b})"

    def every(self, cond: str) -> str:
        """One posture: ``cond`` itself."""
        return cond

    def helper(self, name: str) -> str:
        """The JavaScript helper ``_<name>`` (written once before the function)."""
        self.helpers.add(name)
        return f"_{name}"

    def num(self, v: Any) -> str:
        """A number of a step: a new entry of ``K`` (a dimension is a parameter)."""
        a = np.asarray(v, dtype=float)
        if a.ndim != 0:
            raise Unsupported("a batch of designs cannot be written out as JavaScript")
        if not bool(np.isfinite(a)):
            raise Unsupported(f"a number of {self.owner!r} is not finite")
        k = len(self.slots)
        self.slots.append((f"{self.owner}.{self.count}", float(a)))
        self.count += 1
        name = self.tmp("k")
        self.lines.append(f"  const {name} = K[{k}];")
        return name

    def side(self, step: Step, left: bool) -> bool | str:
        """The branch as a sign in ``K`` (slot ``<label>.branch``: +1 left, -1 right)."""
        k = len(self.slots)
        self.slots.append((f"{self.owner}.branch", 1.0 if left else -1.0))
        name = self.tmp("k")
        self.lines.append(f"  const {name} = K[{k}];")
        return name

    def bind(self, value: Any, hint: str = "k") -> str:
        """No Python objects in JavaScript."""
        raise Unsupported("a Python object cannot be written out as JavaScript")

    def generic(self, step: Step) -> None:
        """No general functions in JavaScript: every operation needs its template."""
        raise Unsupported(f"the operation {step.op!r} has no template")


def generate_js(steps: Sequence[Step], *, requests: Iterable[str],
                tol: Tolerance | None = None, name: str = "construction",
                given: Iterable[str] = (), homogeneous: bool | None = None,
                ideal: Iterable[str] = (), soft: bool = False) -> JSFunction:
    """Write the steps out as one JavaScript function of the inputs and the dimensions.

    Parameters
    ----------
    steps : sequence of Step
        The construction (:attr:`Construction.steps`).
    requests : iterable of str
        The labels the function returns.
    tol : Tolerance, optional
    name : str
    given : iterable of str
        Points read from the inputs as homogeneous ``[x, y, w]`` (finite or at
        infinity) instead of computed by their steps: the primary instant
        centers, taken from the posture (Sec. 3.13).  With any, the function
        works in homogeneous coordinates throughout (``join``, ``meet`` of
        parallel lines at infinity) and returns every point as ``[x, y, w]``.
    homogeneous : bool, optional
        False: the given points are finite, read as ``[x, y]`` and the
        function works in Cartesian coordinates (the curvature constructions
        of a posture, Secs. 4.13-4.17).  Default: homogeneous when any point
        is given.
    ideal : iterable of str
        Given points read as homogeneous ``[x, y, w]`` even in Cartesian
        coordinates (a center of curvature at infinity, Sec. 4.13); only a
        ``join`` or an Euler-Savary lay-off may read them (it then takes its
        homogeneous form).
    soft : bool
        Where a step has no clean answer, return ``null`` for its outputs and
        for every request that reads them, and the other requests' values
        (the curvature panel: Hain's ``G_T`` at infinity, Example 4.16, leaves
        the inflection circle drawn).  Default: the whole function returns
        ``null``.  A given input that is missing or not finite is ``null``
        either way.

    Returns
    -------
    JSFunction

    Raises
    ------
    Unsupported
        A step whose operation has no template, a number that is not finite,
        or a request that no step makes.
    """
    from graphkin.construction.ops import templates  # noqa: F401  (registers the templates)

    tol = tol or DEFAULT_TOL
    requests = tuple(dict.fromkeys(requests))
    given = set(given)
    ideal = set(ideal)
    homogeneous = bool(given) if homogeneous is None else homogeneous
    gen = JSGen(tol, homogeneous=homogeneous)
    gen.soft = soft
    inputs: list[str] = []
    need = _live(steps, set(requests))
    for step, needed in zip(steps, need):
        if not needed:
            continue
        if step.outputs and step.outputs[0] in given and not step.inputs:
            lab = step.outputs[0]
            p = gen.tmp("in")
            gen.lines.append(f"  const {p} = I[{js_string(lab)}];")
            if homogeneous or lab in ideal:
                gen.bail_unless(f"{p} && _fin({p}[0]) && _fin({p}[1]) && _fin({p}[2])")
                gen.put_rows(lab, "point", f"{p}[0]", f"{p}[1]", f"{p}[2]")
            else:
                gen.bail_unless(f"{p} && _fin({p}[0]) && _fin({p}[1])")
                gen.put_point(lab, f"{p}[0]", f"{p}[1]")
            inputs.append(lab)
            continue
        if step.op == "input":
            lab = step.outputs[0]
            if lab not in gen.vals:
                p = gen.tmp("in")
                gen.lines.append(f"  const {p} = I[{js_string(lab)}];")
                gen.bail_unless(f"_fin({p})")
                gen._new(lab, "scalar", (p,), "scalar")
                inputs.append(lab)
            continue
        ins = [gen.val(i) for i in step.inputs]
        pk = _params_key(step.params)
        # a step of given numbers only (a frame point) is never shared: its numbers are its own
        key = None if pk is None or not ins else (step.op, tuple(v.token for v in ins), pk)
        if key is not None and key in gen.cse:
            for lab, v in zip(step.outputs, gen.cse[key]):
                gen.vals[lab] = v
                if key in gen.cse_flags:
                    gen.flags[lab] = gen.cse_flags[key]
            continue
        tpl = TEMPLATES.get(step.op)
        if tpl is None:
            raise Unsupported(f"the operation {step.op!r} has no template")
        gen.owner, gen.count = (step.outputs[0] if step.outputs else step.op), 0
        gen.conds = []
        try:
            tpl(gen, step)
        except NeedGeneric as e:
            raise Unsupported(f"the operation {step.op!r} cannot be written for {e}") from e
        if soft:
            _flag(gen, step)
        gen.conds = None
        if key is not None:
            gen.cse[key] = tuple(gen.vals[o] for o in step.outputs)
            if step.outputs and step.outputs[0] in gen.flags:
                gen.cse_flags[key] = gen.flags[step.outputs[0]]
    out = []
    for lab in requests:
        got = gen.vals.get(lab)
        if got is None:
            raise Unsupported(f"no step makes {lab!r}")
        ex = got.ex[0] if got.form == "scalar" else f"[{', '.join(got.ex)}]"
        if lab in gen.flags:
            ex = f"{gen.flags[lab]} ? {ex} : null"
        out.append(f"    {js_string(lab)}: {ex},")
    fname = _js_ident(name)
    helpers = _helpers_js(tol)
    src = "".join(helpers[h] for h in sorted(gen.helpers))
    src += (f"function {fname}(I, K) {{\n" + "\n".join(gen.lines) + "\n  return {\n"
            + "\n".join(out) + "\n  };\n}\n")
    return JSFunction(src, fname, tuple(inputs), tuple(gen.slots), requests)


def _flag(gen: JSGen, step: Step) -> None:
    """Soft: the name of "this step's outputs are clean" (its conditions and its inputs')."""
    conds = list(gen.conds or [])
    for i in step.inputs:
        f = gen.flags.get(i)
        if f is not None and f not in conds:
            conds.append(f)
    if not conds:
        return
    name = conds[0] if len(conds) == 1 and conds[0] in gen.flags.values() else None
    if name is None:
        name = gen.tmp("ok")
        gen.lines.append(f"  const {name} = {' && '.join(f'({c})' for c in conds)};")
    for o in step.outputs:
        gen.flags[o] = name


def _js_ident(name: str) -> str:
    s = "".join(ch if ch.isascii() and (ch.isalnum() or ch == "_") else "_" for ch in name)
    return s if s[:1].isalpha() else f"f_{s}"
