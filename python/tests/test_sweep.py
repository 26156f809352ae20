"""Sweeps (pendulab.sweep, docs/sweeps.md), how they are computed: the simulated quantities equal one
simulate_ensemble whatever the chunking, workers and backend (threads, a real dask.distributed
LocalCluster, an unreachable scheduler named); chunks on disk are complete or absent (Ctrl-C),
resume computes only what is missing; the CLI end to end. What a sweep computes and refuses is in
test_sweep_inputs.py. Times in seconds, angles in radians, lengths in metres."""

from __future__ import annotations

import json
import logging
import os
import signal
import time
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow.parquet as pq
import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.sweeps import backends as sweep_backends
from pendulab.sweeps import run as sweep_mod

ALL = ["final_state", "rotation_number", "period", "max_sway", "energy_drift"]
GRID = {"theta0": np.linspace(0.2, 2.8, 6), "phi_dot0": np.array([-2.0, 0.0, 0.5, 3.0]), "length": [0.5, 2.0]}


def _same(a: pl.SweepResult, b: pl.SweepResult) -> None:
    assert list(a.units) == list(b.units)
    for k in a.units:
        assert np.array_equal(a[k], b[k], equal_nan=True), k


@pytest.fixture(scope="module")
def reference() -> pl.SweepResult:
    """Every quantity on GRID (48 points, 0.2 s of RATTLE), in memory, default chunking."""
    return pl.sweep(GRID, ALL, t_end=0.2, dt=1e-3, progress=False)


def test_simulated_quantities_equal_simulate_ensemble(reference: pl.SweepResult) -> None:
    """final_state, max_sway and energy_drift are those of one simulate_ensemble call over all points
    (per-trajectory length), bit for bit, although the sweep split them into chunks."""
    p = pl.Pendulum()
    th, pd, ln = np.meshgrid(GRID["theta0"], GRID["phi_dot0"], GRID["length"], indexing="ij")
    ln = ln.ravel()
    states = np.array(
        [
            pl.Pendulum(length=c).state_from_angles(a, 0.0, 0.0, b).as_array()
            for a, b, c in zip(th.ravel(), pd.ravel(), ln, strict=True)
        ]
    )
    ens = pl.simulate_ensemble(p, states, 0.2, dt=1e-3, length=ln)
    assert ens.summary is not None
    for k, name in enumerate("xyz"):
        assert np.array_equal(reference[name], ens.final_x[:, k])
        assert np.array_equal(reference["v" + name], ens.final_v[:, k])
    assert np.array_equal(reference["energy_drift"], ens.summary["energy_drift"])
    assert np.array_equal(reference["max_sway"], np.arccos(np.clip(-ens.summary["z_max"] / ln, -1, 1)))
    assert np.all(reference["max_sway"] >= th.ravel() - 1e-12)  # never below the start's angle
    assert np.array_equal(reference["theta0"], th.ravel()) and np.array_equal(
        reference["point"], np.arange(48)
    )


def test_chunking_and_workers_do_not_change_the_numbers(reference: pl.SweepResult) -> None:
    small = pl.sweep(GRID, ALL, t_end=0.2, dt=1e-3, chunk_size=5, workers=1, progress=False)
    assert small.stats["chunks"] == 10 and small.stats["computed"] == 10
    _same(reference, small)


def test_dask_local_cluster_equals_threads(reference: pl.SweepResult) -> None:
    """A real dask.distributed LocalCluster (2 worker processes, 1 thread each), reached at its tcp://
    address, gives the threads backend's numbers exactly, for every quantity."""
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(
        n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=logging.ERROR
    ) as cluster:
        assert cluster.scheduler_address.startswith("tcp://")
        res = pl.sweep(
            GRID, ALL, t_end=0.2, dt=1e-3, chunk_size=8, scheduler=cluster.scheduler_address, progress=False
        )
    assert "2 worker threads" in res.stats["backend"] and res.stats["computed"] == 6
    _same(reference, res)


