"""The swinging spring as a forward model of :func:`pendulab.fit` (T-7.4): a bob of mass m [kg] on a
spring of stiffness k [N/m] and rest length l₀ [m], gravity g [m/s²] along −z, unconstrained in R³.

- The start at the first sample: the angles and rates of the rod models (``theta0``, ``phi0`` [rad],
  ``theta_dot0``, ``phi_dot0`` [rad/s]) plus the spring's length ``r0`` [m] and its rate ``r_dot0``
  [m/s]: x₀ = r₀ e_r, v₀ = ṙ₀ e_r + r₀ (θ̇₀ e_θ + sin θ₀ φ̇₀ e_φ).
- The motion: the core's triple jump (order 4, symplectic; T-7.4) at a step of 2e-3 / ω, ω the
  fastest of √(k/m), √(g/l) and the start's angular rate, then cubic Hermite interpolation to the
  sample times — positions from (x, v), velocities from (v, a) with a = −(k/m)(|x| − l₀) x̂ + g⃗ — so
  that the model's own error (~1e-11 relative over a hundred swings) stays far below any noise. The
  core keeps only the states of the two steps around each sample (``spring_states_at``): memory in
  proportion to the samples, not to the ~40 steps per sample.
- The exact Jacobian (:func:`motion_tangents`, T-10.8): the same run with the tangents by the start
  and the parameters, interpolated the same way.
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
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from .._core import InvalidInputError, ModelSpec, RunOptions, spring_sensitivities, spring_states_at
from ..memory import check_memory
from ..model import FloatArray

IntArray = npt.NDArray[np.int64]
SPRING_STATE = ("r0", "r_dot0")
#: The start quantities the spring's tangents are carried for (their derivatives of x₀, v₀:
#: :func:`start_tangents`).
START_DIRECTIONS = ("theta0", "phi0", "theta_dot0", "phi_dot0", *SPRING_STATE)
#: The last axis of :func:`motion_tangents`: the start quantities, then the spring's parameters.
TANGENT_NAMES = (*START_DIRECTIONS, "stiffness", "mass", "length", "g")
#: The triple jump's step is this fraction of the fastest time scale 1/ω.
STEP = 2e-3
#: At most this many steps per forward run (its work; the memory is that of the ≤ 2 states per sample kept).
MAX_STEPS = 4_000_000
#: Bytes per sample of :func:`motion_tangents` at its peak: the core's states, tangents and
#: acceleration derivatives at up to two steps per sample ((6 + 3 · 3 · 9) float64 each) and the
#: interpolation's (N, 3, 10) arrays and their temporaries.
TANGENT_BYTES_PER_SAMPLE = 3000


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


@dataclass(frozen=True)
class _Run:
    """The fixed-step run a motion needs: the spring, its start, step dt [s] and step count."""

    spec: ModelSpec
    k_over_m: float
    rest: float
    g: float
    x0: FloatArray
    v0: FloatArray
    dt: float
    n: int


def _plan(values: Mapping[str, float], tau: FloatArray) -> _Run:
    """The run to the last model time ``tau[-1]`` [s] at the step of the module doc (at most
    :data:`MAX_STEPS`)."""
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
    return _Run(spec, k_over_m, rest, g, x0, v0, dt, n)


def _hermite(
    tau: FloatArray, run: _Run
) -> tuple[IntArray, IntArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """The steps the model times ``tau`` [s] need and how to interpolate there: ``keep``, the step
    numbers i and i + 1 around each time (ascending, unique), the rows a, b of ``keep`` that hold them
    per time, and the cubic Hermite weights h00, h10, h01, h11 (N, 1) at its fraction of the step."""
    i = np.minimum((tau / run.dt).astype(np.int64), run.n - 1)
    s = (tau / run.dt - i)[:, None]
    keep = np.unique(np.concatenate([i, i + 1]))
    a, b = np.searchsorted(keep, i), np.searchsorted(keep, i + 1)
    weights = ((1 + 2 * s) * (1 - s) ** 2, s * (1 - s) ** 2, s**2 * (3 - 2 * s), s**2 * (s - 1))
    return keep, np.stack([a, b]), *weights


def motion(values: Mapping[str, float], tau: FloatArray) -> tuple[FloatArray, FloatArray]:
    """x [m], v [m/s] (N, 3) at the model times ``tau`` [s] (≥ 0, ascending): the core keeps the states
    of the steps around each time only (``spring_states_at``), and they are interpolated (module doc)."""
    run = _plan(values, tau)
    keep, (a, b), h00, h10, h01, h11 = _hermite(tau, run)
    options = RunOptions(dt=run.dt, order=4)
    xs, vs = spring_states_at(run.spec, (run.x0, run.v0), keep.astype(np.uint64), options)
    if not (np.all(np.isfinite(xs)) and np.all(np.isfinite(vs))):
        raise InvalidInputError("the spring's motion diverged at these parameters")
    return _interpolated(run, (h00, h10, h01, h11), a, b, xs, vs)


def _cubic(
    w: tuple[FloatArray, ...],
    dt: float,
    q_a: FloatArray,
    rate_a: FloatArray,
    q_b: FloatArray,
    rate_b: FloatArray,
) -> FloatArray:
    """The cubic Hermite interpolant of q from its values and rates at the steps a and b around each
    time, with the weights ``w`` = (h00, h10, h01, h11) of :func:`_hermite` and the step dt [s]."""
    return w[0] * q_a + w[1] * dt * rate_a + w[2] * q_b + w[3] * dt * rate_b


def _interpolated(
    run: _Run, w: tuple[FloatArray, ...], a: IntArray, b: IntArray, xs: FloatArray, vs: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """x [m] from (x, v) and v [m/s] from (v, a) at the steps around each time (module doc): the
    accelerations at those two steps only (a fine run has ~40 steps per sample)."""
    acc0, acc1 = (
        acceleration(xs[a], run.k_over_m, run.rest, run.g),
        acceleration(xs[b], run.k_over_m, run.rest, run.g),
    )
    return _cubic(w, run.dt, xs[a], vs[a], xs[b], vs[b]), _cubic(w, run.dt, vs[a], acc0, vs[b], acc1)


def start_tangents(values: Mapping[str, float]) -> tuple[FloatArray, FloatArray]:
    """∂x₀/∂q [m per unit of q] and ∂v₀/∂q [m/s per unit] (6, 3) of :func:`start_vectors` for q in
    :data:`START_DIRECTIONS` (θ₀, φ₀ [rad], θ̇₀, φ̇₀ [rad/s], r₀ [m], ṙ₀ [m/s])."""
    th, ph = values["theta0"], values["phi0"]
    thd, phd = values["theta_dot0"], values["phi_dot0"]
    r, rd = values["r0"], values["r_dot0"]
    st, ct, sp, cp = math.sin(th), math.cos(th), math.sin(ph), math.cos(ph)
    e_r, e_theta = np.array([st * cp, st * sp, -ct]), np.array([ct * cp, ct * sp, st])
    e_phi, de_phi = np.array([-sp, cp, 0.0]), np.array([-cp, -sp, 0.0])  # de_phi = ∂e_φ/∂φ
    zero = np.zeros(3)
    dx = np.array([r * e_theta, r * st * e_phi, zero, zero, e_r, zero])
    # ∂e_r/∂θ = e_θ, ∂e_θ/∂θ = −e_r; ∂e_r/∂φ = sin θ e_φ, ∂e_θ/∂φ = cos θ e_φ
    dv = np.array(
        [
            rd * e_theta + r * (-thd * e_r + ct * phd * e_phi),
            rd * st * e_phi + r * (thd * ct * e_phi + st * phd * de_phi),
            r * e_theta,
            r * st * e_phi,
            thd * e_theta + st * phd * e_phi,
            e_r,
        ]
    )
    return dx, dv


def motion_tangents(
    values: Mapping[str, float], tau: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """x [m], v [m/s] (N, 3) at the model times ``tau`` [s] as :func:`motion` gives them (the same
    numbers), and their exact derivatives dx, dv (N, 3, 10) by :data:`TANGENT_NAMES`: the core runs the
    triple jump with its tangents (T-10.8) and gives them and the acceleration's derivatives at the
    steps around each sample, and the Hermite interpolation, linear in them, carries them there. The
    step count, a whole number, is held: the derivative is the run's at its dt."""
    run = _plan(values, tau)
    check_memory(
        f"the spring's sensitivities at {tau.size} samples",
        TANGENT_BYTES_PER_SAMPLE * tau.size,
        "fit fewer samples (thin the data)",
    )
    keep, (a, b), h00, h10, h01, h11 = _hermite(tau, run)
    options = RunOptions(dt=run.dt, order=4)
    tangents = start_tangents(values)
    xs, vs, dxs, dvs, das = spring_sensitivities(
        run.spec, (run.x0, run.v0), tangents, keep.astype(np.uint64), options
    )
    x, v = _interpolated(run, (h00, h10, h01, h11), a, b, xs, vs)
    w = tuple(h[:, :, None] for h in (h00, h10, h01, h11))  # over the directions too
    dx = _cubic(w, run.dt, dxs[a], dvs[a], dxs[b], dvs[b])
    dv = _cubic(w, run.dt, dvs[a], das[a], dvs[b], das[b])
    # k/m = stiffness/mass: ∂/∂stiffness = (1/m) ∂/∂κ, ∂/∂mass = −(κ/m) ∂/∂κ
    first, mass = len(START_DIRECTIONS), values["mass"]

    def by_names(d: FloatArray) -> FloatArray:
        kappa = d[:, :, first]
        return np.concatenate(
            [
                d[:, :, :first],
                (kappa / mass)[:, :, None],
                (-run.k_over_m / mass * kappa)[:, :, None],
                d[:, :, first + 1 :],
            ],
            axis=2,
        )

    return x, v, by_names(dx), by_names(dv)


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
