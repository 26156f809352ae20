"""simulate_ensemble(method="dop853"): a damped, dragged, driven pendulum's ensemble equals
simulate(method="dop853", save_at=[0, t_end]) trajectory by trajectory, bit for bit (the same core
solver per trajectory); a moving pivot too; the keywords of the RATTLE kernel and unsuitable models
are refused with clear errors. Units SI."""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl


def _driven() -> pl.Pendulum:
    return pl.Pendulum(length=0.8, g=9.81, damping=0.05, drag=0.3, forcing_amplitude=0.8, forcing_omega=3.1)


def test_matches_single_dop853_runs_bit_for_bit() -> None:
    p = _driven()
    states = pl.states_from_angles(p, theta=np.linspace(0.2, 2.8, 23), phi_dot=np.linspace(-1.5, 1.5, 23))
    res = pl.simulate_ensemble(p, states, t_end=4.0, method="dop853", rtol=1e-9, atol=1e-11, progress=False)
    assert res.x.shape == (23, 2, 3) and np.array_equal(res.t, [0.0, 4.0]) and res.summary is None
    assert not res.interrupted and res.metadata["method"] == "dop853"
    for k in range(23):
        s0 = p.state(states[k, :3], states[k, 3:])
        tr = pl.simulate(p, s0, t_end=4.0, method="dop853", rtol=1e-9, atol=1e-11, save_at=[0.0, 4.0])
        assert np.array_equal(tr.x, res.x[k]) and np.array_equal(tr.v, res.v[k]), k
    # drag and forcing act: the final states are not those of the ideal pendulum
    ideal = pl.simulate_ensemble(pl.Pendulum(length=0.8, g=9.81), states, t_end=4.0, method="dop853")
    assert np.max(np.abs(ideal.final_x - res.final_x)) > 1e-2


def test_moving_pivot_and_conserve() -> None:
    p = pl.Pendulum(model="vibrating", length=1.0, g=9.81, amplitude=0.02, frequency=30.0)
    states = pl.states_from_angles(p, theta=[0.3, 2.5, 3.0])
    res = pl.simulate_ensemble(p, states, t_end=1.0, method="dop853", progress=False)
    tr = pl.simulate(p, p.state(states[2, :3], states[2, 3:]), t_end=1.0, method="dop853", save_at=[0.0, 1.0])
    assert np.array_equal(tr.x, res.x[2])
    q = pl.Pendulum()
    s = pl.states_from_angles(q, theta=[1.0], phi_dot=[2.0])
    res = pl.simulate_ensemble(q, s, t_end=2.0, method="dop853", conserve=True, progress=False)
    tr = pl.simulate(
        q, q.state(s[0, :3], s[0, 3:]), t_end=2.0, method="dop853", conserve=True, save_at=[0.0, 2.0]
    )
    assert np.array_equal(tr.v, res.v[0])


def test_bad_input_is_named() -> None:
    p = _driven()
    states = pl.states_from_angles(p, theta=[0.3, 1.0])
    for kw, word in [
        ({"length": [1.0, 2.0]}, "length"),
        ({"summary": True}, "summary"),
        ({"save_every": 10}, "save_every"),
        ({"rtol": float("nan")}, "rtol"),
        ({"rtol": -1.0}, "rtol"),
    ]:
        with pytest.raises(pl.InvalidInputError, match=word):
            pl.simulate_ensemble(p, states, t_end=1.0, method="dop853", **kw)
    with pytest.raises(pl.InvalidInputError, match="rattle"):
        pl.simulate_ensemble(p, states, t_end=1.0, method="rk4")
    with pytest.raises(pl.InvalidInputError, match="finite"):
        pl.simulate_ensemble(p, np.full((2, 6), np.nan), t_end=1.0, method="dop853")
    forced = pl.Pendulum(force=lambda t, x, v: -0.1 * v)
    with pytest.raises(pl.InvalidInputError, match="callable"):
        pl.simulate_ensemble(forced, pl.states_from_angles(forced, theta=[0.3]), t_end=1.0, method="dop853")
