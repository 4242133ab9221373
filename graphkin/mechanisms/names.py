"""Point names the constructions could take for their own labels (issue 25).

The constructions name their values in the book's notation, built from the
file's link ids and point names: ``θ3``, ``ω3``, ``s4``, ``I13``, ``F_43``,
``V_B``...  A point named like one of them would be read for that value, so
:func:`label_like` says why such a name is refused (``mechanisms/parse.py``
refuses it in one line naming the key; ``docs/formats/mechanism.md`` lists the
grammar).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

__all__ = ["LABEL_PREFIXES", "LINK_SYMBOLS", "contact_names", "label_like"]


#: Prefixes of the labels the constructions make from a point name or a link id, followed
#: by ``_``: forces and their lines (``F_43``, ``P_4``, ``T_12``, ``M_4``, ``W_4``, ``R_4``,
#: ``l_3``, ``q_4``, ``X_4``, ``n_1-4``, ``u_1-4``), velocities and accelerations (``V_B``,
#: ``A_B``), loci and curvature (``k_B``, ``J_B``, ``Q_B``), the Greek symbols, and the live
#: page's friction steps (``σ_1-4``, ``τ_1-4``, ``ι_1-4``: a rough joint's sense, turnover and
#: impending motion; ``n°_1-4``, ``V°_1-4``: its plain normal, its guide's velocity).
LABEL_PREFIXES = ("F", "P", "T", "M", "W", "R", "l", "q", "X", "n", "u", "V", "A", "k", "J",
                  "Q", "θ", "ω", "α", "σ", "τ", "ι", "n°", "V°")
#: Symbols the constructions put before a link id: ``θ3``, ``ω3``, ``α3``, ``s4``, ``ds4``,
#: ``dds4`` (a slider's travel and its rates).
LINK_SYMBOLS = ("θ", "ω", "α", "dds", "ds", "s")


def label_like(name: str, links: Mapping[str, Any]) -> str:
    """Why ``name`` could be taken for a construction's label ("" when it cannot).

    Examples
    --------
    >>> links = {"1": None, "2": None, "3": None, "4": None}
    >>> label_like("F_43", links)
    "it is written like a label of graphkin's constructions (F_…)"
    >>> label_like("ω3", links)
    "it is written like a link's symbol (ω3)"
    >>> label_like("I13", links)
    'it is written like an instant center (I13)'
    >>> label_like("a_b_c", links), label_like("O2", links), label_like("Q", links)
    ('', '', '')
    """
    head, sep, _ = name.partition("_")
    if sep and head in LABEL_PREFIXES:
        return f"it is written like a label of graphkin's constructions ({head}_…)"
    if name[:1] in ("θ", "ω", "α"):
        return f"it is written like a link's symbol ({name})"
    for sym in LINK_SYMBOLS:
        if name.startswith(sym) and name[len(sym):] in links:
            return f"it is written like a link's symbol ({name})"
    if name.startswith("I"):
        rest = name[1:]
        ids = [lid for lid in links if rest.startswith(lid)]
        if any(rest[len(a):].lstrip("-") in links for a in ids):
            return f"it is written like an instant center ({name})"
    return ""


def contact_names(count: int, taken: set[str] | frozenset[str]) -> list[str]:
    """The names of ``count`` rolling contacts' points, none of them a point of the file.

    The book calls the point of rolling contact ``C`` (Example 4.8, ``V_C4 =
    V_C3``) or ``P`` (Sec. 3.7, Fig. 3.14, ``P2``, ``P3``): the first contact is
    ``C`` unless the file has a point ``C``; a contact whose name is taken (a
    second contact, or the user's own pin ``C``) is ``P``, then ``C1``, ``C2``,
    ... the first name no point of the file and no other contact has.

    Examples
    --------
    >>> contact_names(1, {"A", "B"}), contact_names(2, {"A"}), contact_names(2, {"C", "P"})
    (['C'], ['C', 'P'], ['C1', 'C2'])
    """
    used = set(taken)
    out: list[str] = []
    candidates = ["C", "P"]
    k = 0
    for _ in range(count):
        while True:
            if candidates:
                name = candidates.pop(0)
            else:
                k += 1
                name = f"C{k}"
            if name not in used:
                break
        used.add(name)
        out.append(name)
    return out
