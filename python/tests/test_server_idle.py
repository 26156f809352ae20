"""Idle WebSockets (docs/web.md, "A pupil in the room"): a client from which nothing at all arrives — no
command, no ping, no answer to the server's pings — for the idle timeout is closed with code 1001; a
client that sends nothing but answers the server's pings, as the lab's open page does (its browser
answers them by itself), is kept however long it stays quiet. Before, such sockets were never closed by
the lab (only uvicorn's undocumented 20-s pong deadline, a default, stood in for it).

Counted, not timed: the server's protocol is driven ping by ping here (its keepalive timer is what calls
``send_keepalive_ping``), with websockets' sans-I/O client as the page; over a real socket the count of
pings a silent client gets before the close is exact whatever the machine's speed."""

from __future__ import annotations

import asyncio
import re
import socket
import time
from typing import Any

import pytest
from test_server_client_caps import _free_port, _serve_configs
from typer.testing import CliRunner
from uvicorn import Config
from uvicorn.server import ServerState
from websockets.client import ClientProtocol
from websockets.frames import Frame, Opcode
from websockets.uri import parse_uri
from ws_session import live_lab

from pendulab.cli import app as cli
from pendulab.server import create_app
from pendulab.server.hygiene import WS_IDLE_TIMEOUT, WS_PING_INTERVAL, LabWebSocketProtocol
from pendulab.server.serving import MIN_IDLE_TIMEOUT, server_config


class _Transport(asyncio.Transport):
    """What the protocol writes, kept for the client; closing only marks it closed."""

    def __init__(self) -> None:
        super().__init__()
        self.out = bytearray()
        self.closed = False

    def get_extra_info(self, name: str, default: Any = None) -> Any:
        return {"peername": ("127.0.0.9", 50000), "sockname": ("127.0.0.1", 8000)}.get(name, default)

    def write(self, data: Any) -> None:
        self.out += data

    def is_closing(self) -> bool:
        return self.closed

    def close(self) -> None:
        self.closed = True

    def abort(self) -> None:
        self.closed = True

    def pause_reading(self) -> None:
        pass

    def resume_reading(self) -> None:
        pass

    def get_write_buffer_size(self) -> int:
        return len(self.out)


async def _quiet_app(scope: Any, receive: Any, send: Any) -> None:
    """A lab page's server side that expects nothing: accepts, then waits for the client to go."""
    assert (await receive())["type"] == "websocket.connect"
    await send({"type": "websocket.accept"})
    while (await receive())["type"] != "websocket.disconnect":
        pass


async def _accepted(config: Config) -> tuple[Any, ClientProtocol, _Transport]:
    """A WebSocket of ``config`` (loaded) accepted by ``_quiet_app``: the server's protocol, the
    sans-I/O client after the handshake and the transport between them."""
    server = config.ws_protocol_class(  # type: ignore[misc]
        config=config, server_state=ServerState(), app_state={}, _loop=asyncio.get_running_loop()
    )
    transport = _Transport()
    server.connection_made(transport)
    client = ClientProtocol(parse_uri("ws://127.0.0.1:8000/ws"))
    client.send_request(client.connect())
    server.data_received(b"".join(client.data_to_send()))
    for _ in range(50):  # the app accepts
        await asyncio.sleep(0)
    assert server.handshake_complete
    client.receive_data(bytes(transport.out))
    transport.out.clear()
    return server, client, transport


def _quiet_client(pings: int, idle_timeout: float, answers: bool) -> tuple[int, int | None]:
    """A client that sends nothing of its own, answering the server's pings or not, through ``pings``
    of the server's keepalive steps (interval 1000 s: the timer itself never fires here). Returns the
    pings it received and the close code it was sent (None: still open)."""

    async def run() -> tuple[int, int | None]:
        cls = type("Lab", (LabWebSocketProtocol,), {"idle_timeout": idle_timeout})
        config = Config(_quiet_app, ws=cls, ws_ping_interval=1000.0, ws_ping_timeout=None, lifespan="off")
        config.load()
        server, client, transport = await _accepted(config)

        def to_client() -> list[Any]:
            client.receive_data(bytes(transport.out))
            transport.out.clear()
            return list(client.events_received())

        got = 0
        for _ in range(pings):
            server.send_keepalive_ping()
            events = to_client()
            got += sum(1 for e in events if isinstance(e, Frame) and e.opcode is Opcode.PING)
            answer = b"".join(client.data_to_send())  # sans-I/O: the pongs it owes
            if answers and not transport.closed:
                server.data_received(answer)
            if transport.closed:
                break
        code = client.close_rcvd.code if client.close_rcvd is not None else None
        server.connection_lost(None)
        return got, code

    return asyncio.run(run())


