#!/usr/bin/env python3
"""Golden values of the Legendre elliptic integrals and the Jacobi elliptic functions.

Writes ``testdata/elliptic_golden.json`` for ``crates/pendulab-core/tests/elliptic.rs``:
exact values (mpmath, 40 significant digits) of the functions of
``pendulab_core::elliptic`` at float64 arguments, on grids that cover the parameter
m = k^2 from 0 to 1 - 1e-12 (and m = 1 where the value is finite), the characteristic n
from -1e10 to 1 - 1e-12, amplitudes beyond pi/2 and negative, and Jacobi arguments u up
to 1e4, plus reproducible random points.

Usage (from the repository root)::

    .venv/bin/python testdata/generate/elliptic.py           # regenerate, write the JSON
    .venv/bin/python testdata/generate/elliptic.py --check   # recompute, compare, no write

Needs Python >= 3.11 and mpmath (>= 1.3); nothing else. Runs in about half a minute.

Definitions (DLMF chapter 19 and 22, parameter m = k^2 as in mpmath):

* K(m) = F(pi/2 | m), E(m) = E(pi/2 | m), Pi(n | m) = Pi(n; pi/2 | m)   (DLMF 19.2.8)
* F(phi | m)     = int_0^phi dt / sqrt(1 - m sin^2 t)                     (DLMF 19.2.4)
* E(phi | m)     = int_0^phi sqrt(1 - m sin^2 t) dt                       (DLMF 19.2.5)
* Pi(n; phi | m) = int_0^phi dt / ((1 - n sin^2 t) sqrt(1 - m sin^2 t))   (DLMF 19.2.7)
  for every real phi: F(phi + j pi) = F(phi) + 2 j K, likewise E and Pi (DLMF 19.2.10),
  all odd in phi. These are mpmath's ellipk, ellipe, ellippi, ellipf, ellipe(phi, m),
  ellippi(n, phi, m).
* am(u | m) is the inverse of F: F(am(u) | m) = u, continuous in u, am(u + 2K) = am(u) + pi;
  sn = sin am, cn = cos am, dn = sqrt(1 - m sn^2) (DLMF 22.16.1, 22.16.11-12). At m = 1:
  sn = tanh u, cn = dn = sech u, am = gd(u) = atan(sinh u) (DLMF 22.5.3, 4.23.39).

Every argument is a float64 and is evaluated exactly (``mpf(float)``). The Jacobi values
are computed on the reduced argument r = u - 2jK in [-K, K] (j = nint(u / 2K), K at 60
digits): am = j pi + atan2(sn(r), cn(r)), sn = (-1)^j sn(r), cn = (-1)^j cn(r),
dn = dn(r), with mpmath.ellipfun.

Checks (nothing is written unless all pass):

1. Every value recomputed at 60 digits agrees with the 40-digit one to 1e-32 relative.
2. Jacobi: F(am(r) | m) = r to 1e-30 (Legendre integral against theta functions), and for
   |u| <= 100 mpmath.ellipfun evaluated directly at u agrees with the reduced form.
3. Incomplete integrals: quasi-periodicity recomputed by hand (value at phi equals
   2j X(m) + value at phi - j pi) for every row with |phi| > pi/2.

Each row stores, for every value, the nearest float64 ``v``, the float64 ``v_lo`` of the
remainder (exact - v), so that ``v + v_lo`` is the exact value to ~1e-32, and a decimal
string with 22 significant digits. Incomplete integrals also store ``d``, the derivative
with respect to phi (1/Delta, Delta, 1/((1 - n sin^2 phi) Delta), Delta = sqrt(1 - m
sin^2 phi)), for the conditioning allowance of the test.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import random
import sys
import tempfile
import time
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import mpmath
from mpmath import mp, mpf

ROOT = Path(__file__).resolve().parents[2]
OUTPUT = ROOT / "testdata" / "elliptic_golden.json"
DPS = 40
CHECK_DPS = 60
DIGITS = 22
SEED = 20260901

M_GRID = [0.0, 1e-15, 1e-8, 0.1, 0.5, 0.9, 0.99, 1 - 1e-4, 1 - 1e-8, 1 - 1e-12, 1.0]
N_GRID = [-1e10, -1e3, -1.0, -0.45, -1e-8, 0.0, 0.3, 0.9, 1 - 1e-6, 1 - 1e-12]
PHI_GRID = [
    1e-10,
    0.1,
    0.7,
    1.2,
    1.5,
    math.pi / 2,
    1.6,
    2.5,
    3.0,
    4.0,
    7.5,
    31.4,
    1000.0,
    1e4,
    -0.3,
    -math.pi / 2,
    -2.0,
    -12.0,
]
PHI_GRID_PI = [0.7, 1.5, math.pi / 2, 2.5, -4.0, 31.4, 1e4]
# Jacobi also at m = 1 - 1e-15 and 1 - 2^-52, where cn and dn are tiny over most of [0, K].
JACOBI_M_GRID = [*M_GRID[:-1], 1 - 1e-15, 1 - 2.0**-52, 1.0]
U_GRID = [1e-8, 0.1, 0.5, 1.0, 1.7, 3.0, 7.0, 15.0, 19.0, 40.0, 100.0, 1234.5, 1e4, -0.6, -25.0, -9999.5]

Row = list[Any]


class GoldenError(Exception):
    """A self-check failed."""


def split(x: Any) -> list[Any]:
    """[nearest float64, float64 of the remainder, 22-digit string] of an mpf."""
    v = float(x)
    lo = float(x - mpf(v))
    return [v, lo, mpmath.nstr(x, DIGITS, min_fixed=-5, max_fixed=5, strip_zeros=False)]


def random_m(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.4:
        return rng.random()
    if r < 0.8:
        return 1.0 - 10.0 ** rng.uniform(-15.5, -1)
    return 10.0 ** rng.uniform(-16, -1)


def random_n(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.35:
        return -(10.0 ** rng.uniform(-9, 10.5))
    if r < 0.7:
        return rng.random()
    return 1.0 - 10.0 ** rng.uniform(-13, -1)


def random_phi(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.5:
        return rng.uniform(-math.pi / 2, math.pi / 2)
    if r < 0.85:
        return rng.uniform(-20.0, 20.0)
    return rng.choice([-1.0, 1.0]) * 10.0 ** rng.uniform(1.3, 4)


def random_u(rng: random.Random) -> float:
    r = rng.random()
    if r < 0.6:
        return rng.uniform(-60.0, 60.0)
    return rng.choice([-1.0, 1.0]) * 10.0 ** rng.uniform(-3, 4)


# ---------------------------------------------------------------- exact functions


def delta(phi: Any, m: Any) -> Any:
    """sqrt(1 - m sin^2 phi), written without cancellation near m sin^2 phi = 1."""
    return mp.sqrt(mp.cos(phi) ** 2 + (1 - m) * mp.sin(phi) ** 2)


def incomplete(kind: str, phi: Any, m: Any, n: Any = None) -> tuple[Any, Any]:
    """(value, derivative with respect to phi) of F, E or Pi, with 20 guard digits."""
    with mp.workdps(mp.dps + 20):
        if kind == "ellipf":
            val, der = mpmath.ellipf(phi, m), 1 / delta(phi, m)
        elif kind == "ellipe_inc":
            val, der = mpmath.ellipe(phi, m), delta(phi, m)
        else:
            val, der = (
                mpmath.ellippi(n, phi, m),
                1 / ((mp.cos(phi) ** 2 + (1 - n) * mp.sin(phi) ** 2) * delta(phi, m)),
            )
    return +val, +der


def complete(kind: str, m: Any, n: Any = None) -> Any:
    """K, E or Pi(n | m), with 20 guard digits."""
    with mp.workdps(mp.dps + 20):
        if kind in ("ellipf", "ellipk"):
            val = mpmath.ellipk(m)
        elif kind in ("ellipe_inc", "ellipe"):
            val = mpmath.ellipe(m)
        else:
            val = mpmath.ellippi(n, m)
    return +val


def jacobi_exact(u: Any, m: Any) -> tuple[list[Any], Any, Any]:
    """([sn, cn, dn, am], reduced argument r, am(r)) at the current precision."""
    if m == 1:
        sech = 1 / mp.cosh(u)
        return [mp.tanh(u), sech, sech, mp.atan(mp.sinh(u))], u, mp.atan(mp.sinh(u))
    with mp.workdps(mp.dps + 20):
        big_k = mpmath.ellipk(m)
        j = int(mp.nint(u / (2 * big_k)))
        r = u - 2 * j * big_k
        sn = mpmath.ellipfun("sn", r, m=m)
        cn = mpmath.ellipfun("cn", r, m=m)
        dn = mpmath.ellipfun("dn", r, m=m)
        am_r = mp.atan2(sn, cn)
        sign = -1 if j % 2 else 1
        vals = [sign * sn, sign * cn, dn, j * mp.pi + am_r]
    return [+v for v in vals], +r, +am_r


# ---------------------------------------------------------------- tables


def is_finite(*xs: Any) -> bool:
    return all(mp.isfinite(x) for x in xs)


def rel_diff(a: Any, b: Any) -> Any:
    return abs(a - b) / max(abs(a), abs(b), mpf("1e-300"))


def at_two_precisions(f: Callable[[], list[Any]], what: str) -> list[Any]:
    with mp.workdps(CHECK_DPS):
        hi = f()
    lo = f()
    for a, b in zip(lo, hi, strict=True):
        if is_finite(a, b) and rel_diff(a, b) > mpf("1e-32"):
            raise GoldenError(f"{what}: 40 and 60 digits differ: {a} vs {b}")
    return lo


def complete_rows(kind: str, rng: random.Random) -> Iterator[Row]:
    if kind == "ellippi":
        pts = [(n, m) for n in N_GRID for m in M_GRID if m < 1]
        pts += [(random_n(rng), random_m(rng)) for _ in range(60)]
    else:
        pts = [(None, m) for m in M_GRID]
        pts += [(None, random_m(rng)) for _ in range(40)]
    for n, m in pts:
        (val,) = at_two_precisions(
            lambda n=n, m=m: [complete(kind, mpf(m), None if n is None else mpf(n))], kind
        )
        if not is_finite(val):
            continue
        args = [m] if n is None else [n, m]
        yield [*args, *split(val)]


def incomplete_rows(kind: str, rng: random.Random) -> Iterator[Row]:
    if kind == "ellippi_inc":
        pts = [(n, phi, m) for n in N_GRID for m in M_GRID for phi in PHI_GRID_PI]
        pts += [(random_n(rng), random_phi(rng), random_m(rng)) for _ in range(80)]
    else:
        pts = [(None, phi, m) for m in M_GRID for phi in PHI_GRID]
        pts += [(None, random_phi(rng), random_m(rng)) for _ in range(60)]
    for n, phi, m in pts:
        mn = None if n is None else mpf(n)
        val, der = at_two_precisions(
            lambda mn=mn, phi=phi, m=m: list(incomplete(kind, mpf(phi), mpf(m), mn)), kind
        )
        if not is_finite(val, der):
            continue
        if abs(phi) > math.pi / 2:
            j = int(mp.nint(mpf(phi) / mp.pi))
            base, _ = incomplete(kind, mpf(phi) - j * mp.pi, mpf(m), mn)
            by_hand = 2 * j * complete(kind, mpf(m), mn) + base
            if rel_diff(by_hand, val) > mpf("1e-30"):
                raise GoldenError(f"{kind}({n}, {phi}, {m}): quasi-periodicity fails: {by_hand} vs {val}")
        args = [phi, m] if n is None else [n, phi, m]
        yield [*args, *split(val), float(der)]


def jacobi_rows(rng: random.Random) -> Iterator[Row]:
    pts = [(u, m) for m in JACOBI_M_GRID for u in U_GRID]
    for m in JACOBI_M_GRID[:-1]:
        big_k = mpmath.ellipk(mpf(m))
        pts += [(float(c * big_k), m) for c in (1, mpf("0.999"), mpf("1.5"), 2, 3)]
    pts += [(random_u(rng), random_m(rng)) for _ in range(80)]
    for u, m in pts:
        vals = at_two_precisions(lambda u=u, m=m: jacobi_exact(mpf(u), mpf(m))[0], "jacobi")
        _, r, am_r = jacobi_exact(mpf(u), mpf(m))
        if m < 1 and abs(mpmath.ellipf(am_r, mpf(m)) - r) > mpf("1e-30") * max(1, abs(r)):
            raise GoldenError(f"jacobi({u}, {m}): F(am(r)) != r")
        if abs(u) <= 100:
            direct = [mpmath.ellipfun(k, mpf(u), m=mpf(m)) for k in ("sn", "cn", "dn")]
            for a, b in zip(direct, vals[:3], strict=True):
                if abs(a - b) > mpf("1e-30"):
                    raise GoldenError(f"jacobi({u}, {m}): direct and reduced differ: {a} vs {b}")
        yield [u, m, *(x for v in vals for x in split(v))]


def document(log: Callable[[str], None]) -> dict[str, Any]:
    rng = random.Random(SEED)
    value = ["v", "v_lo", "v_str"]
    tables: dict[str, Any] = {}
    for kind, args in (("ellipk", ["m"]), ("ellipe", ["m"]), ("ellippi", ["n", "m"])):
        rows = list(complete_rows(kind, rng))
        tables[kind] = {"columns": [*args, *value], "rows": rows}
        log(f"{kind}: {len(rows)} rows")
    for kind, args in (
        ("ellipf", ["phi", "m"]),
        ("ellipe_inc", ["phi", "m"]),
        ("ellippi_inc", ["n", "phi", "m"]),
    ):
        rows = list(incomplete_rows(kind, rng))
        tables[kind] = {"columns": [*args, *value, "d"], "rows": rows}
        log(f"{kind}: {len(rows)} rows")
    rows = list(jacobi_rows(rng))
    cols = ["u", "m"] + [f"{f}{s}" for f in ("sn", "cn", "dn", "am") for s in ("", "_lo", "_str")]
    tables["jacobi"] = {"columns": cols, "rows": rows}
    log(f"jacobi: {len(rows)} rows")
    return {
        "generator": "testdata/generate/elliptic.py",
        "mp_dps": DPS,
        "string_digits": DIGITS,
        "seed": SEED,
        "convention": "parameter m = k^2; Pi(n; phi | m) = int dt/((1 - n sin^2 t) sqrt(1 - m sin^2 t))",
        "functions": tables,
    }


def to_json(doc: dict[str, Any]) -> str:
    lines = ["{"]
    head = [k for k in doc if k != "functions"]
    lines += [f"  {json.dumps(k)}: {json.dumps(doc[k])}," for k in head]
    lines.append('  "functions": {')
    names = list(doc["functions"])
    for i, name in enumerate(names):
        table = doc["functions"][name]
        lines.append(f"    {json.dumps(name)}: {{")
        lines.append(f'      "columns": {json.dumps(table["columns"])},')
        lines.append('      "rows": [')
        rows = [f"        {json.dumps(r, separators=(',', ':'))}" for r in table["rows"]]
        lines.append(",\n".join(rows))
        lines.append("      ]")
        lines.append("    }" + ("," if i + 1 < len(names) else ""))
    lines += ["  }", "}", ""]
    return "\n".join(lines)


def compare(new: dict[str, Any], old: dict[str, Any]) -> list[str]:
    problems = []
    for name, table in new["functions"].items():
        old_rows = old.get("functions", {}).get(name, {}).get("rows")
        if old_rows is None or len(old_rows) != len(table["rows"]):
            problems.append(f"{name}: row count differs")
            continue
        for a, b in zip(table["rows"], old_rows, strict=True):
            for x, y in zip(a, b, strict=True):
                same = (
                    mpmath.almosteq(mpf(x), mpf(y), rel_eps=mpf("1e-22"), abs_eps=mpf("1e-300"))
                    if isinstance(x, str)
                    else x == y
                )
                if not same:
                    problems.append(f"{name}: {a[:3]}: {x} != {y}")
    return problems


def write_atomic(path: Path, text: str) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name, suffix=".tmp")
    with os.fdopen(fd, "w", encoding="utf-8") as f:
        f.write(text)
    os.chmod(tmp, 0o644)
    os.replace(tmp, path)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="recompute and compare to the committed JSON")
    ap.add_argument("--out", type=Path, default=OUTPUT, help="output file (default: %(default)s)")
    args = ap.parse_args(argv)
    mp.dps = DPS
    t0 = time.perf_counter()
    try:
        doc = document(lambda msg: print(msg, flush=True))
    except GoldenError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
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
    print(f"wrote {args.out} ({len(text) // 1024} KiB) in {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
