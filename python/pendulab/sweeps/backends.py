"""Where the chunks of a sweep run (:func:`pendulab.sweep`): a thread pool, or a ``dask.distributed``
cluster; and the driver that keeps a few chunks in flight, hands each finished one over for writing,
and stops cleanly on Ctrl-C (``docs/sweeps.md``)."""

from __future__ import annotations

import asyncio
import concurrent.futures as cf
import contextlib
import logging
import math
import os
import signal
import threading
import uuid
from collections.abc import Callable, Iterator
from typing import Any

from .._core import InvalidInputError

CONNECT_TIMEOUT = 5.0
"""Seconds to wait for a Dask scheduler before giving up."""

POLL = 0.1
"""Seconds between the driver's checks (progress, Ctrl-C)."""

WORKER_TIMEOUT = 30.0
"""Seconds every Dask worker gets to answer the question asked before the first chunk (what it would
run, :meth:`Dask.ask`): a healthy worker answers in milliseconds (a second or so if it has still to
import pendulab); one that has not answered by then hangs (its event loop blocked, or cut off) and
would hang the sweep. Set it (``pendulab.sweeps.backends.WORKER_TIMEOUT = 120``) for a slower
cluster."""


class Threads:
    """A small thread pool: the core releases the GIL (and the ensemble kernel uses every core)."""

    def __init__(self, workers: int) -> None:
        self.pool = cf.ThreadPoolExecutor(workers, thread_name_prefix="pendulab-sweep")
        self.cancel = threading.Event()
        self.slots = 2 * workers
        self.name = f"threads ({workers} worker{'s' if workers > 1 else ''})"

    def submit(self, fn: Callable[..., Any], task: Any) -> Any:
        return self.pool.submit(fn, task, self.cancel)

    def wait(self, pending: Iterator[Any], timeout: float) -> set[Any]:
        return cf.wait(list(pending), timeout=timeout, return_when=cf.FIRST_COMPLETED).done

    def stop(self, pending: list[Any]) -> list[Any]:
        """Cancels what has not finished; waits for the running chunks to stop; returns the finished."""
        self.cancel.set()
        for f in pending:
            f.cancel()
        cf.wait(pending)
        return [f for f in pending if not f.cancelled() and f.exception() is None]

    def close(self) -> None:
        self.pool.shutdown(wait=True, cancel_futures=True)


class Dask:
    """A ``dask.distributed`` client: on a new LocalCluster (``scheduler`` None), on the scheduler at an
    address (``tcp://HOST:8786``), or a ``distributed.Client`` given by the caller (left open)."""

    def __init__(self, scheduler: Any, workers: int | None) -> None:
        try:
            import distributed
        except ImportError as e:
            raise ImportError("backend 'dask' needs dask.distributed: pip install 'pendulab[sweep]'") from e
        self.distributed = distributed
        self.cluster: Any = None
        self.own_client = True
        if isinstance(scheduler, distributed.Client):
            self.client, self.own_client = scheduler, False
        elif scheduler is None:
            self.cluster = distributed.LocalCluster(
                n_workers=workers or os.cpu_count() or 1,
                threads_per_worker=1,
                processes=True,
                dashboard_address=None,
                silence_logs=logging.ERROR,
            )
            self.client = distributed.Client(self.cluster)
        else:
            self.client = connect(str(scheduler))
        nthreads = sum(self.client.nthreads().values()) or 1
        scheduler = self.client.scheduler  # None only for a client that never connected
        where = "LocalCluster" if self.cluster is not None or scheduler is None else scheduler.address
        self.name = f"dask ({where}, {nthreads} worker thread{'s' if nthreads > 1 else ''})"
        self.slots = 2 * nthreads
        self.run = uuid.uuid4().hex[:8]
        self.late: set[asyncio.Future[Any]] = set()

    def ask(self, fn: Callable[..., Any], *args: Any, timeout: float | None = None) -> dict[str, Any]:
        """``fn(*args)`` on every worker of the cluster now (``distributed.Client.run``, one question a
        worker, all asked at once on the client's own event loop: no thread per worker, whatever the size
        of the cluster): worker address → what it returned, or the exception it raised (also the one of a
        worker that cannot unpickle ``fn``). A ``TimeoutError`` naming the first worker (by address) that
        has not answered within ``timeout`` s (default :data:`WORKER_TIMEOUT`), how many others, and the
        fix. The question to a hung worker is left waiting on that loop (it holds up nothing, and ends
        when the worker answers or the client closes)."""
        wait = WORKER_TIMEOUT if timeout is None else timeout
        if isinstance(wait, bool) or not (isinstance(wait, (int, float)) and 0 < wait < math.inf):
            raise InvalidInputError(
                f"the Dask workers' timeout must be a finite number of seconds > 0, got {wait!r}"
            )
        workers = sorted(self.client.nthreads())
        answers: dict[str, Any] = self.client.sync(self._ask_all, workers, fn, args, wait) if workers else {}
        hung = [addr for addr in workers if addr not in answers]
        if hung:
            raise TimeoutError(
                f"{name_workers(hung, len(workers))} did not answer within {wait:g} s what it would run "
                "(asked before the first chunk): it hangs, its event loop blocked or cut off from the "
                "scheduler; nothing was computed. Restart that worker or take it out of the cluster, or "
                "allow it longer (pendulab.sweeps.backends.WORKER_TIMEOUT), then run the sweep again"
            )
        return answers

    async def _ask_all(
        self, workers: list[str], fn: Callable[..., Any], args: tuple[Any, ...], wait: float
    ) -> dict[str, Any]:
        """On the client's event loop: the answers of the ``workers`` that answered within ``wait`` s.
        The questions still open are kept (:attr:`late`) until they end."""

        async def one(addr: str) -> dict[str, Any]:
            try:
                question = self.client.run(fn, *args, workers=[addr], on_error="return", asynchronous=True)
                answer: dict[str, Any] = await question
                return answer
            except Exception as e:  # the scheduler's own error for this worker (e.g. it left)
                return {addr: e}

        asking = [asyncio.ensure_future(one(addr)) for addr in workers]
        done, late = await asyncio.wait(asking, timeout=wait)
        for question in late:
            self.late.add(question)
            question.add_done_callback(self.late.discard)
        return {addr: a for question in done for addr, a in question.result().items()}

    def submit(self, fn: Callable[..., Any], task: Any) -> Any:
        return self.client.submit(
            fn, task, key=f"pendulab-sweep-{self.run}-{task.index}", pure=False, retries=1
        )

    def wait(self, pending: Iterator[Any], timeout: float) -> set[Any]:
        try:
            res = self.distributed.wait(list(pending), timeout=timeout, return_when="FIRST_COMPLETED")
            return set(res.done)
        except TimeoutError:
            return set()

    def stop(self, pending: list[Any]) -> list[Any]:
        done = [f for f in pending if f.status == "finished"]
        self.client.cancel([f for f in pending if f.status != "finished"])
        return done

    def close(self) -> None:
        if self.own_client:
            self.client.close()
        if self.cluster is not None:
            self.cluster.close()


