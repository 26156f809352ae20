"""Sweeps (pendulab.sweep, docs/sweeps.md): the numbers equal the direct calls (pl.exact,
simulate_ensemble) whatever the chunking, workers and backend (a real dask.distributed LocalCluster);
chunks on disk are complete or absent, resume computes only what is missing; the CLI and the sweep
files; bad input is refused up front with an error naming the bad value."""

from __future__ import annotations

import json
import logging
import math
import os
import signal
import time
from pathlib import Path
from typing import Any

import numpy as np
import pyarrow.parquet as pq
import pytest
from conftest import REPO
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.sweeps import backends as sweep_backends
from pendulab.sweeps import run as sweep_mod
from pendulab.sweeps import sinks as sweep_io
from pendulab.sweeps.file import SweepFileError, load_sweep_file, sweep_file_from_dict

EXAMPLES = REPO / "examples" / "sweeps"
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


def test_exact_quantities_equal_pl_exact() -> None:
    """rotation_number and period equal pl.exact's at every point, for any l, g (g < 0 too), with NaN
    exactly where the exact solution has none (J3 = 0: planar swings, rest); conical starts included."""
    p = pl.Pendulum()
    th = np.array([0.3, 1.2, 1.0, 0.0, 2.0, 0.7, 2.5, 1.1])
    pd = np.array(
        [math.sqrt(9.81 / math.cos(0.3)), math.sqrt(9.81 / math.cos(1.2)), 2.0, 1.0, 0.0, -1.5, 0.4, 5.0]
    )
    length = np.array([1.0, 1.0, 0.5, 1.0, 2.0, 3.0, 1.5, 0.25])
    g = np.array([9.81, 9.81, -9.81, 9.81, 1.6, 24.8, 9.81, -3.0])
    thd = np.array([0.0, 0.0, 0.25, 0.25, 0.0, 0.25, -0.5, 0.25])
    design = pl.sweep_design.points(
        {"theta0": th, "theta_dot0": thd, "phi_dot0": pd, "length": length, "g": g}
    )
    res = pl.sweep(design, ["rotation_number", "period"], pendulum=p, fixed={"phi0": 0.5}, progress=False)
    kinds = []
    for i in range(len(th)):
        q = pl.Pendulum(length=length[i], g=g[i])
        sol = pl.exact(q, q.state_from_angles(th[i], 0.5, thd[i], pd[i]))
        w, tz = sol.rotation_number, sol.period_z
        if w is None:
            assert np.isnan(res["rotation_number"][i]), (i, sol.kind)
        else:
            assert res["rotation_number"][i] == pytest.approx(w, rel=1e-13, abs=1e-15), (i, sol.kind)
        if tz is None:
            assert np.isnan(res["period"][i]), (i, sol.kind)
        else:
            assert res["period"][i] == tz, (i, sol.kind)  # the same core call: bit for bit
        kinds.append(sol.kind)
    assert {"conical", "generic", "planar"} <= set(kinds), kinds
    planar = pl.sweep({"theta0": [0.5, 1.0], "phi_dot0": [0.0]}, "rotation_number", progress=False)
    assert np.isnan(planar["rotation_number"]).all()


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


def test_grid_to_xarray_and_random_designs() -> None:
    """A grid result reshapes onto its axes (C order); random designs are reproducible from the seed,
    inside their ranges, and a Latin hypercube puts one point in each 1/n slice of every range."""
    res = pl.sweep({"theta0": [0.5, 1.0, 1.5], "phi_dot0": [1.0, 2.0]}, "period", progress=False)
    ds = res.to_xarray()
    assert ds["period"].dims == ("theta0", "phi_dot0") and ds["period"].attrs["units"] == "s"
    assert ds["period"].values[2, 1] == res["period"][5]
    assert ds["theta0"].values.tolist() == [0.5, 1.0, 1.5]
    a = pl.sweep_design.random(50, {"theta0": (0.1, 1.0), "g": (1.0, 20.0)}, seed=7, method="lhs")
    b = pl.sweep_design.random(50, {"theta0": (0.1, 1.0), "g": (1.0, 20.0)}, seed=7, method="lhs")
    c = pl.sweep_design.random(50, {"theta0": (0.1, 1.0), "g": (1.0, 20.0)}, seed=8, method="lhs")
    assert a.fingerprint() == b.fingerprint() != c.fingerprint()
    cols = a.columns()
    assert cols["theta0"].min() >= 0.1 and cols["theta0"].max() <= 1.0
    assert sorted(np.floor((cols["g"] - 1.0) / 19.0 * 50).astype(int).tolist()) == list(range(50))
    ds = pl.sweep(a, "rotation_number", progress=False).to_xarray()
    assert ds["rotation_number"].dims == ("point",) and np.array_equal(ds["g"].values, cols["g"])


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
    assert "3 chunks of 4 points: computed 3, skipped 0" in stdout and f"wrote {out} (10 rows)" in stdout
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


