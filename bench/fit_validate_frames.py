"""The data of ``bench/fit_validate.py``'s cases in a rotating frame and below a slewing pivot: a
hand-written Cartesian model integrated by SciPy's DOP853 (no Pendulab code), filmed from the side as
(x, z) by ``independent_pendulum.measure_positions``.

The bob at x ∈ R³ relative to the pivot, |x| = l, z up, held on the sphere by a Lagrange multiplier
λ (Baumgarte-stabilised at α = √(g/l), as testdata/generate/independent_pendulum.py):

- a frame turning at Ω = |Ω| (0, cos λ_L, sin λ_L) (docs/theory.md T-7.3, a turntable or the Earth at
  latitude λ_L): ẍ = −g e_z − c v − 2 Ω × v − Ω × (Ω × x) + λ x;
- a slewing crane's boom tip p(t) = (R cos ωt, R sin ωt, h) (T-7.2), t from the record's first sample:
  ẍ = −g e_z − p̈(t) + λ x with p̈ = −ω² (p − h e_z); the camera sees the bob at p(t) + x.

In both, λ = −(|v|² + x·f + 2α x·v + ½α² (|x|² − l²))/|x|² for the applied acceleration f, so that
d²(|x|² − l²)/dt² = −2α d(|x|² − l²)/dt − α²(|x|² − l²). ``python/tests/test_fit_independent.py``
does not cover these: :func:`check` holds |x| = l and, in the turning frame, the Jacobi integral
½|v|² + g z − ½|Ω × x|² (Coriolis does no work) without damping, and ``--check`` prints both.
Units SI: t [s], positions [m], rates [rad/s], latitude [rad], accelerations [m/s²].
"""

from __future__ import annotations

import functools
import math
import sys
from collections.abc import Callable
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "testdata" / "generate"))
import independent_pendulum as ip
from fit_validate_data import Data

RTOL = 1e-12


def _omega(frame_rate: float, latitude: float) -> np.ndarray:
    """Ω [rad/s] in (east, north, up) axes."""
    return frame_rate * np.array([0.0, math.cos(latitude), math.sin(latitude)])


def _rhs(length: float, g: float, force: Callable[[float, np.ndarray, np.ndarray], np.ndarray]) -> Callable:
    alpha = math.sqrt(abs(g) / length)
    ell2 = length**2

    def rhs(t: float, y: np.ndarray) -> np.ndarray:
        x, v = y[:3], y[3:]
        f = force(t, x, v)
        r2 = x @ x
        lam = -(v @ v + x @ f + 2.0 * alpha * (x @ v) + 0.5 * alpha**2 * (r2 - ell2)) / r2
        return np.concatenate([v, f + lam * x])

    return rhs


def turning_force(g: float, damping: float, omega: np.ndarray) -> Callable:
    """f(t, x, v) [m/s²] in the turning frame: gravity, damping, Coriolis and centrifugal."""
    down = np.array([0.0, 0.0, -g])
    return lambda _t, x, v: (
        down - damping * v - 2.0 * np.cross(omega, v) - np.cross(omega, np.cross(omega, x))
    )


def slewing_force(g: float, radius: float, rate: float) -> Callable:
    """f(t, x, v) [m/s²] below the slewing boom tip: gravity and −p̈(t) = ω² R (cos ωt, sin ωt, 0)."""
    return lambda t, _x, _v: np.array(
        [rate**2 * radius * math.cos(rate * t), rate**2 * radius * math.sin(rate * t), -g]
    )


