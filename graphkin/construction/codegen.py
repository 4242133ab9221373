"""A construction written out as one Python function: its steps as inline numpy expressions.

:meth:`Construction.evaluate <graphkin.construction.Construction.evaluate>`
replays a construction through a list of compiled kernels, one call per step,
each reading and writing a shared runtime.  For a short batch (a sweep of 36
postures) that dispatch, not the arithmetic, is the cost.  :func:`generate`
removes it: it walks the recorded steps once and writes the source of one
function in which every step is a few numpy expressions on local variables
(a point is its two Cartesian rows, a line or circle its three, a vector its
two, an angle one array), then compiles it with :func:`compile`.  Nothing is
written by hand per mechanism: each operation has a *template*
(:data:`TEMPLATES`, :mod:`graphkin.construction.ops.templates`) that writes
the arithmetic of its compiled kernel; an operation without one is called
through its general function (:data:`~graphkin.construction.ops.OPS`), so a
construction with any operation can be generated.

What the generated function computes
------------------------------------
The *clean* case only: every given input finite, every pair of arcs meeting
with room to spare, no two points of a line coincident, no two lines
parallel, no division by a vanishing length, every value finite.  It checks
each of those with one reduction per step and returns ``None`` as soon as one
fails; the caller then runs the exact replay (:meth:`Construction.evaluate`),
which marks the entries that fail.  When it returns, every posture is
constructed (``valid`` everywhere) and its values are those of the compiled
kernels up to rounding, which are those of :meth:`Construction.replay`.

Also: steps whose inputs are all constant are evaluated once, when the
function is written (as :meth:`Construction.evaluate` folds them); a step
repeated on the same values (the acceleration polygon redraws the velocity
polygon's lines) is computed once; a step whose outputs nothing reads is
dropped unless it can fail.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.,
Sec. 2.8 (the posture constructions, cases 1-4), Secs. 3.4-3.6 and 4.2-4.6
(the polygons) -- the steps that are written out here.
"""

from __future__ import annotations

import functools
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field
from types import CodeType
from typing import Any

import numpy as np

from graphkin.construction.ops import OPS
from graphkin.construction.ops.runtime import (
    KERNELS,
    ORIGINATING,
    _all_finite,
    tangent_cc,
    tangent_lc,
)
from graphkin.construction.step import Step
from graphkin.geometry import ops as g
from graphkin.tolerance import DEFAULT_TOL, Tolerance

__all__ = ["Generated", "Unsupported", "generate", "TEMPLATES", "template", "Gen"]


class Unsupported(Exception):
    """The construction cannot be written out (an input not given, a constant not finite)."""


class NeedGeneric(Exception):
    """A template cannot use an input's form: the step is called through its general function."""


Template = Callable[["Gen", Step], None]

def _select(cond: Any, a: Any, b: Any, *, tol: Tolerance) -> Any:
    """``a`` where ``cond`` holds, else ``b``, entry by entry (a cam program's segment)."""
    return np.where(cond, a, b)


def _floor(x: Any, *, tol: Tolerance) -> Any:
    """The largest whole number not above ``x`` (a cam angle taken into one turn)."""
    return np.floor(x)


HELPERS: dict[str, Callable[..., Any]] = {"tangent_cc": tangent_cc, "tangent_lc": tangent_lc,
                                          "select": _select, "floor": _floor}
"""Functions a template may call by name (:meth:`Gen.helper`); the JavaScript writer has its own."""

TEMPLATES: dict[str, Template] = {}
"""Operation -> the function that writes its arithmetic (see :class:`Gen`)."""

PYTHON_GENERIC: set[str] = set()
"""Operations whose template only the JavaScript writer uses: Python calls the general function."""


def template(name: str, python: bool = True) -> Callable[[Template], Template]:
    """Register the template of operation ``name`` (one table for both writers).

    With ``python=False`` the Python writer keeps calling the operation's
    general function (which also handles the unclean postures) and only the
    JavaScript writer (:mod:`graphkin.construction.jsgen`), which has no
    general functions, writes the template.
    """

    def deco(f: Template) -> Template:
        TEMPLATES[name] = f
        if not python:
            PYTHON_GENERIC.add(name)
        return f

    return deco


