"""Posture steps of the drives that are not a pinned link's angle or a slider's travel.

* A joint angle between two moving links, ``θ3/2 = θ3 − θ2`` (the motor in a
  robot's elbow, Problems 5.7-5.11): as soon as one of the two links has its
  angle, the other's is laid off from it, ``θ3 = θ2 + θ3/2``; the link is then
  placed from any known point of it (case 1).
* A point's coordinates in the frame (the pantograph's tracing point,
  Problem 5.13): with ``x`` and ``y`` both given the point is located at
  once and the links that carry it have a known point; with one coordinate
  the point lies on the line ``x = x_P`` (or ``y = y_P``), which an arc about
  a known point of its link cuts (case 2, as a pin in a slot of the frame).

These are free functions on the posture builder
(:class:`graphkin.kinematics.posture._Builder`), kept apart so the builder's
module stays small.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (cases 1 and 2), Sec. 5.4 and
Problems 5.7-5.13.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from graphkin.construction import Mark, Role, Term, VectorEquation
from graphkin.mechanisms.model import FRAME, Drive, Mechanism, Rolling
from graphkin.tolerance import Tolerance

if TYPE_CHECKING:
    from graphkin.kinematics.posture import _Builder

__all__ = ["start_drive", "finish_pairs", "propagate_drives", "coordinate_groups", "do_coordinate",
           "coordinate_line_label", "carrier", "circle_ratio", "carrier_beta"]

K, U = Mark.KNOWN, Mark.UNKNOWN


def coordinate_line_label(d: Drive) -> str:
    """Label of the line ``x = x_P`` (or ``y = y_P``) of a one-coordinate drive."""
    return f"l_{d.kind}({d.point})"


def _partner(b: _Builder, d: Drive) -> Drive | None:
    """The other coordinate drive of the same point, if any."""
    return next((e for e in b.mech.drives if e is not d and e.point == d.point
                 and e.kind in ("x", "y")), None)


def start_drive(b: _Builder, d: Drive) -> bool:
    """Record the input of a relative or coordinate drive; False for the other kinds."""
    if d.kind not in ("relative", "x", "y"):
        return False
    lab = d.label
    b.inputs[lab] = d.value
    b.env[lab] = np.asarray(d.value)
    if d.kind == "relative":
        note = (f"The input: link {d.link} stands at θ{d.link}/{d.relative_to} = "
                f"{math.degrees(d.value):.6g}° to link {d.relative_to} (a joint angle).")
    else:
        note = (f"The input: point {d.point} has {d.kind}_{d.point} = {d.value:.6g} "
                f"{b.mech.length_unit}.")
    b.add("input", (), (lab,), name=lab, role=Role.GIVEN, note=note)
    b.events.append(("input", d))
    if d.kind == "relative":
        return True
    if _partner(b, d) is not None:
        return True  # located with its other coordinate (finish_pairs)
    line = coordinate_line_label(d)
    b.add("coordinate_line", (lab,), (line,), axis=d.kind,
          note=f"Draw the line {d.kind} = {d.label}: {d.point} lies on it.")
    return True


def finish_pairs(b: _Builder) -> None:
    """Place the points whose x and y are both driven (after every input is recorded)."""
    for d in b.mech.drives:
        if d.kind != "x" or d.point in b.env:
            continue
        other = _partner(b, d)
        if other is None:
            continue
        assert d.point is not None
        eq = VectorEquation((Term(f"R_{d.point}", U, U),),
                            (Term(f"x_{d.point}", K, K), Term(f"y_{d.point}", K, K)), case=1)
        b.add("point_xy", (d.label, other.label), (d.point,), role=Role.RESULT, equation=eq,
              note=f"Locate {d.point} at its given coordinates ({d.label}, {other.label}).")
        b.events.append(("point_drive", d, other))


def propagate_drives(b: _Builder) -> bool:
    """Lay off the angle of a link from the other link of a joint drive; True if any."""
    changed = False
    for d in b.mech.drives:
        if d.kind != "relative":
            continue
        i, j = d.link, d.relative_to
        assert j is not None
        if j in b.angle and i not in b.angle:
            b.add("add_angles", (b.angle[j], d.label), (f"θ{i}",), sign=1.0, role=Role.RESULT,
                  equation=VectorEquation((Term(f"θ{i}", U, U),),
                                          (Term(f"θ{j}"), Term(d.label, K, K)), case=1),
                  note=f"Lay off the joint angle from link {j}: θ{i} = θ{j} + {d.label}.")
            b.angle[i] = f"θ{i}"
            b.events.append(("relative_angle", d, True))
            changed = True
        elif i in b.angle and j not in b.angle:
            b.add("add_angles", (b.angle[i], d.label), (f"θ{j}",), sign=-1.0, role=Role.RESULT,
                  equation=VectorEquation((Term(f"θ{j}", U, U),),
                                          (Term(f"θ{i}"), Term(d.label, K, K, -1)), case=1),
                  note=f"Lay off the joint angle back from link {i}: θ{j} = θ{i} − {d.label}.")
            b.angle[j] = f"θ{j}"
            b.events.append(("relative_angle", d, False))
            changed = True
    return changed


def coordinate_groups(b: _Builder) -> list[tuple[Drive, str]]:
    """(drive, link) for each point with one driven coordinate that can be found now.

    The point's link turns about its one known point: an arc meets the line.
    """
    out = []
    for d in b.mech.drives:
        if d.kind not in ("x", "y") or _partner(b, d) is not None or d.point in b.env:
            continue
        assert d.point is not None
        for lid in b.mech.point_links.get(d.point, []):
            if lid not in b.placed and b.one_point(lid):
                out.append((d, lid))
                break
    return out


def do_coordinate(b: _Builder, d: Drive, lid: str, branch: str | None) -> list[str]:
    """Place the point of a one-coordinate drive: an arc about its link's known point (case 2)."""
    x = d.point
    assert x is not None
    (p, ploc), = b.distinct_known(lid)
    sloc = b.mech.links[lid].points[x]
    r = math.hypot(sloc[0] - ploc[0], sloc[1] - ploc[1])
    n = p.split("#")[0].split(":")[-1]
    k = f"k_{x}({n})"
    b.events.append(("coordinate", d, lid, p))
    if k not in b.env:
        b.add("circle", (p,), (k,), radius=r,
              note=f"About {n} draw an arc of radius {n}{x} = {r:.6g}.")
    names = ["behind", "ahead"]
    b.add("intersect_line_circle", (coordinate_line_label(d), k), (x,),
          branch=branch or names[0], role=Role.RESULT,
          equation=VectorEquation((Term(f"R_{x}", U, K),), (Term(f"R_{x}{n}", K, U),), case=2),
          note=f"The arc cuts the line {d.kind} = {d.label} at {x} (case 2).")
    return names


