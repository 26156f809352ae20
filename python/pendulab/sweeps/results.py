"""Where a sweep's results go: memory, or Parquet on disk chunk by chunk (``docs/sweeps.md``).

Output layout of ``out = DIR``::

    DIR/_manifest.json         the settings, the design, the columns and units, the chunks done
    DIR/chunk-000000.parquet   one file per chunk: one row per point (``point``, the axes, the
    DIR/chunk-000001.parquet   quantity columns); units in the field metadata
    ...

``pyarrow.parquet.read_table(DIR)`` or ``pandas.read_parquet(DIR)`` read it as one table (names
starting with ``_`` or ``.`` are skipped). With ``out = FILE.parquet`` the same files are staged in
``.FILE.parquet.chunks/`` beside it and merged into FILE.parquet when the last chunk is done (then the
staging directory is removed). Every file is written atomically (temporary file + rename), so a chunk
file is either complete or absent: resuming trusts the files, and the manifest says what they belong to.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import shutil
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import io
from .._core import InvalidInputError, __version__
from ..display import Row, html_table, number
from ..model import FloatArray
from .design import AXES, Design

MANIFEST = "_manifest.json"
FORMAT = "pendulab-sweep"
VERSION = 1
META_KEY = b"pendulab_sweep"
MANIFEST_EVERY = 1.0
"""Seconds between rewrites of the manifest while chunks finish (and once at the end)."""

MEMORY_FRACTION = 0.5
"""Largest share of the physical memory that results held in memory may take."""

_CHUNK = re.compile(r"^chunk-(\d+)\.parquet$")


def chunk_name(index: int) -> str:
    return f"chunk-{index:06d}.parquet"


def _bad(message: str) -> InvalidInputError:
    return InvalidInputError(message)


def _gib(n: float) -> str:
    return f"{n / 2**30:.3g} GiB" if n >= 2**27 else f"{n / 2**20:.3g} MiB"


def _physical_memory() -> int | None:
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):  # pragma: no cover - not POSIX
        return None


# --- the result ----------------------------------------------------------------------------------


@dataclass(eq=False)
class SweepResult:
    """The results of a sweep, one row per point.

    ``columns``: ``point`` (int64, the point's number in the design), the design's axes (``theta0``,
    ``phi0`` [rad], ``theta_dot0``, ``phi_dot0`` [rad/s], ``length`` [m], ``g`` [m/s²] — those it
    varies) and the quantity columns (float64); ``units`` per column. ``design`` the points,
    ``quantities`` what was computed, ``metadata`` the settings (pendulum, t_end, dt, fingerprint),
    ``stats`` how it ran (chunks, computed, skipped, backend, seconds), ``path`` where it is on disk
    (columns are read from there on first use).
    """

    design: Design
    quantities: tuple[str, ...]
    units: dict[str, str]
    metadata: dict[str, Any]
    stats: dict[str, Any] = field(default_factory=dict)
    path: Path | None = None
    _columns: dict[str, np.ndarray] | None = None

    @property
    def columns(self) -> dict[str, np.ndarray]:
        """Column name → NumPy array of n values (read from ``path`` on first use)."""
        if self._columns is None:
            assert self.path is not None
            self._columns = _read_columns(self.path)
        return self._columns

    def __repr__(self) -> str:
        where = f", at {str(self.path)!r}" if self.path is not None else ""
        return (
            f"SweepResult({self.design.n} points ({self.design.kind}), quantities {list(self.quantities)}"
            f"{where})"
        )

    def _repr_html_(self) -> str:
        rows: list[Row] = [
            ("points", self.design.n, ""),
            ("design", self.design.kind, ""),
            ("quantities", ", ".join(self.quantities), ""),
        ]
        rows += [(f"column {name}", "", unit) for name, unit in self.units.items()]
        if self.path is not None:
            rows.append(("on disk", str(self.path), ""))
        for key in ("computed", "skipped", "backend"):
            if key in self.stats:
                rows.append((key, str(self.stats[key]), ""))
        if "seconds" in self.stats:
            rows.append(("wall time", number(self.stats["seconds"]), "s"))
        return html_table("Sweep", rows, note="sw['column'], sw.to_xarray()")

    def __len__(self) -> int:
        return self.design.n

    def __getitem__(self, name: str) -> np.ndarray:
        if name not in self.units:
            raise KeyError(f"no column {name!r}; the columns are {', '.join(self.units)}")
        return self.columns[name]

    def grid(self, name: str) -> np.ndarray:
        """Column ``name`` shaped as the grid (``design.shape``, axes in order); grids only."""
        if self.design.kind != "grid":
            raise _bad(f"grid() needs a grid design, this one is {self.design.kind!r}; use the columns")
        return self[name].reshape(self.design.shape)

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset``: for a grid, each quantity column on the grid's dims (one per axis,
        with its values as coordinates); otherwise on dim ``point`` with the axes as coordinates.
        Units in the ``units`` attributes, the settings in the dataset's attributes (JSON)."""
        xr = io._require("xarray")
        qcols = [c for c in self.units if c != "point" and c not in self.design.names]
        if self.design.kind == "grid":
            assert self.design.axes is not None
            dims = list(self.design.names)
            coords = {k: (k, v, {"units": AXES[k]}) for k, v in self.design.axes.items()}
            data = {c: (dims, self.grid(c), {"units": self.units[c]}) for c in qcols}
        else:
            coords = {k: ("point", self[k], {"units": AXES[k]}) for k in self.design.names}
            coords["point"] = ("point", self["point"], {"units": "1"})
            data = {c: (["point"], self[c], {"units": self.units[c]}) for c in qcols}
        attrs = {"software": "pendulab", "pendulab_sweep": json.dumps(self.metadata)}
        return xr.Dataset(data, coords=coords, attrs=attrs)


def _read_columns(path: Path) -> dict[str, np.ndarray]:
    import pyarrow.parquet as pq

    if path.is_dir():
        manifest = _read_manifest(path)
        tables = [pq.read_table(path / chunk_name(i)) for i in range(manifest["n_chunks"])]
        cols = {name: [t.column(name).to_numpy() for t in tables] for name in manifest["columns"]}
        return {k: np.concatenate(v) for k, v in cols.items()}
    table = pq.read_table(path)
    return {name: table.column(name).to_numpy() for name in table.column_names}


def _read_manifest(directory: Path) -> dict[str, Any]:
    path = directory / MANIFEST
    try:
        m = json.loads(path.read_text())
    except json.JSONDecodeError as e:
        raise _bad(f"{path}: not a sweep manifest ({e})") from None
    if not isinstance(m, dict) or m.get("format") != FORMAT:
        raise _bad(f"{path}: not a pendulab sweep manifest")
    if m.get("version") != VERSION:
        raise _bad(f"{path}: manifest version {m.get('version')!r}; this pendulab reads version {VERSION}")
    return m


def read_sweep(path: str | os.PathLike[str]) -> SweepResult:
    """A finished sweep from disk: its directory or its ``.parquet`` file."""
    p = Path(path)
    if p.is_dir():
        m = _read_manifest(p)
        if not m.get("complete"):
            done = len(m.get("chunks_done", []))
            raise _bad(
                f"{p} holds an unfinished sweep ({done} of {m['n_chunks']} chunks): "
                "finish it with resume=True"
            )
    else:
        import pyarrow.parquet as pq

        raw = (pq.read_schema(p).metadata or {}).get(META_KEY)
        if raw is None:
            raise _bad(f"{p}: not a pendulab sweep file (no {META_KEY.decode()!r} metadata)")
        m = json.loads(raw)
    cols = None
    if m["design"]["kind"] == "grid":
        design = Design.from_description(m["design"])
    else:
        cols = _read_columns(p)
        design = Design.from_description(m["design"], {k: cols[k] for k in m["design"]["names"]})
    return SweepResult(
        design=design,
        quantities=tuple(m["spec"]["quantities"]),
        units=m["columns"],
        metadata={k: m[k] for k in ("design", "spec", "fingerprint", "columns")},
        stats={"chunks": m["n_chunks"], "chunk_size": m["chunk_size"]},
        path=p,
        _columns=cols,
    )


# --- in memory -----------------------------------------------------------------------------------


class MemorySink:
    """Collects the chunks into preallocated columns (after checking they fit in memory)."""

    def __init__(self, n: int, units: dict[str, str]) -> None:
        need = n * 8 * len(units)
        mem = _physical_memory()
        if mem is not None and need > MEMORY_FRACTION * mem:
            raise _bad(
                f"the results need {_gib(need)} in memory ({n} points x {len(units)} columns x 8 bytes), "
                f"more than half of the {_gib(mem)} here: give out= (a directory) to write them "
                "chunk by chunk"
            )
        self.columns = {k: np.empty(n, dtype=np.int64 if k == "point" else np.float64) for k in units}

    def has(self, index: int) -> bool:
        return False

    def add(self, index: int, start: int, cols: dict[str, FloatArray]) -> None:
        for k, v in cols.items():
            self.columns[k][start : start + len(v)] = v

    def flush(self) -> None:
        return None

    def result(
        self, design: Design, quantities: tuple[str, ...], meta: dict[str, Any], stats: dict[str, Any]
    ) -> SweepResult:
        return SweepResult(design, quantities, meta["columns"], meta, stats, None, self.columns)


# --- on disk -------------------------------------------------------------------------------------


def _differences(old: dict[str, Any], new: dict[str, Any]) -> str:
    parts = []
    if old["design"] != new["design"]:
        parts.append("the points (design)")
    for k in sorted(set(old["spec"]) | set(new["spec"])):
        a, b = old["spec"].get(k), new["spec"].get(k)
        if a != b:
            parts.append(f"{k} ({a!r} there, {b!r} here)")
    return ", ".join(parts) or "the points (values)"


class OutputDir:
    """The chunk files and manifest of a sweep in a directory (see the module docstring)."""

    def __init__(self, target: Path, directory: Path, manifest: dict[str, Any], done: set[int]) -> None:
        self.target = target
        self.directory = directory
        self.manifest = manifest
        self.done = done
        self.chunk_size: int = manifest["chunk_size"]
        self._written = 0.0
        self._merged = False

    @classmethod
    def open(
        cls,
        out: str | os.PathLike[str],
        meta: dict[str, Any],
        chunk_size: int | None,
        default_size: int,
        n: int,
        resume: bool,
    ) -> OutputDir:
        """Prepares ``out`` (a directory, or a .parquet file and its staging directory); with ``resume``
        finds the chunks already done. Refuses up front: an output that holds another or an unfinished
        sweep (without ``resume``), a different sweep (with it), and results larger than the free disk."""
        _require_pyarrow()
        target = Path(out)
        is_file = target.suffix.lower() == ".parquet"
        if not is_file and target.suffix and not target.is_dir():
            raise _bad(f"out {str(target)!r}: give a directory or a file ending in .parquet")
        if is_file and target.is_dir():
            raise _bad(f"out {str(target)!r} is a directory; a file ending in .parquet was expected")
        directory = target.parent / f".{target.name}.chunks" if is_file else target
        has_manifest = (directory / MANIFEST).is_file()
        if not resume and has_manifest:
            m = _read_manifest(directory)
            what = "an unfinished sweep" if is_file or not m.get("complete") else "a sweep"
            raise _bad(
                f"{directory} already holds {what} ({len(m.get('chunks_done', []))} of {m['n_chunks']} "
                "chunks): pass resume=True (--resume) to continue it, or remove it"
            )
        if not is_file and directory.is_dir() and not has_manifest and any(directory.iterdir()):
            raise _bad(f"out directory {str(directory)!r} is not empty and holds no sweep; give a new one")
        if resume and has_manifest:
            old = _read_manifest(directory)
            if old["fingerprint"] != meta["fingerprint"]:
                raise _bad(f"{directory} holds a different sweep: {_differences(old, meta)} differ")
            if chunk_size is not None and chunk_size != old["chunk_size"]:
                raise _bad(
                    f"chunk_size = {chunk_size} differs from {old['chunk_size']} of the sweep in "
                    f"{directory}; resume with the same chunk size (or leave it out)"
                )
            self = cls(target, directory, old, set())
            self._scan()
            return self
        if resume and is_file and target.is_file():
            return cls._finished_file(target, meta)
        size = chunk_size or default_size
        manifest = {
            "format": FORMAT,
            "version": VERSION,
            "software": f"pendulab {__version__}",
            "created": time.strftime("%Y-%m-%dT%H:%M:%S%z"),
            **meta,
            "n_points": n,
            "chunk_size": size,
            "n_chunks": -(-n // size),
            "chunks_done": [],
            "complete": False,
        }
        need = n * 8 * len(meta["columns"]) * (2 if is_file else 1)
        probe = directory
        while not probe.exists():
            probe = probe.parent
        free = shutil.disk_usage(probe).free
        if need > free:
            raise _bad(
                f"the results need about {_gib(need)} on disk ({n} points x {len(meta['columns'])} columns "
                f"x 8 bytes{', twice while merging' if is_file else ''}), more than the {_gib(free)} free "
                f"in {probe}"
            )
        directory.mkdir(parents=True, exist_ok=True)
        self = cls(target, directory, manifest, set())
        self._write_manifest()
        return self

    @classmethod
    def _finished_file(cls, target: Path, meta: dict[str, Any]) -> OutputDir:
        import pyarrow.parquet as pq

        raw = (pq.read_schema(target).metadata or {}).get(META_KEY)
        old = json.loads(raw) if raw else None
        if old is None or old.get("fingerprint") != meta["fingerprint"]:
            why = "is not a sweep file"
            if old is not None:
                why = f"holds a different sweep: {_differences(old, meta)} differ"
            raise _bad(f"{target} {why}; give another --out or remove it")
        self = cls(target, target, old, set(range(old["n_chunks"])))
        self._merged = True
        return self

    def _scan(self) -> None:
        """Finds the chunks done: listed in the manifest with their file present, or a file present but
        not yet listed (written just before an interruption) whose metadata matches. Removes the
        temporary files a killed run may have left."""
        import pyarrow.parquet as pq

        listed = set(self.manifest.get("chunks_done", []))
        n_chunks, size, n = self.manifest["n_chunks"], self.chunk_size, self.manifest["n_points"]
        for path in self.directory.iterdir():
            if path.name.startswith(".") and path.name.endswith(".tmp"):
                with contextlib.suppress(OSError):
                    path.unlink()
                continue
            m = _CHUNK.match(path.name)
            if m is None or not path.is_file() or int(m.group(1)) >= n_chunks:
                continue
            i = int(m.group(1))
            if i not in listed:
                try:
                    md = pq.read_metadata(path)
                    info = json.loads((md.metadata or {}).get(META_KEY, b"{}"))
                except (OSError, ValueError):
                    continue
                rows = min(size, n - i * size)
                if info.get("fingerprint") != self.manifest["fingerprint"] or md.num_rows != rows:
                    continue
            self.done.add(i)

    def has(self, index: int) -> bool:
        return index in self.done

    def add(self, index: int, start: int, cols: dict[str, FloatArray]) -> None:
        """Writes chunk ``index`` (atomically) and, at most every :data:`MANIFEST_EVERY` s, the manifest."""
        import pyarrow as pa
        import pyarrow.parquet as pq

        schema = self._schema({"chunk": index, "start": start}, with_design=False)
        table = pa.Table.from_arrays([cols[k] for k in self.manifest["columns"]], schema=schema)
        with io.atomic_path(self.directory / chunk_name(index)) as tmp:
            pq.write_table(table, tmp)
        self.done.add(index)
        if time.monotonic() - self._written > MANIFEST_EVERY:
            self._write_manifest()

    def _schema(self, extra: dict[str, Any], with_design: bool = True) -> Any:
        """Columns with units; the settings as schema metadata (the design, possibly long, only in a
        merged file: a chunk file carries its number, first point and the fingerprint)."""
        import pyarrow as pa

        fields = [
            pa.field(k, pa.int64() if k == "point" else pa.float64(), metadata={"unit": u})
            for k, u in self.manifest["columns"].items()
        ]
        skip = ("chunks_done",) if with_design else ("chunks_done", "design")
        info = {k: v for k, v in self.manifest.items() if k not in skip} | extra
        return pa.schema(fields, metadata={META_KEY: json.dumps(info)})

    def _write_manifest(self) -> None:
        if self._merged:
            return
        self.manifest["chunks_done"] = sorted(self.done)
        self.manifest["complete"] = len(self.done) == self.manifest["n_chunks"]
        with io.atomic_path(self.directory / MANIFEST) as tmp:
            tmp.write_text(json.dumps(self.manifest, indent=1) + "\n")
        self._written = time.monotonic()

    def flush(self) -> None:
        self._write_manifest()

    def result(
        self, design: Design, quantities: tuple[str, ...], meta: dict[str, Any], stats: dict[str, Any]
    ) -> SweepResult:
        """Marks the sweep complete; for a .parquet target merges the chunks into it (chunk by chunk, as
        row groups) and removes the staging directory."""
        self._write_manifest()
        if self.target != self.directory and not self._merged:
            import pyarrow.parquet as pq

            schema = self._schema({})
            with io.atomic_path(self.target) as tmp, pq.ParquetWriter(tmp, schema) as writer:
                for i in range(self.manifest["n_chunks"]):
                    writer.write_table(pq.read_table(self.directory / chunk_name(i)))
            shutil.rmtree(self.directory)
            self._merged = True
        return SweepResult(design, quantities, meta["columns"], meta, stats, self.target)


def _require_pyarrow() -> None:
    io._require("pyarrow")
