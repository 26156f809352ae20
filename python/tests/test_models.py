"""The real-pendulum models from Python (docs/theory.md §7): the registry, construction from Python and
from scenario files, files, the summary and the command line, and clear errors for bad input. The
physics of the models (the reduction to the ideal pendulum, T-7.1, the J₃ decay, T-7.3, tilted
gravity) is in test_models_physics.py. SI units throughout (m, kg, s, rad; power in W, energy in J)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS
from model_inputs import FORCED, ROSETTE
from typer.testing import CliRunner

import pendulab as pl
from pendulab.cli import app

COMMON = ("length", "mass", "g")


def own_defaults(name: str) -> dict[str, float]:
    """The model's own parameters at their registry defaults."""
    spec = next(m for m in pl.models() if m["name"] == name)
    return {p["name"]: p["default"] for p in spec["params"] if p["name"] not in COMMON}


def scenario_text(model: str, params: dict[str, float], t_end: float = 0.2) -> str:
    keys = "\n".join(f"{k} = {v!r}" for k, v in params.items())
    return (
        f'title = "{model}"\n[pendulum]\nmodel = "{model}"\nlength = 1.0\nmass = 2.0\ng = 9.81\n{keys}\n'
        f"[initial]\ntheta_deg = 30.0\nphi_dot = 1.0\n[simulation]\nt_end = {t_end}\ndt = 1e-3\n"
    )


# --- the registry and construction ------------------------------------------------------------------


def test_models_lists_the_registry_with_units_and_sane_defaults() -> None:
    """pl.models() is the core's registry; every parameter has a unit and a default inside its limits."""
    table = pl.models()
    assert table == pl._core.models()
    assert {"ideal", "damped", "rotating"} <= {m["name"] for m in table}
    for m in table:
        assert [p["name"] for p in m["params"][:3]] == list(COMMON), m["name"]
        assert m["label"] and not re.search(r"T-\d|§|THEORY", m["label"]), m["label"]
        for p in m["params"]:
            assert p["unit"] and p["allowed"] and p["description"] and p["label"], p
            assert p["min"] <= p["default"] <= p["max"], p
            # the words a student reads: no formula numbers (those go into the description, a tooltip)
            assert not re.search(r"T-\d|§|THEORY|_", p["label"].replace("c_q", "")), p["label"]
    damped = {p["name"]: p for p in next(m for m in table if m["name"] == "damped")["params"]}
    assert damped["damping"]["unit"] == "1/s" and damped["drag"]["unit"] == "1/m"
    assert damped["forcing_amplitude"]["unit"] == "m/s^2" and damped["forcing_omega"]["unit"] == "rad/s"


def test_the_callers_copy_of_the_registry_is_the_callers_own() -> None:
    """The checks read one shared table (fetched once, a fit builds a model per residual); changing the
    list pl.models() returned changes neither them nor the next pl.models(), and the fit's per-model
    view of the table is read-only."""
    from pendulab.fitting.problem import model_params

    mine = pl.models()
    mine[1]["params"][3]["max"] = 0.0  # damping [1/s]
    mine[0]["params"].clear()
    assert pl.Pendulum(1.0, model="damped", damping=0.5).params()["damping"] == 0.5
    assert pl.models() == pl._core.models() != mine
    own = model_params("damped")
    assert own["damping"]["max"] > 0.5 and model_params("damped") is own
    with pytest.raises(TypeError):
        own["damping"]["max"] = 0.0  # type: ignore[index]
    with pytest.raises(pl.InvalidInputError, match=r"unknown model 'dampd': use one of ideal, damped"):
        model_params("dampd")


