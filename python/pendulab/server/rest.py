"""The lab's computing REST endpoints (docs/web.md), free of FastAPI: each takes a validated request
(pydantic) and returns JSON-ready data or text. The page never computes physics; these do, with the core.

- :func:`exact_quantities` (``POST /api/exact``): the exact solution of the ideal pendulum's orbit.
- :func:`effective_potential` (``POST /api/effective_potential``): V_eff(θ) of T-2.5.
- :func:`scenario_toml` (``POST /api/scenario.toml``): a session's scenario as a file for ``pendulab run``.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from .._core import InvalidInputError
from ..integrators import _method_table, method_names, unknown_method
from ..model import Pendulum
from ..scenario import Scenario
from .commands import ExactRequest, Vec3, limit_bounds
from .notices import finite_or_none


def exact_quantities(req: ExactRequest) -> dict[str, Any]:
    """The exact-solution quantities of the orbit through a state (docs/theory.md §4–5), JSON-ready.

    Infinite or undefined values (the separatrix's period, the advance of planar motion) are null.
    """
    from ..theory.exact import exact

    p = Pendulum(length=req.length, g=req.g, mass=req.mass)
    state = req.to_state(p)
    sol = exact(p, state)
    phases: dict[str, float | None] | None
    try:
        ph = sol.phases()
        phases = {"total": ph.total, "dynamic": ph.dynamic, "geometric": ph.geometric}
        phases_note = None
    except InvalidInputError as e:
        phases, phases_note = None, " ".join(str(e).split())
    return {
        "kind": sol.kind,
        "energy": p.energy(state),
        "j3": p.j3(state),
        "omega0": sol.omega0,
        "turning_heights": [finite_or_none(z) for z in sol.turning_heights],
        "modulus": finite_or_none(sol.modulus),
        "period_z": finite_or_none(sol.period_z),
        "period_z_infinite": sol.period_z is not None and sol.period_z == float("inf"),
        "azimuth_advance": finite_or_none(sol.azimuth_advance),
        "rotation_number": finite_or_none(sol.rotation_number),
        "phases": phases,
        "phases_note": phases_note,
    }


class _Request(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


class PotentialRequest(_Request):
    """Body of ``POST /api/effective_potential``: l [m], m [kg], g [m/s²], J₃ [kg m²/s], n points."""

    length: float = Field(1.0, description="rod length l in m", **limit_bounds("length"))
    mass: float = Field(1.0, description="bob mass m in kg", **limit_bounds("mass"))
    g: float = Field(9.81, description="gravity g in m/s²", **limit_bounds("g"))
    j3: float = Field(0.0, description="vertical angular momentum J₃ in kg m²/s", ge=-1e9, le=1e9)
    n: int = Field(400, description="number of angles θ", ge=16, le=4000)


def effective_potential(req: PotentialRequest) -> dict[str, Any]:
    """V_eff(θ) = −m g l cos θ + J₃²/(2 m l² sin²θ) [J] (T-2.5) on n angles θ ∈ (0, π) [rad] (the poles,
    where it is infinite for J₃ ≠ 0, left out), with its minimum (the conical orbit of this J₃)."""
    theta = np.linspace(0.0, np.pi, req.n + 2)[1:-1]
    m, ell, g = req.mass, req.length, req.g
    v = -m * g * ell * np.cos(theta) + req.j3**2 / (2 * m * ell**2 * np.sin(theta) ** 2)
    k = int(np.argmin(v))
    return {
        "theta": theta.tolist(),
        "v_eff": v.tolist(),
        "minimum": {"theta": float(theta[k]), "v_eff": float(v[k])},
        "units": {"theta": "rad", "v_eff": "J"},
    }


class ScenarioRequest(_Request):
    """Body of ``POST /api/scenario.toml``: a session's scenario as its ``status`` notice states it."""

    title: str | None = Field(None, max_length=200)
    model: str = Field("ideal", max_length=40)
    length: float = Field(1.0, description="rod length l in m", **limit_bounds("length"))
    mass: float = Field(1.0, description="bob mass m in kg", **limit_bounds("mass"))
    g: float = Field(9.81, description="gravity g in m/s²", **limit_bounds("g"))
    params: dict[str, float] = Field(default_factory=dict, description="the model's own parameters (SI)")
    x: Vec3 = Field(description="start position in m")
    v: Vec3 = Field(description="start velocity in m/s")
    method: str = Field("rattle", max_length=40)
    dt: float | None = Field(
        1e-3,
        description="step size in s (fixed-step methods; not written for an adaptive one)",
        **limit_bounds("dt"),
    )
    rtol: float | None = Field(None, description="relative tolerance (adaptive methods)", ge=1e-15, le=1)
    atol: float | None = Field(None, description="absolute tolerance in m and m/s (adaptive methods)", ge=0)
    t0: float = Field(0.0, description="start time in s", ge=-1e12, le=1e12)
    t_end: float = Field(100.0, description="end time in s", ge=-1e12, le=1e12)


def scenario_toml(req: ScenarioRequest) -> str:
    """The scenario as a TOML file that ``pendulab run`` accepts (and that loads back to the same
    pendulum, start and method). A fixed-step method's ``dt`` is written; an adaptive method's
    (``dop853``) is not (in a file it would be the first step, and the lab's DOP853 lands on its frames'
    times): its ``rtol`` and ``atol`` are, as given (else the defaults apply). Raises
    :class:`pendulab.ScenarioError` naming what is wrong."""
    if req.method not in method_names():
        raise InvalidInputError(unknown_method(req.method))
    pendulum: dict[str, Any] = {"length": req.length, "mass": req.mass, "g": req.g}
    if req.model != "ideal" or req.params:
        pendulum |= {"model": req.model, **req.params}
    simulation: dict[str, Any] = {"t0": req.t0, "t_end": req.t_end, "method": req.method}
    if _method_table()[req.method]["adaptive"]:
        simulation |= {k: v for k, v in (("rtol", req.rtol), ("atol", req.atol)) if v is not None}
    elif req.dt is not None:
        simulation["dt"] = req.dt
    data: dict[str, Any] = {
        "pendulum": pendulum,
        "initial": {"x": list(req.x), "v": list(req.v)},
        "simulation": simulation,
    }
    if req.title:
        data["title"] = req.title
    return Scenario.from_dict(data, "<the lab's scenario>").to_toml()
