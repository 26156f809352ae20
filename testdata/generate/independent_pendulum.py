"""Independent test data for ``pl.fit``: a spherical pendulum integrated by SciPy, not by Pendulab.

Nothing here imports ``pendulab``: the model is written out by hand so that a fit validated on these
data is validated against a different code (issues 23 and 24, item 7). Units: SI throughout (m, s,
rad, m/s², 1/s, 1/m).

The model (docs/theory.md T-2.2, T-7.1, written in Cartesian coordinates with a Lagrange multiplier):
the bob at x ∈ R³ relative to the pivot, |x| = l, z up, gravity −g e_z, and applied forces per mass

    f(x, v) = w                                   steady wind (a uniform force per mass, m/s²)
              − c v                               viscous damping (c [1/s])
              − c_q |v| v                         quadratic drag (c_q [1/m])
              − μ tanh(|v| / v_ε) v / |v|         dry (Coulomb) pivot friction: a constant friction
                                                  torque m μ l at the pivot, regularised smoothly
                                                  below the speed v_ε (μ [m/s²], v_ε [m/s])

    ẍ = −g e_z + f + λ x,   λ = −(|v|² + x·(f − g e_z) + 2 α x·v + ½ α² (|x|² − l²)) / |x|²,

where λ x is the rod's pull per mass: with α = 0, λ keeps d²|x|²/dt² = 0 exactly; the Baumgarte
terms make the constraint error C = |x|² − l² obey C̈ + 2αĊ + α²C = 0 (critically damped, α = ω₀ =
√(g/l)), so round-off drift off |x| = l decays instead of growing where the rod pushes (θ > π/2);
they vanish on the constraint.
All forces are applied in full (the rod removes their radial part through λ). The state is
(x, v, W) with W = ∫ f·v dt the work of the applied forces, so that E(t) − E(0) − W(t) = 0 checks
the integration (E = ½|v|² + g z per mass). Integration: ``scipy.integrate.solve_ivp`` with DOP853,
rtol 1e-12, atol 1e-13·l, dense output evaluated at the sample times.

Sensors (``measure``): positions (with a pivot offset in the camera's frame, a camera scale error,
(x, z) only for a camera looking along y), angles (θ, φ), a planar encoder angle atan2(x, −z) with a
zero offset and quantisation to 2π/steps, a phone's |ẍ − g⃗| (+ an accelerometer bias on the
magnitude) and gyroscope |x × v|/l²; noise white, AR(1)-correlated (lag-1 correlation ρ, marginal σ)
and outliers (a fraction of samples displaced by ±(10…30) σ).

Usage from Python (``bench/fit_validate.py``, ``python/tests/test_fit_independent.py``)::

    sys.path.insert(0, "testdata/generate"); import independent_pendulum as ip
    truth = ip.Truth(length=0.6, damping=0.01)
    x, v, a = ip.simulate(truth, ip.start_state(truth, 0.5, 0.2), t)
    xz = ip.measure_positions(x, rng, sigma=1e-3, pivot=(0.3, 1.2), columns=(0, 2))

``python testdata/generate/independent_pendulum.py --check`` runs the self-checks (exact period of a
planar swing, energy, J_z, the constraint, the work balance with every force on).
"""

from __future__ import annotations

import argparse
import math
import sys
from dataclasses import dataclass

import numpy as np
from scipy.integrate import solve_ivp
from scipy.special import ellipk

RTOL = 1e-12


@dataclass(frozen=True)
class Truth:
    """The true pendulum (SI): rod length l [m], g [m/s²], viscous damping c [1/s], quadratic drag
    c_q [1/m], Coulomb pivot friction μ [m/s²] (tangential deceleration) regularised below v_ε [m/s],
    a steady wind force per mass (wx, wy, wz) [m/s²]."""

    length: float = 1.0
    g: float = 9.81
    damping: float = 0.0
    drag: float = 0.0
    coulomb: float = 0.0
    coulomb_speed: float = 1e-3
    wind: tuple[float, float, float] = (0.0, 0.0, 0.0)


def applied(truth: Truth, v: np.ndarray) -> np.ndarray:
    """The applied force per mass f(v) [m/s²] (without gravity); v is (3,) or (N, 3)."""
    v = np.asarray(v, dtype=float)
    speed = np.linalg.norm(v, axis=-1, keepdims=True)
    f = np.asarray(truth.wind, dtype=float) - truth.damping * v - truth.drag * speed * v
    if truth.coulomb:
        with np.errstate(invalid="ignore", divide="ignore"):
            unit = np.where(speed > 0.0, v / np.where(speed > 0.0, speed, 1.0), 0.0)
        f = f - truth.coulomb * np.tanh(speed / truth.coulomb_speed) * unit
    return f


