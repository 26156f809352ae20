"""The ``pendulab`` command: run with each output format, methods, validate, scenarios, --version,
and the error contract (one ``error: …`` line on stderr, exit code 2, no traceback; Ctrl-C → 130)."""

from __future__ import annotations

import json
import sys
from pathlib import Path

import numpy as np
import pytest
from conftest import SCENARIOS, ctrl_c_after
from typer.testing import CliRunner

import pendulab as pl
from pendulab import cli

ROSETTE = str(SCENARIOS / "rosette.toml")
COLUMNS = ["t", "x", "y", "z", "vx", "vy", "vz", "energy", "j3", "tension", "constraint_error", "tangency"]
SHORT = ["--t-end", "0.5", "--save-every", "50"]  # 500 steps of 1 ms: samples at 0, 0.05, …, 0.5 s → 11


def invoke(*args: str) -> tuple[int, str, str]:
    """Runs the command in-process; returns (exit code, stdout, stderr)."""
    result = CliRunner().invoke(cli.app, list(args))
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        raise result.exception
    return result.exit_code, result.stdout, result.stderr


def assert_user_error(code: int, out: str, err: str, *needles: str) -> None:
    """Exit code 2 and one ``error: …`` line, the last on stderr, naming the needles; no traceback.
    (Status lines such as "running …" may precede it.)"""
    assert code == 2, (code, out, err)
    errors = [line for line in err.splitlines() if line.startswith("error: ")]
    assert len(errors) == 1 and err.rstrip("\n").endswith(errors[0]), err
    assert "Traceback" not in out + err
    for needle in needles:
        assert needle in errors[0], (needle, errors[0])


def read_table(path: Path) -> dict[str, np.ndarray]:
    """Columns of a written trajectory, whatever its format."""
    if path.suffix == ".csv":
        lines = path.read_text().splitlines()
        names = [h.split(" [")[0] for h in lines[1].split(",")]
        data = np.loadtxt(path, delimiter=",", skiprows=2, ndmin=2)
        return {name: data[:, k] for k, name in enumerate(names)}
    if path.suffix == ".parquet":
        import pyarrow.parquet as pq

        table = pq.read_table(path)
        return {name: table.column(name).to_numpy() for name in table.column_names}
    import xarray as xr

    with xr.open_dataset(path, engine="scipy") as ds:
        cols = {"t": ds["time"].values}
        for k, axis in enumerate("xyz"):
            cols[axis] = ds["x"].values[:, k]
            cols[f"v{axis}"] = ds["v"].values[:, k]
        for name in COLUMNS[7:]:
            cols[name] = ds[name].values
    return cols


@pytest.mark.parametrize("suffix", [".csv", ".parquet", ".nc"])
def test_run_writes_each_format(suffix: str, tmp_path: Path) -> None:
    """run --out FILE writes the format of the suffix, with every column and one row per saved sample,
    and prints the summary."""
    out = tmp_path / f"rosette{suffix}"
    code, stdout, stderr = invoke("run", ROSETTE, "--out", str(out), *SHORT)
    assert code == 0, stderr
    assert "energy:" in stdout and "J3:" in stdout and f"wrote {out} (11 samples)" in stdout
    cols = read_table(out)
    assert set(COLUMNS) <= set(cols)
    assert all(len(cols[name]) == 11 for name in COLUMNS)
    assert np.allclose(cols["t"], np.linspace(0.0, 0.5, 11), atol=1e-12) and cols["t"][-1] == 0.5
    radius = np.sqrt(cols["x"] ** 2 + cols["y"] ** 2 + cols["z"] ** 2)
    assert np.max(np.abs(radius - 1.0)) < 1e-14
    assert cols["z"][0] == pytest.approx(-0.5, abs=1e-15)  # θ₀ = 60° from the downward vertical


def test_run_overrides_and_quiet(tmp_path: Path) -> None:
    """--method/--dt override the file; --quiet prints nothing; the file records what was used."""
    out = tmp_path / "r.csv"
    code, stdout, stderr = invoke(
        "run", ROSETTE, "-q", "--method", "rattle4", "--dt", "0.01", "-o", str(out), *SHORT
    )
    assert code == 0 and stdout == "" and stderr == ""
    meta = json.loads(out.read_text().splitlines()[0].split("metadata (JSON): ", 1)[1])
    assert meta["method"] == "rattle4" and meta["options"]["dt"] == 0.01 and meta["stats"]["steps"] == 50


