"""Shared fixtures: the repository paths, a script of tools/ as a module (:func:`load_tool`), the lab
page's words of a server message (:func:`page_words`, :func:`page_template`, from
``web/src/i18n/*/refusals.ts``), the rosette start (l = 1 m, g = 9.81 m/s², θ₀ = 60°, φ̇₀ = 2 rad/s) and its
exact solution, and a real Ctrl-C sent to a child process (:func:`ctrl_c_after`)."""

from __future__ import annotations

import importlib.util
import re
import signal
import subprocess
import sys
import time
import types
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import pendulab as pl

# Ctrl-C tests raise SIGINT in this process and in child processes. A shell that starts pytest in the
# background or under nohup ignores SIGINT (SIG_IGN is inherited, and Python then installs no
# KeyboardInterrupt handler): restore Python's handler, so that the tests do not depend on how they
# were started. Children started with exec then get the default disposition too.
signal.signal(signal.SIGINT, signal.default_int_handler)

REPO = Path(__file__).resolve().parents[2]
SCENARIOS = REPO / "examples" / "scenarios"
TESTDATA = REPO / "testdata"
I18N = REPO / "web" / "src" / "i18n"


def load_tool(name: str) -> types.ModuleType:
    """The script ``tools/<name>.py`` as a module, loaded afresh (tools/ is not a package) and registered
    in ``sys.modules`` under ``name`` (its dataclasses look their module up there)."""
    spec = importlib.util.spec_from_file_location(name, REPO / "tools" / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module


def ctrl_c_after(
    cmd: list[str], ready: str, *, stream: str = "stdout", wait: float = 1.0, timeout: float = 60.0
) -> subprocess.CompletedProcess[str]:
    """Runs ``cmd``, waits for the first line of its ``stream`` ("stdout" or "stderr"), which must start
    with ``ready`` (the child prints it just before its long work begins), sends a real SIGINT (Ctrl-C
    as the user sends it) ``wait`` seconds later, and returns the finished process with its output after
    that first line. The child is killed if it has not ended ``timeout`` seconds after the signal."""
    proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        pipe = proc.stdout if stream == "stdout" else proc.stderr
        assert pipe is not None
        first = pipe.readline()
        assert first.startswith(ready), first
        time.sleep(wait)
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=timeout)
    finally:
        proc.kill()
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def fit_run_clock(monkeypatch: pytest.MonkeyPatch, step: float) -> list[int]:
    """Makes the fit's clock (``search.wall_clock``) the test's: it reads ``step`` [s] per model run
    (``Problem.residuals`` call) and nothing else, so a time limit passes at a fixed run whatever the
    machine's load. Returns the run counter, a one-element list updated as the fit runs."""
    from pendulab.fitting import search
    from pendulab.fitting.problem import Problem

    runs = [0]
    residuals = Problem.residuals

    def counted(self: Problem, *args: Any, **kwargs: Any) -> Any:
        runs[0] += 1
        return residuals(self, *args, **kwargs)

    monkeypatch.setattr(Problem, "residuals", counted)
    monkeypatch.setattr(search, "wall_clock", lambda: step * runs[0])
    return runs


def page_template(lang: str, key: str) -> str:
    """The page's words of message ``key`` in ``lang`` as its table ``web/src/i18n/<lang>/refusals.ts``
    writes them, placeholders (``{name}``) unfilled."""
    table = (I18N / lang / "refusals.ts").read_text(encoding="utf-8")
    line = re.search(rf"'server\.{key}': (['`\"])(.*)\1,", table)
    assert line is not None, (lang, key)
    return line.group(2).replace("\\'", "'")


def page_words(lang: str, key: str, values: dict[str, Any]) -> str:
    """The page's words of message ``key`` in ``lang``, filled as its t() fills them."""
    return re.sub(r"\{(\w+)\}", lambda m: str(values[m.group(1)]), page_template(lang, key))


@pytest.fixture
def pendulum() -> pl.Pendulum:
    return pl.Pendulum(length=1.0, g=9.81, mass=1.0)


@pytest.fixture
def rosette(pendulum: pl.Pendulum) -> pl.State:
    return pendulum.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)


@pytest.fixture
def sol(pendulum: pl.Pendulum, rosette: pl.State) -> pl.ExactSolution:
    """The exact solution of the rosette start (the movie tests, test_animate*.py)."""
    return pl.exact(pendulum, rosette)
