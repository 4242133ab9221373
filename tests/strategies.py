"""Hypothesis strategies: random valid mechanisms whose true posture is known exactly.

Every strategy first chooses a posture *in the world* (points, line
directions, link angles), then writes each link's points in a random local
frame of that link (so links are not all aligned with x), as a mechanism-file
dict for :func:`graphkin.mechanisms.from_dict`.  The generating posture is
therefore the exact answer: ``truth[link] = (x, y, θ)``, the world position
of the link's local origin and the direction of its own x axis.

Near-singular postures are avoided by construction, not by luck: every dyad
is built with its transmission angle between 25° and 155°, every point on a
line makes at least ~20° with the perpendicular to its line of motion, and so
on (see each strategy).  The postures are also kinematically generic: no
link momentarily at rest, no two links turning together (no instant center
at infinity but those of sliders), no moving point momentarily at rest
(checked with the velocity equations solved dyad by dyad, which also give
``omega``, the true angular velocities).  The assembly hints are the true
world positions of the moving points, so a solver that takes the nearer
branch finds the truth.

Use::

    from strategies import mechanisms   # pyproject: pythonpath = ["tests"]
    @given(mechanisms())
    def test_x(rm): mech = rm.mechanism(); ...
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from hypothesis import HealthCheck, assume, settings
from hypothesis import strategies as st

__all__ = [
    "RandomMechanism",
    "fourbars",
    "slider_cranks",
    "inverted_slider_cranks",
    "slotted",
    "double_sliders",
    "six_bars",
    "five_bars",
    "mechanisms",
]

XY = tuple[float, float]
Pose = tuple[float, float, float]

# a transmission angle between these (degrees) keeps every dyad well away from its toggle
_MU_MIN, _MU_MAX = 25.0, 155.0
# a line of motion makes at most this angle (degrees) with the direction that moves along it
_LINE_MAX = 65.0
# relative angular velocities and point speeds at least this fraction of the fastest
_GENERIC = 0.03


@dataclass(frozen=True)
class RandomMechanism:
    """A random mechanism and the posture it was generated from.

    Attributes
    ----------
    kind : str
        Which family (``"fourbar"``, ``"slider-crank"``, ``"six-bar watt2"``, ...).
    data : dict
        The mechanism file as parsed TOML (for ``graphkin.mechanisms.from_dict``).
    truth : dict
        Moving link id -> ``(x, y, θ)``: world position of the link's local
        origin and the angle of its x axis (rad, in (-π, π]).
    omega : dict
        Moving link id -> its true angular velocity (rad/s) at the rates the
        file gives, from the velocity equations solved dyad by dyad (Sec. 3.9);
        empty when the file gives no rates.
    """

    kind: str
    data: dict[str, Any] = field(hash=False)
    truth: dict[str, Pose] = field(hash=False)
    omega: dict[str, float] = field(default_factory=dict, hash=False)

    def mechanism(self) -> Any:
        """The parsed :class:`~graphkin.mechanisms.Mechanism`."""
        from graphkin.mechanisms import from_dict

        return from_dict(self.data, source=f"<random {self.kind}>")

    def world_points(self) -> dict[str, XY]:
        """True world position of every named point."""
        out: dict[str, XY] = {}
        for lid, pts in self.data["links"].items():
            pose = self.truth.get(str(lid), (0.0, 0.0, 0.0))
            for name, p in pts.items():
                out.setdefault(name, _to_world(pose, (p[0], p[1])))
        return out

    def scale(self) -> float:
        """Size of the mechanism: the largest coordinate in the file (as ``Mechanism.scale``)."""
        xs = [1.0]
        for pts in self.data["links"].values():
            for p in pts.values():
                xs.extend((abs(p[0]), abs(p[1])))
        return max(xs)


# ---------------------------------------------------------------------------
# small plane geometry (independent of graphkin)
# ---------------------------------------------------------------------------


def _e(t: float) -> XY:
    return (math.cos(t), math.sin(t))


def _add(p: XY, q: XY, k: float = 1.0) -> XY:
    return (p[0] + k * q[0], p[1] + k * q[1])


def _sub(p: XY, q: XY) -> XY:
    return (p[0] - q[0], p[1] - q[1])


def _dir(v: XY) -> float:
    return math.atan2(v[1], v[0])


def _dot(p: XY, q: XY) -> float:
    return p[0] * q[0] + p[1] * q[1]


def _cross(p: XY, q: XY) -> float:
    return p[0] * q[1] - p[1] * q[0]


def _norm(v: XY) -> float:
    return math.hypot(v[0], v[1])


def _wrap(a: float) -> float:
    w = math.remainder(a, 2.0 * math.pi)
    return math.pi if w == -math.pi else w


def _to_local(pose: Pose, p: XY) -> XY:
    x, y, t = pose
    c, s = math.cos(t), math.sin(t)
    dx, dy = p[0] - x, p[1] - y
    return (c * dx + s * dy, -s * dx + c * dy)


def _to_world(pose: Pose, p: XY) -> XY:
    x, y, t = pose
    c, s = math.cos(t), math.sin(t)
    return (x + c * p[0] - s * p[1], y + s * p[0] + c * p[1])


# ---------------------------------------------------------------------------
# the builder: a posture in the world, turned into a mechanism file at the end
# ---------------------------------------------------------------------------


class _Build:
    """Collects world geometry, then writes links in random local frames."""

    def __init__(self, draw: Callable[[st.SearchStrategy[Any]], Any], kind: str,
                 with_rates: bool) -> None:
        self.draw = draw
        self.kind = kind
        self.with_rates = with_rates
        self.size = draw(st.sampled_from([1.0, 10.0, 100.0])) * self.f(0.5, 5.0)
        self.unit = draw(st.sampled_from(["mm", "in", "cm", "ft"]))
        self.bodies: dict[str, dict[str, XY]] = {"1": {}}
        self.angles: dict[str, float] = {}  # links whose angle the construction fixes
        self.deferred: list[Callable[[dict[str, Pose]], None]] = []
        self.sliders: list[dict[str, Any]] = []
        self.slots: list[dict[str, Any]] = []
        self.drives: list[dict[str, Any]] = []
        self.rates: dict[str, Any] | None = None
        self.no_hint: set[str] = set()
        self.rate_of: dict[str, float] = {}  # drive link -> its drawn ω or slider speed
        self.omegas: dict[str, float] = {}
        self.n_lines = 0

    # -- draws --
    def f(self, lo: float, hi: float) -> float:
        return float(self.draw(st.floats(lo, hi, allow_nan=False, allow_infinity=False)))

    def angle(self) -> float:
        return self.f(-math.pi, math.pi)

    def sign(self) -> float:
        return float(self.draw(st.sampled_from([-1.0, 1.0])))

    def length(self, lo: float, hi: float) -> float:
        return self.f(lo, hi) * self.size

    def point(self, near: XY = (0.0, 0.0), r: float = 1.0) -> XY:
        return (near[0] + self.f(-r, r) * self.size, near[1] + self.f(-r, r) * self.size)

    def mu(self) -> float:
        """A transmission angle, either sense, well away from 0 and 180°."""
        return self.sign() * math.radians(self.f(_MU_MIN, _MU_MAX))

    def along(self) -> float:
        """An angle within ±_LINE_MAX of a direction, either sense of the line."""
        return math.radians(self.f(-_LINE_MAX, _LINE_MAX)) + self.draw(
            st.sampled_from([0.0, math.pi]))

    # -- geometry --
    def add(self, lid: str, name: str, p: XY) -> XY:
        self.bodies.setdefault(lid, {})[name] = p
        return p

    def dyad(self, p1: XY) -> tuple[XY, XY]:
        """The joint ``D`` of a dyad from ``p1``, and its far end (transmission at D ok)."""
        d = _add(p1, _e(self.angle()), self.length(0.4, 1.5))
        far = _add(d, _e(_dir(_sub(p1, d)) + self.mu()), self.length(0.4, 1.5))
        return d, far

    def line_name(self) -> tuple[str, str]:
        self.n_lines += 1
        return f"L{self.n_lines}a", f"L{self.n_lines}b"

    def line(self, on: str, p0: XY, p1: XY) -> list[Any]:
        """A line through world points p0, p1, fixed in link ``on`` (filled in at the end)."""
        spec: list[Any] = [None, None]
        use_names = self.draw(st.booleans())
        names = self.line_name()
        if use_names:
            self.add(on, names[0], p0)
            self.add(on, names[1], p1)
            spec[:] = list(names)
        else:
            def fill(poses: dict[str, Pose]) -> None:
                spec[:] = [list(_to_local(poses[on], p0)), list(_to_local(poses[on], p1))]
            self.deferred.append(fill)
        return spec

    def slider(self, link: str, on: str, point: str, p0: XY, p1: XY) -> None:
        """``point`` of ``link`` slides on the line p0 -> p1 of ``on``; sets link's angle."""
        self.angles[link] = _dir(_sub(p1, p0))
        self.sliders.append({"link": _key(link), "on": _key(on), "point": point,
                             "line": self.line(on, p0, p1)})

    # -- drives and rates --
    def drive_angle(self, link: str) -> dict[str, Any]:
        d: dict[str, Any] = {"link": _key(link), "angle": None}
        w = self.f(0.5, 60.0) * self.sign()
        self.rate_of[link] = w
        if self.with_rates:
            if self.draw(st.booleans()):
                d["omega"] = w
            else:
                d["omega"] = f"{abs(w)!r} rad/s {'cw' if w < 0 else 'ccw'}"
            if self.draw(st.integers(0, 3)):  # mostly given; else 0 by default
                d["alpha"] = self.f(-500.0, 500.0)
        self.drives.append(d)
        return d

    def drive_position(self, link: str, travel: float) -> dict[str, Any]:
        d: dict[str, Any] = {"link": _key(link), "position": travel}
        v = self.f(0.5, 20.0) * self.sign() * self.size
        self.rate_of[link] = v
        if self.with_rates:
            d["velocity"] = v
            if self.draw(st.integers(0, 3)):
                d["acceleration"] = self.f(-200.0, 200.0) * self.size
        self.drives.append(d)
        return d

    def generic_motion(self, fields: dict[str, _Field], locked: set[frozenset[str]]) -> None:
        """Reject special postures: a link momentarily at rest, two links turning together
        (an instant center at infinity), a moving point momentarily at rest.

        ``fields`` holds the velocity field of every moving link at the drawn
        drive rates; ``locked`` the pairs that never turn relative to each
        other (a slider and its guide).
        """
        w = {"1": 0.0, **{k: f.w for k, f in fields.items()}}
        self.omegas = {k: f.w for k, f in fields.items()}
        frame = set(self.bodies["1"])
        speeds = [_norm(fields[k].at(p)) for k, pts in self.bodies.items() if k != "1"
                  for n, p in pts.items() if n not in frame]
        wc = max([abs(x) for x in w.values()] + [v / self.size for v in speeds])
        assume(wc > 0.0)
        ids = sorted(w)
        for i, a in enumerate(ids):
            for b in ids[i + 1:]:
                if frozenset((a, b)) not in locked:
                    assume(abs(w[a] - w[b]) >= _GENERIC * wc)
        for v in speeds:
            assume(v >= _GENERIC * wc * self.size)

    # -- the file --
    def finish(self) -> RandomMechanism:
        # two points of one link either coincide or stand clearly apart: a coupler point
        # 1e-9 from a pin makes lengths that span more than 1e9, which graphkin refuses
        # (issue 14: such a file names the point), so it is no valid random mechanism
        for pts in self.bodies.values():
            xy = list(pts.values())
            for i, p in enumerate(xy):
                for q in xy[i + 1:]:
                    d = _norm(_sub(p, q))
                    assume(d == 0.0 or d > 1e-4 * self.size)
        poses: dict[str, Pose] = {"1": (0.0, 0.0, 0.0)}
        angle_drive = {str(d["link"]): d for d in self.drives if "angle" in d}
        for lid, pts in self.bodies.items():
            if lid == "1":
                continue
            t = self.angles.get(lid, None)
            if t is None:
                t = self.angle()
            if lid in angle_drive:
                deg = math.degrees(t)
                angle_drive[lid]["angle"] = deg
                t = math.radians(deg)  # exactly what the parser will make of it
            xs = [p[0] for p in pts.values()] or [0.0]
            ys = [p[1] for p in pts.values()] or [0.0]
            origin = self.point((sum(xs) / len(xs), sum(ys) / len(ys)), 1.0)
            poses[lid] = (origin[0], origin[1], _wrap(t))
        for fill in self.deferred:
            fill(poses)
        links = {lid: {n: list(_to_local(poses[lid], p)) for n, p in pts.items()}
                 for lid, pts in self.bodies.items()}
        frame_names = set(self.bodies["1"])
        hints = {n: list(p) for lid, pts in self.bodies.items() if lid != "1"
                 for n, p in pts.items() if n not in frame_names and n not in self.no_hint}
        data: dict[str, Any] = {
            "title": f"random {self.kind}",
            "units": {"length": self.unit},
            "links": links,
            "drive": self.drives[0] if len(self.drives) == 1 else self.drives,
            "assembly": hints,
        }
        if self.sliders:
            data["sliders"] = self.sliders
        if self.slots:
            data["slots"] = self.slots
        if self.rates is not None:
            data["rates"] = self.rates
        truth = {lid: poses[lid] for lid in self.bodies if lid != "1"}
        omega = dict(self.omegas) if self.with_rates else {}
        return RandomMechanism(self.kind, data, truth, omega)