def test_example_sweep_files() -> None:
    """The shipped examples load; the rotation-number map is 100 x 100 over theta0 x phi_dot0 and runs."""
    rn = load_sweep_file(EXAMPLES / "rotation_number.toml")
    assert rn.design.kind == "grid" and rn.design.shape == (100, 100)
    assert rn.design.names == ("theta0", "phi_dot0") and rn.spec.quantity == "rotation_number"
    res = pl.sweep(rn.design, progress=False, **rn.sweep_kwargs())
    w = res["rotation_number"]
    assert np.isfinite(w).all() and np.abs(w).min() > 0.5 and np.abs(w).max() < 1.0  # Puiseux: 1/2 < |W| < 1
    sway = load_sweep_file(EXAMPLES / "sway.toml")
    assert sway.design.names == ("theta0", "length") and sway.sweep_kwargs()["t_end"] == 20.0
    settle = load_sweep_file(EXAMPLES / "crane_settle.toml")
    assert settle.design.names == ("theta0", "damping") and settle.sweep_kwargs()["settle_angle"] == 0.01745


def test_settle_time_over_damping_and_start() -> None:
    """settle_time over a damping x theta0 grid equals simulate_ensemble with per-trajectory damping
    and a settle angle, point by point; more damping settles sooner, a bigger swing later."""
    grid = {"damping": [0.2, 0.5, 1.0], "theta0": [0.05, 0.2, 0.6]}
    res = pl.sweep(grid, "settle_time", t_end=40.0, dt=1e-3, settle_angle=0.02, chunk_size=4)
    c, th = (a.ravel() for a in np.meshgrid(grid["damping"], grid["theta0"], indexing="ij"))
    p = pl.Pendulum()
    ens = pl.simulate_ensemble(
        p, pl.states_from_angles(p, theta=th), 40.0, damping=c, settle_angle=0.02, summary=False
    )
    assert ens.settle_time is not None
    assert np.array_equal(res["settle_time"], ens.settle_time)
    ts = res["settle_time"].reshape(3, 3)
    assert np.isfinite(ts).all() and np.all(np.diff(ts, axis=0) < 0) and np.all(np.diff(ts, axis=1) > 0), ts
    assert res.units["settle_time"] == "s"


@pytest.mark.parametrize(
    ("call", "needles"),
    [
        (lambda: pl.sweep({"theta": [1.0]}, "period"), ["unknown axis 'theta'", "did you mean 'theta0'"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "periods"), ["unknown quantity 'periods'", "'period'"]),
        (lambda: pl.sweep({"theta0": []}, "period"), ["axis 'theta0' is empty"]),
        (lambda: pl.sweep({}, "period"), ["at least one axis"]),
        (lambda: pl.sweep({"theta0": [1.0]}, []), ["at least one quantity"]),
        (lambda: pl.sweep({"theta0": [[1.0, 2.0]]}, "period"), ["1-D array", "(1, 2)"]),
        (lambda: pl.sweep({"length": [1.0, -2.0]}, "period"), ["'length' values[1] = -2.0", "[1e-6, 1e4] m"]),
        (lambda: pl.sweep({"theta0": [1.0, np.nan]}, "period"), ["'theta0' values[1] = nan", "rad"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "max_sway"), ["max_sway integrates: give t_end"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "max_sway", t_end=1.0, dt=0.3), ["multiple of dt = 0.3"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "period", fixed={"theta0": 1.0}), ["both an axis"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "period", fixed={"length": 1.0}), ["on the pendulum"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "period", chunk_size=0), ["chunk_size = 0"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "period", backend="mpi"), ["backend = 'mpi'"]),
        (lambda: pl.sweep({"theta0": [1.0]}, "period", resume=True), ["resume=True needs out"]),
        (
            lambda: pl.sweep({"theta0": [1.0]}, "period", pendulum=pl.Pendulum(damping=0.1)),
            ["period come from the exact solution of the undamped pendulum"],
        ),
        (
            lambda: pl.sweep({"theta0": [1.0]}, "max_sway", t_end=1.0, pendulum=pl.Pendulum(drag=0.1)),
            ["optionally with linear damping", "drag=0.1"],
        ),
        (lambda: pl.sweep({"damping": [0.1]}, "rotation_number"), ["undamped"]),
        (
            lambda: pl.sweep({"damping": [0.1, -1.0]}, "max_sway", t_end=1.0),
            ["'damping' values[1] = -1.0", "[0, 1e4]"],
        ),
        (lambda: pl.sweep({"theta0": [1.0]}, "settle_time", t_end=1.0), ["needs settle_angle"]),
        (
            lambda: pl.sweep({"theta0": [1.0]}, "settle_time", t_end=1.0, settle_angle=4.0),
            ["settle_angle = 4.0", "(0, π)"],
        ),
        (lambda: pl.sweep([1.0, 2.0], "period"), ["got list"]),
        (lambda: pl.sweep_design.random(0, {"theta0": (0, 1)}), ["n = 0"]),
        (lambda: pl.sweep_design.random(5, {"theta0": (1, 0)}), ["lo = 1.0 must be <= hi = 0.0"]),
        (lambda: pl.sweep_design.points({"theta0": [1, 2], "g": [1.0]}), ["equal lengths"]),
    ],
)
def test_bad_input_is_refused(call: Any, needles: list[str]) -> None:
    with pytest.raises(pl.InvalidInputError) as e:
        call()
    for needle in needles:
        assert needle in str(e.value), (needle, str(e.value))


