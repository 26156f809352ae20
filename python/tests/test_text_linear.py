"""Every reader of text from outside runs in linear time (issue 30): the scenario-file nesting check,
the data-file layout (separator, header, preamble), header cells and their units, and the numeric
body. Each test times a hostile input of size n and 2n (the cases that took 15-28 s at 30-80 kB with
backtracking regular expressions) and asserts the time at most roughly doubles plus a constant: the
minimum of a few repeats, generous constants, sizes where a quadratic reader would take seconds."""

from __future__ import annotations

import time
from collections.abc import Callable

import pytest

import pendulab as pl
from pendulab.fitting.columns import column, split_unit
from pendulab.fitting.table import parse_table
from pendulab.scenario import Scenario, ScenarioError
from pendulab.validate import check_nesting

REPEATS = 3
SLACK = 0.25
"""Seconds added to the bound at size 2n: scheduling noise on a loaded 2-core machine. A quadratic
reader at these sizes takes seconds at size 2n (17.9 s at 32 kB for the old nesting check)."""
FACTOR = 3.0
"""The most the time may grow from n to 2n: 2 for a linear reader, 4 for a quadratic one."""


def _seconds(run: Callable[[], object]) -> float:
    start = time.perf_counter()
    run()
    return time.perf_counter() - start


def _assert_linear(make: Callable[[int], str], run: Callable[[str], object], n: int) -> None:
    """The minimum of :data:`REPEATS` runs at n and 2n, interleaved so that a change of the machine's
    load falls on both sizes."""
    small, large = make(n), make(2 * n)
    t1 = t2 = float("inf")
    for _ in range(REPEATS):
        t1 = min(t1, _seconds(lambda: run(small)))
        t2 = min(t2, _seconds(lambda: run(large)))
    assert t2 <= FACTOR * t1 + SLACK, f"{t1:.3f} s at {len(small)} chars, {t2:.3f} s at {len(large)}"


def _quiet(call: Callable[[str], object]) -> Callable[[str], object]:
    """``call``, its user errors swallowed (a hostile input is refused: the time is what counts)."""

    def run(text: str) -> object:
        try:
            return call(text)
        except (pl.InvalidInputError, ScenarioError):
            return None

    return run


