"""The layout of a measured-data file as lab software exports it: where the header row is, what came
above it, which character separates the values and whether they use decimal commas.

Handled (examples in ``python/tests/data/exports/``):

- a UTF-8 byte order mark (Excel's "CSV UTF-8", Windows editors): dropped;
- ``#`` comment lines and blank lines anywhere;
- lines above the header row: Tracker's track name (``mass A``), Logger Pro's and Graphical
  Analysis' run name (``Latest``, ``Run 1``), a title: kept as the file's *preamble*;
- the separator of the first data row: a tab, else ``;``, else ``,``, else runs of spaces;
- decimal commas (phyphox' "semicolon, decimal comma", Cassy and Excel in a European locale) when the
  separator is not a comma and the data rows have commas.

Every scan is linear in the text's length (``str.find`` and a line at a time; no backtracking regular
expression sees more than one bounded cell), and only the first :data:`MAX_PREAMBLE` lines are
looked at here: the body is left to the numeric reader (cells.py).
"""

from __future__ import annotations

import csv
from dataclasses import dataclass

from .keyed import KeyedInputError

MAX_PREAMBLE = 50
"""The most non-blank, non-comment lines looked at before the first data row."""
MAX_HEADER_CHARS = 65_536
"""The longest header line read [characters] (a header names columns; 64 kB is hundreds of them)."""
SHOW = 40
"""The most characters of a bad cell echoed in an error message."""


@dataclass(frozen=True)
class Layout:
    """Where the parts of a data file are: ``header`` (cells of the header row, None if there is
    none), ``preamble`` (the non-comment lines above the header row), ``delimiter`` (None: runs of
    whitespace), ``decimal_comma``, ``body_start`` (the offset in the text of the first data row)
    and ``body_line`` (its line number, from 1)."""

    header: list[str] | None
    header_line: int
    preamble: list[str]
    delimiter: str | None
    decimal_comma: bool
    body_start: int
    body_line: int


def clip(text: str) -> str:
    """``repr`` of the first :data:`SHOW` characters of ``text`` (with ``...`` when longer)."""
    return repr(text[:SHOW]) + ("..." if len(text) > SHOW else "")


def is_number(cell: str, decimal_comma: bool = False) -> bool:
    """Whether ``cell`` (stripped of spaces and quotes) is a number as a data row writes it."""
    c = cell.strip().strip('"').strip()
    if decimal_comma:
        c = c.replace(",", ".")
    if not c or len(c) > 64:
        return False
    try:
        float(c)
    except ValueError:
        return False
    return True


def _first_cell(line: str) -> str:
    """The line's first cell (up to the first tab, semicolon, comma or space after its start)."""
    s = line.strip()
    ends = [i for i in (s.find(d) for d in "\t;, ") if i >= 0]
    return s[: min(ends)] if ends else s


def _delimiter(row: str) -> str | None:
    for d in ("\t", ";", ","):
        if d in row:
            return d
    return None


def split_line(line: str, delimiter: str | None) -> list[str]:
    """The cells of one line (quotes removed) by the csv module, which runs in linear time; a line
    the csv module refuses (a cell beyond its 128 kB limit) is split at every separator."""
    try:
        if delimiter is None:
            cells = next(csv.reader([line.strip()], delimiter=" ", skipinitialspace=True), [])
            return [c for c in cells if c != ""]
        return next(csv.reader([line], delimiter=delimiter, skipinitialspace=True), [])
    except csv.Error:
        return [c.strip().strip('"') for c in line.split(delimiter)]


def find_layout(text: str, where: str) -> Layout:
    """The layout of ``text`` (the BOM already dropped): the first data row is the first line (not
    blank, not a ``#`` comment) whose first cell is a number; the line before it is the header row
    unless it is a data row itself."""
    lines: list[tuple[int, int, str]] = []  # (line number, offset, text) of non-comment lines
    pos, number = 0, 0
    n = len(text)
    while pos < n and len(lines) <= MAX_PREAMBLE:
        end = text.find("\n", pos)
        end = n if end < 0 else end
        number += 1
        # only the start of a line is copied until it is known to be short enough to matter
        head = text[pos : min(end, pos + MAX_HEADER_CHARS + 1)].rstrip("\r")
        stripped = head.strip()
        if stripped and not stripped.startswith("#"):
            first = _first_cell(head[:200])
            if is_number(first) or is_number(first, decimal_comma=True):
                return _layout(text, lines, (number, pos, head), where)
            if end - pos > MAX_HEADER_CHARS:
                raise KeyedInputError(
                    f"{where}: line {number} is {end - pos} characters long and not a data row; a "
                    f"header row may have at most {MAX_HEADER_CHARS}",
                    "data_long_line",
                    file=where,
                    line=number,
                    chars=end - pos,
                    most=MAX_HEADER_CHARS,
                )
            lines.append((number, pos, head))
        pos = end + 1
    if len(lines) > MAX_PREAMBLE:
        raise KeyedInputError(
            f"{where}: no data row (a line starting with a number) in the first {MAX_PREAMBLE} lines "
            "that are not comments",
            "data_no_rows_in_first",
            file=where,
            lines=MAX_PREAMBLE,
        )
    raise KeyedInputError(f"{where}: no data rows (lines of numbers)", "data_no_rows", file=where)


def _layout(text: str, above: list[tuple[int, int, str]], first: tuple[int, int, str], where: str) -> Layout:
    number, offset, row = first
    delimiter = _delimiter(row[:4096])
    rows = text[offset : offset + 4096]  # the first rows: a decimal comma may first appear in the second
    decimal_comma = delimiter != "," and "," in rows
    header: list[str] | None = None
    header_line = 0
    preamble = [line.strip() for _, _, line in above]
    if above:
        header_line, _, line = above[-1]
        header = [c.strip() for c in split_line(line, delimiter)]
        preamble = preamble[:-1]
    return Layout(header, header_line, preamble, delimiter, decimal_comma, offset, number)
