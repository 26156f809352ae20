"""Scenario and sweep files (TOML) from outside, read within the limits of the table: at most
:data:`~pendulab.validate.table.FILE_BYTES` bytes [B] (1 MiB) and
:data:`~pendulab.validate.table.FILE_NESTING` levels of arrays, tables and dotted keys, both checked
before parsing (the parser recurses once per level) and the nesting again after; integers too long
for Python refused. Each scanner is linear in the text's length whatever it holds.

A refusal raises :class:`pendulab.InvalidInputError` (a ``ValueError``) saying what is allowed;
``docs/limits.md`` gives the reasons for the bounds.
"""

from __future__ import annotations

import os
import re
import sys
import tomllib
from typing import Any

from .._core import InvalidInputError
from .table import FILE_BYTES, FILE_NESTING, LIMITS

_TOML_INTERESTING = re.compile(r"[\"'#\[\]{}.]")
"""What the nesting check stops at: a string or comment start, a bracket or brace, a dot."""
_KEY_BREAK = re.compile(r"[=,\n]")
"""What ends a dotted key outside strings (besides brackets and braces)."""
_BASIC_STOP = re.compile(r'[\\"\n]')
"""Where a one-line basic string may end: an escape, its closing quote, or the end of the line."""
_MULTILINE_STOP = re.compile(r'\\.|"""', re.S)
"""Where a multi-line basic string may end: an escape (skipped) or its closing triple quote."""


def _skip_string(text: str, i: int) -> int:
    """The position after the TOML string starting at ``text[i]`` (a quote); an unterminated string
    ends at its line's end (the parser reports it). Each character is looked at a bounded number of
    times: linear in the string's length, whatever it holds."""
    n = len(text)
    if text.startswith('"""', i):
        pos = i + 3
        while (m := _MULTILINE_STOP.search(text, pos)) is not None:
            if m.group() == '"""':
                return m.end()
            pos = m.end()
        return n
    if text.startswith("'''", i):
        j = text.find("'''", i + 3)
        return n if j < 0 else j + 3
    if text[i] == "'":  # a literal string: no escapes, ends at the next quote on its line
        j = text.find("'", i + 1)
        stop = n if j < 0 else j
        nl = text.find("\n", i + 1, stop)
        return nl if nl >= 0 else (n if j < 0 else j + 1)
    pos = i + 1
    while (m := _BASIC_STOP.search(text, pos)) is not None:
        c = m.group()
        if c == "\\":
            pos = m.end() + 1  # the escaped character, whatever it is
        elif c == '"':
            return m.end()
        else:
            return m.start()  # unterminated on its line
    return n


def read_file_capped(path: str | os.PathLike[str]) -> str:
    """The UTF-8 text of a scenario or sweep file, refused before parsing when it is larger than
    :data:`FILE_BYTES` (1 MiB; ``/dev/zero`` returns at once) or nests arrays and tables deeper than
    :data:`FILE_NESTING`. Read errors are ``OSError`` naming the file; a refusal is an
    :class:`InvalidInputError` saying what is allowed (the caller adds the file name). A UTF-8 byte
    order mark (Windows editors write one) is dropped."""
    source = os.fspath(path)
    try:
        with open(path, "rb") as f:
            raw = f.read(FILE_BYTES + 1)
    except OSError as e:
        raise OSError(e.errno, e.strerror or str(e), source) from None
    if len(raw) > FILE_BYTES:
        raise InvalidInputError(
            f"the file is larger than {FILE_BYTES} bytes (1 MiB); {LIMITS['file_bytes']['allowed']}"
        )
    try:
        text = raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError as e:
        raise InvalidInputError(f"not UTF-8 text (byte {e.start}): TOML files must be UTF-8") from None
    check_nesting(text)
    return text


def check_nesting(text: str) -> None:
    """Refuses TOML text whose arrays and inline tables nest deeper than :data:`FILE_NESTING` (before
    parsing: the parser recurses once per level). A scanner, not a backtracking regular expression:
    linear time in the text's length whatever it holds (unterminated strings, runs of escapes).

    Dotted keys (``a.b.c = 1``) nest too, and tomllib's work for one grows with the square of its
    parts (16 000 parts: 15 s): more than :data:`FILE_NESTING` dots between two of ``= , [ ] { }`` or
    line ends (outside strings and comments) are refused before parsing. A value has at most one dot
    (a float, a time's fraction of a second)."""
    depth = deepest = pos = dots = 0
    while (m := _TOML_INTERESTING.search(text, pos)) is not None:
        c, i = m.group(), m.start()
        if _KEY_BREAK.search(text, pos, i):  # text[pos:i] is outside strings: each part looked at once
            dots = 0
        if c in "\"'":
            pos = _skip_string(text, i)
            continue
        if c == "#":  # a comment runs to the end of its line
            nl = text.find("\n", i)
            pos = len(text) if nl < 0 else nl + 1
            dots = 0
            continue
        pos = i + 1
        if c == ".":
            dots += 1
            if dots > FILE_NESTING:
                line = text.count("\n", 0, i) + 1
                raise InvalidInputError(
                    f"a dotted key nests more than {FILE_NESTING} levels deep (line {line}); "
                    f"{LIMITS['file_nesting']['allowed']}"
                )
            continue
        dots = 0
        if c in "[{":
            depth += 1
            deepest = max(deepest, depth)
            if deepest > FILE_NESTING:
                line = text.count("\n", 0, i) + 1
                raise InvalidInputError(
                    f"arrays or tables nest more than {FILE_NESTING} levels deep (line {line}); "
                    f"{LIMITS['file_nesting']['allowed']}"
                )
        else:
            depth = max(depth - 1, 0)


def parse_toml(text: str) -> dict[str, Any]:
    """TOML text from outside, parsed with the checks every reader needs: a UTF-8 byte order mark
    dropped, the nesting checked before parsing (:func:`check_nesting`) and after
    (:func:`check_depth`), and an integer too long for Python to convert (more than
    ``sys.get_int_max_str_digits()``, 4300 digits: tomllib raised a bare ``ValueError``) refused as
    :class:`InvalidInputError`. Bad syntax raises ``tomllib.TOMLDecodeError`` (the caller names the
    file, line and column)."""
    text = text.removeprefix("\ufeff")
    check_nesting(text)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        raise
    except ValueError:
        raise InvalidInputError(
            f"a number with more than {sys.get_int_max_str_digits()} digits; numbers in a file are "
            "SI values of at most a few dozen digits"
        ) from None
    check_depth(data)
    return data


def check_depth(data: Any) -> None:
    """Refuses parsed data (dicts and lists) nested deeper than :data:`FILE_NESTING` levels (dotted
    keys such as ``a.b.c`` nest without brackets). Iterative: no recursion on hostile input."""
    stack = [(data, 0)]
    while stack:
        item, depth = stack.pop()
        if depth > FILE_NESTING:
            allowed = LIMITS["file_nesting"]["allowed"]
            raise InvalidInputError(
                f"keys, arrays or tables nest more than {FILE_NESTING} levels deep; {allowed}"
            )
        if isinstance(item, dict):
            stack.extend((v, depth + 1) for v in item.values())
        elif isinstance(item, list):
            stack.extend((v, depth + 1) for v in item)
