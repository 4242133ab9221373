"""Generators of large valid mechanism files (test helpers and benchmarks).

``fourbar_chain(stages)`` chains four-bar stages: the rocker of each stage is
the crank of the next (links 1 + 1 + 2·stages; 14 stages are 30 links), every
pin hinted.  ``driven_cranks(n)`` is the frame and ``n`` cranks, each driven
(``n + 1`` links, ``n`` drives).  The posture is computed here by plain
circle intersections (not by graphkin), and every link's points are written
at that posture, so the file's drawing is the posture itself.
"""

from __future__ import annotations

import math

__all__ = ["fourbar_chain", "driven_cranks", "chain_posture"]

# each stage: crank 4 from its pivot, coupler 12, rocker 11, the next pivot 10 on
# (crank + frame = 14 < coupler + rocker = 23: a crank-rocker, it assembles at any crank angle)
CRANK, COUPLER, ROCKER, PITCH = 4.0, 12.0, 11.0, 10.0


def _meet_above(p: tuple[float, float], r: float, q: tuple[float, float],
                s: float) -> tuple[float, float]:
    """The meet of circles (p, r) and (q, s) left of the directed line p→q."""
    dx, dy = q[0] - p[0], q[1] - p[1]
    d = math.hypot(dx, dy)
    a = (r * r - s * s + d * d) / (2 * d)
    h = math.sqrt(max(r * r - a * a, 0.0))
    mx, my = p[0] + a * dx / d, p[1] + a * dy / d
    return (mx - h * dy / d, my + h * dx / d)


def chain_posture(stages: int, angle_deg: float = 60.0,
                  scale: float = 1.0) -> list[dict[str, tuple[float, float]]]:
    """The points A (pivot), B (crank pin), C (coupler-rocker pin), D (next pivot) of each stage."""
    out = []
    th = math.radians(angle_deg)
    for k in range(stages):
        a = (PITCH * k * scale, 0.0)
        d = (PITCH * (k + 1) * scale, 0.0)
        b = (a[0] + CRANK * scale * math.cos(th), a[1] + CRANK * scale * math.sin(th))
        c = _meet_above(b, COUPLER * scale, d, ROCKER * scale)
        out.append({"A": a, "B": b, "C": c, "D": d})
        # the next crank is the rocker: its pin stands 4 from D, turned 100° from DC
        th = math.atan2(c[1] - d[1], c[0] - d[0]) + math.radians(100.0)
    return out


def _xy(p: tuple[float, float]) -> str:
    return f"[{p[0]!r}, {p[1]!r}]"


def fourbar_chain(stages: int, angle_deg: float = 60.0, scale: float = 1.0,
                  hints: bool = True) -> str:
    """The TOML of ``stages`` chained four-bars (``2 + 2·stages`` links)."""
    post = chain_posture(stages, angle_deg, scale)
    lines = [f'title = "Chain of {stages} four-bar stages"', 'units = { length = "mm" }', "",
             "[links.1]"]
    for k, s in enumerate(post):
        if k == 0:
            lines.append(f"A0 = {_xy(s['A'])}")
        lines.append(f"A{k + 1} = {_xy(s['D'])}")
    # the driven crank in its own coordinates (the drive angle turns its x axis)
    lines += ["", "[links.2]", f"A0 = {_xy(post[0]['A'])}",
              f"B0 = {_xy((post[0]['A'][0] + CRANK * scale, 0.0))}"]
    for k, s in enumerate(post):
        coupler, rocker = 2 * k + 3, 2 * k + 4
        lines += ["", f"[links.{coupler}]", f"B{k} = {_xy(s['B'])}", f"C{k} = {_xy(s['C'])}"]
        lines += ["", f"[links.{rocker}]", f"A{k + 1} = {_xy(s['D'])}", f"C{k} = {_xy(s['C'])}"]
        if k + 1 < stages:
            lines.append(f"B{k + 1} = {_xy(post[k + 1]['B'])}")
    lines += ["", "[drive]", "link = 2", f"angle = {angle_deg!r}", "omega = 10", "alpha = 0"]
    if hints:
        lines += ["", "[assembly]"]
        lines += [f"C{k} = {_xy(s['C'])}" for k, s in enumerate(post)]
    return "\n".join(lines) + "\n"


def driven_cranks(n: int) -> str:
    """The TOML of the frame and ``n`` cranks, each pinned to the frame and driven."""
    lines = [f'title = "{n} driven cranks"', 'units = { length = "mm" }', "", "[links.1]"]
    lines += [f"O{i} = [{10 * i}, 0]" for i in range(n)]
    for i in range(n):
        lines += ["", f"[links.{i + 2}]", f"O{i} = [{10 * i}, 0]", f"P{i} = [{10 * i + 3}, 0]"]
    for i in range(n):
        lines += ["", "[[drive]]", f"link = {i + 2}", f"angle = {(7 * i) % 360}", "omega = 1",
                  "alpha = 0"]
    return "\n".join(lines) + "\n"
