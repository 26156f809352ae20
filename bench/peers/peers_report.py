"""The peers benchmark's report (bench/peers/run.py): the work-precision plot (wall time [s] against
the final position error |x − x_ref|/l, one panel per case; docs/img/peers_work_precision.png) and
the Markdown of the "Against peers" section of docs/performance.md (targets, step rates [steps/s],
ensembles [trajectory-steps/s], ``pl.simulate_ensemble`` against the C RK4 ensemble [s], the best
setting per error level).
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import harness as hz
from peers_cases import FLOOR, T_END, TOL_HI, TOL_LO, Case
from peers_methods import C_FLAGS
from peers_targets import STEPS_SHOWN, best_of


def plot(runs: list[hz.Run], cases: list[Case], path: Path) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = list(dict.fromkeys(r.method for r in runs))
    fig, axes = plt.subplots(1, len(cases), figsize=(6.2 * len(cases), 6.2), squeeze=False)
    cmap = plt.get_cmap("tab20")
    for ax, case in zip(axes[0], cases, strict=True):
        for i, name in enumerate(names):
            # in scan order (coarse to fine), as work-precision diagrams are drawn
            rs = [r for r in runs if r.method == name and r.case == case.name and r.ok]
            if not rs:
                continue
            style = "-" if name.startswith("pendulab") else "--"
            marker = "*" if name == "pendulab exact" else "o"
            ax.loglog(
                [r.wall for r in rs], [max(r.error, 1e-17) for r in rs], style, marker=marker,
                ms=9 if marker == "*" else 3, color=cmap(i % 20), label=name,
            )  # fmt: skip
        for lvl in (TOL_LO, TOL_HI):
            ax.axhline(lvl, color="0.6", lw=0.8, ls=":")
        ax.set_title(f"{case.name}, t = {T_END:g} s")
        ax.set_xlabel("wall time [s] (median)")
        ax.set_ylabel("final position error |x − x_ref| / l")
        ax.set_ylim(1e-16, 10)
        ax.grid(True, which="major", alpha=0.3)
    handles, labels = axes[0][0].get_legend_handles_labels()
    fig.legend(handles, labels, loc="lower center", ncol=9, fontsize=8, frameon=False)
    fig.suptitle("Work–precision: Pendulab (solid) vs peers (dashed); 2-core machine, loaded")
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=110)
    plt.close(fig)


def api_vs_c_table(avc: dict[str, Any]) -> list[str]:
    """Issue 29's ratio: the C RK4 ensemble's wall time over ``pl.simulate_ensemble``'s, per step count."""
    head = "#### `pl.simulate_ensemble` against the C RK4 ensemble (issue 29)"
    if not avc.get("steps"):
        return [head, "", f"Not measured: {avc.get('skipped', 'not run')}.", ""]
    rows = [
        [
            STEPS_SHOWN.get(k, k), r["repeats"], hz.fmt_time(r["api_wall"]), hz.fmt_time(r["c_wall"]),
            f"{r['ratio']:.3g}", f"{r['ratio_cpu']:.3g}",
        ]
        for k, r in avc["steps"].items()
    ]  # fmt: skip
    cols = ["steps", "best of", "`pl.simulate_ensemble`", "C RK4 ensemble", "C / API (wall; goal ≥ 2)"]
    return [
        head,
        "",
        hz.markdown_table([*cols, "C / API (CPU)"], rows),
        "",
        f"{avc['n']} starts, dt = {avc['dt'] * 1e3:g} ms, {avc['threads']} threads (RAYON_NUM_THREADS = "
        "OMP_NUM_THREADS), final states only, in one child process: `pl.simulate_ensemble` as a user "
        f"calls it (its defaults: arithmetic {avc['arithmetic']}, from the result's metadata) and the C "
        "RK4 ensemble, one warm-up call each, then interleaved (API, C, API, C, …); least wall time [s] "
        f"per side. Load average {avc['load_start']:.1f} at the start, {avc['load_end']:.1f} at the end.",
        "",
        *api_vs_c_variants_table(avc.get("variants", {})),
    ]


def api_vs_c_variants_table(variants: dict[str, Any]) -> list[str]:
    """Issue 29, item 3: the same ratio for per-trajectory parameters and damping."""
    if not variants:
        return []

    def ratio(r: dict[str, Any]) -> str:
        return f"{r['ratio']:.3g}"

    rows = [
        [name, STEPS_SHOWN.get(k, k), hz.fmt_time(r["api_wall"]), hz.fmt_time(r["c_wall"]), ratio(r)]
        for name, by_steps in variants.items()
        for k, r in by_steps.items()
    ]
    cols = ["form", "steps", "`pl.simulate_ensemble`", "C RK4 ensemble", "C / API (wall; goal ≥ 2)"]
    return [
        "The same, with per-trajectory parameters and damping (issue 29, item 3; the starts scaled onto "
        "each trajectory's sphere; the C ensemble runs the same lengths and g and has no damping, so a "
        "damped API call does 6 multiplications a trajectory-step more than the C side is asked to):",
        "",
        hz.markdown_table(cols, rows),
        "",
    ]


