#!/usr/bin/env python3
"""Validation of ``pl.fit`` with the defaults a user gets (``sigma`` left out) on data from an
independent integrator (``testdata/generate/independent_pendulum.py``: SciPy DOP853 of a hand-written
Cartesian model; the cases in ``bench/fit_validate_cases.py``). Per case, seeded noisy trials:

- right model: coverage of ±2 stderr per fitted parameter (target 90–98 %; 95.4 % for honest bars),
  and the rate of warnings anyway (false alarms);
- wrong model: the rate of trials with a warning (target ≥ 95 %), and how far the noise-free misfit
  stands above the noise (``detectability`` = rms misfit / σ; below ~0.3 no fit can tell);
- degenerate data: a clear error, a warning, "not determined" or an honest interval, in time — never
  another exception, a hang, or a confident wrong value;
- units: the same swing in m and in mm must give the same fit up to the scale.

A verdict is FAIL when the 95 % Clopper–Pearson interval of the measured rate lies wholly outside the
target (so that a few trials cannot fail an honest fit by chance), or on any crash or hang. Every fit
runs with ``time_limit``; a trial running past ``--hard-limit`` s has its worker process killed
("hang"); the whole run stops dispatching after ``--budget`` s. At most 2 worker processes, niced.

Usage::

    .venv/bin/python bench/fit_validate.py                 # 40 trials per case (make validate-fit)
    .venv/bin/python bench/fit_validate.py --quick         # 4 trials per case (CI-size)
    .venv/bin/python bench/fit_validate.py --trials 20 --cases 1,9 --workers 1

Writes ``bench/results/fit_validate.json`` (every trial) and ``.md`` (the summary, with tracebacks).
Units: SI (seconds for times).
"""

from __future__ import annotations

import argparse
import contextlib
import json
import math
import multiprocessing as mp
import os
import sys
import time
import traceback
from pathlib import Path
from typing import Any

for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS", "RAYON_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

#: Warnings that say the search stopped, not that the data disagree with the model (nor that they agree
#: with a simpler one: a swing consistent with a planar one, fitted as spherical; fitting/mirror.py).
NOT_A_DIAGNOSIS = ("time limit", "did not converge", "interrupted", "consistent with a planar swing")
NUMPY_NOISE = ("encountered in", "divide by zero", "overflow", "invalid value", "Mean of empty")


# --- one trial (in a worker process) ------------------------------------------------------------


def trial(index: int, seed: int, time_limit: float, sigma_given: bool = False) -> dict[str, Any]:
    """Case ``index``, trial ``seed`` (−1: noise-free): data, fit, and what came out; with
    ``sigma_given`` the fit is told the true noise (not a user's default: a check of the σ path)."""
    import warnings

    import numpy as np
    import pendulab as pl
    from fit_validate_cases import MM_SCALE, cases

    case = cases()[index]
    rng = np.random.default_rng([index, seed + 1])
    data = case.make(rng, 0.0 if seed < 0 else 1.0)
    out: dict[str, Any] = {"case": index, "seed": seed, "status": "ok", "warnings": []}

    def one(kw: dict[str, Any], pendulum: dict[str, Any], scale: float = 1.0) -> Any:
        if sigma_given and seed >= 0:
            given = data.sigma_kw if data.sigma_kw is not None else data.sigma
            kw = {**kw, "sigma": given * scale if not isinstance(given, dict) else given}
        return pl.fit(
            pendulum=pl.Pendulum(**pendulum), fit=case.fit, loss=case.loss, time_limit=time_limit, **kw
        )

    began = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            res = one(data.kw, case.pendulum)
            if case.sort == "units":
                kw = {**data.kw, "positions": data.kw["positions"] * 1e3}
                pend = {**case.pendulum, "length": case.pendulum.get("length", 1.0) * 1e3}
                pend["g"] = case.pendulum.get("g", 9.81) * 1e3
                res_mm = one(kw, pend, 1e3)
        except pl.InvalidInputError as e:
            out.update(status="error", error=str(e))
        except Exception as e:
            out.update(status="crash", error=f"{type(e).__name__}: {e}", traceback=traceback.format_exc())
    out["seconds"] = time.perf_counter() - began
    messages = [str(w.message) for w in caught if not any(s in str(w.message) for s in NUMPY_NOISE)]
    out["interrupted"] = any("time limit" in m for m in messages)
    if out["status"] != "ok":
        out["warnings"] = messages
        return out
    messages += [str(m) for m in getattr(res, "warnings", []) or []]
    out["warnings"] = sorted(set(messages))
    out["model_warnings"] = [m for m in out["warnings"] if not any(s in m for s in NOT_A_DIAGNOSIS)]
    out["converged"] = bool(res.converged)
    out["params"] = {n: float(res.params[n]) for n in res.params}
    out["stderr"] = {n: float(res.stderr[n]) for n in res.params}
    out["determined"] = {n: bool(res.determined.get(n, True)) for n in res.params}
    out["sigma_fit"] = {k: float(v) for k, v in res.sigma.items()}
    resid = [np.asarray(r, dtype=float).ravel() for r in res.residuals.values()]
    out["rms_over_sigma"] = float(np.sqrt(np.mean(resid[0] ** 2)) / data.sigma) if resid else math.nan
    # the χ² excess against the TRUE noise, in standard deviations of χ²: a goodness-of-fit test that
    # knew σ would see the mismatch when this is large (≫ 3)
    n_values = resid[0].size if resid else 0
    out["chi2_excess_z"] = (
        float((n_values * out["rms_over_sigma"] ** 2 - n_values) / math.sqrt(2.0 * n_values))
        if n_values
        else math.nan
    )
    out["truth"] = dict(data.truth)
    _same_start(out["truth"], out["params"], bool(res.mirror_blind))
    diff = {n: _difference(n, out["params"][n], v) for n, v in out["truth"].items() if n in out["params"]}
    out["rel_error"] = {
        n: float(abs(d / out["truth"][n]) if out["truth"][n] else abs(d)) for n, d in diff.items()
    }
    out["off_in_stderr"] = {n: float(abs(d) / out["stderr"][n]) for n, d in diff.items()}
    out["inside"] = {
        n: bool(out["determined"][n] and abs(d) <= 2.0 * out["stderr"][n]) for n, d in diff.items()
    }
    out["within3"] = {n: bool(abs(d) <= 3.0 * out["stderr"][n]) for n, d in diff.items()}
    if case.sort == "units":
        shift = {
            n: abs(res_mm.params[n] / MM_SCALE[n] - res.params[n]) / res.stderr[n]
            for n in res.params
            if n in MM_SCALE
        }
        ratio = {n: res_mm.stderr[n] / MM_SCALE[n] / res.stderr[n] for n in res.params if n in MM_SCALE}
        out["units_shift_in_stderr"] = {n: float(v) for n, v in shift.items()}
        out["units_stderr_ratio"] = {n: float(v) for n, v in ratio.items()}
    return out


