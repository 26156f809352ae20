"""The exact solution shown (docs/theory.md §4): its summary in a few lines and its notebook table
(kind T-4.6, turning heights z₁, z₂, z₃ [m], modulus m = k², z-period T_z [s] T-4.3, azimuthal advance
Δφ [rad] and rotation number W T-4.5), the overview figure over three z-periods, and the movie whose
every frame is the exact state at its time t [s] (T-4.2 … T-4.4: nothing integrated or interpolated).

The exact states at given times as a :class:`pendulab.Trajectory` (method ``"exact"``) are here
too, so that a trajectory's diagnostics, summary and file writers apply. The functions take a
finished :class:`pendulab.ExactSolution` (duck-typed, as :mod:`pendulab.overview` does: this module
sits below the class, whose methods call it).
"""

from __future__ import annotations

import math
import os
from typing import TYPE_CHECKING, Any

import numpy as np

from .._core import InvalidInputError
from ..display import Row, html_table, number
from ..model import FloatArray
from ..overview import plot_overview
from ..trajectory import Trajectory
from ..validate import array, show

if TYPE_CHECKING:
    from ..animate import Movie, MovieSettings


def trajectory(sol: Any, t: Any) -> Trajectory:
    """The exact states at the times t [s] (1-D) as the :class:`Trajectory` of
    ``ExactSolution.trajectory`` (method ``"exact"``, no steps)."""
    times = array("t", t, "time")
    if times.ndim != 1 or times.size == 0:
        raise InvalidInputError(f"t must be a non-empty 1-D array of times (s), got shape {times.shape}")
    x, v = sol.state(times)
    return Trajectory(
        sol.pendulum,
        times.copy(),
        x,
        v,
        "exact",
        {"kind": sol.kind},
        {"steps": 0, "samples": len(times)},
    )


def summary(sol: Any) -> str:
    """The lines of ``ExactSolution.summary()``: kind, turning heights, z-period, Δφ and W (SI units)."""
    p = sol.pendulum
    heights = ", ".join(f"{z:.9g}" for z in sol.turning_heights)
    lines = [
        f"pendulum: l = {p.length} m, m = {p.mass} kg, g = {p.g} m/s^2",
        f"kind:     {sol.kind}",
        f"heights:  z1, z2{', z3' if len(sol.turning_heights) == 3 else ''} = {heights} m",
    ]
    if sol.modulus is not None:
        lines.append(f"modulus:  m = k^2 = {sol.modulus:.15g}")
    if sol.period_z is not None:
        lines.append(f"period:   T_z = {sol.period_z:.15g} s")
    if sol.azimuth_advance is not None:
        dphi, w = sol.azimuth_advance, sol.rotation_number
        lines.append(f"advance:  dphi = {dphi:.15g} rad per z-period, W = {w:.15g}")
    return "\n".join(lines)


def html(sol: Any) -> str:
    """The notebook table of an exact solution (SI units)."""
    p = sol.pendulum
    rows: list[Row] = [
        ("pendulum", f"l = {number(p.length)} m, g = {number(p.g)} m/s², m = {number(p.mass)} kg", ""),
        ("kind (T-4.6)", sol.kind, ""),
        (
            "turning heights z₁, z₂" + (", z₃" if len(sol.turning_heights) == 3 else ""),
            ", ".join(number(z, 9) for z in sol.turning_heights),
            "m",
        ),
        ("modulus m = k²", sol.modulus, ""),
        ("z-period T_z", number(sol.period_z, 12), "s"),
        ("azimuthal advance Δφ per T_z", number(sol.azimuth_advance, 12), "rad"),
        ("rotation number W = Δφ/2π", number(sol.rotation_number, 12), ""),
    ]
    return html_table("Exact solution", rows, note="sol.state(t), sol.phases(), sol.plot()")


def default_times(sol: Any, points: int = 2000) -> FloatArray:
    """``points`` times [s] covering three z-periods (or 10/ω₀ when there is no period, 10 s when
    g = 0): what ``ExactSolution.plot`` draws by default."""
    if sol.period_z is not None and math.isfinite(sol.period_z) and sol.period_z > 0.0:
        span = 3.0 * sol.period_z
    elif sol.omega0 > 0.0:
        span = 10.0 / sol.omega0
    else:
        span = 10.0
    return np.linspace(0.0, span, points)


def plot(sol: Any, path: str | os.PathLike[str] | None, t: Any, **kwargs: Any) -> Any:
    """The overview figure of ``ExactSolution.plot``: the exact states at ``t`` [s] (default
    :func:`default_times`) with the turning heights z₁, z₂ [m] dashed; saved to ``path`` if given."""
    if path is not None and not isinstance(path, str | os.PathLike):
        raise InvalidInputError(
            f"plot(path={show(path)}): path must be a file name (.png, .svg, .pdf); "
            "give the times as t=... [s]"
        )
    times = default_times(sol) if t is None else t
    kwargs.setdefault("turning_heights", sol.turning_heights[:2])
    kwargs.setdefault("title", f"exact solution ({sol.kind})")
    return plot_overview(sol.trajectory(times), path, **kwargs)


def animate(
    sol: Any,
    path: str | os.PathLike[str],
    settings: MovieSettings | None,
    t: tuple[float, float] | None,
    **options: Any,
) -> Movie:
    """The movie of ``ExactSolution.animate``: :meth:`state` at every frame's time over ``t`` =
    (t_start, t_end) [s] (default (0, speed · duration), or (0, 10 s) without a duration)."""
    from ..animate import from_function, render
    from ..animate.movie import movie_settings

    s = movie_settings(settings, options)
    if t is None:
        t = (0.0, s.speed * s.duration if s.duration is not None else 10.0)
    try:
        span = (float(t[0]), float(t[1]))
    except (TypeError, ValueError, IndexError):
        raise InvalidInputError(f"t = {t!r} must be a pair (t_start, t_end) of times in s") from None

    def states(times: FloatArray) -> tuple[FloatArray, FloatArray]:
        x, v = sol.state(np.asarray(times, dtype=np.float64))
        return x[:, None, :], v[:, None, :]

    p = sol.pendulum
    motion = from_function(
        states,
        length=p.length,
        g=p.g,
        mass=p.mass,
        span=span,
        label=f"exact solution ({sol.kind} motion)",
    )
    return render(motion, path, s)
