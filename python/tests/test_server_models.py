"""The lab's server with the core's models (docs/web.md): the schema lists every model, a session switches
model and edits its parameters without losing it, frames carry time-dependent diagnostics, the net force
and the pivot; the core's command check agrees with the server's at the ends of its limits. The REST of
the models (scenario as TOML, V_eff): test_server_rest.py; many clients: test_server_robustness.py."""

from __future__ import annotations

import json
import re
from typing import Any

import numpy as np
import pytest
from fastapi.testclient import TestClient
from ws_session import LabClient, status_with, until

import pendulab as pl
from pendulab._core import InvalidInputError
from pendulab.server import FRAME_FIELDS, Session, create_app
from pendulab.server.protocol import LIMITS, MODEL_SPECS, CommandError, own_params, parse_command
from pendulab.server.session import resolve_scenario

F = {name: i for i, name in enumerate(FRAME_FIELDS)}
X, V, A, PIVOT = (slice(F[f"{k}1"], F[f"{k}1"] + 3) for k in ("x", "v", "a", "pivot"))


@pytest.fixture(scope="module")
def client() -> TestClient:
    return LabClient(create_app("rosette"))


def frames(k: str, v: Any) -> bool:
    return k == "frames"


def apply(s: Session, text: str) -> np.ndarray | None:
    return s.apply(parse_command(text))


# --- schema and scenarios -------------------------------------------------------------------------------


def test_schema_lists_every_model_of_the_registry_with_units_limits_and_slider_spans(
    client: TestClient,
) -> None:
    s = client.get("/api/schema").json()
    # the Stepper's models, and the spring and the string with their own steppers; sampled pivot: pendulab run
    lab = [m for m in pl.models() if m["interactive"] or m["name"] in ("spring", "string")]
    assert [m["name"] for m in s["models"]] == [m["name"] for m in lab]
    assert {"ideal", "damped", "rotating", "slewing", "vibrating"} <= {m["name"] for m in lab}
    for m, reg in zip(s["models"], lab, strict=True):
        assert m["label"] == reg["label"]
        own = [p for p in reg["params"] if p["name"] not in ("length", "mass", "g")]
        assert [p["name"] for p in m["params"]] == [p["name"] for p in own]
        for p, q in zip(m["params"], own, strict=True):
            assert (p["label"], p["unit"], p["default"], p["allowed"], p["description"]) == (
                q["label"],
                q["unit"],
                q["default"],
                q["allowed"],
                q["description"],
            )
            assert p["min"] == (q["min"] if np.isfinite(q["min"]) else None)
            assert p["max"] == (q["max"] if np.isfinite(q["max"]) else None)
            assert p["ui_min"] < p["ui_max"] and p["step"] > 0
            assert p["ui_min"] <= p["default"] <= p["ui_max"], p
    assert "set_model" in s["commands"]
    tail = ["power", "a1", "a2", "a3", "pivot1", "pivot2", "pivot3", "taut", "error_x"]
    assert s["frame"]["fields"][-9:] == tail


def test_schema_allowed_words_name_the_limits_the_lab_checks(client: TestClient) -> None:
    # the page's refusal of a typed value quotes `allowed` beside min … max: for length, mass and g it
    # quoted the core's wider range ("length = 5000 is not allowed: a number in [1e-6, 1e4] m
    # (0.001 … 1000 m)")
    s = client.get("/api/schema").json()
    params = s["model"]["params"] + [p for m in s["models"] for p in m["params"]]
    checked = 0
    for p in params:
        said = re.search(r"\[([-+0-9.e]+), ([-+0-9.e]+)\]", p["allowed"])  # in numbers: not [-π/2, π/2]
        if said is not None and p["min"] is not None and p["max"] is not None:
            assert (float(said[1]), float(said[2])) == (p["min"], p["max"]), p
            checked += 1
    assert checked >= 10, checked
    words = {p["name"]: p["allowed"] for p in s["model"]["params"]}
    assert words["length"] == "a number in [0.001, 1000] m", words
    assert words["g"] == "a number in [-1000, 1000] m/s^2 (any sign, 0 allowed)", words


