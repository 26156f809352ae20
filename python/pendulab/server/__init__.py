"""The lab's web server (``pendulab serve``): FastAPI + uvicorn, a WebSocket per client (docs/web.md).

Needs the ``lab`` extra (``pip install 'pendulab[lab]'``: fastapi, uvicorn, websockets); imported only
by ``pendulab serve`` and the tests, so the rest of the package works without it.

- :mod:`.protocol`: frame layout (``frame.json``), the JSON commands (pydantic), encoding.
- :mod:`.session`: one client's pendulum, stepper and pacing, free of I/O.
- :mod:`.app`: the FastAPI application (static front end, ``/ws``, ``/api/…``).
"""

from .app import create_app, exact_quantities, run_session, scenarios, schema
from .protocol import FRAME_FIELDS, FRAME_UNITS, RECORD_BYTES, decode_records, encode_records, parse_command
from .session import Session, Setup, resolve_scenario

__all__ = [
    "FRAME_FIELDS",
    "FRAME_UNITS",
    "RECORD_BYTES",
    "Session",
    "Setup",
    "create_app",
    "decode_records",
    "encode_records",
    "exact_quantities",
    "parse_command",
    "resolve_scenario",
    "run_session",
    "scenarios",
    "schema",
]
