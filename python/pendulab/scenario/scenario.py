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

Other models (docs/theory.md §7; ``pendulab models``) take their own keys in ``[pendulum]`` next to
``model``, in the units the registry gives (e.g. ``model = "damped"``, ``damping = 0.05`` in 1/s); an
angle in rad may instead be given in degrees as ``<name>_deg`` (``latitude_deg = 49.0``).

Files are validated with pydantic (unknown keys, wrong types, NaN/inf, out-of-range values and
contradictions are refused) and then by the core (the start must lie on TS², the saved samples
must fit in memory). Every problem raises :class:`ScenarioError` naming the file, the dotted key,
the bad value and what is allowed.

The file's parts: the tables and their validators in :mod:`pendulab.scenario.schema`, the error
messages (:class:`ScenarioError`) in :mod:`pendulab.scenario.errors`, building the pendulum or
spring and its start with the core's checks in :mod:`pendulab.scenario.build`; this module holds
:class:`Scenario` (construction, overrides, running, writing) and :func:`load_scenario`, and
re-exports the public names of the others; its TOML text, ``repr`` and HTML rows are written by
:mod:`pendulab.scenario.scenario_text`.

A file with a ``[crane]`` table describes a crane instead (docs/scenarios.md "Cranes"; the tables in
:mod:`pendulab.scenario.crane_schema`): it is validated here like any scenario, and the crane is
built and run by :mod:`pendulab.crane` (imported only for such a file: it needs SciPy).
"""

from __future__ import annotations

import dataclasses
import math
import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from pydantic import ValidationError

from .._core import IntegrationError, InvalidInputError
from ..display import Row, html_table
from ..io import atomic_path
from ..model import Pendulum, State
from ..simulation import simulate
from ..trajectory import Trajectory
from ..validate import check_depth, parse_toml, read_file_capped
from ..variants.spring import SpringTrajectory, SwingingSpring, simulate_spring
from .build import SPRING_ORDERS, build_pendulum, build_spring, check_run_settings, start_state
from .crane_schema import CRANE_SECTIONS, CraneSpec, is_crane
from .errors import EMPTY_FILE, ScenarioError, _syntax_error, file_problems
from .examples import find as find_example
from .overrides import RunOverrides, run_overrides
from .scenario_text import _toml_value as _toml_value
from .scenario_text import scenario_repr, summary_rows, toml_text
from .schema import (
    MODELS,
    SECTIONS,
    UNITS,
    InitialSection,
    PendulumSection,
    ScenarioSpec,
    SimulationSection,
    _show,
)

if TYPE_CHECKING:
    from ..crane.scenario import CraneScenario
    from ..crane.system import CraneRun

__all__ = [
    "MODELS",
    "SECTIONS",
    "SPRING_ORDERS",
    "UNITS",
    "InitialSection",
    "PendulumSection",
    "Scenario",
    "ScenarioError",
    "ScenarioSpec",
    "SimulationSection",
    "load_scenario",
]


@dataclass(frozen=True)
class Scenario:
    """A validated scenario: the pendulum, its initial state and the simulation settings.

    Build one with :func:`load_scenario`, :meth:`from_toml_str` or :meth:`from_dict`; construction
    checks everything a run needs (including that the start lies on TS² and that the saved samples
    fit in memory) and raises :class:`ScenarioError` otherwise. Two scenarios are equal when their
    settings are (``source`` is not compared).
    """

    spec: ScenarioSpec | CraneSpec
    source: str = field(default="<string>", compare=False)
    _pendulum: Pendulum = field(init=False, repr=False, compare=False)
    _spring: SwingingSpring | None = field(init=False, repr=False, compare=False)
    _state: State = field(init=False, repr=False, compare=False)
    _crane: CraneScenario | None = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "_spring", None)
        object.__setattr__(self, "_crane", None)
        if isinstance(self.spec, CraneSpec):
            object.__setattr__(self, "_crane", _build_crane(self.spec, self.source))
            return
        p, sim = self.spec.pendulum, self.spec.simulation
        if p.model == "spring":  # off the sphere: its own integrator (spring.py), not a Pendulum
            spring, state = build_spring(self.spec, self.source)
            object.__setattr__(self, "_spring", spring)
            object.__setattr__(self, "_state", state)
            return
        pendulum = build_pendulum(self.spec, self.source)
        object.__setattr__(self, "_pendulum", pendulum)
        object.__setattr__(self, "_state", start_state(pendulum, self.spec.initial, self.source))
        check_run_settings(pendulum, self._state, sim, self.source)

    @property
    def is_crane(self) -> bool:
        """True for a file with ``[crane]`` (a crane, :meth:`crane`), not a pendulum."""
        return isinstance(self.spec, CraneSpec)

    def crane(self) -> CraneScenario:
        """The ``pendulab.crane.scenario.CraneScenario`` of a file with ``[crane]`` (its ``crane``,
        ``shaper``, ``t_end``, ``dt`` [s], ``move_end`` [s], ``run()``); :class:`ScenarioError` for a
        pendulum's file."""
        if self._crane is None:
            raise ScenarioError(
                self.source, "this scenario is a pendulum, not a crane: it has no [crane] table"
            )
        return self._crane

    def _pendulum_spec(self) -> ScenarioSpec:
        if not isinstance(self.spec, ScenarioSpec):
            raise ScenarioError(
                self.source,
                "this scenario is a crane ([crane]), not a pendulum: see Scenario.crane(); "
                "it runs with Scenario.run() and `pendulab run`",
            )
        return self.spec

    def spring(self) -> SwingingSpring | None:
        """The swinging spring of a ``model = "spring"`` scenario (None for the pendulum models)."""
        return self._spring

    # --- construction ---

    @classmethod
    def from_dict(cls, data: dict[str, Any], source: str = "<dict>") -> Scenario:
        """A scenario from the parsed TOML structure (nested dicts); :class:`ScenarioError` if invalid."""
        root: type[ScenarioSpec] | type[CraneSpec] = CraneSpec if is_crane(data) else ScenarioSpec
        if root is CraneSpec and ("pendulum" in data or "initial" in data):
            extra = [f"[{k}]" for k in ("pendulum", "initial") if k in data]
            raise ScenarioError(
                source,
                f"a file with [crane] describes a crane, so {' and '.join(extra)} "
                f"{'does' if len(extra) == 1 else 'do'} not belong in it: a crane file has "
                f"the tables {', '.join(f'[{k}]' for k in CRANE_SECTIONS)} (docs/scenarios.md, Cranes)",
            )
        try:
            check_depth(data)
            spec = root.model_validate(data)
        except InvalidInputError as e:
            raise ScenarioError(source, str(e)) from None
        except ValidationError as e:
            raise ScenarioError(source, file_problems(e.errors(), data, root)) from None
        return cls(spec, source)

    @classmethod
    def from_toml_str(cls, text: str, source: str = "<string>") -> Scenario:
        """A scenario from TOML text; ``source`` names it in error messages."""
        text = text.removeprefix("\ufeff")  # a UTF-8 byte order mark (Windows editors write one)
        try:
            data = parse_toml(text)  # nesting checked before and after, over-long integers refused
        except tomllib.TOMLDecodeError as e:
            raise _syntax_error(source, text, e) from None
        except InvalidInputError as e:
            raise ScenarioError(source, str(e)) from None
        if not data:
            raise ScenarioError(source, EMPTY_FILE)
        return cls.from_dict(data, source)

    def with_overrides(self, overrides: RunOverrides | None = None, **fields: Any) -> Scenario:
        """A copy with some ``[simulation]`` settings replaced: a :class:`RunOverrides` and/or its
        fields as keywords (method, dt [s], t_end [s], save_every, rtol, atol [m and m/s]; ``None``
        keeps the file's value).

        ``save_every`` replaces a ``save_at`` list of the file. The result is validated like a file.
        """
        given = run_overrides(overrides, fields).given()
        if not given:
            return self
        if self.is_crane and (wrong := sorted(set(given) - {"dt", "t_end", "rtol", "atol"})):
            raise ScenarioError(
                self.source,
                f"a crane run takes no {', '.join(wrong)} (its [simulation] has t_end, output_spacing, "
                "sway, rigging_sway, rtol, atol: the crane has its own adaptive integrator)",
            )
        changes = ", ".join(f"{k} = {_show(v)}" for k, v in given.items())
        if self.is_crane and "dt" in given:  # a crane's dt (--dt) is the spacing of its output rows
            given = {("output_spacing" if k == "dt" else k): v for k, v in given.items()}
        data = self.to_dict()
        data["simulation"].update(given)
        if "save_every" in given:
            data["simulation"].pop("save_at", None)
        return Scenario.from_dict(data, f"{self.source} (with {changes})")

    # --- what it describes ---

    @property
    def title(self) -> str | None:
        """The file's title, if any."""
        return self.spec.title or None

    def pendulum(self) -> Pendulum:
        """The pendulum of ``[pendulum]`` (length [m], mass [kg], g [m/s²]). A ``model = "spring"``
        scenario has none (:meth:`spring` instead): :class:`ScenarioError`."""
        self._pendulum_spec()
        if self._spring is not None:
            raise ScenarioError(
                self.source,
                "the 'spring' model is a swinging spring, not a pendulum on the sphere: see "
                "Scenario.spring(); it runs with Scenario.run() and `pendulab run`",
            )
        return self._pendulum

    def initial_state(self) -> State:
        """The start of ``[initial]`` on TS²; with project = true, ``State.projection`` says how far."""
        self._pendulum_spec()
        return self._state

    def expected_samples(self) -> int | None:
        """How many samples a run will save (``None`` when an adaptive method decides, with save_every)."""
        if isinstance(self.spec, CraneSpec):
            return 1 + math.ceil(self.spec.simulation.t_end / self.spec.simulation.output_spacing - 1e-9)
        sim = self.spec.simulation
        if sim.save_at is not None:
            return len(sim.save_at)
        if sim.is_adaptive():
            return None
        steps = math.ceil((sim.t_end - sim.t0) / sim.resolved_dt())
        return 1 + math.ceil(steps / (sim.save_every or 1))

    def run(
        self, progress: bool | None = None, overrides: RunOverrides | None = None, **fields: Any
    ) -> Trajectory | SpringTrajectory | CraneRun:
        """Simulates the scenario; a :class:`RunOverrides` and/or its fields as keywords override
        ``[simulation]`` (see :meth:`with_overrides`).

        ``progress`` as in :func:`pendulab.simulate` (default: a bar only for long runs). Ctrl-C returns
        the samples computed so far with ``Trajectory.interrupted = True``. A crane's file returns the
        crane's run (``pendulab.crane.CraneRun``; overrides: t_end, dt — the crane's output_spacing —,
        rtol, atol).
        """
        sc = self.with_overrides(overrides, **fields)
        if sc._crane is not None:
            try:
                return sc._crane.run()
            except (IntegrationError, InvalidInputError) as e:
                raise type(e)(f"{sc.source}: {e}") from None
        spec = sc._pendulum_spec()
        sim = spec.simulation
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
            return dataclasses.replace(run, t=run.t + sim.t0)
        rtol, atol = sim.resolved_tolerances()
        try:
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
        except (IntegrationError, InvalidInputError) as e:  # name the file the run came from
            raise type(e)(f"{sc.source}: {e}") from None

    # --- showing itself ---

    def _summary(self) -> list[Row]:
        return summary_rows(self.spec, None if self.is_crane else self._state, self._crane)

    def __repr__(self) -> str:
        return scenario_repr(self.spec, None if self.is_crane else self._state, self.source)

    def _repr_html_(self) -> str:
        title = f"Scenario {self.title}" if self.title else "Scenario"
        return html_table(title, self._summary(), note=f"from {self.source}")

    # --- writing ---

    def to_dict(self) -> dict[str, Any]:
        """The settings as nested dicts (defaults filled in, unset optional keys left out)."""
        data = self.spec.model_dump(exclude_none=True)
        if "pendulum" in data:
            data["pendulum"].update(data["pendulum"].pop("params", {}))
        return data

    def to_toml(self) -> str:
        """The scenario as TOML text (units as comments); loading it gives an equal scenario."""
        return toml_text(self.spec, self.to_dict())

    def save(self, path: str | os.PathLike[str]) -> Path:
        """Writes :meth:`to_toml` to ``path`` atomically (temporary file + rename); returns the path."""
        text = self.to_toml()
        with atomic_path(path) as tmp:
            tmp.write_text(text, encoding="utf-8")
        return Path(path)


