"""Where everything stands on a worksheet: paper, markers, the polygon's pole and scale.

Pure numbers, no matplotlib: the worksheet renderer (``render/worksheet.py``)
draws from it, and ``graphkin check --scan`` (``graphkin/scan/``) computes the
same layout again from the mechanism file to know where the pole is, what one
millimetre of the sheet stands for, and where the polygon area is.

The sheet's identity that a photograph keeps is in its **markers**: four ArUco
markers of OpenCV's ``DICT_4X4_50`` at the corners, whose ids say the diagram
and the paper, and a fifth, top centre, whose id says how many construction
steps were printed (``--upto``).  The bit patterns are constants here, so a
worksheet is drawn without OpenCV.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon drawn to a
scale from the pole O_V), Sec. 4.3 (the acceleration polygon from O_A).
"""

from __future__ import annotations

import hashlib
import json
import math
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np

from graphkin.errors import InputError

__all__ = ["ARUCO_4X4_50", "PAPERS", "DIAGRAMS", "MARKER_MM", "MAX_UPTO", "Layout",
           "marker_bits", "corner_ids", "decode_ids", "worksheet_layout", "mechanism_hash",
           "next_round"]

#: DICT_4X4_50 of OpenCV's aruco module: the 4 x 4 inner bits of ids 0-49, row by row from
#: the top left, most significant bit first (tests/scan/test_worksheet.py compares them
#: with ``cv2.aruco.generateImageMarker``).
ARUCO_4X4_50: tuple[int, ...] = (
    46386, 3994, 13101, 39238, 21662, 31181, 40494, 50418, 65242, 53078, 63889, 4519, 3767,
    10767, 9393, 9790, 18021, 26112, 27742, 30383, 34443, 45099, 52437, 56706, 65095, 38001,
    44260, 42324, 8483, 13423, 17429, 22450, 40655, 61643, 2222, 2345, 6261, 1279, 3574, 7258,
    5912, 10792, 12940, 14514, 9448, 12011, 11583, 19300, 20526, 20499)

#: paper name -> (width, height) in mm, portrait
PAPERS: dict[str, tuple[float, float]] = {"a4": (210.0, 297.0), "letter": (215.9, 279.4)}
DIAGRAMS = ("velocity", "acceleration")
MARKER_MM = 18.0
"""Side of a marker with its black border (6 cells of 3 mm)."""
MARGIN_MM = 10.0
MAX_UPTO = 33
"""The largest ``--upto`` the fifth marker can say (ids 16 + K, K = 0 ... 33)."""

#: round scales of the polygon: 1 mm stands for one of these times a power of ten
_ROUND = (1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0)


def marker_bits(marker_id: int) -> np.ndarray:
    """The 6 x 6 cells of a marker (1 = black), border included, row 0 at the top."""
    code = ARUCO_4X4_50[marker_id]
    inner = np.array([(code >> (15 - i)) & 1 for i in range(16)], dtype=int).reshape(4, 4)
    cells = np.ones((6, 6), dtype=int)
    cells[1:5, 1:5] = 1 - inner          # a set bit is white
    return cells


def corner_ids(diagram: str, paper: str) -> tuple[int, int, int, int]:
    """The ids of the markers top left, top right, bottom right, bottom left."""
    code = DIAGRAMS.index(diagram) * 2 + list(PAPERS).index(paper)
    return (4 * code, 4 * code + 1, 4 * code + 2, 4 * code + 3)


