"""Answer keys in the book's notation: ``omega3``, ``V_E``, ``A_CB^n``, ``I13``, ``rho_C``.

:func:`parse_key` reads a key against a mechanism (its links and points),
:func:`valid_keys` lists the keys of the usual forms for suggestions when one
is misspelt (:func:`suggest`).

References
----------
Uicker, Pennock & Shigley, 5th ed., Sec. 3.2-3.4 (notation ``V_P``, ``V_PQ``,
``ω``), 3.6 (coincident points ``A4``), 3.13 (instant centers ``I_ij``),
4.2-4.6 (``A_PQ^n``, ``A_PQ^t``, Coriolis), 4.14 (radius of curvature).
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass, field
from typing import Any

from graphkin.errors import InputError
from graphkin.mechanisms.model import Mechanism

KEY_HELP = ("keys are theta<k>, omega<k>, alpha<k>, V_<P>, A_<P>, V_<P><Q>, A_<P><Q>, "
            "A_<P><Q>^n, A_<P><Q>^t, A_<P>^c, R_<P>, R_<P><Q>, I<i><j>, rho_<P>, "
            "F_<i><j> (force by link i on link j), T_1<k> (the drive's torque)")

#: keys of an answers file that are not answers
META_KEYS = ("tolerance", "student", "name", "title", "comment", "notes", "mechanism")
_SCALAR_KIND = {"omega": "omega", "alpha": "alpha"}
_VECTOR_KIND = {"V": "velocity", "A": "acceleration", "An": "acceleration",
                "At": "acceleration", "Ac": "acceleration", "R": "length"}
_GREEK = {"θ": "theta", "ω": "omega", "α": "alpha", "ρ": "rho"}


@dataclass(frozen=True)
class Key:
    """A quantity named in textbook notation.

    Attributes
    ----------
    text : str
        The key as written.
    kind : str
        ``theta``, ``omega``, ``alpha`` (args: link), ``V``, ``A``, ``R``
        (args: point, or point and reference point), ``An``, ``At`` (the
        normal and tangential components of ``A_PQ``), ``Ac`` (the Coriolis
        component at a point), ``I`` (args: two link ids), ``rho`` (a point).
    args : tuple of str
    link : str or None
        For ``V_A4``, ``A_A4``: the link whose coincident point at A is meant
        (the book's A4, Sec. 3.6), else None.
    """

    text: str
    kind: str
    args: tuple[str, ...]
    link: str | None = field(default=None, repr=False)

    @property
    def quantity(self) -> str:
        """What kind of value the key wants (for units): ``angle``, ``omega``, ``velocity``..."""
        if self.kind == "theta":
            return "angle"
        if self.kind in _SCALAR_KIND:
            return _SCALAR_KIND[self.kind]
        if self.kind in _VECTOR_KIND:
            return _VECTOR_KIND[self.kind]
        if self.kind in ("F", "T"):  # docs/forces.md
            return "force" if self.kind == "F" else "torque"
        return "length"

    @property
    def shape(self) -> str:
        """How the value compares: ``angle``, ``scalar``, ``vector``, ``point``, ``magnitude``."""
        if self.kind == "theta":
            return "angle"
        if self.kind in _SCALAR_KIND or self.kind == "T":
            return "scalar"
        if self.kind == "I" or (self.kind == "R" and len(self.args) == 1):
            return "point"
        if self.kind == "rho":
            return "magnitude"
        return "vector"

    def pretty(self) -> str:
        """The key in the book's symbols: ``ω3``, ``V_CB``, ``I13``."""
        sym = {"theta": "θ", "omega": "ω", "alpha": "α"}
        if self.kind in sym:
            return sym[self.kind] + self.args[0]
        return self.text


def _split_pair(rest: str, names: list[str], key: str, what: str,
                file: str | None) -> tuple[str, str] | None:
    if "-" in rest:
        a, _, b = rest.partition("-")
        if a in names and b in names:
            return a, b
        raise InputError(f"{rest!r} is not two {what} separated by '-'; {what}: "
                         f"{', '.join(names)}", key=key, file=file)
    splits = [(rest[:i], rest[i:]) for i in range(1, len(rest))
              if rest[:i] in names and rest[i:] in names]
    if len(splits) == 1:
        return splits[0]
    if len(splits) > 1:
        raise InputError(f"{rest!r} can be read as {' or '.join('-'.join(s) for s in splits)}; "
                         f"write it with a '-'", key=key, file=file)
    return None


def parse_key(text: str, mech: Mechanism, *, file: str | None = None) -> Key:
    """Read an answer key against a mechanism's link ids and point names.

    Raises
    ------
    InputError
        Unknown kind of key, unknown link or point, or an ambiguous pair.

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.fourbar()
    >>> parse_key("V_CB", mech)
    Key(text='V_CB', kind='V', args=('C', 'B'))
    >>> parse_key("omega3", mech).args, parse_key("I13", mech).args
    (('3',), ('1', '3'))
    >>> parse_key("A_CB^n", mech).kind
    'An'
    """
    raw = text
    s = text.strip()
    for g, name in _GREEK.items():
        if s.startswith(g):
            s = name + s[len(g):]
    names = list(mech.point_names)
    links = list(mech.links)
    shown = [n for n in names if n not in mech.helper_points]  # never slot-definition points

    m = re.fullmatch(r"(theta|omega|alpha)_?(.+)", s)
    if m:
        lid = m.group(2)
        if lid not in links:
            raise InputError(f"no link {lid!r}; links are {', '.join(links)}", key=raw, file=file)
        return Key(raw, m.group(1), (lid,))
    m = re.fullmatch(r"rho_(.+)", s)
    if m:
        p = m.group(1)
        if p not in names:
            raise InputError(f"no point {p!r}; points are {', '.join(shown)}", key=raw, file=file)
        return Key(raw, "rho", (p,))
    m = re.fullmatch(r"I_?(.+)", s)
    if m:
        rest = m.group(1)
        pair = _split_pair(rest, links, raw, "link ids", file)
        if pair is None or pair[0] == pair[1]:
            raise InputError(f"{rest!r} is not two different link ids; links are "
                             f"{', '.join(links)} (write I1-13 for long ids)", key=raw, file=file)
        a, b = sorted(pair, key=_id_order)
        return Key(raw, "I", (a, b))
    m = re.fullmatch(r"([FT])_?(.+)", s)
    if m and mech.has_forces:  # a joint force F_34 or the drive's torque T_12 (Ch. 11-12)
        rest = m.group(2)
        pair = _split_pair(rest, links, raw, "link ids", file)
        if pair is None or pair[0] == pair[1]:
            raise InputError(f"{rest!r} is not two different link ids; links are "
                             f"{', '.join(links)} (write F_3-4 for long ids)", key=raw, file=file)
        return Key(raw, m.group(1), pair)
    m = re.fullmatch(r"([VAR])_(.+)", s)
    if m:
        letter, rest = m.group(1), m.group(2)
        kind = letter
        if rest not in names and letter == "A":
            sm = re.fullmatch(r"(.+?)(?:\^|_)([ntc])", rest)
            if sm:
                rest, comp = sm.group(1), sm.group(2)
                kind = {"n": "An", "t": "At", "c": "Ac"}[comp]
        if rest in names:
            if kind in ("An", "At"):
                raise InputError(f"{kind[-1]} components belong to a difference such as "
                                 f"A_{rest}B^{kind[-1]}", key=raw, file=file)
            return Key(raw, kind, (rest,))
        if kind == "Ac":
            raise InputError(f"no point {rest!r}; points are {', '.join(shown)}", key=raw,
                             file=file)
        pair = _split_pair(rest, names, raw, "points", file)
        if pair is None and kind in ("V", "A"):
            on = point_on_link(rest, mech)
            if on is not None:
                return Key(raw, kind, (on[0],), link=on[1])
        if pair is None:
            raise InputError(f"{rest!r} is not a point or a pair of points; points are "
                             f"{', '.join(shown)}", key=raw, file=file)
        if pair[0] == pair[1]:
            raise InputError("a difference needs two different points", key=raw, file=file)
        return Key(raw, kind, pair)
    raise InputError(f"unknown answer key; {KEY_HELP}", key=raw, file=file)


def point_on_link(text: str, mech: Mechanism) -> tuple[str, str] | None:
    """``"A4"`` -> ``("A", "4")``: the point of link 4 that coincides with A (Sec. 3.6).

    Examples
    --------
    >>> import graphkin
    >>> mech = graphkin.examples.fourbar()   # links 1 to 4
    >>> point_on_link("B4", mech), point_on_link("B5", mech)
    (('B', '4'), None)
    """
    text = text.replace("@", "")
    for i in range(len(text) - 1, 0, -1):
        name, lid = text[:i], text[i:]
        if name in mech.point_names and lid in mech.links:
            return name, lid
    return None


def _id_order(lid: str) -> tuple[int, int | str]:
    return (0, int(lid)) if lid.isdigit() else (1, lid)


def valid_keys(mech: Mechanism) -> list[str]:
    """Every answer key of the usual forms for a mechanism, and the other keys of the file.

    For suggestions (``difflib``) when a key is misspelt.
    """
    links = list(mech.links)
    moving = [lid for lid in links if lid != "1"]
    helpers = mech.helper_points
    names = [n for n in mech.point_names if n not in helpers]
    keys = list(META_KEYS)
    for lid in moving:
        keys += [f"theta{lid}", f"omega{lid}", f"alpha{lid}"]
    for n in names:
        keys += [f"V_{n}", f"A_{n}", f"R_{n}", f"rho_{n}"]
    for link in mech.links.values():
        pts = [n for n in link.points if n in names]
        for p in pts:
            for q in pts:
                if p != q:
                    sep = "" if len(p) == len(q) == 1 else "-"
                    keys += [f"V_{p}{sep}{q}", f"A_{p}{sep}{q}", f"A_{p}{sep}{q}^n",
                             f"A_{p}{sep}{q}^t"]
    for i, a in enumerate(links):
        for b in links[i + 1:]:
            keys.append(f"I{a}{b}" if len(a) == len(b) == 1 else f"I{a}-{b}")
    return list(dict.fromkeys(keys))


def suggest(word: str, valid: Any) -> str:
    """``" (did you mean 'x'?)"`` for the nearest valid key, or ``""``.

    Examples
    --------
    >>> suggest("titel", ["title", "student"])
    " (did you mean 'title'?)"

    A key that differs only in case is the one meant (``V_e`` is V_E, not V_P):

    >>> suggest("V_e", ["V_P", "V_E", "A_E"])
    " (did you mean 'V_E'?)"
    """
    valid = list(valid)
    same = [v for v in valid if v.casefold() == word.casefold()]
    if same:
        return f" (did you mean {same[0]!r}?)"
    near = difflib.get_close_matches(word, valid, n=1, cutoff=0.6)
    return f" (did you mean {near[0]!r}?)" if near else ""
