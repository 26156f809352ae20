"""HTTP hygiene of the lab server (docs/web.md, "Security"): security headers on every response, JSON
bodies only and capped, slow clients timed out.

- :class:`SecurityHeaders`: ``X-Content-Type-Options: nosniff``, a ``Content-Security-Policy`` that
  lets the page load and connect to its own origin only (:func:`content_security_policy`; styles may be
  inline, as lil-gui injects its own), ``frame-ancestors 'self'`` (no foreign page frames the lab),
  ``Referrer-Policy: no-referrer`` (the classroom token never leaves in a ``Referer``) and
  ``Cross-Origin-Resource-Policy: same-origin``.
- :class:`RequestBodies`: a request with a body (POST …) must say ``Content-Type: application/json``
  (else 415: a foreign page cannot send such a request without a CORS preflight, which this server
  never grants); a declared ``Content-Length`` over :data:`MAX_BODY_BYTES` (or the path's own limit
  given as ``larger``: ``/api/fit`` takes data files of 2 MiB) is refused with 413 before
  anything is read, a longer chunked body as soon as it passes the limit; the whole body must arrive
  within :data:`BODY_TIMEOUT` seconds (else 408). The endpoint then reads the body from memory.
- :class:`TimedH11Protocol`: uvicorn's HTTP/1.1 protocol with a deadline for the request *headers*
  (:data:`HEADER_TIMEOUT`): a connection that opens and sends its headers slowly or never
  (slowloris) is closed. uvicorn itself times out only idle keep-alive connections. One client
  (address, a global IPv6 one's /64: :func:`~pendulab.server.room.address_key`) may hold at most
  :data:`~pendulab.server.room.MAX_CONNECTIONS_PER_CLIENT` connections; more are cut (reset) as soon
  as they are accepted, before uvicorn sets up anything for them and without writing an answer, so
  one client's idle sockets cannot fill the server's connection limit for everyone, and one
  reconnecting in a tight loop costs the server an accept and a close each time.
  Nothing more is read from a connection whose request has arrived whole until its answer is sent
  (:class:`PipelineFlow`): a client pipelining requests cannot make the server hold what it sends.
- :class:`LabWebSocketProtocol`: uvicorn's WebSocket protocol with at most :data:`MAX_WS_BUFFER` bytes
  waiting for a client (a client that pings without reading is cut off), at most :data:`PING_RATE`
  pings a second (a burst of :data:`PING_BURST` seconds' worth; a ping flood is cut off too), and an
  idle timeout: the server pings every client every :data:`WS_PING_INTERVAL` seconds, and a client
  from which nothing at all has arrived (no command, ping or pong) for :data:`WS_IDLE_TIMEOUT` seconds
  is closed with code 1001 (cut, when it reads nothing either). The lab's page sends nothing while
  nobody uses it, but its browser answers every ping by itself (also in a background tab), so an open
  page is never idle.
"""

from __future__ import annotations

import asyncio
import math
import re
from collections.abc import Iterable, Mapping
from typing import Any

import anyio
import h11
from starlette.datastructures import Headers, MutableHeaders
from starlette.responses import PlainTextResponse
from starlette.types import ASGIApp, Message, Receive, Scope, Send
from uvicorn.protocols.http.flow_control import FlowControl
from uvicorn.protocols.http.h11_impl import H11Protocol
from uvicorn.protocols.websockets.websockets_sansio_impl import WebSocketsSansIOProtocol

from .room import MAX_CONNECTIONS_PER_CLIENT, address_key

MAX_BODY_BYTES = 64 * 1024
"""Largest request body [bytes] (the lab's requests are a few hundred bytes)."""

BODY_TIMEOUT = 10.0
"""Most seconds a request body may take to arrive."""

HEADER_TIMEOUT = 10.0
"""Most seconds a connection may take to send a request's headers."""

MAX_WS_BUFFER = 1 << 20
"""Most bytes waiting to be sent to one WebSocket client before it is cut off (a client that sends
pings without reading)."""

PING_RATE = 2.0
"""Most WebSocket pings per second one connection may send on average (a browser sends none; a client
library one every 20 s or so); a connection that goes beyond :data:`PING_BURST` seconds' worth is cut."""

PING_BURST = 10.0
"""Seconds' worth of :data:`PING_RATE` pings a connection may send at once."""

WS_PING_INTERVAL = 20.0
"""Seconds between the server's WebSocket pings to each client (uvicorn's keepalive; browsers answer
them by themselves). Shorter when the idle timeout is shorter than two of them."""

WS_IDLE_TIMEOUT = 60.0
"""Default seconds without anything from a WebSocket client (command, ping or pong) after which it is
closed (``pendulab serve --idle-timeout``); it is noticed at the next ping, so within
:data:`WS_PING_INTERVAL` × 2 after."""

_HOST_RE = re.compile(r"^[A-Za-z0-9.\-]+(:\d{1,5})?$|^\[[0-9A-Fa-f:.]+\](:\d{1,5})?$")


