"""The lab's live error estimate (issue 17 item 2; docs/web.md, "Error estimate"; server/live_error.py).

Every frame record carries ``error_x`` [m], the status ``error_estimate`` says how it is obtained. For
the ideal pendulum it is the true error against the exact solution (checked here against ``pl.exact``
evaluated independently); for the other models a companion stepper: Richardson at dt/2 for the
fixed-step methods, a 10× tighter tolerance for DOP853 (as ``accuracy.estimate``). The companion's
estimate is checked against the true error on the ideal pendulum (``Session(exact_error=False)``):
within a factor 2 for RATTLE and RK4 and a factor 10 for DOP853 (issue 17's bound), wherever the true
error is far above round-off. It starts at 0 again after every change of scenario, state, model,
parameters, method or dt; it runs in what is left of the tick's budget (without any left, the lab runs
on and the records say −1: estimate paused, and the companion catches up later).
"""

from __future__ import annotations

import dataclasses
import json
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient
from ws_session import LabClient

import pendulab as pl
from pendulab.server import FRAME_FIELDS, Session, create_app, decode_records
from pendulab.server.protocol import parse_command
from pendulab.server.session import resolve_scenario
from pendulab.server.tick import first_messages, tick_messages

T, ERR = FRAME_FIELDS.index("t"), FRAME_FIELDS.index("error_x")
X = slice(FRAME_FIELDS.index("x1"), FRAME_FIELDS.index("x1") + 3)
UNKNOWN = -1.0  # error_x of a record the estimate has not reached
AMPLE = 30.0  # s: a tick budget no test machine runs out of (the budget's own test sets a tiny one)


def command(session: Session, **cmd: Any) -> None:
    session.apply(parse_command(json.dumps(cmd)))


def run(session: Session, seconds: float, budget: float = AMPLE) -> np.ndarray:
    """The frame records of ``seconds`` of simulated time, ticked as the server does (0.1 s per tick)."""
    out = []
    for _ in range(round(seconds / 0.1)):
        for m in tick_messages(session, [], 0.1, budget_seconds=budget):
            if isinstance(m, bytes):
                out.append(decode_records(m))
    return np.vstack(out)


def true_error(session: Session, records: np.ndarray) -> np.ndarray:
    """|x − x_exact| [m] at the records, the exact solution from the start the estimate counts from."""
    since, start = session.error_start
    sol = pl.exact(session.pendulum, start)
    x, _ = sol.state(records[:, T] - since)
    return np.linalg.norm(records[:, X] - x, axis=1)


def test_ideal_pendulum_frames_carry_the_true_error_against_the_exact_solution() -> None:
    s = Session(resolve_scenario("rosette"))
    st = s.status()["error_estimate"]
    assert st == {"how": "exact", "order": None, "reference": {}, "since": 0.0, "note": None}
    first = [m for m in first_messages(s) if isinstance(m, bytes)]
    assert decode_records(first[0])[0, ERR] == 0.0  # the start is exact
    rec = run(s, 3.0)
    truth = true_error(s, rec)
    assert np.all(rec[:, ERR] >= 0)
    np.testing.assert_allclose(rec[:, ERR], truth, rtol=1e-6, atol=1e-14)
    assert rec[-1, ERR] > 1e-7  # RATTLE at dt = 1e-3 over 3 s: far above round-off


@pytest.mark.parametrize(
    ("method", "dt", "factor"), [("rattle", 1e-3, 2.0), ("rk4", 1e-2, 2.0), ("dop853", 1e-3, 10.0)]
)
def test_the_companion_estimate_is_sane_against_the_exact_solution(
    method: str, dt: float, factor: float
) -> None:
    # dop853: rtol 1e-8, atol 1e-10, loose enough for an error far above round-off within seconds
    setup = dataclasses.replace(resolve_scenario("rosette"), rtol=1e-8, atol=1e-10)
    s = Session(setup, exact_error=False)
    command(s, type="set_method", method=method, dt=dt)
    info = s.status()["error_estimate"]
    order = {m["name"]: m["order"] for m in pl.methods()}[method]
    if method == "dop853":
        assert info["how"] == "companion" and info["reference"] == pytest.approx(
            {"rtol": 1e-9, "atol": 1e-11}, rel=1e-12
        )
    else:
        assert info == {
            "how": "richardson",
            "order": order,
            "reference": {"dt": dt / 2},
            "since": 0.0,
            "note": None,
        }
    rec = run(s, 4.0)
    est, truth = rec[:, ERR], true_error(s, rec)
    far = truth > 1e-10
    assert far.sum() > 0.8 * len(rec), "the check needs errors far above round-off"
    ratio = est[far] / truth[far]
    assert np.all(ratio > 1 / factor) and np.all(ratio < factor), (ratio.min(), ratio.max())


