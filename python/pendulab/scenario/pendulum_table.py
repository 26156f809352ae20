"""The ``[pendulum]`` table of a scenario file: the model (one of the core's registry, ``pendulab
models``; docs/theory.md §7 for their equations), length l [m], mass m [kg], g [m/s²] (g > 0 pulls
along −z), the model's own parameters in the registry's SI units or, for an angle in rad, as
``<name>_deg`` in degrees, and the ``sampled_pivot`` model's pivot times [s] and positions [m]; with
the helpers that name each model's keys (used by the error messages of
:mod:`pendulab.scenario.errors` and by writing a file). The ranges of the model's own parameters are
checked by the core when the scenario is built (:mod:`pendulab.scenario.build`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from pydantic import Field, field_validator, model_validator

from .._core import models
from ..validate import COMMON, abbreviate
from .table_base import _DEG, _lim, _Position, _Section, _show, _Time

if TYPE_CHECKING:
    from .._core import ParamSpec

_MODEL_SPECS = {m["name"]: m for m in models()}
MODELS = tuple(_MODEL_SPECS)
"""Pendulum models a scenario may name (``[pendulum] model``; their parameters: ``pendulab models``)."""


_COMMON_KEYS = ("model", "length", "mass", "g")


def _own_params(model: str) -> dict[str, ParamSpec]:
    """The model's own parameters (beyond length, mass and g) by name."""
    spec = _MODEL_SPECS.get(model)
    return {} if spec is None else {p["name"]: p for p in spec["params"] if p["name"] not in _COMMON_KEYS}


def _degree_keys(model: str) -> dict[str, str]:
    """``<name>_deg`` -> ``<name>`` for the model's angles in rad (e.g. latitude_deg, forcing_phase_deg)."""
    return {f"{name}_deg": name for name, p in _own_params(model).items() if p["unit"] == "rad"}


def _model_keys(model: str) -> list[str]:
    """Every key of ``[pendulum]`` for ``model``: the common ones, the model's own, their ``_deg`` forms."""
    degrees = {rad: deg for deg, rad in _degree_keys(model).items()}
    own = [k for name in _own_params(model) for k in (name, degrees.get(name)) if k is not None]
    return [*_COMMON_KEYS, *own]


def _file_keys(model: str) -> list[str]:
    """Every key ``[pendulum]`` takes for ``model`` (:func:`_model_keys`, and the ``sampled_pivot``
    model's pivot_times [s] and pivot_positions [m]): the allowed keys an error lists."""
    return [*_model_keys(model), *(("pivot_times", "pivot_positions") if model == "sampled_pivot" else ())]


class PendulumSection(_Section):
    """``[pendulum]``: the model and its parameters. Besides length, mass and g, the keys of the chosen
    model are allowed (``pendulab models``; SI units, e.g. ``damping = 0.05`` in 1/s; an angle in rad
    may instead be given in degrees as ``<name>_deg``, e.g. ``latitude_deg = 49.0``); they are
    collected into ``params`` and checked by the core (ranges) when the scenario is built."""

    model: str = Field("ideal", description=f"the pendulum model, one of: {', '.join(map(repr, MODELS))}")
    length: float = Field(description=f"rod length l: {COMMON['length']['allowed']}", **_lim("length"))
    mass: float = Field(description=f"bob mass m: {COMMON['mass']['allowed']}", **_lim("mass"))
    g: float = Field(
        9.81,
        description=f"gravitational acceleration: {COMMON['g']['allowed']} (g > 0 pulls along -z)",
        **_lim("g"),
    )
    params: dict[str, float] = Field(
        default_factory=dict, description="the model's own parameters (SI units; `pendulab models`)"
    )
    pivot_times: list[_Time] | None = Field(
        None,
        min_length=4,
        description="model 'sampled_pivot': times of the pivot samples in s (>= 4, strictly increasing)",
    )
    pivot_positions: list[list[_Position]] | None = Field(
        None, description="model 'sampled_pivot': pivot positions in m, one [x, y, z] per time"
    )

    @model_validator(mode="before")
    @classmethod
    def _collect_params(cls, data: Any) -> Any:
        """Moves the chosen model's own keys into ``params``; anything else stays and, if unknown, is
        reported as an unknown key (``params`` itself is internal, not a key of the file)."""
        if isinstance(data, dict):
            if "params" in data:
                raise ValueError(
                    f"unknown key params = {_show(data['params'])}: write the model's parameters directly "
                    f"in [pendulum] (e.g. damping = 0.05); keys of model {data.get('model', 'ideal')!r}: "
                    f"{', '.join(_file_keys(str(data.get('model', 'ideal'))))}"
                )
            own = set(_model_keys(str(data.get("model", "ideal")))[len(_COMMON_KEYS) :])
            moved = {k: v for k, v in data.items() if k in own}
            if moved:
                data = {k: v for k, v in data.items() if k not in own}
                data["params"] = moved
        return data

    @field_validator("model")
    @classmethod
    def _known_model(cls, name: str) -> str:
        if name not in MODELS:
            raise ValueError(
                f"unknown model {abbreviate(repr(name))}; allowed: {', '.join(map(repr, MODELS))}"
            )
        return name

    @model_validator(mode="after")
    def _rad_or_deg(self) -> PendulumSection:
        for deg, rad in _degree_keys(self.model).items():
            if deg in self.params and rad in self.params:
                raise ValueError(
                    f"give either {rad} (rad) or {deg} (degrees), not both: "
                    f"{rad} = {self.params[rad]!r}, {deg} = {self.params[deg]!r}"
                )
        return self

    @model_validator(mode="after")
    def _pivot_samples(self) -> PendulumSection:
        given = self.pivot_times is not None or self.pivot_positions is not None
        if self.model == "sampled_pivot" and (self.pivot_times is None or self.pivot_positions is None):
            raise ValueError(
                "model 'sampled_pivot' needs pivot_times (s) and pivot_positions (m, [x, y, z] per time)"
            )
        if given and self.model != "sampled_pivot":
            raise ValueError(
                f"pivot_times and pivot_positions belong to model 'sampled_pivot', not {self.model!r}"
            )
        return self

    def pivot_samples(self) -> tuple[list[float], list[list[float]]] | None:
        """The ``sampled_pivot`` model's samples (times [s], positions [m]), else None."""
        if self.pivot_times is None or self.pivot_positions is None:
            return None
        return self.pivot_times, self.pivot_positions

    def extras(self) -> dict[str, float]:
        """The model's own parameters in SI units (``<name>_deg`` converted to ``<name>`` in rad)."""
        degrees = _degree_keys(self.model)
        return {
            degrees.get(k, k): float(v) * _DEG if k in degrees else float(v) for k, v in self.params.items()
        }