def _num(expr: str) -> float | None:
    """The value of a literal expression (``1.5``, ``(-1.5)``: see :func:`lit`), else None."""
    if not (expr[:1].isdigit() or (expr[:2] == "(-" and expr[2:3].isdigit())):
        return None
    try:
        return float(expr.strip("()"))
    except ValueError:
        return None


def lit(v: float) -> str:
    """A float as an exact literal."""
    v = float(v)
    return repr(v) if v >= 0 or v != v else f"({v!r})"


@dataclass
class _Val:
    """How a label's value is held in the generated code.

    ``form`` is ``point`` (``ex`` = its x and y rows, ``w == 1``), ``rows``
    (the rows of a line, circle or vector), ``scalar`` or ``opaque`` (``ex``
    = one homogeneous array, as the general function returned it).
    """

    form: str
    ex: tuple[str, ...]
    kind: str
    token: int
    const: Any = None
    trig: Any = None
    trig_off: dict[float, tuple[str, str]] = field(default_factory=dict)
    homog: str | None = None


@dataclass
class Generated:
    """A construction compiled into one function.

    Attributes
    ----------
    fn : callable
        ``fn(*varying)`` -> a tuple, one entry per request, or ``None`` when
        some posture is not clean (the caller then replays the construction).
    varying : tuple of str
        The inputs the function takes, in order (1-D arrays of one length).
    requests : tuple of (label, part)
    constant : tuple of bool
        Per request: its value does not depend on the varying inputs (a float
        or a small array; the caller broadcasts it).
    source : str
        The generated source (for reading and debugging).
    """

    fn: Callable[..., tuple[Any, ...] | None]
    varying: tuple[str, ...]
    requests: tuple[tuple[str, str], ...]
    constant: tuple[bool, ...]
    source: str

    def values(self, *varying: Any) -> dict[str, Any] | None:
        """Label -> homogeneous value, for requests of part ``value``; None when not clean."""
        out = self.fn(*varying)
        if out is None:
            return None
        return {lab: v for (lab, part), v in zip(self.requests, out) if part == "value"}


