"""Writing trajectories to disk: CSV, Parquet and NetCDF, chosen by the file suffix.

Every file carries units and the run's parameters in its metadata (CSV: ``#`` header lines;
Parquet: schema metadata; NetCDF: attributes); :func:`read_metadata` reads them back. Files are
written atomically: to a temporary file in the same directory, then renamed over the target, so a
crash never leaves a half-written file.
"""

from __future__ import annotations

import contextlib
import errno
import glob
import json
import os
import re
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any, Protocol


class Tabular(Protocol):
    """What the writers take: ``Trajectory``, ``SpringTrajectory`` — named columns with units
    (``columns()``: name → (unit, array)), a header (``metadata()`` or ``file_metadata()``) and, for
    NetCDF, ``to_xarray()``."""

    def columns(self) -> dict[str, tuple[str, Any]]: ...
    def to_xarray(self) -> Any: ...


FORMATS = {".csv": "csv", ".parquet": "parquet", ".nc": "netcdf"}


STALE_SECONDS = 3600.0
"""A temporary file of a writer that left no process id is stale after this long [s]."""


def _remove_stale(target: Path) -> None:
    """Removes the temporary files an interrupted write (kill -9, power loss) to ``target`` left:
    ``.<name>.pid<N>.*.tmp`` of processes that no longer run, and older ``.<name>.*.tmp`` files
    without a process id after :data:`STALE_SECONDS`. Writers still running keep theirs."""
    with contextlib.suppress(OSError):
        for old in target.parent.glob(f".{glob.escape(target.name)}.*.tmp"):
            pid = old.name[len(target.name) + 2 :].split(".", 1)[0]
            if pid.startswith("pid") and pid[3:].isdigit():
                try:
                    os.kill(int(pid[3:]), 0)
                    continue  # that writer is alive
                except ProcessLookupError:
                    pass
                except OSError:
                    continue  # alive, owned by someone else
            elif time.time() - old.stat().st_mtime < STALE_SECONDS:
                continue
            with contextlib.suppress(OSError):
                old.unlink()


def _named(e: OSError, target: Path) -> OSError:
    """``e`` as an OSError naming the file being written (``error: <file>: No space left on device``)."""
    reason = e.strerror or str(e) or type(e).__name__
    return OSError(e.errno, f"cannot write: {reason}", os.fspath(target))


@contextlib.contextmanager
def atomic_path(path: str | os.PathLike[str]) -> Iterator[Path]:
    """Yields a temporary path beside ``path``; renames it onto ``path`` only if the block succeeds.

    The directory must exist (no directories are created: a typo in a path is an error, not a new
    folder). Any OS error (a full disk, a read-only directory, no permission) is re-raised as one
    ``OSError`` naming ``path``; the temporary file is removed, and so are the stale ones earlier
    interrupted writes to the same target left (:func:`_remove_stale`).
    """
    target = Path(path)
    if not target.parent.is_dir():
        raise OSError(
            errno.ENOENT,
            f"cannot write: the directory {os.fspath(target.parent)!r} does not exist (create it first)",
            os.fspath(target),
        )
    _remove_stale(target)
    try:
        fd, tmp = tempfile.mkstemp(
            prefix=f".{target.name}.pid{os.getpid()}.", suffix=".tmp", dir=target.parent
        )
        os.close(fd)
    except OSError as e:
        raise _named(e, target) from None
    try:
        yield Path(tmp)
        # mkstemp creates 0600; give the file the mode a plain open() would (0666 minus the umask).
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)
        os.replace(tmp, target)
    except OSError as e:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise _named(e, target) from None
    except BaseException:
        with contextlib.suppress(FileNotFoundError):
            os.unlink(tmp)
        raise


def format_of(path: str | os.PathLike[str]) -> str:
    """The file format from the suffix: .csv, .parquet or .nc; a clear error otherwise."""
    suffix = Path(path).suffix.lower()
    if suffix not in FORMATS:
        text = str(path)
        if text.endswith(("/", os.sep)) or os.path.isdir(path):
            example = os.path.join(text, "run.csv")
            raise ValueError(
                f"{text!r} is a directory: give a file name ending in .csv, .parquet or .nc"
                f" (e.g. {example!r})"
            )
        raise ValueError(f"unknown output suffix {suffix!r} in {text!r}; use one of .csv, .parquet, .nc")
    return FORMATS[suffix]


def _require(module: str, extra: str = "io") -> Any:
    try:
        return __import__(module)
    except ImportError as e:  # pragma: no cover - depends on the environment
        raise ImportError(f"writing this format needs {module!r}: pip install 'pendulab[{extra}]'") from e


