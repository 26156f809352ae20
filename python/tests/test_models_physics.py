"""The physics of the real-pendulum models (docs/theory.md §7): with zero extras a model runs the ideal
trajectory to round-off, the power balance T-7.1 (P = F·v at the given time, its residual shrinking
like dt²), the exact J₃ decay exp(-c t) of linear damping, Foucault's turn T-7.3 at -Ω sin(latitude),
and tilted gravity as a rotated ideal pendulum. SI units throughout (m, kg, s, rad; power in W,
energy in J)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import SCENARIOS
from model_inputs import FORCED, ROSETTE

import pendulab as pl


def rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    """The rotation matrix about the unit vector ``axis`` by ``angle`` [rad] (Rodrigues)."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


# --- physics ----------------------------------------------------------------------------------------


@pytest.mark.parametrize("method", ["rattle", "rattle4", "dop853"])
def test_zero_extras_give_the_ideal_trajectory_to_round_off(method: str) -> None:
    """Every model with its extra forces switched off (zero damping, drag, forcing, frame rate, pivot
    motion; gravity along −e₃) follows the ideal pendulum to round-off, not merely to the step error."""
    ideal = pl.Pendulum()
    s0 = ideal.state_from_angles(*ROSETTE)
    off = {
        "damped": {"damping": 0.0, "drag": 0.0, "forcing_amplitude": 0.0, "forcing_omega": 3.0},
        "rotating": {"frame_rate": 0.0, "latitude": 0.3},
        "slewing": {"radius": 0.0, "rate": 0.0},
        "vibrating": {"amplitude": 0.0},
    }
    ref = pl.simulate(ideal, s0, 2.0, method=method, save_every=100)
    for name, params in off.items():
        tr = pl.simulate(pl.Pendulum(model=name, **params), s0, 2.0, method=method, save_every=100)
        assert np.array_equal(tr.t, ref.t), name
        gap = np.max(np.abs(tr.x - ref.x)) + np.max(np.abs(tr.v - ref.v))
        assert gap < 1e-13, f"{name} with {method}: {gap:.3e} from the ideal pendulum"


def test_a_damped_file_with_zero_damping_runs_like_the_ideal_rosette() -> None:
    """damped.toml with damping = 0 and rosette.toml (the same start) give the same trajectory."""
    text = (SCENARIOS / "damped.toml").read_text().replace("damping = 0.05", "damping = 0.0")
    damped = pl.Scenario.from_toml_str(text).run(t_end=1.0, progress=False)
    ideal = pl.load_scenario(SCENARIOS / "rosette.toml").run(
        t_end=1.0, method="rattle4", save_every=10, progress=False
    )
    assert np.max(np.abs(damped.x - ideal.x)) < 1e-14


def test_power_is_force_times_velocity_at_the_given_time() -> None:
    """P = m(A cos(ωt + ψ) e·v − c|v|² − c_q|v|³) [W] (T-7.1) at a state, with the time-dependence."""
    p = pl.Pendulum(mass=2.0, forcing_phase=0.4, **FORCED)
    s = p.state_from_angles(0.7, 0.3, 0.5, 1.5)
    speed = float(np.linalg.norm(s.v))
    for t in (0.0, 1.3):
        forced = FORCED["forcing_amplitude"] * math.cos(FORCED["forcing_omega"] * t + 0.4) * s.v[1]
        want = 2.0 * (forced - FORCED["damping"] * speed**2 - FORCED["drag"] * speed**3)
        assert p.power(s, t) == pytest.approx(want, rel=1e-14)
    assert p.power(s, 0.0) != pytest.approx(p.power(s, 1.3))  # the forcing really depends on t


def test_power_balance_residual_is_small_and_shrinks_like_dt_squared() -> None:
    """E(t) − E(0) = ∫P dt (T-7.1) on a damped, dragged and forced run: the residual is RATTLE's and the
    trapezoid rule's O(Δt²) error, so halving Δt divides it by 4 — a wrong power (or forcing taken at
    the wrong time) would leave an O(1) residual that does not shrink."""
    p = pl.Pendulum(**FORCED)
    s0 = p.state_from_angles(*ROSETTE)
    runs = [pl.simulate(p, s0, 10.0, method="rattle", dt=dt) for dt in (2e-3, 1e-3)]
    coarse, fine = (float(np.max(np.abs(tr.power_balance_residual))) for tr in runs)
    lost = runs[1].energy[-1] - runs[1].energy[0]
    assert lost < -2.0, f"the test needs a real energy change, got {lost} J"
    assert fine < 2e-5 and fine < 1e-5 * abs(lost), f"residual {fine:.3e} J of {lost:.3f} J"
    assert 3.8 < coarse / fine < 4.2, f"residual does not shrink like Δt²: {coarse:.3e} → {fine:.3e} J"
    assert not runs[1].is_conservative and "balance:" in runs[1].summary()


