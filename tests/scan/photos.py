"""Synthetic photos of a worksheet with a polygon drawn by hand (numpy and OpenCV only).

``sheet_pixels`` renders the worksheet as ``graphkin worksheet`` prints it;
``draw_hand`` draws a polygon on it as a student would with a pencil (grey
strokes with a wobble, ends overshot or short, arrowheads, a construction
line, small gaps, handwritten-like letters); ``photograph`` takes a photo of
it (perspective, rotation, uneven light, blur, noise, JPEG).  The degradation
levels are the ones the reading rate in docs/checking.md is measured at.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import pytest

import graphkin
from graphkin.render.worksheet_layout import Layout, mechanism_hash, worksheet_layout

cv2 = pytest.importorskip("cv2")

PX = 6.0
"""Pixels per mm of the 'printed' sheet before it is photographed."""


@dataclass(frozen=True)
class Degradation:
    """How bad the photo is."""

    tilt: float          # perspective: corner displacement, fraction of the page
    turn_deg: float      # rotation of the page in the photo
    light: float         # darkest / brightest paper
    blur: float          # Gaussian sigma, px of the photo
    noise: float         # grey levels, sigma
    jpeg: int            # quality
    width: int           # photo's width, px


LEVELS: dict[str, Degradation] = {
    "scan": Degradation(0.0, 0.5, 0.95, 0.5, 2.0, 92, 1400),
    "mild": Degradation(0.04, 4.0, 0.8, 1.0, 4.0, 85, 1700),
    "phone": Degradation(0.08, 10.0, 0.6, 1.5, 6.0, 75, 1800),
    "harsh": Degradation(0.12, 25.0, 0.45, 2.2, 9.0, 55, 1500),
}


def blank_page(h_mm: float, paper: int) -> tuple[np.ndarray, Any]:
    """A square page ``h_mm`` across, all paper of grey ``paper``, at :data:`PX` px/mm.

    Returns the pixels and the layout :func:`draw_hand`'s strokes need (its size).
    """
    from types import SimpleNamespace

    n = int(h_mm * PX)
    return np.full((n, n), paper, np.uint8), SimpleNamespace(size=(h_mm, h_mm))


def as_rectified(img: np.ndarray, paper: int, blur_px: float, noise: float = 0.0,
                 rng: np.random.Generator | None = None) -> np.ndarray:
    """A raster page as the reader's light-flattened ratio (1 = paper) at 5 px/mm.

    Shrunk by area from :data:`PX` px/mm, blurred (σ ``blur_px``) and noised
    (σ ``noise`` grey levels), as a photo rectified to the sheet.
    """
    from graphkin.scan.sheet import PX_PER_MM

    small = cv2.resize(img, None, fx=PX_PER_MM / PX, fy=PX_PER_MM / PX,
                       interpolation=cv2.INTER_AREA).astype(np.float32)
    small = cv2.GaussianBlur(small, (0, 0), blur_px)
    if noise > 0 and rng is not None:
        small += rng.normal(0.0, noise, small.shape).astype(np.float32)
    return np.asarray(np.clip(small / float(paper), 0.0, 1.0))


def in_line(rng: np.random.Generator, od: float, da: float
            ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """The pole, d and a on one line of random direction u, centred on (60, 60) mm.

    ``od``: the pole to d, ``da``: d to a (mm).  Returns u, the pole, d and a.
    """
    ang = rng.uniform(0.0, 2 * math.pi)
    u = np.array([math.cos(ang), math.sin(ang)])
    pole = np.array([60.0, 60.0]) - 0.5 * (od + da) * u
    return u, pole, pole + od * u, pole + (od + da) * u


def toward(rng: np.random.Generator, ray: float
           ) -> tuple[np.ndarray, float, np.ndarray, np.ndarray]:
    """An image V near (60, 60) mm, a random angle a, its direction u, the pole ``ray`` before V."""
    v = np.array([60.0, 60.0]) + rng.uniform(-3.0, 3.0, 2)
    a = float(rng.uniform(0.0, 2 * math.pi))
    u = np.array([math.cos(a), math.sin(a)])
    return v, a, u, v - ray * u


def solved(text: str) -> Any:
    return graphkin.loads(text).solve()


def layout_for(sol: Any, diagram: str, text: str, paper: str = "a4",
               upto: int | None = None) -> Layout:
    return worksheet_layout(sol, diagram, paper, mechanism_hash(text.encode()), upto)


def sheet_pixels(sol: Any, layout: Layout, title: str = "") -> np.ndarray:
    """The printed worksheet, grey, at :data:`PX` px/mm (y down)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.render.worksheet import worksheet_figure

    fig = worksheet_figure(sol, layout, title=title)
    fig.set_dpi(PX * 25.4)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    rgba = np.asarray(canvas.buffer_rgba())
    return np.ascontiguousarray(cv2.cvtColor(rgba[..., :3], cv2.COLOR_RGB2GRAY))


