"""The registry of construction operations by name (:data:`OPS`) and its decorator."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

__all__ = ["OPS", "OUTPUT_KIND", "op"]

Array = np.ndarray

OPS: dict[str, Callable[..., tuple[Array, ...]]] = {}

OUTPUT_KIND: dict[str, str] = {}


def op(name: str, kind: str = "point") -> Callable[[Callable[..., Any]], Callable[..., Any]]:
    """Register an operation under ``name``; ``kind`` is the kind of its outputs."""

    def deco(f: Callable[..., Any]) -> Callable[..., Any]:
        OPS[name] = f
        OUTPUT_KIND[name] = kind
        return f

    return deco
