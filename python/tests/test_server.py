"""The lab's server (``pendulab serve``, docs/web.md): REST endpoints, the WebSocket session (frames decode
to the core's numbers, pacing, pause and step), bad and flooding clients, the session logic alone, and
the command line. FastAPI's TestClient runs the app in-process; no browser is opened, no port is bound
except in the port-in-use test."""

from __future__ import annotations

import json
import math
import re
import socket
from typing import Any

import numpy as np
import pytest
from conftest import SCENARIOS
from fastapi.testclient import TestClient
from typer.testing import CliRunner
from ws_session import LabClient

import pendulab as pl
from pendulab import cli
from pendulab._core import LiveSession
from pendulab.cli import serve as cli_serve
from pendulab.server import (
    FRAME_FIELDS,
    RECORD_BYTES,
    Session,
    create_app,
    decode_records,
    encode_records,
    ticker,
)
from pendulab.server.protocol import (
    RECORD_LEN,
    CommandError,
    Pause,
    SetMethod,
    SetParams,
    SetState,
    parse_command,
)
from pendulab.server.session import MAX_ELAPSED, MAX_SUBSAMPLES, resolve_scenario
from pendulab.server.tick import tick_messages
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


# --- the session without sockets ------------------------------------------------------------------------


def session(**kw: Any) -> Session:
    return Session(resolve_scenario("rosette"), **kw)


def test_pacing_follows_wall_clock_times_time_scale_in_whole_steps() -> None:
    s = session()
    rec = s.advance(1 / 60)
    assert rec is not None and rec.shape == (1, len(FRAME_FIELDS))
    assert rec[0, 0] == pytest.approx(0.016, abs=1e-15)  # 16 whole steps of 1 ms in 16.7 ms
    rec = s.advance(1 / 60)
    assert rec is not None and rec[0, 0] == pytest.approx(0.033, abs=1e-15)  # the fraction carries over
    s.apply(SetParams(type="set_params", g=9.81))  # a new stepper: same t
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 10.0}'))
    rec = s.advance(0.05)
    assert rec is not None and len(rec) == 10 and rec[-1, 0] == pytest.approx(0.533, abs=1e-12)
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 1000.0}'))
    rec = s.advance(1.0, 60.0)  # a stall: catches up at most MAX_ELAPSED, in MAX_SUBSAMPLES records
    assert rec is not None and len(rec) == MAX_SUBSAMPLES
    assert rec[-1, 0] == pytest.approx(0.533 + 1000 * MAX_ELAPSED, abs=1e-9)
    s.apply(Pause(type="pause"))
    assert s.advance(0.05) is None


def test_a_tick_stops_stepping_when_its_time_budget_is_spent_and_says_it_lags() -> None:
    s = session()
    s.apply(SetMethod(type="set_method", dt=1e-6))
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 1000.0}'))
    rec = s.advance(0.05, 0.0)  # spent from the start: one slice of a new stepper, then stop
    assert s.lagging and rec is not None and len(rec) == 1
    assert rec[-1, 0] == pytest.approx(LiveSession.FIRST_SLICE * 1e-6, rel=1e-9)
    assert s.clock == s.t  # behind real time, not piling up the missing time
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 1.0}'))
    s.advance(0.001, 60.0)
    assert not s.lagging


def test_length_change_keeps_angles_and_rates_and_reset_returns_to_the_start() -> None:
    s = session()
    s.advance(0.05)
    before = s.state
    s.apply(SetParams(type="set_params", length=0.5))
    after = s.state
    np.testing.assert_allclose(after.x, 0.5 * np.asarray(before.x), atol=1e-15)
    np.testing.assert_allclose(after.v, 0.5 * np.asarray(before.v), atol=1e-15)
    assert after.angles() == pytest.approx(before.angles(), abs=1e-14)
    rec = s.apply(pl.server.protocol.Reset(type="reset"))
    assert rec is not None and rec[0, 0] == 0.0
    theta, _ = s.state.angles()
    assert theta == pytest.approx(math.radians(60), abs=1e-14) and s.epoch == 2