def _px(layout: Layout, p: np.ndarray) -> np.ndarray:
    """Sheet mm -> OpenCV pixel coordinates (pixel centres whole numbers) of the printed sheet."""
    return np.array([p[0] * PX - 0.5, (layout.size[1] - p[1]) * PX - 0.5])


def _stroke(img: np.ndarray, layout: Layout, p: np.ndarray, q: np.ndarray,
            rng: np.random.Generator, grey: int, gap: bool, width: int = 2) -> None:
    """A pencil line from p to q (mm) with a slow wobble of about 0.1 mm."""
    n = max(int(np.hypot(*(q - p)) / 2.0), 2)
    t = np.linspace(0.0, 1.0, n + 1)
    d = (q - p) / max(float(np.hypot(*(q - p))), 1e-9)
    nrm = np.array([-d[1], d[0]])
    wob = np.cumsum(rng.normal(0.0, 0.04, n + 1))
    wob -= np.linspace(wob[0], wob[-1], n + 1)           # the ends stay where they are meant
    pts = p + np.outer(t, q - p) + np.outer(np.clip(wob, -0.25, 0.25), nrm)
    cut = rng.integers(1, n) if gap and n > 6 else -1
    for i in range(n):
        if i == cut:
            continue                                     # a small gap (about 2 mm)
        a, b = _px(layout, pts[i]), _px(layout, pts[i + 1])
        cv2.line(img, (int(round(a[0] * 16)), int(round(a[1] * 16))),
                 (int(round(b[0] * 16)), int(round(b[1] * 16))), grey, width,
                 cv2.LINE_AA, shift=4)


def draw_hand(img: np.ndarray, layout: Layout, images: dict[str, np.ndarray],
              links: list[list[str]], rng: np.random.Generator, *,
              construction: bool = True) -> np.ndarray:
    """Draw a polygon by hand: a vector from the pole to each image, the images of each link.

    ``images`` are the image points (sheet mm) as the student means them;
    ``links`` the names on each moving link (their images joined, as the
    velocity images of Sec. 3.5).  Every end is overshot or stopped short by
    -0.3 to +0.4 mm; each absolute vector has a two-barb arrowhead.
    """
    out = img.copy()
    pole = np.array(layout.pole)
    grey = int(rng.integers(50, 120))

    def line(a: np.ndarray, b: np.ndarray, arrow: bool) -> None:
        d = (b - a) / max(float(np.hypot(*(b - a))), 1e-9)
        a2 = a - d * rng.uniform(-0.3, 0.4)
        b2 = b + d * rng.uniform(-0.3, 0.4)
        _stroke(out, layout, a2, b2, rng, grey + int(rng.integers(-15, 15)),
                gap=bool(rng.random() < 0.3))
        if arrow:
            for s in (1.0, -1.0):
                ang = math.radians(180.0 + s * rng.uniform(15.0, 25.0))
                rot = np.array([[math.cos(ang), -math.sin(ang)], [math.sin(ang), math.cos(ang)]])
                _stroke(out, layout, b, b + rot @ d * rng.uniform(2.0, 3.0), rng, grey,
                        gap=False)

    for p in images.values():
        line(pole, p, arrow=True)
    for names in links:
        there = [n for n in names if n in images]
        for i in range(len(there)):
            for j in range(i + 1, len(there)):
                line(images[there[i]], images[there[j]], arrow=False)
    for name, p in images.items():
        off = np.array([2.0, 1.5]) + rng.uniform(-0.5, 0.5, 2)
        q = _px(layout, p + off)
        cv2.putText(out, name.lower(), (int(q[0]), int(q[1])), cv2.FONT_HERSHEY_SCRIPT_SIMPLEX,
                    0.9, grey, 2, cv2.LINE_AA)
    if construction and images:
        # a faint construction line through one image, well past it (a direction laid off)
        name = sorted(images)[int(rng.integers(len(images)))]
        p = images[name]
        ang = rng.uniform(0.0, math.pi)
        d = np.array([math.cos(ang), math.sin(ang)])
        _stroke(out, layout, p - 25 * d, p + 25 * d, rng, 185, gap=False, width=1)
    return out


