"""The portable build against a build for this CPU only, in one run (docs/performance.md, *Portable
builds*): the criterion benches of pendulab-core compiled for each build — the reference (by default
this checkout with ``RUSTFLAGS="-C target-cpu=native"``; ``--reference DIR`` takes another checkout as
it builds itself), optionally ``--before DIR`` (another checkout with its own default flags, e.g. a
git worktree of the commit before a change, to show before/after in the same run), and this checkout
with its own flags (the baseline CPU, hot loops dispatched at run time) — and run alternately,
``--rounds`` times each (the order rotating every round), so that the machine's load hits all alike.
Reports per benchmark the median over the rounds of criterion's median [ns], the spread of the rounds
(max/min − 1) and the ratios to the reference (> 1: slower than the reference), with the range of
the per-round ratios.

Usage: python3 bench/portable.py [--reference DIR] [--before DIR] [--rounds 3] [--filter REGEX]
[--markdown FILE] (``make bench-portable``; about 10 min per round with three builds on the 2-core
reference machine).
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
CRITERION_ARGS = ["--bench", "--warm-up-time", "1", "--measurement-time", "3", "--noplot"]


def build(checkout: Path, target_dir: Path, rustflags: str | None) -> list[Path]:
    """Compiles the benches of pendulab-core in `checkout`; returns their executables."""
    env = dict(os.environ, CARGO_TARGET_DIR=str(target_dir))
    if rustflags is not None:
        env["RUSTFLAGS"] = rustflags
    else:
        env.pop("RUSTFLAGS", None)
    cmd = ["cargo", "bench", "-p", "pendulab-core", "--no-run", "--message-format=json"]
    out = subprocess.run(cmd, cwd=checkout, env=env, capture_output=True, text=True, check=False)
    if out.returncode != 0:
        sys.exit(f"build failed in {checkout}:\n{out.stderr[-4000:]}")
    exes = []
    for line in out.stdout.splitlines():
        msg = json.loads(line)
        if (
            msg.get("reason") == "compiler-artifact"
            and "bench" in msg["target"]["kind"]
            and msg.get("executable")
        ):
            exes.append(Path(msg["executable"]))
    return sorted(exes, key=lambda p: p.name)


def run(exes: list[Path], home: Path, baseline: str, filt: str | None, cwd: Path) -> None:
    env = dict(os.environ, CRITERION_HOME=str(home))
    for exe in exes:
        args = [str(exe), *CRITERION_ARGS, "--save-baseline", baseline]
        if filt:
            args.append(filt)
        subprocess.run(args, cwd=cwd, env=env, check=True, stdout=subprocess.DEVNULL)


def medians(home: Path, baseline: str) -> dict[str, float]:
    """Median time per iteration [ns] by benchmark id, for one saved baseline."""
    out: dict[str, float] = {}
    for est in home.rglob(f"{baseline}/estimates.json"):
        info = json.loads((est.parent / "benchmark.json").read_text())
        out[info["full_id"]] = json.loads(est.read_text())["median"]["point_estimate"]
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument(
        "--reference", type=Path, help="checkout built as the reference (default: this one, native)"
    )
    ap.add_argument("--before", type=Path, help="another checkout built with its own flags (before/after)")
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--filter", help="criterion filter (regular expression over benchmark ids)")
    ap.add_argument("--markdown", type=Path, help="also write the table to this file")
    args = ap.parse_args()
    t0 = time.perf_counter()
    load0 = os.getloadavg()[0]
    ref_dir = (args.reference or REPO).resolve()
    ref_flags = None if args.reference else "-C target-cpu=native"
    builds: dict[str, tuple[Path, list[Path]]] = {
        "reference": (ref_dir, build(ref_dir, REPO / "target" / "bench-reference", ref_flags))
    }
    if args.before:
        before = args.before.resolve()
        builds["before"] = (before, build(before, REPO / "target" / "bench-before", None))
    builds["portable"] = (REPO, build(REPO, REPO / "target", None))
    kinds = list(builds)
    print(f"built ({time.perf_counter() - t0:.0f} s): {', '.join(kinds)}", flush=True)
    loads = [load0]
    per_round: dict[str, list[dict[str, float]]] = {k: [] for k in kinds}
    with tempfile.TemporaryDirectory(prefix="criterion-portable-") as tmp:
        home = Path(tmp)
        for r in range(args.rounds):
            order = kinds[r % len(kinds) :] + kinds[: r % len(kinds)]
            for kind in order:
                checkout, exes = builds[kind]
                run(exes, home, f"{kind}{r}", args.filter, checkout / "crates" / "pendulab-core")
                per_round[kind].append(medians(home, f"{kind}{r}"))
            loads.append(os.getloadavg()[0])
            print(f"round {r + 1}/{args.rounds} done ({time.perf_counter() - t0:.0f} s)", flush=True)
    what = f"`{ref_dir}`" if args.reference else "this checkout with `-C target-cpu=native`"
    others = [k for k in kinds if k != "reference"]
    head = ["benchmark", *kinds]
    for k in others:
        head.append(f"{k} / reference (per-round range)")
    lines = [
        f"Reference: {what}; "
        + (f"before: `{builds['before'][0]}` (its default build); " if "before" in builds else "")
        + f"portable: this checkout's default build. Median over {args.rounds} alternating rounds "
        "(criterion's median per round; ± the spread max/min − 1 of the rounds); load average "
        f"{min(loads):.1f}–{max(loads):.1f} (1-min average at the start and after each round).",
        "",
        "| " + " | ".join(head) + " |",
        "|" + "---|" * len(head),
    ]
    ids = sorted(set().union(*(m for rounds in per_round.values() for m in rounds)))
    for k in ids:
        cells = [f"`{k}`"]
        med: dict[str, float | None] = {}
        for kind in kinds:
            xs = [m[k] for m in per_round[kind] if k in m]
            med[kind] = statistics.median(xs) if xs else None
            spread = f" ±{(max(xs) / min(xs) - 1) * 100:.0f} %" if len(xs) > 1 else ""
            cells.append(fmt(med[kind]) + (spread if xs else ""))
        for kind in others:
            a, b = med["reference"], med[kind]
            if a is None or b is None:
                cells.append("—")
                continue
            rr = [
                m2[k] / m1[k]
                for m1, m2 in zip(per_round["reference"], per_round[kind], strict=True)
                if k in m1 and k in m2
            ]
            cells.append(f"{b / a:.3f} ({min(rr):.2f}–{max(rr):.2f})")
        lines.append("| " + " | ".join(cells) + " |")
    table = "\n".join(lines)
    print(table)
    if args.markdown:
        args.markdown.write_text(table + "\n")
    print(f"({time.perf_counter() - t0:.0f} s)")


def fmt(ns: float | None) -> str:
    if ns is None:
        return "—"
    for unit, scale in (("s", 1e9), ("ms", 1e6), ("µs", 1e3)):
        if ns >= scale:
            return f"{ns / scale:.3g} {unit}"
    return f"{ns:.3g} ns"


if __name__ == "__main__":
    main()
