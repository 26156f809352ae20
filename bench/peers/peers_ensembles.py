"""The peers benchmark's throughput runs (bench/peers/run.py): Pendulab's ensemble kernel
(``_core.EnsembleRun``, the kernel of ``pl.simulate_ensemble``, with the API's default arithmetic
resolved by ``check_arithmetic("auto", "rattle")``), the same through the API and the C RK4 ensemble
on 1 and 2 threads, each in a fresh child process (``run.py --ensemble-worker``), in
trajectory-steps per second at dt = 1 ms; issue 29's ratio of the C RK4 ensemble's wall time [s] to
``pl.simulate_ensemble``'s (called with its defaults) at 10³ and 10⁴ steps, 4096 starts, 2 threads,
interleaved in one child process (``run.py --api-vs-c-worker``); and the rotation-number map
(``pl.em_map`` on a grid of points) in seconds. Starts: rosette-like, θ₀ ∈ [20°, 100°],
φ̇₀ ∈ [0.5, 3] rad/s, l = 1 m, g = 9.81 m/s².
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import time
from typing import Any

import harness as hz
import numpy as np
from peers_cases import HERE
from peers_methods import c_ensemble

# The C ensemble's OpenMP threads bound one per core, as pl.simulate_ensemble binds its workers
# (python/rust/threads.rs): both sides get a CPU per thread from the start (docs/performance.md).
BIND = {"OMP_PROC_BIND": "close", "OMP_PLACES": "cores"}

# the script whose --ensemble-worker option runs ensemble_worker in a child process
RUN = HERE / "run.py"


def ensemble_starts(n: int, seed: int = 5) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """n rosette-like starts (θ₀ ∈ [20°, 100°], φ̇₀ ∈ [0.5, 3] rad/s, l = 1 m, g = 9.81 m/s²)."""
    rng = np.random.default_rng(seed)
    th = np.radians(rng.uniform(20.0, 100.0, n))
    ph = rng.uniform(0.0, 2 * np.pi, n)
    phd = rng.uniform(0.5, 3.0, n)
    x = np.stack([np.sin(th) * np.cos(ph), np.sin(th) * np.sin(ph), -np.cos(th)], axis=1)
    v = np.stack([-np.sin(th) * np.sin(ph) * phd, np.sin(th) * np.cos(ph) * phd, np.zeros(n)], axis=1)
    return x, v, np.ones(n)


def ensemble_worker(n: int, steps: int, repeats: int, threads: int, with_c: int) -> dict[str, Any]:
    """Run in a fresh child process (RAYON_NUM_THREADS = threads): Pendulab's ensemble kernel, the same
    through ``pl.simulate_ensemble``, and the C RK4 ensemble on ``threads`` OpenMP threads, timed."""
    import pendulab as pl
    from pendulab import _core
    from pendulab.integrators import check_arithmetic

    x, v, ell = ensemble_starts(n)
    g = np.full(n, 9.81)
    dt = 1e-3
    arithmetic = check_arithmetic("auto", "rattle")  # what pl.simulate_ensemble uses by default

    def kernel() -> Any:
        spec, options = _core.EnsembleSpec(ell, g), _core.RunOptions(dt=dt, arithmetic=arithmetic)
        return _core.EnsembleRun(spec, x, v, options, steps, False).result()

    def api() -> Any:
        p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
        return pl.simulate_ensemble(p, np.hstack([x, v]), steps * dt, dt=dt, summary=False, progress=False)

    kernel()
    wk, _, rk = hz.median_time(kernel, repeats=repeats)
    wa, api_res, _ = hz.median_time(api, repeats=repeats)
    res: dict[str, Any] = {
        "threads": threads,
        "arithmetic": arithmetic,
        "api_arithmetic": api_res.metadata.get("arithmetic", "unfused"),
        "kernel_wall": wk,
        "api_wall": wa,
        "repeats": rk,
        "rate": n * steps / wk,
        "api_rate": n * steps / wa,
    }
    if with_c:
        y = np.ascontiguousarray(np.hstack([x, v]).T)

        def c_run() -> None:
            c_ensemble(y.copy(), ell, g, dt, steps, threads)

        c_run()
        wc, _, _ = hz.median_time(c_run, repeats=repeats)
        res |= {"c_wall": wc, "c_rate": n * steps / wc}
    return res


def ensembles(quick: bool, c_ok: bool) -> dict[str, Any]:
    """Both ensembles in fresh child processes, 1 and 2 threads, alternating (to spread the load of
    the other users of the machine evenly); each figure is the median of ``reps`` runs. Then, with the
    C side available, issue 29's ratio (:func:`api_vs_c`) under the key ``"api_vs_c"``."""
    n, steps = (1024, 1000) if quick else (4096, 2000)
    reps = 3 if quick else 7
    out: dict[str, Any] = {"n": n, "steps": steps, "dt": 1e-3, "pendulab": {}, "C rk4": {}}
    text = ("threads", "arithmetic", "api_arithmetic")
    samples: dict[int, list[dict[str, Any]]] = {1: [], 2: []}
    for _ in range(1 if quick else 3):
        for threads in (1, 2):
            env = dict(os.environ, RAYON_NUM_THREADS=str(threads), OMP_NUM_THREADS=str(threads), **BIND)
            cmd = [sys.executable, str(RUN), "--ensemble-worker", str(n), str(steps), str(reps), str(threads)]
            res = subprocess.run([*cmd, str(int(c_ok))], env=env, check=True, capture_output=True, text=True)
            samples[threads].append(json.loads(res.stdout.strip().splitlines()[-1]))
    for threads, ws in samples.items():
        med = {k: float(np.median([w[k] for w in ws])) for k in ws[0] if k not in text}
        out["arithmetic"], out["api_arithmetic"] = ws[0]["arithmetic"], ws[0]["api_arithmetic"]
        out["pendulab"][threads] = {k: med[k] for k in ("kernel_wall", "api_wall", "rate", "api_rate")}
        print(f"  ensemble pendulab {threads} thread(s): {med['rate']:.3e} trajectory-steps/s", flush=True)
        if c_ok:
            out["C rk4"][threads] = {"wall": med["c_wall"], "rate": med["c_rate"]}
            print(f"  ensemble C rk4 {threads} thread(s): {med['c_rate']:.3e} trajectory-steps/s", flush=True)
    out["api_vs_c"] = api_vs_c(quick) if c_ok else {"skipped": "the C family is not run"}
    return out


