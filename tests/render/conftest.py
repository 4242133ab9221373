"""Shared, cached solutions and drawings for the render tests (drawing is the slow part)."""

from __future__ import annotations

from functools import cache
from types import SimpleNamespace

import pytest
from spec_data import EXAMPLES

import graphkin


@cache
def _solved(name: str) -> graphkin.Solution:
    return graphkin.load(EXAMPLES / f"{name}.toml").solve()


@cache
def _drawn(name: str, diagram: str):
    from graphkin.render import draw

    return draw(_solved(name), diagram)


@cache
def _exact(name: str) -> graphkin.Solution:
    from graphkin.kinematics.analytic import solve_analytic

    return solve_analytic(_solved(name).mechanism)


@cache
def _svg(name: str, diagram: str) -> bytes:
    from graphkin.render import to_bytes

    return to_bytes(_drawn(name, diagram).figure)


@pytest.fixture(scope="session")
def gk():
    """``gk.solved(name)``, ``gk.drawn(name, diagram)``, ``gk.exact(name)``, ``gk.svg(...)``.

    Spec examples solved, drawn, solved analytically (the independent oracle)
    and saved as SVG, each once per session.
    """
    return SimpleNamespace(solved=_solved, drawn=_drawn, exact=_exact, svg=_svg)


@pytest.fixture(scope="module")
def browser():
    """Headless Chromium at the live pages' size, one per test module (skips without it).

    A module that wants another size (tests/render/test_browser.py) defines its own.
    """
    from cdp import browser_or_skip

    b = browser_or_skip(1300, 1000)
    yield b
    b.close()
