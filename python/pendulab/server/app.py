"""The lab's web server: the built front end, a WebSocket per client, and REST endpoints (docs/web.md).

``create_app(scenario)`` builds the FastAPI application; ``pendulab serve`` runs it with uvicorn.

- ``GET /`` and ``/assets/…``: the front end built from ``web/`` (``make web`` copies it into
  ``static/`` beside this file; it is committed, so a user with only the Python package needs no Node).
- ``WS /ws``: one :class:`~pendulab.server.session.Session` per client, seated in the room's ticker
  (:mod:`.ticker`), admitted and served by :mod:`.live_socket`.
- ``GET /api/schema``: every model's parameters (units, limits, defaults), controls, methods, frames.
- ``GET /api/scenarios``: the example scenarios (model, pendulum, start, method, dt).
- ``POST /api/exact``: the exact-solution quantities of a state (kind, turning heights, periods, phases).
- ``POST /api/effective_potential``: V_eff(θ) for l, m, g, J₃.
- ``POST /api/scenario.toml``: a session's scenario as a TOML file for ``pendulab run``.
- ``POST /api/reduced``, ``POST /api/em_map``: the reduced view (σ-space) and the energy–momentum map.
- ``POST /api/fit``: a measured data file fitted (:mod:`.fit`): report, parameters ± errors, the fitted
  scenario and the measured path.

At most ``max_sessions`` clients are served at once (:data:`MAX_SESSIONS`), at most
``max_sessions_per_client`` of one device; one more is refused. The room's stepping budget is shared
fairly between the clients (:mod:`.room`).

Every request first passes the access checks of :mod:`.access` (allowed ``Host`` names, same-origin
pages only, the classroom token) and the HTTP hygiene of :mod:`.hygiene` (security headers, JSON bodies
of at most 64 KiB, a data file for ``/api/fit`` of at most 2 MiB). The analyses (exact, reduced view,
EM map) run in a killable worker process with a wall-time limit (:data:`WORK_SECONDS`), the fits in
another (:mod:`.fit`, :mod:`.worker`), the quick endpoints (V_eff, TOML) in a bounded thread pool
(:data:`REST_THREADS`): never in the event loop, and nothing a request runs can hold the server. One
client may have at most two computations under way (HTTP 429 beyond). ``GET /api/schema`` and
``/api/scenarios`` are computed once. ``GET /api/docs`` is a self-contained page (:mod:`.api_docs`,
no CDN).
"""

from __future__ import annotations

import functools
import logging
import weakref
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, TypeVar

import anyio
import orjson
from fastapi import FastAPI, Request, WebSocket
from fastapi.responses import HTMLResponse, JSONResponse, Response
from fastapi.staticfiles import StaticFiles
from pydantic import BaseModel, ValidationError

from .._core import InvalidInputError, __version__
from ..scenario import ScenarioError, load_scenario
from .access import LOOPBACK_HOSTS, guard
from .api_docs import api_docs_page
from .fit import (
    FIT_OPENAPI,
    FIT_QUEUE,
    FIT_SECONDS,
    FIT_WORKERS,
    MAX_FIT_BODY,
    check_fit_time_limit,
    fit_endpoint,
    fit_wall_seconds,
)
from .hygiene import RequestBodies, SecurityHeaders
from .live_socket import admit, loop_limiter, run_session
from .notices import keyed_body
from .protocol import (
    ExactRequest,
    validation_key,
    validation_problems,
)
from .rest import (
    PotentialRequest,
    ScenarioRequest,
    effective_potential,
    exact_quantities,
    scenario_toml,
)
from .room import MAX_REQUESTS_PER_CLIENT, MAX_SESSIONS_PER_CLIENT, Room, client_key
from .schema import schema
from .session import Session, Setup, describe, example_resolver, resolve_scenario, scenario_files
from .views import EMRequest, ReducedRequest, em_view, reduced_view
from .worker import Busy, WorkerPool, WorkFailed, WorkInvalid, WorkTimeout, shared_pool

MAX_SESSIONS = 64
"""Default for the most lab sessions (WebSockets) at once (a class of 30 with a second tab each); more
are refused with an error notice."""

REST_THREADS = 1
"""Worker threads of the quick POST endpoints (V_eff, TOML: bounded work); at most this many run at
once (the machine's cores are shared with the live sessions); the rest wait."""

