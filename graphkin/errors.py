"""Errors raised by graphkin.

Every error derives from :class:`GraphkinError` *and* a builtin, so callers may
catch either.  Geometry never raises for a point at infinity; the domain layers
(constructions, mechanisms) raise, naming the step or the file key and the
objects involved.  Errors pickle, carrying their attributes.
"""

from __future__ import annotations

from typing import Any

__all__ = [
    "GraphkinError",
    "InputError",
    "ConstructionError",
    "NoIntersectionError",
    "ParallelDirectionsError",
    "DegenerateError",
    "IdealPointError",
    "AssemblyError",
]


class GraphkinError(Exception):
    """Base class of every graphkin error.

    Parameters
    ----------
    message : str
        What went wrong, in one line.
    **info
        Attributes kept on the error (``step``, ``key``, ``file``, objects).
    """

    def __init__(self, message: str, **info: Any) -> None:
        super().__init__(message)
        self.message = message
        self.info = dict(info)
        for name, value in info.items():
            setattr(self, name, value)

    def __reduce__(self) -> tuple[Any, ...]:
        return (_rebuild, (type(self), self.message, self.info))

    def __str__(self) -> str:
        return self.message


def _rebuild(cls: type[GraphkinError], message: str, info: dict[str, Any]) -> GraphkinError:
    return cls(message, **info)


class InputError(GraphkinError, ValueError):
    """A mechanism, answers or vector file that cannot be used as written.

    Carries ``file`` and ``key`` (the dotted TOML key) when known.
    """

    file: str | None
    key: str | None

    def __init__(self, message: str, *, key: str | None = None, file: str | None = None,
                 **info: Any) -> None:
        super().__init__(message, key=key, file=file, **info)

    def one_line(self) -> str:
        """The message the CLI prints: ``file: key: reason``."""
        parts = [p for p in (self.file, self.key) if p]
        return ": ".join([*parts, self.message])


class ConstructionError(GraphkinError, ValueError):
    """A construction step cannot be carried out (carries ``step`` and its objects)."""


class NoIntersectionError(ConstructionError):
    """The arcs or the line and arc of a step do not meet: that branch is missing."""


class ParallelDirectionsError(ConstructionError):
    """A case-3 construction whose two directions are parallel (the lines meet at infinity)."""


class AssemblyError(ConstructionError):
    """The mechanism cannot be assembled at the given drive."""


class DegenerateError(GraphkinError, ArithmeticError):
    """A truly degenerate operation: the join of coincident points, the meet of coincident lines."""


class IdealPointError(GraphkinError, ValueError):
    """Finite coordinates were asked of a point at infinity."""
