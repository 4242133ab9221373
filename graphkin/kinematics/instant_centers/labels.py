"""Link ids and the book's center labels: ``I13``, pair keys, the order of links."""

from __future__ import annotations

from collections.abc import Iterable

from graphkin.errors import InputError

__all__ = ["sort_links", "pair_key", "center_label"]

Pair = tuple[str, str]

# ---------------------------------------------------------------------------
# names
# ---------------------------------------------------------------------------

def _id_key(lid: str) -> tuple[int, int, str]:
    return (0, int(lid), "") if lid.isdigit() else (1, 0, lid)


def sort_links(ids: Iterable[object]) -> list[str]:
    """Link ids in the book's order: numeric ids by number, then named ones.

    Examples
    --------
    >>> sort_links(["10", "2", "1", "crank"])
    ['1', '2', '10', 'crank']
    """
    return sorted((str(i) for i in ids), key=_id_key)


def _triangle(i: str, j: str, k: str) -> tuple[str, str, str]:
    """The links of a Kennedy triangle in the book's order."""
    a, b, c = sort_links([i, j, k])
    return a, b, c


def pair_key(i: object, j: object) -> Pair:
    """The pair of link ids with the lower id first (``I31`` is ``I13``).

    Examples
    --------
    >>> pair_key(3, 1)
    ('1', '3')
    >>> pair_key("13", "2")
    ('2', '13')
    """
    a, b = str(i), str(j)
    if a == b:
        raise InputError(f"an instant center needs two different links, not {a} and {b}")
    return (a, b) if _id_key(a) <= _id_key(b) else (b, a)


def center_label(i: object, j: object) -> str:
    """The book's name of an instant center: ``I13``, or ``I1-13`` for longer ids.

    Examples
    --------
    >>> center_label(3, 1), center_label(1, 13)
    ('I13', 'I1-13')
    """
    a, b = pair_key(i, j)
    return f"I{a}{b}" if len(a) == 1 and len(b) == 1 else f"I{a}-{b}"


def _parse_pair(key: object) -> Pair:
    """``"I13"``, ``"I1-13"``, ``"1-3"``, ``(1, 3)`` -> ``("1", "3")``."""
    if isinstance(key, (tuple, list)) and len(key) == 2:
        return pair_key(*key)
    if isinstance(key, str):
        s = key[1:] if key[:1] in ("I", "i") else key
        if "-" in s:
            a, b = s.split("-", 1)
            return pair_key(a, b)
        if len(s) == 2:
            return pair_key(s[0], s[1])
    raise KeyError(f"not an instant center: {key!r} (write 'I13', 'I1-13', '1-3' or (1, 3))")
