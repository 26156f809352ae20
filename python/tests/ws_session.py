"""Helpers for the lab server's tests (test_server*.py): a TestClient that reaches the lab by a local
name, read one message as a JSON notice or a batch of binary frame records, wait for a message that
matches, and match a status notice by its fields. Units as in the frames (SI)."""

from __future__ import annotations

import asyncio
import contextlib
import json
import socket
import threading
import time
from collections.abc import Iterator
from typing import Any
from urllib.parse import urljoin

import uvicorn
from fastapi.testclient import TestClient
from websockets.sync.client import connect

from pendulab.server import decode_records
from pendulab.server.serving import server_config

LOCAL = "http://127.0.0.1"
"""The address the tests reach the lab by: the server answers only to this machine's names (docs/web.md,
"Security")."""


class LabClient(TestClient):
    """FastAPI's TestClient addressing the lab as http://127.0.0.1, its WebSockets as ws://127.0.0.1
    (TestClient's own default host, ``testserver``, is a foreign Host the lab refuses)."""

    def __init__(self, app: Any, **kwargs: Any) -> None:
        kwargs.setdefault("base_url", LOCAL)
        super().__init__(app, **kwargs)

    def websocket_connect(self, url: str, *args: Any, **kwargs: Any) -> Any:
        base = str(self.base_url).replace("http", "ws", 1)
        return super().websocket_connect(urljoin(base, url), *args, **kwargs)


def receive(ws: Any) -> tuple[str, Any]:
    """("json", notice) or ("frames", records) for the next message."""
    msg = ws.receive()
    if msg.get("text") is not None:
        return "json", json.loads(msg["text"])
    return "frames", decode_records(msg["bytes"])


def until(ws: Any, pred: Any, limit: int = 600) -> Any:
    """The first message value for which pred(kind, value) holds, within `limit` messages."""
    for _ in range(limit):
        kind, value = receive(ws)
        if pred(kind, value):
            return value
    raise AssertionError("message not received")


def status_with(**want: Any) -> Any:
    """A predicate: a status notice whose fields have the given values."""
    return lambda k, v: k == "json" and v["type"] == "status" and all(v[n] == w for n, w in want.items())


@contextlib.contextmanager
def live_lab(app: Any, header_timeout: float = 10.0, **config: Any) -> Iterator[int]:
    """``app`` under uvicorn (the lab's configuration, :func:`pendulab.server.serving.server_config`, with
    ``config``'s settings) on a free loopback port, in a thread; yields the port. Stopped (and joined) on
    exit."""
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    port = sock.getsockname()[1]
    server = uvicorn.Server(server_config(app, "127.0.0.1", port, header_timeout=header_timeout, **config))
    thread = threading.Thread(target=lambda: asyncio.run(server.serve(sockets=[sock])), daemon=True)
    thread.start()
    try:
        for _ in range(500):
            if server.started:
                break
            time.sleep(0.01)
        assert server.started, "the lab did not start"
        yield port
    finally:
        server.should_exit = True
        thread.join(10)
        sock.close()


def frame_gaps(port: int, seconds: float, commands: list[dict[str, Any]] | None = None) -> list[float]:
    """A well-behaved page: connects to the lab on ``port``, sends ``commands``, receives for ``seconds``
    and returns the wall-clock gaps [s] between its binary frame messages (a receive that waits longer
    than ``seconds`` counts as one gap of that length instead of hanging the test)."""
    gaps: list[float] = []
    with connect(f"ws://127.0.0.1:{port}/ws", open_timeout=seconds, proxy=None) as ws:
        for c in commands or []:
            ws.send(json.dumps(c))
        end = time.monotonic() + seconds
        last = None
        while (now := time.monotonic()) < end:
            try:
                msg = ws.recv(timeout=max(end - now, 0.01))
            except TimeoutError:
                gaps.append(time.monotonic() - (last or now))
                break
            if isinstance(msg, bytes):
                t = time.monotonic()
                if last is not None:
                    gaps.append(t - last)
                last = t
    return gaps
