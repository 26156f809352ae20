"""Scenario files: a pendulum, an initial state and the simulation settings in one TOML file.

Units are SI: length [m], mass [kg], g [m/s²], angles [rad] (keys ending in ``_deg``: degrees),
angular rates [rad/s], position x [m], velocity v [m/s], times t0, t_end, dt, save_at [s]. The
format, every key and its default are described in ``docs/scenarios.md``; an example::

    title = "Rosette"
    [pendulum]
    model = "ideal"
    length = 1.0      # m
    mass = 1.0        # kg
    g = 9.81          # m/s²
    [initial]
    theta_deg = 60.0  # from the downward vertical
    phi_dot = 2.0     # rad/s
    [simulation]
    t_end = 100.0     # s
    method = "rattle"
    dt = 1.0e-3       # s
    save_every = 10

Other models (THEORY.md §7; ``pendulab models``) take their own keys in ``[pendulum]`` next to
``model``, in the units the registry gives (e.g. ``model = "damped"``, ``damping = 0.05`` in 1/s); an
angle in rad may instead be given in degrees as ``<name>_deg`` (``latitude_deg = 49.0``).

Files are validated with pydantic (unknown keys, wrong types, NaN/inf, out-of-range values and
contradictions are refused) and then by the core (the start must lie on TS², the saved samples
must fit in memory). Every problem raises :class:`ScenarioError` naming the file, the dotted key,
the bad value and what is allowed.
"""

from __future__ import annotations

import dataclasses
import difflib
import json
import math
import os
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator, model_validator
from pydantic_core import ErrorDetails

from . import _core
from .io import atomic_path
from .model import Pendulum, State, _frozen
from .simulate import DEFAULTS, method_names, simulate
from .spring import SpringTrajectory, SwingingSpring, simulate_spring
from .trajectory import Trajectory

MODELS = tuple(m["name"] for m in _core.models())
"""Pendulum models a scenario may name (``[pendulum] model``; their parameters: ``pendulab models``)."""

SPRING_ORDERS = {"rattle": 2, "rattle4": 4}
"""Methods a ``model = "spring"`` scenario may name: the unconstrained Störmer–Verlet and triple jump."""

_DEG = math.pi / 180
_U64_LIMIT = 2**63  # save_every must fit the core's unsigned 64-bit counter


class ScenarioError(ValueError):
    """A scenario file (or string) cannot be used.

    ``source`` names the file, ``line`` the line of a TOML syntax error (else ``None``) and
    ``problems`` lists one readable message per problem, each naming the key, the bad value and
    what is allowed. ``str(error)`` is a single line: ``"<source>: <problem>"``.
    """

    def __init__(self, source: str, problems: str | list[str], line: int | None = None) -> None:
        self.source = source
        self.line = line
        self.problems = [problems] if isinstance(problems, str) else list(problems)
        where = self.location
        if len(self.problems) == 1:
            text = f"{where}: {self.problems[0]}"
        else:
            numbered = " ".join(f"({k}) {p}" for k, p in enumerate(self.problems, 1))
            text = f"{where}: {len(self.problems)} problems: {numbered}"
        super().__init__(text)

    @property
    def location(self) -> str:
        """The file name, with the line number for TOML syntax errors."""
        return self.source if self.line is None else f"{self.source}, line {self.line}"


