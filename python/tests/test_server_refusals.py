"""What a misbehaving pupil's refused or excess traffic costs the lab server (docs/web.md, "A pupil in
the room"; issue 30): counted as work per refusal, not timed. A connection beyond its client's limit is
cut before uvicorn sets anything up for it; a ping flood is cut; a command flood is read no faster
than the ticks take it, pipelined requests no faster than they are answered; the WebSocket frames are
not compressed (deflate took about a tenth of the event loop for float64 frames). Clients are told
apart by their address: a client binds 127.0.0.N (all of 127/8 is this machine)."""

from __future__ import annotations

import asyncio
import contextlib
import socket
import time
from collections.abc import Iterator
from typing import Any

import pytest
from uvicorn.protocols.http.h11_impl import H11Protocol
from websockets.sync.client import connect
from ws_session import live_lab

from pendulab.server import create_app, live_socket
from pendulab.server.hygiene import PING_BURST, PING_RATE, TimedH11Protocol
from pendulab.server.room import MAX_CONNECTIONS_PER_CLIENT
from pendulab.server.schema import TICK_HZ
from pendulab.server.session import Session, resolve_scenario
from pendulab.server.ticker import MAX_PENDING, Seat


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


class _Flood:
    """A WebSocket whose client sends ``pause`` without end; counts the messages the handler read."""

    def __init__(self) -> None:
        self.read = 0

    async def receive(self) -> dict[str, Any]:
        self.read += 1
        if self.read > 50 * MAX_PENDING:  # read on and on (as before): stop the test's loop
            raise RuntimeError("read past a full inbox")
        return {"type": "websocket.receive", "text": '{"type": "pause"}'}


def test_a_command_flood_is_not_read_past_a_full_inbox_until_the_next_tick() -> None:
    """A client sending commands as fast as it can had every message read, parsed and dropped by the
    event loop (one client's flood of ``pause`` took the other pages' answers from 10 ms to 0.5-2.5 s
    and their frames to 0.4-0.6 s gaps). Now, once one is dropped, the handler reads nothing more
    until the seat's next tick (no ticker here: the ticks are made by hand)."""

    async def run() -> None:
        seat, ws = Seat(Session(resolve_scenario("rosette"))), _Flood()
        reader = asyncio.create_task(live_socket._receive(ws, seat))  # type: ignore[arg-type]
        for _ in range(20):
            await asyncio.sleep(0)
        assert (ws.read, len(seat.inbox), seat.dropped) == (MAX_PENDING + 1, MAX_PENDING, 1)
        for _ in range(3):  # a tick takes some commands and counts the dropped one: read on to the next
            taken = len(seat.inbox) - MAX_PENDING // 2
            with seat.lock:
                for _ in range(taken):
                    seat.inbox.popleft()
                seat.dropped = 0
            seat._deliver([])
            before = ws.read
            for _ in range(20):
                await asyncio.sleep(0)
            assert ws.read - before == taken + 1 and seat.dropped == 1
        reader.cancel()

    asyncio.run(run())


def test_a_flooding_client_has_its_commands_read_no_faster_than_the_ticks(
    port: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """End to end, counted: of 2000 commands sent at once at most MAX_PENDING + 1 are read per tick
    (the rest wait in the client's socket); before, all were read within a few tens of ms (4000 in 6
    ticks)."""
    parsed: list[int] = []
    parse = live_socket.parse_command

    def counted(text: str | bytes) -> Any:
        parsed.append(1)
        return parse(text)

    monkeypatch.setattr(live_socket, "parse_command", counted)
    n = 2000
    with connect(f"ws://127.0.0.1:{port}/ws", open_timeout=10, max_queue=None) as ws:
        ws.recv(10)  # the status: the session is seated
        start = time.monotonic()
        for _ in range(n):
            ws.send('{"type": "pause"}')
        deadline = start + 0.3
        while len(parsed) < n and time.monotonic() < deadline:
            time.sleep(0.01)
        ticks = TICK_HZ * (time.monotonic() - start) + 2  # ticks since the first send, at most
        assert len(parsed) <= (MAX_PENDING + 1) * (ticks + 1), f"{len(parsed)} read in {ticks:.0f} ticks"


def test_pipelined_posts_are_read_no_faster_than_they_are_answered(
    port: int, monkeypatch: pytest.MonkeyPatch
) -> None:
    """One connection sending POSTs without waiting for the answers (HTTP pipelining) had one more
    chunk (up to 256 KiB) of them read into the server's memory per POST answered off the event loop
    (an answer computed in a thread or worker): about 85 MB a second, without end. Counted: what the
    server read beyond the requests it answered stays within a chunk or two."""
    body = b'{"n": 16}'
    request = (
        b"POST /api/effective_potential HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        b"Content-Length: %d\r\n\r\n%s" % (len(body), body)
    )
    read = [0]
    received = TimedH11Protocol.data_received

    def counted(self: TimedH11Protocol, data: bytes) -> None:
        if self.client and self.client[0] == "127.0.0.23":
            read[0] += len(data)
        received(self, data)

    monkeypatch.setattr(TimedH11Protocol, "data_received", counted)
    s = _open(port, "127.0.0.23")
    s.setblocking(False)
    blob, sent, answers, answered = request * 2000, 0, b"", 0
    try:
        deadline = time.monotonic() + 20
        while answered < 300 and time.monotonic() < deadline:
            with contextlib.suppress(BlockingIOError):
                sent += s.send(blob[sent % len(blob) :])
            with contextlib.suppress(BlockingIOError):
                answers += s.recv(1 << 20)
            answered = answers.count(b"HTTP/1.1 200")
            held = read[0] - answered * len(request)  # read, not yet answered
            assert held < 2**20, f"{held} bytes read beyond {answered} answers"
            time.sleep(0.001)
        assert answered >= 300, f"{answered} pipelined requests answered"
    finally:
        s.close()
