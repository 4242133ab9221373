"""The layers import one way (issue 18): a walk over every module's module-level imports.

Only imports that run when a module is loaded count: those at the top of a
module, in a top-level ``try`` or ``if`` (but not under ``if TYPE_CHECKING``).
An import inside a function (``Solution.draw`` reaching ``render``, a command
loading its analysis) runs only when called, and is fine.  See
docs/architecture.md for the layers.
"""

from __future__ import annotations

import ast
from collections import defaultdict
from pathlib import Path

import pytest

import graphkin

PACKAGE = Path(graphkin.__file__).parent

BASE = {"errors", "tolerance", "units", "text", "keys", "progress", "files"}
"""Leaf modules every layer may use."""

MODEL = BASE | {"geometry", "construction", "mechanisms"}

ALLOWED: dict[str, set[str]] = {
    "errors": set(),
    "tolerance": set(),
    "units": {"errors"},
    "text": set(),
    "keys": {"errors"},
    "progress": set(),
    "files": {"errors"},
    "geometry": BASE,
    "construction": BASE | {"geometry"},
    "mechanisms": BASE | {"geometry"},
    "examples": BASE | {"mechanisms"},
    "kinematics": MODEL,
    "forces": MODEL | {"kinematics"},
    "gears": MODEL,
    "cams": MODEL,
    "synthesis": MODEL,
    "io": MODEL | {"kinematics", "cams"},
    "output": MODEL | {"kinematics", "forces", "gears", "synthesis"},
    "render": MODEL | {"kinematics", "forces", "gears", "cams", "synthesis", "output"},
    "check": MODEL | {"kinematics", "forces", "output", "io"},
    "scan": MODEL | {"kinematics", "forces", "output", "io", "check"},
    "graphkin": MODEL | {"kinematics", "forces", "examples"},
    "commands": MODEL | {"kinematics", "forces", "gears", "cams", "synthesis", "output",
                         "render", "check", "scan", "io", "examples", "graphkin"},
    "cli": BASE | {"commands", "graphkin"},
    "__main__": {"cli"},
}
"""Package (or top-level module) -> what it may import when it is loaded."""


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def _part(module: str) -> str:
    """The layer a module belongs to: its package under graphkin, or the top-level module."""
    parts = module.split(".")
    return parts[1] if len(parts) > 1 else "graphkin"


def _loaded_imports(path: Path) -> list[str]:
    """The modules a file imports when it is loaded (relative imports made absolute)."""
    name = _module_name(path)
    is_package = path.name == "__init__.py"
    out: list[str] = []

    def visit(body: list[ast.stmt]) -> None:
        for node in body:
            if isinstance(node, ast.Import):
                out.extend(a.name for a in node.names)
            elif isinstance(node, ast.ImportFrom):
                base = node.module or ""
                if node.level:
                    parts = name.split(".")
                    keep = len(parts) - node.level + (1 if is_package else 0)
                    base = ".".join(parts[:keep] + ([node.module] if node.module else []))
                for a in node.names:
                    # ``from graphkin import text`` imports the module graphkin.text
                    sub = f"{base}.{a.name}"
                    out.append(sub if (PACKAGE.parent / Path(*sub.split("."))).exists()
                               or (PACKAGE.parent / (sub.replace(".", "/") + ".py")).exists()
                               else base)
            elif isinstance(node, ast.If):
                if "TYPE_CHECKING" not in ast.unparse(node.test):
                    visit(node.body)
                    visit(node.orelse)
            elif isinstance(node, ast.Try):
                visit(node.body)
                for h in node.handlers:
                    visit(h.body)
                visit(node.orelse)
                visit(node.finalbody)

    visit(ast.parse(path.read_text(encoding="utf-8")).body)
    return out


