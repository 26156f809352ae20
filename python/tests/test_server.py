"""The lab's server (``pendulab serve``, docs/web.md) over HTTP and WebSocket: REST endpoints, the
WebSocket session (frames decode to the core's numbers, pacing, pause and step), bad, flooding and
vanishing clients. FastAPI's TestClient runs the app in-process; no browser is opened, no port is
bound. The session logic without sockets and the command line are in test_server_session.py. SI units
as in the frames (m, m/s, J, N, s)."""

from __future__ import annotations

import json
import re
from typing import Any

import numpy as np
import pytest
from conftest import SCENARIOS
from fastapi.testclient import TestClient
from ws_session import LabClient

import pendulab as pl
from pendulab.server import (
    FRAME_FIELDS,
    RECORD_BYTES,
    create_app,
    decode_records,
    ticker,
)
from pendulab.server.ticker import MAX_PENDING

E, J3, TENSION = (FRAME_FIELDS.index(k) for k in ("energy", "j3", "tension"))


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


def receive(ws: Any) -> tuple[str, Any]:
    """The next message: ("json", dict) or ("frames", array (N, RECORD_LEN))."""
    msg = ws.receive()
    if msg.get("text") is not None:
        return "json", json.loads(msg["text"])
    return "frames", decode_records(msg["bytes"])


def until(ws: Any, pred: Any, limit: int = 400) -> tuple[str, Any]:
    for _ in range(limit):
        kind, value = receive(ws)
        if pred(kind, value):
            return kind, value
    raise AssertionError("message not received")


def is_status(**want: Any) -> Any:
    return lambda kind, v: (
        kind == "json" and v["type"] == "status" and all(v[k] == w for k, w in want.items())
    )


def is_error(kind: str, v: Any) -> bool:
    return kind == "json" and v["type"] == "error"


# --- REST ---------------------------------------------------------------------------------------------


def test_schema_lists_parameters_with_units_limits_defaults_and_every_method(client: TestClient) -> None:
    s = client.get("/api/schema").json()
    params = {p["name"]: p for p in s["model"]["params"]}
    assert list(params) == ["length", "mass", "g"]
    assert (params["length"]["unit"], params["mass"]["unit"], params["g"]["unit"]) == ("m", "kg", "m/s^2")
    assert params["g"]["default"] == 9.81 and params["g"]["ui_min"] < 0 < params["g"]["ui_max"]
    assert params["length"]["min"] > 0 and params["mass"]["min"] > 0
    assert [m["name"] for m in s["methods"]] == pl.method_names()
    assert {"order", "symplectic", "preserves_j3", "adaptive"} <= s["methods"][0].keys()
    assert s["frame"]["fields"] == list(FRAME_FIELDS) and s["frame"]["record_bytes"] == 152 == RECORD_BYTES
    assert s["frame"]["byte_order"] == "little" and s["frame"]["dtype"] == "float64"
    assert s["controls"]["dt"]["default"] == 1e-3 and s["controls"]["time_scale"]["default"] == 1.0
    assert "load_scenario" in s["commands"]


def test_scenarios_are_the_examples_with_their_start_on_ts2(client: TestClient) -> None:
    listed = {s["name"]: s for s in client.get("/api/scenarios").json()}
    # every example, the cranes' too ([crane]: the lab's crane mode, docs/cranes.md)
    assert set(listed) == {f.stem for f in SCENARIOS.glob("*.toml")}
    assert listed["crane_hoist"]["model"] == "crane" and listed["crane_hoist"]["params"]["length"] == 12.0
    ros = listed["rosette"]
    assert ros["params"] == {"length": 1.0, "mass": 1.0, "g": 9.81} and ros["method"] == "rattle"
    assert np.linalg.norm(ros["start"]["x"]) == pytest.approx(1.0, abs=1e-15)
    assert listed["inverted_g"]["params"]["g"] == -9.81


def test_exact_endpoint_gives_the_exact_solution_quantities(
    client: TestClient, pendulum: pl.Pendulum, rosette: pl.State
) -> None:
    body = {"length": 1.0, "mass": 1.0, "g": 9.81, "x": list(rosette.x), "v": list(rosette.v)}
    q = client.post("/api/exact", json=body).json()
    sol = pl.exact(pendulum, rosette)
    assert q["kind"] == sol.kind == "generic"
    assert q["turning_heights"] == list(sol.turning_heights)
    assert q["period_z"] == sol.period_z and q["azimuth_advance"] == sol.azimuth_advance
    ph = sol.phases()
    assert q["phases"] == {"total": ph.total, "dynamic": ph.dynamic, "geometric": ph.geometric}
    assert q["energy"] == pendulum.energy(rosette)
    # angles work too; planar motion has no phases and says why
    planar = client.post("/api/exact", json={"theta": 1.0}).json()
    assert planar["kind"] == "planar" and planar["phases"] is None and "J3" in planar["phases_note"]


