#!/usr/bin/env python3
"""How fast is a fit's Jacobian by forward sensitivities (fitting/sensitivity.py, T-10.7) against
finite differences of the forward model? Issue 24's case: a rotary encoder's planar angle at 100 Hz
for 140 s (14 000 samples, 2400 steps per turn), released from 86°, a damped pendulum with dry
friction, viscous damping and drag; 6 unknowns (l, damping, drag, friction, θ₀, θ̇₀; g known).

Measured, best of ``--repeat``: one forward run (DOP853 at rtol 1e-12 at the 14 000 sample times);
the central-difference Jacobian (identify.jacobian: 12 runs); the exact Jacobian (one run of the
state + 54 sensitivities); and a whole least-squares solve (SciPy ``least_squares``, trust-region
reflective, from 1 % off) with ``pl.fit``'s forward differences against the exact Jacobian: time,
model runs, and that both reach the same cost. Prints the load average next to the times (the machine
is shared), and for ``pl.fit`` its CPU time too.
Usage: ``python bench/fit_jacobian.py [--repeat N]``. SI units.
"""

from __future__ import annotations

import argparse
import os
import time
from collections.abc import Callable

import numpy as np
import pendulab as pl
from pendulab.fitting.data import observations
from pendulab.fitting.identify import jacobian
from pendulab.fitting.problem import Problem, model_params
from pendulab.fitting.sensitivity import exact_jacobian
from scipy.optimize import least_squares

TRUE = {"length": 0.45, "damping": 0.004, "drag": 0.02, "friction": 0.015, "theta0": 1.5, "theta_dot0": 0.0}
FREE = list(TRUE)


def best_of(fn: Callable[[], object], repeat: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def problem() -> Problem:
    t = np.arange(14_000) * 0.01
    p = pl.Pendulum(
        TRUE["length"], 9.80, 1.0, model="damped", **{k: TRUE[k] for k in ("damping", "drag", "friction")}
    )
    tr = pl.simulate(
        p, p.state_from_angles(TRUE["theta0"], 0.0, 0.0, 0.0), t[-1], method="dop853", rtol=1e-12, save_at=t
    )
    step = 2 * np.pi / 2400  # the encoder's quantisation
    theta = np.round(np.arctan2(tr.x[:, 0], -tr.x[:, 2]) / step) * step
    defaults = {k: float(s["default"]) for k, s in model_params("damped").items()}
    values = {**defaults, "g": 9.80, "mass": 1.0, "phi0": 0.0, "phi_dot0": 0.0, **TRUE}
    return Problem("damped", values, FREE, observations(t, {"planar_angle": theta}))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--repeat", type=int, default=3)
    repeat = ap.parse_args().repeat
    prob = problem()
    sigma = {"planar_angle": 2 * np.pi / 2400 / np.sqrt(12)}
    u_true = np.array([TRUE[n] for n in FREE])
    print(f"{prob.obs.t.size} samples, {len(FREE)} unknowns ({', '.join(FREE)}); load {os.getloadavg()}")

    def fun(u: np.ndarray) -> np.ndarray:
        return prob.residuals(prob.with_free(u), sigma)

    def jac(u: np.ndarray) -> np.ndarray:
        out = exact_jacobian(prob, prob.with_free(u), sigma)
        assert out is not None
        return out

    t_fwd, _ = best_of(lambda: fun(u_true), repeat)
    scales = np.maximum(np.abs(u_true), 1e-3)
    t_fd, j_fd = best_of(lambda: jacobian(fun, u_true, 1e-5 * scales), repeat)
    t_ex, j_ex = best_of(lambda: jac(u_true), repeat)
    assert isinstance(j_fd, np.ndarray) and isinstance(j_ex, np.ndarray)
    rel = np.max(np.abs(j_ex - j_fd), axis=0) / np.max(np.abs(j_fd), axis=0)
    print(f"one forward run          {t_fwd:7.3f} s")
    print(f"Jacobian, central diff.  {t_fd:7.3f} s  ({2 * len(FREE)} runs)")
    print(f"Jacobian, sensitivities  {t_ex:7.3f} s  (largest column difference {rel.max():.1e} relative)")

    u0 = u_true * np.array([1.01, 1.2, 1.2, 1.2, 1.01, 1.0]) + np.array([0, 0, 0, 0, 0, 0.01])
    lower = [1e-3, 0.0, 0.0, 0.0, 0.0, -np.inf]
    upper = [10.0, 1e4, 1e4, 1e4, np.pi, np.inf]
    common = {"bounds": (lower, upper), "x_scale": scales, "method": "trf", "xtol": 1e-10, "ftol": 1e-10}
    for label, kw in (
        ("forward differences (pl.fit)", {"diff_step": 1e-8}),
        ("exact (sensitivities)", {"jac": jac}),
    ):
        prob.evaluations = 0
        t0 = time.perf_counter()
        res = least_squares(fun, u0, **common, **kw)
        took = time.perf_counter() - t0
        print(
            f"solve, {label:28s} {took:7.2f} s  cost {res.cost:.6e}  residual runs {res.nfev}, "
            f"Jacobians {res.njev}; max |u - truth|/truth {np.max(np.abs(res.x - u_true) / scales):.1e}"
        )
    theta = prob.obs.values["planar_angle"][:, 0]
    for _ in range(2):  # pl.fit as a user calls it: sigma left out, starting values read off the data
        t0, cpu0 = time.perf_counter(), time.process_time()
        res = pl.fit(
            prob.obs.t,
            planar_angle=theta,
            pendulum=pl.Pendulum(0.4, 9.80, model="damped"),
            fit=["length", "damping", "drag", "friction"],
            progress=False,
        )
        took, cpu = time.perf_counter() - t0, time.process_time() - cpu0
        off = max(
            abs(res.params[n] - TRUE[n]) / res.stderr[n] for n in ("length", "damping", "drag", "friction")
        )
        print(
            f"pl.fit (sigma left out)  {took:7.2f} s  ({cpu:.2f} s of CPU: the figure to compare on a "
            f"busy machine)  model runs {res.evaluations}, largest |error|/stderr {off:.2g}"
        )
    print(f"load after {os.getloadavg()}")


if __name__ == "__main__":
    main()
