"""Measured data from a file as lab software exports it: CSV (comma, semicolon, tab or whitespace
separated; ``#`` comments; a header row naming the columns, possibly below a track or run name) from
video analysis (Tracker, Logger Pro), phone sensor apps (phyphox, Physics Toolbox) and data loggers
(Cassy, Vernier). The layout (BOM, preamble, header, separator, decimal comma): layout.py; the
numbers: cells.py (NumPy's C reader); names and units: columns.py. SI units: a header cell naming its
unit (``x (cm)``, ``t [ms]``, ``t / s``) is converted.

Column names map to the data kinds of :func:`pendulab.fit`:
``t`` [s]; ``x``, ``y``, ``z`` [m] (positions; ``x``, ``z`` alone: a camera looking along y;
``x``, ``y`` alone: *horizontal* positions seen from above, e.g. a crane hook's sway log — except in
a video-analysis export (Tracker's track-name line, Logger Pro's run name), whose ``x``, ``y`` are the
camera's horizontal and vertical, read as ``x``, ``z``);
``theta``, ``phi`` [rad] (angles); ``angle`` [rad] (planar_angle); ``specific_force`` or ``f``
[m/s²]; ``angular_speed`` or ``w`` [rad/s]; accelerometer components ``ax, ay, az`` (also
``Acceleration x``, Physics Toolbox's ``gFx`` in g₀) → specific_force = |a|, gyroscope components
``wx, wy, wz`` (also ``Gyroscope x``) → angular_speed = |ω|. Other columns are ignored; ``-`` skips one.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from .._core import InvalidInputError
from .cells import read_cells
from .columns import QUANTITY, column, is_unit
from .keyed import KeyedInputError
from .layout import Layout, clip, find_layout, split_line

MAX_BYTES = 256 * 2**20
"""Largest data file read [bytes] (about 5 million rows of 5 columns)."""

KNOWN = set(QUANTITY) | {"-"}
VECTORS = {"specific_force": ("ax", "ay", "az"), "angular_speed": ("wx", "wy", "wz")}
VIDEO_TOOLS = ("Tracker's track name", "Logger Pro's run name")


def _columns(names: list[str], where: str) -> tuple[list[str], list[float]]:
    """The columns' data kinds and their factors to SI (columns.py)."""
    pairs = [column(raw, where) for raw in names]
    out = [n for n, _ in pairs]
    if "t" not in out:
        raise KeyedInputError(
            f"{where}: no time column 't' among {_names(names)}; name the columns with --columns",
            "data_no_time",
            file=where,
            columns=_names(names),
        )
    repeated = sorted({n for n in out if n != "-" and n in KNOWN and out.count(n) > 1})
    if repeated:
        raise KeyedInputError(
            f"{where}: column(s) {repeated} appear more than once among {_names(names)} (an export of "
            "several tracks or runs: keep one, or name the columns with --columns and '-' to skip)",
            "data_repeated_columns",
            file=where,
            repeated=", ".join(repeated),
            columns=_names(names),
        )
    return out, [f for _, f in pairs]


def _names(names: list[str]) -> str:
    """The header's names for an error message, each and the list abbreviated."""
    shown = [clip(n) for n in names[:12]]
    return "[" + ", ".join(shown) + (", ..." if len(names) > 12 else "") + "]"


def read_table(path: str | os.PathLike[str], columns: list[str] | None = None) -> dict[str, Any]:
    """Reads a data file; returns the keyword arguments of :func:`pendulab.fit` (``t`` and the data
    kinds present). ``columns``: the names of the file's columns in order (default: its header row)."""
    return read_table_notes(path, columns)[0]


def read_table_notes(
    path: str | os.PathLike[str], columns: list[str] | None = None
) -> tuple[dict[str, Any], list[str]]:
    """:func:`read_table` and notes on how the file was read (:func:`parse_table_notes`). The text
    is UTF-8 (with or without a BOM), UTF-16 with a BOM (Excel's "Unicode text"), or else Windows-1252
    (older Windows exports: ``°`` as one byte), said in a note."""
    p, name = Path(path), os.fspath(path)  # named as given: ./x.csv, not the x.csv of Path
    try:
        size = p.stat().st_size
        if not p.is_file():
            raise InvalidInputError(f"{name}: not a regular file")
        if size > MAX_BYTES:
            raise InvalidInputError(f"{name}: {size} bytes, more than the {MAX_BYTES} a data file may have")
        with p.open("rb") as fh:
            raw = fh.read(MAX_BYTES + 1)
    except OSError as e:
        raise InvalidInputError(f"{name}: cannot read: {e.strerror or e}") from e
    if len(raw) > MAX_BYTES:
        raise InvalidInputError(f"{name}: more than {MAX_BYTES} bytes")
    text, note = _decode(raw, name)
    del raw
    kwargs, notes = parse_table_notes(text, columns, name)
    return kwargs, ([note] if note else []) + notes


