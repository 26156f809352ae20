"""The lab's two models with their own steppers (docs/web.md): the swinging spring (``spring``, an elastic
rod: the state is (r, v) ∈ R³ × R³, off the sphere) and the pendulum on a string (``string``, hybrid:
taut on the sphere or slack in free flight). Both step in the core, incrementally
(``_SpringStepper``, ``_StringStepper``): the spring in whole steps of dt of Störmer–Verlet
or its triple jump, the string on the grid t₀ + k·dt with its taut/slack mode carried inside the core's
stepper, so that a live run is the same run as ``pl.simulate_spring`` / ``pl.simulate`` from the same
start, cut into pieces. This module only holds parameters and converts states; SI units throughout.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .._core import InvalidInputError, RunOptions, models
from .._core import SpringStepper as _SpringStepper
from .._core import StringStepper as _StringStepper
from ..model import Pendulum, State
from ..scenario import SPRING_ORDERS, Scenario
from ..variants.spring import SwingingSpring
from ..variants.string_pendulum import STRING_METHODS

OWN_STEPPER_MODELS = ("spring", "string")
"""Models of the registry that the lab runs with their own core steppers instead of ``pendulab.Stepper``."""

DEFAULT_METHOD = "rattle"
"""The method a session switches to when its method cannot run the spring or the string."""


def methods_for(model: str) -> tuple[str, ...] | None:
    """The methods that can run ``model`` in the lab (None: every method of ``pendulab.Stepper``)."""
    if model == "spring":
        return tuple(SPRING_ORDERS)
    if model == "string":
        return STRING_METHODS
    return None


def check_method(model: str, method: str) -> None:
    """``InvalidInputError`` naming the alternatives when ``method`` cannot run ``model``."""
    allowed = methods_for(model)
    if allowed is not None and method not in allowed:
        what = {
            "spring": "it leaves the sphere: rattle runs Störmer–Verlet (order 2), "
            "rattle4 its triple jump (order 4)",
            "string": "its taut phases need a fixed-step method that keeps TS²",
        }[model]
        raise InvalidInputError(
            f"method {method!r} cannot run the {model!r} model ({what}); use one of {', '.join(allowed)}"
        )


@dataclass(frozen=True)
class SpringPendulum:
    """The swinging spring as a lab session holds it, in the place of a :class:`pendulab.Pendulum`:
    ``length`` is the rest length l₀ [m], ``stiffness`` k [N/m], ``mass`` [kg], ``g`` [m/s²] along −z.
    The bob hangs at rest at the equilibrium length l₀ + m g/k."""

    length: float
    g: float
    mass: float
    stiffness: float
    model: str = "spring"

    def __post_init__(self) -> None:
        for name, value in (("length", self.length), ("mass", self.mass), ("stiffness", self.stiffness)):
            if not (math.isfinite(value) and value > 0):
                unit = {"length": "m", "mass": "kg", "stiffness": "N/m"}[name]
                raise InvalidInputError(f"invalid {name} = {value!r}: a finite number > 0 ({unit})")
        if not math.isfinite(self.g):
            raise InvalidInputError(f"invalid g = {self.g!r}: a finite number (m/s²)")

    @property
    def extra(self) -> dict[str, float]:
        """The model's own parameters (SI)."""
        return {"stiffness": self.stiffness}

    @property
    def spring(self) -> SwingingSpring:
        """The core's parameters: k/m [1/s²], l₀ [m], g, m."""
        return SwingingSpring(self.stiffness / self.mass, self.length, self.g, self.mass)

    def state(self, x: Any, v: Any, *, project: bool = False) -> State:
        """Any finite (x [m], v [m/s]) with x away from the pivot; ``project`` is ignored (no sphere)."""
        xa = np.asarray(x, dtype=np.float64).reshape(3)
        va = np.asarray(v, dtype=np.float64).reshape(3)
        if not (np.all(np.isfinite(xa)) and np.all(np.isfinite(va))) or not np.any(xa):
            raise InvalidInputError(
                f"the spring's state x = {xa.tolist()} m, v = {va.tolist()} m/s must be finite with x ≠ 0"
            )
        return State(xa, va)

    def state_from_angles(
        self, theta: float, phi: float = 0.0, theta_dot: float = 0.0, phi_dot: float = 0.0
    ) -> State:
        """The state at these angles and rates on the sphere of the equilibrium length l₀ + m g/k
        (the rest length when that is not positive), as scenario files place an angle start."""
        ell = self.spring.equilibrium_length
        ell = ell if math.isfinite(ell) and ell > 0 else self.length
        return Pendulum(length=ell, g=self.g, mass=self.mass).state_from_angles(
            theta, phi, theta_dot, phi_dot
        )


class StringLabPendulum(Pendulum):
    """A ``model="string"`` :class:`pendulab.Pendulum` whose states may be slack: strictly inside the
    sphere |x| < l a state is taken as given (the bob in flight); on or beyond it, as for a rod."""

    def state(self, x: Any, v: Any, *, project: bool = False) -> State:
        xa = np.asarray(x, dtype=np.float64).reshape(3)
        va = np.asarray(v, dtype=np.float64).reshape(3)
        inside = np.linalg.norm(xa) < self.length * (1.0 - 1e-9)
        if inside and np.all(np.isfinite(xa)) and np.all(np.isfinite(va)):
            return State(xa, va)
        return super().state(xa, va, project=project)