class Gen:
    """The state of one generation: the code written so far and each label's form.

    Templates read their inputs with :meth:`pt` (a point's x and y),
    :meth:`rows` (a line, circle or vector; a point as x, y, w),
    :meth:`scalar` and :meth:`cs` (an angle's cosine and sine), write code with
    :meth:`let` and :meth:`bail_unless`, and define their outputs with
    :meth:`put_point`, :meth:`put_rows` and :meth:`put_scalar`.  A template
    that cannot use an input's form raises :class:`NeedGeneric` (what it wrote
    is taken back, and the step is called through its general function).
    """

    def __init__(self, tol: Tolerance) -> None:
        self.tol = tol
        self.lines: list[str] = []
        self.ns: dict[str, Any] = {"np": np, "_sqrt": np.sqrt, "_atan2": np.arctan2,
                                   "_cos": np.cos, "_sin": np.sin, "_min": np.minimum.reduce,
                                   "_max": np.maximum.reduce, "_abs": np.abs,
                                   "_maximum": np.maximum, "_fin": _all_finite,
                                   "_xy": g.xy, "_hstack": _hstack}
        self.vals: dict[str, _Val] = {}
        self.n = 0
        self.cse: dict[tuple[Any, ...], tuple[_Val, ...]] = {}
        self.memo: dict[str, str] = {}

    # ---- names ---------------------------------------------------------
    def tmp(self, hint: str = "t") -> str:
        """A fresh local name."""
        self.n += 1
        return f"_{hint}{self.n}"

    def bind(self, value: Any, hint: str = "k") -> str:
        """A name for a Python object in the function's namespace."""
        name = self.tmp(hint)
        self.ns[name] = value
        return name

    def num(self, v: Any) -> str:
        """A constant as an expression: a literal for a number, a bound name for an array."""
        a = np.asarray(v, dtype=float)
        if a.ndim == 0:
            return lit(float(a))
        return self.bind(a)

    def emit(self, line: str) -> None:
        """Write one line of the function's body."""
        self.lines.append("    " + line)

    def let(self, expr: str, hint: str = "t") -> str:
        """``expr`` as a local name (a name or literal is returned as it is)."""
        if expr.isidentifier() or _num(expr) is not None:
            return expr
        # every name is assigned once: the same expression is the same value
        name = self.memo.get(expr)
        if name is None:
            name = self.memo[expr] = self.tmp(hint)
            self.emit(f"{name} = {expr}")
        return name

    def bail_unless(self, cond: str) -> None:
        """Return None (not clean: replay instead) unless ``cond`` holds (written once)."""
        line = f"if not ({cond}): return None"
        if line not in self.memo:
            self.memo[line] = ""
            self.emit(line)

    # ---- arithmetic with literals folded ----------------------------------
    # Every value is finite in the clean case, so x * 0 = 0, x + 0 = x and 0 - x = -x
    # (up to the sign of a zero).
    def add(self, a: str, b: str) -> str:
        """``a + b`` as a name; a literal zero drops out."""
        x, y = _num(a), _num(b)
        if x is not None and y is not None:
            return lit(x + y)
        if y == 0.0:
            return a
        if x == 0.0:
            return b
        a, b = sorted((a, b))  # a + b is b + a, exactly: one name for both
        return self.let(f"{a} + {b}")

    def sub(self, a: str, b: str) -> str:
        """``a - b`` as a name; a literal zero is not subtracted."""
        x, y = _num(a), _num(b)
        if x is not None and y is not None:
            return lit(x - y)
        if y == 0.0:
            return a
        if x == 0.0:
            return self.neg(b)
        return self.let(f"{a} - {b}")

    def mul(self, a: str, b: str) -> str:
        """``a * b`` as a name; a literal zero makes zero, a literal one drops out."""
        x, y = _num(a), _num(b)
        if x is not None and y is not None:
            return lit(x * y)
        if x == 0.0 or y == 0.0:
            return "0.0"
        if y == 1.0:
            return a
        if x == 1.0:
            return b
        a, b = sorted((a, b))
        return self.let(f"{a} * {b}")

    def neg(self, a: str) -> str:
        """``-a`` as a name (a literal is negated now)."""
        x = _num(a)
        return lit(-x) if x is not None else self.let(f"-{a}")

    # ---- the few forms that differ between the languages (see jsgen.py) -----
    def where(self, cond: str, a: str, b: str) -> str:
        """``a`` where ``cond`` holds for every entry, else ``b`` (a conditional expression)."""
        return f"{a} if {cond} else {b}"

    def every(self, cond: str) -> str:
        """``cond`` (an array of truth values) holds for every entry."""
        return f"({cond}).all()"

    def helper(self, name: str) -> str:
        """The name of a shared helper function (:data:`HELPERS`), with the tolerance bound."""
        return self.bind(functools.partial(HELPERS[name], tol=self.tol), name.split("_")[0])

    def side(self, step: Step, left: bool) -> bool | str:
        """The branch of a two-way step: here the recorded one (JavaScript: a sign in ``K``)."""
        return left

    @staticmethod
    def is_zero(a: str) -> bool:
        """True for the literal zero."""
        return _num(a) == 0.0

    # ---- inputs --------------------------------------------------------
    def val(self, label: str) -> _Val:
        """How ``label`` is held (it must be made or given before)."""
        v = self.vals.get(label)
        if v is None:
            raise Unsupported(f"{label!r} is read before it is made or given")
        return v

    def pt(self, label: str) -> tuple[str, str]:
        """A point's x and y rows (``w == 1``); NeedGeneric for a general function's point."""
        v = self.val(label)
        if v.form == "point":
            return v.ex[0], v.ex[1]
        raise NeedGeneric(label)

    def rows(self, label: str) -> tuple[str, ...]:
        """The rows of a line, circle or vector; a point as ``x, y, w``."""
        v = self.val(label)
        if v.form == "point":
            return (v.ex[0], v.ex[1], "1.0")
        if v.form == "rows":
            return v.ex
        if v.form == "opaque" and v.kind in ("line", "circle", "vector", "point"):
            # the general function's value: its rows (finite, checked when it was made)
            k = 2 if v.kind == "vector" else 3
            return tuple(self.let(f"{v.ex[0]}[..., {i}]", "r") for i in range(k))
        raise NeedGeneric(label)

    def scalar(self, label: str) -> str:
        """A scalar (an angle, a rate)."""
        v = self.val(label)
        if v.form != "scalar":
            raise NeedGeneric(label)
        return v.ex[0]

    def cs(self, label: str, offset: float = 0.0) -> tuple[str, str]:
        """The cosine and sine of an angle plus a constant offset, written once."""
        v = self.val(label)
        t = self.scalar(label)
        if v.const is not None:
            a = np.asarray(v.const, dtype=float) + offset
            return self.num(np.cos(a)), self.num(np.sin(a))
        if offset == 0.0:
            if callable(v.trig):
                v.trig = v.trig()
            if v.trig is None:
                v.trig = (self.let(f"_cos({t})", "c"), self.let(f"_sin({t})", "s"))
            return v.trig
        hit = v.trig_off.get(offset)
        if hit is None:
            u = self.let(f"{t} + {lit(offset)}")
            hit = v.trig_off[offset] = (self.let(f"_cos({u})", "c"), self.let(f"_sin({u})", "s"))
        return hit

    def homog(self, label: str) -> str:
        """The label's value as one homogeneous array (as the general functions take it)."""
        v = self.val(label)
        if v.homog is not None:
            return v.homog
        if v.const is not None:
            v.homog = self.bind(np.asarray(v.const, dtype=float), "h")
        elif v.form == "opaque":
            v.homog = v.ex[0]
        elif v.form == "scalar":
            v.homog = v.ex[0]
        else:
            rows = v.ex + (("1.0",) if v.form == "point" else ())
            v.homog = self.let(f"_hstack({', '.join(rows)})", "h")
        return v.homog

    # ---- outputs -------------------------------------------------------
    def _new(self, label: str, form: str, ex: tuple[str, ...], kind: str, **kw: Any) -> _Val:
        self.n += 1
        v = _Val(form, ex, kind, self.n, **kw)
        self.vals[label] = v
        return v

    def put_point(self, label: str, x: str, y: str) -> None:
        """Define a point by its Cartesian rows."""
        self._new(label, "point", (self.let(x, "x"), self.let(y, "y")), "point")

    def put_rows(self, label: str, kind: str, *rows: str) -> None:
        """Define a line or circle (three rows) or a vector (two)."""
        self._new(label, "rows", tuple(self.let(r, "r") for r in rows), kind)

    def put_scalar(self, label: str, expr: str, trig: Any = None) -> None:
        """Define a scalar; ``trig`` gives its cosine and sine (or writes them when asked)."""
        self._new(label, "scalar", (self.let(expr, "a"),), "scalar", trig=trig)

    def put_const(self, label: str, value: Any, kind: str) -> None:
        """A constant value (folded when written): literals for one posture's numbers."""
        a = np.asarray(value, dtype=float)
        if not bool(np.isfinite(a).all()):
            raise Unsupported(f"the constant {label!r} is not finite")
        if kind == "scalar":
            self._new(label, "scalar", (self.num(a),), kind, const=a)
        elif kind == "point" and a.shape[-1:] == (3,) and bool(np.all(a[..., 2] == 1.0)):
            self._new(label, "point", (self.num(a[..., 0]), self.num(a[..., 1])), kind, const=a)
        elif kind in ("line", "circle", "vector") and a.ndim >= 1:
            self._new(label, "rows", tuple(self.num(a[..., i]) for i in range(a.shape[-1])),
                      kind, const=a)
        else:
            self._new(label, "opaque", (self.bind(a, "h"),), kind, const=a)

    # ---- a step through its general function -------------------------------
    def generic(self, step: Step) -> None:
        """Call the step's general function on homogeneous values; check what it returns."""
        fn = self.bind(functools.partial(OPS[step.op], tol=self.tol, **step.params), "op")
        args = ", ".join(self.homog(i) for i in step.inputs)
        outs = [self.tmp("o") for _ in step.outputs]
        self.emit(f"{', '.join(outs)}, = {fn}({args})")
        for lab, o in zip(step.outputs, outs):
            # the plan checks every output of a step without a kernel: not finite, replay
            self.bail_unless(f"_fin({o})")
            self._new(lab, "opaque", (o,), step.kind)