def content_security_policy(host: str | None) -> str:
    """The page's own origin only: scripts, styles, images, fonts and connections (including its own
    WebSocket, named explicitly for browsers whose ``'self'`` does not cover ws:); no plugins, no base
    or form elsewhere, framed only by itself."""
    connect = "'self'"
    if host and _HOST_RE.match(host):
        connect += f" ws://{host} wss://{host}"
    return (
        "default-src 'self'; script-src 'self'; style-src 'self' 'unsafe-inline'; "
        "img-src 'self' data: blob:; font-src 'self' data:; "
        f"connect-src {connect}; object-src 'none'; base-uri 'self'; form-action 'self'; "
        "frame-ancestors 'self'"
    )


class SecurityHeaders:
    """ASGI middleware adding the security headers of the module doc to every HTTP response."""

    def __init__(self, app: ASGIApp) -> None:
        self.app = app

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        csp = content_security_policy(Headers(scope=scope).get("host"))

        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                headers = MutableHeaders(scope=message)
                headers.setdefault("x-content-type-options", "nosniff")
                headers.setdefault("content-security-policy", csp)
                headers.setdefault("x-frame-options", "SAMEORIGIN")
                headers.setdefault("referrer-policy", "no-referrer")
                headers.setdefault("cross-origin-resource-policy", "same-origin")
            await send(message)

        await self.app(scope, receive, send_with_headers)


class RequestBodies:
    """ASGI middleware: the JSON-only, size-capped, time-limited request bodies of the module doc."""

    def __init__(
        self,
        app: ASGIApp,
        max_bytes: int = MAX_BODY_BYTES,
        timeout: float | None = None,
        larger: Mapping[str, int] | None = None,
    ) -> None:
        self.app = app
        self.max_bytes = max_bytes
        self.larger = dict(larger or {})  # paths whose bodies may be longer: path → most bytes
        self.timeout = BODY_TIMEOUT if timeout is None else timeout

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or scope["method"] in ("GET", "HEAD", "OPTIONS"):
            await self.app(scope, receive, send)
            return
        headers = Headers(scope=scope)
        media = headers.get("content-type", "").split(";")[0].strip().lower()
        if media != "application/json":
            shown = media or "none"
            await _answer(
                scope,
                receive,
                send,
                415,
                f"the body must be JSON (Content-Type: application/json), got {shown}",
            )
            return
        declared = headers.get("content-length")
        limit = self.larger.get(scope["path"], self.max_bytes)
        if declared is not None and (not declared.isdigit() or int(declared) > limit):
            await _answer(scope, receive, send, 413, self._too_long(declared, limit))
            return
        chunks: list[bytes] = []
        size = 0
        try:
            with anyio.fail_after(self.timeout):
                while True:
                    message = await receive()
                    if message["type"] == "http.disconnect":
                        return
                    chunk = message.get("body", b"")
                    size += len(chunk)
                    if size > limit:
                        await _answer(scope, receive, send, 413, self._too_long(f"more than {size}", limit))
                        return
                    chunks.append(chunk)
                    if not message.get("more_body", False):
                        break
        except TimeoutError:
            await _answer(scope, receive, send, 408, f"the body did not arrive within {self.timeout:g} s")
            return
        body = b"".join(chunks)
        sent = False

        async def replay() -> Message:
            nonlocal sent
            if not sent:
                sent = True
                return {"type": "http.request", "body": body, "more_body": False}
            return await receive()

        await self.app(scope, replay, send)

    def _too_long(self, size: str, limit: int) -> str:
        return f"the body is too long ({size} bytes); at most {limit} bytes"


async def _answer(scope: Scope, receive: Receive, send: Send, status: int, message: str) -> None:
    response = PlainTextResponse(message + "\n", status_code=status, headers={"connection": "close"})
    await response(scope, receive, send)


def _open_from(connections: Iterable[Any], key: str) -> int:
    """The open connections (HTTP and WebSocket protocols of uvicorn's server state) of the client
    ``key`` (:func:`~pendulab.server.room.address_key`)."""
    hosts = ((getattr(c, "client", None) or (None,))[0] for c in connections)
    return sum(1 for host in hosts if host is not None and address_key(str(host)) == key)