def test_exact_endpoint_names_bad_input(client: TestClient) -> None:
    r = client.post("/api/exact", json={"g": "strong", "theta": 1.0})
    assert r.status_code == 422 and "g = 'strong'" in r.json()["detail"]
    r = client.post("/api/exact", json={"x": [2, 0, 0], "v": [0, 1, 0]})
    assert r.status_code == 422 and "TS" in r.json()["detail"]
    r = client.post("/api/exact", content=b"{", headers={"content-type": "application/json"})
    assert r.status_code == 422 and "not JSON" in r.json()["detail"]


def test_front_end_is_served_from_the_package(client: TestClient, tmp_path: Any) -> None:
    page = client.get("/")
    assert page.status_code == 200 and '<div id="gui">' in page.text
    bare = LabClient(create_app(static_dir=tmp_path)).get("/")
    assert bare.status_code == 503 and "make web" in bare.text


# --- the WebSocket session -------------------------------------------------------------------------------


def test_session_streams_frames_whose_numbers_are_the_cores(client: TestClient) -> None:
    p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
    with client.websocket_connect("/ws") as ws:
        kind, status = receive(ws)
        assert kind == "json" and status["type"] == "status" and status["scenario"] == "rosette"
        assert status["frame_fields"] == list(FRAME_FIELDS)
        ws.send_json({"type": "set_state", "theta": 1.2, "phi": 0.3, "theta_dot": 0.1, "phi_dot": -1.5})
        until(ws, is_status(epoch=status["epoch"] + 1))
        _, first = until(ws, lambda k, v: k == "frames")
        start = p.state_from_angles(1.2, 0.3, 0.1, -1.5)
        np.testing.assert_array_equal(first[0, 1:4], start.x)
        records = [first]
        while sum(len(r) for r in records) < 6:
            records.append(until(ws, lambda k, v: k == "frames")[1])
        rec = np.concatenate(records)
        assert np.all(np.diff(rec[:, 0]) > 0)
        x, v = rec[:, 1:4], rec[:, 4:7]
        diag = p.diagnostics(x, v)
        np.testing.assert_allclose(rec[:, E], diag["energy"], rtol=0, atol=1e-12)
        np.testing.assert_allclose(rec[:, J3], diag["j3"], rtol=0, atol=1e-12)
        np.testing.assert_allclose(rec[:, TENSION], diag["tension"], rtol=0, atol=1e-12)
        # and the states are RATTLE's own: the same steps as an offline Stepper from the same start
        t_last = rec[-1, 0]  # set_state keeps t: count the steps from the start's record on
        n = round((t_last - rec[0, 0]) / 1e-3)
        assert t_last - rec[0, 0] == pytest.approx(n * 1e-3, abs=1e-12)
        offline = pl.Stepper(p, start, method="rattle", dt=1e-3).step(n)
        np.testing.assert_allclose(rec[-1, 1:4], offline.x, rtol=0, atol=1e-12)


def test_pause_stops_and_step_takes_exactly_n_steps(client: TestClient) -> None:
    with client.websocket_connect("/ws") as ws:
        ws.send_json({"type": "set_method", "method": "rattle4", "dt": 0.002})
        until(ws, is_status(method="rattle4", dt=0.002))
        ws.send_json({"type": "pause"})
        _, paused = until(ws, is_status(paused=True))
        t = paused["t"]
        ws.send_json({"type": "step", "n": 5})
        _, s = until(ws, lambda k, v: k == "json")  # the status after the step: its t is the frame's
        assert s["type"] == "status" and s["t"] == pytest.approx(t + 5 * 0.002, abs=1e-12)
        kind, rec = until(ws, lambda k, v: k == "frames" or (k == "json" and v["type"] == "error"))
        assert kind == "frames" and rec.shape == (1, len(FRAME_FIELDS))
        assert rec[0, 0] == pytest.approx(t + 5 * 0.002, abs=1e-12)
        ws.send_json({"type": "set_time_scale", "time_scale": 4.0})
        _, s = until(ws, is_status(time_scale=4.0))
        assert s["paused"] and s["t"] == pytest.approx(rec[0, 0], abs=1e-12)  # still paused: no frames
        ws.send_json({"type": "reset"})
        _, s = until(ws, is_status(t=0.0))
        ws.send_json({"type": "resume"})
        _, rec = until(ws, lambda k, v: k == "frames" and v[-1, 0] > 0)
        assert rec.shape[0] >= 1


