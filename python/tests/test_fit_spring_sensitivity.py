"""The swinging spring's exact Jacobian (docs/theory.md T-10.8; fitting/spring_model.py
``motion_tangents``, fitting/sensitivity.py): the motion it carries is :func:`spring_model.motion`'s to
the bit; its tangents by the start (θ₀, φ₀, θ̇₀, φ̇₀, r₀, ṙ₀) and by stiffness, mass, rest length and g
agree with central differences of plain runs (no tangent code on that side); the forward model's
states, kept around the samples only, are the full run's; the fit's Jacobian agrees
with central differences of the residuals for positions and an accelerometer, t_offset and a pivot
offset included, for one model run; bad input to the core is named. SI units: the 1:1:2 resonance at
an equilibrium length of 1 m (k/m = 39.24 1/s², l₀ = 0.75 m), g = 9.81 m/s², m = 1 kg."""

from __future__ import annotations

import math

import numpy as np
import pytest

import pendulab as pl
from pendulab import _core
from pendulab.fitting import spring_model
from pendulab.fitting.data import observations
from pendulab.fitting.identify import jacobian
from pendulab.fitting.problem import Problem
from pendulab.fitting.sensitivity import exact_jacobian

VALUES = {
    "theta0": 0.4, "phi0": 0.3, "theta_dot0": 0.2, "phi_dot0": 0.8, "r0": 1.05, "r_dot0": 0.1,
    "stiffness": 39.24, "mass": 1.0, "length": 0.75, "g": 9.81,
}  # fmt: skip
TAU = np.linspace(0.0, 12.0, 601)  # s: about six swings and twelve bounces


def _step(value: float) -> float:
    return 1e-6 * max(abs(value), 1e-3)


def test_the_motion_is_the_plain_motion_to_the_bit() -> None:
    x, v = spring_model.motion(VALUES, TAU)
    x2, v2, dx, dv = spring_model.motion_tangents(VALUES, TAU)
    assert np.array_equal(x, x2) and np.array_equal(v, v2)
    assert dx.shape == dv.shape == (TAU.size, 3, len(spring_model.TANGENT_NAMES))


def test_the_forward_models_states_are_the_full_runs_at_the_steps_it_keeps() -> None:
    """``spring_states_at`` keeps only the steps around the samples; those states are the full run's
    (``spring_simulate``, every step kept) to the bit, and a step list out of order is refused."""
    spec = _core.ModelSpec.spring_model(39.24, 0.75, 9.81, 1.0)
    state = spring_model.start_vectors(VALUES)
    full = _core.spring_simulate(spec, state, _core.RunOptions(dt=1e-3, save_every=1, order=4), 3000)
    keep = np.array([0, 0, 1, 17, 18, 2999, 3000], dtype=np.uint64)
    x, v = _core.spring_states_at(spec, state, keep, _core.RunOptions(dt=1e-3, order=4))
    assert np.array_equal(x, full["x"][keep.astype(np.int64)]) and np.array_equal(
        v, full["v"][keep.astype(np.int64)]
    )
    with pytest.raises(pl.InvalidInputError, match="ascending"):
        _core.spring_states_at(
            spec, state, np.array([3, 2], dtype=np.uint64), _core.RunOptions(dt=1e-3, order=4)
        )


def test_the_start_tangents_are_the_derivatives_of_the_start() -> None:
    dx, dv = spring_model.start_tangents(VALUES)
    for k, name in enumerate(spring_model.START_DIRECTIONS):
        h = 1e-6
        up, down = dict(VALUES), dict(VALUES)
        up[name], down[name] = VALUES[name] + h, VALUES[name] - h
        (xu, vu), (xd, vd) = spring_model.start_vectors(up), spring_model.start_vectors(down)
        np.testing.assert_allclose(dx[k], (xu - xd) / (2 * h), atol=1e-9, err_msg=name)
        np.testing.assert_allclose(dv[k], (vu - vd) / (2 * h), atol=1e-9, err_msg=name)


@pytest.mark.parametrize("name", spring_model.TANGENT_NAMES)
def test_every_tangent_is_the_derivative_of_plain_runs(name: str) -> None:
    _, _, dx, dv = spring_model.motion_tangents(VALUES, TAU)
    k = spring_model.TANGENT_NAMES.index(name)
    h = _step(VALUES[name])
    up, down = dict(VALUES), dict(VALUES)
    up[name], down[name] = VALUES[name] + h, VALUES[name] - h
    (xu, vu), (xd, vd) = spring_model.motion(up, TAU), spring_model.motion(down, TAU)
    fx, fv = (xu - xd) / (2 * h), (vu - vd) / (2 * h)
    scale = max(float(np.abs(fx).max()), float(np.abs(fv).max()))
    # differences' own error: ~1e-16/h of the motion (h = 1e-6 of the value) and O(h²)
    assert float(np.abs(dx[:, :, k] - fx).max()) < 3e-6 * scale, name
    assert float(np.abs(dv[:, :, k] - fv).max()) < 3e-6 * scale, name
    # another direction's tangent is far off: the comparison can fail
    other = (k + 1) % dx.shape[2]
    assert float(np.abs(dx[:, :, other] - fx).max()) > 1e-2 * scale


