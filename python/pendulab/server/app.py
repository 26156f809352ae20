"""The lab's web server: the built front end, a WebSocket per client, and REST endpoints (docs/web.md).

``create_app(scenario)`` builds the FastAPI application; ``pendulab serve`` runs it with uvicorn.

- ``GET /`` and ``/assets/…``: the front end built from ``web/`` (``make web`` copies it into
  ``static/`` beside this file; it is committed, so a user with only the Python package needs no Node).
- ``WS /ws``: one :class:`~pendulab.server.session.Session` per client. The handler runs two tasks:
  one reads and validates commands into a bounded inbox (a client that floods is throttled: beyond
  :data:`MAX_PENDING` waiting commands the rest are dropped with an error notice), the other ticks at
  :data:`TICK_HZ`, applies waiting commands, advances the stepper to wall clock × time scale and sends
  the frames. Only the ticker writes to the socket and touches the session. A client vanishing mid-
  stream ends its own tasks only.
- ``GET /api/schema``: model parameters (units, limits, defaults), controls, methods, frame layout.
- ``GET /api/scenarios``: the example scenarios (pendulum, start, method, dt).
- ``POST /api/exact``: the exact-solution quantities of a state (kind, turning heights, periods, phases).
"""

from __future__ import annotations

import contextlib
import logging
from collections import deque
from pathlib import Path
from typing import Any

import anyio
from fastapi import FastAPI, Request, WebSocket, WebSocketDisconnect
from fastapi.responses import HTMLResponse, JSONResponse
from fastapi.staticfiles import StaticFiles
from pydantic import ValidationError

from .. import _core
from ..scenario import ScenarioError, load_scenario
from ..simulate import methods
from .protocol import (
    COMMAND_TYPES,
    FRAME_FIELDS,
    FRAME_UNITS,
    LIMITS,
    RECORD_BYTES,
    CommandError,
    ExactRequest,
    encode_records,
    error_notice,
    finite_or_none,
    parse_command,
    validation_problems,
)
from .session import Session, Setup, example_resolver, resolve_scenario, scenario_files

TICK_HZ = 60.0
"""Frames per second sent to each client while running."""

MAX_PENDING = 64
"""Most commands waiting for the next tick; more are dropped (throttling)."""

MAX_PER_TICK = 32
"""Most commands applied per tick."""

STATIC_DIR = Path(__file__).with_name("static")

log = logging.getLogger("pendulab.server")

_NOT_BUILT = """<!doctype html><meta charset="utf-8"><title>Pendulab lab</title>
<p>The lab's front end is not built into this package (no <code>static/index.html</code>).
From a source checkout run <code>make web</code> (needs Node 20 and npm), then reload.
The API is up: <a href="/api/schema">/api/schema</a>.</p>"""


def schema() -> dict[str, Any]:
    """What the page builds its controls from: parameters with units and limits, methods, frame layout."""
    ideal = next(m for m in _core.models() if m["name"] == "ideal")
    params = []
    for p in ideal["params"]:
        lim = LIMITS[p["name"]]
        params.append(
            {
                "name": p["name"],
                "unit": p["unit"],
                "description": p["description"],
                "default": p["default"],
                "min": lim["min"],
                "max": lim["max"],
                "ui_min": lim["ui_min"],
                "ui_max": lim["ui_max"],
                "step": lim["step"],
            }
        )
    controls = {
        "dt": {"unit": "s", "description": "step size of fixed-step methods", **LIMITS["dt"]},
        "time_scale": {"unit": "1", "description": "simulated seconds per second", **LIMITS["time_scale"]},
        "step_n": {"unit": "steps", "description": "steps taken by one 'step' command", **LIMITS["step_n"]},
    }
    return {
        "version": _core.__version__,
        "model": {"name": ideal["name"], "summary": ideal["summary"], "params": params},
        "controls": controls,
        "methods": [dict(m) for m in methods()],
        "frame": {
            "fields": list(FRAME_FIELDS),
            "units": list(FRAME_UNITS),
            "dtype": "float64",
            "byte_order": "little",
            "record_bytes": RECORD_BYTES,
        },
        "commands": list(COMMAND_TYPES),
        "tick_hz": TICK_HZ,
    }


