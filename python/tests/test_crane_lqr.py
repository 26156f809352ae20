"""LQR anti-sway feedback (pendulab.crane.lqr, docs/theory.md T-11.9): the Riccati solution satisfies
its equation, the closed loop is stable, the nonlinear planar run brings the trolley to the target
with the sway gone, and its trolley motion replayed in the 3-D crane (core) gives the same sway."""

from __future__ import annotations

import numpy as np
import pytest

from pendulab import InvalidInputError, crane


def test_riccati_gain_and_stable_poles() -> None:
    rope, g = 12.0, 9.81
    ctrl = crane.lqr(rope, g=g, q=(2.0, 1.0, 20.0, 3.0), r=0.5)
    a = np.array([[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1], [0, 0, -g / rope, 0]])
    b = np.array([[0], [1], [0], [-1 / rope]])
    # K = R⁻¹BᵀP with P symmetric positive definite solving AᵀP + PA − PBR⁻¹BᵀP + Q = 0: recover P
    # from the closed loop's Lyapunov equation (A − BK)ᵀP + P(A − BK) = −(Q + KᵀRK)
    from scipy.linalg import solve_continuous_lyapunov

    acl = a - b @ ctrl.K
    p = solve_continuous_lyapunov(acl.T, -(np.diag([2.0, 1.0, 20.0, 3.0]) + ctrl.K.T @ ctrl.K * 0.5))
    np.testing.assert_allclose(ctrl.K, (b.T @ p) / 0.5, rtol=1e-8)
    assert np.all(ctrl.poles.real < 0)


def test_closed_loop_moves_and_kills_the_sway_and_replays_in_3d() -> None:
    ctrl = crane.lqr(10.0, q=(1.0, 1.0, 50.0, 1.0), r=1.0, a_max=0.6)
    run = ctrl.simulate(distance=5.0, t_end=40.0)
    t = np.linspace(0, 40, 4001)
    x, v, u = run.trolley(t)
    assert np.abs(u).max() <= 0.6 + 1e-12
    assert x[-1] == pytest.approx(5.0, abs=5e-3) and abs(v[-1]) < 5e-3
    assert np.abs(run.sway(t[t > 30])).max() < 2e-3
    replay = crane.Crane(rope=10.0, pivot=run, payload_mass=500.0).simulate(
        t_end=40.0, output_spacing=0.05, rtol=1e-11, atol=1e-11
    )
    # the load's offset from the trolley is l sin θ in both models
    np.testing.assert_allclose(replay.offset()[:, 0], 10.0 * np.sin(run.sway(replay.t)), atol=1e-9)
    assert np.abs(replay.payload[:, 1]).max() < 1e-9  # planar


def test_the_loop_path_has_breaks_where_its_acceleration_steps_or_kinks() -> None:
    """An LQRRun as a pivot path: u steps from 0 at t_start and kinks where the limit a_max starts or
    stops clipping it; these are its breaks, so the crane's integrator ends its steps there. Replayed
    in the 3-D crane, the load's offset is l sin θ of the planar loop to 2e-11 m (measured; with no
    breaks 6e-7 m, the jump at t_start smoothed over a knot interval). The loop itself is integrated
    piecewise between the switches; past its t_end the crane run is refused."""
    ctrl = crane.lqr(10.0, q=(1.0, 1.0, 50.0, 1.0), r=1.0, a_max=0.6)
    run = ctrl.simulate(distance=5.0, t_end=30.0, t_start=1.0)
    assert run.switches.size == 1 and run.breaks.tolist() == [1.0, run.switches[0]]
    ts = run.switches[0]
    _, _, u = run.trolley(np.array([ts - 1e-3, ts, ts + 1e-3]))
    assert u[0] == 0.6 and abs(u[1] - 0.6) < 1e-9 and u[2] < 0.6  # the clip lets go at the switch
    assert run.trolley(1.0, left=True)[2][0] == 0.0 and run.trolley(1.0)[2][0] == 0.6  # the step at t0
    c = crane.Crane(rope=10.0, pivot=run, payload_mass=500.0)
    replay = c.simulate(t_end=30.0, output_spacing=0.05, rtol=1e-11, atol=1e-11)
    np.testing.assert_allclose(replay.offset()[:, 0], 10.0 * np.sin(run.sway(replay.t)), atol=1e-9)
    with pytest.raises(InvalidInputError, match=r"ends at t_end = 30 s, .* t_end = 40 s"):
        c.simulate(t_end=40.0)


def test_bad_lqr_input() -> None:
    for kw, word in [
        ({"rope": 0.0}, "rope"),
        ({"rope": 5.0, "r": 0.0}, "r ="),
        ({"rope": 5.0, "q": (0, 1, 1, 1)}, "q ="),
        ({"rope": 5.0, "a_max": 0.0}, "a_max"),
    ]:
        with pytest.raises(InvalidInputError, match=word):
            crane.lqr(**kw)