@pytest.mark.parametrize("name", [m["name"] for m in pl.models() if m["name"] != "spring"])
def test_every_model_is_constructible_from_python_and_from_a_scenario_file(name: str) -> None:
    """Each model with every own parameter given (at its default) builds from Python and from a file;
    the file round-trips through to_toml and runs. (The swinging spring leaves the sphere and is no
    Pendulum: tests/test_spring.py.)"""
    params = own_defaults(name)
    # the sampled pivot's path: a small circle, sampled every 0.05 s over 1 s (arrays, not parameters)
    times = [0.05 * k for k in range(21)]
    positions = [[0.1 * math.cos(t), 0.1 * math.sin(t), 0.0] for t in times]
    samples = (times, positions) if name == "sampled_pivot" else None
    p = pl.Pendulum(length=1.0, g=9.81, mass=2.0, model=name, pivot_samples=samples, **params)
    assert p.model == name and p.extra == params and p.is_ideal == (name == "ideal")
    text = scenario_text(name, params)
    if samples is not None:
        text = text.replace(
            "[initial]", f"pivot_times = {times!r}\npivot_positions = {positions!r}\n[initial]"
        )
    sc = pl.Scenario.from_toml_str(text, source=f"{name}.toml")
    assert sc.pendulum().params() == p.params()
    again = pl.Scenario.from_toml_str(sc.to_toml())
    assert again == sc and again.pendulum().params() == p.params()
    tr = sc.run(progress=False)
    assert tr.t[-1] == pytest.approx(0.2) and np.all(np.isfinite(tr.x))
    assert np.max(np.abs(tr.constraint_error)) < 1e-14  # RATTLE stays on the sphere for every model


def test_the_model_is_inferred_from_the_keywords() -> None:
    """No model= given: the first model that has all the keywords (damping alone → damped)."""
    assert pl.Pendulum(damping=0.003).model == "damped"
    assert pl.Pendulum(frame_rate=0.1, damping=0.1).model == "rotating"
    assert pl.Pendulum(radius=3.0, rate=0.2).model == "slewing"
    assert pl.Pendulum().model == "ideal"
    assert repr(pl.Pendulum(frame_rate=0.1)) == "Pendulum(length=1.0, g=9.81, mass=1.0, frame_rate=0.1)"


# --- files, summary and command line -----------------------------------------------------------------


def test_files_carry_the_model_its_parameters_and_the_power(tmp_path: Path) -> None:
    """CSV, Parquet and NetCDF record the model name, its parameters with units, and the power and
    power-balance columns."""
    import pyarrow.parquet as pq
    import xarray as xr

    p = pl.Pendulum(model="damped", forcing_phase=0.25, **FORCED)
    tr = pl.simulate(p, p.state_from_angles(*ROSETTE), 0.5, save_every=50)
    meta = json.loads(tr.save(tmp_path / "r.csv").read_text().splitlines()[0].split("(JSON): ", 1)[1])
    assert meta["pendulum"] == {"model": "damped", "length": 1.0, "mass": 1.0, "g": 9.81, **p.extra}
    assert meta["units"]["damping"] == "1/s" and meta["units"]["power"] == "W"
    header = (tmp_path / "r.csv").read_text().splitlines()[1]
    assert header.endswith("power [W],power_balance_residual [J]")
    table = pq.read_table(tr.save(tmp_path / "r.parquet"))
    assert json.loads(table.schema.metadata[b"pendulab"])["pendulum"]["model"] == "damped"
    assert np.array_equal(table.column("power").to_numpy(), tr.power)
    with xr.open_dataset(tr.save(tmp_path / "r.nc"), engine="scipy") as ds:
        assert json.loads(ds.attrs["pendulab"])["pendulum"]["forcing_phase"] == 0.25
        assert ds["power"].attrs["units"] == "W"
        assert np.array_equal(ds["power_balance_residual"].values, tr.power_balance_residual)


def test_the_summary_reports_energy_drift_only_when_energy_is_conserved() -> None:
    """Conservative models (here an undamped rotating frame: Coriolis does no work) get the energy
    drift; damped ones the power balance instead."""
    spinning = pl.Pendulum(model="rotating", frame_rate=0.5)
    tr = pl.simulate(spinning, spinning.state_from_angles(*ROSETTE), 1.0, method="rattle4")
    assert tr.is_conservative and np.max(np.abs(tr.energy - tr.energy[0])) < 1e-9
    assert "max |E - E0|" in tr.summary() and "balance:" not in tr.summary()
    damped = pl.load_scenario(SCENARIOS / "damped.toml").run(t_end=1.0, progress=False)
    text = damped.summary()
    assert "balance:" in text and "max |E - E0| /" not in text and "damping = 0.05 1/s" in text


