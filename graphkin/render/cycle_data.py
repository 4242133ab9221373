"""The data of the animation: a mechanism swept through its cycle, as compact JSON.

:func:`cycle_data` sweeps the mechanism (the same constructions as one
posture, evaluated on arrays) and returns the postures, velocity and
acceleration images of every named point, the links' outlines, the ranges
where the linkage cannot be assembled and the limit postures, with each series
stored as integers of a stated quantum (:data:`QUANTUM`).  The page
(:mod:`graphkin.render.animate`) and the SVG frames
(:mod:`graphkin.render.cycle_frames`) both draw from it.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (velocity polygons and images),
Sec. 4.4 (acceleration polygons), Sec. 3.13 (instant centers), Sec. 4.15
(the inflection circle), Sec. 1.10 (limit and dead-center postures).
"""


import math
from typing import Any

import numpy as np

from graphkin.mechanisms.model import FRAME, Mechanism, Slider, Slot
from graphkin.render.scale import choose_scale, paper_unit

__all__ = ["cycle_data", "QUANTUM"]

QUANTUM = 2e-5
"""Each series is stored as integers of this fraction of its largest size."""



def _fill(shape: str) -> str:
    """A link's fill as ``draw`` paints it (render/style.py): a plate grey, a bar white."""
    from graphkin.render.style import STYLES

    return str(STYLES["plate" if shape == "plate" else "link"]["fc"])


def _series(a: Any, q: float) -> list[int | None]:
    """A float array as integers of the quantum ``q`` (None where not defined)."""
    arr = np.asarray(a, dtype=float)
    out: list[int | None] = []
    ints = np.where(np.isfinite(arr), np.round(np.nan_to_num(arr) / q), 0).astype(np.int64)
    for ok, v in zip(np.isfinite(arr).tolist(), ints.tolist()):
        out.append(int(v) if ok else None)
    return out


def _quantum(*arrays: Any) -> float:
    """The quantum of a group of series: QUANTUM of their largest finite size."""
    big = 0.0
    for a in arrays:
        arr = np.abs(np.asarray(a, dtype=float))
        arr = arr[np.isfinite(arr)]
        if arr.size:
            big = max(big, float(arr.max()))
    q = QUANTUM * (big if big > 0 else 1.0)
    return float(f"{q:.3g}")


def _hull_order(local: dict[str, tuple[float, float]]) -> list[str]:
    """The points of a rigid link in order around it (convex hull of its own coordinates)."""
    names = list(local)
    if len(names) <= 2:
        return names
    pts = np.array([local[n] for n in names], dtype=float)
    c = pts.mean(axis=0)
    ang = np.arctan2(pts[:, 1] - c[1], pts[:, 0] - c[0])
    order = [names[i] for i in np.argsort(ang)]
    # keep only the hull (drop points inside), by the monotone chain
    P = sorted(names, key=lambda n: (local[n][0], local[n][1]))

    def cross(o: str, a: str, b: str) -> float:
        (ox, oy), (ax, ay), (bx, by) = local[o], local[a], local[b]
        return (ax - ox) * (by - oy) - (ay - oy) * (bx - ox)

    lower: list[str] = []
    for p in P:
        while len(lower) >= 2 and cross(lower[-2], lower[-1], p) <= 0:
            lower.pop()
        lower.append(p)
    upper: list[str] = []
    for p in reversed(P):
        while len(upper) >= 2 and cross(upper[-2], upper[-1], p) <= 0:
            upper.pop()
        upper.append(p)
    hull = lower[:-1] + upper[:-1]
    return hull if len(hull) >= 3 else order


def _rounded_view(lo: np.ndarray, hi: np.ndarray, pad: float) -> list[float]:
    span = np.maximum(hi - lo, 1e-12)
    m = pad * float(max(span))
    return [float(lo[0] - m), float(lo[1] - m), float(hi[0] + m), float(hi[1] + m)]


