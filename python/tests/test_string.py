"""The pendulum on a string from Python, scenario files and the CLI: a motion that never goes slack
is the rod pendulum's; the string leaves where the tension of T-2.3 vanishes, z* = 2E/(3 m g); flight
is the exact parabola; an elastic snap keeps E and an inelastic one loses exactly the radial kinetic
energy ½ m (x̂·v)²; bad settings are refused with the reason. SI units (m, kg, s, J)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS
from typer.testing import CliRunner

import pendulab as pl
from pendulab.cli import app

G = 9.81


def launch(p: pl.Pendulum, v0_squared: float) -> pl.State:
    """A planar launch from the bottom with speed √v0_squared [m/s] along e₁."""
    return p.state([0.0, 0.0, -p.length], [math.sqrt(v0_squared), 0.0, 0.0])


def test_never_slack_equals_the_rod(pendulum: pl.Pendulum, rosette: pl.State) -> None:
    string = pl.Pendulum(model="string")
    for method in ("rattle", "rattle4"):
        a = pl.simulate(pendulum, rosette, 2.0, method=method, dt=1e-3)
        b = pl.simulate(string, rosette, 2.0, method=method, dt=1e-3)
        assert b.taut is not None and b.taut.all() and len(b.events["t"]) == 0
        np.testing.assert_array_equal(a.t, b.t)
        np.testing.assert_array_equal(a.x, b.x)
        np.testing.assert_array_equal(a.v, b.v)


def test_slack_at_zero_tension_parabola_and_inelastic_snap() -> None:
    p = pl.Pendulum(length=1.5, g=G, mass=2.0, model="string")
    s0 = launch(p, 3.5 * G * 1.5)  # passes the horizontal (2 g l), cannot loop (5 g l)
    e0 = p.energy(s0)
    tr = pl.simulate(p, s0, 3.0, method="rattle8", dt=1e-3)
    ev = tr.events
    assert list(ev["kind"][:2]) == ["slack", "taut"]
    z_star = 2.0 * e0 / (3.0 * p.mass * G)  # T = (m/l)(2E/m − 3 g z) = 0
    assert z_star == pytest.approx(0.75, rel=1e-15)
    assert ev["x"][0, 2] == pytest.approx(z_star, abs=1e-12)
    assert abs(p.tension(pl.State(ev["x"][0], ev["v_after"][0]))) < 1e-12 * p.mass * G
    # flight: the parabola, inside the sphere, energy exact
    t_leave, t_snap = ev["t"][0], ev["t"][1]
    flying = (tr.t > t_leave) & (tr.t < t_snap)
    assert flying.sum() > 100 and not tr.taut[flying].any()
    tau = tr.t[flying] - t_leave
    want = ev["x"][0] + np.outer(tau, ev["v_after"][0]) - np.outer(0.5 * G * tau**2, [0.0, 0.0, 1.0])
    np.testing.assert_allclose(tr.x[flying], want, rtol=0, atol=1e-15)
    assert (np.linalg.norm(tr.x[flying], axis=1) < p.length).all()
    assert t_snap - t_leave == pytest.approx(4.0 * ev["v_after"][0, 2] / G, rel=1e-15)
    # inelastic snap: loses exactly ½ m (x̂·v)², the energy balance E + lost = E0 holds throughout
    n = ev["x"][1] / np.linalg.norm(ev["x"][1])
    radial_ke = 0.5 * p.mass * float(n @ ev["v_before"][1]) ** 2
    assert ev["energy_lost"][1] == pytest.approx(radial_ke, rel=1e-14)
    assert abs(float(n @ ev["v_after"][1])) < 1e-14 * np.linalg.norm(ev["v_after"][1])  # round-off
    assert np.max(np.abs(tr.energy + tr.energy_lost - e0)) < 1e-12 * abs(e0)
    assert (tr.tension[~tr.taut] == 0).all() and (tr.tension[tr.taut] >= -1e-9).all()


def test_elastic_snaps_keep_the_energy() -> None:
    p = pl.Pendulum(model="string", restitution=1.0)
    s0 = p.state_from_angles(0.2, 0.0, 5.5, 3.0)
    tr = pl.simulate(p, s0, 4.0, method="rattle8", dt=1e-3)
    assert list(tr.events["kind"]).count("taut") >= 3
    np.testing.assert_allclose(tr.events["energy_lost"], 0.0, atol=1e-13)
    e0 = p.energy(s0)
    assert np.max(np.abs(tr.energy - e0)) < 1e-11 * abs(e0)
    assert np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-12 * abs(tr.j3[0])


def test_scenario_and_cli(tmp_path: Path) -> None:
    sc = pl.load_scenario(SCENARIOS / "string_slack.toml")
    assert sc.pendulum().model == "string"
    assert pl.Scenario.from_toml_str(sc.to_toml()) == sc
    out = tmp_path / "string.csv"
    result = CliRunner().invoke(app, ["run", str(SCENARIOS / "string_slack.toml"), "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "went slack 1x, snapped taut 1x" in result.output
    header = out.read_text().splitlines()[1]
    assert "taut [1]" in header and "energy_lost [J]" in header
    assert '"kind": "slack"' in out.read_text().splitlines()[0]


@pytest.mark.parametrize(
    ("call", "needle"),
    [
        (lambda: pl.Pendulum(model="string", restitution=1.5), "restitution"),
        (lambda: pl.Pendulum(model="string", restitution=float("nan")), "restitution"),
        (
            lambda: pl.simulate(
                pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0), 1.0, method="dop853"
            ),
            "rattle4",
        ),
        (
            lambda: pl.simulate(pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0), 1.0, save_at=[0.5]),
            "save_at",
        ),
        (lambda: pl.Stepper(pl.Pendulum(model="string"), launch(pl.Pendulum(), 1.0)), "hybrid"),
    ],
)
def test_bad_settings_are_refused(call: object, needle: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=needle):
        call()  # type: ignore[operator]


def test_scenario_refuses_an_adaptive_method() -> None:
    text = (SCENARIOS / "string_slack.toml").read_text().replace('"rattle8"', '"dop853"')
    with pytest.raises(pl.ScenarioError, match="cannot integrate the 'string' model"):
        pl.Scenario.from_toml_str(text)