def test_cli_lists_the_models_and_runs_a_damped_file(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """`pendulab models [--json]` lists every model with units (strict JSON: no limit is null), and
    `pendulab run damped.toml --t-end 1 --out x.csv` writes the power balance."""
    runner = CliRunner()
    out = runner.invoke(app, ["models"])
    assert out.exit_code == 0, out.output
    for m in pl.models():
        assert f"\n{m['name']}: {m['label']} — " in out.output
    assert "friction (linear damping) c: friction force −m c v" in out.output
    assert "damping" in out.output and "[1/s]" in out.output and "latitude_deg" in out.output

    def no_constant(name: str) -> None:
        raise AssertionError(f"not strict JSON: {name}")

    out = runner.invoke(app, ["models", "--json"])
    table = json.loads(out.output, parse_constant=no_constant)
    assert [m["name"] for m in table] == [m["name"] for m in pl.models()]
    length = table[0]["params"][0]
    limit = pl.models()[0]["params"][0]["max"]  # a finite bound, or inf written as null
    assert length["name"] == "length" and length["unit"] == "m"
    assert length["max"] == (limit if math.isfinite(limit) else None)
    out = runner.invoke(app, ["models", "springy"])
    assert out.exit_code == 2 and "springy" in out.output

    monkeypatch.chdir(tmp_path)
    result = runner.invoke(app, ["run", str(SCENARIOS / "damped.toml"), "--t-end", "1", "--out", "x.csv"])
    assert result.exit_code == 0, result.output
    assert "balance:" in result.output and "damped model" in result.output
    data = np.genfromtxt(tmp_path / "x.csv", delimiter=",", skip_header=1, names=True)
    assert data.shape == (101,) and np.max(np.abs(data["power_balance_residual_J"])) < 1e-5
    assert np.all(data["power_W"] <= 0)  # damping alone only takes energy out


# --- bad input --------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kwargs", "needles"),
    [
        ({"damping": -0.1}, ["damping = -0.1:", "[0, 1e4] 1/s"]),
        ({"model": "damped", "dampnig": 0.1}, ["dampnig", "damping"]),
        ({"model": "rotating", "latitude": 2.0}, ["latitude", "π/2"]),
        ({"model": "rotating", "frame_rate": math.inf}, ["frame_rate", "inf", "[-1e3, 1e3] rad/s"]),
        ({"model": "damped", "gravity_x": 0.0, "gravity_y": 0.0, "gravity_z": 0.0}, ["gravity"]),
        ({"model": "springy"}, ["springy", "damped", "rotating"]),
    ],
)
def test_bad_parameters_are_named(kwargs: dict[str, object], needles: list[str]) -> None:
    with pytest.raises(pl.InvalidInputError) as err:
        pl.Pendulum(**kwargs)  # type: ignore[arg-type]
    assert all(n in str(err.value) for n in needles), str(err.value)


def test_methods_and_solutions_of_the_ideal_pendulum_refuse_other_models() -> None:
    """rk4_angles (T-2.5) and the exact solution (§4) exist only for the ideal pendulum."""
    p = pl.Pendulum(damping=0.1)
    s0 = p.state_from_angles(*ROSETTE)
    with pytest.raises(pl.InvalidInputError, match=r"rk4_angles.*'damped'.*rattle"):
        pl.simulate(p, s0, 1.0, method="rk4_angles")
    with pytest.raises(pl.InvalidInputError, match=r"only for the ideal pendulum.*'damped'"):
        pl.exact(p, s0)


@pytest.mark.parametrize(
    ("old", "new", "needles"),
    [
        (
            "frame_rate = 0.02    #",
            "frame_rte = 0.02 #",
            ["frame_rte", "did you mean 'frame_rate'", "latitude_deg"],
        ),
        (
            "frame_rate = 0.02    #",
            "damping = -1.0\nframe_rate = 0.02 #",
            ["damping = -1:", "[0, 1e4] 1/s"],
        ),
        (
            "frame_rate = 0.02    #",
            "radius = 5.0\nframe_rate = 0.02 #",
            ["radius is a parameter of model 'slewing' (and 'hoisted'), not of 'rotating'"],
        ),
        (
            "frame_rate = 0.02    #",
            "latitude = 0.9\nframe_rate = 0.02 #",
            ["latitude", "latitude_deg", "not both"],
        ),
        ("latitude_deg = 49.0", "latitude_deg = 100.0", ["latitude", "latitude_deg = 100.0 degrees"]),
        ("latitude_deg = 49.0", 'latitude_deg = "49 N"', ["pendulum.latitude_deg", "not a number"]),
        ("frame_rate = 0.02    #", "params = {frame_rate = 0.02} #", ["unknown key params", "frame_rate"]),
        (
            'model = "rotating"',
            'model = "ideal"',
            ["frame_rate is a parameter of model 'rotating', not of 'ideal'"],
        ),
    ],
)
def test_bad_model_keys_in_files_are_named(old: str, new: str, needles: list[str]) -> None:
    text = (SCENARIOS / "foucault.toml").read_text()
    assert old in text
    with pytest.raises(pl.ScenarioError) as err:
        pl.Scenario.from_toml_str(text.replace(old, new), source="foucault.toml")
    assert all(n in str(err.value) for n in needles), str(err.value)
    assert str(err.value).startswith("foucault.toml: ")


