"""Every numeric option of every ``pendulab`` command answers a value that is not of its type, not
finite or out of its declared range with the one ``error: …`` line naming the command, the option,
the value as typed and what is allowed, exit code 2 (docs/cli.md, "Exit codes and errors"). The
options are read from the Click commands, so a new option is covered without editing this file."""

from __future__ import annotations

from typing import Any

import pytest
from test_cli import assert_user_error, invoke
from typer.main import get_command

from pendulab import cli


def _commands(command: Any, path: tuple[str, ...]) -> list[tuple[tuple[str, ...], Any]]:
    if hasattr(command, "commands"):
        return [c for name, sub in command.commands.items() for c in _commands(sub, (*path, name))]
    return [(path, command)]


def _numeric_options() -> list[tuple[tuple[str, ...], str, Any]]:
    return [
        (path, param.opts[0], param)
        for path, command in _commands(get_command(cli.app), ())
        for param in command.params
        if param.param_type_name == "option" and param.type_descriptor.annotation in (float, int)
    ]


OPTIONS = _numeric_options()


def test_the_table_holds_every_command_with_numbers() -> None:
    """The enumeration sees the commands it should (a guard against a silently empty table)."""
    commands = {" ".join(path) for path, _, _ in OPTIONS}
    assert {"run", "sweep", "serve", "animate", "em-map", "crane shaper", "crane grid"} <= commands
    assert len(OPTIONS) >= 40


@pytest.mark.parametrize("value", ["abc", "nan", "inf", "-inf", ""])
@pytest.mark.parametrize(
    ("path", "option", "param"), OPTIONS, ids=[f"{' '.join(p)} {o}" for p, o, _ in OPTIONS]
)
def test_a_bad_number_names_the_option_and_the_value(
    path: tuple[str, ...], option: str, param: Any, value: str
) -> None:
    """Not a number (or not a whole one), nan, ±inf, empty: rejected while the command line is read."""
    code, out, err = invoke(*path, option, value)
    assert_user_error(
        code, out, err, f"pendulab {' '.join(path)}: {option}: {value!r} is not ", "; allowed: a "
    )


@pytest.mark.parametrize(
    ("path", "option", "param"),
    [o for o in OPTIONS if o[2].min is not None and o[2].min > -1],
    ids=[f"{' '.join(p)} {o}" for p, o, q in OPTIONS if q.min is not None and q.min > -1],
)
def test_a_number_out_of_its_declared_range_names_the_range(
    path: tuple[str, ...], option: str, param: Any
) -> None:
    """-1 for an option declared with a minimum (``--workers``, ``--port``): out of range, and the range."""
    code, out, err = invoke(*path, option, "-1")
    assert_user_error(code, out, err, f"{option}: '-1' is out of range; allowed: ", f"in [{param.min:g}, ")


def test_the_message_reads_well() -> None:
    """The message of docs/cli.md: the option, the value as typed, the kind and the option's help."""
    code, out, err = invoke("run", "rosette", "--dt", "abc")
    assert (code, out) == (2, "")
    assert err == (
        "error: pendulab run: --dt: 'abc' is not a number; allowed: a finite number (step size in s (> 0)); "
        "see 'pendulab run --help'\n"
    )


def _arguments() -> list[tuple[tuple[str, ...], Any]]:
    return [
        (path, command)
        for path, command in _commands(get_command(cli.app), ())
        if any(p.param_type_name == "argument" for p in command.params)
    ]


@pytest.mark.parametrize(("path", "command"), _arguments(), ids=[" ".join(p) for p, _ in _arguments()])
def test_arguments_read_alike_in_usage_lines_and_errors(path: tuple[str, ...], command: Any) -> None:
    """Every command's usage line writes its arguments as the docs do (``SCENARIO``, ``[MODEL]``,
    ``KINDS...``; not typer's ``{SCENARIO}`` or a lower-case ``{file}``), and a missing one is named
    the same way (``missing argument 'FILE'``)."""
    code, out, _err = invoke(*path, "--help")
    usage = out.splitlines()[0]
    assert code == 0 and usage.startswith(f"Usage: pendulab {' '.join(path)} [OPTIONS]"), out
    arguments = [p for p in command.params if p.param_type_name == "argument"]
    for p in arguments:
        name = p.name.upper() if p.metavar is None else p.metavar
        shown = (name if p.required else f"[{name}]") + ("..." if p.nargs != 1 else "")
        assert name.isupper() and f" {shown}" in usage and "{" not in usage, (shown, usage)
    required = [p for p in arguments if p.required]
    if required:
        name = required[0].metavar or required[0].name.upper()
        assert_user_error(*invoke(*path), f"pendulab {' '.join(path)}: missing argument '{name}'")
