"""What a file says about the run that wrote it (pendulab/io.py ``read_metadata``): an adaptive run
(DOP853) has no step size, so its ``options`` hold rtol, atol and a given first step (``first_step``),
never ``dt`` (0.1.0 wrote ``"dt": 0.0``, documented as "automatic"); the steps it took are in
``stats``. Files of 0.1.0 read back as current ones say it; fixed-step runs keep their ``dt``."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab import io
from pendulab.fitting.table import read_table
from pendulab.trajectory.report import method_line

SUFFIXES = (".csv", ".parquet", ".nc")


def _run(**kw: object) -> pl.Trajectory:
    p = pl.Pendulum()
    return pl.simulate(p, p.state_from_angles(theta=1.0, phi_dot=2.0), 1.0, **kw)  # type: ignore[arg-type]


@pytest.mark.parametrize("suffix", SUFFIXES)
def test_an_adaptive_run_writes_its_tolerances_and_steps_not_a_dt(tmp_path: Path, suffix: str) -> None:
    tr = _run(method="dop853", rtol=1e-9, atol=1e-11)
    meta = io.read_metadata(tr.save(tmp_path / f"run{suffix}"))
    assert meta["method"] == "dop853" and "dt" not in meta["options"] and "first_step" not in meta["options"]
    assert (meta["options"]["rtol"], meta["options"]["atol"]) == (1e-9, 1e-11)
    assert meta["stats"]["steps"] == tr.stats["steps"] > 0 and meta["options"] == tr.options
    given = _run(method="dop853", dt=0.01)
    meta = io.read_metadata(given.save(tmp_path / f"given{suffix}"))
    assert meta["options"]["first_step"] == 0.01 and "dt" not in meta["options"]
    fixed = io.read_metadata(_run(method="rattle4", dt=0.002).save(tmp_path / f"fixed{suffix}"))
    assert fixed["options"]["dt"] == 0.002 and "first_step" not in fixed["options"]


def test_the_summary_says_adaptive_steps_and_a_given_first_step() -> None:
    assert "first step" not in method_line(_run(method="dop853"))
    assert "first step 0.01 s" in method_line(_run(method="dop853", dt=0.01))
    # a Trajectory with 0.1.0's options (dt 0.0: automatic; dt h: the first step) says the same
    new = _run(method="dop853")
    old = dataclasses.replace(new, options={"dt": 0.0, **new.options})
    assert method_line(old) == method_line(new)
    old = dataclasses.replace(new, options={"dt": 0.01, **new.options})
    assert method_line(old) == method_line(_run(method="dop853", dt=0.01))


def _as_0_1_0(path: Path, dt: float) -> None:
    """Rewrites a CSV's metadata line as Pendulab 0.1.0 wrote it for an adaptive run: ``"dt": dt``."""
    first, rest = path.read_text(encoding="utf-8").split("\n", 1)
    head, raw = first.split("metadata (JSON): ", 1)
    meta = json.loads(raw)
    meta["options"] = {"dt": dt, **meta["options"]}
    path.write_text(f"{head}metadata (JSON): {json.dumps(meta, sort_keys=True)}\n{rest}", encoding="utf-8")


def test_files_of_0_1_0_with_dt_zero_read_as_current_ones(tmp_path: Path) -> None:
    """0.1.0 wrote ``"dt": 0.0`` for DOP853's automatic first step and ``"dt": h`` for a given one:
    read_metadata drops the first and names the second ``first_step``; the fit's reader (``pendulab
    fit``) reads the numbers as before."""
    tr = _run(method="dop853", save_every=1)
    for dt, first in ((0.0, None), (0.01, 0.01)):
        path = tr.to_csv(tmp_path / f"old{dt}.csv")
        _as_0_1_0(path, dt)
        assert '"dt": ' in path.read_text().splitlines()[0]
        meta = io.read_metadata(path)
        assert "dt" not in meta["options"] and meta["options"].get("first_step") == first
        assert meta["options"]["rtol"] == 1e-10 and meta["stats"] == tr.stats
        data = read_table(path)
        np.testing.assert_array_equal(data["t"], tr.t)
        np.testing.assert_array_equal(data["positions"], tr.x)
    # a fixed-step file keeps its dt, as any other metadata
    fixed = _run(method="rattle", dt=0.001).to_csv(tmp_path / "fixed.csv")
    assert io.read_metadata(fixed)["options"]["dt"] == 0.001


def test_parquet_and_netcdf_of_0_1_0_read_as_current_ones(tmp_path: Path) -> None:
    pa = pytest.importorskip("pyarrow")
    pq = pytest.importorskip("pyarrow.parquet")
    xr = pytest.importorskip("xarray")
    tr = _run(method="dop853")
    meta = tr.metadata() | {"options": {"dt": 0.0, **tr.options}}
    table = pa.table({"t": tr.t}).replace_schema_metadata({"pendulab": json.dumps(meta)})
    pq.write_table(table, tmp_path / "old.parquet")
    ds = xr.Dataset({"t": ("time", tr.t)}, attrs={"pendulab": json.dumps(meta)})
    ds.to_netcdf(tmp_path / "old.nc", engine="scipy")
    for name in ("old.parquet", "old.nc"):
        options = io.read_metadata(tmp_path / name)["options"]
        assert options == tr.options, name


def test_a_file_without_pendulab_metadata_is_a_clear_error(tmp_path: Path) -> None:
    plain = tmp_path / "plain.csv"
    plain.write_text("t,x,z\n0,0.1,-1\n")
    with pytest.raises(pl.InvalidInputError, match=r"plain\.csv: no Pendulab metadata"):
        io.read_metadata(plain)
    broken = tmp_path / "broken.csv"
    broken.write_text('# pendulab trajectory; metadata (JSON): {"options": \nt,x\n')
    with pytest.raises(pl.InvalidInputError, match=r"broken\.csv: no Pendulab metadata \(JSON\)"):
        io.read_metadata(broken)
    binary = tmp_path / "binary.csv"
    binary.write_bytes(b"PK\x03\x04\xff\xfe")
    with pytest.raises(
        pl.InvalidInputError, match=r"binary\.csv: not a text CSV file \(byte 4 is not UTF-8\)"
    ):
        io.read_metadata(binary)
    with pytest.raises(ValueError, match=r"unknown output suffix '\.txt'"):
        io.read_metadata(tmp_path / "run.txt")


def test_pendulab_run_of_an_adaptive_scenario_writes_no_dt(tmp_path: Path) -> None:
    scenario = Path(__file__).resolve().parents[2] / "examples" / "scenarios" / "rosette.toml"
    out = tmp_path / "run.csv"
    code, _, err = invoke("run", str(scenario), "--method", "dop853", "--t-end", "1", "--out", str(out))
    assert code == 0, err
    options = io.read_metadata(out)["options"]
    assert "dt" not in options and options["rtol"] > 0 and options["atol"] > 0
    assert_user_error(*invoke("run", str(scenario), "--method", "dop853", "--dt", "0"), "dt")
