"""Work-precision at t = 100 s and 10⁴ s with the exact solution as a "method" (issue 17, item 6).

Case: the rosette (l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s), the float64 start and the
40-digit states of ``testdata/golden_states.json`` at t = 100 s and 10⁴ s (the reference; no mpmath
at run time). Error = |x − x_golden| / l at t. Cost = wall time of one state at t from Python: for
the integrators ``pl.simulate`` to t keeping only the end (``save_at=[t]``), for the exact solution
``pl.exact(p, s0).state(t)`` with its set-up. Methods: DOP853 (rtol 1e-6 … 1e-13, with and without
``conserve``), RATTLE8 and RATTLE (dt scans). Times are medians of repeats within this one run; a run
predicted above ``--budget`` s is skipped. Writes ``docs/img/work_precision_exact.png`` and, with
``--markdown FILE``, the table.

Run: ``.venv/bin/python bench/work_precision_exact.py`` (a few minutes).
"""

from __future__ import annotations

import argparse
import json
import statistics
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pendulab as pl

REPO = Path(__file__).resolve().parents[1]
PLOT = REPO / "docs" / "img" / "work_precision_exact.png"
TIMES = (100.0, 1e4)


def median_time(fn: Callable[[], Any], budget: float = 1.0) -> tuple[float, Any]:
    start = time.perf_counter()
    out = fn()
    first = time.perf_counter() - start
    times = [first]
    for _ in range(min(4, int(budget / max(first, 1e-9)))):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--budget", type=float, default=20.0, help="skip runs predicted above this [s]")
    ap.add_argument("--markdown", type=Path)
    args = ap.parse_args()
    data = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    case = next(c for c in data["cases"] if c["name"] == "rosette")
    p = pl.Pendulum(length=case["length"], mass=case["mass"], g=case["g"])
    s0 = p.state(np.array(case["x0"]), np.array(case["v0"]))
    rows: list[tuple[float, str, str, float, float]] = []
    for t in TIMES:
        ref = np.array([float(c) for c in next(s for s in case["samples"] if s["t"] == t)["x_str"]])

        def err(x: np.ndarray, ref: np.ndarray = ref) -> float:
            return float(np.linalg.norm(x - ref) / p.length)

        cost, st = median_time(lambda t=t: pl.exact(p, s0).state(t))
        rows.append((t, "exact", "-", cost, err(st.x)))
        runs: list[tuple[str, str, dict[str, Any]]] = []
        for rtol in (1e-6, 1e-8, 1e-10, 1e-12, 1e-13):
            runs.append(("dop853", f"rtol {rtol:g}", {"method": "dop853", "rtol": rtol, "atol": rtol * 1e-2}))
            runs.append(
                (
                    "dop853 conserve",
                    f"rtol {rtol:g}",
                    {"method": "dop853", "rtol": rtol, "atol": rtol * 1e-2, "conserve": True},
                )
            )
        for dt in (0.1, 0.05, 0.02, 0.01, 0.005):
            runs.append(("rattle8", f"dt {dt:g}", {"method": "rattle8", "dt": dt}))
        for dt in (1e-2, 1e-3, 1e-4):
            runs.append(("rattle", f"dt {dt:g}", {"method": "rattle", "dt": dt}))
        last_rate: dict[str, float] = {}
        for name, setting, kw in runs:
            predicted = last_rate.get(name + setting, 0.0)
            if predicted > args.budget:
                continue
            cost, tr = median_time(lambda kw=kw, t=t: pl.simulate(p, s0, t, save_at=[t], **kw), budget=2.0)
            if t == TIMES[0]:
                last_rate[name + setting] = cost * TIMES[1] / TIMES[0]
            rows.append((t, name, setting, cost, err(tr.x[-1])))
            print(
                f"t = {t:g} s  {name:16} {setting:12} {cost * 1e3:10.3f} ms  error {rows[-1][4]:.2e}",
                flush=True,
            )
    table = ["| t [s] | method | setting | time per state | error / l |", "|---|---|---|---|---|"]
    for t, name, setting, cost, e in rows:
        table.append(f"| {t:g} | {name} | {setting} | {cost * 1e6:.3g} µs | {e:.2e} |")
    text = "\n".join(table)
    print(text)
    if args.markdown:
        args.markdown.write_text(text + "\n")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5), sharey=True)
    for ax, t in zip(axes, TIMES, strict=True):
        for name, marker in (
            ("dop853", "o-"),
            ("dop853 conserve", "s-"),
            ("rattle8", "^-"),
            ("rattle", "v-"),
        ):
            pts = [(c, max(e, 1e-17)) for tt, n, _, c, e in rows if tt == t and n == name]
            if pts:
                ax.loglog(*zip(*pts, strict=True), marker, label=name)
        ex = [(c, max(e, 1e-17)) for tt, n, _, c, e in rows if tt == t and n == "exact"]
        ax.loglog(*zip(*ex, strict=True), "k*", markersize=16, label="exact solution")
        ax.set_title(f"rosette, state at t = {t:g} s")
        ax.set_xlabel("wall time for one state [s]")
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("error |x − x_golden| / l")
    axes[0].legend()
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)
    print(f"wrote {PLOT}")


if __name__ == "__main__":
    main()