class _Section(BaseModel):
    """Common settings: unknown keys are errors, no type coercion (a string is not a number), no NaN/inf."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


_VEC3 = {"min_length": 3, "max_length": 3}


_COMMON_KEYS = ("model", "length", "mass", "g")
_MODEL_SPECS = {m["name"]: m for m in _core.models()}


def _own_params(model: str) -> dict[str, _core.ParamSpec]:
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


def _models_with(key: str) -> list[str]:
    """The models that take ``key`` in ``[pendulum]``."""
    return [name for name in _MODEL_SPECS if key in _model_keys(name)[len(_COMMON_KEYS) :]]


class PendulumSection(_Section):
    """``[pendulum]``: the model and its parameters. Besides length, mass and g, the keys of the chosen
    model are allowed (``pendulab models``; SI units, e.g. ``damping = 0.05`` in 1/s; an angle in rad
    may instead be given in degrees as ``<name>_deg``, e.g. ``latitude_deg = 49.0``); they are
    collected into ``params`` and checked by the core (ranges) when the scenario is built."""

    model: str = Field("ideal", description=f"the pendulum model, one of: {', '.join(map(repr, MODELS))}")
    length: float = Field(gt=0, description="rod length l in m, a finite number > 0")
    mass: float = Field(gt=0, description="bob mass m in kg, a finite number > 0")
    g: float = Field(
        9.81, description="gravitational acceleration in m/s², any finite number (g > 0 pulls along -z)"
    )
    params: dict[str, float] = Field(
        default_factory=dict, description="the model's own parameters (SI units; `pendulab models`)"
    )
    pivot_times: list[float] | None = Field(
        None,
        min_length=4,
        description="model 'sampled_pivot': times of the pivot samples in s (>= 4, strictly increasing)",
    )
    pivot_positions: list[list[float]] | None = Field(
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
                    f"{', '.join(_model_keys(str(data.get('model', 'ideal'))))}"
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
            raise ValueError(f"unknown model {name!r}; allowed: {', '.join(map(repr, MODELS))}")
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


_ANGLE_KEYS = ("theta", "theta_deg", "phi", "phi_deg", "theta_dot", "phi_dot")
_CARTESIAN_KEYS = ("x", "v", "project")


class InitialSection(_Section):
    """``[initial]``: the start, either as angles or as Cartesian position and velocity."""

    theta: float | None = Field(None, description="polar angle from the downward vertical in rad (finite)")
    theta_deg: float | None = Field(None, description="polar angle from the downward vertical in degrees")
    phi: float | None = Field(None, description="azimuth atan2(y, x) in rad (finite; default 0)")
    phi_deg: float | None = Field(None, description="azimuth atan2(y, x) in degrees (default 0)")
    theta_dot: float | None = Field(None, description="polar angular rate in rad/s (finite; default 0)")
    phi_dot: float | None = Field(None, description="azimuthal angular rate in rad/s (finite; default 0)")
    x: list[float] | None = Field(None, description="position of the bob in m, 3 finite numbers", **_VEC3)
    v: list[float] | None = Field(None, description="velocity of the bob in m/s, 3 finite numbers", **_VEC3)
    project: bool | None = Field(
        None, description="true or false: move a Cartesian start onto TS² (default false: refuse it)"
    )

    @model_validator(mode="after")
    def _one_form(self) -> InitialSection:
        given = {k for k in (*_ANGLE_KEYS, *_CARTESIAN_KEYS) if getattr(self, k) is not None}
        for rad, deg in (("theta", "theta_deg"), ("phi", "phi_deg")):
            if rad in given and deg in given:
                raise ValueError(
                    f"give either {rad} (rad) or {deg} (degrees), not both: "
                    f"{rad} = {getattr(self, rad)!r}, {deg} = {getattr(self, deg)!r}"
                )
        angles = sorted(given & set(_ANGLE_KEYS))
        cartesian = sorted(given & set(_CARTESIAN_KEYS))
        if angles and cartesian == ["project"]:
            raise ValueError(
                f"project = {_show(self.project)} applies only to a Cartesian start (x, v); "
                "a start given by angles is always on TS²"
            )
        if angles and cartesian:
            raise ValueError(
                "give the start either as angles (theta_deg or theta, phi_deg or phi, theta_dot, phi_dot) "
                f"or as Cartesian x and v, not both: got {', '.join(angles)} and {', '.join(cartesian)}"
            )
        if cartesian:
            missing = [k for k in ("x", "v") if k not in given]
            if missing:
                raise ValueError(
                    f"{' and '.join(missing)} missing: a Cartesian start needs both x (3 numbers, m) "
                    "and v (3 numbers, m/s)"
                )
        elif "theta" not in given and "theta_deg" not in given:
            raise ValueError(
                "no initial polar angle: give theta_deg (degrees) or theta (rad), "
                "or a Cartesian start x = [..] (m) and v = [..] (m/s)"
            )
        return self

    @property
    def cartesian(self) -> bool:
        """True for a start given as x and v."""
        return self.x is not None

    def angles(self) -> tuple[float, float, float, float]:
        """(θ [rad], φ [rad], θ̇ [rad/s], φ̇ [rad/s]) of an angle start; degrees converted as deg·π/180."""
        theta = self.theta if self.theta is not None else float(self.theta_deg or 0.0) * _DEG
        phi = self.phi if self.phi is not None else float(self.phi_deg or 0.0) * _DEG
        return theta, phi, self.theta_dot or 0.0, self.phi_dot or 0.0


class SimulationSection(_Section):
    """``[simulation]``: time span, integrator, step size or tolerances, and what to save."""

    t_end: float = Field(description="end time in s, a finite number > t0")
    t0: float = Field(0.0, description="start time in s, a finite number (default 0)")
    method: str = Field(
        str(DEFAULTS["method"]), description="an integrator name (see `pendulab methods`), default 'rattle'"
    )
    dt: float | None = Field(
        None,
        gt=0,
        description="step size in s, a finite number > 0 (default 1e-3 s; adaptive methods: the first step)",
    )
    rtol: float | None = Field(
        None,
        ge=1e-15,
        le=1,
        description="relative tolerance of adaptive methods, a number in [1e-15, 1] (default 1e-10)",
    )
    atol: float | None = Field(
        None,
        ge=0,
        description="absolute tolerance of adaptive methods in m and m/s, finite and >= 0 (default 1e-12)",
    )
    save_every: int | None = Field(
        None,
        ge=1,
        lt=_U64_LIMIT,
        description="an integer >= 1: keep every n-th step plus the first and last state (default 1)",
    )
    save_at: list[float] | None = Field(
        None,
        min_length=1,
        description="a non-empty array of strictly increasing times in s within [t0, t_end]",
    )

    @field_validator("method")
    @classmethod
    def _known_method(cls, name: str) -> str:
        names = method_names()
        if name not in names:
            hint = difflib.get_close_matches(name, names, n=1)
            suggestion = f" (did you mean {hint[0]!r}?)" if hint else ""
            raise ValueError(f"unknown method {name!r}{suggestion}; available: {', '.join(names)}")
        return name

    @model_validator(mode="after")
    def _consistent(self) -> SimulationSection:
        if not self.t_end > self.t0:
            raise ValueError(f"t_end = {self.t_end!r} s must be after t0 = {self.t0!r} s")
        if self.save_every is not None and self.save_at is not None:
            raise ValueError(
                f"give either save_every (= {self.save_every!r}) or save_at (= {self.save_at!r}), not both"
            )
        if self.save_at is not None:
            for a, b in zip(self.save_at, self.save_at[1:], strict=False):
                if not b > a:
                    raise ValueError(
                        f"save_at times must be strictly increasing, but {a!r} s is followed by {b!r} s"
                    )
            outside = [t for t in self.save_at if not self.t0 <= t <= self.t_end]
            if outside:
                raise ValueError(
                    f"save_at time {outside[0]!r} s is outside [t0, t_end] = [{self.t0!r}, {self.t_end!r}] s"
                )
        return self

    def is_adaptive(self) -> bool:
        """True when the method chooses its own steps (dop853)."""
        return bool({m["name"]: m for m in _core.methods()}[self.method]["adaptive"])

    def resolved_dt(self) -> float:
        """The step size handed to the core [s]: ``dt``, else 1e-3 s (0 = automatic for adaptive methods)."""
        if self.dt is not None:
            return self.dt
        return 0.0 if self.is_adaptive() else float(DEFAULTS["dt"])

    def resolved_tolerances(self) -> tuple[float, float]:
        """(rtol, atol) handed to the core: the given values, else the defaults 1e-10 and 1e-12."""
        rtol = self.rtol if self.rtol is not None else float(DEFAULTS["rtol"])
        atol = self.atol if self.atol is not None else float(DEFAULTS["atol"])
        return rtol, atol


class ScenarioSpec(_Section):
    """The whole file: optional ``title`` and ``description``, then the three sections."""

    title: str | None = Field(None, description="a one-line title (string, optional)")
    description: str | None = Field(None, description="free text (string, optional)")
    pendulum: PendulumSection = Field(description="the table [pendulum]")
    initial: InitialSection = Field(description="the table [initial]")
    simulation: SimulationSection = Field(description="the table [simulation]")


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


# --- error messages ---------------------------------------------------------------------------------

_TYPE_PROBLEMS = {
    "float_type": "is not a number",
    "int_type": "is not an integer",
    "string_type": "is not a string",
    "bool_type": "is not true or false",
    "list_type": "is not an array",
    "model_type": "is not a table",
    "dict_type": "is not a table",
    "finite_number": "is not a finite number (nan and inf are not allowed)",
}


_BOUNDS = {
    "greater_than": ("gt", ">"),
    "greater_than_equal": ("ge", ">="),
    "less_than": ("lt", "<"),
    "less_than_equal": ("le", "<="),
}


def _show(value: Any) -> str:
    """A value as the user would recognise it from the TOML file."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {_show(v)}" for k, v in value.items()) + "}"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_show(v) for v in value) + "]"
    return repr(value)


