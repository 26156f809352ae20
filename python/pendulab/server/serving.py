"""How ``pendulab serve`` runs the lab with uvicorn (docs/web.md, "Security"): the HTTP protocol with a
header deadline (:class:`~.hygiene.TimedH11Protocol`), message and connection limits, and a shutdown
that ends within :data:`SHUTDOWN_GRACE` seconds whatever the clients do.

uvicorn handles Ctrl-C (SIGINT) and SIGTERM itself: its main loop notices them within 0.1 s, stops
listening, closes every WebSocket (code 1012) and, after ``timeout_graceful_shutdown``, cancels what is
still running. That works only while the event loop is free, which the lab guarantees by stepping in
worker threads with a wall-time budget per tick (:mod:`.tick`); a worker thread finishes its tick
within that budget.
"""

from __future__ import annotations

import numbers
from typing import Any

import uvicorn

from .hygiene import HEADER_TIMEOUT, WS_IDLE_TIMEOUT, WS_PING_INTERVAL, LabWebSocketProtocol, TimedH11Protocol
from .room import MAX_CONNECTIONS_PER_CLIENT

SHUTDOWN_GRACE = 0.5
"""Seconds the open connections get to close after Ctrl-C or SIGTERM before they are cut."""

WS_MAX_BYTES = 65536
"""Largest WebSocket message uvicorn reads [bytes] (a command is a few hundred bytes; longer ones are
closed with code 1009); the session refuses commands over 4096 characters itself."""

KEEP_ALIVE = 5
"""Seconds an idle HTTP keep-alive connection stays open."""

MIN_IDLE_TIMEOUT = 1.0
"""Least idle timeout [s] of a WebSocket (:func:`server_config`, ``pendulab serve --idle-timeout``): the
server pings twice per timeout, and a browser's answer needs a round trip, so a shorter one would ping
every client many times a second and close pages for a hiccup of their network."""

MAX_IDLE_TIMEOUT = 86_400.0
"""Most idle timeout [s] of a WebSocket: one day."""


def check_idle_timeout(seconds: Any) -> float:
    """``seconds`` as the idle timeout of :func:`server_config` and ``pendulab serve --idle-timeout`` (the
    one rule of both): a number from :data:`MIN_IDLE_TIMEOUT` to :data:`MAX_IDLE_TIMEOUT`, else a
    ``ValueError`` naming it and what is allowed."""
    ok = isinstance(seconds, numbers.Real) and not isinstance(seconds, bool)
    if not (ok and MIN_IDLE_TIMEOUT <= seconds <= MAX_IDLE_TIMEOUT):  # nan too
        raise ValueError(
            f"the idle timeout must be a number of seconds from {MIN_IDLE_TIMEOUT:g} to "
            f"{MAX_IDLE_TIMEOUT:g} (one day), got {seconds!r}"
        )
    return float(seconds)


def server_config(
    app: Any,
    host: str,
    port: int,
    *,
    max_sessions: int = 64,
    max_connections_per_client: int = MAX_CONNECTIONS_PER_CLIENT,
    header_timeout: float = HEADER_TIMEOUT,
    idle_timeout: float = WS_IDLE_TIMEOUT,
    log_level: str = "warning",
    trusted_proxies: str | None = None,
) -> uvicorn.Config:
    """The uvicorn configuration of the lab: ``app`` on ``host``:``port`` with the limits of the module
    doc; at most ``max_sessions`` + 64 connections at once (the pages' WebSockets and their requests;
    beyond that uvicorn answers 503), at most ``max_connections_per_client`` of one client (address;
    more are reset when accepted: :class:`~.hygiene.TimedH11Protocol`; a global IPv6 client is its /64,
    :func:`~.room.address_key`); a WebSocket from which nothing (no command, ping or pong) arrives for
    ``idle_timeout`` seconds (:func:`check_idle_timeout`: 1 s to a day, else ``ValueError``) is closed
    (code 1001): the server pings every :data:`~.hygiene.WS_PING_INTERVAL` seconds (at most half the idle
    timeout) and a browser answers by itself, so an open page is kept
    (:class:`~.hygiene.LabWebSocketProtocol`). uvicorn's own pong deadline is off: the idle timeout is
    the one rule.

    The idle check runs only at uvicorn's keepalive pings: it is
    :meth:`~.hygiene.LabWebSocketProtocol.send_keepalive_ping`, which uvicorn's timer calls every
    ``ws_ping_interval`` seconds, and uvicorn starts that timer only when ``ws_ping_interval`` is a
    number > 0. This configuration therefore always turns the pings on (``ws_ping_interval`` is never
    None or 0, whatever ``idle_timeout``); a configuration with them off would never close an idle
    client (tests: ``python/tests/test_server_idle.py``).

    The client is the address a connection comes from. uvicorn would by default believe the
    ``X-Forwarded-For`` and ``X-Forwarded-Proto`` headers of connections from 127.0.0.1, so any program
    on the machine could name its own client key and escape the caps per client: that is off. Behind a
    reverse proxy, ``trusted_proxies`` names it (uvicorn's ``forwarded_allow_ips``: comma-separated
    addresses or networks, ``*`` any); only connections from there may name the client."""
    protocol = type(
        "LabH11Protocol",
        (TimedH11Protocol,),
        {"header_timeout": float(header_timeout), "max_per_client": int(max_connections_per_client)},
    )
    idle_timeout = check_idle_timeout(idle_timeout)
    websocket = type("LabWebSocket", (LabWebSocketProtocol,), {"idle_timeout": idle_timeout})
    return uvicorn.Config(
        app,
        host=host,
        port=port,
        log_level=log_level,
        http=protocol,
        ws=websocket,
        ws_ping_interval=min(WS_PING_INTERVAL, idle_timeout / 2),  # never off: the idle check runs at pings
        ws_ping_timeout=None,  # the idle timeout closes a client that stopped answering (module doc)
        ws_max_size=WS_MAX_BYTES,
        ws_per_message_deflate=False,  # frames are float64: deflate saved little and took ~10 % of the loop
        timeout_keep_alive=KEEP_ALIVE,
        timeout_graceful_shutdown=SHUTDOWN_GRACE,  # type: ignore[arg-type]  # uvicorn waits a float
        limit_concurrency=max_sessions + 64,
        server_header=False,
        proxy_headers=trusted_proxies is not None,  # forged X-Forwarded-For would choose the client key
        forwarded_allow_ips=trusted_proxies if trusted_proxies is not None else "",
    )