def _hstack(*rows: Any) -> np.ndarray:
    """Rows (arrays or numbers) stacked along a new last axis, broadcast."""
    return np.stack(np.broadcast_arrays(*[np.asarray(r, dtype=float) for r in rows]), axis=-1)


def _params_key(params: Mapping[str, Any]) -> tuple[Any, ...] | None:
    """A hashable form of a step's constants, or None when one is an array (no sharing)."""
    out = []
    for k in sorted(params):
        v = params[k]
        if isinstance(v, np.ndarray):
            if v.size > 8:
                return None
            v = ("a", v.shape, tuple(v.ravel().tolist()))
        try:
            hash(v)
        except TypeError:
            return None
        out.append((k, v))
    return tuple(out)


def _live(steps: Sequence[Step], wanted: set[str]) -> list[bool]:
    """Which steps must be written: those read for the wanted labels, and those that can fail."""
    live = set(wanted)
    need = [False] * len(steps)
    for k in range(len(steps) - 1, -1, -1):
        s = steps[k]
        if s.op == "input":
            need[k] = True
            live.difference_update(s.outputs)
            continue
        # a step with no compiled kernel is checked by the replay wherever it runs (an image
        # of a link whose two points coincide): its template's checks are kept too
        fails = (s.op in ORIGINATING or s.op not in TEMPLATES or s.op in PYTHON_GENERIC
                 or (s.op not in KERNELS and bool(s.inputs)))
        if fails or not live.isdisjoint(s.outputs):
            need[k] = True
            live.difference_update(s.outputs)
            live.update(s.inputs)
    return need


