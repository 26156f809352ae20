"""Estimated against true global error on the hard 40-digit cases (issue 17, item 4).

For every case of ``testdata/hard_cases.json`` and every stored time t ≤ ``--t-max`` [s]: DOP853 at
rtol 1e-12 (atol 1e-14 l) and RATTLE8 at dt = 0.05/ω (ω = max(√(|g|/l), |v₀|/l)) with
``error_estimate=True``; the true error is |x − x_golden| [m]. Writes ``docs/img/error_estimates.png``
(estimate against truth, log-log, the float64 floor marked) and prints the figures quoted in
docs/integrators.md: how many samples lie above 100× the floor (``floor_normwise`` × l), how many of
those have the estimate within a factor 10 (and 2) of the truth, and ``accuracy=1e-8`` met or not per
case (to t = min(100 s, t-max)).

Run: ``.venv/bin/python bench/accuracy_validation.py --t-max 1000`` (minutes; 10⁴ s: much longer).

``--cost``: instead, the cost of ``error_estimate=True`` against the plain run, per method on a few
motions (wall time, best of 3, and right-hand side evaluations, the estimate's runs included), and
which companion the fixed-step methods used (docs/integrators.md, "Error estimates").
"""

from __future__ import annotations

import argparse
import json
import math
import os
import time
from pathlib import Path
from typing import Any

import numpy as np
import pendulab as pl
from pendulab.accuracy import estimate

REPO = Path(__file__).resolve().parents[1]
PLOT = REPO / "docs" / "img" / "error_estimates.png"


#: Motions for --cost: (name, model keywords, start angles [rad, rad/s], t_end [s]).
COST_CASES = [
    ("rosette 60°", {}, {"theta": math.radians(60), "phi_dot": 2.0}, 500.0),
    ("near the top 170°", {}, {"theta": math.radians(170), "phi_dot": 0.3}, 500.0),
    ("over the top", {}, {"theta": math.radians(90), "theta_dot": 8.0}, 500.0),
    (
        "damped, driven",
        {"model": "damped", "damping": 0.1, "forcing_amplitude": 1.0, "forcing_omega": 2.0},
        {"theta": 1.0, "phi_dot": 1.0},
        500.0,
    ),
]
#: Step per fixed-step method in units of 1/ω (its error well above round-off, the method stable).
COST_STEPS = {
    "rk4": 0.005,
    "rattle": 0.002,
    "rattle4": 0.01,
    "rattle6": 0.02,
    "rattle8": 0.04,
    "rkmk4": 0.005,
    "rk4_angles": 0.005,
}


def _best_time(*args: Any, repeats: int = 3, **kwargs: Any) -> tuple[float, Any]:
    """The best wall time and CPU time [s] of ``pl.simulate(*args, **kwargs)`` over ``repeats`` runs
    (CPU time: the figure that a loaded machine disturbs least), and its result."""
    wall, cpu, out = math.inf, math.inf, None
    for _ in range(repeats):
        t, c = time.perf_counter(), time.process_time()
        out = pl.simulate(*args, **kwargs)
        wall, cpu = min(wall, time.perf_counter() - t), min(cpu, time.process_time() - c)
    return (wall, cpu), out


