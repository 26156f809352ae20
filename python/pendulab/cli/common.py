"""What every ``pendulab`` command shares: the typer ``app``, the exit codes, and the one-line error
reporting (``error: …`` on stderr, exit code 2 for a user error, 130 for Ctrl-C).

Command modules (``run``, ``exact``, ``sweep``, ``serve``, …) import ``app`` and these helpers from
here and register their commands on it; :mod:`pendulab.cli` imports each command module once.
Units are SI throughout.
"""

from __future__ import annotations

import contextlib
import functools
import math
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
        if parent is None:
            _tidy(self)
        try:
            return super().make_context(info_name, args, parent, **extra)
        except UsageError as e:
            raise _one_line(e) from None

    def invoke(self, ctx: Context) -> Any:
        try:
            return super().invoke(ctx)
        except UsageError as e:
            raise _one_line(e) from None


_KINDS = {float: "a number", int: "a whole number", Path: "a path"}
_RANGE_ERRORS = ("greater_than", "greater_than_equal", "less_than", "less_than_equal")


def _first_clause(text: str) -> str:
    """``text`` up to its first ``;`` or sentence end outside parentheses, without the full stop."""
    depth = 0
    for i, c in enumerate(text):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth == 0 and (c == ";" or text.startswith(". ", i)):
            return text[:i]
    return text.rstrip(".")


def _allowed(param: Any) -> str:
    """What ``param`` takes, for an error: its kind, range and the first clause of its help,
    ``a whole number in [1, 1024] (threads …)``."""
    kind = _KINDS.get(param.type_descriptor.annotation, "a value")
    if param.min is not None or param.max is not None:
        lo = "-inf" if param.min is None else f"{param.min:g}"
        hi = "inf" if param.max is None else f"{param.max:g}"
        kind += f" in [{lo}, {hi}]"
    elif param.type_descriptor.annotation is float:
        kind = "a finite number"
    what = _first_clause(" ".join((getattr(param, "help", None) or "").split()))
    first = what.split(" ")[0]
    if first[1:].islower():  # "Step size in s" → "step size in s"; "RATTLE8 step", "V_tol" stay
        what = what[0].lower() + what[1:]
    return f"{kind} ({what})" if what else kind


def _checked(param: Any) -> Any:
    """``param.process_value`` that names the option, the value as typed and what is allowed when the
    value is not of the option's type (typer's own message is pydantic's ``Input should be a valid
    number``, without either), and that turns away nan and inf for a float."""
    process = param.process_value
    name = param.opts[0] if param.param_type_name == "option" else param.display_name_raw

    def process_value(ctx: Context, value: Any) -> Any:
        try:
            out = process(ctx, value)
        except UsageError as e:
            errors = getattr(e.__cause__, "errors", None)
            if not callable(errors) or not isinstance(value, str):
                raise
            first = (errors() or [{}])[0].get("type", "")
            problem = f"is not {_KINDS.get(param.type_descriptor.annotation, 'allowed')}"
            if first in _RANGE_ERRORS:
                problem = "is out of range" if math.isfinite(float(value)) else "is not a finite number"
            raise UsageError(f"{name}: {value!r} {problem}; allowed: {_allowed(param)}", ctx) from None
        if isinstance(out, float) and not math.isfinite(out):
            raise UsageError(f"{name}: {value!r} is not a finite number; allowed: {_allowed(param)}", ctx)
        return out

    return process_value


_METAVARS = {float: "NUMBER", int: "INTEGER", str: "TEXT", Path: "PATH"}


def _tidy(command: Any) -> None:
    """Once per command line, on every parameter of every command under ``command``: the messages of
    :func:`_checked`; arguments named by an upper-case metavar in usage lines, ``--help`` and errors
    alike (``SCENARIO...`` for a list), an option's value by a word (``--dt NUMBER``), never by typer's
    Python type (``SCENARIO <list[str]>``, ``--dt <float>``)."""
    for sub in getattr(command, "commands", {}).values():
        _tidy(sub)
    for param in command.params:
        typed = hasattr(param, "type_descriptor")
        if typed and not getattr(param, "is_flag", False):
            param.process_value = _checked(param)
        if param.param_type_name == "argument":
            param.metavar = param.metavar or param.name.upper()
            param._usage_display_name = functools.partial(_usage_name, param)
            param._rich_display_name = functools.partial(_listed_name, param)
            param.display_type_rich = _no_type
        elif typed and param.metavar is None and not getattr(param, "is_flag", False):
            param.metavar = _METAVARS.get(param.type_descriptor.annotation, "VALUE")


