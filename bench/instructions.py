"""Instructions executed by the hot paths at two commits, counted by valgrind (docs/performance.md,
*Instruction counts*): a measure that does not depend on the machine's load, for checks such as
issue 25's "no benchmark slower by more than 2 %" that wall-clock benchmarks cannot decide on a
shared machine (criterion swings by 10-20 % from run to run here).

Each commit is exported (``git archive``) into its own folder below ``--work`` and built there with
its own ``CARGO_TARGET_DIR`` (release profile, as the benches): the probe ``bench/instructions/
probe.rs`` as an example of pendulab-core (with the ``api_*.rs`` that fits the tree's ensemble
signature) and, for the Python paths, the extension module copied into the tree's package. Every
path is run under ``valgrind --tool=cachegrind --cache-sim=yes`` at two counts, LO and HI, and the
difference of the two runs' totals divided by HI - LO is the cost of one unit of the path, start-up
and set-up cancelled: instructions (I refs), first-level data-cache misses (D1 mr + mw, simulated)
and last-level misses (LL mr + mw, simulated, instruction and data).

Paths (rosette: l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s): RATTLE ``Stepper::step`` and
``step_n`` (dt = 1 ms), DOP853 ``Stepper::step`` (rtol 1e-10, atol 1e-12), an ensemble step of 192
starts (whole blocks of 64 lanes before 2026-11-27 and of 48 since; RATTLE, one thread),
``ExactSolution::new`` / ``state`` / ``states_at`` (one thread), and
with ``--python`` ``pl.simulate`` for 10 and 1000 steps (``py_simulate_10``, ``py_simulate_1000``):
rough only, since ``simulate`` sizes its chunks by wall time and reads the memory left on each
call. ``--baseline`` repeats the Rust paths at the
baseline instruction set (``isa::set_baseline_only``). Under valgrind the CPU offers at most AVX2, so
the AVX-512 loops of a host that has them are not what is counted.

Usage: python3 bench/instructions.py [--base REV] [--new REV] [--paths a,b]
[--baseline] [--python] [--limit 1.02] [--markdown FILE] (``make bench-instructions``; the first run
builds both commits, about 15 min on the 2-core reference machine, then about 3 min per commit).
Exit status 1 when a path's instruction ratio new / base exceeds ``--limit``.
"""

from __future__ import annotations

import argparse
import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
PROBE = REPO / "bench" / "instructions"
# The last commit before issue 25's work (its first commit, 8a44d91, moved the limits table).
DEFAULT_BASE = "d1cb28b"

# path -> (unit, LO, HI)
RUST_PATHS: dict[str, tuple[str, int, int]] = {
    "rattle_step": ("step", 20_000, 60_000),
    "rattle_step_n": ("step", 20_000, 60_000),
    "dop853_step": ("accepted step", 2_000, 6_000),
    "ensemble_block": ("ensemble step (192 trajectories)", 1_000, 3_000),
    "exact_setup": ("call", 200, 600),
    "exact_state": ("call", 2_000, 6_000),
    "exact_states_at": ("time", 2_000, 6_000),
}
PY_PATHS: dict[str, tuple[str, int, int]] = {
    "py_simulate_10": ("call", 5, 15),
    "py_simulate_1000": ("call", 3, 9),
}
PY_PROBE = """
import sys
import pendulab as pl
count, steps = int(sys.argv[1]), int(sys.argv[2])
p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
s = p.state_from_angles(theta_deg=60.0, phi=0.0, theta_dot=0.0, phi_dot=2.0)
pl.simulate(p, s, steps * 1e-3, method="rattle", dt=1e-3)
for _ in range(count):
    pl.simulate(p, s, steps * 1e-3, method="rattle", dt=1e-3)
"""


@dataclass(frozen=True)
class Counts:
    """Cachegrind's totals of one run: instructions, D1 misses, LL misses (simulated)."""

    instructions: int
    d1_misses: int
    ll_misses: int

    def __sub__(self, other: Counts) -> Counts:
        return Counts(
            self.instructions - other.instructions,
            self.d1_misses - other.d1_misses,
            self.ll_misses - other.ll_misses,
        )


def sh(cmd: list[str], cwd: Path, env: dict[str, str] | None = None) -> str:
    """Runs `cmd`; exits with its error output when it fails."""
    out = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, check=False)
    if out.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed in {cwd}:\n{out.stdout[-2000:]}{out.stderr[-4000:]}")
    return out.stdout + out.stderr


@dataclass(frozen=True)
class Tree:
    """One commit exported and built: its probe binary and its package folder for Python."""

    rev: str
    probe: Path
    python: Path


def prepare(rev: str, work: Path, python: bool) -> Tree:
    """Exports `rev` into work/src-REV (once) and builds the probe (and the extension) there."""
    sha = sh(["git", "rev-parse", "--short=10", f"{rev}^{{commit}}"], REPO).strip()
    src, target = work / f"src-{sha}", work / f"target-{sha}"
    if not (src / "Cargo.toml").exists():
        src.mkdir(parents=True, exist_ok=True)
        archive = subprocess.run(["git", "archive", sha], cwd=REPO, capture_output=True, check=True)
        subprocess.run(["tar", "-x", "-C", str(src)], input=archive.stdout, check=True)
    example = src / "crates" / "pendulab-core" / "examples" / "instr_probe"
    example.mkdir(parents=True, exist_ok=True)
    shutil.copy(PROBE / "probe.rs", example / "main.rs")
    core = (src / "crates" / "pendulab-core" / "src").rglob("*.rs")
    settings = any("pub struct RattleSettings" in f.read_text() for f in core)
    api = "api_settings.rs" if settings else "api_run_with.rs"
    shutil.copy(PROBE / api, example / "api.rs")
    env = dict(os.environ, CARGO_TARGET_DIR=str(target))
    env.pop("RUSTFLAGS", None)
    print(f"building {sha} ({api}) in {src}", file=sys.stderr, flush=True)
    sh(["cargo", "build", "--release", "-p", "pendulab-core", "--example", "instr_probe"], src, env)
    if python:
        sh(["cargo", "build", "--release", "-p", "pendulab-python"], src, env)
        shutil.copy(target / "release" / "lib_core.so", src / "python" / "pendulab" / "_core.abi3.so")
    return Tree(sha, target / "release" / "examples" / "instr_probe", src / "python")