REST_QUEUE = 32
"""Most requests waiting for a worker (thread or process); more are answered 503 (busy, try again)."""

WORK_WORKERS = 1
"""Worker processes of the analyses (exact solution, reduced view, EM map: :mod:`.worker`)."""

WORK_SECONDS = 10.0
"""Most wall-time seconds of one analysis in its worker; past it the worker is killed and the page
told (HTTP 503)."""

STATIC_DIR = Path(__file__).with_name("static")

log = logging.getLogger("pendulab.server")

M = TypeVar("M", bound=BaseModel)
R = TypeVar("R")

_NOT_BUILT = """<!doctype html><meta charset="utf-8"><title>Pendulab lab</title>
<p>The lab's front end is not built into this package (no <code>static/index.html</code>).
From a source checkout run <code>make web</code> (needs Node 20 and npm), then reload.
The API is up: <a href="/api/schema">/api/schema</a>.</p>"""


def scenarios() -> list[dict[str, Any]]:
    """The example scenarios, each with its pendulum, start (x, v), method and dt; an invalid file is
    listed with ``error`` set instead."""
    out: list[dict[str, Any]] = []
    for name, path in scenario_files().items():
        try:
            # a crane file opens the crane mode with its crane (docs/cranes.md, "The lab's crane mode")
            out.append(describe(Setup.from_scenario(load_scenario(path), name)))
        except (ScenarioError, OSError) as e:
            out.append({"name": name, "error": " ".join(str(e).split())})
    return out


async def _body(request: Request, kind: type[M]) -> M | JSONResponse:
    """The request's JSON body validated as ``kind``, or the HTTP 422 answer naming every problem."""
    try:
        body = await request.json()
    except (ValueError, RecursionError) as e:  # RecursionError: nested too deeply
        return JSONResponse(
            {"detail": f"the body is not JSON: {str(e)[:200]}", "key": "not_json", "values": {}},
            status_code=422,
        )
    try:
        return kind.model_validate(body)
    except ValidationError as e:
        key, values = validation_key(e)
        keyed = {"key": key, "values": values} if key is not None else {}
        return JSONResponse({"detail": validation_problems(e, skip=0), **keyed}, status_code=422)


def _unprocessable(e: Exception) -> JSONResponse:
    """HTTP 422 with the refusal's English words; keyed (``messages.json``) when the refusal is."""
    body: dict[str, Any] = {"detail": " ".join(str(e).split())}
    key, values = getattr(e, "key", None), getattr(e, "values", None)
    if isinstance(key, str) and isinstance(values, dict):
        body |= {"key": key, "values": values}
    return JSONResponse(body, status_code=422)


class _Busy(Exception):
    pass


def _json(fn: Callable[..., Any], *args: Any) -> Response:
    """``fn(*args)`` as a JSON response, rendered where it is computed (a worker thread) with orjson: the
    reduced view's largest answer (0.5 MB of numbers) takes 64 ms with the standard library, which
    holds the GIL and so starves the event loop even from another thread, and 1 ms with orjson."""
    return Response(orjson.dumps(fn(*args)), media_type="application/json")


async def _compute(
    limiters: weakref.WeakKeyDictionary[Any, anyio.CapacityLimiter], fn: Callable[..., R], *args: Any
) -> R:
    """``fn(*args)`` in one of the REST worker threads; :class:`_Busy` when too many already wait."""
    limiter = loop_limiter(limiters, REST_THREADS)
    if limiter.available_tokens == 0 and limiter.statistics().tasks_waiting >= REST_QUEUE:
        raise _Busy
    return await anyio.to_thread.run_sync(functools.partial(fn, *args), limiter=limiter)


