"""Dry (Coulomb) pivot friction from Python, scenario files and every integrator (docs/theory.md T-7.6,
docs/models.md): ``pl.Pendulum(friction=ε_f)`` [rad/s²] is the ``damped`` model; the energy lost equals
the friction work m ∫ ε_f l |v| tanh(|v|/(l ω_ε)) dt on every method; a planar swing's amplitude
falls by 4 ε_f/ω₀² per period (linear decay); bad values are named. The decay laws of all three
dissipations are checked in the core (crates/pendulab-core/tests/friction.rs)."""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl
from pendulab.scenario.scenario import load_scenario

L, G = 0.8, 9.81
EPS = 0.05  # rad/s²


def _friction_work(tr: pl.Trajectory, eps: float, w_eps: float) -> np.ndarray:
    speed = np.linalg.norm(tr.v, axis=1)
    p = -eps * L * speed * np.tanh(speed / (L * w_eps))  # W/kg
    return np.concatenate([[0.0], np.cumsum(0.5 * np.diff(tr.t) * (p[1:] + p[:-1]))])


@pytest.mark.parametrize("method", ["rattle", "rattle4", "dop853", "rkmk4", "rk4"])
def test_energy_lost_is_the_friction_work(method: str) -> None:
    p = pl.Pendulum(length=L, g=G, friction=EPS, friction_speed=1e-2)
    assert p.model == "damped"
    s0 = p.state_from_angles(1.0, 0.0, 0.0, 1.0)
    kw = {"dt": 1e-3} if method != "dop853" else {"rtol": 1e-11, "save_at": np.arange(0.0, 10.0 + 1e-9, 1e-3)}
    tr = pl.simulate(p, s0, 10.0, method=method, **kw)
    lost = tr.energy - tr.energy[0]
    work = _friction_work(tr, EPS, 1e-2)  # mass 1 kg
    assert lost[-1] < -0.3  # a real loss (J)
    # the trapezoid rule's O(Δt²) error at 1 ms is ~1e-7 J; a force off by 1 % would leave 3e-3 J
    assert np.max(np.abs(lost - work)) < 2e-5, method
    assert np.max(np.abs(tr.power_balance_residual)) < 2e-5


def test_a_planar_swing_loses_4_eps_over_w0_squared_per_period() -> None:
    p = pl.Pendulum(length=L, g=G, friction=EPS)
    w0 = math.sqrt(G / L)
    tr = pl.simulate(p, p.state_from_angles(0.1, 0.0, 0.0, 0.0), 20.0, method="rattle4", dt=1e-3)
    theta = np.arctan2(tr.x[:, 0], -tr.x[:, 2])
    peaks = [theta[i] for i in range(1, len(theta) - 1) if theta[i - 1] < theta[i] >= theta[i + 1]]
    drop = -np.mean(np.diff(peaks))  # per period
    assert len(peaks) >= 5
    assert drop == pytest.approx(4.0 * EPS / w0**2, rel=2e-2)


def test_scenario_key_and_bad_values(tmp_path: Path) -> None:
    text = (
        '[pendulum]\nmodel = "damped"\nlength = 0.8\nmass = 1.0\ng = 9.81\nfriction = 0.05\n'
        "friction_speed = 0.002\n\n[initial]\ntheta_deg = 20.0\nphi_deg = 0.0\ntheta_dot = 0.0\n"
        "phi_dot = 0.0\n\n[simulation]\nt_end = 2.0\n"
    )
    f = tmp_path / "dry.toml"
    f.write_text(text)
    sc = load_scenario(f)
    tr = sc.run()
    assert tr.energy[-1] < tr.energy[0]
    f.write_text(text.replace("friction = 0.05", "friction = -1"))
    with pytest.raises(Exception, match="friction"):
        load_scenario(f)
    with pytest.raises(pl.InvalidInputError, match="friction_speed"):
        pl.Pendulum(friction=0.1, friction_speed=0.0)


def test_a_real_decay_is_dry_friction_not_viscous_damping() -> None:
    """The MultiArm Pendulum's small free decay (testdata/real, MIT licence; an encoder of 40 000 steps
    per turn): its amplitude falls by nearly the same amount every half swing. Fitted with the exact
    Jacobian from starts read off the data (period from the zero crossings, the drop per half swing),
    dry friction explains it several times better than viscous damping, and the fitted ε_f gives
    back that drop (2 ε_f/ω₀² per half swing, T-7.6)."""
    from scipy.optimize import least_squares

    from pendulab.fitting.data import observations
    from pendulab.fitting.problem import Problem, model_params
    from pendulab.fitting.sensitivity import exact_jacobian

    path = Path(__file__).resolve().parents[2] / "testdata" / "real" / "multiarm_single_small_decay.csv"
    data = np.loadtxt(path, delimiter=",", comments="#", skiprows=4)
    t, y = data[:4000, 0], -data[:4000, 1]  # 4 s, before it stops dead; mirrored so that θ₀ > 0
    above = y >= 0.0  # (a sample of exactly 0 would count twice with np.sign)
    cross = np.flatnonzero(above[1:] != above[:-1])
    period = 2.0 * float(np.mean(np.diff(t[cross])))
    w0 = 2.0 * math.pi / period
    peaks = [float(np.max(np.abs(y[a:b]))) for a, b in itertools.pairwise(cross)]
    drop = float(np.mean(-np.diff(peaks)))  # per half swing
    defaults = {k: float(s["default"]) for k, s in model_params("damped").items()}
    start = {**defaults, "g": 9.80, "mass": 1.0, "phi0": 0.0, "phi_dot0": 0.0, "length": 9.80 / w0**2}
    start.update(theta0=float(y[0]), theta_dot0=float((y[1] - y[0]) / (t[1] - t[0])))
    obs = observations(t, {"planar_angle": y})
    rms = {}
    for law, guess in (("damping", 2.0 * drop * w0 / (math.pi * 0.05)), ("friction", 0.5 * drop * w0**2)):
        free = ["length", law, "theta0", "theta_dot0"]
        prob = Problem("damped", {**start, law: guess}, free, obs)
        u0 = np.array([prob.values[k] for k in free])
        res = least_squares(
            lambda u, p=prob: p.residuals(p.with_free(u), {"planar_angle": 1.0}),
            u0,
            jac=lambda u, p=prob: exact_jacobian(p, p.with_free(u), {"planar_angle": 1.0}),
            bounds=([1e-3, 0.0, 0.0, -np.inf], np.inf),
            x_scale=np.maximum(np.abs(u0), 1e-2),
        )
        rms[law] = float(np.sqrt(np.mean(res.fun**2)))
        if law == "friction":
            eps, length = res.x[1], res.x[0]
            assert 2.0 * eps * length / 9.80 == pytest.approx(drop, rel=0.15)
    assert rms["friction"] < 1e-3 < rms["damping"]  # rad; measured 6.3e-4 and 1.7e-3
    assert rms["damping"] > 2.0 * rms["friction"]
