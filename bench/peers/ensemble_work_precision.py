"""Ensembles: accuracy per unit of work (issue 29's measure per trajectory-step, seen with the error
it buys). 4096 rosette-like starts (``peers_ensembles.ensemble_starts``: θ₀ ∈ [20°, 100°],
φ̇₀ ∈ [0.5, 3] rad/s, l = 1 m, g = 9.81 m/s²) to t = 10 s, 2 threads, final states only:

- ``pl.simulate_ensemble`` with RATTLE and its compositions rattle4, rattle6, rattle8 (dt scans;
  the default arithmetic, no summary), and with DOP853 (rtol scan, atol = rtol/100);
- the C RK4 ensemble of the peers benchmark (rk4.c, gcc -O3 -march=native, OpenMP; dt scan).

Error: the largest and the median over the starts of |x(10 s) − x_exact|/l, with ``pl.exact`` as the
reference (itself within 1e-12 of an independent DOP853 at rtol 1e-13, and tested against 40-digit
mpmath states: testdata/golden_states.json). Cost: wall time [s] of one call, the least of 3 timed
calls each right after an untimed one of the same side (OpenMP's idle threads spin after a C run:
peers_ensembles.api_vs_c_worker). Writes bench/peers/results/ensemble_work_precision.json,
docs/img/ensemble_work_precision.png and the part of docs/performance.md between the
``ensemble-wp`` markers: for each error level, the least wall time of each method that reaches it
(by the largest error over the starts, then by their median) and the C RK4 ensemble's time over the
best Pendulab method's.

Run: ``.venv/bin/python bench/peers/ensemble_work_precision.py`` (about a minute; it runs itself in a
child process with RAYON_NUM_THREADS = OMP_NUM_THREADS = 2 and the C threads bound to cores).
"""

from __future__ import annotations

import datetime as dt_mod
import json
import math
import os
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import harness as hz
from peers_ensembles import BIND, ensemble_starts
from peers_methods import c_ensemble

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
RESULTS = HERE / "results" / "ensemble_work_precision.json"
PLOT = REPO / "docs" / "img" / "ensemble_work_precision.png"
DOCS = REPO / "docs" / "performance.md"
BEGIN = "<!-- ensemble-wp:begin (written by bench/peers/ensemble_work_precision.py; do not edit by hand) -->"
END = "<!-- ensemble-wp:end -->"
N, T_END, THREADS = 4096, 10.0, 2
LEVELS = (1e-3, 1e-5, 1e-7, 1e-9, 1e-11)
# the settings scanned per method: dt [s] (T_END a multiple of each) or rtol
SCANS: dict[str, tuple[float, ...]] = {
    "rattle": (1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4),
    "rattle4": (4e-2, 2e-2, 1e-2, 5e-3, 2.5e-3, 1e-3),
    "rattle6": (5e-2, 4e-2, 2e-2, 1e-2, 5e-3, 2.5e-3),
    "rattle8": (4e-2, 2.5e-2, 2e-2, 1e-2, 5e-3),
    "dop853": (1e-6, 1e-8, 1e-10, 1e-12),
    "C rk4": (2e-2, 1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4, 1e-4),
}


def least_time(fn: Callable[[], Any], repeats: int = 3) -> tuple[float, Any]:
    """The least wall time [s] of ``repeats`` calls, each right after an untimed one, and the last
    call's result."""
    best, out = math.inf, None
    for _ in range(repeats):
        fn()
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def measure() -> dict[str, Any]:
    """Every method at every setting of SCANS: wall time and the errors against the exact solution."""
    import pendulab as pl

    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    x, v, ell = ensemble_starts(N)
    starts = np.hstack([x, v])
    exact = np.array([pl.exact(p, p.state(x[k], v[k])).state(T_END).x for k in range(N)])
    g = np.full(N, 9.81)
    runs: dict[str, list[dict[str, float]]] = {}
    arithmetic = "unfused"
    for method, settings in SCANS.items():
        runs[method] = []
        for s in settings:
            if method == "C rk4":
                y0 = np.ascontiguousarray(starts.T)

                def call(dt: float = s, y0: Any = y0) -> np.ndarray:
                    y = y0.copy()
                    c_ensemble(y, ell, g, dt, round(T_END / dt), THREADS)
                    return y[:3].T

            elif method == "dop853":

                def call(rtol: float = s) -> np.ndarray:
                    kw = {"rtol": rtol, "atol": rtol / 100}
                    return pl.simulate_ensemble(
                        p, starts, T_END, method="dop853", progress=False, **kw
                    ).final_x

            else:

                def call(dt: float = s, m: str = method) -> np.ndarray:
                    res = pl.simulate_ensemble(
                        p, starts, T_END, dt=dt, method=m, summary=False, progress=False
                    )
                    nonlocal arithmetic
                    arithmetic = res.metadata.get("arithmetic", "unfused")
                    return res.final_x

            wall, xs = least_time(call)
            err = np.linalg.norm(xs - exact, axis=1)
            row = {
                "setting": s,
                "wall": wall,
                "max_error": float(err.max()),
                "median_error": float(np.median(err)),
            }
            runs[method].append(row)
            print(
                f"  {method:8s} {s:8.1e}: {hz.fmt_time(wall):>9s}  max error {row['max_error']:.2e}",
                flush=True,
            )
    return {"n": N, "t_end": T_END, "threads": THREADS, "arithmetic": arithmetic, "runs": runs}


