"""The trajectory on the sphere: in 3-D and seen from above (the rosette).

- ``kind="sphere"``: the path x(t) [m] on a faint wire sphere of radius l, with the start (filled
  dot) and the end (square); equal scales on the three axes.
- ``kind="top"``: the top view (x, y) [m] — for a generic orbit the rosette of docs/theory.md T-4.5 — inside
  the circle of radius l (the sphere's outline).
- ``kind="both"``: the two side by side.

Given the orbit's :class:`pendulab.ExactSolution`, the turning heights z₁ ≤ z₂ [m] are drawn as
horizontal circles (radius √(l² − z²) in the top view): the path must stay between them.
"""

from __future__ import annotations

import math
import os
from typing import Any

import numpy as np
import numpy.typing as npt

from .._core import InvalidInputError
from ..figure import new_figure, save_figure
from ..model import FloatArray
from ..theory.exact import ExactSolution
from ..trajectory import Trajectory

KINDS = ("sphere", "top", "both")
"""What :func:`plot_trajectory` draws."""

FIGSIZES: dict[str, tuple[float, float]] = {"sphere": (7.0, 7.0), "top": (7.0, 7.0), "both": (13.0, 6.5)}
"""Default figure sizes [in] per kind (×150 dpi when saved: 1050×1050 and 1950×975 pixels)."""

_PATH = {"color": "tab:blue", "lw": 0.7, "alpha": 0.9}
_TURNING = ({"color": "tab:orange", "ls": "--", "lw": 1.3}, {"color": "tab:red", "ls": "--", "lw": 1.3})


def _thin(n: int, max_points: int) -> npt.NDArray[np.intp]:
    """Indices of ``min(n, max_points)`` evenly spread samples of n, the first and the last included."""
    if n <= max_points:
        return np.arange(n)
    return np.rint(np.linspace(0.0, n - 1.0, max_points)).astype(np.intp)


def _turning_heights(traj: Trajectory, exact: ExactSolution | None) -> list[tuple[int, float]]:
    """z₁, z₂ [m] of ``exact`` (not z₃, which lies off the sphere; nor a pole); checks the pendulum."""
    if exact is None:
        return []
    if exact.pendulum.params() != traj.pendulum.params():
        raise InvalidInputError(
            f"the exact solution is for {exact.pendulum!r}, the trajectory for {traj.pendulum!r}; "
            "overlay the solution of the trajectory's own pendulum"
        )
    ell = traj.pendulum.length
    # a turning "height" at a pole (planar swings, motion over the top) is a point, not a circle
    return [(k, z) for k, z in enumerate(exact.turning_heights[:2]) if abs(z) < ell * (1.0 - 1e-9)]


def _draw_sphere(ax: Any, traj: Trajectory, x: FloatArray, heights: list[tuple[int, float]]) -> None:
    ell = traj.pendulum.length
    u, w = np.meshgrid(np.linspace(0.0, 2.0 * np.pi, 37), np.linspace(0.0, np.pi, 19))
    ax.plot_wireframe(
        ell * np.sin(w) * np.cos(u),
        ell * np.sin(w) * np.sin(u),
        ell * np.cos(w),
        color="0.6",
        lw=0.3,
        alpha=0.4,
    )
    ax.plot(x[:, 0], x[:, 1], x[:, 2], label="path", zorder=5, **_PATH)
    circle = np.linspace(0.0, 2.0 * np.pi, 181)
    for k, z in heights:
        rho = math.sqrt(max(ell * ell - z * z, 0.0))
        ax.plot(
            rho * np.cos(circle),
            rho * np.sin(circle),
            np.full_like(circle, z),
            zorder=6,
            label=f"turning height z{'₁₂'[k]} = {z:.6g} m",
            **_TURNING[k],
        )
    ax.plot(*x[0], "o", color="tab:green", ms=7, zorder=7, label=f"start, t = {traj.t[0]:g} s")
    ax.plot(*x[-1], "s", color="black", ms=5, zorder=7, label=f"end, t = {traj.t[-1]:g} s")
    lim = 1.05 * ell
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_zlim(-lim, lim)
    ax.set_box_aspect((1.0, 1.0, 1.0))
    ax.locator_params(nbins=5)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_zlabel("z [m]")
    ax.set_title("on the sphere")