def test_run_summary_says_how_each_method_stepped_and_saved(tmp_path: Path) -> None:
    """The summary's method line in words: a fixed-step run's dt and saving; an adaptive run (dop853
    without dt) its tolerances, projection and saving, and no dt (it has no fixed step)."""
    code, stdout, stderr = invoke("run", ROSETTE, *SHORT)
    assert code == 0, stderr
    assert "\nmethod:   rattle, dt = 0.001 s, " in stdout and "saved every 50th step\n" in stdout
    adaptive = tmp_path / "adaptive.toml"
    text = Path(ROSETTE).read_text(encoding="utf-8").replace('"rattle"', '"dop853"')
    adaptive.write_text(text.replace("dt = 1.0e-3", "").replace("save_every = 10", ""), encoding="utf-8")
    code, stdout, stderr = invoke("run", str(adaptive), "--t-end", "0.5", "--rtol", "1e-9")
    assert code == 0, stderr
    line = next(line for line in stdout.splitlines() if line.startswith("method:"))
    assert line == (
        "method:   dop853, adaptive steps, rtol = 1e-09, atol = 1e-12, projected onto TS2 after each step, "
        "saved every accepted step"
    )
    assert "saving every accepted step" in stderr and "1-th" not in stderr


def test_bad_suffix_fails_before_the_run(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """An unknown output suffix is an error before any work, naming the allowed suffixes."""

    def no_run(*args: object, **kwargs: object) -> None:
        raise AssertionError("the run must not start")

    monkeypatch.setattr(pl.Scenario, "run", no_run)
    code, out, err = invoke("run", ROSETTE, "--out", str(tmp_path / "r.xlsx"))
    assert_user_error(code, out, err, "'.xlsx'", ".csv, .parquet, .nc")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    ("args", "needles"),
    [
        (["run", "missing.toml"], ["missing.toml", "No such file"]),
        (["run", ROSETTE, "--dt", "-0.001"], ["simulation.dt = -0.001: must be >= 1e-12"]),
        (["run", ROSETTE, "--method", "euler"], ["unknown method 'euler'", "rattle"]),
        (["run", ROSETTE, "--t-end", "nan"], ["--t-end: 'nan'", "finite"]),
        (["run", ROSETTE, "--t-end", "1e6", "--save-every", "1"], ["bytes", "raise save_every"]),
        (  # an IntegrationError: the angle method refuses at the pole of a planar swing
            ["run", str(SCENARIOS / "planar_large.toml"), "--method", "rk4_angles", "--t-end", "3"],
            ["rk4_angles", "pole"],
        ),
    ],
)
def test_user_errors_are_one_line(args: list[str], needles: list[str]) -> None:
    """Bad files, options and runs that cannot continue: ``error: …`` on stderr, exit code 2."""
    assert_user_error(*invoke(*args), *needles)


def test_run_names_the_file_as_typed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """typer made a Path of SCENARIO, so ``./nope.toml`` was named ``nope.toml``: now as typed, in the
    missing file's error, a bad file's problems and the "running …" line."""
    monkeypatch.chdir(tmp_path)
    for typed in ("./nope.toml", "sub/../nope.toml", ".//nope.toml"):
        code, out, err = invoke("run", typed)
        assert_user_error(code, out, err, f"error: {typed}: No such file")
    bad = (SCENARIOS / "rosette.toml").read_text().replace('method = "rattle"', 'method = "euler"')
    Path("bad.toml").write_text(bad)
    code, out, err = invoke("run", "./bad.toml")
    assert_user_error(code, out, err, "error: ./bad.toml: simulation.method = 'euler': unknown method")
    Path("good.toml").write_text((SCENARIOS / "rosette.toml").read_text())
    code, out, err = invoke("run", "./good.toml", *SHORT)
    assert code == 0 and err.startswith("running ./good.toml: "), err


