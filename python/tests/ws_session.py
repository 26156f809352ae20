"""Helpers for the lab server's WebSocket tests (test_server_models.py, test_server_live_models.py):
read one message as a JSON notice or a batch of binary frame records, wait for a message that
matches, and match a status notice by its fields. Units as in the frames (SI)."""

from __future__ import annotations

import json
from typing import Any

from pendulab.server import decode_records


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