def _key(lid: str) -> int:
    return int(lid)


def _neg(v: XY) -> XY:
    return (-v[0], -v[1])


def _perp(v: XY) -> XY:
    return (-v[1], v[0])


@dataclass(frozen=True)
class _Field:
    """Velocity field of a rigid body: angular velocity ``w`` and velocity ``v`` of point ``p``."""

    w: float
    p: XY
    v: XY = (0.0, 0.0)

    def at(self, q: XY) -> XY:
        """V_Q = V_P + ω k×(Q - P) (Eq. 3.4)."""
        return _add(self.v, _perp(_sub(q, self.p)), self.w)


_REST = _Field(0.0, (0.0, 0.0))


def _solve2(a1: XY, a2: XY, rhs: XY) -> tuple[float, float]:
    """x, y with x a1 + y a2 = rhs (Cramer's rule)."""
    det = _cross(a1, a2)
    assume(abs(det) > 1e-12 * (_norm(a1) * _norm(a2) + 1e-300))
    return _cross(rhs, a2) / det, _cross(a1, rhs) / det


def _rrr(f1: _Field, p1: XY, d: XY, f2: _Field, p2: XY) -> tuple[_Field, _Field]:
    """Velocities of a dyad p1-D-p2 whose ends move with fields f1, f2 (Sec. 3.9).

    V_p1 + ωa k×(D - p1) = V_p2 + ωb k×(D - p2).
    """
    v1, v2 = f1.at(p1), f2.at(p2)
    wa, wb = _solve2(_perp(_sub(d, p1)), _neg(_perp(_sub(d, p2))), _sub(v2, v1))
    return _Field(wa, p1, v1), _Field(wb, p2, v2)


