"""The schema of a scenario file: pydantic models of its tables and the keys each one takes.

Holds :class:`ScenarioSpec` (the whole file: ``title``, ``description`` and the three tables) and
the tables :data:`SECTIONS` and :data:`UNITS`, and re-exports the tables' own modules:
:class:`PendulumSection` (``[pendulum]``: the model, length [m], mass [kg], g [m/s²], the model's own
parameters in the registry's SI units or ``<name>_deg`` in degrees, the sampled pivot's times [s]
and positions [m]; :mod:`pendulab.scenario.pendulum_table`, with the helpers naming each model's
keys), :class:`InitialSection` (``[initial]``: θ, φ [rad] or ``*_deg`` [degrees], θ̇, φ̇ [rad/s], or
a Cartesian x [m] and v [m/s]; :mod:`pendulab.scenario.initial_table`), :class:`SimulationSection`
(``[simulation]``: t0, t_end, dt, save_at [s], rtol, atol [m, m/s], save_every [steps], method;
:mod:`pendulab.scenario.simulation_table`), and what they share (strictness, bounds, printable text:
:mod:`pendulab.scenario.table_base`). Messages of the validators name the key, the bad value and what
is allowed; the formatting of pydantic's own errors lives in :mod:`pendulab.scenario.errors`, the
checks that need the core (a start on TS², memory of the saved samples) in
:mod:`pendulab.scenario.build`.
"""

from __future__ import annotations

from typing import Any

from pydantic import Field, field_validator

from .initial_table import _ANGLE_KEYS as _ANGLE_KEYS
from .initial_table import _CARTESIAN_KEYS as _CARTESIAN_KEYS
from .initial_table import InitialSection
from .pendulum_table import _COMMON_KEYS as _COMMON_KEYS
from .pendulum_table import _MODEL_SPECS as _MODEL_SPECS
from .pendulum_table import MODELS as MODELS
from .pendulum_table import PendulumSection
from .pendulum_table import _degree_keys as _degree_keys
from .pendulum_table import _file_keys as _file_keys
from .pendulum_table import _model_keys as _model_keys
from .pendulum_table import _own_params as _own_params
from .simulation_table import _U64_LIMIT as _U64_LIMIT
from .simulation_table import SimulationSection
from .table_base import _DEG as _DEG
from .table_base import _VEC3 as _VEC3
from .table_base import _is_control as _is_control
from .table_base import _lim as _lim
from .table_base import _Position as _Position
from .table_base import _Section, printable
from .table_base import _show as _show
from .table_base import _Time as _Time
from .table_base import _toml_like as _toml_like
from .table_base import _Velocity as _Velocity


class ScenarioSpec(_Section):
    """The whole file: optional ``title`` and ``description``, then the three sections."""

    title: str | None = Field(None, description="a one-line title (string, optional)")
    description: str | None = Field(None, description="free text (string, optional)")
    pendulum: PendulumSection = Field(description="the table [pendulum]")
    initial: InitialSection = Field(description="the table [initial]")
    simulation: SimulationSection = Field(description="the table [simulation]")

    @field_validator("title", "description")
    @classmethod
    def _printable(cls, value: str | None, info: Any) -> str | None:
        """Text that reaches terminals and pages: no control characters (:func:`printable`)."""
        return (
            None if value is None else printable(value, info.field_name, one_line=info.field_name == "title")
        )


SECTIONS: dict[str, type[_Section]] = {
    "pendulum": PendulumSection,
    "initial": InitialSection,
    "simulation": SimulationSection,
}

UNITS: dict[str, dict[str, str]] = {
    "pendulum": {"length": "m", "mass": "kg", "g": "m/s²", "pivot_times": "s", "pivot_positions": "m"},
    "initial": {
        "theta": "rad",
        "theta_deg": "degrees",
        "phi": "rad",
        "phi_deg": "degrees",
        "theta_dot": "rad/s",
        "phi_dot": "rad/s",
        "x": "m",
        "v": "m/s",
    },
    "simulation": {
        "t_end": "s",
        "t0": "s",
        "dt": "s",
        "atol": "m, m/s",
        "save_every": "steps",
        "save_at": "s",
    },
}
"""The unit of every dimensioned key (written as comments by :meth:`Scenario.to_toml`)."""