class LabWebSocketProtocol(WebSocketsSansIOProtocol):
    """uvicorn's WebSocket protocol with a bound on what waits to be sent to a client: the protocol
    answers every ping with a pong at once, whether or not the client reads, so a client that sends
    pings without reading would grow the server's memory without end. Past :data:`MAX_WS_BUFFER`
    bytes waiting, the connection is cut (the lab's own frames never get there: the session waits
    for the socket to drain before it sends more)."""

    max_buffer = MAX_WS_BUFFER
    ping_rate = PING_RATE
    idle_timeout: float | None = WS_IDLE_TIMEOUT
    _pings = 0.0  # the pings counted so far, less PING_RATE per second since ``_ping_at``
    _ping_at = 0.0
    _heard = True  # anything from the client since the server's last ping (the handshake counts)
    _silent = 0  # the server's pings in a row before which nothing came from the client

    def send_keepalive_ping(self) -> None:
        """Before each keepalive ping: a client silent for the last ``idle_timeout`` seconds' worth of
        ping intervals is closed (module doc). Counted in pings, so every step is the event loop's
        timer of uvicorn's keepalive, whatever the clock."""
        if self.idle_timeout is not None and not self.close_sent and not self.transport.is_closing():
            self._silent = 0 if self._heard else self._silent + 1
            self._heard = False
            if self._silent >= self.idle_pings():
                self._close_idle()
                return
        super().send_keepalive_ping()

    def idle_pings(self) -> int:
        """The silent ping intervals in a row after which a client is idle: ``idle_timeout`` rounded up
        to whole intervals, at least one."""
        interval = self.ping_interval or WS_PING_INTERVAL
        return max(1, math.ceil((self.idle_timeout or 0.0) / interval - 1e-9))

    def _close_idle(self) -> None:
        self.stop_keepalive()
        self.conn.fail(1001, f"idle: nothing from the client in {self.idle_timeout:g} s")
        self.transport.write(b"".join(self.conn.data_to_send()))
        self.close_sent = True
        if self.transport.get_write_buffer_size() > 0:
            # The client reads nothing: close() would wait for the buffer to drain, for good, and
            # keep the connection and its session. Cut it.
            self.transport.abort()
        else:
            self.transport.close()

    def handle_ping(self) -> None:
        now = self.loop.time()
        self._pings = max(0.0, self._pings - (now - self._ping_at) * self.ping_rate) + 1.0
        self._ping_at = now
        if self._pings > PING_BURST * self.ping_rate:  # a ping flood: each costs a parse and a pong
            self.transport.abort()
            return
        super().handle_ping()
        if self.transport.get_write_buffer_size() > self.max_buffer:
            self.transport.abort()

    def data_received(self, data: bytes) -> None:
        if self.transport.is_closing():
            return
        self._heard = True
        super().data_received(data)


class PipelineFlow(FlowControl):
    """uvicorn's flow control of one HTTP connection, except that reading does not resume while the
    request under way has arrived whole and its answer is not complete. uvicorn stops reading when a
    client sends the next request before the answer to the last (pipelining), but resumes at every
    ``receive`` of the application, which reads a request's body: each POST then read one more chunk
    (up to 256 KiB) of the pipelined requests into h11's buffer, so one connection sending POSTs
    without waiting for the answers grew the server by about 85 MB a second without end. The
    pipelined requests are read when the answer is complete, as uvicorn does for a GET."""

    def __init__(self, transport: asyncio.Transport, protocol: H11Protocol) -> None:
        super().__init__(transport)
        self._protocol = protocol

    def resume_reading(self) -> None:
        p = self._protocol
        if (
            p.cycle is not None
            and not p.cycle.response_complete
            and p.conn.their_state in (h11.DONE, h11.MUST_CLOSE)
        ):
            return  # the request is in: what follows waits until its answer is sent
        super().resume_reading()


class TimedH11Protocol(H11Protocol):
    """uvicorn's h11 protocol with a deadline for each request's headers (:data:`HEADER_TIMEOUT`,
    from the first byte of a request on a kept-alive connection, from the connection on a new one)."""

    header_timeout = HEADER_TIMEOUT

    max_per_client = MAX_CONNECTIONS_PER_CLIENT
    refused = False

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        self._header_timer: asyncio.TimerHandle | None = None
        peer = transport.get_extra_info("peername")
        if peer and _open_from(self.connections, address_key(str(peer[0]))) >= self.max_per_client:
            self.refused = True  # one client holding the server's connections (idle-socket churn):
            transport.abort()  # cut before uvicorn sets anything up, nothing written (module doc)
            return
        super().connection_made(transport)
        self.flow = PipelineFlow(transport, self)  # before any request: every cycle gets this one
        self._arm()

    def _waiting_for_headers(self) -> bool:
        return self.transport.get_protocol() is self and (self.cycle is None or self.cycle.response_complete)

    def _arm(self) -> None:
        if self._header_timer is None:
            self._header_timer = self.loop.call_later(self.header_timeout, self._too_slow)

    def _disarm(self) -> None:
        if self._header_timer is not None:
            self._header_timer.cancel()
            self._header_timer = None

    def _too_slow(self) -> None:
        self._header_timer = None
        if self._waiting_for_headers() and not self.transport.is_closing():
            self.transport.close()

    def data_received(self, data: bytes) -> None:
        if self._waiting_for_headers():
            self._arm()
        super().data_received(data)
        if not self._waiting_for_headers():
            self._disarm()  # the headers are in (or the connection became a WebSocket)

    def connection_lost(self, exc: Exception | None) -> None:
        if self.refused:
            return  # never set up
        self._disarm()
        super().connection_lost(exc)

    def eof_received(self) -> None:
        if not self.refused:
            super().eof_received()
