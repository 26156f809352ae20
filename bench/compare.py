"""Pendulab against SciPy's ``solve_ivp`` in one process, on the rosette (docs/theory.md T-2.4).

Case: l = 1 m, m = 1 kg, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s, to t = 100 s. Reference: the exact
solution at t = 100 s from ``testdata/golden_states.json`` (mpmath, 40 digits). Error: max(|Δx|/l,
|Δv|/(l ω₀ + |v|)) at t = 100 s. Times: best of several repeats, wall clock [s].

Prints, for each rtol, the error and time of Pendulab's DOP853 and SciPy's DOP853 on the same
Cartesian ODE with their ratio; RATTLE's step rate from Python (saving every 100 steps) against the
same step rate measured through the Rust stepper without saving; and the time each DOP853 needs to
reach an error ≤ 1e-10. ``--markdown FILE`` also writes the tables as Markdown.

Run: ``make bench-compare`` (or ``.venv/bin/python bench/compare.py``).
"""

from __future__ import annotations

import argparse
import json
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pendulab as pl
from scipy.integrate import solve_ivp

REPO = Path(__file__).resolve().parents[1]
L, G, T_END = 1.0, 9.81, 100.0


def best_time(fn: Callable[[], Any], repeats: int) -> tuple[float, Any]:
    """Smallest wall time of ``repeats`` calls [s] and the last result."""
    best, out = float("inf"), None
    for _ in range(repeats):
        start = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - start)
    return best, out


def reference() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    data = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    case = next(c for c in data["cases"] if c["name"] == "rosette")
    sample = next(s for s in case["samples"] if s["t"] == T_END)
    return np.array(case["x0"]), np.array(case["v0"]), np.array(sample["x"]), np.array(sample["v"])


def error(x: np.ndarray, v: np.ndarray, x_ref: np.ndarray, v_ref: np.ndarray) -> float:
    w0 = np.sqrt(G / L)
    return float(
        max(np.linalg.norm(x - x_ref) / L, np.linalg.norm(v - v_ref) / (L * w0 + np.linalg.norm(v_ref)))
    )


def rhs(_t: float, y: np.ndarray) -> np.ndarray:
    """T-2.4: ẋ = v, v̇ = −g e₃ + ((g z − |v|²)/l²) x."""
    x, v = y[:3], y[3:]
    lam = (G * x[2] - v @ v) / (L * L)
    return np.concatenate([v, lam * x - np.array([0.0, 0.0, G])])


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--repeats", type=int, default=5, help="repeats per timing (best is kept)")
    parser.add_argument("--markdown", type=Path, help="also write the tables as Markdown to this file")
    args = parser.parse_args()

    x0, v0, x_ref, v_ref = reference()
    p = pl.Pendulum(length=L, g=G, mass=1.0)
    s0 = p.state(x0, v0)
    lines: list[str] = []

    def emit(line: str = "") -> None:
        print(line)
        lines.append(line)

    emit("## DOP853 at equal rtol: Pendulab vs SciPy (rosette, error at t = 100 s)")
    emit()
    emit(
        "| rtol | Pendulab error | Pendulab time [s] | steps "
        "| SciPy error | SciPy time [s] | steps | time ratio SciPy/Pendulab |"
    )
    emit("|---|---|---|---|---|---|---|---|")
    reach: dict[str, float] = {}
    for rtol in (1e-6, 1e-8, 1e-10, 1e-12, 1e-13):
        atol = rtol * 1e-2
        tp, tr = best_time(
            lambda r=rtol, a=atol: pl.simulate(
                p, s0, T_END, method="dop853", rtol=r, atol=a, save_every=10**9
            ),
            args.repeats,
        )
        ep = error(tr.x[-1], tr.v[-1], x_ref, v_ref)
        ts, sol = best_time(
            lambda r=rtol, a=atol: solve_ivp(
                rhs, (0.0, T_END), np.concatenate([x0, v0]), method="DOP853", rtol=r, atol=a, t_eval=[T_END]
            ),
            max(1, args.repeats // 2),
        )
        es = error(sol.y[:3, -1], sol.y[3:, -1], x_ref, v_ref)
        n_scipy = int(sol.nfev // 12)
        emit(
            f"| {rtol:.0e} | {ep:.2e} | {tp:.2e} | {tr.stats['steps']} "
            f"| {es:.2e} | {ts:.2e} | ~{n_scipy} | {ts / tp:.0f}x |"
        )
        if ep <= 1e-10 and "pendulab" not in reach:
            reach["pendulab"] = tp
        if es <= 1e-10 and "scipy" not in reach:
            reach["scipy"] = ts
    emit()
    emit("## Time to an error <= 1e-10 at t = 100 s")
    emit()
    emit(f"- Pendulab DOP853: {reach.get('pendulab', float('nan')) * 1e3:.2f} ms")
    scipy_reach = f"{reach['scipy'] * 1e3:.1f} ms" if "scipy" in reach else "never reached"
    emit(f"- SciPy DOP853: {scipy_reach}")
    emit()

    emit("## RATTLE step rate (rosette, dt = 1e-3 s)")
    emit()
    n = 2_000_000
    t_rust, _ = best_time(lambda: pl.Stepper(p, s0, method="rattle", dt=1e-3).step(n), args.repeats)
    t_py, tr = best_time(
        lambda: pl.simulate(p, s0, n * 1e-3, method="rattle", dt=1e-3, save_every=100, progress=False),
        args.repeats,
    )
    emit("| path | steps/s | ratio to the bare Rust stepper |")
    emit("|---|---|---|")
    emit(f"| Rust stepper via Python, no saving (`Stepper.step(n)`) | {n / t_rust:.3g} | 1.00 |")
    emit(f"| `pl.simulate`, saving every 100 steps | {n / t_py:.3g} | {t_rust / t_py:.2f} |")
    emit()
    print(f"(each timing: best of {args.repeats}; 2 cores; numpy {np.__version__})")
    if args.markdown:
        args.markdown.parent.mkdir(parents=True, exist_ok=True)
        args.markdown.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
