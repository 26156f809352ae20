"""The exact solution against the integrators at large t, in one process (issue 3, part 6).

Case: the rosette (l = 1 m, m = 1 kg, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s), the float64 start of
``testdata/golden_states.json``. Times are wall clock [s]; comparisons are ratios within this run.

1. **Cost of the exact solution from Python**: the set-up ``pl.exact(p, s0)``; one state
   ``sol.state(t)`` for a scalar t at t = 1 s, t = 10⁶ s and at random t in [−10⁶, 10⁶] s (median over
   batches of calls, per call); the array rate ``sol.state(t)`` for 10⁵ and 10⁶ random times in
   [0, 10⁶] s (states/s, median of repeats).
2. **Error and cost at large t**: the reference is the exact solution at 40 digits (mpmath, the
   generator of the golden data, ``testdata/generate/golden_states.py``) through the same float64
   start; error = max(|Δx|/l, |Δv|/(l ω₀ + |v|)) as in ``bench/compare.py``. The conditioning floor
   is the largest error that changing the start by 2⁻⁵³ relative per component (64 sign patterns)
   causes — what no float64 method can beat. For t = 10³ … 10⁶ s: the error and time of
   ``pl.exact(p, s0).state(t)`` (set-up included), and of DOP853 (rtol 1e-13, atol 1e-15, projected
   onto TS²; also with ``conserve=True``) and RATTLE8 (dt = 2e-3 s) run to t, keeping only the last
   state. A run whose predicted time (linear in t from the last measured one) exceeds ``--budget`` s
   is not made: its time is **extrapolated** linearly in t from the longest measured run and its
   error is not known (the table says so). Such an extrapolation is a lower bound of the cost to
   the exact solution's accuracy, since at these settings the integrators are already less accurate.

``--markdown FILE`` also writes the tables as Markdown.

Run: ``.venv/bin/python bench/exact_vs_integrators.py`` (about 1–2 minutes with the default budget).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pendulab as pl

REPO = Path(__file__).resolve().parents[1]
T_LARGE = (1e3, 1e4, 1e5, 1e6)  # [s]


def per_call(fn: Callable[[], Any], calls: int, batches: int) -> float:
    """Median over ``batches`` of the mean wall time of ``calls`` calls [s]."""
    times = []
    for _ in range(batches):
        start = time.perf_counter()
        for _ in range(calls):
            fn()
        times.append((time.perf_counter() - start) / calls)
    return statistics.median(times)


def median_time(fn: Callable[[], Any], repeats: int) -> tuple[float, Any]:
    """Median wall time of ``repeats`` calls [s] and the last result."""
    times, out = [], None
    for _ in range(repeats):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), out


def power(t: float) -> str:
    """10³-style label of a power of ten."""
    return "10" + str(round(np.log10(t))).translate(str.maketrans("0123456789-", "⁰¹²³⁴⁵⁶⁷⁸⁹⁻"))


def rosette_start() -> tuple[np.ndarray, np.ndarray]:
    data = json.loads((REPO / "testdata" / "golden_states.json").read_text())
    case = next(c for c in data["cases"] if c["name"] == "rosette")
    return np.array(case["x0"]), np.array(case["v0"])


def error(ell: float, w0: float, x: np.ndarray, v: np.ndarray, ref: tuple[np.ndarray, np.ndarray]) -> float:
    """max(|Δx|/l, |Δv|/(l ω₀ + |v_ref|)), dimensionless."""
    x_ref, v_ref = ref
    return float(
        max(np.linalg.norm(x - x_ref) / ell, np.linalg.norm(v - v_ref) / (ell * w0 + np.linalg.norm(v_ref)))
    )


def references(
    ell: float, g: float, x0: np.ndarray, v0: np.ndarray, times: tuple[float, ...]
) -> tuple[dict[float, tuple[np.ndarray, np.ndarray]], dict[float, float]]:
    """States at ``times`` from the 40-digit exact solution through (x0, v0), and the conditioning
    floor at each time (the error measure of :func:`error`)."""
    sys.path.insert(0, str(REPO / "testdata" / "generate"))
    import golden_states as gs  # the generator of the golden data (mpmath)
    from mpmath import mp, mpf

    mp.dps = gs.DPS

    def solve(x: list[Any], v: list[Any]) -> dict[float, tuple[np.ndarray, np.ndarray]]:
        with mp.extraprec(mp.prec):  # as the generator's initial_state
            xs, vs = gs.project(mpf(ell), x, v)
        sol = gs.solve(mpf(ell), mpf(g), xs, vs)
        out = {}
        for t in times:
            x_t, v_t = sol.state(mpf(t))
            out[t] = (np.array([float(c) for c in x_t]), np.array([float(c) for c in v_t]))
        return out

    ref = solve(gs.to_mp(x0), gs.to_mp(v0))
    w0 = float(np.sqrt(g / ell))
    floor = dict.fromkeys(times, 0.0)
    raw = gs.to_mp(x0) + gs.to_mp(v0)
    for signs in gs.floor_patterns():
        y = [c * (1 + s * mpf(2) ** -53) for c, s in zip(raw, signs, strict=True)]
        for t, (x_t, v_t) in solve(y[:3], y[3:]).items():
            floor[t] = max(floor[t], error(ell, w0, x_t, v_t, ref[t]))
    return ref, floor


@dataclass
class Row:
    t: float
    method: str
    error: float | None  # None: not measured
    seconds: float
    extrapolated_from: float | None = None  # t [s] of the run the time is extrapolated from


def main() -> None:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--repeats", type=int, default=5, help="repeats of short timings (median kept)")
    parser.add_argument(
        "--budget",
        type=float,
        default=30.0,
        help="longest integrator run to make [s]; longer ones are extrapolated",
    )
    parser.add_argument("--markdown", type=Path, help="also write the tables as Markdown to this file")
    args = parser.parse_args()

    ell, g = 1.0, 9.81
    w0 = float(np.sqrt(g / ell))
    x0, v0 = rosette_start()
    p = pl.Pendulum(length=ell, g=g, mass=1.0)
    s0 = p.state(x0, v0)
    sol = pl.exact(p, s0)
    rng = np.random.default_rng(2026)
    lines: list[str] = []

    def emit(line: str = "") -> None:
        print(line, flush=True)
        lines.append(line)

    # --- 1. cost of the exact solution from Python ---
    setup = per_call(lambda: pl.exact(p, s0), 1000, 31)
    one = {t: per_call(lambda t=t: sol.state(t), 1000, 31) for t in (1.0, 1e6)}
    random_t = iter(rng.uniform(-1e6, 1e6, 31 * 1000 + 10))
    one_random = per_call(lambda: sol.state(next(random_t)), 1000, 31)
    one_t = np.array([1e6])
    core = per_call(lambda: sol._core.states(one_t), 1000, 31)  # private: the wrapper's overhead
    rates = {}
    for n in (10**5, 10**6):
        times = rng.uniform(0.0, 1e6, n)
        seconds, _ = median_time(lambda times=times: sol.state(times), args.repeats)
        rates[n] = n / seconds
    emit("## Exact solution from Python (rosette)")
    emit()
    emit("| operation | time | rate |")
    emit("|---|---|---|")
    emit(f"| set-up `pl.exact(p, s0)` | {setup * 1e6:.2f} µs | |")
    emit(f"| one state `sol.state(t)`, t = 1 s | {one[1.0] * 1e6:.2f} µs | {1 / one[1.0]:.3g} states/s |")
    emit(f"| one state `sol.state(t)`, t = 10⁶ s | {one[1e6] * 1e6:.2f} µs | {1 / one[1e6]:.3g} states/s |")
    emit(
        f"| one state `sol.state(t)`, random t in [−10⁶, 10⁶] s | {one_random * 1e6:.2f} µs "
        f"| {1 / one_random:.3g} states/s |"
    )
    emit(
        f"| the core call inside it (private `sol._core.states`, 1-element array), t = 10⁶ s "
        f"| {core * 1e6:.2f} µs | {1 / core:.3g} states/s |"
    )
    for n, rate in rates.items():
        emit(
            f"| `sol.state(t)` for an array of {power(n)} random times in [0, 10⁶] s "
            f"| {n / rate * 1e3:.1f} ms | {rate:.3g} states/s |"
        )
    emit()
    emit(
        f"One state from Python at t = 10⁶ s costs {one[1e6] / one[1.0]:.2f}× the one at t = 1 s; "
        f"set-up + one state: {(setup + one[1e6]) * 1e6:.2f} µs."
    )
    emit()

    # --- 2. error and cost at large t ---
    print("computing the 40-digit reference and the conditioning floors (mpmath) ...", flush=True)
    ref, floor = references(ell, g, x0, v0, T_LARGE)
    rows: list[Row] = []
    for t in T_LARGE:
        seconds = per_call(lambda t=t: pl.exact(p, s0).state(t), 200, 21)
        st = pl.exact(p, s0).state(t)
        rows.append(Row(t, "exact", error(ell, w0, st.x, st.v, ref[t]), seconds))

    integrators: dict[str, dict[str, Any]] = {
        "DOP853, rtol 1e-13": {"method": "dop853", "rtol": 1e-13, "atol": 1e-15},
        "DOP853, rtol 1e-13, conserve": {"method": "dop853", "rtol": 1e-13, "atol": 1e-15, "conserve": True},
        "RATTLE8, dt 2e-3 s": {"method": "rattle8", "dt": 2e-3},
    }
    for name, kwargs in integrators.items():
        last: tuple[float, float] | None = None  # (t, seconds) of the longest measured run
        for t in T_LARGE:
            predicted = 0.0 if last is None else last[1] * t / last[0]
            if last is not None and predicted > args.budget:
                rows.append(Row(t, name, None, predicted, extrapolated_from=last[0]))
                continue
            print(f"  {name} to t = {t:.0e} s (predicted {predicted:.3g} s) ...", flush=True)
            repeats = args.repeats if predicted < 1.0 else 1
            seconds, tr = median_time(
                lambda t=t, kw=kwargs: pl.simulate(p, s0, t, save_every=10**12, progress=False, **kw), repeats
            )
            rows.append(Row(t, name, error(ell, w0, tr.x[-1], tr.v[-1], ref[t]), seconds))
            last = (t, seconds)

    exact_time = {r.t: r.seconds for r in rows if r.method == "exact"}
    emit("## Error and cost at large t (rosette; reference: exact solution at 40 digits)")
    emit()
    emit("| t [s] | method | error | wall time | time / exact's time |")
    emit("|---|---|---|---|---|")
    for t in T_LARGE:
        emit(f"| {power(t)} | conditioning floor (start changed by 2⁻⁵³) | {floor[t]:.1e} | | |")
        for r in (r for r in rows if r.t == t):
            err = f"{r.error:.1e}" if r.error is not None else "not measured"
            if r.method == "exact":
                wall = f"{r.seconds * 1e6:.2f} µs (set-up + one state)"
            elif r.extrapolated_from is not None:
                since = power(r.extrapolated_from)
                wall = f"**extrapolated**: {r.seconds:.3g} s (linear in t from t = {since} s)"
            else:
                wall = f"{r.seconds:.3g} s"
            ratio = "1" if r.method == "exact" else f"{r.seconds / exact_time[t]:.2g}"
            emit(f"| {power(t)} | {r.method} | {err} | {wall} | {ratio} |")
    emit()
    print(
        f"(numpy {np.__version__}, {os.cpu_count()} cores, pendulab {pl.__version__}; "
        f"short timings: median of {args.repeats} or of batches; budget {args.budget:g} s)"
    )
    if args.markdown:
        args.markdown.parent.mkdir(parents=True, exist_ok=True)
        args.markdown.write_text("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
