"""Every "did you mean" hint comes from one function, ``pendulab.validate.did_you_mean``: a name equal
to the one given but for case first (which difflib's ratio misses: 'DAMPING' is nowhere near
'damping' for it), else difflib's closest, else no hint. Checked at each place that names an unknown
key: Pendulum's keywords, a scenario file's keys, a sweep's axes, quantities and file keys; and
``pl.load_scenario`` naming a missing file as it was given."""

from __future__ import annotations

from pathlib import Path

import pytest

import pendulab as pl
from pendulab.sweeps.file import SweepFileError, sweep_file_from_dict

SCENARIO = """
[pendulum]
length = 1.0
mass = 1.0
g = 9.81
{pendulum}
[initial]
theta_deg = 30.0
{initial}
[simulation]
t_end = 0.1
"""


def _hint(expected: str | None) -> str:
    """The hint naming ``expected``; for None, any hint (which the message must not have)."""
    return f"(did you mean '{expected}'?)" if expected else "did you mean"


@pytest.mark.parametrize(
    ("given", "expected"), [("DAMPING", "damping"), ("dampnig", "damping"), ("zzzz", None)]
)
def test_pendulum_keyword_no_model_has(given: str, expected: str | None) -> None:
    with pytest.raises(pl.InvalidInputError, match=f"no model has a parameter '{given}'") as e:
        pl.Pendulum(**{given: 0.1})
    assert (_hint(expected) in str(e.value)) is (expected is not None), str(e.value)


@pytest.mark.parametrize(("given", "expected"), [("DRAG", "drag"), ("dragg", "drag"), ("zzzz", None)])
def test_pendulum_keyword_the_model_has_not(given: str, expected: str | None) -> None:
    with pytest.raises(pl.InvalidInputError, match=f"the 'damped' model has no parameter '{given}'") as e:
        pl.Pendulum(model="damped", **{given: 0.1})
    assert (_hint(expected) in str(e.value)) is (expected is not None), str(e.value)


DAMPING_OWNERS = "model 'damped' (and 'rotating', 'slewing', 'vibrating', 'hoisted', 'sampled_pivot')"


@pytest.mark.parametrize(
    ("model", "keyword", "message"),
    [
        (
            "ideal",
            "damping",
            f"invalid parameter damping = 0.1: damping is a parameter of {DAMPING_OWNERS}, not of 'ideal'; "
            "its parameters: length, mass, g",
        ),
        (  # the wrong case of another model's parameter: named, with that model (was: no hint at all)
            "ideal",
            "DAMPING",
            "invalid parameter DAMPING = 0.1: the 'ideal' model has no parameter 'DAMPING' (did you mean "
            f"'damping'?); damping is a parameter of {DAMPING_OWNERS}, not of 'ideal'; "
            "its parameters: length, mass, g",
        ),
        (
            "spring",
            "Frame_Rate",
            "invalid parameter Frame_Rate = 0.1: the 'spring' model has no parameter 'Frame_Rate' (did you "
            "mean 'frame_rate'?); frame_rate is a parameter of model 'rotating', not of 'spring'; "
            "its parameters: length, mass, g, stiffness",
        ),
        (  # the model's own parameter in the wrong case: only the hint, no other model
            "rotating",
            "DAMPING",
            "invalid parameter DAMPING = 0.1: the 'rotating' model has no parameter 'DAMPING' (did you mean "
            "'damping'?); its parameters: length, mass, g, ",
        ),
    ],
)
def test_pendulum_keyword_of_another_model_names_that_model(model: str, keyword: str, message: str) -> None:
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Pendulum(model=model, **{keyword: 0.1})
    assert str(e.value).startswith(message), str(e.value)
    assert str(e.value).count("is a parameter of") == (model != "rotating"), str(e.value)


@pytest.mark.parametrize(
    ("model", "key", "where"),
    [
        ("ideal", "damping", f"damping is a parameter of {DAMPING_OWNERS}, not of 'ideal'"),
        (
            "ideal",
            "DAMPING",
            "the 'ideal' model has no parameter 'DAMPING' (did you mean 'damping'?); "
            f"damping is a parameter of {DAMPING_OWNERS}, not of 'ideal'",
        ),
        ("spring", "frame_rate", "frame_rate is a parameter of model 'rotating', not of 'spring'"),
    ],
)
def test_a_scenario_key_of_another_model_is_worded_as_pendulums_keyword(
    model: str, key: str, where: str
) -> None:
    """A file's key of another model was ``(a parameter of the models 'damped', …, not of 'ideal': set model
    = 'damped'?)``; now the words of ``pl.Pendulum(model=…, KEY=…)`` (registry.elsewhere), with the file's
    own start (the key as written) and end (the keys the model takes in [pendulum])."""
    with pytest.raises(pl.InvalidInputError) as python:
        pl.Pendulum(model=model, **{key: 0.1})
    assert f": {where}; its parameters: " in str(python.value), str(python.value)
    text = SCENARIO.format(pendulum=f'model = "{model}"\n{key} = 0.1', initial="")
    with pytest.raises(pl.ScenarioError) as e:
        pl.Scenario.from_toml_str(text, "s.toml")
    (problem,) = e.value.problems
    keys = "model, length, mass, g" + (", stiffness" if model == "spring" else "")
    assert problem == f"unknown key pendulum.{key} = 0.1: {where}; allowed keys in [pendulum] for model " + (
        f"'{model}': {keys}"
    ), problem


