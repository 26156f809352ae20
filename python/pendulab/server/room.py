"""Fairness per client and per room (docs/web.md, "Security": "a pupil in the room").

A *client* is the address a connection comes from (a pupil's device; in classroom mode every pupil
carries the same token, so the token cannot tell them apart), a global IPv6 address by its /64 network,
a link-local one by itself (:func:`address_key`). :class:`Room` keeps, per client:

- its open lab sessions: at most ``per_client`` (:data:`MAX_SESSIONS_PER_CLIENT`); one more is refused
  with an error notice, as the server-wide ``max_sessions`` is;
- its computing requests under way (fits and analyses): at most :data:`MAX_REQUESTS_PER_CLIENT` at
  once; one more waits up to :data:`REQUEST_WAIT` for one of them to end, then gets HTTP 429,
  instead of taking a place in the shared queue (:meth:`Room.request`);
- the share of the room's stepping budget per tick (:meth:`Room.share`): :data:`ROOM_BUDGET` seconds of
  wall time per tick are split equally between the clients with open sessions, and a client's share
  equally between its sessions, each session's share at most one tick's
  :data:`~pendulab.server.session.TICK_BUDGET`. A page that needs less than its share (the usual
  case) leaves it unused; a greedy one lags (``status.lagging``) instead of slowing the others, however
  many sessions it opens. Commands such as ``load_scenario`` are carried out within the same share
  (:func:`pendulab.server.tick.tick_messages`).

The open connections per client are capped where connections are accepted
(:class:`pendulab.server.hygiene.TimedH11Protocol`, :data:`MAX_CONNECTIONS_PER_CLIENT`). All times in
seconds.
"""

from __future__ import annotations

import asyncio
import contextlib
import functools
import ipaddress
import time
from collections.abc import AsyncIterator, Mapping
from typing import Any

from .protocol import message
from .session import TICK_BUDGET

MAX_SESSIONS_PER_CLIENT = 8
"""Default for the most lab sessions (WebSockets) one client (address) may hold open: a pupil with a
few tabs."""

MAX_REQUESTS_PER_CLIENT = 2
"""Most computing requests (fits, exact solutions, reduced views, EM maps) one client may have under
way or waiting at once; more are answered 429."""

REQUEST_WAIT = 2.0
"""Most seconds a computing request beyond :data:`MAX_REQUESTS_PER_CLIENT` waits for one of its
client's others to end before it is answered 429."""

MAX_CONNECTIONS_PER_CLIENT = 24
"""Most TCP connections one client may hold open at once (its lab sessions plus a browser's six
keep-alive connections per tab, with room); more are closed as soon as they are accepted."""

ROOM_BUDGET = 0.008
"""Wall-clock seconds of stepping per tick (1/60 s ≈ 16.7 ms) shared by all the room's sessions: about a
quarter of two cores' time, the rest left for the sessions' frames, sending them and answering
requests (one tick of the whole room must fit in 16.7 ms, :mod:`.ticker`)."""


IPV6_PREFIX = 64
"""Leading bits of an IPv6 address that name one client. A /64 is the least a network hands out (a
home's or a LAN's subnet, a host's own routed /64); inside it a device takes as many addresses as it
likes (SLAAC privacy addresses, or any it assigns itself), so keyed by the whole address one device
would be as many clients as it has addresses, around every cap per client. Not for link-local
addresses (``fe80::/10``): every link's hosts, on every interface, share the prefix ``fe80::/64``, so
they are keyed by the whole address (:func:`address_key`)."""


