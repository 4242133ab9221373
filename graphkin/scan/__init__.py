"""Marking a polygon drawn by hand on a graphkin worksheet, from a phone photo or a scan.

``graphkin worksheet`` prints the sheet (``render/worksheet.py``): the
mechanism, the pole and the polygon's scale, and ArUco markers.  Reading a
photo of it (``graphkin check FILE --scan photo.jpg``):

1. ``sheet.py`` finds the markers (OpenCV's ``cv2.aruco``) and undoes the
   perspective: a homography from the photo to millimetres on the sheet;
2. ``strokes.py`` finds the pencil line segments in the polygon area (the
   printed sheet is rendered again and masked out, the light flattened, then
   OpenCV's line segment detector and collinear pieces merged);
3. ``read.py`` names the segment ends near where each image can be (the
   exact image, the usual mistakes' images of
   :class:`graphkin.check.diagnose.Diagnoser`, and where the construction
   puts it from the student's own images read before it,
   :class:`graphkin.check.carry.Carry`), all names at once, and hands the
   points, in mm on the sheet, with the printed scale and pole, to the same
   marking as ``check --drawing``.

OpenCV (and pypdfium2, for PDF scans) are the optional extra
``graphkin[scan]``; they are imported only when a scan is read.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.4 (the velocity polygon), Sec. 4.3
(the acceleration polygon).
"""

from __future__ import annotations

from typing import Any

from graphkin.errors import InputError

__all__ = ["need_cv2", "MISSING", "ScanExtraMissing"]

MISSING = '--scan needs OpenCV: pip install "graphkin[scan]"'
"""The message when the extra is not installed (the CLI prints ``graphkin: `` before it)."""


class ScanExtraMissing(InputError):
    """OpenCV (or pypdfium2) is not installed."""


def need_cv2() -> Any:
    """``cv2`` with its aruco module, or :class:`ScanExtraMissing`."""
    try:
        import cv2
    except ImportError:
        raise ScanExtraMissing(MISSING) from None
    if not hasattr(cv2, "aruco"):
        raise ScanExtraMissing(MISSING)
    return cv2
