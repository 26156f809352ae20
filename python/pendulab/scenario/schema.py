"""The schema of a scenario file: pydantic models of its tables and the keys each one takes.

Holds :class:`PendulumSection` (``[pendulum]``: the model, length [m], mass [kg], g [m/s²], the
model's own parameters in the registry's SI units or ``<name>_deg`` in degrees, the sampled pivot's
times [s] and positions [m]), :class:`InitialSection` (``[initial]``: θ, φ [rad] or ``*_deg``
[degrees], θ̇, φ̇ [rad/s], or a Cartesian x [m] and v [m/s]), :class:`SimulationSection`
(``[simulation]``: t0, t_end, dt, save_at [s], rtol, atol [m, m/s], save_every [steps], method)
and :class:`ScenarioSpec` (the whole file), with the validators that refuse contradictions, the
tables :data:`SECTIONS` and :data:`UNITS`, and the helpers naming each model's keys in
``[pendulum]``. Messages of the validators name the key, the bad value and what is allowed; the
formatting of pydantic's own errors lives in :mod:`pendulab.scenario.errors`, the checks that need
the core (a start on TS², memory of the saved samples) in :mod:`pendulab.scenario.build`.
"""

from __future__ import annotations

import difflib
import math
from typing import TYPE_CHECKING, Annotated, Any

from pydantic import BaseModel, ConfigDict, Field, field_validator, model_validator

from .._core import methods, models
from ..integrators import DEFAULTS, method_names
from ..validate import COMMON, LIMITS, MAX_SAMPLES, MAX_STEPS, abbreviate

if TYPE_CHECKING:
    from .._core import ParamSpec

_MODEL_SPECS = {m["name"]: m for m in models()}
MODELS = tuple(_MODEL_SPECS)
"""Pendulum models a scenario may name (``[pendulum] model``; their parameters: ``pendulab models``)."""

_DEG = math.pi / 180
_U64_LIMIT = 2**63  # save_every must fit the core's unsigned 64-bit counter


