"""One ticker for the whole room: every lab session's tick, round robin, in one worker-thread call per
tick (docs/web.md, "Pacing" and "A pupil in the room").

Each WebSocket handler (:func:`pendulab.server.app.run_session`) takes a :class:`Seat` — the session,
its inbox of parsed commands, its :class:`~.tick.Carry`, its share of the room's budget — and sends what
the seat's outbox receives. The :class:`Ticker` of the event loop wakes :data:`~.schema.TICK_HZ` times a
second and hands all the seats' ticks (:func:`.tick.tick_messages`) to worker threads in one call per
group of seats (:data:`GROUPS`: the core releases the interpreter lock while it steps, so two groups
step on two cores), starting each tick at the next seat (round robin: no seat always comes first or
last). One hand-off per tick instead of one per session and tick: a thread hand-off costs about
0.08 ms of processor time, as much as a page's whole tick. Each session's work stays within its share
(:meth:`.room.Room.share`), so the room's total stays within :data:`~.room.ROOM_BUDGET` per tick.

A client that does not read its frames gets no more ticks once :data:`MAX_OUTBOX` ticks' messages wait
for it (its simulation waits too): what waits in memory for one client is bounded. Times in seconds.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import time
import weakref
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import anyio

from .budget import TICK_BUDGET
from .protocol import error_notice
from .session import Session
from .tick import Carry, Message, tick_messages

log = logging.getLogger("pendulab.server")

MAX_PENDING = 64
"""Most commands waiting for the next tick; more are dropped (throttling)."""

MAX_PER_TICK = 32
"""Most commands applied per tick."""

MAX_OUTBOX = 8
"""Most ticks' messages waiting to be sent to one client; beyond, its session is not ticked."""

GROUPS = 2
"""Worker-thread calls per tick (the seats split evenly between them) once there are more than
:data:`GROUP_SIZE` seats."""

GROUP_SIZE = 8
"""Seats one worker-thread call takes before the room is split into :data:`GROUPS`."""


@dataclass(eq=False)
class Seat:
    """One session in the room: its inbox (parsed commands or errors), the commands dropped since the
    last tick, its :class:`~.tick.Carry`, its share [s] of the room's budget per tick, and the outbox
    its handler sends from."""

    session: Session
    share: Callable[[], float] = lambda: TICK_BUDGET
    inbox: deque[Any] = field(default_factory=deque)
    dropped: int = 0
    carry: Carry = field(default_factory=Carry)
    outbox: deque[list[Message]] = field(default_factory=deque)
    ready: asyncio.Event = field(default_factory=asyncio.Event)
    last: float = field(default_factory=time.monotonic)
    failed: BaseException | None = None

    def put(self, item: Any) -> None:
        """A command (or a :class:`~.protocol.CommandError`) from the client; dropped beyond
        :data:`MAX_PENDING` waiting."""
        if len(self.inbox) >= MAX_PENDING:
            self.dropped += 1
        else:
            self.inbox.append(item)

    def _work(self, now: float, tick_hz: float) -> Callable[[], list[Message]] | None:
        """This tick's work (run in a worker thread), or None when the client is not reading."""
        if len(self.outbox) >= MAX_OUTBOX:
            self.last = now  # the time it did not read is not caught up on
            return None
        elapsed, self.last = now - self.last, now
        commands = [self.inbox.popleft() for _ in range(min(len(self.inbox), MAX_PER_TICK))]
        lost, self.dropped = self.dropped, 0
        budget = self.share()
        session, carry = self.session, self.carry

        def work() -> list[Message]:
            out: list[Message] = []
            if lost:
                out.append(
                    error_notice(
                        f"throttled: {lost} command(s) dropped (more than {MAX_PENDING} waiting); "
                        f"send at most {int(tick_hz * MAX_PER_TICK)} per second"
                    )
                )
            out.extend(tick_messages(session, commands, elapsed, budget, dropped=lost, carry=carry))
            return out

        return work

    def _deliver(self, messages: list[Message] | BaseException) -> None:
        if isinstance(messages, BaseException):
            self.failed = messages
        else:
            if self.carry.left:  # not carried out within the budget: first at the next tick
                self.inbox.extendleft(reversed(self.carry.left))
                self.carry.left.clear()
            if messages:
                self.outbox.append(messages)
        self.ready.set()


def _run_group(works: list[tuple[Seat, Callable[[], list[Message]]]]) -> list[Any]:
    """The ticks of one group, in order (in a worker thread); an exception is that seat's result."""
    out: list[Any] = []
    for _, work in works:
        try:
            out.append(work())
        except Exception as e:  # one session's fault ends that session only
            out.append(e)
    return out


class Ticker:
    """The room's ticker on one event loop (module doc). Runs while it has seats."""

    def __init__(self, tick_hz: float) -> None:
        self.tick_hz = tick_hz
        self.seats: list[Seat] = []
        self.turn = 0
        self.task: asyncio.Task[None] | None = None

    def join(self, seat: Seat) -> None:
        self.seats.append(seat)
        if self.task is None or self.task.done():
            self.task = asyncio.get_running_loop().create_task(self._run())

    def leave(self, seat: Seat) -> None:
        with contextlib.suppress(ValueError):
            self.seats.remove(seat)

    async def _run(self) -> None:
        period = 1.0 / self.tick_hz
        next_tick = time.monotonic()
        while self.seats:
            next_tick += period
            delay = next_tick - time.monotonic()
            if delay < -period:  # more than a tick behind: do not try to catch up with a burst
                next_tick, delay = time.monotonic(), 0.0
            await asyncio.sleep(max(delay, 0.0))  # a late tick (a busy machine) is made up at once
            await self.tick()

    async def tick(self) -> None:
        """One tick of every seat (round robin from the next seat on)."""
        seats = list(self.seats)
        if not seats:
            return
        self.turn = (self.turn + 1) % len(seats)
        seats = seats[self.turn :] + seats[: self.turn]
        now = time.monotonic()
        works = [(s, w) for s in seats if (w := s._work(now, self.tick_hz)) is not None]
        if not works:
            return
        n = GROUPS if len(works) > GROUP_SIZE else 1
        groups = [works[i::n] for i in range(n)]
        results: list[list[Any]] = [[] for _ in groups]

        async def run(i: int) -> None:
            results[i] = await anyio.to_thread.run_sync(_run_group, groups[i])

        async with anyio.create_task_group() as tg:
            for i in range(len(groups)):
                tg.start_soon(run, i)
        for group, result in zip(groups, results, strict=True):
            for (seat, _), messages in zip(group, result, strict=True):
                seat._deliver(messages)


_TICKERS: weakref.WeakKeyDictionary[Any, dict[float, Ticker]] = weakref.WeakKeyDictionary()


def room_ticker(tick_hz: float) -> Ticker:
    """The ticker of the running event loop at ``tick_hz`` (one per loop: the tests run apps in
    several)."""
    loop = asyncio.get_running_loop()
    tickers = _TICKERS.setdefault(loop, {})
    if tick_hz not in tickers:
        tickers[tick_hz] = Ticker(tick_hz)
    return tickers[tick_hz]
