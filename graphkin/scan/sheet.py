"""A photo or scan of a worksheet: its pages, its markers, and the sheet rectified.

The worksheet's ArUco markers (``DICT_4X4_50``) say the diagram, the paper
and how many construction steps were printed
(:func:`graphkin.render.worksheet_layout.decode_ids`); their corners, at known
places in millimetres, give the homography from the photo to the sheet, which
is then resampled at :data:`PX_PER_MM` pixels per millimetre (y down, the
sheet's top left at the origin).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the polygon drawn to scale: the
sheet's millimetres are what the scale is read in).
"""

from __future__ import annotations

import itertools
import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.scan import ScanExtraMissing, need_cv2

__all__ = ["PX_PER_MM", "Page", "Rectified", "homography", "read_pages", "rectify",
           "template_ink"]

PX_PER_MM = 5.0
"""Resolution of the rectified sheet: 5 px/mm (127 dpi), a pencil line 2-3 px wide."""

_MAX_PIXELS = 80_000_000
_FIND_PX = 1300
"""The markers are looked for on a copy at most this many pixels long (18 mm is ~80 px)."""
_PDF_DPI = 200.0


@dataclass
class Page:
    """One image to read: ``name`` (the file, ``scan.pdf p.3`` for a page) and its grey pixels.

    ``identity`` is the worksheet's identity when the file is the PDF that
    ``graphkin worksheet`` wrote (its ``Subject`` metadata), else None.
    """

    name: str
    gray: np.ndarray
    identity: dict[str, Any] | None = None


@dataclass
class Rectified:
    """A page undone of its perspective.

    Attributes
    ----------
    gray : ndarray
        The sheet at :data:`PX_PER_MM`, uint8, y down.
    diagram, paper : str
    upto : int or None
        Steps printed (None: the marker that says it was not found).
    found : list of int
        The marker ids found.
    residual_mm : float
        RMS distance of the markers' corners from where the homography puts them.
    blur_mm : float
        The photo's blur (σ of a Gaussian, mm on the sheet), measured across the
        markers' edges (0: not measured).
    """

    gray: np.ndarray
    diagram: str
    paper: str
    upto: int | None
    found: list[int]
    residual_mm: float
    blur_mm: float = 0.0


def read_pages(path: str) -> list[Page]:
    """The pages of an image file (JPEG, PNG, TIFF ...) or of a PDF (each page at 200 dpi).

    Raises
    ------
    InputError
        Missing, unreadable or too large a file.
    """
    cv2 = need_cv2()
    p = Path(path)
    if not p.is_file():
        raise InputError("no such file", file=path, key="--scan")
    if p.suffix.lower() == ".pdf":
        try:
            import pypdfium2 as pdfium
        except ImportError:
            raise ScanExtraMissing('--scan of a PDF needs pypdfium2: pip install '
                                   '"graphkin[scan]"') from None
        try:
            doc = pdfium.PdfDocument(str(p))
        except Exception as exc:  # pdfium raises its own PdfiumError
            raise InputError(f"cannot read the PDF: {exc}", file=path, key="--scan") from None
        identity = None
        try:
            subject = doc.get_metadata_dict().get("Subject", "")
            found = json.loads(subject) if subject.startswith("{") else None
            if isinstance(found, dict) and "graphkin-worksheet" in found:
                identity = found
        except (ValueError, AttributeError):
            identity = None
        pages = []
        for i in range(len(doc)):
            page = doc[i]
            w, h = page.get_size()
            if w * h * (_PDF_DPI / 72) ** 2 > _MAX_PIXELS:
                raise InputError(f"page {i + 1} is too large to read", file=path, key="--scan")
            arr = page.render(scale=_PDF_DPI / 72, grayscale=True).to_numpy()
            gray = arr if arr.ndim == 2 else cv2.cvtColor(arr[..., :3], cv2.COLOR_BGR2GRAY)
            pages.append(Page(f"{path} p.{i + 1}" if len(doc) > 1 else path,
                              np.ascontiguousarray(gray), identity))
        if not pages:
            raise InputError("the PDF has no pages", file=path, key="--scan")
        return pages
    if p.stat().st_size > 60_000_000:
        raise InputError("the image is larger than 60 MB", file=path, key="--scan")
    data = np.fromfile(str(p), dtype=np.uint8)
    gray = cv2.imdecode(data, cv2.IMREAD_GRAYSCALE)
    if gray is None:
        raise InputError("not an image OpenCV can read (JPEG, PNG, TIFF, BMP) nor a PDF",
                         file=path, key="--scan")
    return [Page(path, gray)]


