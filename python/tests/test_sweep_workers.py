"""What a sweep's workers ran, checked before a chunk is written (``sweeps/workers.py``, docs/sweeps.md
"Chunks and backends"): a Dask worker with an older pendulab unpickles a chunk's settings, ignores the
ones it predates (``method``: it integrates RATTLE) and returns plain columns. Such results are made
here without a cluster, by wrapping the function the driver runs (the check is in the calling process,
the same for both backends): ``compute_chunk`` on the settings as an old worker reads them, its echo
(``RAN``) removed. A real LocalCluster's chunks carry the echo (test_sweep.py runs one through the
check). Times in seconds, angles in radians."""

from __future__ import annotations

import asyncio
import re
import threading
import time
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sweep_records import drop_chunk, same

import pendulab as pl
from pendulab import _core
from pendulab.sweeps import backends as sweep_backends
from pendulab.sweeps import compute as sweep_compute
from pendulab.sweeps import run as sweep_mod
from pendulab.sweeps.compute import RAN, ChunkTask
from pendulab.sweeps.design import as_design
from pendulab.sweeps.workers import check_workers

GRID = {"theta0": np.linspace(0.3, 2.5, 5), "phi_dot0": np.array([0.0, 1.5, -2.0])}
QS = ["final_state", "energy_drift"]
KW: dict[str, Any] = {"t_end": 0.2, "dt": 1e-2, "chunk_size": 4, "progress": False}
UPGRADE = f"Upgrade pendulab on every worker to the one this client runs (pendulab {_core.__version__})"


def _workers(monkeypatch: pytest.MonkeyPatch, worker: Any) -> None:
    """Every chunk computed by ``worker(task)`` instead of this pendulab's compute_chunk."""
    monkeypatch.setattr(sweep_mod, "compute_chunk", lambda task, cancel=None: worker(task))


def _old_worker(task: ChunkTask) -> dict[str, Any]:
    """A worker from before methods were recorded: RATTLE whatever the spec says, no echo."""
    cols = sweep_compute.compute_chunk(replace(task, spec=replace(task.spec, method=None)))
    del cols[RAN]
    return cols


@pytest.mark.parametrize("method", ["rattle6", "rattle"])
def test_a_chunk_from_an_old_worker_is_refused(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, method: str
) -> None:
    """Refused before it is written, with any method (an old worker may ignore the arithmetic too),
    naming the chunk, what the worker lacks, the sweep's method and the fix; once the workers run this
    pendulab, a resume finishes the sweep bit for bit as a sweep on this process."""
    out = tmp_path / "sw"
    _workers(monkeypatch, _old_worker)
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep(GRID, QS, method=method, out=out, **KW)
    text = str(e.value)
    assert re.match(r"chunk \d came from a worker whose pendulab is older than this client's", text), text
    for needle in (
        "does not echo what it ran",
        f"it integrates plain RATTLE whatever the sweep names (here {method!r})",
        "its result is not written",
        UPGRADE,
    ):
        assert needle in text, (needle, text)
    assert not list(out.glob("chunk-*.parquet"))
    monkeypatch.undo()
    again = pl.sweep(GRID, QS, method=method, out=out, resume=True, **KW)
    assert same(again, pl.sweep(GRID, QS, method=method, **KW))


def test_exact_quantities_need_no_echo(monkeypatch: pytest.MonkeyPatch) -> None:
    """Nothing integrates: an old worker's rotation numbers are accepted (and equal this pendulab's)."""
    _workers(monkeypatch, _old_worker)
    old = pl.sweep(GRID, "rotation_number", chunk_size=4, progress=False)
    monkeypatch.undo()
    assert same(old, pl.sweep(GRID, "rotation_number", chunk_size=4, progress=False))


def test_a_worker_that_does_not_know_a_setting_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """A worker that echoes but does not honour a setting the sweep uses (as this pendulab's workers
    will be to a later client's new settings) is refused, naming the setting."""

    def without_method(task: ChunkTask) -> dict[str, Any]:
        cols = _old_worker(task)
        honours = [f for f in sweep_compute.ran(task.spec)["honours"] if f != "method"]
        cols[RAN] = sweep_compute.ran(replace(task.spec, method=None)) | {"honours": honours}
        return cols

    _workers(monkeypatch, without_method)
    with pytest.raises(
        pl.InvalidInputError, match=r"cannot honour the sweep's setting method \(it ignores it\)"
    ):
        pl.sweep(GRID, QS, method="rattle8", **KW)


