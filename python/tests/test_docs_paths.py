"""Every code path named in ``docs/physics.md`` and ``ARCHITECTURE.md`` exists in the repository.

What counts as a path: a backticked name without spaces that contains ``/`` or ends in a file
extension of the repository (``.rs``, ``.py``, ``.pyi``, ``.ts``, ``.toml``, ``.md``, ``.json``,
``.mjs``, ``.css``, ``.csv``); a ``::item`` suffix (``tests/physics.rs::conical_start_stays_conical``)
is cut off first. Names starting with ``/`` are URL routes (``/ws``, ``/api/exact``), not files. A
``*`` is a glob (``integrate/*.rs``) that must match at least one file.

How a relative name is resolved: against the repository root first, then against the base folders
of the section (a ``## `` heading) it stands in, in the order of ``BASES`` below; it must exist in one
of them:

- ``docs/physics.md`` (one table of the core, the bindings and the Python package): the core crate's
  ``crates/pendulab-core/src`` (``exact/cubic.rs``), the crate itself for its tests
  (``tests/friction.rs``), then ``python/rust`` and ``python/pendulab``.
- ``ARCHITECTURE.md``: each section names its base in its heading — the core crate section
  ``crates/pendulab-core/src``, the WebAssembly section ``crates/pendulab-wasm/src``, the Python
  section ``python`` (``rust/lib.rs``, ``pendulab/io.py``) and ``python/pendulab`` (``theory/exact.py``),
  the web section ``web`` (``src/state.ts``, ``tests/unit/``); "Where to add things" speaks of all
  layers, so it tries every base above.

In a table row, a bare file name (``cubic.rs`` in the row of ``exact/``, ``frame.json`` in the row of
``server/protocol.py``) is also looked up in the folder of the row's first path: that folder itself
when the path ends in ``/``, else the folder holding the file.

No build is needed: the test reads only the two Markdown files and the work tree.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

CORE = "crates/pendulab-core/src"
PY_ALL = ["python", "python/pendulab"]
WEB = ["web"]
BASES: dict[str, dict[str, list[str]]] = {
    "docs/physics.md": {"": [CORE, "crates/pendulab-core", "python/rust", "python/pendulab"]},
    "ARCHITECTURE.md": {
        "": [],
        "The core crate": [CORE],
        "The WebAssembly engine": ["crates/pendulab-wasm/src", "crates/pendulab-wasm"],
        "The Python package": PY_ALL,
        "The web front end": WEB,
        "Where to add things": [CORE, *PY_ALL, *WEB, "crates/pendulab-core"],
    },
}

EXTENSIONS = (".rs", ".py", ".pyi", ".ts", ".toml", ".md", ".json", ".mjs", ".css", ".csv")
_TICKED = re.compile(r"`([^`\n]+)`")


def is_path(token: str) -> bool:
    """Whether a backticked token names a file or folder (see the module doc)."""
    if " " in token or token.startswith("/") or "://" in token:
        return False
    if not re.fullmatch(r"[\w./*\-]+", token):
        return False
    return "/" in token or token.endswith(EXTENSIONS)


def named_paths(doc: str) -> list[tuple[str, str, int, str]]:
    """(section, path, line number, row folder) for every path named in ``doc``, ``::item`` suffixes
    cut off; the row folder is that of the table row's first path ("" outside tables)."""
    section = ""
    found: list[tuple[str, str, int, str]] = []
    in_fence = False
    for number, line in enumerate((ROOT / doc).read_text(encoding="utf-8").splitlines(), 1):
        if line.startswith("```"):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        if line.startswith("## "):
            section = line[3:].strip()
            continue
        row = ""
        for token in _TICKED.findall(line):
            token = token.split("::", 1)[0]
            if is_path(token):
                if line.startswith("|") and not row:
                    row = token if token.endswith("/") else str(Path(token).parent)
                found.append((section, token, number, row if "/" not in token else ""))
    return found


def bases_for(doc: str, section: str, row: str = "") -> list[str]:
    """The base folders of a section (the entry whose key starts its heading, else the default),
    then, for a bare name in a table row, those folders joined with the row's folder."""
    table = BASES[doc]
    bases = next((b for key, b in table.items() if key and section.startswith(key)), table[""])
    if row and row != ".":
        return [*bases, row, *(f"{base}/{row}" for base in bases)]
    return bases


def resolves(path: str, bases: list[str]) -> bool:
    """Whether ``path`` exists under the root or one of ``bases`` (a glob: matches something)."""
    for base in ["", *bases]:
        folder = ROOT / base if base else ROOT
        if "*" in path:
            if any(folder.glob(path)):
                return True
        elif (folder / path.rstrip("/")).exists():
            return True
    return False


@pytest.mark.parametrize("doc", sorted(BASES))
def test_every_named_path_exists(doc: str) -> None:
    missing = [
        f"{doc}:{number} `{path}` (section {section or 'top'!r}; tried the root and "
        f"{', '.join(bases_for(doc, section, row)) or 'nothing else'})"
        for section, path, number, row in named_paths(doc)
        if not resolves(path, bases_for(doc, section, row))
    ]
    assert not missing, "paths named in the docs that do not exist:\n" + "\n".join(missing)


@pytest.mark.parametrize(("doc", "least"), [("docs/physics.md", 40), ("ARCHITECTURE.md", 150)])
def test_the_docs_name_many_paths(doc: str, least: int) -> None:
    # Guards the extraction itself: a regex that found nothing would pass the test above vacuously.
    assert len(named_paths(doc)) >= least


def test_a_missing_path_is_caught_and_names_are_told_apart() -> None:
    core = bases_for("ARCHITECTURE.md", "The core crate (`crates/pendulab-core/src`)")
    assert resolves("model/registry.rs", core)
    assert resolves("integrate/*.rs", core)
    assert not resolves("model/string_run.rs", core)  # the file docs/physics.md once named
    assert not resolves("integrate/*.nope", core)
    assert not resolves("fitting/noise.py", core)  # a Python name does not resolve in the core
    assert not resolves("cubic.rs", core)
    assert resolves("cubic.rs", bases_for("ARCHITECTURE.md", "The core crate", "exact/"))
    assert resolves("fitting/noise.py", bases_for("ARCHITECTURE.md", "The Python package (`python/`)"))
    assert [is_path(t) for t in ("model::tension", "/api/exact", "pl.exact", "lib.rs", "live/")] == [
        False,
        False,
        False,
        True,
        True,
    ]