def test_latitude_in_degrees_round_trips_as_degrees() -> None:
    """latitude_deg stays latitude_deg in to_toml (the file's form is kept), ±90° are allowed."""
    sc = pl.load_scenario(SCENARIOS / "foucault.toml")
    assert "latitude_deg = 49.0" in sc.to_toml() and pl.Scenario.from_toml_str(sc.to_toml()) == sc
    text = (SCENARIOS / "foucault.toml").read_text()
    for pole in (90.0, -90.0):
        p = pl.Scenario.from_toml_str(
            text.replace("latitude_deg = 49.0", f"latitude_deg = {pole}")
        ).pendulum()
        assert abs(p.extra["latitude"]) == pytest.approx(math.pi / 2, rel=1e-16)


def test_conserve_is_refused_when_damping_makes_e_and_j3_decay() -> None:
    """DOP853's invariant projection would pin J₃ at J₃(0) although damping makes it decay as e^{−ct}
    (measured: J₃(5 s) = 1.5 instead of 0.335 kg m²/s for c = 0.3 1/s); without it DOP853 follows the
    decay to its tolerance."""
    p = pl.Pendulum(damping=0.3)
    s0 = p.state_from_angles(*ROSETTE)
    for run in (
        lambda: pl.simulate(p, s0, 1.0, method="dop853", conserve=True),
        lambda: pl.Stepper(p, s0, method="dop853", conserve=True),
    ):
        with pytest.raises(pl.InvalidInputError, match=r"conserve=True.*damping = 0\.3"):
            run()
    tr = pl.simulate(p, s0, 5.0, method="dop853", rtol=1e-12, atol=1e-14)
    assert tr.j3[-1] == pytest.approx(tr.j3[0] * math.exp(-0.3 * 5.0), rel=1e-9)
    spinning = pl.Pendulum(model="rotating", frame_rate=0.5)  # conservative: conserve stays allowed
    tr = pl.simulate(spinning, spinning.state_from_angles(*ROSETTE), 1.0, method="dop853", conserve=True)
    assert np.max(np.abs(tr.energy - tr.energy[0])) < 1e-12


def test_forcing_direction_defaults_only_when_no_component_is_given() -> None:
    """Regression: ``forcing_y=1`` alone is a force along e₂ (it used to be normalised together with
    the default forcing_x = 1 into a diagonal); the power F·v at a state moving along e₂ says so."""
    state = pl.Pendulum().state([0.0, 0.0, -1.0], [0.0, 1.0, 0.0])
    amp = {"forcing_amplitude": 2.0, "forcing_omega": 0.0}
    assert pl.Pendulum(**amp, forcing_y=1.0).power(state) == pytest.approx(2.0, abs=1e-15)
    assert pl.Pendulum(**amp).power(state) == 0.0  # default e₁, perpendicular to v
    diagonal = pl.Pendulum(**amp, forcing_x=1.0, forcing_y=1.0).power(state)
    assert diagonal == pytest.approx(2.0 / math.sqrt(2.0), rel=1e-15)


def test_the_registry_says_which_models_the_stepper_can_run(pendulum: pl.Pendulum) -> None:
    """``interactive`` is True exactly for the models the incremental Stepper (the lab) runs, but
    ``hoisted``: the Stepper runs it (every method, T-11.10) while the lab's crane mode runs the crane
    model's own integrator (docs/cranes.md "The lab's crane mode"), not this law l(t)."""
    s0 = pendulum.state_from_angles(*ROSETTE)
    for m in pl.models():
        own = {p["name"]: p["default"] for p in m["params"] if p["name"] not in COMMON}
        try:
            pl.Stepper(pl.Pendulum(model=m["name"], **own), s0).step(1)
            ran = True
        except pl.InvalidInputError:
            ran = False
        assert ran == (m["interactive"] or m["name"] == "hoisted"), m["name"]