def test_set_state_off_ts2_can_be_projected_and_errors_leave_the_session_unchanged() -> None:
    s = session()
    with pytest.raises(CommandError, match="TS"):
        s.apply(SetState(type="set_state", x=[0.0, 0.0, -1.5], v=[1.0, 0.0, 0.0]))
    assert s.epoch == 0
    s.apply(SetState(type="set_state", x=[0.0, 0.0, -1.5], v=[1.0, 0.0, 0.3], project=True))
    np.testing.assert_allclose(s.state.x, [0.0, 0.0, -1.0], atol=1e-15)
    with pytest.raises(CommandError, match="no such scenario"):
        s.apply(parse_command('{"type": "load_scenario", "name": "nope"}'))


def test_an_integration_failure_pauses_with_an_error() -> None:
    s = session()
    s.apply(SetMethod(type="set_method", method="rk4_angles"))
    s.apply(SetState(type="set_state", theta=0.3))  # planar: swings through the pole, where angles fail
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 10.0}'))
    with pytest.raises(CommandError, match=r"rk4_angles.*pole.*paused"):
        for _ in range(20):
            s.advance(0.05)
    assert s.paused and s.advance(0.05) is None


def test_frames_encode_as_little_endian_float64_records() -> None:
    rec = np.arange(2 * RECORD_LEN, dtype=np.float64).reshape(2, RECORD_LEN)
    data = encode_records(rec)
    assert len(data) == 2 * RECORD_BYTES and data[:8] == bytes(8)
    assert np.frombuffer(data[8:16], dtype="<f8")[0] == 1.0
    np.testing.assert_array_equal(decode_records(data), rec)
    with pytest.raises(ValueError, match=f"multiple of {RECORD_BYTES}"):
        decode_records(data[:-1])


# --- the command line -----------------------------------------------------------------------------------


def test_serve_help_and_user_errors() -> None:
    r = CliRunner().invoke(cli.app, ["serve", "--help"])
    assert (
        r.exit_code == 0
        and "--no-browser" in r.stdout
        and "127.0.0.1" in r.stdout
        and "--max-sessions" in r.stdout
    )
    r = CliRunner().invoke(cli.app, ["serve", "no_such_scenario", "--no-browser"])
    assert r.exit_code == 2 and "no such scenario" in r.stderr and "rosette" in r.stderr
    r = CliRunner().invoke(cli.app, ["serve", "--max-sessions", "0", "--no-browser"])
    assert r.exit_code == 2 and "max-sessions" in r.stderr


def test_serve_refuses_a_port_in_use() -> None:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        r = CliRunner().invoke(cli.app, ["serve", "--no-browser", "--port", str(port)])
    assert r.exit_code == 2 and "cannot listen" in r.stderr


def test_urls_and_browser_detection(monkeypatch: pytest.MonkeyPatch) -> None:
    assert cli_serve.url_for("127.0.0.1", 8000) == "http://127.0.0.1:8000"
    assert cli_serve.url_for("0.0.0.0", 80) == "http://127.0.0.1:80"
    assert cli_serve.url_for("::", 8000) == "http://[::1]:8000"
    assert cli_serve.url_for("localhost", 8000) == "http://localhost:8000"
    monkeypatch.setenv("CI", "true")
    assert not cli_serve.browser_available()


def test_the_status_counts_every_command_handled_applied_refused_or_dropped() -> None:
    """``status.commands``: the page's language switch waits until it has reached the page's own count,
    so that the URL it reloads from holds a command just sent (docs/web.md, "Languages")."""
    s = Session(resolve_scenario("rosette"))
    assert s.status()["commands"] == 0
    out = tick_messages(s, [parse_command('{"type": "pause"}'), CommandError("bad")], 0.0, dropped=3)
    statuses = [m for m in out if isinstance(m, dict) and m["type"] == "status"]
    assert statuses[-1]["commands"] == 5 and statuses[-1]["paused"] is True
    out = tick_messages(s, [CommandError("refused only")], 0.0)  # a status after refused ones too
    assert [m["commands"] for m in out if isinstance(m, dict) and m["type"] == "status"] == [6]
    assert not [m for m in tick_messages(s, [], 0.0) if isinstance(m, dict)]  # nothing new: no status
