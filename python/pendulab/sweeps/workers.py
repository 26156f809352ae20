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
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from .._core import InvalidInputError, __version__
from ..model import FloatArray
from .compute import RAN, SweepSpec

UPGRADE = (
    "its result is not written. Upgrade pendulab on every worker to the one this client runs (pendulab "
    "{version}), then run the sweep again (a resume keeps the chunks already written)"
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


def check_ran(index: int, cols: Mapping[str, Any], spec: SweepSpec) -> dict[str, FloatArray]:
    """The columns of chunk ``index`` without the worker's echo, once the echo shows that the worker ran
    the sweep's ``spec``; else an ``InvalidInputError`` (module docstring)."""
    out = {k: v for k, v in cols.items() if k != RAN}
    if not spec.simulated:
        return out
    want = _expected(spec)
    upgrade = UPGRADE.format(version=__version__)
    echo = cols.get(RAN)
    if not isinstance(echo, Mapping):
        raise InvalidInputError(
            f"chunk {index} came from a worker whose pendulab is older than this client's: its result "
            f"does not echo what it ran, and such a worker cannot honour the settings it predates — from "
            f"before sweeps' method it integrates plain RATTLE whatever the sweep names (here "
            f"{want['method']!r}), from before their arithmetic it uses its own CPU's (here "
            f"{want['arithmetic']!r}); {upgrade}"
        )
    honours = echo.get("honours") or []
    missing = [key for key in spec.describe() if key not in honours]
    if missing:
        raise InvalidInputError(
            f"chunk {index} came from a worker whose pendulab is older than this client's: it cannot "
            f"honour the sweep's setting{'s' if len(missing) > 1 else ''} {', '.join(missing)} (it "
            f"ignores {'them' if len(missing) > 1 else 'it'}); {upgrade}"
        )
    got = {key: echo.get(key) for key in want}
    if any(want[key] is not None and got[key] != want[key] for key in want):
        raise InvalidInputError(
            f"chunk {index} was computed with {_show(got)} by its worker, not the sweep's {_show(want)}: "
            f"the worker runs another pendulab than this client; {upgrade}"
        )
    return out
