"""One lab session: the core's live session (``pendulab._core.LiveSession``, ``crates/pendulab-core/src/
live``) with what only the server has — scenarios read from files, resolved by name (never a path).

The live-session logic lives once, in Rust, and the page's own engine (WebAssembly, ``crates/
pendulab-wasm``) runs the same code: the pendulum of any lab model and its stepper (the rod models,
the swinging spring T-7.4, the string), the pacing by the wall clock × time scale in slices within a
per-tick wall-time budget, the frame records (``frame.json``: energy T-2.6, J₃, tension T-2.3,
power T-7.1, acceleration T-2.2), the error estimate in every record (exact T-4.x for the ideal
pendulum, else a companion run: docs/web.md, "Error estimate"), the commands, one tick's messages
and the ``status`` notice. This module converts what crosses the border: a scenario as the JSON of
``GET /api/scenarios`` (:func:`describe`, with rtol and atol), a validated command (pydantic,
:mod:`.protocol`) as its JSON, ``load_scenario`` as the scenario it names, and the messages back as
``bytes`` (frame records) and dicts (JSON notices).

Pacing (docs/web.md, "Pacing"): while running, the simulated time advances by (wall-clock seconds
elapsed) × ``time_scale``; fixed-step methods take whole steps of exactly ``dt``, so a live run is the
same sequence of steps as ``pl.simulate`` with that ``dt`` and ``arithmetic="unfused"`` (the lab's
arithmetic, in the server as in the page's engine); ``dop853`` lands on the target times, choosing all
its steps (its first too: it takes no first step from ``dt``, which it keeps for a fixed-step method). A
tick sends up to :data:`MAX_SUBSAMPLES` records; out of budget the simulation runs slower than asked
and ``status.lagging`` says so. Times in seconds, SI units throughout.
"""

from __future__ import annotations

import json
import tomllib
from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from .._core import LiveSession as _LiveSession
from ..model import Pendulum, State
from ..scenario import ScenarioError
from .crane_setup import CRANE_MODEL
from .live_models import LabPendulum, SpringPendulum
from .protocol import Command, CommandError, LoadScenario, decode_records, error_notice_of, own_params
from .scenarios import Setup, example_resolver, resolve_scenario, scenario_files

__all__ = ["Session", "Setup", "example_resolver", "model_params", "resolve_scenario", "scenario_files"]

TICK_BUDGET: float = _LiveSession.TICK_BUDGET
"""Wall-clock seconds one session may step per tick (a tick is 1/60 s ≈ 16.7 ms)."""

MAX_PENDING_STEPS: int = _LiveSession.MAX_PENDING_STEPS
"""Most steps of ``step`` commands waiting to be taken; a ``step`` beyond is refused."""

MAX_SUBSAMPLES: int = _LiveSession.MAX_SUBSAMPLES
"""Most frame records sent per tick."""

MAX_ELAPSED: float = _LiveSession.MAX_ELAPSED
"""Longest wall-clock interval [s] one tick catches up on (after a stall the run resumes, not jumps)."""

MAX_EVENT_NOTICES: int = _LiveSession.MAX_EVENT_NOTICES
"""Most ``event`` notices sent per tick (the latest; each says how many earlier were skipped)."""

Message = dict[str, Any] | bytes
"""A JSON notice (dict) or a binary frame message (bytes)."""

_LOAD_ERRORS = (InvalidInputError, ScenarioError, tomllib.TOMLDecodeError, OSError)


def model_params(pendulum: LabPendulum) -> dict[str, float]:
    """Every own parameter of the pendulum's model (SI units): the given ones, else the registry's default."""
    given = pendulum.extra
    if pendulum.model == CRANE_MODEL:  # the crane mode's parameters (the core fills in the rest)
        return dict(given)
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


def setup_json(setup: Setup) -> str:
    """The JSON of a setup as the core's live session reads it: :func:`describe` with the tolerances."""
    return json.dumps(describe(setup) | {"rtol": setup.rtol, "atol": setup.atol})


def _records(data: bytes | None) -> np.ndarray | None:
    return None if not data else decode_records(data)


def _message(m: bytes | str) -> Message:
    return m if isinstance(m, bytes) else json.loads(m)