def test_linear_damping_decays_j3_exactly_as_exp_minus_ct() -> None:
    """dJ₃/dt = −c J₃ for the axisymmetric pendulum with force −m c v: J₃(t) = J₃(0) e^{−ct}. RATTLE's
    splitting with the exact damping flow keeps this to round-off at every sample."""
    c = 0.3
    p = pl.Pendulum(damping=c)
    tr = pl.simulate(p, p.state_from_angles(*ROSETTE), 10.0, method="rattle", dt=1e-3, save_every=100)
    want = tr.j3[0] * np.exp(-c * tr.t)
    assert np.max(np.abs(tr.j3 - want) / want) < 1e-12
    assert tr.j3[-1] < 0.06 * tr.j3[0]  # it did decay: e^{−3} ≈ 0.05


@pytest.mark.parametrize("hemisphere", [1.0, -1.0])
def test_foucault_plane_turns_at_minus_omega_sin_latitude(hemisphere: float) -> None:
    """T-7.3: the swing plane turns at −|Ω| sin λ to first order in |Ω|/ω₀ (foucault.toml: Ω = 0.02
    rad/s, λ = ±49°, l = 10 m, ω₀ ≈ 0.99 rad/s): clockwise seen from above in the north, anticlockwise
    in the south. Measured: the azimuth of the turning points (mod π) fitted by a line over 120 s."""
    text = (SCENARIOS / "foucault.toml").read_text()
    sc = pl.Scenario.from_toml_str(text.replace("latitude_deg = 49.0", f"latitude_deg = {49.0 * hemisphere}"))
    tr = sc.run(progress=False)
    rho = np.hypot(tr.x[:, 0], tr.x[:, 1])
    turning = np.flatnonzero((rho[1:-1] > rho[:-2]) & (rho[1:-1] >= rho[2:])) + 1
    plane = np.unwrap(2 * np.arctan2(tr.x[turning, 1], tr.x[turning, 0])) / 2  # a line: angle mod π
    rate = np.polyfit(tr.t[turning], plane, 1)[0]
    p = sc.pendulum()
    want = -p.extra["frame_rate"] * math.sin(p.extra["latitude"])
    assert p.extra["latitude"] == pytest.approx(hemisphere * math.radians(49.0), rel=1e-15)
    assert abs(plane[-1] - plane[0]) > 1.5  # a visible turn (about 100°)
    assert rate == pytest.approx(want, rel=0.05), f"turn rate {rate:.5f} rad/s, first order {want:.5f}"


def test_tilted_gravity_is_a_rotated_ideal_pendulum() -> None:
    """Gravity along d = R(−e₃): the motion is R applied to the ideal motion from R⁻¹(start), with the
    same energy; and it is really different from the untilted motion from the same start."""
    axis = np.array([1.0, 2.0, 0.5]) / np.linalg.norm([1.0, 2.0, 0.5])
    r = rotation(axis, 0.7)
    d = r @ np.array([0.0, 0.0, -1.0])
    tilted = pl.Pendulum(model="damped", gravity_x=d[0], gravity_y=d[1], gravity_z=d[2])
    ideal = pl.Pendulum()
    s0 = ideal.state_from_angles(*ROSETTE)
    start = tilted.state(r @ s0.x, r @ s0.v, project=True)
    assert max(start.projection or (1.0, 1.0)) < 1e-15
    a = pl.simulate(tilted, start, 3.0, method="rattle4", dt=1e-3, save_every=100)
    b = pl.simulate(ideal, s0, 3.0, method="rattle4", dt=1e-3, save_every=100)
    assert np.max(np.abs(a.x - b.x @ r.T)) < 1e-10
    assert np.max(np.abs(a.energy - b.energy)) < 1e-12 and a.is_conservative
    untilted = pl.simulate(ideal, start, 3.0, method="rattle4", dt=1e-3, save_every=100)
    assert np.max(np.abs(a.x - untilted.x)) > 0.1
