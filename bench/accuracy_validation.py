"""Estimated against true global error on the hard 40-digit cases (issue 17, item 4).

For every case of ``testdata/hard_cases.json`` and every stored time t ≤ ``--t-max`` [s]: DOP853 at
rtol 1e-12 (atol 1e-14 l) and RATTLE8 at dt = 0.05/ω (ω = max(√(|g|/l), |v₀|/l)) with
``error_estimate=True``; the true error is |x − x_golden| [m]. Writes ``docs/img/error_estimates.png``
(estimate against truth, log-log, the float64 floor marked) and prints the figures quoted in
docs/integrators.md: how many samples lie above 100× the floor (``floor_normwise`` × l), how many of
those have the estimate within a factor 10 (and 2) of the truth, and ``accuracy=1e-8`` met or not per
case (to t = min(100 s, t-max)).

Run: ``.venv/bin/python bench/accuracy_validation.py --t-max 1000`` (minutes; 10⁴ s: much longer).
"""

from __future__ import annotations

import argparse
import json
import math
from pathlib import Path

import numpy as np
import pendulab as pl

REPO = Path(__file__).resolve().parents[1]
PLOT = REPO / "docs" / "img" / "error_estimates.png"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--t-max", type=float, default=1000.0)
    args = ap.parse_args()
    cases = json.loads((REPO / "testdata" / "hard_cases.json").read_text())["cases"]
    points: dict[str, list[tuple[float, float, float]]] = {"dop853": [], "rattle8": []}
    met, total, missed = 0, 0, []
    for case in cases:
        ell = case["length"]
        p = pl.Pendulum(length=ell, mass=case["mass"], g=case["g"])
        s0 = p.state(np.array(case["x0"]), np.array(case["v0"]))
        omega = max(math.sqrt(abs(case["g"]) / ell), float(np.linalg.norm(case["v0"])) / ell)
        for method in points:
            samples = [s for s in case["samples"] if s["t"] <= args.t_max]
            if method == "rattle8":
                samples = [s for s in samples if s["t"] * omega / 0.05 <= 2e7]  # bound the work
            times = [s["t"] for s in samples]
            kw = {"rtol": 1e-12, "atol": 1e-14 * ell} if method == "dop853" else {"dt": 0.05 / omega}
            tr = pl.simulate(p, s0, times[-1], method=method, save_at=times, error_estimate=True, **kw)
            for s in samples:
                i = int(np.argmin(np.abs(tr.t - s["t"])))
                true = float(np.linalg.norm(tr.x[i] - np.array([float(c) for c in s["x_str"]])))
                points[method].append((true, float(tr.error_estimate.position[i]), s["floor_normwise"] * ell))
        times = [s["t"] for s in case["samples"] if s["t"] <= min(100.0, args.t_max)]
        total += 1
        try:
            tr = pl.simulate(p, s0, times[-1], accuracy=1e-8, save_at=times)
            worst = max(
                float(
                    np.linalg.norm(
                        tr.x[int(np.argmin(np.abs(tr.t - s["t"])))] - np.array([float(c) for c in s["x_str"]])
                    )
                )
                for s in case["samples"]
                if s["t"] <= times[-1]
            )
            ok = worst <= 1e-8 * ell
        except pl.InvalidInputError as e:
            ok, worst = False, math.nan
            print(f"{case['name']}: accuracy=1e-8 refused: {e}")
        met += ok
        if not ok:
            missed.append(case["name"])
        print(
            f"{case['name']:28} accuracy=1e-8: true {worst / ell:.2e} l {'met' if ok else 'MISSED'}",
            flush=True,
        )
    for method, pts in points.items():
        arr = np.array(pts)
        above = arr[arr[:, 0] > 100 * arr[:, 2]]
        r = above[:, 1] / above[:, 0]
        print(
            f"{method}: {len(arr)} samples, {len(above)} above 100x floor; estimate within 10x: "
            f"{np.sum((r >= 0.1) & (r <= 10))}, within 2x: {np.sum((r >= 0.5) & (r <= 2))}; "
            f"ratio range {r.min():.2f} .. {r.max():.2f}; true error range {above[:, 0].min():.1e} .. "
            f"{above[:, 0].max():.1e} m"
        )
    print(f"accuracy=1e-8 met in {met} of {total} cases; missed: {missed}")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(6.5, 6))
    for (method, pts), marker in zip(points.items(), ("o", "^"), strict=True):
        arr = np.array(pts)
        above = arr[:, 0] > 100 * arr[:, 2]
        ax.loglog(
            arr[above, 0], arr[above, 1], marker, ms=5, alpha=0.7, label=f"{method} (true > 100× floor)"
        )
        ax.loglog(
            arr[~above, 0].clip(1e-18),
            arr[~above, 1].clip(1e-18),
            marker,
            ms=4,
            mfc="none",
            alpha=0.4,
            label=f"{method} (at the floor)",
        )
    lo, hi = 1e-17, 10.0
    ax.plot([lo, hi], [lo, hi], "k-", lw=1)
    ax.plot([lo, hi], [10 * lo, 10 * hi], "k:", lw=1)
    ax.plot([lo, hi], [lo / 10, hi / 10], "k:", lw=1, label="factor 10")
    ax.set_xlabel("true error |x − x_golden| [m]")
    ax.set_ylabel("estimated error [m]")
    ax.set_title(f"{len(cases)} hard cases, t ≤ {args.t_max:g} s")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(PLOT, dpi=110)
    print(f"wrote {PLOT}")


if __name__ == "__main__":
    main()