def start_phases(b: _Builder) -> None:
    """Each rolling contact places one link at the file's drive, as a drive does.

    The no-slip condition fixes a link's angle only up to a constant; at the
    file's drive the file gives it (:mod:`graphkin.kinematics.analytic.phase`):
    an angle, laid off as a given scalar, or a slider's travel, laid off along
    its line as soon as the line is drawn (``Builder.propagate``).
    """
    from graphkin.kinematics.analytic.phase import rolling_phases

    rolls = {r.key: r for r in b.mech.rolling}
    for ph in rolling_phases(b.mech):
        r = rolls[ph.key]
        if ph.link != r.link:  # not the rolling link itself: say which link it places
            b.notes.append(ph.describe(r.angle_given))
        if ph.kind == "angle":
            lid = ph.link
            if lid in b.angle or r.key in b.travel:  # travel: laid off from the travel
                continue
            lab = f"θ{lid}"
            who = "rolls" if lid == r.link else f"is turned by the rolling of {r.key}"
            b.add("scalar", (), (lab,), value=ph.value, role=Role.GIVEN,
                  note=f"Link {lid} {who}; at this drive it stands at "
                       f"θ{lid} = {math.degrees(ph.value):.6g}° (its reference).")
            b.angle[lid] = lab
            b.events.append(("roll_angle", r, lid))
            continue
        s = ph.slider
        assert s is not None
        b.add("scalar", (), (f"s{s.link}",), value=ph.value, role=Role.GIVEN,
              note=f"The slider {s.link} is moved by the rolling of {r.key}; at this "
                   f"drive it has travelled {ph.value:.6g} along its line (as drawn).")
        b.rolled.append((r, s))