def test_every_model_gets_an_estimate() -> None:
    for model, method in (
        ("damped", "rattle"),
        ("slewing", "rk4"),
        ("spring", "rattle4"),
        ("string", "rattle"),
    ):
        s = Session(resolve_scenario("rosette"))
        command(s, type="set_method", method=method)
        command(s, type="set_model", model=model)
        info = s.status()["error_estimate"]
        assert info["how"] == "richardson" and info["reference"] == {"dt": 5e-4}, (model, info)
        rec = run(s, 1.0)
        assert np.all(rec[:, ERR] >= 0) and 0 < rec[-1, ERR] < 1e-2, (model, rec[-1, ERR])


@pytest.mark.parametrize(
    "cmd",
    [
        {"type": "set_state", "theta": 1.0, "phi_dot": 1.0},
        {"type": "set_method", "method": "rk4"},
        {"type": "set_method", "dt": 5e-4},
        {"type": "set_params", "length": 1.5},
        {"type": "set_model", "model": "damped"},
        {"type": "load_scenario", "name": "conical"},
        {"type": "reset"},
    ],
)
def test_the_estimate_starts_afresh_when_the_run_changes(cmd: dict[str, Any]) -> None:
    s = Session(resolve_scenario("rosette"))
    before = run(s, 2.0)[-1, ERR]
    assert before > 1e-7
    t = s.t
    out = tick_messages(s, [parse_command(json.dumps(cmd))], 0.0, budget_seconds=AMPLE)
    status = [m for m in out if isinstance(m, dict) and m["type"] == "status"][-1]
    since = 0.0 if cmd["type"] in ("reset", "load_scenario") else t
    assert status["error_estimate"]["since"] == pytest.approx(since, abs=1e-12)
    frames = [decode_records(m) for m in out if isinstance(m, bytes)]
    if frames:  # a discontinuity sends the new start: error 0
        assert frames[0][0, ERR] == 0.0
    after = run(s, 0.2)
    assert 0 <= after[0, ERR] < before / 10  # counted from the new start


def test_without_budget_the_lab_runs_on_and_the_estimate_pauses_then_catches_up() -> None:
    s = Session(resolve_scenario("rosette"))
    command(s, type="set_model", model="damped")
    run(s, 0.5)
    spent = 0.0
    rec = s.advance(0.1, AMPLE)  # the lab's own stepping had its time …
    assert rec is not None and rec[-1, T] == pytest.approx(0.6, abs=1e-9) and not s.lagging
    s.fill_errors(rec, spent)  # … and none is left for the companion
    assert np.all(rec[:, ERR] == UNKNOWN)
    # a later tick with time to spare: the companion catches up over both ticks' steps
    rec = run(s, 0.1)
    assert np.all(rec[:, ERR] > 0)
    fresh = Session(resolve_scenario("rosette"))
    command(fresh, type="set_model", model="damped")
    ref = run(fresh, 0.7)
    assert rec[-1, ERR] == ref[-1, ERR]  # the same estimate as a companion never behind


def test_a_tight_budget_never_slows_the_lab() -> None:
    """Per tick the lab steps first; the companion gets only the rest: with a budget that the lab's own
    stepping alone uses up, the lab keeps its pace and the records say 'estimate paused'."""
    s = Session(resolve_scenario("rosette"))
    command(s, type="set_model", model="damped")
    command(s, type="set_method", method="rattle", dt=1e-6)  # 1e5 steps per simulated 0.1 s
    command(s, type="set_time_scale", time_scale=1e-2)
    rec = run(s, 2.0, budget=1e-9)  # every slice overruns at once
    assert np.all(rec[:, ERR] == UNKNOWN)
    assert rec[-1, T] > 0  # frames came


def test_the_status_and_frames_over_the_websocket() -> None:
    client: TestClient = LabClient(create_app("rosette"))
    with client.websocket_connect("/ws") as ws:
        status = ws.receive_json()
        assert status["error_estimate"]["how"] == "exact"
        errs = []
        while len(errs) < 30:
            msg = ws.receive()
            if msg.get("bytes") is not None:
                errs.extend(decode_records(msg["bytes"])[:, ERR])
        assert errs[0] == 0.0 and all(e >= 0 for e in errs) and errs[-1] > 0
