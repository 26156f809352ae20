"""A seeded corpus of mutated scenario files through ``pendulab validate`` and ``pendulab run`` (issue 13).

Each file starts from one of ``examples/scenarios/*.toml`` and gets one to four mutations: a number
replaced by an extreme (1e308, 5e-324, nan, inf, 10**22, 1e400, a string, a table), a line deleted,
duplicated or truncated, a key renamed, deep nesting (arrays, inline tables, dotted keys), invalid
UTF-8, NUL bytes, a file beyond 1 MiB, a hostile [simulation] (dt = 1e-308, t_end = 1e308). Every
file goes through ``pendulab validate`` and ``pendulab run`` in-process (typer's runner), each
under a 60 s alarm. Passing means: exit code 0 or 2; exit 2 prints ``error:`` lines only (``run``
exactly one) of bounded length and no traceback; exit 0 prints no ``nan``/``inf``. Files that
validate but would plan more than :data:`RUN_WORK` steps (valid, just long) are validated only.

    python tools/fuzz_scenarios.py --files 2500 --seed 13      # make fuzz
    python tools/fuzz_scenarios.py --files 150 --keep corpus/  # keep the files

Prints the counts and the failures; exit code 1 if any file failed.
"""

from __future__ import annotations

import argparse
import math
import random
import re
import signal
import sys
import tempfile
import warnings
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
SEEDS = sorted((REPO / "examples" / "scenarios").glob("*.toml"))
RUN_WORK = 200_000
"""Most steps a corpus file may plan to be run (not only validated)."""
LINE_CHARS = 1200
"""Longest error line accepted per problem it lists (values are abbreviated to 80 characters)."""

EXTREMES = [
    "1e308",
    "-1e308",
    "5e-324",
    "-5e-324",
    "0",
    "-0.0",
    "nan",
    "inf",
    "-inf",
    "1e-308",
    "1e16",
    "10000000000000000000000",
    "-1",
    "1e400",
    "-1e400",
    '"1.0"',
    "true",
    "[1, 2]",
    "{ a = 1 }",
    "1e12",
    "1e-12",
    "123456789012345678901234567890",
    "0x7fffffffffffffff",
    "18446744073709551616",
    "1e6",
    "1e9",
]
KEYS = [
    "length",
    "mass",
    "g",
    "model",
    "damping",
    "theta",
    "theta_deg",
    "phi",
    "theta_dot",
    "phi_dot",
    "x",
    "v",
    "project",
    "t_end",
    "t0",
    "dt",
    "method",
    "save_every",
    "save_at",
    "rtol",
    "atol",
    "drag",
    "frame_rate",
    "latitude_deg",
    "stiffness",
    "restitution",
    "pivot_times",
    "pivot_positions",
    "bogus",
]
HOSTILE_SIMULATION = [
    "dt = 1e-308",
    "dt = 5e-324",
    "t_end = 1e308",
    "t_end = 1e12",
    "save_every = 0",
    "save_every = 18446744073709551616",
    "save_at = [0.0, nan]",
    'method = "rk4"',
    'method = "dop853"',
    "rtol = 1e-300",
    "atol = 1e300",
    "t0 = -1e308",
    "save_at = []",
]
NUMBER = re.compile(r"(?<![\w.])-?\d+(\.\d+)?([eE][-+]?\d+)?(?![\w.])")


def mutate(text: str, rng: random.Random) -> bytes:
    """One to four random mutations of a scenario's TOML text (bytes: some are not UTF-8)."""
    data: bytes | None = None
    for _ in range(rng.randint(1, 4)):
        kind = rng.randrange(12)
        lines = text.splitlines()
        if kind <= 2:  # a number replaced by an extreme
            numbers = list(NUMBER.finditer(text))
            if numbers:
                m = rng.choice(numbers)
                text = text[: m.start()] + rng.choice(EXTREMES) + text[m.end() :]
        elif kind == 3 and lines:  # a line deleted
            del lines[rng.randrange(len(lines))]
            text = "\n".join(lines)
        elif kind == 4 and lines:  # a line duplicated
            k = rng.randrange(len(lines))
            lines.insert(k, lines[k])
            text = "\n".join(lines)
        elif kind == 5:  # a key renamed
            key = rng.choice(KEYS)
            text = re.sub(rf"^{key}\b", rng.choice(KEYS), text, count=1, flags=re.M)
        elif kind == 6:  # deep nesting
            depth = rng.choice([2, 10, 17, 100, 1000, 5000])
            style = rng.randrange(3)
            if style == 0:
                value = "[" * depth + "1" + "]" * depth
            elif style == 1:
                value = "{ a = " * depth + "1" + " }" * depth
            else:
                value = None
            line = ".".join(["k"] * depth) + " = 1" if value is None else f"{rng.choice(KEYS)} = {value}"
            lines.insert(rng.randrange(len(lines) + 1), line)
            text = "\n".join(lines)
        elif kind == 7:  # truncated
            text = text[: rng.randrange(len(text) + 1)]
        elif kind == 8:  # a hostile [simulation] setting
            at = next((i for i, ln in enumerate(lines) if ln.strip() == "[simulation]"), len(lines) - 1)
            lines.insert(at + 1, rng.choice(HOSTILE_SIMULATION))
            text = "\n".join(lines)
        elif kind == 9:  # a model swapped
            name = rng.choice(["ideal", "damped", "rotating", "slewing", "string", "spring", "x"])
            text = re.sub(
                r'model = "[a-z_]*"',
                f'model = "{name}"',
                text,
                count=1,
            )
        elif kind == 10:  # bytes: invalid UTF-8 or NUL
            raw = text.encode()
            k = rng.randrange(len(raw) + 1)
            data = raw[:k] + rng.choice([b"\xff\xfe", b"\x00", b"\xc3", b"\x80\x80"]) + raw[k:]
        else:  # a huge value (beyond 1 MiB) or a long string / array
            size = rng.choice([2000, 100_000, 1_100_000])
            text += f'\ntitle2 = "{"x" * size}"' if rng.random() < 0.5 else f"\nzz = [{'1,' * (size // 2)}]"
    return data if data is not None else text.encode()