class _Section(BaseModel):
    """Common settings: unknown keys are errors, no type coercion (a string is not a number), no NaN/inf."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


_VEC3 = {"min_length": 3, "max_length": 3}


def _lim(name: str) -> dict[str, float]:
    """pydantic bounds of entry ``name`` of the table of limits (:mod:`pendulab.validate`)."""
    spec = COMMON[name] if name in COMMON else LIMITS[name]
    return {"ge": spec["min"], "le": spec["max"]}


_Position = Annotated[float, Field(**_lim("position"))]
_Velocity = Annotated[float, Field(**_lim("velocity"))]
_Time = Annotated[float, Field(**_lim("time"))]


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


def _models_with(key: str) -> list[str]:
    """The models that take ``key`` in ``[pendulum]``."""
    return [name for name in _MODEL_SPECS if key in _model_keys(name)[len(_COMMON_KEYS) :]]


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


_ANGLE_KEYS = ("theta", "theta_deg", "phi", "phi_deg", "theta_dot", "phi_dot")
_CARTESIAN_KEYS = ("x", "v", "project")


class InitialSection(_Section):
    """``[initial]``: the start, either as angles or as Cartesian position and velocity."""

    theta: float | None = Field(
        None, description="polar angle from the downward vertical in rad, in [-1e6, 1e6]", **_lim("angle")
    )
    theta_deg: float | None = Field(
        None, description="polar angle from the downward vertical in degrees, in [-1e6, 1e6]", **_lim("angle")
    )
    phi: float | None = Field(
        None, description="azimuth atan2(y, x) in rad, in [-1e6, 1e6] (default 0)", **_lim("angle")
    )
    phi_deg: float | None = Field(
        None, description="azimuth atan2(y, x) in degrees, in [-1e6, 1e6] (default 0)", **_lim("angle")
    )
    theta_dot: float | None = Field(
        None, description="polar angular rate in rad/s, in [-1e9, 1e9] (default 0)", **_lim("angle_rate")
    )
    phi_dot: float | None = Field(
        None, description="azimuthal angular rate in rad/s, in [-1e9, 1e9] (default 0)", **_lim("angle_rate")
    )
    x: list[_Position] | None = Field(
        None, description="position of the bob in m, 3 numbers in [-1e9, 1e9]", **_VEC3
    )
    v: list[_Velocity] | None = Field(
        None, description="velocity of the bob in m/s, 3 numbers in [-1e7, 1e7]", **_VEC3
    )
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

    t_end: float = Field(description="end time in s, a number > t0 in [-1e12, 1e12]", **_lim("time"))
    t0: float = Field(
        0.0, description="start time in s, a number in [-1e12, 1e12] (default 0)", **_lim("time")
    )
    method: str = Field(
        str(DEFAULTS["method"]), description="an integrator name (see `pendulab methods`), default 'rattle'"
    )
    dt: float | None = Field(
        None,
        description="step size in s, a number in [1e-12, 1e6] (default 1e-3 s; adaptive methods: the first "
        "step); (t_end - t0)/dt at most 1e10 steps",
        **_lim("dt"),
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
    save_at: list[_Time] | None = Field(
        None,
        min_length=1,
        max_length=MAX_SAMPLES,
        description="a non-empty array of strictly increasing times in s within [t0, t_end]",
    )

    @field_validator("method")
    @classmethod
    def _known_method(cls, name: str) -> str:
        names = method_names()
        if name not in names:
            hint = difflib.get_close_matches(name[:100], names, n=1)
            suggestion = f" (did you mean {hint[0]!r}?)" if hint else ""
            raise ValueError(
                f"unknown method {abbreviate(repr(name))}{suggestion}; available: {', '.join(names)}"
            )
        return name

    @model_validator(mode="after")
    def _consistent(self) -> SimulationSection:
        if not self.t_end > self.t0:
            raise ValueError(f"t_end = {self.t_end!r} s must be after t0 = {self.t0!r} s")
        if not self.is_adaptive() and not (self.t_end - self.t0) / self.resolved_dt() <= MAX_STEPS:
            raise ValueError(
                f"(t_end - t0)/dt = {(self.t_end - self.t0) / self.resolved_dt():.3g} steps "
                f"(t_end = {self.t_end!r} s, t0 = {self.t0!r} s, dt = {self.resolved_dt()!r} s); "
                f"{LIMITS['steps']['allowed']}"
            )
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
        return bool({m["name"]: m for m in methods()}[self.method]["adaptive"])

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

    @field_validator("title", "description")
    @classmethod
    def _printable(cls, value: str | None, info: Any) -> str | None:
        """Text that reaches terminals and pages: no control characters (:func:`printable`)."""
        return (
            None if value is None else printable(value, info.field_name, one_line=info.field_name == "title")
        )


def printable(value: str, what: str, *, one_line: bool) -> str:
    """``value`` when it has no control characters (an ANSI escape sequence in a title would
    recolour, move or retitle the terminal that prints it); a description may have line breaks and
    tabs. A ``ValueError`` naming the character and its position otherwise."""
    allowed = "" if one_line else "\n\t"
    bad = next((c for c in value if _is_control(c) and c not in allowed), None)
    if bad is not None:
        raise ValueError(
            f"has the control character {bad!r} at character {value.index(bad) + 1}: a {what} is "
            f"printable text{' on one line' if one_line else ''} (no escape sequences)"
        )
    return value


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


def _is_control(c: str) -> bool:
    """A C0 or C1 control character or DEL (ESC starts ANSI sequences; U+009B is a one-character CSI)."""
    o = ord(c)
    return o < 0x20 or 0x7F <= o <= 0x9F


def _show(value: Any) -> str:
    """A value as the user would recognise it from the TOML file, abbreviated to 80 characters."""
    return abbreviate(_toml_like(value))


def _toml_like(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k} = {_toml_like(v)}" for k, v in list(value.items())[:20]) + "}"
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_toml_like(v) for v in value[:20]) + (", ..." if len(value) > 20 else "") + "]"
    return repr(value)
