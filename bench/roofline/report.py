"""The roofline plot and the Markdown tables of bench/roofline/run.py's results (rates in units of work
per second, flop/s, B/s). Files are written atomically: a temporary file beside the target, renamed
into place, so a reader never sees half a plot or half a page."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import counts
from counts import Kernel

# the probe's kernel keys → counts.KERNELS keys
RATES = {
    "ensemble": "ensemble_1_thread",
    "rattle": "rattle_steps",
    "rk4_c": "rk4_c_1_thread",
    "dop853": "dop853_steps",
}


def sci(x: float) -> str:
    m, e = f"{x:.2e}".split("e")
    return f"{m} × 10^{int(e)}".replace("^", "").replace(f"10{int(e)}", f"10{_sup(int(e))}")


def _sup(k: int) -> str:
    return str(k).translate(str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹"))


def per_core_points(res: dict[str, Any], kernels: list[Kernel]) -> list[dict[str, Any]]:
    """Each counted kernel's rate per CPU second, GFLOP/s per core and arithmetic intensity."""
    kr = res["kernels"]
    pts = []
    for k in kernels:
        rate = kr[RATES[k.key]]["per_cpu_s"]
        flop = k.flop
        if k.key == "dop853":  # rejected steps: more evaluations per accepted step than 12
            flop = k.flop * kr["dop853_evals_per_step"] / 12.0
        pts.append(
            {
                "kernel": k,
                "rate": rate,
                "wall": kr[RATES[k.key]]["per_wall_s"],
                "flop": flop,
                "gflops": rate * flop / 1e9,
                "intensity": flop / k.bytes,
            }
        )
    return pts


def plot(res: dict[str, Any], pts: list[dict[str, Any]], path: Path, note: str) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    fig, ax = plt.subplots(figsize=(8, 5.2), dpi=110)
    ai = np.logspace(-2, 3.2, 200)
    fma, bw = res["roof"]["fma"], res["roof"]["bandwidth"]
    top = max(v["cpu"] for k, v in fma.items() if k.endswith("x1")) / 1e9
    peaks = sorted((int(k.split("x")[0]), v["cpu"] / 1e9) for k, v in fma.items() if k.endswith("x1"))
    for idx, (width, y) in enumerate(peaks):
        ax.axhline(y, color="0.55", lw=0.8, ls="--")
        # equal roofs (256 and 512 bits on CPUs that split 512-bit operations) labelled apart
        x, ha = (1.2e3, "right") if idx % 2 == 0 else (1.2e1, "right")
        ax.text(x, y * 1.04, f"FMA {width}-bit: {y:.0f}", ha=ha, fontsize=8, color="0.35")
    for level, color in (("L1", "tab:green"), ("L2", "tab:olive"), ("DRAM", "tab:brown")):
        b = bw[f"{level}x1"] / 1e9
        ax.plot(ai, np.minimum(ai * b, top), color=color, lw=1.2, label=f"{level} triad {b:.0f} GB/s")
    for p, m in zip(pts, "os^Dv", strict=False):
        ax.plot(p["intensity"], p["gflops"], m, ms=8, label=f"{p['kernel'].name}: {p['gflops']:.1f} GFLOP/s")
    ax.set(
        xscale="log",
        yscale="log",
        xlabel="arithmetic intensity [flop/B of load/store traffic]",
        ylabel="GFLOP/s per core (per CPU second)",
        ylim=(0.5, top * 2.5),
    )
    ax.set_title("Roofline, one core of this machine\n" + note.replace("; ", "\n", 1), fontsize=8)
    ax.legend(fontsize=7, loc="lower right")
    ax.grid(True, which="both", alpha=0.25)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    tmp = path.with_suffix(".tmp.png")
    fig.savefig(tmp)
    plt.close(fig)
    os.replace(tmp, path)


