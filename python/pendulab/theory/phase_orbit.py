"""The reduced orbit behind the geometric phase (docs/theory.md T-5.1): one z-period of an exact
orbit in the (σ₁, p_z) plane, σ₁ = z/l [1], p_z = σ₂/(1 − σ₁²) [1/s] with σ₂ = ż/l, run clockwise,
and the area it encloses, A = ∮ p_z dσ₁ [1/s]. With J = J₃/(m l²) [1/s], Δφ_geom = −A/J; the area
is taken from the quadrature behind :attr:`pendulab.Phases.geometric` (A = −J Δφ_geom), the curve
from ``samples`` exact states. What :func:`pendulab.plot.plot_phases` draws.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .._core import InvalidInputError
from ..model import FloatArray
from .exact import ExactSolution, Phases
from .reduce import reduce


@dataclass(frozen=True)
class PhaseOrbit:
    """One z-period of the reduced orbit: ``sigma1`` [1] and ``p_z`` [1/s] at ``samples`` times from
    t = 0 (clockwise), ``j`` = J₃/(m l²) [1/s], ``area`` = ∮ p_z dσ₁ = −J Δφ_geom [1/s], ``phases``
    (T-5.1) and ``conical`` (constant height: the orbit is a point and encloses nothing)."""

    sigma1: FloatArray
    p_z: FloatArray
    j: float
    area: float
    phases: Phases
    conical: bool


def phase_orbit(sol: ExactSolution, samples: int = 4001, phases: Phases | None = None) -> PhaseOrbit:
    """The reduced orbit of ``sol`` over one z-period from ``samples`` (≥ 16) exact states, with its
    enclosed area; ``phases``: ``sol.phases()`` if already computed. Needs J₃ ≠ 0 and g ≠ 0 (kinds
    ``generic``, ``conical``), as :meth:`ExactSolution.phases` does."""
    if samples < 16:
        raise InvalidInputError(f"samples = {samples} must be at least 16")
    phases = sol.phases() if phases is None else phases
    tz = sol.period_z
    if tz is None or not math.isfinite(tz):  # pragma: no cover - generic and conical orbits have one
        raise InvalidInputError(f"the z-period is {tz}; no closed reduced orbit to draw")
    red = reduce(sol.trajectory(np.linspace(0.0, tz, samples)))
    s1, s2 = red.sigma[:, 0], red.sigma[:, 1]
    pz = s2 / ((1.0 - s1) * (1.0 + s1))
    j = float(np.mean(red.j))
    area = -j * phases.geometric  # ∮ p_z dσ₁ from the quadrature behind Phases.geometric
    return PhaseOrbit(s1, pz, j, area, phases, sol.kind == "conical")
