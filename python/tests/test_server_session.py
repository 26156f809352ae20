"""The lab's session without sockets (``pendulab.server.session``, ``tick``, docs/web.md): pacing in
whole steps of wall-clock time x time scale, a tick's time budget, parameter and state changes,
integration failures, the frame encoding as little-endian float64 records and the status counts; and
the ``pendulab serve`` command line (help, user errors, a port in use, URLs and browser detection).
No browser is opened, no port is bound except in the port-in-use test. Times in seconds, SI units as
in the frames."""

from __future__ import annotations

import math
import socket
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

import pendulab as pl
from pendulab import cli
from pendulab._core import LiveSession
from pendulab.cli import serve as cli_serve
from pendulab.server import (
    FRAME_FIELDS,
    RECORD_BYTES,
    Session,
    decode_records,
    encode_records,
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

E, J3, TENSION = (FRAME_FIELDS.index(k) for k in ("energy", "j3", "tension"))

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
    assert r.exit_code == 2 and "no example scenario of that name" in r.stderr and "rosette" in r.stderr
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
