"""The words a user meets first on the command line: output files named as typed (``wrote ./out.csv``,
not typer's normalised ``out.csv``), ``--help`` without Python type names, ``pendulab models``
describing length per model (the spring's rest length only for the spring)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import SCENARIOS
from test_cli import assert_user_error, invoke

from pendulab import cli

ROSETTE = str(SCENARIOS / "rosette.toml")


def test_run_and_exact_name_the_written_file_as_typed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """``--out ./o.csv`` was reported as ``wrote o.csv`` (typer's Path); the inputs were already as typed."""
    monkeypatch.chdir(tmp_path)
    code, out, err = invoke("run", ROSETTE, "--t-end", "0.1", "--save-every", "50", "--out", "./o.csv")
    assert code == 0 and "wrote ./o.csv (3 samples)" in out, (code, out, err)
    code, out, err = invoke("exact", ROSETTE, "--t", "0:1:0.5", "-o", ".//e.csv")
    assert code == 0 and "wrote .//e.csv (3 samples)" in out, (code, out, err)
    assert Path("o.csv").is_file() and Path("e.csv").is_file()


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["run", ROSETTE, "--out", "./o.txt"], "unknown output suffix '.txt' in './o.txt'"),
        (["run", ROSETTE, "--out", "./nodir/o.csv"], "--out './nodir/o.csv': the directory"),
        (["run", ROSETTE, "--out", "./"], "'./' is a directory: give a file name ending in .csv"),
        (
            ["run", ROSETTE, "--out", "."],
            "'.' is a directory: give a file name ending in .csv, .parquet or .nc (e.g. './run.csv')",
        ),
        (["exact", ROSETTE, "--out", "./o.txt"], "in './o.txt'"),
        (["phases", ROSETTE, "--plot", "./p.bmp"], "--plot: unknown image suffix '.bmp' in './p.bmp'"),
        (["plot", ROSETTE, "--out", "./nodir/p.png"], "--out './nodir/p.png': the directory"),
        (["reduced", ROSETTE, "--out", "./p.bmp"], "in './p.bmp'"),
        (["em-map", "--out", "./m.txt"], "in './m.txt'"),
        (["animate", ROSETTE, "--out", "./m.txt"], "'./m.txt'"),
        (["crane", "sensitivity", "zv", "--plot", "./v.bmp"], "in './v.bmp'"),
        (["crane", "run", "x.toml", "--out", "./r.txt"], "--out './r.txt': crane runs are written as .csv"),
        (["crane", "grid", "--out", "./g.txt"], "--out './g.txt': the grid is written as .csv"),
        (["fit", "d.csv", "--out", "./f.txt"], "--out './f.txt': the fitted scenario is written as TOML"),
        (["fit", "d.csv", "--out", "./nodir/f.toml"], "--out './nodir/f.toml': the directory"),
    ],
)
def test_output_errors_name_the_file_as_typed(
    args: list[str], needle: str, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Every check of an output path before the work names it as typed (``./o.txt``, not ``o.txt``)."""
    monkeypatch.chdir(tmp_path)
    code, out, err = invoke(*args)
    assert_user_error(code, out, err, needle)


def test_crane_writes_name_the_files_as_typed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """``pendulab crane sensitivity --plot ./v.svg`` says ``wrote ./v.svg``."""
    monkeypatch.chdir(tmp_path)
    code, out, err = invoke("crane", "sensitivity", "zv", "--points", "3", "--plot", "./v.svg")
    assert code == 0 and out.rstrip().endswith("wrote ./v.svg"), (code, out, err)


def _commands(group: object, path: tuple[str, ...] = ()) -> list[tuple[str, ...]]:
    from typer.main import get_command

    click_group = get_command(group) if path == () else group  # type: ignore[arg-type]
    out: list[tuple[str, ...]] = []
    for name, sub in getattr(click_group, "commands", {}).items():
        if getattr(sub, "commands", None):
            out += _commands(sub, (*path, name))
        else:
            out.append((*path, name))
    return out


@pytest.mark.parametrize("command", _commands(cli.app))
def test_help_shows_what_to_type_not_python_types(command: tuple[str, ...]) -> None:
    """``--help`` of every command names values by what to type: ``SCENARIO...``, ``KIND...``, ``FILE``,
    ``NUMBER`` (typer showed ``SCENARIO <list[str]>``, ``KINDS <list[str]>``, ``--dt <float>``)."""
    code, out, _ = invoke(*command, "--help")
    assert code == 0, out
    assert not re.search(r"<[A-Za-z_]", out) and "list[" not in out, (command, out)


def test_validate_and_sensitivity_usage_names_their_lists() -> None:
    code, out, _ = invoke("validate", "--help")
    assert code == 0 and "[OPTIONS] SCENARIO..." in out and "\n  SCENARIO...  " in out, out
    code, out, _ = invoke("crane", "sensitivity", "--help")
    assert code == 0 and "[OPTIONS] KIND..." in out and "\n  KIND...  " in out, out
    code, out, _ = invoke("run", "--help")
    assert code == 0 and "--dt NUMBER" in out and "--save-every INTEGER" in out and "-o, --out FILE" in out


def test_models_describe_length_per_model() -> None:
    """``length`` said "(the spring's rest length l₀)" for every model: now the rod, the hoisted rope
    at t = 0, the spring's rest length, the string's length, each for its own model."""
    words = {}
    for model in ("ideal", "rotating", "hoisted", "spring", "string"):
        code, out, _ = invoke("models", model)
        assert code == 0, out
        line = next(line for line in out.splitlines() if line.strip().startswith("length "))
        words[model] = line.split("default 1", 1)[1].strip()
    assert "length of the rod from the pivot to the bob;" in words["ideal"]
    assert words["rotating"] == words["ideal"]
    assert "rope length at t = 0" in words["hoisted"]
    assert "rest length l₀ of the spring" in words["spring"]
    assert "length of the string" in words["string"]
    assert all("spring" not in words[m] for m in ("ideal", "rotating", "hoisted", "string"))
    code, out, _ = invoke("models")  # the list: a model's length shown where it means something else
    lines = out.splitlines()
    spring = lines.index(next(line for line in lines if line.startswith("spring:")))
    assert "rest length l₀ of the spring" in lines[spring + 1], lines[spring : spring + 3]
    ideal = lines.index(next(line for line in lines if line.startswith("ideal:")))
    assert lines[ideal + 1].strip() == "(no parameters of its own)"


def test_several_unknown_parameters_are_each_named_as_one_is() -> None:
    """Several unknown parameters: each with its did-you-mean, then the model's parameters once, in
    pl.Pendulum and ``pendulab fit --param`` alike (Pendulum named the first only; fit said "give
    NAME=VALUE with NAME one of ..." without a hint). Scenario files name each key as one problem."""
    import pendulab as pl

    damped = "the 'damped' model has no parameter"
    want = (
        f"invalid parameters dampin = 1, drg = 2: {damped} 'dampin' (did you mean 'damping'?); "
        f"{damped} 'drg' (did you mean 'drag'?); its parameters: length, mass, g, damping, drag,"
    )
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Pendulum(model="damped", dampin=1, drg=2)
    assert str(e.value).startswith(want), e.value
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Pendulum(foo=1, bar=2)
    nowhere = "no model has a parameter"
    two = f"invalid parameters foo = 1, bar = 2: {nowhere} 'foo'; {nowhere} 'bar'; Pendulum takes length"
    assert str(e.value).startswith(two), e.value
    with pytest.raises(pl.InvalidInputError) as e:
        pl.Pendulum(model="damped", dampin=1)
    one = f"invalid parameter dampin = 1: {damped} 'dampin' (did you mean 'damping'?); its parameters:"
    assert str(e.value).startswith(one), e.value
    code, out, err = invoke("fit", "d.csv", "--model", "damped", "--param", "dampin=1.5", "--param", "drg=x")
    fit = want.replace("dampin = 1, drg = 2", "dampin = 1.5, drg = 'x'")
    assert_user_error(code, out, err, "error: --param: " + fit)