@functools.lru_cache(maxsize=4096)
def address_key(host: str) -> str:
    """The client an address belongs to, the key of the caps per client: an IPv4 address itself; an
    IPv6 address its /64 network (``2001:db8:1:2::/64``, :data:`IPV6_PREFIX`; a zone index such as
    ``%eth0`` dropped); a link-local IPv6 address (``fe80::/10``) itself, with its zone index where it
    names one (``fe80::1%eth0``; uvicorn names a client without it): the /64 of every link-local address
    is ``fe80::/64``, on every link, so keyed by it all link-local clients of all interfaces were one;
    an IPv4-mapped IPv6 address (``::ffff:192.0.2.7``, how a socket bound to ``::`` sees an IPv4 client)
    the IPv4 address. Anything that is no IP address (a Unix socket, a test client's name) is its own
    key."""
    try:
        ip = ipaddress.ip_address(host)
    except ValueError:
        return host
    if isinstance(ip, ipaddress.IPv6Address):
        if ip.ipv4_mapped is not None:
            return str(ip.ipv4_mapped)
        if ip.is_link_local:
            return str(ip)  # compressed, lower case, with its zone (``%eth0``) where one was given
        return str(ipaddress.IPv6Network((int(ip), IPV6_PREFIX), strict=False))  # no zone
    return str(ip)


def client_key(scope: Mapping[str, Any]) -> str:
    """The client a request or WebSocket comes from: its address's :func:`address_key` (``"?"`` when
    the server does not know it)."""
    client = scope.get("client")
    return address_key(str(client[0])) if client else "?"


class Room:
    """The sessions and requests of every client (module doc). Used from the event loop only."""

    def __init__(
        self,
        per_client: int = MAX_SESSIONS_PER_CLIENT,
        room_budget: float = ROOM_BUDGET,
        computations: int = MAX_REQUESTS_PER_CLIENT,
    ):
        self.per_client = per_client
        self.room_budget = room_budget
        self.computations = computations  # most computing requests of one client at once
        self.sessions: dict[str, int] = {}
        self.requests: dict[str, int] = {}

    def open_session(self, key: str) -> str | None:
        """Counts a new session of ``key``; None when allowed, else the message why not."""
        have = self.sessions.get(key, 0)
        if have >= self.per_client:
            return (
                f"too many lab sessions from your device: {have} are open, the most one device may "
                f"have (pendulab serve --max-sessions-per-client {self.per_client}); close another tab"
            )
        self.sessions[key] = have + 1
        return None

    def close_session(self, key: str) -> None:
        left = self.sessions.get(key, 0) - 1
        if left > 0:
            self.sessions[key] = left
        else:
            self.sessions.pop(key, None)

    def share(self, key: str) -> float:
        """The stepping budget [s] of one tick of one of ``key``'s sessions (module doc)."""
        clients = max(1, len(self.sessions))
        mine = max(1, self.sessions.get(key, 1))
        return min(TICK_BUDGET, self.room_budget / clients / mine)

    @contextlib.asynccontextmanager
    async def request(self, key: str, wait: float = REQUEST_WAIT) -> AsyncIterator[bool]:
        """Counts a computing request of ``key`` while it runs. When the client already has
        ``computations`` (:data:`MAX_REQUESTS_PER_CLIENT`) under way, the request waits up to ``wait``
        seconds for one of them to end (a client sending in a tight loop is slowed down, not answered
        at once), then yields False (counting nothing): the caller answers 429
        (:meth:`too_many_requests`)."""
        deadline = time.monotonic() + wait
        while self.requests.get(key, 0) >= self.computations:
            if time.monotonic() >= deadline:
                yield False
                return
            await asyncio.sleep(0.05)
        self.requests[key] = self.requests.get(key, 0) + 1
        try:
            yield True
        finally:
            left = self.requests.get(key, 1) - 1
            if left > 0:
                self.requests[key] = left
            else:
                self.requests.pop(key, None)

    def too_many_requests(self) -> dict[str, Any]:
        """The body of the HTTP 429 answer (with ``retry-after: 1``) to a computing request beyond the
        client's ``computations``: the English ``detail`` and, for a page that translates it, ``key``
        (``messages.json``) and ``values``."""
        values = {"most": self.computations}
        return {"detail": message("device_busy", **values), "key": "device_busy", "values": values}