def test_a_worker_that_ran_another_method_or_arithmetic_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """An echo naming other settings than the sweep's (another pendulab) is refused, naming both."""

    def rattle4(task: ChunkTask) -> dict[str, Any]:
        return sweep_compute.compute_chunk(replace(task, spec=replace(task.spec, method="rattle4")))

    _workers(monkeypatch, rattle4)
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep(GRID, QS, method="rattle6", arithmetic="fused", **KW)
    assert re.match(
        r"chunk \d was computed with method 'rattle4', arithmetic 'fused', arithmetic_version 1 by its "
        r"worker, not the sweep's method 'rattle6', arithmetic 'fused', arithmetic_version 1",
        str(e.value),
    ), str(e.value)

    def unfused(task: ChunkTask) -> dict[str, Any]:
        return sweep_compute.compute_chunk(replace(task, spec=replace(task.spec, arithmetic="unfused")))

    _workers(monkeypatch, unfused)
    with pytest.raises(pl.InvalidInputError, match=r"arithmetic 'unfused'.*not the sweep's .*'fused'"):
        pl.sweep(GRID, QS, arithmetic="fused", **KW)


def test_this_pendulab_echoes_what_it_ran(tmp_path: Path) -> None:
    """compute_chunk's echo: every setting of SweepSpec, the method, arithmetic and version it ran (none
    for exact quantities); the echo is not a column of the result or of the files."""
    spec = sweep_compute.make_spec(
        as_design(GRID), QS, t_end=0.2, dt=1e-2, arithmetic="unfused", method="rattle4"
    )
    echo = sweep_compute.ran(spec)
    assert echo["method"] == "rattle4" and echo["arithmetic"] == "unfused"
    assert echo["arithmetic_version"] == _core.arithmetic_version("unfused")
    assert {"method", "arithmetic", "arithmetic_version", "t_end", "dt"} <= set(echo["honours"])
    exact = sweep_compute.ran(replace(spec, quantities=("period",)))
    assert (exact["method"], exact["arithmetic"], exact["arithmetic_version"]) == (None, None, None)
    sw = pl.sweep(GRID, QS, out=tmp_path / "sw", **KW)
    assert RAN not in sw.units and RAN not in pl.read_sweep(tmp_path / "sw").units
    drop_chunk(tmp_path / "sw", 1)  # the check runs on a resume's chunks too
    assert pl.sweep(GRID, QS, out=tmp_path / "sw", resume=True, **KW).stats["computed"] == 1


# --- before any chunk: every Dask worker asked what it would run ----------------------------------------


def _age(client: Any, kind: str) -> None:
    """Makes the pendulab of every worker of ``client`` (in its own process) one of an older kind:
    "silent" — from before the echo: no ``compute.ran`` (so it cannot unpickle the question) and chunks
    integrated with RATTLE whatever the sweep names, without an echo; "no_method" — it echoes, but does
    not know sweeps' ``method``; "current" — this pendulab again. Each worker counts the chunks it
    computes from here on (``compute.computed``)."""

    def age(kind: str) -> None:
        import types
        from dataclasses import replace

        from pendulab.sweeps import compute

        if not hasattr(compute, "real"):
            compute.real = dict(vars(compute))  # type: ignore[attr-defined]  # the module as it is
        real = compute.real  # type: ignore[attr-defined]
        compute.computed = 0  # type: ignore[attr-defined]
        counted = types.FunctionType(real["compute_chunk"].__code__, real, "counted", (None,))

        def chunk(task: Any, cancel: Any = None) -> Any:
            compute.computed += 1  # type: ignore[attr-defined]
            if kind != "silent":
                return counted(task, cancel)
            cols = counted(replace(task, spec=replace(task.spec, method=None)), cancel)
            del cols[real["RAN"]]
            return cols

        def ran_without_method(spec: Any) -> dict[str, Any]:
            echo = real["ran"](replace(spec, method=None))
            return echo | {"honours": [h for h in echo["honours"] if h != "method"]}

        compute.compute_chunk = chunk
        compute.ran = {"no_method": ran_without_method}.get(kind, real["ran"])
        if kind == "silent":
            del compute.ran

    client.run(age, kind)


