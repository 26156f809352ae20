"""Pendulab against its peers (issue 5, parts 3 and 4), side by side in one process.

Cases (t_end = 100 s, l = 1 m, m = 1 kg, g = 9.81 m/s²): the scenarios ``rosette``, ``near_top``
(1° below the top) and ``over_the_top`` (planar revolutions, J₃ = 0) of examples/scenarios/.
Reference: Pendulab's exact solution at t = 100 s (``pl.exact``), itself checked here against the
40-digit mpmath golden data of testdata/golden_states.json (the difference is printed and stored).
Error: the final position error |x(100 s) − x_ref|/l. For every method a step size (fixed-step) or a
tolerance (adaptive; atol = rtol/100) is scanned from coarse to fine until the error stops improving,
falls below 1e-13, one run takes more than ``--cap`` seconds (default 5) or the whole scan 10 times
that; "time to 1e-10" is the cheapest setting that reaches it. Every wall time is a median of
repeated runs (5 for fast runs, at least 3, 1 beyond 1.5 s), and every comparison is a ratio of
figures measured in this one run.

Peers (each behind a function, so this module imports with numpy and pendulab alone):
- SciPy ``solve_ivp`` RK45 and DOP853 on the Cartesian ODE T-2.4 (ẋ = v, v̇ = −g e₃ + λ x,
  λ = (g z − |v|²)/l²) — not the angle ODE, which is singular at the poles (sin θ in a denominator;
  the over-the-top case passes through both);
- numba: a fixed-step RK4 loop on T-2.4 (``@njit``, compile time excluded);
- C: rk4.c, a plain RK4 loop and a hand-vectorised ensemble (SoA blocks of 64, ``omp simd``, OpenMP
  over 1 or 2 threads), built with ``gcc -O3 -march=native -fopenmp``, called once per run via ctypes;
- MuJoCo: a point mass on a ball joint, RK4 integrator, contacts and constraints disabled, stepped
  in C with ``mj_step(m, d, nstep=n)``; the body carries a tiny isotropic inertia I_c = 1e-6 m l²
  (MuJoCo needs one) and gravity is raised by the factor (1 + I_c/(m l²)) that makes the motion of
  its centre of mass exactly the spherical pendulum's (the spin about the rod stays zero);
- JAX + Diffrax on CPU, float64: Tsit5 and Dopri8 with a PID controller (pcoeff = icoeff = 0.3),
  ``jax.jit``-compiled once per solver (compile time excluded).
Pendulab: every method of ``pl.methods()`` through ``pl.simulate``, DOP853 also with ``conserve``,
the ensemble kernel (``_core.EnsembleRun``, the kernel of ``pl.simulate_ensemble``) and the exact
solution.

Run: ``make bench-peers`` (installs the peers into bench/peers/.venv, builds Pendulab there, runs
this script, writes bench/peers/results/, docs/img/peers_work_precision.png and the "Against peers"
section of docs/performance.md). ``--quick`` is a short smoke run that writes
results/peers_quick.json only. ``--ensembles-only`` runs the ensembles alone (the throughput table and
issue 29's ratio C RK4 / ``pl.simulate_ensemble`` at 10³ and 10⁴ steps) and writes
results/peers_ensembles.json (quick: peers_ensembles_quick.json) only.

The parts, one concept each: peers_cases.py (cases, reference, what a method is), peers_methods.py
(Pendulab, SciPy, numba, C), peers_engines.py (MuJoCo, JAX + Diffrax), peers_measure.py (scans,
step rates), peers_ensembles.py (ensembles, the rotation-number map), peers_targets.py (issue 5's
targets), peers_report.py (plot, Markdown); harness.py (timing, errors, tables). This file: which
peers are installed, the command line and the results files.
"""

from __future__ import annotations

import argparse
import datetime as dt_mod
import json
import math
import os
import platform
import shutil
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import harness as hz
from peers_cases import CASES, DOCS, PLOT, RESULTS, Method, load_cases
from peers_engines import diffrax_methods, mujoco_methods
from peers_ensembles import api_vs_c_worker, ensemble_worker, ensembles, rotation_map
from peers_measure import exact_run, scan, step_rates
from peers_methods import c_methods, numba_methods, pendulab_methods, scipy_methods
from peers_report import markdown, plot
from peers_targets import targets