def markdown(
    runs: list[hz.Run], cases: list[Case], rates: dict[str, Any], ens: dict[str, Any], rmap: dict[str, Any],
    tgt: list[dict[str, Any]], meta: dict[str, Any],
) -> str:  # fmt: skip
    v = meta["versions"]
    # the benchmark itself keeps one core busy (load ≈ 1); the wheel build just before adds to the start
    busy = max(meta["load_start"], meta["load_end"]) >= 1.6
    setting = "**while other work was running on it**" if busy else "with nothing else running on it"
    caveat = "absolute figures are pessimistic and noisy, and only the ratios" if busy else "the ratios"
    lines = [
        f"Measured {meta['date']} by `make bench-peers` (`bench/peers/run.py`, "
        f"{meta['wall_total']:.0f} s) on the 2-core machine "
        f"({meta.get('machine', {}).get('cpu', 'CPU not recorded')}) "
        f"{setting} (load average "
        f"{meta['load_start']:.1f} at the start, {meta['load_end']:.1f} at the end; the benchmark itself "
        f"accounts for about 1): {caveat}, all taken within this one run, are what carries over to other "
        "machines. Every time is a median of repeated runs (5 for fast runs, at least 3, a "
        "single run beyond 1.5 s).",
        "",
        f"Peers: SciPy {v.get('scipy')}, numba {v.get('numba')}, MuJoCo {v.get('mujoco')}, "
        f"JAX {v.get('jax')} + Diffrax {v.get('diffrax')} (CPU, float64), gcc {v.get('gcc')} "
        f"(`{' '.join(C_FLAGS[:3])}`), numpy {v.get('numpy')}, all in their own virtual environment "
        f"bench/peers/.venv with Pendulab {v.get('pendulab')} installed there from a release wheel of "
        "this checkout (`maturin build --release`, "
        + (
            f"RUSTFLAGS=`{meta['rustflags']}`)."
            if meta.get("rustflags")
            else "the portable build: baseline x86-64, the hot loops dispatched to AVX2/AVX-512 at run time)."
        )
        + "".join(f" **{k}: skipped, {why}.**" for k, why in meta["skipped"].items() if why),
        "",
        "Cases (examples/scenarios/, l = 1 m, g = 9.81 m/s²) to t = 100 s. Reference: `pl.exact` at "
        "t = 100 s; its difference from the mpmath golden data (max(|Δx|/l, |Δv|/(lω₀+|v|))) is "
        + ", ".join(f"{c.name} {c.exact_vs_golden:.1e} (conditioning floor {c.floor:.1e})" for c in cases)
        + ". Error = final position error |x − x_ref|/l. The peers integrate the Cartesian ODE T-2.4 "
        "(ẋ = v, v̇ = −g e₃ + λx, λ = (g z − |v|²)/l²) without projection — the angle ODE is singular "
        "at the poles, which the over-the-top case crosses; MuJoCo integrates its ball joint's "
        "quaternion. Each method's step count (fixed-step: dt = 100 s/n, n up by √2) or rtol "
        "(adaptive: 1e-3 … 1e-14 by √10, atol = rtol/100) is scanned until the error stops improving "
        "(once below 1e-9), "
        f"drops below {FLOOR:.0e}, or one run exceeds {meta['cap']:g} s; a tolerance is reached by the "
        "cheapest setting that reaches it.",
        "",
        "### Targets of issues 5 and 29",
        "",
    ]
    rows = []
    for t in tgt:
        val = t["value"]
        if val is None:
            shown = "—"
        elif "robustness" in t["target"]:
            shown = f"{round(val * len(cases))}/{len(cases)} cases"
        elif "map" in t["target"]:
            shown = f"{val * 10:.3g} s"
        else:
            shown = f"{val:.3g}" if math.isfinite(val) else "∞"
        goal = ("≥ " if t["higher_is_better"] else "≤ ") + f"{t['goal']:g}"
        if "robustness" in t["target"]:
            goal = "all"
        elif "map" in t["target"]:
            goal = "≤ 10 s"
        elif "every level" in t["target"]:
            goal = "< 1"
        rows.append([t["target"], shown, goal, f"**{t['verdict']}**", t["detail"]])
    lines += [hz.markdown_table(["target", "measured (ratio)", "goal", "verdict", "detail"], rows), ""]

    lines += ["### Step rates (rosette, dt = 1 ms, no saving)", ""]
    base = rates.get("C rk4", {}).get("steps_per_s")
    listed = {k: r for k, r in rates.items() if "steps_per_s" in r}
    rrows = [
        [f"`{k}`", hz.fmt_sci(r["steps_per_s"]), f"{r['steps_per_s'] / base:.3g}" if base else "—"]
        for k, r in sorted(listed.items(), key=lambda kv: -kv[1]["steps_per_s"])
    ]
    lines += [hz.markdown_table(["method", "steps/s", "relative to the C RK4 loop"], rrows), ""]
    if "_overhead" in rates:
        oh = rates["_overhead"]
        lines += [
            f"Fixed cost of one call (median of 301): `pl.simulate` of one RATTLE step "
            f"{hz.fmt_time(oh['simulate_one_step'])}, `pl.Stepper(...)` + `step(1)` "
            f"{hz.fmt_time(oh['stepper_one_step'])}; it matters only for runs of less than a millisecond "
            "(the coarsest error levels below).",
            "",
        ]

    pe, ce = ens["pendulab"], ens.get("C rk4", {})
    lines += [
        f"### Ensembles ({ens['n']} rosette-like starts × {ens['steps']} steps, dt = 1 ms, "
        "final states only)",
        "",
    ]
    erows = []
    for th in (1, 2):
        p = pe.get(th, {})
        c = ce.get(th, {})
        erows.append(
            [
                th,
                hz.fmt_sci(p.get("rate")),
                hz.fmt_sci(p.get("api_rate")),
                hz.fmt_sci(c.get("rate")),
                f"{p['rate'] / c['rate']:.3g}" if p and c else "—",
            ]
        )
    lines += [
        hz.markdown_table(
            [
                "threads",
                "Pendulab RATTLE kernel (`_core.EnsembleRun`)",
                "`pl.simulate_ensemble`",
                "C RK4 ensemble (OpenMP, simd)",
                "Pendulab / C",
            ],
            erows,
        ),
        "",
        "Trajectory-steps/s. Pendulab's thread count is set with RAYON_NUM_THREADS in a child process. "
        "`pl.simulate_ensemble` polls the background run every 50 ms, so on runs this short its wall time "
        "includes up to 50 ms of waiting; the kernel column times the same run without the poll, with "
        f'the arithmetic `pl.simulate_ensemble` uses by default on this CPU (`arithmetic="auto"` → '
        f"{ens.get('arithmetic', '—')}).",
        "",
    ]
    lines += api_vs_c_table(ens.get("api_vs_c", {}))

    for case in cases:
        lines += [f"### {case.name}: cheapest settings reaching 1e-6 and 1e-10 at t = 100 s", ""]
        crow = []
        names = list(dict.fromkeys(r.method for r in runs if r.case == case.name))
        for name in names:
            rs = [r for r in runs if r.case == case.name and r.method == name]
            lo, hi = hz.cheapest(rs, TOL_LO), hz.cheapest(rs, TOL_HI)
            ok = [r for r in rs if r.ok]
            best = min(ok, key=lambda r: r.error) if ok else None
            shown = hi or best
            fails = [r for r in rs if r.failed]

            def setting(r: hz.Run | None) -> str:
                if r is None or r.setting_kind == "none":
                    return ""
                if r.setting_kind == "rtol":
                    return f" (rtol {r.setting:.0e})"
                return f" (dt {T_END / r.setting:.2g} s)"

            crow.append(
                [
                    name,
                    (hz.fmt_time(lo.wall) + setting(lo)) if lo else "not reached",
                    (hz.fmt_time(hi.wall) + setting(hi)) if hi else "not reached",
                    hz.fmt_err(best.error) if best else ("failed: " + fails[0].failed[:50] if fails else "—"),
                    hz.fmt_sci(shown.steps / shown.wall) if shown and shown.steps else "—",
                    hz.fmt_err(shown.energy_drift) if shown else "—",
                    hz.fmt_err(shown.constraint_drift) if shown else "—",
                ]
            )
        lines += [
            hz.markdown_table(
                [
                    "method",
                    "time to ≤ 1e-6",
                    "time to ≤ 1e-10",
                    "smallest error",
                    "steps/s",
                    "energy drift",
                    "constraint drift [m]",
                ],
                crow,
            ),
            "",
        ]
    lines += [
        "Steps/s, energy drift |E(100 s) − E(0)|/(m g l) and constraint drift ||x(100 s)| − l| are "
        "those of the setting that reaches 1e-10 (or, where none does, of the most accurate one). "
        "`pendulab exact` is the elliptic-function solution (set-up and one state, median of 101 "
        "calls); its error column is against the mpmath golden data.",
        "",
        "### Work–precision (rosette): least wall time to reach each error level",
        "",
    ]
    wrow = []
    for lvl in hz.LEVELS:
        b = best_of(runs, "rosette", lvl, "pendulab")
        pb = best_of(runs, "rosette", lvl, "peers")
        wrow.append(
            [
                f"{lvl:.0e}",
                f"{b.method} {hz.fmt_time(b.wall)}" if b else "not reached",
                f"{pb.method} {hz.fmt_time(pb.wall)}" if pb else "not reached",
                f"{pb.wall / b.wall:.3g}" if b and pb else "—",
            ]
        )
    lines += [
        hz.markdown_table(["error ≤", "Pendulab's best", "best peer", "peer / Pendulab time"], wrow),
        "",
        "![work-precision](img/peers_work_precision.png)",
        "",
        f"Rotation-number map: `pl.em_map(p, grid=({math.isqrt(rmap['points'])}, "
        f"{math.isqrt(rmap['points'])}))`, {rmap['points']:,} points from the exact solution's "
        f"formulas (T-4.5), {hz.fmt_time(rmap['wall'])} (median of {rmap['repeats']}). Machine-readable "
        "results: bench/peers/results/peers.json (every run) and peers_runs.csv.",
    ]
    return "\n".join(lines)