def test_unreachable_scheduler_is_a_clear_error(monkeypatch: pytest.MonkeyPatch) -> None:
    pytest.importorskip("distributed")
    monkeypatch.setattr(sweep_backends, "CONNECT_TIMEOUT", 0.5)
    t0 = time.perf_counter()
    with pytest.raises(
        OSError, match=r"cannot reach the Dask scheduler at tcp://127\.0\.0\.1:1 within 0\.5 s"
    ):
        pl.sweep({"theta0": [1.0]}, "period", scheduler="tcp://127.0.0.1:1")
    # no hang, however loaded the machine (the message above says the 0.5 s limit ended the wait)
    assert time.perf_counter() - t0 < 20.0


def _count_chunks(monkeypatch: pytest.MonkeyPatch, hook: Any = None) -> list[int]:
    """Wraps compute_chunk (what the thread pool runs) to record the chunks computed."""
    calls: list[int] = []
    real = sweep_mod.compute_chunk

    def counting(task: sweep_mod.ChunkTask, cancel: Any = None) -> dict[str, np.ndarray]:
        calls.append(task.index)
        if hook is not None:
            hook(task)
        return real(task, cancel)

    monkeypatch.setattr(sweep_mod, "compute_chunk", counting)
    return calls


def _chunk_files(directory: Path) -> dict[int, Path]:
    return {int(p.name[6:12]): p for p in directory.glob("chunk-*.parquet")}


def test_resume_computes_only_the_missing_chunks(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, reference: pl.SweepResult
) -> None:
    """A deleted chunk file is the only one computed again; a chunk file written but not yet in the
    manifest (interrupted in between) is kept; a finished sweep resumes to nothing; results equal."""
    out = tmp_path / "sw"
    kw: dict[str, Any] = {"t_end": 0.2, "dt": 1e-3, "out": out, "progress": False}
    first = pl.sweep(GRID, ALL, chunk_size=8, **kw)
    _same(reference, first)
    assert sorted(_chunk_files(out)) == list(range(6))
    manifest = json.loads((out / "_manifest.json").read_text())
    assert manifest["complete"] and manifest["chunks_done"] == list(range(6)) and manifest["n_points"] == 48
    (out / "chunk-000002.parquet").unlink()
    manifest["chunks_done"] = [0, 1, 2, 3, 5]  # chunk 4's file exists but the manifest missed it
    manifest["complete"] = False
    (out / "_manifest.json").write_text(json.dumps(manifest))
    calls = _count_chunks(monkeypatch)
    again = pl.sweep(GRID, ALL, resume=True, **kw)  # chunk_size comes from the manifest
    assert calls == [2] and again.stats["skipped"] == 5 and again.stats["computed"] == 1
    _same(reference, again)
    assert pl.sweep(GRID, ALL, resume=True, **kw).stats["computed"] == 0 and calls == [2]
    _same(reference, pl.read_sweep(out))
    table = pq.read_table(out)  # the directory is a Parquet dataset (the manifest is skipped)
    assert table.num_rows == 48 and table.schema.field("period").metadata[b"unit"] == b"s"


def test_ctrl_c_keeps_complete_chunks_only(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, reference: pl.SweepResult
) -> None:
    """SIGINT while chunk 3 runs: KeyboardInterrupt, every chunk file on disk is complete and correct,
    no temporary files, the manifest lists them; --resume then computes exactly the others."""
    out = tmp_path / "sweep.parquet"

    armed = [True]

    def interrupt(task: sweep_mod.ChunkTask) -> None:
        if task.index == 3 and armed[0]:
            os.kill(os.getpid(), signal.SIGINT)
            time.sleep(0.05)

    calls = _count_chunks(monkeypatch, interrupt)
    kw: dict[str, Any] = {"t_end": 0.2, "dt": 1e-3, "out": out, "progress": False}
    with pytest.raises(KeyboardInterrupt):
        pl.sweep(GRID, ALL, chunk_size=4, workers=1, **kw)
    staging = tmp_path / ".sweep.parquet.chunks"
    assert not out.exists() and staging.is_dir()
    assert not [p for p in staging.iterdir() if p.name.startswith(".")]
    files = _chunk_files(staging)
    assert 3 <= len(files) < 12 and set(files) <= set(calls)
    for i, path in files.items():
        table = pq.read_table(path)
        rows = slice(4 * i, 4 * i + 4)
        assert table.num_rows == 4
        for name in ("point", "x", "period", "max_sway"):
            assert np.array_equal(table.column(name).to_numpy(), reference[name][rows], equal_nan=True)
    manifest = json.loads((staging / "_manifest.json").read_text())
    assert sorted(manifest["chunks_done"]) == sorted(files) and not manifest["complete"]
    calls.clear()
    armed[0] = False
    res = pl.sweep(GRID, ALL, resume=True, **kw)
    assert sorted(calls) == sorted(set(range(12)) - set(files))
    assert out.is_file() and not staging.exists()
    _same(reference, res)
    _same(reference, pl.read_sweep(out))


