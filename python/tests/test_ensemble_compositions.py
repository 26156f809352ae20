"""simulate_ensemble with the symmetric compositions of RATTLE (method="rattle4", "rattle6",
"rattle8"; docs/theory.md T-8.2): every trajectory equals simulate() with the same method bit for bit
(both arithmetics, per-trajectory lengths, g and damping), the observed order against the exact
solution (T-4.6) is the composition's, J₃ and the sphere are kept, and the work bound counts the
sub-steps. Units SI."""

from __future__ import annotations

import numpy as np
import pytest

import pendulab as pl
from pendulab.ensemble.run import SUBSTEPS

COMPOSITIONS = ["rattle4", "rattle6", "rattle8"]


@pytest.mark.parametrize("method", COMPOSITIONS)
@pytest.mark.parametrize("arithmetic", ["unfused", "fused"])
def test_every_trajectory_equals_the_single_composition(method: str, arithmetic: str) -> None:
    p = pl.Pendulum(length=1.0, g=9.81)
    n = 53  # a block of 48 and a partial one
    states = pl.states_from_angles(p, theta=np.linspace(0.2, 2.9, n), phi_dot=np.linspace(-2, 2, n))
    lengths = np.linspace(0.6, 1.4, n)
    starts = np.hstack([states[:, :3] * lengths[:, None], states[:, 3:] * lengths[:, None]])
    gs = np.linspace(9.0, 10.0, n)
    cs = np.where(np.arange(n) % 3 == 0, 0.0, np.linspace(0.0, 0.5, n))
    for kw, rows in [({}, states), ({"length": lengths, "g": gs, "damping": cs}, starts)]:
        res = pl.simulate_ensemble(
            p, rows, 1.0, dt=0.02, method=method, arithmetic=arithmetic, save_every=25, progress=False, **kw
        )
        assert res.metadata["method"] == method and np.array_equal(res.t, [0.0, 0.5, 1.0])
        for k in (0, 1, 47, 52):
            pk = pl.Pendulum(
                length=float(lengths[k]) if kw else 1.0,
                g=float(gs[k]) if kw else 9.81,
                damping=float(cs[k]) if kw else 0.0,
            )
            s0 = pk.state(rows[k, :3], rows[k, 3:])
            tr = pl.simulate(pk, s0, 1.0, method=method, dt=0.02, arithmetic=arithmetic, save_every=25)
            assert np.array_equal(tr.x, res.x[k]) and np.array_equal(tr.v, res.v[k]), (kw.keys(), k)


def test_observed_order_against_the_exact_solution() -> None:
    """Final-position error after 5 s against pl.exact for dt and dt/2: log₂ of the ratio is the
    method's order (2, 4, 6, 8; at steps where the errors are asymptotic: 2.00, 4.04, 6.15, 8.1
    measured)."""
    p = pl.Pendulum(length=1.0, g=9.81)
    states = pl.states_from_angles(p, theta=np.linspace(0.4, 1.6, 8), phi_dot=np.linspace(0.5, 2.5, 8))
    exact = np.array([pl.exact(p, p.state(s[:3], s[3:])).state(5.0).x for s in states])

    def error(method: str, dt: float) -> float:
        r = pl.simulate_ensemble(p, states, 5.0, dt=dt, method=method, summary=False, progress=False)
        return float(np.max(np.linalg.norm(r.final_x - exact, axis=1)))

    steps = [("rattle", 2, 0.01), ("rattle4", 4, 0.025), ("rattle6", 6, 0.05), ("rattle8", 8, 0.025)]
    for method, order, dt in steps:
        e1, e2 = error(method, dt), error(method, dt / 2)
        observed = np.log2(e1 / e2)
        assert abs(observed - order) < 0.35, f"{method}: errors {e1:.3e}, {e2:.3e}, order {observed:.2f}"


def test_observed_order_with_damping_against_an_independent_integrator() -> None:
    """Linear damping c = 0.3/s (the damping flow on either side of each sub-step keeps every
    sub-step symmetric, so the compositions keep their order): errors after 5 s against the DOP853
    ensemble at rtol 1e-13 (measured: 2.00, 4.03, 6.10, 8.09)."""
    p = pl.Pendulum(length=1.0, g=9.81, damping=0.3)
    states = pl.states_from_angles(p, theta=np.linspace(0.4, 1.6, 8), phi_dot=np.linspace(0.5, 2.5, 8))
    ref = pl.simulate_ensemble(p, states, 5.0, method="dop853", rtol=1e-13, atol=1e-15, progress=False)

    def error(method: str, dt: float) -> float:
        r = pl.simulate_ensemble(p, states, 5.0, dt=dt, method=method, summary=False, progress=False)
        return float(np.max(np.linalg.norm(r.final_x - ref.final_x, axis=1)))

    for method, order, dt in [
        ("rattle", 2, 0.01),
        ("rattle4", 4, 0.025),
        ("rattle6", 6, 0.05),
        ("rattle8", 8, 0.025),
    ]:
        observed = np.log2(error(method, dt) / error(method, dt / 2))
        assert abs(observed - order) < 0.35, f"{method}: order {observed:.2f}"


