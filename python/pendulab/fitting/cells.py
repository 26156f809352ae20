"""The numbers of a data file's body, read by NumPy's C reader (``numpy.loadtxt``): about a second
per million rows, where a Python loop over cells took a minute.

Empty cells, ``NA`` and ``""`` are NaN (Tracker leaves a cell empty where no mark was set; the fit
drops rows with NaN and counts them). Decimal commas become points before reading. A cell that is not
a number, a row with too few cells, ``inf`` or a value beyond float64 (``1e400``), a subnormal value
(0 < |v| < 2.2e-308: no instrument writes one), a value beyond its quantity's bound (:data:`BOUNDS`,
in SI: times ±1e12 s, lengths ±1e9 m, angles ±1e6 rad, angular rates ±1e9 rad/s — the limits of
docs/limits.md — and accelerations ±1e9 m/s²) and two times closer than 1e-12 s (the shortest time
step) are errors naming the row, the file's line, the column and the cell.

Every text operation is linear in the body's length: ``str.replace`` and regular expressions
anchored at a line start or a separator whose repeated part is a run of blanks (each character is
looked at a bounded number of times).
"""

from __future__ import annotations

import io
import re
from functools import partial
from typing import Any

import numpy as np

from .._core import InvalidInputError
from .._numbers import shown
from ..model import FloatArray
from ..validate import LIMITS
from .data import MAX_SAMPLES
from .keyed import KeyedInputError
from .layout import Layout, clip, split_line

BOUNDS: dict[str, float] = {
    "time": LIMITS["time"]["max"],
    "length": LIMITS["position"]["max"],
    "angle": LIMITS["angle"]["max"],
    "angular rate": LIMITS["angle_rate"]["max"],
    "acceleration": 1e9,
}
"""The largest magnitude of a value in SI per quantity (columns.py's QUANTITY)."""
MIN_STEP = LIMITS["dt"]["min"]
"""The closest two distinct times may be [s]."""

_BLANK_LINE = re.compile(r"^[ \t]*\n", re.M)
"""An empty line or one of spaces and tabs only (NumPy would read it as a row of one empty cell)."""


def _empty_cells(delimiter: str) -> re.Pattern[str]:
    """An empty cell (nothing, blanks, ``""`` or ``NA``) between separators or line ends."""
    d = re.escape(delimiter)
    b = "[ ]" if delimiter == "\t" else "[ \t]"  # blanks that are not the separator
    return re.compile(rf'(^|{d}){b}*(?:(?:""|NA|N/A){b}*)?(?={d}|\n)', re.M)


def _may_have(body: str, needles: tuple[str, ...]) -> bool:
    """Whether any of ``needles`` is in ``body`` (``str.find`` in C: a regular expression pass over
    a million rows costs seconds, so it runs only when it may change something)."""
    return any(needle in body for needle in needles)


def read_cells(
    text: str,
    layout: Layout,
    names: list[str],
    use: list[int],
    where: str,
    factors: list[float] | None = None,
    quantities: list[str] | None = None,
) -> FloatArray:
    """The columns ``use`` (indices into the rows) of the body of ``text`` as an (N, len(use))
    float64 array, each multiplied by its factor to SI (``factors``, one per column used) and checked
    against the bound of its quantity (``quantities``: columns.py's names; "time" also for the
    spacing); ``names`` name the columns in errors."""
    body = text[layout.body_start :]
    rows = body.count("\n") + 1
    if rows > MAX_SAMPLES:
        raise KeyedInputError(
            f"{where}: {rows} lines of data; at most {MAX_SAMPLES} samples are fitted",
            "data_too_many_rows",
            file=where,
            rows=rows,
            most=MAX_SAMPLES,
        )
    if "\r" in body:
        body = body.replace("\r\n", "\n").replace("\r", "\n")
    if layout.decimal_comma:
        body = body.replace(",", ".")
    if layout.delimiter is not None:
        if not body.endswith("\n"):
            body += "\n"
        if _may_have(body, ("\n\n", "\n ", "\n\t")) or body[:1] in (" ", "\t", "\n"):
            body = _BLANK_LINE.sub("", body)
        d = layout.delimiter
        if body[:1] == d or _may_have(body, (d + d, "\n" + d, d + "\n", d + " ", d + "\t", "NA", '""')):
            body = _empty_cells(d).sub(r"\1nan", body)
    raw = io.BytesIO(body.encode("utf-8"))  # 1 byte a character (StringIO holds 4)
    del body
    try:
        data = np.loadtxt(
            raw,
            encoding="utf-8",
            dtype=np.float64,
            delimiter=layout.delimiter,
            comments="#",
            quotechar='"',
            usecols=use,
            ndmin=2,
        )
    except (ValueError, IndexError):
        data = None  # find the bad cell in the original text for the message
    if data is None or data.shape[1] != len(use):
        _raise_bad_cell(text, layout, names, use, where)
        raise InvalidInputError(f"{where}: cannot read the data rows")  # not reached

    fail = partial(_fail, text, layout, [clip(names[j]) for j in use], use, where)

    with np.errstate(invalid="ignore"):
        magnitude = np.abs(data)
        bad = np.isinf(data) | ((magnitude > 0.0) & (magnitude < np.finfo(np.float64).tiny))
    if bad.any():
        row, k = (int(i) for i in np.argwhere(bad)[0])
        if np.isinf(data[row, k]):
            fail(row, k, "is infinite or beyond the largest float (1.8e308)", "data_cell_infinite")
        fail(
            row, k, "is subnormal (0 < |value| < 2.2e-308), not a measurement: write 0", "data_cell_subnormal"
        )
    for k in range(len(use)):
        if factors is not None:
            data[:, k] *= factors[k]
        quantity = quantities[k] if quantities is not None else None
        if quantity not in BOUNDS:
            continue
        with np.errstate(invalid="ignore"):
            beyond = np.abs(data[:, k]) > BOUNDS[quantity]
        if beyond.any():
            unit = {"time": "s", "length": "m", "angle": "rad", "angular rate": "rad/s"}.get(quantity, "m/s²")
            fail(
                int(np.argmax(beyond)),
                k,
                f"is beyond ±{shown(BOUNDS[quantity])} {unit} (a {quantity} in SI)",
                "data_cell_beyond",
                limit=shown(BOUNDS[quantity]),
                unit=unit,
            )
        if quantity == "time":
            _check_spacing(data[:, k], fail, k)
    return data


