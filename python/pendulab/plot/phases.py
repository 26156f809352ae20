"""The phase split of docs/theory.md T-5.1 as a picture: Δφ = Δφ_dyn + Δφ_geom per z-period [rad].

Left (or alone, for several orbits side by side): bars of the dynamic phase Δφ_dyn = 2 T_z⟨K⟩/J₃, the
geometric phase Δφ_geom = −A/J and their sum, each with its value; a black bar marks Δφ from T-4.5
(elliptic integrals of the third kind), which the sum equals to rounding. Dotted lines mark ±π and
±2π, between which Δφ lies (Puiseux). When the parts dwarf Δφ (small J₃: they grow like 1/J₃ and
cancel), the value axis is symmetric-logarithmic, linear within ±2π.

Right (one orbit): the reduced orbit in the (σ₁, p_z) plane — σ₁ = z/l [1], p_z = σ₂/(1 − σ₁²) [1/s]
with σ₂ = ż/l — run clockwise, its enclosed area A = ∮ p_z dσ₁ [1/s] shaded. With J = J₃/(m l²)
[1/s], the geometric phase is Δφ_geom = −A/J. The orbit and its area are computed by
:func:`pendulab.theory.phase_orbit.phase_orbit`; this module only draws.
"""

from __future__ import annotations

import math
import os
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .._core import InvalidInputError
from ..figure import new_figure, save_figure
from ..theory.exact import ExactSolution, Phases
from ..theory.phase_orbit import PhaseOrbit, phase_orbit

_COLORS = {"dynamic": "tab:blue", "geometric": "tab:orange", "sum": "tab:green"}
_SYMLOG_RATIO = 20.0
"""Use a symmetric-log axis when the largest part exceeds this many times the largest |Δφ|."""
_SPIKE_RATIO = 50.0
"""Use a symmetric-log p_z axis when max |p_z| exceeds this many times its median (a pole skimmed)."""


def _named(
    solutions: ExactSolution | Sequence[ExactSolution] | Mapping[str, ExactSolution],
) -> list[tuple[str, ExactSolution]]:
    if isinstance(solutions, ExactSolution):
        items = [("", solutions)]
    elif isinstance(solutions, Mapping):
        items = [(str(k), v) for k, v in solutions.items()]
    else:
        items = [("", s) for s in solutions]
    if not items:
        raise InvalidInputError("no exact solution to draw the phases of")
    for _, s in items:
        if not isinstance(s, ExactSolution):
            raise InvalidInputError(
                f"expected pendulab.ExactSolution objects (from pl.exact), got {type(s).__name__}"
            )
    out = []
    for name, s in items:
        c = s.constants()
        orbit = f"ε = {c['epsilon']:.4g}, j = {c['j']:.4g}" if "epsilon" in c and "j" in c else s.kind
        out.append((f"{name}\n{orbit}" if name else orbit, s))
    return out


def _decade_ticks(ax: Any, linthresh: float, top: float, negative: bool) -> None:
    """Value ticks 0 and ±10ᵏ above ``linthresh`` up to ``top`` on a symmetric-log axis (the default
    ticks crowd around 0)."""
    decades = 10.0 ** np.arange(math.floor(math.log10(linthresh)) + 1, math.floor(math.log10(top)) + 1)
    ax.set_yticks(np.concatenate([-decades[::-1], [0.0], decades]) if negative else np.append(0.0, decades))


def _bars(ax: Any, named: list[tuple[str, ExactSolution]], phases: list[Phases]) -> None:
    width = 0.26
    parts = [
        ("dynamic", "Δφ_dyn = 2 T_z⟨K⟩/J₃"),
        ("geometric", "Δφ_geom = −A/J"),
        ("sum", "Δφ_dyn + Δφ_geom"),
    ]
    totals = np.array([ph.total for ph in phases])
    biggest = max(max(abs(ph.dynamic), abs(ph.geometric)) for ph in phases)
    symlog = biggest > _SYMLOG_RATIO * float(np.max(np.abs(totals)))
    for k, (attr, label) in enumerate(parts):
        xs = np.arange(len(phases)) + (k - 1) * width
        values = [float(getattr(ph, attr)) for ph in phases]
        ax.bar(xs, values, width * 0.92, color=_COLORS[attr], label=label)
        for x, v in zip(xs, values, strict=True):
            ax.annotate(
                f"{v:.6g}",
                (x, v),
                xytext=(0, 3 if v >= 0 else -3),
                textcoords="offset points",
                ha="center",
                va="bottom" if v >= 0 else "top",
                fontsize="x-small",
                rotation=90 if len(phases) > 3 else 0,
            )
    xs = np.arange(len(phases)) + width
    ax.hlines(totals, xs - width / 2, xs + width / 2, colors="black", lw=2.5, label="Δφ (T-4.5)", zorder=5)
    for sign in sorted({math.copysign(1.0, t) for t in totals}):
        for level, style in ((math.pi, ":"), (2 * math.pi, "-.")):
            ax.axhline(sign * level, color="0.4", lw=0.8, ls=style)
    ax.axhline(0.0, color="black", lw=0.6)
    ax.set_xticks(
        np.arange(len(phases)),
        [
            f"{name}\nW = {ph.total / (2 * math.pi):.6f}\nΔφ − sum = {ph.difference:.1e} rad"
            for (name, _), ph in zip(named, phases, strict=True)
        ],
        fontsize="small",
    )
    ax.set_xlim(-0.6, len(phases) - 0.4)
    if symlog:
        ax.set_yscale("symlog", linthresh=2 * math.pi, linscale=3.0)
        ax.set_ylabel("phase per z-period [rad] (symmetric log, linear within ±2π)")
        lim = 500.0 * biggest  # room for the values
        negative = any(min(ph.dynamic, ph.geometric, ph.total) < 0 for ph in phases)
        _decade_ticks(ax, 2 * math.pi, lim, negative)
        ax.set_ylim(-lim if negative else 0.0, lim)
    else:
        ax.set_ylabel("phase per z-period [rad]")
        ax.use_sticky_edges = False  # room below 0 for the values, as above
        ax.margins(y=0.12)
    ax.set_title("T-5.1: Δφ = Δφ_dyn + Δφ_geom   (dotted ±π, dash-dotted ±2π)")
    ax.legend(loc="best", fontsize="small")


