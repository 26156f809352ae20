"""``[crane]`` in ordinary scenario files (docs/scenarios.md "Cranes"): ``pl.load_scenario``,
``pendulab validate`` and ``pendulab run`` read a crane's file, the shipped example validates, runs
and keeps its energy balance (E − E₀ − ΣW, the crane's works, in J) and gives the same run as the
crane module's own loader; bad contents are clear errors naming the file and the key; the pendulum's
accessors refuse a crane and the lab's scenario list leaves it out."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.crane.scenario import load as load_crane_file

EXAMPLE = SCENARIOS / "crane_hoist.toml"


def test_the_example_is_a_crane_scenario_that_round_trips_through_toml() -> None:
    sc = pl.load_scenario(EXAMPLE)
    assert sc.is_crane and sc.title.startswith("Gantry crane")
    assert sc.expected_samples() == 801  # 40 s every 0.05 s
    again = pl.Scenario.from_toml_str(sc.to_toml(), "<written>")
    assert again == sc and again.is_crane
    c = sc.crane()
    assert c.shaper is not None and c.shaper.kind == "zv"
    assert (
        repr(sc)
        == "Scenario('crane_hoist.toml': crane, rope=12 m, payload=2000 kg, hoisted, shaper zv; t=0…40 s)"
    )
    assert "sway modes" in sc._repr_html_() and "0.904" in sc._repr_html_()
    assert c.crane.hoist.length([14.0])[0] == pytest.approx(6.0)


def test_a_crane_scenario_runs_as_the_crane_module_runs_it() -> None:
    sc = pl.load_scenario(EXAMPLE).with_overrides(t_end=20.0)
    run = sc.run()
    direct = load_crane_file(EXAMPLE)
    ref = direct.crane.simulate(
        20.0, output_spacing=direct.output_spacing, rtol=direct.rtol, atol=direct.atol
    )
    np.testing.assert_array_equal(run.payload, ref.payload)
    scale = direct.crane.payload_mass * 9.81 * 12.0
    assert np.abs(run.energy_residual()).max() < 1e-9 * scale
    assert run.rope[-1] == pytest.approx(6.0)  # hoisted 12 m -> 6 m by t = 14 s


def test_validate_and_run_from_the_command_line(tmp_path: Path) -> None:
    code, text, err = invoke("validate", str(EXAMPLE), "rosette")
    assert code == 0, err
    assert "crane_hoist.toml: OK (Gantry crane" in text and "rosette: OK" in text
    out = tmp_path / "run.csv"
    code, text, err = invoke("run", "crane_hoist", "--t-end", "18", "--out", str(out))
    assert code == 0, err
    assert "sway modes 0.90416 rad/s; shaper zv" in text
    data = np.genfromtxt(out, delimiter=",", skip_header=1, names=True)  # after the # metadata line
    assert data["t_s"][-1] == pytest.approx(18.0)
    assert_user_error(*invoke("run", "crane_hoist", "--method", "rk4"), "takes no method")
    assert_user_error(*invoke("run", "crane_hoist", "--out", str(tmp_path / "x.parquet")), ".csv")


BASE = "[crane]\nrope = 10.0\n[simulation]\nt_end = 5.0\n"


@pytest.mark.parametrize(
    ("text", "needles"),
    [
        (
            "[crane]\nrope = -3.0\npayloadmass = 5.0\n[simulation]\nt_end = 1.0\n",
            ["crane.payloadmass = 5.0 (did you mean 'payload_mass'?)", "crane.rope = -3.0: must be >= 1e-6"],
        ),
        (BASE + "[pendulum]\nlength = 1.0\n", ["so [pendulum] does not belong in it"]),
        (BASE + "[initial]\ntheta = 1.0\n", ["[initial] does not belong"]),
        ("[crane]\nrope = 10.0\n", ["the table [simulation] is missing"]),
        (BASE.replace("t_end = 5.0", "t_end = nan"), ["simulation.t_end = nan"]),
        (
            BASE + "[move]\ndistance = 5.0\nv_max = 0.5\na_max = 0.5\n[shaper]\nkind = 'zzz'\n",
            ["shaper kind 'zzz'", "zv, zvd, zvdd, ei, 2hump_ei"],
        ),
        (BASE + "[shaper]\nkind = 'zv'\n", ["needs a [move]"]),
        (
            BASE + "[hoist]\nt = [0.0, 1.0]\nlength = [10.0, -1.0]\n",
            ["hoist.length[1] = -1.0: must be >= 1e-6"],
        ),
        (BASE + "[wind]\nvelocity = [1.0, 2.0]\n", ["wind.velocity = [1.0, 2.0]", "3 items"]),
        (BASE + "[simulation2]\nx = 1\n", ["unknown key simulation2", "allowed keys in the top level"]),
    ],
)
def test_bad_crane_files_are_clear_errors_naming_the_key(
    tmp_path: Path, text: str, needles: list[str]
) -> None:
    path = tmp_path / "bad.toml"
    path.write_text(text, encoding="utf-8")
    with pytest.raises(pl.ScenarioError) as e:
        pl.load_scenario(path)
    message = str(e.value)
    assert message.startswith(str(path)), message
    for needle in needles:
        assert needle in message, message
    code, _, err = invoke("validate", str(path))  # one error line per problem, exit code 2
    assert code == 2 and all(needle in err for needle in needles), err


def test_the_pendulum_accessors_refuse_a_crane_and_the_crane_accessor_a_pendulum() -> None:
    sc = pl.load_scenario(EXAMPLE)
    for call in (sc.pendulum, sc.initial_state):
        with pytest.raises(pl.ScenarioError, match=r"is a crane \(\[crane\]\), not a pendulum"):
            call()
    with pytest.raises(pl.ScenarioError, match="has no \\[crane\\] table"):
        pl.load_scenario(SCENARIOS / "rosette.toml").crane()


def test_the_labs_scenario_list_opens_the_crane_in_its_crane_mode() -> None:
    """The lab lists crane files too (its crane mode runs them, server/crane_setup.py): as the crane
    model with DOP853, the file's rope, load and shaper, and no entry with an error."""
    pytest.importorskip("fastapi")
    from pendulab.server.app import scenarios

    listed = {s["name"]: s for s in scenarios()}
    assert "rosette" in listed
    crane = listed["crane_hoist"]
    assert crane["model"] == "crane" and crane["method"] == "dop853", crane
    assert crane["params"]["length"] == 12.0 and crane["params"]["mass"] == 2000.0, crane
    assert crane["model_params"]["shaping"] == 1.0  # the file's ZV shaper
    assert not [s for s in listed.values() if "error" in s]