def test_bad_outputs_and_sizes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Outputs that hold something else, a resume of different settings, and results larger than the
    memory or the free disk are refused before any work, with the estimate."""
    grid = {"theta0": [0.5, 1.0]}
    pl.sweep(grid, "period", out=tmp_path / "a", progress=False)
    with pytest.raises(pl.InvalidInputError, match=r"already holds a sweep .*resume=True"):
        pl.sweep(grid, "period", out=tmp_path / "a")
    with pytest.raises(pl.InvalidInputError, match=r"different sweep: quantities \(\['period'\] there"):
        pl.sweep(grid, "rotation_number", out=tmp_path / "a", resume=True)
    (tmp_path / "junk").mkdir()
    (tmp_path / "junk" / "notes.txt").write_text("x")
    with pytest.raises(pl.InvalidInputError, match="not empty and holds no sweep"):
        pl.sweep(grid, "period", out=tmp_path / "junk")
    with pytest.raises(pl.InvalidInputError, match=r"directory or a file ending in \.parquet"):
        pl.sweep(grid, "period", out=tmp_path / "x.csv")
    big = {"theta0": np.linspace(0.1, 1, 1000), "phi_dot0": np.linspace(-1, 1, 1000)}
    monkeypatch.setattr(sweep_io, "_physical_memory", lambda: 2**20)
    with pytest.raises(pl.InvalidInputError, match=r"need 30\.5 MiB in memory \(1000000 points x 4 columns"):
        pl.sweep(big, "period")
    monkeypatch.setattr(sweep_io.shutil, "disk_usage", lambda _: type("U", (), {"free": 1000})())
    with pytest.raises(
        pl.InvalidInputError, match=r"need about 30\.5 MiB on disk .* more than the 0\.000954 MiB"
    ):
        pl.sweep(big, "period", out=tmp_path / "b")
    assert not (tmp_path / "b").exists()


@pytest.mark.parametrize(
    ("text", "needles"),
    [
        ('quantity = "period"', ["exactly one of the tables [grid] and [random]"]),
        ('quantity = "period"\ncolor = 1\n[grid]\ntheta0 = [1.0]', ["unknown key color", "allowed keys"]),
        ('quantity = "max_sway"\n[grid]\ntheta0 = [1.0]', ["add [simulation] t_end"]),
        (
            'quantity = "period"\n[grid]\ntheta0 = {start = 0, stop = 1}',
            ["[grid] theta0 = {start = 0, stop = 1}"],
        ),
        ('quantity = "period"\n[grid]\ntheta0 = 1.0', ["goes in [fixed]"]),
        ('quantity = "period"\n[grid]\nthet0 = [1.0]', ["[grid] unknown axis 'thet0'"]),
        ('quantity = "period"\n[pendulum]\nlength = -1\n[grid]\ntheta0 = [1.0]', ["pendulum.length = -1"]),
        ('quantity = "period"\n[random]\nn = 3\nranges = {g = [2, 1]}', ["[random] range of 'g'"]),
        ('quantity = "period"\n[grid\n', ["invalid TOML"]),
    ],
)
def test_bad_sweep_files(tmp_path: Path, text: str, needles: list[str]) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(text + "\n")
    with pytest.raises(SweepFileError) as e:
        load_sweep_file(path)
    assert str(e.value).startswith(str(path))
    for needle in needles:
        assert needle in str(e.value), (needle, str(e.value))
    code, out, err = invoke("sweep", str(path), "--out", str(tmp_path / "o"))
    assert_user_error(code, out, err, needles[0])
    with pytest.raises(SweepFileError):
        sweep_file_from_dict({"quantity": "period"})