CG_LINE = re.compile(r"==\d+==\s+(I\s+refs|D1\s+misses|LL\s+misses):\s+([\d,]+)")


def cachegrind(cmd: list[str], env: dict[str, str]) -> Counts:
    """Totals of one run of `cmd` under cachegrind (no output file)."""
    vg = ["valgrind", "--tool=cachegrind", "--cache-sim=yes", "--cachegrind-out-file=/dev/null"]
    out = subprocess.run(vg + cmd, env=env, capture_output=True, text=True, check=False)
    if out.returncode != 0:
        sys.exit(f"{' '.join(cmd)} failed under valgrind:\n{out.stderr[-4000:]}")
    found = {re.sub(r"\s+", " ", name): int(n.replace(",", "")) for name, n in CG_LINE.findall(out.stderr)}
    return Counts(found["I refs"], found["D1 misses"], found["LL misses"])


def per_unit(tree: Tree, path: str, baseline: bool) -> tuple[Counts, int]:
    """The counts of one unit of `path` in `tree` (HI run minus LO run) and HI - LO."""
    env = dict(os.environ, PYTHONHASHSEED="0", RAYON_NUM_THREADS="1")
    if path in PY_PATHS:
        _, lo, hi = PY_PATHS[path]
        env["PYTHONPATH"] = str(tree.python)
        steps = path.rsplit("_", 1)[1]

        def cmd(c: int) -> list[str]:
            return [sys.executable, "-c", PY_PROBE, str(c), steps]
    else:
        _, lo, hi = RUST_PATHS[path]

        def cmd(c: int) -> list[str]:
            return [str(tree.probe), path, str(c)] + (["baseline"] if baseline else [])

    return cachegrind(cmd(hi), env) - cachegrind(cmd(lo), env), hi - lo


def miss_ratio(base: int, new: int, units: int) -> str:
    """The ratio of two miss counts, or both per unit where they are below one miss per unit."""
    if base > units:
        return f"{new / base:.3f}"
    return f"{base / units:.2g} → {new / units:.2g} per unit"


def compare(base: Tree, new: Tree, path: str, baseline: bool, limit: float) -> tuple[str, float]:
    """One table row for `path` (per unit of base and new; the ratios) and the instruction ratio."""
    (b, units), (n, _) = per_unit(base, path, baseline), per_unit(new, path, baseline)
    unit = (RUST_PATHS | PY_PATHS)[path][0]
    ratio = n.instructions / b.instructions
    name = path + (" (baseline level)" if baseline else "")
    over = " **over**" if ratio > limit else ""
    d1, ll = miss_ratio(b.d1_misses, n.d1_misses, units), miss_ratio(b.ll_misses, n.ll_misses, units)
    row = (
        f"| `{name}` ({unit}) | {b.instructions / units:,.1f} | {n.instructions / units:,.1f} | "
        f"{ratio:.4f}{over} | {d1} | {ll} |"
    )
    return row, ratio


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--base", default=DEFAULT_BASE, help=f"the commit before (default {DEFAULT_BASE})")
    ap.add_argument("--new", default="HEAD", help="the commit after (default HEAD)")
    ap.add_argument("--work", type=Path, default=REPO / "target" / "instructions")
    ap.add_argument("--paths", default="", help="comma-separated subset of the paths")
    ap.add_argument(
        "--python",
        action="store_true",
        help="also pl.simulate (rough: its chunks are sized by wall time, so its counts vary)",
    )
    ap.add_argument("--baseline", action="store_true", help="also the baseline instruction set")
    ap.add_argument("--limit", type=float, default=1.02, help="largest allowed ratio new/base")
    ap.add_argument("--markdown", type=Path, help="also write the table to this file")
    args = ap.parse_args()
    if shutil.which("valgrind") is None:
        sys.exit("valgrind is not installed (Debian: apt-get install valgrind)")
    paths = list(RUST_PATHS) + (list(PY_PATHS) if args.python else [])
    if args.paths:
        paths = [p for p in args.paths.split(",") if p]
        unknown = set(paths) - set(RUST_PATHS) - set(PY_PATHS)
        if unknown:
            sys.exit(f"unknown paths {sorted(unknown)}; known: {list(RUST_PATHS) + list(PY_PATHS)}")
    python = any(p in PY_PATHS for p in paths)
    base, new = (prepare(r, args.work, python) for r in (args.base, args.new))
    runs = [(p, False) for p in paths] + [(p, True) for p in paths if args.baseline and p in RUST_PATHS]
    rows = [
        f"| path (unit) | instructions {base.rev} | instructions {new.rev} | ratio | "
        "D1 misses ratio | LL misses ratio |",
        "|---|---|---|---|---|---|",
    ]
    worst = 0.0
    for path, baseline in runs:
        row, ratio = compare(base, new, path, baseline, args.limit)
        worst = max(worst, ratio)
        rows.append(row)
        print(row, flush=True)
    table = "\n".join(rows)
    print(f"\n{table}\n\nlargest ratio {worst:.4f} (limit {args.limit})")
    if args.markdown:
        args.markdown.write_text(table + "\n")
    sys.exit(1 if worst > args.limit else 0)


if __name__ == "__main__":
    main()