def _graph() -> tuple[dict[str, set[str]], dict[tuple[str, str], str], list[str]]:
    edges: dict[str, set[str]] = defaultdict(set)
    where: dict[tuple[str, str], str] = {}
    matplotlib: list[str] = []
    for path in sorted(PACKAGE.rglob("*.py")):
        module = _module_name(path)
        for imported in _loaded_imports(path):
            top = imported.split(".")[0]
            if top == "matplotlib" and _part(module) != "render":
                matplotlib.append(module)
            if top == "graphkin":
                a, b = _part(module), _part(imported)
                if a != b:
                    edges[a].add(b)
                    where.setdefault((a, b), f"{module} imports {imported}")
    return edges, where, matplotlib


def _cycle(edges: dict[str, set[str]]) -> list[str] | None:
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> list[str] | None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(edges.get(node, ())):
            if state.get(nxt) == 1:
                return stack[stack.index(nxt):] + [nxt]
            if nxt not in state:
                found = visit(nxt)
                if found:
                    return found
        state[node] = 2
        stack.pop()
        return None

    for node in sorted(edges):
        if node not in state:
            found = visit(node)
            if found:
                return found
    return None


def test_no_import_cycle_between_packages():
    edges, where, _ = _graph()
    cycle = _cycle(edges)
    assert cycle is None, ("import cycle between packages: " + " -> ".join(cycle) + "; "
                           + "; ".join(where[(a, b)] for a, b in zip(cycle, cycle[1:])))


def test_matplotlib_is_loaded_only_by_render():
    _, _, modules = _graph()
    assert not modules, f"matplotlib imported at module level outside render: {modules}"


def test_every_package_imports_only_the_layers_below_it():
    edges, where, _ = _graph()
    unknown = sorted(set(edges) - set(ALLOWED))
    assert not unknown, (f"new package(s) {unknown}: add them to ALLOWED here and to "
                         "docs/architecture.md")
    wrong = [where[(a, b)] for a in edges for b in sorted(edges[a]) if b not in ALLOWED[a]]
    assert not wrong, "imports against the layers: " + "; ".join(wrong)


def test_the_walk_sees_imports():
    """The walk is not vacuous: it finds the imports known to be there."""
    edges, _, _ = _graph()
    assert {"geometry", "construction", "mechanisms"} <= edges["kinematics"]
    assert "kinematics" in edges["output"]
    assert "kinematics" in edges["render"]


def test_a_cycle_is_found():
    assert _cycle({"a": {"b"}, "b": {"c"}, "c": {"a"}}) == ["a", "b", "c", "a"]
    assert _cycle({"a": {"b"}, "b": {"c"}}) is None


@pytest.mark.parametrize("module", ["graphkin", "graphkin.kinematics", "graphkin.output",
                                    "graphkin.check"])
def test_importing_below_render_does_not_load_matplotlib(module):
    import subprocess
    import sys

    code = f"import sys, {module}; print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True).stdout.strip()
    assert out == "False"


MAX_LINES = 800
"""The house's size limit (issue 18): no module in graphkin/ over about 800 lines."""


def _long_modules(root: Path, limit: int = MAX_LINES) -> list[str]:
    out = []
    for path in sorted(root.rglob("*.py")):
        n = len(path.read_text(encoding="utf-8").splitlines())
        if n > limit:
            out.append(f"{path.relative_to(root.parent)} ({n} lines)")
    return out


def test_no_module_over_800_lines():
    long = _long_modules(PACKAGE)
    assert not long, ("split by idea (docs/architecture.md): " + ", ".join(long))


def test_the_size_check_sees_a_long_module(tmp_path):
    """The size check is not vacuous: a file of 801 lines is found, one of 800 is not."""
    pkg = tmp_path / "pkg"
    pkg.mkdir()
    (pkg / "long.py").write_text("x = 1\n" * (MAX_LINES + 1), encoding="utf-8")
    (pkg / "ok.py").write_text("x = 1\n" * MAX_LINES, encoding="utf-8")
    assert _long_modules(pkg) == [f"pkg/long.py ({MAX_LINES + 1} lines)"]
