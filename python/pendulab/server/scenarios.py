"""The scenarios a lab session can start from: the example files by name, a file given to
``pendulab serve``, or a built-in rosette should the package's examples be missing. A page may load examples
by name only, never a path (it must not make the server read files).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ..integrators import DEFAULTS
from ..model import State
from ..scenario import Scenario, ScenarioError, load_scenario
from ..scenario.crane_schema import CraneSpec as CraneFileSpec
from ..scenario.examples import find as find_example
from ..scenario.examples import scenario_files as shipped_scenarios
from .crane_setup import crane_pendulum, crane_start
from .live_models import LabPendulum, scenario_pendulum
from .protocol import MODEL_SPECS

BUILTIN_SCENARIO = """
title = "Rosette: 60° release with sideways spin (built in)"
[pendulum]
length = 1.0
mass = 1.0
g = 9.81
[initial]
theta_deg = 60.0
phi_dot = 2.0
[simulation]
t_end = 100.0
method = "rattle"
dt = 1.0e-3
"""
"""Used when the package's example scenarios are missing (a package built without its data files)."""


@dataclass(frozen=True)
class Setup:
    """What a scenario gives a session: pendulum, start, integrator settings."""

    name: str | None
    title: str | None
    pendulum: LabPendulum
    state: State
    method: str
    dt: float
    rtol: float
    atol: float
    t0: float

    @classmethod
    def from_scenario(cls, sc: Scenario, name: str | None) -> Setup:
        """The setup of ``sc``; :class:`ScenarioError` if its model does not run in the lab (sampled
        pivot paths run with ``pendulab run`` only). A crane's file, ``[crane]``, starts the crane mode
        with its crane (:mod:`.crane_setup`)."""
        if isinstance(sc.spec, CraneFileSpec):  # sc.is_crane
            crane = crane_pendulum(sc.spec)
            sim_c = sc.spec.simulation
            # the crane's output_spacing is no step: the session's dt, used if a fixed-step method is
            # chosen after the crane mode, is the default step
            dt_next = float(DEFAULTS["dt"])
            return cls(
                name, sc.title, crane, crane_start(crane), "dop853", dt_next, sim_c.rtol, sim_c.atol, 0.0
            )
        model = sc._pendulum_spec().pendulum.model
        if model not in MODEL_SPECS:
            raise ScenarioError(
                sc.source,
                f"[pendulum] model = {model!r} does not run in the lab (use pendulab run); "
                f"the lab's models: {', '.join(MODEL_SPECS)}",
            )
        sim = sc._pendulum_spec().simulation
        rtol, atol = sim.resolved_tolerances()
        dt = sim.dt if sim.dt is not None else float(DEFAULTS["dt"])
        return cls(
            name, sc.title, scenario_pendulum(sc), sc.initial_state(), sim.method, dt, rtol, atol, sim.t0
        )


def scenario_files() -> dict[str, Path]:
    """The example scenarios by name (file stem): those shipped in the package
    (:mod:`pendulab.scenario.examples`)."""
    return shipped_scenarios()


def builtin_setup() -> Setup:
    return Setup.from_scenario(Scenario.from_toml_str(BUILTIN_SCENARIO, "<built-in rosette>"), "rosette")


def resolve_scenario(spec: str | Path | None) -> Setup:
    """A setup from a scenario name (``rosette``), a file path, or None (``rosette``, else the built-in)."""
    files = scenario_files()
    if spec is None:
        return (
            Setup.from_scenario(load_scenario(files["rosette"]), "rosette")
            if "rosette" in files
            else (builtin_setup())
        )
    text = str(spec)
    path = Path(text)
    if path.is_file():  # a file wins over an example of the same name, as for every command (docs/cli.md)
        return Setup.from_scenario(load_scenario(path), path.stem)
    try:  # an example by name, with or without .toml or example: (``pendulab run`` takes the same)
        found = find_example(text, "scenario")
    except OSError as e:
        raise ScenarioError(text, str(e).removeprefix(f"{text}: ")) from None
    return Setup.from_scenario(load_scenario(found), found.stem)


def example_resolver(default: Setup) -> Callable[[str], Setup]:
    """What ``load_scenario`` may load from a page: the example scenarios by name, and the server's own
    default scenario by its name. Never a path: a page must not read the server's files."""

    def resolve(name: str) -> Setup:
        if name == default.name:
            return default
        files = scenario_files()
        if name in files:
            return Setup.from_scenario(load_scenario(files[name]), name)
        known = ", ".join(sorted({*files, *([default.name] if default.name else [])}))
        raise ScenarioError(repr(name), f"no such scenario; available: {known}")

    return resolve