def create_app(
    scenario: str | Path | None = None,
    *,
    static_dir: Path | None = None,
    max_sessions: int = MAX_SESSIONS,
    allowed_hosts: Sequence[str] = LOOPBACK_HOSTS,
    token: str | None = None,
    max_sessions_per_client: int = MAX_SESSIONS_PER_CLIENT,
    max_computations_per_client: int = MAX_REQUESTS_PER_CLIENT,
    work_seconds: float = WORK_SECONDS,
    fit_seconds: float | None = None,
    fit_time_limit: float = FIT_SECONDS,
) -> FastAPI:
    """The lab application; every client starts with ``scenario`` (an example name or a file; default
    ``rosette``). At most ``max_sessions`` WebSockets are served at once: one more gets an ``error``
    notice saying so and is closed (code 1013, try again later). Only requests whose ``Host`` is one of
    ``allowed_hosts`` are served (default: the loopback names; :func:`pendulab.server.access.allowed_hosts`
    for another address), only the lab's own page may open ``/ws`` or POST, and with ``token`` every
    request must carry it (classroom mode, :mod:`.access`). One client (address, a global IPv6 one's /64:
    :mod:`.room`) may hold ``max_sessions_per_client`` WebSockets and have
    ``max_computations_per_client`` computing requests under way or waiting (one more: 429, key
    ``device_busy``). A fit (``POST /api/fit``) is given ``fit_time_limit`` [s] (> 0, at most
    :data:`~pendulab.server.fit.MAX_FIT_SECONDS`: else ``ValueError``), its request ``fit_seconds`` of
    wall time in its worker (default :func:`~pendulab.server.fit.fit_wall_seconds` of the limit; the
    fit then gets at most half of it). Raises :class:`pendulab.ScenarioError` for a bad scenario."""
    fit_time_limit = check_fit_time_limit(fit_time_limit)
    default = resolve_scenario(scenario)
    app = FastAPI(title="Pendulab lab", version=__version__, docs_url=None, redoc_url=None)
    app.add_middleware(RequestBodies, larger={"/api/fit": MAX_FIT_BODY})
    app.add_middleware(guard_middleware, hosts=list(allowed_hosts), token=token)
    app.add_middleware(SecurityHeaders)
    room = Room(max_sessions_per_client, computations=max_computations_per_client)
    analyses = shared_pool("analysis", WORK_WORKERS, REST_QUEUE, work_seconds)
    wall = fit_wall_seconds(fit_time_limit) if fit_seconds is None else fit_seconds
    fits = shared_pool("fit", FIT_WORKERS, FIT_QUEUE, wall)
    app.state.room, app.state.pools, app.state.fit_time_limit = room, (analyses, fits), fit_time_limit
    _add_error_handlers(app)
    _add_gets(app, default)
    _add_posts(app, room, analyses)
    post_fit = fit_endpoint(fits, room, fit_time_limit)
    app.add_api_route("/api/fit", post_fit, methods=["POST"], openapi_extra=FIT_OPENAPI)
    _add_websocket(app, default, max_sessions, room)
    _add_front_end(app, STATIC_DIR if static_dir is None else static_dir)
    return app


def _add_error_handlers(app: FastAPI) -> None:
    """The answers to a full worker queue (503), a failed computation (500, logged) and a full thread
    queue (503)."""

    @app.exception_handler(Busy)
    async def busy_pool(request: Request, exc: Busy) -> JSONResponse:
        return JSONResponse(
            keyed_body("busy", waiting=exc.waiting), status_code=503, headers={"retry-after": "1"}
        )

    @app.exception_handler(WorkFailed)
    async def failed(request: Request, exc: WorkFailed) -> JSONResponse:
        log.error("a computation failed: %s", exc)
        if exc.key is not None:  # the worker died: said in the page's language
            return JSONResponse({"detail": str(exc), "key": exc.key, "values": exc.values}, status_code=500)
        return JSONResponse(keyed_body("internal_error", detail=str(exc)), status_code=500)

    @app.exception_handler(_Busy)
    async def busy(request: Request, exc: _Busy) -> JSONResponse:
        return JSONResponse(
            keyed_body("busy", waiting=REST_QUEUE), status_code=503, headers={"retry-after": "1"}
        )


def _add_gets(app: FastAPI, default: Setup) -> None:
    """``GET /api/docs``, ``/api/schema`` and ``/api/scenarios``: the last two computed once per app
    (the schema and the examples do not change while the server runs: a flood of GETs costs no
    computing)."""
    cached: dict[str, bytes] = {}

    def once(name: str, make: Callable[[], Any]) -> Response:
        if name not in cached:
            cached[name] = orjson.dumps(make())
        return Response(cached[name], media_type="application/json")

    @app.get("/api/docs", response_class=HTMLResponse, include_in_schema=False)
    def api_docs() -> HTMLResponse:
        return HTMLResponse(api_docs_page(app.openapi()))

    def listed_scenarios() -> list[dict[str, Any]]:
        listed = scenarios()
        if default.name not in {s["name"] for s in listed}:  # a file given to `pendulab serve`
            listed.insert(0, describe(default))
        return listed

    @app.get("/api/schema")
    def get_schema() -> Response:
        return once("schema", schema)

    @app.get("/api/scenarios")
    def get_scenarios() -> Response:
        return once("scenarios", listed_scenarios)


