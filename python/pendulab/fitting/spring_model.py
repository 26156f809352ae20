"""The swinging spring as a forward model of :func:`pendulab.fit` (T-7.4): a bob of mass m [kg] on a
spring of stiffness k [N/m] and rest length l₀ [m], gravity g [m/s²] along −z, unconstrained in R³.

- The start at the first sample: the angles and rates of the rod models (``theta0``, ``phi0`` [rad],
  ``theta_dot0``, ``phi_dot0`` [rad/s]) plus the spring's length ``r0`` [m] and its rate ``r_dot0``
  [m/s]: x₀ = r₀ e_r, v₀ = ṙ₀ e_r + r₀ (θ̇₀ e_θ + sin θ₀ φ̇₀ e_φ).
- The motion: the core's triple jump (order 4, symplectic; T-7.4) at a step of 2e-3 / ω, ω the
  fastest of √(k/m), √(g/l) and the start's angular rate, then cubic Hermite interpolation to the
  sample times — positions from (x, v), velocities from (v, a) with a = −(k/m)(|x| − l₀) x̂ + g⃗ — so
  that the model's own error (~1e-11 relative over a hundred swings) stays far below any noise.
- The specific force an accelerometer on the bob reads is the spring's pull per mass,
  |a − g⃗| = (k/m) | |x| − l₀ |.
- Starting values from 3-D positions (:func:`spring_start`): along e_r the equation of motion is
  linear in k/m and (k/m) l₀: a·e_r + g z/r = −(k/m) r + (k/m) l₀ (g from the swing's period), a
  least-squares fit with
  accelerations from a Savitzky–Golay filter (evenly sampled data; otherwise the hanging length and
  the given stiffness are the start).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from .._core import InvalidInputError, ModelSpec, RunOptions, spring_simulate
from ..model import FloatArray

SPRING_STATE = ("r0", "r_dot0")
#: The triple jump's step is this fraction of the fastest time scale 1/ω.
STEP = 2e-3
#: At most this many steps per forward run (memory: 48 bytes per step).
MAX_STEPS = 4_000_000


def start_vectors(values: Mapping[str, float]) -> tuple[FloatArray, FloatArray]:
    """x₀ [m] and v₀ [m/s] from the angles, rates, r₀ and ṙ₀ (module doc)."""
    th, ph = values["theta0"], values["phi0"]
    thd, phd = values["theta_dot0"], values["phi_dot0"]
    r, rd = values["r0"], values["r_dot0"]
    st, ct, sp, cp = math.sin(th), math.cos(th), math.sin(ph), math.cos(ph)
    e_r = np.array([st * cp, st * sp, -ct])
    e_theta = np.array([ct * cp, ct * sp, st])
    e_phi = np.array([-sp, cp, 0.0])
    return r * e_r, rd * e_r + r * (thd * e_theta + st * phd * e_phi)


def acceleration(x: FloatArray, k_over_m: float, rest: float, g: float) -> FloatArray:
    """ẍ [m/s²] = −(k/m)(|x| − l₀) x̂ − g ẑ for positions x (N, 3)."""
    r: FloatArray = np.linalg.norm(x, axis=1)  # (N,): a norm along an axis is Any in numpy's stubs
    a = -(k_over_m * (r - rest) / np.where(r > 0.0, r, 1.0))[:, None] * x
    a[:, 2] -= g
    return a


def motion(values: Mapping[str, float], tau: FloatArray) -> tuple[FloatArray, FloatArray]:
    """x [m], v [m/s] (N, 3) at the model times ``tau`` [s] (≥ 0, ascending)."""
    k_over_m = values["stiffness"] / values["mass"]
    rest, g = values["length"], values["g"]
    x0, v0 = start_vectors(values)
    r0 = max(float(np.linalg.norm(x0)), 1e-300)
    rate = float(np.linalg.norm(v0)) / r0
    omega = max(math.sqrt(k_over_m), math.sqrt(abs(g) / max(rest, r0)), rate, 1e-300)
    span = float(tau[-1])
    n = max(1, math.ceil(span * omega / STEP))
    if n > MAX_STEPS:
        raise InvalidInputError(
            f"the spring's fit would need {n} steps per model run (record {span:g} s, time scale "
            f"{1 / omega:.3g} s); at most {MAX_STEPS}: fit a shorter record"
        )
    dt = span / n if span > 0.0 else 1.0
    spec = ModelSpec.spring_model(float(k_over_m), float(rest), float(g), float(values["mass"]))
    out = spring_simulate(spec, (x0, v0), RunOptions(dt=dt, save_every=1, order=4), int(n))
    xs, vs = out["x"], out["v"]
    if not (np.all(np.isfinite(xs)) and np.all(np.isfinite(vs))):
        raise InvalidInputError("the spring's motion diverged at these parameters")
    i = np.minimum((tau / dt).astype(np.int64), len(xs) - 2)
    s = (tau / dt - i)[:, None]
    h00, h10 = (1 + 2 * s) * (1 - s) ** 2, s * (1 - s) ** 2
    h01, h11 = s**2 * (3 - 2 * s), s**2 * (s - 1)
    x = h00 * xs[i] + h10 * dt * vs[i] + h01 * xs[i + 1] + h11 * dt * vs[i + 1]
    # the accelerations at the two steps around each sample only (row by row, the same numbers as of
    # every step: a fine run has ~40 steps per sample, and this was a fifth of the fit's time)
    acc0, acc1 = acceleration(xs[i], k_over_m, rest, g), acceleration(xs[i + 1], k_over_m, rest, g)
    v = h00 * vs[i] + h10 * dt * acc0 + h01 * vs[i + 1] + h11 * dt * acc1
    return x, v


def specific_force(x: FloatArray, values: Mapping[str, float]) -> FloatArray:
    """|a − g⃗| [m/s²] = (k/m) | |x| − l₀ |, what an accelerometer on the bob reads."""
    r: FloatArray = np.linalg.norm(x, axis=1)  # (N,): a norm along an axis is Any in numpy's stubs
    return (values["stiffness"] / values["mass"]) * np.abs(r - values["length"])


def _smoothed(t: FloatArray, rel: FloatArray, period: float | None) -> tuple[FloatArray, FloatArray] | None:
    """Positions [m] and accelerations [m/s²] of evenly sampled data by a Savitzky–Golay filter (cubic,
    over a tenth of the swing's period [s] when known), so that second differences do not
    amplify the noise; None for uneven times or too short a record."""
    from scipy.signal import savgol_filter

    dt = np.diff(t)
    if not (np.all(dt > 0.0) and float(np.ptp(dt)) <= 1e-6 * float(np.mean(dt))):
        return None
    h = float(np.mean(dt))
    width = round(0.1 * period / h) if period is not None else 7
    width = max(7, min(width, len(t) // 4)) | 1
    if width >= len(t):
        return None
    pos = savgol_filter(rel, width, 3, axis=0)
    acc = savgol_filter(rel, width, 3, deriv=2, delta=h, axis=0)
    cut = width // 2  # the ends, where the filter extrapolates
    return pos[cut:-cut], acc[cut:-cut]


def spring_start(
    t: FloatArray, rel: FloatArray, out: dict[str, Any], free: set[str], period: float | None
) -> None:
    """k/m and l₀ of a spring from 3-D positions relative to the pivot [m] by the radial equation of
    motion (module doc), where the data allow it; otherwise ``out`` stays as it is."""
    if len(t) < 16:
        return
    smooth = _smoothed(t, rel, period)
    if smooth is None:
        return
    pos, acc = smooth
    rr, zz = np.linalg.norm(pos, axis=1), pos[:, 2]
    radial = np.einsum("ij,ij->i", acc, pos) / rr
    g = out["g"]  # from the swing's period: beside the constant, −z/r ≈ 1 is nearly collinear with it
    cols = np.column_stack([-rr, np.ones_like(rr)])
    sol, *_ = np.linalg.lstsq(cols, radial + g * zz / rr, rcond=None)
    kom, kl = (float(v) for v in sol)
    if not (math.isfinite(kom) and kom > 0.0 and math.isfinite(kl) and kl > 0.0):
        return
    if "stiffness" in free:
        out["stiffness"] = kom * out["mass"]
    if "length" in free:
        out["length"] = kl / kom