def _decode(raw: bytes, where: str) -> tuple[str, str | None]:
    """The text of a file's bytes and a note on its encoding when it is not UTF-8."""
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        try:
            return raw.decode("utf-16"), "read as UTF-16"
        except UnicodeDecodeError as e:
            raise InvalidInputError(f"{where}: not UTF-16 text: {e.reason} at byte {e.start}") from None
    try:
        return raw.decode("utf-8"), None
    except UnicodeDecodeError as e:
        first = e
    try:
        return raw.decode("cp1252"), f"not UTF-8 (byte {first.start}): read as Windows-1252"
    except UnicodeDecodeError:
        raise InvalidInputError(
            f"{where}: not a text (UTF-8) file: {first.reason} at byte {first.start}"
        ) from None


def parse_table(text: str, columns: list[str] | None = None, where: str = "<data>") -> dict[str, Any]:
    """The text of a data file (see the module doc) as the keyword arguments of :func:`pendulab.fit`;
    ``where`` names it in error messages (a path, or e.g. the uploaded file's name). The caller bounds
    its size (:func:`read_table` at :data:`MAX_BYTES`)."""
    return parse_table_notes(text, columns, where)[0]


def parse_table_notes(
    text: str, columns: list[str] | None = None, where: str = "<data>"
) -> tuple[dict[str, Any], list[str]]:
    """:func:`parse_table` and notes for the user on how the file was read (the program it looks
    like, a preamble skipped, how x, y were taken)."""
    text = text.removeprefix("\ufeff")  # Excel's "CSV UTF-8" and Windows editors write a BOM
    if "\r" in text and "\n" not in text:  # Excel for Mac's "CSV (Macintosh)": CR line ends
        text = text.replace("\r", "\n")
    _refuse_crane_csv(text, where)  # also with columns named: naming them does not make it a pendulum
    layout = find_layout(text, where)
    names = columns if columns is not None else _vernier_names(layout) or layout.header
    if names is None:
        raise KeyedInputError(
            f"{where}: the file has no header row: name its columns (e.g. --columns t,x,y,z)",
            "data_no_header",
            file=where,
        )
    kinds, factors = _columns(list(names), where)
    unknown = [n for n in kinds if n not in KNOWN]
    if unknown and columns is not None:
        raise KeyedInputError(
            f"{where}: unknown column name(s) {_names(unknown)}; use {', '.join(sorted(KNOWN))}",
            "data_unknown_columns",
            file=where,
            unknown=_names(unknown),
            allowed=", ".join(sorted(KNOWN)),
        )
    use = [j for j, n in enumerate(kinds) if n in KNOWN and n != "-"]
    data = read_cells(
        text,
        layout,
        [str(n) for n in names],
        use,
        where,
        factors=[factors[j] for j in use],
        quantities=[QUANTITY[kinds[j]] for j in use],
    )
    col = {kinds[j]: data[:, k] for k, j in enumerate(use)}
    notes = _notes(layout, columns is not None)
    return _kinds(col, kinds, layout, columns is not None, where, notes), notes


CRANE_GRID_HEADER = "shaper,rope [m],ratio,sway [m]"
"""The header of ``pendulab crane grid --out`` (below its ``# pendulab crane grid`` line)."""
MAKES_FITTABLE = "pendulab run SCENARIO.toml --out FILE.csv"
"""The command whose CSV ``pendulab fit`` reads, named when a file of another Pendulab command is refused."""


def _refuse_crane_csv(text: str, where: str) -> None:
    """Refuses the CSV of ``pendulab crane run`` or ``crane grid`` (known by its ``# pendulab crane …``
    line, or by its header in files written before the crane grid had that line), naming its columns,
    what a fit needs and the command that writes a fittable file. A crane's payload hangs below a hook
    from a trolley that moves, on a rope that may be hoisted, in wind: not the fixed-pivot pendulum the
    fit's models describe, and its absolute payload x, y, z are not a bob's position about a pivot."""
    lines = (line.strip() for line in text[:MAX_HEADER_PEEK].split("\n"))
    first = next((line for line in lines if line), "")
    header = first if not first.startswith("#") else next((line for line in lines if line), "")
    names = [n.strip() for n in header.split(",")]
    bare = {n.split(" [")[0] for n in names}
    needs = "t and x, y, z (or x, z; x, y seen from above; theta, phi; angle) of a bob about a fixed pivot"
    makes = f"as {MAKES_FITTABLE} writes (a pendulum's t, x, y, z)"
    if first.startswith("# pendulab crane grid") or header == CRANE_GRID_HEADER:
        raise KeyedInputError(
            f"{where}: a crane grid (pendulab crane grid --out): one row per case with the columns "
            f"{_names(names)}, no time series; a fit needs {needs}, {makes}",
            "data_crane_grid",
            file=where,
            columns=_names(names),
            command=MAKES_FITTABLE,
        )
    if first.startswith("# pendulab crane run") or {"t", "pivot_x", "payload_x"} <= bare:
        raise KeyedInputError(
            f"{where}: a crane run (pendulab crane run --out) with the columns {_names(names)}: its payload "
            "hangs from a moving trolley (pivot_x, pivot_y, pivot_z), maybe below a hook and on a hoisted "
            f"rope, which none of the fit's models (a fixed pivot) describes; a fit needs {needs}, "
            f"{makes}. For a crane's sway after the move, write t and the payload's offset from "
            "the pivot (payload_x - pivot_x, payload_y - pivot_y) as t,x,y (seen from above)",
            "data_crane_run",
            file=where,
            columns=_names(names),
            command=MAKES_FITTABLE,
        )