def _rrp(f1: _Field, p1: XY, c: XY, u: XY) -> tuple[_Field, _Field]:
    """Rod p1-C and a slider at C moving along the frame direction u: V_C = s u."""
    v1 = f1.at(p1)
    w, s = _solve2(_perp(_sub(c, p1)), _neg(u), _neg(v1))
    return _Field(w, p1, v1), _Field(0.0, c, (s * u[0], s * u[1]))


# ---------------------------------------------------------------------------
# the families
# ---------------------------------------------------------------------------


def _fourbar_core(b: _Build) -> tuple[XY, XY, XY, XY]:
    """Crank O2-A (link 2), coupler A-B (3), rocker O4-B (4): returns O2, A, B, O4."""
    o2 = b.add("1", "O2", b.point())
    a = b.add("2", "A", _add(o2, _e(b.angle()), b.length(0.2, 0.8)))
    b.add("3", "A", a)
    bb, o4 = b.dyad(a)
    assume(_norm(_sub(o4, o2)) > 0.1 * b.size)
    b.add("3", "B", bb)
    b.add("4", "B", bb)
    b.add("4", "O4", o4)
    b.add("1", "O4", o4)
    b.add("2", "O2", o2)
    return o2, a, bb, o4


def _fourbar_fields(b: _Build, o2: XY, a: XY, bb: XY, o4: XY) -> dict[str, _Field]:
    f2 = _Field(b.rate_of["2"], o2)
    f3, f4 = _rrr(f2, a, bb, _REST, o4)
    return {"2": f2, "3": f3, "4": f4}


