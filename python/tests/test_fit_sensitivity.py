"""The exact Jacobian of a fit by forward sensitivities (fitting/sensitivity.py, docs/theory.md T-10.7)
against central differences of the forward model (identify.jacobian, the fit's old way): every column
— start angles and rates, l, g, damping, drag, dry friction, t_offset, pivot offsets — agrees to the
differences' own error, for each data kind; the core's sensitivities agree with differences of its
own runs; models without sensitivities say None."""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl
from pendulab import _core
from pendulab.fitting.data import observations
from pendulab.fitting.identify import jacobian
from pendulab.fitting.problem import Problem, model_params
from pendulab.fitting.sensitivity import MOTIONLESS, SENSITIVE, exact_jacobian

START = {"theta0": 1.1, "phi0": 0.2, "theta_dot0": 0.1, "phi_dot0": 0.6}


def _problem(model: str, extra: dict[str, float], kinds: dict[str, object], free: list[str]) -> Problem:
    defaults = {k: float(spec["default"]) for k, spec in model_params(model).items()}
    values = {
        **defaults,
        "length": 0.9,
        "g": 9.81,
        "mass": 1.0,
        **START,
        **extra,
        "pivot_x": 0.0,
        "t_offset": 0.0,
    }
    p = pl.Pendulum(0.9, 9.81, 1.0, model=model, **extra) if model != "ideal" else pl.Pendulum(0.9, 9.81)
    t = np.linspace(0.0, 6.0, 601)
    tr = pl.simulate(p, p.state_from_angles(*START.values()), 6.0, method="dop853", rtol=1e-12, save_at=t)
    data = {}
    for kind in kinds:
        if kind == "positions":
            data[kind] = tr.x + 0.01
        elif kind == "planar_angle":
            data[kind] = np.arctan2(tr.x[:, 0], -tr.x[:, 2]) + 0.001
        elif kind == "angular_speed":
            data[kind] = np.linalg.norm(np.cross(tr.x, tr.v), axis=1) / 0.81
        elif kind == "specific_force":
            data[kind] = np.full(t.size, 10.0)  # m/s²: only the derivatives matter here
    obs = observations(t, data)
    return Problem(model, values, free, obs)


CASES = [
    (
        "damped",
        {"damping": 0.05, "drag": 0.1, "friction": 0.2},
        ["positions"],
        ["theta0", "phi0", "theta_dot0", "phi_dot0", "length", "g", "damping", "drag", "friction", "pivot_x"],
    ),
    (
        "damped",
        {"damping": 0.05, "friction": 0.3},
        ["planar_angle"],
        ["theta0", "theta_dot0", "length", "damping", "drag", "friction"],
    ),
    ("damped", {"drag": 0.2}, ["specific_force", "angular_speed"], ["theta0", "length", "g", "drag"]),
    ("ideal", {}, ["positions"], ["theta0", "phi_dot0", "length", "g", "t_offset"]),
    ("rotating", {"frame_rate": 0.5, "latitude": 0.7}, ["positions"], ["theta0", "length", "frame_rate"]),
]


@pytest.mark.parametrize(("model", "extra", "kinds", "free"), CASES)
def test_the_exact_jacobian_is_the_difference_quotient(
    model: str, extra: dict[str, float], kinds: list[str], free: list[str]
) -> None:
    problem = _problem(model, extra, dict.fromkeys(kinds), free)
    sigma = {k: 1.0 for k in kinds}
    u = np.array([problem.values[n] for n in free])
    before = problem.evaluations
    exact = exact_jacobian(problem, problem.values, sigma)
    differenced = sum(n not in SENSITIVE and n not in MOTIONLESS and n != "t_offset" for n in free)
    assert problem.evaluations == before + 1 + 2 * differenced  # model runs, not moved predictions
    assert exact is not None and exact.shape == (problem.obs.n_residuals, len(free))
    # central differences of the forward model (rtol 1e-12): error ~ h² f''' + 1e-12/h ~ 1e-7 relative
    steps = 1e-5 * np.maximum(np.abs(u), 1e-2)
    fd = jacobian(lambda uu: problem.residuals(problem.with_free(uu), sigma), u, steps)
    for k, name in enumerate(free):
        size = np.max(np.abs(fd[:, k]))
        assert size > 0.0, name
        assert np.max(np.abs(exact[:, k] - fd[:, k])) < 1e-5 * size, name
    # a wrong column (another parameter's) would be far off: the test can fail
    assert np.max(np.abs(exact[:, 0] - fd[:, -1])) > 1e-2 * np.max(np.abs(fd[:, -1]))


def test_models_without_sensitivities_say_none() -> None:
    problem = _problem("damped", {}, {"positions": None}, ["theta0"])
    problem.model = "vibrating"
    assert (
        exact_jacobian(problem, {**problem.values, "amplitude": 0.05, "frequency": 200.0}, {"positions": 1.0})
        is None
    )


def test_bad_input_to_the_core_is_named() -> None:
    damped = _core.ModelSpec(1.0, 1.0, 9.81, "damped")
    slewing = _core.ModelSpec(1.0, 1.0, 9.81, "slewing")
    tight = _core.RunOptions(rtol=1e-12, atol=1e-14)
    with pytest.raises(pl.InvalidInputError, match="save times"):
        _core.sensitivities(damped, [0.5, 0.0, 0.0, 0.0], np.array([0.0, 2.0, 1.0]), tight)
    with pytest.raises(pl.InvalidInputError, match="rtol"):
        _core.sensitivities(damped, [0.5, 0.0, 0.0, 0.0], np.array([1.0]), _core.RunOptions(rtol=0.0))
    with pytest.raises(pl.InvalidInputError, match="rod models"):
        _core.sensitivities(slewing, [0.5, 0.0, 0.0, 0.0], np.array([1.0]), tight)
