"""The lab's swinging spring and string pendulum (docs/web.md): over the WebSocket, a session of each
streams frames whose energy is conserved (the spring's kinetic + elastic + gravity energy; the string's
with restitution 1, through taut phases, flights and snaps) and whose states are those of the offline
run from the same start (``pl.simulate_spring``, ``pl.simulate`` of the string) bit for bit: the core's
incremental steppers cut the same run into pieces. The string's slack episodes are in the frames
(``taut`` = 0, tension 0, inside the sphere), and each of its events — the leave where the tension
reaches 0, the snap losing ½m(1 − e²)u² — arrives as an ``event`` notice whose time, position and energy
lost are the offline run's event bit for bit; bad parameters get an error notice and the connection stays
usable; a change of parameters carries the string's slack state without pushing it onto the sphere."""

from __future__ import annotations

import itertools
import json
from typing import Any

import numpy as np
import pytest
import ws_session
from fastapi.testclient import TestClient
from ws_session import LabClient, receive, status_with

import pendulab as pl
from pendulab.server import FRAME_FIELDS, Session, create_app
from pendulab.server.protocol import parse_command
from pendulab.server.session import resolve_scenario
from pendulab.variants.string_pendulum import simulate_string

F = {name: i for i, name in enumerate(FRAME_FIELDS)}
X, V, A = (slice(F[f"{k}1"], F[f"{k}1"] + 3) for k in ("x", "v", "a"))
G = 9.81


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


def until(ws: Any, pred: Any, limit: int = 2000) -> Any:
    """ws_session.until with room for the long runs of these sessions."""
    return ws_session.until(ws, pred, limit)


def take_steps(s: Session, n: int) -> None:
    """A ``step`` command of n steps, carried out at once (a tick's budget of a minute)."""
    s.apply(parse_command(f'{{"type": "step", "n": {n}}}'))
    s.take_pending_steps(60.0)


def frames_until(ws: Any, t_end: float) -> np.ndarray:
    """Every frame record received until one reaches t_end [s] (an error notice fails the test)."""
    rec: list[np.ndarray] = []
    while not rec or rec[-1][-1, 0] < t_end:
        kind, value = receive(ws)
        assert not (kind == "json" and value["type"] == "error"), value
        if kind == "frames":
            rec.append(value)
    return np.concatenate(rec)


def start_paused(ws: Any, *commands: dict[str, Any]) -> dict[str, Any]:
    """Pauses, applies ``commands`` (each a new epoch), and returns the last status."""
    ws.send_json({"type": "pause"})
    s = until(ws, status_with(paused=True))
    for c in commands:
        ws.send_json(c)
        s = until(ws, status_with(epoch=s["epoch"] + 1))
    return s


def test_a_spring_session_conserves_energy_and_is_the_offline_run_state_for_state(client: TestClient) -> None:
    x0, v0 = [0.3, 0.1, -1.1], [0.0, 0.6, 0.4]  # stretched beyond l0 = 1 m, swinging and bouncing
    with client.websocket_connect("/ws") as ws:
        s = start_paused(
            ws,
            {"type": "set_model", "model": "spring", "params": {"stiffness": 40.0}},
            {"type": "set_state", "x": x0, "v": v0},
        )
        assert s["model"] == "spring" and s["model_params"] == {"stiffness": 40.0}
        assert s["method"] == "rattle" and s["start"] == {"x": x0, "v": v0}  # not projected: no sphere
        t_s, dt = s["t"], s["dt"]
        ws.send_json({"type": "set_time_scale", "time_scale": 8.0})
        ws.send_json({"type": "resume"})
        r = frames_until(ws, t_s + 4.0)
    t, x, v = r[:, 0], r[:, X], r[:, V]
    assert np.all(np.diff(t) > 0) and t[0] >= t_s
    m, ell, k = 1.0, 1.0, 40.0
    stretch = np.linalg.norm(x, axis=1) - ell
    energy = m * (0.5 * np.sum(v * v, axis=1) + G * x[:, 2]) + 0.5 * k * stretch**2
    np.testing.assert_allclose(r[:, F["energy"]], energy, rtol=0, atol=1e-12)
    np.testing.assert_allclose(r[:, F["tension"]], k * stretch, rtol=0, atol=1e-12)
    assert np.ptp(stretch) > 0.05  # it bounces: the rod's length varies
    e0 = m * (0.5 * np.dot(v0, v0) + G * x0[2]) + 0.5 * k * (np.linalg.norm(x0) - ell) ** 2
    # Störmer–Verlet: the energy error is bounded, O(dt²); here within 1e-5 of m g l
    assert np.max(np.abs(r[:, F["energy"]] - e0)) < 1e-5 * m * G * ell
    j3 = m * (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0])
    np.testing.assert_allclose(j3, j3[0], rtol=0, atol=1e-13)  # J₃: kept to round-off
    assert np.all(r[:, F["taut"]] == 1.0) and np.all(r[:, F["power"]] == 0.0)
    # the same steps as the offline run from the same start
    n = round((t[-1] - t_s) / dt)
    off = pl.simulate_spring(pl.SwingingSpring(k / m, ell, G, m), x0, v0, n * dt, dt=dt)
    idx = np.rint((t - t_s) / dt).astype(int)
    np.testing.assert_array_equal(x, off.x[idx])
    np.testing.assert_array_equal(v, off.v[idx])