@st.composite
def _fourbar(draw: Any, with_rates: bool, other_rates: bool) -> RandomMechanism:
    b = _Build(draw, "fourbar", with_rates)
    o2, a, bb, o4 = _fourbar_core(b)
    b.add("3", "E", b.point(a, 1.0))  # a coupler point
    if draw(st.booleans()):
        b.add("4", "F", b.point(o4, 1.0))
    d = b.drive_angle("2")
    b.generic_motion(_fourbar_fields(b, o2, a, bb, o4), set())
    if with_rates and other_rates and draw(st.integers(0, 3)) == 0:
        # the known rates belong to the coupler or the rocker: [rates]
        k = draw(st.sampled_from(["3", "4"]))
        rates: dict[str, Any] = {"link": int(k), "omega": d.pop("omega")}
        if "alpha" in d:
            rates["alpha"] = d.pop("alpha")
        b.rates = rates
        b.kind = f"fourbar, rates of link {k}"
        # the drawn ω now belongs to link k: every ω scales by ω_drawn / ω_k
        scale = b.rate_of["2"] / b.omegas[k]
        b.omegas = {lid: w * scale for lid, w in b.omegas.items()}
    return b.finish()


def fourbars(with_rates: bool = True, other_rates: bool = True) -> st.SearchStrategy[
        RandomMechanism]:
    """Crank-driven four-bars with coupler and rocker points.

    Links 2 (crank O2-A), 3 (coupler A-B-E), 4 (rocker O4-B, maybe F).  The
    transmission angle at B is between 25° and 155°.  With ``other_rates``
    a quarter of them give the rates of the coupler or rocker in ``[rates]``.
    """
    return _fourbar(with_rates, other_rates)