def _metadata(tr: Any) -> dict[str, Any]:
    """What a file's header carries: ``Trajectory.metadata()`` (``SpringTrajectory.file_metadata()``)."""
    # Tabular names neither method (SpringTrajectory's `metadata` is a field): both return the header
    header: Callable[[], dict[str, Any]] = tr.file_metadata if hasattr(tr, "file_metadata") else tr.metadata
    return header()


_TRAILING_ZERO = re.compile(r"\.0(?=[,\n])")
_CSV_CHUNK = 1 << 14  # rows formatted at a time


def csv_number(value: float) -> str:
    """A float as CSV text: the shortest decimal that reads back as exactly ``value`` (Python's
    ``repr``: 0.1 stays ``0.1``, not ``0.10000000000000001``), an integral value without ``.0``
    (``5``, ``-0``, ``1e+16``); ``nan``, ``inf``, ``-inf`` as NumPy and ``float()`` read them."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


def csv_rows(data: Any) -> Iterator[str]:
    """The lines (with ``\\n``) of a 2-D float array, comma-separated, each number as :func:`csv_number`
    writes it; formatted a chunk of rows at a time."""
    import numpy as np

    table = np.asarray(data, dtype=np.float64)
    for start in range(0, table.shape[0], _CSV_CHUNK):
        rows = table[start : start + _CSV_CHUNK].tolist()
        yield _TRAILING_ZERO.sub("", "".join(",".join(map(repr, row)) + "\n" for row in rows))


def csv_header(kind: str, metadata: dict[str, Any], columns: dict[str, tuple[str, Any]]) -> list[str]:
    """The two header lines of every Pendulab CSV file: ``# pendulab <kind>; metadata (JSON): {...}``
    (keys sorted; readers skip it as a comment) and the column names with units, ``t [s],x [m],…``."""
    return [
        f"# pendulab {kind}; metadata (JSON): {json.dumps(metadata, sort_keys=True)}",
        ",".join(f"{name} [{unit}]" for name, (unit, _) in columns.items()),
    ]


def write_columns_csv(
    path: str | os.PathLike[str], kind: str, metadata: dict[str, Any], columns: dict[str, tuple[str, Any]]
) -> None:
    """Writes :func:`csv_header` and then one row per sample of the equal-length ``columns`` (name →
    (unit, floats)), each number as :func:`csv_number` writes it, to ``path`` atomically: the CSV
    writer of trajectories, exact solutions, energy-momentum maps and crane runs."""
    import numpy as np

    data = np.column_stack([values for _, values in columns.values()])
    with atomic_path(path) as tmp, open(tmp, "w", encoding="utf-8", newline="") as f:
        f.write("".join(line + "\n" for line in csv_header(kind, metadata, columns)))
        f.writelines(csv_rows(data))


def write_csv(tr: Tabular, path: str | os.PathLike[str]) -> None:
    """CSV with a ``#`` header of metadata (JSON) and one row per sample, columns with units; numbers
    in the shortest form that reads back exactly (:func:`csv_number`)."""
    write_columns_csv(path, "trajectory", _metadata(tr), tr.columns())


def write_parquet(tr: Tabular, path: str | os.PathLike[str]) -> None:
    """Parquet, one row per sample; units per column in field metadata, run metadata in the schema."""
    _require("pyarrow")
    import pyarrow as pa
    import pyarrow.parquet as pq

    fields, arrays = [], []
    for name, (unit, values) in tr.columns().items():
        fields.append(pa.field(name, pa.float64(), metadata={"unit": unit}))
        arrays.append(pa.array(values))
    schema = pa.schema(fields, metadata={"pendulab": json.dumps(_metadata(tr), sort_keys=True)})
    table = pa.Table.from_arrays(arrays, schema=schema)
    with atomic_path(path) as tmp:
        pq.write_table(table, tmp)


def write_netcdf(tr: Tabular, path: str | os.PathLike[str]) -> None:
    """NetCDF (via xarray; the scipy engine, NetCDF3 classic) with units and metadata as attributes."""
    _require("xarray")
    _require("scipy")
    ds = tr.to_xarray()
    with atomic_path(path) as tmp:
        ds.to_netcdf(tmp, engine="scipy")


WRITERS: dict[str, Callable[[Tabular, str | os.PathLike[str]], None]] = {
    "csv": write_csv,
    "parquet": write_parquet,
    "netcdf": write_netcdf,
}


def save(tr: Tabular, path: str | os.PathLike[str]) -> Path:
    """Writes ``tr`` to ``path`` in the format its suffix names; returns the path."""
    WRITERS[format_of(path)](tr, path)
    return Path(path)


_CSV_MARK = "metadata (JSON): "
_CSV_LINE_MAX = 1 << 22  # characters of a CSV's first line read [about 4 MB]


def read_metadata(path: str | os.PathLike[str]) -> dict[str, Any]:
    """The metadata a Pendulab file carries (parameters, ``method``, ``options``, ``stats``, units), from
    a CSV's ``# pendulab <kind>; metadata (JSON): {...}`` line, a Parquet file's schema metadata or a
    NetCDF file's ``pendulab`` attribute; a clear error for a file without it.

    An adaptive run's ``options`` (``dop853``) hold ``rtol`` and ``atol`` and, when one was given, the
    ``first_step`` [s], never a ``dt``; files of Pendulab 0.1.0 wrote ``"dt": 0.0`` for a first step
    chosen automatically (``"dt": h`` for a given one), read here as the current files say it. A crane
    run's CSV says the spacing of its rows [s] as ``file.simulation.output_spacing`` (its file's
    ``[simulation] dt``); older ones said ``dt`` there, also read as today's.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> from pendulab.io import read_metadata
    >>> p = pl.Pendulum()
    >>> tr = pl.simulate(p, p.state_from_angles(theta=0.5), t_end=1.0, method="dop853")
    >>> path = tr.to_csv("swing.csv")
    >>> meta = read_metadata(path)
    >>> meta["method"], meta["options"]["rtol"], "dt" in meta["options"]
    ('dop853', 1e-10, False)
    """
    from ._core import InvalidInputError

    fmt = format_of(path)
    where = os.fspath(path)
    if fmt == "csv":
        try:
            with open(path, encoding="utf-8-sig") as f:
                first = f.readline(_CSV_LINE_MAX)
        except UnicodeDecodeError as e:
            raise InvalidInputError(
                f"{where}: not a text CSV file (byte {e.start} is not UTF-8): no Pendulab metadata"
            ) from None
        if not (first.startswith("# pendulab ") and _CSV_MARK in first):
            mark = f"# pendulab <kind>; {_CSV_MARK}{{...}}"
            raise InvalidInputError(f"{where}: no Pendulab metadata: the first line is not {mark!r}")
        raw: str | bytes = first.split(_CSV_MARK, 1)[1]
    elif fmt == "parquet":
        _require("pyarrow")
        import pyarrow.parquet as pq

        raw = (pq.read_schema(path).metadata or {}).get(b"pendulab", b"")
    else:
        _require("xarray")
        _require("scipy")
        import xarray as xr

        with xr.open_dataset(path, engine="scipy") as ds:
            raw = str(ds.attrs.get("pendulab", ""))
    try:
        meta = json.loads(raw)
    except ValueError:
        meta = None
    if not isinstance(meta, dict):
        raise InvalidInputError(f"{where}: no Pendulab metadata (JSON) in this {fmt} file")
    return _upgraded(meta)


def _upgraded(meta: dict[str, Any]) -> dict[str, Any]:
    """``meta`` (a file's metadata) with the ``options`` of an adaptive run of Pendulab 0.1.0 as current
    files write them: ``"dt": 0.0`` (a first step chosen automatically) dropped, ``"dt": h`` > 0 (a
    given first step) as ``"first_step": h``; a crane run's ``file.simulation.dt`` (the spacing of its
    output rows) as ``output_spacing``. Other metadata is returned as it is."""
    file = meta.get("file")
    if isinstance(file, dict) and "crane" in file:  # a crane run's CSV (pendulab crane run --out)
        from .crane.scenario import file_settings

        meta = meta | {"file": file_settings(file)}
    options = meta.get("options")
    if not (isinstance(options, dict) and "dt" in options and _adaptive(meta.get("method"))):
        return meta
    options = dict(options)
    first = options.pop("dt")
    if isinstance(first, int | float) and first > 0:
        options.setdefault("first_step", first)
    return meta | {"options": options}


def _adaptive(method: object) -> bool:
    """True for the name of a method that chooses its own steps (``dop853``): the integrators' table,
    the one :func:`pendulab.simulate` reads (an unknown name, or not a name: False)."""
    from .integrators import _method_table

    info = _method_table().get(method) if isinstance(method, str) else None
    return info is not None and bool(info["adaptive"])
