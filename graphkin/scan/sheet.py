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

import json
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from graphkin.errors import InputError
from graphkin.scan import ScanExtraMissing, need_cv2

__all__ = ["PX_PER_MM", "Page", "Rectified", "read_pages", "rectify", "template_ink"]

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
    """

    gray: np.ndarray
    diagram: str
    paper: str
    upto: int | None
    found: list[int]
    residual_mm: float


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
    if found and scale != 1.0:          # their corners then refined on the full image
        full = np.concatenate([c.reshape(4, 2) for c in corners]) / scale
        win = max(3, int(round(2 / scale)))
        full = cv2.cornerSubPix(page.gray, full.astype(np.float32).reshape(-1, 1, 2),
                                (win, win), (-1, -1),
                                (cv2.TERM_CRITERIA_EPS + cv2.TERM_CRITERIA_MAX_ITER, 30, 0.01))
        corners = [c.reshape(1, 4, 2) * scale for c in full.reshape(-1, 4, 2)]
    what = decode_ids(found)
    if what is None:
        raise InputError("no graphkin worksheet markers found (is the whole sheet in the "
                         "photo, in focus?)", file=page.name, key="--scan")
    diagram, paper, upto = what
    w, h = PAPERS[paper]
    m, s = 10.0, MARKER_MM
    corner = dict(zip(corner_ids(diagram, paper),
                      ((m, h - m - s), (w - m - s, h - m - s), (w - m - s, m), (m, m)),
                      strict=True))
    if upto is not None:
        corner[16 + upto] = ((w - s) / 2, h - m - s)
    src, dst = [], []
    for c, i in zip(corners, found, strict=True):
        if i not in corner:
            continue
        x0, y0 = corner[i]
        sheet = [(x0, y0 + s), (x0 + s, y0 + s), (x0 + s, y0), (x0, y0)]   # TL TR BR BL
        src += [tuple(q) for q in c.reshape(4, 2) / scale]
        # OpenCV's pixel centres are whole numbers: mm x is at x * PX_PER_MM - 0.5
        dst += [(x * PX_PER_MM - 0.5, (h - y) * PX_PER_MM - 0.5) for x, y in sheet]
    n_corner = sum(1 for i in found if i in corner and i < 16)
    if n_corner < 3:
        raise InputError(f"found {n_corner} of the worksheet's 4 corner markers, need 3 or 4 "
                         "(is the whole sheet in the photo?)", file=page.name, key="--scan")
    S, D = np.array(src, dtype=np.float64), np.array(dst, dtype=np.float64)
    H, _ = cv2.findHomography(S, D, 0)
    if H is None:
        raise InputError("the markers give no perspective to undo", file=page.name,
                         key="--scan")
    back = cv2.perspectiveTransform(S.reshape(-1, 1, 2), H).reshape(-1, 2)
    res = float(np.sqrt(np.mean(np.sum((back - D) ** 2, axis=1)))) / PX_PER_MM
    size = (round(w * PX_PER_MM), round(h * PX_PER_MM))
    out = cv2.warpPerspective(page.gray, H, size, flags=cv2.INTER_AREA,
                              borderMode=cv2.BORDER_REPLICATE)
    return Rectified(out, diagram, paper, upto, found, res)


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
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    from graphkin.render.worksheet import worksheet_figure

    fig = worksheet_figure(sol, layout, title=title)
    fig.set_dpi(PX_PER_MM * 25.4)
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    rgba = np.asarray(canvas.buffer_rgba())
    ink = rgba[..., :3].min(axis=2) < 235
    w, h = layout.size
    want = (round(h * PX_PER_MM), round(w * PX_PER_MM))
    if ink.shape != want:
        cv2 = need_cv2()
        ink = cv2.resize(ink.astype(np.uint8), (want[1], want[0]),
                         interpolation=cv2.INTER_NEAREST).astype(bool)
    _TEMPLATES.clear()
    _TEMPLATES[key] = ink
    return ink
