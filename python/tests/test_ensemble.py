"""simulate_ensemble: every trajectory equals simulate(method="rattle") bit for bit (same step,
same arithmetic), per-trajectory l and g, saving, summaries (J₃ conserved, energy bounded), Ctrl-C
and bad input. Units SI; l = 1 m, g = 9.81 m/s²."""

from __future__ import annotations

import json
import time
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl


def test_matches_single_trajectories(pendulum: pl.Pendulum) -> None:
    theta = np.linspace(0.2, 2.9, 70)
    states = pl.states_from_angles(pendulum, theta=theta, phi_dot=np.linspace(-2, 2, 70))
    assert states.shape == (70, 6)
    res = pl.simulate_ensemble(pendulum, states, t_end=2.0, dt=1e-3, save_every=500)
    assert res.x.shape == (70, 5, 3) and np.array_equal(res.t, [0.0, 0.5, 1.0, 1.5, 2.0])
    for k in (0, 33, 69):
        s0 = pendulum.state(states[k, :3], states[k, 3:])
        tr = pl.simulate(pendulum, s0, t_end=2.0, method="rattle", dt=1e-3, save_every=500)
        assert np.array_equal(tr.x, res.x[k]) and np.array_equal(tr.v, res.v[k])
    assert res.summary is not None
    assert np.max(res.summary["j3_drift"]) < 1e-13
    assert np.max(res.summary["energy_drift"]) < 1e-3  # bounded energy error of RATTLE at dt = 1 ms


def test_crossings_count_turns_over_the_top(pendulum: pl.Pendulum) -> None:
    """Planar swings from the bottom with speed w: below √(2gl) they stay under the pivot's plane (no
    crossing), above it they rise through it, and over the top (w > 2√(gl)) they cross it twice per
    turn; every count equals the one taken from the single-path trajectory saved at every step."""
    speeds = np.array([2.0, 5.0, 7.0, 10.0])
    states = pl.states_from_angles(pendulum, theta=0.0, theta_dot=speeds)
    res = pl.simulate_ensemble(pendulum, states, t_end=5.0, dt=1e-3, save=pl.Save.summary())
    assert res.summary is not None
    crossings = res.summary["crossings"]
    for k, w in enumerate(speeds):
        s0 = pendulum.state(states[k, :3], states[k, 3:])
        z = pl.simulate(pendulum, s0, t_end=5.0, method="rattle", dt=1e-3, save_every=1).x[:, 2]
        assert crossings[k] == np.count_nonzero(np.diff(z > 0.0)), w
    assert crossings[0] == 0 and crossings[1] > 0  # √(2g) ≈ 4.43 m/s: 2 stays below, 5 rises above
    # over the top: the turn rate lies between v_top/(2πl) and w/(2πl)
    for k in (2, 3):
        turns = crossings[k] / 2
        v_top = np.sqrt(speeds[k] ** 2 - 4 * 9.81)
        assert 5.0 * v_top / (2 * np.pi) - 1 <= turns <= 5.0 * speeds[k] / (2 * np.pi) + 1


def test_per_trajectory_parameters(pendulum: pl.Pendulum) -> None:
    lengths = np.array([0.5, 1.0, 2.0])
    states = np.array([[ln * 0.6, 0.0, -ln * 0.8, 0.0, 0.7, 0.0] for ln in lengths])
    res = pl.simulate_ensemble(pendulum, states, t_end=1.0, length=lengths, g=[9.81, 3.7, 24.8])
    for k, (ln, g) in enumerate(zip(lengths, [9.81, 3.7, 24.8], strict=True)):
        p = pl.Pendulum(length=ln, g=g)
        tr = pl.simulate(p, p.state(states[k, :3], states[k, 3:]), t_end=1.0, method="rattle", dt=1e-3)
        assert np.array_equal(tr.x[-1], res.final_x[k])


