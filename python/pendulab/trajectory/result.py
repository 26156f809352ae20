"""The result of one run, :class:`Trajectory`: saved times t [s] and states x [m], v [m/s] (N, 3),
the diagnostics computed along them on first use (docs/theory.md: energy [J] and J₃ [kg m²/s] T-2.6,
tension [N] T-2.3, constraint residuals, angles θ, φ [rad] T-2.5; for the real-pendulum models of §7
the power [W] and power balance [J] of T-7.1, a moving pivot's path [m]), and the ways out: files,
tables, text, figure, movie.

Its tables (columns, metadata, xarray) are :mod:`pendulab.trajectory.tables`, its words (``repr``,
``summary``) :mod:`pendulab.trajectory.report`.
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from .. import io
from ..display import html_table, number
from ..error_estimate import ErrorEstimate
from ..model import FloatArray, Pendulum, State
from ..overview import plot_overview
from . import tables
from .report import key_numbers
from .report import summary as _summary

if TYPE_CHECKING:
    from ..animate import Movie, MovieSettings


@dataclass(frozen=True)
class Trajectory:
    """Samples of one run. ``interrupted`` is True when the run was stopped (Ctrl-C) before t_end.

    ``options``: how it ran, as its files' metadata carry it: a fixed-step method's ``dt`` [s]; an
    adaptive method's (``dop853``) ``rtol``, ``atol`` and ``project``, and ``first_step`` [s] when one
    was given (no ``dt``: it chooses its steps); ``t0``, ``t_end`` [s] and how samples were kept.
    ``stats``: the core's counters (``steps``, for DOP853 also ``rejected`` and ``rhs_evals``).

    The string model (``model="string"``) also has ``taut`` (N,) bool — the string is taut at the
    sample — and ``events``: a dict of arrays ``t`` [s], ``kind`` ("slack": the tension reached 0;
    "taut": the string snapped taut), ``x`` [m], ``v_before``, ``v_after`` [m/s], ``energy_lost`` [J].

    ``error_estimate`` (``simulate(..., error_estimate=True)`` or ``accuracy=``): the estimated global
    position [m] and velocity [m/s] error at every sample; ``error``: the true error against the exact
    solution (ideal pendulum only). Both :class:`pendulab.accuracy.ErrorEstimate`, else None.
    """

    pendulum: Pendulum
    t: FloatArray
    x: FloatArray
    v: FloatArray
    method: str
    options: dict[str, Any] = field(default_factory=dict)
    stats: dict[str, int] = field(default_factory=dict)
    interrupted: bool = False
    taut: npt.NDArray[np.bool_] | None = None
    events: dict[str, Any] | None = None
    error_estimate: ErrorEstimate | None = None
    error: ErrorEstimate | None = None

    def __len__(self) -> int:
        return int(self.t.shape[0])

    @functools.cached_property
    def _diag(self) -> dict[str, FloatArray]:
        # with the times: forcing, pivot and tension of time-dependent models depend on t
        return self.pendulum.diagnostics(self.x, self.v, self.t)

    @property
    def energy(self) -> FloatArray:
        """E = m(½|v|² + g z) [J] at each sample."""
        return self._diag["energy"]

    @property
    def j3(self) -> FloatArray:
        """J₃ = m (x × v)·e₃ [kg m²/s] at each sample."""
        return self._diag["j3"]

    @property
    def tension(self) -> FloatArray:
        """Rod tension [N] at each sample (T-2.3); for the string model 0 where the string is slack."""
        if self.taut is not None:
            return np.where(self.taut, self._diag["tension"], 0.0)
        return self._diag["tension"]

    @property
    def energy_lost(self) -> FloatArray:
        """String model: the energy lost in the snaps up to each sample [J] (zeros otherwise), so that
        E + energy_lost is conserved (T-2.6 between events; up to the integrator's error)."""
        if not self.events or len(self.events["t"]) == 0:
            return np.zeros_like(self.t)
        te, lost = np.asarray(self.events["t"]), np.asarray(self.events["energy_lost"])
        cumulative = np.concatenate([[0.0], np.cumsum(lost)])
        return cumulative[np.searchsorted(te, self.t, side="right")]

    @property
    def radius_error(self) -> FloatArray:
        """|x| − l [m]."""
        return self._diag["radius_error"]

    @property
    def constraint_error(self) -> FloatArray:
        """(|x| − l)/l, dimensionless; 0 on the sphere."""
        return self._diag["radius_error"] / self.pendulum.length

    @property
    def tangency(self) -> FloatArray:
        """x·v [m²/s]; 0 on TS²."""
        return self._diag["tangency"]

    @property
    def power(self) -> FloatArray:
        """Power of the non-conservative forces P = dE/dt [W] at each sample (T-7.1): forcing, damping
        and drag, or a moving pivot's inertial force. Identically 0 for conservative models (the ideal
        pendulum, tilted gravity, an undamped rotating frame — Coriolis does no work)."""
        return self._diag["power"]

    @functools.cached_property
    def power_balance_residual(self) -> FloatArray:
        """E(t) − E(0) − ∫₀ᵗ P dt [J] at each sample, the work integrated by the trapezoidal rule over
        the saved samples (T-7.1). Zero up to the integrator's error and the rule's O(Δt²) error,
        Δt the sample spacing: save densely (``save_every=1``) to check the balance tightly. For a
        conservative model it is E(t) − E(0), the energy error."""
        e, p = self.energy, self.power
        # typed: numpy's stubs make both the concatenation of a list with an array and an element Any
        work: FloatArray = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(self.t) * (p[1:] + p[:-1]))])
        return e - float(e[0]) - work

    @property
    def is_conservative(self) -> bool:
        """True when no non-conservative force did work at any sample (``power`` is 0 throughout):
        then E is conserved and the summary reports its drift; otherwise the power balance."""
        return not bool(np.any(self.power != 0.0))

    @property
    def pivot(self) -> FloatArray | None:
        """The pivot position p(t) [m], (N, 3), for the moving-pivot models (``slewing``,
        ``vibrating``); the bob is at p + x in the inertial frame. ``None`` for a fixed pivot."""
        return self._diag.get("pivot")

    @property
    def boom(self) -> FloatArray | None:
        """The slewing crane (``model="slewing"``): the payload's position relative to the boom tip in
        the frame turning with the boom [m], (N, 3) = (radial, tangential, vertical) — x rotated by −ωt
        about e₃. Compare with :func:`pendulab.slewing_sway` (the linear theory, T-7.2). ``None`` for
        other models."""
        return self._diag.get("boom")

    @property
    def sway_angle(self) -> FloatArray:
        """The cable's angle from the downward vertical [rad] (the polar angle θ; for a moving pivot
        measured at the pivot)."""
        return self.theta

    @property
    def theta(self) -> FloatArray:
        """Polar angle from the downward vertical [rad]."""
        return np.arctan2(np.hypot(self.x[:, 0], self.x[:, 1]), -self.x[:, 2])

    @property
    def phi(self) -> FloatArray:
        """Azimuth atan2(y, x) [rad], continuous. Between two samples where the vertical angular
        momentum per mass ℓ₃ = x v_y − y v_x has the same sign at both ends, φ moves in that sign's
        direction (φ̇ = ℓ₃/ρ², T-2.5), so a step that looks backwards is taken forwards by 2π: near a
        pole φ turns by up to π between samples and a plain unwrap (nearest branch) picks the wrong
        way half the time. Elsewhere (ℓ₃ ≈ 0 or changing sign) the nearest branch is taken."""
        x, v = self.x, self.v
        raw = np.arctan2(x[:, 1], x[:, 0])
        if len(raw) < 2:
            return raw
        step = np.angle(np.exp(1j * np.diff(raw)))  # principal value in (−π, π]
        l3 = x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]
        tiny = 1e-12 * float(np.max(np.linalg.norm(x, axis=1) * np.linalg.norm(v, axis=1), initial=0.0))
        sign = np.where(np.abs(l3) > tiny, np.sign(l3), 0.0)
        turn = np.where(sign[:-1] == sign[1:], sign[1:], 0.0)
        step = np.where(turn * step < -1e-9, step + turn * 2.0 * np.pi, step)
        return np.concatenate([[raw[0]], raw[0] + np.cumsum(step)])

    def state(self, i: int) -> State:
        """The i-th saved state."""
        return State(self.x[i].copy(), self.v[i].copy())

    def metadata(self) -> dict[str, Any]:
        """Parameters, method, options, counters and units (what every output file carries)."""
        return tables.metadata(self)

    def columns(self) -> dict[str, tuple[str, npt.NDArray[np.float64]]]:
        """Flat columns name -> (unit, values) for tabular files. Models other than the ideal pendulum
        add ``power`` [W] and ``power_balance_residual`` [J], a moving pivot ``pivot_x/y/z`` [m]."""
        return tables.columns(self)

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` with dims (time, axis), units as attributes, metadata in ``attrs``."""
        return tables.dataset(self)

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes the trajectory atomically; the format comes from the suffix (.csv, .parquet, .nc)."""
        return io.save(self, path)

    def to_csv(self, path: str | os.PathLike[str]) -> Path:
        """Writes CSV (see :func:`pendulab.io.write_csv`)."""
        io.write_csv(self, path)
        return Path(path)

    def to_parquet(self, path: str | os.PathLike[str]) -> Path:
        """Writes Parquet (needs pyarrow)."""
        io.write_parquet(self, path)
        return Path(path)

    def to_netcdf(self, path: str | os.PathLike[str]) -> Path:
        """Writes NetCDF (needs xarray and scipy)."""
        io.write_netcdf(self, path)
        return Path(path)

    def animate(
        self, path: str | os.PathLike[str], settings: MovieSettings | None = None, **options: Any
    ) -> Movie:
        """Writes a movie of this trajectory to ``path`` (.mp4, .webm or .gif) and returns a
        :class:`pendulab.animate.Movie` (frames, fps, size, bytes, ...).

        ``settings``: a :class:`pendulab.animate.MovieSettings`, and/or its fields as keywords:
        ``fps`` [frames per s of video]; ``speed`` [simulated s per s of video]; ``duration`` [s of
        video] (default: all of it); ``panels``: any of ``3d``, ``top``, ``z``, ``reduced``, ``veff``;
        ``size`` [px] (width, height) or "1280x720". Between saved samples the bob moves along the
        cubic Hermite interpolant of (x, v) (error O(h⁴) in the sample spacing h); a moving pivot's
        path is drawn and the rod hangs from where the pivot is. Also
        ``trail`` [s], ``vectors``, ``azimuth``, ``elevation`` [deg], ``progress`` (see
        :func:`pendulab.animate.render`; ``docs/animate.md``)."""
        from ..animate import from_samples, render
        from ..animate.words import method_words, model_words

        p = self.pendulum
        label = f"{model_words(p.model)}: {method_words(self.method)}"
        motion = from_samples(
            self.t, self.x, self.v, length=p.length, g=p.g, mass=p.mass, label=label, pivot=self.pivot
        )
        return render(motion, path, settings, **options)

    def __repr__(self) -> str:
        if len(self) == 0:
            return f"Trajectory({self.method}, no samples)"
        rows = {name: value for name, value, _ in key_numbers(self)}
        drift = rows.get("max |E − E₀| / (m|g|l)")
        return (
            f"Trajectory({self.method}, {len(self)} samples, t = {number(self.t[0])} … {number(self.t[-1])} s"
            + (f", ΔE/(m|g|l) = {drift}" if drift is not None else "")
            + f", ΔJ₃ = {rows['max |J₃ − J₃₀|']} kg m²/s"
            + (", INTERRUPTED" if self.interrupted else "")
            + ")"
        )

    def _repr_html_(self) -> str:
        if len(self) == 0:
            return html_table("Trajectory", [("samples", 0, "")])
        note = "tr.summary() for more; tr.plot() to see it"
        return html_table("Trajectory", key_numbers(self), note=note)

    def plot(self, path: str | os.PathLike[str] | None = None, **kwargs: Any) -> Any:
        """An overview figure: the path on the sphere, z(t), and the drift of E and J₃ (log scale,
        float64 floor marked) — :func:`pendulab.overview.plot_overview`; saved atomically to
        ``path`` if given (.png, .svg, .pdf). Needs matplotlib. Returns the Figure."""
        return plot_overview(self, path, **kwargs)

    def summary(self) -> str:
        """A few lines: span, samples, conservation of E and J₃ (or, for non-conservative models, the
        power balance E(t) − E(0) − ∫P dt of T-7.1 instead of an energy drift), constraint residuals,
        work."""
        return _summary(self)
