"""A typo of a required key is one problem, not two: ``lenght = 2`` in [pendulum] was reported as the
unknown key (with its did-you-mean) and again as "pendulum.length is missing". Now the unknown key's
line says that the required key is therefore missing, and the missing key is not listed again; the
same for a misspelt table ([pendlum]), for crane files ([crane], [shaper], [simulaton]) and for the
``sampled_pivot`` model's pivot keys, which the allowed keys now list."""

from __future__ import annotations

from typing import Any

import pytest
from conftest import SCENARIOS

import pendulab as pl
from pendulab import crane
from pendulab.crane.scenario import parse

ROSETTE = (SCENARIOS / "rosette.toml").read_text(encoding="utf-8")


def problems(text: str) -> list[str]:
    with pytest.raises(pl.ScenarioError) as e:
        pl.Scenario.from_toml_str(text, "f.toml")
    return e.value.problems


def test_a_misspelt_required_key_is_one_problem() -> None:
    found = problems(ROSETTE.replace("length = 1.0", "lenght = 1.0", 1))
    assert found == [
        "unknown key pendulum.lenght = 1.0 (did you mean 'length'? so the required pendulum.length is "
        "missing); allowed keys in [pendulum] for model 'ideal': model, length, mass, g"
    ]


def test_other_problems_are_still_listed() -> None:
    """A second, unrelated missing key and a typo of an optional key keep their own lines."""
    text = ROSETTE.replace("length = 1.0", "lenght = 1.0", 1).replace("mass = 1.0", "", 1)
    text = text.replace("theta_deg = 60.0", "theta_dg = 60.0", 1)
    found = problems(text)
    assert len(found) == 3, found
    assert found[0].startswith("unknown key pendulum.lenght = 1.0 (did you mean 'length'? so the required")
    assert found[1].startswith("unknown key initial.theta_dg = 60.0 (did you mean 'theta_deg'?);"), found
    assert found[2].startswith("pendulum.mass is missing; expected bob mass m"), found


def test_two_typos_of_one_key_name_it_missing_once() -> None:
    text = ROSETTE.replace("length = 1.0", "lenght = 1.0\nlengh = 2.0", 1)
    found = problems(text)
    assert len(found) == 2 and sum("so the required pendulum.length is missing" in p for p in found) == 1


def test_a_misspelt_table_is_one_problem() -> None:
    found = problems(ROSETTE.replace("[pendulum]", "[pendlum]", 1))
    assert len(found) == 1, found
    assert found[0].startswith("unknown key pendlum = {")
    assert "(did you mean 'pendulum'? so the required table [pendulum] is missing)" in found[0]


def test_the_sampled_pivot_keys_are_suggested_and_listed() -> None:
    """The allowed keys of model 'sampled_pivot' left out pivot_times and pivot_positions, so a typo of
    them had no did-you-mean."""
    times = ", ".join(str(k) for k in range(4))
    text = ROSETTE.replace('model = "ideal"', 'model = "sampled_pivot"', 1).replace(
        "mass = 1.0",
        f"mass = 1.0\npivot_time = [{times}]\npivot_positions = [{', '.join(['[0, 0, 0]'] * 4)}]",
        1,
    )
    (found,) = problems(text)
    assert found.startswith("unknown key pendulum.pivot_time = [0, 1, 2, 3] (did you mean 'pivot_times'?)")
    assert found.endswith("model, length, mass, g, damping, pivot_times, pivot_positions"), found


@pytest.mark.parametrize(
    ("data", "want"),
    [
        (
            {"crane": {"rop": 10.0, "payload_mass": 1000.0}, "simulation": {"t_end": 5.0}},
            "unknown key crane.rop = 10.0 (did you mean 'rope'? so the required crane.rope is missing)",
        ),
        (
            {"crane": {"rope": 10.0, "payload_mass": 1000.0}, "simulaton": {"t_end": 5.0}},
            "unknown key simulaton = {t_end = 5.0} (did you mean 'simulation'? so the required table "
            "[simulation] is missing)",
        ),
        (
            {
                "crane": {"rope": 10.0, "payload_mass": 1.0},
                "simulation": {"t_end": 5.0},
                "shaper": {"knd": "zv"},
            },
            "unknown key shaper.knd = 'zv' (did you mean 'kind'? so the required shaper.kind is missing)",
        ),
    ],
)
def test_crane_files_too(data: dict[str, Any], want: str) -> None:
    with pytest.raises(crane.CraneFileError) as e:
        parse(data, "c.toml")
    assert len(e.value.problems) == 1 and e.value.problems[0].startswith(want), e.value.problems
    with pytest.raises(pl.ScenarioError) as s:  # the same file read as a scenario
        pl.Scenario.from_dict(data, "c.toml")
    assert len(s.value.problems) == 1 and s.value.problems[0].startswith(want), s.value.problems
