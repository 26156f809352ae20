"""The data of ``bench/fit_validate.py``'s cases: a trial's data and a case's description (``Data``,
``Case``), and the makers of seeded noisy data from the true motion of the independent integrator
(``testdata/generate/independent_pendulum.py``, SciPy DOP853 of a hand-written Cartesian model, no
Pendulab code): video positions (optionally 3-D, AR(1)-correlated, with outliers, a scale error),
a rotary encoder's planar angle (quantised, with a zero offset), a phone's specific force
|a − g⃗| and angular speed |ω|, angles (θ, φ), constant positions and pure noise.

Each maker returns ``make(rng, noise_scale)`` → ``Data``; ``noise_scale`` = 0 gives the noise-free
data (the ``detectability`` of bench/fit_validate.py). Units SI: t [s], positions [m], angles [rad],
specific force [m/s²], angular speed [rad/s], sampling rates [Hz].
"""

from __future__ import annotations

import functools
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "testdata" / "generate"))
import independent_pendulum as ip


@dataclass(frozen=True)
class Data:
    """One trial's data: keyword arguments of ``pl.fit`` without the pendulum (``kw``), the true
    values of the fitted parameters (``truth``), and the noise σ of the main data kind."""

    kw: dict[str, Any]
    truth: dict[str, float]
    sigma: float
    sigma_kw: Any = None  # the true noise as pl.fit's sigma= (a dict for several kinds); None: ``sigma``


@dataclass(frozen=True)
class Case:
    """name, sort (right / wrong / degenerate / units), the fitted names, the starting pendulum as
    ``pl.Pendulum`` keyword arguments, ``make(rng, noise_scale)`` → Data, a note, and the fit's loss."""

    name: str
    sort: str
    fit: list[str]
    pendulum: dict[str, Any]
    make: Callable[[np.random.Generator, float], Data]
    note: str
    loss: str = "linear"
    key: list[str] = field(default_factory=list)  # degenerate: parameters whose determination matters


