"""``POST /api/fit``: a measured data file fitted in the lab (docs/fit.md, "In the lab"; docs/web.md).

The page sends the text of a CSV data file (the format of :mod:`pendulab.fitting.table`, which parses
it: t [s]; x, y, z [m]; theta, phi, angle [rad]; specific_force [m/s²]; angular_speed [rad/s]), the
model and the parameters to fit; :func:`fit_data` runs :func:`pendulab.fit` (T-10.1 … T-10.4 of
docs/theory.md) and answers with

- ``report``: the text of :meth:`pendulab.FitResult.report`, and the ``warnings`` the fit gave;
  ``notes`` and ``items``: the warnings and the report as message keys with values (:mod:`.fit_words`);
- ``params``: name → value, standard error (null where the data do not determine it), unit, and
  ``determined``; ``combinations`` what the data determine instead; ``blocks``: the block check of a
  misfit (:meth:`pendulab.fitting.blocks.BlockCheck.as_dict`: ``made``, ``stop`` (what stopped one not
  made), ``starts`` [s], ``scale`` per parameter (null: not made, so not measured and not widened),
  the blocks' ``values``, ``stderr``, ``units``) or null where none was due; ``chi2``, ``dof``, ``converged``;
- ``scenario_toml``: the fitted scenario (:meth:`pendulab.FitResult.to_scenario` as TOML) and
  ``lab``: the same scenario as the lab's scenarios are described (``GET /api/scenarios``), so that
  the page can load it into the running session;
- ``measured``: the measured path as bob positions relative to the FITTED pivot [m] (z up), at most
  :data:`PATH_POINTS` of them (evenly thinned), with their times [s] from the first sample (the
  fitted motion's t = 0). Positions (x, y, z) minus the fitted pivot; (x, z) seen along y get the
  fitted motion's y; angles (θ, φ) and a planar angle become points on the fitted sphere of radius
  l. Frame-free data (|a − g|, |ω|) have no path: ``measured`` is null.

Work is bounded: the body is at most :data:`MAX_FIT_BODY` (the server's body check, :mod:`.hygiene`), the
fits run one at a time in a killable worker process of their own (:mod:`.worker`; :data:`FIT_WORKERS`,
:data:`FIT_QUEUE`), each fit at most the server's time limit (:data:`FIT_SECONDS` unless ``pendulab
serve --fit-time-limit`` sets another, at most :data:`MAX_FIT_SECONDS`; then the best values reached are
returned, marked not converged), the whole request at most twice that plus 10 s
(:func:`fit_wall_seconds`; then the worker is killed and the page told): no data file can hold the
server.
"""

from __future__ import annotations

import csv
import json
import math
import numbers
import warnings
from collections.abc import Awaitable, Callable
from typing import Any

import numpy as np
from fastapi import Request
from fastapi.responses import JSONResponse, Response
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from .._core import InvalidInputError
from ..fitting import FitResult, fit
from ..fitting.keyed import KeyedInputError
from ..fitting.problem import ROD_MODELS
from ..fitting.table import parse_table
from ..model import FloatArray, Pendulum
from .fit_words import keyed, reasons, report_items
from .notices import keyed_body
from .protocol import validation_key, validation_problems
from .room import Room, client_key
from .scenarios import Setup
from .session import describe
from .worker import Busy, WorkerPool, WorkInvalid, WorkTimeout

MAX_FIT_BYTES = 2 * 2**20
"""Largest body of ``POST /api/fit`` [bytes] (about 50 000 rows of t, x, z)."""

FIT_SECONDS = 20.0
"""The fit's time limit [s] by default (``pl.fit``'s ``time_limit``: the whole fit, from reading the data
to the error bars; the error analysis adds a few model runs past it); ``pendulab serve
--fit-time-limit`` and ``create_app(fit_time_limit=…)`` set another."""

MAX_FIT_SECONDS = 600.0
"""The largest time limit a lab's fit may be given [s]: the fits run one at a time, so a long one holds
up every other page's; longer fits belong to ``pendulab fit FILE --time-limit none``."""

