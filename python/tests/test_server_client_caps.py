"""The lab server's caps per client (docs/web.md, "A pupil in the room"): WebSockets (lab sessions),
TCP connections and computing requests of one client (its address), each set by ``pendulab serve``
(``--max-sessions-per-client``, ``--max-connections-per-client``, ``--max-computations-per-client``)
and refused clearly: a WebSocket with the ``device_full`` notice and close code 1013, a computation
with HTTP 429 and the ``device_busy`` message key, a connection reset as soon as it is accepted. Other
clients (another address: a client binds 127.0.0.N, all of 127/8 is this machine) are served
meanwhile."""

from __future__ import annotations

import json
import os
import socket
import sys
import time
from collections.abc import Iterator
from typing import Any

import httpx
import pytest
from typer.testing import CliRunner
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import connect
from ws_session import LabClient, live_lab

from pendulab.cli import app as cli
from pendulab.server import create_app
from pendulab.server.protocol import MESSAGES
from pendulab.server.serving import server_config


def _ws(port: int, source: str) -> object:
    sock = socket.socket()
    sock.bind((source, 0))
    sock.connect(("127.0.0.1", port))
    return connect(f"ws://127.0.0.1:{port}/ws", sock=sock, proxy=None, open_timeout=10, max_queue=None)


def _first_notice(ws: object) -> dict:
    for _ in range(50):
        msg = ws.recv(timeout=10)  # type: ignore[attr-defined]
        if isinstance(msg, str):
            return json.loads(msg)
    raise AssertionError("no notice")


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    with live_lab(create_app("rosette", max_sessions_per_client=2)) as p:
        yield p


def test_websockets_beyond_the_client_cap_are_refused_with_a_key(port: int) -> None:
    with _ws(port, "127.0.0.31") as a, _ws(port, "127.0.0.31") as b:  # type: ignore[attr-defined]
        assert _first_notice(a)["type"] == "status" and _first_notice(b)["type"] == "status"
        with _ws(port, "127.0.0.31") as c:  # type: ignore[attr-defined]
            notice = _first_notice(c)
            assert notice["type"] == "error" and notice["key"] == "device_full"
            assert notice["values"] == {"have": 2}
            with pytest.raises(ConnectionClosed) as closed:
                c.recv(timeout=10)
            assert closed.value.rcvd is not None and closed.value.rcvd.code == 1013
        with _ws(port, "127.0.0.32") as other:  # type: ignore[attr-defined]  # another device
            assert _first_notice(other)["type"] == "status"


def _ws_forwarded(port: int, forwarded: str) -> object:
    headers = {"X-Forwarded-For": forwarded, "X-Forwarded-Proto": "https"}
    return connect(
        f"ws://127.0.0.1:{port}/ws", additional_headers=headers, proxy=None, open_timeout=10, max_queue=None
    )


def test_a_forged_x_forwarded_for_does_not_change_the_client(port: int) -> None:
    """A local program (127.0.0.1, which uvicorn trusts as a proxy by default) naming another address
    in ``X-Forwarded-For`` is still the client it connects from: its third session is refused."""
    with _ws_forwarded(port, "10.9.8.1") as a, _ws_forwarded(port, "10.9.8.2") as b:  # type: ignore[attr-defined]
        assert _first_notice(a)["type"] == "status" and _first_notice(b)["type"] == "status"
        with _ws_forwarded(port, "10.9.8.3, 10.9.8.4") as c:  # type: ignore[attr-defined]
            notice = _first_notice(c)
            assert notice["type"] == "error" and notice["key"] == "device_full"


def test_the_client_key_is_the_peer_unless_a_proxy_is_trusted() -> None:
    """What the application sees as the client (its key, :func:`pendulab.server.room.client_key`) with
    a forged ``X-Forwarded-For``: the connecting address by default; the named one only from a proxy
    given to ``server_config(trusted_proxies=...)`` (``pendulab serve --trust-proxy``)."""
    import asyncio

    from pendulab.server.room import client_key

    seen: list[tuple[str, str]] = []

    async def app(scope: dict, receive: object, send: object) -> None:
        seen.append((client_key(scope), scope["scheme"]))

    async def call(trusted: str | None, peer: str) -> tuple[str, str]:
        config = server_config(app, "127.0.0.1", 8000, trusted_proxies=trusted)
        config.load()
        headers = [(b"x-forwarded-for", b"10.9.8.7"), (b"x-forwarded-proto", b"https")]
        scope = {"type": "http", "scheme": "http", "client": (peer, 5000), "headers": headers}
        await config.loaded_app(scope, None, None)
        return seen.pop()

    assert asyncio.run(call(None, "127.0.0.1")) == ("127.0.0.1", "http")
    assert asyncio.run(call("10.0.0.2", "127.0.0.1")) == ("127.0.0.1", "http")
    assert asyncio.run(call("10.0.0.2", "10.0.0.2")) == ("10.9.8.7", "https")


