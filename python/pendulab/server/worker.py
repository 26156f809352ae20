"""Killable worker processes for the lab's heavy requests (docs/web.md, "Security": "a pupil in the room").

A fit (``POST /api/fit``) or an analysis (``/api/exact``, ``/api/reduced``, ``/api/em_map``) runs code
whose time the server cannot bound beforehand: a LAPACK call handed an infinite matrix may never
return, and it holds the interpreter lock while it runs, so a worker *thread* would freeze every
session, every HTTP answer and even Ctrl-C. These requests therefore run in worker *processes*
(:class:`WorkerPool`): each pool has ``size`` processes (started by ``multiprocessing``'s
``forkserver``, which imports the package once, so a new worker is ready in milliseconds), at most
``queue`` requests wait for one (more get :class:`Busy`, HTTP 503), and each job has a wall-time
limit of ``seconds``: past it the worker is killed (SIGKILL: no code of the job can ignore it), a new
one started, and the request answered with :class:`WorkTimeout` (HTTP 503 naming the limit). A
request cancelled while its job runs (the server stopping on Ctrl-C or SIGTERM) kills the worker too,
so the server stops within its shutdown grace whatever the job does.

The event loop never blocks on a worker: it waits for the answer on the pipe's file descriptor
(``loop.add_reader``). A job is a module-level function and its arguments (pickled); the worker
returns the function's value as JSON bytes (orjson), or the error to report: :class:`WorkInvalid`
for bad input (the core's :class:`~pendulab.InvalidInputError` and ``IntegrationError``, ScenarioError,
ValueError, ArithmeticError: HTTP 422), :class:`WorkFailed` for anything else (HTTP 500, logged).
Workers ignore SIGINT (a Ctrl-C in the terminal reaches the whole process group; the server ends
them itself) and end when the server's end of their pipe closes (the server killed by SIGKILL).
They run at the server's own priority: niced, a worker on a busy machine got so little of the
processor that the wall-time limits stopped short jobs (a 0.5 s limit at load 18), and the pupil's
analyses used 1-7 % of a core (its two computations at once bound it).
The apps of one process share their pools (:func:`shared_pool`). Times in seconds.
"""

from __future__ import annotations

import asyncio
import contextlib
import logging
import multiprocessing
import signal
import sys
import threading
import weakref
from collections.abc import Callable
from multiprocessing.connection import Connection
from typing import Any

log = logging.getLogger("pendulab.server")

PRELOAD = ["pendulab", "pendulab.server.fit", "pendulab.server.views", "pendulab.server.rest"]
"""Modules the fork server imports once, so that every worker starts with them loaded."""


class Busy(Exception):
    """Too many requests already wait for this pool's workers (HTTP 503, try again); ``waiting``: how
    many."""

    def __init__(self, message: str, waiting: int = 0) -> None:
        super().__init__(message)
        self.waiting = waiting


class WorkTimeout(Exception):
    """The job ran past its wall-time limit of ``seconds`` [s]; its worker was killed (HTTP 503)."""

    def __init__(self, message: str, seconds: float = 0.0) -> None:
        super().__init__(message)
        self.seconds = seconds


class _KeyedWork(Exception):
    """A job's error with ``key`` and ``values`` naming it for a page that words it in its language
    (``messages.json``; ``key`` None: not keyed, the page shows the English message)."""

    def __init__(self, message: str, key: str | None = None, values: dict[str, Any] | None = None) -> None:
        super().__init__(message)
        self.key = key
        self.values = values or {}


class WorkInvalid(_KeyedWork):
    """The job refused its input (HTTP 422); the message names the problem."""


class WorkFailed(_KeyedWork):
    """The job failed in an unexpected way or its worker died (HTTP 500); the message says how."""


_INVALID_NAMES = {"InvalidInputError", "IntegrationError", "ScenarioError"}


