"""A finished sweep (``docs/sweeps.md``): the layout of its files on disk — the manifest
``_manifest.json`` (format, version, settings, design, columns and units, the chunks done) and one
Parquet file per chunk, or one merged ``.parquet`` file with the same settings in its schema metadata
— and :class:`SweepResult`, its columns (one row per point: ``point``, the design's axes θ₀, φ₀ [rad],
θ̇₀, φ̇₀ [rad/s], l [m], g [m/s²], the quantities with their SI units) read from there on first use,
as grids or an ``xarray.Dataset``; :func:`read_sweep` opens one.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import io
from .._core import InvalidInputError
from ..display import Row, html_table, number
from .design import AXES, Design

MANIFEST = "_manifest.json"
FORMAT = "pendulab-sweep"
VERSION = 1
META_KEY = b"pendulab_sweep"

_CHUNK = re.compile(r"^chunk-(\d+)\.parquet$")


def chunk_name(index: int) -> str:
    return f"chunk-{index:06d}.parquet"


def _bad(message: str) -> InvalidInputError:
    return InvalidInputError(message)


@dataclass(eq=False)
class SweepResult:
    """The results of a sweep, one row per point.

    ``columns``: ``point`` (int64, the point's number in the design), the design's axes (``theta0``,
    ``phi0`` [rad], ``theta_dot0``, ``phi_dot0`` [rad/s], ``length`` [m], ``g`` [m/s²] — those it
    varies) and the quantity columns (float64); ``units`` per column. ``design`` the points,
    ``quantities`` what was computed, ``metadata`` the settings (``spec``: the pendulum, t_end, dt and
    the RATTLE ``arithmetic``, "fused" or "unfused", of simulated quantities and the version of its
    bits, ``arithmetic_version``; ``fingerprint``),
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
        if "arithmetic" in self.metadata.get("spec", {}):
            rows.append(("arithmetic", str(self.metadata["spec"]["arithmetic"]), ""))
        if "arithmetic_version" in self.metadata.get("spec", {}):
            rows.append(("arithmetic version", str(self.metadata["spec"]["arithmetic_version"]), ""))
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