def test_parameters_scenarios_and_negative_g(client: TestClient) -> None:
    with client.websocket_connect("/ws") as ws:
        ws.send_json({"type": "load_scenario", "name": "inverted_g"})
        _, s = until(ws, is_status(scenario="inverted_g"))
        assert s["params"]["g"] == -9.81 and s["t"] == 0.0
        _, rec = until(ws, lambda k, v: k == "frames")
        assert rec[0, 3] > 0  # hangs above the pivot
        ws.send_json({"type": "set_params", "length": 2.0})
        _, s = until(ws, is_status(params={"length": 2.0, "mass": 1.0, "g": -9.81}))
        _, rec = until(ws, lambda k, v: k == "frames")
        assert np.linalg.norm(rec[0, 1:4]) == pytest.approx(2.0, abs=1e-12)


def test_bad_messages_get_an_error_and_the_connection_stays_usable(client: TestClient) -> None:
    bad: list[tuple[str | bytes, str]] = [
        ("garbage", "not JSON"),
        ("[1, 2]", "a JSON object"),
        ('{"kind": "pause"}', "missing 'type'"),
        ('{"type": "explode"}', "unknown command type 'explode'"),
        ('{"type": "set_params", "g": NaN}', "g = NaN"),
        ('{"type": "set_params", "g": 1e9}', "less than or equal to 1000"),
        ('{"type": "set_params", "length": -1}', "length = -1"),
        ('{"type": "set_params"}', "at least one"),
        ('{"type": "set_params", "g": "9.81"}', "valid number"),
        ('{"type": "pause", "now": true}', "unknown key 'now'"),
        ('{"type": "set_state", "x": [1, 0, 0]}', "both x"),
        ('{"type": "set_state", "x": [2, 0, 0], "v": [0, 0, 0]}', "TS"),
        ('{"type": "set_method", "method": "euler"}', "unknown method 'euler'"),
        ('{"type": "step", "n": 0}', "n = 0"),
        ('{"type": "load_scenario", "name": "../../etc/passwd"}', "no such scenario"),
        (b"\x00\x01", "binary messages are not accepted"),
        ('{"type": "pause", "pad": "' + "x" * 5000 + '"}', "too long"),
    ]
    with client.websocket_connect("/ws") as ws:
        for message, needle in bad:
            if isinstance(message, bytes):
                ws.send_bytes(message)
            else:
                ws.send_text(message)
            _, err = until(ws, is_error)
            assert needle in err["message"], (message, err)
        ws.send_json({"type": "pause"})
        _, s = until(ws, is_status(paused=True))
        assert s["params"] == {"length": 1.0, "mass": 1.0, "g": 9.81}  # nothing bad got through


def test_a_flooding_client_is_throttled_and_still_served(
    client: TestClient, monkeypatch: pytest.MonkeyPatch
) -> None:
    # Deterministic, whatever the machine's speed: the ticks apply nothing while the client floods, so
    # the inbox fills to its (small) limit and the rest is dropped; then the ticks catch up.
    assert MAX_PENDING >= 32  # the real limit
    monkeypatch.setattr(ticker, "MAX_PENDING", 4)
    monkeypatch.setattr(ticker, "MAX_PER_TICK", 0)
    with client.websocket_connect("/ws") as ws:
        for _ in range(10):
            ws.send_text('{"type": "set_time_scale", "time_scale": 2.0}')
        dropped = 0
        while dropped < 6:  # reported per tick: 6 in all, maybe over several ticks
            _, err = until(ws, lambda k, v: is_error(k, v) and "throttled" in v["message"])
            dropped += int(re.search(r"(\d+) command\(s\) dropped", err["message"]).group(1))
        assert dropped == 6
        monkeypatch.setattr(ticker, "MAX_PER_TICK", 32)
        until(ws, is_status(time_scale=2.0))
        ws.send_json({"type": "set_time_scale", "time_scale": 3.0})
        until(ws, is_status(time_scale=3.0))


def test_the_server_survives_clients_that_vanish(client: TestClient) -> None:
    for _ in range(3):
        with client.websocket_connect("/ws") as ws:
            receive(ws)  # gone right after the first message
    with client.websocket_connect("/ws") as ws:
        until(ws, lambda k, v: k == "frames")
    assert client.get("/api/schema").status_code == 200
