"""Four-bar linkages: recognising one, Grashof's law and the transmission angle.

References
----------
Uicker, Pennock & Shigley, *Theory of Machines and Mechanisms*, 5th ed.:
Sec. 1.9 (Grashof's law, Eq. 1.6, Fig. 1.28), Sec. 1.10 (transmission angle).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from graphkin.errors import InputError
from graphkin.kinematics.solution import Solution
from graphkin.kinematics.sweep.report import Sweep
from graphkin.mechanisms.model import FRAME, Mechanism
from graphkin.tolerance import DEFAULT_TOL, Tolerance

Array = np.ndarray


@dataclass(frozen=True)
class FourBar:
    """A four-bar linkage found in a mechanism: frame, input, coupler, output.

    Attributes
    ----------
    frame, input, coupler, output : str
        Link ids.  The input is the driven link when it is pinned to the frame.
    pins : (str, str, str, str)
        ``(A, B, C, D)``: frame-input, input-coupler, coupler-output, output-frame.
    lengths : dict
        Link id -> the distance between its two pins.
    """

    frame: str
    input: str
    coupler: str
    output: str
    pins: tuple[str, str, str, str]
    lengths: dict[str, float] = field(hash=False, compare=False)


def fourbar(mech: Mechanism) -> FourBar:
    """Recognise a four-bar linkage (four links, four pins) in a mechanism.

    Raises
    ------
    InputError
        The mechanism is not a four-bar of revolute pairs.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.9, Fig. 1.28.

    Examples
    --------
    >>> import graphkin
    >>> fb = fourbar(graphkin.examples.crank_rocker())
    >>> fb.pins, fb.lengths
    (('A', 'B', 'C', 'D'), {'1': 200.0, '2': 100.0, '3': 250.0, '4': 300.0})
    """
    def fail(why: str) -> InputError:
        return InputError(f"not a four-bar linkage: {why}", file=mech.source)

    if len(mech.links) != 4 or mech.sliders or mech.slots:
        raise fail("it needs exactly four links joined by four pins and no sliders or slots")
    pins = [p for p in mech.pins if len(p.links) == 2]
    if len(pins) != 4 or len(mech.pins) != 4:
        raise fail("it needs four pins, each joining two links")
    grounded = [p for p in pins if FRAME in p.links]
    if len(grounded) != 2:
        raise fail("the frame must carry exactly two pins")
    side = {next(k for k in p.links if k != FRAME): p.name for p in grounded}
    if len(side) != 2:
        raise fail("the two frame pins must go to two different links")
    drive_link = mech.drives[0].link if mech.drives else None
    ids = list(side)
    inp = drive_link if drive_link in side else ids[0]
    out = next(k for k in ids if k != inp)
    coupler = next(k for k in mech.moving if k not in side)
    byp = {frozenset(p.links): p.name for p in pins}
    try:
        b = byp[frozenset((inp, coupler))]
        c = byp[frozenset((coupler, out))]
    except KeyError:
        raise fail("the coupler must be pinned to both links that turn about the frame") from None
    a, d = side[inp], side[out]

    def length(lid: str, p: str, q: str) -> float:
        pts = mech.links[lid].points
        return math.hypot(pts[q][0] - pts[p][0], pts[q][1] - pts[p][1])

    lengths = {FRAME: length(FRAME, a, d), inp: length(inp, a, b),
               coupler: length(coupler, b, c), out: length(out, d, c)}
    return FourBar(FRAME, inp, coupler, out, (a, b, c, d), lengths)


@dataclass(frozen=True)
class Grashof:
    """Grashof's classification of a four-bar linkage (Sec. 1.9).

    Attributes
    ----------
    kind : str
        ``"crank-rocker"`` (the shortest link is beside the frame: it is the
        crank), ``"double-crank"`` (drag link: the shortest link is the
        frame), ``"double-rocker"`` (the shortest link is the coupler, which
        turns fully while both side links rock), or ``"non-Grashof"`` (``s + l >
        p + q``: no link turns fully relative to another; a triple rocker).
    s, l, p, q : float
        Shortest, longest and the other two lengths.
    shortest, longest : str
        Link ids.
    grashof : bool
        ``s + l <= p + q`` (Eq. 1.6).
    change_point : bool
        ``s + l == p + q`` (within the length tolerance): the links can fold
        flat, where the two branches meet.
    cranks : tuple of str
        Links that can turn through full turns relative to the frame.
    """

    kind: str
    s: float
    l: float  # noqa: E741 - the book's name
    p: float
    q: float
    shortest: str
    longest: str
    grashof: bool
    change_point: bool
    cranks: tuple[str, ...]

    def __str__(self) -> str:
        name = {"double-crank": "double-crank (drag link)"}.get(self.kind, self.kind)
        rel = "=" if self.change_point else ("<" if self.grashof else ">")
        text = f"{name}: s + l = {self.s + self.l:.6g} {rel} p + q = {self.p + self.q:.6g}"
        if self.change_point:
            text += " (change point)"
        if self.cranks:
            text += "; crank" + ("s" if len(self.cranks) > 1 else "") + ": link " + \
                ", ".join(self.cranks)
        return text


def grashof(mech: Mechanism | FourBar, tol: Tolerance | None = None) -> Grashof:
    """Classify a four-bar linkage by Grashof's law, ``s + l <= p + q`` (Eq. 1.6).

    Parameters
    ----------
    mech : Mechanism or FourBar
    tol : Tolerance, optional
        Decides ``s + l == p + q`` (a change point).

    Returns
    -------
    Grashof

    Raises
    ------
    InputError
        Not a four-bar linkage.

    Notes
    -----
    When ``s + l <= p + q`` the shortest link turns fully relative to the
    other three, and which link is fixed names the linkage (Fig. 1.28): the
    shortest link beside the frame, a crank-rocker; the shortest link as the
    frame, a double-crank (drag link); the shortest link as the coupler, a
    double-rocker.  Otherwise no link turns fully relative to another.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.9, Eq. 1.6, Fig. 1.28,
    Example 1.6.

    Examples
    --------
    Example 1.6: s = 3 in (the frame), l = 6 in, p = 4 in, q = 5 in; 3 + 6 <= 4 + 5,
    and the shortest link is the frame, so it is a drag link.

    >>> fb = FourBar("1", "2", "3", "4", ("A", "B", "C", "D"),
    ...              {"1": 3.0, "2": 4.0, "3": 6.0, "4": 5.0})
    >>> str(grashof(fb))
    'double-crank (drag link): s + l = 9 = p + q = 9 (change point); cranks: link 2, 4'
    """
    fb = mech if isinstance(mech, FourBar) else fourbar(mech)
    tol = tol or DEFAULT_TOL
    lengths = fb.lengths
    order = sorted(lengths, key=lambda k: (lengths[k], k))
    shortest, longest = order[0], order[-1]
    s, l = lengths[shortest], lengths[longest]  # noqa: E741
    p, q = (lengths[k] for k in order[1:3])
    excess = (s + l) - (p + q)
    eps = tol.length(max(lengths.values()))
    change = abs(excess) <= eps
    is_grashof = excess <= eps
    if not is_grashof:
        return Grashof("non-Grashof", s, l, p, q, shortest, longest, False, False, ())
    # ties for the shortest link: any of them may serve as s; prefer the frame, then a side link
    ties = [k for k in order if lengths[k] - s <= eps]
    if fb.frame in ties:
        return Grashof("double-crank", s, l, p, q, fb.frame, longest, True, change,
                       (fb.input, fb.output))
    side = [k for k in ties if k in (fb.input, fb.output)]
    if side:
        return Grashof("crank-rocker", s, l, p, q, side[0], longest, True, change,
                       tuple(side))
    return Grashof("double-rocker", s, l, p, q, fb.coupler, longest, True, change, ())


def transmission_angle(obj: Solution | Sweep | Mechanism) -> Array:
    """The transmission angle γ of a four-bar, in degrees (0-180), Sec. 1.10.

    The angle at the coupler-output pin C between the coupler (C to B) and
    the output link (C to D).  At a dead-center posture it is 0° or 180°.

    Parameters
    ----------
    obj : Solution, Sweep or Mechanism
        One posture (a mechanism is solved first) or many.

    Returns
    -------
    ndarray
        Shape () for one posture, (N,) for a sweep; NaN where not assembled.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 1.10, Fig. 1.31, Example 1.7.

    Examples
    --------
    Example 1.7: R_DA = 180 mm, R_BA = 60 mm, R_CB = 210 mm, R_CD = 120 mm,
    crank at 60°: γ = 48.65°.

    >>> import graphkin
    >>> mech = graphkin.loads('''
    ... drive = { link = 2, angle = 60 }
    ... assembly = { C = [150, 110] }
    ... [links]
    ... 1 = { A = [0, 0], D = [180, 0] }
    ... 2 = { A = [0, 0], B = [60, 0] }
    ... 3 = { B = [0, 0], C = [210, 0] }
    ... 4 = { D = [0, 0], C = [120, 0] }
    ... ''')
    >>> round(float(transmission_angle(mech)), 2)
    48.65
    """
    if isinstance(obj, Mechanism):
        from graphkin.kinematics.solve import solve

        obj = solve(obj)
    sol = obj.solution if isinstance(obj, Sweep) else obj
    fb = fourbar(sol.mechanism)
    _, b, c, d = fb.pins
    with np.errstate(invalid="ignore", divide="ignore"):
        pc = sol.position(c, fb.coupler)
        pb = sol.position(b, fb.coupler)
        pd = sol.position(d, fb.output)
        u, v = pb - pc, pd - pc
        cr = u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]
        dt = u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]
        out = np.degrees(np.arctan2(np.abs(cr), dt))
    if isinstance(obj, Sweep):
        out = np.where(obj.assembled, out, np.nan)
    return out
