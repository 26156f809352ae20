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
- ``GET /api/schema``: every model's parameters (units, limits, defaults), controls, methods, frames.
- ``GET /api/scenarios``: the example scenarios (model, pendulum, start, method, dt).
- ``POST /api/exact``: the exact-solution quantities of a state (kind, turning heights, periods, phases).
- ``POST /api/effective_potential``: V_eff(θ) for l, m, g, J₃.
- ``POST /api/scenario.toml``: a session's scenario as a TOML file for ``pendulab run``.
- ``POST /api/reduced``, ``POST /api/em_map``: the reduced view (σ-space) and the energy–momentum map.

At most ``max_sessions`` clients are served at once (:data:`MAX_SESSIONS`); one more is refused.
"""

from __future__ import annotations

import contextlib
import logging
from collections import deque
from pathlib import Path
from typing import Any, TypeVar

import anyio
from fastapi import FastAPI, Request, WebSocket, WebSocketDisconnect
from fastapi.responses import HTMLResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel, ValidationError

from .._core import IntegrationError, InvalidInputError, __version__
from ..scenario import ScenarioError, load_scenario
from .protocol import (
    CommandError,
    ExactRequest,
    encode_records,
    error_notice,
    parse_command,
    validation_problems,
)
from .rest import (
    PotentialRequest,
    ScenarioRequest,
    effective_potential,
    exact_quantities,
    scenario_toml,
)
from .schema import TICK_HZ, schema
from .session import Session, Setup, example_resolver, model_params, resolve_scenario, scenario_files
from .views import EMRequest, ReducedRequest, em_view, reduced_view

MAX_PENDING = 64
"""Most commands waiting for the next tick; more are dropped (throttling)."""

MAX_PER_TICK = 32
"""Most commands applied per tick."""

MAX_SESSIONS = 16
"""Default for the most lab sessions (WebSockets) at once; more are refused with an error notice."""

STATIC_DIR = Path(__file__).with_name("static")

log = logging.getLogger("pendulab.server")

M = TypeVar("M", bound=BaseModel)

_NOT_BUILT = """<!doctype html><meta charset="utf-8"><title>Pendulab lab</title>
<p>The lab's front end is not built into this package (no <code>static/index.html</code>).
From a source checkout run <code>make web</code> (needs Node 20 and npm), then reload.
The API is up: <a href="/api/schema">/api/schema</a>.</p>"""


def _describe(setup: Setup) -> dict[str, Any]:
    p = setup.pendulum
    return {
        "name": setup.name,
        "title": setup.title,
        "params": {"length": p.length, "mass": p.mass, "g": p.g},
        "model": p.model,
        "model_params": model_params(p),
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


async def _body(request: Request, kind: type[M]) -> M | JSONResponse:
    """The request's JSON body validated as ``kind``, or the HTTP 422 answer naming every problem."""
    try:
        body = await request.json()
    except ValueError as e:
        return JSONResponse({"detail": f"the body is not JSON: {e}"}, status_code=422)
    try:
        return kind.model_validate(body)
    except ValidationError as e:
        return JSONResponse({"detail": validation_problems(e, skip=0)}, status_code=422)


def _unprocessable(e: Exception) -> JSONResponse:
    return JSONResponse({"detail": " ".join(str(e).split())}, status_code=422)


def create_app(
    scenario: str | Path | None = None, *, static_dir: Path | None = None, max_sessions: int = MAX_SESSIONS
) -> FastAPI:
    """The lab application; every client starts with ``scenario`` (an example name or a file; default
    ``rosette``). At most ``max_sessions`` WebSockets are served at once: one more gets an ``error``
    notice saying so and is closed (code 1013, try again later). Raises :class:`pendulab.ScenarioError`
    for a bad scenario."""
    default = resolve_scenario(scenario)
    resolve = example_resolver(default)
    static = STATIC_DIR if static_dir is None else static_dir
    app = FastAPI(title="Pendulab lab", version=__version__, docs_url="/api/docs", redoc_url=None)
    active = 0

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
        req = await _body(request, ExactRequest)
        if isinstance(req, JSONResponse):
            return req
        try:
            return JSONResponse(exact_quantities(req))
        except (InvalidInputError, IntegrationError) as e:
            return _unprocessable(e)

    @app.post("/api/effective_potential")
    async def post_potential(request: Request) -> JSONResponse:
        req = await _body(request, PotentialRequest)
        if isinstance(req, JSONResponse):
            return req
        return JSONResponse(effective_potential(req))

    @app.post("/api/reduced")
    async def post_reduced(request: Request) -> JSONResponse:
        req = await _body(request, ReducedRequest)
        if isinstance(req, JSONResponse):
            return req
        try:
            return JSONResponse(reduced_view(req))
        except (InvalidInputError, IntegrationError) as e:
            return _unprocessable(e)

    @app.post("/api/em_map")
    async def post_em_map(request: Request) -> JSONResponse:
        req = await _body(request, EMRequest)
        if isinstance(req, JSONResponse):
            return req
        try:
            return JSONResponse(em_view(req))
        except (InvalidInputError, IntegrationError) as e:
            return _unprocessable(e)

    @app.post("/api/scenario.toml")
    async def post_scenario(request: Request) -> Response:
        req = await _body(request, ScenarioRequest)
        if isinstance(req, JSONResponse):
            return req
        try:
            text = scenario_toml(req)
        except (ScenarioError, InvalidInputError) as e:
            return _unprocessable(e)
        return Response(
            text,
            media_type="application/toml; charset=utf-8",
            headers={"content-disposition": 'attachment; filename="pendulab-scenario.toml"'},
        )

    @app.websocket("/ws")
    async def websocket(ws: WebSocket) -> None:
        nonlocal active
        await ws.accept()
        if active >= max_sessions:
            message = (
                f"the server is full: {active} lab sessions are open, the most it serves at once "
                f"(pendulab serve --max-sessions {max_sessions}); close another tab or try again later"
            )
            with contextlib.suppress(WebSocketDisconnect, OSError, RuntimeError):
                await ws.send_json(error_notice(message))
                await ws.close(code=1013, reason="server full")
            return
        active += 1
        try:
            await run_session(ws, Session(default, resolve))
        finally:
            active -= 1

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
            for notice in session.take_event_notices():  # the string's leaves and snaps, after their frames
                await ws.send_json(notice)
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
