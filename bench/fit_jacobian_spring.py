#!/usr/bin/env python3
"""How fast is the swinging spring's exact Jacobian (docs/theory.md T-10.8, fitting/spring_model.py
``motion_tangents``) against central differences of its forward model, and what does it do to a whole
``pl.fit``? The case: a spring at the 1:1:2 resonance of a 1 m hang (k/m = 39.24 1/s², l₀ = 0.75 m,
g = 9.81 m/s², m = 1 kg) filmed in 3-D at 50 Hz for ``--seconds`` (default 20 s), positions with 1 mm
of noise, the data from SciPy's DOP853 of the equations written here (not pendulab's integrators);
9 unknowns (stiffness, rest length, g and the start: θ₀, φ₀, θ̇₀, φ̇₀, r₀, ṙ₀).

Measured in one process, best of ``--repeat``: one forward run, the central-difference Jacobian
(``identify.jacobian``: 18 runs), the exact Jacobian (one run with its tangents) and the largest
relative difference of their columns; then ``pl.fit`` as a user calls it (σ left out, starting values
read off the data) with the tangents and with them switched off (the Jacobians differenced, as before
2026-11-29), alternately, wall and CPU time and model runs. Prints the load average.
Usage: ``python bench/fit_jacobian_spring.py [--repeat N] [--seconds S]``. SI units.
"""

from __future__ import annotations

import argparse
import os
import time
import warnings

import numpy as np
import pendulab as pl
from fit_jacobian import best_of  # bench/ is the script's directory, on sys.path
from pendulab.fitting import sensitivity
from pendulab.fitting.data import observations
from pendulab.fitting.identify import jacobian
from pendulab.fitting.problem import Problem
from pendulab.fitting.sensitivity import exact_jacobian
from scipy.integrate import solve_ivp

K_OVER_M, REST, G = 4.0 * 9.81, 0.75, 9.81  # 1/s², m, m/s²
START = {"theta0": 0.35, "phi0": 0.3, "theta_dot0": 0.0, "phi_dot0": 0.6, "r0": 1.03, "r_dot0": 0.0}
FREE = ["stiffness", "length", "g", *START]


def positions(seconds: float) -> tuple[np.ndarray, np.ndarray]:
    """Times [s] and noisy positions [m]: ẍ = −(k/m)(|x| − l₀) x/|x| − g e_z by SciPy's DOP853."""
    from pendulab.fitting.spring_model import start_vectors

    def rhs(_: float, s: np.ndarray) -> np.ndarray:
        x, v = s[:3], s[3:]
        r = float(np.linalg.norm(x))
        return np.concatenate([v, -K_OVER_M * (r - REST) * x / r + np.array([0.0, 0.0, -G])])

    x0, v0 = start_vectors(START)
    t = np.arange(round(50 * seconds) + 1) / 50.0
    sol = solve_ivp(rhs, (0.0, t[-1]), [*x0, *v0], "DOP853", t_eval=t, rtol=1e-12, atol=1e-12)
    assert sol.success, sol.message
    return t, sol.y[:3].T + 1e-3 * np.random.default_rng(1).standard_normal((t.size, 3))


def fit_once(t: np.ndarray, x: np.ndarray, tangents: bool) -> tuple[float, float, int, float]:
    """``pl.fit`` of the spring: wall [s], CPU [s], model runs, σ of the stiffness [N/m]."""
    kept = sensitivity.MODELS
    if not tangents:
        sensitivity.MODELS = tuple(m for m in kept if m != "spring")
    try:
        t0, cpu0 = time.perf_counter(), time.process_time()
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            res = pl.fit(
                t,
                positions=x,
                pendulum=pl.SwingingSpring(35.0, 0.8, 9.81, 1.0),
                fit="stiffness,length,g",
                progress=False,
            )
        return time.perf_counter() - t0, time.process_time() - cpu0, res.evaluations, res.stderr["stiffness"]
    finally:
        sensitivity.MODELS = kept


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--seconds", type=float, default=20.0)
    args = ap.parse_args()
    t, x = positions(args.seconds)
    values = {**START, "stiffness": K_OVER_M, "mass": 1.0, "length": REST, "g": G}
    prob = Problem(
        "spring",
        {**values, "pivot_x": 0.0, "pivot_y": 0.0, "pivot_z": 0.0},
        FREE,
        observations(t, {"positions": x}),
    )
    sigma = {"positions": 1e-3}
    u = np.array([values[n] for n in FREE])
    print(f"{t.size} samples over {t[-1]:g} s, {len(FREE)} unknowns; load {os.getloadavg()}")

    def fun(uu: np.ndarray) -> np.ndarray:
        return prob.residuals(prob.with_free(uu), sigma)

    t_fwd, _ = best_of(lambda: fun(u), args.repeat)
    t_fd, j_fd = best_of(lambda: jacobian(fun, u, 1e-6 * np.maximum(np.abs(u), 1e-2)), args.repeat)
    t_ex, j_ex = best_of(lambda: exact_jacobian(prob, prob.with_free(u), sigma), args.repeat)
    assert isinstance(j_fd, np.ndarray) and isinstance(j_ex, np.ndarray)
    rel = np.max(np.abs(j_ex - j_fd), axis=0) / np.max(np.abs(j_fd), axis=0)
    print(f"one forward run          {t_fwd:7.4f} s")
    print(f"Jacobian, central diff.  {t_fd:7.4f} s  ({2 * len(FREE)} runs)")
    print(
        f"Jacobian, tangents       {t_ex:7.4f} s  ({t_fd / t_ex:.1f}x faster; largest column difference "
        f"{rel.max():.1e} relative)"
    )
    for _ in range(args.repeat):
        for tangents in (True, False):
            wall, cpu, runs, bar = fit_once(t, x, tangents)
            label = "tangents" if tangents else "differences"
            print(
                f"pl.fit, {label:11s}  {wall:7.2f} s wall, {cpu:6.2f} s CPU, {runs} model runs, "
                f"σ(stiffness) {bar:.4g} N/m"
            )
    print(f"load after {os.getloadavg()}")


if __name__ == "__main__":
    main()
