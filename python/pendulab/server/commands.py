"""The lab's commands (docs/web.md, "Commands"): one JSON object per text message, told apart by
``"type"`` — a pydantic discriminated union (:data:`COMMAND`) of ``set_params``, ``set_model``,
``set_state``, ``set_method``, ``set_time_scale``, ``pause``, ``resume``, ``step``, ``reset``,
``load_scenario`` and ``crane``; :func:`parse_command` validates one message. Unknown keys, wrong
types, NaN/inf and out-of-range values are refused with a :class:`~.notices.CommandError` naming the
problem.

The bounds are the core's (:data:`CORE_LIMITS`: ``crates/pendulab-core/src/live/wire.rs``, which the
page's engine and the server's sessions check too), the models those of the registry that run in the
lab (:data:`MODEL_SPECS`). SI units: l [m], m [kg], g [m/s²], dt [s], states in m, m/s, rad, rad/s.
"""

from __future__ import annotations

import json
from typing import TYPE_CHECKING, Annotated, Any, Literal, TypedDict

from pydantic import BaseModel, ConfigDict, Field, TypeAdapter, ValidationError, model_validator

from .._core import LiveSession, models
from ..integrators import method_names, unknown_method, unknown_method_key
from ..model import Pendulum, State
from ..model.registry import Elsewhere, elsewhere
from .live_models import OWN_STEPPER_MODELS
from .notices import CommandError, KeyedValueError, show_value, validation_key, validation_problems

if TYPE_CHECKING:
    from .._core import LiveLimit, ModelInfo, ParamSpec

MAX_MESSAGE_BYTES: int = LiveSession.MAX_MESSAGE_BYTES
"""Longest command the server reads [characters] (a command is a few hundred bytes): the core's
(``live::wire::MAX_MESSAGE_BYTES``)."""

CORE_LIMITS: dict[str, LiveLimit] = LiveSession.limits()
"""The lab's command limits as the core checks them (``crates/pendulab-core/src/live/wire.rs``,
``LIMITS``; the page's engine checks the same table): name → min, max, unit. The one source of the
bounds below and of the commands' pydantic fields (the core itself accepts any finite g and any
positive l, m outside the lab)."""

_CONTROLS: dict[str, tuple[str, dict[str, float]]] = {
    "length": ("length", {"ui_min": 0.1, "ui_max": 5.0, "step": 0.01}),
    "mass": ("mass", {"ui_min": 0.1, "ui_max": 10.0, "step": 0.01}),
    "g": ("g", {"ui_min": -30.0, "ui_max": 30.0, "step": 0.01}),
    "dt": ("dt", {"ui_min": 1e-4, "ui_max": 0.05, "step": 1e-4, "default": 1e-3}),
    "time_scale": ("time_scale", {"ui_min": 0.01, "ui_max": 100.0, "step": 0.01, "default": 1.0}),
    "step_n": ("n", {}),
}
"""The live controls: the core's limit each takes its bounds from, and how the page shows it (slider
range, step, default; presentation only)."""


def _bounds(core_name: str, integer: bool) -> dict[str, float]:
    lim = CORE_LIMITS[core_name]
    lo, hi = lim["min"], lim["max"]
    return {"min": int(lo), "max": int(hi)} if integer else {"min": lo, "max": hi}


LIMITS: dict[str, dict[str, float]] = {
    name: _bounds(core, name == "step_n") | ui for name, (core, ui) in _CONTROLS.items()
}
"""Limits of the live controls: the core's bounds (:data:`CORE_LIMITS`) with the page's presentation."""


COMMON_PARAMS = ("length", "mass", "g")
"""The parameters every model shares (l [m], m [kg], g [m/s²]); the rest are a model's own."""

