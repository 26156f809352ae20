#!/usr/bin/env python3
"""Golden reference states of the ideal spherical pendulum, from its exact solution.

Writes ``testdata/golden_states.json``: for every scenario in
``examples/scenarios/*.toml`` the state (x, v) at t = 1, 10, 100, 1000 and 10^4 s,
computed from the closed-form solution in elliptic functions at 40 significant digits
(mpmath), stored as float64 and as 30-digit strings, with conditioning floors per sample;
the orbit's scalar quantities (eps, j, heights z1 < z2, roots, m, period, Delta_phi and its
T-5.1 split into a dynamic and a geometric phase), each as float and 30-digit string; and
the worked example of docs/theory.md T-5.1 ("phase_example"). Equation numbers (T-x.y) refer to
docs/theory.md; units SI (m, kg, s, rad).

Usage (from the repository root)::

    python3 testdata/generate/golden_states.py           # regenerate, write the JSON
    python3 testdata/generate/golden_states.py --check   # recompute, compare, no write

Needs Python >= 3.11 and mpmath (>= 1.3); nothing else. Runs in about a minute.

Model (T-2.4): x' = v, v' = -g e3 + ((g z - |v|^2)/l^2) x on TS^2 (|x| = l, x.v = 0),
invariants (T-2.6) E = m(|v|^2/2 + g z) and J3 = m(x1 v2 - x2 v1).

The generator's parts, one concept each (this file: the T-5.1 example and the command line):

* golden_base.py: precision, times, tolerances, units, vector helpers, the scenarios' float64
  starts projected onto TS^2;
* golden_generic.py: the generic solution (g > 0, J3 != 0; T-4.1 to T-4.5, T-5.1, T-3.6);
* golden_special.py: the special cases of T-4.6 (g < 0 mirrored, g = 0, J3 = 0) and ``solve``;
* golden_checks.py: checks 1-4 and 6, the conditioning floors;
* golden_case.py: one scenario's result, with check 5 (recomputed at 60 digits);
* golden_json.py: the JSON document, its atomic write and the ``--check`` comparison.

The names the other generators and benches use (``hard_cases.py``, ``degenerate_cases.py``,
bench/exact_vs_integrators.py) are re-exported here. The T-5.1 example of docs/theory.md
(l = g = 1, eps = 0.3, j = 0.5) must reproduce every digit docs/theory.md prints (check 6).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mpmath
from golden_base import (
    DPS,
    OUTPUT,
    REPO,
    STR_DIGITS,
    TIMES,
    UNITS,
    GoldenError,
    Scenario,
    float_initial_state,
    load_scenarios,
    project,
    to_mp,
)
from golden_case import derived, run_case
from golden_checks import phase_split
from golden_generic import GenericSolution
from golden_json import (
    case_json,
    compare,
    compare_quantities,
    document,
    quantity_fields,
    sci,
    to_json,
    write_atomic,
)
from golden_special import solve
from mpmath import mp, mpf

# what hard_cases.py, degenerate_cases.py and bench/exact_vs_integrators.py use
__all__ = [
    "DPS",
    "REPO",
    "STR_DIGITS",
    "TIMES",
    "UNITS",
    "GoldenError",
    "Scenario",
    "case_json",
    "compare_quantities",
    "float_initial_state",
    "mp",
    "project",
    "run_case",
    "solve",
    "to_json",
    "to_mp",
    "write_atomic",
]


# The T-5.1 example of docs/theory.md: l = g = 1, eps = 0.3, j = 0.5, as printed there.
PHASE_EXAMPLE_PRINTED = {
    "delta_phi": "4.16859732561",
    "phase_dynamic": "9.5651005316",
    "phase_geometric": "-5.39650320598",
}


def phase_example(log: Callable[[str], None]) -> dict[str, Any]:
    """The T-5.1 example of docs/theory.md, recomputed; its printed digits must agree (half a unit in
    the last printed place). Start on the equator (u0 = 0, x0 = (l, 0, 0)) with
    v0 = (0, j, sqrt(2 eps - j^2)) in units l = g = m = 1, so that E = eps and J3 = j."""
    eps, j = mpf("0.3"), mpf("0.5")
    x0 = [mpf(1), mpf(0), mpf(0)]
    v0 = [mpf(0), j, mp.sqrt(2 * eps - j * j)]
    sol = solve(1, 1, x0, v0)
    if not isinstance(sol, GenericSolution):
        raise GoldenError("phase example: not a generic orbit")
    tiny = mpf(10) ** (-DPS + 2)
    if abs(sol.eps - eps) > tiny or abs(sol.j - j) > tiny:
        raise GoldenError(f"phase example: eps = {sol.eps}, j = {sol.j}")
    split = phase_split("phase_example", sol)
    quantities = derived(sol)
    quantities.update(phase_dynamic=split["phase_dynamic"], phase_geometric=split["phase_geometric"])
    for key, printed in PHASE_EXAMPLE_PRINTED.items():
        decimals = len(printed.split(".")[1])
        err = abs(quantities[key] - mpf(printed))
        if not err <= mpf(10) ** (-decimals) / 2:
            raise GoldenError(
                f"phase example: {key} = {mpmath.nstr(quantities[key], 20)}, docs/theory.md prints {printed}"
            )
    log(
        "[phase_example] docs/theory.md T-5.1 reproduced: delta_phi, dynamic, geometric = "
        + ", ".join(mpmath.nstr(quantities[k], 15) for k in PHASE_EXAMPLE_PRINTED)
    )
    return {
        "source": "docs/theory.md T-5.1",
        "length": 1.0,
        "mass": 1.0,
        "g": 1.0,
        "x0_str": [sci(c) for c in x0],
        "v0_str": [sci(c) for c in v0],
        "kind": sol.kind,
        **quantity_fields(quantities),
        "theory_printed": dict(PHASE_EXAMPLE_PRINTED),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--check",
        action="store_true",
        help="recompute and compare to the committed JSON",
    )
    ap.add_argument("--out", type=Path, default=OUTPUT, help="output file (default: %(default)s)")
    args = ap.parse_args(argv)
    mp.dps = DPS
    t0 = time.perf_counter()

    def log(msg: str) -> None:
        print(msg, flush=True)

    try:
        results = [run_case(sc, log) for sc in load_scenarios()]
        example = phase_example(log)
    except GoldenError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    doc = document(results, example)
    text = to_json(doc)
    elapsed = time.perf_counter() - t0
    if args.check:
        try:
            old = json.loads(args.out.read_text(encoding="utf-8"))
        except (OSError, ValueError) as e:
            print(f"error: cannot read {args.out}: {e}", file=sys.stderr)
            return 1
        problems = compare(doc, old)
        for p in problems:
            print(f"MISMATCH {p}", file=sys.stderr)
        print(f"{'FAILED' if problems else 'OK'}: {args.out} checked in {elapsed:.0f} s")
        return 1 if problems else 0
    write_atomic(args.out, text)
    print(f"wrote {args.out} ({len(results)} cases) in {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
