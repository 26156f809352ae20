"""The lab server as a classroom service (docs/web.md, "Security": "a pupil in the room"), part 2 of
issue 30's attacks: fairness per client and per room. One client's greedy sessions and
``load_scenario`` flood, idle sockets, parallel computing requests, GET floods and WebSocket pings
without reading must leave other clients their frames and answers (``pendulab/server/room.py``,
``tick.py``, ``hygiene.py``). Other clients are told apart by their address: a client binds 127.0.0.N
(all of 127/8 is this machine). Times in seconds, budgets in seconds of CPU per frame."""

from __future__ import annotations

import asyncio
import base64
import contextlib
import json
import os
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from typing import Any

import httpx
import pytest
from websockets.sync.client import connect
from ws_session import LabClient, frame_gaps, live_lab, receive

from pendulab.server import create_app, tick
from pendulab.server.hygiene import MAX_WS_BUFFER
from pendulab.server.protocol import parse_command
from pendulab.server.room import MAX_CONNECTIONS_PER_CLIENT, MAX_REQUESTS_PER_CLIENT, Room
from pendulab.server.session import Session, resolve_scenario


def _local(n: int) -> str:
    return f"127.0.0.{n}"


def _ws(port: int, source: int = 1) -> Any:
    """A WebSocket to the lab from 127.0.0.``source``."""
    sock = socket.socket()
    sock.bind((_local(source), 0))
    sock.connect(("127.0.0.1", port))
    return connect(f"ws://127.0.0.1:{port}/ws", sock=sock, proxy=None, open_timeout=10, max_queue=None)


# --- 2. fairness per client and per room ------------------------------------------------------------------


def test_one_client_may_hold_only_its_share_of_sessions() -> None:
    client = LabClient(create_app("rosette", max_sessions_per_client=2))
    with client.websocket_connect("/ws") as a, client.websocket_connect("/ws") as b:
        assert receive(a)[1]["type"] == "status" and receive(b)[1]["type"] == "status"
        with client.websocket_connect("/ws") as c:
            _, notice = receive(c)
            assert notice["type"] == "error" and "too many lab sessions from your device" in notice["message"]
    with client.websocket_connect("/ws") as d:  # the closed ones are counted off
        assert receive(d)[1]["type"] == "status"


def test_the_room_budget_is_shared_by_clients_then_by_their_sessions() -> None:
    room = Room(per_client=8, room_budget=0.012)  # (the default is 8 ms)
    for _ in range(8):
        assert room.open_session("greedy") is None
    assert room.open_session("greedy") is not None
    for i in range(29):
        room.open_session(f"pupil{i}")
    assert room.share("pupil0") == pytest.approx(0.012 / 30)
    assert room.share("greedy") == pytest.approx(0.012 / 30 / 8)  # 8 sessions: the same as one page

    async def three() -> None:
        async with room.request("x") as first, room.request("x") as second:
            t0 = time.monotonic()
            async with room.request("x", wait=0.2) as third:
                assert first and second and not third and MAX_REQUESTS_PER_CLIENT == 2
            assert time.monotonic() - t0 >= 0.2  # it waited for a slot first
        async with room.request("x") as again:
            assert again

    asyncio.run(three())


def test_commands_are_carried_out_within_the_budget_and_the_rest_wait() -> None:
    s = Session(resolve_scenario("rosette"))
    names = ("damped", "rosette") * 10
    loads = [parse_command(json.dumps({"type": "load_scenario", "name": n})) for n in names]
    carry = tick.Carry()
    tick.tick_messages(s, loads, 1 / 60, 1e-6, carry=carry)
    assert s.commands == 1 and len(carry.left) == 19, "one command when the budget is spent at once"
    assert carry.debt > 0, "its cost beyond the budget is owed"
    left, carry.left = carry.left, []
    tick.tick_messages(s, left, 1 / 60, 1e-6, carry=carry)
    assert s.commands == 1 and len(carry.left) == 19, "none while the debt is paid off"
    carry = tick.Carry()
    s2 = Session(resolve_scenario("rosette"))
    tick.tick_messages(s2, left, 1 / 60, 1.0, carry=carry)
    assert s2.commands == 19 and not carry.left, "all of them within a large budget"
    assert s2.scenario == "rosette"


GREEDY = [
    {"type": "set_model", "model": "damped", "params": {"forcing_amplitude": 1e3, "forcing_omega": 1e4}},
    {"type": "set_method", "method": "dop853"},
    {"type": "set_time_scale", "time_scale": 1000.0},
]


PUPIL = """
import asyncio, json, sys, time
from websockets.asyncio.client import connect
port, sessions, flooding, seconds = (int(a) for a in sys.argv[1:5])
greedy = json.loads(sys.argv[5])

async def session(k):
    url = f"ws://127.0.0.1:{port}/ws"
    async with connect(url, max_queue=None, max_size=2**22, local_addr=("127.0.0.2", 0)) as ws:
        async def drain():
            async for _ in ws:
                pass
        reader = asyncio.create_task(drain())
        for c in greedy:
            await ws.send(json.dumps(c))
        end, i = time.monotonic() + seconds, 0
        while time.monotonic() < end and not reader.done():
            if k < flooding:
                await ws.send(json.dumps({"type": "load_scenario", "name": ("kepler", "rosette")[i % 2]}))
                i += 1
            await asyncio.sleep(0.002)
        reader.cancel()

async def main():
    await asyncio.gather(*(session(k) for k in range(sessions)), return_exceptions=True)

asyncio.run(main())
"""