def name_workers(addresses: list[str], cluster: int) -> str:
    """The first of ``addresses`` and how many more of the ``cluster``'s workers: ``the Dask worker
    tcp://10.0.0.7:40211 (and 2 others of the cluster's 5)``."""
    named = f"the Dask worker {addresses[0]}"
    if len(addresses) > 1:
        more = len(addresses) - 1
        named += f" (and {more} other{'s' if more > 1 else ''} of the cluster's {cluster})"
    return named


def connect(address: str, timeout: float | None = None) -> Any:
    """A ``distributed.Client`` on the scheduler at ``address``; a clear ``OSError`` naming it when it
    cannot be reached within ``timeout`` s (default :data:`CONNECT_TIMEOUT`)."""
    import distributed

    if "://" not in address:
        raise InvalidInputError(f"scheduler {address!r}: give an address such as tcp://HOST:8786")
    wait = CONNECT_TIMEOUT if timeout is None else timeout
    try:
        return distributed.Client(address, timeout=f"{wait}s")
    except Exception as e:  # OSError (refused, timed out) or garbage from a non-Dask server
        raise OSError(
            f"cannot reach the Dask scheduler at {address} within {wait:g} s "
            f"({type(e).__name__}: {' '.join(str(e).split())[:200]})"
        ) from None


@contextlib.contextmanager
def _deferred_ctrl_c() -> Iterator[threading.Event]:
    """While the sweep runs in the main thread with Python's default SIGINT handler, a Ctrl-C only sets
    the yielded flag (the driver stops at its next safe point, never in the middle of writing a chunk)
    and restores the default handler, so that a second Ctrl-C interrupts at once."""
    flag = threading.Event()
    if (
        threading.current_thread() is not threading.main_thread()
        or signal.getsignal(signal.SIGINT) is not signal.default_int_handler
    ):
        yield flag
        return

    def handler(signum: int, frame: Any) -> None:
        flag.set()
        signal.signal(signal.SIGINT, signal.default_int_handler)

    signal.signal(signal.SIGINT, handler)
    try:
        yield flag
    finally:
        signal.signal(signal.SIGINT, signal.default_int_handler)


def drive(
    runner: Threads | Dask,
    fn: Callable[..., Any],
    todo: list[int],
    task: Callable[[int], Any],
    done: Callable[[int, Any], None],
    bar: Any,
) -> None:
    """Runs ``fn(task(i))`` for the chunks i in ``todo`` with at most ``runner.slots`` in flight and
    hands each result to ``done(i, result)`` in the calling thread. On any error or Ctrl-C it stops the
    others, still hands over (on Ctrl-C) the chunks that finished, and re-raises."""
    pending: dict[Any, int] = {}
    queue = iter(todo)
    with _deferred_ctrl_c() as ctrl_c:
        try:
            while True:
                while len(pending) < runner.slots and (i := next(queue, None)) is not None:
                    pending[runner.submit(fn, task(i))] = i
                if not pending:
                    break
                for f in runner.wait(iter(pending), POLL):
                    i = pending.pop(f)
                    done(i, f.result())
                    bar.update(1)
                if ctrl_c.is_set():
                    raise KeyboardInterrupt
        except BaseException as e:
            finished = runner.stop(list(pending))
            if isinstance(e, KeyboardInterrupt):  # keep what is done; resume computes the rest
                for f in finished:
                    try:
                        done(pending[f], f.result())
                    except Exception:  # pragma: no cover - e.g. the disk filled up meanwhile
                        break
            raise
        finally:
            runner.close()