def _draw_top(ax: Any, traj: Trajectory, x: FloatArray, heights: list[tuple[int, float]]) -> None:
    ell = traj.pendulum.length
    circle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(ell * np.cos(circle), ell * np.sin(circle), color="black", lw=1.0, label=f"|x| = l = {ell:g} m")
    ax.plot(x[:, 0], x[:, 1], label="path (x, y)", **_PATH)
    for k, z in heights:
        rho = math.sqrt(max(ell * ell - z * z, 0.0))
        ax.plot(
            rho * np.cos(circle),
            rho * np.sin(circle),
            label=f"turning height z{'₁₂'[k]} = {z:.6g} m",
            **_TURNING[k],
        )
    ax.plot(*x[0, :2], "o", color="tab:green", ms=7, label=f"start, t = {traj.t[0]:g} s")
    ax.plot(*x[-1, :2], "s", color="black", ms=5, label=f"end, t = {traj.t[-1]:g} s")
    lim = 1.05 * ell
    ax.set_xlim(-lim, lim)
    ax.set_ylim(-lim, lim)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.set_xlabel("x [m]")
    ax.set_ylabel("y [m]")
    ax.set_title("top view")


def plot_trajectory(
    traj: Trajectory,
    path: str | os.PathLike[str] | None = None,
    *,
    exact: ExactSolution | None = None,
    kind: str = "both",
    max_points: int = 50_000,
    figsize: tuple[float, float] | None = None,
) -> Any:
    """Draws ``traj`` on the sphere (``kind="sphere"``), from above (``"top"``) or both side by side
    (``"both"``, the default); saves atomically to ``path`` if given (.png, .svg, .pdf).

    ``exact``: the orbit's exact solution (same pendulum), whose turning heights z₁, z₂ [m] are drawn
    as horizontal circles. Long trajectories are thinned to ``max_points`` evenly spread samples for
    drawing (the first and the last included). Axes in m. Returns the Figure.
    """

    if kind not in KINDS:
        raise InvalidInputError(f"unknown kind {kind!r}; use one of {', '.join(KINDS)}")
    if len(traj) == 0:
        raise InvalidInputError("the trajectory has no samples to draw")
    if max_points < 2:
        raise InvalidInputError(f"max_points = {max_points} must be at least 2")
    heights = _turning_heights(traj, exact)
    x = traj.x[_thin(len(traj), max_points)]

    fig = new_figure(figsize=figsize or FIGSIZES[kind], layout="constrained")
    if kind == "both":
        ax3 = fig.add_subplot(1, 2, 1, projection="3d", computed_zorder=False)
        ax2 = fig.add_subplot(1, 2, 2)
    elif kind == "sphere":
        ax3, ax2 = fig.add_subplot(projection="3d", computed_zorder=False), None
    else:
        ax3, ax2 = None, fig.add_subplot()
    if ax3 is not None:
        _draw_sphere(ax3, traj, x, heights)
    if ax2 is not None:
        _draw_top(ax2, traj, x, heights)
    handles, labels = (ax2 if ax2 is not None else ax3).get_legend_handles_labels()
    fig.legend(handles, labels, loc="outside lower center", ncols=3, fontsize="small")

    p = traj.pendulum
    fig.suptitle(
        f"Trajectory ({traj.method}, t = {traj.t[0]:g} .. {traj.t[-1]:g} s): "
        f"l = {p.length:g} m, g = {p.g:g} m/s², m = {p.mass:g} kg"
    )
    if path is not None:
        save_figure(fig, path)
    return fig