def _no_type(ctx: Context) -> None:
    """No type after an argument's name in ``--help`` (typer wrote ``SCENARIO <str>``)."""
    return None


def _listed_name(param: Any) -> str:
    """An argument in ``--help``'s list: ``SCENARIO``, ``SCENARIO...`` if repeatable."""
    return str(param.metavar) + ("..." if param.nargs != 1 else "")


def _usage_name(param: Any) -> str:
    """An argument in a usage line as in ``missing argument 'SCENARIO'`` and the docs: ``SCENARIO``
    if required, ``[MODEL]`` if not, ``SCENARIO...`` if repeatable (typer writes ``{SCENARIO}``)."""
    name = param.metavar if param.required else f"[{param.metavar}]"
    return name + ("..." if param.nargs != 1 else "")


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


def _as_typed(arg: str | Path, kind: str) -> str:
    """The file a SCENARIO or SWEEP argument names, for the loaders whose messages name it: ``arg`` as
    typed when it is a file (``./x.toml``, not the ``x.toml`` of ``Path``: take such arguments as
    ``str``, as typer normalises a ``Path``), else the shipped example ``kind`` of that name;
    FileNotFoundError naming it as typed and the examples (a user error) otherwise."""
    found = find_example(arg, kind)
    return os.fspath(arg) if found == Path(arg) else os.fspath(found)


def _scenario_file(arg: str | Path) -> str:
    """A SCENARIO argument: an existing file as typed, else the shipped example of that name
    (``rosette``) — :func:`_as_typed`."""
    return _as_typed(arg, "scenario")


def _sweep_file(arg: str | Path) -> str:
    """A SWEEP argument: an existing file as typed, else the shipped example sweep of that name."""
    return _as_typed(arg, "sweep")


def _check_output(out: str | Path) -> None:
    """Everything about --out that can be checked before the run: suffix, writer, directory; the
    messages name ``out`` as typed (take such options as ``str``: typer normalises a ``Path``)."""
    typed, out = os.fspath(out), Path(out)
    try:
        fmt = io.format_of(typed)
    except ValueError as e:
        _fail(str(e))
    if fmt == "parquet":
        io._require("pyarrow")
    elif fmt == "netcdf":
        io._require("xarray")
        io._require("scipy")
    if out.is_dir():
        _fail(f"--out {typed!r} is a directory; give a file name ending in .csv, .parquet or .nc")
    parent = out.resolve().parent
    if not parent.is_dir():  # --out does not create directories (docs/cli.md)
        _fail(f"--out {typed!r}: the directory {str(parent)!r} does not exist; create it first")
    if not os.access(parent, os.W_OK | os.X_OK):
        _fail(f"--out {typed!r}: cannot write to the directory {str(parent)!r}")


IMAGE_SUFFIXES = (".png", ".svg", ".pdf")


def _check_image(option: str, path: str | Path) -> None:
    """An image path (--plot, --out of a figure) checked before any work: a suffix matplotlib writes,
    not a directory, in a directory that exists (it is not created, docs/limits.md); named as typed."""
    typed, path = os.fspath(path), Path(path)
    if path.suffix.lower() not in IMAGE_SUFFIXES:
        _fail(f"{option}: unknown image suffix {path.suffix!r} in {typed!r}; use .png, .svg or .pdf")
    if path.is_dir():
        _fail(f"{option} {typed!r} is a directory; give a file name ending in .png, .svg or .pdf")
    parent = path.resolve().parent
    if not parent.is_dir():
        _fail(f"{option} {typed!r}: the directory {str(parent)!r} does not exist; create it first")
