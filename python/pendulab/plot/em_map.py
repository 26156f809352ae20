"""The energy–momentum map as a picture (T-6.4): rotation number W as colour over (J₃ [kg m²/s], E [J]).

Drawn: |W| = |Δφ|/2π on the grid as colour, with white contours every 0.05 (blank outside the image
and on J₃ = 0; W itself has the sign of J₃, and 1/2 < |W| < 1); the conical boundary; the critical
line J₃ = 0 of planar motions from the stable bottom (0, −m|g|l) (filled dot) up through the
unstable top (0, +m|g|l) (open dot); the monodromy loop around the top (red, with its direction),
with W where it starts and the continued W where it ends — they differ by ±1.
"""

from __future__ import annotations

import os
from typing import Any

import numpy as np

from ..figure import new_figure, save_figure
from ..theory.em_map import EMMap


def plot_em_map(
    emmap: EMMap,
    path: str | os.PathLike[str] | None = None,
    *,
    loop_radius: float = 0.5,
    figsize: tuple[float, float] = (7.5, 6.0),
) -> Any:
    """Draws ``emmap`` (from :func:`pendulab.em_map`); saves it atomically to ``path`` if given (.png, .svg,
    .pdf). ``loop_radius`` is the monodromy loop's radius in units of (m l² ω₀, m|g|l). Returns the Figure."""

    fig = new_figure(figsize=figsize, layout="constrained")
    ax = fig.add_subplot()
    w_abs = np.ma.masked_invalid(np.abs(emmap.W))
    mesh = ax.pcolormesh(emmap.J3, emmap.E, w_abs, cmap="viridis", vmin=0.5, vmax=1.0, shading="nearest")
    fig.colorbar(mesh, ax=ax, label="|W| = |Δφ|/2π per z-period (W has the sign of J₃)")
    with np.errstate(invalid="ignore"):
        ax.contour(
            emmap.J3, emmap.E, w_abs, levels=np.arange(0.55, 1.0, 0.05), colors="white", linewidths=0.5
        )

    jb, eb = emmap.boundary
    inside = eb <= emmap.E[-1] + 0.05 * (emmap.E[-1] - emmap.E[0])
    ax.plot(jb[inside], eb[inside], color="black", lw=1.5, label="conical orbits (boundary)")
    eu = emmap.energy_unit
    bottom, top = emmap.critical_values["bottom"], emmap.critical_values["top"]
    ax.plot(
        [0.0, 0.0], [bottom[1], emmap.E[-1]], color="black", lw=1.0, ls="--", label="planar motion, J₃ = 0"
    )
    ax.plot(*bottom, "o", color="black", ms=7, clip_on=False, label=f"stable bottom (0, −mgl = {-eu:.4g} J)")
    ax.plot(*top, "o", mfc="white", mec="black", mew=1.5, ms=8, label=f"unstable top (0, mgl = {eu:.4g} J)")

    lj, le, lw = emmap.loop(loop_radius)
    change = emmap.monodromy(loop_radius)
    ax.plot(lj, le, color="red", lw=2.0, label=f"loop around the top: W changes by {change:+.9f}")
    quarter = len(lj) // 4
    ax.annotate(
        "",
        xy=(lj[quarter + 5], le[quarter + 5]),
        xytext=(lj[quarter], le[quarter]),
        arrowprops={"arrowstyle": "-|>", "color": "red", "lw": 2.0},
    )
    box = {"boxstyle": "round", "fc": "white", "ec": "red", "alpha": 0.9}
    ax.annotate(
        f"start: W = {lw[0]:.4f}", (lj[0], le[0]), xytext=(10, 10), textcoords="offset points", bbox=box
    )
    ax.annotate(
        f"once around: W = {lw[-1]:.4f}",
        (lj[-1], le[-1]),
        xytext=(-10, 10),
        textcoords="offset points",
        ha="right",
        bbox=box,
    )

    p = emmap.pendulum
    ax.set_xlim(emmap.J3[0], emmap.J3[-1])
    ax.set_ylim(emmap.E[0], emmap.E[-1])
    ax.set_xlabel("vertical angular momentum J₃ [kg m²/s]")
    ax.set_ylabel("energy E [J]")
    ax.set_title(f"Energy–momentum map (l = {p.length:g} m, g = {p.g:g} m/s², m = {p.mass:g} kg)")
    fig.legend(loc="outside lower center", ncols=2, fontsize="small")
    if path is not None:
        save_figure(fig, path)
    return fig
