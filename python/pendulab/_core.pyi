"""Type stubs of the compiled core ``pendulab._core`` (hand-written; keep in sync with python/rust/lib.rs).
``make lint`` type-checks the package against them (mypy) and ``make lint-stubs`` checks them against the
built core (mypy's stubtest: names, parameters and defaults; the core's classes are final and built by
``__new__``, PyO3's ``#[new]``).

Units are SI: m, kg, s, rad. Vectors are float64 arrays of shape (3,), sequences (N, 3).
"""

from collections.abc import Callable
from typing import Any, Self, TypedDict, final

import numpy as np
import numpy.typing as npt

__version__: str
ENSEMBLE_LANES: int
"""Trajectories per block of the RATTLE ensemble (48): the unit of its parallel work."""

FloatArray = npt.NDArray[np.float64]
Steps = npt.NDArray[np.uint64]

class InvalidInputError(ValueError):
    """Bad input: the message names the value and what is allowed."""

class IntegrationError(RuntimeError):
    """The integration could not continue (diverged, near a pole for rk4_angles, step underflow)."""

class MethodInfo(TypedDict):
    name: str
    order: int
    symplectic: bool
    preserves_ts2: bool
    preserves_j3: bool
    adaptive: bool
    dense_output: bool
    default: bool
    summary: str

class ParamSpec(TypedDict):
    name: str
    label: str
    unit: str
    default: float
    min: float
    max: float
    description: str
    allowed: str

class ModelInfo(TypedDict):
    name: str
    label: str
    summary: str
    interactive: bool
    params: list[ParamSpec]

# Work counters (``stats``): a dict with the keys steps, rejected and rhs_evals (python/rust/convert.rs,
# stats_dict).

def methods() -> list[MethodInfo]: ...
def fused_is_fast() -> bool: ...
def arithmetic_version(arithmetic: str) -> int:
    """The version of the bits of the RATTLE arithmetic ``"unfused"`` or ``"fused"`` (bumped whenever
    any bit of its results changes); InvalidInputError for another name."""

