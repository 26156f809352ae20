"""What every ``pendulab`` command shares: the typer ``app``, the exit codes, and the one-line error
reporting (``error: …`` on stderr, exit code 2 for a user error, 130 for Ctrl-C).

Command modules (``run``, ``exact``, ``sweep``, ``serve``, …) import ``app`` and these helpers from
here and register their commands on it; :mod:`pendulab.cli` imports each command module once.
Units are SI throughout.
"""

from __future__ import annotations

import contextlib
import os
import sys
from collections.abc import Iterator
from pathlib import Path
from typing import IO, Annotated, Any, NoReturn

import typer
from typer.core import TyperGroup

try:  # the Click that typer runs on: its own copy in recent typer, else the click package
    from typer._click.core import Context
    from typer._click.exceptions import UsageError
except ImportError:  # pragma: no cover - older typer
    from click import Context, UsageError  # type: ignore[assignment]

from .. import io
from .._core import IntegrationError, InvalidInputError, __version__
from ..scenario import ScenarioError
from ..scenario.examples import find as find_example

EXIT_USER_ERROR = 2
EXIT_INTERRUPTED = 130

_USER_ERRORS = (ScenarioError, InvalidInputError, IntegrationError, OSError, ImportError)


class _UsageError(UsageError):
    """A command-line usage error reported like every other user error: one line on stderr,
    ``error: pendulab run: no such option: --bogus; see 'pendulab run --help'``, exit code 2."""

    def show(self, file: IO[Any] | None = None) -> None:
        command = self.ctx.command_path if self.ctx is not None else "pendulab"
        text = " ".join(self.format_message().split()).rstrip(".")
        if text[:2].istitle():  # "No such option" → "no such option"; "SCENARIO" stays
            text = text[0].lower() + text[1:]
        see = f"{' See' if text.endswith('?') else '; see'} '{command} --help'"  # after "Did you mean …?"
        typer.echo(f"error: {command}: {text}{see}", file=file or sys.stderr)


def _one_line(e: UsageError) -> UsageError:
    """``e`` as a :class:`_UsageError` (the help that a bare group prints stays as it is)."""
    if isinstance(e, _UsageError) or type(e).__name__ == "NoArgsIsHelpError":
        return e
    one = _UsageError(e.format_message(), e.ctx)
    one.exit_code = e.exit_code
    return one


class _Commands(TyperGroup):
    """The ``pendulab`` group: Click's usage errors (unknown option or command, missing argument, a
    value of the wrong type), which it prints as three lines (Usage, Try --help, Error), become the
    one ``error: …`` line of every other user error (docs/cli.md)."""

    def make_context(
        self, info_name: str | None, args: list[str], parent: Context | None = None, **extra: Any
    ) -> Context:
        try:
            return super().make_context(info_name, args, parent, **extra)
        except UsageError as e:
            raise _one_line(e) from None

    def invoke(self, ctx: Context) -> Any:
        try:
            return super().invoke(ctx)
        except UsageError as e:
            raise _one_line(e) from None


app = typer.Typer(
    cls=_Commands,
    name="pendulab",
    help="Pendulab: the spherical pendulum, simulated right. SI units (m, kg, s, rad), z up.",
    epilog="Scenario files: docs/scenarios.md. This command: docs/cli.md. "
    "Exit codes: 0 ok, 2 user error, 130 interrupted (Ctrl-C).",
    no_args_is_help=True,
    add_completion=False,
    pretty_exceptions_enable=False,
    rich_markup_mode=None,
    context_settings={"help_option_names": ["-h", "--help"]},
)


def _say(message: str, *, err: bool = False) -> None:
    typer.echo(message, err=err)


def _fail(message: str, code: int = EXIT_USER_ERROR) -> NoReturn:
    _say(f"error: {message}", err=True)
    raise typer.Exit(code)


def _describe(e: BaseException) -> str:
    """One line for a user error (no traceback)."""
    if isinstance(e, OSError) and e.strerror:
        where = e.filename if e.filename is not None else ""
        return f"{where}: {e.strerror}" if where else e.strerror
    return " ".join(str(e).split()) or type(e).__name__


@contextlib.contextmanager
def _user_errors() -> Iterator[None]:
    """Turns user errors into ``error: …`` and exit code 2, Ctrl-C into exit code 130."""
    try:
        yield
    except _USER_ERRORS as e:
        _fail(_describe(e))
    except KeyboardInterrupt:
        _fail("interrupted (Ctrl-C)", EXIT_INTERRUPTED)


def _version(value: bool) -> None:
    if value:
        _say(f"pendulab {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: Annotated[
        bool,
        typer.Option("--version", help="Print the version and exit.", is_eager=True, callback=_version),
    ] = False,
) -> None:
    """Pendulab: the spherical pendulum, simulated right. SI units (m, kg, s, rad), z up."""


def _scenario_file(arg: Path) -> Path:
    """A SCENARIO argument: an existing file as given, else the shipped example of that name
    (``rosette``); FileNotFoundError naming it and the examples (a user error) otherwise."""
    return find_example(arg, "scenario")


def _sweep_file(arg: Path) -> Path:
    """A SWEEP argument: an existing file as given, else the shipped example sweep of that name."""
    return find_example(arg, "sweep")


def _check_output(out: Path) -> None:
    """Everything about --out that can be checked before the run: suffix, writer, directory."""
    try:
        fmt = io.format_of(out)
    except ValueError as e:
        _fail(str(e))
    if fmt == "parquet":
        io._require("pyarrow")
    elif fmt == "netcdf":
        io._require("xarray")
        io._require("scipy")
    if out.is_dir():
        _fail(f"--out {str(out)!r} is a directory; give a file name ending in .csv, .parquet or .nc")
    parent = out.resolve().parent
    if not parent.is_dir():  # --out does not create directories (docs/cli.md)
        _fail(f"--out {str(out)!r}: the directory {str(parent)!r} does not exist; create it first")
    if not os.access(parent, os.W_OK | os.X_OK):
        _fail(f"--out {str(out)!r}: cannot write to the directory {str(parent)!r}")


IMAGE_SUFFIXES = (".png", ".svg", ".pdf")


def _check_image(option: str, path: Path) -> None:
    """An image path (--plot, --out of a figure) checked before any work: a suffix matplotlib writes,
    not a directory, in a directory that exists (it is not created, docs/limits.md)."""
    if path.suffix.lower() not in IMAGE_SUFFIXES:
        _fail(f"{option}: unknown image suffix {path.suffix!r} in {str(path)!r}; use .png, .svg or .pdf")
    if path.is_dir():
        _fail(f"{option} {str(path)!r} is a directory; give a file name ending in .png, .svg or .pdf")
    parent = path.resolve().parent
    if not parent.is_dir():
        _fail(f"{option} {str(path)!r}: the directory {str(parent)!r} does not exist; create it first")