def test_a_string_session_with_elastic_snaps_conserves_energy_reports_slack_and_is_the_offline_run(
    client: TestClient,
) -> None:
    with client.websocket_connect("/ws") as ws:
        s = start_paused(
            ws,
            {"type": "load_scenario", "name": "string_slack"},
            {"type": "set_params", "params": {"restitution": 1.0}},
        )
        assert s["model"] == "string" and s["model_params"] == {"restitution": 1.0}
        t_s, dt, method = s["t"], s["dt"], s["method"]
        assert (t_s, method) == (0.0, "rattle8")
        ws.send_json({"type": "set_time_scale", "time_scale": 5.0})
        ws.send_json({"type": "resume"})
        r = frames_until(ws, 3.0)
    t, x, v, taut = r[:, 0], r[:, X], r[:, V], r[:, F["taut"]]
    radius = np.linalg.norm(x, axis=1)
    slack = taut == 0.0
    # taut, then slack from z = l/2 on (with restitution 1 each snap bounces the bob back into flight)
    assert not slack[0] and slack.any() and abs(x[np.flatnonzero(slack)[0] - 1, 2] - 0.5) < 0.05
    assert np.all(radius[slack] < 1.0) and np.all(np.abs(radius[~slack] - 1.0) < 1e-12)
    assert np.all(r[slack, F["tension"]] == 0.0) and np.all(r[~slack, F["tension"]] >= 0.0)
    np.testing.assert_array_equal(r[slack][:, A], np.tile([0.0, 0.0, -G], (slack.sum(), 1)))  # free fall
    energy = 0.5 * np.sum(v * v, axis=1) + G * x[:, 2]
    np.testing.assert_allclose(r[:, F["energy"]], energy, rtol=0, atol=1e-12)
    e0 = 0.5 * 3.5 * G - G  # v0² = 3.5 g l from the bottom
    assert np.max(np.abs(energy - e0)) < 1e-9 * G  # restitution 1: the snaps keep E, rattle8 too
    # the offline hybrid run from the same start: the same states on the same grid, the same modes
    p = pl.Pendulum(length=1.0, g=G, mass=1.0, model="string", restitution=1.0)
    start = resolve_scenario("string_slack").state
    off = simulate_string(p, start, t[-1] + dt, method=method, dt=dt, t0=t_s)
    where = {float(tk): i for i, tk in enumerate(off.t)}
    idx = np.array([where[float(tk)] for tk in t])
    np.testing.assert_array_equal(x, off.x[idx])
    np.testing.assert_array_equal(v, off.v[idx])
    np.testing.assert_array_equal(~slack, off.taut[idx])
    assert off.events is not None and len(off.events["t"]) >= 2


