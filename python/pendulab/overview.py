"""The one-call overview behind ``Trajectory.plot()`` and ``ExactSolution.plot()``: what a run did
and how well it kept its invariants, in one figure.

- left: the path x(t) [m] on a faint wire sphere of radius l (start: dot, end: square);
- top right: the height z(t) [m], with the turning heights z₁ ≤ z₂ of the exact solution (T-4.2)
  as dashed lines when given;
- bottom right: the drift of the invariants — for a conservative model |E − E₀|/(m|g|l) and, when the
  model is axisymmetric, |J₃ − J₃₀|/(m l² ω₀) on a log scale with the float64 floor ε = 2.2e-16
  marked; for a model that gains or loses energy, E(t) [J] itself.

Duck-typed on the trajectory (``t``, ``x``, ``energy``, ``j3``, ``pendulum``, ``method``,
``is_conservative``) so that the trunk can call it without importing upward.
"""

from __future__ import annotations

import math
import os
from collections.abc import Sequence
from typing import Any

import numpy as np
import numpy.typing as npt

from ._core import InvalidInputError
from .figure import new_figure, save_figure

FLOAT64_EPS = float(np.finfo(np.float64).eps)
_TINY = 1e-18  # drawn floor of a log axis: exact zeros would vanish from it


def _thin(n: int, max_points: int) -> npt.NDArray[np.intp]:
    if n <= max_points:
        return np.arange(n)
    return np.rint(np.linspace(0.0, n - 1.0, max_points)).astype(np.intp)


def _sphere(ax: Any, ell: float, x: npt.NDArray[np.float64]) -> None:
    u = np.linspace(0.0, 2.0 * math.pi, 25)
    for zc in np.linspace(-0.8, 0.8, 5) * ell:
        r = math.sqrt(ell * ell - zc * zc)
        ax.plot(r * np.cos(u), r * np.sin(u), np.full_like(u, zc), color="0.85", lw=0.5)
    w = np.linspace(0.0, math.pi, 25)
    for phi in np.linspace(0.0, math.pi, 4, endpoint=False):
        ax.plot(
            ell * np.sin(w) * math.cos(phi),
            ell * np.sin(w) * math.sin(phi),
            ell * np.cos(w),
            color="0.85",
            lw=0.5,
        )
    ax.plot(x[:, 0], x[:, 1], x[:, 2], color="tab:blue", lw=0.7)
    ax.scatter(*x[0], color="tab:green", s=25, label="start", depthshade=False)
    ax.scatter(*x[-1], color="tab:red", marker="s", s=25, label="end", depthshade=False)
    ax.plot([0.0], [0.0], [0.0], "k+", ms=8)
    ax.set_xlim(-ell, ell)
    ax.set_ylim(-ell, ell)
    ax.set_zlim(-ell, ell)
    ax.set_box_aspect((1.0, 1.0, 1.0))
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.legend(loc="upper left", fontsize="small")


def plot_overview(
    traj: Any,
    path: str | os.PathLike[str] | None = None,
    *,
    turning_heights: Sequence[float] | None = None,
    title: str | None = None,
    max_points: int = 20_000,
    figsize: tuple[float, float] = (12.0, 6.0),
) -> Any:
    """The overview figure of a trajectory (see the module doc); saved atomically to ``path`` if given
    (.png, .svg, .pdf). ``turning_heights``: z₁, z₂ [m] drawn on z(t). Long runs are thinned to
    ``max_points`` samples for drawing (the drifts are computed from all of them). Returns the Figure."""
    n = len(traj.t)
    if n == 0:
        raise InvalidInputError("the trajectory has no samples to draw")
    if not isinstance(max_points, int) or max_points < 2:
        raise InvalidInputError(f"max_points = {max_points!r} must be an integer of at least 2")
    p = traj.pendulum
    keep = _thin(n, max_points)
    t, x = np.asarray(traj.t)[keep], np.asarray(traj.x)[keep]

    fig = new_figure(figsize=figsize, layout="constrained")
    grid = fig.add_gridspec(2, 2, width_ratios=(1.0, 1.25))
    ax3 = fig.add_subplot(grid[:, 0], projection="3d", computed_zorder=False)
    axz = fig.add_subplot(grid[0, 1])
    axd = fig.add_subplot(grid[1, 1], sharex=axz)
    _sphere(ax3, p.length, x)

    axz.plot(t, x[:, 2], color="tab:blue", lw=0.8, label="z(t)")
    for k, z in enumerate(turning_heights or ()):
        if abs(z) <= p.length:
            axz.axhline(z, color=("tab:orange", "tab:red")[k % 2], ls="--", lw=1.0, label=f"z{k + 1} (exact)")
    axz.set_ylabel("height z [m]")
    axz.legend(loc="upper right", fontsize="small")
    axz.tick_params(labelbottom=False)

    energy = np.asarray(traj.energy)
    if traj.is_conservative:
        e_scale = p.mass * abs(p.g) * p.length if p.g != 0.0 else max(abs(energy[0]), 1e-300)
        de = np.abs(energy - energy[0])[keep] / e_scale
        axd.semilogy(t, np.maximum(de, _TINY), lw=0.8, label="|E − E₀| / (m|g|l)")
        if p.is_ideal:
            omega0 = math.sqrt(abs(p.g) / p.length) if p.g != 0.0 else 1.0
            j3 = np.asarray(traj.j3)
            dj = np.abs(j3 - j3[0])[keep] / (p.mass * p.length**2 * omega0)
            axd.semilogy(t, np.maximum(dj, _TINY), lw=0.8, label="|J₃ − J₃₀| / (m l² ω₀)")
        axd.axhline(FLOAT64_EPS, color="0.4", ls=":", lw=1.0, label="float64 ε")
        axd.set_ylabel("relative drift [1]")
    else:
        axd.plot(t, energy[keep], lw=0.8, label="E(t)")
        axd.set_ylabel("energy E [J]")
    axd.set_xlabel("time t [s]")
    axd.legend(loc="upper left", fontsize="small", ncols=3)

    fig.suptitle(
        title
        or f"{traj.method}, t = {traj.t[0]:g} .. {traj.t[-1]:g} s: "
        f"l = {p.length:g} m, g = {p.g:g} m/s², m = {p.mass:g} kg ({p.model})"
    )
    if path is not None:
        save_figure(fig, path)
    return fig
