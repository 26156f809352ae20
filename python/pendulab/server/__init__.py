"""The lab's web server (``pendulab serve``): FastAPI + uvicorn, a WebSocket per client (docs/web.md).

Needs the ``lab`` extra (``pip install 'pendulab[lab]'``: fastapi, uvicorn, websockets); imported only
by ``pendulab serve`` and the tests, so the rest of the package works without it.

- :mod:`.protocol`: frame layout (``frame.json``), the JSON commands (pydantic), encoding.
- :mod:`.session`: one client's lab: the core's live session (``pendulab._core.LiveSession``: pendulum,
  stepper, pacing, frames and their error estimate), free of I/O.
- :mod:`.scenarios`: the scenarios a session starts from (examples by name, a file, built in).
- :mod:`.schema`: ``/api/schema`` (the registry's models and parameters, slider spans).
- :mod:`.rest`: the computing endpoints (exact solution, V_eff, scenario as TOML).
- :mod:`.app`: the FastAPI application (static front end, ``/ws``, ``/api/…``); :mod:`.live_socket`
  admits and serves the WebSocket of each client.
"""

from .app import create_app, scenarios
from .live_socket import run_session
from .protocol import FRAME_FIELDS, FRAME_UNITS, RECORD_BYTES, decode_records, encode_records, parse_command
from .rest import effective_potential, exact_quantities, scenario_toml
from .schema import schema
from .session import Session, Setup, resolve_scenario

__all__ = [
    "FRAME_FIELDS",
    "FRAME_UNITS",
    "RECORD_BYTES",
    "Session",
    "Setup",
    "create_app",
    "decode_records",
    "effective_potential",
    "encode_records",
    "exact_quantities",
    "parse_command",
    "resolve_scenario",
    "run_session",
    "scenario_toml",
    "scenarios",
    "schema",
]
