"""The lab's geometric views of the ideal pendulum (docs/web.md), computed here with the core:

- :func:`reduced_view` (``POST /api/reduced``): Holm's Figure 2 in σ-space (docs/theory.md §3) — the orbit
  (σ₁, σ₂, σ₃) over one z-period from :func:`pendulab.reduce`, the J₃ surface
  C = σ₃(1 − σ₁²) − σ₂² − σ₆² = 0 on a grid, the energy plane H = ½σ₃ + (g/l)σ₁ and the current point.
- :func:`em_view` (``POST /api/em_map``): the energy–momentum map's boundary (the conical orbits, T-6.1)
  with the bottom, the top and the current (J₃, E).

σ in unit-length variables (σ₁ = z/l [1], σ₂ = ż/l [1/s], σ₃ = |v|²/l² [1/s²], σ₆ = J₃/(m l²) [1/s]);
J₃ [kg m²/s], E [J].
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
from pydantic import Field

from ..model import Pendulum
from ..theory.em_map import conical_boundary
from ..theory.exact import exact
from ..theory.reduce import invariants, reduce
from ..trajectory import Trajectory
from .protocol import ExactRequest

MAX_ORBIT_TIME = 30.0
"""Longest stretch of the orbit [s] the reduced view shows (an orbit near the separatrix has a very long
z-period; its curve is then the part covered in this time)."""


class ReducedRequest(ExactRequest):
    """Body of ``POST /api/reduced``: l [m], m [kg], g [m/s²], a state (as ``set_state``), n points."""

    n: int = Field(400, description="points on the orbit", ge=16, le=4000)
    grid: int = Field(41, description="grid points per axis of the J₃ surface", ge=5, le=121)


class EMRequest(ExactRequest):
    """Body of ``POST /api/em_map``: l [m], m [kg], g [m/s²] (≠ 0) and a state (its (J₃, E) is marked)."""

    n: int = Field(401, description="points on the boundary", ge=16, le=4001)


def _pendulum(req: ExactRequest) -> Pendulum:
    return Pendulum(length=req.length, g=req.g, mass=req.mass)


def reduced_view(req: ReducedRequest) -> dict[str, Any]:
    """The orbit, the J₃ surface, the energy plane and the point in σ-space (module docstring)."""
    p = _pendulum(req)
    state = req.to_state(p)
    sol = exact(p, state)
    period = sol.period_z
    span = period if period is not None and math.isfinite(period) and period > 0 else MAX_ORBIT_TIME
    span = min(span, MAX_ORBIT_TIME)
    t = np.linspace(0.0, span, req.n)
    x, v = sol.state(t)
    red = reduce(Trajectory(p, t, x, v, "exact", {"t_end": span}, {}))
    sigma = invariants(p, state.x, state.v)[0]
    j = float(sigma[5])
    gamma = p.g / p.length
    h = 0.5 * float(sigma[2]) + gamma * float(sigma[0])
    # the surface σ₃ = (σ₂² + j²)/(1 − σ₁²) over σ₁ ∈ (−1, 1), σ₂ within the orbit's span and a margin
    s2max = max(1.5 * float(np.max(np.abs(red.sigma[:, 1]))), 1.0, abs(j))
    s1 = np.linspace(-0.95, 0.95, req.grid)
    s2 = np.linspace(-s2max, s2max, req.grid)
    s3 = (s2[None, :] ** 2 + j * j) / (1.0 - s1[:, None] ** 2)
    return {
        "orbit": {
            "sigma1": red.sigma[:, 0].tolist(),
            "sigma2": red.sigma[:, 1].tolist(),
            "sigma3": red.sigma[:, 2].tolist(),
        },
        "orbit_time": span,
        "surface": {"sigma1": s1.tolist(), "sigma2": s2.tolist(), "sigma3": s3.tolist()},
        "plane": {"h": h, "gamma": gamma},
        "point": [float(sigma[0]), float(sigma[1]), float(sigma[2])],
        "j": j,
        "units": {
            "sigma1": "1",
            "sigma2": "1/s",
            "sigma3": "1/s^2",
            "h": "1/s^2",
            "gamma": "1/s^2",
            "j": "1/s",
        },
    }


def em_view(req: EMRequest) -> dict[str, Any]:
    """The boundary of the image of (J₃, E), the equilibria and the current point (module docstring)."""
    p = _pendulum(req)
    state = req.to_state(p)
    j3, energy = conical_boundary(p, req.n)
    weight = p.mass * abs(p.g) * p.length
    d = p.diagnostics(state.x, state.v)
    return {
        "boundary": {"j3": j3.tolist(), "energy": energy.tolist()},
        "bottom": {"j3": 0.0, "energy": -weight},
        "top": {"j3": 0.0, "energy": weight},
        "point": {"j3": float(d["j3"][0]), "energy": float(d["energy"][0])},
        "units": {"j3": "kg m^2/s", "energy": "J"},
    }
