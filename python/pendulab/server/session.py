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
time, so trails and plots stay smooth). A tick's stepping — a ``step`` command's n steps and the
advance — shares one wall-time budget (:mod:`.budget`): the core is called in slices until the work is
done or the budget spent; then the simulation runs slower than asked and ``status.lagging`` says so
(a ``step`` of many steps goes on at the next ticks, its frame sent when done).
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from ..model import Pendulum, State
from ..scenario import ScenarioError
from ..simulation import Stepper, methods
from .budget import Budget, Slicer
from .live_error import UNKNOWN, LiveError
from .live_models import (
    DEFAULT_METHOD,
    OWN_STEPPER_MODELS,
    LabPendulum,
    OwnStepper,
    carry_state,
    lab_pendulum,
    methods_for,
    own_stepper,
)
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
    SetModel,
    SetParams,
    SetState,
    SetTimeScale,
    Step,
    check_model_params,
    event_notice,
    own_params,
)
from .scenarios import Setup, example_resolver, resolve_scenario, scenario_files

__all__ = ["Session", "Setup", "example_resolver", "model_params", "resolve_scenario", "scenario_files"]

MAX_PENDING_STEPS = 1_000_000
"""Most steps of ``step`` commands waiting to be taken; a ``step`` beyond is refused (it would keep the
session busy for long)."""

MAX_SUBSAMPLES = 16
"""Most frame records sent per tick."""

MAX_ELAPSED = 0.1
"""Longest wall-clock interval [s] one tick catches up on (after a stall the run resumes, not jumps)."""

MAX_EVENT_NOTICES = 16
"""Most ``event`` notices sent per tick (the latest ones; each says how many earlier were skipped):
a fast bouncing string at a high time scale cannot flood the page."""

_SCALAR = {
    name: FRAME_FIELDS.index(name) for name in ("t", "energy", "j3", "tension", "power", "taut", "error_x")
}
_VECTOR = {name: FRAME_FIELDS.index(f"{name}1") for name in ("x", "v", "a", "pivot")}


