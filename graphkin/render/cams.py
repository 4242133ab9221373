"""Drawings of a cam: its profile laid out by inversion, its displacement diagram.

The layout is drawn like Figs. 6.8-6.11, the displacement diagram with its
kinematic coefficients like Figs. 6.12-6.24.

Every element carries a gid (``profile``, ``prime-circle``, ``station-3-roller``,
``diagram-y1``, ``boundary-2`` ...) so that tests and pages find it in the SVG.
The drawings are built from the recorded layout (:func:`graphkin.cams.layout`):
the stations are the construction's values at equal cam angles.

References
----------
Uicker, Pennock & Shigley, 5th ed., Secs. 6.3-6.4, Figs. 6.8-6.11, 6.12-6.24.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle, FancyArrowPatch

from graphkin.cams import design
from graphkin.cams.analytic import profile
from graphkin.cams.layout import layout, stations
from graphkin.cams.model import Cam, FollowerKind
from graphkin.render.style import GREY, HIGHLIGHT, INK, rc_context
from graphkin.render.svg import save
from graphkin.text import g6
from graphkin.tolerance import DEFAULT_TOL

__all__ = ["layout_figure", "displacement_figure", "design_figure", "save_cam_figure"]

Array = np.ndarray
DASHDOT = (0, (8, 2, 1.5, 2))
PHANTOM = (0, (10, 2, 1.5, 2, 1.5, 2))


def _xy(p: Array) -> Array:
    return p[..., :2] / p[..., 2:3]


def _circle(ax: Any, c: tuple[float, float], r: float, gid: str, **kw: Any) -> None:
    patch = Circle(c, r, fill=False, **kw)
    patch.set_gid(gid)
    ax.add_patch(patch)


def layout_figure(cam: Cam, n: int = 12, fig: Any = None, upto: int | None = None) -> Any:
    """The layout of the profile by inversion, drawn like Figs. 6.8-6.11.

    The cam is held still; the follower is drawn at ``n`` stations 0, 1, 2, ...
    turned against the cam's rotation, with its centerline (or arm), its roller
    or face, and the profile drawn tangent to them all.  ``upto`` (``steps -d
    cam``) draws the first ``upto`` stations only, the newest highlighted, and
    leaves the profile and the pitch curve out until ``upto > n``; the framing
    is the whole drawing's in every case.
    """
    final = upto is None or upto > n
    fig = fig or Figure(figsize=(7.0, 7.4))
    ax = fig.add_axes((0.03, 0.06, 0.94, 0.86))
    ax.set_aspect("equal")
    ax.set_axis_off()
    lay = layout(cam)
    f = cam.follower
    fine = stations(1440)
    prof = lay.contact(fine)
    st = stations(n)
    ev = lay.evaluate(st)
    T = _xy(ev["T"])
    C = lay.contact(st)
    # circles of the cam
    _circle(ax, (0, 0), cam.prime, "prime-circle", color=GREY, lw=0.6, ls=PHANTOM)
    if f.kind.roller:
        _circle(ax, (0, 0), cam.base, "base-circle", color=GREY, lw=0.6)
    if f.offset and not f.kind.oscillating:
        _circle(ax, (0, 0), abs(f.offset), "offset-circle", color=GREY, lw=0.5)
    if f.kind.oscillating:
        _circle(ax, (0, 0), math.hypot(*f.pivot), "pivot-circle", color=GREY, lw=0.5,
                ls=PHANTOM)
    # the pitch curve (roller: the trace point's path) and the profile
    size = cam.prime + cam.program.lift * (1 if not f.kind.oscillating else f.arm) + f.roller
    pitch = None
    if f.kind.roller:
        pitch = _xy(lay.evaluate(fine)["T"])
    if f.kind.roller and final:
        assert pitch is not None
        ln, = ax.plot(np.append(pitch[:, 0], pitch[:1, 0]), np.append(pitch[:, 1], pitch[:1, 1]),
                      color=GREY, lw=0.6, ls=DASHDOT)
        ln.set_gid("pitch-curve")
    if final:
        ln, = ax.plot(np.append(prof.real, prof.real[:1]), np.append(prof.imag, prof.imag[:1]),
                      color=INK, lw=1.8, solid_joinstyle="round")
        ln.set_gid("profile")
    for j, cut in enumerate(design.undercuts(cam) if final else []):  # Figs. 6.25, 6.29
        th = np.linspace(cut.start, cut.end if cut.end >= cut.start else cut.end + 2 * math.pi,
                         200)
        z = lay.contact(th)
        ln, = ax.plot(z.real, z.imag, color=HIGHLIGHT, lw=2.2)
        ln.set_gid(f"undercut-{j}")
    # the stations
    reach = 0.12 * size
    drawn: list[Array] = []          # the ends of what is drawn, to frame the figure
    numbers: list[tuple[Any, Array]] = []   # each station's number and where it is asked for
    extent = design.face_width(cam)
    face_half = max(extent) if extent else reach
    for i in range(n):
        bold = i == 0
        lw = 1.1 if bold else 0.5
        col = INK if bold else GREY
        if not final and upto is not None and i >= upto:
            continue
        if not final and upto is not None and i == upto - 1:
            col, lw = HIGHLIGHT, 1.2           # the newest station (steps -d cam)
        t = T[i]
        if f.kind.oscillating:
            o4 = _xy(ev["O4"][i])
            arm_end = t
            ln, = ax.plot([o4[0], arm_end[0]], [o4[1], arm_end[1]], color=col, lw=lw)
            ln.set_gid(f"station-{i}-arm")
            dot, = ax.plot([o4[0]], [o4[1]], "o", ms=2.5, color=col)
            dot.set_gid(f"station-{i}-O4")
            anchor = o4 * (1 + 0.06 * size / max(np.hypot(*o4), 1e-300))
        else:
            a = _xy(ev["A"][i])
            fpt = _xy(ev["F"][i])
            d = (a - fpt) / np.hypot(*(a - fpt))
            tip = t + d * reach * (2.0 if bold else 1.0)
            base_pt = fpt if f.offset else a - d * 0.0
            ln, = ax.plot([base_pt[0], tip[0]], [base_pt[1], tip[1]], color=col, lw=lw,
                          ls="-" if bold else DASHDOT)
            ln.set_gid(f"station-{i}-axis")
            drawn.append(tip)
            anchor = a - d * (min(0.07 * size, 0.15 * cam.prime)
                              + (f.roller if f.kind.roller else 0.0))
        lbl = ax.text(anchor[0], anchor[1], str(i), ha="center", va="center", fontsize=7,
                      color=INK)
        lbl.set_gid(f"station-{i}-label")
        numbers.append((lbl, np.asarray(anchor, dtype=float)))
        if f.kind.roller:
            _circle(ax, (float(t[0]), float(t[1])), f.roller, f"station-{i}-roller", color=col,
                    lw=lw)
        elif f.kind.flat:
            c = np.array([C[i].real, C[i].imag])
            if f.kind is FollowerKind.FLAT_FACE:
                u = np.array([-d[1], d[0]])
                half = 0.5 * f.face if f.face else 1.1 * face_half
                p0, p1 = t - u * half, t + u * half
            else:
                u = (c - t) / max(np.hypot(*(c - t)), 1e-300)
                p0, p1 = t - u * 0.1 * size, c + u * 0.25 * size
            ln, = ax.plot([p0[0], p1[0]], [p0[1], p1[1]], color=col, lw=lw * 1.3)
            ln.set_gid(f"station-{i}-face")
            drawn += [p0, p1]
        else:
            dot, = ax.plot([t[0]], [t[1]], "o", ms=2.0, color=col)
            dot.set_gid(f"station-{i}-T")
        cc, = ax.plot([C[i].real], [C[i].imag], "o", ms=1.6, color=INK)
        cc.set_gid(f"station-{i}-C")
    # the shaft and the sense of rotation
    m = 0.05 * cam.prime
    ln, = ax.plot([-m, m, np.nan, 0, 0], [0, 0, np.nan, -m, m], color=INK, lw=0.8)
    ln.set_gid("O2")
    t2 = ax.text(0.6 * m, -0.6 * m, r"$O_2$", fontsize=8, ha="left", va="top")
    t2.set_gid("O2-label")
    r = 0.35 * cam.prime
    a0, a1 = (math.radians(200), math.radians(250)) if cam.s > 0 else \
        (math.radians(250), math.radians(200))
    arrow = FancyArrowPatch((r * math.cos(a0), r * math.sin(a0)),
                            (r * math.cos(a1), r * math.sin(a1)),
                            connectionstyle=f"arc3,rad={0.2 * cam.s}", arrowstyle="->",
                            mutation_scale=9, color=INK, lw=0.8)
    arrow.set_gid("rotation")
    ax.add_patch(arrow)
    w = ax.text(r * 1.05 * math.cos(math.radians(225)), r * 1.05 * math.sin(math.radians(225)),
                r"$\omega$", fontsize=8, ha="right", va="top")
    w.set_gid("rotation-label")
    # frame the drawing on everything drawn
    pts = np.concatenate([np.c_[prof.real, prof.imag], T, np.zeros((1, 2))])
    if f.kind.oscillating:
        pts = np.concatenate([pts, _xy(ev["O4"])])
    if drawn:
        pts = np.concatenate([pts, np.asarray(drawn)])
    if final:
        _nomenclature(ax, cam, prof, pitch if f.kind.roller else None, n, pts)
    lo, hi = np.nanmin(pts, axis=0), np.nanmax(pts, axis=0)
    pad = 0.18 * float(np.max(hi - lo))
    ax.set_xlim(lo[0] - pad, hi[0] + pad)
    ax.set_ylim(lo[1] - pad, hi[1] + pad)
    _station_numbers(ax, numbers, 0.02 * size)
    what = {FollowerKind.KNIFE_EDGE: "knife-edge", FollowerKind.ROLLER: "roller",
            FollowerKind.FLAT_FACE: "flat-face", FollowerKind.OSCILLATING_ROLLER:
            "oscillating roller", FollowerKind.OSCILLATING_FLAT_FACE:
            "oscillating flat-face"}[f.kind]
    title = fig.text(0.5, 0.965, (cam.title + " — " if cam.title else "")
                     + f"profile laid out by inversion ({what} follower)", ha="center",
                     va="top", fontsize=10)
    title.set_gid("title")
    note = (f"$R_0$ = {g6(cam.prime)} {cam.unit}"
            + (f", $R_r$ = {g6(f.roller)} {cam.unit}" if f.kind.roller else "")
            + (f", $\\varepsilon$ = {g6(f.offset)} {cam.unit}" if f.offset else "")
            + f"; stations every {g6(360 / n)}°, the follower turned against the cam")
    sub = fig.text(0.5, 0.03, note, ha="center", va="bottom", fontsize=8, color=GREY)
    sub.set_gid("note")
    return fig


def _station_numbers(ax: Any, numbers: list[tuple[Any, Array]], step: float) -> None:
    """Set each station's number on its ray from O2, off the profile, circles and followers.

    A number stands where it is asked for (inside the prime circle, or beyond an
    oscillating follower's pivot) when that place is clear; else the nearest clear
    place along the same ray, in or out by ``step`` at a time, so that it still
    reads as its station's; it may cross its own station's center line (or arm), the
    line it names, as the book's numbers stand at their lines' ends (Fig. 6.8), where
    nothing else is clear.  Before, Ex. 6.3's 9, 10 and 11 sat on the profile
    where it runs on the prime circle, and Ex. 6.7's 2 and 8 on rollers.
    """
    from graphkin.render.clearance import measuring

    if numbers:
        with measuring(ax.figure) as r:
            _settle_numbers(ax, numbers, step, r)


def _settle_numbers(ax: Any, numbers: list[tuple[Any, Array]], step: float, r: Any) -> None:
    from graphkin.render.clearance import Obstacles, settle

    obst = Obstacles(ax, r, skip=lambda gid: gid.startswith("station-")
                     and gid.endswith("-label"))
    for t, a in numbers:
        n = float(np.hypot(*a))
        u = a / n if n > 0 else np.array([0.0, 1.0])
        v = np.array([-u[1], u[0]])
        # along the ray, in and out (never nearer O2 than 0.4 of the way: the number stays
        # on its station's side), then a little to either side of it
        places = [(*(a + u * step * k + v * step * side), "center", "center")
                  for side in (0.0, 0.6, -0.6, 1.2, -1.2) for j in range(20)
                  for k in ((j, -j) if j else (0,))
                  if n + step * k >= 0.4 * n]
        i = (t.get_gid() or "").split("-")[1]
        settle(t, places, obst, r, own=frozenset({f"station-{i}-axis", f"station-{i}-arm"}))


def _nomenclature(ax: Any, cam: Cam, prof: Array, pitch: Array | None, n: int,
                  pts: Array) -> None:
    """Name the circles and curves as Fig. 6.8 does, with leaders out to the margin.

    Each name sits between two stations (half a station's angle off), on a
    ray from O2, beyond everything drawn; its leader ends on the curve or
    circle that ray meets.
    """
    reach = float(np.max(np.hypot(pts[:, 0], pts[:, 1]))) + \
        (cam.follower.roller if cam.follower.kind.roller else 0.0)
    step = 360.0 / n
    items: list[tuple[str, str, complex]] = []
    base_dir = 90.0 + step / 2

    def on_curve(z: Array, deg: float) -> complex:
        ang = np.angle(z)
        k = int(np.argmin(np.abs(np.angle(np.exp(1j * (ang - math.radians(deg)))))))
        return complex(z[k])

    names = [("profile", "cam profile", lambda d: on_curve(prof, d)),
             ("prime-circle", "prime circle", lambda d: cam.prime * np.exp(1j * math.radians(d)))]
    if pitch is not None:
        pz = pitch[:, 0] + 1j * pitch[:, 1]
        names.insert(1, ("pitch-curve", "pitch curve", lambda d: on_curve(pz, d)))
        names.append(("base-circle", "base circle",
                      lambda d: cam.base * np.exp(1j * math.radians(d))))
    # each name on the free ray where its curve stands farthest from the others
    rays = [base_dir + step * k for k in range(1, n)]       # not beside station 0's follower
    taken: set[int] = set()
    # the circles first: they stand apart from the profile only where the follower has risen
    for gid, text, where in sorted(names, key=lambda t: not t[0].endswith("circle")):
        def gap(deg: float, where: Any = where, gid: str = gid) -> float:
            # a circle stands apart where the curves leave it (circles keep their distance)
            z = complex(where(deg))
            return min(abs(z - complex(w(deg))) for g, _, w in names
                       if w is not where and not (gid.endswith("circle") and
                                                  g.endswith("circle")))

        free = [k for k in range(len(rays)) if k not in taken]
        apart = [k for k in free if k - 1 not in taken and k + 1 not in taken]
        # rays where the gaps are equal but for round-off (a dwell) keep their order
        order = sorted(apart or free, key=lambda k: round(-gap(rays[k]) / reach, 9))
        if not order:
            break
        taken.add(order[0])
        items.append((gid, text, complex(where(rays[order[0]]))))
    for gid, text, z in items:
        d = z / abs(z)
        at = d * reach * 1.1
        ha = "left" if d.real > 0.2 else "right" if d.real < -0.2 else "center"
        ann = ax.annotate(text, xy=(z.real, z.imag), xytext=(at.real, at.imag), fontsize=7.5,
                          ha=ha, va="center", color=INK,
                          arrowprops={"arrowstyle": "-|>", "color": GREY, "lw": 0.5,
                                      "mutation_scale": 6, "shrinkA": 1, "shrinkB": 0})
        ann.set_gid(f"name-{gid}")
        ann.arrow_patch.set_gid(f"name-{gid}-leader")
        pts.resize((len(pts) + 1, 2), refcheck=False)
        pts[-1] = (at.real, at.imag)


def displacement_figure(cam: Cam, fig: Any = None) -> Any:
    """The displacement diagram and y', y'' over one turn, one above the other (Fig. 6.24)."""
    fig = fig or Figure(figsize=(7.0, 7.4))
    prog = cam.program
    th = np.linspace(0.0, 2 * math.pi, 3601)
    k = prog.evaluate(th[:-1])
    deg = np.degrees(th[:-1])
    ang = cam.follower.kind.oscillating
    unit = "rad" if ang else cam.unit
    rows = [("Y", k.Y, f"(a) displacement Y, {unit}"),
            ("y1", k.y1, f"(b) \u201cvelocity\u201d y', {unit}/rad"),
            ("y2", k.y2, f"(c) \u201cacceleration\u201d y'', {unit}/rad\u00b2")]
    axes = fig.subplots(3, 1, sharex=True, gridspec_kw={"hspace": 0.35})
    starts = np.degrees(prog.starts)
    letters = [chr(ord("A") + i) for i in range(len(prog.segments))]
    for ax, (key, y, label) in zip(axes, rows):
        # break the line at the joints, so that a jump shows as a jump
        br = np.flatnonzero(np.diff(k.segment) != 0) + 1
        xs = np.insert(deg, br, np.nan)
        ys = np.insert(y, br, np.nan)
        ln, = ax.plot(xs, ys, color=INK, lw=1.2)
        ln.set_gid(f"diagram-{key}")
        ax.axhline(0.0, color=GREY, lw=0.5).set_gid(f"zero-{key}")
        for j, s in enumerate(starts):
            if j == 0:
                continue
            ax.axvline(s, color=GREY, lw=0.5, ls=(0, (3, 2))).set_gid(f"boundary-{key}-{j}")
        ax.set_ylabel(label, fontsize=8)
        ax.tick_params(labelsize=7)
        order = {"Y": 0, "y1": 1, "y2": 2}[key]
        if cam.omega and order:          # the same curve read in time rates (Eq. 6.11)
            w = cam.omega ** order
            sec = ax.secondary_yaxis("right", functions=(lambda v, w=w: v * w,
                                                         lambda v, w=w: v / w))
            sec.set_ylabel(f"{('velocity', 'acceleration')[order - 1]}, {unit}/s"
                           + ("\u00b2" if order == 2 else ""), fontsize=8)
            sec.tick_params(labelsize=7)
            sec.set_gid(f"rate-axis-{key}")
        ax.set_xlim(0, 360)
        ax.spines[["top", "right"]].set_visible(False)
    for j, s in enumerate(list(starts) + [360.0]):
        name = letters[j % len(prog.segments)]
        t = axes[0].text(s, 1.02, name, transform=axes[0].get_xaxis_transform(), ha="center",
                         va="bottom", fontsize=8)
        t.set_gid(f"joint-{j}")
    names: list[tuple[Any, float, float]] = []
    for j, seg in enumerate(prog.segments):
        mid = float(starts[j] + math.degrees(seg.angle) / 2)
        txt = seg.name or (seg.motion.value if seg.kind != "dwell" else "dwell")
        t = axes[2].text(mid, 0.02, txt, transform=axes[2].get_xaxis_transform(),
                         ha="center", va="bottom", fontsize=6.5, color=GREY)
        t.set_gid(f"segment-label-{j}")
        names.append((t, float(starts[j]), math.degrees(seg.angle)))
    axes[2].set_xlabel("cam angle \u0398, degrees", fontsize=8)
    axes[2].set_xticks(np.arange(0, 361, 45))
    title = fig.suptitle((cam.title + " — " if cam.title else "") + "displacement diagram",
                         fontsize=10)
    title.set_gid("title")
    _segment_names(axes[2], names)
    return fig


_JOINTS = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
_SHORT = {"modified-trapezoid": "mod. trap.", "half-cycloidal": "½ cycl.",
          "half-harmonic": "½ harm.", "cycloidal": "cycl.", "harmonic": "harm.",
          "polynomial8": "poly. 8", "parabolic": "parab."}
"""Shorter names of the standard motions, for a segment too narrow for the whole name."""


def _segment_names(ax: Any, names: list[tuple[Any, float, float]]) -> None:
    """Set each segment's name inside its span of the y'' plot, off the curve and the joints.

    Tried at the foot of the plot, then at its head, from the middle of the segment
    outward; a segment too narrow for its name takes a shorter one (``cycl.``), then
    its joints' letters (``DE``, as the letters over plot (a)); before, Ex. 6.8's
    "parabolic" stood on y'' = -37 and on the jump at 255°,
    and Ex. 6.2's "CD" on the trough of y''.
    """
    from graphkin.render.clearance import Obstacles, measuring, settle

    with measuring(ax.figure) as r:
        ax.get_xlim(), ax.get_ylim()
        obst = Obstacles(ax, r, skip=lambda gid: gid.startswith("segment-label-"))
        for j, (t, start, span) in enumerate(names):
            mid = start + span / 2
            places = [(mid + span * f, y, "center", va)
                      for y, va in ((0.02, "bottom"), (0.98, "top"), (0.5, "center"))
                      for f in (0.0, -0.125, 0.125, -0.25, 0.25, -0.35, 0.35)]
            full = t.get_text()
            # a name wider than its segment: shorter, then the segment's joints ("DE")
            pair = _JOINTS[j % 26] + _JOINTS[(j + 1) % len(names) % 26]
            for text in dict.fromkeys([full, _SHORT.get(full, full), pair]):
                t.set_text(text)
                if settle(t, places, obst, r, last=False):
                    break
            else:
                t.set_text(full)
                settle(t, places, obst, r)


def design_figure(cam: Cam, fig: Any = None) -> Any:
    """The pressure angle and the radius of curvature over one turn (Secs. 6.9-6.10).

    The largest |φ| and the least convex radius are marked; an undercut
    stretch is shaded.
    """
    fig = fig or Figure(figsize=(7.0, 5.6))
    th = stations(3600)
    pr = profile(cam, th)
    deg = np.degrees(th)
    chk = design.check(cam)
    axes = fig.subplots(2, 1, sharex=True, gridspec_kw={"hspace": 0.3})
    # a pressure angle within round-off of zero is zero (a circular cam's is 1e-15 rad: drawn
    # as it came, its plot was noise scaled to fill the axes, its note "8.2e-15°")
    phi = np.where(np.abs(pr.pressure) <= DEFAULT_TOL.angle, 0.0, pr.pressure)
    ln, = axes[0].plot(deg, np.degrees(phi), color=INK, lw=1.2)
    ln.set_gid("pressure-angle")
    m = chk.pressure
    i = int(np.argmin(np.abs(np.angle(np.exp(1j * (th - m.theta))))))
    mk, = axes[0].plot([math.degrees(m.theta)], [math.degrees(phi[i])], "o", ms=4,
                       color=HIGHLIGHT)
    mk.set_gid("pressure-max")
    some = abs(m.value) > DEFAULT_TOL.angle
    notes = [(axes[0], f"|\u03c6|max = {g6(math.degrees(m.value)) if some else 0}\u00b0",
              (math.degrees(m.theta), math.degrees(phi[i])), "pressure-max-label")]
    axes[0].set_ylabel("pressure angle \u03c6, degrees", fontsize=8)
    rho = pr.rho
    ok = np.isfinite(rho)
    big = np.percentile(np.abs(rho[ok]), 90) * 3 if np.any(ok) else 1.0
    ln, = axes[1].plot(deg, np.where(np.abs(rho) <= big, rho, np.nan), color=INK, lw=1.2)
    ln.set_gid("radius-of-curvature")
    if chk.rho is not None:
        r = chk.rho
        mk, = axes[1].plot([math.degrees(r.theta)], [r.value], "o", ms=4, color=HIGHLIGHT)
        mk.set_gid("radius-min")
        notes.append((axes[1], f"\u03c1min = {g6(r.value)} {cam.unit}",
                      (math.degrees(r.theta), r.value), "radius-min-label"))
    for j, cut in enumerate(chk.undercut):
        for a, b in ((cut.start, cut.end),) if cut.end >= cut.start else \
                ((cut.start, 2 * math.pi), (0.0, cut.end)):
            for ax in axes:
                ax.axvspan(math.degrees(a), math.degrees(b), color=HIGHLIGHT, alpha=0.15,
                           lw=0).set_gid(f"undercut-{j}")
    axes[1].set_ylabel(f"radius of curvature \u03c1, {cam.unit}\n(convex +)", fontsize=8)
    axes[1].set_xlabel("cam angle \u0398, degrees", fontsize=8)
    axes[1].set_xticks(np.arange(0, 361, 45))
    for ax in axes:
        ax.axhline(0.0, color=GREY, lw=0.5)
        ax.set_xlim(0, 360)
        ax.tick_params(labelsize=7)
        ax.spines[["top", "right"]].set_visible(False)
    title = fig.suptitle((cam.title + " \u2014 " if cam.title else "")
                         + "pressure angle and radius of curvature", fontsize=10)
    title.set_gid("title")
    _notes(fig, notes)
    return fig


def _notes(fig: Any, notes: list[tuple[Any, str, tuple[float, float], str]]) -> None:
    """Set each extreme's note beside its marker, off the curves and the other notes.

    Tried nearest first, eight ways round (:func:`graphkin.render.clearance.ring`);
    a note set farther than a few points keeps a leader to its marker.  Before,
    the note stood at a fixed offset, across the curve where it climbs past the
    marker (Ex. 6.4's |φ|max) or under the axis where the marker is at the
    bottom (Ex. 6.3's ρmin).
    """
    from graphkin.render.clearance import Obstacles, measuring

    with measuring(fig) as r:
        seen: dict[int, Obstacles] = {}
        for ax, text, xy, gid in notes:
            _note(ax, text, xy, gid, seen, r)


def _note(ax: Any, text: str, xy: tuple[float, float], gid: str, seen: dict[int, Any],
          r: Any) -> None:
    """One extreme's note (see :func:`_notes`)."""
    from graphkin.render.clearance import Obstacles, ring, settle

    ax.get_xlim(), ax.get_ylim()          # the limits final before anything is measured
    obst = seen.get(id(ax)) or seen.setdefault(id(ax), Obstacles(ax, r))
    t = ax.annotate(text, xy=xy, xytext=(6, 6), textcoords="offset points", fontsize=7.5,
                    arrowprops={"arrowstyle": "-", "color": GREY, "lw": 0.5,
                                "shrinkA": 1, "shrinkB": 3})
    t.set_gid(gid)
    leader = t.arrow_patch
    assert leader is not None
    leader.set_gid(f"{gid}-leader")
    settle(t, ring(), obst, r)
    x, y = t.get_position()
    if math.hypot(x, y) < 10:
        leader.set_visible(False)   # beside its marker: no leader


def save_cam_figure(cam: Cam, path: str | Path, *, diagram: str = "layout",
                    stations: int = 12) -> Path:
    """Draw ``diagram`` (``layout``, ``displacement`` or ``design``); save it (.svg/.png/.pdf)."""
    with rc_context():
        if diagram == "layout":
            fig = layout_figure(cam, stations)
        elif diagram == "design":
            fig = design_figure(cam)
        else:
            fig = displacement_figure(cam)
    return save(fig, path)
