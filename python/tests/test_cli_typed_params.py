"""First contact with the command line: ``pendulab fit --param NAME=VALUE`` shows the value as typed
(``1``, ``2.00``, not ``1.0``, ``2.0``) in its refusals and on the report's ``fixed:`` line, while the
fit computes with the parsed number; a file that is missing, a directory or empty is refused naming it
and what belongs there (``pendulab crane run``; empty scenario and crane files)."""

from __future__ import annotations

from pathlib import Path

import pytest
from test_cli import assert_user_error, invoke

from pendulab.cli.fit import _typed_in_report

EMPTY = "nothing in it (an empty file, or only comments): a scenario file has the tables [pendulum]"


@pytest.mark.parametrize(
    ("item", "shown"),
    [
        ("length=-1", "--param length=-1: out of range; allowed: a number in [1e-6, 1e4] m (length l)"),
        ("length=1e9", "--param length=1e9: out of range; allowed: a number in [1e-6, 1e4] m"),
        ("mass=0", "--param mass=0: out of range; allowed: a number in [1e-6, 1e6] kg (bob mass m)"),
        ("length=abc", "--param length=abc: not a number; allowed: a number in [1e-6, 1e4] m"),
        ("length=nan", "--param length=nan: not a finite number; allowed: a number in [1e-6, 1e4] m"),
        (
            "lenght=1",
            "--param: invalid parameter lenght = 1: the 'ideal' model has no parameter 'lenght' "
            "(did you mean 'length'?)",
        ),
    ],
)
def test_param_refusals_show_the_value_as_typed(item: str, shown: str) -> None:
    """``--param length=-1`` was refused as ``invalid length = -1.0`` (and 1e9 as 1000000000.0): the
    parsed float, not what the user typed. The refusal comes before the data are read."""
    code, out, err = invoke("fit", "never_read.csv", "--param", item)
    assert_user_error(code, out, err, "error: " + shown)
    assert "1.0" not in err and "1000000000" not in err


def test_the_fixed_line_shows_the_values_as_typed() -> None:
    """Only the ``fixed:`` line's values given by --param change; fitted values and units stay."""
    report = "\n".join(
        [
            "  length     =        1.000000000 ± 0.001 m",
            "  chi2 = 10 for 8 degrees of freedom (chi2/dof = 1.25); noise positions: 0.001 m",
            "  fixed: mass = 2 kg, g = 9.81 m/s^2, damping = 0.05 1/s, forcing_x = 1",
        ]
    )
    typed = {"mass": "2.00", "g": "9.810", "forcing_x": "1.0", "length": "1.50"}
    lines = _typed_in_report(report, typed).splitlines()
    assert lines[:2] == report.splitlines()[:2]
    assert lines[2] == "  fixed: mass = 2.00 kg, g = 9.810 m/s^2, damping = 0.05 1/s, forcing_x = 1.0"


def test_a_fit_reports_the_held_values_as_typed() -> None:
    pytest.importorskip("scipy")
    code, out, err = invoke(
        "fit", "example:filmed_swing", "--fit", "length", "--param", "g=9.810", "--param", "mass=2.0"
    )
    assert code == 0, (out, err)
    assert "  fixed: mass = 2.0 kg, g = 9.810 m/s^2" in out.splitlines(), out


def test_crane_run_names_a_missing_file_or_a_directory(tmp_path: Path) -> None:
    """``pendulab crane run`` said ``x: No such file or directory`` and ``x: Is a directory`` (the
    system's words), without what the argument should be."""
    missing = str(tmp_path / "nope.toml")
    code, out, err = invoke("crane", "run", missing)
    assert_user_error(code, out, err, f"error: {missing}: No such file; give a crane file: TOML with [crane]")
    code, out, err = invoke("crane", "run", str(tmp_path))
    assert_user_error(code, out, err, f"error: {tmp_path}: a directory, not a crane file; give a crane file")


@pytest.mark.parametrize("command", [("run",), ("validate",), ("exact",), ("crane", "run")])
@pytest.mark.parametrize("text", ["", "# only a comment\n", "\ufeff\n\n"])
def test_an_empty_file_says_what_a_scenario_file_holds(
    tmp_path: Path, command: tuple[str, ...], text: str
) -> None:
    """An empty file was three problems, one per missing table (two for ``crane run``)."""
    path = tmp_path / "empty.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = invoke(*command, str(path))
    assert_user_error(code, out, err, f"error: {path}: {EMPTY}", "a crane file [crane] and [simulation]")
    assert "is missing" not in err