def test_bad_input(pendulum: pl.Pendulum) -> None:
    with pytest.raises(pl.InvalidInputError, match="shape"):
        pl.simulate_ensemble(pendulum, np.zeros((3, 5)), t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="multiple of dt"):
        pl.simulate_ensemble(pendulum, np.array([[0.0, 0, -1, 0.1, 0, 0]]), t_end=1.00005)
    with pytest.raises(pl.InvalidInputError, match="length"):
        pl.simulate_ensemble(pendulum, np.array([[0.0, 0, -1, 0.1, 0, 0]] * 2), t_end=1.0, length=[1, 2, 3])
    with pytest.raises(pl.InvalidInputError, match="TS"):
        pl.simulate_ensemble(pendulum, np.array([[0.0, 0, -1.5, 0.1, 0, 0]]), t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="linear damping"):
        pl.simulate_ensemble(pl.Pendulum(drag=0.1), np.array([[0.0, 0, -1, 0.1, 0, 0]]), t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="linear damping"):
        pl.simulate_ensemble(
            pl.Pendulum(damping=0.1, gravity_x=1.0), np.array([[0.0, 0, -1, 0.1, 0, 0]]), t_end=1.0
        )
    start = np.array([[0.0, 0, -1, 0.1, 0, 0]])
    for with_force in (
        pl.Pendulum(force=lambda t, x, v: [0.0, 0.0, 0.0]),
        pl.Pendulum(damping=0.1, force=lambda t, x, v: [0.0, 0.0, 0.0]),
    ):
        with pytest.raises(pl.InvalidInputError, match="force callable"):
            pl.simulate_ensemble(with_force, start, t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="damping"):
        pl.simulate_ensemble(pendulum, start, t_end=1.0, damping=-0.5)
    with pytest.raises(pl.InvalidInputError, match="damping"):
        pl.simulate_ensemble(pendulum, start, t_end=1.0, damping=np.nan)
    with pytest.raises(pl.InvalidInputError, match="damping = 'a'"):
        pl.simulate_ensemble(pendulum, start, t_end=1.0, damping="a")
    with pytest.raises(pl.InvalidInputError, match="settle_angle"):
        pl.simulate_ensemble(pendulum, start, t_end=1.0, settle_angle=-0.1)


def test_start_rows_in_any_memory_layout_and_at_the_limits(pendulum: pl.Pendulum) -> None:
    """The start rows are read as views, not copied: a Fortran-ordered array, a strided slice and a list
    of State give the bits of a C-ordered array. The limits are told by one min/max over both halves,
    else per half: a position beyond the velocities' bound (1e7) but within its own (1e9) is no limit
    error (the core then names it off the sphere), a velocity beyond 1e7 m/s is named."""
    states = pl.states_from_angles(pendulum, theta=np.linspace(0.2, 1.2, 5), phi_dot=1.0)
    ref = pl.simulate_ensemble(pendulum, states, t_end=0.2, progress=False)
    wide = np.zeros((5, 12))
    wide[:, ::2] = states
    rows = [pl.State(r[:3], r[3:]) for r in states]
    for layout in (np.asfortranarray(states), wide[:, ::2], rows):
        res = pl.simulate_ensemble(pendulum, layout, t_end=0.2, progress=False)
        assert np.array_equal(res.x, ref.x) and np.array_equal(res.v, ref.v)
    far = states.copy()
    far[2, 0] = 5e7
    with pytest.raises(pl.InvalidInputError, match="TS"):
        pl.simulate_ensemble(pendulum, far, t_end=0.2)
    fast = states.copy()
    fast[2, 4] = -2e7
    with pytest.raises(pl.InvalidInputError, match="states v"):
        pl.simulate_ensemble(pendulum, fast, t_end=0.2)


def test_damped_ensemble_matches_the_damped_model() -> None:
    """Per-trajectory damping c [1/s]: each trajectory equals simulate() of the ``damped`` model."""
    p = pl.Pendulum(length=1.0, g=9.81, damping=0.3)
    states = pl.states_from_angles(p, theta=[0.3, 1.0, 2.0], phi_dot=[0.5, -1.0, 0.0])
    cs = np.array([0.3, 0.0, 1.5])
    res = pl.simulate_ensemble(p, states, t_end=3.0, damping=cs, save_every=1000)
    for k, c in enumerate(cs):
        pk = pl.Pendulum(length=1.0, g=9.81, damping=c)
        tr = pl.simulate(
            pk, pk.state(states[k, :3], states[k, 3:]), t_end=3.0, method="rattle", dt=1e-3, save_every=1000
        )
        assert np.array_equal(tr.x, res.x[k]) and np.array_equal(tr.v, res.v[k])
    # the model's own damping is the default
    res2 = pl.simulate_ensemble(p, states, t_end=3.0)
    tr0 = pl.simulate(p, p.state(states[0, :3], states[0, 3:]), t_end=3.0, method="rattle", dt=1e-3)
    assert np.array_equal(res2.final_x[0], tr0.x[-1])