@functools.cache
def traj(
    truth: ip.Truth, start: tuple[float, float, float, float], t_from: float, duration: float, dt: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """t [s] and x, v, ẍ (N, 3) of the true motion released at ``start`` = (θ, φ, θ̇, φ̇) at t = 0,
    sampled every ``dt`` from ``t_from`` for ``duration`` s (computed once per process)."""
    t = t_from + np.arange(0.0, duration, dt)
    x, v, a, _ = ip.simulate(truth, ip.start_state(truth, *start), t)
    return t, x, v, a


def video(
    truth: ip.Truth,
    *,
    start: tuple[float, float, float, float] = (0.5, 0.0, 0.0, 0.8),
    t_from: float = 1.3,
    duration: float = 15.0,
    fps: float = 30.0,
    pivot: tuple[float, float, float] = (0.31, 0.0, 1.25),
    sigma: float = 1.5e-3,
    rho: float = 0.0,
    outliers: float = 0.0,
    scale: float = 1.0,
    columns: tuple[int, ...] = (0, 2),
    start_truth: bool = False,
) -> Callable[[np.random.Generator, float], Data]:
    """A bob released at rest-or-moving ``start`` = (θ, φ, θ̇, φ̇) at t = 0 and filmed from ``t_from``
    (mid-swing) for ``duration`` s: positions (x, z) by default, the pivot at ``pivot`` in the camera's
    frame. With ``start_truth`` the truth has the start at the first sample too (theta0, phi0,
    theta_dot0, phi_dot0 [rad, rad/s]; bench/fit_validate.py mirrors phi's for a mirror-blind fit)."""
    names = {0: "pivot_x", 1: "pivot_y", 2: "pivot_z"}
    true = {
        "length": truth.length,
        "g": truth.g,
        "damping": truth.damping,
        "drag": truth.drag,
        **{names[c]: pivot[c] * scale for c in columns},  # measured = pivot' + scale·x, pivot' = scale·pivot
    }

    def make(rng: np.random.Generator, s: float) -> Data:
        t, x, v, _ = traj(truth, start, t_from, duration, 1.0 / fps)
        pos = ip.measure_positions(x, rng, s * sigma, pivot, columns, scale, rho, outliers if s else 0.0)
        started = _angles(x[0], v[0]) if start_truth else {}
        return Data({"t": t, "positions": pos}, {**true, **started}, sigma)

    return make


def _angles(x: np.ndarray, v: np.ndarray) -> dict[str, float]:
    """θ, φ [rad] and θ̇, φ̇ [rad/s] of the bob at x [m] with velocity v [m/s] (pivot at the origin;
    x = l (sin θ cos φ, sin θ sin φ, −cos θ), as ``ip.start_state``)."""
    ell = float(np.linalg.norm(x))
    theta, phi = float(np.arctan2(np.hypot(x[0], x[1]), -x[2])), float(np.arctan2(x[1], x[0]))
    e_theta = np.array([np.cos(theta) * np.cos(phi), np.cos(theta) * np.sin(phi), np.sin(theta)])
    e_phi = np.array([-np.sin(phi), np.cos(phi), 0.0])
    return {
        "theta0": theta,
        "phi0": phi,
        "theta_dot0": float(v @ e_theta) / ell,
        "phi_dot0": float(v @ e_phi) / (ell * np.sin(theta)),
    }


def encoder(
    truth: ip.Truth,
    *,
    amplitude: float,
    t_from: float,
    duration: float,
    rate: float,
    sigma: float,
    steps: int = 2400,
    offset: float = 0.0,
) -> Callable[[np.random.Generator, float], Data]:
    """A rotary encoder on a planar swing released from rest at ``amplitude`` [rad]; sampled from
    ``t_from`` at ``rate`` [Hz], white noise σ, quantised to 2π/``steps``, a zero ``offset``."""
    true = {"length": truth.length, "g": truth.g, "damping": truth.damping, "drag": truth.drag}

    def make(rng: np.random.Generator, s: float) -> Data:
        t, x, _, _ = traj(truth, (amplitude, 0.0, 0.0, 0.0), t_from, duration, 1.0 / rate)
        a = ip.measure_encoder(x, rng, s * sigma, offset, steps if s else 0)
        return Data({"t": t, "planar_angle": a}, true, float(np.hypot(sigma, 2 * np.pi / steps / 12**0.5)))

    return make


def phone(truth: ip.Truth, *, bias: float = 0.0) -> Callable[[np.random.Generator, float], Data]:
    """A phone as the bob of an elliptical swing, 100 Hz for 15 s from mid-swing: |a − g⃗| (σ 0.03
    m/s², + ``bias``) and |ω| (σ 0.005 rad/s)."""
    true = {"length": truth.length, "g": truth.g, "damping": truth.damping}

    def make(rng: np.random.Generator, s: float) -> Data:
        t, x, v, a = traj(truth, (0.45, 0.0, 0.0, 0.6), 0.7, 15.0, 0.01)
        f, w = ip.measure_phone(truth, x, v, a, rng, s * 0.03, s * 0.005, bias)
        both = {"specific_force": 0.03, "angular_speed": 0.005}
        return Data({"t": t, "specific_force": f, "angular_speed": w}, true, 0.03, both)

    return make


def angles(truth: ip.Truth) -> Callable[[np.random.Generator, float], Data]:
    def make(rng: np.random.Generator, s: float) -> Data:
        t, x, _, _ = traj(truth, (0.6, 0.2, 0.1, 0.9), 0.0, 20.0, 0.05)
        return Data({"t": t, "angles": ip.measure_angles(x, rng, s * 2e-3)}, {"g": truth.g}, 2e-3)

    return make


def constant(value: tuple[float, ...], sigma: float, n: int = 400) -> Callable[..., Data]:
    t = np.arange(n) / 30.0

    def make(rng: np.random.Generator, s: float) -> Data:
        pos = np.tile(np.asarray(value, dtype=float), (n, 1)) + sigma * rng.standard_normal((n, len(value)))
        return Data({"t": t, "positions": pos}, {}, max(sigma, 1e-12))

    return make


def pure_noise(rng_sigma: float = 0.01) -> Callable[..., Data]:
    t = np.arange(0.0, 20.0, 0.02)

    def make(rng: np.random.Generator, s: float) -> Data:
        return Data({"t": t, "planar_angle": rng_sigma * rng.standard_normal(len(t))}, {}, rng_sigma)

    return make


def also(make: Callable[[np.random.Generator, float], Data], **truth: float) -> Callable[..., Data]:
    """``make`` with more true values: the systematic terms a case fits (scale, angle_offset, …)."""

    def more(rng: np.random.Generator, s: float) -> Data:
        d = make(rng, s)
        return Data(d.kw, {**d.truth, **truth}, d.sigma, d.sigma_kw)

    return more
