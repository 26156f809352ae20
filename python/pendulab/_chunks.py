"""The chunk loop of :func:`pendulab.simulate` (its ``Solver`` and ``ForceSolver``) and of the string
pendulum's run (``StringRunner``): a core runner advanced in chunks of about 0.1 s of work (the GIL
released inside each chunk), one tqdm progress bar updated between chunks, and a clean stop on Ctrl-C
after the current chunk, returning what was computed so far with a warning. Times in s. (The spring
driver runs in one core call; the ensembles and the crane loops have loops of their own.)
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable
from typing import Any, Protocol

from ._progress import seconds_bar
from ._warn import warn_user

_CHUNK_SECONDS = 0.1
_PROGRESS_AFTER_STEPS = 5_000_000
"""Runs of more steps than this show a progress bar unless told otherwise."""


class ChunkedRun(Protocol):
    """What :func:`run_in_chunks` drives: ``Solver``, ``ForceSolver``, ``StringRunner``."""

    def advance(self, budget: int, /) -> bool: ...
    def take_samples(self) -> Any: ...
    @property
    def progress(self) -> float: ...
    @property
    def t(self) -> float: ...
    @property
    def t_end(self) -> float: ...


def run_in_chunks(
    solver: ChunkedRun,
    show: bool,
    desc: str,
    take_rest: Callable[[], Any] | None = None,
) -> tuple[list[Any], bool]:
    """Advances ``solver`` to its end in chunks of about 0.1 s of work (the GIL released inside each),
    updating a tqdm bar (``show``) between chunks. Ctrl-C stops after the current chunk: returns the
    parts taken so far and True, with a RuntimeWarning at the user's line (:func:`~._warn.warn_user`).
    ``take_rest`` takes the last part after an interruption (default ``solver.take_samples``). The bar
    counts seconds of simulated time from the solver's start ``solver.t`` (it has not advanced yet) to
    its ``solver.t_end`` [s] (``solver.progress`` is the fraction of it done)."""
    parts: list[Any] = []
    interrupted = False
    budget = 10_000
    # no bar object at all when it is not shown: a disabled tqdm still costs ~10 µs per call
    t_start = solver.t
    seconds = solver.t_end - t_start
    bar = seconds_bar(seconds, f"{desc}, simulated s from t={t_start:g}") if show else None
    with bar if bar is not None else contextlib.nullcontext():
        try:
            done = False
            while not done:
                start = time.perf_counter()
                done = solver.advance(budget)
                elapsed = time.perf_counter() - start
                budget = int(min(max(budget * _CHUNK_SECONDS / max(elapsed, 1e-6), 1_000), 1e9))
                parts.append(solver.take_samples())
                if bar is not None:
                    bar.update(seconds * solver.progress - bar.n)
        except KeyboardInterrupt:
            interrupted = True
            parts.append(take_rest() if take_rest is not None else solver.take_samples())
            warn_user(
                f"simulation interrupted at t = {solver.t:g} s; returning the samples computed so far",
                RuntimeWarning,
            )
    return parts, interrupted
