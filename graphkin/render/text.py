r"""User strings made safe for matplotlib text: no mathtext surprise, never a ParseSyntaxException.

Matplotlib reads any string with a pair of unescaped ``$`` as mathtext, so a
point called ``$\frac{$`` or a title with two dollar signs would stop a
drawing with a parse error, and a point called ``P%`` or ``a_b_c`` breaks the
mathtext graphkin builds around it (``$A^{n}_{P%}$``).  Two escapes:

* :func:`plain` for a user string printed as text (titles, point names in
  labels and tables): every ``$`` becomes ``\$``;
* :func:`math_escape` for a user string placed inside graphkin's own
  mathtext (the subscript of ``A^n_{CB}``): the mathtext specials are escaped.

:func:`sanitize_figure` is the last guard: before a figure is saved, every
text that would be parsed as mathtext is parsed once, and one that does not
parse is shown as plain text instead.

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 1.6 (lettering: the names must be
readable as written).
"""

from __future__ import annotations

from functools import lru_cache
from typing import Any

__all__ = ["plain", "math_escape", "is_math", "math_ok", "sanitize_figure"]

_MATH_SPECIALS = {
    "\\": r"\backslash{}",
    "{": r"\{",
    "}": r"\}",
    "_": r"\_",
    "^": r"\^{}",
    "%": r"\%",
    "#": r"\#",
    "~": r"\sim{}",
}


def plain(text: str) -> str:
    r"""A user string shown as plain text by matplotlib.

    Every ``$`` is escaped (no mathtext) and control characters are shown as
    ``\xNN`` (a title with an escape sequence prints what it holds).

    Examples
    --------
    >>> plain("P%"), plain("$\\frac{$"), plain("a_b_c"), plain("a\x1bb")
    ('P%', '\\$\\frac{\\$', 'a_b_c', 'a\\x1bb')
    """
    if any(ord(ch) < 32 or 127 <= ord(ch) < 160 for ch in text):
        text = "".join(f"\\x{ord(ch):02x}" if ord(ch) < 32 or 127 <= ord(ch) < 160 else ch
                       for ch in text)
    return text.replace("$", r"\$")


def math_escape(text: str) -> str | None:
    r"""A user string placed inside mathtext, its specials escaped; None when it cannot be.

    A ``$`` cannot appear inside mathtext at all: the caller then prints the
    whole label as plain text.

    Examples
    --------
    >>> math_escape("CB"), math_escape("P%"), math_escape("a_b"), math_escape("x$")
    ('CB', 'P\\%', 'a\\_b', None)
    """
    if "$" in text:
        return None
    return "".join(_MATH_SPECIALS.get(ch, ch) for ch in text)


def is_math(text: str) -> bool:
    """True when matplotlib would parse ``text`` as mathtext (an even, non-zero count of ``$``)."""
    n = text.count("$") - text.count(r"\$")
    return n > 0 and n % 2 == 0


MIN_PT = 6.0
"""The smallest type on any figure, in points (sub- and superscripts included)."""
SCRIPT = 0.7
"""mathtext's size of a sub- or superscript relative to its text."""


def shown_size(text: str, size: float) -> float:
    """The size (pt) a text is set at so that no glyph of it is under :data:`MIN_PT`.

    A mathtext label with a subscript (``$R_{A}$``) sets its script at 0.7 of
    the size: at 7 pt the ``A`` would be 4.9 pt, so such a text is set at
    6/0.7 = 8.6 pt.

    Examples
    --------
    >>> shown_size("B", 9.0), shown_size("B", 5.0), round(shown_size("$R_{A}$", 7.0), 2)
    (9.0, 6.0, 8.57)
    """
    if is_math(text) and ("_" in text or "^" in text) and size * SCRIPT < MIN_PT:
        return MIN_PT / SCRIPT
    return max(size, MIN_PT)


@lru_cache(maxsize=4096)
def math_ok(text: str) -> bool:
    """True when a mathtext string parses (cached: the same labels recur on every sheet).

    A text of several lines is parsed line by line, as matplotlib lays it out.
    """
    from matplotlib.mathtext import MathTextParser

    if "\n" in text:
        return all(math_ok(line) for line in text.split("\n") if is_math(line))

    try:
        MathTextParser("path").parse(text, 72, None)
    except Exception:  # noqa: BLE001 - pyparsing's and matplotlib's errors alike
        return False
    return True


def sanitize_figure(fig: Any) -> int:
    """Show every text of ``fig`` that would not parse as mathtext as plain text.

    Returns
    -------
    int
        How many texts were changed (0 when every string was already safe).
    """
    from matplotlib.text import Text

    changed = 0
    for t in fig.findobj(Text):
        s = t.get_text()
        if is_math(s) and not math_ok(s):
            t.set_text(plain(s.replace(r"\$", "$")))
            changed += 1
    return changed
