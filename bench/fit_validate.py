#!/usr/bin/env python3
"""Are ``pl.fit``'s error bars honest? Synthetic data from known pendulums with Gaussian noise, 300
seeded trials per data kind by default: the fraction of trials whose true value lies within 2
standard errors (95.4 % for honest errors; the target is 90–98 %), and the largest relative error
without noise (target ≤ 1e-8). Prints a Markdown table (for docs/fit.md) and writes it to
bench/results/fit_validate.md. Usage: ``make validate-fit`` or
``.venv/bin/python bench/fit_validate.py [--trials N] [--kinds a,b]``. SI units.
"""

from __future__ import annotations

import argparse
import math
import time
import warnings
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pendulab as pl
from tqdm.auto import tqdm

G = np.array([0.0, 0.0, 9.81])


def _truth(model: str) -> tuple[pl.Pendulum, pl.State]:
    if model == "ideal":
        p = pl.Pendulum(length=0.8, g=9.81)
        return p, p.state_from_angles(0.5, 0.3, 0.1, 0.8)
    p = pl.Pendulum(length=0.7, g=9.81, damping=0.04)
    return p, p.state_from_angles(0.45, 0.0, 0.0, 0.2)


def _motion(model: str, t: np.ndarray) -> tuple[pl.Pendulum, np.ndarray, np.ndarray]:
    p, s = _truth(model)
    if model == "ideal":
        x, v = pl.exact(p, s).state(t)
        return p, x, v
    tr = pl.simulate(p, s, float(t[-1]), method="dop853", rtol=1e-13, atol=1e-15, save_at=t)
    return p, tr.x, tr.v


Case = tuple[str, str, list[str], Callable[[np.random.Generator, float], dict]]


def cases() -> list[Case]:
    t1 = np.linspace(0.0, 10.0, 400)
    _, x1, _ = _motion("ideal", t1)
    t2 = np.arange(0.0, 15.0, 1 / 30)
    _, x2, _ = _motion("damped", t2)
    t3 = np.arange(0.0, 15.0, 0.02)
    p3, x3, v3 = _motion("damped", t3)
    acc = p3.diagnostics(x3, v3, t3)["acceleration"]
    f3 = np.linalg.norm(acc + G, axis=1)
    w3 = np.linalg.norm(np.cross(x3, v3), axis=1) / 0.7**2
    th1 = np.arctan2(np.hypot(x1[:, 0], x1[:, 1]), -x1[:, 2])
    ph1 = np.arctan2(x1[:, 1], x1[:, 0])
    planar = np.arctan2(x2[:, 0], -x2[:, 2])

    def noisy(a: np.ndarray, rng: np.random.Generator, s: float) -> np.ndarray:
        return a + s * rng.standard_normal(a.shape)

    return [
        (
            "positions (3-D, ideal)",
            "ideal",
            ["length", "g"],
            lambda rng, s: {"t": t1, "positions": noisy(x1, rng, 2e-3 * s), "sigma": 2e-3 if s else None},
        ),
        (
            "angles (ideal, l known)",
            "ideal",
            ["g"],
            lambda rng, s: {
                "t": t1,
                # σ is the noise of θ and of the arc sin θ·φ (isotropic on the unit sphere, docs/fit.md)
                "angles": (
                    noisy(th1, rng, 2e-3 * s),
                    ph1 + 2e-3 * s * rng.standard_normal(len(ph1)) / np.sin(th1),
                ),
                "sigma": 2e-3 if s else None,
            },
        ),
        (
            "video x, z, unknown pivot (damped)",
            "damped",
            ["length", "g", "damping", "pivot"],
            lambda rng, s: {
                "t": t2,
                "positions": noisy(x2[:, [0, 2]] + [0.3, 1.1], rng, 1.5e-3 * s),
                "sigma": 1.5e-3 if s else None,
            },
        ),
        (
            "planar angle (damped, l known)",
            "damped",
            ["g", "damping"],
            lambda rng, s: {
                "t": t2,
                "planar_angle": noisy(planar, rng, 3e-3 * s),
                "sigma": 3e-3 if s else None,
            },
        ),
        (
            "phone |a - g|, |w| (damped)",
            "damped",
            ["length", "g", "damping"],
            lambda rng, s: {
                "t": t3,
                "specific_force": noisy(f3, rng, 0.03 * s),
                "angular_speed": noisy(w3, rng, 0.005 * s),
                "sigma": {"specific_force": 0.03, "angular_speed": 0.005} if s else None,
            },
        ),
    ]


def run_case(case: Case, trials: int) -> dict:
    name, model, names, make = case
    truth_p, _ = _truth(model)
    truth = {
        "length": truth_p.length,
        "g": truth_p.g,
        "damping": truth_p.extra.get("damping", 0.0),
        "pivot_x": 0.3,
        "pivot_z": 1.1,
    }
    base = pl.Pendulum(length=truth_p.length, model=model)
    kw = make(np.random.default_rng(0), 0.0)
    kw.pop("sigma")
    exact_fit = pl.fit(pendulum=base, fit=names, **kw)
    worst = max(abs(exact_fit.params[n] / truth[n] - 1.0) for n in exact_fit.params if n in truth)
    inside = {n: 0 for n in exact_fit.params if n in truth}
    began = time.perf_counter()
    for seed in tqdm(range(trials), desc=name, leave=False):
        kw = make(np.random.default_rng(seed + 1), 1.0)
        sigma = kw.pop("sigma")
        res = pl.fit(pendulum=base, fit=names, sigma=sigma, **kw)
        for n in inside:
            inside[n] += abs(res.params[n] - truth[n]) <= 2.0 * res.stderr[n]
    per = (time.perf_counter() - began) / trials
    return {
        "name": name,
        "worst_noise_free": worst,
        "coverage": {n: c / trials for n, c in inside.items()},
        "seconds": per,
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=300)
    ap.add_argument("--kinds", default=None, help="comma-separated case numbers (1-based) to run")
    args = ap.parse_args()
    chosen = cases()
    if args.kinds:
        chosen = [chosen[int(k) - 1] for k in args.kinds.split(",")]
    rows = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        for case in chosen:
            r = run_case(case, args.trials)
            rows.append(r)
            print(r)
    lines = [
        f"| data kind | fitted | within 2σ ({args.trials} trials; 95.4 % expected) "
        "| noise-free max rel. error | s per fit | |",
        "|---|---|---|---|---|---|",
    ]
    for r in rows:
        cov = ", ".join(f"{n} {100 * c:.0f} %" for n, c in r["coverage"].items())
        ok = all(0.90 <= c <= 0.98 for c in r["coverage"].values()) and r["worst_noise_free"] <= 1e-8
        lines.append(
            f"| {r['name']} | {', '.join(r['coverage'])} | {cov} | {r['worst_noise_free']:.1e} "
            f"| {r['seconds']:.2f} | " + ("PASS" if ok else "CHECK") + " |"
        )
    table = "\n".join(lines)
    print(table)
    out = Path(__file__).resolve().parent / "results" / "fit_validate.md"
    out.parent.mkdir(exist_ok=True)
    out.write_text(table + "\n", encoding="utf-8")
    if not math.isfinite(len(rows)):  # pragma: no cover
        raise SystemExit(1)


if __name__ == "__main__":
    main()