def state_records(pendulum: Pendulum, t: np.ndarray, x: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Frame records (N, RECORD_LEN) of states x [m], v [m/s] at times t [s]: the core's diagnostics at
    those times (time-dependent models: forcing, moving pivot), the acceleration ẍ [m/s²] relative to
    the pivot (m ẍ is the net force there) and the pivot's position [m] (0 for a fixed pivot); ``taut``
    is 1 (the bob is on the sphere); ``error_x`` unknown until :meth:`Session.fill_errors`."""
    diag = pendulum.diagnostics(x, v, t)
    rec = np.zeros((len(t), RECORD_LEN))
    rec[:, _SCALAR["t"]] = t
    rec[:, _SCALAR["taut"]] = 1.0
    rec[:, _SCALAR["error_x"]] = UNKNOWN
    for name in ("energy", "j3", "tension", "power"):
        rec[:, _SCALAR[name]] = diag[name]
    for name, values in (("x", x), ("v", v), ("a", diag["acceleration"]), ("pivot", diag.get("pivot"))):
        if values is not None:
            rec[:, _VECTOR[name] : _VECTOR[name] + 3] = values
    return rec


def own_record(stepper: OwnStepper) -> np.ndarray:
    """The frame record (RECORD_LEN,) of the spring's or the string's stepper at its current state:
    the core's energy, J₃, tension (the spring's k(|r| − l₀); the string's, 0 while slack) and
    acceleration; power 0 (both conservative between the string's snaps), pivot 0; ``taut`` 0 while the
    string is slack; ``error_x`` unknown until :meth:`Session.fill_errors`."""
    d = stepper.diagnostics()
    s = stepper.state
    rec = np.zeros(RECORD_LEN)
    rec[_SCALAR["t"]] = stepper.t
    for name in ("energy", "j3", "tension"):
        rec[_SCALAR[name]] = d[name]
    rec[_SCALAR["taut"]] = 1.0 if d["taut"] else 0.0
    rec[_SCALAR["error_x"]] = UNKNOWN
    for name, values in (("x", s.x), ("v", s.v), ("a", d["acceleration"])):
        rec[_VECTOR[name] : _VECTOR[name] + 3] = values
    return rec


def model_params(pendulum: LabPendulum) -> dict[str, float]:
    """Every own parameter of the pendulum's model (SI units): the given ones, else the registry's default."""
    given = pendulum.extra
    return {p["name"]: given.get(p["name"], float(p["default"])) for p in own_params(pendulum.model)}


def describe(setup: Setup) -> dict[str, Any]:
    """A setup as ``GET /api/scenarios`` lists it and the page loads it (also a fitted scenario,
    ``POST /api/fit``): name, title, length [m], mass [kg], g [m/s²], model and its parameters, the
    start x [m], v [m/s], method, dt [s] and t0 [s]."""
    p = setup.pendulum
    return {
        "name": setup.name,
        "title": setup.title,
        "params": {"length": p.length, "mass": p.mass, "g": p.g},
        "model": p.model,
        "model_params": model_params(p),
        "start": {"x": [float(c) for c in setup.state.x], "v": [float(c) for c in setup.state.v]},
        "method": setup.method,
        "dt": setup.dt,
        "t0": setup.t0,
    }


def rebuild(pendulum: LabPendulum, **changes: Any) -> LabPendulum:
    """The same model with some of length [m], mass [kg], g [m/s²] or its own parameters changed
    (``model=`` switches the model: its own parameters start from the registry's defaults)."""
    model = changes.pop("model", None) or pendulum.model
    common = {k: changes.pop(k, None) for k in ("length", "mass", "g")}
    own = model_params(pendulum) if model == pendulum.model else {}
    own |= {p["name"]: float(p["default"]) for p in own_params(model) if p["name"] not in own}
    own |= {k: float(v) for k, v in changes.items()}
    return lab_pendulum(
        pendulum.length if common["length"] is None else common["length"],
        pendulum.g if common["g"] is None else common["g"],
        pendulum.mass if common["mass"] is None else common["mass"],
        model,
        **own,
    )


class Session:
    """The state of one client's lab. Not thread-safe: one owner calls :meth:`apply` and :meth:`advance`.

    ``exact_error=False`` estimates the ideal pendulum's error with a companion too, as for the other
    models, instead of taking the true error from the exact solution (for tests of the estimate)."""

    def __init__(
        self, setup: Setup, resolve: Callable[[str], Setup] | None = None, *, exact_error: bool = True
    ) -> None:
        self._resolve = resolve or example_resolver(setup)
        self.time_scale = 1.0
        self.paused = False
        self.epoch = 0
        self.lagging = False
        self.pending_steps = 0
        self._slicer = Slicer()
        self._adaptive = {m["name"]: bool(m["adaptive"]) for m in methods()}
        self._events: list[tuple[dict[str, Any], int]] = []
        self.exact_error = exact_error
        self.commands = 0  # command messages handled (applied, refused or dropped): status.commands
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
        return carry_state(self.pendulum, np.array(self._start.x) * k, np.array(self._start.v) * k)

    def _new_stepper(self, state: State, t: float, pendulum: LabPendulum | None = None) -> None:
        """A stepper from ``state`` at ``t``; with ``pendulum``, that pendulum replaces the current one
        only once its stepper exists (a method refusing the model leaves the session unchanged). The
        spring and the string step with their own core steppers (:mod:`.live_models`)."""
        self._collect_events()  # the old stepper's events keep their epoch
        p = self.pendulum if pendulum is None else pendulum
        self.stepper: Stepper | OwnStepper = self._make_stepper(p, state, t, {"dt": self.dt})
        self.pendulum = p
        self.clock = t
        self.pending_steps = 0  # a `step` still under way belonged to the stepper replaced
        self._slicer.reset()
        options = {"dt": self.dt, "rtol": self.rtol, "atol": self.atol}
        self.error = LiveError(
            p,
            state,
            t,
            self.method,
            options,
            self.adaptive,
            lambda ref: self._make_stepper(p, state, t, options | ref),
            exact=self.exact_error,
        )

    def _make_stepper(
        self, p: LabPendulum, state: State, t: float, options: dict[str, float]
    ) -> Stepper | OwnStepper:
        """A stepper of ``p`` from ``state`` at ``t`` with the session's method and ``options`` (dt [s],
        and rtol, atol for ``dop853``; the session's own where not given)."""
        dt = float(options.get("dt", self.dt))
        if p.model in OWN_STEPPER_MODELS:
            return own_stepper(p, state, self.method, dt, t)
        assert isinstance(p, Pendulum)
        rtol, atol = options.get("rtol", self.rtol), options.get("atol", self.atol)
        dt = 0.0 if self.adaptive else dt
        return Stepper(p, state, method=self.method, dt=dt, rtol=rtol, atol=atol, t0=t)

    def fill_errors(self, records: np.ndarray | None, budget: Budget) -> None:
        """Sets the ``error_x`` column [m] of the current stepper's ``records`` (:mod:`.live_error`):
        the companion steps only within what is left of ``budget``."""
        self.error.fill(records, budget)

    @property
    def adaptive(self) -> bool:
        """True when the method chooses its own steps (``dop853``)."""
        return self._adaptive[self.method]

    # --- what is sent ---

    def records(self) -> np.ndarray:
        """The current state as one frame record, shape (1, RECORD_LEN)."""
        if not isinstance(self.stepper, Stepper):
            return own_record(self.stepper)[None, :]
        s = self.stepper.state
        return state_records(self.pendulum, np.array([self.stepper.t]), s.x[None, :], s.v[None, :])

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
            "model": p.model,
            "model_params": model_params(p),
            "t": self.stepper.t,
            "t0": self.t0,
            "start": {"x": [float(c) for c in start.x], "v": [float(c) for c in start.v]},
            "lagging": self.lagging,
            "error_estimate": self.error.describe(),
            "commands": self.commands,
            "frame_fields": list(FRAME_FIELDS),
        }

    def _collect_events(self) -> None:
        take = getattr(getattr(self, "stepper", None), "take_events", None)
        if take is not None:
            self._events.extend((e, self.epoch) for e in take())

    def take_event_notices(self) -> list[dict[str, Any]]:
        """The JSON ``event`` notices of the string's leaves and snaps (the core's
        ``StringStepper.take_events()``) since the last call, oldest first: at most
        :data:`MAX_EVENT_NOTICES`, the latest, each counting the earlier ones it skipped. Empty for the
        other models."""
        self._collect_events()
        events, self._events = self._events, []
        skipped = max(0, len(events) - MAX_EVENT_NOTICES)
        return [event_notice(e, epoch, skipped) for e, epoch in events[skipped:]]

    # --- commands ---

    def apply(self, cmd: Command) -> np.ndarray | None:
        """Carries out one command; returns frame records to send at once (or None).

        Raises :class:`CommandError` when the command is valid JSON but cannot be carried out here
        (unknown scenario, a state off TS², …); the session is then unchanged.
        """
        try:
            return self._apply(cmd)
        except (InvalidInputError, ScenarioError, tomllib.TOMLDecodeError, OSError) as e:
            raise CommandError(" ".join(str(e).split()), command=cmd.type) from None
        except IntegrationError as e:
            self.paused = True
            raise CommandError(
                f"integration stopped: {e}; paused", cmd.type, "integration_stopped", {"detail": str(e)}
            ) from None

    def _apply(self, cmd: Command) -> np.ndarray | None:
        match cmd:
            case SetParams():
                p = self.pendulum
                check_model_params(p.model, cmd.params or {})
                new = rebuild(p, length=cmd.length, mass=cmd.mass, g=cmd.g, **(cmd.params or {}))
                s, k = self.stepper.state, new.length / p.length
                state = new.state(np.array(s.x) * k, np.array(s.v) * k, project=True)
                self._new_stepper(state, self.stepper.t, new)
                self.epoch += 1
                return self.records()
            case SetModel():
                new = rebuild(self.pendulum, model=cmd.model, **cmd.params)
                s = self.stepper.state
                old = self.method
                allowed = methods_for(cmd.model)
                if allowed is not None and self.method not in allowed:
                    self.method = DEFAULT_METHOD  # the spring and the string run the RATTLE family
                try:
                    self._new_stepper(carry_state(new, s.x, s.v), self.stepper.t, new)
                except Exception:
                    self.method = old
                    raise
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
                self.pending_steps = 0
                self.clock = self.stepper.t
                return None
            case Step():
                if self.pending_steps + cmd.n > MAX_PENDING_STEPS:
                    raise CommandError(
                        f"still stepping: {self.pending_steps} steps are waiting to be taken (at most "
                        f"{MAX_PENDING_STEPS}); wait for the frame, or pause",
                        command="step",
                    )
                self.paused = True
                self.pending_steps += cmd.n  # taken within the tick's budget (take_pending_steps)
                return None
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

    def take_pending_steps(self, budget: Budget) -> np.ndarray | None:
        """Takes the waiting steps of ``step`` commands within ``budget``; the frame record of the state
        reached (None when none were waiting). Raises :class:`CommandError` (command ``step``) and
        pauses when the integration cannot go on."""
        if self.pending_steps <= 0:
            return None
        try:
            self.pending_steps -= self._slicer.steps(self.stepper.step, self.pending_steps, budget)
        except IntegrationError as e:
            self.pending_steps = 0
            raise CommandError(
                f"integration stopped at t = {self.stepper.t:g} s: {e}; paused",
                "step",
                "integration_stopped",
                {"detail": str(e)},
            ) from None
        self.clock = self.stepper.t
        return self.records()

    def advance(self, elapsed: float, budget: Budget | None = None) -> np.ndarray | None:
        """Advances by ``elapsed`` wall-clock seconds × time_scale within ``budget`` (default: a new
        :class:`Budget` of one tick); the records to send (or None). Out of budget, it stops where it
        got to and sets ``lagging``.

        Raises :class:`CommandError` (command None) and pauses when the integration cannot go on.
        """
        if self.paused:
            return None
        budget = Budget() if budget is None else budget
        elapsed = min(max(float(elapsed), 0.0), MAX_ELAPSED)
        t = self.stepper.t
        self.clock = max(self.clock, t) + elapsed * self.time_scale
        n_sub = max(1, min(MAX_SUBSAMPLES, math.ceil(self.time_scale - 1e-9)))
        try:
            if self.adaptive:
                targets = [t + (self.clock - t) * (i + 1) / n_sub for i in range(n_sub)]
                stepper = self.stepper
                assert isinstance(stepper, Stepper)

                def to_target(k: int) -> bool:
                    target = targets[k]

                    def capped(cap: int) -> bool:
                        stepper.step_to(target, max_steps=cap)
                        return stepper.t >= target

                    return self._slicer.until(capped, budget)

                return self._sample(to_target, n_sub)
            n = math.floor((self.clock - t) / self.dt + 1e-9)
            if n <= 0:
                self.lagging = False
                return None
            n_sub = min(n_sub, n)
            bounds = [round(n * (i + 1) / n_sub) for i in range(n_sub)]
            steps = [b - a for a, b in zip([0, *bounds[:-1]], bounds, strict=True)]
            return self._sample(
                lambda k: self._slicer.steps(self.stepper.step, steps[k], budget) == steps[k], n_sub
            )
        except IntegrationError as e:
            self.paused = True
            raise CommandError(
                f"integration stopped at t = {self.stepper.t:g} s: {e}; paused",
                key="integration_stopped",
                values={"detail": str(e)},
            ) from None

    def _sample(self, advance: Callable[[int], bool], n: int) -> np.ndarray:
        """Records of the states after ``advance(k)`` for k < n; ``advance`` returns False when the
        budget ran out first: the records stop there, the session lags (its clock is set back to
        where the stepper got, so the missing time is not piled up)."""
        done = True
        taken = 0
        ts = np.empty(n)
        xs = np.empty((n, 3))
        vs = np.empty((n, 3))
        rows = []
        for k in range(n):
            done = advance(k)
            if isinstance(self.stepper, Stepper):
                s = self.stepper.state
                ts[taken], xs[taken], vs[taken] = self.stepper.t, s.x, s.v
            else:
                rows.append(own_record(self.stepper))
            taken += 1
            if not done:
                break
        self.lagging = not done
        if not done:
            self.clock = self.stepper.t
        if not isinstance(self.stepper, Stepper):
            return np.vstack(rows)
        return state_records(self.pendulum, ts[:taken], xs[:taken], vs[:taken])