def test_summary_and_settle_time_are_taken_after_every_full_step() -> None:
    """With a composition the summary and the settle time see the state after each full step of dt
    (not the sub-steps): the extremes of z, the crossings of the pivot's plane and the settle time
    equal those of simulate() with the same method saved at every step; damped, g > 0 and g < 0."""
    theta_s, dt, t_end = 0.05, 0.02, 20.0
    settled = 0
    for g, c in [(9.81, 0.5), (-9.81, 0.3)]:
        p = pl.Pendulum(length=1.0, g=g, damping=c)
        theta = np.array([0.3, 1.2, 2.0]) if g > 0 else np.pi - np.array([0.3, 1.2, 2.0])
        states = pl.states_from_angles(p, theta=theta, phi_dot=[0.5, -1.0, 2.0], theta_dot=[0.0, 3.0, 6.0])
        for method in ["rattle4", "rattle6"]:
            res = pl.simulate_ensemble(
                p, states, t_end, dt=dt, method=method, settle_angle=theta_s, summary=True, progress=False
            )
            assert res.summary is not None and res.settle_time is not None
            for k in range(len(states)):
                tr = pl.simulate(p, p.state(states[k, :3], states[k, 3:]), t_end, method=method, dt=dt)
                z = tr.x[1:, 2]  # the states after each full step
                assert res.summary["z_min"][k] == min(states[k, 2], z.min()), (g, method, k)
                assert res.summary["z_max"][k] == max(states[k, 2], z.max()), (g, method, k)
                above = np.concatenate([[states[k, 2] > 0.0], z > 0.0])
                assert res.summary["crossings"][k] == np.count_nonzero(np.diff(above)), (g, method, k)
                out = np.flatnonzero(z * -np.sign(g) < np.cos(theta_s))  # outside the settle band
                steps = len(z)  # z[i] is after step i + 1; settled from the step after the last one out
                expected = 0.0 if out.size == 0 else np.inf if out[-1] + 1 == steps else (out[-1] + 2) * dt
                assert res.settle_time[k] == pytest.approx(expected, abs=1e-12), (g, method, k)
                settled += bool(0.0 < expected < np.inf)
    assert settled >= 4  # the comparison covered runs that settle, not only the never-settled


def test_structure_kept_and_no_energy_drift() -> None:
    """rattle4 and rattle6 at 20 ms over 20 s and over 200 s (~100 periods): J₃ to round-off, |x| = l,
    x·v = 0, and the energy error bounded: its range over 200 s is that over the first 20 s (a
    method whose energy drifts would show ten times more)."""
    p = pl.Pendulum(length=1.0, g=9.81)
    states = pl.states_from_angles(p, theta=np.linspace(0.3, 2.8, 16), phi_dot=np.linspace(-3, 3, 16))
    for method in ["rattle4", "rattle6"]:
        drift = {}
        for t_end in [20.0, 200.0]:
            r = pl.simulate_ensemble(p, states, t_end, dt=0.02, method=method, progress=False)
            assert r.summary is not None
            assert np.max(r.summary["j3_drift"]) < 1e-13
            drift[t_end] = r.summary["energy_drift"]
            x, v = r.final_x, r.final_v
            assert np.max(np.abs(np.linalg.norm(x, axis=1) - 1.0)) < 1e-14
            assert np.max(np.abs(np.einsum("ij,ij->i", x, v))) < 1e-13
        assert np.all(drift[200.0] < 1.05 * drift[20.0] + 1e-15), method


def test_bad_method_and_the_work_bound_counts_sub_steps() -> None:
    p = pl.Pendulum()
    states = pl.states_from_angles(p, theta=[0.5, 1.0])
    for bad in ["rk4", "rkmk4", "RATTLE4", 4, None]:
        with pytest.raises(pl.InvalidInputError, match="rattle4"):
            pl.simulate_ensemble(p, states, 1.0, method=bad)  # type: ignore[arg-type]
    assert SUBSTEPS == {"rattle": 1, "rattle4": 3, "rattle6": 7, "rattle8": 15}
    # 2 trajectories × 4·10⁹ steps = 8·10⁹ RATTLE steps: allowed; ×15 sub-steps = 1.2·10¹¹: refused
    # before anything runs (the limit is 10¹⁰), the message naming that product and its factors
    with pytest.raises(pl.InvalidInputError) as e:
        pl.simulate_ensemble(p, states, 4e6, dt=1e-3, method="rattle8", progress=False)
    assert str(e.value) == (
        "the run would take 1.2e11 RATTLE steps (2 trajectories × t_end/dt = 4000000.0 s / 0.001 s = 4e9 "
        "steps × 15 RATTLE sub-steps per step of rattle8), more than the limit of 1e10: lower t_end, raise "
        "dt, use fewer trajectories or use a method of fewer sub-steps"
    ), str(e.value)
    with pytest.raises(pl.InvalidInputError) as e:  # RATTLE: no sub-steps to name
        pl.simulate_ensemble(p, states, 1e8, dt=1e-3, progress=False)
    assert str(e.value) == (
        "the run would take 2e11 RATTLE steps (2 trajectories × t_end/dt = 100000000.0 s / 0.001 s = 1e11 "
        "steps), more than the limit of 1e10: lower t_end, raise dt or use fewer trajectories"
    ), str(e.value)
