"""The 400-line limit per source file (tools/check_file_length.py, also run by ``make lint``): the
repository keeps it, a file over the limit fails with its name and length, an allowlisted file may
shrink but not grow, and a stale allowlist entry fails."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import REPO, load_tool

check = load_tool("check_file_length")


def write(root: Path, name: str, lines: int) -> None:
    path = root / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("x = 1\n" * lines)


def test_the_repository_keeps_the_limit() -> None:
    found = check.lengths(REPO)
    assert "python/pendulab/simulation.py" in found and "crates/pendulab-core/src/lib.rs" in found
    assert check.problems(found) == []
    assert len(check.ALLOWED) <= 5, "the allowlist is for a few exceptions: split files instead"


def test_a_file_over_the_limit_fails_with_its_name_and_length(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write(tmp_path, "python/pendulab/ok.py", 400)
    write(tmp_path, "web/src/long.ts", 401)
    write(tmp_path, "web/notes.ts", 900)  # outside the checked trees
    write(tmp_path, "crates/x/target/gen.rs", 900)  # build output
    write(tmp_path, "python/.venv/lib/big.py", 900)
    write(tmp_path, "tools/data.txt", 900)  # not a source file
    found = check.lengths(tmp_path)
    assert found == {"python/pendulab/ok.py": 400, "web/src/long.ts": 401}
    assert check.problems(found, allowed={}) == [
        "web/src/long.ts: 401 lines (limit 400): split it into files of one concept each"
    ]
    assert check.main(["check_file_length", str(tmp_path)]) == 1  # with the real ALLOWED: stale too
    err = capsys.readouterr().err
    assert "web/src/long.ts: 401 lines" in err and "python/pendulab/_core.pyi" in err


def test_an_allowlisted_file_may_shrink_but_not_grow(tmp_path: Path) -> None:
    allowed = {"python/pendulab/big.py": 450}
    write(tmp_path, "python/pendulab/big.py", 450)
    assert check.problems(check.lengths(tmp_path), allowed) == []
    write(tmp_path, "python/pendulab/big.py", 420)
    assert check.problems(check.lengths(tmp_path), allowed) == []
    write(tmp_path, "python/pendulab/big.py", 451)
    (problem,) = check.problems(check.lengths(tmp_path), allowed)
    assert problem.startswith("python/pendulab/big.py: 451 lines, longer than the 450 it is allowed")


def test_a_stale_allowlist_entry_fails(tmp_path: Path) -> None:
    write(tmp_path, "python/pendulab/big.py", 400)
    allowed = {"python/pendulab/big.py": 450, "tools/gone.py": 500}
    assert check.problems(check.lengths(tmp_path), allowed) == [
        "python/pendulab/big.py: 400 lines, within the limit 400 now: remove it from ALLOWED",
        "tools/gone.py: listed in ALLOWED but not found: remove the entry",
    ]


def test_lines_are_counted_as_wc_does(tmp_path: Path) -> None:
    path = tmp_path / "a.py"
    for text, n in [("", 0), ("a\n", 1), ("a\nb", 2), ("a\n\n", 2), ("a\x0cb\n", 1)]:
        path.write_text(text)
        assert check.count_lines(path) == n, repr(text)
