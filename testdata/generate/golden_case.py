"""One case of the golden generator: a scenario's exact solution, its checks and floors
(golden_checks.py), its samples at the output times and the orbit's scalar quantities, as a
``CaseResult``. Units SI (m, kg, s, rad; E in J, J3 in kg m^2/s).

Check 5 is made here: recomputed at 60 digits, the samples agree with the 40-digit ones to 1e-32,
the scalar quantities to 1e-32 relative (and, in golden_checks.conditioning_floors, the perturbed
orbits that set the floors to 1e-25).
"""

from __future__ import annotations

import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import mpmath
from golden_base import DPS, HIGH_DPS, TIMES, TOL_HIGH, GoldenError, Scenario, State, Vec
from golden_checks import (
    conditioning_floors,
    energy,
    initial_state,
    j3,
    phase_split,
    state_error,
    v_scale,
    verify,
)
from golden_generic import GenericSolution, Solution
from golden_special import MirroredSolution, solve
from mpmath import mp, mpf

# --------------------------------------------------------------------------------------
# One case


@dataclass
class CaseResult:
    scenario: Scenario
    solution: Solution
    x0: Vec  # projected initial state
    v0: Vec
    energy: Any
    j3: Any
    samples: list[State]
    floors: list[float]
    floors_normwise: list[float]
    checks: dict[str, float]
    derived: dict[str, Any]  # scalar quantities of the orbit (mpf or None), see derived()


def derived(sol: Solution) -> dict[str, Any]:
    """The orbit's scalar quantities: period_z, eps, j, z1, z2, then the kind's own (info)."""
    z1, z2 = sol.z_range if sol.z_range is not None else (None, None)
    out = {"period_z": sol.period_z, "eps": sol.eps, "j": sol.j, "z1": z1, "z2": z2}
    out.update((k, v) for k, v in sol.info.items() if k != "period_z")
    return out


def generic_part(sol: Solution) -> GenericSolution | None:
    """The generic solution behind sol (also through the mirror), or None."""
    inner = sol.inner if isinstance(sol, MirroredSolution) else sol
    return inner if isinstance(inner, GenericSolution) else None


def run_case(sc: Scenario, log: Callable[[str], None]) -> CaseResult:
    t_start = time.perf_counter()
    x0, v0 = initial_state(sc)
    sol = solve(sc.length, sc.g, x0, v0)
    log(f"[{sc.name}] kind={sol.kind}, g={sc.g}")
    checks = verify(sc, sol, x0, v0, log)
    samples = [sol.state(mpf(t)) for t in TIMES]

    quantities = derived(sol)

    # 5. recompute at higher precision: the samples and the scalar quantities
    with mp.workdps(HIGH_DPS):
        xh, vh = initial_state(sc)
        sol_h = solve(sc.length, sc.g, xh, vh)
        ell = mpf(sc.length)
        worst = mpf(0)
        for t, ref in zip(TIMES, samples, strict=True):
            hi = sol_h.state(mpf(t))
            worst = max(worst, state_error(ell, v_scale(ell, mpf(sc.g), hi[1]), hi, ref))
        worst_q, worst_key = mpf(0), ""
        for key, val in derived(sol_h).items():
            ref = quantities[key]
            if (val is None) != (ref is None):
                raise GoldenError(f"{sc.name}: {key} is {ref} at {DPS} digits, {val} at {HIGH_DPS}")
            if val is not None and val != ref:
                err = abs(val - ref) / abs(val)
                if err > worst_q:
                    worst_q, worst_key = err, key
    checks["5_high_precision"] = float(worst)
    checks["5_quantities"] = float(worst_q)
    if not worst <= TOL_HIGH:
        raise GoldenError(f"{sc.name}: {DPS}-digit and {HIGH_DPS}-digit results differ by {worst}")
    if not worst_q <= TOL_HIGH:
        raise GoldenError(f"{sc.name}: {worst_key} at {DPS} and {HIGH_DPS} digits differs by {worst_q}")

    # 6. the phase split of T-5.1 (generic orbits)
    gen = generic_part(sol)
    if gen is not None:
        split = phase_split(sc.name, gen)
        quantities["phase_dynamic"] = split["phase_dynamic"]
        quantities["phase_geometric"] = split["phase_geometric"]
        checks["6_phase_sum"] = float(split["6_sum"])
        checks["6_phase_closed"] = float(split["6_closed"])
        log(
            f"    phases: dynamic {mpmath.nstr(split['phase_dynamic'], 12)}, geometric "
            f"{mpmath.nstr(split['phase_geometric'], 12)}; sum - delta_phi {mpmath.nstr(split['6_sum'], 2)}"
        )

    floors, checks["5_floor_orbits"] = conditioning_floors(sc, samples, normwise=False)
    floors_nw, recheck_nw = conditioning_floors(sc, samples, normwise=True)
    checks["5_floor_orbits"] = max(checks["5_floor_orbits"], recheck_nw)
    mass, g = mpf(sc.mass), mpf(sc.g)
    log(
        f"    check 5 ({HIGH_DPS} digits): samples {checks['5_high_precision']:.1e}, quantities "
        f"{checks['5_quantities']:.1e}, floor orbits {checks['5_floor_orbits']:.1e}"
    )
    log(
        f"    floors at t = {', '.join(f'{t:g}' for t in TIMES)} s: "
        + ", ".join(f"{f:.2e}" for f in floors)
        + "; normwise: "
        + ", ".join(f"{f:.2e}" for f in floors_nw)
        + f"  ({time.perf_counter() - t_start:.1f} s)"
    )
    return CaseResult(
        sc,
        sol,
        x0,
        v0,
        energy(mass, g, x0, v0),
        j3(mass, x0, v0),
        samples,
        floors,
        floors_nw,
        checks,
        quantities,
    )
