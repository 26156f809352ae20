"""One ticker for the whole room: every lab session's tick, round robin, in one worker-thread call per
tick (docs/web.md, "Pacing" and "A pupil in the room").

Each WebSocket handler (:func:`pendulab.server.live_socket.run_session`) takes a :class:`Seat` — the session,
its inbox of parsed commands, its :class:`~.tick.Carry`, its share of the room's budget — and sends what
the seat's outbox receives. The :class:`Ticker` of the event loop is a thread of its own that wakes
:data:`~.schema.TICK_HZ` times a second, ticks all the seats (:func:`.tick.tick_messages`; in a full room
split into :data:`GROUPS` threads: the core releases the interpreter lock while it steps, so two
groups step on two cores), starting each tick at the next seat (round robin: no seat always comes
first or last), and hands the messages to the event loop in one call. One hand-off per tick instead
of two per session and tick: a thread hand-off costs about 0.08 ms of processor time, as much as a
page's whole tick, and on a busy machine each waits for the scheduler. Each session's work stays
within its share (:meth:`.room.Room.share`), so the room's total stays within
:data:`~.room.ROOM_BUDGET` per tick.

A client that does not read its frames gets no more ticks once :data:`MAX_OUTBOX` ticks' messages wait
for it (its simulation waits too): what waits in memory for one client is bounded. Times in seconds.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import threading
import time
import weakref
from collections import deque
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any

from .protocol import keyed_notice
from .session import TICK_BUDGET, Session
from .tick import Carry, Message, tick_messages

log = logging.getLogger("pendulab.server")

MAX_PENDING = 64
"""Most commands waiting for the next tick; more are dropped (throttling), and after a dropped one
nothing more is read from the client until its next tick (:meth:`Seat.throttle`)."""

MAX_PER_TICK = 32
"""Most commands applied per tick."""

MAX_OUTBOX = 8
"""Most ticks' messages waiting to be sent to one client; beyond, its session is not ticked."""

GROUPS = 2
"""Threads ticking the room (the ticker's and one more; the seats split evenly between them) once
there are more than :data:`GROUP_SIZE` seats."""

GROUP_SIZE = 8
"""Seats one worker-thread call takes before the room is split into :data:`GROUPS`."""


