"""Ready mechanisms from the textbook's worked examples, shipped with graphkin.

Something to try right after ``pip install graphkin``, and the mechanisms the
docstring examples use::

    >>> import graphkin
    >>> sol = graphkin.examples.fourbar().solve()
    >>> round(float(sol.angle(3)), 2)  # θ₃ of Example 3.1: the book gives 20.92°
    20.92
    >>> names()[:3]
    ['cam_follower', 'coriolis_block', 'crank_rocker']
    >>> text("fourbar").splitlines()[0]
    'title = "Four-bar linkage with coupler and rocker points (Uicker Examples 3.1, 4.2)"'

Each function returns a fresh :class:`~graphkin.mechanisms.model.Mechanism`;
:func:`text` gives the mechanism file itself (``graphkin example NAME``
prints it, to copy and edit).

References
----------
Uicker, Pennock & Shigley, 5th ed.: Examples 2.6, 3.1, 3.2, 3.3, 3.9, 4.4, 4.7,
4.11 and 5.4; Sec. 1.10 (the crank-shaper quick-return).
"""

from __future__ import annotations

from importlib import resources
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from graphkin.mechanisms.model import Mechanism

__all__ = ["names", "text", "load", "fourbar", "crank_rocker", "slider_crank",
           "inverted_slider_crank", "coriolis_block", "fivebar", "cam_follower", "rapsons_slide",
           "rolling_wheel", "planetary", "quick_return", "inline_engine", "watt_sixbar"]


def _data():  # type: ignore[no-untyped-def]
    return resources.files(__package__).joinpath("data")


def names() -> list[str]:
    """The names of the shipped mechanisms, sorted."""
    return sorted(p.name[:-5] for p in _data().iterdir() if p.name.endswith(".toml"))


def text(name: str) -> str:
    """The mechanism file ``name`` as text (see :func:`names`).

    Raises
    ------
    InputError
        For a name that is not shipped (the message lists the names).
    """
    from graphkin.errors import InputError

    if name not in names():
        raise InputError(f"no example {name!r} (examples: {', '.join(names())})", key=name)
    return _data().joinpath(f"{name}.toml").read_text(encoding="utf-8")


def load(name: str) -> Mechanism:
    """The shipped mechanism ``name``, parsed."""
    from graphkin.mechanisms import loads

    return loads(text(name), source=f"<example {name}>")


def fourbar() -> Mechanism:
    """The four-bar of Examples 3.1 and 4.2 (θ₂ = 120°, ω₂ = 900 rev/min cw)."""
    return load("fourbar")


def crank_rocker() -> Mechanism:
    """The crank-rocker of Example 2.6 with its coupler point P (θ₂ = 60°, ω₂ = 10 rad/s ccw)."""
    return load("crank_rocker")


def slider_crank() -> Mechanism:
    """The offset slider-crank of Examples 3.2 and 3.8, driven by its slider."""
    return load("slider_crank")


def inverted_slider_crank() -> Mechanism:
    """The inverted slider-crank of Examples 3.3 and 4.6."""
    return load("inverted_slider_crank")


def coriolis_block() -> Mechanism:
    """The block sliding on a rotating link of Example 4.4 (Coriolis)."""
    return load("coriolis_block")


def fivebar() -> Mechanism:
    """The two-input five-bar of Examples 5.1-5.4."""
    return load("fivebar")


def cam_follower() -> Mechanism:
    """The circular cam and flat-faced follower of Example 4.7, as its equivalent linkage."""
    return load("cam_follower")


def rapsons_slide() -> Mechanism:
    """Rapson's slide of Examples 4.11 and 4.15."""
    return load("rapsons_slide")


def rolling_wheel() -> Mechanism:
    """The wheel rolling on the ground of Example 3.9."""
    return load("rolling_wheel")


def planetary() -> Mechanism:
    """A planet gear rolling outside a fixed sun, carried by an arm."""
    return load("planetary")


def quick_return() -> Mechanism:
    """The crank-shaper quick-return of Sec. 1.10 (the tutorial's): block 3 as a pin in a slot."""
    return load("quick_return")


def inline_engine() -> Mechanism:
    """An in-line slider-crank at 1800 rev/min: crank 2 in, rod 8 in (the tutorial's)."""
    return load("inline_engine")


def watt_sixbar() -> Mechanism:
    """A Watt I six-bar (two adjacent ternary links) whose link 5 nearly translates here."""
    return load("watt_sixbar")
