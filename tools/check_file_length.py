"""Fails (exit 1) on a source file longer than 400 lines: the rule "one concept per file, at most 400
lines" (ARCHITECTURE.md, *File length*), for the Rust, Python and TypeScript sources under crates/, python/,
web/src, bench/ and tools/ (``.rs``, ``.py``, ``.pyi``, ``.ts``, ``.tsx``; build output, virtual
environments and Node packages skipped).

The files that are longer today are listed in :data:`ALLOWED` by name with their length: such a file
may shrink but not grow, and an entry whose file is gone or back within the limit fails too (remove
it), so the list stays short and true. A failure prints each file with its length.

Usage: ``python tools/check_file_length.py [REPO_ROOT]`` (default: the checkout this script is in).
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from pathlib import Path

LIMIT = 400
"""Lines a source file may have."""

ROOTS = ("crates", "python", "web/src", "bench", "tools")
"""The source trees checked, relative to the repository root."""

SUFFIXES = (".rs", ".py", ".pyi", ".ts", ".tsx")

SKIPPED = {"target", "node_modules", "__pycache__", "dist", "build"}
"""Directories not descended into (and every directory whose name starts with a dot, e.g. .venv)."""

ALLOWED: dict[str, int] = {
    # the hand-written stub of the whole compiled module pendulab._core, one file because mypy's
    # stubtest checks it against that one module (make lint-stubs); 473 before the spring's bindings
    # spring_sensitivities and spring_states_at (2026-11-29)
    "python/pendulab/_core.pyi": 484,
    "python/pendulab/fitting/blocks.py": 401,
}
"""Files longer than :data:`LIMIT` today → their length in lines, which they may not exceed."""


def count_lines(path: Path) -> int:
    """Lines of ``path`` as ``wc -l`` counts them, plus an unterminated last line."""
    data = path.read_bytes()
    return data.count(b"\n") + (1 if data and not data.endswith(b"\n") else 0)


def source_files(root: Path) -> list[Path]:
    """Every checked source file under ``root``'s :data:`ROOTS`, sorted."""
    out: list[Path] = []
    for top in ROOTS:
        stack = [root / top]
        while stack:
            folder = stack.pop()
            if not folder.is_dir():
                continue
            for entry in folder.iterdir():
                if entry.is_dir():
                    if not entry.name.startswith(".") and entry.name not in SKIPPED:
                        stack.append(entry)
                elif entry.suffix in SUFFIXES and entry.is_file():
                    out.append(entry)
    return sorted(out)


def lengths(root: Path) -> dict[str, int]:
    """Path relative to ``root`` (with ``/``) → number of lines, for every :func:`source_files` file."""
    return {p.relative_to(root).as_posix(): count_lines(p) for p in source_files(root)}


def problems(found: Mapping[str, int], allowed: Mapping[str, int] = ALLOWED, limit: int = LIMIT) -> list[str]:
    """One line per file over ``limit`` that ``allowed`` does not list, per listed file longer than its
    entry, and per entry whose file is missing or no longer over ``limit``."""
    out: list[str] = []
    for name, n in sorted(found.items()):
        if name in allowed:
            if n > allowed[name]:
                out.append(
                    f"{name}: {n} lines, longer than the {allowed[name]} it is allowed "
                    f"(tools/check_file_length.py ALLOWED): split it rather than raise the number"
                )
        elif n > limit:
            out.append(f"{name}: {n} lines (limit {limit}): split it into files of one concept each")
    for name in sorted(allowed):
        if name not in found:
            out.append(f"{name}: listed in ALLOWED but not found: remove the entry")
        elif found[name] <= limit:
            out.append(f"{name}: {found[name]} lines, within the limit {limit} now: remove it from ALLOWED")
    return out


def main(argv: list[str]) -> int:
    root = Path(argv[1]) if len(argv) > 1 else Path(__file__).resolve().parents[1]
    found = lengths(root)
    bad = problems(found)
    for line in bad:
        print(line, file=sys.stderr)
    if not bad:
        for name in sorted(set(ALLOWED) & set(found)):
            if found[name] < ALLOWED[name]:  # a note, not a failure: the entry may be lowered
                print(f"note: {name} has {found[name]} lines now; lower its ALLOWED entry ({ALLOWED[name]})")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
