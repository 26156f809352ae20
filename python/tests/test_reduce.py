"""Symmetry reduction from Python (docs/theory.md §3): the invariants σ₁…σ₆ and their units, the relations
T-3.2, the Casimir and H conserved (T-3.3), the reduced flow's sign against the full flow (T-3.4), the
oscillator's first integral (T-3.5), and the reduced flow with reconstruction (T-3.6) as a third
path to x(t), against the exact solution. SI units; σ in Holm's unit-length variables.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import pendulab as pl


@pytest.fixture
def exact_traj(pendulum: pl.Pendulum, rosette: pl.State) -> pl.Trajectory:
    return pl.exact(pendulum, rosette).trajectory(np.linspace(0.0, 20.0, 2001))


def test_invariants_have_the_documented_meaning() -> None:
    """σ₁ = z/l, σ₂ = ż/l, σ₃ = |v|²/l², σ₄ = ρ²/l², σ₅ = (x ẋ + y ẏ)/l², σ₆ = J₃/(m l²), for l ≠ 1 too."""
    p = pl.Pendulum(length=2.5, g=9.81, mass=3.0)
    tr = pl.exact(p, p.state_from_angles(theta=1.0, phi_dot=1.5, theta_dot=0.4)).trajectory(
        np.linspace(0, 3, 31)
    )
    s, x, v, length = pl.reduce(tr).sigma, tr.x, tr.v, 2.5
    assert s.shape == (31, 6)
    assert np.allclose(s[:, 0], x[:, 2] / length, rtol=0, atol=1e-15)
    assert np.allclose(s[:, 1], v[:, 2] / length, rtol=0, atol=1e-14)
    assert np.allclose(s[:, 2], np.sum(v * v, axis=1) / length**2, rtol=1e-14)
    assert np.allclose(s[:, 3], (x[:, 0] ** 2 + x[:, 1] ** 2) / length**2, rtol=1e-14)
    assert np.allclose(s[:, 4], (x[:, 0] * v[:, 0] + x[:, 1] * v[:, 1]) / length**2, rtol=0, atol=1e-14)
    assert np.allclose(s[:, 5], tr.j3 / (3.0 * length**2), rtol=1e-13)


@pytest.mark.parametrize("source", ["exact", "rattle8"])
def test_relations_casimir_and_energy_along_a_trajectory(
    source: str, pendulum: pl.Pendulum, rosette: pl.State, exact_traj: pl.Trajectory
) -> None:
    """T-3.2 residuals ≤ 1e-12 (relative to their scale) and C = 0 along the motion; H = ½σ₃ + (g/l)σ₁
    equals E/(m l²) and is conserved (to rounding for the exact solution, to the method's error for
    RATTLE8)."""
    tr = exact_traj if source == "exact" else pl.simulate(pendulum, rosette, 20.0, method="rattle8", dt=2e-3)
    red = pl.reduce(tr)
    scale2 = pendulum.g / pendulum.length + float(np.max(red.sigma[:, 2]))  # 1/s²
    res = red.relation_residuals
    assert res.shape == (len(tr), 4)
    assert np.max(np.abs(res[:, [0, 3]])) <= 1e-12 * scale2
    assert np.max(np.abs(res[:, 1])) <= 1e-12
    assert np.max(np.abs(res[:, 2])) <= 1e-12 * math.sqrt(scale2)
    assert np.max(np.abs(red.casimir)) <= 1e-12 * scale2
    assert np.allclose(red.hamiltonian, tr.energy / (pendulum.mass * pendulum.length**2), rtol=0, atol=1e-13)
    drift = np.max(np.abs(red.hamiltonian - red.hamiltonian[0])) / scale2
    assert drift <= (1e-14 if source == "exact" else 1e-10)
    assert np.ptp(red.j) <= 1e-14


def test_reduced_flow_sign_is_the_derivative_along_the_full_flow(exact_traj: pl.Trajectory) -> None:
    """T-3.4 with its sign pinned: the central difference of σ along the exact motion equals σ̇ = ∇H × ∇C:
    σ̇₁ = σ₂, σ̇₂ = −γ(1 − σ₁²) − σ₁σ₃, σ̇₃ = −2γσ₂ (Holm's printed (H1.19)–(H1.21) has the opposite sign)."""
    p = exact_traj.pendulum
    sol = pl.exact(p, exact_traj.state(0))
    t, h, gamma = np.linspace(0.1, 5.0, 50), 1e-4, p.g / p.length
    sig = [pl.reduce(sol.trajectory(t + d)).sigma for d in (-h, 0.0, h)]
    deriv = (sig[2] - sig[0]) / (2 * h)
    s1, s2, s3 = sig[1][:, 0], sig[1][:, 1], sig[1][:, 2]
    field = np.column_stack([s2, -gamma * (1 - s1 * s1) - s1 * s3, -2 * gamma * s2])
    assert np.max(np.abs(deriv[:, :3] - field)) <= 1e-6 * (gamma + np.max(s3))
    assert np.max(np.abs(deriv[:, :3] + field)) > 1.0  # the other sign is far off


def test_oscillator_first_integral(exact_traj: pl.Trajectory) -> None:
    """T-3.5 on the plane H = const: σ̇₁² = 2(H − γσ₁)(1 − σ₁²) − J² along the motion."""
    red = pl.reduce(exact_traj)
    s1, s2, gamma = red.sigma[:, 0], red.sigma[:, 1], red.gamma
    rhs = 2 * (red.hamiltonian - gamma * s1) * (1 - s1 * s1) - red.j**2
    assert np.max(np.abs(s2 * s2 - rhs)) <= 1e-12 * gamma


def test_reduced_flow_is_a_third_path_to_x(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """The RK4-integrated reduced flow with reconstruction agrees with the exact solution at t = 5 s to
    1e-8 (dt = 1 ms), its error falls like dt⁴, and it ends exactly at t_end."""
    sol = pl.exact(pendulum, rosette)
    exact = sol.state(5.0)
    errors = []
    for dt in (2e-3, 1e-3):
        tr = pl.reduced_flow(pendulum, rosette, 5.0, dt=dt)
        assert tr.method == "reduced_rk4" and tr.t[-1] == 5.0 and len(tr) == round(5.0 / dt) + 1
        errors.append(
            max(
                np.linalg.norm(tr.x[-1] - exact.x) / pendulum.length,
                np.linalg.norm(tr.v[-1] - exact.v)
                / (pendulum.length * pendulum.omega0 + np.linalg.norm(exact.v)),
            )
        )
    assert errors[1] <= 1e-8
    assert 10.0 < errors[0] / errors[1] < 22.0  # 2⁴ = 16
    tr = pl.reduced_flow(pendulum, rosette, 0.35, dt=0.0066)  # dt shortened to 0.35/54 s: 54 steps
    assert len(tr) == 55 and tr.t[-1] == 0.35 and tr.options["dt"] == pytest.approx(0.35 / 54)


def test_reduced_flow_bad_input(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """J₃ = 0 (through the pole) is refused with IntegrationError; bad t_end, dt and step counts with
    InvalidInputError naming the value."""
    with pytest.raises(pl.IntegrationError):
        pl.reduced_flow(pendulum, pendulum.state_from_angles(theta=0.5), 1.0)
    with pytest.raises(pl.InvalidInputError, match="t_end"):
        pl.reduced_flow(pendulum, rosette, -1.0)
    with pytest.raises(pl.InvalidInputError, match="dt"):
        pl.reduced_flow(pendulum, rosette, 1.0, dt=float("nan"))
    with pytest.raises(pl.InvalidInputError, match="limit"):
        pl.reduced_flow(pendulum, rosette, 1e6, dt=1e-6)
