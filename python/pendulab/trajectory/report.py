"""A trajectory in words: the key numbers of its ``repr`` and notebook table, and the few lines of
``Trajectory.summary()`` — span, samples, steps; conservation of E [J] (relative to m|g|l) and J₃
[kg m²/s] (T-2.6), or for the non-conservative models the power balance E(t) − E(0) − ∫P dt [J] of
T-7.1 (trapezoid rule over the saved samples); the string's slack and taut events with the energy lost
in snaps [J]; the constraint residuals (|x| − l)/l and x·v [m²/s]; the error estimates [m, m/s].

The functions take a finished :class:`pendulab.Trajectory` (duck-typed: this module sits below the
class, which calls it).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..display import Row, number, relative_drift
from ..integrators import _method_table
from .tables import param_units


def key_numbers(tr: Any) -> list[Row]:
    """The rows of the ``repr`` and the notebook table: pendulum, method, span, samples, steps, the
    drift of E (conservative runs) and J₃, the largest constraint error."""
    p, e, j = tr.pendulum, tr.energy, tr.j3
    described = f"{p.model}: l = {number(p.length)} m, g = {number(p.g)} m/s², m = {number(p.mass)} kg"
    rows: list[Row] = [
        ("pendulum", described, ""),
        ("method", tr.method, ""),
        ("time span", f"{number(tr.t[0])} … {number(tr.t[-1])}", "s"),
        ("samples", len(tr), ""),
        ("steps", tr.stats.get("steps", 0), ""),
    ]
    if len(tr) and tr.is_conservative and tr.taut is None:
        scale = p.mass * abs(p.g) * p.length if p.g != 0.0 else max(abs(float(e[0])), 1e-300)
        rows.append(("max |E − E₀| / (m|g|l)", number(relative_drift(e, scale), 3), ""))
    if len(tr):
        rows.append(("max |J₃ − J₃₀|", number(relative_drift(j, 1.0), 3), "kg m²/s"))
        on = slice(None) if tr.taut is None else tr.taut
        radius = np.max(np.abs(tr.constraint_error[on]), initial=0.0)
        rows.append(("max ||x| − l| / l", number(radius, 3), ""))
    if tr.interrupted:
        rows.append(("interrupted", "yes (Ctrl-C)", ""))
    return rows


def nth(n: int) -> str:
    """1 → "", 2 → "2nd ", 11 → "11th ", 23 → "23rd " (for "every 2nd step")."""
    if n == 1:
        return ""
    suffix = "th" if n % 100 in (11, 12, 13) else {1: "st", 2: "nd", 3: "rd"}.get(n % 10, "th")
    return f"{n}{suffix} "


def method_line(tr: Any) -> str:
    """The method and how it ran, in words: a fixed-step method's dt [s]; an adaptive one's (DOP853)
    tolerances rtol and atol [m, m/s] (its own step sizes: no dt, unless a first step was given) and
    whether it projects onto TS²; the arithmetic; which samples were kept (every n-th step or the
    requested ``save_at`` times); then any other option as ``key = value``."""
    o = dict(tr.options)
    info = _method_table().get(tr.method)
    adaptive = bool(info and info["adaptive"])
    parts = []
    if adaptive:
        parts.append(f"adaptive steps, rtol = {o.pop('rtol', float('nan')):g}, atol = {o.pop('atol', 0.0):g}")
        first = o.pop("first_step", 0.0)
        first = o.pop("dt", 0.0) or first  # options of 0.1.0: "dt" 0.0 (automatic) or the first step
        if first:
            parts.append(f"first step {first:g} s")
        if "project" in o:
            parts.append("projected onto TS2 after each step" if o.pop("project") else "not projected")
    elif "dt" in o:
        parts.append(f"dt = {o.pop('dt'):g} s")
    if "arithmetic" in o:
        parts.append(f"{o.pop('arithmetic')} arithmetic")
    t0, t_end = o.pop("t0", None), o.pop("t_end", None)
    if len(tr):  # the span line shows t[0] .. t[-1]: the run's own span only if it differs
        start = tr.t[0] if t0 is None else t0
        end = tr.t[-1] if t_end is None else t_end
        if start != tr.t[0] or end != tr.t[-1]:  # save_at inside the run, or interrupted
            parts.append(f"run from t = {start:g} to {end:g} s")
    step = "accepted step" if adaptive else "step"
    times, every = o.pop("save_at_times", None), o.pop("save_every", None)
    if times is not None:
        parts.append(f"saved at {times} requested times")
    elif every is not None or adaptive or "dt" in tr.options:
        parts.append(f"saved every {nth(int(every or 1))}{step}")
    parts += [f"{k} = {v}" for k, v in o.items()]
    return ", ".join([tr.method, *parts])


def summary(tr: Any) -> str:
    """A few lines: span, samples, conservation of E and J₃ (or, for non-conservative models, the
    power balance E(t) − E(0) − ∫P dt of T-7.1 instead of an energy drift), constraint residuals,
    work."""
    e, j = tr.energy, tr.j3
    e_scale = max(abs(e[0]), tr.pendulum.mass * max(abs(tr.pendulum.g), 1e-300) * tr.pendulum.length)
    p, steps = tr.pendulum, tr.stats.get("steps", 0)
    described = f"l = {p.length} m, m = {p.mass} kg, g = {p.g} m/s^2"
    if not p.is_ideal:
        units = param_units(tr.pendulum)
        extras = "".join(
            f", {k} = {v:g}" + (f" {units[k]}" if units.get(k, "1") != "1" else "")
            for k, v in p.extra.items()
        )
        described = f"{p.model} model, {described}{extras}"
    lines = [
        f"pendulum: {described}",
        f"method:   {method_line(tr)}",
        f"span:     t = {tr.t[0]:g} .. {tr.t[-1]:g} s, {len(tr)} samples, {steps} steps"
        + ("  (INTERRUPTED)" if tr.interrupted else ""),
    ]
    if tr.taut is not None:
        kinds = list((tr.events or {}).get("kind", []))
        lost = tr.energy_lost
        drift_e = np.max(np.abs(e + lost - e[0])) / e_scale
        lines += [
            f"string:   went slack {kinds.count('slack')}x, snapped taut {kinds.count('taut')}x "
            f"(restitution {p.extra.get('restitution', 0.0):g}); taut at {np.count_nonzero(tr.taut)} "
            f"of {len(tr)} samples",
            f"energy:   E0 = {e[0]:.12g} J, lost in snaps {lost[-1]:.6g} J, "
            f"max |E + lost - E0| / (m |g| l) = {drift_e:.3e}",
        ]
    elif tr.is_conservative:
        drift_e = np.max(np.abs(e - e[0])) / e_scale
        lines.append(f"energy:   E0 = {e[0]:.12g} J, max |E - E0| / (m |g| l) = {drift_e:.3e}")
    else:
        residual = np.max(np.abs(tr.power_balance_residual))
        work = e[-1] - e[0] - tr.power_balance_residual[-1]
        lines += [
            f"energy:   E0 = {e[0]:.12g} J, E(end) = {e[-1]:.12g} J, work of the non-conservative "
            f"forces {work:.6g} J",
            f"balance:  max |E - E0 - int P dt| = {residual:.3e} J, / (m |g| l) = "
            f"{residual / e_scale:.3e}  (T-7.1, trapezoid rule over the saved samples)",
        ]
    if p.is_ideal:
        lines.append(
            f"J3:       J3_0 = {j[0]:.12g} kg m^2/s, max |J3 - J3_0| = {np.max(np.abs(j - j[0])):.3e}"
        )
    else:
        lines.append(
            f"J3:       J3_0 = {j[0]:.12g} kg m^2/s, J3(end) = {j[-1]:.12g} kg m^2/s, "
            f"max |J3 - J3_0| = {np.max(np.abs(j - j[0])):.3e}"
        )
    on = slice(None) if tr.taut is None else tr.taut
    where = "" if tr.taut is None else " (taut samples)"
    lines += [
        f"sphere:   max ||x| - l| / l = {np.max(np.abs(tr.constraint_error[on]), initial=0.0):.3e}, "
        f"max |x.v| = {np.max(np.abs(tr.tangency[on]), initial=0.0):.3e} m^2/s{where}",
        f"height:   z in [{tr.x[:, 2].min():.6f}, {tr.x[:, 2].max():.6f}] m",
    ]
    for label, err in (("estimate", tr.error_estimate), ("error", tr.error)):
        if err is not None:
            how = err.how + (f", {err.reference['companion']}" if "companion" in err.reference else "")
            lines.append(
                f"{label + ':':<10}max |dx| = {err.max_position:.3e} m "
                f"({err.max_position / p.length:.1e} l), "
                f"max |dv| = {err.max_velocity:.3e} m/s, at t_end {err.position[-1]:.3e} m  ({how})"
            )
    return "\n".join(lines)
