"""The swinging spring (elastic pendulum, THEORY.md T-7.4): a bob of mass m [kg] on a spring of
stiffness k [N/m] and rest length l₀ [m] from a fixed pivot, gravity g [m/s²] along −z. The state is
unconstrained (r [m], v [m/s]); E and J₃ are conserved and kept by the symplectic Störmer–Verlet
method (order 2) or its triple jump (order 4). At the 1:1:2 resonance √(k/m) = 2√(g/l), with
l = l₀ + m g/k, energy passes between bouncing and swinging and the swing plane turns in steps.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from . import _core
from .model import FloatArray


@dataclass(frozen=True)
class SwingingSpring:
    """Stiffness per unit mass ``k_over_m`` [1/s²], rest length ``rest_length`` [m], ``g`` [m/s²],
    ``mass`` [kg]. ``SwingingSpring.resonant(l)`` gives the 1:1:2 resonance at equilibrium length l."""

    k_over_m: float
    rest_length: float
    g: float = 9.81
    mass: float = 1.0

    @classmethod
    def resonant(cls, equilibrium_length: float = 1.0, g: float = 9.81, mass: float = 1.0) -> SwingingSpring:
        """k/m = 4g/l and l₀ = 3l/4, so that √(k/m) = 2√(g/l) (T-7.4)."""
        return cls(4.0 * g / equilibrium_length, 0.75 * equilibrium_length, g, mass)

    @property
    def equilibrium_length(self) -> float:
        """l = l₀ + g/(k/m) [m]."""
        return self.rest_length + self.g / self.k_over_m


@dataclass(frozen=True)
class SpringTrajectory:
    """Times ``t`` [s], positions ``x`` and velocities ``v`` (N, 3) [m, m/s], ``energy`` [J], ``j3``
    [kg m²/s], and ``bouncing_energy`` [J]: the radial (spring) part ½m ṙ² + ½k(|r| − l)²."""

    spring: SwingingSpring
    t: FloatArray
    x: FloatArray
    v: FloatArray
    energy: FloatArray
    j3: FloatArray
    metadata: dict[str, Any] = field(default_factory=dict)

    @property
    def bouncing_energy(self) -> FloatArray:
        r = np.linalg.norm(self.x, axis=1)
        rdot = np.einsum("ij,ij->i", self.x, self.v) / r
        dl = r - self.spring.equilibrium_length
        return self.spring.mass * (0.5 * rdot**2 + 0.5 * self.spring.k_over_m * dl**2)


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
        raise _core.InvalidInputError(f"t_end = {t_end!r} s and dt = {dt!r} s must be finite and > 0")
    n = max(1, round(t_end / dt))
    out = _core.spring_simulate(
        float(spring.k_over_m),
        float(spring.rest_length),
        float(spring.g),
        float(spring.mass),
        np.ascontiguousarray(np.asarray(x0, dtype=np.float64)),
        np.ascontiguousarray(np.asarray(v0, dtype=np.float64)),
        float(t_end / n),
        int(n),
        int(save_every),
        int(order),
    )
    meta = {"model": "spring", "dt": t_end / n, "order": order, "t_end": t_end}
    return SpringTrajectory(spring, out["t"], out["x"], out["v"], out["energy"], out["j3"], meta)