# --------------------------------------------------------------------------------------------------
# Report


def peer_versions() -> dict[str, str | None]:
    """Version of each peer, or None when it does not import (then its methods are skipped)."""
    out: dict[str, str | None] = {}
    for mod in ("pendulab", "numpy", "scipy", "numba", "mujoco", "jax", "diffrax", "matplotlib"):
        try:
            out[mod] = __import__(mod).__version__
        except Exception:
            out[mod] = None
    try:
        out["gcc"] = subprocess.run(
            ["gcc", "-dumpfullversion"], capture_output=True, text=True
        ).stdout.strip()
    except OSError:
        out["gcc"] = None
    return out


def all_methods(
    versions: dict[str, str | None], only: set[str] | None
) -> tuple[list[Method], dict[str, str | None]]:
    """The methods to scan and, per family, why it is skipped (None: included)."""
    families: dict[str, tuple[str | None, Callable[[], list[Method]]]] = {
        "pendulab": ("pendulab", pendulab_methods),
        "C": ("gcc", c_methods),
        "numba": ("numba", numba_methods),
        "mujoco": ("mujoco", mujoco_methods),
        "scipy": ("scipy", scipy_methods),
        "diffrax": ("diffrax", diffrax_methods),
    }
    methods: list[Method] = []
    skipped: dict[str, str | None] = {}
    for fam, (mod, make) in families.items():
        if only is not None and fam not in only:
            skipped[fam] = "not selected"
        elif mod is not None and versions.get(mod) is None:
            skipped[fam] = f"{mod} is not installed"
        elif fam == "diffrax" and versions.get("jax") is None:
            skipped[fam] = "jax is not installed"
        else:
            skipped[fam] = None
            methods += make()
    return methods, skipped


