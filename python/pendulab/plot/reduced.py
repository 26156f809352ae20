"""Holm's Figure 2 (docs/theory.md T-3.3): the reduced motion in (σ₁, σ₂, σ₃) space.

σ₁ = z/l [1], σ₂ = ż/l [1/s], σ₃ = |v|²/l² [1/s²] (see :mod:`pendulab.reduce`). Drawn: the orbit
manifold C = σ₃(1 − σ₁²) − σ₂² − J² = 0 of the orbit's J = σ₆ = J₃/(m l²), a surface
σ₃ = (σ₂² + J²)/(1 − σ₁²); the energy plane H = ½σ₃ + (g/l)σ₁ = E/(m l²); and the orbit, which runs
along their intersection (drawn on top). Both surfaces are cut off at 1.4 times the orbit's largest σ₃.
The surfaces are computed by :func:`pendulab.theory.reduce.reduced_surfaces`; this module only draws.
"""

from __future__ import annotations

import os
from typing import Any

from ..figure import new_figure, save_figure
from ..theory.reduce import Reduced, reduced_surfaces
from ..trajectory import Trajectory


def plot_reduced(
    data: Trajectory | Reduced,
    path: str | os.PathLike[str] | None = None,
    *,
    figsize: tuple[float, float] = (7.5, 6.5),
    resolution: int = 60,
) -> Any:
    """Draws the surface C = 0, the plane H = const and the orbit of ``data`` (a trajectory, or its
    :func:`pendulab.reduce`); saves atomically to ``path`` if given (.png, .svg, .pdf). Returns the Figure."""

    pic = reduced_surfaces(data, resolution)
    red, a, b, cap, j, h = pic.reduced, pic.sigma1, pic.sigma2, pic.cap, pic.j, pic.h
    s1, s2, s3 = red.sigma[:, 0], red.sigma[:, 1], red.sigma[:, 2]

    fig = new_figure(figsize=figsize, layout="constrained")
    # Draw in the order given (mplot3d's depth sorting of whole artists would hide the orbit).
    ax = fig.add_subplot(projection="3d", computed_zorder=False)
    ax.plot_surface(a, b, pic.surface, color="tab:blue", alpha=0.35, linewidth=0, antialiased=True)
    ax.plot_surface(a, b, pic.plane, color="tab:orange", alpha=0.35, linewidth=0, antialiased=True)
    ax.plot(s1, s2, s3, color="black", lw=2.5, label="orbit (intersection)", zorder=10)
    # proxies for the legend (surfaces have none)
    ax.plot([], [], color="tab:blue", lw=6, alpha=0.5, label=f"C = 0 for J₃/(m l²) = {j:.4g} 1/s")
    ax.plot([], [], color="tab:orange", lw=6, alpha=0.5, label=f"H = ½σ₃ + (g/l)σ₁ = {h:.4g} 1/s²")
    ax.set_xlabel("σ₁ = z/l [1]")
    ax.set_ylabel("σ₂ = ż/l [1/s]")
    ax.set_zlabel("σ₃ = |v|²/l² [1/s²]")
    ax.set_zlim(0.0, cap)
    p = red.pendulum
    ax.set_title(f"Reduced space (Holm, Fig. 2): l = {p.length:g} m, g = {p.g:g} m/s²")
    ax.legend(loc="upper left", fontsize="small")
    if path is not None:
        save_figure(fig, path)
    return fig