def thread_pool() -> tuple[int, bool]: ...
def check_params(length: float, mass: float, g: float) -> None: ...
def models() -> list[ModelInfo]: ...
def limits() -> list[ParamSpec]: ...
def sensitivities(
    spec: ModelSpec, angles: list[float], times: FloatArray, options: RunOptions
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """x (n, 3) [m], v (n, 3) [m/s] at ``times`` [s] (≥ 0, non-decreasing; the start ``angles`` (θ₀,
    φ₀ [rad], θ̇₀, φ̇₀ [rad/s]) at t = 0) and dx, dv (n, 3, 9) by ``sensitivity_params()`` (T-10.7);
    the spec's model ideal, damped or rotating; DOP853 at the options' rtol, atol [m, m/s]."""

def sensitivity_params() -> list[str]:
    """theta0, phi0, theta_dot0, phi_dot0, length, g, damping, drag, friction: the last axis of
    ``sensitivities``."""

def spring_sensitivities(
    spec: ModelSpec, state: StateArrays, tangents: StateArrays, keep: Steps, options: RunOptions
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """x, v (n, 3) at the step numbers ``keep``; dx, dv, da (n, 3, m + 3) by the start tangents (dx0, dv0),
    (m, 3) each, then ``spring_sensitivity_params()`` (T-10.8, python/rust/sensitivity.rs)."""

def spring_sensitivity_params() -> list[str]: ...
def state_on_ts2(spec: ModelSpec, x: FloatArray, v: FloatArray) -> tuple[FloatArray, FloatArray]: ...
def project_state(
    spec: ModelSpec, x: FloatArray, v: FloatArray
) -> tuple[tuple[FloatArray, FloatArray], float, float]: ...
def state_from_angles(spec: ModelSpec, angles: list[float]) -> tuple[FloatArray, FloatArray]:
    """The state at (θ, φ [rad], θ̇, φ̇ [rad/s]): x [m], v [m/s]."""

def diagnostics(
    spec: ModelSpec, x: FloatArray, v: FloatArray, t: FloatArray | None = None
) -> dict[str, FloatArray]: ...

# --- python/rust/spec.rs: the run as one description, (spec, state, options) ---

StateArrays = tuple[FloatArray, FloatArray]
"""A start state: x0 [m], v0 [m/s], 3 components each."""

@final
class ModelSpec:
    """A model built and checked once: a registry model (l [m], m [kg], g [m/s²], its extra
    parameters, pivot samples (times [s], positions [m])) or, by ``spring_model``, the swinging spring."""

    def __new__(
        cls,
        length: float,
        mass: float,
        g: float,
        model_name: str | None = None,
        extra: list[tuple[str, float]] | None = None,
        pivot: tuple[FloatArray, FloatArray] | None = None,
    ) -> Self: ...
    @staticmethod
    def spring_model(k_over_m: float, rest_length: float, g: float, mass: float) -> ModelSpec: ...
    @property
    def name(self) -> str: ...
    @property
    def length(self) -> float: ...
    @property
    def mass(self) -> float: ...
    @property
    def g(self) -> float: ...

@final
class RunOptions:
    """How to run (keywords only; the method's dt [s], rtol, atol and projection default to the
    core's ``SolveOptions``): t0, t_end [s], conserve, the save rule, the saved-bytes cap, the spring's
    order (2 or 4), a cap on steps (the crane's runs), and the RATTLE family's ``arithmetic``
    (``"unfused"``, the default, or ``"fused"``; ``Solver``, ``Stepper`` and ``EnsembleRun``);
    ``halved_steps``: every fixed step as two halves (``Solver``, ``ForceSolver``, ``Stepper``; the error
    estimate's dt/2 companion on a sampled pivot, docs/integrators.md); ``steps_on_samples``: dt the
    longest fixed step, the steps landing on every sample of a sampled pivot (``Solver``,
    ``ForceSolver``, ``Stepper``; ``accuracy=``; ``pl.Stepper(steps_on_samples=True)``)."""

    def __new__(
        cls,
        *,
        t0: float = 0.0,
        t_end: float | None = None,
        method: str | None = None,
        dt: float | None = None,
        rtol: float | None = None,
        atol: float | None = None,
        project: bool | None = None,
        conserve: bool = False,
        save_every: int | None = None,
        save_times: FloatArray | None = None,
        max_saved_bytes: int | None = None,
        order: int = 2,
        max_steps: int | None = None,
        arithmetic: str = "unfused",
        halved_steps: bool = False,
        steps_on_samples: bool = False,
    ) -> Self: ...
    @property
    def arithmetic(self) -> str: ...
    @property
    def t0(self) -> float: ...
    @property
    def t_end(self) -> float | None: ...
    @property
    def method(self) -> str: ...
    @property
    def dt(self) -> float: ...

@final
class Solver:
    def __new__(cls, spec: ModelSpec, state: StateArrays, options: RunOptions) -> Self: ...
    def advance(self, budget: int) -> bool: ...
    def take_samples(self) -> tuple[FloatArray, FloatArray, FloatArray]: ...
    @property
    def progress(self) -> float: ...
    @property
    def t(self) -> float: ...
    @property
    def t_end(self) -> float: ...
    @property
    def done(self) -> bool: ...
    @property
    def stats(self) -> dict[str, int]: ...

@final
class Stepper:
    def __new__(cls, spec: ModelSpec, state: StateArrays, options: RunOptions) -> Self: ...
    def step(self, n: int = 1) -> None: ...
    def step_to(self, t: float, max_steps: int | None = None) -> bool: ...
    def set_state(self, x: FloatArray, v: FloatArray) -> None: ...
    @property
    def t(self) -> float: ...
    @property
    def x(self) -> FloatArray: ...
    @property
    def v(self) -> FloatArray: ...
    @property
    def stats(self) -> dict[str, int]: ...

# --- python/rust/exact.rs: the exact solution, the reduction, the energy–momentum map ---

@final
class ExactSolution:
    def __new__(cls, spec: ModelSpec, state: StateArrays) -> Self: ...
    def states(self, t: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]: ...
    @property
    def kind(self) -> str: ...
    @property
    def turning_heights(self) -> tuple[float, float, float | None]: ...
    @property
    def modulus(self) -> float | None: ...
    @property
    def period_z(self) -> float | None: ...
    @property
    def azimuth_advance(self) -> float | None: ...
    @property
    def omega0(self) -> float: ...
    def phases(self) -> tuple[float, float, float] | None: ...
    def constants(self) -> dict[str, float] | None: ...
    def weierstrass(self) -> dict[str, Any] | None: ...
    def heights_weierstrass(self, t: FloatArray) -> tuple[FloatArray, FloatArray] | None: ...

def invariants(length: float, x: FloatArray, v: FloatArray) -> FloatArray: ...
def relation_residuals(sigma: FloatArray) -> FloatArray: ...
def reduced_flow(
    spec: ModelSpec, state: StateArrays, options: RunOptions, n_steps: int
) -> tuple[FloatArray, FloatArray]: ...
def rotation_numbers(eps: FloatArray, j: FloatArray) -> FloatArray: ...
def conical_curve(u: FloatArray) -> tuple[FloatArray, FloatArray]: ...
def monodromy(r: float = 0.5, n: int = 720) -> float: ...

# --- python/rust/ensemble.rs: many trajectories at once ---

@final
class EnsembleSpec:
    """The ensemble's models: l [m], g [m/s²], damping c [1/s] (None: undamped), each one value or
    one per trajectory."""

    def __new__(cls, length: FloatArray, g: FloatArray, damping: FloatArray | None = None) -> Self: ...

@final
class EnsembleRun:
    """``n_steps`` steps of ``options.dt`` [s] of ``options.method`` ("rattle", or its compositions
    "rattle4", "rattle6", "rattle8"; others raise InvalidInputError) from x [m], v [m/s] (N, 3),
    saving every ``options``' ``save_every`` steps (None: the final state only), with
    ``options.arithmetic``."""

    def __new__(
        cls,
        spec: EnsembleSpec,
        x: FloatArray,
        v: FloatArray,
        options: RunOptions,
        n_steps: int,
        summary: bool = True,
        settle_angle: float | None = None,
    ) -> Self: ...
    @property
    def progress(self) -> float: ...
    @property
    def done(self) -> bool: ...
    def wait(self, timeout: float) -> bool: ...
    def cancel(self) -> None: ...
    def result(self) -> dict[str, Any]: ...

# --- python/rust/ensemble_adaptive.rs: any rod model (one or one per trajectory), DOP853 ---

@final
class AdaptiveEnsembleRun:
    def __new__(
        cls,
        spec: ModelSpec,
        x: FloatArray,
        v: FloatArray,
        options: RunOptions,
        models: list[ModelSpec] | None = None,
        index: npt.NDArray[np.int64] | None = None,
    ) -> Self: ...
    @property
    def progress(self) -> float: ...
    def wait(self, timeout: float) -> bool: ...
    def cancel(self) -> None: ...
    def result(self) -> dict[str, Any]: ...

# --- python/rust/spring.rs: the swinging spring ---

def spring_simulate(
    spec: ModelSpec, state: StateArrays, options: RunOptions, n_steps: int
) -> dict[str, Any]: ...
def spring_states_at(
    spec: ModelSpec, state: StateArrays, keep: Steps, options: RunOptions
) -> tuple[FloatArray, FloatArray]: ...

@final
class SpringStepper:
    def __new__(cls, spec: ModelSpec, state: StateArrays, options: RunOptions) -> Self: ...
    def step(self, n: int = 1) -> None: ...
    def diagnostics(self) -> dict[str, Any]: ...
    @property
    def t(self) -> float: ...
    @property
    def x(self) -> FloatArray: ...
    @property
    def v(self) -> FloatArray: ...

# --- python/rust/string.rs: the string pendulum (hybrid: taut, slack, snaps) ---

def string_simulate(spec: ModelSpec, state: StateArrays, options: RunOptions) -> dict[str, Any]: ...

@final
class StringRunner:
    def __new__(cls, spec: ModelSpec, state: StateArrays, options: RunOptions) -> Self: ...
    def advance(self, max_steps: int) -> bool: ...
    def take_samples(self, all: bool = False) -> dict[str, Any]: ...
    @property
    def progress(self) -> float: ...
    @property
    def t(self) -> float: ...
    @property
    def t_end(self) -> float: ...
    @property
    def stats(self) -> dict[str, int]: ...

@final
class StringStepper:
    def __new__(cls, spec: ModelSpec, state: StateArrays, options: RunOptions) -> Self: ...
    def step(self, n: int = 1) -> None: ...
    def diagnostics(self) -> dict[str, Any]: ...
    def take_events(self) -> list[dict[str, Any]]: ...
    @property
    def t(self) -> float: ...
    @property
    def x(self) -> FloatArray: ...
    @property
    def v(self) -> FloatArray: ...
    @property
    def taut(self) -> bool: ...

# --- python/rust/slewing.rs: the linearised slewing crane (T-7.2) ---

def slewing_linear(spec: ModelSpec, start: list[float], t: FloatArray) -> dict[str, Any]:
    """The small sway of the spec's ``slewing`` model from the boom-frame start (x₀, y₀ [m], ẋ₀,
    ẏ₀ [m/s]) at times t [s]."""

# --- python/rust/crane.rs: the crane dynamics (hoist, hook + payload, wind; T-11.4 – T-11.7) ---

Knots = tuple[FloatArray, FloatArray, FloatArray, FloatArray]
"""Knot times [s] (n,), values, rates, second derivatives (n, 3)."""

@final
class CraneSpec:
    """The crane: pivot and hoist knots, bodies ((mass [kg], c_W A [m²]), the payload under a hook
    (mass, c_W A, rigging [m]) or None), g [m/s²], damping [1/s], wind (steady, gust peak [m/s],
    gust start, duration [s], air density [kg/m³], turbulence (ω [rad/s], amplitudes [m/s], phases))."""

    def __new__(
        cls,
        pivot: Knots,
        hoist: Knots,
        bodies: tuple[tuple[float, float], tuple[float, float, float] | None],
        g: float,
        damping: float,
        wind: tuple[
            tuple[float, float, float],
            tuple[float, float, float],
            float,
            float,
            float,
            tuple[list[float], list[list[float]], list[list[float]]],
        ],
    ) -> Self: ...

def crane_simulate(spec: CraneSpec, y0: list[float], options: RunOptions) -> dict[str, Any]:
    """From y0 (16,) at the first of ``options.save_times`` [s] through all of them, at the options'
    rtol, atol and max_steps: t, y (N, 16), tension (N, 2) [N], steps, rejected."""

def crane_residual_grid(
    moves: list[tuple[Knots, float]],
    ropes: list[float],
    ratios: list[float],
    crane: tuple[float, float, float],
    settle: float,
    options: RunOptions,
) -> FloatArray:
    """Residual sway [m] per (move, rope, ratio); ``crane`` = (hook mass [kg], rigging [m], g [m/s²]);
    the options' dt [s], rtol, atol, max_steps."""

# --- python/rust/force.rs: a user force given as a Python callable (the slow path) ---

@final
class ForceSolver:
    def __new__(
        cls,
        spec: ModelSpec,
        state: StateArrays,
        options: RunOptions,
        force: Callable[[float, list[float], list[float]], Any],
    ) -> Self: ...
    def advance(self, budget: int) -> bool: ...
    def take_samples(self) -> tuple[FloatArray, FloatArray, FloatArray]: ...
    @property
    def progress(self) -> float: ...
    @property
    def t(self) -> float: ...
    @property
    def t_end(self) -> float: ...
    @property
    def done(self) -> bool: ...
    @property
    def stats(self) -> dict[str, int]: ...

# --- python/rust/live.rs: the lab's live session (pendulab_core::live), the server's sessions ---

class LiveLimit(TypedDict):
    """One of the lab's command limits (``LiveSession.limits()``): the allowed range and its SI unit."""

    min: float
    max: float
    unit: str

@final
class LiveSession:
    """One client's lab session of the core: commands in (the lab's JSON), frame records (bytes,
    frame.json's float64 values) and JSON notices (str) out; the interpreter lock is released while it
    steps. Times in s, SI units."""

    TICK_BUDGET: float
    FIRST_SLICE: int
    MAX_SUBSAMPLES: int
    MAX_ELAPSED: float
    MAX_EVENT_NOTICES: int
    MAX_PENDING_STEPS: int
    MAX_MESSAGE_BYTES: int
    @staticmethod
    def command_types() -> tuple[str, ...]: ...
    @staticmethod
    def limits() -> dict[str, LiveLimit]: ...
    def __new__(cls, setup_json: str, exact_error: bool = True) -> Self: ...
    def first_messages(self) -> list[bytes | str]: ...
    def tick(
        self,
        commands: list[str | tuple[Any, ...]],
        elapsed: float,
        budget: float,
        dropped: int = 0,
        debt: float | None = None,
    ) -> tuple[list[bytes | str], int, float | None]: ...
    def apply(self, command: str | tuple[Any, ...]) -> bytes | None: ...
    def advance(self, elapsed: float, budget: float) -> bytes: ...
    def take_pending_steps(self, budget: float) -> bytes | None: ...
    def fill_errors(self, records: bytes, budget: float) -> bytes: ...
    def take_event_notices(self) -> list[str]: ...
    def record(self) -> bytes: ...
    def status(self) -> str: ...
    paused: bool
    @property
    def epoch(self) -> int: ...
    @property
    def lagging(self) -> bool: ...
    @property
    def pending_steps(self) -> int: ...
    @property
    def commands(self) -> int: ...
    @property
    def t(self) -> float: ...
    @property
    def clock(self) -> float: ...
    @property
    def x(self) -> FloatArray: ...
    @property
    def v(self) -> FloatArray: ...
    @property
    def error_start(self) -> tuple[float, FloatArray, FloatArray]: ...
    @property
    def scenario(self) -> str | None: ...
    @property
    def model(self) -> str: ...
    @property
    def method(self) -> str: ...
    @property
    def dt(self) -> float: ...
    @property
    def time_scale(self) -> float: ...