# issue 29, item 2: the starts, threads and step counts of the ratio C RK4 / pl.simulate_ensemble
API_VS_C: dict[str, Any] = {"n": 4096, "threads": 2, "dt": 1e-3, "steps": (1000, 10_000)}


def api_vs_c_reps(steps: int, quick: bool) -> int:
    """Interleaved rounds (API, C) per step count: best of 9 at 10³ steps, 3 at 10⁴ (quick: 3, 1)."""
    return (3 if quick else 9) if steps <= 1000 else (1 if quick else 3)


def api_vs_c_variants(n: int) -> dict[str, tuple[dict[str, Any], np.ndarray, np.ndarray]]:
    """Issue 29, item 3: the API's forms with per-trajectory parameters and damping, each as
    (``pl.simulate_ensemble`` keywords, lengths [m] and g [m/s²] for the C ensemble, which runs the
    same lengths and g but has no damping). "shared" is item 2's call (one pendulum, many starts)."""
    ell = np.linspace(0.8, 1.2, n)
    g = np.linspace(9.0, 10.0, n)
    c = np.linspace(0.05, 0.5, n)
    one, g0 = np.ones(n), np.full(n, 9.81)
    return {
        "shared": ({}, one, g0),
        "lengths per trajectory": ({"length": ell}, ell, g0),
        "damped (one c = 0.1/s)": ({"damping": np.full(n, 0.1)}, one, g0),
        "damping per trajectory": ({"damping": c}, one, g0),
        "lengths, g and damping per trajectory": ({"length": ell, "g": g, "damping": c}, ell, g),
    }


