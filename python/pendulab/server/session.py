"""One lab session: a pendulum, an incremental :class:`pendulab.Stepper` and the pacing, without any I/O.

The WebSocket handler (:mod:`pendulab.server.app`) owns one :class:`Session` per client, calls
:meth:`Session.apply` for each validated command and :meth:`Session.advance` once per tick with the
wall-clock time elapsed; both return what to send (frame records, JSON notices). Keeping this free
of asyncio and sockets makes it testable on its own and keeps the physics in the core: the session
only decides *how far* to step, the core steps.

Pacing: while running, the simulated time advances by (wall-clock seconds elapsed) × ``time_scale``.
Fixed-step methods take whole steps of exactly ``dt`` (``Stepper.step(n)``), so a live run is the
same sequence of steps as ``pl.simulate`` with that ``dt`` — the frames show the method's true long-time
behaviour; the adaptive ``dop853`` lands on the target times with ``step_to``. Each tick sends up to
:data:`MAX_SUBSAMPLES` records spread over the tick's simulated interval (more when faster than real
time, so trails and plots stay smooth) and never takes more than :data:`MAX_STEPS_PER_TICK` steps;
when that limit bites, the simulation runs slower than asked and ``status.lagging`` says so.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from .. import _core
from ..model import Pendulum, State
from ..scenario import Scenario, ScenarioError, load_scenario
from ..simulate import DEFAULTS, Stepper, methods
from .protocol import (
    FRAME_FIELDS,
    RECORD_LEN,
    Command,
    CommandError,
    LoadScenario,
    Pause,
    Reset,
    Resume,
    SetMethod,
    SetParams,
    SetState,
    SetTimeScale,
    Step,
)

MAX_STEPS_PER_TICK = 200_000
"""Most integrator steps one tick may take (about 7 ms of RATTLE on the reference machine)."""

MAX_SUBSAMPLES = 16
"""Most frame records sent per tick."""

MAX_ELAPSED = 0.1
"""Longest wall-clock interval [s] one tick catches up on (after a stall the run resumes, not jumps)."""

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
"""Used when no scenario files are found (a package installed without the source tree's examples)."""


@dataclass(frozen=True)
class Setup:
    """What a scenario gives a session: pendulum, start, integrator settings."""

    name: str | None
    title: str | None
    pendulum: Pendulum
    state: State
    method: str
    dt: float
    rtol: float
    atol: float
    t0: float

    @classmethod
    def from_scenario(cls, sc: Scenario, name: str | None) -> Setup:
        sim = sc.spec.simulation
        rtol, atol = sim.resolved_tolerances()
        dt = sim.dt if sim.dt is not None else float(DEFAULTS["dt"])
        return cls(name, sc.title, sc.pendulum(), sc.initial_state(), sim.method, dt, rtol, atol, sim.t0)


def scenario_dirs() -> list[Path]:
    """Where example scenarios are looked for: ./examples/scenarios, then the source tree's."""
    here = Path(__file__).resolve()
    found: list[Path] = []
    for d in (Path.cwd() / "examples" / "scenarios", here.parents[3] / "examples" / "scenarios"):
        if d.is_dir() and d.resolve() not in found:
            found.append(d.resolve())
    return found


def scenario_files() -> dict[str, Path]:
    """Example scenarios by name (file stem); the first directory of :func:`scenario_dirs` wins."""
    files: dict[str, Path] = {}
    for d in reversed(scenario_dirs()):
        files.update({f.stem: f for f in sorted(d.glob("*.toml"))})
    return dict(sorted(files.items()))


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
    if text in files:
        return Setup.from_scenario(load_scenario(files[text]), text)
    path = Path(text)
    if path.is_file():
        return Setup.from_scenario(load_scenario(path), path.stem)
    known = ", ".join(files) or "none found"
    raise ScenarioError(text, f"no such scenario file or example name (examples: {known})")


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


def _state_record(t: float, x: np.ndarray, v: np.ndarray, diag: dict[str, np.ndarray]) -> np.ndarray:
    rec = np.empty((len(t), RECORD_LEN))
    rec[:, 0] = t
    rec[:, 1:4] = x
    rec[:, 4:7] = v
    rec[:, 7] = diag["energy"]
    rec[:, 8] = diag["j3"]
    rec[:, 9] = diag["tension"]
    return rec


class Session:
    """The state of one client's lab. Not thread-safe: one owner calls :meth:`apply` and :meth:`advance`."""

    def __init__(self, setup: Setup, resolve: Callable[[str], Setup] | None = None) -> None:
        self._resolve = resolve or example_resolver(setup)
        self.time_scale = 1.0
        self.paused = False
        self.epoch = 0
        self.lagging = False
        self._adaptive = {m["name"]: bool(m["adaptive"]) for m in methods()}
        self._load(setup)

    # --- set-up ---

    def _load(self, setup: Setup) -> None:
        self.scenario = setup.name
        self.title = setup.title
        self.pendulum = setup.pendulum
        self.method, self.dt, self.rtol, self.atol = setup.method, setup.dt, setup.rtol, setup.atol
        self.t0 = setup.t0
        self._set_start(setup.state)
        self._new_stepper(setup.state, setup.t0)

    def _set_start(self, state: State) -> None:
        self._start, self._start_length = state, self.pendulum.length

    def _start_state(self) -> State:
        """The start for the current pendulum: after a length change, the same angles and angular rates."""
        ell = self.pendulum.length
        if ell == self._start_length:
            return self._start
        k = ell / self._start_length
        return self.pendulum.state(np.array(self._start.x) * k, np.array(self._start.v) * k, project=True)

    def _new_stepper(self, state: State, t: float) -> None:
        dt = 0.0 if self.adaptive else self.dt
        self.stepper = Stepper(
            self.pendulum, state, method=self.method, dt=dt, rtol=self.rtol, atol=self.atol, t0=t
        )
        self.clock = t

    @property
    def adaptive(self) -> bool:
        """True when the method chooses its own steps (``dop853``)."""
        return self._adaptive[self.method]

    # --- what is sent ---

    def records(self) -> np.ndarray:
        """The current state as one frame record, shape (1, RECORD_LEN)."""
        s = self.stepper.state
        diag = self.pendulum.diagnostics(s.x, s.v)
        return _state_record(np.array([self.stepper.t]), s.x[None, :], s.v[None, :], diag)

    def status(self) -> dict[str, Any]:
        """The JSON ``status`` notice: everything the page needs to show and to encode in its URL."""
        start = self._start_state()
        p = self.pendulum
        return {
            "type": "status",
            "epoch": self.epoch,
            "scenario": self.scenario,
            "title": self.title,
            "paused": self.paused,
            "time_scale": self.time_scale,
            "method": self.method,
            "adaptive": self.adaptive,
            "dt": self.dt,
            "params": {"length": p.length, "mass": p.mass, "g": p.g},
            "t": self.stepper.t,
            "t0": self.t0,
            "start": {"x": [float(c) for c in start.x], "v": [float(c) for c in start.v]},
            "lagging": self.lagging,
            "frame_fields": list(FRAME_FIELDS),
        }

    # --- commands ---

    def apply(self, cmd: Command) -> np.ndarray | None:
        """Carries out one command; returns frame records to send at once (or None).

        Raises :class:`CommandError` when the command is valid JSON but cannot be carried out here
        (unknown scenario, a state off TS², …); the session is then unchanged.
        """
        try:
            return self._apply(cmd)
        except (_core.InvalidInputError, ScenarioError, tomllib.TOMLDecodeError, OSError) as e:
            raise CommandError(" ".join(str(e).split()), command=cmd.type) from None
        except _core.IntegrationError as e:
            self.paused = True
            raise CommandError(f"integration stopped: {e}; paused", command=cmd.type) from None

    def _apply(self, cmd: Command) -> np.ndarray | None:
        match cmd:
            case SetParams():
                p = self.pendulum
                new = Pendulum(
                    length=p.length if cmd.length is None else cmd.length,
                    g=p.g if cmd.g is None else cmd.g,
                    mass=p.mass if cmd.mass is None else cmd.mass,
                )
                s, k = self.stepper.state, new.length / p.length
                state = new.state(np.array(s.x) * k, np.array(s.v) * k, project=True)
                self.pendulum = new
                self._new_stepper(state, self.stepper.t)
                self.epoch += 1
                return self.records()
            case SetState():
                state = cmd.to_state(self.pendulum)
                self._new_stepper(state, self.stepper.t)
                self._set_start(state)
                self.epoch += 1
                return self.records()
            case SetMethod():
                old = (self.method, self.dt)
                self.method = cmd.method or self.method
                self.dt = cmd.dt or self.dt
                try:
                    self._new_stepper(self.stepper.state, self.stepper.t)
                except Exception:
                    self.method, self.dt = old
                    raise
                return None
            case SetTimeScale():
                self.time_scale = cmd.time_scale
                return None
            case Pause():
                self.paused = True
                return None
            case Resume():
                self.paused = False
                self.clock = self.stepper.t
                return None
            case Step():
                self.paused = True
                self.stepper.step(cmd.n)
                self.clock = self.stepper.t
                return self.records()
            case Reset():
                self._new_stepper(self._start_state(), self.t0)
                self.epoch += 1
                return self.records()
            case LoadScenario():
                self._load(self._resolve(cmd.name))
                self.epoch += 1
                return self.records()
        raise CommandError(f"command {cmd.type!r} is not handled")  # pragma: no cover - exhaustive

    # --- pacing ---

    def advance(self, elapsed: float) -> np.ndarray | None:
        """Advances by ``elapsed`` wall-clock seconds × time_scale; the records to send (or None).

        Raises :class:`CommandError` (command None) and pauses when the integration cannot go on.
        """
        if self.paused:
            return None
        elapsed = min(max(float(elapsed), 0.0), MAX_ELAPSED)
        t = self.stepper.t
        self.clock = max(self.clock, t) + elapsed * self.time_scale
        n_sub = max(1, min(MAX_SUBSAMPLES, math.ceil(self.time_scale - 1e-9)))
        try:
            if self.adaptive:
                targets = [t + (self.clock - t) * (i + 1) / n_sub for i in range(n_sub)]
                return self._sample(lambda k: self.stepper.step_to(targets[k]), n_sub)
            n = math.floor((self.clock - t) / self.dt + 1e-9)
            lagging = n > MAX_STEPS_PER_TICK
            if lagging:
                n = MAX_STEPS_PER_TICK
                self.clock = t + n * self.dt
            self.lagging = lagging
            if n <= 0:
                return None
            n_sub = min(n_sub, n)
            bounds = [round(n * (i + 1) / n_sub) for i in range(n_sub)]
            steps = [b - a for a, b in zip([0, *bounds[:-1]], bounds, strict=True)]
            return self._sample(lambda k: self.stepper.step(steps[k]), n_sub)
        except _core.IntegrationError as e:
            self.paused = True
            raise CommandError(f"integration stopped at t = {self.stepper.t:g} s: {e}; paused") from None

    def _sample(self, advance: Callable[[int], object], n: int) -> np.ndarray:
        ts = np.empty(n)
        xs = np.empty((n, 3))
        vs = np.empty((n, 3))
        for k in range(n):
            advance(k)
            s = self.stepper.state
            ts[k], xs[k], vs[k] = self.stepper.t, s.x, s.v
        return _state_record(ts, xs, vs, self.pendulum.diagnostics(xs, vs))
