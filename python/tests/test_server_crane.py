"""The lab's crane mode through the server's session (the core's live session behind the WebSocket's
commands; docs/cranes.md "The lab's crane mode"): a trolley move's residual sway unshaped and shaped
against ``pendulab.crane`` (its own move profile and shapers, simulated in the crane model), hoisting,
and the command's checks. SI units."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from pendulab import crane
from pendulab.server.protocol import CommandError, parse_command
from pendulab.server.session import Session, resolve_scenario

ROPE, MASS, G = 10.0, 100.0, 9.81


def _session() -> Session:
    s = Session(resolve_scenario("rosette"))
    for cmd in (
        {"type": "set_params", "length": ROPE, "mass": MASS, "g": G},
        {"type": "set_state", "theta": 0.0},
        {"type": "crane", "on": True},
        {"type": "set_params", "params": {"drag_area": 0.0, "v_max": 0.5, "a_max": 0.25}},
    ):
        s.apply(parse_command(json.dumps(cmd)))
    return s


def _run(s: Session, t_end: float) -> np.ndarray:
    """Frame records every 0.05 s of simulated time up to ``t_end`` [s] (paused: whole `step`s)."""
    out = []
    while s.t < t_end - 1e-9:
        r = s.advance(0.05, 1.0)
        if r is not None:
            out.append(r[-1])
    return np.array(out)


def _sway(records: np.ndarray) -> np.ndarray:
    x = records[:, 1:4]
    return np.arctan2(np.hypot(x[:, 0], x[:, 1]), -x[:, 2])


@pytest.mark.parametrize("shaping", [0, 1, 2])
def test_a_trolley_move_sways_as_pendulab_crane_predicts(shaping: int) -> None:
    s = _session()
    s.apply(parse_command(json.dumps({"type": "set_params", "params": {"shaping": shaping}})))
    s.apply(parse_command(json.dumps({"type": "crane", "move": [5.0, 0.0]})))
    last = s.status()["crane"]["last_move"]
    assert last["shaping"] == ("off", "zv", "zvd")[shaping]
    period = 2 * math.pi * math.sqrt(ROPE / G)
    t0 = s.t
    records = _run(s, last["end"] + 1.5 * period)
    live = _sway(records[records[:, 0] >= last["end"]]).max()
    # pendulab.crane: its move profile and shaper, the crane model simulated from rest
    omega = math.sqrt(G / ROPE)
    shaper = None if shaping == 0 else crane.shaper(("zv", "zvd")[shaping - 1], omega=omega)
    path = crane.move(distance=5.0, v_max=0.5, a_max=0.25, shaper=shaper, t_start=t0)
    run = crane.Crane(rope=ROPE, pivot=path, payload_mass=MASS, g=G).simulate(
        t_end=last["end"] + 1.5 * period, t_start=t0, output_spacing=0.05
    )
    reference = run.sway[run.t >= last["end"], 0].max()
    assert records[-1, 14] == pytest.approx(5.0, abs=1e-9)  # the trolley stopped after 5 m
    if shaping == 0:
        assert live == pytest.approx(reference, rel=2e-3)
        assert live == pytest.approx(last["residual_unshaped"], rel=0.01)  # the linear prediction
    else:
        assert last["residual_shaped"] < 1e-12
        assert live < 0.01 * last["residual_unshaped"] and reference < 0.01 * last["residual_unshaped"]
        assert live == pytest.approx(reference, abs=2e-4)


def test_hoisting_changes_the_rope_length_live() -> None:
    s = _session()
    s.apply(parse_command('{"type": "crane", "rope": 6.0}'))
    records = _run(s, s.t + 12.0)
    rope = np.linalg.norm(records[:, 1:4], axis=1)
    assert rope[0] > 9.5 and rope[-1] == pytest.approx(6.0, abs=1e-9)
    assert np.all(np.diff(rope) <= 1e-12)  # shortening only, at most 0.5 m/s
    assert np.all(-np.diff(rope) <= 0.5 * 0.05 + 1e-9)
    assert s.status()["crane"]["rope"] == pytest.approx(6.0, abs=1e-12)


def test_crane_commands_are_checked() -> None:
    with pytest.raises(CommandError, match="unknown key 'speed'"):
        parse_command('{"type": "crane", "speed": 1}')
    s = Session(resolve_scenario("rosette"))
    with pytest.raises(CommandError, match="not in the crane mode"):
        s.apply(parse_command('{"type": "crane", "move": [1.0, 0.0]}'))
    s = _session()
    with pytest.raises(CommandError, match="v_max"):
        s.apply(parse_command('{"type": "crane", "drive": [1.0, 0.0]}'))
    with pytest.raises(CommandError, match=r"0\.5 to 200 m"):
        s.apply(parse_command('{"type": "crane", "rope": 500.0}'))


def test_a_crane_file_opens_the_crane_mode_with_its_crane() -> None:
    """``crane_hoist.toml`` (12 m rope, 2 t, ZV, v_max 0.8 m/s, a_max 0.4 m/s², 8 m/s cross wind on
    2 m² × 1.2) loads as the crane mode's crane, hanging at rest; its wind blows the load out along y."""
    s = Session(resolve_scenario("rosette"))
    s.apply(parse_command('{"type": "load_scenario", "name": "crane_hoist"}'))
    st = s.status()
    c = st["crane"]
    assert st["model"] == "crane" and st["method"] == "dop853" and st["params"]["mass"] == 2000.0
    assert c["rope"] == 12.0 and c["shaping"] == "zv" and c["wind"] == [0.0, 8.0, 0.0]
    assert (c["v_max"], c["a_max"], c["drag_area"]) == (0.8, 0.4, pytest.approx(2.4))
    records = _run(s, 3.0)
    assert records[-1, 2] > 0.0  # downwind
    force = 0.5 * 1.225 * 2.4 * 8.0**2
    peak = _sway(records).max()
    assert peak > 1.5 * math.atan(force / (2000.0 * G))  # the first swing overshoots the static angle


def test_a_crane_load_of_tonnes_can_be_set_as_a_share_link_sets_it() -> None:
    """A share link or the mass field sets the crane file's 2 t load with ``set_params`` (the lab's mass
    limit is 1e5 kg, docs/web.md "Commands"); beyond it the refusal names the value and the range."""
    s = Session(resolve_scenario("crane_hoist"))
    s.apply(parse_command('{"type": "set_params", "mass": 2000.0}'))
    assert s.status()["params"]["mass"] == 2000.0
    s.apply(parse_command('{"type": "set_params", "mass": 50000.0}'))
    assert s.status()["params"]["mass"] == 50000.0
    with pytest.raises(CommandError, match=r"mass = 200000: input should be less than or equal to 100000"):
        parse_command('{"type": "set_params", "mass": 200000.0}')
