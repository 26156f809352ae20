"""Pure-Python parts of the peer benchmark (``bench/peers/run.py``): the error against the reference,
the medians of repeated timings, the cheapest setting that reaches a tolerance, work-precision
envelopes, the issue's targets as PASS/MISS ratios, Markdown tables and their insertion between
markers. Only numpy is needed, so the project's test suite checks this module without the peers.
"""

from __future__ import annotations

import math
import statistics
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, field
from typing import Any

import numpy as np

BEGIN = "<!-- peers:begin (written by bench/peers/run.py; do not edit by hand) -->"
END = "<!-- peers:end -->"
LEVELS = tuple(10.0**-k for k in range(4, 13))
"""Error levels 1e-4 … 1e-12 of the work-precision target."""


@dataclass
class Run:
    """One integration to t_end with one setting (a step size or a tolerance).

    ``error``: final position error |x − x_ref|/l; ``state_error``: max(|Δx|/l, |Δv|/(l ω₀ + |v_ref|));
    ``energy_drift``: |E(t_end) − E(0)|/(m |g| l); ``constraint_drift``: | |x(t_end)| − l | [m];
    ``wall``: median wall time of ``repeats`` runs [s]; ``failed``: why the run stopped, if it did."""

    method: str
    case: str
    setting: float
    setting_kind: str
    wall: float
    steps: int
    error: float = math.nan
    state_error: float = math.nan
    energy_drift: float = math.nan
    constraint_drift: float = math.nan
    repeats: int = 1
    failed: str | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def ok(self) -> bool:
        return self.failed is None and math.isfinite(self.error)

    def as_dict(self) -> dict[str, Any]:
        return asdict(self)


def position_error(x: np.ndarray, x_ref: np.ndarray, length: float) -> float:
    """|x − x_ref| / l (dimensionless); NaN if x is not finite."""
    x = np.asarray(x, dtype=float)
    if not np.all(np.isfinite(x)):
        return math.nan
    return float(np.linalg.norm(x - np.asarray(x_ref, dtype=float)) / length)


def state_error(
    x: np.ndarray, v: np.ndarray, x_ref: np.ndarray, v_ref: np.ndarray, length: float, omega0: float
) -> float:
    """max(|Δx|/l, |Δv|/(l ω₀ + |v_ref|)): the measure of bench/compare.py and the golden data."""
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        return math.nan
    dx = np.linalg.norm(np.asarray(x) - x_ref) / length
    dv = np.linalg.norm(np.asarray(v) - v_ref) / (length * omega0 + np.linalg.norm(v_ref))
    return float(max(dx, dv))


def drifts(x: np.ndarray, v: np.ndarray, x0: np.ndarray, v0: np.ndarray, length: float, g: float) -> tuple:
    """(energy drift |E − E₀|/(|g| l) per unit mass, constraint drift | |x| − l | [m]) at the end."""

    def energy(xx: np.ndarray, vv: np.ndarray) -> float:
        return 0.5 * float(np.dot(vv, vv)) + g * float(xx[2])

    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(v))):
        return math.nan, math.nan
    de = abs(energy(x, v) - energy(x0, v0)) / (abs(g) * length)
    return de, abs(float(np.linalg.norm(x)) - length)


# Intel server cores by (family, model), for virtual machines whose model name is only "Intel(R) Xeon(R)
# Processor" (Intel's "Intel Processors and Processor Cores based on Intel Microarchitectures" list)
INTEL_CORES = {
    (6, 85): "Skylake-SP / Cascade Lake",
    (6, 106): "Ice Lake-SP",
    (6, 143): "Sapphire Rapids",
    (6, 207): "Emerald Rapids",
    (6, 173): "Granite Rapids",
}


def cpu_description(cpuinfo: str = "/proc/cpuinfo") -> str:
    """The CPU a benchmark ran on, for its results: ``/proc/cpuinfo``'s model name with its family and
    model numbers (and the core's name for the Intel server cores of :data:`INTEL_CORES`), else what
    ``platform`` knows. Ratios against a baseline change from one CPU to the next (a second 512-bit FMA
    unit doubles a throughput-bound C ensemble, not a latency-bound kernel: docs/performance.md), so
    every recorded figure names its CPU."""
    import platform

    try:
        with open(cpuinfo) as f:
            head = f.read().split("\n")[:40]
        info = {k.strip(): v.strip() for k, _, v in (line.partition(":") for line in head)}
        family, model = int(info["cpu family"]), int(info["model"])
        core = INTEL_CORES.get((family, model)) if "Intel" in info["model name"] else None
        return f"{info['model name']} (family {family}, model {model}{', ' + core if core else ''})"
    except (OSError, KeyError, ValueError):
        return platform.processor() or platform.machine()


def repeats_for(first: float, budget: float = 1.0, most: int = 5, least: int = 3) -> int:
    """How many runs in all (the first included) to time a call that took ``first`` seconds: ``most``
    for quick calls, down to ``least`` for calls whose repeats would exceed ``budget`` seconds, and 1
    for calls longer than ``budget`` itself."""
    if first >= budget:
        return 1
    return max(least, min(most, int(budget / max(first, 1e-9))))