def _robust_box(xs: list[np.ndarray], ys: list[np.ndarray],
                keep: float = 98.0) -> tuple[np.ndarray, np.ndarray]:
    """A box holding the points at most postures (outliers near a toggle are clipped)."""
    x = np.concatenate([np.ravel(a) for a in xs]) if xs else np.zeros(1)
    y = np.concatenate([np.ravel(a) for a in ys]) if ys else np.zeros(1)
    ok = np.isfinite(x) & np.isfinite(y)
    if not ok.any():
        return np.zeros(2) - 1, np.zeros(2) + 1
    x, y = x[ok], y[ok]
    lo = np.array([np.percentile(x, 100 - keep), np.percentile(y, 100 - keep)])
    hi = np.array([np.percentile(x, keep), np.percentile(y, keep)])
    return lo, hi


def _polygon_box(X: list[Any], Y: list[Any], keep: float = 90.0) -> tuple[np.ndarray,
                                                                          np.ndarray]:
    """A box that holds the polygon (and its pole) at most postures.

    Per posture the polygon's extremes are taken; the box is their ``keep``
    percentile, so that the huge polygons near a toggle posture do not shrink
    the others to nothing (they are clipped instead).
    """
    x = np.vstack([np.asarray(a, dtype=float) for a in X] + [np.zeros(len(X[0]))])
    y = np.vstack([np.asarray(a, dtype=float) for a in Y] + [np.zeros(len(Y[0]))])
    ok = np.isfinite(x).all(axis=0) & np.isfinite(y).all(axis=0)
    if not ok.any():
        return np.array([-1.0, -1.0]), np.array([1.0, 1.0])
    x, y = x[:, ok], y[:, ok]
    lo = np.array([np.percentile(x.min(axis=0), 100 - keep),
                   np.percentile(y.min(axis=0), 100 - keep)])
    hi = np.array([np.percentile(x.max(axis=0), keep), np.percentile(y.max(axis=0), keep)])
    return np.minimum(lo, 0.0), np.maximum(hi, 0.0)


def _coincident(mech: Mechanism, sol: Any, cols: dict[str, Any], names: list[str],
                qV: float, qA: float) -> list[dict[str, Any]]:
    """Images of the point of a moving guide that coincides with its slider's point.

    For a point P sliding on link k (which turns), the image of P_k joins the
    image of P by the apparent velocity V_P/k (along the slide, Eq. 3.6), and
    in the acceleration polygon by the Coriolis and apparent components (Eq. 4.17).
    """
    out = []
    guided: list[Slider | Slot] = [*mech.sliders, *mech.slots]
    for sl in guided:
        if sl.on == FRAME or sl.point not in names or sl.key.startswith("rolling"):
            continue
        st = sol.links[sl.on]
        pw = np.stack([cols[f"x_{sl.point}"], cols[f"y_{sl.point}"]], axis=-1)
        d = pw - st.origin
        c, s = np.cos(st.angle), np.sin(st.angle)
        local = np.stack([c * d[..., 0] + s * d[..., 1], -s * d[..., 0] + c * d[..., 1]],
                         axis=-1)
        v, a = st.velocity(local), st.acceleration(local)
        out.append({"point": sl.point, "on": sl.on,
                    "vx": _series(v[..., 0], qV), "vy": _series(v[..., 1], qV),
                    "ax": _series(a[..., 0], qA), "ay": _series(a[..., 1], qA)})
    return out


