"""A user force given as a Python callable (the slow path, T-7.1): a callable equal to linear damping
reproduces the ``damped`` model; zero force is the ideal pendulum bit for bit; the power F·v and the
power balance E(t) − E(0) − ∫P dt include it; exceptions from the callable propagate unchanged and
malformed or non-finite results are errors naming the value. SI units (N, m, s, W, J)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pytest

import pendulab as pl

START = (math.radians(60.0), 0.0, 0.0, 2.0)  # θ₀, φ₀ [rad], θ̇₀, φ̇₀ [rad/s]


def test_a_damping_callable_reproduces_the_damped_model() -> None:
    mass, c = 2.0, 0.3  # kg, 1/s: F = −m c v
    damped = pl.Pendulum(mass=mass, damping=c)
    user = pl.Pendulum(mass=mass, force=lambda t, x, v: [-mass * c * vi for vi in v])
    assert user.model == "ideal" and not user.is_ideal
    s0 = damped.state_from_angles(*START)
    a = pl.simulate(damped, s0, 5.0, method="dop853", rtol=1e-12, atol=1e-14, save_at=[1.0, 5.0])
    b = pl.simulate(user, s0, 5.0, rtol=1e-12, atol=1e-14, save_at=[1.0, 5.0])  # dop853 by default
    assert b.method == "dop853"
    assert np.max(np.abs(a.x - b.x)) < 1e-10 and np.max(np.abs(a.v - b.v)) < 1e-10
    np.testing.assert_allclose(b.power, a.power, rtol=1e-9)  # −m c |v|², from the callable
    # every diagnostic at the same states, the acceleration and tension with the user force included
    da, db = damped.diagnostics(a.x, a.v, a.t), user.diagnostics(a.x, a.v, a.t)
    for key in ("energy", "j3", "tension", "power", "acceleration"):
        np.testing.assert_allclose(db[key], da[key], rtol=1e-12, atol=1e-12, err_msg=key)


def test_zero_force_is_the_ideal_pendulum_bit_for_bit(pendulum: pl.Pendulum) -> None:
    s0 = pendulum.state_from_angles(*START)
    zero = pl.Pendulum(force=lambda t, x, v: (0.0, 0.0, 0.0))
    for method in ("dop853", "rkmk4"):
        a = pl.simulate(pendulum, s0, 2.0, method=method)
        b = pl.simulate(zero, s0, 2.0, method=method)
        np.testing.assert_array_equal(a.x, b.x)
        np.testing.assert_array_equal(a.v, b.v)
        assert np.all(b.power == 0.0)


def test_power_balance_with_a_time_and_velocity_dependent_force() -> None:
    """F = 0.8 cos(2.7 t) e_y − 0.05 |v| v [N] on 1 kg: the residual is the trapezoid rule's O(Δt²)
    error, so halving the sample spacing divides it by ≈ 4 (a wrong power would not shrink)."""

    def force(t: float, x: list[float], v: list[float]) -> list[float]:
        speed = math.sqrt(sum(vi * vi for vi in v))
        return [-0.05 * speed * v[0], 0.8 * math.cos(2.7 * t) - 0.05 * speed * v[1], -0.05 * speed * v[2]]

    p = pl.Pendulum(force=force)
    s0 = p.state_from_angles(*START)

    def worst(spacing: float) -> float:
        times = np.arange(0.0, 10.0 + spacing / 2, spacing)
        tr = pl.simulate(p, s0, 10.0, save_at=times, rtol=1e-12, atol=1e-14)
        f = np.array([force(t, list(x), list(v)) for t, x, v in zip(tr.t, tr.x, tr.v, strict=True)])
        np.testing.assert_allclose(tr.power, np.einsum("ij,ij->i", f, tr.v), rtol=1e-13, atol=1e-15)
        assert abs(tr.energy[-1] - tr.energy[0]) > 0.1  # the force really does work
        return float(np.max(np.abs(tr.power_balance_residual)))

    coarse, fine = worst(2e-2), worst(1e-2)
    assert fine < 1e-4 and 3.5 < coarse / fine < 4.5, (coarse, fine)


class Boom(Exception):
    pass


def test_errors_of_the_callable_propagate_and_bad_results_are_named(pendulum: pl.Pendulum) -> None:
    s0 = pendulum.state_from_angles(*START)

    def explode(t: float, x: Any, v: Any) -> list[float]:
        if t > 0.5:
            raise Boom(f"at t = {t}")
        return [0.0, 0.0, 0.0]

    with pytest.raises(Boom, match="at t = 0"):
        pl.simulate(pl.Pendulum(force=explode), s0, 1.0)
    # every number as the core's messages write them (error::Shown): nan, 0, 1e-7; not NaN, 0.0, 1e-7 as 1e-07
    with pytest.raises(pl.InvalidInputError, match=r"F = \[1e-7, nan, 0\] N at t = 0 s, x = \[") as e:
        pl.simulate(pl.Pendulum(force=lambda t, x, v: [1e-7, float("nan"), 0.0]), s0, 1.0)
    assert str(e.value).endswith("m/s: component 1 = nan is not a finite number")
    assert "NaN" not in str(e.value) and ".0," not in str(e.value)
    with pytest.raises(pl.InvalidInputError, match="returned 2 numbers"):
        pl.simulate(pl.Pendulum(force=lambda t, x, v: [0.0, 1.0]), s0, 1.0)
    with pytest.raises(pl.InvalidInputError, match="not 3 numbers"):
        pl.simulate(pl.Pendulum(force=lambda t, x, v: "north"), s0, 1.0)
    with pytest.raises(pl.InvalidInputError, match="not callable"):
        pl.Pendulum(force=3.0)  # type: ignore[arg-type]
    user = pl.Pendulum(force=lambda t, x, v: [0.0, 0.0, 0.0])
    with pytest.raises(pl.InvalidInputError, match="RATTLE"):
        pl.simulate(user, s0, 1.0, method="rattle")
    with pytest.raises(pl.InvalidInputError, match="conserve"):
        pl.simulate(user, s0, 1.0, conserve=True)
    with pytest.raises(pl.InvalidInputError, match="Stepper"):
        pl.Stepper(user, s0)
    with pytest.raises(pl.InvalidInputError, match="exact"):
        pl.exact(user, s0)
