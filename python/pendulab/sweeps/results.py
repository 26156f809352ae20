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

The finished sweep and its files' layout: :mod:`pendulab.sweeps.sweep_result` (``SweepResult``,
``read_sweep``); where a running sweep's chunks go: :mod:`pendulab.sweeps.sinks` (``MemorySink``,
``OutputDir``). This module only re-exports them.
"""

from .sinks import (
    MANIFEST_EVERY,
    MEMORY_FRACTION,
    MemorySink,
    OutputDir,
)
from .sweep_result import (
    FORMAT,
    MANIFEST,
    META_KEY,
    VERSION,
    SweepResult,
    chunk_name,
    read_sweep,
)

__all__ = [
    "FORMAT",
    "MANIFEST",
    "MANIFEST_EVERY",
    "MEMORY_FRACTION",
    "META_KEY",
    "VERSION",
    "MemorySink",
    "OutputDir",
    "SweepResult",
    "chunk_name",
    "read_sweep",
]
