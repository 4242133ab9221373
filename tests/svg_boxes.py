"""Reading a saved SVG back by gid: its texts' boxes from font metrics, its drawn lines.

graphkin writes text as text (``svg.fonttype = "none"``), so a test can find a
note by its gid and measure the box its glyphs take with matplotlib's own font
metrics, and read every stroked path (lines, circles as Bézier arcs, markers
placed by ``<use>``) as polylines, all in the SVG's points (72 per inch).
Nothing here uses the code that placed the notes.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
from shapely import box as shapely_box
from shapely.geometry import LineString, Polygon

SVG = "{http://www.w3.org/2000/svg}"
XLINK = "{http://www.w3.org/1999/xlink}"
_TOKEN = re.compile(r"[MLCQZmlcqz]|-?\d*\.?\d+(?:[eE][-+]?\d+)?")


@lru_cache(maxsize=4096)
def _advance(text: str, size: float, italic: bool) -> tuple[float, float, float]:
    """Width, height and descent (points) of ``text`` in DejaVu Sans at ``size`` points.

    The font's own unhinted metrics, as a vector drawing sets the text
    (matplotlib's ``TextToPath``); Agg's hinted metrics round each glyph to a
    pixel (a 7.5 pt note of 18 letters measures 81 pt at 72 dpi, 69 at 100, 75 here).
    """
    from matplotlib.font_manager import FontProperties
    from matplotlib.textpath import TextToPath

    prop = FontProperties(family="DejaVu Sans", size=size,
                          style="oblique" if italic else "normal")
    w, h, d = TextToPath().get_text_width_height_descent(text, prop, ismath=False)
    return float(w), float(h), float(d)


def _size(style: str) -> float:
    m = re.search(r"font-size:\s*([0-9.]+)px", style)
    return float(m.group(1)) if m else 10.0


def _run_box(x: float, y: float, text: str, style: str) -> tuple[float, float, float, float]:
    """The box of one run of text whose baseline starts (or is anchored) at (x, y)."""
    size = _size(style)
    w, h, d = _advance(text, size, "oblique" in style or "italic" in style)
    anchor = re.search(r"text-anchor:\s*(\w+)", style)
    if anchor and anchor.group(1) == "middle":
        x -= w / 2
    elif anchor and anchor.group(1) == "end":
        x -= w
    return x, y - (h - d), x + w, y + d       # SVG's y grows downward


@dataclass
class Note:
    gid: str
    text: str
    box: Polygon


def _translate(el: ET.Element) -> tuple[float, float]:
    m = re.search(r"translate\(([-\d.e]+)[ ,]+([-\d.e]+)\)", el.get("transform", ""))
    return (float(m.group(1)), float(m.group(2))) if m else (0.0, 0.0)


def texts(root: ET.Element) -> list[Note]:
    """Every text of the drawing with the gid of its group, unrotated ones only."""
    out: list[Note] = []

    def walk(el: ET.Element, gid: str, off: tuple[float, float]) -> None:
        if el.tag == f"{SVG}g":
            gid = el.get("id") or gid
            tx, ty = _translate(el)
            off = (off[0] + tx, off[1] + ty)
        if el.tag == f"{SVG}text":
            rot = re.search(r"rotate\(([-\d.e]+)", el.get("transform", ""))
            if rot and abs(float(rot.group(1))) not in (0.0,):
                return   # an axis label turned on its side
            boxes = []
            runs = list(el.iter(f"{SVG}tspan")) or [el]
            for t in runs:
                s = "".join(t.itertext()) if t is el else (t.text or "")
                if not s.strip():
                    continue
                style = t.get("style", "") or el.get("style", "")
                x = float(t.get("x", el.get("x", "0"))) + off[0]
                y = float(t.get("y", el.get("y", "0"))) + off[1]
                boxes.append(_run_box(x, y, s, style))
            if boxes:
                b = np.array(boxes)
                out.append(Note(gid, "".join(el.itertext()).strip(),
                                shapely_box(b[:, 0].min(), b[:, 1].min(), b[:, 2].max(),
                                            b[:, 3].max())))
            return
        for ch in el:
            walk(ch, gid, off)

    walk(root, "", (0.0, 0.0))
    return out


def _polylines(d: str, at: tuple[float, float] = (0.0, 0.0)) -> list[np.ndarray]:
    """An SVG path of absolute M, L, Q, C, Z commands as polylines (curves sampled)."""
    toks = _TOKEN.findall(d)
    runs: list[list[np.ndarray]] = []
    cur: list[np.ndarray] = []
    start = np.zeros(2)
    i, cmd = 0, ""
    s = np.linspace(0.0, 1.0, 9)[1:, None]
    ox, oy = at
    while i < len(toks):
        if toks[i].isalpha():
            cmd = toks[i].upper()
            i += 1
            if cmd == "Z":
                if cur:
                    cur.append(start)
                continue
        n = {"M": 2, "L": 2, "Q": 4, "C": 6}[cmd]
        v = np.array([float(t) for t in toks[i:i + n]]).reshape(-1, 2) + (ox, oy)
        i += n
        if cmd == "M":
            if len(cur) >= 2:
                runs.append(cur)
            cur, start = [v[0]], v[0]
            cmd = "L"
        elif cmd == "L":
            cur.append(v[0])
        else:
            p0 = cur[-1]
            if cmd == "Q":
                pts = (1 - s) ** 2 * p0 + 2 * (1 - s) * s * v[0] + s ** 2 * v[1]
            else:
                pts = ((1 - s) ** 3 * p0 + 3 * (1 - s) ** 2 * s * v[0]
                       + 3 * (1 - s) * s ** 2 * v[1] + s ** 3 * v[2])
            cur.extend(pts)
    if len(cur) >= 2:
        runs.append(cur)
    return [np.array(r) for r in runs]


def strokes(root: ET.Element) -> list[tuple[str, LineString]]:
    """Every stroked path and placed marker, with the gid of its nearest named group.

    Filled shapes without a stroke (an axes' background, a shaded band) are left
    out; a marker (``<use>`` of a path in ``<defs>``) is its outline at its place.
    """
    defs = {p.get("id"): p.get("d", "") for p in root.iter(f"{SVG}path") if p.get("id")}
    out: list[tuple[str, LineString]] = []

    def walk(el: ET.Element, gid: str) -> None:
        if el.tag == f"{SVG}defs":
            return
        if el.tag == f"{SVG}g":
            gid = el.get("id") or gid
        style = el.get("style", "")
        if el.tag == f"{SVG}path" and "stroke:" in style and "stroke: none" not in style:
            out.extend((gid, LineString(r)) for r in _polylines(el.get("d", "")) if len(r) >= 2)
        if el.tag == f"{SVG}use":
            ref = (el.get(f"{XLINK}href") or "").lstrip("#")
            at = (float(el.get("x", "0")), float(el.get("y", "0")))
            out.extend((gid, LineString(r)) for r in _polylines(defs.get(ref, ""), at)
                       if len(r) >= 2)
        for ch in el:
            walk(ch, gid)

    walk(root, "")
    return out


def page(root: ET.Element) -> Polygon:
    """The page's rectangle (the viewBox)."""
    x, y, w, h = (float(v) for v in root.get("viewBox", "0 0 0 0").split())
    return shapely_box(x, y, x + w, y + h)


def hidden_texts(root: ET.Element) -> list[tuple[str, str, str]]:
    """Texts painted over by a filled shape drawn after them: (text gid, text, shape gid).

    SVG paints in document order, so a text is hidden where a later path with
    a fill (a link's white disc, a plate) covers the middle of its box.
    """
    notes = {id(el): n for el, n in _text_elements(root)}
    out: list[tuple[str, str, str]] = []
    shown: list[Note] = []

    def walk(el: ET.Element, gid: str) -> None:
        if el.tag == f"{SVG}defs":
            return
        if el.tag == f"{SVG}g":
            gid = el.get("id") or gid
        if id(el) in notes:
            shown.append(notes[id(el)])
            return
        style = el.get("style", "")
        if el.tag == f"{SVG}path" and "fill:" in style and "fill: none" not in style:
            for run in _polylines(el.get("d", "")):
                if len(run) >= 3:
                    shape = Polygon(run).buffer(0)
                    for n in shown:
                        if shape.contains(n.box.centroid):
                            out.append((n.gid, n.text, gid))
        for ch in el:
            walk(ch, gid)

    walk(root, "")
    return sorted(set(out))


def _text_elements(root: ET.Element) -> list[tuple[ET.Element, Note]]:
    """Each ``<text>`` element with its :class:`Note` (as :func:`texts` reads them)."""
    els = []

    def walk(el: ET.Element) -> None:
        if el.tag == f"{SVG}text":
            els.append(el)
            return
        for ch in el:
            walk(ch)

    walk(root)
    found = texts(root)
    # texts() reads the same elements in the same order, less the rotated and empty ones
    by_text: dict[str, list[Note]] = {}
    for n in found:
        by_text.setdefault(n.text, []).append(n)
    out = []
    for el in els:
        s = "".join(el.itertext()).strip()
        if by_text.get(s):
            out.append((el, by_text[s].pop(0)))
    return out
