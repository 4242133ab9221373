"""Angular velocity ratios, kinematic coefficients and mechanical advantage (Secs. 3.15-3.17)."""

from __future__ import annotations

import numpy as np

from graphkin.errors import DegenerateError, InputError
from graphkin.geometry import ops as g
from graphkin.kinematics.instant_centers.centers import InstantCenters
from graphkin.kinematics.instant_centers.kennedy import _centers, _perp
from graphkin.kinematics.instant_centers.labels import center_label
from graphkin.kinematics.solution import Solution
from graphkin.mechanisms.model import FRAME, Mechanism

__all__ = ["angular_velocity_ratio", "kinematic_coefficient", "mechanical_advantage"]

Array = np.ndarray


def _ratio_homogeneous(a: Array, b: Array, c: Array) -> Array:
    """Signed ``R_CA / R_CB`` along the line of three collinear centers (homogeneous).

    With coordinates ``t`` along the line and weights ``w``:
    ``(t_c w_a - t_a w_c) w_b / ((t_c w_b - t_b w_c) w_a)``.  This is 1 when
    ``C`` is at infinity, 0 when ``B`` is, and unbounded when ``A`` is.
    """
    # a direction along the line: from any two distinct points of the three
    cands = []
    for p, q in ((a, b), (a, c), (b, c)):
        with np.errstate(invalid="ignore", divide="ignore"):
            cands.append(g.join(p, q))
    line = cands[0]
    for other in cands[1:]:
        line = np.where(np.isfinite(line).all(axis=-1, keepdims=True), line, other)
    u = g.direction(line)

    def t(p: Array) -> Array:
        return g.dot2(p, u)  # = (x·u) for finite (w = 1), ±1 at infinity on the line

    ta, tb, tc = t(a), t(b), t(c)
    wa, wb, wc = a[..., 2], b[..., 2], c[..., 2]
    num = (tc * wa - ta * wc) * wb
    den = (tc * wb - tb * wc) * wa
    with np.errstate(invalid="ignore", divide="ignore"):
        return num / den


def _unbounded(ic: InstantCenters, values: Array) -> bool:
    """True when a result has no finite value at some posture that could be assembled."""
    valid = np.broadcast_to(np.asarray(ic.solution.valid, dtype=bool), np.shape(values))
    return bool(np.any(~np.isfinite(values) & valid))


def angular_velocity_ratio(sol: Solution | InstantCenters, i: object, j: object,
                           reference: object = FRAME) -> Array:
    """``ω_j / ω_i`` (both relative to ``reference``) by the angular-velocity-ratio theorem.

    Eq. 3.22: the ratio is inversely as the segments into which the common
    center ``Iij`` cuts the line of centers,

    ``ω_j / ω_i = R(Iij, I1i) / R(Iij, I1j)``

    (signed distances along the line): positive (the same sense) when ``Iij``
    lies outside ``I1i`` and ``I1j``, negative (opposite senses) when it lies
    between them.  Found from the centers only, not from the solution's ω.

    Parameters
    ----------
    sol : Solution or InstantCenters
    i, j : link ids
    reference : link id
        The third link (the frame by default).

    Returns
    -------
    ndarray
        The ratio (0-d for one posture).

    Raises
    ------
    DegenerateError
        When link ``i`` does not turn relative to the reference (``I1i`` at
        infinity), so the ratio is unbounded.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.16, Eq. 3.22; Example 3.13.

    Examples
    --------
    A parallelogram four-bar: I24 is at infinity (the ratio is 1, the same
    sense), and the coupler translates, so I13 is at infinity and ω3/ω2 = 0.

    >>> import graphkin
    >>> sol = graphkin.loads('''
    ... [links]
    ... 1 = { A = [0, 0], D = [4, 0] }
    ... 2 = { A = [0, 0], B = [2, 0] }
    ... 3 = { B = [0, 0], C = [4, 0] }
    ... 4 = { D = [0, 0], C = [2, 0] }
    ... [drive]
    ... link = 2
    ... angle = 60
    ... [assembly]
    ... C = [5, 1.7]
    ... ''').solve()
    >>> float(angular_velocity_ratio(sol, 2, 4)), float(angular_velocity_ratio(sol, 2, 3))
    (1.0, 0.0)
    """
    ic = _centers(sol)
    r = str(reference)
    a = ic[(r, i)].point
    b = ic[(r, j)].point
    c = ic[(i, j)].point
    with np.errstate(invalid="ignore", divide="ignore"):
        out = _ratio_homogeneous(a, b, c)
    if _unbounded(ic, out):
        raise DegenerateError(
            f"link {i} does not turn relative to link {r} ({center_label(r, i)} is at infinity "
            f"or coincides with {center_label(i, j)}), so ω{j}/ω{i} is unbounded",
            links=(str(i), str(j), r))
    return out