def tables(res: dict[str, Any], pts: list[dict[str, Any]], note: str) -> list[str]:
    fma, bw = res["roof"]["fma"], res["roof"]["bandwidth"]
    kr = res["kernels"]
    widest = max((k for k in fma if k.endswith("x1")), key=lambda k: int(k.split("x")[0]))
    peak1 = fma[widest]["cpu"]
    lines = [
        note,
        "",
        "**The roof** (best of repeated short runs; GFLOP/s = 10⁹ flop/s, one FMA = 2 flop):",
        "",
    ]
    lines += ["| FMA width | 1 core, per CPU second | 1 core, wall | 2 cores, wall |", "|---|---|---|---|"]
    for w in sorted({int(k.split("x")[0]) for k in fma}):
        a, b = fma[f"{w}x1"], fma.get(f"{w}x2", {"wall": float("nan")})
        lines.append(f"| {w} bits | {a['cpu'] / 1e9:.1f} | {a['wall'] / 1e9:.1f} | {b['wall'] / 1e9:.1f} |")
    lines += ["", "| triad bandwidth | 1 core | 2 cores |", "|---|---|---|"]
    for level in ("L1", "L2", "DRAM"):
        lines.append(f"| {level} | {bw[f'{level}x1'] / 1e9:.0f} GB/s | {bw[f'{level}x2'] / 1e9:.0f} GB/s |")
    lines += [
        "",
        f"**The kernels** (instruction-set level `{kr['isa']}`; flops and bytes counted in "
        "`bench/roofline/counts.py`; share of the one-core peak at the widest width):",
        "",
    ]
    lines += [
        "| kernel | counted flop per unit | B per unit | units per CPU second | GFLOP/s per core | "
        "share of peak | units per wall second |",
        "|---|---|---|---|---|---|---|",
    ]
    for p in pts:
        k = p["kernel"]
        lines.append(
            f"| {k.name} | {p['flop']:.0f} / {k.unit} | {k.bytes:.3g} | {sci(p['rate'])} | "
            f"{p['gflops']:.1f} | {p['gflops'] * 1e9 / peak1:.0%} | {sci(p['wall'])} |"
        )
    e2 = kr["ensemble_2_threads"]
    ens = next(p for p in pts if p["kernel"].key == "ensemble")
    lines.append(
        f"| RATTLE ensemble, 2 threads | {ens['flop']:.0f} / trajectory-step | | {sci(e2['per_cpu_s'])} "
        f"| {e2['per_cpu_s'] * ens['flop'] / 1e9:.1f} | {e2['per_cpu_s'] * ens['flop'] / peak1:.0%} "
        f"| {sci(e2['per_wall_s'])} |"
    )
    for key, label in (("ensemble_1_thread_fused", "1 thread"), ("ensemble_2_threads_fused", "2 threads")):
        if key in kr:  # the opt-in fused arithmetic (arithmetic="fused")
            e, flop = kr[key], ens["flop"] - counts.FUSED_FEWER_FLOP
            lines.append(
                f"| RATTLE ensemble, fused arithmetic, {label} | {flop:.0f} / trajectory-step | "
                f"| {sci(e['per_cpu_s'])} | {e['per_cpu_s'] * flop / 1e9:.1f} "
                f"| {e['per_cpu_s'] * flop / peak1:.0%} | {sci(e['per_wall_s'])} |"
            )
    ex = kr["exact_states"]
    lines.append(
        f"| exact solution, `states_at` | not counted | | {sci(ex['per_cpu_s'])} | | "
        f"| {sci(ex['per_wall_s'])} |"
    )
    lines += [
        "",
        "**Issue 29's targets** (`pl.simulate_ensemble`, 4096 starts, 2 threads, against the C RK4 "
        "ensemble called from the same Python process, interleaved):",
        "",
    ]
    lines += ["| target | measured, wall | measured, CPU time | goal |", "|---|---|---|---|"]
    share = ens["gflops"] * 1e9 / peak1
    lines.append(f"| ensemble kernel, share of the one-core FMA peak | | {share:.0%} | ≥ 30 % |")
    for steps, r in res["api_vs_c"].items():
        default = r.get("default_arithmetic", "unfused")
        lines.append(
            f"| API / C RK4 at {int(steps):,} steps (default arithmetic, here {default}) "
            f"| {r['ratio_wall']:.2f} | {r['ratio_cpu']:.2f} | ≥ 2 |"
        )
        if "ratio_unfused_wall" in r:
            lines.append(
                f'| API / C RK4 at {int(steps):,} steps, `arithmetic="unfused"` '
                f"| {r['ratio_unfused_wall']:.2f} | {r['ratio_unfused_cpu']:.2f} | |"
            )
    return lines


def write_report(
    res: dict[str, Any], kernels: list[Kernel], plot_path: Path, docs: Path, begin: str, end: str
) -> None:
    m = res["meta"]
    note = (
        f"Measured {m['date']} by `bench/roofline/run.py` ({m['seconds']:.0f} s) on {m['cores']} cores "
        f"of {m['cpu']}; "
        f"load average {m['load_start'][0]:.1f} at the start, {m['load_end'][0]:.1f} at the end"
    )
    pts = per_core_points(res, kernels)
    plot(res, pts, plot_path, note.replace("`", ""))
    text = docs.read_text()
    i, j = text.index(begin) + len(begin), text.index(end)
    new = text[:i] + "\n" + "\n".join(tables(res, pts, note + ".")) + "\n" + text[j:]
    tmp = docs.with_suffix(".md.tmp")
    tmp.write_text(new)
    os.replace(tmp, docs)