PATH_POINTS = 2000
"""Most points of the measured path sent to the page."""


class FitRequest(BaseModel):
    """Body of ``POST /api/fit``: the data file's text, its name (for messages), the model, the
    parameters to fit (default by the data: see :func:`default_fit`), the column names when the file
    has no header, and the noise of one value in the data's unit (default: from the residual)."""

    model_config = ConfigDict(extra="forbid", strict=True, allow_inf_nan=False, frozen=True)

    csv: str = Field(description="the data file's text (CSV, SI units)", max_length=MAX_FIT_BYTES)
    name: str = Field("data", description="the file's name, for messages", max_length=200)
    model: str = Field("damped", description=f"one of {', '.join(ROD_MODELS)}", max_length=40)
    fit: list[str] | None = Field(None, description="parameters to fit", max_length=24)
    columns: list[str] | None = Field(None, description="the file's column names in order", max_length=32)
    sigma: float | None = Field(None, description="noise of one value in the data's unit", gt=0.0, le=1e6)


def default_fit(model: str, kinds: set[str]) -> list[str]:
    """What the data can determine (docs/fit.md, "What the data determine"): positions give l, g and
    the pivot; angles only g/l, so l with g fixed; frame-free scalars l and g; plus the damping of the
    damped model. The start is always fitted."""
    if "positions" in kinds:
        names = ["length", "g", "pivot"]
    elif kinds & {"angles", "planar_angle"}:
        names = ["length"]
    else:
        names = ["length", "g"]
    return names + (["damping"] if model == "damped" else [])


def _thin(n: int) -> FloatArray:
    """Indices of at most :data:`PATH_POINTS` evenly spread samples of n (the first and last kept)."""
    return np.unique(np.linspace(0, n - 1, min(n, PATH_POINTS)).round().astype(np.int64))


def measured_path(res: FitResult, data: dict[str, Any]) -> dict[str, Any] | None:
    """The data as bob positions relative to the fitted pivot [m] (see the module doc), thinned, with
    their times [s] from the first sample; None for frame-free data. Rows the fit dropped (NaN) are
    left out, the rest sorted by time like the fit's."""
    t = np.asarray(data["t"], dtype=np.float64)
    values = {**res.fixed, **res.params}
    assert isinstance(res.pendulum, Pendulum), "the lab fits a Pendulum (run_fit), never a spring"
    ell = res.pendulum.length
    along_y = False
    if "positions" in data:
        p = np.asarray(data["positions"], dtype=np.float64)
        pivot = np.array([values.get(f"pivot_{a}", 0.0) for a in "xyz"])
        along_y = p.shape[1] == 2
        if along_y:
            xyz = np.column_stack([p[:, 0] - pivot[0], np.zeros(len(p)), p[:, 1] - pivot[2]])
        else:
            xyz = p - pivot
    elif "angles" in data:
        theta, phi = np.asarray(data["angles"], dtype=np.float64).T
        xyz = ell * np.column_stack(
            [np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), -np.cos(theta)]
        )
    elif "planar_angle" in data:
        a = np.asarray(data["planar_angle"], dtype=np.float64)
        xyz = ell * np.column_stack([np.sin(a), np.zeros_like(a), -np.cos(a)])
    else:
        return None
    keep = np.isfinite(t) & np.isfinite(xyz).all(axis=1)
    t, xyz = t[keep], xyz[keep]
    order = np.argsort(t, kind="stable")
    t, xyz = t[order], xyz[order]
    if along_y:  # the camera saw x and z only: y is the fitted motion's at the same time
        fitted = res.trajectory
        xyz[:, 1] = np.interp(t - res.t0, fitted.t, fitted.x[:, 1])
    idx = _thin(len(t))
    return {
        "t": [float(v) for v in t[idx] - res.t0],
        "x": [[float(c) for c in row] for row in xyz[idx]],
        "points": len(t),
        "units": {"t": "s", "x": "m"},
    }