def _spring_problem(kinds: list[str], free: list[str]) -> Problem:
    truth = pl.SwingingSpring.resonant(1.0)
    x0, v0 = spring_model.start_vectors(VALUES)
    t = np.linspace(0.0, 8.0, 401)
    tr = pl.simulate_spring(truth, x0, v0, 8.0, dt=1e-3, save_every=20, order=4)
    data: dict[str, object] = {}
    if "positions" in kinds:
        data["positions"] = tr.x + 0.01
    if "specific_force" in kinds:
        data["specific_force"] = np.full(t.size, 10.0)  # m/s²: only the derivatives matter here
    values = {**VALUES, "pivot_x": 0.0, "pivot_y": 0.0, "pivot_z": 0.0, "t_offset": 0.0}
    return Problem("spring", values, free, observations(t, data))


@pytest.mark.parametrize(
    ("kinds", "free"),
    [
        (["positions"], [*spring_model.TANGENT_NAMES, "pivot_x", "t_offset"]),
        (["specific_force"], ["theta0", "r0", "r_dot0", "stiffness", "mass", "length", "g"]),
    ],
)
def test_the_fits_jacobian_is_the_difference_quotient_for_one_run(kinds: list[str], free: list[str]) -> None:
    problem = _spring_problem(kinds, free)
    sigma = dict.fromkeys(kinds, 1.0)
    values = {**problem.values, "t_offset": -0.05} if "t_offset" in free else problem.values
    before = problem.evaluations
    exact = exact_jacobian(problem, values, sigma)
    assert problem.evaluations == before + 1  # one run with its tangents, no differenced column
    assert exact is not None and exact.shape == (problem.obs.n_residuals, len(free))
    u = np.array([values[n] for n in free])
    steps = 1e-6 * np.maximum(np.abs(u), 1e-2)
    fd = jacobian(lambda uu: problem.residuals(problem.with_free(uu), sigma), u, steps)
    for k, name in enumerate(free):
        size = float(np.max(np.abs(fd[:, k])))
        assert size > 0.0, name
        assert float(np.max(np.abs(exact[:, k] - fd[:, k]))) < 1e-5 * size, name


def test_a_spring_fit_takes_its_jacobians_from_the_tangents() -> None:
    """Noise-free positions at the resonance: the fit finds k, l₀ and g to ~1e-6 and makes far fewer
    model runs than the 2 × 9 per Jacobian that differences cost."""
    truth = pl.SwingingSpring.resonant(1.0)
    x0, v0 = np.array([0.15, 0.05, -1.02]), np.array([0.0, 0.2, 0.0])
    tr = pl.simulate_spring(truth, x0, v0, 6.0, dt=1.0 / 30.0 / 50, save_every=50, order=4)
    res = pl.fit(
        tr.t, positions=tr.x, pendulum=pl.SwingingSpring(30.0, 0.8, 9.81, 1.0), fit="stiffness,length,g"
    )
    assert res.params["stiffness"] == pytest.approx(truth.k_over_m * truth.mass, rel=1e-6)
    assert res.params["length"] == pytest.approx(truth.rest_length, rel=1e-6)
    assert res.params["g"] == pytest.approx(truth.g, rel=1e-6)
    assert math.isfinite(res.stderr["stiffness"])


def test_bad_input_to_the_core_is_named() -> None:
    spec = _core.ModelSpec.spring_model(39.24, 0.75, 9.81, 1.0)
    state = (np.array([0.3, 0.1, -1.0]), np.zeros(3))
    options = _core.RunOptions(dt=1e-3, save_every=1, order=4)
    one, keep = np.zeros((1, 3)), np.array([1], dtype=np.uint64)
    with pytest.raises(pl.InvalidInputError, match="shape"):
        _core.spring_sensitivities(spec, state, (one, np.zeros((2, 3))), keep, options)
    with pytest.raises(pl.InvalidInputError, match="ascending"):
        _core.spring_sensitivities(spec, state, (one, one), np.array([5, 3], dtype=np.uint64), options)
    with pytest.raises(pl.InvalidInputError, match=r"start_tangents\[0\] = nan"):
        _core.spring_sensitivities(spec, state, (np.full((1, 3), np.nan), one), keep, options)
    assert _core.spring_sensitivity_params() == ["k_over_m", "rest_length", "g"]