def generate(steps: Sequence[Step], *, varying: Sequence[str],
             constants: Mapping[str, Any] | None = None,
             requests: Iterable[tuple[str, str]], tol: Tolerance | None = None,
             name: str = "construction") -> Generated:
    """Write the steps out as one function of the ``varying`` inputs.

    Parameters
    ----------
    steps : sequence of Step
        The construction (:attr:`Construction.steps`).
    varying : sequence of str
        Inputs given per call, as 1-D arrays of one length (a sweep's drive).
    constants : mapping, optional
        Inputs fixed when the function is written (held drives, given rates).
    requests : iterable of (label, part)
        What the function returns, in order: ``part`` is ``"x"`` or ``"y"``
        (a point's Cartesian coordinate, a vector's or circle's first or second
        row), or ``"value"`` (a scalar, or the homogeneous value).
    tol : Tolerance, optional

    Returns
    -------
    Generated

    Raises
    ------
    Unsupported
        An input that is neither varying nor a constant, a request of a label
        that no step makes, or a constant that is not finite.
    """
    from graphkin.construction.ops import templates  # noqa: F401  (registers the templates)

    tol = tol or DEFAULT_TOL
    constants = dict(constants or {})
    requests = tuple(requests)
    gen = Gen(tol)
    params = []
    for k, lab in enumerate(varying):
        p = f"_in{k}"
        params.append(p)
        gen._new(lab, "scalar", (p,), "scalar")
        # a non-finite input: the replay marks it
        gen.bail_unless(f"_fin({p})")
    for lab, v in constants.items():
        if lab not in varying:
            gen.put_const(lab, v, "scalar" if np.ndim(v) == 0 else "point")
    made = set(varying) | set(constants)
    need = _live(steps, {lab for lab, _ in requests})
    for step, needed in zip(steps, need):
        if not needed:
            continue
        if step.op == "input":
            if step.outputs[0] not in made:
                raise Unsupported(f"the input {step.outputs[0]!r} is not given")
            continue
        for i in step.inputs:
            gen.val(i)
        made.update(step.outputs)
        ins = [gen.vals[i] for i in step.inputs]
        if all(v.const is not None for v in ins):
            _fold(gen, step, [v.const for v in ins])
            continue
        pk = _params_key(step.params)
        key = None if pk is None else (step.op, tuple(v.token for v in ins), pk)
        if key is not None and key in gen.cse:
            for lab, v in zip(step.outputs, gen.cse[key]):
                gen.vals[lab] = v
            continue
        tpl = None if step.op in PYTHON_GENERIC else TEMPLATES.get(step.op)
        done = False
        if tpl is not None:
            mark = len(gen.lines)
            memo = dict(gen.memo)
            saved = [(v, v.trig, dict(v.trig_off), v.homog) for v in ins]
            try:
                tpl(gen, step)
                done = True
            except NeedGeneric:
                # what the template wrote is taken back
                del gen.lines[mark:]
                gen.memo = memo
                for v, trig, off, homog in saved:
                    v.trig, v.trig_off, v.homog = trig, off, homog
        if not done:
            gen.generic(step)
        if key is not None:
            gen.cse[key] = tuple(gen.vals[o] for o in step.outputs)
    outs: list[str] = []
    constant: list[bool] = []
    for lab, part in requests:
        v = gen.vals.get(lab)
        if v is None:
            raise Unsupported(f"no step makes {lab!r}")
        constant.append(v.const is not None)
        outs.append(_request(gen, v, lab, part))
    ret = f"return ({', '.join(outs)},)"
    body = "\n".join(_release(gen.lines, ret))
    # the function's name and its file name are graphkin's own: no text of the user's (a
    # title, a point's name) is ever written into the source (issue 25)
    fname = _ident(name)
    src = f"def {fname}({', '.join(params)}):\n{body}\n    {ret}\n"
    code = _CODE.get(src)
    if code is None:
        if len(_CODE) >= 64:
            _CODE.clear()
        code = _CODE[src] = compile(src, f"<graphkin: {fname}>", "exec")
    ns = gen.ns
    exec(code, ns)
    fn = ns[fname]
    return Generated(fn, tuple(varying), requests, tuple(constant), src)