def carrier(mech: Mechanism, r: Rolling) -> str | None:
    """The link (not the two gears) that holds both centers of a contact on a circle.

    The arm of a planetary train, or the frame for gears on fixed centers
    (Sec. 7.15); the frame first.  None for a contact on a line, or when no
    single link holds both centers.
    """
    if r.on_line or not r.fixed_centers or r.on_center_point is None:
        return None
    both = [lid for lid, link in mech.links.items() if lid not in (r.link, r.on)
            and r.center in link.points and r.on_center_point in link.points]
    if FRAME in both:
        return FRAME
    return both[0] if both else None


def circle_ratio(r: Rolling) -> float:
    """``k`` of the no-slip condition on a circle: ``(R + r)/r`` outside, ``-(R - r)/r`` inside.

    ``ω_l - ω_o = k (ω_m - ω_o)`` with ``m`` the link that holds both centers
    (Eq. 3.13; the train value of a planet, Sec. 7.15, Eq. 7.25).
    """
    big, rad = float(r.on_radius or 0.0), float(r.radius)
    return (big + rad) / rad if r.contact == "outside" else -(big - rad) / rad


def carrier_beta(mech: Mechanism, r: Rolling, m: str) -> float:
    """``β``: the angle of the line of centers ``O → P`` in the axes of ``m``, which holds both."""
    assert r.on_center_point is not None
    (ox, oy), (px, py) = mech.links[m].points[r.on_center_point], mech.links[m].points[r.center]
    return math.atan2(py - oy, px - ox)


#: The steps whose angle is counted on the covering when their angle inputs are: a given
#: angle, one laid off from another by a constant or a joint angle, a rolling link's.
_COVERING = {"input": (), "scalar": (), "add_angle": (0,), "add_angles": (0, 1),
             "roll_angle": (0,), "roll_circle_angle": (0, 1), "planetary_arm": (0, 1)}


def on_covering(b: _Builder, label: str) -> bool:
    """Whether the angle ``label`` is counted on continuously (not taken modulo 2π).

    An input, a given angle, or one laid off from such angles (a slider's
    angle, a joint angle, a rolling link's) is; an angle measured from two
    points (``link_angle``, an ``atan2``) is not: a gear laid off from it
    would jump by ``2π k`` where it wraps.
    """
    step = next((s for s in reversed(b.cx.steps) if label in s.outputs), None)
    if step is None or step.op not in _COVERING:
        return False
    return all(on_covering(b, step.inputs[i]) for i in _COVERING[step.op])


def _roll_circle(b: _Builder, r: Rolling, c: float) -> bool:
    """Lay off the angle of one gear of a contact on a circle from the other's and the arm's."""
    m = carrier(b.mech, r)
    if m is None or m not in b.angle or (r.link in b.angle) == (r.on in b.angle):
        return False
    known = r.on if r.link not in b.angle else r.link
    if not (on_covering(b, b.angle[m]) and on_covering(b, b.angle[known])):
        return False  # an angle measured modulo 2π: the analytic solver follows the covering
    k = circle_ratio(r)
    beta = carrier_beta(b.mech, r, m)
    rolling = r.link not in b.angle
    known, lid = (r.on, r.link) if rolling else (r.link, r.on)
    lab = f"θ{lid}"
    arm = "the frame" if m == FRAME else f"the arm {m}"
    b.add("roll_circle_angle", (b.angle[known], b.angle[m]), (lab,), k=k, beta=beta, c=c,
          solve="rolling" if rolling else "on", role=Role.RESULT,
          note=f"Gear {r.link} rolls on gear {r.on} without slip, both centers on {arm}: "
               f"θ{r.link} - θ{r.on} = k (θ{m} + β - θ{r.on}) + c with k = {k:.6g} "
               f"(Sec. 7.15), counted on continuously: {lab}.")
    b.angle[lid] = lab
    b.events.append(("roll_angle", r, lid))
    return True


