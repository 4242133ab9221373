"""Text that is safe to show on a terminal and to open in a spreadsheet.

Student names, keys, answers and drawing labels come from files graphkin did
not write: their control characters are escaped before they reach a terminal
(an escape sequence could retitle or clear it), and CSV cells that a
spreadsheet would run as a formula are neutralised.
"""

from __future__ import annotations

import re
import unicodedata

__all__ = ["printable", "spreadsheet_safe"]


def printable(text: object) -> str:
    r"""``text`` with control and direction-override characters escaped (safe on a terminal).

    Examples
    --------
    >>> print(printable("Ann\x1b[2J"))
    Ann\x1b[2J
    """
    out = []
    for ch in str(text):
        cat = unicodedata.category(ch)
        if cat == "Cc" and ch not in "\n" or cat == "Cf" and ch not in "\u200d":
            code = ord(ch)
            out.append(f"\\x{code:02x}" if code < 0x100 else f"\\u{code:04x}")
        else:
            out.append(ch)
    return "".join(out)


_PLAIN_NUMBER = re.compile(r"^[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?$")


def spreadsheet_safe(cell: object) -> object:
    """A CSV cell a spreadsheet will not run as a formula (``=``, ``+``, ``-``, ``@`` first).

    Numbers stay numbers; other text starting with a formula character gets a
    leading apostrophe (OWASP's advice on CSV injection).

    Examples
    --------
    >>> spreadsheet_safe("=HYPERLINK(1)"), spreadsheet_safe("-5.88"), spreadsheet_safe(3)
    ("'=HYPERLINK(1)", '-5.88', 3)
    """
    if not isinstance(cell, str):
        return cell
    text = printable(cell).replace("\n", " ")
    if text[:1] in ("=", "+", "-", "@", "\t", "\r") and not _PLAIN_NUMBER.match(text):
        return "'" + text
    return text