def test_settle_time_follows_the_exponential_envelope() -> None:
    """A small swing of the linearly damped pendulum, θ = A e^{−γt} cos(ω_d t − ψ) with γ = c/2 and
    A = θ₀ (1 + γ²/ω_d²)^{1/2}, stays inside its envelope: the settle time to θ_s is at most
    ln(A/θ_s)/γ and at least half a period less (the last exceedance is at a peak)."""
    g, c, theta_s = 9.81, 0.4, 0.002
    p = pl.Pendulum(length=1.0, g=g, damping=c)
    theta0 = np.array([0.02, 0.01, 0.005, 0.001])
    res = pl.simulate_ensemble(
        p, pl.states_from_angles(p, theta=theta0), t_end=30.0, settle_angle=theta_s, summary=True
    )
    assert res.settle_time is not None and res.summary is not None
    gamma = c / 2
    omega_d = np.sqrt(g - gamma**2)
    envelope = np.log(theta0[:3] * np.sqrt(1 + (gamma / omega_d) ** 2) / theta_s) / gamma
    half_period = np.pi / omega_d
    ts = res.settle_time[:3]
    # resolution one step (1 ms) plus the O(θ₀²) nonlinear correction
    assert np.all(ts <= envelope + 2e-3) and np.all(ts >= envelope - half_period), (ts, envelope)
    assert res.settle_time[3] == 0.0
    assert np.allclose(res.summary["max_sway"], theta0, rtol=1e-6)
    # undamped: outside the band at the end, never settles
    ideal = pl.Pendulum(length=1.0, g=g)
    res = pl.simulate_ensemble(
        ideal, pl.states_from_angles(ideal, theta=[0.02]), t_end=2.0, settle_angle=theta_s
    )
    assert res.settle_time is not None and np.isinf(res.settle_time[0])


def test_non_finite_rows_are_reported_per_row(pendulum: pl.Pendulum) -> None:
    """A NaN or inf start row does not stop the run: its results are NaN, the others are exact."""
    states = pl.states_from_angles(pendulum, theta=[0.3, 0.5, 0.7, 0.9])
    bad = states.copy()
    bad[1, 4] = np.nan
    bad[3, 0] = np.inf
    with pytest.warns(RuntimeWarning, match=r"2 of 4 start rows are not finite \(rows 1, 3\)") as said:
        res = pl.simulate_ensemble(pendulum, bad, t_end=0.5, settle_angle=0.1, damping=[0.1, 0.2, 0.3, 0.4])
    assert [w.filename for w in said] == [__file__]  # the caller's line
    ref = pl.simulate_ensemble(pendulum, states[[0, 2]], t_end=0.5, settle_angle=0.1, damping=[0.1, 0.3])
    assert list(res.invalid_rows) == [1, 3] and res.x.shape == (4, 2, 3)
    assert np.isnan(res.x[[1, 3]]).all() and np.array_equal(res.x[[0, 2]], ref.x)
    assert res.summary is not None and ref.summary is not None and res.settle_time is not None
    assert np.array_equal(res.summary["max_sway"][[0, 2]], ref.summary["max_sway"])
    assert np.isnan(res.settle_time[1]) and np.isnan(res.summary["energy_drift"][3])
    with pytest.raises(pl.InvalidInputError, match="every start row is non-finite"):
        pl.simulate_ensemble(pendulum, np.full((2, 6), np.nan), t_end=0.5)


