"""The swinging spring from Python (T-7.4): E and J₃ conserved by the symplectic integrator, the
1:1:2 resonance exchanges energy between bouncing and swinging, bad input; the same from scenario
files (``model = "spring"``) and ``pendulab run``, with r, E and J₃ in the output. SI units."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS
from typer.testing import CliRunner

import pendulab as pl
from pendulab.cli import app


def test_resonant_exchange_and_conservation() -> None:
    sp = pl.SwingingSpring.resonant(1.0)
    assert np.isclose(np.sqrt(sp.k_over_m), 2 * np.sqrt(sp.g / sp.equilibrium_length))
    tr = pl.simulate_spring(
        sp, [0.01, 0.002, -1.05], [0.0, 0.003, 0.0], t_end=60.0, dt=1e-3, save_every=10, order=4
    )
    assert np.max(np.abs(tr.energy - tr.energy[0])) < 1e-8 * abs(tr.energy[0])
    assert np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-15
    b = tr.bouncing_energy
    assert b.min() < 0.1 * b[0], "energy must leave the bouncing mode at resonance"


def test_resonant_for_negative_g_is_the_mirror_image() -> None:
    """g < 0: the 1:1:2 resonance about the stable rest point above the pivot, k/m = 4|g|/l (was
    k/m = 4g/l < 0, which the core refused naming k_over_m only). Mirrored through z = 0, its run is
    the g > 0 run: the bouncing energy leaves the spring in the same way."""
    up, down = pl.SwingingSpring.resonant(1.0, g=-9.81), pl.SwingingSpring.resonant(1.0, g=9.81)
    assert (up.k_over_m, up.rest_length, up.g) == (down.k_over_m, down.rest_length, -9.81)
    assert up.equilibrium_length == pytest.approx(1.0, rel=1e-15)
    x0, v0 = np.array([0.01, 0.002, -1.05]), np.array([0.0, 0.003, 0.0])
    mirror = np.array([1.0, 1.0, -1.0])
    a = pl.simulate_spring(down, x0, v0, t_end=60.0, dt=1e-3, save_every=100, order=4)
    b = pl.simulate_spring(up, x0 * mirror, v0 * mirror, t_end=60.0, dt=1e-3, save_every=100, order=4)
    assert np.abs(b.x * mirror - a.x).max() < 1e-12
    assert b.bouncing_energy.min() < 0.1 * b.bouncing_energy[0]


@pytest.mark.parametrize(
    ("args", "words"),
    [
        ((1.0, 0.0), "g = 0.0 m/s² is not allowed: a finite number other than 0"),
        ((1.0, float("nan")), "g = nan m/s² is not allowed"),
        ((0.0, 9.81), "equilibrium_length = 0.0 m is not allowed: the stable rest length must be a finite"),
        ((-1.0, 9.81), "equilibrium_length = -1.0 m is not allowed"),
        ((float("inf"), 9.81), "equilibrium_length = inf m is not allowed"),
    ],
)
def test_resonant_refuses_what_has_no_resonance(args: tuple[float, float], words: str) -> None:
    with pytest.raises(pl.InvalidInputError, match=words):
        pl.SwingingSpring.resonant(*args)


@pytest.mark.parametrize("g", [9.81, -4.0])
def test_the_equilibrium_length_is_the_stable_rest_point(g: float) -> None:
    """l = l₀ + |g|/(k/m): the bob rests on the vertical on the side gravity pulls it to, the spring
    stretched (for g < 0 above the pivot). Started there at rest it stays, with bouncing energy 0;
    pushed sideways it swings about it and stays near (stable). For g < 0 the formula l₀ + g/(k/m)
    gave the compressed point below the pivot, where the bob does not rest (before the fix: 0.6 m)."""
    sp = pl.SwingingSpring(k_over_m=20.0, rest_length=0.8, g=g)
    ell = sp.equilibrium_length
    assert ell == pytest.approx(0.8 + abs(g) / 20.0, rel=1e-15)
    up = np.sign(-g)  # the side gravity pulls to: −e₃ for g > 0, +e₃ for g < 0
    rest = pl.simulate_spring(sp, [0.0, 0.0, up * ell], [0.0, 0.0, 0.0], t_end=5.0, dt=1e-3, save_every=100)
    assert np.abs(rest.x - [0.0, 0.0, up * ell]).max() < 1e-12
    assert np.abs(rest.bouncing_energy).max() < 1e-24
    pushed = pl.simulate_spring(
        sp, [0.0, 0.0, up * ell], [0.05, 0.02, 0.01], t_end=30.0, dt=1e-3, save_every=100, order=4
    )
    assert np.abs(pushed.x - [0.0, 0.0, up * ell]).max() < 0.1  # measured 0.023 m (g > 0), 0.035 m
    assert np.abs(pushed.r - ell).max() < 0.01


def test_bad_input() -> None:
    with pytest.raises(pl.InvalidInputError, match="k_over_m"):
        pl.simulate_spring(pl.SwingingSpring(-1.0, 1.0), [0, 0, -1], [0, 0, 0], t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="rest_length"):
        pl.simulate_spring(pl.SwingingSpring(10.0, 0.0), [0, 0, -1], [0, 0, 0], t_end=1.0)
    with pytest.raises(pl.InvalidInputError, match="order"):
        pl.simulate_spring(pl.SwingingSpring(10.0, 1.0), [0, 0, -1], [0, 0, 0], t_end=1.0, order=3)


# --- scenario files and the command line (model = "spring") ------------------------------------------

SPRING_TOML = SCENARIOS / "swinging_spring.toml"


def test_spring_scenario_runs_like_simulate_spring() -> None:
    """``model = "spring"``: length is the rest length l₀, stiffness k [N/m]; the run is
    simulate_spring's (rattle4 → the triple jump), E and J₃ conserved."""
    sc = pl.load_scenario(SPRING_TOML)
    sp = sc.spring()
    assert sp is not None and sp.k_over_m == 39.24 and sp.rest_length == 0.75
    assert sp.equilibrium_length == pytest.approx(1.0, rel=1e-15)  # l₀ + m g/k
    assert pl.Scenario.from_toml_str(sc.to_toml()) == sc
    tr = sc.run(t_end=5.0)
    direct = pl.simulate_spring(
        sp, sc.initial_state().x, sc.initial_state().v, 5.0, dt=1e-3, save_every=100, order=4
    )
    np.testing.assert_array_equal(tr.x, direct.x)
    assert abs(tr.j3[0]) == pytest.approx(5e-5, rel=1e-12) and np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-14
    assert np.max(np.abs(tr.energy - tr.energy[0])) < 1e-10
    np.testing.assert_allclose(tr.r, np.linalg.norm(tr.x, axis=1), rtol=1e-15)
    # an angle start lies on the sphere of the equilibrium length
    angles = (
        SPRING_TOML.read_text()
        .replace("x = [0.01, 0.0, -1.05]", "theta_deg = 10.0")
        .replace("v = [0.0, 0.005, 0.0]", "phi_dot = 0.5")
    )
    start = pl.Scenario.from_toml_str(angles).initial_state()
    assert np.linalg.norm(start.x) == pytest.approx(1.0, rel=1e-15)


