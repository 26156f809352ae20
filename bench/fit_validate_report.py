"""The summary of ``bench/fit_validate.py``: per case the rates, their 95 % Clopper–Pearson intervals
(``scipy.stats.binomtest``), a verdict, and the failures with their tracebacks, as a dict (JSON) and
Markdown. A rate's verdict is FAIL only when its whole interval lies outside the target: coverage of
±2 stderr 90–98 % where the model is right, warnings in ≥ 95 % of the trials where it is wrong.
Units: seconds for times; rates as fractions.
"""

from __future__ import annotations

import math
import platform
import time
from collections import Counter
from typing import Any

import numpy as np
from scipy.stats import binomtest

COVERAGE = (0.90, 0.98)
WARN = 0.95
DETECTABLE = 5.0  # χ² excess against the true σ [its sd] below which no fit can be asked to see it


def _ci(k: int, n: int) -> tuple[float, float]:
    if n == 0:
        return 0.0, 1.0
    c = binomtest(k, n).proportion_ci(confidence_level=0.95, method="exact")
    return float(c.low), float(c.high)


def _rate(k: int, n: int) -> str:
    lo, hi = _ci(k, n)
    return f"{k}/{n} = {100 * k / max(n, 1):.0f} % [{100 * lo:.0f}–{100 * hi:.0f}]"


def _degenerate_ok(r: dict, key: list[str]) -> tuple[bool, str]:
    if r["status"] == "error":
        return True, "error: " + r["error"][:100]
    if r["status"] != "ok":
        return False, r["status"] + ": " + r.get("error", "")[:100]
    if r.get("model_warnings"):
        return True, "warned: " + r["model_warnings"][0][:100]
    undetermined = [n for n in key if n in r["determined"] and not r["determined"][n]]
    if undetermined:
        return True, "not determined: " + ", ".join(undetermined)
    if r.get("within3") and all(r["within3"].get(n, False) for n in key if n in r["within3"]):
        return True, "honest: truth within 3 stderr"
    shown = ", ".join(f"{n} = {r['params'][n]:.4g} ± {r['stderr'][n]:.2g}" for n in key if n in r["params"])
    return False, "confident nonsense: " + shown


