"""The peers benchmark (bench/peers/run.py, full scans) for two wheels of this checkout in one run:
the portable build (baseline x86-64, hot loops dispatched at run time by crates/pendulab-core/src/
isa.rs) and a build for this CPU only (``RUSTFLAGS="-C target-cpu=native"``), run alternately
(``--rounds`` times each, the order swapped every round) so that the load of the machine's other
users hits both alike. Reports, per figure, the median over the rounds for each build, the spread of
the rounds (max/min − 1) and the ratio portable / native of the medians with the range of the
per-round ratios (> 1: the portable wheel is slower). docs/performance.md, *Portable builds*.

Figures: step rates (RATTLE and every fixed-step method through ``Stepper.step``, RATTLE through
``pl.simulate``, exact states at 10⁵ times), the ensemble kernel on 1 and 2 threads, and for every
Pendulab method, case and setting of the scans the wall time of ``pl.simulate`` (DOP853: every
tolerance of the scan), summarised per method as the median ratio over its runs. The C RK4 loop and
ensemble run in the same processes as a yardstick of the load (their ratio should be 1).

Usage: python bench/peers/native_vs_portable.py [--rounds 2] [--only pendulab,C] [--markdown FILE]
(``make bench-peers-portable``; builds both wheels, then about 10 min per run on the 2-core machine).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

HERE = Path(__file__).resolve().parent
REPO = HERE.parents[1]
BUILD = HERE / "build" / "native_vs_portable"
KINDS = ("native", "portable")


def build_wheel(kind: str) -> Path:
    """Builds the wheel of this checkout for `kind` and installs it into its own directory."""
    env = dict(os.environ)
    env.pop("RUSTFLAGS", None)
    if kind == "native":
        env |= {
            "RUSTFLAGS": "-C target-cpu=native",
            "CARGO_TARGET_DIR": str(REPO / "target" / "peers-rustflags"),
        }
    out = BUILD / f"wheel-{kind}"
    site = BUILD / f"site-{kind}"
    for d in (out, site):
        subprocess.run(["rm", "-rf", str(d)], check=True)
    maturin = Path(sys.executable).parent / "maturin"
    cmd = [str(maturin), "build", "--release", "--quiet", "-m", "python/Cargo.toml"]
    subprocess.run([*cmd, "--interpreter", sys.executable, "-o", str(out)], cwd=REPO, env=env, check=True)
    wheel = next(out.glob("pendulab-*.whl"))
    pip = [sys.executable, "-m", "pip", "install", "--quiet", "--no-deps", "--target", str(site)]
    subprocess.run([*pip, str(wheel)], check=True)
    return site


def figures(res: dict[str, Any]) -> dict[str, float]:
    """Time-like figures [s] (smaller is better) by name, from one results JSON of run.py."""
    out: dict[str, float] = {}
    for name, r in res["rates"].items():
        if "steps_per_s" in r:
            out[f"rate: {name} [s per 1e6 steps]"] = 1e6 / r["steps_per_s"]
    for fam in ("pendulab", "C rk4"):
        for threads, e in res["ensembles"].get(fam, {}).items():
            rate = e.get("rate")
            if rate:
                out[f"ensemble: {fam} {threads} thread(s) [s per 1e9 trajectory-steps]"] = 1e9 / rate
    for r in res["runs"]:
        if r["method"].startswith("pendulab") and not r["failed"] and r["wall"] == r["wall"]:
            setting = "" if r["setting_kind"] == "none" else f" {r['setting_kind']}={r['setting']:.3g}"
            out[f"run: {r['method']} | {r['case']}{setting}"] = r["wall"]
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--only", default="pendulab,C", help="families for run.py --only")
    ap.add_argument("--markdown", type=Path, help="also write the tables to this file")
    ap.add_argument("--skip-build", action="store_true", help="reuse the wheels installed by a previous run")
    ap.add_argument(
        "--more", action="store_true", help="keep the rounds of the previous run and add --rounds more"
    )
    args = ap.parse_args()
    t0 = time.perf_counter()
    sites = {k: BUILD / f"site-{k}" for k in KINDS} if args.skip_build else {k: build_wheel(k) for k in KINDS}
    print(f"built ({time.perf_counter() - t0:.0f} s)", flush=True)
    per_round: dict[str, list[dict[str, float]]] = {k: [] for k in KINDS}
    loads: list[float] = [os.getloadavg()[0]]
    first = 0
    while args.more and all((BUILD / f"{k}{first}.json").exists() for k in KINDS):
        for kind in KINDS:
            res = json.loads((BUILD / f"{kind}{first}.json").read_text())
            per_round[kind].append(figures(res))
            loads += [res["meta"]["load_start"], res["meta"]["load_end"]]
        first += 1
    for r in range(first, first + args.rounds):
        for kind in KINDS if r % 2 == 0 else KINDS[::-1]:
            out = BUILD / f"{kind}{r}.json"
            env = dict(os.environ, PYTHONPATH=str(sites[kind]))
            cmd = [
                sys.executable,
                str(HERE / "run.py"),
                "--only",
                args.only,
                "--no-report",
                "--out",
                str(out),
            ]
            subprocess.run(cmd, env=env, check=True, stdout=subprocess.DEVNULL)
            res = json.loads(out.read_text())
            per_round[kind].append(figures(res))
            loads += [res["meta"]["load_start"], res["meta"]["load_end"]]
            print(f"round {r + 1}: {kind} done ({time.perf_counter() - t0:.0f} s)", flush=True)
    table = report(per_round, first + args.rounds, loads)
    print(table)
    if args.markdown:
        args.markdown.write_text(table + "\n")
    print(f"({time.perf_counter() - t0:.0f} s)")


def report(per_round: dict[str, list[dict[str, float]]], rounds: int, loads: list[float]) -> str:
    names = sorted(set(per_round["native"][0]) & set(per_round["portable"][0]))
    rows, by_method = [], {}
    for name in names:
        med, spread = {}, {}
        for kind in KINDS:
            xs = [m[name] for m in per_round[kind] if name in m]
            med[kind] = statistics.median(xs)
            spread[kind] = max(xs) / min(xs) - 1
        ratios = [
            p[name] / n[name] for n, p in zip(per_round["native"], per_round["portable"], strict=True)
            if name in n and name in p
        ]  # fmt: skip
        ratio = med["portable"] / med["native"]
        if name.startswith("run: "):
            by_method.setdefault(name[5:].split(" | ")[0], []).append(ratio)
            continue
        rows.append(
            f"| {name} | {fmt(med['native'])} ±{spread['native'] * 100:.0f} % | "
            f"{fmt(med['portable'])} ±{spread['portable'] * 100:.0f} % | {ratio:.3f} "
            f"({min(ratios):.2f}–{max(ratios):.2f}) |"
        )
    lines = [
        f"Median over {rounds} alternating rounds of the full scans (`run.py --only pendulab,C`); ± the "
        f"spread max/min − 1 of the rounds; load average {min(loads):.1f}–{max(loads):.1f} (1-min "
        "average at the start and end of each run).",
        "",
        "| figure | native | portable | portable / native (per-round range) |",
        "|---|---|---|---|",
        *rows,
        "",
        "| method (`pl.simulate`, every case and setting of the scans) | runs | median portable / native "
        "| range |",
        "|---|---|---|---|",
    ]
    for method, rs in sorted(by_method.items()):
        lines.append(f"| {method} | {len(rs)} | {statistics.median(rs):.3f} | {min(rs):.2f}–{max(rs):.2f} |")
    return "\n".join(lines)


def fmt(s: float) -> str:
    for unit, scale in (("s", 1.0), ("ms", 1e-3), ("µs", 1e-6)):
        if s >= scale:
            return f"{s / scale:.3g} {unit}"
    return f"{s * 1e9:.3g} ns"


if __name__ == "__main__":
    main()
