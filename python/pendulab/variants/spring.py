"""The swinging spring (elastic pendulum, docs/theory.md T-7.4): a bob of mass m [kg] on a spring of
stiffness k [N/m] and rest length l₀ [m] from a fixed pivot, gravity g [m/s²] along −z. The state is
unconstrained (r [m], v [m/s]); E and J₃ are conserved and kept by the symplectic Störmer–Verlet
method (order 2) or its triple jump (order 4). At the 1:1:2 resonance √(k/m) = 2√(|g|/l), with
l = l₀ + m |g|/k, energy passes between bouncing and swinging and the swing plane turns in steps.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .. import io
from .._core import InvalidInputError, ModelSpec, RunOptions, spring_simulate
from ..display import Row, html_table, number, relative_drift
from ..model import FloatArray


@dataclass(frozen=True)
class SwingingSpring:
    """Stiffness per unit mass ``k_over_m`` [1/s²], rest length ``rest_length`` [m], ``g`` [m/s²],
    ``mass`` [kg]. ``SwingingSpring.resonant(l)`` gives the 1:1:2 resonance at equilibrium length l
    (also for g < 0: the mirror image, the bob resting above the pivot)."""

    k_over_m: float
    rest_length: float
    g: float = 9.81
    mass: float = 1.0

    @classmethod
    def resonant(cls, equilibrium_length: float = 1.0, g: float = 9.81, mass: float = 1.0) -> SwingingSpring:
        """The 1:1:2 resonance at the stable rest length l = ``equilibrium_length`` [m]: k/m = 4|g|/l
        and l₀ = 3l/4, so that √(k/m) = 2√(|g|/l) (T-7.4). For g < 0 it is the mirror image of g > 0
        (the bob rests above the pivot at l, the spring stretched, and swings about that stable point).
        Refused (``InvalidInputError`` naming the value): l not a finite number > 0, and g = 0 or not
        finite (without gravity the bob has no swing frequency, so there is no resonance)."""
        ell, grav = float(equilibrium_length), float(g)
        if not (math.isfinite(ell) and ell > 0.0):
            raise InvalidInputError(
                f"SwingingSpring.resonant: equilibrium_length = {equilibrium_length!r} m is not allowed: "
                "the stable rest length must be a finite number > 0 m"
            )
        if not (math.isfinite(grav) and grav != 0.0):
            raise InvalidInputError(
                f"SwingingSpring.resonant: g = {g!r} m/s² is not allowed: a finite number other than 0 "
                "m/s² (g > 0 hangs the bob below the pivot, g < 0 rests it above; with g = 0 it has no "
                "swing frequency and no 1:1:2 resonance)"
            )
        return cls(4.0 * abs(grav) / ell, 0.75 * ell, grav, mass)

    @property
    def equilibrium_length(self) -> float:
        """l = l₀ + |g|/(k/m) [m], the length at the stable equilibrium: the bob at rest on the vertical
        through the pivot, on the side gravity pulls it to, the spring stretched by |g|/(k/m) — below
        the pivot for g > 0, above it for g < 0 (the mirror image of g > 0; the other rest point, the
        spring compressed to l₀ − |g|/(k/m) on the far side, is unstable); l₀ for g = 0."""
        return self.rest_length + abs(self.g) / self.k_over_m

    @property
    def spec(self) -> ModelSpec:
        """The spring as the core builds and checks it (``pendulab._core.ModelSpec``), for its runs."""
        return ModelSpec.spring_model(
            float(self.k_over_m), float(self.rest_length), float(self.g), float(self.mass)
        )


@dataclass(frozen=True)
class SpringTrajectory:
    """Times ``t`` [s], positions ``x`` and velocities ``v`` (N, 3) [m, m/s], ``energy`` [J], ``j3``
    [kg m²/s], and ``bouncing_energy`` [J]: the radial (spring) part ½m ṙ² + ½k(|r| − l)² about the
    stable equilibrium length l (:attr:`SwingingSpring.equilibrium_length`)."""

    spring: SwingingSpring
    t: FloatArray
    x: FloatArray
    v: FloatArray
    energy: FloatArray
    j3: FloatArray
    metadata: dict[str, Any] = field(default_factory=dict)

    interrupted: bool = False

    def __len__(self) -> int:
        return int(self.t.shape[0])

    @property
    def r(self) -> FloatArray:
        """The spring's length |r| [m] at each sample."""
        r: FloatArray = np.linalg.norm(self.x, axis=1)  # (N,): a norm along an axis is Any in numpy's stubs
        return r

    @property
    def bouncing_energy(self) -> FloatArray:
        r: FloatArray = np.linalg.norm(self.x, axis=1)
        xv: FloatArray = np.einsum("ij,ij->i", self.x, self.v)  # x·v (N,), Any in numpy's stubs
        rdot = xv / r
        dl = r - self.spring.equilibrium_length
        return self.spring.mass * (0.5 * rdot**2 + 0.5 * self.spring.k_over_m * dl**2)

    def columns(self) -> dict[str, tuple[str, FloatArray]]:
        """Flat columns name -> (unit, values) for files: t, x/y/z, vx/vy/vz, r, energy, j3,
        bouncing_energy."""
        cols: dict[str, tuple[str, FloatArray]] = {"t": ("s", self.t)}
        for k, axis in enumerate("xyz"):
            cols[axis] = ("m", self.x[:, k])
        for k, axis in enumerate("xyz"):
            cols[f"v{axis}"] = ("m/s", self.v[:, k])
        cols["r"] = ("m", self.r)
        cols["energy"] = ("J", self.energy)
        cols["j3"] = ("kg m^2/s", self.j3)
        cols["bouncing_energy"] = ("J", self.bouncing_energy)
        return cols

    def file_metadata(self) -> dict[str, Any]:
        """The spring's parameters (SI), the integrator and the units, as files carry them."""
        sp = self.spring
        return {
            "software": "pendulab",
            "pendulum": {
                "model": "spring",
                "k_over_m": sp.k_over_m,
                "stiffness": sp.k_over_m * sp.mass,
                "rest_length": sp.rest_length,
                "equilibrium_length": sp.equilibrium_length,
                "g": sp.g,
                "mass": sp.mass,
            },
            "method": "stormer_verlet" if self.metadata.get("order", 2) == 2 else "triple_jump",
            "options": dict(self.metadata),
            "interrupted": self.interrupted,
            "units": {name: unit for name, (unit, _) in self.columns().items()}
            | {"k_over_m": "1/s^2", "stiffness": "N/m", "rest_length": "m", "equilibrium_length": "m"},
            "conventions": "SI units, z up, gravity along -z for g > 0",
        }

    def to_xarray(self) -> Any:
        """An ``xarray.Dataset`` (dims time, axis) with units as attributes."""
        xr = io._require("xarray")
        cols = self.columns()
        data: dict[str, Any] = {
            "x": (("time", "axis"), self.x, {"units": "m"}),
            "v": (("time", "axis"), self.v, {"units": "m/s"}),
        }
        for name in ("r", "energy", "j3", "bouncing_energy"):
            data[name] = ("time", cols[name][1], {"units": cols[name][0]})
        return xr.Dataset(
            data,
            coords={"time": ("time", self.t, {"units": "s"}), "axis": ["x", "y", "z"]},
            attrs={"pendulab": json.dumps(self.file_metadata(), sort_keys=True)},
        )

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes the run atomically; the format from the suffix (.csv, .parquet, .nc)."""
        return io.save(self, path)

    def animate(self, path: str | os.PathLike[str], settings: Any = None, **options: Any) -> Any:
        """Writes a movie of the swinging spring to ``path`` (.mp4, .webm or .gif): a coil from the
        pivot to the bob whose drawn length is |x| [m]; panels ``3d``, ``top``, ``z``. ``settings`` (a
        :class:`pendulab.animate.MovieSettings`) and ``options`` as :meth:`pendulab.Trajectory.animate`
        (fps, speed, duration, panels, size, trail [s], ...);
        returns a :class:`pendulab.animate.Movie`."""
        from ..animate import from_samples, render
        from ..animate.words import method_words, model_words

        sp = self.spring
        method = str(self.file_metadata()["method"])
        motion = from_samples(
            self.t,
            self.x,
            self.v,
            length=sp.equilibrium_length,
            g=sp.g,
            mass=sp.mass,
            label=f"{model_words('spring')}: {method_words(method)}",
            spring=True,
        )
        return render(motion, path, settings, **options)

    def __repr__(self) -> str:
        if len(self) == 0:
            return "SpringTrajectory(no samples)"
        return (
            f"SpringTrajectory({len(self)} samples, t = {number(self.t[0])} … {number(self.t[-1])} s, "
            f"r in [{number(self.r.min())}, {number(self.r.max())}] m"
            + (", INTERRUPTED" if self.interrupted else "")
            + ")"
        )

    def _repr_html_(self) -> str:
        sp = self.spring
        rows: list[Row] = [
            ("stiffness k", sp.k_over_m * sp.mass, "N/m"),
            ("rest length l₀", sp.rest_length, "m"),
            ("equilibrium length l", sp.equilibrium_length, "m"),
            ("samples", len(self), ""),
        ]
        if len(self):
            scale = max(abs(float(self.energy[0])), sp.mass * abs(sp.g) * sp.equilibrium_length, 1e-300)
            rows += [
                ("time span", f"{number(self.t[0])} … {number(self.t[-1])}", "s"),
                ("max |E − E₀| / (m|g|l)", number(relative_drift(self.energy, scale), 3), ""),
                ("max |J₃ − J₃₀|", number(relative_drift(self.j3, 1.0), 3), "kg m²/s"),
            ]
        return html_table("Swinging spring run", rows, note="tr.summary() for more")

    def summary(self) -> str:
        """A few lines: parameters, span, conservation of E and J₃ (both invariants, T-7.4), the
        range of the spring's length and of the bouncing energy."""
        sp, e, j = self.spring, self.energy, self.j3
        scale = max(abs(e[0]), sp.mass * abs(sp.g) * sp.equilibrium_length, 1e-300)
        bounce = self.bouncing_energy
        drift = np.max(np.abs(e - e[0])) / scale
        return "\n".join(
            [
                f"spring:   k = {sp.k_over_m * sp.mass:g} N/m (k/m = {sp.k_over_m:g} 1/s^2), "
                f"rest length {sp.rest_length:g} m, equilibrium length {sp.equilibrium_length:g} m, "
                f"m = {sp.mass} kg, g = {sp.g} m/s^2",
                f"method:   {self.file_metadata()['method']} (order {self.metadata.get('order', 2)}), "
                f"dt = {self.metadata.get('dt', float('nan')):g} s",
                f"span:     t = {self.t[0]:g} .. {self.t[-1]:g} s, {len(self)} samples",
                f"energy:   E0 = {e[0]:.12g} J, max |E - E0| / (m |g| l) = {drift:.3e}",
                f"J3:       J3_0 = {j[0]:.12g} kg m^2/s, max |J3 - J3_0| = {np.max(np.abs(j - j[0])):.3e}",
                f"length:   r in [{self.r.min():.6f}, {self.r.max():.6f}] m",
                f"bouncing: energy in [{bounce.min():.6g}, {bounce.max():.6g}] J",
            ]
        )


def simulate_spring(
    spring: SwingingSpring,
    x0: Any,
    v0: Any,
    t_end: float,
    *,
    dt: float = 1e-3,
    save_every: int = 1,
    order: int = 2,
) -> SpringTrajectory:
    """Integrates the swinging spring from x0 [m], v0 [m/s] to ``t_end`` [s] with step ``dt`` [s]
    (order 2: Störmer–Verlet, order 4: triple jump), keeping every ``save_every``-th step."""
    if not (math.isfinite(t_end) and t_end > 0 and math.isfinite(dt) and dt > 0):
        raise InvalidInputError(f"t_end = {t_end!r} s and dt = {dt!r} s must be finite and > 0")
    n = max(1, round(t_end / dt))
    out = spring_simulate(
        spring.spec,
        (np.ascontiguousarray(x0, dtype=np.float64), np.ascontiguousarray(v0, dtype=np.float64)),
        RunOptions(dt=float(t_end / n), save_every=int(save_every), order=int(order)),
        int(n),
    )
    meta = {"model": "spring", "dt": t_end / n, "order": order, "t_end": t_end}
    return SpringTrajectory(spring, out["t"], out["x"], out["v"], out["energy"], out["j3"], meta)