def test_an_inelastic_string_session_goes_taut_again_losing_the_snaps_energy() -> None:
    s = Session(resolve_scenario("string_slack"))  # restitution 0
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 4.0}'))
    r = np.concatenate([rec for rec in (s.advance(0.05) for _ in range(15)) if rec is not None])
    taut = r[:, F["taut"]] == 1.0
    changes = np.flatnonzero(np.diff(taut.astype(int)))
    assert len(changes) >= 2 and taut[0] and not taut[changes[0] + 1] and taut[changes[1] + 1]
    off = simulate_string(s.pendulum, resolve_scenario("string_slack").state, 3.0, method="rattle8", dt=s.dt)
    assert off.events is not None
    snap = int(np.flatnonzero(np.asarray(off.events["kind"]) == "taut")[0])
    lost = float(off.events["energy_lost"][snap])
    e = r[:, F["energy"]]
    assert lost > 1.0 and abs((e[changes[0]] - e[changes[1] + 1]) - lost) < 1e-9


def test_bad_parameters_of_the_spring_and_the_string_get_an_error_and_the_connection_stays_up(
    client: TestClient,
) -> None:
    with client.websocket_connect("/ws") as ws:
        s = start_paused(ws, {"type": "set_model", "model": "spring"})
        for cmd, needle in [
            ({"type": "set_params", "params": {"stiffness": -3.0}}, "stiffness = -3"),
            ({"type": "set_params", "params": {"stiffness": "stiff"}}, "valid number"),
            (
                {"type": "set_params", "params": {"restitution": 0.5}},
                "restitution is a parameter of model 'string', not of 'spring'",
            ),
            ({"type": "set_params", "params": {"bounce": 0.5}}, "'spring' model has no parameter 'bounce'"),
            ({"type": "set_method", "method": "dop853"}, "use one of rattle, rattle4"),
            ({"type": "set_state", "x": [0, 0, 0], "v": [0, 0, 0]}, "x ≠ 0"),
        ]:
            ws.send_json(cmd)
            err = until(ws, lambda k, v: k == "json" and v["type"] == "error")
            assert needle in err["message"], err
        ws.send_json({"type": "set_model", "model": "string"})
        s = until(ws, status_with(model="string"))
        for cmd, needle in [
            ({"type": "set_params", "params": {"restitution": 1.5}}, "restitution"),
            ({"type": "set_state", "x": [0, 0, -2.0], "v": [0, 0, 0]}, "|x|"),
            ({"type": "set_method", "method": "rk4"}, "use one of rattle, rattle4, rattle6, rattle8, rkmk4"),
        ]:
            ws.send_json(cmd)
            err = until(ws, lambda k, v: k == "json" and v["type"] == "error")
            assert needle in err["message"], err
        # still usable: a valid change goes through
        ws.send_json({"type": "set_params", "params": {"restitution": 0.5}})
        s = until(ws, status_with(epoch=s["epoch"] + 1))
        assert s["model_params"] == {"restitution": 0.5} and s["method"] == "rattle"


def test_a_slack_string_keeps_its_mode_through_a_parameter_change_and_a_model_switch_projects() -> None:
    s = Session(resolve_scenario("string_slack"))
    rec = s.apply(parse_command('{"type": "set_state", "x": [0.3, 0.0, -0.4], "v": [1.0, 0.0, 0.5]}'))
    assert rec is not None and rec[0, F["taut"]] == 0.0  # inside the sphere: slack, taken as given
    take_steps(s, 50)
    x_before = s.state.x.copy()
    rec = s.apply(parse_command('{"type": "set_params", "g": 9.0}'))
    assert rec is not None and rec[0, F["taut"]] == 0.0
    np.testing.assert_array_equal(rec[0, X], x_before)  # not pushed onto the sphere
    # to the spring: the state is kept as it is (rattle8 cannot run it: rattle); back to a rod: on TS²
    rec = s.apply(parse_command('{"type": "set_model", "model": "spring"}'))
    assert rec is not None and s.method == "rattle"
    np.testing.assert_array_equal(rec[0, X], x_before)
    rec = s.apply(parse_command('{"type": "set_model", "model": "ideal"}'))
    assert rec is not None and abs(np.linalg.norm(rec[0, X]) - 1.0) < 1e-12


