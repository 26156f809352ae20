"""A method name in the wrong case (or misspelt) is refused with the nearest registered name, by the
Python API, a scenario file, the CLI and the lab's commands alike; the wrong case is never accepted."""

from __future__ import annotations

import pytest
from conftest import SCENARIOS
from typer.testing import CliRunner

import pendulab as pl
from pendulab import cli
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


@pytest.mark.parametrize(
    ("given", "hint"), [("RATTLE", "rattle"), ("Rattle4", "rattle4"), ("DOP853", "dop853")]
)
def test_simulate_names_the_method_in_the_right_case(given: str, hint: str) -> None:
    p, s = pl.Pendulum(), pl.Pendulum().state_from_angles(theta=0.5, phi_dot=1.0)
    with pytest.raises(pl.InvalidInputError, match=rf"invalid method = '{given}': .*did you mean '{hint}'\?"):
        pl.simulate(p, s, 0.1, method=given)
    with pytest.raises(pl.InvalidInputError, match=rf"did you mean '{hint}'\?"):
        pl.Stepper(p, s, method=given)


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