def summarise(
    cases: list,
    chosen: list[int],
    results: list[dict],
    trials: int,
    seconds: float,
    sigma_given: bool = False,
) -> tuple[dict, str]:
    """(summary dict, Markdown text) of a run."""
    by_case: dict[int, list[dict]] = {i: [] for i in chosen}
    for r in results:
        by_case.setdefault(r["case"], []).append(r)
    rows, failures, summary = [], [], {}
    for i in chosen:
        case = cases[i]
        rs = by_case[i]
        clean = [r for r in rs if r["seed"] < 0]
        noisy = [r for r in rs if r["seed"] >= 0]
        n = len(noisy)
        status = Counter(r["status"] for r in noisy)
        secs = [r.get("seconds", 0.0) for r in noisy]
        s: dict[str, Any] = {
            "name": case.name,
            "sort": case.sort,
            "fit": case.fit,
            "loss": case.loss,
            "trials": n,
            "status": dict(status),
            "seconds_median": float(np.median(secs)) if secs else None,
            "seconds_max": float(max(secs)) if secs else None,
            "interrupted": sum(bool(r.get("interrupted")) for r in noisy),
        }
        warned = sum(bool(r.get("model_warnings")) for r in noisy if r["status"] == "ok")
        s["not_converged"] = sum(r.get("converged") is False for r in noisy)
        verdict = "PASS"
        if status.get("crash") or status.get("hang"):
            verdict = "FAIL"
        if clean and clean[0]["status"] == "ok":
            s["noise_free_rms_over_sigma"] = clean[0]["rms_over_sigma"]
            s["noise_free_params"] = clean[0]["params"]
            s["noise_free_max_rel_error"] = max(clean[0]["rel_error"].values(), default=math.nan)
        if case.sort == "right":
            cover = {}
            names = list(dict.fromkeys(n for r in noisy for n in r.get("inside", {})))
            for name in names:
                k = sum(bool(r.get("inside", {}).get(name)) for r in noisy)
                lo, hi = _ci(k, n)
                cover[name] = {"inside": k, "n": n, "rate": k / max(n, 1), "ci": [lo, hi]}
                if hi < COVERAGE[0] or lo > COVERAGE[1]:
                    verdict = "FAIL"
            s["coverage"] = cover
            s["false_alarms"] = warned
            measure = (
                ", ".join(f"{nm} {_rate(c['inside'], c['n'])}" for nm, c in cover.items())
                or "no fit returned"
            )
            if not cover:
                verdict = "FAIL"
            measure += f"; warned {warned}/{n}"
            if "noise_free_max_rel_error" in s:
                measure += f"; noise-free rel. error {s['noise_free_max_rel_error']:.1e}"
        elif case.sort == "wrong":
            lo, hi = _ci(warned, n)
            s["warned"] = {"k": warned, "n": n, "rate": warned / max(n, 1), "ci": [lo, hi]}
            zs = [r["chi2_excess_z"] for r in noisy if r["status"] == "ok"]
            det = float(np.median(zs)) if zs else math.nan
            offs = [
                max(r["off_in_stderr"].values()) for r in noisy if r["status"] == "ok" and r["off_in_stderr"]
            ]
            s["chi2_excess_z_median"] = det
            s["worst_param_off_in_stderr_median"] = float(np.median(offs)) if offs else None
            measure = (
                f"warned {_rate(warned, n)}; χ² excess vs true σ {det:.3g} sd; "
                f"worst parameter {s['worst_param_off_in_stderr_median'] or math.nan:.3g} stderr off (median)"
            )
            if hi < WARN:
                verdict = "FAIL" if not det < DETECTABLE else "not detectable"
        elif case.sort == "degenerate":
            oks = [_degenerate_ok(r, case.key) for r in noisy]
            s["outcomes"] = [w for _, w in oks]
            bad = [w for ok, w in oks if not ok]
            if bad or not oks:
                verdict = "FAIL"
            measure = (
                f"{sum(ok for ok, _ in oks)}/{len(oks)} clear; "
                + "; ".join(sorted({w for _, w in oks}))[:300]
            )
        else:  # units
            shifts = [max(r["units_shift_in_stderr"].values()) for r in noisy if r["status"] == "ok"]
            ratios = [
                max(abs(v - 1.0) for v in r["units_stderr_ratio"].values())
                for r in noisy
                if r["status"] == "ok"
            ]
            s["max_shift_in_stderr"] = max(shifts) if shifts else None
            s["max_stderr_ratio_change"] = max(ratios) if ratios else None
            if not shifts or max(shifts) > 0.1 or max(ratios) > 0.01 or len(shifts) < n:
                verdict = "FAIL"
            measure = (
                f"m vs mm: values differ by ≤ {max(shifts):.3g} stderr, stderr by {100 * max(ratios):.2g} %"
                if shifts
                else "no fit returned"
            )
        if n == 0:
            verdict, measure = "NOT RUN", "no noisy trial finished"
        s["verdict"] = verdict
        summary[str(i + 1)] = s
        rows.append(
            f"| {i + 1} | {case.name} | {case.sort} | {measure} | {s['seconds_median'] or 0:.1f} / "
            f"{s['seconds_max'] or 0:.1f} | {verdict} |"
        )
        for r in rs:
            if r["status"] in ("crash", "hang"):
                failures.append(
                    f"### case {i + 1} ({case.name}), seed {r['seed']}: {r['status']}\n\n"
                    f"```\n{r.get('traceback', r.get('error', ''))[-3000:]}\n```\n"
                )
    load = _load()
    head = [
        f"# pl.fit validation ({time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())})",
        "",
        f"`bench/fit_validate.py`: {trials} noisy trials per case, "
        + ("the true sigma given (--sigma-given)" if sigma_given else "sigma left out")
        + ", data from "
        f"`testdata/generate/independent_pendulum.py`; {seconds:.0f} s wall, load average {load}, "
        f"{platform.python_version()}. Rates as k/n = % [95 % Clopper–Pearson interval].",
        "",
        "| # | case | sort | measured | s per fit (median / max) | verdict |",
        "|---|---|---|---|---|---|",
    ]
    return summary, "\n".join(head + rows) + "\n\n" + (
        "## Crashes and hangs\n\n" + "\n".join(failures) if failures else ""
    )


def _load() -> str:
    try:
        with open("/proc/loadavg", encoding="ascii") as f:
            return " ".join(f.read().split()[:3])
    except OSError:  # pragma: no cover
        return "?"
