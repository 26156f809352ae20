"""What a command can check about its options it checks before any work (docs/cli.md): a figure's
suffix and folder for ``fit --plot``/``--out``, ``phases --plot``/``--dt``, ``em-map``, ``reduced`` and
the crane commands; ``pendulab sweep --out`` in a folder that does not exist is refused, not created
(docs/limits.md, "Output directories are not created"). Found by the first-contact audit of the docs."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.cli import fit as fit_cli


@pytest.fixture
def no_fit(monkeypatch: pytest.MonkeyPatch) -> None:
    """A fit that must not start: the checks come first."""

    def refuse(*args: object, **kwargs: object) -> None:
        raise AssertionError("the fit ran before its options were checked")

    monkeypatch.setattr(fit_cli, "fit", refuse)


@pytest.mark.usefixtures("no_fit")
@pytest.mark.parametrize(
    ("option", "name", "needle"),
    [
        ("--plot", "fit.xyz", "unknown image suffix '.xyz'"),
        ("--plot", "missing/fit.png", "does not exist"),
        ("--out", "missing/fitted.toml", "does not exist"),
    ],
)
def test_fit_checks_its_files_before_fitting(tmp_path: Path, option: str, name: str, needle: str) -> None:
    target = tmp_path / name
    assert_user_error(*invoke("fit", "example:crane_sway", option, str(target)), option, needle)
    assert not (tmp_path / "missing").exists()


@pytest.mark.parametrize(
    "args",
    [
        ("phases", "rosette", "--plot", "{d}/missing/p.png"),
        ("em-map", "--grid", "4x4", "--out", "{d}/missing/em.png"),
        ("em-map", "--grid", "4x4", "--out", "{d}/missing/em.csv"),
        ("reduced", "rosette", "--out", "{d}/missing/r.png"),
        ("crane", "residual", "--plot", "{d}/missing/s.png"),
    ],
)
def test_a_figure_in_a_missing_folder_is_refused_first(tmp_path: Path, args: tuple[str, ...]) -> None:
    code, out, err = invoke(*(a.format(d=tmp_path) for a in args))
    assert_user_error(code, out, err, "does not exist; create it first")
    assert out == "", out  # nothing computed or printed before the refusal
    assert not (tmp_path / "missing").exists()


def test_phases_refuses_a_bad_dt_before_printing() -> None:
    code, out, err = invoke("phases", "rosette", "--dt", "-1")
    assert_user_error(code, out, err, "--dt -1.0", "> 0 s")
    assert out == ""


@pytest.mark.parametrize("name", ["missing/sway/", "missing/sway.parquet"])
def test_a_sweep_into_a_missing_folder_is_refused(tmp_path: Path, name: str) -> None:
    design = {"theta0": np.array([0.1, 0.2])}
    with pytest.raises(pl.InvalidInputError, match="does not exist; create it first"):
        pl.sweep(design, "period", out=tmp_path / name)
    assert not (tmp_path / "missing").exists()
    sw = pl.sweep(design, "period", out=tmp_path / "sway")  # the sweep's own folder is still made
    assert (tmp_path / "sway" / "_manifest.json").is_file() and len(sw["period"]) == 2


def test_a_crane_file_without_its_tables_names_them(tmp_path: Path) -> None:
    path = tmp_path / "c.toml"
    path.write_text("[simulation]\ndt = 0.1\n", encoding="utf-8")
    assert_user_error(
        *invoke("crane", "run", str(path)), "the table [crane] is missing", "simulation.t_end is missing"
    )


def test_the_command_list_shows_the_crane_help_whole() -> None:
    code, out, _ = invoke("--help")
    line = next(ln for ln in out.splitlines() if ln.strip().startswith("crane "))
    assert code == 0 and not line.rstrip().endswith("..."), line


def test_a_parameter_not_determined_has_its_unit_beside_its_value() -> None:
    p = pl.Pendulum(length=0.8, model="damped", damping=0.05)
    t = np.linspace(0.0, 8.0, 400)
    tr = pl.simulate(p, p.state_from_angles(0.3, 0.0, 0.0, 0.0), 8.0, method="dop853", save_at=t)
    angle = np.arctan2(tr.x[:, 0], -tr.x[:, 2]) + np.random.default_rng(1).normal(0.0, 1e-3, t.size)
    res = pl.fit(t, planar_angle=angle, pendulum=pl.Pendulum(model="damped"), fit=["length", "g", "damping"])
    rows = [ln for ln in res.report().splitlines() if ln.strip().startswith(("length ", "g "))]
    assert len(rows) == 2, res.report()
    for row, unit in zip(rows, ("m", "m/s^2"), strict=True):
        head, found, _ = row.partition("not determined")
        assert found and head.split()[-1] == unit, row


def test_animate_states_its_gif_choices_only_once_they_are_checked(tmp_path: Path) -> None:
    code, out, err = invoke("animate", "rosette", "--out", str(tmp_path / "a.gif"), "--fps", "-1")
    assert_user_error(code, out, err, "fps = -1.0")
    assert "GIF:" not in err, err  # was "GIF: 640x360 at -1 frames/s" before the refusal


def test_a_folder_given_as_a_scenario_is_called_a_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "runs").mkdir()
    monkeypatch.chdir(tmp_path)
    assert_user_error(*invoke("validate", "runs"), "runs: a directory, not a scenario file", "rosette")
    assert_user_error(*invoke("fit", "runs"), "runs: a directory, not a data file")


def test_the_lab_finds_a_scenario_as_every_command_does(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from pendulab.server.scenarios import resolve_scenario

    monkeypatch.chdir(tmp_path)  # no rosette.toml here: the example, as `pendulab run rosette.toml` takes it
    assert resolve_scenario("rosette.toml").name == resolve_scenario("example:rosette").name == "rosette"
    (tmp_path / "rosette").write_text(  # a file wins over an example of the same name (docs/cli.md)
        "title = 'mine'\n[pendulum]\nlength = 2.0\nmass = 1.0\n"
        "[initial]\ntheta = 0.5\n[simulation]\nt_end = 1.0\n",
        encoding="utf-8",
    )
    assert resolve_scenario("rosette").title == "mine"
    (tmp_path / "runs").mkdir()
    with pytest.raises(pl.ScenarioError, match="runs: a directory, not a scenario file"):
        resolve_scenario("runs")


def _command_paths() -> list[tuple[str, ...]]:
    from typer.main import get_command

    from pendulab import cli

    paths: list[tuple[str, ...]] = [()]
    root: Any = get_command(cli.app)  # a group: .commands by name (typer's own click classes)
    for name, cmd in root.commands.items():
        paths.append((name,))
        paths += [(name, sub) for sub in getattr(cmd, "commands", {})]
    return paths


def test_every_help_reads_cleanly() -> None:
    """No doubled brackets in a usage line (``[[MODEL]]``), no reST quotes, no cut-off summaries."""
    paths = _command_paths()
    assert len(paths) > 20
    for path in paths:
        code, out, _ = invoke(*path, "--help")
        assert code == 0, path
        assert "[[" not in out and "``" not in out, (path, out)
        summaries = [line for line in out.splitlines() if not line.startswith("Usage:")]  # [ARGS]... is fine
        assert not any(line.rstrip().endswith("...") for line in summaries), (path, out)