def test_switching_to_the_spring_or_the_string_picks_a_method_that_runs_it() -> None:
    s = Session(resolve_scenario("rosette"))
    s.apply(parse_command('{"type": "set_method", "method": "dop853"}'))
    s.apply(parse_command('{"type": "set_model", "model": "string"}'))
    assert s.status()["method"] == "rattle" and not s.status()["adaptive"]
    s.apply(parse_command('{"type": "set_method", "method": "rattle4"}'))
    s.apply(parse_command('{"type": "set_model", "model": "spring"}'))
    assert s.status()["method"] == "rattle4"  # the spring's triple jump (order 4)
    take_steps(s, 10)
    assert s.status()["t"] == pytest.approx(10 * s.dt)


def test_a_string_session_sends_each_leave_and_snap_as_an_event_notice_equal_to_the_offline_runs(
    client: TestClient,
) -> None:
    with client.websocket_connect("/ws") as ws:
        s = start_paused(ws, {"type": "load_scenario", "name": "string_slack"})  # restitution 0
        assert s["model"] == "string" and s["t"] == 0.0
        epoch, dt, method = s["epoch"], s["dt"], s["method"]
        ws.send_json({"type": "set_time_scale", "time_scale": 5.0})
        ws.send_json({"type": "resume"})
        events: list[dict[str, Any]] = []
        last_t = 0.0
        while len(events) < 2:
            kind, value = receive(ws)
            assert not (kind == "json" and value["type"] == "error"), value
            if kind == "frames":
                last_t = float(value[-1, 0])
            elif value["type"] == "event":
                assert value["t"] <= last_t  # sent after the frames that pass it
                events.append(value)
    assert [e["kind"] for e in events] == ["slack", "taut"]
    assert all(e["epoch"] == epoch and e["skipped"] == 0 for e in events)
    sc = resolve_scenario("string_slack")
    off = simulate_string(sc.pendulum, sc.state, 3.0, method=method, dt=dt)
    assert off.events is not None
    assert list(off.events["kind"][:2]) == ["slack", "taut"]
    for k, e in enumerate(events):  # the same events, bit for bit: the same core run cut into pieces
        assert e["t"] == float(off.events["t"][k])
        assert e["energy_lost"] == float(off.events["energy_lost"][k])
        assert e["x"] == [float(c) for c in off.events["x"][k]]
    assert events[0]["energy_lost"] == 0.0 and events[1]["energy_lost"] > 1.0
    assert abs(events[0]["x"][2] - 0.5) < 1e-6  # it leaves the sphere at z = l/2 (v0² = 3.5 g l)


def test_event_notices_keep_the_epoch_they_happened_in_and_a_flood_is_cut_to_the_latest() -> None:
    from pendulab.server.session import MAX_EVENT_NOTICES

    s = Session(resolve_scenario("string_slack"))
    assert s.take_event_notices() == []
    take_steps(s, 1500)  # past the leave (t ≈ 0.9 s at dt = 1e-3)
    epoch = s.epoch
    s.apply(parse_command('{"type": "reset"}'))
    notices = s.take_event_notices()
    assert notices and notices[0]["kind"] == "slack" and all(n["epoch"] == epoch for n in notices)
    assert s.epoch == epoch + 1 and s.take_event_notices() == []
    # a string bouncing elastically in a tiny sphere: many snaps in one tick, only the latest are sent
    s.apply(parse_command('{"type": "set_params", "length": 0.01, "params": {"restitution": 1.0}}'))
    s.apply(parse_command('{"type": "set_state", "x": [0.0, 0.0, -0.005], "v": [0.0, 0.0, 0.0]}'))
    s.apply(parse_command('{"type": "resume"}'))  # step paused it
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 100.0}'))
    s.advance(0.1)
    notices = s.take_event_notices()
    assert len(notices) == MAX_EVENT_NOTICES and notices[0]["skipped"] > 0
    assert all(n["skipped"] == notices[0]["skipped"] for n in notices)
    assert all(a["t"] <= b["t"] for a, b in itertools.pairwise(notices))
    json.dumps(notices, allow_nan=False)