@pytest.fixture(scope="module")
def cluster() -> Any:
    """A real LocalCluster of two worker processes and a client on it (left as this pendulab)."""
    distributed = pytest.importorskip("distributed")
    with (
        distributed.LocalCluster(
            n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None, silence_logs=40
        ) as local,
        distributed.Client(local) as client,
    ):
        try:
            yield client
        finally:
            _age(client, "current")


def _computed(client: Any) -> int:
    def count() -> int:
        from pendulab.sweeps import compute

        return int(getattr(compute, "computed", 0))

    return sum(client.run(count).values())


def test_an_old_dask_worker_is_refused_before_any_chunk_is_computed(tmp_path: Path, cluster: Any) -> None:
    """Real worker processes whose pendulab predates the echo: every worker is asked what it would run
    before the first chunk is sent, and the sweep is refused naming a worker, how many others, what
    it lacks and the fix, with no chunk computed on any worker (before, each chunk was computed in full
    and then refused by its missing echo) and none written. The same for workers that echo but do not
    know ``method``. Exact quantities integrate nothing: such workers compute them."""
    out = tmp_path / "sw"
    _age(cluster, "silent")
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep(GRID, QS, method="rattle6", scheduler=cluster, out=out, **KW)
    text = str(e.value)
    assert re.match(
        r"the Dask worker tcp://\S+ \(and 1 other of the cluster's 2\) cannot say what it would run "
        r"\(AttributeError\W.*'ran'.*\): its pendulab is older than this client's \(or missing\), and such "
        r"a worker cannot honour the settings it predates — from before sweeps' method it integrates "
        r"plain RATTLE whatever the sweep names \(here 'rattle6'\)",
        text,
    ), text
    assert f"; nothing was computed. {UPGRADE}" in text, text
    assert _computed(cluster) == 0 and not list(out.glob("chunk-*.parquet"))
    exact = pl.sweep(GRID, "rotation_number", scheduler=cluster, chunk_size=4, progress=False)
    assert _computed(cluster) == 4 and same(exact, pl.sweep(GRID, "rotation_number", progress=False))

    _age(cluster, "no_method")
    with pytest.raises(pl.InvalidInputError) as e:
        pl.sweep(GRID, QS, method="rattle8", scheduler=cluster, **KW)
    assert re.match(
        r"the Dask worker tcp://\S+ \(and 1 other of the cluster's 2\) runs a pendulab older than this "
        r"client's: it cannot honour the sweep's setting method \(it ignores it\); nothing was computed",
        str(e.value),
    ), str(e.value)
    assert _computed(cluster) == 0

    _age(cluster, "current")
    assert same(pl.sweep(GRID, QS, scheduler=cluster, **KW), pl.sweep(GRID, QS, **KW))
    assert _computed(cluster) == 4


def test_a_dask_worker_that_would_run_another_method_is_named() -> None:
    """The answers of a cluster of which one worker runs another pendulab (rattle4 for the sweep's
    rattle6): refused naming that worker and both settings; all answering this pendulab's: accepted."""
    spec = sweep_compute.make_spec(
        as_design(GRID), QS, t_end=0.2, dt=1e-2, arithmetic="fused", method="rattle6"
    )
    mine, other = sweep_compute.ran(spec), sweep_compute.ran(replace(spec, method="rattle4"))
    check_workers({"tcp://10.0.0.1:1": mine, "tcp://10.0.0.2:1": mine}, spec)
    with pytest.raises(pl.InvalidInputError) as e:
        check_workers({"tcp://10.0.0.1:1": mine, "tcp://10.0.0.2:1": other}, spec)
    assert str(e.value).startswith(
        "the Dask worker tcp://10.0.0.2:1 would compute with method 'rattle4', arithmetic 'fused', "
        "arithmetic_version 1, not the sweep's method 'rattle6', arithmetic 'fused', arithmetic_version 1: "
        f"it runs another pendulab than this client; nothing was computed. {UPGRADE}"
    ), str(e.value)


HANG = 5.0
"""Seconds the hung worker's event loop stays blocked (longer than the sweep may wait for it)."""