LabPendulum = Pendulum | SpringPendulum
"""What a session holds: a pendulum on the sphere (the string's may be slack) or the swinging spring."""


def lab_pendulum(length: float, g: float, mass: float, model: str, **own: float) -> LabPendulum:
    """The session's pendulum of ``model`` (own parameters by name, SI; the core checks them)."""
    if model == "spring":
        unknown = set(own) - {"stiffness"}
        if unknown:
            raise InvalidInputError(f"the 'spring' model has no parameter {', '.join(map(repr, unknown))}")
        return SpringPendulum(length, g, mass, float(own.get("stiffness", _spring_default())))
    if model == "string":
        return StringLabPendulum(length=length, g=g, mass=mass, model=model, **own)
    return Pendulum(length=length, g=g, mass=mass, model=model, **own)


def _spring_default() -> float:
    spec = next(m for m in models() if m["name"] == "spring")
    return float(next(p["default"] for p in spec["params"] if p["name"] == "stiffness"))


def carry_state(pendulum: LabPendulum, x: Any, v: Any) -> State:
    """The state (x [m], v [m/s]) for ``pendulum`` after a change of model or parameters: kept as it is
    for the spring, and for the string while strictly inside the sphere (slack: never pushed onto the
    sphere); otherwise moved onto TS² (x ← l x/|x|, v ← its tangential part)."""
    return pendulum.state(x, v, project=True)


def scenario_pendulum(sc: Scenario) -> LabPendulum:
    """The session's pendulum of a scenario (the spring's from ``Scenario.spring()``)."""
    spring = sc.spring()
    if spring is not None:
        return SpringPendulum(spring.rest_length, spring.g, spring.mass, spring.k_over_m * spring.mass)
    p = sc.pendulum()
    if p.model == "string":
        return StringLabPendulum(length=p.length, g=p.g, mass=p.mass, model="string", **p.extra)
    return p


def _pair(state: State) -> tuple[Any, Any]:
    """The start (x [m], v [m/s]) as float64 arrays (a spring's state need not lie on a sphere)."""
    return np.ascontiguousarray(state.x, dtype=np.float64), np.ascontiguousarray(state.v, dtype=np.float64)


class SpringStepper:
    """The swinging spring stepped in the core (``_SpringStepper``): ``rattle`` runs Störmer–Verlet
    (order 2), ``rattle4`` its triple jump (order 4), as in scenario files; whole steps of dt."""

    def __init__(self, pendulum: SpringPendulum, state: State, method: str, dt: float, t0: float) -> None:
        check_method("spring", method)
        sp = pendulum.spring
        self.pendulum = pendulum
        run = RunOptions(t0=float(t0), dt=float(dt), order=SPRING_ORDERS[method])
        self._core = _SpringStepper(sp.spec, _pair(state), run)

    @property
    def t(self) -> float:
        return self._core.t

    @property
    def state(self) -> State:
        return State(self._core.x, self._core.v)

    def step(self, n: int = 1) -> None:
        self._core.step(int(n))

    def diagnostics(self) -> dict[str, Any]:
        """energy (kinetic + elastic + gravity) [J], j3, tension k(|r| − l₀) [N], acceleration, taut
        (always True)."""
        return dict(self._core.diagnostics()) | {"taut": True}


class StringStepper:
    """The string pendulum stepped in the core (``_StringStepper``) on the grid t₀ + k·dt; its
    taut/slack mode lives in the core's stepper. ``take_events()``: the leaves and snaps since the last
    call."""

    def __init__(self, pendulum: Pendulum, state: State, method: str, dt: float, t0: float) -> None:
        check_method("string", method)
        self.pendulum = pendulum
        run = RunOptions(t0=float(t0), method=method, dt=float(dt))
        self._core = _StringStepper(pendulum.spec, _pair(state), run)

    @property
    def t(self) -> float:
        return self._core.t

    @property
    def state(self) -> State:
        return State(self._core.x, self._core.v)

    @property
    def taut(self) -> bool:
        return bool(self._core.taut)

    def step(self, n: int = 1) -> None:
        self._core.step(int(n))

    def take_events(self) -> list[dict[str, Any]]:
        return list(self._core.take_events())

    def diagnostics(self) -> dict[str, Any]:
        """energy [J], j3, tension (0 while slack) [N], acceleration [m/s²], taut."""
        return dict(self._core.diagnostics())


OwnStepper = SpringStepper | StringStepper


def own_stepper(pendulum: LabPendulum, state: State, method: str, dt: float, t0: float) -> OwnStepper:
    """The core stepper of the spring or the string from ``state`` at ``t0`` [s]."""
    if isinstance(pendulum, SpringPendulum):
        return SpringStepper(pendulum, state, method, dt, t0)
    return StringStepper(pendulum, state, method, dt, t0)
