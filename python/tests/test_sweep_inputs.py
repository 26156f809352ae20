"""Sweeps (pendulab.sweep, docs/sweeps.md), what they compute and refuse: the exact quantities equal
pl.exact point by point, grids reshape onto their axes and random designs are reproducible, the
shipped sweep files load, settle_time over damping and start equals simulate_ensemble; bad input,
bad outputs and sizes and bad sweep files are refused up front with an error naming the bad value.
How sweeps are computed (chunks, workers, backends, resume, the CLI) is in test_sweep.py. Times in
seconds, angles in radians, lengths in metres."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from conftest import REPO
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.sweeps import sinks as sweep_io
from pendulab.sweeps.file import SweepFileError, SweepSpecFile, load_sweep_file, sweep_file_from_dict

EXAMPLES = REPO / "examples" / "sweeps"


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
        (  # refused before anything is drawn (was a MemoryError, or the process killed for ~2e9 points)
            lambda: pl.sweep_design.random(2**40, {"theta0": (0, 1)}),
            ["a random design of 1099511627776 points needs about 3.28e+04 GiB of memory", "draw fewer"],
        ),
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
        (  # pl.sweep takes at most 1e9 points: refused as the file is read, before any point is drawn
            'quantity = "period"\n[random]\nn = 2_000_000_000\nranges = {theta0 = [0, 1]}',
            ["random.n = 2000000000: must be less than or equal to 1000000000"],
        ),
        ('quantity = "period"\n[grid\n', ["invalid TOML"]),
        ("# only a comment", ["nothing in it (an empty file, or only comments): a sweep file has quantity"]),
        (  # a typo of the required key is one problem
            'quantitty = "period"\n[grid]\ntheta0 = [1.0]',
            ["unknown key quantitty (did you mean 'quantity'? so the required quantity is missing)"],
        ),
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


def test_a_typo_of_the_required_key_is_said_once() -> None:
    """The misspelt key's line names the missing one, which is not listed again."""
    with pytest.raises(SweepFileError) as e:
        sweep_file_from_dict({"Quantity": "period", "grid": {"theta0": [0.1]}}, "s.toml")
    assert e.value.problems == [
        "unknown key Quantity (did you mean 'quantity'? so the required quantity is missing); "
        f"allowed keys in the top level: {', '.join(SweepSpecFile.model_fields)}"
    ], e.value.problems