_NAME = re.compile(r"\b_[a-z]+\d+\b")
_ASSIGNED = re.compile(r"^\s*((?:_[a-z]+\d+,?\s*)+)=")


def _release(lines: list[str], ret: str) -> list[str]:
    """The lines with ``del`` after the last use of each local that is not returned.

    A long block's intermediates are let go as soon as they are used, so the
    next ones reuse the memory while it is still in the cache.
    """
    local: set[str] = set()
    last: dict[str, int] = {}
    for k, line in enumerate(lines):
        m = _ASSIGNED.match(line)
        if m:
            local.update(_NAME.findall(m.group(1)))
        for name in _NAME.findall(line):
            last[name] = k
    kept = set(_NAME.findall(ret))
    dead: dict[int, list[str]] = {}
    for name, k in last.items():
        if name in local and name not in kept:
            dead.setdefault(k, []).append(name)
    out = []
    for k, line in enumerate(lines):
        out.append(line)
        if k in dead:
            out.append(f"    del {', '.join(sorted(dead[k]))}")
    return out


_CODE: dict[str, CodeType] = {}
"""Compiled sources (the same constructions with other constants of the same shapes)."""


def _request(gen: Gen, v: _Val, lab: str, part: str) -> str:
    if part == "value":
        return gen.homog(lab)
    comp = {"x": 0, "y": 1}[part]
    if v.form in ("point", "rows"):
        return v.ex[comp]
    if v.form == "opaque" and v.kind == "point":
        q = gen.let(f"_xy({v.ex[0]})", "q")
        return f"{q}[..., {comp}]"
    if v.form == "opaque":
        return f"{v.ex[0]}[..., {comp}]"
    raise Unsupported(f"{lab!r} has no {part}")


def _ident(name: str) -> str:
    """An ASCII identifier from ``name`` (letters, digits and ``_`` only; never a keyword).

    ``str.isalnum`` is not enough: ``²`` and ``½`` are alphanumeric but not valid in
    an identifier, and a ligature is rewritten by the parser (NFKC).
    """
    s = "".join(ch if (ch.isascii() and ch.isalnum()) else "_" for ch in name)[:40]
    return f"_gk_{s}"


def _fold(gen: Gen, step: Step, args: list[Any]) -> None:
    """A step whose inputs are all constant, evaluated now (as the compiled plan folds it)."""
    with np.errstate(invalid="ignore", divide="ignore", over="ignore"):
        outs = OPS[step.op](*args, tol=gen.tol, **step.params)
    for lab, val in zip(step.outputs, outs):
        gen.put_const(lab, val, step.kind)