def _describe(setup: Setup) -> dict[str, Any]:
    p = setup.pendulum
    return {
        "name": setup.name,
        "title": setup.title,
        "params": {"length": p.length, "mass": p.mass, "g": p.g},
        "start": {"x": [float(c) for c in setup.state.x], "v": [float(c) for c in setup.state.v]},
        "method": setup.method,
        "dt": setup.dt,
        "t0": setup.t0,
    }


def scenarios() -> list[dict[str, Any]]:
    """The example scenarios, each with its pendulum, start (x, v), method and dt; an invalid file is
    listed with ``error`` set instead."""
    out: list[dict[str, Any]] = []
    for name, path in scenario_files().items():
        try:
            out.append(_describe(Setup.from_scenario(load_scenario(path), name)))
        except (ScenarioError, OSError) as e:
            out.append({"name": name, "error": " ".join(str(e).split())})
    return out


def exact_quantities(req: ExactRequest) -> dict[str, Any]:
    """The exact-solution quantities of the orbit through a state (THEORY §4–5), JSON-ready.

    Infinite or undefined values (the separatrix's period, the advance of planar motion) are null.
    """
    from ..exact import exact
    from ..model import Pendulum

    p = Pendulum(length=req.length, g=req.g, mass=req.mass)
    state = req.to_state(p)
    sol = exact(p, state)
    phases: dict[str, float | None] | None
    try:
        ph = sol.phases()
        phases = {"total": ph.total, "dynamic": ph.dynamic, "geometric": ph.geometric}
        phases_note = None
    except _core.InvalidInputError as e:
        phases, phases_note = None, " ".join(str(e).split())
    return {
        "kind": sol.kind,
        "energy": p.energy(state),
        "j3": p.j3(state),
        "omega0": sol.omega0,
        "turning_heights": [finite_or_none(z) for z in sol.turning_heights],
        "modulus": finite_or_none(sol.modulus),
        "period_z": finite_or_none(sol.period_z),
        "period_z_infinite": sol.period_z is not None and sol.period_z == float("inf"),
        "azimuth_advance": finite_or_none(sol.azimuth_advance),
        "rotation_number": finite_or_none(sol.rotation_number),
        "phases": phases,
        "phases_note": phases_note,
    }


def create_app(scenario: str | Path | None = None, *, static_dir: Path | None = None) -> FastAPI:
    """The lab application; every client starts with ``scenario`` (an example name or a file; default
    ``rosette``). Raises :class:`pendulab.ScenarioError` for a bad scenario."""
    default = resolve_scenario(scenario)
    resolve = example_resolver(default)
    static = STATIC_DIR if static_dir is None else static_dir
    app = FastAPI(title="Pendulab lab", version=_core.__version__, docs_url="/api/docs", redoc_url=None)

    @app.get("/api/schema")
    def get_schema() -> dict[str, Any]:
        return schema()

    @app.get("/api/scenarios")
    def get_scenarios() -> list[dict[str, Any]]:
        listed = scenarios()
        if default.name not in {s["name"] for s in listed}:  # a file given to `pendulab serve`
            listed.insert(0, _describe(default))
        return listed

    @app.post("/api/exact")
    async def post_exact(request: Request) -> JSONResponse:
        try:
            body = await request.json()
        except ValueError as e:
            return JSONResponse({"detail": f"the body is not JSON: {e}"}, status_code=422)
        try:
            req = ExactRequest.model_validate(body)
        except ValidationError as e:
            return JSONResponse({"detail": validation_problems(e, skip=0)}, status_code=422)
        try:
            return JSONResponse(exact_quantities(req))
        except ImportError as e:  # pragma: no cover - the exact module ships with the package
            return JSONResponse({"detail": f"the exact solution is not available: {e}"}, status_code=501)
        except (_core.InvalidInputError, _core.IntegrationError) as e:
            return JSONResponse({"detail": " ".join(str(e).split())}, status_code=422)

    @app.websocket("/ws")
    async def websocket(ws: WebSocket) -> None:
        await ws.accept()
        await run_session(ws, Session(default, resolve))

    if (static / "index.html").is_file():
        app.mount("/", StaticFiles(directory=static, html=True), name="static")
    else:

        @app.get("/", response_class=HTMLResponse)
        def not_built() -> HTMLResponse:
            return HTMLResponse(_NOT_BUILT, status_code=503)

    return app


