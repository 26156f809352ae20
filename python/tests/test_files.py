"""Outputs on disk: CSV, Parquet and NetCDF with units and parameters, written atomically."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl
from pendulab import io


@pytest.fixture
def trajectory(pendulum: pl.Pendulum, rosette: pl.State) -> pl.Trajectory:
    return pl.simulate(pendulum, rosette, t_end=1.0, dt=1e-3, save_every=100)


def test_csv_round_trip_with_metadata(trajectory: pl.Trajectory, tmp_path: Path) -> None:
    """CSV: a JSON metadata header line (parameters, units), a header with units, full precision."""
    path = trajectory.to_csv(tmp_path / "out.csv")
    first, header = path.read_text().splitlines()[:2]
    meta = json.loads(first.split("metadata (JSON): ", 1)[1])
    assert meta["pendulum"]["length"] == 1.0 and meta["units"]["t"] == "s"
    assert header.startswith("t [s],x [m]")
    data = np.loadtxt(path, delimiter=",", skiprows=2)
    assert data.shape == (len(trajectory), 12)
    assert np.array_equal(data[:, 1:4], trajectory.x)


def _read_back(path: Path, skip: int) -> np.ndarray:
    return np.loadtxt(path, delimiter=",", skiprows=skip, ndmin=2)


def _same_bits(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and np.array_equal(a.view(np.uint64), b.view(np.uint64))


def test_csv_numbers_are_shortest_and_exact(pendulum: pl.Pendulum, rosette: pl.State, tmp_path: Path) -> None:
    """Every CSV writer (trajectory, exact solution, energy-momentum map; the crane's in
    test_crane_cli.py) writes each float as the shortest text that reads back as the same bits:
    0.1 s as ``0.1``, not ``0.10000000000000001``; integral values as ``5``; -0.0, nan and inf kept."""
    tricky = np.array([0.1, 1 / 3, -0.0, 5.0, 1e16, 2.5e-300, 5e-324, np.nan, np.inf, -np.inf, 1e300])
    table = np.column_stack([tricky, np.where(np.isnan(tricky), np.nan, -tricky)])  # NaN has no sign
    lines = "".join(io.csv_rows(table)).splitlines()
    assert lines[:4] == ["0.1,-0.1", "0.3333333333333333,-0.3333333333333333", "-0,0", "5,-5"]
    path = tmp_path / "t.csv"
    path.write_text("\n".join(lines) + "\n")
    assert _same_bits(_read_back(path, 0), table)

    tr = pl.simulate(pendulum, rosette, t_end=1.0, dt=0.1)
    text = tr.to_csv(tmp_path / "run.csv").read_text()
    times = [line.split(",", 1)[0] for line in text.splitlines()[2:]]
    assert times[:3] == ["0", "0.1", "0.2"] and times[-1] == "1", times
    assert _same_bits(
        _read_back(tmp_path / "run.csv", 2), np.column_stack([values for _, values in tr.columns().values()])
    )
    exact = pl.exact(pendulum, rosette).trajectory(np.linspace(0.0, 1.0, 11))
    exact.save(tmp_path / "exact.csv")
    cols = [values for _, values in exact.columns().values()]
    assert _same_bits(_read_back(tmp_path / "exact.csv", 2), np.column_stack(cols))
    emm = pl.em_map(pendulum, grid=(5, 7))
    emm.save(tmp_path / "em.csv")
    ee, jj = np.meshgrid(emm.E, emm.J3, indexing="ij")
    grid = np.column_stack([ee.ravel(), jj.ravel(), emm.W.ravel()])
    assert _same_bits(_read_back(tmp_path / "em.csv", 2), grid)
    assert (tmp_path / "em.csv").read_text().startswith("# pendulab em-map; metadata (JSON): {")


def test_parquet_and_netcdf_carry_units(trajectory: pl.Trajectory, tmp_path: Path) -> None:
    """Parquet field metadata and NetCDF attributes carry units and the run's parameters."""
    import pyarrow.parquet as pq
    import xarray as xr

    table = pq.read_table(trajectory.save(tmp_path / "out.parquet"))
    assert table.schema.field("vx").metadata[b"unit"] == b"m/s"
    assert json.loads(table.schema.metadata[b"pendulab"])["pendulum"]["g"] == 9.81
    assert np.array_equal(table.column("z").to_numpy(), trajectory.x[:, 2])
    with xr.open_dataset(trajectory.save(tmp_path / "out.nc"), engine="scipy") as ds:
        assert ds["x"].attrs["units"] == "m" and ds["time"].attrs["units"] == "s"
        assert json.loads(ds.attrs["pendulab"])["method"] == "rattle"
        assert np.array_equal(ds["x"].values, trajectory.x)


def test_unknown_suffix_is_refused(trajectory: pl.Trajectory, tmp_path: Path) -> None:
    """The format comes from the suffix; an unknown one names the allowed suffixes."""
    with pytest.raises(ValueError, match=r"\.csv, \.parquet, \.nc"):
        trajectory.save(tmp_path / "out.xlsx")


def test_writes_are_atomic(
    trajectory: pl.Trajectory, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A writer that fails half-way leaves the old file untouched and no temporary file behind."""
    target = tmp_path / "out.csv"
    target.write_text("old contents")

    def broken(data: object) -> Iterator[str]:
        yield "0,half a file"
        raise OSError("disk full")

    monkeypatch.setattr(io, "csv_rows", broken)
    with pytest.raises(OSError, match="disk full"):
        io.write_csv(trajectory, target)
    assert target.read_text() == "old contents"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.csv"]


def test_written_files_get_the_usual_permissions(trajectory: pl.Trajectory, tmp_path: Path) -> None:
    """Atomic writes must not leave files readable only by their owner (mkstemp's 0600)."""
    import os

    umask = os.umask(0o022)
    try:
        target = tmp_path / "out.csv"
        trajectory.save(target)
        assert target.stat().st_mode & 0o777 == 0o644
    finally:
        os.umask(umask)