def _slide_direction(ic: InstantCenters, lid: str, reference: str) -> Array:
    """Unit direction of positive travel of a link translating relative to ``reference``.

    From the slider of the file between the two (its line from first to second
    point); otherwise the center at infinity turned -90°, so that positive
    travel is a positive (ccw) turn about it (footnote to Example 3.14).
    """
    sol, mech = ic.solution, ic.solution.mechanism
    for s in mech.sliders:
        if {s.link, s.on} == {lid, reference}:
            th = np.asarray(sol.links[s.on].angle, dtype=float) + s.direction_angle
            u = np.stack([np.cos(th), np.sin(th)], axis=-1)
            return u if s.link == lid else -u
    d = ic[(reference, lid)].point[..., :2]
    return np.stack([d[..., 1], -d[..., 0]], axis=-1)


def _translates(mech: Mechanism, lid: str) -> bool:
    """True for a link joined to the frame by sliders only (it can never turn)."""
    seen, todo = {FRAME}, [FRAME]
    while todo:
        k = todo.pop()
        for s in mech.sliders:
            for a, b in ((s.link, s.on), (s.on, s.link)):
                if a == k and b not in seen:
                    seen.add(b)
                    todo.append(b)
    return lid in seen and lid != FRAME


def _input_link(mech: Mechanism, given: object) -> object:
    """The input link: the one given, or the single drive's."""
    if given is not None:
        return given
    if len(mech.drives) != 1:
        raise InputError("say which link is the input: the file has "
                         f"{len(mech.drives)} drives", key="drive")
    return mech.drives[0].link