def test_save_rules_combine(pendulum: pl.Pendulum) -> None:
    """pl.Save.final() | pl.Save.every(n) | pl.Save.summary() is the same run as the keywords."""
    states = pl.states_from_angles(pendulum, theta=[0.4, 1.2])
    res = pl.simulate_ensemble(
        pendulum, states, t_end=1.0, save=pl.Save.final() | pl.Save.every(250) | pl.Save.summary()
    )
    ref = pl.simulate_ensemble(pendulum, states, t_end=1.0, save_every=250, summary=True)
    assert res.x.shape == (2, 5, 3) and np.array_equal(res.x, ref.x) and res.summary is not None
    only = pl.simulate_ensemble(pendulum, states, t_end=1.0, save=pl.Save.final())
    assert only.x.shape == (2, 2, 3) and only.summary is None
    assert repr(pl.Save.every(3) | pl.Save.summary()) == "Save.final() | Save.every(3) | Save.summary()"
    with pytest.raises(pl.InvalidInputError, match="give one interval"):
        pl.Save.every(2) | pl.Save.every(3)
    with pytest.raises(pl.InvalidInputError, match=r"Save.every\(0\)"):
        pl.Save.every(0)
    with pytest.raises(pl.InvalidInputError, match="method = 'rk4'"):
        pl.simulate_ensemble(pendulum, states, t_end=1.0, method="rk4")
    with pytest.raises(pl.InvalidInputError, match="not both"):
        pl.simulate_ensemble(pendulum, states, t_end=1.0, save=pl.Save.final(), save_every=10)


@pytest.mark.parametrize("suffix", [".nc", ".zarr"])
def test_arrays_to_xarray_netcdf_and_zarr(pendulum: pl.Pendulum, tmp_path: Path, suffix: str) -> None:
    """save() writes x, v, the summary and settle times with units; reading back gives the same numbers."""
    xr = pytest.importorskip("xarray")
    states = pl.states_from_angles(pendulum, theta=[0.3, 0.6, 0.9])
    states[1, 0] = np.nan
    with pytest.warns(RuntimeWarning, match="not finite"):
        res = pl.simulate_ensemble(
            pendulum,
            states,
            t_end=1.0,
            damping=0.5,
            settle_angle=0.2,
            save=pl.Save.every(100) | pl.Save.summary(),
        )
    ds = res.to_xarray()
    assert ds["x"].dims == ("trajectory", "time", "axis") and ds["x"].attrs["units"] == "m"
    assert ds["settle_time"].attrs["units"] == "s" and list(ds["valid"].values) == [True, False, True]
    path = res.save(tmp_path / f"ens{suffix}")
    back = xr.open_zarr(path) if suffix == ".zarr" else xr.open_dataset(path)
    try:
        np.testing.assert_array_equal(back["x"].values, res.x)
        np.testing.assert_array_equal(back["time"].values, res.t)
        assert res.summary is not None and res.settle_time is not None
        np.testing.assert_array_equal(back["max_sway"].values, res.summary["max_sway"])
        np.testing.assert_array_equal(back["settle_time"].values, res.settle_time)
        assert back["v"].attrs["units"] == "m/s"
        assert json.loads(back.attrs["pendulab"])["settle_angle"] == 0.2
    finally:
        back.close()
    res.save(path)  # overwriting a store of ours works
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"ens{suffix}"]  # no temporary left behind
    with pytest.raises(ValueError, match=r"use \.nc or \.zarr"):
        res.save(tmp_path / "ens.csv")


def test_wait_returns_when_the_run_ends_not_at_a_poll(pendulum: pl.Pendulum) -> None:
    """EnsembleRun.wait(timeout) returns True the moment the run has finished (far sooner than a long
    timeout), False while it runs; a cancelled run is seen at once too; bad timeouts are named."""
    from pendulab._core import EnsembleRun, EnsembleSpec, RunOptions

    states = pl.states_from_angles(pendulum, theta=np.linspace(0.2, 2.9, 64), phi_dot=1.0)
    x, v = np.ascontiguousarray(states[:, :3]), np.ascontiguousarray(states[:, 3:])
    one, g = np.array([1.0]), np.array([9.81])
    spec, options = EnsembleSpec(one, g), RunOptions(dt=1e-3)
    small = EnsembleRun(spec, x, v, options, 100)
    t0 = time.perf_counter()
    assert small.wait(60.0)
    assert time.perf_counter() - t0 < 30.0  # returned on completion, not after the 60 s timeout
    assert small.done and small.wait(0.0)
    assert small.result()["steps"] == 100
    big = EnsembleRun(spec, x, v, options, 10**9)  # would take minutes
    assert not big.wait(0.0) and not big.done
    big.cancel()
    t0 = time.perf_counter()
    assert big.wait(60.0)
    assert time.perf_counter() - t0 < 30.0
    assert big.result()["cancelled"]
    for bad in (-1.0, float("nan"), float("inf")):
        with pytest.raises(pl.InvalidInputError, match="timeout"):
            small.wait(bad)