@pytest.mark.parametrize(
    ("command", "options"),
    [
        (["validate"], []),
        (["exact"], []),
        (["phases"], []),
        (["reduced"], ["--out", "r.png"]),
        (["plot"], ["--out", "p.png"]),
        (["animate"], ["--out", "m.gif"]),
        (["sweep"], ["--out", "s"]),
        (["crane", "run"], []),
    ],
)
def test_every_command_names_its_file_as_typed(
    command: list[str], options: list[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """As ``pendulab run`` (above): typer's Path made ``./nope.toml`` ``nope.toml`` in the messages of
    validate, sweep, exact, phases, reduced, plot, animate and crane run (crane.scenario.load names the
    file by its Path too)."""
    monkeypatch.chdir(tmp_path)
    for typed in ("./nope.toml", ".//nope.toml"):
        code, out, err = invoke(*command, typed, *options)
        assert_user_error(code, out, err, f"error: {typed}: No such file")
    Path("bad.toml").write_text("[pendulum]\nlength = -1.0\n")
    code, out, err = invoke(*command, "./bad.toml", *options)
    if command == ["validate"]:  # one line per problem
        assert code == 2 and all(line.startswith("error: ./bad.toml: ") for line in err.splitlines()), err
    else:
        assert_user_error(code, out, err, "error: ./bad.toml: ")


def test_validate_and_sweep_name_good_files_as_typed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    Path("good.toml").write_text((SCENARIOS / "rosette.toml").read_text())
    code, out, err = invoke("validate", "./good.toml", ".//good.toml", "rosette")
    assert code == 0 and out.startswith("./good.toml: OK (Rosette") and "\n.//good.toml: OK (" in out, out
    sway = (SCENARIOS.parent / "sweeps" / "sway.toml").read_text()
    Path("sweep.toml").write_text(
        sway.replace("num = 40", "num = 2").replace("num = 25", "num = 1").replace("20.0", "0.1")
    )
    code, out, err = invoke("sweep", "./sweep.toml", "--out", "sweep")
    assert code == 0 and err.startswith("sweep ./sweep.toml: Max sway"), (code, out, err)


@pytest.mark.parametrize(
    ("args", "needles"),
    [
        (["run", ROSETTE, "--bogus"], ["pendulab run: no such option: --bogus", "'pendulab run --help'"]),
        (["run"], ["pendulab run: missing argument 'SCENARIO'", "'pendulab run --help'"]),
        (["run", ROSETTE, "--dt", "abc"], ["pendulab run: --dt: 'abc' is not a number; allowed:", "--help"]),
        (["run", ROSETTE, "extra.toml"], ["unexpected extra argument", "extra.toml"]),
        (["bogus"], ["pendulab: no such command 'bogus'", "'pendulab --help'"]),
        (["--bogus"], ["pendulab: no such option: --bogus", "'pendulab --help'"]),
        (["crane", "bogus"], ["pendulab crane: no such command 'bogus'", "'pendulab crane --help'"]),
        (["crane", "run"], ["pendulab crane run: missing argument 'FILE'", "'pendulab crane run --help'"]),
    ],
)
def test_usage_errors_are_one_line_too(args: list[str], needles: list[str]) -> None:
    """Unknown options and commands, missing or extra arguments, values of the wrong type: the one
    ``error: …`` line of every user error (not Click's Usage / Try / Error block), naming the command
    and its --help; exit code 2."""
    code, out, err = invoke(*args)
    assert_user_error(code, out, err, *needles)
    assert err.count("\n") == 1 and "Usage:" not in err and "Try " not in err


def test_a_bare_group_still_prints_its_help() -> None:
    """``pendulab`` and ``pendulab crane`` alone list their commands (Click's help, exit code 2)."""
    for args in ([], ["crane"]):
        code, out, err = invoke(*args)
        assert code == 2 and "Commands:" in out + err and "error:" not in out + err


def test_bad_scenario_file_error(tmp_path: Path) -> None:
    """A bad file is named with the key and value, in one line."""
    bad = tmp_path / "bad.toml"
    bad.write_text((SCENARIOS / "rosette.toml").read_text().replace("length = 1.0", "length = -2.0"))
    assert_user_error(*invoke("run", str(bad)), str(bad), "pendulum.length = -2.0")


def test_methods_json_and_table() -> None:
    """methods --json is the registry as JSON; the table names every method and marks the default."""
    code, out, _ = invoke("methods", "--json")
    assert code == 0
    table = json.loads(out)
    assert table == pl.methods()
    assert "rattle" in [m["name"] for m in table]
    code, out, _ = invoke("methods")
    assert code == 0 and "rattle (default)" in out
    assert all(m["name"] in out for m in table)


def test_validate_good_and_bad(tmp_path: Path) -> None:
    """validate prints OK per good file and every problem of a bad one; exit 2 if any is bad."""
    code, out, err = invoke("validate", *map(str, sorted(SCENARIOS.glob("*.toml"))))
    assert code == 0 and err == ""
    assert out.count(": OK") == len(list(SCENARIOS.glob("*.toml")))
    bad = tmp_path / "bad.toml"
    bad.write_text(
        (SCENARIOS / "rosette.toml")
        .read_text()
        .replace("mass = 1.0", "mass = nan")
        .replace('method = "rattle"', 'method = "rk5"')
    )
    syntax = tmp_path / "syntax.toml"
    syntax.write_text("[pendulum]\nlength = \n")
    code, out, err = invoke("validate", ROSETTE, str(bad), str(syntax))
    assert code == 2
    assert f"{ROSETTE}: OK" in out
    lines = err.strip().splitlines()
    assert len(lines) == 3 and all(line.startswith("error: ") for line in lines)
    assert "pendulum.mass = nan" in lines[0] and "unknown method 'rk5'" in lines[1]
    assert f"{syntax}, line 2: invalid TOML" in lines[2]


def test_scenarios_lists_the_examples() -> None:
    """scenarios lists every shipped example with its title."""
    code, out, _ = invoke("scenarios")
    assert code == 0
    for path in SCENARIOS.glob("*.toml"):
        line = next(line for line in out.splitlines() if line.startswith(path.stem + " "))
        assert pl.load_scenario(path).title in line


def test_examples_by_name(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """run, validate and exact take a shipped example's name; the listing has the sweeps too; an
    unknown name is a user error listing the examples; a local file of that name wins."""
    monkeypatch.chdir(tmp_path)  # outside the checkout: the examples come from the package
    code, out, err = invoke("run", "rosette", *SHORT, "-q", "--out", "r.csv")
    assert code == 0, err
    rows = [line for line in Path("r.csv").read_text().splitlines() if line and not line.startswith("#")]
    assert len(rows) == 1 + 11  # the header and 11 samples
    code, out, _ = invoke("validate", "conical", "near_top.toml")
    assert code == 0 and out.count(": OK") == 2
    code, out, _ = invoke("exact", "rosette", "--t", "0:1:0.5", "-q", "--out", "e.csv")
    assert code == 0 and Path("e.csv").is_file()
    code, out, _ = invoke("scenarios")
    assert code == 0 and "Example sweeps" in out
    assert all(name in out for name in ("rotation_number", "sway", "crane_settle"))
    code, _, err = invoke("run", "no_such_example")
    assert code == 2 and err.count("\n") == 1
    assert "no_such_example: No such file, and no example scenario of that name" in err and "rosette" in err
    mine = (SCENARIOS / "zero_g.toml").read_text().replace("Zero gravity: a great circle", "my own")
    Path("rosette").write_text(mine)
    code, out, _ = invoke("validate", "rosette")
    assert code == 0 and out.strip() == "rosette: OK (my own)"


def test_fit_help_shows_what_to_type_not_python_types() -> None:
    """pendulab fit --help names the values of its repeatable and composite options by what to type
    (typer showed ``--sigma <list[str]>`` and ``--param <list[str]>``)."""
    code, out, _ = invoke("fit", "--help")
    assert code == 0
    flat = " ".join(out.split())
    for shown in ("--sigma VALUE|KIND=VALUE", "--param NAME=VALUE", "--pivot X,Y,Z"):
        assert shown in flat, (shown, out)
    assert "list[" not in out, out


def test_serve_help_names_the_host_not_a_python_type() -> None:
    """pendulab serve --help shows ``--allow-host HOST`` (typer showed ``--allow-host <list[str]>``)."""
    code, out, _ = invoke("serve", "--help")
    assert code == 0
    assert "--allow-host HOST" in " ".join(out.split()), out
    assert "list[" not in out, out


def test_version_and_help() -> None:
    """--version prints the version; --help lists every command, run --help every option."""
    code, out, _ = invoke("--version")
    assert code == 0 and out.strip() == f"pendulab {pl.__version__}"
    code, out, _ = invoke("--help")
    assert code == 0
    assert all(name in out for name in ("run", "methods", "validate", "scenarios", "--version"))
    code, out, _ = invoke("run", "--help")
    options = [
        "--out",
        "--method",
        "--dt",
        "--t-end",
        "--save-every",
        "--rtol",
        "--atol",
        "--progress",
        "--quiet",
    ]
    assert code == 0 and all(option in out for option in options)


def test_projection_is_reported(tmp_path: Path) -> None:
    """A Cartesian start with project = true runs, and run says by how much it was moved."""
    path = tmp_path / "cartesian.toml"
    path.write_text(
        "[pendulum]\nlength = 1.0\nmass = 1.0\n[initial]\nx = [0.0, 0.0, -1.1]\nv = [0.3, 0.0, 0.2]\n"
        "project = true\n[simulation]\nt_end = 0.1\n"
    )
    code, _, err = invoke("run", str(path))
    assert code == 0
    assert "projected the start onto TS²: moved x by 0.1 m, v by 0.2 m/s" in err


def test_ctrl_c_writes_what_was_computed(tmp_path: Path) -> None:
    """SIGINT during a long run: the samples so far are written, stderr says so, exit code 130."""
    out = tmp_path / "long.csv"
    cmd = [sys.executable, "-m", "pendulab.cli", "run", ROSETTE, "--t-end", "1e6", "--save-every", "1000"]
    # "running …" is printed just before the run starts
    proc = ctrl_c_after([*cmd, "--out", str(out)], "running", stream="stderr", wait=0.3, timeout=20)
    stdout, stderr = proc.stdout, proc.stderr
    assert proc.returncode == 130, stderr
    assert "interrupted (Ctrl-C) at t = " in stderr and f"to {out}" in stderr
    assert "Traceback" not in stderr and "INTERRUPTED" in stdout
    data = np.loadtxt(out, delimiter=",", skiprows=2, ndmin=2)
    assert len(data) > 1 and 0.0 < data[-1, 0] < 1e6
    assert np.all(np.isfinite(data))