def _build_crane(spec: CraneSpec, source: str) -> CraneScenario:
    """The crane of a validated ``[crane]`` file, built by :mod:`pendulab.crane` (imported here only:
    it needs SciPy); what it refuses is a :class:`ScenarioError` naming the file."""
    try:
        from ..crane.scenario import from_spec
    except ImportError as e:
        raise ScenarioError(source, f"a crane scenario needs pendulab.crane: {e}") from None
    try:
        return from_spec(spec, source)
    except InvalidInputError as e:
        raise ScenarioError(source, str(e).removeprefix(f"{source}: ")) from None


def load_scenario(path: str | os.PathLike[str]) -> Scenario:
    """Reads and validates a scenario file (TOML, UTF-8): ``path`` as given when it exists, else the
    shipped example scenario of that name (``"rosette"``, as ``pendulab run rosette``; ``pendulab
    scenarios`` lists them).

    Raises :class:`ScenarioError` for bad contents (a file above 1 MiB or nested deeper than 16 levels
    is refused before parsing, docs/limits.md), :class:`FileNotFoundError` naming ``path`` and the
    shipped examples when it is neither a file nor an example's name, and ``OSError`` naming the file
    if it cannot be read.

    Examples
    --------
    >>> import pendulab as pl
    >>> pl.load_scenario("rosette").title
    'Rosette: 60° release with sideways spin'
    """
    found = find_example(os.fspath(path), "scenario")  # a path that exists wins over an example's name
    source = os.fspath(path) if found == Path(path) else os.fspath(found)
    try:
        text = read_file_capped(source)
    except InvalidInputError as e:
        raise ScenarioError(source, str(e)) from None
    return Scenario.from_toml_str(text, source)