async def run_session(ws: WebSocket, session: Session, tick_hz: float = TICK_HZ) -> None:
    """Serves one client until it goes away (see the module doc)."""
    inbox: deque[Any] = deque()
    dropped = 0

    async def receive() -> None:
        nonlocal dropped
        while True:
            msg = await ws.receive()
            if msg["type"] == "websocket.disconnect":
                return
            text, data = msg.get("text"), msg.get("bytes")
            item: Any
            try:
                item = parse_command(text if text is not None else (data or b""))
            except CommandError as e:
                item = e
            if len(inbox) >= MAX_PENDING:
                dropped += 1
            else:
                inbox.append(item)

    async def tick() -> None:
        nonlocal dropped
        period = 1.0 / tick_hz
        await ws.send_json(session.status())
        await ws.send_bytes(encode_records(session.records()))
        last = next_tick = anyio.current_time()
        while True:
            next_tick += period
            delay = next_tick - anyio.current_time()
            if delay < 0:  # behind: do not try to catch up with a burst
                next_tick, delay = anyio.current_time(), 0.0
            await anyio.sleep(delay)
            now = anyio.current_time()
            elapsed, last = now - last, now
            changed, records = False, None
            for _ in range(min(len(inbox), MAX_PER_TICK)):
                item = inbox.popleft()
                if isinstance(item, CommandError):
                    await ws.send_json(error_notice(str(item), item.command))
                    continue
                changed = True
                try:
                    out = session.apply(item)
                except CommandError as e:
                    await ws.send_json(error_notice(str(e), e.command))
                    continue
                if out is not None:
                    records = out  # only the last discontinuity matters; the status below announces it
            if dropped:
                await ws.send_json(
                    error_notice(
                        f"throttled: {dropped} command(s) dropped (more than {MAX_PENDING} waiting); "
                        f"send at most {int(tick_hz * MAX_PER_TICK)} per second"
                    )
                )
                dropped = 0
            if changed:
                await ws.send_json(session.status())
            was_lagging = session.lagging
            try:
                advanced = session.advance(elapsed)
            except CommandError as e:
                await ws.send_json(error_notice(str(e)))
                await ws.send_json(session.status())
                advanced = None
            if records is not None:
                await ws.send_bytes(encode_records(records))
            if advanced is not None:
                await ws.send_bytes(encode_records(advanced))
            if session.lagging != was_lagging:
                await ws.send_json(session.status())

    async with anyio.create_task_group() as tg:

        async def reader() -> None:
            with contextlib.suppress(WebSocketDisconnect, OSError):
                await receive()
            tg.cancel_scope.cancel()  # the client is gone: stop ticking

        async def ticker() -> None:
            try:
                await tick()
            except (WebSocketDisconnect, OSError):
                pass  # sending to a client that went away
            except RuntimeError as e:  # starlette: sending after the socket closed
                if "close" not in str(e).lower() and "disconnect" not in str(e).lower():
                    raise
            except Exception as e:
                log.error("lab session failed", exc_info=e)
                with contextlib.suppress(Exception):
                    await ws.send_json(error_notice(f"internal error: {e}"))
                    await ws.close(code=1011)
            tg.cancel_scope.cancel()

        tg.start_soon(reader)
        tg.start_soon(ticker)
