"""Fitting the swinging spring (T-7.4; pendulab/fitting/spring_model.py): stiffness k [N/m], rest length
l₀ [m] and g [m/s²] come back from its positions — to the model's own accuracy without noise, within
their error bars with noise — and the fitted scenario runs with `pendulab run`."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from typer.testing import CliRunner

import pendulab as pl
from pendulab.cli import app

SPRING = pl.SwingingSpring.resonant(1.0)  # k/m = 4g/l, l₀ = 0.75 m: the 1:1:2 resonance
X0, V0 = np.array([0.15, 0.05, -1.02]), np.array([0.0, 0.2, 0.0])  # m, m/s: off the sphere l = 1 m


def _positions(t_end: float, rate: float) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and positions [m] of the truth, by the triple jump at 1/50 of the sample spacing."""
    every = 50
    tr = pl.simulate_spring(SPRING, X0, V0, t_end, dt=1.0 / rate / every, save_every=every, order=4)
    return tr.t, tr.x


def test_noise_free_spring_positions_give_k_l0_and_g_back() -> None:
    t, x = _positions(6.0, 30.0)
    guess = pl.SwingingSpring(30.0, 0.8, 9.81, 1.0)
    res = pl.fit(t, positions=x, pendulum=guess, fit="stiffness,length,g")
    assert res.model == "spring" and isinstance(res.pendulum, pl.SwingingSpring)
    # the truth itself is a triple-jump run: both sides agree to ~1e-8 of l
    assert res.params["stiffness"] == pytest.approx(SPRING.k_over_m * SPRING.mass, rel=1e-6)
    assert res.params["length"] == pytest.approx(SPRING.rest_length, rel=1e-6)
    assert res.params["g"] == pytest.approx(SPRING.g, rel=1e-6)
    np.testing.assert_allclose(res.state0.x, X0, atol=1e-6)
    np.testing.assert_allclose(res.state0.v, V0, atol=1e-5)


def test_noisy_spring_within_error_bars_and_the_fitted_scenario_runs(tmp_path: Path) -> None:
    t, x = _positions(10.0, 50.0)
    noisy = x + 1e-3 * np.random.default_rng(0).standard_normal(x.shape)
    res = pl.fit(
        t,
        positions=noisy,
        pendulum=pl.SwingingSpring(30.0, 0.8, 9.81, 1.0),
        fit="stiffness,length,g",
        sigma=1e-3,
    )
    truth = {"stiffness": SPRING.k_over_m * SPRING.mass, "length": SPRING.rest_length, "g": SPRING.g}
    for name, value in truth.items():
        assert abs(res.params[name] - value) < 3.0 * res.stderr[name], name
    assert 0.8 < res.reduced_chi2 < 1.2
    energy = res.trajectory.energy
    assert np.ptp(energy) < 1e-6 * np.max(np.abs(energy))  # the fitted motion conserves E
    path = res.save(tmp_path / "spring.toml")
    out = tmp_path / "run.csv"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert out.exists()


def test_mass_and_stiffness_are_not_both_determined() -> None:
    """Only k/m enters the motion: fitting both leaves them undetermined, with k/m reported instead."""
    t, x = _positions(4.0, 30.0)
    res = pl.fit(t, positions=x, pendulum=pl.SwingingSpring(39.0, 0.75, 9.81, 1.0), fit="stiffness,mass")
    assert not res.determined["mass"] and not res.determined["stiffness"]
    assert res.combinations


@pytest.mark.parametrize(
    ("spring", "named"),
    [
        (pl.SwingingSpring(float("nan"), 0.75, 9.81, 1.0), "stiffness"),
        (pl.SwingingSpring(-1.0, 0.75, 9.81, 1.0), "stiffness"),
        (pl.SwingingSpring(1e308, 0.75, 9.81, 1.0), "stiffness"),
        (pl.SwingingSpring(39.0, 0.0, 9.81, 1.0), "length"),
        (pl.SwingingSpring(39.0, 0.75, math.inf, 1.0), "g"),
        (pl.SwingingSpring(39.0, 0.75, 9.81, 0.0), "mass"),
    ],
)
def test_a_bad_spring_is_a_clear_error_naming_the_value(spring: pl.SwingingSpring, named: str) -> None:
    t, x = _positions(1.0, 30.0)
    with pytest.raises(pl.InvalidInputError, match=f"spring's {named} = "):
        pl.fit(t, positions=x, pendulum=spring, fit="stiffness,length")