def test_a_hung_dask_worker_is_named_within_the_timeout(
    tmp_path: Path, cluster: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A real worker process that hangs at the question before the first chunk (its event loop blocked
    for ``HANG`` s, as by a stuck call): the sweep waited for it as long as it hung (for good, for a
    worker that never comes back). Now it is refused after ``WORKER_TIMEOUT`` (1 s here), naming that
    worker, the timeout and the fix, with nothing computed on any worker and nothing written."""
    _age(cluster, "current")  # every worker has pendulab imported: the healthy one answers at once
    slow, _ = sorted(cluster.nthreads())

    def hang(seconds: float) -> None:
        import time

        from pendulab.sweeps import compute

        ran = compute.ran

        def hung(spec: Any) -> Any:
            compute.ran = ran  # hangs once
            time.sleep(seconds)
            return ran(spec)

        compute.ran = hung

    cluster.run(hang, HANG, workers=[slow])
    monkeypatch.setattr(sweep_backends, "WORKER_TIMEOUT", 1.0)
    out = tmp_path / "sw"
    t0 = time.perf_counter()
    with pytest.raises(TimeoutError) as e:
        pl.sweep(GRID, QS, method="rattle6", scheduler=cluster, out=out, **KW)
    took = time.perf_counter() - t0
    assert str(e.value) == (
        f"the Dask worker {slow} did not answer within 1 s what it would run (asked before the first "
        "chunk): it hangs, its event loop blocked or cut off from the scheduler; nothing was computed. "
        "Restart that worker or take it out of the cluster, or allow it longer "
        "(pendulab.sweeps.backends.WORKER_TIMEOUT), then run the sweep again"
    )
    assert took < HANG, took  # it did not wait for the worker
    assert _computed(cluster) == 0 and not list(out.glob("chunk-*.parquet"))  # (waits for the worker)
    assert same(pl.sweep(GRID, QS, scheduler=cluster, **KW), pl.sweep(GRID, QS, **KW))  # it is back


@pytest.mark.parametrize("bad", [0.0, -1.0, float("nan"), float("inf"), True])
def test_the_workers_timeout_is_a_number_of_seconds(cluster: Any, bad: Any) -> None:
    runner = sweep_backends.Dask(cluster, None)
    with pytest.raises(pl.InvalidInputError) as e:
        runner.ask(sweep_compute.ran, None, timeout=bad)
    assert str(e.value) == f"the Dask workers' timeout must be a finite number of seconds > 0, got {bad!r}"


def test_asking_many_dask_workers_takes_no_thread_per_worker(
    cluster: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A cluster of 500 workers (the real client, its scheduler's answers made up: each worker answers
    after 20 ms, three hang for 6 s): every worker is asked at once, without a thread per worker (before,
    500 threads, one ``Client.run`` each), the answers all come back, and the hung ones are named after
    the timeout (1.5 s: 75 answer times, so that a loaded machine still answers the others in time; it
    failed once at 0.5 s with 448 of 500 late while a browser test ran beside it) without waiting for
    them."""
    workers = [f"tcp://10.0.{k // 200}.{k % 200}:40211" for k in range(500)]
    hung = {workers[7], workers[123], workers[321]}
    peak = 0

    async def answer(function: Any, *args: Any, workers: list[str], **kwargs: Any) -> dict[str, Any]:
        nonlocal peak
        peak = max(peak, threading.active_count())
        await asyncio.sleep(6.0 if hung & set(workers) else 0.02)
        return {addr: function(*args) for addr in workers}

    monkeypatch.setattr(cluster, "nthreads", lambda: dict.fromkeys(workers, 1))
    monkeypatch.setattr(cluster, "_run", answer)
    runner = sweep_backends.Dask(cluster, None)
    before = threading.active_count()
    t0 = time.perf_counter()
    with pytest.raises(TimeoutError) as e:
        runner.ask(abs, -2, timeout=1.5)
    took = time.perf_counter() - t0
    assert str(e.value).startswith(
        f"the Dask worker {workers[123]} (and 2 others of the cluster's 500) did not answer within 1.5 s"
    ), str(e.value)
    assert took < 4.0 and peak <= before + 1, (took, peak, before)
    hung.clear()
    assert runner.ask(abs, -2, timeout=5.0) == dict.fromkeys(workers, 2)
    assert peak <= before + 1, (peak, before)
