"""A crane scenario file (``[crane]``) as the lab's crane mode starts it (docs/cranes.md "The lab's crane
mode"): the load (hook and payload as one mass, m₁ + m₂ [kg]) hanging at rest on the file's rope [m]
below the trolley at the origin, g [m/s²], and the crane mode's parameters from the file — the shaper
(``zv`` → 1, ``zvd`` → 2; another kind → 2, the mode's ZVD; none → 0), the move's ``v_max`` [m/s] and
``a_max`` [m/s²] (within the mode's limits), the steady wind's horizontal velocity [m/s] and the
payload's c_W·A [m²]. The file's move, hoist table, gust and turbulence are not played: the operator
drives the crane (``pendulab run`` runs the file as written). SI units."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..model import State

CRANE_MODEL = "crane"
"""The crane mode's model name (the core's ``live::crane::CRANE``)."""

_LIMITS = {"v_max": (0.01, 5.0), "a_max": (0.01, 5.0), "wind": (-50.0, 50.0), "drag_area": (0.0, 100.0)}


@dataclass(frozen=True)
class CranePendulum:
    """The crane mode's load as a scenario gives it to the lab: rope ``length`` [m], ``mass`` [kg],
    ``g`` [m/s²] and the mode's parameters ``extra`` (SI; the core checks them)."""

    length: float
    g: float
    mass: float
    extra: dict[str, float] = field(default_factory=dict)
    model: str = CRANE_MODEL


def _clip(name: str, value: float) -> float:
    lo, hi = _LIMITS[name]
    return float(min(max(value, lo), hi))


def crane_pendulum(spec: Any) -> CranePendulum:
    """The lab's crane of a crane file's tables (``pendulab.scenario.crane_schema.CraneSpec``)."""
    c = spec.crane
    mass = c.payload_mass + (c.hook_mass or 0.0)
    extra: dict[str, float] = {"shaping": 0.0}
    if spec.shaper is not None:
        extra["shaping"] = {"zv": 1.0}.get(spec.shaper.kind, 2.0)
    if spec.move is not None:
        extra["v_max"] = _clip("v_max", spec.move.v_max)
        extra["a_max"] = _clip("a_max", spec.move.a_max)
    if spec.wind is not None:
        w = spec.wind
        extra["wind_x"] = _clip("wind", w.velocity[0])
        extra["wind_y"] = _clip("wind", w.velocity[1])
        extra["drag_area"] = _clip("drag_area", w.area * w.drag_coefficient)
    return CranePendulum(length=c.rope, g=c.g, mass=mass, extra=extra)


def crane_start(p: CranePendulum) -> State:
    """The load at rest straight below the trolley: x = (0, 0, −l) [m], v = 0."""
    return State(np.array([0.0, 0.0, -p.length]), np.zeros(3))
