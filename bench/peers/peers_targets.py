"""The targets of issues 5 and 29 from one run of the peers benchmark (bench/peers/run.py), each a
measured ratio with a PASS/MISS verdict: RATTLE steps/s against the C RK4 loop and MuJoCo, the
ensemble against the C RK4 ensemble and its speed-up on two threads, ``pl.simulate_ensemble`` against
the C RK4 ensemble at 10³ and 10⁴ steps (wall time [s], issue 29), the time to an error ≤ 1e-10
against C and MuJoCo, Pendulab's best against every peer's best at every level 1e-4…1e-12,
robustness, and the rotation-number map's time [s].
"""

from __future__ import annotations

import math
from typing import Any

import harness as hz
from peers_cases import TOL_HI, Case

API_VS_C_TARGET = "simulate_ensemble ≥ 2 × C RK4 ensemble at 10³ and 10⁴ steps (2 threads, issue 29)"
API_VS_C_VARIANTS_TARGET = (
    "the same with per-trajectory lengths, g, damping and with damping (issue 29, item 3)"
)
STEPS_SHOWN = {"1000": "10³", "10000": "10⁴"}


def best_of(
    runs: list[hz.Run], case: str, tol: float, family: str | None, exclude_exact: bool = True
) -> hz.Run | None:
    sel = [
        r
        for r in runs
        if r.case == case
        and (family is None or (r.method.startswith("pendulab") == (family == "pendulab")))
        and not (exclude_exact and r.method == "pendulab exact")
    ]
    return hz.cheapest(sel, tol)


