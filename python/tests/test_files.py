"""Outputs on disk: CSV, Parquet and NetCDF with units and parameters, written atomically."""

from __future__ import annotations

import json
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

    def broken(fname: object, *args: object, **kwargs: object) -> None:
        Path(str(fname)).write_text("half a file")
        raise OSError("disk full")

    monkeypatch.setattr(np, "savetxt", broken)
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
