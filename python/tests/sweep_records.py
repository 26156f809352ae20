"""Helpers of the sweep tests that read and tamper with a sweep's records on disk (the manifest and
its chunk files, docs/sweeps.md "Resume") and count the ensemble runs a sweep starts, shared by
test_sweep_arithmetic.py, test_sweep_arithmetic_version.py and test_sweep_method.py; the sweep of
the two arithmetic test files (GRID, QS, KW); and ``sweep_file``, GRID's sweep as a sweep file, for
all three. A plain module (no ``test_`` prefix): test files import from it, never from each other.
Times in seconds, angles in radians."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import pendulab as pl
from pendulab.sweeps import compute as sweep_compute


def same(a: pl.SweepResult, b: pl.SweepResult) -> bool:
    """Whether two sweeps have the same columns with the same numbers bit for bit (NaN equal to NaN)."""
    return list(a.units) == list(b.units) and all(np.array_equal(a[k], b[k], equal_nan=True) for k in a.units)


def manifest(out: Path) -> dict[str, Any]:
    """The sweep's manifest in ``out``."""
    return json.loads((out / "_manifest.json").read_text())


def drop_chunk(out: Path, index: int) -> None:
    """As if the run had been interrupted before chunk ``index`` was written."""
    (out / f"chunk-{index:06d}.parquet").unlink()
    m = manifest(out)
    m["chunks_done"] = [i for i in m["chunks_done"] if i != index]
    m["complete"] = False
    (out / "_manifest.json").write_text(json.dumps(m))


def counting(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Counts the chunks' ensemble runs from here on (``calls[0]``)."""
    calls = [0]
    real = sweep_compute._simulate

    def counted(*args: Any) -> Any:
        calls[0] += 1
        return real(*args)

    monkeypatch.setattr(sweep_compute, "_simulate", counted)
    return calls


GRID = {"theta0": np.linspace(0.3, 2.5, 5), "phi_dot0": np.array([0.0, 1.5, -2.0])}
QS = ["final_state", "energy_drift"]
KW: dict[str, Any] = {"t_end": 0.2, "dt": 1e-3, "progress": False}


def sweep_file(tmp_path: Path, quantities: list[str], dt: float, **simulation_keys: str | None) -> Path:
    """GRID, ``quantities`` to t_end = 0.2 s at step ``dt`` as a sweep file (chunks of 4), with each of
    ``simulation_keys`` that is not None a key of ``[simulation]`` (its value as TOML, e.g.
    ``method='"rattle6"'``); a new file in ``tmp_path`` each call."""
    keys = "".join(f"{key} = {value}\n" for key, value in simulation_keys.items() if value is not None)
    path = tmp_path / f"sw-{len(list(tmp_path.glob('sw-*.toml')))}.toml"
    path.write_text(
        f"quantity = {json.dumps(quantities)}\n"
        "[grid]\ntheta0 = { start = 0.3, stop = 2.5, num = 5 }\nphi_dot0 = [0.0, 1.5, -2.0]\n"
        f"[simulation]\nt_end = 0.2\ndt = {dt!r}\n{keys}[run]\nchunk_size = 4\n"
    )
    return path