def _orbit(ax: Any, orbit: PhaseOrbit) -> None:
    s1, pz, j, area, phases = orbit.sigma1, orbit.p_z, orbit.j, orbit.area, orbit.phases
    if orbit.conical:  # constant height: the reduced orbit is a point and encloses nothing
        ax.plot(s1[0], 0.0, "o", color="black", ms=7, label=f"conical orbit: a point, A = {area:.3g} 1/s")
        ax.set_xlim(s1[0] - 0.1, s1[0] + 0.1)
        ax.set_ylim(-1.0, 1.0)
    else:
        ax.fill(s1, pz, color=_COLORS["geometric"], alpha=0.35, lw=0, label=f"A = ∮ p_z dσ₁ = {area:.6g} 1/s")
        ax.plot(s1, pz, color="black", lw=1.2, label="reduced orbit (one z-period, clockwise)")
        ax.plot(s1[0], pz[0], "o", color="tab:green", ms=6, label="t = 0")
        quarter = len(s1) // 4
        step = max(len(s1) // 100, 1)
        for i in (quarter, 3 * quarter):
            ax.annotate(
                "",
                xy=(s1[i + step], pz[i + step]),
                xytext=(s1[i], pz[i]),
                arrowprops={"arrowstyle": "-|>", "color": "black", "lw": 1.2},
            )
        ax.margins(x=0.08, y=0.15)
    ax.axhline(0.0, color="0.5", lw=0.6)
    ax.text(
        0.03,
        0.04,
        f"J = J₃/(m l²) = {j:.6g} 1/s\nΔφ_geom = −A/J = {phases.geometric:.9g} rad",
        transform=ax.transAxes,
        fontsize="small",
        bbox={"boxstyle": "round", "fc": "white", "ec": "0.6", "alpha": 0.9},
    )
    ax.set_xlabel("σ₁ = z/l [1]")
    typical = float(np.median(np.abs(pz)))
    if typical > 0.0 and float(np.max(np.abs(pz))) > _SPIKE_RATIO * typical:
        # an orbit that skims a pole: p_z spikes there, so show it on a symmetric-log axis
        ax.set_yscale("symlog", linthresh=typical)
        _decade_ticks(ax, typical, float(np.max(np.abs(pz))), True)
        ax.set_ylabel(f"p_z = σ₂/(1 − σ₁²) [1/s]   (symmetric log, linear within ±{typical:.2g})")
    else:
        ax.set_ylabel("p_z = σ₂/(1 − σ₁²) [1/s]   (σ₂ = ż/l)")
    ax.set_title("reduced orbit in the (z, p_z) plane")
    ax.legend(loc="upper right", fontsize="small")


def plot_phases(
    solutions: ExactSolution | Sequence[ExactSolution] | Mapping[str, ExactSolution],
    path: str | os.PathLike[str] | None = None,
    *,
    orbit: bool | None = None,
    samples: int = 4001,
    figsize: tuple[float, float] | None = None,
) -> Any:
    """Draws the phase split (T-5.1) of one orbit or of several side by side; saves atomically to
    ``path`` if given (.png, .svg, .pdf). Returns the Figure.

    ``solutions``: an :class:`pendulab.ExactSolution`, a sequence of them, or a mapping name → solution
    (the names label the groups, e.g. scenario names). Each must have J₃ ≠ 0 and g ≠ 0 (kinds
    ``generic``, ``conical``); otherwise :meth:`ExactSolution.phases` raises ``InvalidInputError``.
    ``orbit``: add the reduced orbit in the (σ₁, p_z) plane with its area shaded, drawn from
    ``samples`` exact states over one z-period (default: yes for one solution; it needs exactly one).
    Default sizes: 13 × 5.5 in with the orbit, else (2.6 n + 3.5) × 5.5 in for n orbits.
    """

    named = _named(solutions)
    phases = [s.phases() for _, s in named]
    if orbit is None:
        orbit = len(named) == 1
    if orbit and len(named) != 1:
        raise InvalidInputError(
            f"the reduced-orbit panel is drawn for one solution, not {len(named)}; pass orbit=False"
        )
    if samples < 16:
        raise InvalidInputError(f"samples = {samples} must be at least 16")
    reduced = phase_orbit(named[0][1], samples, phases[0]) if orbit else None
    if figsize is None:
        figsize = (13.0, 5.5) if orbit else (2.6 * len(named) + 3.5, 5.5)

    fig = new_figure(figsize=figsize, layout="constrained")
    if reduced is not None:
        ax_bars, ax_orbit = fig.subplots(1, 2, width_ratios=(1.0, 1.15))
        _orbit(ax_orbit, reduced)
    else:
        ax_bars = fig.add_subplot()
    _bars(ax_bars, named, phases)
    p = named[0][1].pendulum
    if all(s.pendulum.params() == p.params() for _, s in named):
        fig.suptitle(
            f"Azimuthal advance per z-period and its split: l = {p.length:g} m, g = {p.g:g} m/s², "
            f"m = {p.mass:g} kg"
        )
    else:
        fig.suptitle("Azimuthal advance per z-period and its split")
    if path is not None:
        save_figure(fig, path)
    return fig