@functools.cache
def motion(
    length: float,
    g: float,
    kind: str,
    p: tuple[float, ...],
    start: tuple[float, ...],
    t_end: float,
    dt: float,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """t [s] (from 0, step ``dt``) and x, v (N, 3) released at ``start`` = (θ, φ, θ̇, φ̇) at t = 0:
    ``kind`` "turning" with p = (frame_rate, latitude, damping), "slewing" with p = (radius, rate)."""
    force = turning_force(g, p[2], _omega(p[0], p[1])) if kind == "turning" else slewing_force(g, p[0], p[1])
    x0, v0 = ip.start_state(ip.Truth(length=length, g=g), *start)
    t = np.arange(0.0, t_end, dt)
    sol = solve_ivp(
        _rhs(length, g, force),
        (0.0, float(t[-1])),
        np.concatenate([x0, v0]),
        method="DOP853",
        rtol=RTOL,
        atol=1e-13 * length,
        t_eval=t,
    )
    if not sol.success:  # pragma: no cover - a bad truth
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    return t, sol.y[:3].T, sol.y[3:].T


def turning(
    *,
    length: float = 0.6,
    g: float = 9.81,
    damping: float = 0.01,
    frame_rate: float = 0.4,
    latitude: float = 0.9,
    start: tuple[float, float, float, float] = (0.5, 0.0, 0.0, 0.8),
    duration: float = 15.0,
    fps: float = 30.0,
    pivot: tuple[float, float, float] = (0.31, 0.0, 1.25),
    sigma: float = 1.5e-3,
) -> Callable[[np.random.Generator, float], Data]:
    """A pendulum on a turntable (Ω = ``frame_rate`` at ``latitude``) filmed as (x, z) from the turning
    frame, released at ``start`` at the first frame, for ``duration`` s at ``fps``."""
    true = {"length": length, "g": g, "damping": damping, "pivot_x": pivot[0], "pivot_z": pivot[2]}

    def make(rng: np.random.Generator, s: float) -> Data:
        t, x, _ = motion(length, g, "turning", (frame_rate, latitude, damping), start, duration, 1.0 / fps)
        pos = ip.measure_positions(x, rng, s * sigma, pivot, (0, 2))
        return Data({"t": t, "positions": pos}, dict(true), sigma)

    return make


def slewing(
    *,
    length: float = 0.6,
    g: float = 9.81,
    radius: float = 0.3,
    rate: float = 0.5,
    height: float = 0.0,
    start: tuple[float, float, float, float] = (0.5, 0.0, 0.0, 0.8),
    duration: float = 15.0,
    fps: float = 30.0,
    pivot: tuple[float, float, float] = (0.31, 0.0, 1.25),
    sigma: float = 1.5e-3,
) -> Callable[[np.random.Generator, float], Data]:
    """A bob below a slewing boom tip (``radius`` [m], ``rate`` [rad/s], ``height`` [m]; the boom along
    x at the first frame) filmed as (x, z) of p(t) + x from a fixed camera whose origin is −``pivot``
    from the slewing axis' foot (the fitted pivot offset)."""
    true = {"length": length, "g": g, "pivot_x": pivot[0], "pivot_z": pivot[2]}

    def make(rng: np.random.Generator, s: float) -> Data:
        t, x, _ = motion(length, g, "slewing", (radius, rate), start, duration, 1.0 / fps)
        boom = np.column_stack(
            [radius * np.cos(rate * t), radius * np.sin(rate * t), np.full_like(t, height)]
        )
        pos = ip.measure_positions(boom + x, rng, s * sigma, pivot, (0, 2))
        return Data({"t": t, "positions": pos}, dict(true), sigma)

    return make


def check() -> dict[str, float]:
    """The integrator's own errors: max ||x| − l| [m] of both, and the drift of the turning frame's
    Jacobi integral ½|v|² + g z − ½|Ω × x|² [m²/s²] without damping, over 20 s."""
    omega = _omega(0.4, 0.9)
    _, x, v = motion(0.6, 9.81, "turning", (0.4, 0.9, 0.0), (0.5, 0.0, 0.0, 0.8), 20.0, 0.01)
    jacobi = 0.5 * np.sum(v * v, axis=1) + 9.81 * x[:, 2] - 0.5 * np.sum(np.cross(omega, x) ** 2, axis=1)
    _, xs, _ = motion(0.6, 9.81, "slewing", (0.3, 0.5), (0.5, 0.0, 0.0, 0.8), 20.0, 0.01)
    return {
        "turning_length_error": float(np.max(np.abs(np.linalg.norm(x, axis=1) - 0.6))),
        "turning_jacobi_drift": float(np.max(np.abs(jacobi - jacobi[0]))),
        "slewing_length_error": float(np.max(np.abs(np.linalg.norm(xs, axis=1) - 0.6))),
    }


if __name__ == "__main__":
    if "--check" in sys.argv:
        print(check())
