"""The roofline of this machine and where Pendulab's hot kernels sit on it (issue 29 items 1, 2, 5).

Measures, in one run:
- the roof: fused multiply-add throughput per core and on all cores at every vector width the CPU has
  and the build dispatches to (scalar, 128, 256, 512 bits of float64; ``probe.c``), and the bandwidth of
  a STREAM-like triad in L1, in L2 and in DRAM;
- the kernels: RATTLE on one trajectory, the RATTLE ensemble on 1 and 2 threads, DOP853 and the exact
  solution's states (``crates/pendulab-core/examples/roofline_kernels.rs``, no Python in the way), and
  the C RK4 ensemble of the peers benchmark (``bench/peers/rk4.c``);
- the issue's target: ``pl.simulate_ensemble`` against the C RK4 ensemble through Python, 4096 starts,
  2 threads, 10³ and 10⁴ steps, interleaved, with the default arithmetic (``"auto"``: fused where the
  CPU has FMA) and with ``arithmetic="unfused"`` (the same bits on every CPU).

Flops and bytes per unit of work are counted by hand from the source (``counts.py`` says how). Every
figure is the best of repeated short runs, in wall time and in CPU time (``CLOCK_PROCESS_CPUTIME_ID``):
on a machine shared with other work the CPU time is what the work costs a core, the wall time includes
waiting for one; the load average at the start and the end is recorded next to the numbers.

Writes bench/roofline/results/roofline.json, docs/img/roofline.png (atomically: a temporary file
renamed into place) and the part of docs/performance.md between the roofline markers.
Run: ``make bench-roofline`` (or ``.venv/bin/python bench/roofline/run.py [--quick]``).
"""

from __future__ import annotations

import argparse
import ctypes
import datetime as dt_mod
import json
import os
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

os.environ.setdefault("OMP_WAIT_POLICY", "passive")  # idle OpenMP threads sleep (fair CPU times)
# OpenMP threads (the roof probe, the C RK4 ensemble) bound one per core, as pl.simulate_ensemble binds
# its workers: unbound, a 2-thread run after a pause often had both threads on one vCPU (the roof's
# 2-core column then equalled the 1-core one)
os.environ.setdefault("OMP_PROC_BIND", "close")
os.environ.setdefault("OMP_PLACES", "cores")

import numpy as np

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(REPO / "bench" / "peers"))
import counts  # noqa: E402
import harness as hz  # noqa: E402

BUILD = HERE / "build"
RESULTS = HERE / "results"
PLOT = REPO / "docs" / "img" / "roofline.png"
DOCS = REPO / "docs" / "performance.md"
BEGIN = "<!-- roofline:begin (written by bench/roofline/run.py; do not edit by hand) -->"
END = "<!-- roofline:end -->"
WIDTHS = {64: "fma", 128: "fma", 256: "avx2", 512: "avx512f"}  # the flag each width needs


def cpu_flags() -> set[str]:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("flags"):
                return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def build_c(name: str, flags: list[str]) -> ctypes.CDLL:
    BUILD.mkdir(exist_ok=True)
    so = BUILD / f"lib{Path(name).stem}.so"
    subprocess.run(["gcc", *flags, "-fopenmp", "-shared", "-fPIC", name, "-o", str(so)], check=True)
    return ctypes.CDLL(str(so))


def best(f: Any, reps: int) -> tuple[float, float]:
    """Least wall time and least CPU time [s] of ``reps`` calls of ``f``."""
    w, c = float("inf"), float("inf")
    for _ in range(reps):
        t0, c0 = time.perf_counter(), time.process_time()
        f()
        w, c = min(w, time.perf_counter() - t0), min(c, time.process_time() - c0)
    return w, c