#: The start's angles [rad]: compared modulo 2π (:func:`_difference`).
ANGLES = ("theta0", "phi0")


def _difference(name: str, fitted: float, truth: float) -> float:
    """fitted − truth [the parameter's unit]; for an angle of :data:`ANGLES` wrapped to (−π, π], so
    that φ₀ = −3.1 and 3.1 rad are 0.08 rad apart, not 6.2."""
    d = fitted - truth
    if name in ANGLES:
        d -= 2.0 * math.pi * math.ceil((d - math.pi) / (2.0 * math.pi))
    return d


def _same_start(truth: dict[str, float], params: dict[str, float], mirror_blind: bool) -> None:
    """The true start written as the fit writes it (in place): θ₀ is signed (problem.bounds_of), and
    with φ₀ fitted (θ, φ, θ̇, φ̇) and (−θ, φ + π, −θ̇, φ̇) are the same start; data blind to the mirror
    y → −y cannot tell (φ₀, φ̇₀) from (−φ₀, −φ̇₀): the truth takes the sign of the fit's φ̇₀."""
    if "phi0" in params and truth.get("theta0", 0.0) * params.get("theta0", 0.0) < 0.0:
        truth["theta0"] = -truth["theta0"]
        for n, flip in (("phi0", lambda v: v + math.pi), ("theta_dot0", lambda v: -v)):
            if n in truth:
                truth[n] = flip(truth[n])
    if mirror_blind and params.get("phi_dot0", 0.0) * truth.get("phi_dot0", 0.0) < 0.0:
        for n in ("phi0", "phi_dot0"):  # the data cannot tell the motion from its mirror image y -> -y
            if n in truth:
                truth[n] = -truth[n]


def _worker(conn: Any, time_limit: float, sigma_given: bool) -> None:
    with contextlib.suppress(OSError):
        os.nice(10)
    while True:
        job = conn.recv()
        if job is None:
            return
        index, seed = job
        try:
            result = trial(index, seed, time_limit, sigma_given)
        except BaseException as e:
            result = {
                "case": index,
                "seed": seed,
                "status": "crash",
                "error": repr(e),
                "traceback": traceback.format_exc(),
            }
        conn.send(result)


# --- the pool: at most N workers, a trial past the hard limit is killed ------------------------