def _invalid(e: BaseException) -> bool:
    """True for an error that means "bad input" (HTTP 422) rather than a fault of the server."""
    kinds = {k.__name__ for k in type(e).__mro__}
    return bool(kinds & _INVALID_NAMES) or isinstance(e, (ValueError, ArithmeticError, TypeError))


def _keyed(e: BaseException) -> tuple[str | None, dict[str, Any]]:
    """The message key and values of a keyed refusal (:class:`pendulab.fitting.keyed.KeyedInputError`,
    or anything with ``key`` and ``values`` of those types), else ``(None, {})``."""
    key, values = getattr(e, "key", None), getattr(e, "values", None)
    if not isinstance(key, str) or not isinstance(values, dict):
        return None, {}
    return key, {str(k): v for k, v in values.items() if isinstance(v, str | int | float)}


def _serve(conn: Connection) -> None:  # pragma: no cover - runs in the worker process
    """A worker's loop: receive (fn, args), send ("ok", JSON bytes) or (kind, message)."""
    import orjson

    signal.signal(signal.SIGINT, signal.SIG_IGN)
    with contextlib.suppress(Exception):
        from threadpoolctl import threadpool_limits

        threadpool_limits(1)  # one core per worker: the live sessions share the others
    while True:
        try:
            fn, args = conn.recv()
        except (EOFError, OSError):
            return
        try:
            reply: tuple[str, Any] = ("ok", orjson.dumps(fn(*args)))
        except MemoryError:
            reply = (
                "invalid",
                ("the request needs more memory than the server has for it", "out_of_memory", {}),
            )
        except Exception as e:
            text = " ".join(str(e).split())[:2000] or type(e).__name__
            key, values = _keyed(e)
            reply = (
                ("invalid", (text, key, values)) if _invalid(e) else ("failed", f"{type(e).__name__}: {text}")
            )
        try:
            conn.send(reply)
        except (OSError, ValueError):
            return


def _context() -> Any:
    """The forkserver context (Linux, macOS) with :data:`PRELOAD`; spawn where there is none."""
    if sys.platform != "win32" and "forkserver" in multiprocessing.get_all_start_methods():
        ctx = multiprocessing.get_context("forkserver")
        ctx.set_forkserver_preload(PRELOAD)
        return ctx
    return multiprocessing.get_context("spawn")


class _Worker:
    """One worker process and the server's end of its pipe."""

    def __init__(self, ctx: Any) -> None:
        self.conn, child = ctx.Pipe(duplex=True)
        self.proc = ctx.Process(target=_serve, args=(child,), daemon=True, name="pendulab-worker")
        self.proc.start()
        child.close()

    def kill(self) -> None:
        with contextlib.suppress(Exception):
            self.proc.kill()
        with contextlib.suppress(Exception):
            self.conn.close()
        with contextlib.suppress(Exception):
            self.proc.join(1.0)

    def alive(self) -> bool:
        return self.proc.is_alive() and not self.conn.closed