def generate(n: int, seed: int, directory: Path) -> list[Path]:
    """``n`` mutated files in ``directory`` (file k from seed ``seed``, mutation k)."""
    rng = random.Random(seed)
    texts = [p.read_text(encoding="utf-8") for p in SEEDS]
    paths = []
    for k in range(n):
        path = directory / f"fuzz_{k:05d}.toml"
        path.write_bytes(mutate(rng.choice(texts), rng))
        paths.append(path)
    return paths


@dataclass
class Tally:
    """Counts of outcomes and the failures (file, command, why)."""

    counts: Counter[str] = field(default_factory=Counter)
    failures: list[tuple[str, str, str]] = field(default_factory=list)


class _Hang(Exception):
    pass


def _alarm(_signum: int, _frame: object) -> None:
    raise _Hang


def _invoke(args: list[str]) -> tuple[int, str, str, BaseException | None]:
    from pendulab import cli
    from typer.testing import CliRunner

    result = CliRunner().invoke(cli.app, args)
    exc = result.exception if not isinstance(result.exception, SystemExit) else None
    return result.exit_code, result.stdout, result.stderr, exc


def _planned_work(path: Path) -> float:
    """Steps the file's run plans (inf when it cannot tell: an adaptive run of > 50 s, a crane)."""
    import pendulab as pl

    sc = pl.load_scenario(path)
    if sc.is_crane:  # the crane's own adaptive integrator: its work cannot be told, validate only
        return math.inf
    sim = sc.spec.simulation
    span = sim.t_end - sim.t0
    if sim.is_adaptive():
        return 0.0 if span <= 50.0 else math.inf
    return span / sim.resolved_dt()


def check_file(path: Path, tally: Tally, timeout: int = 60, run_work: float = RUN_WORK) -> None:
    """``validate`` and (when affordable) ``run`` on one file; failures go to ``tally``."""
    signal.signal(signal.SIGALRM, _alarm)
    for command in ("validate", "run"):
        args = [command, str(path)] + (["--quiet"] if command == "run" else [])
        if command == "run":
            try:
                work = _planned_work(path)
            except Exception:
                work = 0.0  # invalid: run must refuse it in one line
            if work > run_work:
                tally.counts[f"run skipped (valid, > {run_work:.0e} steps)"] += 1
                continue
        signal.alarm(timeout)
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                code, out, err, exc = _invoke(args)
        except _Hang:
            tally.failures.append((path.name, command, f"no answer within {timeout} s"))
            continue
        finally:
            signal.alarm(0)
        tally.counts[f"{command}: exit {code}"] += 1
        why = _judge(command, code, out, err, exc)
        if why:
            tally.failures.append((path.name, command, why))


def _judge(command: str, code: int, out: str, err: str, exc: BaseException | None) -> str | None:
    if exc is not None:
        return f"traceback: {type(exc).__name__}: {str(exc)[:200]}"
    if "Traceback" in out + err:
        return "a traceback was printed"
    if code not in (0, 2):
        return f"exit code {code}"
    lines = [ln for ln in err.splitlines() if ln.strip()]
    if code == 2:
        if not lines or not all(ln.startswith("error: ") for ln in lines):
            return f"exit 2 without only error: lines: {err[:300]!r}"
        if command == "run" and len(lines) != 1:
            return f"run printed {len(lines)} error lines"
        for ln in lines:  # a line lists every problem of the file: bounded per problem
            problems = max(1, len(re.findall(r"\(\d+\) ", ln)))
            if len(ln) > LINE_CHARS * problems:
                return f"an error line of {len(ln)} characters for {problems} problems"
    # a summary of a run must not show nan/inf (validate echoes only the file's own title)
    if code == 0 and command == "run" and re.search(r"\b(nan|inf)\b", out, re.I):
        return f"a non-finite number in the output: {out[:300]!r}"
    return None


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--files", type=int, default=2500, help="number of mutated files")
    ap.add_argument("--seed", type=int, default=13)
    ap.add_argument("--keep", type=Path, default=None, help="write the corpus here (kept)")
    args = ap.parse_args(argv)
    with tempfile.TemporaryDirectory() as tmp:
        directory = args.keep or Path(tmp)
        directory.mkdir(parents=True, exist_ok=True)
        paths = generate(args.files, args.seed, directory)
        tally = Tally()
        for path in paths:
            check_file(path, tally)
    print(f"fuzz corpus: {len(paths)} mutated scenario files (seed {args.seed})")
    for k, v in sorted(tally.counts.items()):
        print(f"  {k}: {v}")
    print(f"  failures (hangs, tracebacks, bad exits, silent non-finite): {len(tally.failures)}")
    for name, command, why in tally.failures[:50]:
        print(f"    {name} {command}: {why}")
    return 1 if tally.failures else 0


if __name__ == "__main__":
    sys.exit(main())
