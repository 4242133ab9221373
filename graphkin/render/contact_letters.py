"""The letters of image points, one rule for the drawings and the live page.

The book letters an image by its point in lowercase (``b``, ``c′`` for the
acceleration image, Secs. 3.5 and 4.3) and a point of one link by the link as
a subscript (``a₄``).  At a rolling contact the coincident points of the two
links have one velocity (no slip, Eq. 3.13), so their image carries both
letters, as in Fig. 3.14b (``P₂ = P₃``): ``c₄ = c₂``.  Their accelerations
differ by the rolling component (Eq. 4.19), so each link's contact image has
its own letters (``c′₄``, ``c′₂``); a link in two contacts (a planet on its sun
and in its ring) names the other link: ``c′₄ (4/2)``.

A point whose name ends in digits (a third contact ``C1``, a pivot ``O2``) keeps
its digits as its own subscript and puts the link apart in parentheses,
``c₁ (4)``, never ``c₁₄`` or ``c1₄``, where the digit of the name and the link
would run together.

This module imports nothing from matplotlib: :mod:`graphkin.render.paint` (``draw``)
and :mod:`graphkin.render.live` (the live page) both letter through it.
"""

from __future__ import annotations

from collections.abc import Sequence

__all__ = ["point_letters", "contact_velocity_letters", "contact_acceleration_letters"]

_SUB = str.maketrans("0123456789", "₀₁₂₃₄₅₆₇₈₉")


def _split(name: str) -> tuple[str, str]:
    """``C1`` -> ``("C", "1")``; ``O2`` -> ``("O", "2")``; ``12`` -> ``("12", "")``."""
    i = len(name)
    while i > 0 and name[i - 1].isdigit():
        i -= 1
    return (name[:i], name[i:]) if i else (name, "")


def point_letters(name: str, link: str = "", prime: bool = False, of: str = "") -> str:
    """The letters of the image of point ``name`` (of link ``link``), primed for accelerations.

    ``of`` names the pair of links (``"4/2"``) when the point must say which
    contact it is; it replaces the plain link in the parentheses.

    Examples
    --------
    >>> point_letters("B"), point_letters("C", prime=True), point_letters("A", "4")
    ('b', 'c′', 'a₄')
    >>> point_letters("O2"), point_letters("O2", prime=True), point_letters("C1", "4")
    ('o₂', 'o′₂', 'c₁ (4)')
    >>> point_letters("C", "4", True, of="4/2"), point_letters("C1", "4", True, of="4/2")
    ('c′₄ (4/2)', 'c′₁ (4/2)')
    """
    letters, digits = _split(name)
    head = letters.lower() + ("′" if prime else "")
    if digits and link:
        return f"{head}{digits.translate(_SUB)} ({of or link})"
    return f"{head}{(digits + link).translate(_SUB)}" + (f" ({of})" if of else "")


def contact_velocity_letters(name: str, links: Sequence[str]) -> str:
    """The one velocity image of a contact's coincident points: ``c₄ = c₂`` (Fig. 3.14b).

    Examples
    --------
    >>> contact_velocity_letters("C", ("4", "2")), contact_velocity_letters("C1", ("4", "1"))
    ('c₄ = c₂', 'c₁ (4) = c₁ (1)')
    """
    return " = ".join(point_letters(name, lid) for lid in links)


def contact_acceleration_letters(name: str, link: str, other: str, shared: bool) -> str:
    """The acceleration image of link ``link``'s contact point with ``other`` (Eq. 4.19).

    ``shared``: the link is in another contact too, so the letters name the pair.

    Examples
    --------
    >>> contact_acceleration_letters("C", "4", "2", False)
    'c′₄'
    >>> contact_acceleration_letters("P", "4", "1", True)
    'p′₄ (4/1)'
    >>> contact_acceleration_letters("C1", "4", "2", False)
    'c′₁ (4)'
    """
    return point_letters(name, link, True, of=f"{link}/{other}" if shared else "")
