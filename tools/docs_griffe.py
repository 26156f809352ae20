"""A Griffe extension for the API reference (mkdocs.yml, mkdocstrings ``extensions``).

Pendulab's docstrings are prose; the few with a NumPy-style ``Parameters`` section write each entry on
one line, ``name : description``, where the NumPy convention reads the text after the colon as the
type. This extension rewrites such entries to ``name`` followed by the indented description before
the docstring is parsed (``a, b : text`` as one entry each, so that each row shows its own default from
the signature), so the parameters table shows the description as a description, and puts
prose that follows the section under a "Notes" header (a NumPy section runs to the next header).
"""

from __future__ import annotations

import re
from typing import Any

try:
    import griffe
except ImportError:  # python/tests/test_docs_api.py uses one_line_entries_to_numpy without the docs tools
    griffe = None

_SECTION = re.compile(r"^(?P<indent>[ \t]*)(?:Parameters|Other Parameters)\n(?P=indent)-{3,}\n", re.MULTILINE)
_ENTRY = re.compile(r"^(?P<name>\*{0,2}\w+(?:, \*{0,2}\w+)*) : (?P<text>.+)$")


def one_line_entries_to_numpy(text: str) -> str:
    """``name : description`` entries of NumPy parameter sections as ``name`` + indented description;
    prose after such a section (NumPy sections run to the next header) goes under a "Notes" header."""
    out: list[str] = []
    in_section = False
    lines = text.splitlines()
    for i, line in enumerate(lines):
        if i + 1 < len(lines) and _SECTION.match(f"{line}\n{lines[i + 1]}\n"):
            in_section = True
            out.append(line)
            continue
        header = i + 1 < len(lines) and re.fullmatch(r"\s*-{3,}\s*", lines[i + 1]) is not None
        if in_section and header:  # the next NumPy section ("Examples") ends this one
            in_section = False
            out.append(line)
            continue
        prose = in_section and line.strip() and not line.startswith((" ", "-")) and not _ENTRY.match(line)
        if prose and out and not out[-1].strip():
            out += ["Notes", "-----"]
            in_section = False
        match = _ENTRY.match(line) if in_section else None
        if match:  # "rtol, atol : text": one entry each, so each row gets its own default
            for name in match.group("name").split(", "):
                out += [name, f"    {match.group('text')}"]
        else:
            out.append(line)
    return "\n".join(out)


if griffe is not None:

    class OneLineNumpyParameters(griffe.Extension):
        """Applies :func:`one_line_entries_to_numpy` to every docstring."""

        def on_instance(self, *, obj: griffe.Object, **kwargs: Any) -> None:
            if obj.docstring is not None and "----" in obj.docstring.value:
                obj.docstring.value = one_line_entries_to_numpy(obj.docstring.value)
