"""The portable build against a build for this CPU only, in one run (docs/performance.md, *Portable
builds*): the criterion benches of pendulab-core compiled twice — the reference (by default this
checkout with ``RUSTFLAGS="-C target-cpu=native"``; ``--reference DIR`` takes another checkout as it
builds itself, e.g. a git worktree of the commit before a change) and this checkout with its own
flags (the baseline CPU, hot loops dispatched at run time) — and run alternately, ``--rounds`` times
each, so that the machine's load hits both alike. Reports the best median per benchmark [ns] and the
ratio portable / reference (> 1: the portable build is slower).

Usage: python3 bench/portable.py [--reference DIR] [--rounds 2] [--filter REGEX] [--markdown FILE]
(``make bench-portable``; about 10 min on the 2-core reference machine).
"""

from __future__ import annotations

import argparse
import json
import os
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
    ap.add_argument("--rounds", type=int, default=2)
    ap.add_argument("--filter", help="criterion filter (regular expression over benchmark ids)")
    ap.add_argument("--markdown", type=Path, help="also write the table to this file")
    args = ap.parse_args()
    t0 = time.perf_counter()
    ref_dir = (args.reference or REPO).resolve()
    ref_flags = None if args.reference else "-C target-cpu=native"
    ref = build(ref_dir, REPO / "target" / "bench-reference", ref_flags)
    port = build(REPO, REPO / "target", None)
    print(f"built ({time.perf_counter() - t0:.0f} s): {len(ref)} + {len(port)} bench executables", flush=True)
    with tempfile.TemporaryDirectory(prefix="criterion-portable-") as tmp:
        home = Path(tmp)
        for r in range(args.rounds):
            run(ref, home, f"reference{r}", args.filter, ref_dir / "crates" / "pendulab-core")
            run(port, home, f"portable{r}", args.filter, REPO / "crates" / "pendulab-core")
            print(f"round {r + 1}/{args.rounds} done ({time.perf_counter() - t0:.0f} s)", flush=True)
        best: dict[str, dict[str, float]] = {"reference": {}, "portable": {}}
        for kind in best:
            for r in range(args.rounds):
                for k, v in medians(home, f"{kind}{r}").items():
                    best[kind][k] = min(v, best[kind].get(k, float("inf")))
    what = f"`{ref_dir}`" if args.reference else "this checkout with `-C target-cpu=native`"
    lines = [
        f"Reference: {what}; portable: this checkout's default build. Best median of {args.rounds} "
        f"alternating rounds, load average {os.getloadavg()[0]:.1f} at the end.",
        "",
        "| benchmark | reference | portable | portable / reference |",
        "|---|---|---|---|",
    ]
    for k in sorted(set(best["reference"]) | set(best["portable"])):
        a, b = best["reference"].get(k), best["portable"].get(k)
        ratio = f"{b / a:.3f}" if a is not None and b is not None else "—"
        lines.append(f"| `{k}` | {fmt(a)} | {fmt(b)} | {ratio} |")
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