def photograph(img: np.ndarray, deg: Degradation, rng: np.random.Generator) -> np.ndarray:
    """A photo of the sheet: perspective, rotation, uneven light, blur, noise, JPEG."""
    h, w = img.shape
    W = deg.width
    H = int(W * 1.35)
    src = np.float32([[0, 0], [w, 0], [w, h], [0, h]])
    # the page, turned, fitted into 80 % of the frame, its corners moved for perspective
    c = np.array([W / 2, H / 2])
    k = 0.8 * min(W / w, H / h) / (1 + abs(math.sin(math.radians(deg.turn_deg))) * 0.35)
    t = math.radians(deg.turn_deg * rng.choice([-1.0, 1.0]))
    rot = np.array([[math.cos(t), -math.sin(t)], [math.sin(t), math.cos(t)]])
    dst = np.array([c + rot @ ((q - np.array([w / 2, h / 2])) * k) for q in src])
    dst += rng.uniform(-1.0, 1.0, (4, 2)) * deg.tilt * np.array([W, H]) * 0.5
    M = cv2.getPerspectiveTransform(src, dst.astype(np.float32))
    photo = cv2.warpPerspective(img, M, (W, H), flags=cv2.INTER_AREA,
                                borderMode=cv2.BORDER_CONSTANT, borderValue=90).astype(np.float32)
    yy, xx = np.mgrid[0:H, 0:W].astype(np.float32)
    ang = rng.uniform(0, 2 * math.pi)
    ramp = (math.cos(ang) * (xx / W - 0.5) + math.sin(ang) * (yy / H - 0.5)) + 0.5
    photo *= deg.light + (1 - deg.light) * np.clip(ramp, 0, 1)
    if deg.blur > 0:
        photo = cv2.GaussianBlur(photo, (0, 0), deg.blur)
    photo += rng.normal(0.0, deg.noise, photo.shape).astype(np.float32)
    ok, buf = cv2.imencode(".jpg", np.clip(photo, 0, 255).astype(np.uint8),
                           [cv2.IMWRITE_JPEG_QUALITY, deg.jpeg])
    assert ok
    return cv2.imdecode(buf, cv2.IMREAD_GRAYSCALE)


READABLE_MM = 7.0
"""docs/checking.md: an image under 7 mm from the pole is too short to read from a photo
and is not marked (a note says so)."""


def readable(images: dict[str, np.ndarray], layout: Layout) -> set[str]:
    """The images a photo is marked at: those at least :data:`READABLE_MM` from the pole."""
    pole = np.array(layout.pole)
    return {n for n, p in images.items() if float(np.hypot(*(p - pole))) >= READABLE_MM}


