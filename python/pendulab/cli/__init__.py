"""The ``pendulab`` command line (typer). Units are SI throughout; exit codes: 0 success, 2 a user
error (one line ``error: …`` on stderr), 130 interrupted by Ctrl-C. Commands: ``docs/cli.md``.

This face only imports each command module once, which registers its commands on the one ``app``
of :mod:`pendulab.cli.common`; command modules import from ``common`` and never from here.
"""

from __future__ import annotations

from . import animate, crane, exact, fit, run, serve, sweep  # noqa: F401  (each registers its commands on `app`)
from .common import EXIT_INTERRUPTED, EXIT_USER_ERROR, app


def main() -> None:
    """Entry point of the ``pendulab`` script."""
    app(prog_name="pendulab")


__all__ = ["EXIT_INTERRUPTED", "EXIT_USER_ERROR", "app", "main"]
