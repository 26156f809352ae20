"""The package layout stays as ARCHITECTURE.md draws it: no import cycle inside ``pendulab``
(tools/check_imports.py, also run by ``make lint``), and no module hidden behind a public function of
the same name (``pendulab.exact`` is the function, its module is ``pendulab.theory.exact``)."""

from __future__ import annotations

import pkgutil
import types
from pathlib import Path

from conftest import load_tool

import pendulab as pl

ROOT = Path(__file__).resolve().parents[2]


def test_the_package_has_no_import_cycle() -> None:
    check = load_tool("check_imports")
    graph = check.import_graph(Path(pl.__file__).parent)
    assert "pendulab.simulation" in graph and "pendulab.cli.common" in graph
    assert check.cycles(graph) == []


def test_the_check_finds_a_cycle_hidden_in_a_function(tmp_path: Path) -> None:
    pkg = tmp_path / "pendulab"
    (pkg / "sub").mkdir(parents=True)
    (pkg / "__init__.py").write_text("from .a import f\n")
    (pkg / "a.py").write_text("def f():\n    from .sub import b\n    return b\n")
    (pkg / "sub" / "__init__.py").write_text("")
    (pkg / "sub" / "b.py").write_text("from .. import a\n")
    (pkg / "c.py").write_text("from .a import f\n")  # downward only: not part of the cycle
    check = load_tool("check_imports")
    assert check.cycles(check.import_graph(pkg)) == [["pendulab.a", "pendulab.sub.b"]]
    assert check.main(["check_imports", str(pkg)]) == 1


def test_no_public_name_shadows_a_module() -> None:
    modules = {m.name for m in pkgutil.iter_modules(pl.__path__)}
    for name in pl.__all__:
        value = getattr(pl, name)
        if name in modules:
            assert isinstance(value, types.ModuleType), f"pendulab.{name} is a module and a {type(value)}"


def test_the_check_sees_the_servers_rules_that_pendulab_serve_reads_its_options_by() -> None:
    """``pendulab serve`` checks --idle-timeout and --fit-time-limit by the server's own rules, imported
    when the option is read: edges of the graph (they were reached by importlib with strings, unseen)."""
    check = load_tool("check_imports")
    serve = check.import_graph(Path(pl.__file__).parent)["pendulab.cli.serve"]
    assert {"pendulab.server.serving", "pendulab.server.fit"} <= serve, serve
