"""Δφ per z-period measured from simulated trajectories (``pl.measured_azimuth_advance``) against the
exact T-4.5: RATTLE8 runs of the rosette (both reference events, fine and coarse sampling), of the
near-top scenario (the bob skims the bottom pole, where φ swings by ≈ π within microseconds), of
mirrored gravity and of reversed spin; the physical unwrapping of φ; bad input. SI units, rad.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from conftest import SCENARIOS

import pendulab as pl
from pendulab.theory.advance import monotone_azimuth


def run(
    name: str, periods: float, dt: float = 2e-3, every: int = 1
) -> tuple[pl.Trajectory, pl.ExactSolution]:
    sc = pl.load_scenario(SCENARIOS / f"{name}.toml")
    p, s0 = sc.pendulum(), sc.initial_state()
    sol = pl.exact(p, s0)
    tr = pl.simulate(p, s0, periods * sol.period_z, method="rattle8", dt=dt, save_every=every)
    return tr, sol


@pytest.mark.parametrize("reference", ["mid", "lowest"])
@pytest.mark.parametrize("every", [1, 10])
def test_rosette_from_rattle8(reference: str, every: int) -> None:
    """~5 z-periods at dt = 2 ms, sampled every step or every 10th (≈ 54 samples per period): the mean
    and every single period's Δφ, and T_z, within 1e-6 of T-4.5 and T-4.3."""
    tr, sol = run("rosette", 6.05, every=every)
    m = pl.measured_azimuth_advance(tr, reference=reference)  # type: ignore[arg-type]
    assert m.reference == reference and len(m.per_period) >= 5
    assert abs(m.delta_phi - sol.azimuth_advance) <= 1e-6
    assert np.max(np.abs(m.per_period - sol.azimuth_advance)) <= 1e-6
    assert abs(m.period_z - sol.period_z) <= 1e-6
    assert np.all(np.diff(m.times) > 0.9 * sol.period_z)


def test_lowest_points_are_the_lowest() -> None:
    """With reference="lowest" the events sit at the exact solution's lowest height z₁ (to 1e-9 m)."""
    tr, sol = run("rosette", 3.2)
    m = pl.measured_azimuth_advance(tr, reference="lowest")
    z = np.array([sol.state(t).x[2] for t in m.times])
    assert np.allclose(z, sol.turning_heights[0], rtol=0, atol=1e-9)


def test_near_top_skimming_the_pole() -> None:
    """near_top passes 2e-5 l from the bottom pole with tiny J₃: the mid-height reference still gives
    T-4.5 to 1e-6 rad; the unwrapped φ never runs backwards."""
    tr, sol = run("near_top", 3.1)
    m = pl.measured_azimuth_advance(tr)
    assert abs(m.delta_phi - sol.azimuth_advance) <= 1e-6
    phi = monotone_azimuth(tr.x, math.copysign(1.0, tr.j3[0]))
    assert np.all(np.diff(phi) >= -1e-9)
    # Trajectory.phi follows the sign of ℓ₃ = x v_y − y v_x: the same as the monotone azimuth
    assert np.allclose(tr.phi, phi, rtol=0, atol=1e-12)


def test_trajectory_phi_turns_with_the_angular_momentum() -> None:
    """The conical orbit at θ = 60° turns at Ω = (g/(l cos θ))^{1/2} = 4.43 rad/s; sampled every
    0.9 s it turns 3.99 rad > π between samples: a plain unwrap (nearest branch) then runs backwards,
    Trajectory.phi follows sign(ℓ₃) and gives Ω t (to the integrator's error)."""
    p = pl.Pendulum()
    theta = math.radians(60.0)
    omega = math.sqrt(p.g / (p.length * math.cos(theta)))
    tr = pl.simulate(
        p, p.state_from_angles(theta=theta, phi_dot=omega), 9.0, method="rattle8", dt=1e-3, save_every=900
    )
    raw_unwrap = np.unwrap(np.arctan2(tr.x[:, 1], tr.x[:, 0]))
    assert np.all(np.diff(raw_unwrap) < 0)  # the old Trajectory.phi: backwards at every step
    assert np.allclose(tr.phi - tr.phi[0], omega * tr.t, rtol=0, atol=1e-8)
    back = pl.simulate(
        p, p.state_from_angles(theta=theta, phi_dot=-omega), 9.0, method="rattle8", dt=1e-3, save_every=900
    )
    assert np.allclose(back.phi - back.phi[0], -omega * back.t, rtol=0, atol=1e-8)


def test_mirrored_gravity_and_reversed_spin() -> None:
    """g < 0 (events of the mirrored frame) gives the same Δφ as its mirror image; reversing the spin
    reverses Δφ."""
    tr, sol = run("inverted_g", 4.1)
    assert abs(pl.measured_azimuth_advance(tr).delta_phi - sol.azimuth_advance) <= 1e-6
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=math.radians(60), phi_dot=-2.0)
    sol = pl.exact(p, s0)
    tr = pl.simulate(p, s0, 4.1 * sol.period_z, method="rattle8", dt=2e-3)
    m = pl.measured_azimuth_advance(tr, reference="lowest")
    assert sol.azimuth_advance < 0 and abs(m.delta_phi - sol.azimuth_advance) <= 1e-6


def test_bad_input(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    """Planar motion (φ jumps at the pole), too short a run, a conical orbit, an unknown reference."""
    planar = pl.exact(pendulum, pendulum.state_from_angles(theta=0.5)).trajectory(np.linspace(0, 10, 1001))
    with pytest.raises(pl.InvalidInputError, match="J3 = 0"):
        pl.measured_azimuth_advance(planar)
    short = pl.exact(pendulum, rosette).trajectory(np.linspace(0, 0.5, 101))
    with pytest.raises(pl.InvalidInputError, match="event"):
        pl.measured_azimuth_advance(short)
    alpha = math.radians(45)
    cone = pendulum.state_from_angles(theta=alpha, phi_dot=math.sqrt(9.81 / math.cos(alpha)))
    with pytest.raises(pl.InvalidInputError, match="conical"):
        pl.measured_azimuth_advance(pl.exact(pendulum, cone).trajectory(np.linspace(0, 10, 1001)))
    with pytest.raises(pl.InvalidInputError, match="reference"):
        pl.measured_azimuth_advance(short, reference="highest")  # type: ignore[arg-type]
    with pytest.raises(pl.InvalidInputError, match="Trajectory"):
        pl.reduce((rosette.x, rosette.v))  # type: ignore[arg-type]
