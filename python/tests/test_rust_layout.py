"""The Rust core's module graph has no cycle (tools/check_rust_modules.py, also run by ``make lint``),
and the check finds the cycles it is meant to find: a file reaching up into a module that uses it,
written as a ``use`` group or inline, while comments, strings and unit tests do not count."""

from __future__ import annotations

from pathlib import Path

from conftest import load_tool

ROOT = Path(__file__).resolve().parents[2]


def test_the_core_crate_has_no_module_cycle() -> None:
    check = load_tool("check_rust_modules")
    _, edges = check.parse(ROOT / "crates" / "pendulab-core" / "src")
    assert "state" in edges["model::registry"] and "limits" in edges["state"]
    assert "model::registry" in edges["model::any_model"]  # a `use super::registry::spec`
    assert "elastic" in edges["model::any_model"]  # inline `crate::elastic::SwingingSpring::new`
    assert check.cycles(edges) == []
    assert check.main(["x", str(ROOT / "crates" / "pendulab-core" / "src")]) == 0


def _crate(tmp_path: Path, state_rs: str) -> Path:
    src = tmp_path / "src"
    (src / "model").mkdir(parents=True)
    (src / "lib.rs").write_text("pub mod model;\npub mod state;\n")
    (src / "model" / "mod.rs").write_text(
        "pub mod registry;\npub use registry::Spec;\nuse crate::state::State;\npub fn f(_: State) {}\n"
    )
    (src / "model" / "registry.rs").write_text("use crate::state::{self, State};\npub struct Spec;\n")
    (src / "state.rs").write_text(state_rs)
    return src


def test_the_check_finds_a_file_reaching_up(tmp_path: Path) -> None:
    check = load_tool("check_rust_modules")
    up = _crate(tmp_path / "a", "pub struct State;\nfn g() { let _ = crate::model::Spec; }\n")
    _, edges = check.parse(up)
    assert edges["state"] == {"model::registry"}  # followed through the re-export of model/mod.rs
    assert check.cycles(edges) == [["model::registry", "state"]]
    assert check.main(["x", str(up)]) == 1


def test_comments_strings_and_tests_are_not_edges(tmp_path: Path) -> None:
    check = load_tool("check_rust_modules")
    text = (
        "pub struct State;\n// crate::model::Spec in a comment\n"
        'const S: &str = "crate::model::Spec // in a string";\n'
        "#[cfg(test)]\nmod tests {\n    use crate::model::Spec;\n    fn t() { let _ = Spec; }\n}\n"
    )
    down = _crate(tmp_path / "b", text)
    assert check.parse(down)[1]["state"] == set()
    assert check.main(["x", str(down)]) == 0
