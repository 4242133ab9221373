"""Pencil strokes drawn straight onto a light-flattened page, for the reader's raster tests.

No photo: the strokes are where the test puts them, 0.4 mm wide at darkness
0.55 (a pencil line on a page whose paper is 1.0), blurred as a photo blurs;
what the reader must find is then known from the drawing itself.
"""

from __future__ import annotations

import math

import cv2
import numpy as np

from graphkin.scan.inkfit import Sheet
from graphkin.scan.sheet import PX_PER_MM


def _px(p: np.ndarray, h_mm: float) -> tuple[int, int]:
    """Sheet mm (y up) -> the raster's pixel, 16ths (cv2's ``shift=4``)."""
    return (int(round((p[0] * PX_PER_MM - 0.5) * 16)),
            int(round(((h_mm - p[1]) * PX_PER_MM - 0.5) * 16)))


def pencil_sheet(strokes: list[tuple[np.ndarray, np.ndarray]], blur: float,
                 h_mm: float = 80.0) -> Sheet:
    """A light-flattened page ``h_mm`` square (1.0 paper), pencil strokes 0.4 mm wide."""
    n = int(h_mm * PX_PER_MM)
    img = np.full((n, n), 255, np.uint8)
    for a, b in strokes:
        cv2.line(img, _px(a, h_mm), _px(b, h_mm), 115, 2, cv2.LINE_AA, shift=4)
    out = cv2.GaussianBlur(img.astype(np.float32) / 255.0, (0, 0), blur)
    return Sheet(out, (0, 0), h_mm)


def unit(deg: float) -> np.ndarray:
    """The unit vector at ``deg`` degrees from +x."""
    return np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])
