"""Scenario files with the real-pendulum models (docs/theory.md §7): the model's own keys in [pendulum]
reach the core, round-trip through to_toml, and bad keys or values are named. SI units."""

from __future__ import annotations

import numpy as np
import pytest
from conftest import SCENARIOS

import pendulab as pl


def test_damped_and_slewing_scenarios_load_run_and_round_trip() -> None:
    for name, model in (("damped.toml", "damped"), ("slewing_crane.toml", "slewing")):
        sc = pl.load_scenario(SCENARIOS / name)
        p = sc.pendulum()
        assert p.model == model and p.extra, p
        again = pl.Scenario.from_toml_str(sc.to_toml())
        assert again == sc and again.pendulum().extra == p.extra
        tr = sc.run(t_end=0.5, progress=False)
        assert np.all(np.isfinite(tr.x))


def test_damping_from_a_file_decays_j3_like_exp_minus_ct() -> None:
    # J₃(t) = J₃(0) e^{−ct} exactly for linear damping (the RATTLE splitting keeps it to round-off)
    sc = pl.load_scenario(SCENARIOS / "damped.toml")
    tr = sc.run(t_end=5.0, method="rattle", progress=False)
    c = sc.pendulum().extra["damping"]
    assert abs(tr.j3[-1] - tr.j3[0] * np.exp(-c * 5.0)) < 1e-12 * abs(tr.j3[0])


@pytest.mark.parametrize(
    ("edit", "needle"),
    [
        (("damping = 0.05", "dampnig = 0.05"), "dampnig"),
        (("damping = 0.05", "damping = -1.0"), "damping"),
        (("damping = 0.05", 'damping = "a lot"'), "damping"),
        (('model = "damped"', 'model = "springy"'), "springy"),
    ],
)
def test_bad_model_keys_are_named(edit: tuple[str, str], needle: str) -> None:
    text = (SCENARIOS / "damped.toml").read_text().replace(*edit)
    with pytest.raises(pl.ScenarioError, match=needle):
        pl.Scenario.from_toml_str(text, source="damped.toml")


def test_models_command_lists_every_model_with_units() -> None:
    import json

    from typer.testing import CliRunner

    from pendulab.cli import app

    out = CliRunner().invoke(app, ["models", "--json"])
    assert out.exit_code == 0, out.output
    table = {m["name"]: m for m in json.loads(out.output)}
    assert {"ideal", "damped", "rotating", "slewing", "vibrating"} <= table.keys()
    damping = next(p for p in table["damped"]["params"] if p["name"] == "damping")
    assert damping["unit"] == "1/s" and damping["min"] == 0.0
    text = CliRunner().invoke(app, ["models"]).output
    assert "slewing" in text and "[rad/s]" in text