def cycle_data(mech: Mechanism, *, count: int = 360, start: float | None = None,
               stop: float | None = None, centers: bool = False,
               inflection: bool = False) -> dict[str, Any]:
    """The postures of a cycle as plain data for the animation page (from one sweep).

    Parameters
    ----------
    mech : Mechanism
    count, start, stop
        The postures: ``count`` values of the drive from ``start`` to ``stop``
        (degrees, or a slider's travel), as for ``graphkin sweep``.
    centers : bool
        Add every instant center.
    inflection : bool
        Add each moving link's inflection circle (needs rates).

    Returns
    -------
    dict
        JSON-able: the drive values, which postures assemble, the special
        postures, the links' shapes, and per named point its position,
        velocity and acceleration as integer series with their quantum.

    Examples
    --------
    >>> import graphkin
    >>> d = cycle_data(graphkin.examples.fourbar(), count=12)
    >>> d["n"], sorted(d["points"])[:3], d["rates"]
    (12, ['A', 'B', 'C'], True)

    References
    ----------
    Uicker, Pennock & Shigley, 5th ed., Sec. 3.4, 4.4.
    """
    sw = mech.sweep(count=count, start=start, stop=stop, centers=centers or inflection,
                    curvature=inflection and mech.has_rates)
    mech = sw.mechanism  # a cam mechanism's: its followers moved by the cams' programs
    cols = sw.columns
    sol = sw.solution
    rated = mech.has_rates and "vx_" + next(iter(mech.point_links)) in cols
    helpers = mech.helper_points
    names = [n for n in mech.point_links if n not in helpers and f"x_{n}" in cols]
    n = len(sw.values)
    xs = [cols[f"x_{p}"] for p in names]
    ys = [cols[f"y_{p}"] for p in names]
    qL = _quantum(*xs, *ys)
    data: dict[str, Any] = {
        "title": mech.title or "mechanism", "unit": mech.length_unit, "n": n,
        "rates": bool(rated), "q": {"L": qL},
    }
    d = sw.drive
    if d.is_angle:
        data["drive"] = {"label": d.label, "unit": "°",
                         "values": [round(float(v), 6) for v in sw.drive_values]}
    else:
        data["drive"] = {"label": d.label, "unit": mech.length_unit,
                         "values": [round(float(v), 6) for v in sw.drive_values]}
    held = [x.label for x in mech.drives[1:] if x.law is None]  # coupled inputs are swept
    data["held"] = (f"{data['drive']['label']} is swept; {', '.join(held)} held at the file's "
                    "value (its rate applies throughout)") if held else ""
    # the page plays the cycle in time: with the drive's rate negative (ω2 cw, a slider
    # moving back) the drive's value falls as time goes on (Sec. 3.2: the sense of ω)
    rate = mech.drives[0].rate if mech.drives else None
    dv = np.asarray(sw.drive_values, dtype=float)
    rising = len(dv) < 2 or float(dv[-1] - dv[0]) >= 0.0
    data["sense"] = 1 if (rate is None or rate >= 0.0) == rising else -1
    data["valid"] = "".join("1" if v else "0" for v in np.asarray(sw.assembled).tolist())
    data["rated_valid"] = "".join("1" if v else "0" for v in np.asarray(sw.valid).tolist())
    events = []
    vals = np.asarray(sw.drive_values, dtype=float)
    for sp in sw.singular:
        i = int(np.argmin(np.abs(vals - sp.drive)))
        ev: dict[str, Any] = {"kind": sp.kind, "drive": round(float(sp.drive), 4), "i": i,
                              "note": sp.note}
        if sp.end is not None:
            ev["end"] = round(float(sp.end), 4)
            ev["j"] = int(np.argmin(np.abs(vals - sp.end)))
        events.append(ev)
    data["events"] = events
    pts: dict[str, Any] = {}
    for p in names:
        pts[p] = {"x": _series(cols[f"x_{p}"], qL), "y": _series(cols[f"y_{p}"], qL)}
    links = []
    pins = [p for p in names if len(mech.point_links[p]) >= 2]
    slider_links = {s.link for s in mech.sliders}
    for lid in mech.moving:
        local = {p: mech.links[lid].points[p] for p in mech.links[lid].points if p in names}
        order = _hull_order(local)
        shape = "plate" if len(order) >= 3 else ("bar" if len(order) == 2 else "point")
        if lid in slider_links and len(order) <= 1:
            shape = "block"
        links.append({"id": lid, "points": order, "all": list(local), "shape": shape,
                      "fill": _fill(shape)})
    data["links"] = links
    data["pins"] = pins
    data["frame"] = [p for p in mech.links[FRAME].points if p in names]
    # guides (slider lines and slots), blocks and wheels, in world coordinates per posture
    extent_pts = [np.asarray(a, dtype=float) for a in (*xs, *ys)]
    big = max((float(np.nanmax(np.abs(a))) for a in extent_pts if np.isfinite(a).any()),
              default=1.0)
    guides = []
    # the equivalent slot of a rolling wheel's center (Example 4.7) is no part: not drawn
    lined: list[Slider | Slot] = [*mech.sliders,
                                  *(sl for sl in mech.slots if not sl.key.startswith("rolling"))]
    for gl in lined:
        st = sol.links[gl.on]
        if gl.p0 is not None and gl.p1 is not None and getattr(gl, "center", None) is None:
            p0: np.ndarray = np.asarray(gl.p0, dtype=float)
            p1: np.ndarray = np.asarray(gl.p1, dtype=float)
            u = (p1 - p0) / max(float(np.hypot(*(p1 - p0))), 1e-300)
            a = st.position(p0 - 3 * big * u)
            b = st.position(p0 + 3 * big * u)
            g: dict[str, Any] = {"kind": "line", "x0": _series(a[..., 0], qL),
                                 "y0": _series(a[..., 1], qL), "x1": _series(b[..., 0], qL),
                                 "y1": _series(b[..., 1], qL), "point": gl.point,
                                 "block": gl.link in slider_links and gl.key == "sliders",
                                 # the guide's own points: its arm is drawn to the slide
                                 "arms": [] if gl.on == FRAME else
                                 [n for n in mech.links[gl.on].points if n in names]}
            guides.append(g)
        elif isinstance(gl, Slot) and gl.center is not None and gl.radius is not None:
            c = st.position(np.asarray(gl.center, dtype=float))
            guides.append({"kind": "circle", "cx": _series(c[..., 0], qL),
                           "cy": _series(c[..., 1], qL), "r": round(float(gl.radius) / qL),
                           "point": gl.point, "block": False})
    for rl in mech.rolling:
        if rl.on_line and rl.p0 is not None and rl.p1 is not None:
            st = sol.links[rl.on]
            p0 = np.asarray(rl.p0, dtype=float)
            p1 = np.asarray(rl.p1, dtype=float)
            u = (p1 - p0) / max(float(np.hypot(*(p1 - p0))), 1e-300)
            a, b = st.position(p0 - 3 * big * u), st.position(p0 + 3 * big * u)
            guides.append({"kind": "line", "x0": _series(a[..., 0], qL),
                           "y0": _series(a[..., 1], qL), "x1": _series(b[..., 0], qL),
                           "y1": _series(b[..., 1], qL), "point": rl.center, "block": False,
                           "surface": True})
    data["guides"] = guides
    data["wheels"] = [{"point": w.center, "r": round(float(w.radius) / qL)}
                      for w in mech.rolling if w.center in names]
    # block angle: the slider turns with its guide
    blocks = []
    for sl in mech.sliders:
        if sl.point in names:
            st = sol.links[sl.on]
            q0, q1 = np.asarray(sl.p0, dtype=float), np.asarray(sl.p1, dtype=float)
            ang = np.asarray(st.angle, dtype=float) + math.atan2(q1[1] - q0[1], q1[0] - q0[0])
            blocks.append({"point": sl.point, "link": sl.link,
                           "angle": _series(np.degrees(ang), 1e-3)})
    data["blocks"] = blocks
    data["bodies"], bx, by = _bodies(mech, sol, n, qL)
    lo, hi = _robust_box(xs + bx, ys + by, keep=100.0)
    data["view"] = _rounded_view(lo, hi, 0.12)
    if rated:
        vx = [cols[f"vx_{p}"] for p in names]
        vy = [cols[f"vy_{p}"] for p in names]
        ax = [cols[f"ax_{p}"] for p in names]
        ay = [cols[f"ay_{p}"] for p in names]
        qV, qA = _quantum(*vx, *vy), _quantum(*ax, *ay)
        data["q"].update({"V": qV, "A": qA})
        for p in names:
            pts[p].update({"vx": _series(cols[f"vx_{p}"], qV), "vy": _series(cols[f"vy_{p}"], qV),
                           "ax": _series(cols[f"ax_{p}"], qA), "ay": _series(cols[f"ay_{p}"], qA)})
        paper = paper_unit(mech.length_unit)
        for key, X, Y, unit in (("velocity", vx, vy, f"{mech.length_unit}/s"),
                                ("acceleration", ax, ay, f"{mech.length_unit}/s²")):
            lo, hi = _polygon_box(X, Y)
            view = _rounded_view(lo, hi, 0.1)
            extent = max(view[2] - view[0], view[3] - view[1])
            sc = choose_scale(extent, 3.0, paper, unit)
            data[key] = {"view": view, "scale": {"value": sc.value, "unit": sc.unit,
                                                 "factor": sc.factor, "text": sc.text,
                                                 "bar": sc.value * sc.factor}}
        data["coincident"] = _coincident(mech, sol, cols, names, qV, qA)
        data["omega"] = {lid: _series(cols[f"omega_{lid}"], 1e-6) for lid in mech.moving}
        data["alpha"] = {lid: _series(cols[f"alpha_{lid}"], 1e-5) for lid in mech.moving}
    data["points"] = pts
    if centers or inflection:
        cen = {}
        for col in cols:
            if col.startswith("x_I") and f"y_{col[2:]}" in cols:
                cen[col[2:]] = {"x": _series(cols[col], qL),
                                "y": _series(cols[f"y_{col[2:]}"], qL)}
        data["centers"] = cen if centers else {}
        if inflection:
            circles = {}
            for lid in mech.moving:
                jx, jy = cols.get(f"jx_{lid}"), cols.get(f"jy_{lid}")
                ic = f"I1{lid}" if f"x_I1{lid}" in cols else f"I{lid}1"
                if jx is None or jy is None or f"x_{ic}" not in cols:
                    continue
                px, py = cols[f"x_{ic}"], cols[f"y_{ic}"]
                cx, cy = (px + jx) / 2, (py + jy) / 2
                r = np.hypot(jx - px, jy - py) / 2
                r = np.where(r > 50 * (data["view"][2] - data["view"][0]), np.nan, r)
                circles[lid] = {"cx": _series(cx, qL), "cy": _series(cy, qL),
                                "r": _series(r, qL), "jx": _series(jx, qL),
                                "jy": _series(jy, qL)}
            data["inflection"] = circles
    return data


