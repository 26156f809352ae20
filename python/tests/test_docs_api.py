"""The documentation site's API reference (docs/reference/api.md, rendered by ``make docs``) has an
entry for every public name of ``pendulab`` and none for a name that is not public. (The build itself
checks that each entry was rendered with its anchor: tools/docs_site.py.)"""

from __future__ import annotations

import inspect
import re
from pathlib import Path

from conftest import load_tool

import pendulab as pl

API_PAGE = Path(__file__).resolve().parents[2] / "docs" / "reference" / "api.md"


def test_api_reference_lists_every_public_name_once() -> None:
    text = API_PAGE.read_text(encoding="utf-8")
    entries = re.findall(r"^::: pendulab\.(\S+)\s*$", text, flags=re.MULTILINE)
    duplicates = sorted({name for name in entries if entries.count(name) > 1})
    assert not duplicates, f"listed more than once in {API_PAGE.name}: {duplicates}"
    missing = sorted(set(pl.__all__) - set(entries))
    assert not missing, f"public names without an entry in docs/reference/api.md: {missing}"
    stale = sorted(name for name in set(entries) - set(pl.__all__) if not _public_in_module(name))
    assert not stale, f"entries in docs/reference/api.md that are not public names of pendulab: {stale}"
    # the names a user reads a file back with (README, "Reading a CSV back")
    assert "io.read_metadata" in entries


def _public_in_module(dotted: str) -> bool:
    """True for ``module.name`` naming a public function or class of a public submodule of pendulab
    (``io.read_metadata``): no part starts with ``_`` and the object exists with a docstring."""
    import importlib

    module, _, name = dotted.rpartition(".")
    if not module or any(part.startswith("_") for part in dotted.split(".")):
        return False
    try:
        obj = getattr(importlib.import_module(f"pendulab.{module}"), name)
    except (ImportError, AttributeError):
        return False
    return (inspect.isfunction(obj) or inspect.isclass(obj)) and bool(inspect.getdoc(obj))


# ------------------------------------------------------------------- documented parameters and defaults
# The reference renders a docstring's "Parameters" section (one line per entry, "name : text";
# tools/docs_griffe.py) as a table whose defaults come from the signature: so every entry must name a
# real parameter, every parameter must have an entry, and a default written in the text, "(default X)",
# must be the signature's (where the signature's is not None, which stands for a computed default).

_ENTRY = re.compile(r"^(?P<names>\*{0,2}\w+(?:, \*{0,2}\w+)*) : (?P<text>.+)$")


def _documented(obj: object) -> dict[str, str] | None:
    """name -> description of a docstring's Parameters section (None: no such section)."""
    doc = inspect.getdoc(obj) or ""
    lines = doc.splitlines()
    try:
        start = next(
            i for i in range(len(lines) - 1) if lines[i] == "Parameters" and lines[i + 1].startswith("---")
        )
    except StopIteration:
        return None
    out: dict[str, str] = {}
    last: list[str] = []
    for line in lines[start + 2 :]:
        m = _ENTRY.match(line)
        if m:
            last = [n.lstrip("*") for n in m.group("names").split(", ")]
            for n in last:
                out[n] = m.group("text")
        elif line.startswith(" ") and last:
            for n in last:
                out[n] += " " + line.strip()
        elif line.strip():
            break  # prose after the section
    return out


def _public_callables() -> list[tuple[str, object]]:
    found = []
    for name in pl.__all__:
        obj = getattr(pl, name)
        if inspect.isclass(obj) or inspect.isfunction(obj):
            found.append((name, obj))
    return found


def _signature(obj: object) -> inspect.Signature | None:
    try:
        return inspect.signature(obj)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        return None


def test_documented_parameters_match_the_signatures() -> None:
    checked = 0
    for name, obj in _public_callables():
        documented = _documented(obj)
        sig = _signature(obj)
        if documented is None or sig is None:
            continue
        params = {p.name: p for p in sig.parameters.values() if p.name != "self"}
        unknown = sorted(set(documented) - set(params))
        assert not unknown, f"pl.{name}: documented parameters not in its signature {sig}: {unknown}"
        undocumented = sorted(
            n
            for n, p in params.items()
            if n not in documented and p.kind is not inspect.Parameter.VAR_POSITIONAL
        )
        assert not undocumented, f"pl.{name}: parameters without a row in its docstring: {undocumented}"
        for n, text in documented.items():
            m = re.search(r"\(default ``?([^`),;]+)``?", text) or re.search(r"\(default ([^),;\s]+)", text)
            default = params[n].default
            if m is None or default in (None, inspect.Parameter.empty):
                continue
            written = m.group(1).strip().strip("\"'")
            if isinstance(default, bool):
                assert written == str(default), (
                    f"pl.{name}({n}): docstring says {written}, signature {default}"
                )
            elif isinstance(default, int | float):
                value = float(written.split()[0])
                assert value == default, f"pl.{name}({n}): docstring says {written}, signature {default!r}"
            elif isinstance(default, str):
                assert written == default, (
                    f"pl.{name}({n}): docstring says {written!r}, signature {default!r}"
                )
            checked += 1
    assert checked >= 2  # simulate's project and drift, ...


def test_simulate_reference_has_every_row_with_its_default() -> None:
    """The reported case: the reference gave atol the default 1e-10 (rtol's) and had no rows for
    pendulum, state, t_end, t0."""
    documented = _documented(pl.simulate)
    assert documented is not None
    assert {"pendulum", "state", "t_end", "t0", "rtol", "atol"} <= set(documented)
    sig = inspect.signature(pl.simulate)
    assert sig.parameters["atol"].default == 1e-12 and sig.parameters["rtol"].default == 1e-10


def test_the_reference_gives_each_of_two_names_on_one_line_its_own_row() -> None:
    """tools/docs_griffe.py turns ``rtol, atol : text`` into two entries, so that mkdocstrings shows each
    with its own default from the signature (it showed rtol's 1e-10 for both)."""
    griffe = load_tool("docs_griffe")
    text = griffe.one_line_entries_to_numpy("Parameters\n----------\nrtol, atol : tolerances of dop853.\n")
    assert text.splitlines()[2:] == ["rtol", "    tolerances of dop853.", "atol", "    tolerances of dop853."]