def test_scenarios_carry_their_model(client: TestClient) -> None:
    listed = {s["name"]: s for s in client.get("/api/scenarios").json()}
    assert listed["damped"]["model"] == "damped" and listed["damped"]["model_params"]["damping"] > 0
    assert listed["rosette"]["model"] == "ideal" and listed["rosette"]["model_params"] == {}
    # the string and the swinging spring run in the lab too
    assert listed["string_slack"]["model"] == "string" and listed["string_slack"]["method"] == "rattle8"
    assert listed["swinging_spring"]["model"] == "spring"
    assert listed["swinging_spring"]["model_params"] == {"stiffness": 39.24}


# --- a session's model ----------------------------------------------------------------------------------


def test_changing_a_parameter_of_a_damped_session_keeps_the_damping_and_energy_decays(
    client: TestClient,
) -> None:
    with client.websocket_connect("/ws") as ws:
        ws.send_json({"type": "load_scenario", "name": "damped"})
        s = until(ws, status_with(scenario="damped"))
        damping = s["model_params"]["damping"]
        assert s["model"] == "damped" and damping > 0
        ws.send_json({"type": "set_params", "length": 1.5, "g": 9.0})
        s = until(ws, status_with(epoch=s["epoch"] + 1))
        assert s["model"] == "damped" and s["model_params"]["damping"] == damping  # the bug: it was lost
        assert s["params"] == {"length": 1.5, "mass": s["params"]["mass"], "g": 9.0}
        ws.send_json({"type": "set_params", "params": {"damping": 0.5}})
        s = until(ws, status_with(epoch=s["epoch"] + 1))
        assert s["model_params"]["damping"] == 0.5 and s["params"]["length"] == 1.5
        ws.send_json({"type": "set_time_scale", "time_scale": 20.0})
        rec = [until(ws, frames)]
        while rec[-1][-1, 0] - rec[0][0, 0] < 6.0:
            rec.append(until(ws, frames))
    r = np.concatenate(rec)
    energy, power = r[:, F["energy"]], r[:, F["power"]]
    assert energy[-1] < energy[0] - 0.5 * abs(energy[0] - (-1.5 * 9.0 * s["params"]["mass"]))
    assert np.all(power <= 1e-12)  # damping only takes energy out: P = −c m |v|²
    # and the numbers are those of a damped pendulum with these parameters
    p = pl.Pendulum(length=1.5, g=9.0, mass=s["params"]["mass"], model="damped", **s["model_params"])
    np.testing.assert_allclose(
        r[:, F["energy"]], p.diagnostics(r[:, X], r[:, V], r[:, 0])["energy"], atol=1e-12
    )


def test_set_model_switches_model_with_defaults_and_given_parameters() -> None:
    s = Session(resolve_scenario("rosette"))
    apply(s, '{"type": "set_model", "model": "vibrating", "params": {"amplitude": 0.02}}')
    st = s.status()
    assert st["model"] == "vibrating" and st["epoch"] == 1
    assert st["model_params"] == {"amplitude": 0.02, "frequency": 200.0, "damping": 0.0}
    assert st["params"] == {"length": 1.0, "mass": 1.0, "g": 9.81}
    apply(s, '{"type": "set_model", "model": "ideal"}')
    assert s.status()["model"] == "ideal" and s.status()["model_params"] == {}