def _rhs(truth: Truth):
    ell2 = truth.length**2
    alpha = math.sqrt(abs(truth.g) / truth.length)  # Baumgarte constant [1/s]
    down = np.array([0.0, 0.0, -truth.g])

    def rhs(_t: float, y: np.ndarray) -> np.ndarray:
        x, v = y[0:3], y[3:6]
        f = applied(truth, v)
        total = f + down
        r2 = x @ x
        lam = -(v @ v + x @ total + 2.0 * alpha * (x @ v) + 0.5 * alpha**2 * (r2 - ell2)) / r2
        return np.concatenate([v, total + lam * x, [f @ v]])

    return rhs


def start_state(truth: Truth, theta: float, phi: float = 0.0, theta_dot: float = 0.0, phi_dot: float = 0.0):
    """A state on the sphere from spherical angles (θ from the downward vertical, azimuth φ) and their
    rates [rad/s]: x = l (sin θ cos φ, sin θ sin φ, −cos θ)."""
    ell = truth.length
    st, ct, sp, cp = math.sin(theta), math.cos(theta), math.sin(phi), math.cos(phi)
    x = ell * np.array([st * cp, st * sp, -ct])
    e_theta = np.array([ct * cp, ct * sp, st])
    e_phi = np.array([-sp, cp, 0.0])
    v = ell * (theta_dot * e_theta + st * phi_dot * e_phi)
    return x, v


