"""simulate_ensemble: every trajectory equals simulate(method="rattle") bit for bit (same step,
same arithmetic), per-trajectory l and g, saving, summaries (J₃ conserved, energy bounded), Ctrl-C
and bad input. Units SI; l = 1 m, g = 9.81 m/s²."""

from __future__ import annotations

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
    with pytest.raises(pl.InvalidInputError, match="ideal"):
        pl.simulate_ensemble(pl.Pendulum(damping=0.1), np.array([[0.0, 0, -1, 0.1, 0, 0]]), t_end=1.0)
