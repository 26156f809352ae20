"""A computed trajectory: saved times and states plus the diagnostics that prove it right.

Arrays (N samples): ``t`` [s], ``x`` [m] (N, 3), ``v`` [m/s] (N, 3); derived on first use:
``energy`` [J], ``j3`` [kg m²/s], ``tension`` [N] (T-2.3, T-2.6), ``radius_error`` = |x| − l [m],
``constraint_error`` = (|x| − l)/l (dimensionless), ``tangency`` = x·v [m²/s], ``theta``, ``phi`` [rad],
and for the real-pendulum models (docs/theory.md §7) ``power`` [W] of the non-conservative forces,
``power_balance_residual`` E(t) − E(0) − ∫P dt [J] (the check of T-7.1) and ``pivot`` [m] (moving pivot).
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
import numpy.typing as npt

from . import io
from .display import Row, html_table, number, relative_drift
from .error_estimate import ErrorEstimate
from .model import FloatArray, Pendulum, State, models
from .overview import plot_overview

if TYPE_CHECKING:
    from .animate import Movie, MovieSettings

UNITS = {
    "t": "s",
    "x": "m",
    "v": "m/s",
    "energy": "J",
    "j3": "kg m^2/s",
    "tension": "N",
    "radius_error": "m",
    "constraint_error": "1",
    "tangency": "m^2/s",
    "power": "W",
    "power_balance_residual": "J",
    "pivot": "m",
    "boom": "m",
    "taut": "1",
    "err_x_est": "m",
    "err_v_est": "m/s",
    "err_x": "m",
    "err_v": "m/s",
}


@dataclass(frozen=True)
class Trajectory:
    """Samples of one run. ``interrupted`` is True when the run was stopped (Ctrl-C) before t_end.

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
        work = np.concatenate([[0.0], np.cumsum(0.5 * np.diff(self.t) * (p[1:] + p[:-1]))])
        return e - e[0] - work

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
        return {
            "software": "pendulab",
            "pendulum": self.pendulum.params(),
            "method": self.method,
            "options": self.options,
            "stats": self.stats,
            "interrupted": self.interrupted,
            **({"events": self._event_list()} if self.events is not None else {}),
            **({"error_estimate": self.error_estimate.describe()} if self.error_estimate else {}),
            **({"error": self.error.describe()} if self.error else {}),
            "units": UNITS | self._param_units(),
            "conventions": "SI units, z up, gravity along -z for g > 0, theta from the downward vertical",
        }

    def _event_list(self) -> list[dict[str, Any]]:
        """The string model's events as JSON-ready records (t [s], kind, energy_lost [J])."""
        ev = self.events or {}
        return [
            {"t": float(t), "kind": str(k), "energy_lost": float(e)}
            for t, k, e in zip(ev.get("t", []), ev.get("kind", []), ev.get("energy_lost", []), strict=True)
        ]

    def _param_units(self) -> dict[str, str]:
        """Units of the pendulum's parameters: length, mass, g and the model's own (registry)."""
        spec = next(m for m in models() if m["name"] == self.pendulum.model)
        return {p["name"]: p["unit"] for p in spec["params"]}

    def columns(self) -> dict[str, tuple[str, npt.NDArray[np.float64]]]:
        """Flat columns name -> (unit, values) for tabular files. Models other than the ideal pendulum
        add ``power`` [W] and ``power_balance_residual`` [J], a moving pivot ``pivot_x/y/z`` [m]."""
        cols: dict[str, tuple[str, npt.NDArray[np.float64]]] = {"t": ("s", self.t)}
        for k, axis in enumerate("xyz"):
            cols[axis] = ("m", self.x[:, k])
        for k, axis in enumerate("xyz"):
            cols[f"v{axis}"] = ("m/s", self.v[:, k])
        for name in ("energy", "j3", "tension", "constraint_error", "tangency"):
            cols[name] = (UNITS[name], getattr(self, name))
        if not self.pendulum.is_ideal and self.taut is None:
            for name in ("power", "power_balance_residual"):
                cols[name] = (UNITS[name], getattr(self, name))
        if self.pivot is not None:
            for k, axis in enumerate("xyz"):
                cols[f"pivot_{axis}"] = ("m", self.pivot[:, k])
        if self.boom is not None:
            for k, axis in enumerate(("radial", "tangential", "vertical")):
                cols[f"boom_{axis}"] = ("m", self.boom[:, k])
        if self.taut is not None:
            cols["taut"] = ("1", self.taut.astype(np.float64))
            cols["energy_lost"] = ("J", self.energy_lost)
        for suffix, err in (("_est", self.error_estimate), ("", self.error)):
            if err is not None:
                cols[f"err_x{suffix}"] = ("m", err.position)
                cols[f"err_v{suffix}"] = ("m/s", err.velocity)
        return cols

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` with dims (time, axis), units as attributes, metadata in ``attrs``."""
        import json

        xr = io._require("xarray")
        extra: dict[str, Any] = {}
        if not self.pendulum.is_ideal and self.taut is None:
            power = {"units": "W", "long_name": "power of the non-conservative forces"}
            extra["power"] = ("time", self.power, power)
            extra["power_balance_residual"] = (
                "time",
                self.power_balance_residual,
                {"units": "J", "long_name": "E(t) - E(0) - integral of P dt (trapezoid)"},
            )
        if self.pivot is not None:
            extra["pivot"] = (("time", "axis"), self.pivot, {"units": "m", "long_name": "pivot position"})
        if self.boom is not None:
            extra["boom"] = (("time", "axis"), self.boom, {"units": "m", "long_name": "x in the boom frame"})
        if self.taut is not None:
            extra["taut"] = ("time", self.taut.astype(np.int8), {"units": "1", "long_name": "string taut"})
            extra["energy_lost"] = ("time", self.energy_lost, {"units": "J", "long_name": "lost in snaps"})
        for suffix, err, what in (("_est", self.error_estimate, "estimated"), ("", self.error, "true")):
            if err is not None:
                extra[f"err_x{suffix}"] = (
                    "time",
                    err.position,
                    {"units": "m", "long_name": f"{what} position error"},
                )
                extra[f"err_v{suffix}"] = (
                    "time",
                    err.velocity,
                    {"units": "m/s", "long_name": f"{what} velocity error"},
                )
        ds = xr.Dataset(
            {
                "x": (("time", "axis"), self.x, {"units": "m", "long_name": "bob position"}),
                "v": (("time", "axis"), self.v, {"units": "m/s", "long_name": "bob velocity"}),
                "energy": ("time", self.energy, {"units": "J"}),
                "j3": ("time", self.j3, {"units": "kg m^2/s", "long_name": "vertical angular momentum"}),
                "tension": ("time", self.tension, {"units": "N"}),
                "constraint_error": ("time", self.constraint_error, {"units": "1", "long_name": "(|x|-l)/l"}),
                "tangency": ("time", self.tangency, {"units": "m^2/s", "long_name": "x.v"}),
                **extra,
            },
            coords={"time": ("time", self.t, {"units": "s"}), "axis": ["x", "y", "z"]},
            attrs={"pendulab": json.dumps(self.metadata(), sort_keys=True)},
        )
        return ds

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
        from .animate import from_samples, render
        from .animate.words import method_words, model_words

        p = self.pendulum
        label = f"{model_words(p.model)}: {method_words(self.method)}"
        motion = from_samples(
            self.t, self.x, self.v, length=p.length, g=p.g, mass=p.mass, label=label, pivot=self.pivot
        )
        return render(motion, path, settings, **options)

    def _key_numbers(self) -> list[Row]:
        p, e, j = self.pendulum, self.energy, self.j3
        described = f"{p.model}: l = {number(p.length)} m, g = {number(p.g)} m/s², m = {number(p.mass)} kg"
        rows: list[Row] = [
            ("pendulum", described, ""),
            ("method", self.method, ""),
            ("time span", f"{number(self.t[0])} … {number(self.t[-1])}", "s"),
            ("samples", len(self), ""),
            ("steps", self.stats.get("steps", 0), ""),
        ]
        if len(self) and self.is_conservative and self.taut is None:
            scale = p.mass * abs(p.g) * p.length if p.g != 0.0 else max(abs(float(e[0])), 1e-300)
            rows.append(("max |E − E₀| / (m|g|l)", number(relative_drift(e, scale), 3), ""))
        if len(self):
            rows.append(("max |J₃ − J₃₀|", number(relative_drift(j, 1.0), 3), "kg m²/s"))
            on = slice(None) if self.taut is None else self.taut
            radius = np.max(np.abs(self.constraint_error[on]), initial=0.0)
            rows.append(("max ||x| − l| / l", number(radius, 3), ""))
        if self.interrupted:
            rows.append(("interrupted", "yes (Ctrl-C)", ""))
        return rows

    def __repr__(self) -> str:
        if len(self) == 0:
            return f"Trajectory({self.method}, no samples)"
        rows = {name: value for name, value, _ in self._key_numbers()}
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
        return html_table("Trajectory", self._key_numbers(), note=note)

    def plot(self, path: str | os.PathLike[str] | None = None, **kwargs: Any) -> Any:
        """An overview figure: the path on the sphere, z(t), and the drift of E and J₃ (log scale,
        float64 floor marked) — :func:`pendulab.overview.plot_overview`; saved atomically to
        ``path`` if given (.png, .svg, .pdf). Needs matplotlib. Returns the Figure."""
        return plot_overview(self, path, **kwargs)

    def summary(self) -> str:
        """A few lines: span, samples, conservation of E and J₃ (or, for non-conservative models, the
        power balance E(t) − E(0) − ∫P dt of T-7.1 instead of an energy drift), constraint residuals,
        work."""
        e, j = self.energy, self.j3
        e_scale = max(
            abs(e[0]), self.pendulum.mass * max(abs(self.pendulum.g), 1e-300) * self.pendulum.length
        )
        p, steps = self.pendulum, self.stats.get("steps", 0)
        described = f"l = {p.length} m, m = {p.mass} kg, g = {p.g} m/s^2"
        if not p.is_ideal:
            units = self._param_units()
            extras = "".join(
                f", {k} = {v:g}" + (f" {units[k]}" if units.get(k, "1") != "1" else "")
                for k, v in p.extra.items()
            )
            described = f"{p.model} model, {described}{extras}"
        lines = [
            f"pendulum: {described}",
            f"method:   {self.method}  {self.options}",
            f"span:     t = {self.t[0]:g} .. {self.t[-1]:g} s, {len(self)} samples, {steps} steps"
            + ("  (INTERRUPTED)" if self.interrupted else ""),
        ]
        if self.taut is not None:
            kinds = list((self.events or {}).get("kind", []))
            lost = self.energy_lost
            drift_e = np.max(np.abs(e + lost - e[0])) / e_scale
            lines += [
                f"string:   went slack {kinds.count('slack')}x, snapped taut {kinds.count('taut')}x "
                f"(restitution {p.extra.get('restitution', 0.0):g}); taut at {np.count_nonzero(self.taut)} "
                f"of {len(self)} samples",
                f"energy:   E0 = {e[0]:.12g} J, lost in snaps {lost[-1]:.6g} J, "
                f"max |E + lost - E0| / (m |g| l) = {drift_e:.3e}",
            ]
        elif self.is_conservative:
            drift_e = np.max(np.abs(e - e[0])) / e_scale
            lines.append(f"energy:   E0 = {e[0]:.12g} J, max |E - E0| / (m |g| l) = {drift_e:.3e}")
        else:
            residual = np.max(np.abs(self.power_balance_residual))
            work = e[-1] - e[0] - self.power_balance_residual[-1]
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
        on = slice(None) if self.taut is None else self.taut
        where = "" if self.taut is None else " (taut samples)"
        lines += [
            f"sphere:   max ||x| - l| / l = {np.max(np.abs(self.constraint_error[on]), initial=0.0):.3e}, "
            f"max |x.v| = {np.max(np.abs(self.tangency[on]), initial=0.0):.3e} m^2/s{where}",
            f"height:   z in [{self.x[:, 2].min():.6f}, {self.x[:, 2].max():.6f}] m",
        ]
        for label, err in (("estimate", self.error_estimate), ("error", self.error)):
            if err is not None:
                how = err.how + (f", {err.reference['companion']}" if "companion" in err.reference else "")
                lines.append(
                    f"{label + ':':<10}max |dx| = {err.max_position:.3e} m "
                    f"({err.max_position / p.length:.1e} l), "
                    f"max |dv| = {err.max_velocity:.3e} m/s, at t_end {err.position[-1]:.3e} m  ({how})"
                )
        return "\n".join(lines)