def _train_row(mech: Mechanism, r: Rolling, p: str, m: str,
               c: float) -> tuple[float, float, float, float]:
    """Contact ``r`` as ``a θ_p + b θ_m = g θ_g + e`` (``p`` the planet, ``g`` the other gear)."""
    k, beta = circle_ratio(r), carrier_beta(mech, r, m)
    if p == r.link:  # θ_p = (1 - k) θ_g + k θ_m + k β + c
        return 1.0, -k, 1.0 - k, k * beta + c
    return 1.0 - k, k, 1.0, -k * beta - c  # θ_g = (1 - k) θ_p + k θ_m + k β + c


def _roll_arm(b: _Builder) -> bool:
    """The arm of two contacts that share a planet, from the two other gears (Sec. 7.15).

    A planet ``p`` meshing with a first gear ``F`` and a last gear ``L`` on one
    arm ``A`` (a sun driven, a ring fixed, the arm the output): neither
    contact alone gives an angle, both together give the arm's, the
    integrated form of the train formula ``(ω_L - ω_A)/(ω_F - ω_A) = e``
    (Eq. 7.25)::

        θ_A = u θ_F + v θ_L + w,

    eliminating ``θ_p`` between the two contacts' rows (:func:`_train_row`);
    the planet then follows from one contact (``roll_circle_angle``).
    """
    from graphkin.tolerance import is_zero

    rolls = [r for r in b.mech.rolling if r.key in b.travel and not r.on_line]
    done = {id(ev[1]) for ev in b.events if ev[0] == "roll_angle"}
    for i, r1 in enumerate(rolls):
        for r2 in rolls[i + 1:]:
            m = carrier(b.mech, r1)
            if m is None or m != carrier(b.mech, r2) or m in b.angle \
                    or id(r1) in done or id(r2) in done:
                continue
            shared = {r1.link, r1.on} & {r2.link, r2.on}
            if len(shared) != 1:
                continue
            (p,) = shared
            g1 = r1.on if p == r1.link else r1.link
            g2 = r2.on if p == r2.link else r2.link
            if p in b.angle or g1 not in b.angle or g2 not in b.angle \
                    or not (on_covering(b, b.angle[g1]) and on_covering(b, b.angle[g2])):
                continue
            a1, b1, c1, e1 = _train_row(b.mech, r1, p, m, b.travel[r1.key])
            a2, b2, c2, e2 = _train_row(b.mech, r2, p, m, b.travel[r2.key])
            det = a2 * b1 - a1 * b2
            if is_zero(det, max(abs(a1 * b2), abs(a2 * b1))):
                continue  # the two contacts turn the planet alike: they do not fix the arm
            u, v, w = a2 * c1 / det, -a1 * c2 / det, (a2 * e1 - a1 * e2) / det
            lab = f"θ{m}"
            b.add("planetary_arm", (b.angle[g1], b.angle[g2]), (lab,), u=u, v=v, w=w,
                  role=Role.RESULT,
                  note=f"The planet {p} meshes with gear {g1} ({r1.key}) and gear {g2} "
                       f"({r2.key}) on the arm {m}: the train formula integrated "
                       f"(Sec. 7.15, Eq. 7.25) gives the arm, θ{m} = {u:.6g} θ{g1} "
                       f"+ {v:.6g} θ{g2} + {w:.6g}.")
            b.angle[m] = lab
            b.events.append(("roll_angle", r2, m))
            return True
    return False