def test_cli_sweep_end_to_end(tmp_path: Path) -> None:
    """pendulab sweep FILE --out X.parquet: plan, per-column ranges, the file; --resume skips all."""
    toml = tmp_path / "tiny.toml"
    toml.write_text(
        'title = "tiny"\nquantity = ["max_sway", "rotation_number"]\n'
        "[grid]\ntheta0 = { start = 0.2, stop = 1.2, num = 5 }\nphi_dot0 = [1.0, 2.0]\n"
        "[pendulum]\nlength = 2.0\n[simulation]\nt_end = 0.5\ndt = 0.001\n[run]\nchunk_size = 4\n"
    )
    out = tmp_path / "tiny.parquet"
    code, stdout, stderr = invoke("sweep", str(toml), "--out", str(out), "--workers", "2", "--no-progress")
    assert code == 0, stderr
    assert "10 points: grid 5 x 2 (theta0, phi_dot0) -> max_sway, rotation_number" in stderr
    assert "3 chunks of 4 points (the last of 2): computed 3, skipped 0" in stdout, stdout
    assert f"wrote {out} (10 rows)" in stdout
    assert "max_sway [rad]: " in stdout and "rotation_number [1]: " in stdout
    direct = pl.sweep(
        {"theta0": np.linspace(0.2, 1.2, 5), "phi_dot0": [1.0, 2.0]},
        ["max_sway", "rotation_number"],
        pendulum=pl.Pendulum(length=2.0),
        t_end=0.5,
        progress=False,
    )
    _same(direct, pl.read_sweep(out))
    code, stdout, _ = invoke("sweep", str(toml), "--out", str(out), "--resume", "--no-progress")
    assert code == 0 and "computed 0, skipped 3" in stdout
    code, out_, err = invoke(
        "sweep", str(toml), "--out", str(tmp_path / "d"), "--workers", "2", "--scheduler", "tcp://x:1"
    )
    assert_user_error(code, out_, err, "--workers and --scheduler")


@pytest.mark.parametrize(
    ("theta0", "chunk", "want"),
    [
        ("[0.5, 1.0]", "", "1 chunk of 2 points: computed 1,"),  # the default chunk size, 50 000
        ("[0.5]", "", "1 chunk of 1 point: computed 1,"),
        ("[0.5, 1.0, 1.5, 2.0]", "chunk_size = 2\n", "2 chunks of 2 points: computed 2,"),
        ("[0.5, 1.0, 1.5]", "chunk_size = 2\n", "2 chunks of 2 points (the last of 1): computed 2,"),
    ],
)
def test_cli_summary_counts_the_chunks_as_they_are(
    tmp_path: Path, theta0: str, chunk: str, want: str
) -> None:
    """The summary line gives the chunks' real number and size (not the default chunk size for a sweep
    of fewer points), the last one's where it is smaller, singular or plural as they are."""
    toml = tmp_path / "few.toml"
    toml.write_text(f'quantity = "period"\n[grid]\ntheta0 = {theta0}\nphi_dot0 = [1.0]\n[run]\n{chunk}')
    code, stdout, stderr = invoke("sweep", str(toml), "--out", str(tmp_path / "o"), "--no-progress")
    assert code == 0, stderr
    assert want in stdout, stdout
