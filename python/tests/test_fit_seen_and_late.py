"""Two corners of the fit's error analysis: what a camera's ``perspective`` acts on (only positions,
so only there can a held perspective break the mirror y → −y: estimator.seen_by for
mirror_sign.broken_by), and the Jacobian after the time limit (forward differences of the whole
record, one run per unknown instead of two: identify.jacobian's ``centre``, inference._polished)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import pendulab as pl
from pendulab.fitting.data import observations
from pendulab.fitting.estimator import seen_by
from pendulab.fitting.identify import jacobian
from pendulab.fitting.mirror_sign import broken_by
from pendulab.fitting.problem import Problem

START = {"theta0": 0.6, "phi0": 0.2, "theta_dot0": 0.1, "phi_dot0": 0.9}
VALUES = {"length": 0.9, "g": 9.81, "mass": 1.0, **START, "pivot_x": 0.0, "pivot_y": 0.0, "pivot_z": 0.0}


def _swing() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    p = pl.Pendulum(0.9, 9.81)
    t = np.linspace(0.0, 6.0, 301)
    tr = pl.simulate(p, p.state_from_angles(*START.values()), 6.0, method="dop853", rtol=1e-12, save_at=t)
    return t, tr.x, tr.v


def test_a_held_perspective_breaks_the_mirror_only_for_positions() -> None:
    """broken_by counted a held perspective ≠ 0 for any data blind to y, a phone's |a − g⃗| and |ω|
    too, which no camera sees: such a fit was told its model is no mirror symmetry (the mirror check
    skipped, the sign refit run instead). Only positions (x, z) are seen through the camera."""
    t, x, v = _swing()
    held = {**VALUES, "perspective": 0.2}
    phone = observations(t, {"angular_speed": np.linalg.norm(np.cross(x, v), axis=1) / 0.81})
    filmed = observations(t, {"positions": x[:, [0, 2]]})
    assert "perspective" not in seen_by(phone, held) and seen_by(filmed, held) == held
    assert broken_by("ideal", seen_by(phone, held), set()) == ""
    assert "perspective" in broken_by("ideal", seen_by(filmed, held), set())


def test_the_perspective_acts_on_positions_only() -> None:
    """The pinhole's 1/(1 + κ y) was applied to the bob's position before every data kind, so a held
    perspective changed a phone's predicted |ω| = |x × v|/|x|² (by 1 + κ y: a y-odd term in frame-free
    data). Now it scales the positions alone; angles and |ω| are as without it."""
    t, x, v = _swing()
    kinds = {
        "positions": x[:, [0, 2]],
        "angles": np.column_stack([np.arccos(-x[:, 2] / 0.9), np.arctan2(x[:, 1], x[:, 0])]),
        "angular_speed": np.linalg.norm(np.cross(x, v), axis=1) / 0.81,
    }
    for kind, data in kinds.items():
        obs = observations(t, {kind: data})
        plain = Problem("ideal", dict(VALUES), [], obs).predictions(VALUES)[kind]
        near = Problem("ideal", dict(VALUES), [], obs).predictions({**VALUES, "perspective": 0.5})[kind]
        if kind == "positions":
            depth = 1.0 + 0.5 * x[:, 1]
            assert np.allclose(near, plain / depth[:, None], rtol=1e-9, atol=1e-12)
        else:
            assert np.array_equal(near, plain), kind


def test_forward_differences_take_one_run_per_column() -> None:
    """identify.jacobian with ``centre`` = r(u): one residual run per unknown (central: two), columns
    agreeing with the central ones to O(h); a step the model refuses is taken backward."""
    calls = []

    def residuals(u: np.ndarray) -> np.ndarray:
        calls.append(1)
        if u[1] > 2.0:
            raise pl.InvalidInputError("beyond the bound")
        return np.array([u[0] ** 2, math.sin(u[1]) * u[0], math.exp(u[0] - u[1])])

    u, steps = np.array([1.3, 2.0 - 1e-9]), np.array([1e-5, 1e-5])
    central = jacobian(residuals, u, steps)
    calls.clear()
    forward = jacobian(residuals, u, steps, centre=residuals(u))
    assert len(calls) == 1 + 2 + 1  # the centre, one forward step each, one refused and taken backward
    assert np.allclose(forward, central, rtol=1e-4, atol=1e-8)


def test_the_jacobian_after_the_time_limit_is_forward(monkeypatch: pytest.MonkeyPatch) -> None:
    """Past the time limit a model without sensitivities (then the spring) differenced its Jacobian over
    the whole record centrally, 2 runs per unknown — 4.6 of the 4.9 s a 1 s limit ran over on an 80 s
    spring (docs/fit.md, "In the lab"). Now forward: one run per unknown; the bars it gives agree with
    the central Jacobian's at the same values to 1e-3. The spring has exact sensitivities since
    (T-10.8); they are switched off here, so that it stands for the models without them (the pivot
    models)."""
    from pendulab.fitting import identify, inference, sensitivity

    monkeypatch.setattr(sensitivity, "MODELS", tuple(m for m in sensitivity.MODELS if m != "spring"))

    seen: list[bool] = []
    ratios: list[np.ndarray] = []
    real = identify.jacobian

    def spy(f, u, steps, logged=None, centre=None):  # type: ignore[no-untyped-def]
        seen.append(centre is not None)
        out = real(f, u, steps, logged, centre)
        if centre is not None:
            central = real(f, u, steps, logged)
            bars = [np.sqrt(np.diag(np.linalg.inv(j.T @ j))) for j in (out, central)]
            ratios.append(bars[0] / bars[1])
        return out

    monkeypatch.setattr(inference, "jacobian", spy)
    spring = pl.SwingingSpring(60.0, 0.5, 9.81, 1.0)
    x0, v0 = np.array([0.25, 0.05, -0.6]), np.array([0.0, 0.3, 0.0])  # m, m/s
    tr = pl.simulate_spring(spring, x0, v0, 4.0, dt=1e-3, save_every=20, order=4)
    t, xyz = tr.t, tr.x + 1e-3 * np.random.default_rng(5).standard_normal(tr.x.shape)
    fit = ["stiffness", "length"]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(t, positions=xyz, pendulum=spring, fit=fit)
        assert seen == [False] and not res.interrupted, [str(w.message) for w in caught]
        seen.clear()
        late = pl.fit(t, positions=xyz, pendulum=spring, fit=fit, time_limit=1e-3)
    assert seen == [True] and late.interrupted, seen
    assert any("time limit" in str(w.message) for w in caught)
    assert np.allclose(ratios[0], 1.0, atol=1e-3), ratios
    for name in fit:
        assert math.isfinite(late.stderr[name]) and late.stderr[name] > 0.0, late.stderr