@pytest.mark.parametrize(
    ("text", "needle"),
    [
        ('{"type": "set_model", "model": "sampled_pivot"}', "model 'sampled_pivot' does not run in the lab"),
        ('{"type": "set_model", "model": "spring", "params": {"stiffness": -1}}', "stiffness = -1:"),
        ('{"type": "set_model", "model": "string", "params": {"restitution": 2}}', "restitution"),
        ('{"type": "set_model", "model": "sprung"}', "unknown model 'sprung'; available: ideal, damped"),
        ('{"type": "set_model", "model": "damped", "params": {"lattitude": 1}}', "no parameter 'lattitude'"),
        (
            '{"type": "set_model", "model": "damped", "params": {"latitude": 1}}',
            "latitude is a parameter of model 'rotating', not of 'damped'; its parameters: length, mass, g, "
            "damping, drag,",
        ),
        ('{"type": "set_model", "model": "damped", "params": {"damping": -1}}', "damping = -1:"),
        ('{"type": "set_model", "model": "rotating", "params": {"latitude": 2}}', "latitude = 2:"),
        ('{"type": "set_model", "model": "damped", "params": {"damping": -0.01}}', "damping = -0.01:"),
        ('{"type": "set_model", "model": "damped", "params": {"damping": "a"}}', "valid number"),
        ('{"type": "set_params", "params": {"dampling": 0.1}}', "'ideal' model has no parameter 'dampling'"),
        (
            '{"type": "set_params", "params": {"damping": 0.1}}',
            "damping is a parameter of model 'damped' (and 'rotating', ",
        ),
        ('{"type": "set_params", "params": {}}', "at least one"),
    ],
)
def test_bad_models_and_parameters_are_refused_naming_the_value(text: str, needle: str) -> None:
    s = Session(resolve_scenario("rosette"))
    before = s.status()
    with pytest.raises(CommandError, match=r".") as e:
        apply(s, text)
    assert needle in str(e.value), str(e.value)
    assert s.status() == before  # unchanged


def test_the_cores_refusal_of_a_parameter_is_worded_as_set_models() -> None:
    """``set_params`` with a parameter the model lacks is refused by the core
    (``crates/pendulab-core/src/live/no_parameter.rs``: the server's sessions and the one-file lab alike;
    the server rewrote it before), ``set_model`` by the server's check: for every lab model and every
    own parameter of the lab's models the same words, key and values — another model's parameter named
    with the models that have it, as ``pl.Pendulum`` words it; in its case, in upper case and for keys no
    model has (the two decide "near one of the model's own parameters" by one rule, difflib's:
    ``error::close_match`` in the core)."""
    for model in MODEL_SPECS:
        s = Session(resolve_scenario("rosette"))
        apply(s, json.dumps({"type": "set_model", "model": model}))
        mine = {p["name"] for p in own_params(model)}
        for key in sorted({p["name"] for other in MODEL_SPECS for p in own_params(other)} - mine):
            for sent in (key, key.upper(), "lenght", "dampnig", "Frame_Rate", "zzzz"):
                with pytest.raises(CommandError) as core:
                    apply(s, json.dumps({"type": "set_params", "params": {sent: 0.5}}))
                with pytest.raises(CommandError) as server:
                    parse_command(json.dumps({"type": "set_model", "model": model, "params": {sent: 0.5}}))
                got, want = core.value, server.value
                assert (str(got), got.key, got.values) == (str(want), want.key, want.values), (model, sent)


@pytest.mark.parametrize(
    ("key", "refusal", "words"),
    [
        # near friction by difflib: the hint of pl.Pendulum, so not the string's (the core named it)
        ("restitution", "unknown_parameter", "the 'damped' model has no parameter 'restitution'; "),
        # near no own parameter by difflib: the vibrating pendulum's (the core found forcing_amplitude)
        (
            "AMPLITUDE",
            "parameter_of_other_model",
            "the 'damped' model has no parameter 'AMPLITUDE' (did you mean 'amplitude'?); amplitude is a "
            "parameter of model 'vibrating', not of 'damped'; ",
        ),
        ("lenght", "unknown_parameter", "the 'damped' model has no parameter 'lenght'; "),
        (
            "stiffness",
            "parameter_of_other_model",
            "stiffness is a parameter of model 'spring', not of 'damped'; ",
        ),
    ],
)
def test_near_one_of_the_models_own_parameters_by_one_rule(key: str, refusal: str, words: str) -> None:
    """The lab's engine (``set_params``: crates/pendulab-core/tests/live.rs checks the same cases) and
    ``pl.Pendulum`` decide alike whether a key is near one of the model's own parameters (then only that
    hint) or another model's parameter (then that model named): ``validate.did_you_mean``'s rule."""
    s = Session(resolve_scenario("rosette"))
    apply(s, json.dumps({"type": "set_model", "model": "damped"}))
    with pytest.raises(CommandError) as core:
        apply(s, json.dumps({"type": "set_params", "params": {key: 0.5}}))
    assert str(core.value).startswith(words + "its parameters: "), str(core.value)
    assert core.value.key == refusal
    with pytest.raises(InvalidInputError) as python:
        pl.Pendulum(model="damped", **{key: 0.5})
    named = refusal.startswith("parameter_of")
    assert ("is a parameter of model" in str(python.value)) is named, python.value
    if named:
        assert f"invalid parameter {key} = 0.5: {words}its parameters: " in str(python.value), python.value


