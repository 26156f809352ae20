"""Scenario files (TOML): ``load_scenario`` and ``Scenario`` (load, override, run, write); the tables
as pydantic models (``schema``), the error messages (``errors``), and building the pendulum or spring
and its start with the core's checks (``build``). Keys and units: ``docs/scenarios.md``."""

from .overrides import RunOverrides
from .scenario import (
    MODELS,
    SECTIONS,
    SPRING_ORDERS,
    UNITS,
    InitialSection,
    PendulumSection,
    Scenario,
    ScenarioError,
    ScenarioSpec,
    SimulationSection,
    load_scenario,
)

__all__ = [
    "MODELS",
    "SECTIONS",
    "SPRING_ORDERS",
    "UNITS",
    "InitialSection",
    "PendulumSection",
    "RunOverrides",
    "Scenario",
    "ScenarioError",
    "ScenarioSpec",
    "SimulationSection",
    "load_scenario",
]
