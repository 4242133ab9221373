"""Saving drawings: deterministic SVG with real text, vector PDF, PNG; and Jupyter's ``_repr_svg_``.

The same figure saved twice gives the same bytes: the SVG ids are salted
with a fixed string (``svg.hashsalt``), the date is left out of the
metadata and text stays text (``svg.fonttype = "none"``), so that every
label is a ``<text>`` element a test or a browser can find.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 2.8 (the drawings this saves).
"""

from __future__ import annotations

import hashlib
import io
import os
import re
from pathlib import Path
from typing import Any

from graphkin.errors import GraphkinError

__all__ = ["save", "to_bytes", "to_svg", "repr_svg", "FORMATS"]

FORMATS = ("svg", "pdf", "png")
"""The formats :func:`save` writes, chosen by the file's suffix."""

_METADATA = {
    "svg": {"Date": None, "Creator": "graphkin"},
    "pdf": {"CreationDate": None, "ModDate": None, "Creator": "graphkin", "Producer": "graphkin"},
    "png": {"Software": "graphkin"},
}


def to_bytes(fig: Any, fmt: str = "svg", dpi: float = 150.0) -> bytes:
    """The figure as SVG, PDF or PNG bytes, deterministically.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    fmt : str
        ``svg``, ``pdf`` or ``png``.
    dpi : float
        Resolution of a PNG.
    """
    from graphkin.render.style import rc_context
    from graphkin.render.text import sanitize_figure

    if fmt not in FORMATS:
        raise GraphkinError(f"cannot write {fmt!r} drawings; valid: {', '.join(FORMATS)}")
    buf = io.BytesIO()
    sanitize_figure(fig)  # a user string that is not valid mathtext is shown as typed
    with rc_context():
        fig.savefig(buf, format=fmt, metadata=_METADATA[fmt], dpi=dpi, facecolor="white")
    data = buf.getvalue()
    if fmt == "svg":
        data = stable_ids(data.replace(b"\r\n", b"\n"))
    return data


_HASHED = re.compile(r'\bid="([a-z][0-9a-f]{10})"')
_DEF = r'<(\w+)\b[^>]*\bid="{}".*?(?:/>|</\1>)'
_DIGITS = re.compile(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def stable_ids(data: bytes) -> bytes:
    """Matplotlib's hashed SVG ids (clip paths, markers) made from what they define, rounded.

    Matplotlib names a clip path by a hash of its rectangle and transform as
    Python prints them, to the last digit: the same drawing made on another
    machine (whose sin or solve differs in the last digit) gets other ids.
    Each such id is renamed by a hash of its definition with every number
    rounded to 1/100 pt, so the bytes are the same wherever the drawing is
    the same.

    Examples
    --------
    >>> a = (b'<clipPath id="p0123456789"><rect x="7.2000000001"/></clipPath>'
    ...      b'<g clip-path="url(#p0123456789)"/>')
    >>> b = a.replace(b"p0123456789", b"p9876543210").replace(b"7.2000000001", b"7.1999999999")
    >>> stable_ids(a)[:26] == stable_ids(b)[:26] == b'<clipPath id="pabedee3381"'
    True
    """
    text = data.decode("utf-8")
    seen: dict[str, int] = {}
    rename = {}
    for old in dict.fromkeys(_HASHED.findall(text)):
        m = re.search(_DEF.format(old), text, flags=re.DOTALL)
        body = m.group(0).replace(old, "") if m else old
        key = _DIGITS.sub(lambda d: f"{float(d.group(0)):.2f}", body)
        seen[key] = seen.get(key, 0) + 1  # two definitions alike to 1/100 pt: two ids still
        new = old[0] + hashlib.sha256(f"{key}#{seen[key]}".encode()).hexdigest()[:10]
        rename[old] = new
    for old, new in rename.items():
        text = text.replace(f'id="{old}"', f'id="{new}"').replace(f"#{old}", f"#{new}")
    return text.encode("utf-8")


def to_svg(fig: Any) -> str:
    """The figure as SVG text."""
    return to_bytes(fig, "svg").decode("utf-8")


def save(fig: Any, path: str | os.PathLike[str], dpi: float = 150.0) -> Path:
    """Write the figure to ``path``; the suffix (``.svg``, ``.pdf``, ``.png``) chooses the format.

    Returns
    -------
    Path
        The file written.

    Raises
    ------
    GraphkinError
        An unknown suffix.
    """
    p = Path(path)
    fmt = p.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise GraphkinError(f"{p}: cannot tell the format from the suffix {p.suffix!r}; use "
                            + ", ".join("." + f for f in FORMATS))
    data = to_bytes(fig, fmt, dpi=dpi)
    p.write_bytes(data)
    return p


def repr_svg(obj: Any, diagram: str | None = None, *, table: bool | None = None
             ) -> str | None:
    """SVG text of a solved mechanism or a construction, for Jupyter's ``_repr_svg_``.

    A solution shows every diagram it has (``all``); a construction is drawn
    by itself when it can be evaluated alone.  Returns None (so that Jupyter
    falls back to the text repr) instead of raising.  ``table=False`` leaves
    the results table out (a Solution's own ``_repr_svg_``: its posture only).

    Examples
    --------
    >>> from graphkin.construction import Construction
    >>> cx = Construction()
    >>> _ = cx.add("point", (), ("A",), xy=(0.0, 0.0), role="given")
    >>> _ = cx.add("point", (), ("C",), xy=(8.0, 0.0), role="result")
    >>> svg = repr_svg(cx)
    >>> 'id="step-01-C"' in svg and ">C</text>" in svg
    True
    """
    from graphkin.render.mpl import draw

    try:
        d = draw(obj, diagram or _default_diagram(obj), max_inches=3.5, table=table)
    except (GraphkinError, TypeError, ValueError):
        return None
    assert d.figure is not None
    return to_svg(d.figure)


def _default_diagram(obj: Any) -> str:
    from graphkin.construction import Construction

    if isinstance(obj, Construction):
        for s in reversed(obj.steps):
            return s.diagram or "posture"
        return "posture"
    return "all"