MODEL_SPECS: dict[str, ModelInfo] = {
    m["name"]: m for m in models() if m["interactive"] or m["name"] in OWN_STEPPER_MODELS
}
"""The core's models that run in the lab, by name: parameters with units, defaults, limits. Those of
``pendulab.models()`` marked ``interactive`` (the incremental ``pendulab.Stepper``), and the swinging
spring and the string with their own core steppers (:mod:`pendulab.server.live_models`)."""

OFFLINE_MODELS = tuple(m["name"] for m in models() if m["name"] not in MODEL_SPECS)
"""Models of the registry that only run with ``pendulab run`` / ``pl.simulate`` (a sampled pivot path:
it needs arrays), not in the lab."""


def own_params(model: str) -> list[ParamSpec]:
    """The parameters of ``model`` beyond length, mass and g, in the registry's order."""
    return [p for p in MODEL_SPECS[model]["params"] if p["name"] not in COMMON_PARAMS]


def _check_param_names(model: str, names: Any) -> None:
    allowed = [p["name"] for p in own_params(model)]
    unknown = [n for n in names if n not in allowed]
    if len(unknown) == 1 and (other := _elsewhere(model, unknown[0])) is not None:
        every = [p["name"] for p in MODEL_SPECS[model]["params"]]
        key = "parameter_of_other_models" if len(other.owners) > 1 else "parameter_of_other_model"
        raise KeyedValueError(
            f"{other}; its parameters: {', '.join(every)}",
            key,
            model=model,
            name=other.name,
            owner=other.owners[0],
            available=", ".join(every),
            **({"others": ", ".join(other.owners[1:])} if len(other.owners) > 1 else {}),
        )
    if unknown:
        has = f"its parameters: {', '.join(allowed)}" if allowed else "it has none besides length, mass, g"
        words = f"the {model!r} model has no parameter {', '.join(map(repr, unknown))}; {has}"
        named = {"model": model, "name": ", ".join(unknown)}
        if allowed:
            raise KeyedValueError(words, "unknown_parameter", **named, available=", ".join(allowed))
        raise KeyedValueError(words, "no_parameters", **named)


def _elsewhere(model: str, key: str) -> Elsewhere | None:
    """The lab's other models whose own parameter ``key`` is (the same but for case), in the words of
    ``pl.Pendulum`` (:func:`pendulab.model.registry.elsewhere`); None if ``model`` has one like it."""
    own = {name: [p["name"] for p in own_params(name)] for name in MODEL_SPECS}
    return elsewhere(model, key, own[model], own)


# --- commands -----------------------------------------------------------------------------------------


class _Command(BaseModel):
    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)


class Bounds(TypedDict):
    """pydantic's bounds of a number (``Field(**limit_bounds(name))``)."""

    ge: float
    le: float


def limit_bounds(name: str) -> Bounds:
    """The pydantic ``ge``/``le`` of the live control ``name`` (:data:`LIMITS`, the core's bounds)."""
    return {"ge": LIMITS[name]["min"], "le": LIMITS[name]["max"]}


class SetParams(_Command):
    """Change the pendulum's parameters, keeping its model; omitted values stay. A new length rescales
    the state (same angles and rates). ``params``: the current model's own parameters by name, SI units
    (``GET /api/schema`` → ``models``); the session checks the names, the core the values."""

    type: Literal["set_params"]
    length: float | None = Field(None, description="rod length l in m", **limit_bounds("length"))
    mass: float | None = Field(None, description="bob mass m in kg", **limit_bounds("mass"))
    g: float | None = Field(None, description="gravity g in m/s² (g > 0 pulls along -z)", **limit_bounds("g"))
    params: dict[str, float] | None = Field(None, description="the model's own parameters (SI units)")

    @model_validator(mode="after")
    def _something(self) -> SetParams:
        if self.length is None and self.mass is None and self.g is None and not self.params:
            raise ValueError("give at least one of length (m), mass (kg), g (m/s²), params {name: value}")
        return self


