"""How a fit's result presents itself: the text report (the fitted parameters ± standard errors in
their SI units, what the data determine instead, the goodness of fit per data kind against the
noise floor, χ², AIC and BIC (T-10.2, T-10.5), what was held fixed, convergence), the rows of the
notebook's HTML table, and the figure (data and fit, the residuals in the data's unit, the parameter
correlations). :class:`pendulab.FitResult` calls these with itself as ``res`` (typed ``Any``:
result.py imports this module, not the reverse); nothing here computes a fit.
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np

from ..display import Row, html_table, number
from .data import KINDS
from .problem import SYSTEMATIC_NAMES

#: Legend names of the data columns per (kind, number of columns).
_COLUMN_NAMES = {
    ("positions", 3): ("x", "y", "z"),
    ("positions", 2): ("x", "z"),
    ("horizontal", 2): ("x", "y"),
    ("angles", 2): ("θ", "φ"),
}


def bound_note(res: Any, name: str) -> str:
    """The note " (near its lower bound b: 95 % interval [a, c])" (or upper) when the value [its unit]
    lies within 2 standard errors of a bound of its allowed range; otherwise the empty string."""
    lo, hi = res.bounds.get(name, (-math.inf, math.inf))
    value, err = res.params[name], res.stderr[name]
    for side, b in (("lower", lo), ("upper", hi)):
        if math.isfinite(b) and abs(value - b) <= max(2.0 * err, 1e-12 * max(abs(b), 1.0)):
            a, c = res.interval(name)
            return f" (near its {side} bound {b:g}: 95 % interval [{a:.4g}, {c:.4g}])"
    return ""


def fit_rows(res: Any) -> list[tuple[str, str, str, str]]:
    """(name, value, "± error" or why not determined, unit) per fitted parameter."""
    rows = []
    for n in res.names:
        value, err = res.params[n], res.stderr[n]
        if res.determined[n]:
            shown = f"± {number(err, 3)}" + bound_note(res, n) + _widened(res, n)
        else:
            shown = "not determined: " + res.reasons.get(n, "by these data")
        rows.append((n, f"{value:.10g}", shown, res.units.get(n, "")))
    return rows


def _widened(res: Any, name: str) -> str:
    """What the error bar of ``name`` was widened by: correlated residuals (goodness.py) and the record's
    blocks (blocks.py: their scale factor S, or that their check was not made, so not widened by it)."""
    blocks = res.blocks
    scale = blocks.scale.get(name, 1.0) if blocks is not None and blocks.made else 1.0
    out = ""
    if res.inflation.get(name, 1.0) / max(scale, 1.0) > 1.05:
        out += f" (x{res.inflation[name] / max(scale, 1.0):.3g} for correlated residuals)"
    if scale > 1.0:
        out += f" (x{scale:.3g} by the record's blocks)"
    if blocks is not None and not blocks.made and name in blocks.scale:
        out += " (block check not made: not widened by it)"
    return out


def report_text(res: Any) -> str:
    """A table of the fitted parameters ± standard errors (SI units), the combinations the data
    determine where single parameters are not, χ², the noise, what was held fixed, convergence."""
    lines = [
        f"fit of the {res.model} pendulum to {len(res.t)} samples "
        f"({', '.join(f'{k} [{KINDS[k]}]' for k in res.residuals)}), t0 = {res.t0:g} s"
    ]
    if res.dropped:
        lines.append(f"  ({res.dropped} rows with NaN were dropped)")
    width = max(len(n) for n in res.names)
    for name, value, err, unit in fit_rows(res):
        if res.determined[name]:
            lines.append(f"  {name.ljust(width)} = {value:>18} {err:<28} {unit}")
        else:  # the unit beside the value, not after the reason's sentence
            lines.append(f"  {name.ljust(width)} = {value:>18} {unit:<28} {err}")
    for label, (value, err) in res.combinations.items():
        lines.append(f"  determined instead: {label} = {value:.10g} ± {number(err, 3)}")
    if res.mirror_blind and {"phi0", "phi_dot0"} & set(res.names):
        lines.append(
            "  the data cannot tell this motion from its mirror image y -> -y "
            "(phi0, phi_dot0 -> -phi0, -phi_dot0): the sign of the sideways motion is a choice"
        )
    if res.mirror_sign is not None:
        lines.append(f"  {res.mirror_sign.line()}")
    noise = ", ".join(f"{k}: {number(s, 3)} {KINDS[k]}" for k, s in res.sigma.items())
    if res.sigma_estimated:
        noise += " (estimated from the residual, so chi2/dof = 1 by construction)"
    lines.append(f"  AIC {res.aic:.6g}, BIC {res.bic:.6g} (pl.compare_fits ranks fits of the same data)")
    if res.body is not None:
        lines += res.body.report_lines()
    if res.planar:
        lines.append(
            "  planar pendulum (a hinge): phi0 = phi_dot0 = 0 held; planar=False fits the spherical one"
        )
    if res.goodness is not None:
        for kind, c in res.goodness.kinds.items():
            lines.append(
                f"  {kind}: residual rms {number(c.rms, 3)} {KINDS[kind]}, noise floor of the data "
                f"{number(c.floor, 3)}, lag-1 autocorrelation {c.lag1:.3f}, runs z {c.runs_z:.2g}"
            )
        lines += [f"  WARNING: {text}" for text in res.goodness.findings]
    lines += [
        f"  chi2 = {res.chi2:.6g} for {res.dof} degrees of freedom "
        f"(chi2/dof = {res.reduced_chi2:.4g}); noise {noise}",
        "  fixed: "
        + ", ".join(
            f"{k} = {number(v)}" + (f" {res.units[k]}" if res.units.get(k, "1") not in ("1", "") else "")
            for k, v in res.fixed.items()
            if k in ("length", "g", "mass") or v != {**SYSTEMATIC_NAMES, **res._defaults}.get(k, 0.0)
        ),
        f"  {'converged' if res.converged else 'NOT converged'}: {res.message} "
        f"({res.evaluations} model runs, {res.starts} start(s), {res.seconds:.3g} s)",
    ]
    return "\n".join(lines)


def report_html(res: Any) -> str:
    """The HTML table of a notebook: the fitted parameters, the determined combinations, χ²/dof."""
    rows: list[Row] = [(n, f"{v} {e}", u) for n, v, e, u in fit_rows(res)]
    rows += [
        (f"{label} (determined)", f"{value:.10g} ± {number(err, 3)}", "")
        for label, (value, err) in res.combinations.items()
    ]
    if res.mirror_sign is not None:
        rows.append(("sign of phi0, phi_dot0", res.mirror_sign.short(), ""))
    rows.append(("χ²/dof", res.reduced_chi2, ""))
    return html_table("Fit", rows, note="res.report(), res.plot(), res.save('fitted.toml')")


def fit_figure(res: Any, path: str | os.PathLike[str] | None = None) -> Any:
    """Data and fit, the residuals, and the parameter correlations; saved atomically to ``path``
    if given. Needs matplotlib. Returns the Figure."""
    from ..figure import new_figure, save_figure

    kinds = list(res.residuals)
    fig = new_figure(figsize=(12.0, 3.2 * len(kinds) + 1.0), layout="constrained")
    grid = fig.add_gridspec(len(kinds), 3, width_ratios=(2.2, 1.6, 1.0))
    pred = res._problem.predictions({**res.fixed, **res.params})
    for row, kind in enumerate(kinds):
        measured = res._problem.obs.values[kind]
        ax = fig.add_subplot(grid[row, 0])
        axr = fig.add_subplot(grid[row, 1], sharex=ax)
        for c in range(measured.shape[1]):
            name = _COLUMN_NAMES.get((kind, measured.shape[1]), (kind,) * 3)[c]
            ax.plot(res.t, measured[:, c], ".", ms=2, alpha=0.5, label=f"{name} measured")
            ax.plot(res.t, pred[kind][:, c], "-", lw=0.9, label=f"{name} fit")
            axr.plot(res.t, res.residuals[kind][:, c], ".", ms=2)
        ax.set_ylabel(f"{kind} [{KINDS[kind]}]")
        axr.set_ylabel(f"residual [{KINDS[kind]}]")
        axr.axhline(0.0, color="0.4", lw=0.8)
        ax.legend(fontsize="x-small", ncols=2)
        if row == len(kinds) - 1:
            ax.set_xlabel("time t [s]")
            axr.set_xlabel("time t [s]")
    axc = fig.add_subplot(grid[:, 2])
    image = axc.imshow(np.nan_to_num(res.correlation, nan=0.0), vmin=-1.0, vmax=1.0, cmap="RdBu_r")
    axc.set_xticks(range(len(res.names)), res.names, rotation=90, fontsize="small")
    axc.set_yticks(range(len(res.names)), res.names, fontsize="small")
    axc.set_title("correlation")
    fig.colorbar(image, ax=axc, shrink=0.6)
    fig.suptitle(f"fit: chi2/dof = {res.reduced_chi2:.3g}")
    if path is not None:
        save_figure(fig, path)
    return fig
