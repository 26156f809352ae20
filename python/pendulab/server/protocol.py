"""The lab's wire protocol (docs/web.md): binary state frames out, JSON commands in, JSON notices out.

**Frames** (server → page): every binary WebSocket message holds one or more *records* of
:data:`FRAME_FIELDS` as little-endian float64 — ``[t, x1, x2, x3, v1, v2, v3, energy, j3, tension,
power, a1, a2, a3, pivot1, pivot2, pivot3, taut, error_x]`` in s, m, m/s, J, kg m²/s, N, W, m/s², m, 1,
m (152 bytes each; ``error_x``: the global position error, −1 while unknown, docs/web.md "Error
estimate"). The layout is read from ``frame.json`` beside this file, which the page's
``web/src/protocol/frames.ts`` imports too, so the two cannot disagree.

**Commands** (page → server): one JSON object per text message, told apart by ``"type"``
(a pydantic discriminated union, :data:`COMMAND`): ``set_params``, ``set_model``, ``set_state``,
``set_method``, ``set_time_scale``, ``pause``, ``resume``, ``step``, ``reset``, ``load_scenario``,
``crane``.
Unknown keys, wrong types, NaN/inf and out-of-range values are refused with an ``error`` notice naming
the problem.

**Notices** (server → page, JSON text): ``{"type": "status", …}`` after every change (see
:meth:`pendulab.server.session.Session.status`), ``{"type": "error", "message": …, "command": …}`` and,
for the string, ``{"type": "event", "kind": "slack" | "taut", "t": …, "energy_lost": …, "x": […],
"epoch": …, "skipped": …}`` for each leave and snap (:func:`event_notice`).

The frames are here; the commands are :mod:`.commands`, the notices and message keys :mod:`.notices`.
This module names them all, so ``from pendulab.server.protocol import …`` reaches the whole protocol.
"""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from .commands import (
    COMMAND,
    COMMAND_TYPES,
    COMMON_PARAMS,
    CORE_LIMITS,
    LIMITS,
    MAX_MESSAGE_BYTES,
    MODEL_SPECS,
    OFFLINE_MODELS,
    Command,
    Crane,
    ExactRequest,
    LoadScenario,
    Pause,
    Reset,
    Resume,
    SetMethod,
    SetModel,
    SetParams,
    SetState,
    SetTimeScale,
    StateSpec,
    Step,
    own_params,
    parse_command,
)
from .notices import (
    MESSAGES,
    CommandError,
    error_notice,
    error_notice_of,
    event_notice,
    finite_or_none,
    keyed_notice,
    message,
    validation_key,
    validation_problems,
)

__all__ = [
    "COMMAND",
    "COMMAND_TYPES",
    "COMMON_PARAMS",
    "CORE_LIMITS",
    "FRAME_FIELDS",
    "FRAME_UNITS",
    "LIMITS",
    "MAX_MESSAGE_BYTES",
    "MESSAGES",
    "MODEL_SPECS",
    "OFFLINE_MODELS",
    "RECORD_BYTES",
    "RECORD_LEN",
    "Command",
    "CommandError",
    "Crane",
    "ExactRequest",
    "LoadScenario",
    "Pause",
    "Reset",
    "Resume",
    "SetMethod",
    "SetModel",
    "SetParams",
    "SetState",
    "SetTimeScale",
    "StateSpec",
    "Step",
    "decode_records",
    "encode_records",
    "error_notice",
    "error_notice_of",
    "event_notice",
    "finite_or_none",
    "keyed_notice",
    "message",
    "own_params",
    "parse_command",
    "validation_key",
    "validation_problems",
]

_LAYOUT = json.loads((Path(__file__).with_name("frame.json")).read_text(encoding="utf-8"))
FRAME_FIELDS: tuple[str, ...] = tuple(_LAYOUT["fields"])
"""Names of the float64 values of one frame record, in wire order."""

FRAME_UNITS: tuple[str, ...] = tuple(_LAYOUT["units"])
"""SI unit of each value of :data:`FRAME_FIELDS`."""

RECORD_LEN = len(FRAME_FIELDS)
RECORD_BYTES = 8 * RECORD_LEN
_WIRE = np.dtype("<f8")


def encode_records(records: np.ndarray) -> bytes:
    """Records of shape (N, RECORD_LEN) (or one record) as the bytes of one binary message."""
    arr = np.asarray(records, dtype=np.float64).reshape(-1, RECORD_LEN)
    return arr.astype(_WIRE, copy=False).tobytes()


def decode_records(data: bytes) -> np.ndarray:
    """The inverse of :func:`encode_records`: an array (N, RECORD_LEN); ValueError on a bad length."""
    if len(data) == 0 or len(data) % RECORD_BYTES:
        raise ValueError(f"a frame message has a multiple of {RECORD_BYTES} bytes, got {len(data)}")
    return np.frombuffer(data, dtype=_WIRE).astype(np.float64).reshape(-1, RECORD_LEN)