def simulate(
    truth: Truth, state: tuple[np.ndarray, np.ndarray], t: np.ndarray, t_start: float = 0.0
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Integrates from ``state`` = (x, v) at time ``t_start`` [s] and returns x, v, ẍ (N, 3) and the
    work W (N,) at the sample times ``t`` (all ≥ t_start; sampling may start mid-swing)."""
    t = np.asarray(t, dtype=float)
    x0, v0 = state
    y0 = np.concatenate([x0, v0, [0.0]])
    sol = solve_ivp(
        _rhs(truth),
        (t_start, float(t[-1])),
        y0,
        method="DOP853",
        rtol=RTOL,
        atol=1e-13 * truth.length,
        t_eval=t,
    )
    if not sol.success:  # pragma: no cover - a bad truth
        raise RuntimeError(f"solve_ivp failed: {sol.message}")
    y = sol.y.T
    x, v, work = y[:, 0:3], y[:, 3:6], y[:, 6]
    rhs = _rhs(truth)
    acc = np.array([rhs(0.0, row)[3:6] for row in y])
    return x, v, acc, work


# --- sensors and noise -------------------------------------------------------------------------


def noise(rng: np.random.Generator, shape: tuple[int, ...], sigma: float, rho: float = 0.0) -> np.ndarray:
    """Gaussian noise of marginal standard deviation σ, AR(1) along axis 0 with lag-1 correlation ρ
    (white for ρ = 0): e_i = ρ e_{i−1} + √(1 − ρ²) σ ξ_i, started in its stationary law."""
    xi = rng.standard_normal(shape)
    if rho == 0.0:
        return sigma * xi
    e = np.empty(shape)
    e[0] = sigma * xi[0]
    scale = sigma * math.sqrt(1.0 - rho * rho)
    for i in range(1, shape[0]):
        e[i] = rho * e[i - 1] + scale * xi[i]
    return e


def outliers(rng: np.random.Generator, values: np.ndarray, sigma: float, fraction: float) -> np.ndarray:
    """Displaces a ``fraction`` of the rows by ±(10…30) σ in every column (a tracker's wrong blob)."""
    out = values.copy()
    rows = rng.random(values.shape[0]) < fraction
    kick = rng.uniform(10.0, 30.0, size=values[rows].shape) * rng.choice([-1.0, 1.0], size=values[rows].shape)
    out[rows] = out[rows] + sigma * kick
    return out


def measure_positions(
    x: np.ndarray,
    rng: np.random.Generator,
    sigma: float,
    pivot: tuple[float, ...] = (0.0, 0.0, 0.0),
    columns: tuple[int, ...] = (0, 1, 2),
    scale: float = 1.0,
    rho: float = 0.0,
    outlier_fraction: float = 0.0,
) -> np.ndarray:
    """Positions [m] as a camera or motion capture reads them: (x + pivot)·scale (a scale error of the
    ruler in the video), the chosen columns ((0, 2): a camera looking along y), plus noise."""
    p = (x + np.asarray(pivot, dtype=float)) * scale
    p = p[:, list(columns)]
    p = p + noise(rng, p.shape, sigma, rho)
    return outliers(rng, p, sigma, outlier_fraction) if outlier_fraction else p


def measure_angles(x: np.ndarray, rng: np.random.Generator, sigma: float) -> tuple[np.ndarray, np.ndarray]:
    """(θ, φ) [rad] with noise σ on θ and on the arc sin θ·φ (isotropic on the sphere)."""
    theta = np.arctan2(np.hypot(x[:, 0], x[:, 1]), -x[:, 2])
    phi = np.arctan2(x[:, 1], x[:, 0])
    return theta + sigma * rng.standard_normal(len(theta)), phi + sigma * rng.standard_normal(
        len(phi)
    ) / np.sin(theta)


def measure_encoder(
    x: np.ndarray,
    rng: np.random.Generator,
    sigma: float = 0.0,
    offset: float = 0.0,
    steps: int = 0,
    rho: float = 0.0,
) -> np.ndarray:
    """A rotary encoder's planar angle [rad]: atan2(x, −z) + a zero ``offset``, plus noise, then
    rounded to 2π/``steps`` (0: not quantised; 2400 steps per turn: a step of 2.6 mrad)."""
    a = np.arctan2(x[:, 0], -x[:, 2]) + offset
    a = a + noise(rng, a.shape, sigma, rho) if sigma else a
    if steps:
        q = 2.0 * math.pi / steps
        a = q * np.round(a / q)
    return a


def measure_phone(
    truth: Truth,
    x: np.ndarray,
    v: np.ndarray,
    acc: np.ndarray,
    rng: np.random.Generator,
    sigma_force: float,
    sigma_rate: float,
    bias: float = 0.0,
) -> tuple[np.ndarray, np.ndarray]:
    """A phone on the bob: |ẍ − g⃗| [m/s²] (+ a constant ``bias`` on the magnitude: an accelerometer
    offset along the rod, where the reading points) and |x × v|/l² [rad/s], each with white noise."""
    gvec = np.array([0.0, 0.0, -truth.g])
    f = np.linalg.norm(acc - gvec, axis=1) + bias
    w = np.linalg.norm(np.cross(x, v), axis=1) / truth.length**2
    return f + sigma_force * rng.standard_normal(len(f)), w + sigma_rate * rng.standard_normal(len(w))


# --- self-checks --------------------------------------------------------------------------------


def planar_period(truth: Truth, amplitude: float) -> float:
    """The exact period [s] of a planar swing of amplitude θ₀: 4 K(k²)/ω₀, k = sin(θ₀/2)."""
    return 4.0 * float(ellipk(math.sin(amplitude / 2.0) ** 2)) / math.sqrt(truth.g / truth.length)


def check() -> dict[str, float]:
    """The generator's own checks (no Pendulab): the exact period of a 2.5 rad planar swing from the
    crossings of x, energy and J_z of a conservative elliptical swing over 60 s, and the work balance
    E − E₀ − W with every force on. Returns the errors (all should be ≲ 1e-9)."""
    out: dict[str, float] = {}
    truth = Truth(length=0.7, g=9.81)
    amp = 2.5
    period = planar_period(truth, amp)
    t = np.linspace(0.0, 10.0 * period, 20001)
    x, v, _, _ = simulate(truth, start_state(truth, amp), t)
    s = x[:, 0]
    idx = np.nonzero((s[:-1] > 0.0) & (s[1:] <= 0.0))[0]  # downward crossings of x = 0, one per period
    # refine by the velocity (x crosses zero with speed v_x): t* = t_i − s_i / v_i
    crossings = t[idx] - s[idx] / v[idx, 0]
    measured = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
    out["period_rel"] = abs(measured / period - 1.0)
    truth3 = Truth(length=1.3, g=9.79)
    t3 = np.linspace(0.0, 60.0, 6001)
    x3, v3, _, _ = simulate(truth3, start_state(truth3, 1.1, 0.3, 0.4, 1.7), t3)
    energy = 0.5 * np.einsum("ij,ij->i", v3, v3) + truth3.g * x3[:, 2]
    jz = x3[:, 0] * v3[:, 1] - x3[:, 1] * v3[:, 0]
    out["energy_rel"] = float(np.max(np.abs(energy - energy[0])) / (truth3.g * truth3.length))
    out["jz_rel"] = float(np.max(np.abs(jz - jz[0])) / abs(jz[0]))
    out["constraint_rel"] = float(np.max(np.abs(np.linalg.norm(x3, axis=1) / truth3.length - 1.0)))
    full = Truth(length=0.9, g=9.8, damping=0.02, drag=0.05, coulomb=0.01, wind=(0.2, -0.1, 0.0))
    xf, vf, _, wf = simulate(full, start_state(full, 0.8, 0.1, 0.2, 0.9), t3)
    ef = 0.5 * np.einsum("ij,ij->i", vf, vf) + full.g * xf[:, 2]
    out["work_balance_rel"] = float(np.max(np.abs(ef - ef[0] - wf)) / (full.g * full.length))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="run the self-checks; exit 1 if any error > 1e-9")
    args = ap.parse_args()
    errors = check()
    for k, e in errors.items():
        print(f"{k:18s} {e:.2e}")
    if args.check and max(errors.values()) > 1e-9:
        sys.exit(1)


if __name__ == "__main__":
    main()