def cost() -> None:
    """Prints the cost ratios of error_estimate=True against the plain run (a markdown table); the
    estimate / true error range over the samples whose true error is above 10 % of its largest."""
    print(f"load average before: {os.getloadavg()[0]:.2f}")
    print(
        "| motion | method | setting | companion | rhs evaluations | CPU time: estimate | CPU time: all "
        "| wall time: all | estimate / true error | largest: estimate / true |"
    )
    print("|---|---|---|---|---:|---:|---:|---:|---:|---:|")
    for name, model, angles, t_end in COST_CASES:
        p = pl.Pendulum(length=1.0, g=9.81, **model)
        s0 = p.state_from_angles(**angles)
        omega = max(math.sqrt(9.81), float(np.linalg.norm(s0.v)))
        for method in pl.method_names():
            if method == "dop853":
                settings = [{"rtol": 1e-10, "atol": 1e-12}, {"rtol": 1e-13, "atol": 1e-15}]
            else:
                settings = [{"dt": t_end / (20 * math.ceil(t_end * omega / (20 * COST_STEPS[method])))}]
            for kw in settings:
                kw = kw | ({"save_every": 20} if "dt" in kw else {"save_at": np.linspace(0, t_end, 51)})
                try:
                    t_plain, plain = _best_time(p, s0, t_end, method=method, **kw)
                    t_est, tr = _best_time(p, s0, t_end, method=method, error_estimate=True, **kw)
                except (pl.InvalidInputError, pl.IntegrationError) as e:
                    print(f"| {name} | {method} | refused: {str(e).splitlines()[0][:70]} | | | | | | | |")
                    continue
                est = tr.error_estimate
                work = 1.0 + est.cost
                # the estimate alone (without tr.error, the exact solution at every sample)
                plain_kw = kw | {"method": method, "t0": 0.0, "drift": "raise"}
                c = time.process_time()
                estimate(pl.simulate, plain, s0, plain_kw)
                cpu_est = (t_plain[1] + time.process_time() - c) / t_plain[1]
                fit, largest = "—", "—"
                if tr.error is not None:
                    big = tr.error.position > max(0.1 * tr.error.max_position, 1e-13)
                    if big.any():
                        r = est.position[big] / tr.error.position[big]
                        fit = f"{r.min():.2f} … {r.max():.2f}"
                        largest = f"{est.max_position / tr.error.max_position:.2f}"
                setting = f"dt = {kw['dt']:.2e} s" if "dt" in kw else f"rtol {kw['rtol']:.0e}"
                print(
                    f"| {name} | {method} | {setting} | {est.reference.get('companion', 'tighter')} | "
                    f"{work:.2f} | {cpu_est:.2f} | {t_est[1] / t_plain[1]:.2f} | "
                    f"{t_est[0] / t_plain[0]:.2f} | {fit} | {largest} |",
                    flush=True,
                )
                del plain


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t-max", type=float, default=1000.0)
    ap.add_argument("--cost", action="store_true", help="measure the cost of the estimate instead")
    args = ap.parse_args()
    if args.cost:
        cost()
        return
    cases = json.loads((REPO / "testdata" / "hard_cases.json").read_text())["cases"]
    points: dict[str, list[tuple[float, float, float]]] = {"dop853": [], "rattle8": []}
    met, total, missed = 0, 0, []
    companions: dict[str, list[tuple[str, float]]] = {}
    for case in cases:
        ell = case["length"]
        p = pl.Pendulum(length=ell, mass=case["mass"], g=case["g"])
        s0 = p.state(np.array(case["x0"]), np.array(case["v0"]))
        omega = max(math.sqrt(abs(case["g"]) / ell), float(np.linalg.norm(case["v0"])) / ell)
        for method in points:
            samples = [s for s in case["samples"] if s["t"] <= args.t_max]
            if method == "rattle8":
                samples = [s for s in samples if s["t"] * omega / 0.05 <= 2e7]  # bound the work
            times = [s["t"] for s in samples]
            kw = {"rtol": 1e-12, "atol": 1e-14 * ell} if method == "dop853" else {"dt": 0.05 / omega}
            tr = pl.simulate(p, s0, times[-1], method=method, save_at=times, error_estimate=True, **kw)
            ref = tr.error_estimate.reference
            companions.setdefault(method, []).append(
                (ref.get("companion", "tighter"), tr.error_estimate.cost)
            )
            if ref.get("why"):
                print(f"{case['name']} {method}: dt/2 companion: {ref['why']}")
            for s in samples:
                i = int(np.argmin(np.abs(tr.t - s["t"])))
                true = float(np.linalg.norm(tr.x[i] - np.array([float(c) for c in s["x_str"]])))
                points[method].append((true, float(tr.error_estimate.position[i]), s["floor_normwise"] * ell))
        times = [s["t"] for s in case["samples"] if s["t"] <= min(100.0, args.t_max)]
        total += 1
        try:
            tr = pl.simulate(p, s0, times[-1], accuracy=1e-8, save_at=times)
            worst = max(
                float(
                    np.linalg.norm(
                        tr.x[int(np.argmin(np.abs(tr.t - s["t"])))] - np.array([float(c) for c in s["x_str"]])
                    )
                )
                for s in case["samples"]
                if s["t"] <= times[-1]
            )
            ok = worst <= 1e-8 * ell
        except pl.InvalidInputError as e:
            ok, worst = False, math.nan
            print(f"{case['name']}: accuracy=1e-8 refused: {e}")
        met += ok
        if not ok:
            missed.append(case["name"])
        print(
            f"{case['name']:28} accuracy=1e-8: true {worst / ell:.2e} l {'met' if ok else 'MISSED'}",
            flush=True,
        )
    for method, used in companions.items():
        kinds = {k: sum(1 for c, _ in used if c == k) for k in sorted({c for c, _ in used})}
        costs = [1.0 + c for _, c in used]
        print(
            f"{method}: companions {kinds}; total cost (rhs evaluations, plain run = 1) "
            f"{min(costs):.2f} .. {max(costs):.2f}, median {float(np.median(costs)):.2f}"
        )
    for method, pts in points.items():
        arr = np.array(pts)
        above = arr[arr[:, 0] > 100 * arr[:, 2]]
        r = above[:, 1] / above[:, 0]
        print(
            f"{method}: {len(arr)} samples, {len(above)} above 100x floor; estimate within 10x: "
            f"{np.sum((r >= 0.1) & (r <= 10))}, within 2x: {np.sum((r >= 0.5) & (r <= 2))}; "
            f"ratio range {r.min():.2f} .. {r.max():.2f}; true error range {above[:, 0].min():.1e} .. "
            f"{above[:, 0].max():.1e} m"
        )
    print(f"accuracy=1e-8 met in {met} of {total} cases; missed: {missed}")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 6))
    for (method, pts), marker in zip(points.items(), ("o", "^"), strict=True):
        arr = np.array(pts)
        above = arr[:, 0] > 100 * arr[:, 2]
        ax.loglog(
            arr[above, 0], arr[above, 1], marker, ms=5, alpha=0.7, label=f"{method} (true > 100× floor)"
        )
        ax.loglog(
            arr[~above, 0].clip(1e-18),
            arr[~above, 1].clip(1e-18),
            marker,
            ms=4,
            mfc="none",
            alpha=0.4,
            label=f"{method} (at the floor)",
        )
    lo, hi = 1e-17, 10.0
    ax.plot([lo, hi], [lo, hi], "k-", lw=1)
    ax.plot([lo, hi], [10 * lo, 10 * hi], "k:", lw=1)
    ax.plot([lo, hi], [lo / 10, hi / 10], "k:", lw=1, label="factor 10")
    ax.set_xlabel("true error |x − x_golden| [m]")
    ax.set_ylabel("estimated error [m]")
    ax.set_title(f"{len(cases)} hard cases, t ≤ {args.t_max:g} s")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)
    print(f"wrote {PLOT}")


if __name__ == "__main__":
    main()
