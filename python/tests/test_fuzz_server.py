"""Property tests (hypothesis) of the lab server's uploads and computing endpoints (issue 30; docs/web.md,
"A pupil in the room"): generated data files for ``POST /api/fit`` — numbers from the extremes of
float64 (1e308, 5e-324, times 1e-300 apart), text fragments (quotes, brackets, separators, control
characters, a BOM), long fields up to the body cap — and generated bodies for ``/api/exact``,
``/api/reduced``, ``/api/em_map``, ``/api/effective_potential`` and ``/api/scenario.toml``. Every
answer must be 200 with JSON, or a 4xx / 503 whose ``detail`` names the problem in at most a few
hundred characters; never a 500, never a hang (the fits run in the worker with a short wall-time
limit here). Examples per test: ``FUZZ_EXAMPLES`` (default 25, derandomised, for CI). Units: SI.
"""

from __future__ import annotations

import json
import os
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from ws_session import LabClient

from pendulab.server import create_app
from pendulab.server.fit import MAX_FIT_BYTES

EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "25"))
FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=EXAMPLES <= 1000,
    database=None,
    suppress_health_check=list(HealthCheck),
)

EXTREME = [0.0, -0.0, 1.0, -1.0, 1e308, -1e308, 5e-324, -5e-324, 1e-300, 1e300, 2.2250738585072014e-308]
NUMBER = st.one_of(
    st.sampled_from(EXTREME),
    st.floats(allow_nan=True, allow_infinity=True, width=64),
    st.integers(min_value=-(10**30), max_value=10**30),
)
CELL = st.one_of(
    NUMBER.map(repr),
    st.sampled_from(["", '"', "'", "(", ")", "[", ",", ";", "\t", "nan", "inf", "-inf", "1e999", "0x10"]),
    st.sampled_from(["\ufeff", "\x1b[31m", "\x00", "m", "s", "t", "x", "z", "theta", "(m)", "[s]"]),
    st.text(max_size=12),
)
HEADER = st.sampled_from(["t,x,z", "t,x,y,z", "t,theta,phi", "t,angle", "time (s),x (m),z (m)", ""])


@st.composite
def data_file(draw: Any) -> str:
    """A data file: a header, rows of cells (mostly numbers), sometimes a field or a line blown up to
    tens or hundreds of kB (within the body cap)."""
    rows = draw(st.lists(st.lists(CELL, min_size=1, max_size=5), min_size=0, max_size=25))
    text = draw(HEADER) + "\n" + "\n".join(",".join(r) for r in rows) + "\n"
    blow = draw(st.sampled_from([0, 0, 0, 1_000, 50_000, 200_000]))
    if blow:
        text += draw(st.sampled_from(["1", "(", '"', ",'a", '\\"'])) * (blow // 2) + "\n"
    return text[:MAX_FIT_BYTES]


@pytest.fixture(scope="module")
def client() -> LabClient:
    return LabClient(create_app("rosette", fit_seconds=8.0))


def _post(client: LabClient, path: str, body: Any) -> Any:
    """POST ``body`` as JSON text as Python writes it: NaN and Infinity included (a hostile client may
    send them; Python's JSON reader takes them)."""
    return client.post(path, content=json.dumps(body), headers={"content-type": "application/json"})


def _clear(r: Any) -> None:
    assert r.status_code != 500, r.text[:500]
    assert r.status_code in (200, 413, 415, 422, 429, 503), (r.status_code, r.text[:300])
    body = r.json()
    if r.status_code != 200:
        assert isinstance(body["detail"], str) and 0 < len(body["detail"]) <= 2500, body


@FUZZ
@given(
    csv=data_file(),
    fit=st.one_of(st.none(), st.lists(st.sampled_from(["length", "g", "pivot", "damping", "x"]), max_size=3)),
    sigma=st.one_of(st.none(), st.sampled_from([1e-300, 5e-324, 1e-3, 1e6, 0.0, -1.0])),
    model=st.sampled_from(["damped", "ideal", "spring", "nope"]),
)
def test_fit_uploads_get_a_result_or_a_clear_error(
    client: LabClient, csv: str, fit: list[str] | None, sigma: float | None, model: str
) -> None:
    body: dict[str, Any] = {"csv": csv, "name": "fuzz.csv", "model": model}
    if fit is not None:
        body["fit"] = fit
    if sigma is not None:
        body["sigma"] = sigma
    _clear(_post(client, "/api/fit", body))


VALUE = st.one_of(NUMBER, st.none(), st.booleans(), st.text(max_size=8), st.lists(NUMBER, max_size=4))
KEYS = ["length", "g", "mass", "theta", "phi", "theta_dot", "phi_dot", "x", "v", "n", "grid", "j3"]


@FUZZ
@given(
    path=st.sampled_from(["/api/exact", "/api/reduced", "/api/em_map", "/api/effective_potential"]),
    body=st.dictionaries(st.sampled_from(KEYS), VALUE, max_size=6),
)
def test_computing_endpoints_answer_every_body_clearly(client: LabClient, path: str, body: dict) -> None:
    _clear(_post(client, path, body))


@FUZZ
@given(
    body=st.fixed_dictionaries(
        {"x": st.lists(NUMBER, min_size=3, max_size=3), "v": st.lists(NUMBER, min_size=3, max_size=3)},
        optional={
            "title": st.text(max_size=300),
            "method": st.sampled_from(["rattle", "dop853", "nope", ""]),
            "dt": NUMBER,
            "t_end": NUMBER,
            "params": st.dictionaries(st.text(max_size=10), NUMBER, max_size=3),
            "model": st.sampled_from(["ideal", "damped", "spring", "string", "x"]),
        },
    )
)
def test_scenario_toml_answers_every_body_clearly(client: LabClient, body: dict) -> None:
    r = _post(client, "/api/scenario.toml", body)
    assert r.status_code != 500, r.text[:500]
    assert r.status_code in (200, 422), (r.status_code, r.text[:300])