class WorkerPool:
    """``size`` killable worker processes (module doc), at most ``queue`` requests waiting, a wall-time
    limit of ``seconds`` per job."""

    def __init__(self, name: str, size: int = 1, queue: int = 4, seconds: float = 30.0) -> None:
        self.name, self.size, self.queue, self.seconds = name, size, queue, float(seconds)
        self._idle: list[_Worker] = []
        self._lock = threading.Lock()
        self._ctx: Any = None
        self._gates: weakref.WeakKeyDictionary[Any, asyncio.Semaphore] = weakref.WeakKeyDictionary()
        self._waiting = 0
        self.killed = 0  # workers killed at their time limit (or cancelled): for tests and logs
        weakref.finalize(self, WorkerPool._close_all, self._idle)

    @staticmethod
    def _close_all(idle: list[_Worker]) -> None:
        for w in idle:
            w.kill()
        idle.clear()

    def close(self) -> None:
        """Ends the idle workers (busy ones end when their job does or is cancelled)."""
        with self._lock:
            WorkerPool._close_all(self._idle)

    def _take(self) -> _Worker:
        with self._lock:
            while self._idle:
                w = self._idle.pop()
                if w.alive():
                    return w
                w.kill()
            if self._ctx is None:
                self._ctx = _context()
        return _Worker(self._ctx)

    def _give_back(self, w: _Worker) -> None:
        with self._lock:
            if len(self._idle) < self.size:
                self._idle.append(w)
                return
        w.kill()

    def warm(self) -> None:
        """Starts the workers now (else at the first job)."""
        with self._lock:
            if self._ctx is None:
                self._ctx = _context()
            while len(self._idle) < self.size:
                self._idle.append(_Worker(self._ctx))

    def _gate(self) -> asyncio.Semaphore:
        loop = asyncio.get_running_loop()
        gate = self._gates.get(loop)
        if gate is None:
            gate = self._gates[loop] = asyncio.Semaphore(self.size)
        return gate

    async def run(self, fn: Callable[..., Any], *args: Any, seconds: float | None = None) -> bytes:
        """``fn(*args)`` in a worker, as JSON bytes. Raises :class:`Busy`, :class:`WorkTimeout`,
        :class:`WorkInvalid` or :class:`WorkFailed` (module doc)."""
        gate = self._gate()
        if gate.locked() and self._waiting >= self.queue:
            raise Busy(
                f"busy: {self._waiting} {self.name} requests are waiting; try again in a moment",
                self._waiting,
            )
        self._waiting += 1
        try:
            await gate.acquire()
        finally:
            self._waiting -= 1
        try:
            return await self._run(fn, args, self.seconds if seconds is None else seconds)
        finally:
            gate.release()

    async def _run(self, fn: Callable[..., Any], args: tuple[Any, ...], seconds: float) -> bytes:
        loop = asyncio.get_running_loop()
        w = await asyncio.to_thread(self._take)  # the first start launches the fork server: seconds
        ready: asyncio.Future[None] = loop.create_future()
        fd = w.conn.fileno()

        def readable() -> None:
            if not ready.done():
                ready.set_result(None)

        done = False
        try:
            w.conn.send((fn, args))
            loop.add_reader(fd, readable)
            try:
                await asyncio.wait_for(ready, seconds)
            finally:
                loop.remove_reader(fd)
            try:
                kind, value = w.conn.recv()
            except (EOFError, OSError):
                # the pipe closes a moment before the process's exit code is known: wait for it (≤ 1 s)
                await asyncio.to_thread(w.proc.join, 1.0)
                code = w.proc.exitcode
                raise WorkFailed(
                    f"the {self.name} worker died (exit code {code}); the request may need more "
                    "memory than the server has",
                    "worker_died",
                    {"code": str(code)},
                ) from None
            done = True
        except TimeoutError:
            self.killed += 1
            raise WorkTimeout(
                f"the {self.name} took longer than {seconds:g} s and was stopped; "
                "try fewer data, fewer parameters or a simpler model",
                seconds,
            ) from None
        finally:
            if done:
                self._give_back(w)
            else:
                w.kill()  # timed out, cancelled (the server stopping) or died: never reused
        if kind == "ok":
            return bytes(value)
        if kind == "invalid":
            text, key, values = value
            raise WorkInvalid(str(text), key, values)
        raise WorkFailed(str(value))


_SHARED: dict[tuple[str, int, int, float], WorkerPool] = {}
_SHARED_LOCK = threading.Lock()


def shared_pool(name: str, size: int = 1, queue: int = 4, seconds: float = 30.0) -> WorkerPool:
    """The process's pool with these settings, made on first use: the apps of one process (the tests
    make many) share their workers instead of each keeping processes of its own."""
    key = (name, size, queue, float(seconds))
    with _SHARED_LOCK:
        pool = _SHARED.get(key)
        if pool is None:
            pool = _SHARED[key] = WorkerPool(name, size, queue, seconds)
        return pool
