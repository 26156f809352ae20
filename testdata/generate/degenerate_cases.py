#!/usr/bin/env python3
"""Degenerate starts of the ideal spherical pendulum at 40+ digits: the exact solution's regression cases.

Writes ``testdata/degenerate_cases.json``: starts at which the float64 exact solution once failed
(refused a valid state, returned NaN, or lost 1e-9 … 1 of the state) — nearly planar swings, starts
next to the top pole, the separatrix with tiny J₃, J₃ = 5e-41 and 5e-101 — each with its state
(x [m], v [m/s]) at τ = ω₀t = 0.37, 1.3 and 3, computed by ``golden_states.py``'s exact solution
(``solve``: elliptic functions in mpmath, T-4.1 … T-4.4; planar and mirrored cases included).

The working precision grows with the smallness of j = J₃/(m l² ω₀): the roots sit j²/4(1 + ε)
from the poles, so 1 + u₁ ≈ 1e-201 needs 200 digits more than the 40 of the golden data. Each
case is computed twice, at that precision and 20 digits above it, and the two must agree to
1e-30 relative to l (resp. lω₀ + |v₀|), or the generator stops.

The float64 starts below are those ``pl.Pendulum.state(x, v, project=True)`` made from the
descriptions; they are taken as exact binary numbers and projected onto TS² at the working
precision, as in golden_states.py. Units SI. Usage (from the repository root)::

    python3 testdata/generate/degenerate_cases.py           # write testdata/degenerate_cases.json
    python3 testdata/generate/degenerate_cases.py --check   # recompute and compare, write nothing

Needs Python >= 3.11 and mpmath; runs in a few seconds.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path
from typing import Any

import mpmath
from mpmath import mp, mpf

sys.path.insert(0, str(Path(__file__).resolve().parent))
import golden_states as gs

OUT = Path(__file__).resolve().parents[1] / "degenerate_cases.json"
TAUS = ("0.37", "1.3", "3")
DIGITS = 30

# (name, l [m], g [m/s²], x0 [m], v0 [m/s], what)
CASES: list[tuple[str, float, float, list[float], list[float], str]] = [
    (
        "near_planar_issue",
        1.0,
        9.84,
        [0.2937907090157387, 2.0999335906502766e-08, -0.9558697710964759],
        [0.02890490321187151, 5.500035046783289e-08, 0.00888404703802595],
        "nearly planar small swing (issue 17's reproducer), j ~ 5e-9",
    ),
    (
        "near_planar_slow",
        4.799838080286795,
        -274.0,
        [1.4680070098545466, 1.8499210968897086, 4.178659228900044],
        [7.409222812579741e-07, 9.336793012985902e-07, -6.736400327591697e-07],
        "almost at rest with J3 at 2e-12 of its planar scale, g < 0: P(u0) below the rounding of P(-1)",
    ),
    (
        "near_top_fast",
        70.42702860091016,
        9.84,
        [4.6696861556655663e-07, -7.363353267900027e-07, 70.42702860091016],
        [7.939554241444792, -1.0216972735200303, -6.332560860111664e-08],
        "1.2e-8 l from the top, moving: n+ = 1 - 2e-17, the start's amplitude next to pi/2",
    ),
    (
        "near_top_slow",
        2.5009090159421956,
        9.84,
        [-3.337617486836954e-08, 1.351829625666022e-08, 2.5009090159421956],
        [7.354824819780914e-09, 2.714387292106565e-09, 8.348245634300504e-17],
        "1.4e-8 l from the top, creeping: m = 1 - 5e-17 rounds to 1.0",
    ),
    (
        "separatrix_small_j",
        0.5171005623885531,
        -274.0,
        [-0.2301773666971849, -0.4487128921647535, -0.11431584268179887],
        [1.4990854118241388, 2.9223505351267933, -14.489259355715923],
        "E = mgl to 3e-16 with j = 9e-16, g < 0: 1 - m = 5e-16",
    ),
    (
        "separatrix_above_equator",
        0.23600905606821132,
        9.84,
        [-0.12597072646349464, -0.18981187804342523, 0.061669291986331615],
        [0.2676386631888221, 0.40327621125233204, 1.7879441827237945],
        "J3 at rounding level, E = mgl to an ulp, started above the equator",
    ),
    (
        "tiny_j_1e-40",
        1.0,
        1.0,
        [0.5000000000000001, 0.0, -0.8660254037844388],
        [0.4330127018922193, 1e-40, 0.25],
        "a swing with j = 5e-41: 1 + u1 = 2.4e-81",
    ),
    (
        "tiny_j_1e-100_over_top",
        1.0,
        1.0,
        [0.5000000000000001, 0.0, -0.8660254037844388],
        [2.598076211353316, 1e-100, 1.5],
        "over the top with j = 5e-101",
    ),
    (
        "tiny_amplitude_spherical",
        1.0,
        9.81,
        [2.9999999999999984e-08, 9.999999999999995e-09, -0.9999999999999996],
        [9.809999999999985e-08, 1.9619999999999994e-07, 4.904999999999995e-15],
        "a 3e-8 rad spherical swing",
    ),
]


def digits_for(length: float, g: float, x: list[float], v: list[float]) -> int:
    """40 digits plus twice the decimal exponent of a small j (see the module docstring)."""
    w0 = abs(g / length) ** 0.5
    j = abs(x[0] * v[1] - x[1] * v[0]) / (length**2 * w0)
    return 50 + (2 * int(-mpmath.log10(j)) if 0 < j < 1e-10 else 0)


def states(length: float, g: float, x: list[float], v: list[float], dps: int) -> tuple[str, list[Any]]:
    """The kind and the states at TAUS, at dps digits."""
    with mp.workdps(dps):
        ell, gg = mpf(length), mpf(g)
        x0, v0 = gs.project(ell, gs.to_mp(x), gs.to_mp(v))
        sol = gs.solve(ell, gg, x0, v0)
        w0 = mp.sqrt(abs(gg) / ell)
        return sol.kind, [(mpf(tau) / w0, *sol.state(mpf(tau) / w0)) for tau in TAUS]


def case(name: str, length: float, g: float, x: list[float], v: list[float], what: str) -> dict[str, Any]:
    dps = digits_for(length, g, x, v)
    kind, lo = states(length, g, x, v, dps)
    _, hi = states(length, g, x, v, dps + 20)
    vs = length * abs(g / length) ** 0.5 + sum(c * c for c in v) ** 0.5
    for (t, xa, va), (_, xb, vb) in zip(lo, hi, strict=True):
        dx = max(abs(a - b) for a, b in zip(xa, xb, strict=True)) / length
        dv = max(abs(a - b) for a, b in zip(va, vb, strict=True)) / vs
        if max(dx, dv) > 1e-30:
            gap = mpmath.nstr(max(dx, dv), 3)
            raise SystemExit(f"{name}: {dps} and {dps + 20} digits differ by {gap} at t = {t}")
    return {
        "name": name,
        "what": what,
        "length": length,
        "mass": 1.0,
        "g": g,
        "x0": x,
        "v0": v,
        "kind": kind,
        "digits": dps,
        "samples": [
            {
                "tau": float(tau),
                "t": float(t),
                "x_str": [mpmath.nstr(c, DIGITS, strip_zeros=False) for c in xs],
                "v_str": [mpmath.nstr(c, DIGITS, strip_zeros=False) for c in vs_],
            }
            for tau, (t, xs, vs_) in zip(TAUS, lo, strict=True)
        ],
    }


def main(argv: list[str]) -> int:
    doc = {
        "generator": "testdata/generate/degenerate_cases.py",
        "units": "SI: length m, g m/s^2, mass kg, t s, x m, v m/s; tau = omega0 t",
        "cases": [case(*c) for c in CASES],
    }
    text = json.dumps(doc, indent=1, ensure_ascii=False) + "\n"
    if "--check" in argv:
        if json.loads(OUT.read_text()) != json.loads(text):
            print(f"{OUT} differs from a fresh run", file=sys.stderr)
            return 1
        print(f"{OUT}: up to date")
        return 0
    tmp = OUT.with_suffix(".json.tmp")
    tmp.write_text(text)
    tmp.replace(OUT)
    print(f"wrote {OUT} ({len(doc['cases'])} cases)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