def targets(
    runs: list[hz.Run], rates: dict[str, Any], ens: dict[str, Any], rmap: dict[str, Any], cases: list[Case]
) -> list[dict[str, Any]]:
    """The issue's targets, each as a measured ratio with PASS/MISS."""
    out: list[dict[str, Any]] = []

    def add(name: str, value: float | None, target: float, higher: bool, detail: str) -> None:
        out.append(
            {
                "target": name,
                "value": value,
                "goal": target,
                "higher_is_better": higher,
                "verdict": hz.ratio_verdict(value, target, higher),
                "detail": detail,
            }
        )

    rat = rates.get("pendulab rattle (Stepper.step)", {}).get("steps_per_s")
    crk = rates.get("C rk4", {}).get("steps_per_s")
    mj = rates.get("mujoco rk4 (mj_step, nstep)", {}).get("steps_per_s")
    add(
        "RATTLE steps/s ≥ 1.2 × C RK4 loop", rat / crk if rat and crk else None, 1.2, True,
        f"{hz.fmt_sci(rat)} vs {hz.fmt_sci(crk)} steps/s",
    )  # fmt: skip
    add(
        "RATTLE steps/s ≥ 50 × MuJoCo (RK4)", rat / mj if rat and mj else None, 50.0, True,
        f"{hz.fmt_sci(rat)} vs {hz.fmt_sci(mj)} steps/s",
    )  # fmt: skip
    pe, ce = ens["pendulab"], ens.get("C rk4", {})
    p2, c2 = pe.get(2, {}).get("rate"), ce.get(2, {}).get("rate")
    add(
        "ensemble ≥ 0.8 × C RK4 ensemble (2 threads)", p2 / c2 if p2 and c2 else None, 0.8, True,
        f"{hz.fmt_sci(p2)} vs {hz.fmt_sci(c2)} trajectory-steps/s",
    )  # fmt: skip
    p1 = pe.get(1, {}).get("rate")
    add(
        "ensemble speed-up 1 → 2 threads ≥ 1.8", p2 / p1 if p1 and p2 else None, 1.8, True,
        f"{hz.fmt_sci(p1)} → {hz.fmt_sci(p2)} (C RK4: "
        + (f"{ce[2]['rate'] / ce[1]['rate']:.2f}" if 1 in ce and 2 in ce else "—")
        + ")",
    )  # fmt: skip
    avc = ens.get("api_vs_c", {})
    by_steps = avc.get("steps", {})
    ratios = [r["ratio"] for r in by_steps.values()]
    parts = [
        f"{STEPS_SHOWN.get(k, k)} steps: C / API wall {r['ratio']:.3g} ({hz.fmt_time(r['c_wall'])} vs "
        f"{hz.fmt_time(r['api_wall'])}, best of {r['repeats']})"
        for k, r in by_steps.items()
    ]
    if ratios:
        parts.append(f"arithmetic {avc.get('arithmetic')}; the smaller ratio counts")
    add(
        API_VS_C_TARGET, min(ratios) if set(STEPS_SHOWN) <= set(by_steps) else None, 2.0, True,
        "; ".join(parts) or avc.get("skipped", "not run"),
    )  # fmt: skip
    variants = avc.get("variants", {})
    worst = [
        (r["ratio"], f"{name}, {STEPS_SHOWN.get(k, k)} steps")
        for name, vs in variants.items()
        for k, r in vs.items()
    ]
    add(
        API_VS_C_VARIANTS_TARGET, min(worst)[0] if worst else None, 2.0, True,
        f"smallest: {min(worst)[1]} ({len(worst)} forms × step counts; the C ensemble has the same lengths "
        "and g, no damping)" if worst else avc.get("skipped", "not run"),
    )  # fmt: skip
    ros = "rosette"
    best = best_of(runs, ros, TOL_HI, "pendulab")
    for peer, goal in (("C rk4", 0.2), ("mujoco rk4", 0.01)):
        peer_runs = [r for r in runs if r.method == peer and r.case == ros and r.ok]
        pr = hz.cheapest(peer_runs, TOL_HI)
        if not peer_runs:
            val, det = None, f"{peer} was not run"
        elif best and pr:
            val, det = (
                best.wall / pr.wall,
                f"{best.method} {hz.fmt_time(best.wall)} vs {hz.fmt_time(pr.wall)}",
            )
        elif best:
            longest = max(r.wall for r in peer_runs)
            val = best.wall / longest
            det = (
                f"{best.method} {hz.fmt_time(best.wall)}; {peer} never reached 1e-10 (its longest run, "
                f"{hz.fmt_time(longest)}, gives this ratio as an upper bound)"
            )
        else:
            val, det = None, "Pendulab did not reach 1e-10"
        add(f"time to ≤1e-10 (rosette) ≤ {goal:g} × {peer}", val, goal, False, det)
    misses: list[str] = []
    worst = 0.0
    compared = 0
    for case in cases:
        for lvl in hz.LEVELS:
            b = best_of(runs, case.name, lvl, "pendulab")
            pb = best_of(runs, case.name, lvl, "peers")
            if pb is None:
                continue
            compared += 1
            if b is None:
                misses.append(f"{case.name} {lvl:.0e} (not reached)")
                worst = math.inf
                continue
            worst = max(worst, b.wall / pb.wall)
            if b.wall >= pb.wall:
                misses.append(
                    f"{case.name} {lvl:.0e}: {b.method} {hz.fmt_time(b.wall)} "
                    f"vs {pb.method} {hz.fmt_time(pb.wall)}"
                )
    add(
        "every level 1e-4…1e-12, every case: Pendulab's best faster than every peer's best",
        worst if compared else None, 1.0, False,
        f"{compared} (case, level) pairs compared; largest ratio Pendulab/peer "
        + (f"{worst:.3g}" if math.isfinite(worst) else "∞")
        + ("; misses: " + "; ".join(misses) if misses else ""),
    )  # fmt: skip
    reached = {c.name: best_of(runs, c.name, TOL_HI, "pendulab") for c in cases}
    n_ok = sum(r is not None for r in reached.values())
    add(
        "robustness: every case reaches ≤1e-10 (Pendulab's best)", n_ok / len(cases), 1.0, True,
        ", ".join(f"{k}: {r.method if r else 'not reached'}" for k, r in reached.items()),
    )  # fmt: skip
    add(
        f"rotation-number map of {rmap['points']:.0e} points ≤ 10 s", rmap["wall"] / 10.0, 1.0, False,
        f"pl.em_map: {hz.fmt_time(rmap['wall'])}",
    )  # fmt: skip
    return out
