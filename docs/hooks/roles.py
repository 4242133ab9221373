"""MkDocs hook: Sphinx cross-reference roles in docstrings shown as plain code.

graphkin's docstrings follow numpydoc, whose ``See Also`` and prose use Sphinx
roles (``:func:`load```, ``:class:`Mechanism```).  mkdocstrings renders the
backquoted name as code but leaves the role's prefix as text (":func:"), so
the API pages read "see :func: load".  This hook drops the prefix and keeps
the code.
"""

from __future__ import annotations

import re
from typing import Any

_ROLE = re.compile(r":(?:py:)?(?:func|class|meth|mod|data|attr|exc|obj|const|ref|term):"
                   r"\s*(?=<code>|`)")
_TILDE = re.compile(r"<code>~")


def on_page_content(html: str, **_: Any) -> str:
    """Drop ``:func:`` and its kin before inline code (and Sphinx's ``~`` shortener)."""
    return _TILDE.sub("<code>", _ROLE.sub("", html))