def _detector(cv2: Any) -> Any:
    params = cv2.aruco.DetectorParameters()
    params.cornerRefinementMethod = cv2.aruco.CORNER_REFINE_SUBPIX
    return cv2.aruco.ArucoDetector(cv2.aruco.getPredefinedDictionary(cv2.aruco.DICT_4X4_50),
                                   params)


def rectify(page: Page) -> Rectified:
    """Find the worksheet's markers and resample the sheet at :data:`PX_PER_MM`.

    Raises
    ------
    InputError
        Fewer than three of the sheet's corner markers found (not a graphkin
        worksheet, or too blurred, dark or cut off).
    """
    from graphkin.render.worksheet_layout import PAPERS

    cv2 = need_cv2()
    H, (diagram, paper, upto), found, res, blur = homography(page)
    w, h = PAPERS[paper]
    size = (round(w * PX_PER_MM), round(h * PX_PER_MM))
    gray = page.gray
    # The warp samples the photo bilinearly (four pixels an output pixel): from a photo
    # finer than the sheet's 5 px/mm it would skip the pixels between, and their noise
    # would not average out.  Such a photo is first shrunk by area (each pixel the mean
    # of the light that fell on it, as a scanner at 5 px/mm would see it).
    c = np.array([[size[0] / 2, size[1] / 2], [size[0] / 2 + 1, size[1] / 2],
                  [size[0] / 2, size[1] / 2 + 1]])
    q = cv2.perspectiveTransform(c.reshape(-1, 1, 2), np.linalg.inv(H)).reshape(-1, 2)
    a, b = q[1] - q[0], q[2] - q[0]
    k = math.sqrt(abs(float(a[0] * b[1] - a[1] * b[0])))    # photo px a sheet px
    if k > _SHRINK_ABOVE:
        small = (max(round(gray.shape[1] / k), 1), max(round(gray.shape[0] / k), 1))
        fx, fy = small[0] / gray.shape[1], small[1] / gray.shape[0]
        gray = cv2.resize(gray, small, interpolation=cv2.INTER_AREA)
        # pixel centres are whole numbers: x_small = (x + 0.5) fx - 0.5
        S = np.array([[fx, 0.0, 0.5 * fx - 0.5], [0.0, fy, 0.5 * fy - 0.5], [0.0, 0.0, 1.0]])
        H = H @ np.linalg.inv(S)
    out = cv2.warpPerspective(gray, H, size, flags=cv2.INTER_LINEAR,
                              borderMode=cv2.BORDER_REPLICATE)
    return Rectified(out, diagram, paper, upto, found, res, blur)


_SHRINK_ABOVE = 2.0
"""A photo more than this many pixels a sheet pixel across is shrunk by area before the warp."""


def homography(page: Page) -> tuple[np.ndarray, tuple[str, str, int | None], list[int], float,
                                     float]:
    """The homography from the photo's pixels to the rectified sheet's, from the markers.

    Returns the 3x3 matrix, what the markers say (diagram, paper, steps
    printed), the marker ids found, the RMS residual of their corners (mm) and
    the photo's blur (σ, mm on the sheet: the median over the markers' edges).
    The markers are found on a copy at most :data:`_FIND_PX` long; their
    corners are then placed on the full image where their edges' lines
    cross (:func:`_edge_corners`).
    """
    from graphkin.render.worksheet_layout import (
        MARKER_MM,
        PAPERS,
        corner_ids,
        decode_ids,
    )

    cv2 = need_cv2()
    gray = page.gray
    scale = 1.0
    longest = max(gray.shape)
    if longest > _FIND_PX:              # the markers are large: found on a smaller copy
        scale = _FIND_PX / longest
        gray = cv2.resize(gray, None, fx=scale, fy=scale, interpolation=cv2.INTER_AREA)
    corners, ids, _ = _detector(cv2).detectMarkers(gray)
    found = [] if ids is None else [int(i) for i in ids.ravel()]
    what = decode_ids(found)
    if what is None:
        raise InputError("no graphkin worksheet markers found (is the whole sheet in the "
                         "photo, in focus?)", file=page.name, key="--scan")
    diagram, paper, upto = what
    # the corners on the full image, where the marker's straight edges cross
    fitted = [_edge_corners(page.gray, c.reshape(4, 2).astype(np.float64) / scale)
              for c in corners]
    quads = [q for q, _ in fitted]
    # each marker's edge blur, px of the photo, in mm of the sheet (its side is MARKER_MM)
    per_mm = [float(np.mean(np.hypot(*(q - np.roll(q, 1, axis=0)).T))) / MARKER_MM
              for q in quads]
    blurs = [b / k for (_, b), k in zip(fitted, per_mm, strict=True) if b > 0 and k > 0]
    blur = float(np.median(blurs)) if blurs else 0.0
    w, h = PAPERS[paper]
    m, s = 10.0, MARKER_MM
    corner = dict(zip(corner_ids(diagram, paper),
                      ((m, h - m - s), (w - m - s, h - m - s), (w - m - s, m), (m, m)),
                      strict=True))
    if upto is not None:
        corner[16 + upto] = ((w - s) / 2, h - m - s)
    src, dst = [], []
    for q, i in zip(quads, found, strict=True):
        if i not in corner:
            continue
        x0, y0 = corner[i]
        sheet = [(x0, y0 + s), (x0 + s, y0 + s), (x0 + s, y0), (x0, y0)]   # TL TR BR BL
        src += [tuple(p) for p in q]
        # OpenCV's pixel centres are whole numbers: mm x is at x * PX_PER_MM - 0.5
        dst += [(x * PX_PER_MM - 0.5, (h - y) * PX_PER_MM - 0.5) for x, y in sheet]
    n_corner = sum(1 for i in found if i in corner and i < 16)
    used = [corner[i] for i in dict.fromkeys(found) if i in corner]
    if n_corner < 3 and not (n_corner == 2 and _spread(used, w * h)):
        raise InputError(f"found {n_corner} of the worksheet's 4 corner markers, need 3 or 4, "
                         "or 2 across the sheet and the top one (is the whole sheet in the "
                         "photo?)", file=page.name, key="--scan")
    S, D = np.array(src, dtype=np.float64), np.array(dst, dtype=np.float64)
    H, _ = cv2.findHomography(S, D, 0)
    if H is None:
        raise InputError("the markers give no perspective to undo", file=page.name,
                         key="--scan")
    back = cv2.perspectiveTransform(S.reshape(-1, 1, 2), H).reshape(-1, 2)
    res = float(np.sqrt(np.mean(np.sum((back - D) ** 2, axis=1)))) / PX_PER_MM
    return H, (diagram, paper, upto), found, res, blur