@contextlib.contextmanager
def pupil(port: int, sessions: int, flooding: int, seconds: float) -> Iterator[None]:
    """A misbehaving client from 127.0.0.2 in another process: ``sessions`` greedy sessions, the first
    ``flooding`` of them sending ``load_scenario`` without pause, for ``seconds``."""
    args = [str(port), str(sessions), str(flooding), str(int(seconds)), json.dumps(GREEDY)]
    with subprocess.Popen([sys.executable, "-c", PUPIL, *args]) as proc:
        try:
            time.sleep(1.0)
            yield
        finally:
            proc.kill()


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    with live_lab(create_app("rosette")) as p:
        yield p


def test_greedy_sessions_and_a_load_scenario_flood_leave_the_others_their_frames(port: int) -> None:
    """Issue 30: 16 greedy sessions of one client cut others to 18 frames/s of 60, four sessions
    flooding ``load_scenario`` to 6.6 with 2.6 s gaps. Both at once left the neighbour 4-6 % of
    what it got alone on the server of before (on a machine with a load average of 17 on 2 cores:
    2-3 frames/s of 55-59), 20-65 % now; the margin is for the shared machine the tests run on (the
    load benchmark, bench/lab_load.py, measures the room on an idle one)."""
    alone = frame_gaps(port, 2.0)
    with pupil(port, sessions=16, flooding=4, seconds=6):
        beside = frame_gaps(port, 3.0)
    ratio = (len(beside) / 3.0) / (len(alone) / 2.0)
    assert ratio > 0.12, f"{len(beside)} frames in 3 s beside the pupil, {len(alone)} in 2 s alone"
    assert max(beside) < 1.0, f"a gap of {max(beside):.2f} s"


def _closed(s: socket.socket) -> bool:
    """True when the server has closed (or reset) the connection."""
    try:
        return s.recv(1, socket.MSG_DONTWAIT | socket.MSG_PEEK) == b""
    except BlockingIOError:
        return False
    except OSError:
        return True


def test_idle_sockets_of_one_client_cannot_fill_the_server(port: int) -> None:
    """Issue 30: ~150 idle sockets from one client made every other request 503."""
    idle = []
    try:
        for _ in range(150):
            s = socket.socket()
            s.bind((_local(3), 0))
            s.connect(("127.0.0.1", port))
            idle.append(s)
        time.sleep(0.3)
        r = httpx.get(f"http://127.0.0.1:{port}/api/schema", timeout=5)
        assert r.status_code == 200
        cut = sum(_closed(s) for s in idle)
        assert cut >= 150 - MAX_CONNECTIONS_PER_CLIENT
    finally:
        for s in idle:
            s.close()


def test_parallel_computing_requests_of_one_client_do_not_crowd_out_another(port: int) -> None:
    """Issue 30: 40 parallel ``/api/reduced`` requests got others' ``/api/exact`` 503 in 22 of 25 (they
    filled the shared queue); now one client has at most two under way or waiting, the rest wait for
    those (then 429) or are cut beyond its connection limit."""
    body = {"length": 1.0, "g": 9.81, "theta": 2.9, "phi_dot": 0.1, "n": 4000, "grid": 121}
    codes: list[int] = []

    def flood() -> None:
        transport = httpx.HTTPTransport(local_address=_local(4))
        with httpx.Client(base_url=f"http://127.0.0.1:{port}", transport=transport, timeout=30) as c:
            for _ in range(2):
                try:
                    codes.append(c.post("/api/reduced", json=body).status_code)
                except httpx.TransportError:
                    codes.append(-1)  # cut: more connections than one client may hold

    threads = [threading.Thread(target=flood) for _ in range(40)]
    for t in threads:
        t.start()
    time.sleep(0.3)
    mine = [
        httpx.post(f"http://127.0.0.1:{port}/api/exact", json={"theta": 1.0}, timeout=30) for _ in range(5)
    ]
    for t in threads:
        t.join(60)
    assert [r.status_code for r in mine] == [200] * 5, [r.text[:200] for r in mine]
    assert 200 in codes and set(codes) <= {200, 429, -1}, codes


def test_get_answers_are_cached(monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 30: 12 parallel ``GET /api/scenarios`` (a foreign page can send them) cut pages to 9.5
    frames/s: each listed and parsed every example file."""
    import pendulab.server.app as app_module

    calls = []
    listed = app_module.scenarios
    monkeypatch.setattr(app_module, "scenarios", lambda: calls.append(1) or listed())
    client = LabClient(create_app("rosette"))
    first = client.get("/api/scenarios")
    assert first.status_code == 200 and len(first.json()) > 3
    assert all(client.get("/api/scenarios").content == first.content for _ in range(5))
    assert len(calls) == 1


def _ws_frame(opcode: int, payload: bytes) -> bytes:
    mask = os.urandom(4)
    masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
    return bytes([0x80 | opcode, 0x80 | len(payload)]) + mask + masked


def test_a_client_that_pings_without_reading_is_cut_off(port: int) -> None:
    """Issue 30: pings without reading grew the server from 72 to 342 MiB."""
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.connect(("127.0.0.1", port))
    key = base64.b64encode(os.urandom(16)).decode()
    s.sendall(
        (
            f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
            f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n"
        ).encode()
    )
    ping = _ws_frame(0x9, b"p" * 125) * 64
    sent = 0
    cut = False
    s.settimeout(5)
    try:
        while sent < 40 * MAX_WS_BUFFER:  # never reads: the pongs pile up on the server
            s.sendall(ping)
            sent += len(ping)
    except OSError:  # reset (or blocked: the server stopped reading us)
        cut = True
    finally:
        s.close()
    assert cut, f"{sent} bytes of pings sent and the connection still open"
