"""A method name in the wrong case (or misspelt) is refused with the nearest registered name, by the
Python API, a scenario file, the CLI and the lab's commands alike; the wrong case is never accepted."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest
from conftest import SCENARIOS
from typer.testing import CliRunner

import pendulab as pl
from pendulab import cli, simulation
from pendulab.integrators import unknown_method
from pendulab.validate import did_you_mean

FILE = """
[pendulum]
length = 1.0
mass = 1.0
g = 9.81
[initial]
theta_deg = 30.0
phi_dot = 1.0
[simulation]
t_end = 0.1
method = "{method}"
"""
RUN = dict(
    dt=None,
    rtol=1e-10,
    atol=1e-12,
    project=True,
    conserve=False,
    save_every=None,
    save_at=None,
    t0=0.0,
    progress=None,
    max_saved_bytes=None,
    drift="warn",
)
START = np.array([[0.0, 0.0, -1.0, 1.0, 0.0, 0.0]])  # one start (x, v) [m, m/s] on the unit sphere


@pytest.mark.parametrize(
    ("given", "hint"), [("RATTLE", "rattle"), ("Rattle4", "rattle4"), ("DOP853", "dop853")]
)
def test_simulate_names_the_method_in_the_right_case(given: str, hint: str) -> None:
    """pl.simulate and pl.Stepper say what every other entry point says (integrators.unknown_method)."""
    p, s = pl.Pendulum(), pl.Pendulum().state_from_angles(theta=0.5, phi_dot=1.0)
    message = unknown_method(given)
    assert message.startswith(f"unknown method '{given}' (did you mean '{hint}'?); available: rattle, ")
    with pytest.raises(pl.InvalidInputError) as e:
        pl.simulate(p, s, 0.1, method=given)
    assert str(e.value) == message
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Stepper(p, s, method=given)
    assert str(e.value) == message


@pytest.mark.parametrize("given", [3, None, b"rattle", ["rattle"]])
def test_stepper_and_simulate_word_a_method_that_is_no_string_as_everywhere(given: object) -> None:
    p, s = pl.Pendulum(), pl.Pendulum().state_from_angles(theta=0.5, phi_dot=1.0)
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Stepper(p, s, method=given)  # type: ignore[arg-type]
    assert str(e.value) == f"unknown method {given!r}; available: {', '.join(pl.method_names())}"
    if given is not None:  # simulate's None is its default method
        with pytest.raises(pl.InvalidInputError) as e:
            pl.simulate(p, s, 0.1, method=given)  # type: ignore[arg-type]
        assert str(e.value) == unknown_method(given)


def test_scenario_file_names_the_method_in_the_right_case() -> None:
    with pytest.raises(pl.ScenarioError, match=r"unknown method 'RATTLE' \(did you mean 'rattle'\?\)"):
        pl.Scenario.from_toml_str(FILE.format(method="RATTLE"), "m.toml")
    with pytest.raises(pl.ScenarioError, match=r"unknown method 'RK4' \(did you mean 'rk4'\?\)"):
        pl.Scenario.from_toml_str(FILE.format(method="rattle"), "m.toml").with_overrides(method="RK4")
    assert pl.Scenario.from_toml_str(FILE.format(method="rattle"), "m.toml").run().method == "rattle"


def test_cli_names_the_method_in_the_right_case() -> None:
    result = CliRunner().invoke(cli.app, ["run", str(SCENARIOS / "rosette.toml"), "--method", "RATTLE"])
    assert result.exit_code == 2, result.output
    assert "unknown method 'RATTLE' (did you mean 'rattle'?)" in result.stderr


def test_lab_commands_name_the_method_in_the_right_case() -> None:
    from pendulab.server.commands import SetMethod

    with pytest.raises(ValueError, match=r"did you mean 'rattle'\?"):
        SetMethod(type="set_method", method="RATTLE")


def test_did_you_mean_prefers_the_same_name_in_another_case() -> None:
    names = ["rattle", "rattle4", "rk4", "rk4_angles"]
    assert did_you_mean("RK4", names) == " (did you mean 'rk4'?)"  # not the closer-looking 'rattle4'
    assert did_you_mean("ratle", names) == " (did you mean 'rattle'?)"
    assert did_you_mean("zzzz", names) == ""
    assert did_you_mean(3, names) == ""
    with pytest.raises(pl.InvalidInputError, match=r"invalid drift = 'RAISE': .*did you mean 'raise'\?"):
        p = pl.Pendulum()
        pl.simulate(p, p.state_from_angles(theta=0.5, phi_dot=1.0), 0.1, drift="RAISE")


@pytest.mark.parametrize(("given", "hint"), [("RATTLE", "rattle"), ("ratle", "rattle"), ("zzzz", None)])
def test_sweeps_and_ensembles_refuse_an_unknown_method_as_everywhere(given: str, hint: str | None) -> None:
    """pl.sweep, `pendulab sweep --method`, pl.simulate_ensemble and the core runner of pl.simulate give
    the message a scenario file gives (integrators.unknown_method): the hint, and the registered names."""
    with pytest.raises(pl.ScenarioError) as e:
        pl.Scenario.from_toml_str(FILE.format(method=given), "m.toml")
    message = unknown_method(given)
    assert message in str(e.value)
    assert (f"(did you mean '{hint}'?)" in message) is (hint is not None), message
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep({"theta0": [0.1]}, "max_sway", t_end=0.1, method=given)
    assert str(e.value) == message
    result = CliRunner().invoke(cli.app, ["sweep", "rotation_number", "--method", given, "--out", "unused"])
    assert result.exit_code == 2, result.output
    assert result.stderr.strip() == f"error: --method: {message}"
    p = pl.Pendulum()
    with pytest.raises(pl.InvalidInputError) as e:
        pl.simulate_ensemble(p, START, 0.1, method=given)
    assert str(e.value) == message
    start = p.state_from_angles(theta=0.5, phi_dot=1.0)
    run = simulation.check_run(p, 0.1, **{**RUN, "method": "rattle"})
    with pytest.raises(pl.InvalidInputError) as e:
        simulation._run_in_core(p, start, dataclasses.replace(run, method=given))
    assert str(e.value) == message


def test_a_registered_method_sweeps_do_not_run_is_named_so() -> None:
    """rk4 is registered but not vectorised: refused with the methods that sweeps and ensembles run."""
    with pytest.raises(pl.InvalidInputError, match=r"method = 'rk4': sweeps integrate with 'rattle', "):
        pl.sweep({"theta0": [0.1]}, "max_sway", t_end=0.1, method="rk4")
    with pytest.raises(pl.InvalidInputError, match=r"method = 'rk4': simulate_ensemble runs 'rattle' "):
        pl.simulate_ensemble(pl.Pendulum(), START, 0.1, method="rk4")