@st.composite
def _slider_crank(draw: Any, with_rates: bool) -> RandomMechanism:
    driven = draw(st.sampled_from(["crank", "slider"]))
    b = _Build(draw, f"slider-crank, {driven}-driven", with_rates)
    o2 = b.add("1", "O2", b.point())
    a = b.add("2", "A", _add(o2, _e(b.angle()), b.length(0.2, 0.8)))
    b.add("2", "O2", o2)
    b.add("3", "A", a)
    if driven == "crank":
        # C moves along the line: the rod A-C must not be perpendicular to it
        psi = b.angle()
        c = _add(a, _e(psi), b.length(0.5, 2.0))
        phi = psi + b.along()
    else:
        # A is found from C: the crank and rod must not be in line (angle at A)
        psi = _dir(_sub(o2, a)) + b.mu()
        c = _add(a, _e(psi), b.length(0.5, 2.0))
        phi = b.angle()
    b.add("3", "C", c)
    b.add("3", "D", b.point(_add(a, _sub(c, a), 0.5), 0.8))  # coupler point
    b.add("4", "C", c)
    if draw(st.booleans()):
        b.add("4", "G", b.point(c, 0.3))
    u = _e(phi)
    t1 = b.length(-1.0, 1.0)
    p0 = _add(c, u, -t1)
    p1 = _add(p0, u, b.length(0.3, 2.0))
    b.slider("4", "1", "C", p0, p1)
    if driven == "crank":
        b.drive_angle("2")
        f2 = _Field(b.rate_of["2"], o2)
        f3, f4 = _rrp(f2, a, c, u)
    else:
        b.drive_position("4", _dot(_sub(c, p0), u))
        vc = b.rate_of["4"]
        # V_A = ω2 k×(A - O2) = V_C + ω3 k×(A - C)
        w2, w3 = _solve2(_perp(_sub(a, o2)), _neg(_perp(_sub(a, c))), (vc * u[0], vc * u[1]))
        f2 = _Field(w2, o2)
        f3, f4 = _Field(w3, c, (vc * u[0], vc * u[1])), _Field(0.0, c, (vc * u[0], vc * u[1]))
    b.generic_motion({"2": f2, "3": f3, "4": f4}, {frozenset(("1", "4"))})
    return b.finish()


