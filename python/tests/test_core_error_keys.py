"""The core's common refusals carry a message key (docs/web.md, "Languages"): an ``IntegrationError`` or
``InvalidInputError`` of a diverged solution, a pole, a state off the sphere or a bad parameter has
``key`` and ``values`` (``pendulab/server/messages.json``) beside its English words, and the lab server's
422 answer of such a refusal in an analysis worker is keyed (the page words it in en/de/fr). Times in s,
step sizes in s, residuals dimensionless; every number written as a user writes it (``-1``, ``0.01``,
``1e-9``; ``pendulab_core::error::Shown``), never ``-1e0``."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

import pendulab as pl
from pendulab.server.app import _unprocessable
from pendulab.server.notices import MESSAGES, message
from pendulab.server.worker import WorkInvalid, _keyed


def _refusal(run: object) -> BaseException:
    with pytest.raises((pl.IntegrationError, pl.InvalidInputError)) as e:
        run()  # type: ignore[operator]
    return e.value


def test_a_diverged_solution_is_keyed_with_time_method_and_step() -> None:
    p = pl.Pendulum()
    e = _refusal(
        lambda: pl.simulate(p, p.state_from_angles(1.0, 0, 0, 0), t_end=100.0, dt=10.0, method="rk4")
    )
    assert isinstance(e, pl.IntegrationError)
    # the last state known finite: rk4 does not check its steps, the save at t = 20 s found it not finite
    assert (e.key, e.values) == ("diverged", {"t": "10", "method": "rk4", "dt": "10"})  # type: ignore[attr-defined]
    assert "after t = 10 s with method 'rk4' (dt = 10 s)" in str(e)  # as the user wrote them, not 1e1


def test_a_pole_of_the_angle_equations_is_keyed_with_its_time() -> None:
    p = pl.Pendulum()
    e = _refusal(lambda: pl.simulate(p, p.state_from_angles(1e-9, 0, 0, 5.0), t_end=1.0, method="rk4_angles"))
    assert (e.key, e.values) == ("near_pole", {"t": "0"})  # type: ignore[attr-defined]


def test_a_start_off_the_sphere_is_keyed_with_its_residual() -> None:
    p = pl.Pendulum()
    e = _refusal(lambda: pl.simulate(p, pl.State(np.array([0.5, 0, -0.5]), np.zeros(3)), t_end=1.0))
    assert e.key == "off_sphere"  # type: ignore[attr-defined]
    # the residual as the English words write it (was rounded to 4 significant digits, -0.2929)
    assert e.values == {"what": "(|x| - l)/l", "value": "-0.2928932188134524", "tolerance": "1e-9"}  # type: ignore[attr-defined]
    assert "(|x| - l)/l = -0.2928932188134524 exceeds the tolerance 1e-9" in str(e)


def test_a_parameter_out_of_range_is_keyed_with_name_value_and_range() -> None:
    p = pl.Pendulum()
    e = _refusal(
        lambda: pl.simulate(p, p.state_from_angles(1.0, 0, 0, 0), t_end=1.0, method="dop853", rtol=-1.0)
    )
    assert e.key == "invalid_parameter"  # type: ignore[attr-defined]
    assert e.values["name"] == "rtol" and e.values["value"] == "-1"  # type: ignore[attr-defined]
    assert "invalid rtol = -1: " in str(e)  # as the user wrote it (was -1e0)
    assert "[1e-15, 1]" in e.values["allowed"]  # type: ignore[attr-defined]


def test_a_keyed_core_refusal_answers_422_with_key_and_values() -> None:
    p = pl.Pendulum()
    e = _refusal(
        lambda: pl.simulate(p, p.state_from_angles(1.0, 0, 0, 0), t_end=100.0, dt=10.0, method="rk4")
    )
    key, values = _keyed(e)  # as the analysis worker passes it on
    answer = _unprocessable(WorkInvalid(str(e), key, values))
    body = json.loads(bytes(answer.body))
    assert answer.status_code == 422
    assert body == {"detail": " ".join(str(e).split()), "key": "diverged", "values": values}
    assert "{" not in message(body["key"], **body["values"])  # every placeholder filled


def test_every_core_key_has_english_words() -> None:
    for key in (
        "step_too_small",
        "diverged",
        "diverged_rattle",
        "diverged_dop853",
        "diverged_dt",
        "near_pole",
        "not_finite",
        "off_sphere",
        "invalid_parameter",
        "unknown_model",
        "integration_stopped",
    ):
        assert key in MESSAGES


def test_a_run_that_blows_up_is_a_divergence_not_bad_input() -> None:
    # g = 1000 m/s² at dt = 0.05 s: the angles' RK4 blows up, and the speed it rebuilt from its angles (above
    # 1e7 m/s, or not finite) was refused as "invalid speed = 49745656823029380", as if the user had given it
    p = pl.Pendulum(g=1000.0)
    start = p.state_from_angles(1.0, 0, 0, 2.0)
    e = _refusal(lambda: pl.simulate(p, start, t_end=5.0, dt=0.05, method="rk4_angles"))
    assert isinstance(e, pl.IntegrationError), repr(e)
    # the step from t = 0.05 s diverged: the last state computed, where the run stands (was its end, 0.1 s)
    assert (e.key, e.values) == ("diverged", {"t": "0.05", "method": "rk4_angles", "dt": "0.05"})  # type: ignore[attr-defined]
    words = str(e)
    assert words.startswith(
        "the integration diverged after t = 0.05 s with method 'rk4_angles' (dt = 0.05 s)"
    ), words
    assert words.endswith(
        "reduce dt, or use an adaptive ('dop853') or structure-preserving ('rattle') method"
    )
    assert "speed" not in words and "invalid" not in words
    assert "{" not in message("diverged", **e.values)  # type: ignore[attr-defined]
    # the same start at dt = 1 ms runs
    assert pl.simulate(p, start, t_end=1.0, dt=1e-3, method="rk4_angles").t[-1] == 1.0


def test_a_speed_the_user_gives_is_still_refused_as_input() -> None:
    p = pl.Pendulum()
    for run in (
        lambda: p.state_from_angles(1.0, 0, 1e8, 0),
        lambda: pl.simulate(p, pl.State(np.array([0, 0, -1.0]), np.array([2e7, 0, 0])), t_end=1.0),
    ):
        e = _refusal(run)
        assert isinstance(e, pl.InvalidInputError) and e.key == "invalid_parameter", repr(e)  # type: ignore[attr-defined]
        assert re.match(r"invalid speed = (1e8|2e7): a speed \|v\| <= 1e7 m/s$", str(e)), str(e)