@pytest.mark.parametrize(
    "unit",
    [
        '\\"',  # an unterminated basic string of escaped quotes (17.9 s at 32 kB before)
        "'a",  # literal strings opened on one line
        '"a\\',  # escapes running to the line's end
        '"""\\',  # an unterminated multi-line string of escapes
        "# [",  # brackets in comments
        "1.5, ",  # floats: a dot each, the key's count reset by every comma
        'a."=".',  # quoted key parts holding a break
        "'''",
    ],
)
def test_the_nesting_check_is_linear(unit: str) -> None:
    _assert_linear(lambda n: "title = " + unit * (n // len(unit)), _quiet(check_nesting), 200_000)


def test_a_scenario_with_an_unterminated_string_is_refused_in_linear_time() -> None:
    _assert_linear(lambda n: 'title = "' + '\\"' * (n // 2) + "\n", _quiet(Scenario.from_toml_str), 200_000)


@pytest.mark.parametrize(
    "first_line",
    [
        ",'a",  # froze the lab server 28 s at 78 kB (csv.Sniffer's regular expressions)
        '"a",',
        "t,(",
        "; ",
        "\t\"'",
    ],
)
def test_the_data_file_layout_is_found_in_linear_time(first_line: str) -> None:
    _assert_linear(lambda n: first_line * (n // len(first_line)) + "\n0,1,2\n", _quiet(parse_table), 30_000)


@pytest.mark.parametrize("unit", ["(", "[", "x (", " / ", ": ", "(]"])
def test_header_cells_and_units_are_split_in_linear_time(unit: str) -> None:
    """A 30 kB header cell of ``(`` took 15 s (a lazy name before a bracketed unit)."""
    _assert_linear(lambda n: unit * (n // len(unit)) + ")", split_unit, 200_000)
    _assert_linear(lambda n: unit * (n // len(unit)) + "z", _quiet(lambda c: column(c, "<h>")), 200_000)
    _assert_linear(lambda n: "t," + unit * (n // len(unit)) + ",x,z\n0,1,2,3\n", _quiet(parse_table), 30_000)


@pytest.mark.parametrize(
    "row",
    [
        "0; " + "{pad}" + "x\n",  # blanks inside a cell, then a bad cell
        "0;" + "{pad}" + ";1;2\n",  # a cell of blanks (an empty cell)
        '0,1,"' + "{pad}" + "\n",  # an unterminated quote
    ],
)
def test_the_data_rows_are_read_in_linear_time(row: str) -> None:
    def make(n: int) -> str:
        sep = ";" if ";" in row else ","
        return sep.join(["t", "x", "z"]) + "\n" + row.replace("{pad}", " " * n)

    _assert_linear(make, _quiet(parse_table), 100_000)


def test_many_rows_are_read_in_linear_time() -> None:
    def make(n: int) -> str:
        return "t,x,z\n" + "".join(f"{i},0.{i % 97},-0.5\n" for i in range(n // 12))

    _assert_linear(make, parse_table, 1_200_000)


CAP_SECONDS = 20.0
"""A bound on one read at the caps: linear readers take well under a second (idle), a quadratic one
hours (a 2 MiB first line of ``,'a`` at 28 s per 78 kB)."""


@pytest.mark.parametrize(
    "unit",
    [",'a", "(", '"a",', "\t\"'", "0; ", "t,x,z\n0,1,2\n", "#\n", ",,\n", "\ufeff", " / ", ": "],
)
def test_an_upload_at_the_servers_cap_is_read_in_seconds(unit: str) -> None:
    """The lab's fit upload is at most 2 MiB (server/fit.py MAX_FIT_BYTES): hostile text of that size,
    as one line and as many lines, is read or refused within :data:`CAP_SECONDS`."""
    cap = 2 * 2**20
    for text in (unit * (cap // len(unit)), ("t,x,z\n" + unit + "\n") * (cap // (len(unit) + 7))):
        start = time.perf_counter()
        _quiet(parse_table)(text)
        assert time.perf_counter() - start < CAP_SECONDS


@pytest.mark.parametrize("unit", ['\\"', "'", '"""', "[", "]", "#", "{", '"\\', "a = '''", ".a", "1.5, "])
def test_a_scenario_file_at_its_cap_is_checked_in_seconds(unit: str) -> None:
    """Scenario and sweep files are at most 1 MiB (validate.FILE_BYTES)."""
    text = "title = " + unit * ((2**20 - 8) // len(unit))
    start = time.perf_counter()
    _quiet(check_nesting)(text)
    _quiet(Scenario.from_toml_str)(text)
    assert time.perf_counter() - start < CAP_SECONDS


@pytest.mark.parametrize(
    "text",
    [
        "a" + ".a" * 16_000 + " = 1",
        "a" + '."="' * 16_000 + " = 1",
        "[a" + ".a" * 16_000 + "]",
        "x = {a" + ".a" * 16_000 + " = 1}",
    ],
)
def test_a_dotted_key_of_many_parts_is_refused_before_parsing(text: str) -> None:
    """The audit of issue 30: tomllib's work for a dotted key grows with the square of its parts
    (16 000 parts: 15 s; a 1 MiB file holds 500 000); more than 16 parts are refused at once, and
    ordinary dotted keys, floats and times still pass."""
    start = time.perf_counter()
    with pytest.raises(ScenarioError, match="dotted key nests more than 16 levels"):
        Scenario.from_toml_str(text)
    assert time.perf_counter() - start < 1.0
    check_nesting("a.b.c = 1.5\nt = 1979-05-27T07:32:00.999\nx = [1.5, 2.5, {y.z = 0.5}]\n" * 1000)
