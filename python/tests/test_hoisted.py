"""The hoisted rope from Python (model ``hoisted``, docs/models.md "Hoisted rope", theory T-11.10):
every method of the registry against an independent code (SciPy's ``solve_ivp`` on a hand-written
Cartesian model of the rheonomic constraint |x| = l(t)), the constraint and the power balance in the
trajectory's diagnostics, a scenario file, and the clear errors. SI units (m, s, kg, rad, J, W)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.integrate import solve_ivp

import pendulab as pl

G = 9.81
L0, RATE, AMP, NU = 5.0, -0.1, 0.3, 1.3


def rope(t: float) -> tuple[float, float, float]:
    s, c = np.sin(NU * t), np.cos(NU * t)
    return L0 + RATE * t + AMP * s, RATE + AMP * NU * c, -AMP * NU**2 * s


def reference(x0: np.ndarray, v0: np.ndarray, t_end: float) -> np.ndarray:
    """ẍ = −g e₃ + Λx, Λ = (l l̈ + l̇² − |v|² + g z)/l² (the multiplier that keeps |x| = l(t))."""

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        x, v = y[:3], y[3:]
        length, ld, ldd = rope(t)
        lam = (length * ldd + ld * ld - v @ v + G * x[2]) / (length * length)
        return np.concatenate([v, lam * x - np.array([0.0, 0.0, G])])

    sol = solve_ivp(rhs, (0.0, t_end), np.concatenate([x0, v0]), method="DOP853", rtol=1e-12, atol=1e-12)
    return sol.y[:, -1]


def pendulum() -> pl.Pendulum:
    return pl.Pendulum(
        length=L0, g=G, model="hoisted", hoist_rate=RATE, hoist_amplitude=AMP, hoist_frequency=NU
    )


@pytest.mark.parametrize("method", [m["name"] for m in pl.methods()])
def test_every_method_agrees_with_scipy_on_the_moving_sphere(method: str) -> None:
    p = pendulum()
    s0 = p.state_from_angles(0.3, 0.5, theta_dot=0.1, phi_dot=0.4)
    # the start's radial velocity is the rope's: v0 + l̇(0) x̂
    v0 = s0.v + rope(0.0)[1] * s0.x / L0
    order = next(m["order"] for m in pl.methods() if m["name"] == method)
    dt = {2: 1e-3, 4: 5e-3}.get(order, 1e-2)
    tr = pl.simulate(p, s0, 4.0, method=method, dt=dt, rtol=1e-12, atol=1e-12)
    want = reference(s0.x, v0, 4.0)
    err = max(np.abs(tr.x[-1] - want[:3]).max() / L0, np.abs(tr.v[-1] - want[3:]).max() / np.sqrt(G * L0))
    assert err < 2e-6, (method, err)
    # the constraint and the power balance (hoist + damping-free fixed pivot) in the diagnostics
    l_t = L0 + RATE * tr.t + AMP * np.sin(NU * tr.t)
    np.testing.assert_allclose(np.linalg.norm(tr.x, axis=1), l_t, rtol=1e-6)
    assert np.abs(tr.radius_error).max() < 1e-6 * L0
    assert np.abs(tr.power).max() > 1.0  # the hoist works on the load
    assert np.abs(tr.power_balance_residual).max() < 1e-4 * G * L0


def test_the_tension_includes_the_hoists_acceleration() -> None:
    p = pl.Pendulum(length=L0, g=G, model="hoisted", hoist_rate=0.0, hoist_amplitude=AMP, hoist_frequency=NU)
    s0 = p.state([0.0, 0.0, -L0], [0.0, 0.0, 0.0])
    tr = pl.simulate(p, s0, 2.0, method="dop853")
    ldd = -AMP * NU**2 * np.sin(NU * tr.t)
    np.testing.assert_allclose(tr.tension, G - ldd, rtol=1e-9)  # m (g − l̈), m = 1 kg


def test_a_rope_that_would_become_too_short_is_refused_before_the_run() -> None:
    p = pl.Pendulum(length=2.0, model="hoisted", hoist_rate=-0.5)
    s0 = p.state_from_angles(0.1)
    with pytest.raises(pl.InvalidInputError, match="hoist more slowly"):
        pl.simulate(p, s0, 10.0)
    with pytest.raises(pl.InvalidInputError, match="hoist_rate"):
        pl.Pendulum(model="hoisted", hoist_rate=float("nan"))


def test_a_hoisted_scenario_file(tmp_path) -> None:  # type: ignore[no-untyped-def]
    text = (
        '[pendulum]\nmodel = "hoisted"\nlength = 10.0\nmass = 1.0\ng = 9.81\nhoist_rate = -0.025\n'
        '[initial]\ntheta = 0.06\n[simulation]\nt_end = 60.0\nmethod = "rattle4"\ndt = 0.02\n'
    )
    tr = pl.Scenario.from_toml_str(text).run()
    assert np.linalg.norm(tr.x[-1]) == pytest.approx(10.0 - 0.025 * 60.0, rel=1e-12)
    bad = text.replace("hoist_rate = -0.025", "hoist_rate = -1.0")
    with pytest.raises((pl.ScenarioError, pl.InvalidInputError), match="rope"):
        pl.Scenario.from_toml_str(bad).run()