def cheapest(rows: list[dict[str, float]], level: float, key: str = "max_error") -> float | None:
    """The least wall time [s] of the runs whose error ``key`` (``"max_error"``: the largest over the
    starts; ``"median_error"``) is at or below ``level``."""
    times = [r["wall"] for r in rows if r[key] <= level]
    return min(times) if times else None


def level_table(runs: dict[str, list[dict[str, float]]], key: str, what: str) -> str:
    """Per error level the least wall time of each method reaching it (error ``key``) and the C RK4
    ensemble's time over the best Pendulab method's."""
    methods = list(runs)
    head = [f"{what} ≤", *[f"`{m}`" for m in methods], "best Pendulab: C RK4 time / its time"]
    rows = []
    for level in LEVELS:
        times = {m: cheapest(runs[m], level, key) for m in methods}
        ours = [(t, m) for m, t in times.items() if m != "C rk4" and t is not None]
        best = min(ours) if ours else None
        c = times["C rk4"]
        ratio = f"{c / best[0]:.1f} (`{best[1]}`)" if best and c else "—"
        rows.append([f"{level:.0e}", *[hz.fmt_time(times[m]) for m in methods], ratio])
    return hz.markdown_table(head, rows)


def markdown(res: dict[str, Any]) -> str:
    meta, runs = res["meta"], res["runs"]
    load = f"load {meta['load_start']:.1f} → {meta['load_end']:.1f}"
    intro = (
        f"Measured {meta['date']} on {meta['cpu']} ({load}); {res['n']} starts to t = {res['t_end']:g} s, "
        f"{res['threads']} threads, `pl.simulate_ensemble` with arithmetic {res['arithmetic']} and no "
        "summary. Least wall time of the settings scanned (bench/peers/ensemble_work_precision.py) whose "
        "final-position error is at or below the level, first the largest error over the starts, then "
        "their median; — where no setting scanned reached it."
    )
    largest = level_table(runs, "max_error", "largest error")
    median = level_table(runs, "median_error", "median error")
    figure = "![ensembles: error against wall time](img/ensemble_work_precision.png)"
    return f"\n{intro}\n\n{largest}\n\n{median}\n\n{figure}\n"


def plot(res: dict[str, Any]) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(7, 4.5))
    for method, rows in res["runs"].items():
        style = "s--" if method == "C rk4" else ("^:" if method == "dop853" else "o-")
        ax.loglog([r["wall"] for r in rows], [max(r["max_error"], 1e-16) for r in rows], style, label=method)
    ax.set_xlabel("wall time of the call [s] (4096 starts, 2 threads)")
    ax.set_ylabel("largest |x(10 s) − x_exact| / l")
    ax.set_title("Ensembles: accuracy per unit of work")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    tmp = PLOT.with_suffix(".tmp.png")
    fig.savefig(tmp, dpi=110)
    os.replace(tmp, PLOT)


def main() -> None:
    if os.environ.get("PENDULAB_WP_CHILD") != "1":
        env = dict(os.environ, RAYON_NUM_THREADS=str(THREADS), OMP_NUM_THREADS=str(THREADS), **BIND)
        env["PENDULAB_WP_CHILD"] = "1"
        load_start = os.getloadavg()[0]
        out = subprocess.run([sys.executable, __file__], env=env, check=True, capture_output=True, text=True)
        print(out.stdout, end="")
        res = json.loads(out.stdout.strip().splitlines()[-1])
        date = dt_mod.datetime.now(dt_mod.UTC).strftime("%Y-%m-%d %H:%M UTC")
        res["meta"] = {"date": date, "cpu": hz.cpu_description(), "load_start": load_start,
                       "load_end": os.getloadavg()[0]}  # fmt: skip
        tmp = RESULTS.with_suffix(".tmp")
        tmp.write_text(json.dumps(res, indent=1) + "\n")
        os.replace(tmp, RESULTS)
        plot(res)
        text = hz.replace_between_markers(DOCS.read_text(), markdown(res), BEGIN, END)
        tmp = DOCS.with_suffix(".tmp")
        tmp.write_text(text)
        os.replace(tmp, DOCS)
        print(f"wrote {RESULTS.relative_to(REPO)}, {PLOT.relative_to(REPO)} and docs/performance.md")
        return
    print(json.dumps(measure()))


if __name__ == "__main__":
    main()