def _fail(
    text: str,
    layout: Layout,
    columns: list[str],
    use: list[int],
    where: str,
    row: int,
    k: int,
    what: str,
    key: str,
    **values: Any,
) -> None:
    """Raises the keyed refusal of cell (row, k) of the used columns: ``what`` is wrong with it."""
    line, cells = _row(text, layout, row)
    cell = clip(cells[use[k]].strip() if use[k] < len(cells) else "")
    raise KeyedInputError(
        f"{where}: row {row + 1} (line {line}), column {columns[k]}: {cell} {what}",
        key,
        file=where,
        row=row + 1,
        line=line,
        column=columns[k],
        cell=cell,
        **values,
    )


def _check_spacing(t: FloatArray, fail: Any, k: int) -> None:
    """Refuses two distinct times closer than :data:`MIN_STEP`."""
    finite = np.flatnonzero(np.isfinite(t))
    if finite.size < 2:
        return
    order = finite[np.argsort(t[finite], kind="stable")]
    step = np.diff(t[order])
    close = (step > 0.0) & (step < MIN_STEP)
    if close.any():
        i = int(np.argmax(close))
        fail(
            int(max(order[i], order[i + 1])),
            k,
            f"is {shown(step[i], 3)} s from another time; samples closer than {shown(MIN_STEP)} s "
            "(the shortest "
            "time step) cannot be told apart",
            "data_times_too_close",
            step=shown(step[i], 3),
            most=shown(MIN_STEP),
        )


def _row(text: str, layout: Layout, index: int) -> tuple[int, list[str]]:
    """The line number and cells of data row ``index`` (from 0) of the body: a linear walk over the
    lines, run only to name a bad cell."""
    pos, number, seen = layout.body_start, layout.body_line, -1
    n = len(text)
    while pos < n:
        end = text.find("\n", pos)
        end = n if end < 0 else end
        line = text[pos:end]
        stripped = line.strip()
        if stripped and not stripped.startswith("#"):
            seen += 1
            if seen == index:
                return number, split_line(line.rstrip("\r"), layout.delimiter)
        pos, number = end + 1, number + 1
    return number, []


def _raise_bad_cell(text: str, layout: Layout, names: list[str], use: list[int], where: str) -> None:
    """Finds the first data line with a bad or missing cell in a used column and raises its error."""
    pos, number, row = layout.body_start, layout.body_line, 0
    n = len(text)
    width = max(use) + 1
    while pos < n:
        end = text.find("\n", pos)
        end = n if end < 0 else end
        line = text[pos:end].rstrip("\r")
        stripped = line.strip()
        comment = stripped.find("#")
        if comment >= 0:
            line = line[: line.find("#")]
            stripped = line.strip()
        if stripped:
            row += 1
            cells = split_line(line, layout.delimiter)
            if len(cells) < width:
                raise KeyedInputError(
                    f"{where}: row {row} (line {number}) has {len(cells)} values; the columns used "
                    f"need {width}: {[clip(c) for c in names[:width]]}",
                    "data_row_short",
                    file=where,
                    row=row,
                    line=number,
                    have=len(cells),
                    need=width,
                )
            for j in use:
                cell = cells[j].strip()
                if cell in ("", "NA", "N/A"):
                    continue
                c = cell.replace(",", ".") if layout.decimal_comma else cell
                try:
                    float(c)
                except ValueError:
                    raise KeyedInputError(
                        f"{where}: row {row} (line {number}), column {names[j]!r}: {clip(cell)} "
                        "is not a number",
                        "data_not_number",
                        file=where,
                        row=row,
                        line=number,
                        column=clip(names[j]),
                        cell=clip(cell),
                    ) from None
        pos, number = end + 1, number + 1
    raise InvalidInputError(f"{where}: the data rows cannot be read as numbers")
