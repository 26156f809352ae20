"""Where a running sweep's results go, chunk by chunk (``docs/sweeps.md``): :class:`MemorySink`
(preallocated columns, refused beyond :data:`MEMORY_FRACTION` of the physical memory [B]) or
:class:`OutputDir` (one Parquet file per chunk and the manifest in a directory, or staged beside a
``.parquet`` file and merged into it at the end; refused up front beyond the free disk [B]). Every
file is written atomically (temporary file + rename), so a chunk file is either complete or absent:
resuming trusts the files, and the manifest — rewritten at most every :data:`MANIFEST_EVERY` s —
says what they belong to. Both hand back a :class:`~pendulab.sweeps.sweep_result.SweepResult`.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import time
from pathlib import Path
from typing import Any

import numpy as np

from .. import io
from .._core import __version__
from ..model import FloatArray
from .design import Design
from .sweep_result import (
    _CHUNK,
    FORMAT,
    MANIFEST,
    META_KEY,
    VERSION,
    SweepResult,
    _bad,
    _read_manifest,
    chunk_name,
)

MANIFEST_EVERY = 1.0
"""Seconds between rewrites of the manifest while chunks finish (and once at the end)."""

MEMORY_FRACTION = 0.5
"""Largest share of the physical memory that results held in memory may take."""


def _gib(n: float) -> str:
    return f"{n / 2**30:.3g} GiB" if n >= 2**27 else f"{n / 2**20:.3g} MiB"


def _physical_memory() -> int | None:
    try:
        return int(os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES"))
    except (AttributeError, ValueError, OSError):  # pragma: no cover - not POSIX
        return None


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
        target, is_file, directory = _paths(out)
        parent = target.resolve().parent
        if not parent.is_dir():  # a typo in a path is an error, not new folders (docs/limits.md)
            raise _bad(f"out {str(target)!r}: the directory {str(parent)!r} does not exist; create it first")
        if not is_file and target.suffix and not target.is_dir():
            raise _bad(f"out {str(target)!r}: give a directory or a file ending in .parquet")
        if is_file and target.is_dir():
            raise _bad(f"out {str(target)!r} is a directory; a file ending in .parquet was expected")
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
        directory.mkdir(exist_ok=True)
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


def _paths(out: str | os.PathLike[str]) -> tuple[Path, bool, Path]:
    """``out``, whether it is a .parquet file, and the directory of its chunks (``out`` itself, or the
    staging directory beside the file)."""
    target = Path(out)
    is_file = target.suffix.lower() == ".parquet"
    return target, is_file, target.parent / f".{target.name}.chunks" if is_file else target


def recorded_sweep(out: str | os.PathLike[str]) -> tuple[Path, dict[str, Any]] | None:
    """The sweep already in ``out`` — where (the directory or the finished file) and its manifest
    (``spec``, ``fingerprint``, …) — or None if there is none (:meth:`OutputDir.open` then refuses
    whatever else is there). Read before a resume to carry over what the file records."""
    target, is_file, directory = _paths(out)
    if (directory / MANIFEST).is_file():
        return directory, _read_manifest(directory)
    if not (is_file and target.is_file()):
        return None
    _require_pyarrow()
    import pyarrow.parquet as pq

    try:
        raw = (pq.read_schema(target).metadata or {}).get(META_KEY)
        m = json.loads(raw) if raw else None
    except (OSError, ValueError):
        return None
    return (target, m) if isinstance(m, dict) and isinstance(m.get("spec"), dict) else None