def median_time(fn: Callable[[], Any], repeats: int | None = None, budget: float = 1.0) -> tuple:
    """Median wall time [s] of repeated calls, the last result and the number of calls. With
    ``repeats`` None the number follows from the first call's time (:func:`repeats_for`)."""
    start = time.perf_counter()
    out = fn()
    times = [time.perf_counter() - start]
    n = repeats if repeats is not None else repeats_for(times[0], budget)
    for _ in range(n - 1):
        start = time.perf_counter()
        out = fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times), out, len(times)


def cheapest(runs: Iterable[Run], tol: float) -> Run | None:
    """The run with the smallest wall time among those whose error is ≤ tol (None if none is)."""
    good = [r for r in runs if r.ok and r.error <= tol]
    return min(good, key=lambda r: r.wall) if good else None


def envelope(runs: Sequence[Run], levels: Sequence[float] = LEVELS) -> dict[float, float | None]:
    """For each error level, the least wall time [s] at which the runs reach it (None: never)."""
    out: dict[float, float | None] = {}
    for lvl in levels:
        best = cheapest(runs, lvl)
        out[lvl] = best.wall if best else None
    return out


def should_refine(
    errors: Sequence[float],
    walls: Sequence[float],
    floor: float,
    cap: float,
    window: int = 3,
    converged: float = 1e-9,
    max_failures: int = 20,
) -> bool:
    """Whether a scan (step sizes decreasing or tolerances tightening) should try a finer setting.

    No once the last run took more than ``cap`` seconds, or its error is below ``floor``; no once the
    error has come below ``converged`` and the last ``window`` settings have not improved on the best
    error before them by a factor 2 (the error stagnates at round-off; a single noisy setting does
    not stop the scan, and a lucky error at a coarse setting — errors above ``converged`` — does not
    either); no after ``max_failures`` failed runs in a row (NaN errors). Coarse settings whose
    errors are O(1) or that fail never stop a scan by themselves before that."""
    if walls and walls[-1] > cap:
        return False
    if errors and math.isfinite(errors[-1]) and errors[-1] <= floor:
        return False
    if len(errors) >= max_failures and not any(math.isfinite(e) for e in errors[-max_failures:]):
        return False
    if len(errors) > window:
        earlier = [e for e in errors[:-window] if math.isfinite(e)]
        if earlier and min(earlier) < converged:
            recent = [e for e in errors[-window:] if math.isfinite(e)]
            if not recent or min(recent) > min(earlier) / 2:
                return False
    return True


def ratio_verdict(value: float | None, target: float, higher_is_better: bool = True) -> str:
    """ "PASS" if value meets target (≥ when higher is better, ≤ otherwise), "MISS" if not, "n/a" if
    the value could not be measured."""
    if value is None or not math.isfinite(value):
        return "n/a"
    ok = value >= target if higher_is_better else value <= target
    return "PASS" if ok else "MISS"


def fmt_time(seconds: float | None) -> str:
    """A wall time with a unit that keeps 3 significant figures (µs, ms, s); "—" if None."""
    if seconds is None or not math.isfinite(seconds):
        return "—"
    if seconds < 1e-3:
        return f"{seconds * 1e6:.3g} µs"
    if seconds < 1.0:
        return f"{seconds * 1e3:.3g} ms"
    return f"{seconds:.3g} s"


def fmt_sci(value: float | None, digits: int = 2) -> str:
    """1.23e+07 → "1.23 × 10⁷" ("—" if None or NaN)."""
    if value is None or not math.isfinite(value):
        return "—"
    if value == 0:
        return "0"
    exp = math.floor(math.log10(abs(value)))
    mant = value / 10**exp
    if round(mant, digits) >= 10:
        mant, exp = mant / 10, exp + 1
    sup = str(exp).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))
    return f"{mant:.{digits}f} × 10{sup}"


def fmt_err(value: float | None) -> str:
    if value is None or not math.isfinite(value):
        return "—"
    return f"{value:.1e}"


def markdown_table(headers: Sequence[str], rows: Iterable[Sequence[Any]]) -> str:
    """A GitHub Markdown table; cells are str()-ed and "|" in them escaped."""

    def cell(c: Any) -> str:
        return str(c).replace("|", "\\|")

    lines = ["| " + " | ".join(cell(h) for h in headers) + " |", "|" + "---|" * len(headers)]
    lines += ["| " + " | ".join(cell(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def replace_between_markers(text: str, body: str, begin: str = BEGIN, end: str = END) -> str:
    """``text`` with what lies between the marker lines replaced by ``body`` (markers kept). If the
    markers are missing, a section "## Against peers" holding them is appended. A begin marker
    without its end (or in the wrong order) is an error rather than a silent overwrite."""
    i, j = text.find(begin), text.find(end)
    if i < 0 and j < 0:
        sep = "" if text.endswith("\n") else "\n"
        return f"{text}{sep}\n## Against peers\n{begin}\n{body.strip()}\n{end}\n"
    if i < 0 or j < 0 or j < i:
        raise ValueError(f"markers out of order or unpaired: {begin!r} … {end!r}")
    return f"{text[: i + len(begin)]}\n{body.strip()}\n{text[j:]}"
