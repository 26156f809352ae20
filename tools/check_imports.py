"""Fails (exit 1) on any import cycle inside the ``pendulab`` package: the layout rule of
ARCHITECTURE.md is that modules import downward only.

The graph is read from the source with ``ast`` — every ``import`` and ``from … import`` anywhere in a
module, inside functions and ``if TYPE_CHECKING:`` blocks included, since a cycle hidden in a function
is still a cycle of the design. An edge goes to the module named; ``from pkg import name`` goes to
``pkg.name`` when that is a module, else to ``pkg`` (its ``__init__``). The package's own face
(``pendulab/__init__.py``, which re-exports everything) and the compiled ``_core`` are left out.

Usage: ``python tools/check_imports.py [PACKAGE_DIR]`` (default ``python/pendulab``).
"""

from __future__ import annotations

import ast
import sys
from collections.abc import Iterable, Mapping
from pathlib import Path

ROOT = "pendulab"


def module_names(package_dir: Path) -> dict[str, Path]:
    """Dotted module name → file, for every ``.py`` under ``package_dir``."""
    names: dict[str, Path] = {}
    for path in sorted(package_dir.rglob("*.py")):
        parts = list(path.relative_to(package_dir).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        names[".".join([ROOT, *parts])] = path
    return names


def _resolve(importer: str, is_package: bool, level: int, module: str | None) -> str:
    """The absolute name of ``from <level dots><module> import …`` written in ``importer``."""
    if level == 0:
        return module or ""
    base = importer.split(".")
    if not is_package:
        base = base[:-1]
    base = base[: len(base) - (level - 1)]
    return ".".join(base + ([module] if module else []))


def import_graph(package_dir: Path) -> dict[str, set[str]]:
    """Module → the modules of the package it imports (anywhere in its source)."""
    modules = module_names(package_dir)
    graph: dict[str, set[str]] = {m: set() for m in modules}
    for name, path in modules.items():
        is_package = path.name == "__init__.py"
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"), str(path))):
            targets: list[str] = []
            if isinstance(node, ast.Import):
                targets = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                base = _resolve(name, is_package, node.level, node.module)
                for alias in node.names:
                    sub = f"{base}.{alias.name}"
                    targets.append(sub if sub in modules else base)
            for t in targets:
                if t in modules and t != ROOT and t != name:
                    graph[name].add(t)
    graph.pop(ROOT, None)
    return graph


def cycles(graph: Mapping[str, Iterable[str]]) -> list[list[str]]:
    """The strongly connected components with more than one module (Tarjan), each sorted."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    counter = 0

    def visit(v: str) -> None:
        nonlocal counter
        index[v] = low[v] = counter
        counter += 1
        stack.append(v)
        on_stack.add(v)
        for w in graph.get(v, ()):
            if w not in graph:
                continue
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on_stack:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on_stack.discard(w)
                component.append(w)
                if w == v:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    sys.setrecursionlimit(max(sys.getrecursionlimit(), 10 * len(graph) + 100))
    for v in sorted(graph):
        if v not in index:
            visit(v)
    return sorted(found)


def main(argv: list[str]) -> int:
    package_dir = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parents[1] / "python" / ROOT
    graph = import_graph(package_dir)
    found = cycles(graph)
    for component in found:
        members = set(component)
        edges = [f"{a} -> {b}" for a in component for b in sorted(graph[a]) if b in members]
        print(f"import cycle among {len(component)} modules: " + "; ".join(edges), file=sys.stderr)
    if found:
        print("error: modules must import downward only (ARCHITECTURE.md)", file=sys.stderr)
        return 1
    print(f"import graph of {ROOT}: {len(graph)} modules, no cycles")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