def _bodies(mech: Mechanism, sol: Any, n: int, qL: float
            ) -> tuple[list[dict[str, Any]], list[np.ndarray], list[np.ndarray]]:
    """The bodies (``[[bodies]]``: a cam's profile, a roller, a face; drawing only).

    Each in its link's own coordinates, with the link's origin and angle at
    every posture: the page turns and moves it (a cam turning under its
    follower, Ch. 6).  Also the x and y that bound them (for the view).
    """
    out: list[dict[str, Any]] = []
    bx: list[np.ndarray] = []
    by: list[np.ndarray] = []
    for bd in mech.bodies:
        st = sol.links.get(bd.link)
        if st is None:
            continue
        o = np.broadcast_to(np.asarray(st.position(np.zeros(2)), dtype=float), (n, 2))
        ang = np.broadcast_to(np.degrees(np.asarray(st.angle, dtype=float)), (n,))
        local = [bd.center] if bd.kind == "circle" and bd.center is not None else bd.points
        out.append({"link": bd.link, "kind": bd.kind,
                    "local": [[round(float(x), 9), round(float(y), 9)] for x, y in local],
                    "r": float(bd.radius or 0.0), "ox": _series(o[:, 0], qL),
                    "oy": _series(o[:, 1], qL), "angle": _series(ang, 1e-4)})
        reach = max((math.hypot(x, y) for x, y in local), default=0.0) + float(bd.radius or 0.0)
        bx += [o[:, 0] - reach, o[:, 0] + reach]
        by += [o[:, 1] - reach, o[:, 1] + reach]
    return out, bx, by
