"""What a new user types first, taken from README.md and docs/ but outside the checkout (an installed
wheel): a path into the checkout's ``examples/`` names the shipped example to give by name instead, and
``python -m pendulab`` is the ``pendulab`` command."""

from __future__ import annotations

import subprocess
import sys
import tomllib
from pathlib import Path

import numpy as np
import pytest
from conftest import REPO
from typer.testing import CliRunner

import pendulab as pl
from pendulab import cli
from pendulab.scenario import examples


@pytest.mark.parametrize(
    ("path", "kind", "given"),
    [
        ("examples/scenarios/rosette.toml", "scenario", "'rosette'"),
        ("examples/sweeps/rotation_number.toml", "sweep", "'rotation_number'"),
        ("examples/data/filmed_swing.csv", "data", "'example:filmed_swing'"),
    ],
)
def test_a_path_into_the_checkouts_examples_names_the_example(
    path: str, kind: str, given: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)  # no examples/ here, as for a wheel
    with pytest.raises(FileNotFoundError) as info:
        examples.find(path, kind)
    message = str(info.value)
    assert message.startswith(f"{path}: No such file here; the example {kind} ")
    assert f"give its name alone, {given}, instead of the path" in message
    assert examples.find(given.strip("'"), kind).name == Path(path).name  # and that name works


def test_other_missing_files_keep_the_plain_message(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    for text, kind in [("examples/scenarios/mine.toml", "scenario"), ("rosette.csv", "scenario")]:
        with pytest.raises(FileNotFoundError, match=r": No such file, and no example scenario of that name"):
            examples.find(text, kind)


def test_cli_run_with_the_readme_path_outside_the_checkout(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(cli.app, ["run", "examples/scenarios/rosette.toml", "-q"])
    assert result.exit_code == 2, result.output
    errors = [ln for ln in result.stderr.splitlines() if ln.startswith("error: ")]
    assert len(errors) == 1 and "give its name alone, 'rosette', instead of the path" in errors[0]


def test_python_dash_m_pendulab_is_the_command(tmp_path: Path) -> None:
    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run(
            [sys.executable, "-m", "pendulab", *args],
            cwd=tmp_path,
            capture_output=True,
            text=True,
            timeout=60.0,
        )

    p = run("--version")
    assert p.returncode == 0 and p.stdout.strip() == f"pendulab {pl.__version__}", p.stderr
    p = run("rn")
    assert p.returncode == 2 and "error: pendulab: no such command 'rn'" in p.stderr, p.stderr


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="needs /dev/zero")
def test_a_device_is_read_as_a_file_not_called_missing(tmp_path: Path) -> None:
    """docs/limits.md: `pendulab validate /dev/zero` answers at once, with the file-size limit (it said
    "No such file", the device not being a regular file); a scenario piped to /dev/stdin is read."""
    for command in (["validate"], ["run"], ["sweep", "--out", str(tmp_path / "z.parquet")]):
        result = CliRunner().invoke(cli.app, [command[0], "/dev/zero", *command[1:]])
        assert result.exit_code == 2, result.output
        refused = "error: /dev/zero: the file is larger than 1048576 bytes (1 MiB)"
        assert refused in result.stderr, result.stderr
    rosette = examples.find("rosette").read_text(encoding="utf-8")
    p = subprocess.run(
        [sys.executable, "-m", "pendulab", "validate", "/dev/stdin"],
        input=rosette,
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert p.returncode == 0 and p.stdout.startswith("/dev/stdin: OK (Rosette"), p.stderr


def test_a_misspelt_or_misplaced_model_parameter_is_named_with_its_fix() -> None:
    """Pendulum(lenght=1.0) said "the 'damped' model has no parameter", a model the user never named;
    now each message names the keyword, its value, the nearest name or the models that have it."""
    cases = [
        (
            {"lenght": 1.0},
            "invalid parameter lenght = 1.0: no model has a parameter 'lenght' (did you mean 'length'?)",
        ),
        (
            {"frame_rate": 1e-4, "radius": 5.0},
            "invalid parameters frame_rate = 0.0001, radius = 5.0: no one model has all of them "
            "(the models of each: frame_rate: rotating; radius: slewing, hoisted); give model='…'",
        ),
        (
            {"model": "ideal", "lenght": 1.0},
            "the 'ideal' model has no parameter 'lenght' (did you mean 'length'?); "
            "its parameters: length, mass, g",
        ),
        ({"model": "ideal", "damping": 0.1}, "damping is a parameter of model 'damped' (and 'rotating', "),
    ]
    for keywords, message in cases:
        with pytest.raises(pl.InvalidInputError) as info:
            pl.Pendulum(**keywords)  # type: ignore[arg-type]
        assert message in str(info.value), str(info.value)
        assert "'damped' model" not in str(info.value)
    assert pl.Pendulum(damping=0.1, radius=5.0).model == "slewing"  # one model has both: inferred
    assert pl.Pendulum(model="rotating", frame_rate=1e-4, damping=0.1).model == "rotating"


def test_fitting_names_the_extra_that_brings_scipy(monkeypatch: pytest.MonkeyPatch) -> None:
    """pl.fit needs SciPy, which the README's `[lab]` install (whose lab fits data files) did not bring:
    `pendulab fit` then said only "No module named 'scipy'". The `fit` and `lab` extras have it now, and
    without it the command names the extra."""
    extras = tomllib.loads((REPO / "python" / "pyproject.toml").read_text(encoding="utf-8"))["project"][
        "optional-dependencies"
    ]
    for extra in ("fit", "lab", "crane"):
        assert any(req.startswith("scipy") for req in extras[extra]), extra
    monkeypatch.setitem(sys.modules, "scipy", None)  # as if SciPy were not installed
    result = CliRunner().invoke(cli.app, ["fit", "example:filmed_swing"])
    assert result.exit_code == 2, result.output
    assert (
        result.stderr.strip()
        == "error: pendulab fit needs SciPy: pip install 'pendulab[fit]' (or scipy>=1.11)"
    )


def test_pl_fit_without_scipy_names_the_extra(monkeypatch: pytest.MonkeyPatch) -> None:
    """pl.fit without SciPy raised a bare "No module named 'scipy'" from deep in its search (after
    reading the data and the noise): now one ImportError at the start names the package and the extra."""
    t = np.linspace(0.0, 5.0, 200)
    angle = 0.3 * np.cos(np.sqrt(9.81) * t)
    monkeypatch.setitem(sys.modules, "scipy", None)  # as if SciPy were not installed
    with pytest.raises(ImportError) as info:
        pl.fit(t, planar_angle=angle, fit=["g"])
    assert str(info.value) == "pl.fit needs SciPy: pip install 'pendulab[fit]' (or scipy>=1.11)"
    assert info.value.name == "scipy"