def roof(quick: bool) -> dict[str, Any]:
    """FMA throughput [flop/s] per width and thread count, triad bandwidth [B/s] per level."""
    lib = build_c(str(HERE / "probe.c"), ["-O3"])
    lib.fma_peak.restype, lib.triad.restype = ctypes.c_double, ctypes.c_double
    lib.fma_peak.argtypes = [ctypes.c_int, ctypes.c_long, ctypes.c_int]
    lib.triad.argtypes = [ctypes.c_long, ctypes.c_int, ctypes.c_int]
    flags = cpu_flags()
    iters, reps = 2_000_000, 5 if quick else 30
    fma: dict[str, dict[str, float]] = {}
    for width, flag in WIDTHS.items():
        if flag not in flags:
            continue
        for threads in (1, 2):
            work = 2.0 * 12 * (width // 64) * iters * threads
            wall_rate = max(lib.fma_peak(width, iters, threads) for _ in range(reps))
            _, cpu = best(lambda w=width, t=threads: lib.fma_peak(w, iters, t), reps)
            fma[f"{width}x{threads}"] = {"wall": wall_rate, "cpu": work / cpu}
    bw: dict[str, float] = {}
    for level, n in (("L1", 1000), ("L2", 40_000), ("DRAM", 8_000_000)):
        for threads in (1, 2):
            bw[f"{level}x{threads}"] = lib.triad(n, 3 if level == "DRAM" else 30, threads)
    return {"fma": fma, "bandwidth": bw}


def kernels(quick: bool) -> dict[str, Any]:
    """The Rust probe's rates (units of work per wall second and per CPU second)."""
    env = dict(os.environ, CARGO_TERM_QUIET="true")
    cmd = ["cargo", "build", "--release", "-p", "pendulab-core", "--example", "roofline_kernels"]
    subprocess.run(cmd, cwd=REPO, check=True, env=env)
    exe = REPO / "target" / "release" / "examples" / "roofline_kernels"
    out = subprocess.run(
        [str(exe), "5" if quick else "20", "1000"], check=True, capture_output=True, text=True
    )
    return json.loads(out.stdout)


def c_ensemble_fn(n: int, steps: int, threads: int) -> Any:
    from peers_ensembles import ensemble_starts  # the peers benchmark's starts (bench/peers)

    lib = build_c(str(REPO / "bench" / "peers" / "rk4.c"), ["-O3", "-march=native"])
    dp = ctypes.POINTER(ctypes.c_double)
    lib.rk4_ensemble.argtypes = [dp, dp, dp, ctypes.c_long, ctypes.c_double, ctypes.c_long, ctypes.c_int]
    x, v, ell = ensemble_starts(n)
    g = np.full(n, 9.81)
    y0 = np.ascontiguousarray(np.hstack([x, v]).T)

    def c_run() -> None:
        y = y0.copy()
        lib.rk4_ensemble(
            y.ctypes.data_as(dp), ell.ctypes.data_as(dp), g.ctypes.data_as(dp), n, 1e-3, steps, threads
        )

    return c_run, np.hstack([x, v])


def api_vs_c(quick: bool) -> dict[str, Any]:
    """``pl.simulate_ensemble`` (its default arithmetic, as a user calls it, and ``"unfused"``) and the C
    RK4 ensemble, 4096 starts, 2 threads, interleaved."""
    import pendulab as pl

    n, out = 4096, {}
    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    for steps in (1000, 10_000):
        c_run, starts = c_ensemble_fn(n, steps, 2)

        def api(s: int = steps, st: np.ndarray = starts, arithmetic: str = "auto") -> Any:
            return pl.simulate_ensemble(
                p, st, s * 1e-3, dt=1e-3, summary=False, progress=False, arithmetic=arithmetic
            )

        def api_unfused(s: int = steps, st: np.ndarray = starts) -> None:
            api(s, st, "unfused")

        default = api().metadata.get("arithmetic", "unfused")
        api_unfused(), c_run()
        reps = (3 if quick else 9) if steps == 1000 else (1 if quick else 3)
        rows = {"api": [float("inf")] * 2, "api_unfused": [float("inf")] * 2, "c": [float("inf")] * 2}
        for _ in range(reps):
            for name, f in (("api", api), ("c", c_run), ("api_unfused", api_unfused)):
                # OpenMP's idle threads spin-wait for a while after the C run: a pause before each
                # timed call, so that none is timed while they still hold the cores
                time.sleep(0.05)
                w, c = best(f, 1)
                rows[name] = [min(rows[name][0], w), min(rows[name][1], c)]
        work = n * steps
        out[str(steps)] = {
            "default_arithmetic": default,
            "api_rate_wall": work / rows["api"][0],
            "api_rate_cpu": work / rows["api"][1],
            "c_rate_wall": work / rows["c"][0],
            "c_rate_cpu": work / rows["c"][1],
            "ratio_wall": rows["c"][0] / rows["api"][0],
            "ratio_cpu": rows["c"][1] / rows["api"][1],
            "api_unfused_rate_wall": work / rows["api_unfused"][0],
            "api_unfused_rate_cpu": work / rows["api_unfused"][1],
            "ratio_unfused_wall": rows["c"][0] / rows["api_unfused"][0],
            "ratio_unfused_cpu": rows["c"][1] / rows["api_unfused"][1],
        }
        r = out[str(steps)]
        print(
            f"  {steps} steps: API (default: {default}) / C RK4 = {r['ratio_wall']:.2f} (wall), "
            f"{r['ratio_cpu']:.2f} (CPU); unfused {r['ratio_unfused_wall']:.2f} (wall), "
            f"{r['ratio_unfused_cpu']:.2f} (CPU)",
            flush=True,
        )
    return out


def c_rk4_rate(quick: bool) -> tuple[float, float]:
    """The C RK4 ensemble on one thread: trajectory-steps per wall and per CPU second."""
    c_run, _ = c_ensemble_fn(4096, 1000, 1)
    w, c = best(c_run, 3 if quick else 10)
    return 4096 * 1000 / w, 4096 * 1000 / c


if __name__ == "__main__":
    from report import write_report  # the plot and the tables

    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quick", action="store_true", help="few repetitions; results/roofline_quick.json only")
    ap.add_argument(
        "--replot", action="store_true", help="only redraw the plot and tables from results/roofline.json"
    )
    ap.add_argument(
        "--api-only", action="store_true", help="only the API / C RK4 ratios (printed, nothing written)"
    )
    args = ap.parse_args()
    # pendulab's worker pool starts at import with the CPUs the process may use: before the first
    # OpenMP region binds this (the initial) thread to one core (OMP_PROC_BIND above)
    import pendulab  # noqa: F401

    if args.api_only:
        print(f"load average {os.getloadavg()}", flush=True)
        api_vs_c(args.quick)
        print(f"load average {os.getloadavg()}", flush=True)
        sys.exit(0)
    if args.replot:
        write_report(
            json.loads((RESULTS / "roofline.json").read_text()), counts.KERNELS, PLOT, DOCS, BEGIN, END
        )
        sys.exit(0)
    load0 = os.getloadavg()
    t0 = time.time()
    print("roof (FMA, triad)", flush=True)
    res: dict[str, Any] = {"roof": roof(args.quick)}
    print("kernels (Rust probe)", flush=True)
    res["kernels"] = kernels(args.quick)
    res["kernels"]["rk4_c_1_thread"] = dict(
        zip(("per_wall_s", "per_cpu_s"), c_rk4_rate(args.quick), strict=True)
    )
    print("pl.simulate_ensemble vs C RK4 ensemble", flush=True)
    res["api_vs_c"] = api_vs_c(args.quick)
    res["meta"] = {
        "date": dt_mod.datetime.now(dt_mod.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "seconds": round(time.time() - t0, 1),
        "load_start": [round(x, 2) for x in load0],
        "load_end": [round(x, 2) for x in os.getloadavg()],
        "cpu": hz.cpu_description(),
        "cores": os.cpu_count(),
    }
    RESULTS.mkdir(exist_ok=True)
    name = "roofline_quick.json" if args.quick else "roofline.json"
    (RESULTS / name).write_text(json.dumps(res, indent=1))
    if not args.quick:
        write_report(res, counts.KERNELS, PLOT, DOCS, BEGIN, END)
    print(f"wrote {RESULTS / name}" + ("" if args.quick else f", {PLOT}, {DOCS}"))
