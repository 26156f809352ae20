"""What the workers of a sweep ran, checked in the calling process before a chunk is written
(``docs/sweeps.md``, "Chunks and backends"). A Dask worker runs the ``compute_chunk`` of *its*
pendulab on the chunk's settings as unpickled there: one older than a setting keeps it without reading
it (a worker from before ``method`` integrates RATTLE whatever the sweep names; one from before
``arithmetic`` uses its own CPU's), and its per-chunk checks cannot see what they do not know. So
``compute_chunk`` echoes under ``RAN`` the settings its pendulab honours and the method, arithmetic and
arithmetic version it integrated with (:func:`pendulab.sweeps.compute.ran`), and the calling process
refuses a chunk of simulated quantities whose result carries no echo (a worker older than the echo),
leaves out a setting the sweep uses, or names another method, arithmetic or version: an
``InvalidInputError`` naming the chunk, what the worker lacks and the fix (the client's pendulab on
every worker), raised before the chunk is written. The check runs on the thread pool's results too,
where it always holds. Exact quantities integrate nothing: their chunks are accepted without an echo.

A chunk's echo comes back only once the chunk is computed, so before the first chunk is sent to a Dask
cluster every worker is asked what it would run (:func:`check_workers`: ``ran`` of the sweep's spec on
each, ``distributed.Client.run``; one that has not answered within :data:`~.backends.WORKER_TIMEOUT` s
hangs, and is named in a ``TimeoutError``: :meth:`.backends.Dask.ask`); a worker older than the echo
cannot even unpickle that function and answers with the error. A worker that would not run the sweep
is refused as above, naming its address, before anything is computed. Workers that join the cluster
later are checked by their chunks' echo.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .. import validate as limits
from .._core import InvalidInputError, __version__
from ..model import FloatArray
from .backends import name_workers
from .compute import RAN, SweepSpec

UPGRADE = (
    "Upgrade pendulab on every worker to the one this client runs (pendulab {version}), then run the sweep "
    "again (a resume keeps the chunks already written)"
)

PREDATES = (
    "such a worker cannot honour the settings it predates — from before sweeps' method it integrates "
    "plain RATTLE whatever the sweep names (here {method!r}), from before their arithmetic it uses its "
    "own CPU's (here {arithmetic!r})"
)


def _expected(spec: SweepSpec) -> dict[str, Any]:
    """The method (RATTLE for a spec made without one), arithmetic and arithmetic version the chunks of
    ``spec`` must run (a sweep sets up its spec with both; None: not checked, as on the worker)."""
    return {
        "method": spec.method or "rattle",
        "arithmetic": spec.arithmetic,
        "arithmetic_version": spec.arithmetic_version,
    }


def _show(settings: Mapping[str, Any]) -> str:
    return ", ".join(f"{k} {v!r}" for k, v in settings.items() if v is not None)


def _problem(echo: Any, spec: SweepSpec) -> tuple[str, str, str] | None:
    """Why ``echo`` (what a worker ran or runs, :func:`~.compute.ran`; None: no echo) does not show the
    settings of ``spec``: ("silent", what such a worker predates, ""), ("older", the settings it
    ignores, "") or ("other", what it runs, what the sweep runs); None when it shows them."""
    want = _expected(spec)
    if not isinstance(echo, Mapping):
        return "silent", PREDATES.format(**want), ""
    honours = echo.get("honours") or []
    missing = [key for key in spec.describe() if key not in honours]
    if missing:
        s, them = ("s", "them") if len(missing) > 1 else ("", "it")
        return "older", f"the sweep's setting{s} {', '.join(missing)} (it ignores {them})", ""
    got = {key: echo.get(key) for key in want}
    if any(want[key] is not None and got[key] != want[key] for key in want):
        return "other", _show(got), _show(want)
    return None


def check_ran(index: int, cols: Mapping[str, Any], spec: SweepSpec) -> dict[str, FloatArray]:
    """The columns of chunk ``index`` without the worker's echo, once the echo shows that the worker ran
    the sweep's ``spec``; else an ``InvalidInputError`` (module docstring)."""
    out = {k: v for k, v in cols.items() if k != RAN}
    problem = _problem(cols.get(RAN), spec) if spec.simulated else None
    if problem is None:
        return out
    kind, what, want = problem
    upgrade = "its result is not written. " + UPGRADE.format(version=__version__)
    older = f"chunk {index} came from a worker whose pendulab is older than this client's"
    if kind == "silent":
        raise InvalidInputError(f"{older}: its result does not echo what it ran, and {what}; {upgrade}")
    if kind == "older":
        raise InvalidInputError(f"{older}: it cannot honour {what}; {upgrade}")
    raise InvalidInputError(
        f"chunk {index} was computed with {what} by its worker, not the sweep's {want}: the worker runs "
        f"another pendulab than this client; {upgrade}"
    )


def check_workers(answers: Mapping[str, Any], spec: SweepSpec) -> None:
    """Before any chunk is sent: ``answers`` maps each Dask worker's address to its :func:`~.compute.ran`
    of ``spec``, or to the exception it raised instead (a pendulab older than the echo cannot even
    unpickle that function); an ``InvalidInputError`` naming the first worker (by address) that would
    not run ``spec``, how many others would not, what it lacks and the fix, unless every one would
    (module docstring). Exact quantities integrate nothing: not checked."""
    if not spec.simulated:
        return
    bad: list[tuple[str, Any, tuple[str, str, str]]] = []
    for addr in sorted(answers):
        problem = _problem(_echo(answers[addr]), spec)
        if problem is not None:
            bad.append((addr, answers[addr], problem))
    if not bad:
        return
    addr, answer, (kind, what, want) = bad[0]
    worker = name_workers([a for a, _, _ in bad], len(answers))
    upgrade = "nothing was computed. " + UPGRADE.format(version=__version__)
    if kind == "silent":
        said = _error(answer) if isinstance(answer, BaseException) else f"it answered {limits.show(answer)}"
        raise InvalidInputError(
            f"{worker} cannot say what it would run ({said}): its pendulab is older than this client's "
            f"(or missing), and {what}; {upgrade}"
        )
    if kind == "older":
        raise InvalidInputError(
            f"{worker} runs a pendulab older than this client's: it cannot honour {what}; {upgrade}"
        )
    raise InvalidInputError(
        f"{worker} would compute with {what}, not the sweep's {want}: it runs another pendulab than this "
        f"client; {upgrade}"
    )


def _error(e: BaseException) -> str:
    """An error a worker answered, in one line; the cause itself where the scheduler wrapped it (an
    error unpickling the question comes as ``Exception(AttributeError(...))``)."""
    while type(e) is Exception and len(e.args) == 1 and isinstance(e.args[0], BaseException):
        e = e.args[0]
    text = " ".join(str(e).split())[:300]
    return text if type(e) is Exception else f"{type(e).__name__}: {text}"


def _echo(answer: Any) -> Any:
    return None if isinstance(answer, BaseException) else answer