def test_a_client_that_sends_nothing_and_answers_no_ping_is_closed_after_the_idle_timeout() -> None:
    interval = 1000.0
    got, code = _quiet_client(pings=50, idle_timeout=3 * interval, answers=False)
    # ping 1 finds the handshake heard; pings 2 and 3 find nothing since the last: 3 intervals silent
    assert (got, code) == (3, 1001)
    assert _quiet_client(pings=50, idle_timeout=2.5 * interval, answers=False) == (3, 1001)  # rounded up
    assert _quiet_client(pings=50, idle_timeout=1.0, answers=False) == (1, 1001)  # at least one interval


def test_a_quiet_page_that_answers_the_pings_is_never_idle() -> None:
    """The lab's page sends no command while nobody uses it (web/src sends none on a timer), but its
    browser answers every ping: 200 intervals of the idle timeout's 3, still open."""
    assert _quiet_client(pings=200, idle_timeout=3000.0, answers=True) == (200, None)


def test_a_silent_client_of_the_real_lab_gets_exactly_the_idle_timeouts_pings_then_1001() -> None:
    """Over a real socket with the lab itself: a client that completed the handshake and then answers
    nothing (it reads the frames the lab streams) gets the pings of the idle timeout, no more, and the
    close. Timeout 1 s (the least allowed), pings every 0.5 s: 2 silent intervals after the first ping."""
    lab = create_app("rosette")
    with live_lab(lab, idle_timeout=MIN_IDLE_TIMEOUT) as port:
        client = ClientProtocol(parse_uri(f"ws://127.0.0.1:{port}/ws"))
        client.send_request(client.connect())
        with socket.create_connection(("127.0.0.1", port), timeout=20) as s:
            s.sendall(b"".join(client.data_to_send()))
            pings = 0
            while client.close_rcvd is None and (data := s.recv(65536)):
                client.receive_data(data)
                for e in client.events_received():
                    pings += isinstance(e, Frame) and e.opcode is Opcode.PING
                client.data_to_send()  # the pongs: never sent
        for _ in range(1000):  # its session ends and frees the client's place (bounded wait)
            if not lab.state.room.sessions:
                break
            time.sleep(0.01)
        assert not lab.state.room.sessions
    assert client.close_rcvd is not None, "the silent client was not closed"
    assert (pings, client.close_rcvd.code) == (2, 1001)
    assert "idle" in client.close_rcvd.reason


