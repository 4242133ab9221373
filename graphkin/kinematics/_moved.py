"""Names that moved up to the output layer, still importable from their old kinematics module."""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import Any

__all__ = ["moved_to"]


def moved_to(module: str, names: tuple[str, ...], old: str) -> Callable[[str], Any]:
    """A module ``__getattr__`` (PEP 562) that finds ``names`` in ``module`` on first use.

    The report functions of the instant-center and curvature packages live in
    :mod:`graphkin.output`, above the kinematics; importing them lazily keeps
    ``from graphkin.kinematics.curvature import curvature_json`` working
    without the kinematics loading the layer above it.

    Examples
    --------
    >>> getattr_ = moved_to("graphkin.output.curvature", ("paths_json",), "somewhere")
    >>> getattr_("paths_json").__module__
    'graphkin.output.curvature'
    """

    def __getattr__(name: str) -> Any:
        if name in names:
            return getattr(importlib.import_module(module), name)
        raise AttributeError(f"module {old!r} has no attribute {name!r}")

    return __getattr__