@dataclass(eq=False)
class Seat:
    """One session in the room: its inbox (parsed commands or errors), the commands dropped since the
    last tick, its :class:`~.tick.Carry`, its share [s] of the room's budget per tick, and the outbox
    its handler sends from; ``ticked`` is set in the event loop after each of its ticks."""

    session: Session
    share: Callable[[], float] = lambda: TICK_BUDGET
    inbox: deque[Any] = field(default_factory=deque)
    dropped: int = 0
    carry: Carry = field(default_factory=Carry)
    outbox: deque[list[Message]] = field(default_factory=deque)
    ready: asyncio.Event = field(default_factory=asyncio.Event)
    ticked: asyncio.Event = field(default_factory=asyncio.Event)
    last: float = field(default_factory=time.monotonic)
    failed: BaseException | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)

    def put(self, item: Any) -> None:
        """A command (or a :class:`~.protocol.CommandError`) from the client; dropped beyond
        :data:`MAX_PENDING` waiting (then the handler waits in :meth:`throttle`)."""
        with self.lock:
            if len(self.inbox) >= MAX_PENDING:
                self.dropped += 1
            else:
                self.inbox.append(item)

    async def throttle(self) -> None:
        """In the event loop, after :meth:`put`: while messages have been dropped since the last tick,
        waits for the seat's next tick. The handler reads nothing meanwhile, so a client that floods
        has at most :data:`MAX_PENDING` + 1 of its messages parsed per tick; the rest wait in its
        socket (uvicorn stops reading from a socket whose messages the handler does not take; one
        read's worth at most waits in its queue) instead of being read, parsed and dropped as fast
        as it sends them."""
        while self.dropped:
            self.ticked.clear()
            await self.ticked.wait()

    def _work(self, now: float, tick_hz: float) -> Callable[[], list[Message]] | None:
        """This tick's work (run in a worker thread), or None when the client is not reading."""
        if len(self.outbox) >= MAX_OUTBOX:
            self.last = now  # the time it did not read is not caught up on
            return None
        elapsed, self.last = now - self.last, now
        with self.lock:
            commands = [self.inbox.popleft() for _ in range(min(len(self.inbox), MAX_PER_TICK))]
            lost, self.dropped = self.dropped, 0
        budget = self.share()
        session, carry = self.session, self.carry

        def work() -> list[Message]:
            try:
                return tick(out=[])
            finally:
                if carry.left:  # not carried out within the budget: first at the next tick
                    with self.lock:
                        self.inbox.extendleft(reversed(carry.left))
                    carry.left.clear()

        def tick(out: list[Message]) -> list[Message]:
            if lost:
                out.append(keyed_notice("throttled", lost=lost, per_second=int(tick_hz * MAX_PER_TICK)))
            out.extend(tick_messages(session, commands, elapsed, budget, dropped=lost, carry=carry))
            return out

        return work

    def _deliver(self, messages: list[Message] | BaseException) -> None:
        """In the event loop: the tick's messages into the outbox (or the failure), the handler woken."""
        if isinstance(messages, BaseException):
            self.failed = messages
        elif messages:
            self.outbox.append(messages)
        self.ready.set()
        self.ticked.set()


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
    """The room's ticker for one event loop (module doc): a thread of its own that runs while the room
    has seats, so that the event loop is never on a tick's path (on a busy machine each hand-off
    between threads waits for the scheduler)."""

    def __init__(self, tick_hz: float, loop: asyncio.AbstractEventLoop) -> None:
        self.tick_hz = tick_hz
        self.loop = loop
        self.seats: list[Seat] = []
        self.turn = 0
        self.lock = threading.Lock()
        self.thread: threading.Thread | None = None
        self.pool: ThreadPoolExecutor | None = None

    def join(self, seat: Seat) -> None:
        with self.lock:
            self.seats.append(seat)
            if self.thread is None or not self.thread.is_alive():
                self.thread = threading.Thread(target=self._run, name="pendulab-ticker", daemon=True)
                self.thread.start()

    def leave(self, seat: Seat) -> None:
        with self.lock, contextlib.suppress(ValueError):
            self.seats.remove(seat)

    def _run(self) -> None:
        period = 1.0 / self.tick_hz
        next_tick = time.monotonic()
        try:
            while True:
                next_tick += period
                delay = next_tick - time.monotonic()
                if delay < -period:  # more than a tick behind: do not try to catch up with a burst
                    next_tick, delay = time.monotonic(), 0.0
                time.sleep(max(delay, 0.0))  # a late tick (a busy machine) is made up at once
                with self.lock:
                    if not self.seats or self.loop.is_closed():
                        self.thread = None
                        return
                    seats = list(self.seats)
                try:
                    self.tick(seats)
                except Exception as e:  # a fault of the ticker itself: logged, the room goes on
                    log.error("the lab's ticker failed", exc_info=e)
        finally:
            if self.pool is not None:
                self.pool.shutdown(wait=False)
                self.pool = None

    def tick(self, seats: list[Seat]) -> None:
        """One tick of ``seats`` (round robin from the next seat on), in this thread (and, for a full
        room, :data:`GROUPS` - 1 more); the messages are handed to the event loop."""
        self.turn = (self.turn + 1) % len(seats)
        seats = seats[self.turn :] + seats[: self.turn]
        now = time.monotonic()
        works = [(s, w) for s in seats if (w := s._work(now, self.tick_hz)) is not None]
        if not works:
            return
        n = GROUPS if len(works) > GROUP_SIZE else 1
        groups = [works[i::n] for i in range(n)]
        if n > 1 and self.pool is None:
            self.pool = ThreadPoolExecutor(GROUPS - 1, thread_name_prefix="pendulab-tick")
        others = [self.pool.submit(self._group, g) for g in groups[1:]] if self.pool else []
        self._group(groups[0])
        for f in others:
            f.result()

    def _group(self, group: list[tuple[Seat, Callable[[], list[Message]]]]) -> None:
        """Ticks one group and hands its messages to the event loop at once."""
        deliveries = list(zip((seat for seat, _ in group), _run_group(group), strict=True))
        with contextlib.suppress(RuntimeError):  # the loop closed meanwhile
            self.loop.call_soon_threadsafe(_deliver_all, deliveries)


def _deliver_all(deliveries: list[tuple[Seat, Any]]) -> None:
    for seat, messages in deliveries:
        seat._deliver(messages)


_TICKERS: weakref.WeakKeyDictionary[Any, dict[float, Ticker]] = weakref.WeakKeyDictionary()


def room_ticker(tick_hz: float) -> Ticker:
    """The ticker of the running event loop at ``tick_hz`` (one per loop: the tests run apps in
    several)."""
    loop = asyncio.get_running_loop()
    tickers = _TICKERS.setdefault(loop, {})
    if tick_hz not in tickers:
        tickers[tick_hz] = Ticker(tick_hz, loop)
    return tickers[tick_hz]