def test_spring_from_the_cli_writes_r_energy_and_j3(tmp_path: Path) -> None:
    out = tmp_path / "spring.csv"
    result = CliRunner().invoke(app, ["run", str(SPRING_TOML), "--t-end", "2", "--out", str(out)])
    assert result.exit_code == 0, result.output
    assert "equilibrium length 1 m" in result.output and "max |E - E0|" in result.output
    header = out.read_text().splitlines()[1]
    for column in ("r [m]", "energy [J]", "j3 [kg m^2/s]", "bouncing_energy [J]"):
        assert column in header
    data = np.loadtxt(out, delimiter=",", skiprows=2)
    assert data.shape == (21, 11) and data[-1, 0] == pytest.approx(2.0)


@pytest.mark.parametrize(
    ("edit", "needle"),
    [
        (('method = "rattle4"', 'method = "dop853"'), "cannot integrate the 'spring' model"),
        (("stiffness = 39.24", "stiffness = 0.0"), "k/m"),
        (("stiffness = 39.24", "stiffnes = 1.0"), "did you mean 'stiffness'"),
        (("x = [0.01, 0.0, -1.05]", "x = [0.0, 0.0, 0.0]"), "away from the pivot"),
    ],
)
def test_bad_spring_scenarios_are_named(edit: tuple[str, str], needle: str) -> None:
    with pytest.raises(pl.ScenarioError, match=needle):
        pl.Scenario.from_toml_str(SPRING_TOML.read_text().replace(*edit))


def test_spring_is_not_a_pendulum() -> None:
    with pytest.raises(pl.InvalidInputError, match="SwingingSpring"):
        pl.Pendulum(model="spring")
    with pytest.raises(pl.ScenarioError, match="not a pendulum"):
        pl.load_scenario(SPRING_TOML).pendulum()


def test_a_stiff_spring_becomes_the_rod() -> None:
    """As k → ∞ the swinging spring (rest length l, started on the rod's state) follows the rigid
    pendulum of length l: the largest distance between the two bobs over 2 s falls like 1/k (the
    stretch and the bouncing it starts are O(T/k)); measured ratios for k/m = 1e4, 1e5, 1e6 1/s²."""
    p = pl.Pendulum(length=1.0, g=9.81)
    s = p.state_from_angles(theta=1.0, phi_dot=2.0)
    rod = pl.simulate(p, s, 2.0, method="rattle8", dt=1e-4)
    dev = []
    for k_over_m in (1e4, 1e5, 1e6):
        tr = pl.simulate_spring(pl.SwingingSpring(k_over_m, 1.0), s.x, s.v, 2.0, dt=1e-4, order=4)
        assert np.array_equal(tr.t, rod.t)
        dev.append(float(np.max(np.linalg.norm(tr.x - rod.x, axis=1))))
    assert 9.5 < dev[0] / dev[1] < 10.5 and 9.5 < dev[1] / dev[2] < 10.5, dev
    assert dev[2] < 1e-4  # m, at k/m = 1e6 1/s²