def _refused(e: Exception, command: str | None) -> CommandError:
    """A refusal of the core (or of a scenario file) as a :class:`CommandError` in one line, keyed as the
    core keyed it (``key`` and ``values`` of its exception: ``messages.json``) for a page that words it in
    its language; a refusal the core did not key keeps its English words alone. The core words another
    lab model's parameter as ``set_model`` does here, naming those models (``parameter_of_other_model``,
    ``crates/pendulab-core/src/live/no_parameter.rs``)."""
    key, values = getattr(e, "key", None), getattr(e, "values", None)
    return CommandError(" ".join(str(e).split()), command=command, key=key, values=values)


class Session:
    """One client's lab (module doc). Not thread-safe: one owner ticks it.

    ``exact_error=False`` estimates the ideal pendulum's error with a companion too, as for the other
    models, instead of taking the true error from the exact solution (for tests of the estimate)."""

    def __init__(
        self, setup: Setup, resolve: Callable[[str], Setup] | None = None, *, exact_error: bool = True
    ) -> None:
        self._resolve = resolve or example_resolver(setup)
        self._setups: dict[str, str] = {}  # scenarios resolved by name (their JSON), each read once
        self.core = _LiveSession(setup_json(setup), exact_error)

    # --- what crosses the border ---

    def _setup(self, name: str) -> str:
        if name not in self._setups:
            self._setups[name] = setup_json(self._resolve(name))
        return self._setups[name]

    def _item(self, cmd: Command | CommandError) -> str | tuple[Any, ...]:
        """A parsed command as the core's tick takes it: its JSON, or for ``load_scenario`` the
        scenario it names; :class:`CommandError` for a refused message or an unknown scenario."""
        if isinstance(cmd, CommandError):
            raise cmd
        if isinstance(cmd, LoadScenario):
            try:
                return ("setup", self._setup(cmd.name))
            except _LOAD_ERRORS as e:
                raise _refused(e, cmd.type) from None
        return cmd.model_dump_json(exclude_none=True)

    def tick(
        self,
        commands: list[Any],
        elapsed: float,
        budget_seconds: float = TICK_BUDGET,
        dropped: int = 0,
        debt: float | None = None,
    ) -> tuple[list[Message], list[Any], float | None]:
        """One tick in the core (``LiveSession.tick``, the interpreter lock released while it steps):
        the messages to send, the commands left for a later tick and the debt [s] (see
        :class:`~.tick.Carry`; with ``debt`` None every command is carried out). Refused messages
        (:class:`CommandError`, keyed for a page that translates them) and unknown scenarios are
        answered first, counted with ``dropped`` (each gets a status after it, as a command does)."""
        refused: list[Message] = []
        items, passed = [], []
        for c in commands:
            try:
                items.append(self._item(c))
                passed.append(c)
            except CommandError as e:
                refused.append(error_notice_of(e))
        raw, taken, debt = self.core.tick(items, elapsed, budget_seconds, dropped + len(refused), debt)
        return refused + [_message(m) for m in raw], passed[taken:], debt

    def first_messages(self) -> list[Message]:
        """What a new connection gets first: the status and the current state's frame."""
        return [_message(m) for m in self.core.first_messages()]

    def status(self) -> dict[str, Any]:
        """The JSON ``status`` notice: everything the page needs to show and to encode in its URL."""
        status = json.loads(self.core.status())
        assert isinstance(status, dict), f"the core's status is not a JSON object: {status!r}"
        return status

    # --- one part of a tick at a time (tests, tools) ---

    def apply(self, cmd: Command) -> np.ndarray | None:
        """Carries out one command; the frame record to send at once (or None). :class:`CommandError`
        when it cannot be carried out here (unknown scenario, a state off TS², …): the session is then
        unchanged (an integration that cannot go on pauses it)."""
        item = self._item(cmd)
        try:
            return _records(self.core.apply(item))
        except (InvalidInputError, IntegrationError) as e:
            raise _refused(e, cmd.type) from None

    def advance(self, elapsed: float, budget_seconds: float = TICK_BUDGET) -> np.ndarray | None:
        """Advances by ``elapsed`` wall-clock seconds × time_scale within ``budget_seconds``; the records
        reached (None: none; ``error_x`` unknown). :class:`CommandError` keyed ``integration_stopped`` (as
        the tick's notice) when the integration stops: the session is then paused at the last state
        computed."""
        try:
            return _records(self.core.advance(elapsed, budget_seconds))
        except (InvalidInputError, IntegrationError) as e:
            raise _refused(e, None) from None

    def take_pending_steps(self, budget_seconds: float = TICK_BUDGET) -> np.ndarray | None:
        """Takes the waiting steps of ``step`` commands within ``budget_seconds``; the record reached.
        :class:`CommandError` keyed ``integration_stopped`` when the integration stops (none left waiting,
        paused)."""
        try:
            return _records(self.core.take_pending_steps(budget_seconds))
        except (InvalidInputError, IntegrationError) as e:
            raise _refused(e, "step") from None

    def fill_errors(self, records: np.ndarray, budget_seconds: float = TICK_BUDGET) -> np.ndarray:
        """``records`` (the current stepper's, in time order) with ``error_x`` [m] filled within
        ``budget_seconds`` (−1 where the estimate did not get there)."""
        data = np.ascontiguousarray(records, dtype="<f8").tobytes()
        out = _records(self.core.fill_errors(data, budget_seconds))
        return np.empty((0, records.shape[-1])) if out is None else out

    def take_event_notices(self) -> list[dict[str, Any]]:
        """The JSON ``event`` notices of the string's leaves and snaps since the last call, oldest
        first: at most :data:`MAX_EVENT_NOTICES`, the latest, each counting the earlier ones it skipped."""
        return [json.loads(m) for m in self.core.take_event_notices()]

    def records(self) -> np.ndarray:
        """The current state as one frame record, shape (1, RECORD_LEN) (``error_x`` unknown)."""
        out = _records(self.core.record())
        assert out is not None
        return out

    # --- state ---

    @property
    def state(self) -> State:
        """The state reached (x [m], v [m/s])."""
        return State(self.core.x, self.core.v)

    @property
    def pendulum(self) -> LabPendulum:
        """The current pendulum, as the status describes it (l [m], m [kg], g [m/s²], model and its own
        parameters): a new object."""
        st = self.status()
        p, own = st["params"], st["model_params"]
        if st["model"] == "spring":
            return SpringPendulum(p["length"], p["g"], p["mass"], own["stiffness"])
        return Pendulum(length=p["length"], mass=p["mass"], g=p["g"], model=st["model"], **own)

    @property
    def error_start(self) -> tuple[float, State]:
        """The time [s] and state the error estimate counts from."""
        t0, x, v = self.core.error_start
        return t0, State(x, v)

    @property
    def t(self) -> float:
        """Time reached [s]."""
        return self.core.t

    @property
    def clock(self) -> float:
        """The simulated time [s] the pacing aims at."""
        return self.core.clock

    @property
    def paused(self) -> bool:
        """Paused."""
        return self.core.paused

    @property
    def epoch(self) -> int:
        """Discontinuities so far (reset, new state, parameters, model, scenario)."""
        return self.core.epoch

    @property
    def lagging(self) -> bool:
        """Out of budget in the last advance."""
        return self.core.lagging

    @property
    def pending_steps(self) -> int:
        """Steps of ``step`` commands waiting."""
        return self.core.pending_steps

    @property
    def commands(self) -> int:
        """Command messages handled (applied, refused or dropped): ``status.commands``."""
        return self.core.commands

    @property
    def scenario(self) -> str | None:
        """Scenario name."""
        return self.core.scenario

    @property
    def model(self) -> str:
        """The model's registry name."""
        return self.core.model

    @property
    def method(self) -> str:
        """The method's name."""
        return self.core.method

    @property
    def dt(self) -> float:
        """Step [s] of a fixed-step method; with ``dop853`` unused (it chooses all its steps, the first
        too) and kept as the step of a fixed-step method chosen next."""
        return self.core.dt

    @property
    def time_scale(self) -> float:
        """Simulated seconds per wall-clock second."""
        return self.core.time_scale