def kinematic_coefficient(sol: Solution | InstantCenters, output: object,
                          input: object | None = None) -> Array:
    """First-order kinematic coefficient of ``output`` for ``input``, from instant centers.

    The speed of the output divided by the speed of the input, both relative
    to the frame.  A link that can turn has speed ω (zero at an instant when
    its absolute center is at infinity); a slider (a link joined to the frame
    by sliders only, its absolute center always at infinity) has speed ṙ
    along its slider's line (from the line's first point to its second):

    * turning input, turning output: ``θ'_j = R(Iij, I1i) / R(Iij, I1j)`` (Eq. 3.24);
    * sliding input, turning output: ``θ'_j = ±1 / R(Iij, I1j)`` (Eq. 3.26), in
      rad per length unit;
    * turning input, sliding output: the velocity of ``Iij`` as a point of the
      input, along the output's line, per unit ω;
    * both sliding: the ratio of the travels whose difference is perpendicular
      to the direction of ``Iij`` at infinity.

    With several degrees of freedom this is the ratio of the speeds at the
    file's input speeds (the centers depend on them, Sec. 5.4).

    Parameters
    ----------
    sol : Solution or InstantCenters
    output : link id
    input : link id, optional
        Default: the drive's link (the file must have one drive).

    Returns
    -------
    ndarray

    Raises
    ------
    InputError
        No input given and the file has several drives.
    DegenerateError
        The input does not move relative to the output's motion (a ratio over zero).

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.17, Eqs. 3.23-3.26; Examples 3.13, 3.14.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.examples.fourbar().solve()
    >>> round(float(kinematic_coefficient(sol, 4)), 4)  # ω4/ω2 = 49.50/94.25 rad/s (Example 3.1)
    0.5252
    """
    ic = _centers(sol)
    mech = ic.solution.mechanism
    input = _input_link(mech, input)
    i, j = str(input), str(output)
    if i == j:
        return np.ones(np.shape(ic.solution.links[FRAME].angle))
    a = ic[(FRAME, i)].point
    b = ic[(FRAME, j)].point
    c = ic[(i, j)].point
    # a slider's speed is its travel ṙ; a link that can turn has speed ω, even
    # at an instant when it does not turn (its center at infinity, ω = 0)
    shape = np.shape(g.is_ideal(c))
    ia = np.full(shape, _translates(mech, i))
    ib = np.full(shape, _translates(mech, j))
    with np.errstate(invalid="ignore", divide="ignore"):
        rot_rot = _ratio_homogeneous(a, b, c)
        out = rot_rot
        if np.any(ia) or np.any(ib):
            # the velocity of Iij: ω_i k×(C - A) per unit ω_i, or s_i per unit ṙ_i
            ci = g.xy(c)
            s_i = _slide_direction(ic, i, FRAME) if np.any(ia) else np.zeros(c.shape[:-1] + (2,))
            s_j = _slide_direction(ic, j, FRAME) if np.any(ib) else np.zeros(c.shape[:-1] + (2,))
            v_c = np.where(ia[..., None], s_i, _perp(ci - g.xy(a)))
            rb = ci - g.xy(b)
            # turning output: ω_j = v_c · (k × R) / R²; 0 while its center is at infinity
            to_rot = np.where(g.is_ideal(b), 0.0, g.dot2(v_c, _perp(rb)) / g.dot2(rb, rb))
            # sliding output: ṙ_j = v_c · s_j
            to_slide = g.dot2(v_c, s_j)
            # both sliding, Iij at infinity in direction d: (ṙ_j s_j - ṙ_i s_i) ⊥ d
            d = c[..., :2]
            both = g.dot2(s_i, d) / g.dot2(s_j, d)
            mixed = np.where(ib, to_slide, to_rot)
            mixed = np.where(ia & ib & g.is_ideal(c), both, mixed)
            out = np.where(ia | ib, mixed, rot_rot)
    if _unbounded(ic, out):
        raise DegenerateError(f"the speed of link {j} per unit speed of link {i} is unbounded "
                              "here (the input is at a dead point)", links=(i, j))
    return out


def mechanical_advantage(sol: Solution | InstantCenters, output: object,
                         input: object | None = None) -> Array:
    """Mechanical advantage: output torque (force) over input torque (force), Eq. 3.34.

    With no friction or inertia, power in equals power out, so
    ``T_out / T_in = ω_in / ω_out`` (and ``F/T = ω/ṙ`` for a slider): the
    reciprocal of :func:`kinematic_coefficient`, from the instant centers.
    It is infinite in toggle (the output at rest), where this returns ``inf``.

    Parameters
    ----------
    sol : Solution or InstantCenters
    output : link id
    input : link id, optional
        Default: the drive's link.

    Returns
    -------
    ndarray
        Signed: negative when output and input turn opposite ways.

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.19, Eqs. 3.34-3.35.

    Examples
    --------
    >>> import graphkin
    >>> sol = graphkin.examples.fourbar().solve()
    >>> round(float(mechanical_advantage(sol, 4)), 4)  # ω2/ω4 = 1/0.5252
    1.9039
    """
    ic = _centers(sol)
    mech = ic.solution.mechanism
    input = _input_link(mech, input)
    k = kinematic_coefficient(ic, output, input)
    with np.errstate(divide="ignore"):
        return np.where(k == 0.0, np.inf, 1.0 / np.where(k == 0.0, 1.0, k))
