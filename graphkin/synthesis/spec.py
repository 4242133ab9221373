"""The synthesis file: postures to guide a body through, or a function to generate.

Read strictly, like a mechanism file: an unknown key, a posture written
twice, a point that is not two numbers end with one line naming the file and
the key (format: ``docs/formats/synthesis.md``).

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 9.2-9.7, 9.11.
"""

from __future__ import annotations

import ast
import math
import operator
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.files import parse_toml, read_text
from graphkin.keys import SYNTHESIS, nearest, read_units
from graphkin.synthesis.analytic import chebyshev
from graphkin.synthesis.postures import Postures

__all__ = ["Spec", "FunctionSpec", "PathSpec", "load_spec", "loads_spec", "SCHEMA",
           "is_synthesis_file"]

SCHEMA = SYNTHESIS
"""Every key of a synthesis file (:data:`graphkin.keys.SYNTHESIS`)."""


#: How far (relative) two postures' distances between the body's two points may differ:
#: the rounding of coordinates typed to three or four figures, not a different body.
TYPED_LENGTH_REL = 5e-3


@dataclass(frozen=True)
class FunctionSpec:
    """Function generation: y = f(x) over a range, by a crank and rocker (Sec. 9.11)."""

    expression: str
    f: Callable[[np.ndarray], np.ndarray]
    x_range: tuple[float, float]
    points: int
    input_start: float
    input_span: float
    output_start: float
    output_span: float
    ground: float


@dataclass(frozen=True)
class PathSpec:
    """A coupler point through three precision points with prescribed timing (Sec. 9.12).

    ``points``: the coupler point's positions (complex); ``crank``: the crank's
    angles φ_j; ``coupler``: the coupler's rotations α_j from the first (rad);
    ``rocker_pin``: where the rocker is pinned on the coupler, as a fraction of
    the way from the crank pin A to the coupler point.
    """

    points: np.ndarray
    crank: np.ndarray
    coupler: np.ndarray
    rocker_pin: float


@dataclass(frozen=True)
class Spec:
    """A parsed synthesis file."""

    source: str
    title: str
    units: str
    postures: Postures | None
    circle_points: list[tuple[float, float]] | None
    center_points: list[tuple[float, float]] | None
    function: FunctionSpec | None
    path: PathSpec | None = None
    cognates: dict[str, complex] | None = None
    write: str = "1"
    dwell: dict[str, complex] | None = None
    dwell_span: float = math.radians(60.0)
    dwell_slider: bool = False
    """``[dwell] slider = true``: a straight stretch and a slotted link 6 (Fig. 9.44)."""
    overlay: np.ndarray | None = None
    """The overlay method (Sec. 9.8): the desired path's points (complex)."""
    closed: bool = False
    coupler: dict[str, Any] | None = None
    """Coupler-curve synthesis (Sec. 9.9): ``points`` (4 complex), ``O4``, ``O2`` (complex,
    near the bisectors), ``R``, ``r``."""
    crank_rocker: dict[str, Any] | None = None
    """A crank-rocker from two limit postures (Sec. 9.3): ``O4``, ``B1`` (complex),
    ``swing``, ``x_angle`` (rad) and ``Q``."""


_KIND = re.compile(r"^\s*\[\[?\s*(postures|function|path|cognates|dwell|overlay|coupler_curve|"
                   r"crank_rocker)\s*\]", re.MULTILINE)
_LINKS = re.compile(r"^\s*\[\s*links\s*\.", re.MULTILINE)


def is_synthesis_file(path: str | Path) -> bool:
    """Whether a file is a synthesis file (a table of its own, no ``[links.<id>]``).

    Only the text's headers are looked at (the file is parsed once, by
    whoever reads it): ``graphkin steps`` dispatches on this.
    """
    text = read_text(Path(path))
    return bool(_KIND.search(text)) and not _LINKS.search(text)


def load_spec(path: str | Path) -> Spec:
    """Read a synthesis file (``docs/formats/synthesis.md``)."""
    p = Path(path)
    return loads_spec(read_text(p), str(p))


def loads_spec(text: str, source: str = "<synthesis>") -> Spec:
    """Parse synthesis-file text (see :func:`load_spec`)."""
    return _Reader(parse_toml(text, source), source).spec()


_OPS: dict[type, Callable[..., Any]] = {
    ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul,
    ast.Div: operator.truediv, ast.Pow: operator.pow, ast.USub: operator.neg,
    ast.UAdd: operator.pos,
}
_FUNCS: dict[str, Callable[..., Any]] = {
    "sin": np.sin, "cos": np.cos, "tan": np.tan, "exp": np.exp, "log": np.log,
    "log10": np.log10, "sqrt": np.sqrt, "abs": np.abs,
}