def run_all(
    jobs: list[tuple[int, int]],
    workers: int,
    time_limit: float,
    hard: float,
    budget: float,
    stream: Path | None = None,
    sigma_given: bool = False,
) -> list[dict]:
    """Runs the jobs (case index, seed) on at most 2 workers; every result is also appended to the
    JSON-lines file ``stream`` as it arrives (``--summarise`` makes the summary of a partial run)."""
    ctx = mp.get_context("spawn")
    pool: list[dict[str, Any]] = []
    results: list[dict] = []
    pending = list(jobs)
    began = time.monotonic()

    sink = stream.open("a", encoding="utf-8") if stream else None

    def record(r: dict) -> None:
        results.append(r)
        if sink:
            sink.write(json.dumps(r) + "\n")
            sink.flush()

    def spawn() -> dict[str, Any]:
        here, there = ctx.Pipe()
        proc = ctx.Process(target=_worker, args=(there, time_limit, sigma_given), daemon=True)
        proc.start()
        return {"proc": proc, "conn": here, "job": None, "since": 0.0}

    pool = [spawn() for _ in range(max(1, min(workers, 2, len(jobs))))]
    done = 0
    while pending or any(w["job"] is not None for w in pool):
        for i, w in enumerate(pool):
            if w["job"] is None and pending and time.monotonic() - began < budget:
                w["job"], w["since"] = pending.pop(0), time.monotonic()
                w["conn"].send(w["job"])
            elif w["job"] is not None and w["conn"].poll(0.05):
                record(w["conn"].recv())
                done += 1
                print(f"[{done}/{len(jobs)}] {_line(results[-1])}", flush=True)
                w["job"] = None
            elif w["job"] is not None and time.monotonic() - w["since"] > hard:
                index, seed = w["job"]
                w["proc"].kill()  # our own worker, by its handle
                w["proc"].join()
                record(
                    {
                        "case": index,
                        "seed": seed,
                        "status": "hang",
                        "seconds": hard,
                        "warnings": [],
                        "error": f"no answer within {hard:g} s (worker killed)",
                    }
                )
                done += 1
                print(f"[{done}/{len(jobs)}] {_line(results[-1])}", flush=True)
                pool[i] = spawn()
        if pending and time.monotonic() - began >= budget and all(w["job"] is None for w in pool):
            print(f"budget of {budget:g} s spent: {len(pending)} trials not run", flush=True)
            break
        time.sleep(0.02)
    for w in pool:
        with contextlib.suppress(BrokenPipeError, OSError):
            w["conn"].send(None)
        w["proc"].join(timeout=5)
        if w["proc"].is_alive():
            w["proc"].kill()
    if sink:
        sink.close()
    return results


def _line(r: dict) -> str:
    return (
        f"case {r['case'] + 1} seed {r['seed']}: {r['status']} {r.get('seconds', 0):.1f} s"
        + (f" warn={len(r['warnings'])}" if r.get("warnings") else "")
        + (f" {r['error'][:120]}" if "error" in r else "")
    )


def main() -> None:
    from fit_validate_cases import cases
    from fit_validate_report import summarise

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--trials", type=int, default=40, help="noisy trials per case (default 40)")
    ap.add_argument("--quick", action="store_true", help="4 trials per case, degenerate cases 2")
    ap.add_argument("--cases", default=None, help="comma-separated case numbers (1-based)")
    ap.add_argument("--workers", type=int, default=2, help="worker processes (at most 2)")
    ap.add_argument("--time-limit", type=float, default=60.0, help="pl.fit(time_limit=) per fit [s]")
    ap.add_argument("--hard-limit", type=float, default=240.0, help="kill a trial after this [s]")
    ap.add_argument("--budget", type=float, default=4 * 3600.0, help="stop dispatching after this [s]")
    ap.add_argument(
        "--out", default=str(HERE / "results" / "fit_validate"), help="output path without suffix"
    )
    ap.add_argument(
        "--sigma-given", action="store_true", help="tell the fit the true noise (not the default)"
    )
    ap.add_argument("--summarise", action="store_true", help="summarise OUT.jsonl (a partial run) and stop")
    args = ap.parse_args()
    with contextlib.suppress(OSError):
        os.nice(5)
    all_cases = cases()
    chosen = [int(k) - 1 for k in args.cases.split(",")] if args.cases else list(range(len(all_cases)))
    trials = 4 if args.quick else args.trials
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    stream = out.with_suffix(".jsonl")
    if args.summarise:
        results = [json.loads(line) for line in stream.read_text("utf-8").splitlines() if line.strip()]
        summary, text = summarise(all_cases, chosen, results, trials, math.nan, args.sigma_given)
        out.with_suffix(".md").write_text(text, "utf-8")
        print(text)
        return
    stream.unlink(missing_ok=True)
    # noise-free fits first (detectability, accuracy), then seed by seed across the cases, so that a
    # partial run (budget, --summarise) has every case
    jobs = [(i, -1) for i in chosen if all_cases[i].sort in ("right", "wrong")]
    for s in range(trials):
        for i in chosen:
            n = min(trials, 2) if all_cases[i].sort in ("degenerate", "units") and args.quick else trials
            jobs += [(i, s)] if s < n else []
    began = time.monotonic()
    results = run_all(
        jobs, args.workers, args.time_limit, args.hard_limit, args.budget, stream, args.sigma_given
    )
    summary, text = summarise(all_cases, chosen, results, trials, time.monotonic() - began, args.sigma_given)
    out.with_suffix(".json").write_text(
        json.dumps({"summary": summary, "trials": results}, indent=1), "utf-8"
    )
    out.with_suffix(".md").write_text(text, "utf-8")
    print(text)


if __name__ == "__main__":
    main()