MAX_HEADER_PEEK = 1 << 20
"""Characters of a file looked at for the first lines of a Pendulab crane CSV (its metadata line
is a few kB)."""


def _vernier_names(layout: Layout) -> list[str] | None:
    """The header of Vernier's text format (Logger Pro's *Export As Text*: ``Vernier Format 2``, the
    source and date, the data set's name, then lines of long names, short names and units above the
    data) as ``long name (unit)`` cells; None when the header row is not a line of units."""
    units, above = layout.header, layout.preamble
    if not units or not above or not all(u == "" or is_unit(u) for u in units):
        return None
    candidates = [split_line(line, layout.delimiter) for line in above[-2:]]  # long, short names
    names = next((c for c in candidates if len(c) == len(units)), None)
    if names is None:
        return None
    return [f"{n.strip()} ({u})" if u else n.strip() for n, u in zip(names, units, strict=True)]


def _video_export(layout: Layout) -> str | None:
    """The video-analysis program whose export this looks like, if any: Tracker writes the track's
    name (``mass A``) on the line above the header; Logger Pro and Graphical Analysis put the run's
    name before each header cell (``Latest: X (m)``) or on a line of its own."""
    header = layout.header or []
    if any(":" in c.partition("(")[0] for c in header):
        return VIDEO_TOOLS[1]
    if layout.preamble:
        if layout.preamble[0].lower().startswith("vernier format"):
            return VIDEO_TOOLS[1]
        last = layout.preamble[-1]
        return VIDEO_TOOLS[1] if last.lower().startswith(("latest", "run ")) else VIDEO_TOOLS[0]
    return None


def _notes(layout: Layout, named: bool) -> list[str]:
    notes = []
    if layout.preamble and not named:
        shown = ", ".join(clip(p) for p in layout.preamble[-3:])
        notes.append(f"skipped {len(layout.preamble)} line(s) above the header row: {shown}")
    if layout.decimal_comma:
        notes.append("read decimal commas")
    return notes


def _kinds(
    col: dict[str, Any], names: list[str], layout: Layout, named: bool, where: str, notes: list[str]
) -> dict[str, Any]:
    """The columns (in SI) as the data kinds of :func:`pendulab.fit`."""
    for kind, parts in VECTORS.items():  # a sensor's components → the frame-free magnitude
        have = [c for c in parts if c in col]
        if have and kind in col:  # the app wrote the magnitude too (Physics Toolbox's TgF): use it
            for c in have:
                col.pop(c)
            continue
        if have and len(have) < 3:
            raise KeyedInputError(
                f"{where}: {kind} needs all three components {parts}; found {have}",
                "data_components",
                file=where,
                kind=kind,
                parts=", ".join(parts),
                found=", ".join(have),
            )
        if have:
            col[kind] = np.sqrt(sum(col.pop(c) ** 2 for c in parts))
    out: dict[str, Any] = {"t": col["t"]}
    if {"x", "y", "z"} <= col.keys():
        out["positions"] = np.column_stack([col["x"], col["y"], col["z"]])
    elif {"x", "z"} <= col.keys():
        out["positions"] = np.column_stack([col["x"], col["z"]])
    elif {"x", "y"} <= col.keys() and "z" not in col:
        tool = None if named else _video_export(layout)
        if tool is not None:  # a camera's image plane: x across, y up (Tracker's and Logger Pro's default)
            out["positions"] = np.column_stack([col["x"], col["y"]])
            notes.append(
                f"x, y taken as a camera's (horizontal, vertical), the fit's x, z ({tool} above the "
                "header: a video-analysis export); for positions seen from above name them "
                "--columns t,x,y"
            )
        else:
            out["horizontal"] = np.column_stack([col["x"], col["y"]])
            notes.append(
                "x, y taken as horizontal positions (seen from above, e.g. a crane hook's sway); for a "
                "camera's side view (horizontal, vertical) name them --columns t,x,z"
            )
    elif ("x" in col) != ("z" in col) or "y" in col:
        have = sorted(k for k in ("x", "y", "z") if k in col)
        raise KeyedInputError(
            f"{where}: position column(s) {have} alone; positions are x, y, z, or x, z (a camera's side "
            "view), or x, y (horizontal, seen from above)",
            "data_positions_alone",
            file=where,
            have=", ".join(have),
        )
    if {"theta", "phi"} <= col.keys():
        out["angles"] = np.column_stack([col["theta"], col["phi"]])
    if "angle" in col:
        out["planar_angle"] = col["angle"]
    for kind in ("specific_force", "angular_speed"):
        if kind in col:
            out[kind] = col[kind]
    if len(out) == 1:
        raise KeyedInputError(
            f"{where}: no data columns among {_names(names)}; see docs/fit.md for the names",
            "data_no_columns",
            file=where,
            columns=_names(names),
        )
    return out