def test_the_idle_timeout_is_a_setting_of_the_server_and_of_pendulab_serve(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    config = server_config(create_app("rosette"), "127.0.0.1", 8000)
    assert config.ws.idle_timeout == WS_IDLE_TIMEOUT  # type: ignore[union-attr]
    assert (config.ws_ping_interval, config.ws_ping_timeout) == (WS_PING_INTERVAL, None)
    short = server_config(create_app("rosette"), "127.0.0.1", 8000, idle_timeout=10.0)
    assert short.ws_ping_interval == 5.0  # two pings at least within the timeout
    least, most = (server_config(_quiet_app, "127.0.0.1", 8000, idle_timeout=t) for t in (1, 86_400.0))
    assert (least.ws.idle_timeout, least.ws_ping_interval) == (1.0, 0.5)  # type: ignore[union-attr]
    assert (most.ws.idle_timeout, most.ws_ping_interval) == (86_400.0, 20.0)  # type: ignore[union-attr]
    # inf: its ceil(inf / interval) raised at each ping; 1e-9 and 0.999: pings every half of it
    bads: list[Any] = [0.0, -1.0, float("nan"), float("inf"), 1e-9, 0.05, 0.999, 86_400.5, True, "60"]
    for bad in bads:
        allowed = f"the idle timeout must be a number of seconds from 1 to 86400 (one day), got {bad!r}"
        with pytest.raises(ValueError, match=re.escape(allowed)):
            server_config(_quiet_app, "127.0.0.1", 8000, idle_timeout=bad)
    ran = _serve_configs(monkeypatch)
    args = ["serve", "--no-browser", "--port", str(_free_port()), "--idle-timeout", "300"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.output
    (config,) = ran
    assert config.ws.idle_timeout == 300.0  # type: ignore[union-attr]
    # nan and ±inf get the message of every float option (test_cli_values.py)
    for arg, shown in (("0", "0.0"), ("1e-9", "1e-09"), ("0.5", "0.5"), ("86401", "86401.0")):
        bad = CliRunner().invoke(cli, ["serve", "--no-browser", "--idle-timeout", arg])
        assert bad.exit_code == 2, bad.output
        assert (
            "error: pendulab serve: --idle-timeout: the idle timeout must be a number of seconds from 1 to "
            f"86400 (one day), got {shown}; see 'pendulab serve --help'" in bad.output
        ), bad.output
    assert len(ran) == 1  # none of them started a server


def test_an_idle_client_that_reads_nothing_is_cut_and_its_session_ends() -> None:
    """A client that stopped reading (a frozen device, or on purpose) leaves the server's frames
    unsent in its socket buffer. Closing the socket waits for that buffer to drain — for good, here —
    so the idle close used to leave the connection and its session in place; it cuts it (a reset)
    instead. A real socket pair with small buffers, the app sending 1 MB; the keepalive driven by hand."""
    ended: list[str] = []

    async def talkative_app(scope: Any, receive: Any, send: Any) -> None:
        assert (await receive())["type"] == "websocket.connect"
        await send({"type": "websocket.accept"})
        await send({"type": "websocket.send", "bytes": bytes(1 << 20)})  # more than the socket takes
        while (await receive())["type"] != "websocket.disconnect":
            pass
        ended.append("disconnect")

    async def run() -> tuple[bool, bool]:
        config = Config(talkative_app, ws_ping_interval=1000.0, ws_ping_timeout=None, lifespan="off")
        config.load()
        cls = type("Lab", (LabWebSocketProtocol,), {"idle_timeout": 2000.0})
        loop = asyncio.get_running_loop()
        server = cls(config=config, server_state=ServerState(), app_state={}, _loop=loop)
        ours, theirs = socket.socketpair()
        for s in (ours, theirs):
            s.setsockopt(socket.SOL_SOCKET, socket.SO_SNDBUF, 4096)
            s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        transport, _ = await loop.connect_accepted_socket(lambda: server, ours)
        client = ClientProtocol(parse_uri("ws://127.0.0.1:8000/ws"))
        client.send_request(client.connect())
        theirs.sendall(b"".join(client.data_to_send()))  # the handshake; then it reads nothing
        for _ in range(200):
            await asyncio.sleep(0)
            if transport.get_write_buffer_size() > 0:
                break
        assert transport.get_write_buffer_size() > 0, "the frame fit the socket: nothing waits"
        for _ in range(3):  # pings 1-3: the handshake heard, then 2 intervals of silence: closed
            server.send_keepalive_ping()
        for _ in range(200):
            await asyncio.sleep(0)
            if server.disconnected and ended:
                break
        theirs.close()
        return server.disconnected, bool(ended)

    assert asyncio.run(run()) == (True, True)


@pytest.mark.parametrize("idle_timeout", [1.0, 10.0, 60.0, 3600.0, 86_400.0])
def test_the_idle_check_runs_at_the_keepalive_pings_which_server_config_always_turns_on(
    idle_timeout: float,
) -> None:
    """The idle check is the protocol's ``send_keepalive_ping``, which uvicorn's keepalive timer calls,
    and uvicorn arms that timer only when ``ws_ping_interval`` is a number > 0. With the lab's
    configuration (``server_config``) the timer is armed when the handshake completes, for at most
    half the idle timeout, whatever the timeout; with uvicorn's pings turned off it is not, and a
    silent client is never closed. For the shortest timeout allowed (1 s) the timer is let run: the
    silent client gets the close (1001) in real time, from nothing but the configuration's own timer."""

    async def run(pings_on: bool) -> tuple[float | None, int | None]:
        config = server_config(_quiet_app, "127.0.0.1", 8000, idle_timeout=idle_timeout)
        if not pings_on:
            config.ws_ping_interval = None  # what the idle check must not be left with
        config.load()
        server, client, transport = await _accepted(config)
        timer = server.ping_timer
        armed = None if timer is None else timer.when() - asyncio.get_running_loop().time()
        if idle_timeout == MIN_IDLE_TIMEOUT:  # 1 s: pings every 0.5 s, the close after 2 silent intervals
            deadline = asyncio.get_running_loop().time() + 20 * idle_timeout  # bounded, however loaded
            while not transport.closed and asyncio.get_running_loop().time() < deadline:
                await asyncio.sleep(0.005)
        client.receive_data(bytes(transport.out))
        code = client.close_rcvd.code if client.close_rcvd is not None else None
        server.connection_lost(None)
        return armed, code

    armed, code = asyncio.run(run(pings_on=True))
    assert armed is not None, "server_config left uvicorn's keepalive pings off: nothing checks idleness"
    assert 0.0 < armed <= idle_timeout / 2 + 1e-3
    if idle_timeout == MIN_IDLE_TIMEOUT:
        assert code == 1001
    assert asyncio.run(run(pings_on=False)) == (None, None)  # pings off: never checked, never closed
