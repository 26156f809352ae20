"""Scenario files (TOML): every shipped example loads; every kind of bad input is refused with a
message naming the file, the key, the value and what is allowed; round trips; degrees; a short run."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS

import pendulab as pl

EXAMPLES = sorted(SCENARIOS.glob("*.toml"))
ROSETTE = (SCENARIOS / "rosette.toml").read_text(encoding="utf-8")

CARTESIAN = """
title = "Cartesian start"
[pendulum]
length = 2.0
mass = 0.5
g = 9.81
[initial]
x = [0.0, 0.0, -2.2]        # 10 % off the sphere of radius 2 m
v = [0.3, 0.0, 0.2]
{project}
[simulation]
t_end = 1.0
save_at = [0.0, 0.25, 0.5, 1.0]
"""


def edited(old: str, new: str) -> str:
    """The rosette file with one piece replaced (fails loudly if the piece is not there)."""
    assert old in ROSETTE, old
    return ROSETTE.replace(old, new, 1)


def test_the_examples_are_there() -> None:
    """The README promises these shipped scenarios."""
    names = {p.stem for p in EXAMPLES}
    assert {
        "rosette",
        "conical",
        "small_ellipse",
        "planar_large",
        "near_top",
        "inverted_g",
        "zero_g",
    } <= names


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_every_example_loads_and_validates(path: Path) -> None:
    """Each example has a title, a valid pendulum and a start on TS², and a known method."""
    sc = pl.load_scenario(path)
    assert sc.title
    if sc.is_crane:  # a crane, not a pendulum: tests/test_scenario_crane.py
        assert sc.crane().crane.modes()[0] > 0
        return
    if sc.spec.pendulum.model == "spring":  # off the sphere: tests/test_spring.py
        assert sc.spring() is not None
        return
    p, s = sc.pendulum(), sc.initial_state()
    assert p.length > 0 and p.mass > 0
    assert abs(np.linalg.norm(s.x) - p.length) < 1e-12 * p.length
    assert abs(float(s.x @ s.v)) < 1e-12
    assert sc.spec.simulation.method in pl.method_names()
    assert sc.source == str(path)


@pytest.mark.parametrize(
    ("text", "needles"),
    [
        pytest.param(
            edited("length = 1.0", "length = = 1.0"), ["rosette.toml, line 8", "invalid TOML"], id="syntax"
        ),
        pytest.param(
            edited("length = 1.0", "lenght = 1.0"),
            ["unknown key pendulum.lenght = 1.0", "did you mean 'length'", "allowed keys in [pendulum]"],
            id="unknown-key",
        ),
        pytest.param(
            edited("[simulation]", "[output]\nfile = 'a.csv'\n[simulation]"),
            ["unknown key output"],
            id="unknown-table",
        ),
        pytest.param(edited("g = 9.81", "g = nan"), ["pendulum.g = nan is not a finite number"], id="nan"),
        pytest.param(
            edited("mass = 1.0", "mass = inf"), ["pendulum.mass = inf is not a finite number"], id="inf"
        ),
        pytest.param(
            CARTESIAN.format(project="").replace("-2.2", "nan"),
            ["initial.x[2] = nan is not a finite number"],
            id="nan-in-x",
        ),
        pytest.param(
            edited("length = 1.0", "length = -1.0"),
            ["pendulum.length = -1.0: must be >= 1e-6", "rod length l"],
            id="negative-length",
        ),
        pytest.param(
            edited("length = 1.0", 'length = "1"'),
            ["pendulum.length = '1'", "is not a number"],
            id="string-number",
        ),
        pytest.param(
            edited("theta_deg = 60.0", "theta_deg = 60.0\ntheta = 1.0"),
            ["theta = 1.0", "theta_deg = 60.0", "not both"],
            id="theta-and-theta_deg",
        ),
        pytest.param(
            edited("phi_deg = 0.0", "phi_deg = 0.0\nx = [0.0, 0.0, -1.0]"),
            ["either as angles", "x"],
            id="angles-and-x",
        ),
        pytest.param(
            edited('method = "rattle"', 'method = "euler"'),
            ["simulation.method = 'euler'", "available: rattle"],
            id="unknown-method",
        ),
        pytest.param(
            edited('model = "ideal"', 'model = "double"'),
            ["pendulum.model = 'double'", "allowed: 'ideal'"],
            id="unknown-model",
        ),
        pytest.param(
            edited("save_every = 10", "save_every = 10\nsave_at = [1.0, 2.0]"),
            ["save_every (= 10)", "save_at (= [1.0, 2.0])", "not both"],
            id="save_every-and-save_at",
        ),
        pytest.param(
            edited("save_every = 10", "save_every = 2.5"),
            ["simulation.save_every = 2.5", "integer"],
            id="fraction",
        ),
        pytest.param(
            edited("save_every = 10", "save_at = [2.0, 1.0]"),
            ["strictly increasing", "2.0 s"],
            id="save_at-order",
        ),
        pytest.param(edited("t_end = 100.0", "t_end = -5.0"), ["t_end = -5.0 s", "after t0"], id="t_end"),
        pytest.param(edited("dt = 1.0e-3", "dt = 0.0"), ["simulation.dt = 0.0: must be >= 1e-12"], id="dt"),
        pytest.param(
            edited("length = 1.0      # m\n", ""), ["pendulum.length is missing", "rod length"], id="missing"
        ),
        pytest.param(
            edited("t_end = 100.0", "t_end = 1e6").replace("save_every = 10", "save_every = 1"),
            ["saved samples would need", "bytes", "raise save_every"],
            id="absurd-memory",
        ),
        pytest.param(
            CARTESIAN.format(project=""),
            ["[initial]", "not on TS²", "|x| - l = 0.2 m", "x·v = -0.44 m²/s", "project = true"],
            id="off-TS2",
        ),
        pytest.param(
            CARTESIAN.format(project="").replace("0.0, 0.0, -2.2", "0.0, 0.0"),
            ["initial.x = [0.0, 0.0]", "3 items"],
            id="x-two-numbers",
        ),
    ],
)
def test_bad_input_is_named(text: str, needles: list[str]) -> None:
    """Each bad file raises ScenarioError (a ValueError) starting with the file name and naming the
    key, the bad value and what is allowed, on one line."""
    with pytest.raises(pl.ScenarioError) as info:
        pl.Scenario.from_toml_str(text, source="rosette.toml")
    message = str(info.value)
    assert isinstance(info.value, ValueError)
    assert message.startswith("rosette.toml")
    assert "\n" not in message
    for needle in needles:
        assert needle in message, (needle, message)


def test_syntax_errors_carry_the_line() -> None:
    """The line of a TOML syntax error is in the message and in ``ScenarioError.line``."""
    text = edited("mass = 1.0", "mass = 1.0.0")
    line = text.splitlines().index("mass = 1.0.0        # kg") + 1
    with pytest.raises(pl.ScenarioError, match=f"line {line}") as info:
        pl.Scenario.from_toml_str(text, "f.toml")
    assert info.value.line == line


def test_all_problems_are_reported() -> None:
    """Several independent problems are listed together (numbered), one entry each in ``problems``."""
    text = edited("length = 1.0", "length = 0.0").replace('method = "rattle"', 'method = "euler"')
    with pytest.raises(pl.ScenarioError, match=r"2 problems: \(1\) .*\(2\) ") as info:
        pl.Scenario.from_toml_str(text)
    assert len(info.value.problems) == 2


def test_files_that_cannot_be_read(tmp_path: Path) -> None:
    """A missing file is an OSError; a file that is not UTF-8 is a ScenarioError."""
    with pytest.raises(FileNotFoundError):
        pl.load_scenario(tmp_path / "missing.toml")
    bad = tmp_path / "latin1.toml"
    bad.write_bytes(ROSETTE.encode("utf-8").replace("°".encode(), b"\xb0"))
    with pytest.raises(pl.ScenarioError, match="UTF-8"):
        pl.load_scenario(bad)


@pytest.mark.parametrize("path", [*EXAMPLES, None], ids=[*(p.stem for p in EXAMPLES), "cartesian"])
def test_to_toml_round_trips(path: Path | None, tmp_path: Path) -> None:
    """Writing a scenario and loading it again gives an equal scenario (and the same start, bit for bit)."""
    if path is None:
        sc = pl.Scenario.from_toml_str(CARTESIAN.format(project="project = true"))
    else:
        sc = pl.load_scenario(path)
    again = pl.load_scenario(sc.save(tmp_path / "again.toml"))
    assert again == sc
    assert again.to_dict() == sc.to_dict()
    if not sc.is_crane:  # a crane has no pendulum's start (tests/test_scenario_crane.py)
        assert np.array_equal(again.initial_state().as_array(), sc.initial_state().as_array())
    assert sc.with_overrides(t_end=1.5) != sc


def test_degrees_become_radians() -> None:
    """theta_deg/phi_deg convert as deg·π/180; the same start in radians gives the same state."""
    deg = pl.Scenario.from_toml_str(
        edited("theta_deg = 60.0", "theta_deg = 90.0").replace("phi_deg = 0.0", "phi_deg = 180.0")
    )
    rad = pl.Scenario.from_toml_str(
        edited("theta_deg = 60.0", f"theta = {math.pi / 2!r}").replace("phi_deg = 0.0", f"phi = {math.pi!r}")
    )
    assert deg.spec.initial.angles()[:2] == (90 * (math.pi / 180), 180 * (math.pi / 180))
    assert np.array_equal(deg.initial_state().x, rad.initial_state().x)
    assert np.allclose(deg.initial_state().x, [-1.0, 0.0, 0.0], atol=1e-15)
    rosette = pl.load_scenario(SCENARIOS / "rosette.toml").initial_state()
    assert rosette.angles()[0] == pytest.approx(math.radians(60), abs=1e-15)
    assert rosette.x[2] == pytest.approx(-0.5, abs=1e-15)  # z = -l cos 60°


def test_cartesian_start_is_projected_when_asked() -> None:
    """project = true moves an off-TS² start onto TS² and records by how much."""
    sc = pl.Scenario.from_toml_str(CARTESIAN.format(project="project = true"))
    s = sc.initial_state()
    assert s.projection is not None
    assert s.projection[0] == pytest.approx(0.2) and s.projection[1] == pytest.approx(0.2)
    assert np.linalg.norm(s.x) == pytest.approx(2.0, abs=1e-15)


def test_short_rosette_run_conserves() -> None:
    """The rosette for 2 s (2000 RATTLE steps of 1 ms): |ΔE|/(m g l) < 1e-5, J₃ and |x| = l to round-off,
    and as many samples as estimated."""
    sc = pl.load_scenario(SCENARIOS / "rosette.toml")
    tr = sc.run(t_end=2.0)
    assert tr.t[-1] == 2.0 and tr.method == "rattle" and tr.stats["steps"] == 2000
    assert len(tr) == sc.with_overrides(t_end=2.0).expected_samples() == 201
    assert np.max(np.abs(tr.energy - tr.energy[0])) / (1.0 * 9.81 * 1.0) < 1e-5
    assert np.max(np.abs(tr.j3 - tr.j3[0])) < 1e-13
    assert np.max(np.abs(tr.constraint_error)) < 1e-14


def test_overrides_are_validated_and_replace_save_at() -> None:
    """Overrides are checked like file values; save_every replaces a file's save_at."""
    sc = pl.Scenario.from_toml_str(CARTESIAN.format(project="project = true"), "c.toml")
    assert sc.expected_samples() == 4
    tr = sc.run(method="rattle4", dt=1e-3, save_every=250)
    assert tr.method == "rattle4" and np.allclose(tr.t, [0.0, 0.25, 0.5, 0.75, 1.0], atol=1e-12)
    with pytest.raises(pl.ScenarioError, match=r"c\.toml \(with dt = -0\.1\): simulation\.dt = -0\.1"):
        sc.run(dt=-0.1)
    with pytest.raises(pl.ScenarioError, match="unknown method 'euler'"):
        sc.with_overrides(method="euler")
    # one object for the overrides, the same as its fields as keywords; keywords go over it
    from pendulab.scenario import RunOverrides

    quick = RunOverrides(method="rattle4", dt=1e-3, save_every=250)
    assert sc.with_overrides(quick) == sc.with_overrides(method="rattle4", dt=1e-3, save_every=250)
    assert np.array_equal(sc.run(overrides=quick).x, tr.x)
    assert sc.with_overrides(quick, save_every=500).expected_samples() == 3
    with pytest.raises(TypeError, match="unknown run override"):
        sc.with_overrides(steps=5)


def test_save_at_lands_on_the_times() -> None:
    """save_at keeps exactly the listed times (fixed-step methods shorten one step per time)."""
    sc = pl.Scenario.from_toml_str(CARTESIAN.format(project="project = true"))
    tr = sc.run()
    assert np.array_equal(tr.t, [0.0, 0.25, 0.5, 1.0])


def test_dop853_scenario() -> None:
    """Needs the real DOP853 (a stub panics): an adaptive scenario with save_at agrees with RATTLE8."""
    sc = pl.load_scenario(SCENARIOS / "rosette.toml").with_overrides(method="dop853", rtol=1e-12, atol=1e-14)
    assert sc.expected_samples() is None
    tr = sc.run(t_end=1.0)
    ref = sc.run(t_end=1.0, method="rattle8", dt=1e-3)
    assert tr.t[-1] == 1.0
    assert np.linalg.norm(tr.x[-1] - ref.x[-1]) < 1e-9