def _finite(v: float) -> float | None:
    return float(v) if math.isfinite(v) else None


def fit_data(req: FitRequest, time_limit: float = FIT_SECONDS) -> dict[str, Any]:
    """Parses and fits the data of ``req`` (see the module doc); JSON-ready. Raises
    :class:`pendulab.InvalidInputError` naming what is wrong with the data or the settings."""
    if req.model not in ROD_MODELS:
        raise KeyedInputError(
            f"model {req.model!r}: use one of {', '.join(ROD_MODELS)}",
            "fit_unknown_model",
            model=req.model,
            allowed=", ".join(ROD_MODELS),
        )
    name = req.name[:80]
    try:
        data = parse_table(req.csv, req.columns, req.name)
    except csv.Error as e:  # e.g. a field over the csv module's limit (a 200 kB cell)
        raise KeyedInputError(f"{name}: not a readable CSV file: {e}", "data_not_csv", file=name) from None
    kinds = {k for k in data if k != "t"}
    names = req.fit if req.fit is not None else default_fit(req.model, kinds)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            res = fit(
                pendulum=Pendulum(model=req.model),
                fit=names,
                sigma=req.sigma,
                progress=False,
                time_limit=time_limit,
                **data,
            )
        except InvalidInputError:
            raise
        except (ValueError, ArithmeticError) as e:  # numpy/SciPy on extreme data: said as the data's
            raise KeyedInputError(
                f"the fit of {name} failed: {' '.join(str(e).split())[:300]}; the data hold values "
                "the fit cannot follow in floating point (times or positions extremely far apart or "
                "close together, or a noise sigma far from the data's scale)",
                "fit_failed",
                file=name,
            ) from None
    shown = "".join(c for c in name if c.isprintable())  # a title has no control characters
    scenario = res.to_scenario(title=f"fitted to {shown}")
    try:
        lab: dict[str, Any] | None = describe(Setup.from_scenario(scenario, None))
    except ValueError:  # ScenarioError: a model the lab does not run
        lab = None
    said = [" ".join(str(w.message).split()) for w in caught]
    why = reasons(res)
    return {
        "report": res.report(),
        "warnings": said,
        # the report and the warnings as message keys for a page that translates them (.fit_words)
        "notes": [keyed(w) for w in said],
        "items": report_items(res),
        "model": res.model,
        "fit": names,
        "params": {
            n: {
                "value": res.params[n],
                "stderr": _finite(res.stderr[n]) if res.determined[n] else None,
                "unit": res.units.get(n, ""),
                "determined": bool(res.determined[n]),
                **({"reason": why[n]} if n in why else {}),
            }
            for n in res.names
        },
        "combinations": {k: {"value": v, "stderr": _finite(e)} for k, (v, e) in res.combinations.items()},
        "blocks": res.blocks.as_dict() if res.blocks is not None else None,
        "chi2": _finite(res.chi2),
        "dof": res.dof,
        "converged": bool(res.converged),
        "samples": len(res.t),
        "dropped": res.dropped,
        "scenario_toml": scenario.to_toml(),
        "lab": lab,
        "measured": measured_path(res, data),
    }


# --- the endpoint's plumbing (HTTP, threads) -------------------------------------------------------------

MAX_FIT_BODY = MAX_FIT_BYTES + MAX_FIT_BYTES // 8
"""Largest JSON body [bytes]: the file plus room for its escaping (a newline is sent as two bytes)."""

FIT_WORKERS = 1
"""Fits running at once, each in a worker process of its own pool (:mod:`.worker`): a fit takes
seconds and a core, and must not hold up the quick analyses (:data:`pendulab.server.app.WORK_SECONDS`)."""

FIT_QUEUE = 4
"""Most fits waiting for the worker; more are answered 503 (busy, try again)."""