def exact_images(sol: Any, layout: Layout) -> dict[str, np.ndarray]:
    """Every image point away from the pole, sheet mm (the analytic solver's values)."""
    from graphkin.kinematics.analytic import solve_analytic

    an = solve_analytic(sol.mechanism)
    f = an.velocity if layout.diagram == "velocity" else an.acceleration
    pole = np.array(layout.pole)
    mech = sol.mechanism
    out = {}
    for n in mech.point_names:
        if n in mech.helper_points:
            continue
        v = np.asarray(f(n), dtype=float) / layout.per_mm
        if float(np.hypot(*v)) >= 2.5:
            out[n] = pole + v
    return out


def pinned_case(case: dict[str, Any]) -> tuple[Any, Layout, dict[str, np.ndarray]]:
    """A pinned photo's mechanism (``data``, ``diagram``, ``kind``): solution, sheet, images."""
    from graphkin.mechanisms import from_dict

    sol = from_dict(case["data"]).solve()
    lay = layout_for(sol, case["diagram"], case["kind"])
    return sol, lay, exact_images(sol, lay)


def off_line(p: np.ndarray, a: np.ndarray, b: np.ndarray) -> float:
    """How far (mm) ``p`` stands from the line through ``a`` and ``b``."""
    u = (b - a) / float(np.hypot(*(b - a)))
    return abs(float(u[0] * (p - a)[1] - u[1] * (p - a)[0]))


def links_of(sol: Any) -> list[list[str]]:
    """The point names of each moving link (their images are joined on the sheet)."""
    mech = sol.mechanism
    return [[n for n in link.points if n not in mech.helper_points]
            for lid, link in mech.links.items() if lid != "1"]


def hand_photo(sol: Any, layout: Layout, sheet: np.ndarray, images: dict[str, np.ndarray],
               level: str, seed: int) -> np.ndarray:
    """The sheet with ``images`` drawn by hand, photographed at ``level``."""
    rng = np.random.default_rng(seed)
    return photograph(draw_hand(sheet, layout, images, links_of(sol), rng), LEVELS[level], rng)


def read_photo(sol: Any, layout: Layout, drawn: dict[str, np.ndarray], level: str,
               seed: int) -> tuple[Any, Any, dict[str, Any]]:
    """``drawn`` photographed at ``level``, read, marked: the read, the report, its rows by key."""
    from graphkin.check import CheckTolerance, Diagnoser, Evaluator
    from graphkin.scan.mark import mark_scan
    from graphkin.scan.read import read_sheet
    from graphkin.scan.sheet import Page

    diag = Diagnoser(Evaluator(sol))
    photo = hand_photo(sol, layout, sheet_pixels(sol, layout), drawn, level, seed)
    read = read_sheet(sol, Page("p", photo), diag, layout.digest)
    rep = mark_scan(sol, read, "p", CheckTolerance(), diag)
    return read, rep, {r.key: r for r in rep.rows}


def between_pole_and(pole: np.ndarray, a: np.ndarray, d: np.ndarray) -> bool:
    """Whether ``d`` lies on the segment from the pole to ``a``, within 0.01 mm of its line."""
    v_a, v_d = a - pole, d - pole
    on_line = abs(float(v_a[0] * v_d[1] - v_a[1] * v_d[0])) < 0.01 * float(np.hypot(*v_a))
    return on_line and 0.0 < float(v_d @ v_a) < float(v_a @ v_a)


def class_pdf(path: Any, photos: list[np.ndarray]) -> None:
    """A PDF of one photo per A4 page, as a scanner of a stack of sheets writes."""
    from matplotlib.backends.backend_pdf import PdfPages
    from matplotlib.figure import Figure

    with PdfPages(path) as pdf:
        for ph in photos:
            fig = Figure(figsize=(8.27, 11.69))
            ax = fig.add_axes((0, 0, 1, 1))
            ax.imshow(ph, cmap="gray", vmin=0, vmax=255, interpolation="nearest")
            ax.set_axis_off()
            pdf.savefig(fig, dpi=150)
