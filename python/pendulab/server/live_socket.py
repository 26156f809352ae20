"""The lab's WebSocket ``/ws`` (docs/web.md, "Pacing", "A pupil in the room"): admission of a client's
session, then one :class:`~.session.Session` served until the client goes away.

:func:`admit` refuses a WebSocket beyond the server's ``max_sessions`` (key ``server_full``) or beyond
its client's ``max_sessions_per_client`` (key ``device_full``): an ``error`` notice, then close code
1013 (try again later). :func:`run_session` serves an admitted session with two tasks: one reads and
validates commands into the seat's bounded inbox (a client that floods is throttled: beyond
:data:`.ticker.MAX_PENDING` waiting commands the next is dropped with an error notice and nothing more
is read from the client until the seat's next tick, :meth:`.ticker.Seat.throttle`), the other
sends what the seat's outbox receives. The room's ticker (:mod:`.ticker`) ticks every seat at
:data:`~.schema.TICK_HZ` in worker threads (:mod:`.tick`), which apply the commands and advance the
stepper to wall clock × time scale within the session's share of the room's budget [s]. Only the
handler writes to its socket, only the ticker's worker touches the session. A client vanishing
mid-stream ends its own tasks only.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import time
import weakref
from collections.abc import Callable
from typing import Any

import anyio
from fastapi import WebSocket, WebSocketDisconnect

from .protocol import CommandError, error_notice, parse_command
from .room import Room, client_key
from .schema import TICK_HZ
from .session import TICK_BUDGET, Session
from .tick import Message, first_messages
from .ticker import Seat, room_ticker

STEP_THREADS = 4
"""Worker threads computing a new session's first messages (its status and first frame); the ticks
themselves run in the room's ticker (:mod:`.ticker`)."""

log = logging.getLogger("pendulab.server")


def loop_limiter(store: weakref.WeakKeyDictionary[Any, anyio.CapacityLimiter], tokens: int) -> Any:
    """A capacity limiter of ``tokens`` for the running event loop (one per loop: the tests run apps in
    several)."""
    loop = asyncio.get_running_loop()
    limiter = store.get(loop)
    if limiter is None:
        limiter = store[loop] = anyio.CapacityLimiter(tokens)
    return limiter


_STEP_LIMITERS: weakref.WeakKeyDictionary[Any, anyio.CapacityLimiter] = weakref.WeakKeyDictionary()


async def _refuse(ws: WebSocket, notice: dict[str, Any], reason: str) -> None:
    with contextlib.suppress(WebSocketDisconnect, OSError, RuntimeError):
        await ws.send_json(notice)
        await ws.close(code=1013, reason=reason)


async def admit(ws: WebSocket, active: int, max_sessions: int, room: Room) -> str | None:
    """Accepts the WebSocket and counts its session in ``room``; returns the client's key, or None when
    it was refused (module doc: notice sent, socket closed). ``active``: the sessions open now."""
    await ws.accept()
    if active >= max_sessions:
        message = (
            f"the server is full: {active} lab sessions are open, the most it serves at once "
            f"(pendulab serve --max-sessions {max_sessions}); close another tab or try again later"
        )
        await _refuse(ws, error_notice(message, None, "server_full", {"active": active}), "server full")
        return None
    key = client_key(ws.scope)
    refused = room.open_session(key)
    if refused is not None:
        notice = error_notice(refused, None, "device_full", {"have": room.sessions.get(key, 0)})
        await _refuse(ws, notice, "too many sessions from this device")
        return None
    return key


async def _receive(ws: WebSocket, seat: Seat) -> None:
    """Reads the client's messages into the seat's inbox, parsed (or the refusal) until it goes away."""
    while True:
        msg = await ws.receive()
        if msg["type"] == "websocket.disconnect":
            return
        text, data = msg.get("text"), msg.get("bytes")
        item: Any
        try:
            item = parse_command(text if text is not None else (data or b""))
        except CommandError as e:
            item = e
        seat.put(item)
        await seat.throttle()  # a flood: nothing more is read from this client until its next tick


async def _send_all(ws: WebSocket, messages: list[Message]) -> None:
    for m in messages:
        if isinstance(m, bytes):
            await ws.send_bytes(m)
        else:
            await ws.send_json(m)


async def _send(ws: WebSocket, seat: Seat, tick_hz: float) -> None:
    """The first messages, then whatever the room's ticker puts in the seat's outbox."""
    limiter = loop_limiter(_STEP_LIMITERS, STEP_THREADS)
    await _send_all(ws, await anyio.to_thread.run_sync(first_messages, seat.session, limiter=limiter))
    ticker = room_ticker(tick_hz)
    seat.last = time.monotonic()
    ticker.join(seat)
    try:
        while True:
            await seat.ready.wait()
            seat.ready.clear()
            if seat.failed is not None:
                raise seat.failed
            while seat.outbox:
                await _send_all(ws, seat.outbox.popleft())
    finally:
        ticker.leave(seat)


async def _send_or_report(ws: WebSocket, seat: Seat, tick_hz: float) -> None:
    """:func:`_send` until the client goes away; a failure of the session is logged and told."""
    try:
        await _send(ws, seat, tick_hz)
    except (WebSocketDisconnect, OSError):
        pass  # sending to a client that went away
    except RuntimeError as e:  # starlette: sending after the socket closed
        if "close" not in str(e).lower() and "disconnect" not in str(e).lower():
            raise
    except Exception as e:
        log.error("lab session failed", exc_info=e)
        with contextlib.suppress(Exception):
            notice = error_notice(f"internal error: {e}", None, "internal_error", {"detail": str(e)})
            await ws.send_json(notice)
            await ws.close(code=1011)


async def run_session(
    ws: WebSocket, session: Session, tick_hz: float = TICK_HZ, share: Callable[[], float] | None = None
) -> None:
    """Serves one client until it goes away (see the module doc): its commands go to its
    :class:`~.ticker.Seat` in the room's :class:`~.ticker.Ticker`, which ticks every session in worker
    threads (:func:`.tick.tick_messages`, round robin) within ``share()`` seconds each (the session's
    share of the room, :meth:`.room.Room.share`; default one tick's budget); this handler sends what
    the seat's outbox receives. The event loop only moves messages."""
    seat = Seat(session, share or (lambda: TICK_BUDGET))
    async with anyio.create_task_group() as tg:

        async def reader() -> None:
            with contextlib.suppress(WebSocketDisconnect, OSError):
                await _receive(ws, seat)
            tg.cancel_scope.cancel()  # the client is gone: stop ticking

        async def sender() -> None:
            await _send_or_report(ws, seat, tick_hz)
            tg.cancel_scope.cancel()

        tg.start_soon(reader)
        tg.start_soon(sender)
