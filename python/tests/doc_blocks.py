"""The code blocks of README.md and docs/*.md and how each kind is run: every code block runs as written
(issue 31: a new user can follow any page to the letter; test_doc_blocks.py runs the python and toml
blocks, test_doc_shell_blocks.py the shell blocks). Blocks are taken from the text, nothing is added to
them:

- ``python`` blocks: the blocks of one page run in order, in one fresh namespace (names defined earlier
  on the page stay defined, as for a reader going down the page; nothing else is set up), in this
  process (no second start-up of Python, NumPy and pendulab per page) with a temporary folder as the
  working folder, ``examples`` linked to the checkout's (the pages are written for the top of the
  checkout). A block that is a script (``if __name__ == "__main__":``) runs as its own file, in a child
  process. Matplotlib draws off screen (``Agg``).
- shell blocks (```` ```sh ````, ```` ```console ````, or untagged with a first line that is a command):
  each command runs there: a plain ``pendulab …`` line (no pipes, globs, variables or other shell
  syntax) in this process (the same app as the ``pendulab`` script, through typer's CliRunner), any
  other command in bash, with ``pendulab`` and ``python`` of this environment first on PATH.
  In a transcript (lines ``$ command`` followed by its output) a command whose shown output has
  lines starting with ``error:`` must fail with exit code 2 and print ``error:``; every other command
  must succeed. The output shown for a ``pendulab`` command must be what it prints: every shown line
  (an annotation ``(stderr)`` at its end dropped) equals a line of its stdout or stderr, where ``…``
  stands for any text, a round-off figure (``4.441e-16``: an exponent of -13 or below) for any number
  and ``'fused'`` (``, fused arithmetic``) for ``'unfused'`` (``, unfused arithmetic``) too (both depend
  on the CPU's arithmetic: docs/cli.md).
  Commands that cannot finish are checked, not run: a synopsis line (placeholders in capitals such as
  ``FILE.toml`` or ``tcp://HOST:8786``, ``[optional parts]``, ``…``) and ``pendulab serve`` (a server
  runs until stopped) must name a real command and only options its ``--help`` lists (an address to
  fill in is never contacted); a ``make TARGET`` line must name a target of the Makefile (``make -n``;
  building takes minutes and is what CI does anyway).
- ``toml`` blocks are whole files, loaded as ``pendulab validate`` and ``pendulab sweep`` load them: a
  sweep file (a top-level ``quantity``) by the sweep file's loader, any other as a scenario (crane files
  too). A block whose first line is ``# examples/….toml (abridged)…`` shows part of that shipped file:
  each value it shows must be the file's.
- other blocks (output, file trees) are text.

What runs in this process warns as for a reader: warnings are printed, not raised (a page may show the
fit's ``UserWarning`` on purpose), except a deprecation (``DeprecationWarning``,
``PendingDeprecationWarning``, ``FutureWarning``) raised for a block's code or for pendulab's, which
fails the test with the page, its line and the warning's text (:func:`no_deprecations`): a page must
not teach a deprecated call such as ``Crane.simulate(dt=…)``. One page's python blocks, a script block
and each shell command must finish within :data:`TIMEOUT` s (:func:`time_limit` for what runs in this
process).

A block preceded by ``<!-- docs-test: skip (reason) -->`` is not run; :data:`ALLOWED_SKIPS` keeps that
list short and explicit. The README's wheel-install block (``<!-- wheel-install … -->``) is run by
tools/check_wheel.py (``make test-wheel``), its sweep script by test_readme.py.

What runs in this process (a page's python blocks, a plain ``pendulab …`` line) runs inside
:func:`isolated`: the environment, the working folder, ``sys.path``, the standard streams, the umask,
the SIGINT and SIGTERM handlers, NumPy's print options, floating-point error handling and global random
state, Python's random state, the warnings filters and Matplotlib's rcParams are put back afterwards
(also after a failing block), so that a block cannot change what later tests see. Modules a block
imported stay imported: NumPy, SciPy and the core cannot be loaded twice in one process.
"""

from __future__ import annotations

import ctypes
import os
import random
import re
import signal
import subprocess
import sys
import threading
import warnings
from collections.abc import Iterator
from contextlib import ExitStack, contextmanager
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from conftest import REPO

import pendulab

# The README and every page of the site (docs/ with its sub-folders: the tour's index, the reference),
# but not the READMEs mkdocs.yml leaves out of it (exclude_docs).
PAGES = [REPO / "README.md", *sorted(p for p in (REPO / "docs").rglob("*.md") if p.name != "README.md")]
COMMANDS = ("pendulab", "make", "python", "python3", "pip", ".", "source", "echo", "cd")
# Blocks that are not run, by page: (first line of the block, reason). Keep this short.
ALLOWED_SKIPS = {
    "README.md": {"make wheel": "run by tools/check_wheel.py (make test-wheel) against the built wheel"},
}
TIMEOUT = 300.0  # s, one page's python blocks or one shell command (in bash or in this process)
# warnings a page must not make: it would teach a call that is deprecated (Crane.simulate(dt=…))
DEPRECATIONS = (DeprecationWarning, PendingDeprecationWarning, FutureWarning)