def api_vs_c_worker(quick: int) -> dict[str, Any]:
    """Run in a fresh child process (RAYON_NUM_THREADS = OMP_NUM_THREADS = 2): ``pl.simulate_ensemble``
    with its defaults and the C RK4 ensemble on the same 4096 starts, one warm-up call each, then
    API, C, API, C, … ; the least wall time [s] and CPU time [s] of each side per step count; for
    the one-pendulum call (``"steps"``) and for every form of :func:`api_vs_c_variants` (``"variants"``;
    starts scaled onto each trajectory's sphere)."""
    import pendulab as pl

    n, threads, dt = API_VS_C["n"], API_VS_C["threads"], API_VS_C["dt"]
    x, v, _ = ensemble_starts(n)
    out: dict[str, Any] = {"n": n, "threads": threads, "dt": dt, "steps": {}, "variants": {}}
    for name, (kw, ell, g) in api_vs_c_variants(n).items():
        starts = np.hstack([x * ell[:, None], v * ell[:, None]])
        y0 = np.ascontiguousarray(starts.T)
        model = {"model": "damped", "damping": 0.1} if "damping" in kw else {}
        p = pl.Pendulum(length=1.0, g=9.81, mass=1.0, **model)
        by_steps: dict[str, Any] = {}
        for steps in API_VS_C["steps"]:
            meta: dict[str, Any] = {}

            def api(
                s: int = steps, m: dict[str, Any] = meta, p: Any = p, x0: Any = starts, kw: Any = kw
            ) -> None:
                res = pl.simulate_ensemble(p, x0, s * dt, dt=dt, summary=False, progress=False, **kw)
                m["arithmetic"] = res.metadata.get("arithmetic", "unfused")

            def c_run(s: int = steps, y0: Any = y0, ell: Any = ell, g: Any = g) -> None:
                c_ensemble(y0.copy(), ell, g, dt, s, threads)

            api(), c_run()
            best = {"api": [math.inf, math.inf], "c": [math.inf, math.inf]}
            reps = api_vs_c_reps(steps, bool(quick))
            for _ in range(reps):
                for side, f in (("api", api), ("c", c_run)):
                    # each timed call right after an untimed one of the same side: OpenMP's idle threads
                    # spin-wait for milliseconds after a C run and would take the cores from an API call
                    # timed right after it (measured: its 10³-step wall time 9.4 ms instead of 4.8), and
                    # after a pause both sides start cold (threads asleep); so every call is timed warm,
                    # as the best of N is meant to find the least disturbed run of each
                    f()
                    t0, c0 = time.perf_counter(), time.process_time()
                    f()
                    w, c = time.perf_counter() - t0, time.process_time() - c0
                    best[side] = [min(best[side][0], w), min(best[side][1], c)]
            (wa, ca), (wc, cc) = best["api"], best["c"]
            by_steps[str(steps)] = {
                "repeats": reps, "api_wall": wa, "api_cpu": ca, "c_wall": wc, "c_cpu": cc,
                "ratio": wc / wa, "ratio_cpu": cc / ca, "api_rate": n * steps / wa, "c_rate": n * steps / wc,
            }  # fmt: skip
            out["arithmetic"] = meta["arithmetic"]
        if name == "shared":
            out["steps"] = by_steps
        else:
            out["variants"][name] = by_steps
    return out


def api_vs_c(quick: bool) -> dict[str, Any]:
    """Issue 29's ratio C RK4 ensemble / ``pl.simulate_ensemble`` (wall time, best of N, interleaved) in
    one child process on 2 threads, with the load average (1 min) at its start and end."""
    threads = str(API_VS_C["threads"])
    env = dict(os.environ, RAYON_NUM_THREADS=threads, OMP_NUM_THREADS=threads, **BIND)
    load_start = os.getloadavg()[0]
    cmd = [sys.executable, str(RUN), "--api-vs-c-worker", str(int(quick))]
    res = subprocess.run(cmd, env=env, check=True, capture_output=True, text=True)
    out = json.loads(res.stdout.strip().splitlines()[-1])
    out |= {"load_start": load_start, "load_end": os.getloadavg()[0]}
    for steps, r in out["steps"].items():
        print(
            f"  pl.simulate_ensemble ({out['arithmetic']}) vs C RK4, {steps} steps, 2 threads: "
            f"C / API wall = {r['ratio']:.2f} (best of {r['repeats']})",
            flush=True,
        )
    for name, by_steps in out.get("variants", {}).items():
        ratios = ", ".join(f"{steps} steps {r['ratio']:.2f}" for steps, r in by_steps.items())
        print(f"    {name}: C / API wall = {ratios}", flush=True)
    return out


def rotation_map(quick: bool) -> dict[str, Any]:
    import pendulab as pl

    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    side = 300 if quick else 1000
    wall, em, reps = hz.median_time(lambda: pl.em_map(p, grid=(side, side)), repeats=3)
    finite = int(np.isfinite(em.W).sum())
    print(f"  em_map {side}x{side}: {hz.fmt_time(wall)} ({finite} finite values)", flush=True)
    return {"points": side * side, "wall": wall, "finite": finite, "repeats": reps}
