#!/usr/bin/env python3
"""How fast is ``pl.fit``? The issue's case: 10⁴ samples over 60 s, 5 unknowns (g and the start, the
length known, positions with 1 mm noise) — target under 2 s on a 2-core machine — and the same for
the damped model (DOP853 forward model, g, damping and the start: 6 unknowns). Each time is also given
as a ratio to one run of its forward model measured in the same run (exact solution or DOP853 at the
10⁴ sample times), i.e. how many model runs the fit costs. Usage: ``make bench-fit``. SI units.
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Callable

import numpy as np
import pendulab as pl


def best_of(fn: Callable[[], object], repeat: int = 3) -> float:
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return min(times)


def main() -> None:
    t = np.linspace(0.0, 60.0, 10_000)
    rng = np.random.default_rng(1)
    rows = []
    for model, fitted in (("ideal", ["g"]), ("damped", ["g", "damping"])):
        p = (
            pl.Pendulum(length=1.0, g=9.81)
            if model == "ideal"
            else pl.Pendulum(length=1.0, g=9.81, damping=0.02)
        )
        s = p.state_from_angles(0.5, 0.0, 0.1, 0.6)

        def forward(p: pl.Pendulum = p, s: pl.State = s) -> np.ndarray:
            if p.is_ideal:
                return pl.exact(p, s).state(t)[0]
            return pl.simulate(p, s, 60.0, method="dop853", rtol=1e-12, atol=1e-14, save_at=t).x

        x = forward()
        data = x + 1e-3 * rng.standard_normal(x.shape)
        base = pl.Pendulum(length=1.0, model=model)
        one = best_of(forward)
        holder: dict[str, pl.FitResult] = {}

        def run(
            data: np.ndarray = data,
            base: pl.Pendulum = base,
            fitted: list[str] = fitted,
            holder: dict[str, pl.FitResult] = holder,
        ) -> None:
            holder["res"] = pl.fit(t, positions=data, pendulum=base, fit=fitted, sigma=1e-3)

        with warnings.catch_warnings():
            warnings.simplefilter("error")
            took = best_of(run, repeat=2)
        res = holder["res"]
        unknowns = len(res.names)
        rows.append((model, unknowns, took, one, res.evaluations))
        print(
            f"{model}: {unknowns} unknowns, fit {took:.3f} s, one forward run {one * 1e3:.2f} ms, "
            f"ratio {took / one:.0f}, {res.evaluations} model runs; "
            f"g = {res.params['g']:.6f} ± {res.stderr['g']:.1e}"
        )
    print()
    print("| model | unknowns | fit [s] | one forward run [ms] | fit / one run | model runs |")
    print("|---|---|---|---|---|---|")
    for model, k, took, one, n in rows:
        print(f"| {model} | {k} | {took:.2f} | {one * 1e3:.2f} | {took / one:.0f} | {n} |")


if __name__ == "__main__":
    main()
