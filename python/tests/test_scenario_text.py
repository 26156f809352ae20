"""Scenario text from outside (issue 30): a UTF-8 byte order mark is accepted (Windows editors write
one), control characters in the title and description (ANSI escape sequences that would recolour or
retitle the terminal printing them) are refused with a clear error, and the file's nesting check
still counts brackets right around strings and comments (its linear time: test_text_linear.py)."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import SCENARIOS
from test_cli import assert_user_error, invoke

import pendulab as pl
from pendulab.scenario import Scenario, ScenarioError
from pendulab.sweeps.file import load_sweep_file
from pendulab.validate import FILE_NESTING, check_nesting

ROSETTE = (SCENARIOS / "rosette.toml").read_text(encoding="utf-8")


def test_a_byte_order_mark_is_accepted_in_files_and_strings(tmp_path: Path) -> None:
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + ROSETTE.encode())
    assert pl.load_scenario(path).pendulum().length == Scenario.from_toml_str(ROSETTE).pendulum().length
    assert Scenario.from_toml_str("\ufeff" + ROSETTE).title == Scenario.from_toml_str(ROSETTE).title
    code, out, err = invoke("validate", str(path))
    assert code == 0, (out, err)


BASE = "\n".join(line for line in ROSETTE.splitlines() if not line.startswith("title = "))


@pytest.mark.parametrize(
    ("key", "value"),
    [
        ("title", "\\u001b]0;pwned\\u0007Rosette"),  # sets the terminal's window title
        ("title", "\\u001b[2J\\u001b[31mred"),  # clears the screen, red text
        ("title", "one\\ntwo"),  # a title is one line
        ("title", "\\u009b31m"),  # the one-character CSI
        ("description", "\\u001b[8mhidden"),
        ("description", "a\\u007fb"),
    ],
)
def test_control_characters_in_titles_are_refused(key: str, value: str, tmp_path: Path) -> None:
    text = f'{key} = "{value}"\n' + BASE
    with pytest.raises(ScenarioError, match="control character"):
        Scenario.from_toml_str(text)
    path = tmp_path / "escape.toml"
    path.write_text(text, encoding="utf-8")
    code, out, err = invoke("validate", str(path))
    assert_user_error(code, out, err, "control character")
    assert "\x1b" not in out + err and "\x9b" not in out + err


def test_a_description_may_have_line_breaks_and_tabs() -> None:
    text = 'description = """two\n\tlines"""\n' + BASE
    assert Scenario.from_toml_str(text).spec.description == "two\n\tlines"


@pytest.mark.parametrize(
    ("text", "deepest"),
    [
        ('a = "[[[["\nb = [1]', 1),
        ("a = '[[[['\nb = [[1]]", 2),
        ('a = """\n[[[[\\"""\n"""\nb = [1]', 1),
        ("a = '''\n[[[[\n'''\nb = [[[1]]]", 3),
        ("# [[[[[[[[\nb = [1]", 1),
        ('a = "\\\\"\nb = [[1]]', 2),  # an escaped backslash ends before the quote
        ('a = "\\"[[[[" \nb = [1]', 1),  # an escaped quote inside
        ('a = "unterminated [[[[\nb = [1]', 1),  # the string ends at its line's end
    ],
)
def test_the_nesting_check_counts_brackets_outside_strings_and_comments(text: str, deepest: int) -> None:
    def nest(k: int) -> str:  # b's value k levels deeper
        return text.replace("b = ", "b = " + "[" * k, 1) + "]" * k

    check_nesting(nest(FILE_NESTING - deepest))
    with pytest.raises(pl.InvalidInputError, match="nest more than"):
        check_nesting(nest(FILE_NESTING - deepest + 1))


def test_control_characters_in_a_sweep_title_are_refused(tmp_path: Path) -> None:
    sweep = (SCENARIOS.parent / "sweeps" / "sway.toml").read_text(encoding="utf-8")
    lines = [ln for ln in sweep.splitlines() if not ln.startswith("title = ")]
    path = tmp_path / "escape_sweep.toml"
    path.write_text('title = "\\u001b]0;pwned\\u0007sway"\n' + "\n".join(lines) + "\n", encoding="utf-8")
    code, out, err = invoke("sweep", str(path), "--out", str(tmp_path / "out.parquet"))
    assert_user_error(code, out, err, "control character")
    assert "\x1b" not in out + err
    path.write_bytes(b"\xef\xbb\xbf" + sweep.encode())  # a BOM is fine
    assert load_sweep_file(path).title == load_sweep_file(SCENARIOS.parent / "sweeps" / "sway.toml").title


def test_a_fitted_scenarios_title_drops_control_characters_of_the_uploads_name() -> None:
    from pendulab.server.fit import FitRequest, fit_data

    text = (SCENARIOS.parents[0] / "data" / "crane_sway.csv").read_text(encoding="utf-8")
    res = fit_data(FitRequest(csv=text, name="sway\x1b[31m.csv", model="damped"))
    title = Scenario.from_toml_str(res["scenario_toml"]).title
    assert title == "fitted to sway[31m.csv"