_SPREAD = 0.1
"""Markers whose places span a triangle of at least this fraction of the sheet's area fix
the perspective (any three corner markers span a half; two opposite corners and the top
one about a fifth; two on one side and the top one, in a line, nothing)."""


def _spread(places: list[tuple[float, float]], area: float) -> bool:
    """Whether markers at ``places`` (their lower-left corners, mm) are spread across the sheet.

    A homography has 8 unknowns; each marker's four corners alone fix them
    only over the marker itself.  Three markers not in a line hold the
    perspective over the sheet between them, which is what ``rectify`` needs.
    """
    pts = np.array(places, dtype=float)
    best = 0.0
    for i, j, k in itertools.combinations(range(len(pts)), 3):
        a, b = pts[j] - pts[i], pts[k] - pts[i]
        best = max(best, 0.5 * abs(float(a[0] * b[1] - a[1] * b[0])))
    return best >= _SPREAD * area


_EDGE_ENDS = 0.15
"""The first and last 15 % of a marker's side are left out of its edge's line (the blur
rounds the corner there)."""
_EDGE_REACH = 0.12
"""How far across a marker's side its edge is looked for, a fraction of the side: on the
marker's black border (a sixth of the side wide) inside, on the white paper outside."""


def _edge_corners(gray: np.ndarray, quad: np.ndarray) -> tuple[np.ndarray, float]:
    """A marker's four corners (photo px), where the lines of its four edges cross, and the blur.

    A blurred photo rounds a corner: a corner detector's point (a window of
    a few pixels at the corner, ``cornerSubPix``) is pulled inside the marker
    by about the blur's width and jitters with the noise.  A straight edge is
    not moved by a symmetric blur: across it the grey goes from the border's
    black to the paper's white, and the edge is where the area under that
    profile says a sharp step would be (``s = r - ∫(g - dark) ds / (white -
    dark)`` over ``-r ... r``: every sample counts, so the noise averages
    out, and the dark and white levels are the profile's own, so light
    falling across the sheet does not move it).  Each side's edge is found
    so at a point every pixel along its middle 70 %, a line is fitted to
    those points (the points farther than 3 MADs left out), and the corners
    are where the lines of neighbouring sides cross (a perspective keeps
    straight lines straight).  Done twice, the second time about the first's
    corners.  A marker whose edges cannot be fitted keeps the corners given
    (blur 0: not measured).

    The blur (σ of a Gaussian, photo px) is the area between the profile and
    the sharp step at the edge found, over the step: ``0.80 σ`` for a
    Gaussian blur (``2σ/√(2π)``), taken signed (the profile above the dark
    level before the edge, below the white after it), so that the noise
    averages out; the median over the edge's points and the four sides.
    """
    cv2 = need_cv2()
    q = np.asarray(quad, dtype=np.float64)
    # the marker and the paper around it (a quarter of its side each way), as float
    pad = 0.25 * float(np.max(np.ptp(q, axis=0))) + 4.0
    lo = np.maximum(np.floor(q.min(axis=0) - pad), 0).astype(int)
    hi = np.minimum(np.ceil(q.max(axis=0) + pad), np.array(gray.shape[::-1]) - 1).astype(int)
    g = gray[lo[1]:hi[1] + 1, lo[0]:hi[0] + 1].astype(np.float32)
    q = q - lo
    for _ in range(2):
        lines = []
        sigmas: list[float] = []
        centre = q.mean(axis=0)
        for k in range(4):
            a, b = q[k], q[(k + 1) % 4]
            side = float(np.hypot(*(b - a)))
            if side < 12.0:
                return quad.astype(np.float64), 0.0
            u = (b - a) / side
            n = np.array([-u[1], u[0]])
            if float((a - centre) @ n) < 0:
                n = -n                                      # outward, onto the paper
            r = _EDGE_REACH * side
            t = np.arange(_EDGE_ENDS * side, (1 - _EDGE_ENDS) * side, 1.0)
            s = np.linspace(-r, r, max(int(4 * r), 8) + 1)
            pts = a + t[:, None, None] * u + s[None, :, None] * n        # (t, s, 2)
            prof = cv2.remap(g, pts[..., 0].astype(np.float32), pts[..., 1].astype(np.float32),
                             cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE).astype(float)
            quarter = max(len(s) // 4, 1)
            dark = prof[:, :quarter].mean(axis=1)
            white = prof[:, -quarter:].mean(axis=1)
            step = white - dark
            ds = float(s[1] - s[0])
            area = ((prof - dark[:, None]).sum(axis=1) - 0.5 * (prof[:, 0] + prof[:, -1]
                                                                - 2 * dark)) * ds
            good = step > 0.25 * max(float(np.median(step)), 1.0)
            if np.count_nonzero(good) < 6:
                return quad.astype(np.float64), 0.0
            off = r - area[good] / step[good]
            pg, dg, wg = prof[good], dark[good, None], white[good, None]
            before = s[None, :] < off[:, None]
            spill = np.where(before, pg - dg, wg - pg).sum(axis=1) * ds / step[good]
            sigmas.append(float(np.median(spill)) / 0.7979)
            e = a + t[good, None] * u + off[:, None] * n
            keep = np.ones(len(e), bool)
            for _fit in range(2):
                c = e[keep].mean(axis=0)
                _, _, vt = np.linalg.svd(e[keep] - c)
                d = vt[0]
                dist = (e - c) @ np.array([-d[1], d[0]])
                mad = float(np.median(np.abs(dist[keep] - np.median(dist[keep])))) + 1e-3
                keep = np.abs(dist) <= 3 * 1.4826 * mad + 0.05
                if np.count_nonzero(keep) < 6:
                    return quad.astype(np.float64), 0.0
            lines.append((c, d))
        out = np.empty((4, 2))
        for k in range(4):
            (c1, d1), (c2, d2) = lines[(k - 1) % 4], lines[k]   # the sides meeting at corner k
            A = np.array([d1, -d2]).T
            if abs(float(np.linalg.det(A))) < 0.1:
                return quad.astype(np.float64), 0.0
            st = np.linalg.solve(A, c2 - c1)
            out[k] = c1 + st[0] * d1
        if float(np.max(np.hypot(*(out - q).T))) > 0.1 * float(np.hypot(*(q[1] - q[0]))):
            return quad.astype(np.float64), 0.0                  # not this marker's edges
        q = out
    return q + lo, max(float(np.median(sigmas)), 0.0)


_TEMPLATES: dict[Any, np.ndarray] = {}


def template_ink(sol: Any, layout: Any, title: str = "") -> np.ndarray:
    """Where the printed worksheet has ink, at :data:`PX_PER_MM` (bool, y down), cached.

    The worksheet is drawn again as ``graphkin worksheet`` drew it, so that
    nothing printed (the pole, its label, given construction steps, the
    area's frame) is read as pencil.
    """
    key = (id(sol), layout)
    if key in _TEMPLATES:
        return _TEMPLATES[key]
    from graphkin.render.worksheet import worksheet_pixels

    ink = worksheet_pixels(sol, layout, PX_PER_MM, title=title).min(axis=2) < 235
    w, h = layout.size
    want = (round(h * PX_PER_MM), round(w * PX_PER_MM))
    if ink.shape != want:
        cv2 = need_cv2()
        ink = cv2.resize(ink.astype(np.uint8), (want[1], want[0]),
                         interpolation=cv2.INTER_NEAREST).astype(bool)
    _TEMPLATES.clear()
    _TEMPLATES[key] = ink
    return ink