def _reset(s: socket.socket) -> bool:
    s.settimeout(5)
    try:
        return s.recv(1) == b""
    except OSError:
        return True


def test_connections_beyond_the_configured_cap_are_reset() -> None:
    import asyncio
    import threading

    import uvicorn

    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    config = server_config(create_app("rosette"), "127.0.0.1", port, max_connections_per_client=5)
    server = uvicorn.Server(config)
    thread = threading.Thread(target=lambda: asyncio.run(server.serve(sockets=[sock])), daemon=True)
    thread.start()
    held: list[socket.socket] = []
    try:
        for _ in range(500):
            if server.started:
                break
            time.sleep(0.01)
        for _ in range(5):
            s = socket.socket()
            s.bind(("127.0.0.33", 0))
            s.connect(("127.0.0.1", port))
            held.append(s)
        time.sleep(0.2)
        extra = socket.socket()
        extra.bind(("127.0.0.33", 0))
        extra.connect(("127.0.0.1", port))
        held.append(extra)
        assert _reset(extra), "the sixth connection of one client was kept"
        r = httpx.get(f"http://127.0.0.1:{port}/api/schema", timeout=10)  # another client
        assert r.status_code == 200
    finally:
        for s in held:
            s.close()
        server.should_exit = True
        thread.join(10)
        sock.close()


def test_a_computation_beyond_the_client_cap_gets_429_with_a_key() -> None:
    app = create_app("rosette", max_computations_per_client=1)
    client = LabClient(app)
    app.state.room.requests["testclient"] = 1  # one of this client's computations under way
    r = client.post("/api/exact", json={"theta": 1.0})
    assert r.status_code == 429
    body = r.json()
    assert body["key"] == "device_busy" and body["values"] == {"most": 1}
    assert body["detail"] == MESSAGES["device_busy"].format(most=1)
    r = client.post("/api/fit", json={"csv": "t,x,z\n0,0.1,-0.9\n", "name": "a.csv"})
    assert r.status_code == 429 and r.json()["key"] == "device_busy"
    app.state.room.requests.clear()
    assert client.post("/api/exact", json={"theta": 1.0}).status_code == 200


def _serve_configs(monkeypatch: pytest.MonkeyPatch) -> list[Any]:
    """``pendulab serve`` made to record the uvicorn configs it would serve with instead of serving
    (and to leave with sys.exit where it calls os._exit): the list it fills."""
    import uvicorn

    ran: list[uvicorn.Config] = []

    def run(self: uvicorn.Server) -> None:  # instead of serving: what it would serve with
        ran.append(self.config)
        self.started = True

    monkeypatch.setattr(uvicorn.Server, "run", run)
    monkeypatch.setenv("PENDULAB_NO_BROWSER", "1")
    monkeypatch.setattr(os, "_exit", lambda code: sys.exit(code))  # serve leaves with os._exit
    return ran


def test_pendulab_serve_takes_the_caps_per_client(monkeypatch: pytest.MonkeyPatch) -> None:
    ran = _serve_configs(monkeypatch)
    args = ["serve", "--no-browser", "--port", str(_free_port()), "--max-sessions-per-client", "5"]
    args += ["--max-connections-per-client", "7", "--max-computations-per-client", "3"]
    result = CliRunner().invoke(cli, args)
    assert result.exit_code == 0, result.output
    (config,) = ran
    assert config.http.max_per_client == 7  # type: ignore[union-attr]
    room = config.app.state.room  # type: ignore[union-attr]
    assert (room.per_client, room.computations) == (5, 3)
    bad = CliRunner().invoke(cli, ["serve", "--max-connections-per-client", "0"])
    assert bad.exit_code != 0 and "--max-connections-per-client" in bad.output


def test_pendulab_serve_trusts_proxy_headers_only_when_told(monkeypatch: pytest.MonkeyPatch) -> None:
    ran = _serve_configs(monkeypatch)
    base = ["serve", "--no-browser", "--port", str(_free_port())]
    assert CliRunner().invoke(cli, base).exit_code == 0
    assert CliRunner().invoke(cli, [*base, "--trust-proxy", "10.0.0.2, fd00::/8"]).exit_code == 0
    off, on = ran
    assert off.proxy_headers is False
    assert on.proxy_headers is True and on.forwarded_allow_ips == "10.0.0.2, fd00::/8"
    bad = CliRunner().invoke(cli, [*base, "--trust-proxy", "proxy.example"])
    assert bad.exit_code == 2 and "--trust-proxy: 'proxy.example' is not an IP address" in bad.output


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])