@dataclass(frozen=True)
class Block:
    page: str
    line: int  # 1-based line of the opening fence
    lang: str
    text: str
    marker: str  # the HTML comment just before the block, if any

    @property
    def where(self) -> str:
        return f"{self.page}:{self.line}"


def _name(path: Path) -> str:
    """The page as the messages name it: README.md, cli.md, tour/index.md."""
    docs = REPO / "docs"
    return path.relative_to(docs).as_posix() if path.is_relative_to(docs) else path.name


def blocks(path: Path) -> list[Block]:
    lines = path.read_text(encoding="utf-8").split("\n")
    out, i = [], 0
    while i < len(lines):
        m = re.match(r"^```(\w*)\s*$", lines[i])
        if not m:
            i += 1
            continue
        j = i + 1
        while not lines[j].startswith("```"):
            j += 1
        k = i - 1
        while k >= 0 and not lines[k].strip():
            k -= 1
        marker = lines[k].strip() if k >= 0 and lines[k].strip().startswith("<!--") else ""
        out.append(Block(_name(path), i + 1, m.group(1), "\n".join(lines[i + 1 : j]), marker))
        i = j + 1
    return out


def kind(b: Block) -> str:
    """python, shell or text."""
    if b.lang == "python":
        return "python"
    if b.lang in ("sh", "bash", "console", "shell"):
        return "shell"
    if b.lang:
        return "text"
    first = next((ln for ln in b.text.splitlines() if ln.strip()), "")
    word = first.removeprefix("$ ").split(" ")[0]
    return "shell" if word in COMMANDS else "text"


def skipped(b: Block) -> str | None:
    """The reason a block is not run here, or None."""
    if "wheel-install" in b.marker:
        return "run by tools/check_wheel.py"
    m = re.match(r"<!--\s*docs-test:\s*skip\s*\((.+)\)\s*-->", b.marker)
    return m.group(1) if m else None


ALL = [b for page in PAGES for b in blocks(page)]


# --------------------------------------------------------------------------------- where blocks run


def workdir(tmp_path: Path) -> Path:
    """``tmp_path`` with ``examples`` linked to the checkout's (the pages are written for the top of the
    checkout): the working folder of a page's blocks."""
    (tmp_path / "examples").symlink_to(REPO / "examples")
    return tmp_path


def env() -> dict[str, str]:
    """The environment of a child process: this Python's ``pendulab`` and ``python`` first on PATH,
    Matplotlib off screen, this process's import path."""
    out = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH",)}
    out["PATH"] = f"{Path(sys.executable).parent}{os.pathsep}{out.get('PATH', '')}"
    out["MPLBACKEND"] = "Agg"
    out["PYTHONPATH"] = os.pathsep.join(p for p in sys.path if p)
    return out


@contextmanager
def isolated() -> Iterator[None]:
    """Whatever runs inside leaves this process's global state as it found it (the module doc lists
    what is put back), also when it raises."""
    import matplotlib

    environ, cwd, path = dict(os.environ), os.getcwd(), list(sys.path)
    streams = (sys.stdin, sys.stdout, sys.stderr)
    handlers = {s: signal.getsignal(s) for s in (signal.SIGINT, signal.SIGTERM)}
    umask = os.umask(0o022)
    os.umask(umask)
    np_random, py_random = np.random.get_state(), random.getstate()
    with ExitStack() as stack:
        stack.enter_context(warnings.catch_warnings())
        stack.enter_context(np.printoptions())
        stack.enter_context(np.errstate())
        stack.enter_context(matplotlib.rc_context())
        try:
            yield
        finally:
            for name in set(os.environ) - set(environ):
                del os.environ[name]
            os.environ.update({k: v for k, v in environ.items() if os.environ.get(k) != v})
            os.chdir(cwd)
            sys.path[:] = path
            sys.stdin, sys.stdout, sys.stderr = streams
            for s, handler in handlers.items():
                if signal.getsignal(s) is not handler:  # signal.signal: the main thread only
                    signal.signal(s, handler)
            os.umask(umask)
            np.random.set_state(np_random)
            random.setstate(py_random)


class TooLong(Exception):
    """What runs in this process did not finish within :data:`TIMEOUT` s (not a ``TimeoutError``: that is
    an ``OSError``, which the command line reports as a user's ``error:``, as a transcript may show)."""


def _expired(message: str) -> type[TooLong]:
    """A :class:`TooLong` that says ``message`` when raised without arguments (as
    ``PyThreadState_SetAsyncExc`` raises the class it is given)."""

    class Expired(TooLong):
        def __init__(self, *args: object) -> None:
            super().__init__(*(args or (message,)))

    Expired.__name__ = Expired.__qualname__ = "TooLong"
    return Expired


