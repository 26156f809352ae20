"""What the peers benchmark measures per method (bench/peers/run.py): the work-precision scan of one
method on one case (from coarse to fine until the error stops improving, falls below ``FLOOR`` =
1e-13, one run takes more than ``cap`` seconds or the whole scan 10 times that), the exact solution's
run against the golden data, and the step rates [steps/s] at dt = 1 ms on the rosette. Every wall
time [s] is a median of repeated runs (harness.median_time); errors are |x(100 s) − x_ref|/l.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from typing import Any

import harness as hz
import numpy as np
from peers_cases import FLOOR, REPO, T_END, Case, Method, adaptive_settings, fixed_settings
from peers_engines import mujoco_model, mujoco_set_state
from peers_methods import _dp, c_library, numba_rk4

# --------------------------------------------------------------------------------------------------
# Scans


def scan(method: Method, case: Case, quick: bool, cap: float, budget: float) -> list[hz.Run]:
    run = method.prepare(case)
    settings = adaptive_settings(quick) if method.kind == "adaptive" else fixed_settings(quick)
    runs: list[hz.Run] = []
    scan_start = time.perf_counter()
    for s in settings:
        if time.perf_counter() - scan_start > 10 * cap:  # e.g. many slow failures in a row
            print(f"  {method.name:26s} {case.name:13s} scan stopped after {10 * cap:g} s", flush=True)
            break
        kind = "rtol" if method.kind == "adaptive" else "steps"
        t0 = time.perf_counter()
        try:
            wall, (x, v, steps), reps = hz.median_time(lambda s=s: run(s), budget=budget)
            x, v = np.asarray(x, dtype=float), np.asarray(v, dtype=float)
            err = hz.position_error(x, case.x_ref, case.length)
            de, dc = hz.drifts(x, v, case.x0, case.v0, case.length, case.g)
            r = hz.Run(
                method.name, case.name, float(s), kind, wall, steps, err,
                hz.state_error(x, v, case.x_ref, case.v_ref, case.length, case.omega0),
                de, dc, reps,
            )  # fmt: skip
        except Exception as exc:  # a diverged or refused run is a result too
            r = hz.Run(
                method.name, case.name, float(s), kind, time.perf_counter() - t0, 0,
                failed=f"{type(exc).__name__}: {exc}",
            )  # fmt: skip
        runs.append(r)
        print(
            f"  {method.name:26s} {case.name:13s} {kind}={s:<10.3g} err={r.error:9.2e} "
            f"wall={hz.fmt_time(r.wall):>10s} steps={r.steps}"
            + (f"  FAILED {r.failed[:60]}" if r.failed else ""),
            flush=True,
        )
        errors = [q.error if q.ok else math.nan for q in runs]
        walls = [q.wall for q in runs]
        if not hz.should_refine(errors, walls, FLOOR, cap):
            break
    return runs


def exact_run(case: Case) -> hz.Run:
    import pendulab as pl

    p = pl.Pendulum(length=case.length, g=case.g, mass=case.mass)
    s0 = p.state(case.x0, case.v0)
    wall, st, reps = hz.median_time(lambda: pl.exact(p, s0).state(T_END), repeats=101)
    golden = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    gs = next(
        s for s in next(c for c in golden["cases"] if c["name"] == case.name)["samples"] if s["t"] == T_END
    )
    x, v = np.asarray(st.x), np.asarray(st.v)
    de, dc = hz.drifts(x, v, case.x0, case.v0, case.length, case.g)
    return hz.Run(
        "pendulab exact", case.name, math.nan, "none", wall, 0,
        hz.position_error(x, np.array(gs["x"]), case.length),
        hz.state_error(x, v, np.array(gs["x"]), np.array(gs["v"]), case.length, case.omega0),
        de, dc, reps, extra={"note": "error against the mpmath golden data (the reference is this solution)"},
    )  # fmt: skip


# --------------------------------------------------------------------------------------------------
# Step rates, ensembles, the rotation-number map


def step_rates(cases: list[Case], quick: bool, available: dict[str, str | None]) -> dict[str, dict[str, Any]]:
    """Steps per second at dt = 1e-3 s on the rosette (median of 7; MuJoCo 5)."""
    import pendulab as pl

    case = cases[0]
    p = pl.Pendulum(length=case.length, g=case.g, mass=case.mass)
    s0 = p.state(case.x0, case.v0)
    n = 200_000 if quick else 1_000_000
    rates: dict[str, dict[str, Any]] = {}

    def put(name: str, steps: int, fn: Callable[[], Any], repeats: int = 7) -> None:
        wall, _, reps = hz.median_time(fn, repeats=repeats)
        rates[name] = {"steps": steps, "wall": wall, "steps_per_s": steps / wall, "repeats": reps}
        print(f"  rate {name:34s} {steps / wall:10.3e} steps/s", flush=True)

    for info in pl.methods():
        if info["adaptive"]:
            continue
        m = info["name"]
        k = n if m in ("rattle", "rk4") else n // 5
        put(f"pendulab {m} (Stepper.step)", k, lambda m=m, k=k: pl.Stepper(p, s0, method=m, dt=1e-3).step(k))
    w_sim, _, _ = hz.median_time(
        lambda: pl.simulate(p, s0, 1e-3, method="rattle", dt=1e-3, save_every=10**9, progress=False),
        repeats=301,
    )
    w_step, _, _ = hz.median_time(lambda: pl.Stepper(p, s0, method="rattle", dt=1e-3).step(1), repeats=301)
    rates["_overhead"] = {"simulate_one_step": w_sim, "stepper_one_step": w_step}
    print(f"  overhead of one call: simulate {w_sim * 1e6:.1f} µs, Stepper {w_step * 1e6:.1f} µs", flush=True)
    put(
        "pendulab rattle (simulate)",
        n,
        lambda: pl.simulate(p, s0, n * 1e-3, method="rattle", dt=1e-3, save_every=10**9, progress=False),
    )
    sol, times = pl.exact(p, s0), np.linspace(0.0, T_END, n // 10)
    put("pendulab exact (states at many times)", len(times), lambda: sol.state(times))
    if available.get("C") is None:
        lib = c_library()

        def c_run() -> None:
            y = case.y0.copy()
            lib.rk4_run(_dp(y), case.length, case.g, 1e-3, n)

        put("C rk4", n, c_run)
    if available.get("numba") is None:
        rk4 = numba_rk4()
        put("numba rk4", n, lambda: rk4(case.y0.copy(), 1.0 / case.length**2, case.g, 1e-3, n))
    if available.get("mujoco") is None:
        import mujoco

        m_, d_ = mujoco_model(case, 1e-3)
        k = n // 20

        def mj() -> None:
            mujoco_set_state(case, m_, d_)
            mujoco.mj_step(m_, d_, nstep=k)

        put("mujoco rk4 (mj_step, nstep)", k, mj, repeats=5)
        kk = k // 5

        def mj_loop() -> None:
            mujoco_set_state(case, m_, d_)
            for _ in range(kk):
                mujoco.mj_step(m_, d_)

        put("mujoco rk4 (mj_step from a Python loop)", kk, mj_loop, repeats=5)
    return rates