def decode_ids(ids: list[int]) -> tuple[str, str, int | None] | None:
    """``(diagram, paper, upto)`` from the marker ids found (None: not a worksheet).

    The diagram and paper are those of the corner ids found most often; upto
    is ``None`` when the fifth marker was not found.
    """
    corners = [i for i in ids if 0 <= i < 16]
    if not corners:
        return None
    code = max(set(i // 4 for i in corners), key=lambda c: sum(i // 4 == c for i in corners))
    upto = [i - 16 for i in ids if 16 <= i <= 16 + MAX_UPTO]
    return DIAGRAMS[code // 2], list(PAPERS)[code % 2], (upto[0] if upto else None)


def mechanism_hash(text: bytes) -> str:
    """The first 10 hex digits of the SHA-256 of the mechanism file: printed on the sheet."""
    return hashlib.sha256(text).hexdigest()[:10]


def _round_up(x: float) -> float:
    """The smallest round number (``_ROUND`` × 10^n) at least ``x``."""
    if not x > 0 or not math.isfinite(x):
        return 1.0
    e = math.floor(math.log10(x))
    for k in range(e - 1, e + 2):
        for r in _ROUND:
            if r * 10.0**k >= x * (1 - 1e-12):
                return r * 10.0**k
    return 10.0 ** (e + 1)


def next_round(x: float) -> float:
    """The round number (``_ROUND`` × 10^n) next above ``x``."""
    return _round_up(x * (1 + 1e-9))


@dataclass(frozen=True)
class Layout:
    """A worksheet's numbers, in mm on the sheet (origin bottom left, y up).

    Attributes
    ----------
    paper, diagram : str
    size : (w, h)
    markers : tuple of (id, x, y)
        Each marker's id and its bottom-left corner; side :data:`MARKER_MM`.
    mechanism_box, polygon_box : (x0, y0, x1, y1)
    mech_per_mm : float
        Length (file unit) of 1 mm of the mechanism drawing.
    mech_center : (x, y)
        The mechanism point (file unit) at the centre of its box.
    pole : (x, y)
        O_V or O_A on the sheet.
    per_mm : float
        Velocity or acceleration (internal units) of 1 mm of the polygon.
    scale_text : str
        ``"1 mm = 10 in/s"``: the scale as printed (read by ``check``).
    length_unit : str
    upto : int
        Construction steps printed (0: none).
    digest : str
        :func:`mechanism_hash` of the file.
    """

    paper: str
    diagram: str
    size: tuple[float, float]
    markers: tuple[tuple[int, float, float], ...]
    mechanism_box: tuple[float, float, float, float]
    polygon_box: tuple[float, float, float, float]
    mech_per_mm: float
    mech_center: tuple[float, float]
    pole: tuple[float, float]
    per_mm: float
    scale_text: str
    length_unit: str
    upto: int
    digest: str

    def identity(self) -> dict[str, Any]:
        """The machine-readable identity (PDF metadata ``Subject``, JSON)."""
        d = asdict(self)
        d.pop("markers")
        return {"graphkin-worksheet": 1, **d}

    def identity_line(self) -> str:
        """One printed line: what the sheet is."""
        letter = "V" if self.diagram == "velocity" else "A"
        return (f"graphkin worksheet {self.digest} · {self.diagram} · {self.paper} · "
                f"{self.scale_text} · O_{letter} at ({self.pole[0]:.1f}, {self.pole[1]:.1f}) mm"
                + (f" · steps 0-{self.upto - 1} given" if self.upto else ""))

    def identity_json(self) -> str:
        """:meth:`identity` as one line of JSON."""
        return json.dumps(self.identity(), sort_keys=True)


def _fmt(x: float) -> str:
    return f"{x:.6g}"


def worksheet_layout(sol: Any, diagram: str, paper: str, digest: str,
                     upto: int | None = None) -> Layout:
    """The layout of the worksheet of ``sol``'s ``diagram`` polygon on ``paper``.

    The polygon's scale is the smallest round one at which the polygon and
    the polygon turned 180° (a reversed sense) both fit around the pole in
    the middle of the polygon area; the mechanism is drawn to the smallest
    round scale that fits its box.

    Raises
    ------
    InputError
        The mechanism has no rates for this diagram, or ``upto`` is too large
        for the marker that says it.
    """
    if diagram not in DIAGRAMS:
        raise InputError(f"a worksheet is for the velocity or acceleration polygon, not "
                         f"{diagram!r}", key="--diagram")
    if not sol.has_rates or (diagram == "acceleration" and not sol.has_accelerations):
        raise InputError(f"the mechanism file gives no rates, so it has no {diagram} polygon",
                         key="--diagram")
    k = int(upto or 0)
    if not 0 <= k <= MAX_UPTO:
        raise InputError(f"a worksheet prints at most {MAX_UPTO} construction steps",
                         key="--upto")
    w, h = PAPERS[paper]
    m, s = MARGIN_MM, MARKER_MM
    markers = tuple(zip(corner_ids(diagram, paper),
                        (m, w - m - s, w - m - s, m), (h - m - s, h - m - s, m, m), strict=True))
    markers = ((*markers, (16 + k, (w - s) / 2, h - m - s)))
    inner = 16.0
    mech_box = (inner, 0.60 * h, w - inner, h - m - s - 14.0)
    poly_box = (inner, m + s + 10.0, w - inner, 0.60 * h - 14.0)
    mech = sol.mechanism
    names = [n for n in mech.point_names if n not in mech.helper_points]
    pos = np.array([np.asarray(sol.position(n), dtype=float) for n in names])
    lo, hi = pos.min(axis=0), pos.max(axis=0)
    bw, bh = mech_box[2] - mech_box[0], mech_box[3] - mech_box[1]
    mech_per_mm = _round_up(max((hi[0] - lo[0]) / (0.85 * bw), (hi[1] - lo[1]) / (0.7 * bh),
                                1e-300))
    center = (float(lo[0] + hi[0]) / 2, float(lo[1] + hi[1]) / 2)
    f = sol.velocity if diagram == "velocity" else sol.acceleration
    vec = np.array([np.asarray(f(n), dtype=float) for n in names])
    pw, ph = poly_box[2] - poly_box[0], poly_box[3] - poly_box[1]
    need = max(float(np.max(np.abs(vec[:, 0]))) / (0.44 * pw),
               float(np.max(np.abs(vec[:, 1]))) / (0.44 * ph))
    if not need > 0:
        raise InputError(f"the {diagram} polygon has no length (every image point at the "
                         "pole)", key="--diagram")
    per_mm = _round_up(need)
    lu = mech.length_unit
    unit = f"{lu}/s" if diagram == "velocity" else f"{lu}/s²"
    pole = ((poly_box[0] + poly_box[2]) / 2, (poly_box[1] + poly_box[3]) / 2)
    return Layout(paper, diagram, (w, h), markers, mech_box, poly_box, mech_per_mm, center,
                  pole, per_mm, f"1 mm = {_fmt(per_mm)} {unit}", lu, k, digest)