class SetModel(_Command):
    """Switch to another model of the core's registry (``pendulab.models()``), keeping length, mass, g,
    the state and t; its own parameters are the registry's defaults overridden by ``params`` (SI units)."""

    type: Literal["set_model"]
    model: str = Field(min_length=1, max_length=40)
    params: dict[str, float] = Field(default_factory=dict, description="the model's own parameters (SI)")

    @model_validator(mode="after")
    def _known(self) -> SetModel:
        available = ", ".join(MODEL_SPECS)
        if self.model in OFFLINE_MODELS:
            raise KeyedValueError(
                f"model {self.model!r} does not run in the lab (use pendulab run); "
                f"the lab's models: {available}",
                "not_lab_model",
                model=self.model,
                available=available,
            )
        if self.model not in MODEL_SPECS:
            raise KeyedValueError(
                f"unknown model {self.model!r}; available: {available}",
                "unknown_model",
                model=self.model,
                available=available,
            )
        _check_param_names(self.model, self.params)
        return self


Vec3 = Annotated[list[float], Field(min_length=3, max_length=3)]


class StateSpec(_Command):
    """A state on TS² (for the swinging spring any (x, v) with x ≠ 0; for the string also a slack one,
    strictly inside the sphere): either Cartesian ``x`` [m] and ``v`` [m/s] (on TS², or moved there with
    ``project: true``) or angles ``theta`` (from the downward vertical), ``phi`` [rad] and rates
    ``theta_dot``, ``phi_dot`` [rad/s] (omitted ones are 0)."""

    x: Vec3 | None = None
    v: Vec3 | None = None
    project: bool = False
    theta: float | None = None
    phi: float | None = None
    theta_dot: float | None = None
    phi_dot: float | None = None

    @model_validator(mode="after")
    def _one_form(self) -> StateSpec:
        cartesian = [k for k in ("x", "v") if getattr(self, k) is not None]
        angles = [k for k in ("theta", "phi", "theta_dot", "phi_dot") if getattr(self, k) is not None]
        if cartesian and angles:
            raise ValueError(
                f"give either x and v or angles (theta, phi, theta_dot, phi_dot), not both: "
                f"got {', '.join(cartesian + angles)}"
            )
        if cartesian and len(cartesian) != 2:
            raise ValueError("a Cartesian state needs both x (3 numbers, m) and v (3 numbers, m/s)")
        if not cartesian and self.theta is None:
            raise ValueError("give x and v (m, m/s), or at least theta (rad) with phi, theta_dot, phi_dot")
        return self

    def to_state(self, pendulum: Pendulum) -> State:
        """The state for ``pendulum``; ``InvalidInputError`` when it is off TS² (and not projected)."""
        if self.x is not None and self.v is not None:
            return pendulum.state(self.x, self.v, project=self.project)
        return pendulum.state_from_angles(
            float(self.theta or 0.0),
            float(self.phi or 0.0),
            float(self.theta_dot or 0.0),
            float(self.phi_dot or 0.0),
        )


class SetState(StateSpec):
    """Replace the state and the start that ``reset`` returns to; t is kept. Fields: :class:`StateSpec`."""

    type: Literal["set_state"]


class ExactRequest(StateSpec):
    """Body of ``POST /api/exact``: the pendulum (defaults l = 1 m, m = 1 kg, g = 9.81 m/s²) and a state."""

    length: float = Field(1.0, description="rod length l in m", **limit_bounds("length"))
    mass: float = Field(1.0, description="bob mass m in kg", **limit_bounds("mass"))
    g: float = Field(9.81, description="gravity g in m/s²", **limit_bounds("g"))


