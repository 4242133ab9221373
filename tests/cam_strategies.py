"""Hypothesis strategies for cams: random programs and random cams of every follower kind."""

from __future__ import annotations

import math

from hypothesis import strategies as st

from graphkin.cams import Cam, Follower, FollowerKind, Motion, Program, Rest, Segment, Sense

FULL = [Motion.HARMONIC, Motion.CYCLOIDAL, Motion.POLYNOMIAL8, Motion.POLYNOMIAL345,
        Motion.MODIFIED_TRAPEZOID, Motion.PARABOLIC]


@st.composite
def programs(draw, lift: float = 1.0) -> Program:
    """Rises, dwells and returns from Y = 0 back to Y = 0 over 360°.

    Every segment starts where the last ended (the program chains lifts), so
    every one is a valid program; slopes may jump (reported, not refused).
    """
    n = draw(st.integers(2, 5))
    weights = draw(st.lists(st.floats(0.5, 3.0), min_size=n, max_size=n))
    angles = [2 * math.pi * w / sum(weights) for w in weights]
    segs = []
    y = 0.0
    for i, a in enumerate(angles):
        if i == n - 1:
            h = -y
        else:
            h = draw(st.floats(-y, lift - y))
            if abs(h) < 1e-3 * lift:
                h = 0.0
        if h == 0.0:
            segs.append(Segment(Motion.DWELL, 0.0, a))
            continue
        motion = draw(st.sampled_from(FULL + [Motion.HALF_HARMONIC, Motion.HALF_CYCLOIDAL]))
        rest = draw(st.sampled_from(list(Rest))) if motion in (Motion.HALF_HARMONIC,
                                                                Motion.HALF_CYCLOIDAL) else None
        segs.append(Segment(motion, h, a, rest))
        y += h
    if abs(segs[-1].lift) == 0.0 and y != 0.0:   # pragma: no cover - h = -y above
        raise AssertionError
    return Program(tuple(segs))


@st.composite
def cams(draw, kinds=tuple(FollowerKind)) -> Cam:
    """A cam of a random follower kind, sized so that it can be laid out."""
    kind = draw(st.sampled_from(list(kinds)))
    sense = draw(st.sampled_from(list(Sense)))
    if kind.oscillating:
        swing = draw(st.floats(0.05, 0.3))        # rad; |y'| stays well below 1
        prog = draw(programs(lift=swing))
        prime = draw(st.floats(1.0, 3.0))
        d = prime + draw(st.floats(0.5, 3.0))
        ang = draw(st.floats(-math.pi, math.pi))
        pivot = (d * math.cos(ang), d * math.sin(ang))
        rise = draw(st.sampled_from(list(Sense)))
        if kind is FollowerKind.OSCILLATING_ROLLER:
            arm = draw(st.floats(0.6, 1.4)) * d
            arm = min(max(arm, d - prime + 0.1), d + prime - 0.1)
            fol = Follower(kind, roller=draw(st.floats(0.05, 0.8)) * prime, pivot=pivot,
                           arm=arm, rise=rise)
        else:
            fol = Follower(kind, pivot=pivot, face_offset=draw(st.floats(0.0, 0.4)) * (d - prime),
                           rise=rise)
        return Cam(prog, prime, fol, sense)
    lift = draw(st.floats(0.5, 50.0))
    prog = draw(programs(lift=lift))
    prime = lift * draw(st.floats(0.8, 4.0))
    fol = Follower(kind, offset=draw(st.floats(-0.6, 0.6)) * prime,
                   roller=draw(st.floats(0.05, 0.9)) * prime if kind.roller else 0.0)
    return Cam(prog, prime, fol, sense)


def cam_toml(cam: Cam) -> str:
    """A cam file (docs/formats/cam.md) written by hand from a Cam (test-only)."""
    f = cam.follower
    osc = f.kind.oscillating
    lines = ['units = "mm"', "[cam]", f"prime = {cam.prime!r}", f'rotation = "{cam.sense.value}"',
             "[follower]", f'kind = "{f.kind.value}"']
    if f.kind.roller:
        lines.append(f"roller = {f.roller!r}")
    if osc:
        lines += [f"pivot = [{f.pivot[0]!r}, {f.pivot[1]!r}]", f'rise = "{f.rise.value}"']
        lines.append(f"arm = {f.arm!r}" if f.kind.roller else f"face_offset = {f.face_offset!r}")
    else:
        lines.append(f"offset = {f.offset!r}")
    for s in cam.program.segments:
        lift = f'"{s.lift!r} rad"' if osc else repr(s.lift)
        lines += ["[[segment]]", f'motion = "{s.motion.value}"', f'angle = "{s.angle!r} rad"']
        if s.lift != 0.0:
            lines.append(f"lift = {lift}")
        if s.rest is not None:
            lines.append(f'rest = "{s.rest.value}"')
    return "\n".join(lines) + "\n"