def check_fit_time_limit(seconds: Any) -> float:
    """``seconds`` as the time limit of the lab's fits (``create_app(fit_time_limit=…)`` and ``pendulab
    serve --fit-time-limit``, one rule for both): a number of seconds > 0 and at most
    :data:`MAX_FIT_SECONDS`, else a ``ValueError`` naming it and what is allowed."""
    ok = isinstance(seconds, numbers.Real) and not isinstance(seconds, bool)
    if not (ok and 0.0 < seconds <= MAX_FIT_SECONDS):  # nan too
        raise ValueError(
            f"the lab's fit time limit must be a number of seconds > 0 and at most {MAX_FIT_SECONDS:g} "
            f"(longer fits: pendulab fit FILE --time-limit none), got {seconds!r}"
        )
    return float(seconds)


def fit_wall_seconds(time_limit: float) -> float:
    """Most wall-time seconds of one fit request in its worker for a fit time limit of ``time_limit``
    [s]: twice it plus 10 s, room for the error analysis and the rendering after the limit; past it
    the worker is killed and the page told (HTTP 503)."""
    return 2.0 * time_limit + 10.0


FIT_WALL_SECONDS = fit_wall_seconds(FIT_SECONDS)
"""Most wall-time seconds of one fit request with the default time limit (:func:`fit_wall_seconds`)."""

FIT_OPENAPI = {
    "requestBody": {
        "required": True,
        "content": {"application/json": {"schema": FitRequest.model_json_schema()}},
    }
}
"""The body's schema for the API page (``/api/docs``): the endpoint reads the body itself."""


def _problem(
    status: int, detail: str, key: str | None = None, values: dict[str, Any] | None = None
) -> JSONResponse:
    """An error answer: the English ``detail``; with ``key`` and ``values`` for a page that words it
    (``messages.json``; the data file's and the settings' refusals, :mod:`pendulab.fitting.keyed`)."""
    body: dict[str, Any] = {"detail": " ".join(detail.split())}
    if key is not None:
        body |= {"key": key, "values": values or {}}
    return JSONResponse(body, status_code=status)


def fit_endpoint(
    pool: WorkerPool, room: Room, time_limit: float = FIT_SECONDS
) -> Callable[[Request], Awaitable[Response]]:
    """The handler of ``POST /api/fit`` for one app: its fits run in ``pool``'s worker processes with
    ``time_limit`` [s] (at most half the pool's wall time), at most ``room.computations``
    (:data:`~pendulab.server.room.MAX_REQUESTS_PER_CLIENT`) computations per client (``room``)."""

    async def post_fit(request: Request) -> Response:
        """``POST /api/fit`` (see the module doc): 200 with the fit; 422 a bad body or bad data (naming
        the problem), 429 when this client already has its computations under way, 503 when
        :data:`FIT_QUEUE` fits already wait or the fit ran past the pool's wall time
        (:func:`fit_wall_seconds`; then it was stopped). The server's :class:`.hygiene.RequestBodies`
        has already answered 415 to another Content-Type than JSON and 413 to a body over
        :data:`MAX_FIT_BODY`."""
        body = await request.body()
        try:
            raw = json.loads(body)
        except (ValueError, RecursionError) as e:  # RecursionError: nested too deeply
            return _problem(422, f"the body is not JSON: {str(e)[:200]}", "not_json", {})
        try:
            req = FitRequest.model_validate(raw)
        except ValidationError as e:
            return _problem(422, validation_problems(e, skip=0), *validation_key(e))
        async with room.request(client_key(request.scope)) as allowed:
            if not allowed:
                return JSONResponse(room.too_many_requests(), status_code=429, headers={"retry-after": "1"})
            seconds = pool.seconds
            try:
                out = await pool.run(fit_data, req, min(time_limit, 0.5 * seconds))
            except Busy:
                return JSONResponse(
                    keyed_body("busy", waiting=FIT_QUEUE), status_code=503, headers={"retry-after": "5"}
                )
            except WorkTimeout as e:
                return JSONResponse(keyed_body("work_timeout", seconds=f"{e.seconds:g}"), status_code=503)
            except WorkInvalid as e:
                return _problem(422, str(e), e.key, e.values)
        return Response(out, media_type="application/json")

    return post_fit
