"""The compound (physical) pendulum as its equivalent point pendulum (variants/compound.py, T-7.7):
textbook equivalent lengths, an independent rigid-body integration (SciPy DOP853 of
I θ̈ = −M g h sin θ − τ_f tanh(θ̇/ω_ε) − b θ̇) against pl.simulate of the equivalent pendulum, the
geometry solved back from an equivalent length, and bad input named. SI units."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import pendulab as pl
from pendulab import CompoundPendulum, Part


def test_textbook_equivalent_lengths() -> None:
    assert CompoundPendulum((Part.rod(0.3, 1.2),)).equivalent_length == pytest.approx(0.8, rel=1e-15)  # 2L/3
    assert CompoundPendulum((Part.sphere(1.0, 0.0, 0.7),)).equivalent_length == pytest.approx(0.7, rel=1e-15)
    bob = CompoundPendulum((Part.sphere(2.0, 0.05, 0.5),))
    assert bob.equivalent_length == pytest.approx(0.5 + 2 * 0.05**2 / (5 * 0.5), rel=1e-15)
    ring = CompoundPendulum((Part.disk(1.0, 0.1, 0.3),))
    assert ring.equivalent_length == pytest.approx(0.3 + 0.1**2 / (2 * 0.3), rel=1e-15)
    assert "l_eq = I_O/(M h)" in bob.formula and f"{bob.equivalent_length:.6g}" in bob.formula


def test_the_body_moves_as_its_equivalent_point_pendulum() -> None:
    body = CompoundPendulum((Part.rod(0.4, 0.6), Part.sphere(1.5, 0.04, 0.55), Part(0.2, -0.05, 1e-4)))
    g, tau_f, b, w_eps = 9.81, 0.004, 0.002, 1e-3
    m, h, inertia = body.mass, body.centre, body.inertia

    def rhs(_t: float, y: np.ndarray) -> list[float]:
        th, w = y
        torque = -m * g * h * math.sin(th) - tau_f * math.tanh(w / w_eps) - b * w
        return [w, torque / inertia]

    t = np.linspace(0.0, 15.0, 1501)
    ref = solve_ivp(rhs, (0.0, 15.0), [1.2, 0.0], method="DOP853", rtol=1e-11, atol=1e-13, t_eval=t)
    p = body.pendulum(g, friction_torque=tau_f, damping_torque=b)
    assert p.model == "damped" and p.length == pytest.approx(body.equivalent_length)
    tr = pl.simulate(p, p.state_from_angles(1.2, 0.0, 0.0, 0.0), 15.0, method="dop853", rtol=1e-12, save_at=t)
    theta = np.arctan2(tr.x[:, 0], -tr.x[:, 2])
    assert np.ptp(ref.y[0]) > 2.0  # a real swing, decaying
    assert np.max(np.abs(theta - ref.y[0])) < 1e-7


def test_the_geometry_from_an_equivalent_length() -> None:
    body = CompoundPendulum((Part.rod(0.4, 0.6), Part.sphere(1.5, 0.04, 0.55)))
    moved = CompoundPendulum((Part.rod(0.4, 0.6), Part.sphere(1.5, 0.04, 0.43)))
    back = body.solve_distance(1, moved.equivalent_length)
    assert back.parts[1].distance == pytest.approx(0.43, rel=1e-12)
    with pytest.raises(pl.InvalidInputError, match="no position of part 1"):
        body.solve_distance(1, 0.01)


def test_bad_input_is_named() -> None:
    with pytest.raises(pl.InvalidInputError, match="mass"):
        Part(-1.0, 0.3)
    with pytest.raises(pl.InvalidInputError, match="inertia"):
        Part(1.0, 0.3, float("nan"))
    with pytest.raises(pl.InvalidInputError, match="below"):
        CompoundPendulum((Part(1.0, -0.2),))
    with pytest.raises(pl.InvalidInputError, match="rod length"):
        Part.rod(1.0, 0.0)