def roll_angles(b: _Builder) -> bool:
    """Lay off each roller's angle from its travel once its center and its line are drawn.

    A circle rolling on a line without slip turns with its travel:
    ``θ_l = θ_o + c - σ s/ρ`` (Sec. 2.19, Eq. b; Example 3.9), ``s`` the
    travel of its center along the line, ``c`` the constant of the file's
    posture (:attr:`_Builder.travel`).  Only a contact whose roller the file
    places by its angle, on a line.  A gear rolling on a circle whose center
    and the other's are held by one link (a planet on its arm) turns with that
    link: ``θ_l = θ_o + k (θ_m + β - θ_o) + c`` (``roll_circle_angle``), as
    soon as the arm's angle and one gear's are known.  Returns whether a step
    was added.
    """
    added = False
    for r in b.mech.rolling:
        c = b.travel.get(r.key)
        if c is None:
            continue
        if not r.on_line:
            added = _roll_circle(b, r, c) or added
            continue
        if r.link in b.angle or r.center not in b.env or r.on not in b.placed \
                or f"{r.key}:L0" not in b.env or r.on not in b.angle:
            continue
        lab = f"θ{r.link}"
        sigma = 1.0 if r.side == "left" else -1.0
        b.add("roll_angle", (b.angle[r.on], r.center, f"{r.key}:L0", f"{r.key}:L1"), (lab,),
              c=c, k=sigma / float(r.radius), role=Role.RESULT,
              note=f"Link {r.link} rolls without slip: it turns by -σ s/ρ as its center "
                   f"{r.center} travels s along the line: {lab}.")
        b.angle[r.link] = lab
        b.events.append(("roll_angle", r, r.link))
        added = True
    return added or _roll_arm(b)


def rolling_travel(mech: Mechanism, tol: Tolerance) -> dict[str, float] | None:
    """The constant ``c`` of every rolling contact, when each roller's angle follows its travel.

    For a sweep (or a live page) away from the file's drive, a circle rolling
    on a line, placed at the file's drive by its own angle (its phase,
    :mod:`graphkin.kinematics.analytic.phase`), has the angle
    ``θ_l = θ_o + c - σ s/ρ``; a gear rolling on a circle whose two centers
    one link ``m`` holds has ``θ_l = θ_o + k (θ_m + β - θ_o) + c``
    (:func:`circle_ratio`, :func:`carrier_beta`).  ``c`` is read from the
    construction at the file's drive.  None when a contact is of neither kind
    (a roller on a line whose phase places another link; a circle whose
    centers no one link holds) or the file's posture is not constructed.
    """
    from graphkin.errors import GraphkinError
    from graphkin.kinematics.analytic.phase import rolling_phases
    from graphkin.kinematics.posture import build_posture

    phases = {p.key: p for p in rolling_phases(mech)}
    for r in mech.rolling:
        ph = phases.get(r.key)
        if ph is None or ph.kind != "angle":
            return None
        if r.on_line and ph.link != r.link:
            return None
        if not r.on_line and carrier(mech, r) is None:
            return None
    try:
        pc = build_posture(mech, tol)
    except GraphkinError:
        return None
    env = pc.values
    out: dict[str, float] = {}
    for r in mech.rolling:
        th_o = pc.angles.get(r.on)
        if not r.on_line:
            m = carrier(mech, r)
            assert m is not None
            labs = (pc.angles.get(r.link), th_o, pc.angles.get(m))
            if any(t is None or t not in env for t in labs):
                return None
            t_l, t_o, t_m = (float(np.asarray(env[t])) for t in labs if t is not None)
            # the constant of θ_l = θ_o + k (θ_m + β - θ_o) + c through the file's posture
            out[r.key] = t_l - t_o - circle_ratio(r) * (t_m + carrier_beta(mech, r, m) - t_o)
            continue
        names = (r.center, f"{r.key}:L0", f"{r.key}:L1")
        if th_o is None or any(n not in env for n in names):
            return None
        p, a, bb = (np.asarray(env[n], dtype=float) for n in names)
        p, a, bb = p[:2] / p[2], a[:2] / a[2], bb[:2] / bb[2]
        u = (bb - a) / float(np.hypot(*(bb - a)))
        s = float(np.dot(p - a, u))
        sigma = 1.0 if r.side == "left" else -1.0
        out[r.key] = phases[r.key].value - float(np.asarray(env[th_o])) + sigma * s / float(
            r.radius)
    return out
