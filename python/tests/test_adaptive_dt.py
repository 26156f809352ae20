"""One rule for dt of an adaptive method (``dop853``), and files that say what an adaptive run is.

dt is its first step: > 0 (in [1e-12, 1e6] s) or left out (None: chosen automatically), in
``pl.simulate``, ``pl.Stepper``, ``--dt`` and scenario files alike; ``pl.simulate(dt=0.0)`` was taken as
"automatic" while the CLI and scenario files refused it. What the lab and the fit write for an adaptive
run carries its tolerances and no dt (a dt there would be read back as the first step): the lab's
``status`` says ``rtol`` and ``atol``, ``POST /api/scenario.toml`` writes them without dt, the fit's
scenario has no dt for ``dop853``. The method's "adaptive" flag is read from one table
(``integrators._method_table``)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
import pendulab._core
from pendulab import io
from pendulab.scenario import ScenarioError

ROSETTE = Path(__file__).resolve().parents[2] / "examples" / "scenarios" / "rosette.toml"


@pytest.fixture
def start() -> tuple[pl.Pendulum, pl.State]:
    p = pl.Pendulum()
    return p, p.state_from_angles(theta=0.5, phi_dot=1.0)


@pytest.mark.parametrize("dt", [0.0, 0, -1e-3, float("nan"), 1e-13])
def test_simulate_and_stepper_refuse_dt_0_for_dop853_naming_the_value_and_the_rule(start, dt) -> None:
    p, s0 = start
    rule = r"invalid dt = .*: a finite number in \[1e-12, 1e6\] s \(the first step of dop853\), or None"
    with pytest.raises(pl.InvalidInputError, match=rule):
        pl.simulate(p, s0, 1.0, method="dop853", dt=dt)
    with pytest.raises(pl.InvalidInputError, match=rule):
        pl.Stepper(p, s0, method="dop853", dt=dt)


def test_dop853_without_dt_chooses_its_first_step_and_a_given_one_is_kept(start) -> None:
    p, s0 = start
    auto = pl.simulate(p, s0, 1.0, method="dop853")
    assert "first_step" not in auto.options and "dt" not in auto.options
    given = pl.simulate(p, s0, 1.0, method="dop853", dt=1e-4)
    assert given.options["first_step"] == 1e-4
    np.testing.assert_allclose(given.x[-1], auto.x[-1], atol=1e-8)


def test_the_cli_and_scenario_files_refuse_dt_0_as_simulate_does(tmp_path: Path) -> None:
    text = ROSETTE.read_text(encoding="utf-8")
    assert "dt = 1.0e-3" in text and 'method = "rattle"' in text
    bad = tmp_path / "zero.toml"
    bad.write_text(text.replace("dt = 1.0e-3", "dt = 0.0").replace('"rattle"', '"dop853"'), encoding="utf-8")
    with pytest.raises(ScenarioError, match=r"simulation\.dt = 0\.0"):
        pl.load_scenario(bad)
    assert_user_error(*invoke("run", str(ROSETTE), "--method", "dop853", "--dt", "0"), "dt", "0")


def test_adaptive_is_read_from_the_integrators_table(monkeypatch) -> None:
    """io._adaptive scanned ``_core.methods()`` on every call; it reads ``integrators._method_table``."""
    pl.integrators._method_table()  # the table, built once

    def scan() -> None:
        raise AssertionError("the core's list scanned again")

    monkeypatch.setattr(pendulab._core, "methods", scan)
    assert io._adaptive("dop853") and not io._adaptive("rattle") and not io._adaptive("euler")
    assert not io._adaptive(None)


def _lab_body(method: str, **extra: object) -> dict[str, object]:
    p = pl.Pendulum()
    st = p.state_from_angles(1.0, 0.5, 0.1, 1.5)
    body = {"model": "ideal", "length": 1.0, "mass": 1.0, "g": 9.81, "params": {}}
    return body | {"x": st.x.tolist(), "v": st.v.tolist(), "method": method, "t0": 0.0, "t_end": 5.0} | extra


def test_the_labs_toml_of_an_adaptive_run_has_its_tolerances_and_no_dt() -> None:
    from pendulab.server.rest import ScenarioRequest, scenario_toml

    text = scenario_toml(ScenarioRequest(**_lab_body("dop853", dt=1e-3, rtol=1e-8, atol=1e-11)))
    sim = pl.Scenario.from_toml_str(text).spec.simulation
    assert sim.dt is None and (sim.rtol, sim.atol) == (1e-8, 1e-11), text
    bare = pl.Scenario.from_toml_str(scenario_toml(ScenarioRequest(**_lab_body("dop853", dt=1e-3))))
    assert bare.spec.simulation.dt is None and bare.spec.simulation.rtol is None
    fixed = scenario_toml(ScenarioRequest(**_lab_body("rattle4", dt=2e-3, rtol=1e-8)))
    sim = pl.Scenario.from_toml_str(fixed).spec.simulation
    assert sim.dt == 2e-3 and sim.rtol is None


def test_the_labs_status_says_the_tolerances_it_runs_with(tmp_path: Path) -> None:
    from pendulab.server.session import Session, resolve_scenario

    path = tmp_path / "tight.toml"
    text = ROSETTE.read_text(encoding="utf-8").replace('method = "rattle"', 'method = "dop853"')
    path.write_text(text.replace("dt = 1.0e-3", "rtol = 1e-8\natol = 1e-11"), encoding="utf-8")
    status = Session(resolve_scenario(path)).status()
    assert status["adaptive"] is True and (status["rtol"], status["atol"]) == (1e-8, 1e-11)


def test_the_fits_scenario_of_an_adaptive_model_has_no_dt() -> None:
    p = pl.Pendulum(length=0.5, model="damped", damping=0.05)
    t = np.linspace(0.0, 3.0, 120)
    tr = pl.simulate(p, p.state_from_angles(0.3), 3.0, method="dop853", save_at=t)
    angle = np.arctan2(tr.x[:, 0], -tr.x[:, 2])
    res = pl.fit(t, planar_angle=angle, pendulum=pl.Pendulum(length=0.5, model="damped"), fit=["damping"])
    sim = pl.Scenario.from_toml_str(res.to_scenario().to_toml()).spec.simulation
    assert sim.method == "dop853" and sim.dt is None