def _model_at(loc: tuple[int | str, ...]) -> type[BaseModel] | None:
    """The pydantic model holding the key at ``loc`` (None if there is none)."""
    model: type[BaseModel] = ScenarioSpec
    for part in loc[:-1]:
        if not isinstance(part, str):
            return None
        info = model.model_fields.get(part)
        sub = info.annotation if info is not None else None
        if not (isinstance(sub, type) and issubclass(sub, BaseModel)):
            return None
        model = sub
    return model


def _allowed(loc: tuple[int | str, ...]) -> str | None:
    keys = tuple(p for p in loc if isinstance(p, str))
    model = _model_at(keys)
    if model is None or not keys:
        return None
    info = model.model_fields.get(keys[-1])
    return None if info is None else info.description


def _key(loc: tuple[int | str, ...]) -> str:
    out = ""
    for part in loc:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else part)
    return out


def _pendulum_model(data: Any) -> str:
    """The model named in the raw ``[pendulum]`` table (``"ideal"`` when absent or not a string)."""
    table = data.get("pendulum") if isinstance(data, dict) else None
    model = table.get("model", "ideal") if isinstance(table, dict) else "ideal"
    return model if isinstance(model, str) else "ideal"


def _unknown_pendulum_key(name: str, value: Any, model: str) -> str:
    """An unknown key of ``[pendulum]``: the keys of the chosen model, and which models take it."""
    keys = _model_keys(model)
    text = f"unknown key pendulum.{name} = {_show(value)}"
    if others := _models_with(name):
        text += f" (a parameter of the model{'s' if len(others) > 1 else ''} {', '.join(map(repr, others))}"
        text += f", not of {model!r}: set model = {others[0]!r}?)"
    elif hint := difflib.get_close_matches(name, keys, n=1):
        text += f" (did you mean {hint[0]!r}?)"
    return text + f"; allowed keys in [pendulum] for model {model!r}: {', '.join(keys)}"