def _add_posts(app: FastAPI, room: Room, analyses: WorkerPool) -> None:
    """The POST analyses (exact, V_eff, reduced view, EM map) and ``POST /api/scenario.toml``."""
    rest_limiters: weakref.WeakKeyDictionary[Any, anyio.CapacityLimiter] = weakref.WeakKeyDictionary()

    async def analysis(request: Request, fn: Callable[..., Any], req: BaseModel) -> Response:
        """``fn(req)`` in the analysis worker process, as JSON; 422/429/503 as the module doc says."""
        async with room.request(client_key(request.scope)) as allowed:
            if not allowed:
                return JSONResponse(room.too_many_requests(), status_code=429, headers={"retry-after": "1"})
            try:
                return Response(await analyses.run(fn, req), media_type="application/json")
            except WorkTimeout as e:
                return JSONResponse(keyed_body("work_timeout", seconds=f"{e.seconds:g}"), status_code=503)
            except WorkInvalid as e:
                return _unprocessable(e)

    def post_route(
        path: str, name: str, kind: type[M], fn: Callable[[M], Any], *, worker: bool = True
    ) -> None:
        """POST ``path``, the request boilerplate named once: the body read and checked as ``kind`` (422
        naming the problem), then ``fn(body)`` as JSON — in the analysis worker process (``worker``:
        429/503 as the module doc says) or, for a quick answer, on a thread of this process."""

        async def endpoint(request: Request) -> Response:
            req = await _body(request, kind)
            if isinstance(req, JSONResponse):
                return req
            if worker:
                return await analysis(request, fn, req)
            return await _compute(rest_limiters, _json, fn, req)

        app.add_api_route(path, endpoint, methods=["POST"], name=name)

    post_route("/api/exact", "post_exact", ExactRequest, exact_quantities)
    post_route(
        "/api/effective_potential", "post_potential", PotentialRequest, effective_potential, worker=False
    )
    post_route("/api/reduced", "post_reduced", ReducedRequest, reduced_view)
    post_route("/api/em_map", "post_em_map", EMRequest, em_view)

    @app.post("/api/scenario.toml")
    async def post_scenario(request: Request) -> Response:
        req = await _body(request, ScenarioRequest)
        if isinstance(req, JSONResponse):
            return req
        try:
            text = await _compute(rest_limiters, scenario_toml, req)
        except (ScenarioError, InvalidInputError) as e:
            return _unprocessable(e)
        return Response(
            text,
            media_type="application/toml; charset=utf-8",
            headers={"content-disposition": 'attachment; filename="pendulab-scenario.toml"'},
        )


def _add_websocket(app: FastAPI, default: Setup, max_sessions: int, room: Room) -> None:
    """``WS /ws``: each client's session from ``default``, admitted and served by :mod:`.live_socket`."""
    resolve = example_resolver(default)
    active = 0

    @app.websocket("/ws")
    async def websocket(ws: WebSocket) -> None:
        nonlocal active
        key = await admit(ws, active, max_sessions, room)
        if key is None:
            return
        active += 1
        try:
            await run_session(ws, Session(default, resolve), share=lambda: room.share(key))
        finally:
            active -= 1
            room.close_session(key)


def _add_front_end(app: FastAPI, static: Path) -> None:
    """The built front end at ``/``, or a page saying how to build it."""
    if (static / "index.html").is_file():
        app.mount("/", StaticFiles(directory=static, html=True), name="static")
        return

    @app.get("/", response_class=HTMLResponse)
    def not_built() -> HTMLResponse:
        return HTMLResponse(_NOT_BUILT, status_code=503)


def guard_middleware(app: Any, hosts: list[str], token: str | None) -> Any:
    """The access checks of :mod:`.access` as one middleware (for ``app.add_middleware``)."""
    return guard(app, hosts, token)