def slider_cranks(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Offset slider-cranks on a line at any angle, crank-driven or slider-driven.

    Links 2 (crank O2-A), 3 (rod A-C with coupler point D), 4 (slider C, maybe G)
    sliding on a frame line.  Crank-driven: the rod makes at most 65° with the
    line; slider-driven: crank and rod make 25°-155°.
    """
    return _slider_crank(with_rates)


@st.composite
def _inverted(draw: Any, with_rates: bool) -> RandomMechanism:
    b = _Build(draw, "inverted slider-crank", with_rates)
    d = b.add("1", "D", b.point())
    b.add("4", "D", d)
    psi = b.angle()
    u, n = _e(psi), _e(psi + math.pi / 2)
    e = b.length(-0.5, 0.5) if draw(st.booleans()) else 0.0
    bpt = _add(_add(d, n, e), u, b.length(0.3, 2.0) * b.sign())
    same = draw(st.integers(0, 2)) == 0  # the block's pin on its line (Example 4.11)
    a = bpt if same else b.point(bpt, 0.6)
    # rod angle from A: n·(A - D) is fixed, so u·(A - D) must stay away from 0
    assume(_norm(_sub(a, d)) > 0.2 * b.size)
    assume(abs(_dot(u, _sub(a, d))) > 0.35 * _norm(_sub(a, d)))
    e_pt = _add(a, _e(b.angle()), b.length(0.2, 0.8))
    b.add("1", "E", e_pt)
    b.add("2", "E", e_pt)
    b.add("2", "A", a)
    b.add("3", "A", a)
    point = "A"
    if not same:
        b.add("3", "B", bpt)
        point = "B"
    b.add("4", "R", _add(d, u, b.length(0.5, 2.0)))  # the rod's end (its hint fixes the branch)
    b.slider("3", "4", point, _add(bpt, u, -b.length(0.1, 1.0)), _add(bpt, u, b.length(0.1, 1.0)))
    b.drive_angle("2")
    # V_A = ω2 k×(A - E) = ω4 k×(A - D) + ṡ u  (block 3 turns with rod 4, Sec. 3.5)
    f2 = _Field(b.rate_of["2"], e_pt)
    w4, _ = _solve2(_perp(_sub(a, d)), u, f2.at(a))
    b.generic_motion({"2": f2, "3": _Field(w4, a, f2.at(a)), "4": _Field(w4, d)},
                     {frozenset(("3", "4"))})
    return b.finish()


def inverted_slider_cranks(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Inverted slider-cranks (Example 3.3): block 3 pinned to crank 2, sliding on rod 4.

    The rod (pivot D) carries the line, possibly offset from D; the block's
    slider point may be its pin A or another point B.  The line never makes
    more than ~70° with D-A, so the rod angle is a regular root.
    """
    return _inverted(with_rates)


@st.composite
def _slotted(draw: Any, with_rates: bool) -> RandomMechanism:
    pin_on = draw(st.sampled_from(["2", "3"]))
    straight = draw(st.booleans())
    slot_on = "3" if pin_on == "2" else "2"
    b = _Build(draw, f"pin in {'straight' if straight else 'circular'} slot of link {slot_on}",
               with_rates)
    p = b.add(pin_on, "P", b.point())
    spec: dict[str, Any] = {"link": int(pin_on), "on": int(slot_on), "point": "P"}
    if straight:
        phi = b.angle()
        u = _e(phi)
        normal = _perp(u)
        # the follower 3 turns about O3: u·(P - O3) must stay away from 0 (either way round)
        o3 = _add(p, _e(phi + b.along()), -b.length(0.4, 1.5))
        spec["line"] = b.line(slot_on, _add(p, u, -b.length(0.1, 1.0)),
                              _add(p, u, b.length(0.1, 1.0)))
    else:
        rho = b.length(0.2, 1.2)
        c = _add(p, _e(b.angle()), rho)
        normal = _sub(p, c)
        if slot_on == "3":  # the centre turns about O3: C-O3 not along P-C
            o3 = _add(c, _e(_dir(_sub(c, p)) + b.mu()), b.length(0.3, 1.5))
        else:  # the pin turns about O3: P-O3 not along P-C
            o3 = _add(p, _e(_dir(_sub(p, c)) + b.mu()), b.length(0.3, 1.5))
        circle: dict[str, Any] = {"radius": rho}
        if draw(st.booleans()):
            b.add(slot_on, "K", c)
            b.no_hint.add("K")
            circle["center"] = "K"
        else:
            def fill(poses: dict[str, Pose]) -> None:
                circle["center"] = list(_to_local(poses[slot_on], c))
            b.deferred.append(fill)
        spec["circle"] = circle
    b.slots.append(spec)
    b.add("1", "O3", o3)
    b.add("3", "O3", o3)
    if pin_on == "2":  # a point of the follower, whose hint fixes the branch
        b.add("3", "F", _add(o3, _e(b.angle()), b.length(0.3, 1.0)))
    o2 = _add(p, _e(b.angle()), b.length(0.3, 1.0)) if pin_on == "2" else b.point(o3, 1.0)
    assume(_norm(_sub(o2, o3)) > 0.1 * b.size)
    b.add("1", "O2", o2)
    b.add("2", "O2", o2)
    b.drive_angle("2")
    # the pin slides along its slot: n·(V_P as a point of the pin's link
    # - V_P as a point of the slot's link) = 0, linear in ω3
    f2 = _Field(b.rate_of["2"], o2)

    def gap(w3: float) -> float:
        f3 = _Field(w3, o3)
        fp, fs = (f2, f3) if pin_on == "2" else (f3, f2)
        return _dot(normal, _sub(fp.at(p), fs.at(p)))

    g0, g1 = gap(0.0), gap(1.0)
    assume(abs(g1 - g0) > 0.0)
    b.generic_motion({"2": f2, "3": _Field(-g0 / (g1 - g0), o3)}, set())
    return b.finish()


def slotted(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """A pin in a slot of a moving link (Example 4.7's equivalent linkage).

    Crank 2 (pivot O2) and follower 3 (pivot O3); the pin P is on one of them
    and a straight or circular slot on the other.  Regular by construction:
    the follower's rotation always moves the pin across its slot.
    """
    return _slotted(with_rates)


@st.composite
def _double_slider(draw: Any, with_rates: bool) -> RandomMechanism:
    driven = draw(st.sampled_from(["rod", "tiller"]))
    b = _Build(draw, f"Rapson's slide, {driven}-driven", with_rates)
    psi1 = b.angle()
    u1 = _e(psi1)
    l0 = b.point()
    a = _add(l0, u1, b.length(-1.0, 1.0))
    if driven == "tiller":  # A is where two lines meet: they must cross well
        psi4 = psi1 + b.mu()
    else:
        psi4 = b.angle()
    u4, n4 = _e(psi4), _e(psi4 + math.pi / 2)
    same = draw(st.booleans())
    q = a if same else b.point(a, 0.3)
    e = b.length(-0.5, 0.5) if draw(st.booleans()) else 0.0
    o4 = _add(_add(q, u4, b.length(0.5, 2.0) * b.sign()), n4, e)
    if driven == "rod":  # the tiller angle from A: u4·(A - O4) away from 0
        assume(_norm(_sub(a, o4)) > 0.2 * b.size)
        assume(abs(_dot(u4, _sub(a, o4))) > 0.35 * _norm(_sub(a, o4)))
    b.add("1", "O4", o4)
    b.add("4", "O4", o4)
    b.add("4", "B", _add(o4, u4, b.length(0.5, 2.0) * b.sign()))
    b.add("2", "A", a)
    b.add("3", "A", a)
    if draw(st.booleans()):
        b.add("2", "R", _add(a, u1, b.length(0.2, 1.0)))
    point = "A"
    if not same:
        b.add("3", "Q", q)
        point = "Q"
    p0 = _add(a, u1, -b.length(-1.0, 1.0))
    p1 = _add(p0, u1, b.length(0.3, 2.0))
    b.slider("2", "1", "A", p0, p1)
    b.slider("3", "4", point, _add(q, u4, -b.length(0.1, 1.0)), _add(q, u4, b.length(0.1, 1.0)))
    # the block slides on the tiller: n4·(ṡ1 u1 + ω4 k×(O4 - A)) = 0
    k1, k4 = _dot(n4, u1), _dot(n4, _perp(_sub(o4, a)))
    if driven == "rod":
        b.drive_position("2", _dot(_sub(a, p0), u1))
        s1 = b.rate_of["2"]
        w4 = -s1 * k1 / k4
    else:
        b.drive_angle("4")
        w4 = b.rate_of["4"]
        s1 = -w4 * k4 / k1
    v_a = (s1 * u1[0], s1 * u1[1])
    b.generic_motion({"2": _Field(0.0, a, v_a), "3": _Field(w4, a, v_a), "4": _Field(w4, o4)},
                     {frozenset(("1", "2")), frozenset(("3", "4"))})
    return b.finish()


def double_sliders(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Rapson's slide (Example 4.11): rod 2 slides on the frame, block 3 on tiller 4.

    Driven by the rod's travel or by the tiller's angle.  The block's slider
    point is its pin A or another point Q.
    """
    return _double_slider(with_rates)


@st.composite
def _five_bar(draw: Any, with_rates: bool) -> RandomMechanism:
    b = _Build(draw, "five-bar", with_rates)
    o2 = b.add("1", "O2", b.point())
    b.add("2", "O2", o2)
    a = b.add("2", "A", _add(o2, _e(b.angle()), b.length(0.2, 0.8)))
    b.add("4", "A", a)
    bb, c = b.dyad(a)
    b.add("4", "B", bb)
    b.add("5", "B", bb)
    b.add("5", "C", c)
    b.add("3", "C", c)
    o3 = b.add("3", "O3", _add(c, _e(b.angle()), b.length(0.2, 0.8)))
    assume(_norm(_sub(o3, o2)) > 0.1 * b.size)
    b.add("1", "O3", o3)
    b.add("4", "P", b.point(a, 1.0))
    b.drive_angle("2")
    b.drive_angle("3")
    f2, f3 = _Field(b.rate_of["2"], o2), _Field(b.rate_of["3"], o3)
    f4, f5 = _rrr(f2, a, bb, f3, c)
    b.generic_motion({"2": f2, "3": f3, "4": f4, "5": f5}, set())
    return b.finish()


def five_bars(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Two-input five-bars (Example 5.4): cranks 2 and 3 driven, links 4 (A-B-P) and 5 (C-B)."""
    return _five_bar(with_rates)


@st.composite
def _six_bar(draw: Any, with_rates: bool) -> RandomMechanism:
    variant = draw(st.sampled_from(["watt1", "watt2", "stephenson3", "stephenson3-slider"]))
    b = _Build(draw, f"six-bar {variant}", with_rates)
    o2, a, bb, o4 = _fourbar_core(b)
    if variant == "watt2":  # second loop from the rocker 4 to the frame
        c = b.add("4", "C", b.point(o4, 1.0))
    else:  # from the coupler 3
        c = b.add("3", "C", b.point(_add(a, _sub(bb, a), 0.5), 1.0))
    b.add("5", "C", c)
    b.drive_angle("2")
    fields = _fourbar_fields(b, o2, a, bb, o4)
    fc = fields["4" if variant == "watt2" else "3"]
    locked: set[frozenset[str]] = set()
    if variant == "stephenson3-slider":
        psi = b.angle()
        dd = _add(c, _e(psi), b.length(0.5, 2.0))
        phi = psi + b.along()
        b.add("5", "D", dd)
        b.add("6", "D", dd)
        u = _e(phi)
        p0 = _add(dd, u, -b.length(-1.0, 1.0))
        b.slider("6", "1", "D", p0, _add(p0, u, b.length(0.3, 2.0)))
        fields["5"], fields["6"] = _rrp(fc, c, dd, u)
        locked.add(frozenset(("1", "6")))
    else:
        dd, far = b.dyad(c)
        b.add("5", "D", dd)
        b.add("6", "D", dd)
        if variant == "watt1":  # the dyad ends on the rocker 4
            b.add("4", "G", far)
            b.add("6", "G", far)
            ffar = fields["4"]
        else:
            b.add("1", "O6", far)
            b.add("6", "O6", far)
            ffar = _REST
        fields["5"], fields["6"] = _rrr(fc, c, dd, ffar, far)
    b.generic_motion(fields, locked)
    return b.finish()


def six_bars(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Watt I, Watt II and Stephenson III six-bars (the last also with a slider).

    A crank-driven four-bar O2-A-B-O4 (links 2, 3, 4) and a dyad 5-6 from a
    point C of the coupler 3 (Stephenson III; Watt I when the dyad ends on the
    rocker 4) or of the rocker 4 (Watt II) to the frame.
    """
    return _six_bar(with_rates)


def mechanisms(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Any of the families above."""
    return st.one_of(fourbars(with_rates), slider_cranks(with_rates),
                     inverted_slider_cranks(with_rates), slotted(with_rates),
                     double_sliders(with_rates), six_bars(with_rates), five_bars(with_rates))


@st.composite
def _scotch_yoke(draw: Any, with_rates: bool) -> RandomMechanism:
    # Fig. 3.27: crank 2 about O2; block 3 pinned at A slides in a straight slot of yoke 4,
    # which slides on a guide of the frame.  Link 4's x axis runs along the guide and 3's
    # along the slot (a slider's link keeps its axis along its line).
    f = lambda lo, hi: draw(st.floats(lo, hi, allow_nan=False))  # noqa: E731
    o2 = (f(-1.0, 1.0), f(-1.0, 1.0))
    r2, t2 = f(0.3, 1.0), f(-math.pi, math.pi)
    a = _add(o2, _e(t2), r2)
    psi, beta = f(-math.pi, math.pi), f(0.5, math.pi - 0.5)  # the guide's and slot's angles
    g0 = _add(o2, _e(psi + math.pi / 2), f(-2.0, -0.8))
    s0 = (f(-0.5, 0.5), f(0.2, 1.0))  # the slot's first point, in the yoke's axes
    u, w = _e(psi), _e(psi + beta)
    rs0 = _to_world((0.0, 0.0, psi), s0)
    # the yoke's travel t along the guide puts A on the slot: t u + λ w = A - G0 - R(ψ) S0
    t, lam = _solve2(u, w, _sub(_sub(a, g0), rs0))
    f_w = _add(g0, u, t)
    data: dict[str, Any] = {
        "units": {"length": "m"},
        "links": {"1": {"O2": list(o2), "G0": list(g0), "G1": list(_add(g0, u))},
                  "2": {"O2": [0.0, 0.0], "A": [r2, 0.0]},
                  "3": {"A": [0.0, 0.0]},
                  "4": {"F": [0.0, 0.0], "S0": list(s0),
                        "S1": list(_add(s0, _e(beta)))}},
        "sliders": [{"link": 3, "on": 4, "point": "A", "line": ["S0", "S1"]},
                    {"link": 4, "on": 1, "point": "F", "line": ["G0", "G1"]}],
        "drive": {"link": 2, "angle": math.degrees(t2)},
        "assembly": {"F": list(f_w)},
    }
    if with_rates:
        data["drive"].update(omega=f(-20.0, 20.0), alpha=f(-50.0, 50.0))
    truth = {"2": (o2[0], o2[1], t2), "3": (a[0], a[1], psi + beta),
             "4": (f_w[0], f_w[1], psi)}
    return RandomMechanism("scotch yoke", data, truth)


def scotch_yokes(with_rates: bool = True) -> st.SearchStrategy[RandomMechanism]:
    """Scotch yokes at any angles (Fig. 3.27): two sliders close one loop.

    The construction cannot find link 4 one group at a time; Newton's method
    solves it.  ``omega`` is left empty.
    """
    return _scotch_yoke(with_rates)


def examples(n: int) -> settings:
    """Settings of a property test over random mechanisms: ``n`` examples, no deadline.

    Drawing a mechanism that assembles takes several tries, so the slow-data
    and filter health checks are off.
    """
    return settings(max_examples=n, deadline=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])