@contextmanager
def time_limit(what: str) -> Iterator[None]:
    """Raises :class:`TooLong` (naming ``what``) in this thread if the body runs longer than
    :data:`TIMEOUT` s. In the main thread by ``SIGALRM`` (on a POSIX system), which also ends a blocking
    call such as ``time.sleep`` (the core gives Python a chance to act on signals between its chunks of
    work). In any other thread (a runner that runs tests in threads; signals only reach the main thread)
    a timer thread raises it in this one (``PyThreadState_SetAsyncExc``) at the next line of Python it
    runs: a blocking call ends first."""
    limit = TIMEOUT
    message = f"{what} did not finish within {limit:g} s"
    if threading.current_thread() is threading.main_thread():

        def too_long(signum: int, frame: object) -> None:
            raise TooLong(message)

        before = signal.signal(signal.SIGALRM, too_long)
        signal.setitimer(signal.ITIMER_REAL, limit)
        try:
            yield
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, before)
        return
    me, lock, state = threading.get_ident(), threading.Lock(), {"running": True, "fired": False}

    def expire() -> None:
        with lock:  # not once the body has ended: the exception would land in whatever runs next
            if state["running"]:
                state["fired"] = True
                ctypes.pythonapi.PyThreadState_SetAsyncExc(
                    ctypes.c_ulong(me), ctypes.py_object(_expired(message))
                )

    timer = threading.Timer(limit, expire)
    timer.daemon = True
    timer.start()
    try:
        yield
    finally:
        with lock:
            state["running"] = False
        timer.cancel()
        if state["fired"]:  # still pending if the body ended in between: taken back (NULL), raised below
            ctypes.pythonapi.PyThreadState_SetAsyncExc(ctypes.c_ulong(me), None)
    if state["fired"]:
        raise TooLong(message)


_PACKAGE = str(Path(pendulab.__file__).parent)


def taught(category: type[Warning], filename: str) -> bool:
    """Whether a warning of ``category`` that Python attributes to ``filename`` is a deprecation the page
    teaches: one of :data:`DEPRECATIONS` raised for a block's own code (a block's file name is its
    :attr:`Block.where`; a deprecation's ``stacklevel`` points at its caller) or for pendulab's (what a
    command calls; pendulab calling what another library deprecates). One that another library raises
    for its own code (Matplotlib calling NumPy) is that library's, only printed."""
    own = filename.startswith(_PACKAGE) or re.fullmatch(r".+\.md:\d+", filename) is not None
    return own and issubclass(category, DEPRECATIONS)


@contextmanager
def no_deprecations(where: str) -> Iterator[None]:
    """Warnings are shown as before (inside :func:`isolated`, which puts ``warnings.showwarning`` back); a
    deprecation the page teaches (:func:`taught`) fails the test once the body has run, naming ``where``
    and each such warning with its line (on the page, ``cranes.md:131``, for one a block makes)."""
    show = warnings.showwarning
    found: list[str] = []

    def record(message, category, filename, lineno, file=None, line=None):  # type: ignore[no-untyped-def]
        show(message, category, filename, lineno, file, line)
        if taught(category, filename):
            block = re.fullmatch(r"(.+\.md):(\d+)", filename)
            at = f"{block[1]}:{int(block[2]) + lineno}" if block else f"{filename}:{lineno}"
            found.append(f"{at}: {category.__name__}: {message}")

    warnings.showwarning = record
    try:
        yield
    finally:
        warnings.showwarning = show
    assert not found, f"{where} uses what is deprecated (write what the warning says):\n" + "\n".join(found)


def exec_in_order(todo: list[Block], work: Path) -> None:
    """The blocks ``todo`` in order in one fresh namespace, in this process (:func:`isolated`), in the
    folder ``work``; each page within :data:`TIMEOUT` s. A failing block's error names it (``the block
    at fit.md:8``); so does a deprecation a block makes (:func:`no_deprecations`): other warnings are
    printed, as for a reader (the fit's ``UserWarning`` that a page shows on purpose)."""
    import matplotlib

    matplotlib.use("Agg")
    ns: dict[str, object] = {"__name__": "__docs__"}
    try:
        with time_limit(f"the python blocks of {todo[0].page}" if todo else "no blocks"), isolated():
            os.chdir(work)
            warnings.simplefilter("default")  # as for a reader: printed, not raised (pytest's "error")
            for b in todo:
                try:
                    with no_deprecations(f"the block at {b.where}"):
                        exec(compile(b.text, b.where, "exec"), ns)
                except BaseException as e:
                    e.add_note(f"FAILED: the block at {b.where}")
                    raise
    finally:
        if "matplotlib.pyplot" in sys.modules:  # a figure drawn with pyplot (xarray's .plot())
            sys.modules["matplotlib.pyplot"].close("all")


def check(cmd: list[str], cwd: Path, where: str) -> subprocess.CompletedProcess[str]:
    """``cmd`` run in a child process in ``cwd``; it must succeed."""
    p = subprocess.run(cmd, cwd=cwd, env=env(), capture_output=True, text=True, timeout=TIMEOUT)
    assert p.returncode == 0, f"{where}:\n{p.stdout[-2000:]}\n{p.stderr[-4000:]}"
    return p