def _compile(expr: str, source: str, key: str) -> Callable[[np.ndarray], np.ndarray]:
    """The function f of a formula of numbers, x, + − × / ** and a few functions (no eval)."""
    try:
        tree = ast.parse(expr, mode="eval")
    except SyntaxError:
        raise InputError(f"not a formula in x: {expr[:60]!r}", key=key, file=source) from None
    except (RecursionError, MemoryError):
        raise InputError(f"{expr[:60]!r}: the formula is nested too deep", key=key,
                         file=source) from None

    def ev(node: ast.AST, x: np.ndarray) -> Any:
        if isinstance(node, ast.Expression):
            return ev(node.body, x)
        if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
                and not isinstance(node.value, bool):
            return float(node.value)
        if isinstance(node, ast.Name) and node.id == "x":
            return x
        if isinstance(node, ast.Name) and node.id in ("pi", "e"):
            return math.pi if node.id == "pi" else math.e
        if isinstance(node, ast.BinOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.left, x), ev(node.right, x))
        if isinstance(node, ast.UnaryOp) and type(node.op) in _OPS:
            return _OPS[type(node.op)](ev(node.operand, x))
        if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) \
                and node.func.id in _FUNCS and len(node.args) == 1 and not node.keywords:
            return _FUNCS[node.func.id](ev(node.args[0], x))
        raise InputError(f"{expr[:60]!r}: only numbers, x, + - * / **, pi, e and "
                         f"{', '.join(_FUNCS)} may be used", key=key, file=source)

    def f(x: np.ndarray) -> np.ndarray:
        try:
            with np.errstate(all="ignore"):
                return np.asarray(ev(tree, np.asarray(x, dtype=float)), dtype=float)
        except (OverflowError, ZeroDivisionError, RecursionError, MemoryError):
            # 9**9**9 in floats, 1/0 of constants, a formula nested a thousand deep
            raise InputError(f"{expr[:60]!r} cannot be evaluated (too large, nested too "
                             "deep or dividing by zero)", key=key, file=source) from None

    f(np.array([1.5]))  # refuse what is not allowed before any use


    return f


