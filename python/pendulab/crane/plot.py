"""Crane figures (matplotlib on demand, via :mod:`pendulab.figure`; no pyplot): the sensitivity
curves V(ω/ω₀) of shapers (T-11.1), the sway against time of several runs (shaped vs unshaped, LQR),
and the load's path seen from above. Each returns a ``matplotlib.figure.Figure``; write it with
``pendulab.plot.save_figure(fig, "x.png")``. Axes in SI units.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from ..figure import new_figure
from ..validate import invalid
from ._checks import numbers, real
from .shaper import Shaper, check_shaper, residual_vibration
from .system import CraneRun


def plot_sensitivity(
    shapers: Sequence[Shaper],
    ratio: tuple[float, float] = (0.0, 2.0),
    damping: float = 0.0,
    tolerance: float | None = 0.05,
    labels: Sequence[str] | None = None,
) -> Any:
    """V(ω, ζ) [%] against ω/ω₀ (ω₀ each shaper's design frequency) over ``ratio``, for a mode of
    damping ratio ``damping``; a dashed line at ``tolerance`` (a fraction; None: none)."""
    lo, hi = numbers("ratio", ratio, "(ω/ω₀)", shape=(2,)).tolist()
    if not 0 <= lo < hi:
        raise invalid("ratio", ratio, "(lo, hi) with 0 <= lo < hi (ω/ω₀)")
    if tolerance is not None:
        tolerance = real(
            "tolerance", tolerance, "a fraction in [0, 1] (None: no line)", lambda v: 0 <= v <= 1
        )
    for i, s in enumerate(shapers):
        check_shaper(f"shapers[{i}]", s)
    fig = new_figure(figsize=(7, 4.2))
    ax = fig.add_subplot()
    x = np.linspace(max(lo, 1e-3), hi, 1201)
    for i, s in enumerate(shapers):
        label = labels[i] if labels is not None else s.kind.upper()
        ax.plot(x, 100 * residual_vibration(s, x * s.omega, damping), label=label)
    if tolerance is not None:
        ax.axhline(100 * tolerance, color="grey", ls="--", lw=0.8, label=f"{100 * tolerance:g} %")
    ax.set_xlabel("ω / ω₀ (actual / design frequency)")
    ax.set_ylabel("residual vibration V [%]")
    ax.set_ylim(0, 105)
    ax.grid(alpha=0.3)
    ax.legend()
    ax.set_title("Shaper sensitivity (Singer & Seering 1990)")
    return fig


def plot_sway(runs: Mapping[str, CraneRun], t_marks: Sequence[float] = ()) -> Any:
    """The payload's horizontal offset from the pivot [m] (both components) and its sway angle in the
    x–z plane, atan2(Δx, −Δz) [deg], against time [s], one line per run (label → run); vertical lines
    at ``t_marks`` [s]."""
    marks = numbers("t_marks", t_marks, "s").ravel()
    fig = new_figure(figsize=(8, 5.5))
    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    for label, run in runs.items():
        off = run.offset()
        ax1.plot(run.t, off[:, 0], label=f"{label}: x")
        if np.abs(off[:, 1]).max() > 1e-9:
            ax1.plot(run.t, off[:, 1], ls=":", label=f"{label}: y")
        dz = run.payload[:, 2] - run.pivot[:, 2]
        ax2.plot(run.t, np.degrees(np.arctan2(off[:, 0], -dz)), label=label)
    for t in marks:
        for ax in (ax1, ax2):
            ax.axvline(t, color="grey", lw=0.7, ls="--")
    ax1.set_ylabel("payload − pivot [m]")
    ax2.set_ylabel("sway angle in x–z [deg]")
    ax2.set_xlabel("t [s]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    return fig


def plot_top_view(runs: Mapping[str, CraneRun]) -> Any:
    """The payload's and the pivot's paths seen from above (x, y [m])."""
    fig = new_figure(figsize=(6, 6))
    ax = fig.add_subplot()
    for label, run in runs.items():
        ax.plot(run.payload[:, 0], run.payload[:, 1], label=f"{label}: payload")
        ax.plot(run.pivot[:, 0], run.pivot[:, 1], ls="--", lw=0.8, label=f"{label}: pivot")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_grid(result: Any) -> Any:
    """A :class:`~pendulab.crane.grid.GridResult` as a crane engineer's chart: the residual sway [m]
    against the rope length [m] for each shaper, the line the median and the band the range over
    the payload ratios (log scale)."""
    fig = new_figure(figsize=(7.5, 4.5))
    ax = fig.add_subplot()
    for i, label in enumerate(result.labels):
        s = np.maximum(result.sway[i], 1e-9)
        line = ax.plot(result.ropes, np.median(s, axis=1), label=label.upper())[0]
        ax.fill_between(result.ropes, s.min(axis=1), s.max(axis=1), color=line.get_color(), alpha=0.2)
    ax.set_yscale("log")
    ax.set_xlabel("rope length [m]")
    ax.set_ylabel("residual sway of the payload [m]")
    r = result.ratios
    ax.set_title(f"{result.sway.size} runs: payload/hook mass ratio {r.min():g} … {r.max():g} (bands)")
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    return fig
