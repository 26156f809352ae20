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


def test_per_trajectory_length_g_damping_bit_for_bit() -> None:
    # lengths, g and damping per trajectory: each trajectory is simulate() of its own pendulum
    p = pl.Pendulum(length=1.0, g=9.81, damping=0.05, drag=0.2, forcing_amplitude=0.4, forcing_omega=2.0)
    n = 19
    lengths = np.where(np.arange(n) % 3 == 0, 0.6, 1.4)
    gs = np.linspace(3.7, 24.8, n)
    cs = np.where(np.arange(n) % 2 == 0, 0.0, 0.3)
    starts = np.vstack(
        [
            pl.states_from_angles(pl.Pendulum(length=lengths[k]), theta=0.2 + 0.14 * k, phi_dot=1.0 - 0.1 * k)
            for k in range(n)
        ]
    )
    res = pl.simulate_ensemble(
        p, starts, t_end=3.0, method="dop853", length=lengths, g=gs, damping=cs, progress=False
    )
    assert res.metadata["distinct_models"] == len(
        {(a, b, c) for a, b, c in zip(lengths, gs, cs, strict=True)}
    )
    for k in range(n):
        q = pl.Pendulum(
            length=lengths[k], g=gs[k], damping=cs[k], drag=0.2, forcing_amplitude=0.4, forcing_omega=2.0
        )
        tr = pl.simulate(
            q, q.state(starts[k, :3], starts[k, 3:]), t_end=3.0, method="dop853", save_at=[0.0, 3.0]
        )
        assert np.array_equal(tr.x, res.x[k]) and np.array_equal(tr.v, res.v[k]), k
    # one value broadcasts; the pendulum's own damping where none is given
    one = pl.simulate_ensemble(p, starts[:4], t_end=1.0, method="dop853", length=lengths[:4], progress=False)
    for k in range(4):
        q = pl.Pendulum(
            length=lengths[k], g=9.81, damping=0.05, drag=0.2, forcing_amplitude=0.4, forcing_omega=2.0
        )
        tr = pl.simulate(
            q, q.state(starts[k, :3], starts[k, 3:]), t_end=1.0, method="dop853", save_at=[0.0, 1.0]
        )
        assert np.array_equal(tr.v, one.v[k]), k


def test_per_trajectory_bad_values_are_named() -> None:
    p = pl.Pendulum()
    starts = pl.states_from_angles(p, theta=[0.3, 1.0, 1.5])
    for kw, word in [
        ({"length": [1.0, 1.0]}, "length"),
        ({"length": [1.0, -1.0, 1.0]}, "length"),
        ({"g": [9.81, float("nan"), 1.0]}, "g"),
        ({"damping": [0.1, -0.2, 0.0]}, "damping"),
        ({"damping": np.zeros((3, 2))}, "damping"),
        ({"length": [1.0, 2.0, 1.0]}, "length|sphere|TS"),  # start 1 is not on the sphere of l = 2 m
    ]:
        with pytest.raises(pl.InvalidInputError, match=word):
            pl.simulate_ensemble(p, starts, t_end=1.0, method="dop853", **kw)
    # a model without damping (the ideal pendulum) refuses it by name
    with pytest.raises(pl.InvalidInputError, match="damping"):
        pl.simulate_ensemble(p, starts, t_end=1.0, method="dop853", damping=[0.1, 0.2, 0.3])
