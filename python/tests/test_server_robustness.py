"""The lab's server under many clients (docs/web.md): the connection limit, a flooding client does not
stall another one, a client that vanishes mid-stream frees its slot."""

from __future__ import annotations

import threading
import time
from typing import Any

from ws_session import LabClient, receive, until

from pendulab.server import create_app


def frames(k: str, v: Any) -> bool:
    return k == "frames"


def _once_a_slot_frees(c: LabClient) -> dict[str, Any]:
    """A new page's first message, tried again until it is a status (at most 100 times, 0.05 s apart):
    the slot of a session that ended frees once the server notices."""
    for _ in range(100):
        with c.websocket_connect("/ws") as ws:
            _, msg = receive(ws)
            if msg["type"] == "status":
                break
        time.sleep(0.05)
    return msg


def test_one_client_too_many_is_refused_clearly_and_a_slot_frees_when_one_leaves() -> None:
    with LabClient(create_app("rosette", max_sessions=1)) as c:
        with c.websocket_connect("/ws") as ws1:
            until(ws1, frames)
            with c.websocket_connect("/ws") as ws2:
                kind, msg = receive(ws2)
                assert kind == "json" and msg["type"] == "error" and "server is full" in msg["message"]
                assert "--max-sessions 1" in msg["message"]
                closed = ws2.receive()
                assert closed["type"] == "websocket.close" and closed["code"] == 1013
        assert _once_a_slot_frees(c)["type"] == "status"  # the first session's, once the server notices


def test_a_flooding_client_does_not_stall_another() -> None:
    c = LabClient(create_app("rosette"))
    with c, c.websocket_connect("/ws") as flood, c.websocket_connect("/ws") as calm:
        until(calm, frames)
        stop = threading.Event()
        sent = 0

        def spam() -> None:
            nonlocal sent
            while not stop.is_set():
                flood.send_text('{"type": "set_time_scale", "time_scale": 1.0}')
                sent += 1
                if sent % 50 == 0:
                    time.sleep(0.01)  # hundreds per second, and the test thread still runs

        spammer = threading.Thread(target=spam)
        spammer.start()
        try:
            t_start, wall_start = until(calm, frames)[-1, 0], time.monotonic()
            while time.monotonic() - wall_start < 2.0:
                t_end = until(calm, frames)[-1, 0]
            wall = time.monotonic() - wall_start
        finally:
            stop.set()
            spammer.join()
    rate = sent / wall
    assert rate > 300, f"the test sent only {rate:.0f} commands/s"
    ratio = (t_end - t_start) / wall
    assert ratio > 0.5, f"the calm client got {ratio:.2f} simulated s per s while the other sent {rate:.0f}/s"


def test_a_client_vanishing_mid_stream_leaves_the_others_streaming_and_frees_its_slot() -> None:
    c = LabClient(create_app("rosette", max_sessions=2))
    with c, c.websocket_connect("/ws") as steady:
        until(steady, frames)
        with c.websocket_connect("/ws") as gone:
            ws_frames = [until(gone, frames) for _ in range(3)]  # streaming …
            assert ws_frames[-1][-1, 0] > ws_frames[0][0, 0]
        # … and gone without a word; the other session goes on
        t0 = until(steady, frames)[-1, 0]
        for _ in range(20):
            t1 = until(steady, frames)[-1, 0]
        assert t1 > t0
        # its slot is free again: a new page gets a status, not "server is full"
        assert _once_a_slot_frees(c)["type"] == "status"
