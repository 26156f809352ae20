"""Measured data from a file: CSV (comma, semicolon, tab or whitespace separated; ``#`` comments; an
optional header row naming the columns) as exported by video-analysis tools and phone sensor apps.

Column names map to the data kinds of :func:`pendulab.fit` (SI units unless a header cell names its
unit, ``x (cm)``, ``t [ms]``, which is converted: columns.py):
``t`` [s]; ``x``, ``y``, ``z`` [m] (positions; ``x``, ``z`` alone: a camera looking along y);
``theta``, ``phi`` [rad] (angles); ``angle`` [rad] (planar_angle); ``specific_force`` or ``f``
[m/s²]; ``angular_speed`` or ``w`` [rad/s]; accelerometer components ``ax, ay, az`` (also
``Acceleration x``, Physics Toolbox's ``gFx`` in g₀) → specific_force = |a|, gyroscope components
``wx, wy, wz`` (also ``Gyroscope x``) → angular_speed = |ω|. Other columns are ignored; ``-`` skips one.
"""

from __future__ import annotations

import csv
import io
import os
from pathlib import Path
from typing import Any

import numpy as np

from .._core import InvalidInputError
from .columns import QUANTITY, column

MAX_BYTES = 256 * 2**20
"""Largest data file read [bytes] (about 5 million rows of 5 columns)."""

KNOWN = set(QUANTITY) | {"-"}
VECTORS = {"specific_force": ("ax", "ay", "az"), "angular_speed": ("wx", "wy", "wz")}


def _columns(names: list[str], where: str) -> tuple[list[str], list[float]]:
    """The columns' data kinds and their factors to SI (columns.py)."""
    pairs = [column(raw, where) for raw in names]
    out = [n for n, _ in pairs]
    if "t" not in out:
        raise InvalidInputError(f"{where}: no time column 't' among {names}; name the columns with --columns")
    repeated = sorted({n for n in out if n != "-" and n in KNOWN and out.count(n) > 1})
    if repeated:
        raise InvalidInputError(f"{where}: column(s) {repeated} appear more than once among {names}")
    return out, [f for _, f in pairs]


def read_table(path: str | os.PathLike[str], columns: list[str] | None = None) -> dict[str, Any]:
    """Reads a data file; returns the keyword arguments of :func:`pendulab.fit` (``t`` and the data
    kinds present). ``columns``: the names of the file's columns in order (default: its header row)."""
    p = Path(path)
    try:
        size = p.stat().st_size
        if not p.is_file():
            raise InvalidInputError(f"{p}: not a regular file")
        if size > MAX_BYTES:
            raise InvalidInputError(f"{p}: {size} bytes, more than the {MAX_BYTES} a data file may have")
        with p.open("r", encoding="utf-8", errors="strict", newline="") as fh:
            text = fh.read(MAX_BYTES + 1)
    except UnicodeDecodeError as e:
        raise InvalidInputError(f"{p}: not a text (UTF-8) file: {e.reason} at byte {e.start}") from e
    except OSError as e:
        raise InvalidInputError(f"{p}: cannot read: {e.strerror or e}") from e
    if len(text) > MAX_BYTES:
        raise InvalidInputError(f"{p}: more than {MAX_BYTES} bytes")
    return parse_table(text, columns, str(p))


def parse_table(text: str, columns: list[str] | None = None, where: str = "<data>") -> dict[str, Any]:
    """The text of a data file (see the module doc) as the keyword arguments of :func:`pendulab.fit`;
    ``where`` names it in error messages (a path, or e.g. the uploaded file's name). The caller bounds
    its size (:func:`read_table` at :data:`MAX_BYTES`)."""
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise InvalidInputError(f"{where}: no data rows")
    try:
        dialect: Any = csv.Sniffer().sniff(lines[0], delimiters=",;\t ")
    except csv.Error:
        dialect = csv.excel
    rows = list(csv.reader(io.StringIO("\n".join(lines)), dialect, skipinitialspace=True))
    rows = [[c for c in r if c != ""] if dialect.delimiter == " " else r for r in rows]
    header = None
    try:
        [float(c) for c in rows[0]]
    except ValueError:
        header, rows = rows[0], rows[1:]
    names = columns if columns is not None else header
    if names is None:
        raise InvalidInputError(
            f"{where}: the file has no header row: name its columns (e.g. --columns t,x,y,z)"
        )
    names, factors = _columns(list(names), where)
    unknown = [n for n in names if n not in KNOWN]
    if unknown and columns is not None:
        raise InvalidInputError(f"unknown column name(s) {unknown}; use {', '.join(sorted(KNOWN))}")
    width = len(names)
    data = np.full((len(rows), width), np.nan)
    for i, r in enumerate(rows):
        if len(r) < width:
            raise InvalidInputError(
                f"{where}: row {i + 1} has {len(r)} values, the columns are {width}: {names}"
            )
        for j in range(width):
            cell = r[j].strip()
            if dialect.delimiter != "," and "," in cell and "." not in cell:
                cell = cell.replace(",", ".")  # a decimal comma (a European locale's export)
            try:
                data[i, j] = float(cell) if cell not in ("", "nan", "NaN", "NA") else np.nan
            except ValueError as e:
                raise InvalidInputError(
                    f"{where}: row {i + 1}, column {names[j]!r}: {cell[:40]!r} is not a number"
                ) from e
    col = {n: data[:, j] * factors[j] for j, n in enumerate(names) if n in KNOWN and n != "-"}
    for kind, parts in VECTORS.items():  # a sensor's components → the frame-free magnitude
        have = [c for c in parts if c in col]
        if have and kind in col:  # the app wrote the magnitude too (Physics Toolbox's TgF): use it
            for c in have:
                col.pop(c)
            continue
        if have and len(have) < 3:
            raise InvalidInputError(f"{where}: {kind} needs all three components {parts}; found {have}")
        if have:
            col[kind] = np.sqrt(sum(col.pop(c) ** 2 for c in parts))
    out: dict[str, Any] = {"t": col["t"]}
    if {"x", "y", "z"} <= col.keys():
        out["positions"] = np.column_stack([col["x"], col["y"], col["z"]])
    elif {"x", "z"} <= col.keys():
        out["positions"] = np.column_stack([col["x"], col["z"]])
    elif {"x", "y"} <= col.keys() and "z" not in col:
        raise InvalidInputError(
            f"{where}: columns x, y but no z: a camera's (horizontal, vertical) are x, z here (z up); "
            "rename them"
        )
    if {"theta", "phi"} <= col.keys():
        out["angles"] = np.column_stack([col["theta"], col["phi"]])
    if "angle" in col:
        out["planar_angle"] = col["angle"]
    for kind in ("specific_force", "angular_speed"):
        if kind in col:
            out[kind] = col[kind]
    if len(out) == 1:
        raise InvalidInputError(f"{where}: no data columns among {names}; see docs/fit.md for the names")
    return out