def ensembles_only(quick: bool, out: Path | None) -> None:
    """``--ensembles-only``: the ensembles section alone, its results JSON with the load average (1 min)
    at the start and the end; no report."""
    load_start = os.getloadavg()[0]
    c_ok = shutil.which("gcc") is not None
    print("ensembles" + ("" if c_ok else " (gcc not found: no C RK4 ensemble)"), flush=True)
    ens = ensembles(quick, c_ok)
    meta = {
        "date": dt_mod.datetime.now(dt_mod.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "quick": quick,
        "cpu": hz.cpu_description(),
        "load_start": load_start,
        "load_end": os.getloadavg()[0],
    }
    RESULTS.mkdir(exist_ok=True)
    out = out or RESULTS / ("peers_ensembles_quick.json" if quick else "peers_ensembles.json")
    out.write_text(json.dumps({"meta": meta, "ensembles": ens}, indent=1, default=str) + "\n")
    print(f"wrote {out} (load average {load_start:.1f} at the start, {meta['load_end']:.1f} at the end)")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="short smoke run (rosette only, coarse scans)")
    ap.add_argument("--only", help="comma-separated families: pendulab,C,numba,mujoco,scipy,diffrax")
    ap.add_argument("--cap", type=float, help="stop refining a scan after a run longer than this [s]")
    ap.add_argument("--docs", type=Path, help="Markdown file to update between the peers markers")
    ap.add_argument(
        "--out", type=Path, help="results JSON (default results/peers.json, quick: peers_quick.json)"
    )
    ap.add_argument(
        "--no-report", action="store_true", help="write the results JSON only (no CSV, plot or docs)"
    )
    ap.add_argument(
        "--ensembles-only", action="store_true",
        help="only the ensembles (with issue 29's ratio); writes results/peers_ensembles[_quick].json",
    )  # fmt: skip
    ap.add_argument("--ensemble-worker", nargs=5, type=int, help=argparse.SUPPRESS)
    ap.add_argument("--api-vs-c-worker", type=int, help=argparse.SUPPRESS)
    args = ap.parse_args()
    if args.ensemble_worker:
        print(json.dumps(ensemble_worker(*args.ensemble_worker)))
        return
    if args.api_vs_c_worker is not None:
        print(json.dumps(api_vs_c_worker(args.api_vs_c_worker)))
        return
    if args.ensembles_only:
        ensembles_only(args.quick, args.out)
        return

    t_start = time.perf_counter()
    load_start = os.getloadavg()[0]
    cap = args.cap if args.cap is not None else (0.5 if args.quick else 5.0)
    budget = 0.3 if args.quick else 1.5
    versions = peer_versions()
    if versions["pendulab"] is None:
        raise SystemExit(
            "pendulab does not import: run `make bench-peers` (builds it into bench/peers/.venv)"
        )
    only = set(args.only.split(",")) if args.only else None
    methods, skipped = all_methods(versions, only)
    print("versions:", versions, "\nskipped:", {k: v for k, v in skipped.items() if v}, flush=True)
    cases = load_cases(("rosette",) if args.quick else CASES)
    for c in cases:
        print(f"case {c.name}: exact vs golden {c.exact_vs_golden:.1e}, floor {c.floor:.1e}", flush=True)

    runs: list[hz.Run] = []
    for case in cases:
        runs.append(exact_run(case))
        for m in methods:
            try:
                runs += scan(m, case, args.quick, cap, budget)
            except Exception as exc:  # a peer that cannot even be set up is reported, not fatal
                print(f"  {m.name} {case.name}: set-up failed: {exc}", flush=True)
                runs.append(hz.Run(m.name, case.name, math.nan, "none", math.nan, 0, failed=f"set-up: {exc}"))
    print("step rates", flush=True)
    rates = step_rates(cases, args.quick, skipped)
    print("ensembles", flush=True)
    ens = ensembles(args.quick, skipped.get("C") is None)
    print("rotation-number map", flush=True)
    rmap = rotation_map(args.quick)
    tgt = targets(runs, rates, ens, rmap, cases)
    meta = {
        "date": dt_mod.datetime.now(dt_mod.UTC).strftime("%Y-%m-%d %H:%M UTC"),
        "quick": args.quick,
        "cap": cap,
        "versions": versions,
        "skipped": skipped,
        "rustflags": os.environ.get("PEERS_RUSTFLAGS", ""),
        "machine": {
            "cpus": os.cpu_count(),
            "platform": platform.platform(),
            "processor": platform.processor(),
            "cpu": hz.cpu_description(),
        },
        "load_start": load_start,
        "load_end": os.getloadavg()[0],
        "wall_total": time.perf_counter() - t_start,
    }
    for t in tgt:
        print(f"{t['verdict']:4s}  {t['target']}: {t['value']}  ({t['detail']})")
    RESULTS.mkdir(exist_ok=True)
    out = args.out or RESULTS / ("peers_quick.json" if args.quick else "peers.json")
    payload = {
        "meta": meta,
        "cases": [
            {
                "name": c.name, "x0": c.x0.tolist(), "v0": c.v0.tolist(), "x_ref": c.x_ref.tolist(),
                "v_ref": c.v_ref.tolist(), "exact_vs_golden": c.exact_vs_golden, "floor": c.floor,
            }
            for c in cases
        ],
        "targets": tgt,
        "rates": rates,
        "ensembles": ens,
        "rotation_map": rmap,
        "runs": [r.as_dict() for r in runs],
    }  # fmt: skip
    out.write_text(json.dumps(payload, indent=1, default=str) + "\n")
    if not args.quick and not args.no_report:
        import csv

        with (RESULTS / "peers_runs.csv").open("w", newline="") as fh:
            cols = list(runs[0].as_dict())
            w = csv.DictWriter(fh, fieldnames=cols)
            w.writeheader()
            for r in runs:
                w.writerow({k: (json.dumps(v) if isinstance(v, dict) else v) for k, v in r.as_dict().items()})
        plot(runs, cases, PLOT)
    docs = args.docs or (None if args.quick or args.no_report else DOCS)
    if docs is not None:
        body = markdown(runs, cases, rates, ens, rmap, tgt, meta)
        docs.write_text(hz.replace_between_markers(docs.read_text(), body))
        print(f"wrote {docs}")
    print(f"wrote {out} ({time.perf_counter() - t_start:.0f} s)")


if __name__ == "__main__":
    main()
