"""The documentation site's API reference (docs/reference/api.md, rendered by ``make docs``) has an
entry for every public name of ``pendulab`` and none for a name that is not public. (The build itself
checks that each entry was rendered with its anchor: tools/docs_site.py.)"""

from __future__ import annotations

import re
from pathlib import Path

import pendulab as pl

API_PAGE = Path(__file__).resolve().parents[2] / "docs" / "reference" / "api.md"


def test_api_reference_lists_every_public_name_once() -> None:
    text = API_PAGE.read_text(encoding="utf-8")
    entries = re.findall(r"^::: pendulab\.(\S+)\s*$", text, flags=re.MULTILINE)
    duplicates = sorted({name for name in entries if entries.count(name) > 1})
    assert not duplicates, f"listed more than once in {API_PAGE.name}: {duplicates}"
    missing = sorted(set(pl.__all__) - set(entries))
    assert not missing, f"public names without an entry in docs/reference/api.md: {missing}"
    stale = sorted(set(entries) - set(pl.__all__))
    assert not stale, f"entries in docs/reference/api.md that are not in pendulab.__all__: {stale}"