def test_a_scenario_key_in_degrees_of_another_model_names_that_model() -> None:
    text = SCENARIO.format(pendulum='model = "damped"\nlatitude_deg = 49.0', initial="")
    with pytest.raises(pl.ScenarioError) as e:
        pl.Scenario.from_toml_str(text, "s.toml")
    (problem,) = e.value.problems
    assert problem.startswith(
        "unknown key pendulum.latitude_deg = 49.0: latitude_deg is a parameter of model 'rotating', not of "
        "'damped'; allowed keys in [pendulum] for model 'damped': model, length, mass, g, damping, "
    ), problem


@pytest.mark.parametrize(
    ("pendulum", "initial", "needle", "expected"),
    [
        ("LENGTH = 2.0", "", "unknown key pendulum.LENGTH = 2.0", "length"),
        ("lenhgt = 2.0", "", "unknown key pendulum.lenhgt = 2.0", "length"),
        ("zzzz = 2.0", "", "unknown key pendulum.zzzz = 2.0", None),
        ("", "PHI_DOT = 1.0", "unknown key initial.PHI_DOT = 1.0", "phi_dot"),
        ("", "phi_dt = 1.0", "unknown key initial.phi_dt = 1.0", "phi_dot"),
        ("", "zzzz = 1.0", "unknown key initial.zzzz = 1.0", None),
    ],
)
def test_scenario_keys(pendulum: str, initial: str, needle: str, expected: str | None) -> None:
    with pytest.raises(pl.ScenarioError) as e:
        pl.Scenario.from_toml_str(SCENARIO.format(pendulum=pendulum, initial=initial), "s.toml")
    (problem,) = e.value.problems
    assert problem.startswith(needle), problem
    assert (_hint(expected) in problem) is (expected is not None), problem


@pytest.mark.parametrize(("given", "expected"), [("THETA0", "theta0"), ("thta0", "theta0"), ("zzzz", None)])
def test_sweep_axis(given: str, expected: str | None) -> None:
    with pytest.raises(pl.InvalidInputError, match=f"unknown axis '{given}'") as e:
        pl.sweep({given: [0.1]}, "period")
    assert (_hint(expected) in str(e.value)) is (expected is not None), str(e.value)


@pytest.mark.parametrize(("given", "expected"), [("PERIOD", "period"), ("perod", "period"), ("zzzz", None)])
def test_sweep_quantity(given: str, expected: str | None) -> None:
    with pytest.raises(pl.InvalidInputError, match=f"unknown quantity '{given}'") as e:
        pl.sweep({"theta0": [0.1]}, given)
    assert (_hint(expected) in str(e.value)) is (expected is not None), str(e.value)


@pytest.mark.parametrize(("given", "expected"), [("GRID", "grid"), ("gird", "grid"), ("zzzz", None)])
def test_sweep_file_key(given: str, expected: str | None) -> None:
    with pytest.raises(SweepFileError, match=f"unknown key {given}") as e:
        sweep_file_from_dict({"quantity": "period", "grid": {"theta0": [0.1]}, given: {}}, "s.toml")
    assert (_hint(expected) in str(e.value)) is (expected is not None), str(e.value)


@pytest.mark.parametrize("given", ["./nope.toml", "./nope", "sub/./nope.toml", "sub//nope.toml"])
def test_load_scenario_names_the_path_as_given(
    given: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Not as pathlib normalises it (``nope.toml``, ``sub/nope.toml``); a Path is shown as it prints."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "sub").mkdir()
    with pytest.raises(FileNotFoundError) as e:
        pl.load_scenario(given)
    assert str(e.value).startswith(f"{given}: No such file, and no example scenario"), str(e.value)
    with pytest.raises(FileNotFoundError, match=f"^{Path(given)}: No such file"):
        pl.load_scenario(Path(given))


def test_load_scenario_still_finds_the_example_of_a_dotted_name(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    assert pl.load_scenario("./rosette.toml").spec == pl.load_scenario("rosette").spec