class SetMethod(_Command):
    """Change the integrator (a name of ``pendulab.method_names()``) and/or its step dt [s]."""

    type: Literal["set_method"]
    method: str | None = None
    dt: float | None = Field(
        None, description="step in s of fixed-step methods (dop853 chooses its own)", **limit_bounds("dt")
    )

    @model_validator(mode="after")
    def _known(self) -> SetMethod:
        if self.method is None and self.dt is None:
            raise ValueError("give method, dt (s) or both")
        if self.method is not None and self.method not in method_names():
            key, values = unknown_method_key(self.method)
            raise KeyedValueError(unknown_method(self.method), key, **values)
        return self


class SetTimeScale(_Command):
    """Simulated seconds per wall-clock second."""

    type: Literal["set_time_scale"]
    time_scale: float = Field(**limit_bounds("time_scale"))


class Pause(_Command):
    type: Literal["pause"]


class Resume(_Command):
    type: Literal["resume"]


class Step(_Command):
    """Take n integrator steps at once (``dop853``: n accepted steps) and send the frame; pauses first."""

    type: Literal["step"]
    n: int = Field(1, ge=int(LIMITS["step_n"]["min"]), le=int(LIMITS["step_n"]["max"]))


class Reset(_Command):
    """Back to the start (the scenario's or the last ``set_state``), t = t0, with the current parameters."""

    type: Literal["reset"]


class LoadScenario(_Command):
    """Load an example scenario by name (``GET /api/scenarios``): pendulum, start, method, dt."""

    type: Literal["load_scenario"]
    name: str = Field(min_length=1, max_length=100)


class Crane(_Command):
    """The crane mode (docs/cranes.md "The lab's crane mode"; the core checks the values): ``on``
    switches to it, ``drive`` the trolley's commanded velocity (x, y) [m/s], ``move`` by (x, y) [m] and
    stop, ``stop`` (drive 0), ``rope`` hoist to this rope length [m]."""

    type: Literal["crane"]
    on: bool | None = None
    drive: list[float] | None = Field(None, min_length=2, max_length=2)
    move: list[float] | None = Field(None, min_length=2, max_length=2)
    stop: bool | None = None
    rope: float | None = None


Command = (
    SetParams
    | SetModel
    | SetState
    | SetMethod
    | SetTimeScale
    | Pause
    | Resume
    | Step
    | Reset
    | LoadScenario
    | Crane
)
# Any: mypy 1.20 takes this Annotated[...] type form for TypeAdapter's argument in one run and not in
# another (inline: a "special form", as an alias: a UnionType, depending on its cache); the annotation of
# COMMAND states the adapter's type.
_TAGGED_COMMAND: Any = Annotated[Command, Field(discriminator="type")]
COMMAND: TypeAdapter[Command] = TypeAdapter(_TAGGED_COMMAND)
COMMAND_TYPES: tuple[str, ...] = LiveSession.command_types()
"""The command types in the lab's order (the core's ``live::wire::COMMAND_TYPES``)."""


def parse_command(text: str | bytes) -> Command:
    """A validated command from one message; :class:`CommandError` naming every problem otherwise."""
    if isinstance(text, bytes | bytearray):
        raise CommandError("commands are JSON text messages; binary messages are not accepted")
    if len(text) > MAX_MESSAGE_BYTES:
        raise CommandError(f"message of {len(text)} characters is too long (at most {MAX_MESSAGE_BYTES})")
    try:
        raw = json.loads(text)
    except (json.JSONDecodeError, RecursionError) as e:
        raise CommandError(f"not JSON: {e}") from None
    if not isinstance(raw, dict):
        raise CommandError(f"a command is a JSON object with a 'type', got {type(raw).__name__}")
    kind = raw.get("type")
    if kind not in COMMAND_TYPES:
        what = "missing 'type'" if kind is None else f"unknown command type {show_value(kind)}"
        raise CommandError(f"{what}; expected one of: {', '.join(COMMAND_TYPES)}")
    try:
        return COMMAND.validate_python(raw)
    except ValidationError as e:
        key, values = validation_key(e, skip=1)
        raise CommandError(validation_problems(e, skip=1), command=kind, key=key, values=values) from None