def test_a_method_that_refuses_the_model_leaves_the_session_unchanged() -> None:
    s = Session(resolve_scenario("rosette"))
    apply(s, '{"type": "set_method", "method": "rk4_angles"}')
    with pytest.raises(CommandError, match=r"rk4_angles|ideal"):
        apply(s, '{"type": "set_model", "model": "damped", "params": {"damping": 0.1}}')
    assert s.status()["model"] == "ideal" and s.pendulum.model == "ideal"


def test_frames_carry_time_dependent_diagnostics_net_force_and_the_moving_pivot() -> None:
    s = Session(resolve_scenario("rosette"))
    apply(s, '{"type": "set_model", "model": "vibrating", "params": {"amplitude": 0.05, "frequency": 30}}')
    s.apply(parse_command('{"type": "set_time_scale", "time_scale": 3.0}'))
    r = np.concatenate([s.advance(0.05) for _ in range(10)])
    t = r[:, 0]
    assert np.ptp(t) > 1.0
    p = s.pendulum
    d = p.diagnostics(r[:, X], r[:, V], t)
    np.testing.assert_allclose(r[:, F["tension"]], d["tension"], rtol=0, atol=1e-12)
    np.testing.assert_allclose(r[:, PIVOT], d["pivot"], rtol=0, atol=1e-15)
    np.testing.assert_allclose(r[:, PIVOT][:, 2], 0.05 * np.cos(30 * t), rtol=0, atol=1e-12)
    # at t = 0 the tension would differ: the pivot's acceleration A ν² cos νt enters it
    assert np.max(np.abs(r[:, F["tension"]] - p.diagnostics(r[:, X], r[:, V])["tension"])) > 1.0
    # net force m a = m(−g e₃ − p̈) − T x/l: the acceleration is ẍ relative to the pivot
    m, ell, g = p.mass, p.length, p.g
    pdd = np.zeros_like(r[:, X])
    pdd[:, 2] = -0.05 * 30**2 * np.cos(30 * t)
    want = -g * np.array([0, 0, 1.0]) - pdd - (r[:, F["tension"]] / (m * ell))[:, None] * r[:, X] / ell
    np.testing.assert_allclose(r[:, A], want, rtol=0, atol=1e-9)


def test_ideal_frames_have_zero_pivot_and_zero_power() -> None:
    s = Session(resolve_scenario("rosette"))
    r = s.records()
    assert np.all(r[:, PIVOT] == 0) and r[0, F["power"]] == 0


@pytest.mark.parametrize(
    ("kind", "key"),
    [
        ("set_params", "length"),
        ("set_params", "mass"),
        ("set_params", "g"),
        ("set_method", "dt"),
        ("set_time_scale", "time_scale"),
    ],
)
def test_the_cores_command_check_accepts_every_value_the_servers_accepts(kind: str, key: str) -> None:
    """The server checks a command with its pydantic models first, then the core's live session checks
    it again (``crates/pendulab-core/src/live/wire.rs``, the page's only check): at both ends of each of
    the server's ``LIMITS`` the core agrees, so no command the server accepts is refused by the core."""
    lim = LIMITS[key]
    for value in (lim["min"], lim["max"]):
        s = Session(resolve_scenario("rosette"))
        text = json.dumps({"type": kind, key: value})
        cmd = parse_command(text)  # the server's check
        s.core.apply(text)  # the core's: raises if it refused
        status = s.status()
        got = status["params"][key] if kind == "set_params" else status[key]
        assert got == value
        outside = value + abs(value) * 1e-9 if value == lim["max"] else value - abs(value) * 1e-9
        with pytest.raises(CommandError):
            parse_command(json.dumps({"type": kind, key: outside}))
        with pytest.raises(InvalidInputError, match=key):
            s.core.apply(json.dumps({"type": kind, key: outside}))
        assert cmd.type == kind
