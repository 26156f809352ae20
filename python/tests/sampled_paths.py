"""The sampled pivots of the ``steps_on_samples`` and ``halved_steps`` tests (``test_steps_on_samples.py``,
``test_stepper_steps_on_samples.py``, ``test_stepper_halved_steps.py``): unevenly spaced sample times,
a path the spline reproduces exactly (an independent reference: ``pl.exact`` under g + its
acceleration) and a kinked one. SI units:
l = 1 m, g = 9.81 m/s², samples about 10 ms apart.
"""

from __future__ import annotations

import numpy as np

import pendulab as pl

G, A_UP = 9.81, 2.0  # gravity and the pivot's upward acceleration [m/s²]
ORDERS = {"rk4": 4.0, "rattle": 2.0, "rattle4": 4.0}


def uneven(seed: int, t_end: float = 3.3, spread: float = 0.6) -> np.ndarray:
    """Sample times [s]: two before t = 0, one at 0, then gaps of 10 ms ± spread/2 (uniform) past t_end."""
    gaps = 0.01 * (1.0 + spread * (np.random.default_rng(seed).random(int(t_end / 0.006)) - 0.5))
    t = np.concatenate([[-0.02, -0.01], np.cumsum(np.concatenate([[0.0], gaps]))])
    return t[: int(np.searchsorted(t, t_end)) + 2]


def accelerating(times: np.ndarray) -> pl.Pendulum:
    """A pivot on p(t) = (0.3 t, −0.2 t, ½·A_UP·t²) m: the not-a-knot spline through its samples is p
    itself (it reproduces cubics), p̈ = (0, 0, A_UP), so relative to the pivot the bob is the ideal
    pendulum under g + A_UP, whose exact solution (T-4.x, ``pl.exact``) is the reference."""
    path = np.stack([0.3 * times, -0.2 * times, 0.5 * A_UP * times**2], axis=-1)
    return pl.Pendulum(length=1.0, g=G, pivot_samples=(times, path), damping=0.0)


def wavy(times: np.ndarray) -> pl.Pendulum:
    """A pivot on (0.3 sin 1.3t, 0.2 sin(0.7t + 0.5), 0.1 cos 2t) m: p̈ kinked at every sample."""
    path = np.stack([0.3 * np.sin(1.3 * times), 0.2 * np.sin(0.7 * times + 0.5), 0.1 * np.cos(2 * times)], -1)
    return pl.Pendulum(length=1.0, g=G, pivot_samples=(times, path), damping=0.03)


def start(p: pl.Pendulum) -> pl.State:
    return p.state_from_angles(theta=1.3, phi=0.9, theta_dot=0.6, phi_dot=2.5)


def error(tr: pl.Trajectory, x_ref: np.ndarray) -> float:
    """The largest position error [m] over the saved samples."""
    return float(np.max(np.linalg.norm(tr.x - x_ref, axis=1)))