def _problem(err: ErrorDetails, data: Any = None) -> str:
    """One readable line for one pydantic error: the dotted key, the bad value, what is allowed.
    ``data`` is the raw input (it names the model whose keys ``[pendulum]`` takes)."""
    loc = tuple(err["loc"])
    kind, value = err["type"], err.get("input")
    if kind == "extra_forbidden" and len(loc) == 2 and loc[0] == "pendulum":
        return _unknown_pendulum_key(str(loc[1]), value, _pendulum_model(data))
    allowed = _allowed(loc)
    if loc[:2] == ("pendulum", "params") and len(loc) == 3:  # a model parameter: shown as written
        model = _pendulum_model(data)
        name = str(loc[2])
        spec = _own_params(model).get(_degree_keys(model).get(name, name))
        if spec is not None:
            unit = "degrees" if name.endswith("_deg") else spec["unit"]
            allowed = f"{spec['allowed']} (in {unit}; {spec['description']})"
        loc = ("pendulum", name)
    key = _key(loc)
    if kind == "missing" and len(loc) == 1 and loc[0] in SECTIONS:
        return f"the table [{key}] is missing"
    if kind == "missing":
        return f"{key} is missing; expected {allowed}" if allowed else f"{key} is missing"
    if kind == "extra_forbidden":
        parent = _model_at(loc)
        names = list(parent.model_fields) if parent is not None else []
        section = f"[{_key(loc[:-1])}]" if len(loc) > 1 else "the top level"
        hint = difflib.get_close_matches(str(loc[-1]), names, n=1)
        text = f"unknown key {key} = {_show(value)}"
        if hint:
            text += f" (did you mean {hint[0]!r}?)"
        return text + f"; allowed keys in {section}: {', '.join(names)}"
    if kind == "value_error":
        reason = str(err.get("ctx", {}).get("error", err["msg"]))
        return f"[{key}] {reason}" if key and isinstance(value, dict) else f"{key} = {_show(value)}: {reason}"
    ctx = err.get("ctx", {})
    if kind in _TYPE_PROBLEMS:
        reason = _TYPE_PROBLEMS[kind]
    elif kind in ("too_short", "too_long") and ctx.get("min_length") == ctx.get("max_length") is not None:
        reason = f"must have exactly {ctx['min_length']} items, not {ctx.get('actual_length')}"
    elif kind in ("too_short", "too_long"):
        reason = err["msg"].replace("List should", "must").replace(" after validation", "")
    elif kind in _BOUNDS:
        bound = ctx[_BOUNDS[kind][0]]
        if isinstance(bound, float) and bound.is_integer() and abs(bound) < 1e15:
            bound = int(bound)
        reason = f"must be {_BOUNDS[kind][1]} {bound!r}"
    else:  # anything else: pydantic says "Input should be …"
        reason = re.sub(r"^(Input|Value|List) should", "must", err["msg"])
    text = (
        f"{key} = {_show(value)} {reason}" if kind in _TYPE_PROBLEMS else f"{key} = {_show(value)}: {reason}"
    )
    return f"{text}; allowed: {allowed}" if allowed else text


