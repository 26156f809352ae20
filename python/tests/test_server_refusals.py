"""What a misbehaving pupil's refused or excess traffic costs the lab server (docs/web.md, "A pupil in
the room"; issue 30): counted as work per refusal, not timed. A connection beyond its client's limit is
cut before uvicorn sets anything up for it; a ping flood is cut; the WebSocket frames are not
compressed (deflate took about a tenth of the event loop for float64 frames). Clients are told apart
by their address: a client binds 127.0.0.N (all of 127/8 is this machine)."""

from __future__ import annotations

import socket
import time
from collections.abc import Iterator
from typing import Any

import pytest
from uvicorn.protocols.http.h11_impl import H11Protocol
from websockets.sync.client import connect
from ws_session import live_lab

from pendulab.server import create_app
from pendulab.server.hygiene import PING_BURST, PING_RATE
from pendulab.server.room import MAX_CONNECTIONS_PER_CLIENT


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    with live_lab(create_app("rosette")) as p:
        yield p


def _open(port: int, source: str) -> socket.socket:
    s = socket.socket()
    s.bind((source, 0))
    s.connect(("127.0.0.1", port))
    return s


def test_a_connection_beyond_the_client_limit_costs_no_http_set_up(
    port: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Issue 30: the pupil's requests were refused at about 130 a second, each set up as an HTTP
    connection by uvicorn (its state, flow control, addresses, logging) and then cut. Now a connection
    over the limit is cut before that: uvicorn's set-up runs once per allowed connection only."""
    made: list[Any] = []
    setup = H11Protocol.connection_made

    def counted(self: H11Protocol, transport: Any) -> None:
        made.append(self)
        setup(self, transport)

    monkeypatch.setattr(H11Protocol, "connection_made", counted)
    extra = 40
    held = [_open(port, "127.0.0.21") for _ in range(MAX_CONNECTIONS_PER_CLIENT + extra)]
    try:
        time.sleep(0.5)
        assert len(made) == MAX_CONNECTIONS_PER_CLIENT, (
            f"{len(made)} connections set up for {MAX_CONNECTIONS_PER_CLIENT} allowed and {extra} over"
        )
        other = _open(port, "127.0.0.22")  # another client is served meanwhile
        other.sendall(b"GET /api/schema HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n\r\n")
        other.settimeout(10)
        assert other.recv(12).startswith(b"HTTP/1.1 200")
        other.close()
    finally:
        for s in held:
            s.close()


def test_a_ping_flood_is_cut_off(port: int) -> None:
    """Each ping costs the event loop a parse and a pong; a client reading its pongs could send
    thousands a second for good (the pupil of lab_load sent one every 0.5 ms). Beyond
    ``PING_RATE`` a second (a burst of ``PING_BURST`` seconds' worth) the connection is cut."""
    with connect(f"ws://127.0.0.1:{port}/ws", open_timeout=10, ping_interval=None) as ws:
        pings = 0
        try:
            for _ in range(int(4 * PING_BURST * PING_RATE)):
                ws.ping().wait(5)
                pings += 1
        except Exception:  # closed (or the pong never came: cut)
            pass
        assert pings <= PING_BURST * PING_RATE + 1, f"{pings} pings answered at once"


def test_a_few_pings_are_answered(port: int) -> None:
    with connect(f"ws://127.0.0.1:{port}/ws", open_timeout=10, ping_interval=None) as ws:
        for _ in range(5):
            assert ws.ping().wait(5)


def test_frames_are_not_compressed(port: int) -> None:
    """permessage-deflate took about 10 % of the event loop's samples in the pupil's room for frames of
    float64 numbers that hardly compress; the server no longer offers it."""
    with connect(f"ws://127.0.0.1:{port}/ws", open_timeout=10) as ws:
        assert ws.protocol.extensions == []
        assert ws.response is not None
        assert "permessage-deflate" not in ws.response.headers.get("Sec-WebSocket-Extensions", "")