class _Reader:
    def __init__(self, data: Mapping[str, Any], source: str) -> None:
        self.data = data
        self.source = source

    def fail(self, key: str, message: str) -> InputError:
        return InputError(message, key=key, file=self.source)

    def number(self, value: Any, key: str) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)) \
                or not math.isfinite(float(value)):
            raise self.fail(key, f"expected a finite number, not {value!r}")
        return float(value)

    def xy(self, value: Any, key: str) -> tuple[float, float]:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(key, f"a point must be two numbers [x, y], not {value!r}")
        return self.number(value[0], key), self.number(value[1], key)

    def points(self, value: Any, key: str) -> list[tuple[float, float]]:
        if not isinstance(value, list) or len(value) != 2:
            raise self.fail(key, "expected two points [[x, y], [x, y]] (one per dyad)")
        return [self.xy(v, f"{key}[{i}]") for i, v in enumerate(value)]

    def spec(self) -> Spec:
        from graphkin.keys import check_keys

        check_keys(self.data, SCHEMA, self.source)
        for k in ("body", "pivots", "function", "path", "cognates", "dwell", "crank_rocker"):
            if k in self.data and not isinstance(self.data[k], Mapping):
                raise self.fail(k, f"expected a table [{k}], not {type(self.data[k]).__name__}")
        units = read_units(self.data.get("units", "mm"), "units", self.source).get("length",
                                                                                   "mm")
        title = str(self.data.get("title", ""))
        post = self.postures() if "postures" in self.data else None
        piv = self.data.get("pivots", {})
        circ = self.points(piv["circle_points"], "pivots.circle_points") \
            if "circle_points" in piv else None
        cent = self.points(piv["center_points"], "pivots.center_points") \
            if "center_points" in piv else None
        func = self.function() if "function" in self.data else None
        path = self.path() if "path" in self.data else None
        cog, write = self.cognates() if "cognates" in self.data else (None, "1")
        dw, span = self.dwell() if "dwell" in self.data else (None, math.radians(60.0))
        ov, closed = self.overlay() if "overlay" in self.data else (None, False)
        cc = self.coupler_curve() if "coupler_curve" in self.data else None
        cr = self.crank_rocker() if "crank_rocker" in self.data else None
        kinds = [k for k, v in (("postures", post), ("function", func), ("path", path),
                                ("cognates", cog), ("dwell", dw), ("overlay", ov),
                                ("coupler_curve", cc), ("crank_rocker", cr)) if v is not None]
        if not kinds:
            raise self.fail("postures", "give [[postures]] (body guidance), [function] "
                                        "(function generation), [path] (path generation) or "
                                        "[cognates]")
        if len(kinds) > 1:
            raise self.fail(kinds[1], "give one of [[postures]], [function], [path], "
                                      "[cognates], [dwell], [overlay], [coupler_curve] or "
                                      "[crank_rocker], "
                                      f"not "
                                      f"{' and '.join(kinds)}")
        if post is not None:
            if post.n < 2 or post.n > 5:
                raise self.fail("postures", f"{post.n} postures given: two to five can be "
                                            "synthesized (Secs. 9.3-9.6)")
            if circ is not None and cent is not None and post.n != 2:
                raise self.fail("pivots", "give circle_points or center_points, not both")
            if post.n == 4 and circ is not None:
                raise self.fail("pivots.circle_points", "for four postures choose center "
                                "points (on the center-point curve); give center_points")
            post.check()
        slider = self.data["dwell"].get("slider", False) if dw is not None else False
        if not isinstance(slider, bool):
            raise self.fail("dwell.slider", f"true or false, not {slider!r}")
        return Spec(self.source, title, units, post, circ, cent, func, path, cog, write, dw,
                    span, slider, ov, closed, cc, cr)

    def fourbar(self, table: str, point: str) -> dict[str, complex]:
        f = self.data[table]
        pts = {}
        for k in ("O_A", "A", "B", "O_B", point):
            if k not in f:
                raise self.fail(f"{table}.{k}", "missing (the four-bar O_A A B O_B and its "
                                                f"coupler point {point} in one posture)")
            pts[k] = complex(*self.xy(f[k], f"{table}.{k}"))
        for k1, k2 in (("O_A", "A"), ("A", "B"), ("B", "O_B"), ("O_A", "O_B"), ("A", point),
                       ("B", point)):
            if pts[k1] == pts[k2]:
                raise self.fail(f"{table}.{k2}", f"{k1} and {k2} coincide: a link of no "
                                                 "length")
        return pts

    def dwell(self) -> tuple[dict[str, complex], float]:
        pts = self.fourbar("dwell", "C")
        span = self.number(self.data["dwell"].get("span", 60.0), "dwell.span")
        if not 5.0 <= span <= 180.0:
            raise self.fail("dwell.span", "the crank's turn of the dwell, 5° to 180°")
        return pts, math.radians(span)

    def crank_rocker(self) -> dict[str, Any]:
        f = self.data["crank_rocker"]
        for k in ("O4", "B1", "swing", "Q", "x_angle"):
            if k not in f:
                raise self.fail(f"crank_rocker.{k}", "missing (a crank-rocker from its limit "
                                "postures needs O4, B1, swing, Q and x_angle, Fig. 9.3)")
        o4 = complex(*self.xy(f["O4"], "crank_rocker.O4"))
        b1 = complex(*self.xy(f["B1"], "crank_rocker.B1"))
        if o4 == b1:
            raise self.fail("crank_rocker.B1", "O4 and B1 coincide: a rocker of no length")
        return {"O4": o4, "B1": b1, "Q": self.number(f["Q"], "crank_rocker.Q"),
                **{k: math.radians(self.number(f[k], f"crank_rocker.{k}"))
                   for k in ("swing", "x_angle")}}

    def coupler_curve(self) -> dict[str, Any]:
        f = self.data["coupler_curve"]
        for k in ("points", "O4", "O2", "R", "r"):
            if k not in f:
                raise self.fail(f"coupler_curve.{k}", "missing (coupler-curve synthesis needs "
                                "four points, O4 and O2 near their bisectors, R and r)")
        pts = f["points"]
        if not isinstance(pts, list) or len(pts) != 4:
            raise self.fail("coupler_curve.points", "expected four precision points "
                                                    "[[x, y], ...]")
        z = np.array([complex(*self.xy(v, f"coupler_curve.points[{i}]"))
                      for i, v in enumerate(pts)])
        size = float(np.max(np.abs(z - z.mean())))
        if any(abs(z[i] - z[j]) <= 1e-9 * size for i in range(4) for j in range(i)) \
                or not size > 0:
            raise self.fail("coupler_curve.points", "two precision points coincide")
        out: dict[str, Any] = {"points": z}
        for k in ("O4", "O2"):
            out[k] = complex(*self.xy(f[k], f"coupler_curve.{k}"))
        for k in ("R", "r"):
            v = self.number(f[k], f"coupler_curve.{k}")
            if not v > 0:
                raise self.fail(f"coupler_curve.{k}", f"a radius must be positive, not {v!r}")
            out[k] = v
        return out

    def overlay(self) -> tuple[np.ndarray, bool]:
        f = self.data["overlay"]
        pts = f.get("points")
        if not isinstance(pts, list) or len(pts) < 4:
            raise self.fail("overlay.points", "the desired path: at least four points "
                                              "[[x, y], ...] in order along it")
        xy = [self.xy(v, f"overlay.points[{i}]") for i, v in enumerate(pts)]
        closed = f.get("closed", False)
        if not isinstance(closed, bool):
            raise self.fail("overlay.closed", f"true or false, not {closed!r}")
        z = np.array([complex(x, y) for x, y in xy])
        if float(np.max(np.abs(z - z.mean()))) <= 1e-12 * max(float(np.max(np.abs(z))), 1e-300):
            raise self.fail("overlay.points", "the points of the path coincide")
        return z, closed

    def cognates(self) -> tuple[dict[str, complex], str]:
        f = self.data["cognates"]
        pts = self.fourbar("cognates", "P")
        write = str(f.get("write", 1))
        if write not in ("1", "2", "3"):
            raise self.fail("cognates.write", "which cognate -o writes: 1, 2 or 3")
        return pts, write

    def path(self) -> PathSpec:
        f = self.data["path"]
        for k in ("points", "crank", "coupler"):
            if k not in f:
                raise self.fail(f"path.{k}", "missing (path generation needs points, crank "
                                             "and coupler, three of each)")
        pts = f["points"]
        if not isinstance(pts, list) or len(pts) != 3:
            raise self.fail("path.points", "expected three points [[x, y], [x, y], [x, y]]")
        xy = [self.xy(v, f"path.points[{i}]") for i, v in enumerate(pts)]
        ang = {}
        for k in ("crank", "coupler"):
            v = f[k]
            if not isinstance(v, list) or len(v) != 3:
                raise self.fail(f"path.{k}", "expected three angles (degrees)")
            ang[k] = np.radians([self.number(a, f"path.{k}[{i}]") for i, a in enumerate(v)])
        if abs(ang["coupler"][0]) > 0:
            raise self.fail("path.coupler[0]", "the coupler's rotations are measured from the "
                                               "first precision point: the first is 0")
        z = np.array([complex(*p) for p in xy])
        if min(abs(z[0] - z[1]), abs(z[1] - z[2]), abs(z[0] - z[2])) == 0.0:
            raise self.fail("path.points", "two precision points coincide")
        pin = self.number(f.get("rocker_pin", 0.5), "path.rocker_pin")
        if not 0.0 < pin < 1.0:
            raise self.fail("path.rocker_pin", "a fraction of the coupler between 0 and 1")
        return PathSpec(z, ang["crank"], ang["coupler"], pin)

    def postures(self) -> Postures:
        entries = self.data["postures"]
        if not isinstance(entries, list) or not all(isinstance(e, Mapping) for e in entries):
            raise self.fail("postures", "write each posture as a [[postures]] table")
        body = self.data.get("body", {})
        names = body.get("points", ["D", "E"])
        if not (isinstance(names, list) and len(names) == 2
                and all(isinstance(n, str) and n.isidentifier() for n in names)
                and names[0] != names[1]):
            raise self.fail("body.points", "expected two different point names, "
                                           "e.g. [\"D\", \"E\"]")
        pts: list[tuple[float, float]] = []
        angs: list[float] = []
        seconds: list[float | None] = []
        for i, e in enumerate(entries):
            key = f"postures[{i}]"
            valid = ["point", "angle", *names]
            for k in e:
                if k not in valid:
                    guess = nearest(str(k), valid)
                    hint = f" (did you mean {guess!r}?)" if guess else \
                        f" (valid keys: {', '.join(valid)})"
                    raise self.fail(f"{key}.{k}", f"unknown key {k!r}{hint}")
            if "point" in e or "angle" in e:
                if "point" not in e or "angle" not in e:
                    raise self.fail(key, "a posture is a point and an angle, or the body's "
                                         f"two points {names[0]} and {names[1]}")
                p = self.xy(e["point"], f"{key}.point")
                ang = math.radians(self.number(e["angle"], f"{key}.angle"))
                pts.append(p)
                angs.append(ang)
                seconds.append(None)
            elif names[0] in e and names[1] in e:
                p = self.xy(e[names[0]], f"{key}.{names[0]}")
                q = self.xy(e[names[1]], f"{key}.{names[1]}")
                d = math.hypot(q[0] - p[0], q[1] - p[1])
                if d == 0.0:
                    raise self.fail(f"{key}.{names[1]}", f"{names[0]} and {names[1]} coincide")
                pts.append(p)
                angs.append(math.atan2(q[1] - p[1], q[0] - p[0]))
                seconds.append(d)
            else:
                raise self.fail(key, "a posture is a point and an angle, or the body's two "
                                     f"points {names[0]} and {names[1]}")
        lengths = [s for s in seconds if s is not None]
        if lengths and len(lengths) != len(seconds):
            raise self.fail("postures", "write every posture the same way (point and angle, "
                                        "or two points)")
        if lengths:
            for i, s in enumerate(lengths):
                # the body's angle is the direction of its two points; their distance only
                # tells a slip from coordinates typed to three or four figures, as the book
                # prints them (1.8, 0.87 for a length of 2: 0.04 % off)
                if abs(s - lengths[0]) > TYPED_LENGTH_REL * max(lengths[0], 1e-300):
                    raise self.fail(f"postures[{i}].{names[1]}",
                                    f"{names[0]}{names[1]} is {s:g} here but {lengths[0]:g} in "
                                    "posture 1: a rigid body keeps its length")
            second = (lengths[0], 0.0)
        else:
            spread = np.ptp(np.array(pts), axis=0).max() if len(pts) > 1 else 1.0
            second = (float(spread) / 2 or 1.0, 0.0)
        return Postures(np.array(pts, dtype=float), np.array(angs, dtype=float),
                        (names[0], names[1]), second, self.source, "postures",
                        second_given=bool(lengths))

    def function(self) -> FunctionSpec:
        f = self.data["function"]
        for k in ("expression", "range"):
            if k not in f:
                raise self.fail(f"function.{k}", "missing (function generation needs "
                                                 "expression and range)")
        expr = f["expression"]
        if not isinstance(expr, str):
            raise self.fail("function.expression", "expected a formula in x, e.g. \"1/x\"")
        fun = _compile(expr, self.source, "function.expression")
        rng = f["range"]
        if not isinstance(rng, list) or len(rng) != 2:
            raise self.fail("function.range", "expected [x0, x1]")
        x0, x1 = self.number(rng[0], "function.range"), self.number(rng[1], "function.range")
        if not x1 > x0:
            raise self.fail("function.range", "x1 must be greater than x0")
        n = f.get("points", 3)
        if n != 3:
            raise self.fail("function.points", "Freudenstein's equation takes three precision "
                                               "points (Sec. 9.11)")

        def pair(name: str, default: tuple[float, float]) -> tuple[float, float]:
            v = f.get(name, {"start": default[0], "span": default[1]})
            if not isinstance(v, Mapping) or set(v) - {"start", "span"}:
                raise self.fail(f"function.{name}", "expected { start = deg, span = deg }")
            return (math.radians(self.number(v.get("start", default[0]), f"function.{name}")),
                    math.radians(self.number(v.get("span", default[1]), f"function.{name}")))

        i0, i1 = pair("input", (30.0, 90.0))
        o0, o1 = pair("output", (240.0, 90.0))
        with np.errstate(all="ignore"):  # a constant ("3") is one number: both ends
            ys = np.broadcast_to(fun(np.array([x0, x1])), (2,))
        if not np.all(np.isfinite(ys)) or ys[0] == ys[1]:
            raise self.fail("function.expression", f"{expr!r} is not finite and different at "
                                                   "the ends of the range")
        # inside the range too: at the precision points (Chebyshev, Eq. 9.22) and where
        # the structural error is sampled, so a pole or a log(x - 1) is named, not blamed
        # on Freudenstein's equation ("r3² < 0")
        inside = np.concatenate([chebyshev(x0, x1, 3), np.linspace(x0, x1, 201)])
        with np.errstate(all="ignore"):
            bad = ~np.isfinite(np.broadcast_to(fun(inside), inside.shape))
        if np.any(bad):
            raise self.fail("function.expression", f"{expr!r} is not finite at x = "
                                                   f"{inside[np.argmax(bad)]:.6g}, inside the "
                                                   "range")
        ground = self.number(f.get("ground", 1.0), "function.ground")
        if ground <= 0:
            raise self.fail("function.ground", "the ground link's length must be positive")
        return FunctionSpec(expr, fun, (x0, x1), 3, i0, i1, o0, o1, ground)