def _syntax_error(source: str, text: str, err: tomllib.TOMLDecodeError) -> ScenarioError:
    message = str(err)
    line: int | None = getattr(err, "lineno", None)
    column: int | None = getattr(err, "colno", None)
    if m := re.search(r"\s*\(at line (\d+), column (\d+)\)$", message):
        line, column = int(m.group(1)), int(m.group(2))
        message = message[: m.start()]
    elif m := re.search(r"\s*\(at end of document\)$", message):
        line = text.count("\n") + 1
        message = message[: m.start()] + " at the end of the file"
    where = f" (column {column})" if column else ""
    return ScenarioError(source, f"invalid TOML: {message[:1].lower()}{message[1:]}{where}", line=line)


# --- the scenario -----------------------------------------------------------------------------------


def _toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        return repr(value)  # shortest repr: reads back to the same float
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False).replace("\x7f", "\\u007f")
    if isinstance(value, list):
        return "[" + ", ".join(_toml_value(v) for v in value) + "]"
    raise TypeError(f"cannot write {value!r} to TOML")


@dataclass(frozen=True)
class Scenario:
    """A validated scenario: the pendulum, its initial state and the simulation settings.

    Build one with :func:`load_scenario`, :meth:`from_toml_str` or :meth:`from_dict`; construction
    checks everything a run needs (including that the start lies on TS² and that the saved samples
    fit in memory) and raises :class:`ScenarioError` otherwise. Two scenarios are equal when their
    settings are (``source`` is not compared).
    """

    spec: ScenarioSpec
    source: str = field(default="<string>", compare=False)
    _pendulum: Pendulum = field(init=False, repr=False, compare=False)
    _spring: SwingingSpring | None = field(init=False, repr=False, compare=False)
    _state: State = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        p, sim = self.spec.pendulum, self.spec.simulation
        object.__setattr__(self, "_spring", None)
        if p.model == "spring":  # off the sphere: its own integrator (spring.py), not a Pendulum
            self._init_spring()
            return
        try:
            pendulum = Pendulum(
                length=p.length,
                g=p.g,
                mass=p.mass,
                model=p.model,
                pivot_samples=p.pivot_samples(),
                **p.extras(),
            )
        except _core.InvalidInputError as e:
            given = "".join(
                f" (given as {deg} = {p.params[deg]!r} degrees)"
                for deg, rad in _degree_keys(p.model).items()
                if deg in p.params and rad in str(e)
            )
            raise ScenarioError(self.source, f"[pendulum] {e}{given}") from None
        object.__setattr__(self, "_pendulum", pendulum)
        if (samples := pendulum.pivot_samples) is not None:
            first, last = float(samples[0][0]), float(samples[0][-1])
            if not (first <= sim.t0 and sim.t_end <= last):
                raise ScenarioError(
                    self.source,
                    f"[simulation] the run [t0, t_end] = [{sim.t0!r}, {sim.t_end!r}] s leaves the pivot "
                    f"samples' span [{first!r}, {last!r}] s (pendulum.pivot_times)",
                )
        object.__setattr__(self, "_state", self._make_state(pendulum))
        if pendulum.model == "string":  # hybrid (string_pendulum.py): its own, fewer settings
            from .string_pendulum import check_string_settings

            try:
                check_string_settings(sim.method)
            except _core.InvalidInputError as e:
                raise ScenarioError(self.source, f"[simulation] {e}") from None
            return
        try:  # the core's own up-front checks (memory of the saved samples, save times), no stepping
            _core.Solver(
                *pendulum._core_args(),
                np.ascontiguousarray(self._state.x),
                np.ascontiguousarray(self._state.v),
                sim.t0,
                sim.t_end,
                sim.method,
                sim.resolved_dt(),
                *sim.resolved_tolerances(),
                True,
                sim.save_every,
                None if sim.save_at is None else np.asarray(sim.save_at, dtype=np.float64),
                None,
                **pendulum._model_kwargs(),
            )
        except _core.InvalidInputError as e:
            raise ScenarioError(self.source, f"[simulation] {e}") from None

    def _init_spring(self) -> None:
        """The swinging spring (T-7.4): ``length`` is the rest length l₀ [m], ``stiffness`` k [N/m]; an
        angle start lies on the sphere of the equilibrium length l = l₀ + m g/k, a Cartesian start is
        taken as given (x [m], v [m/s] anywhere). Methods: rattle → Störmer–Verlet (order 2), rattle4
        → its triple jump (order 4); save_every only. Validated by the core."""
        p, sim, ini = self.spec.pendulum, self.spec.simulation, self.spec.initial
        k = float(p.extras().get("stiffness", _own_params("spring")["stiffness"]["default"]))
        spring = SwingingSpring(k / p.mass, p.length, p.g, p.mass)
        if sim.method not in SPRING_ORDERS:
            raise ScenarioError(
                self.source,
                f"[simulation] method {sim.method!r} cannot integrate the 'spring' model (it leaves the "
                "sphere): use 'rattle' (Störmer–Verlet, order 2) or 'rattle4' (its triple jump, order 4)",
            )
        if sim.save_at is not None:
            raise ScenarioError(self.source, "[simulation] save_at is not available for the 'spring' model")
        if ini.project:
            raise ScenarioError(
                self.source, "[initial] project applies to pendulums on the sphere, not to the 'spring' model"
            )
        if ini.cartesian:
            state = State(np.asarray(ini.x, dtype=np.float64), np.asarray(ini.v, dtype=np.float64))
        else:
            ell = spring.equilibrium_length
            if not (math.isfinite(ell) and ell > 0):
                raise ScenarioError(
                    self.source,
                    "[initial] an angle start needs an equilibrium length l = l0 + m g/k > 0, "
                    f"got {ell!r} m; give a Cartesian start x, v instead",
                )
            state = Pendulum(length=ell, g=p.g, mass=p.mass).state_from_angles(*ini.angles())
        try:  # the core's checks of parameters, start and step, without stepping
            _core.spring_simulate(
                spring.k_over_m,
                spring.rest_length,
                spring.g,
                spring.mass,
                np.ascontiguousarray(state.x),
                np.ascontiguousarray(state.v),
                sim.resolved_dt(),
                0,
                int(sim.save_every or 1),
                2,
            )
        except _core.InvalidInputError as e:
            raise ScenarioError(self.source, f"[pendulum] {e}") from None
        object.__setattr__(self, "_spring", spring)
        object.__setattr__(self, "_state", state)

    def spring(self) -> SwingingSpring | None:
        """The swinging spring of a ``model = "spring"`` scenario (None for the pendulum models)."""
        return self._spring

    def _make_state(self, pendulum: Pendulum) -> State:
        ini = self.spec.initial
        if pendulum.model == "string" and ini.cartesian and not ini.project:
            # a string may start slack: strictly inside the sphere, x and v as given (the core checks
            # them when the run starts; on the sphere the TS² rules below apply)
            x, v = np.asarray(ini.x, dtype=np.float64), np.asarray(ini.v, dtype=np.float64)
            if np.linalg.norm(x) < pendulum.length * (1.0 - 1e-9):
                return State(_frozen(x), _frozen(v))
        try:
            if not ini.cartesian:
                return pendulum.state_from_angles(*ini.angles())
            if ini.project:
                return pendulum.state(ini.x, ini.v, project=True)
            return pendulum.state(ini.x, ini.v)
        except _core.InvalidInputError as e:
            if not ini.cartesian or ini.project or "not on TS²" not in str(e):
                raise ScenarioError(self.source, f"[initial] {e}") from None
            x, v = np.asarray(ini.x), np.asarray(ini.v)
            m = re.search(r": (.*?); pass project=True", str(e))
            why = f" ({m.group(1)})" if m else ""
            raise ScenarioError(
                self.source,
                f"[initial] the start x = {_show(ini.x)}, v = {_show(ini.v)} is not on TS² "
                "(|x| = l, x·v = 0): "
                f"|x| - l = {np.linalg.norm(x) - pendulum.length:.6g} m, x·v = {float(x @ v):.6g} m²/s{why}; "
                "set project = true in [initial] to move it onto TS²",
            ) from None

    # --- construction ---

    @classmethod
    def from_dict(cls, data: dict[str, Any], source: str = "<dict>") -> Scenario:
        """A scenario from the parsed TOML structure (nested dicts); :class:`ScenarioError` if invalid."""
        try:
            spec = ScenarioSpec.model_validate(data)
        except ValidationError as e:
            errors = sorted(e.errors(), key=lambda err: err["type"] != "extra_forbidden")
            raise ScenarioError(source, [_problem(err, data) for err in errors]) from None
        return cls(spec, source)

    @classmethod
    def from_toml_str(cls, text: str, source: str = "<string>") -> Scenario:
        """A scenario from TOML text; ``source`` names it in error messages."""
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as e:
            raise _syntax_error(source, text, e) from None
        return cls.from_dict(data, source)

    def with_overrides(
        self,
        *,
        method: str | None = None,
        dt: float | None = None,
        t_end: float | None = None,
        save_every: int | None = None,
        rtol: float | None = None,
        atol: float | None = None,
    ) -> Scenario:
        """A copy with some ``[simulation]`` settings replaced (``None`` keeps the file's value).

        ``save_every`` replaces a ``save_at`` list of the file. The result is validated like a file.
        """
        given = {
            k: v
            for k, v in {
                "method": method,
                "dt": dt,
                "t_end": t_end,
                "save_every": save_every,
                "rtol": rtol,
                "atol": atol,
            }.items()
            if v is not None
        }
        if not given:
            return self
        data = self.to_dict()
        data["simulation"].update(given)
        if "save_every" in given:
            data["simulation"].pop("save_at", None)
        changes = ", ".join(f"{k} = {_show(v)}" for k, v in given.items())
        return Scenario.from_dict(data, f"{self.source} (with {changes})")

    # --- what it describes ---

    @property
    def title(self) -> str | None:
        """The file's title, if any."""
        return self.spec.title

    def pendulum(self) -> Pendulum:
        """The pendulum of ``[pendulum]`` (length [m], mass [kg], g [m/s²]). A ``model = "spring"``
        scenario has none (:meth:`spring` instead): :class:`ScenarioError`."""
        if self._spring is not None:
            raise ScenarioError(
                self.source,
                "the 'spring' model is a swinging spring, not a pendulum on the sphere: see "
                "Scenario.spring(); it runs with Scenario.run() and `pendulab run`",
            )
        return self._pendulum

    def initial_state(self) -> State:
        """The start of ``[initial]`` on TS²; with project = true, ``State.projection`` says how far."""
        return self._state

    def expected_samples(self) -> int | None:
        """How many samples a run will save (``None`` when an adaptive method decides, with save_every)."""
        sim = self.spec.simulation
        if sim.save_at is not None:
            return len(sim.save_at)
        if sim.is_adaptive():
            return None
        steps = math.ceil((sim.t_end - sim.t0) / sim.resolved_dt())
        return 1 + math.ceil(steps / (sim.save_every or 1))

    def run(
        self,
        progress: bool | None = None,
        *,
        method: str | None = None,
        dt: float | None = None,
        t_end: float | None = None,
        save_every: int | None = None,
        rtol: float | None = None,
        atol: float | None = None,
    ) -> Trajectory | SpringTrajectory:
        """Simulates the scenario; keyword arguments override ``[simulation]`` (see :meth:`with_overrides`).

        ``progress`` as in :func:`pendulab.simulate` (default: a bar only for long runs). Ctrl-C returns
        the samples computed so far with ``Trajectory.interrupted = True``.
        """
        sc = self.with_overrides(
            method=method, dt=dt, t_end=t_end, save_every=save_every, rtol=rtol, atol=atol
        )
        sim = sc.spec.simulation
        if sc._spring is not None:
            run = simulate_spring(
                sc._spring,
                sc._state.x,
                sc._state.v,
                sim.t_end - sim.t0,
                dt=sim.resolved_dt(),
                save_every=sim.save_every or 1,
                order=SPRING_ORDERS[sim.method],
            )
            return dataclasses.replace(run, t=run.t + sim.t0)  # type: ignore[return-value]
        rtol, atol = sim.resolved_tolerances()
        return simulate(
            sc.pendulum(),
            sc.initial_state(),
            sim.t_end,
            method=sim.method,
            dt=sim.dt,
            rtol=rtol,
            atol=atol,
            save_every=sim.save_every,
            save_at=sim.save_at,
            t0=sim.t0,
            progress=progress,
        )

    # --- writing ---

    def to_dict(self) -> dict[str, Any]:
        """The settings as nested dicts (defaults filled in, unset optional keys left out)."""
        data = self.spec.model_dump(exclude_none=True)
        data["pendulum"].update(data["pendulum"].pop("params", {}))
        return data

    def to_toml(self) -> str:
        """The scenario as TOML text (units as comments); loading it gives an equal scenario."""
        data = self.to_dict()
        model = self.spec.pendulum.model
        units = {section: dict(table) for section, table in UNITS.items()}
        units["pendulum"] |= {k: p["unit"] for k, p in _own_params(model).items() if p["unit"] != "1"}
        units["pendulum"] |= dict.fromkeys(_degree_keys(model), "degrees")
        lines = [f"# Pendulab scenario (pendulab {_core.__version__}); SI units, angles *_deg in degrees"]
        lines += [f"{k} = {_toml_value(data[k])}" for k in ("title", "description") if k in data]
        for section in SECTIONS:
            lines += ["", f"[{section}]"]
            for key, value in data[section].items():
                unit = units[section].get(key)
                entry = f"{key} = {_toml_value(value)}"
                lines.append(f"{entry:<24}  # {unit}" if unit else entry)
        return "\n".join(lines) + "\n"

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes :meth:`to_toml` to ``path`` atomically (temporary file + rename); returns the path."""
        text = self.to_toml()
        with atomic_path(path) as tmp:
            tmp.write_text(text, encoding="utf-8")
        return Path(path)


def load_scenario(path: str | os.PathLike[str]) -> Scenario:
    """Reads and validates a scenario file (TOML, UTF-8).

    Raises :class:`ScenarioError` for bad contents and ``OSError`` if the file cannot be read.
    """
    source = os.fspath(path)
    raw = Path(path).read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as e:
        raise ScenarioError(source, f"not UTF-8 text (byte {e.start}): TOML files must be UTF-8") from None
    return Scenario.from_toml_str(text, source)
