"""The lab server as a classroom service (docs/web.md, "Security": "a pupil in the room"), part 1 of
issue 30's attacks: nothing run on request can hold the server. A fit whose linear algebra never
returns runs in a worker process with a time limit (3 s here) while HTTP and the 60 frames/s go on and
Ctrl-C still stops the server; a worker that dies is named with its exit code, one past its time is
killed and replaced (``pendulab/server/worker.py``). Times in seconds."""

from __future__ import annotations

import asyncio
import contextlib
import json
import math
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import httpx
import pytest
from ws_session import frame_gaps

from pendulab.server.worker import WorkerPool, WorkFailed, WorkInvalid, WorkTimeout

ROOT = Path(__file__).resolve().parents[2]
FILMED = ROOT / "examples" / "data" / "filmed_swing.csv"
POISON = FILMED.read_text().rstrip("\n") + "\n20.0,1e308,0.67\n"
"""Issue 30: this file made numpy's lstsq spin for good, holding the interpreter lock."""

# --- 1. nothing run on request can hold the server -------------------------------------------------------

SERVE = """
import sys, uvicorn
from pendulab.server import create_app
from pendulab.server.serving import server_config
try:
    app = create_app("rosette", fit_seconds=3.0)
except TypeError:  # the server of before had no limit
    app = create_app("rosette")
uvicorn.Server(server_config(app, "127.0.0.1", int(sys.argv[1]))).run()
"""


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@contextlib.contextmanager
def _server_process() -> Iterator[tuple[subprocess.Popen[bytes], int]]:
    port = _free_port()
    quiet = subprocess.DEVNULL
    with subprocess.Popen([sys.executable, "-c", SERVE, str(port)], stdout=quiet, stderr=quiet) as proc:
        try:
            for _ in range(300):
                try:
                    if httpx.get(f"http://127.0.0.1:{port}/api/schema", timeout=1.0).status_code == 200:
                        break
                except httpx.TransportError:
                    time.sleep(0.1)
            yield proc, port
        finally:
            if proc.poll() is None:
                proc.kill()


def test_a_fit_that_never_returns_cannot_hold_the_server_nor_its_signals() -> None:
    with _server_process() as (proc, port):
        url = f"http://127.0.0.1:{port}"
        answer: dict[str, Any] = {}

        def post() -> None:
            t0 = time.monotonic()
            with contextlib.suppress(httpx.HTTPError):
                r = httpx.post(f"{url}/api/fit", json={"csv": POISON, "name": "poison.csv"}, timeout=40)
                answer.setdefault("fit", (r.status_code, r.text))
            answer["seconds"] = time.monotonic() - t0

        poster = threading.Thread(target=post)
        poster.start()
        time.sleep(0.5)
        t0 = time.monotonic()
        r = httpx.get(f"{url}/api/schema", timeout=10)
        assert r.status_code == 200 and time.monotonic() - t0 < 3.0, "HTTP answered during the fit"
        gaps = frame_gaps(port, 2.0)
        assert len(gaps) > 20 and max(gaps) < 1.0, f"{len(gaps)} frames in 2 s beside the fit"
        poster.join(40)
        # a result, or a clear error within the limit (3 s in the worker, plus starting it)
        assert "fit" in answer and answer["seconds"] < 25.0, answer
        assert answer["fit"][0] in (200, 422, 503), answer
        if answer["fit"][0] == 503:  # keyed, so that the page words it in its language (messages.json)
            body = json.loads(answer["fit"][1])
            assert "longer than 3 s" in body["detail"] and body["key"] == "work_timeout", body
            assert body["values"] == {"seconds": "3"}, body
        del answer["seconds"]
        # Ctrl-C while a fit runs (or has just been refused) stops the server promptly
        poster = threading.Thread(target=post, daemon=True)
        poster.start()
        time.sleep(0.7)
        t0 = time.monotonic()
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=15)
        assert time.monotonic() - t0 < 3.0


def _close_pipe_then_exit(code: int) -> None:  # runs in a worker: its pipe closes 0.3 s before it exits
    os.closerange(3, 4096)
    time.sleep(0.3)
    os._exit(code)


def test_a_worker_that_dies_is_named_with_its_exit_code() -> None:
    """A worker that exits mid-job (the kernel's OOM killer, a crash) is a keyed ``worker_died`` with its
    exit code (it said "exit code None": the pipe closes before the code is known), and the next job gets
    a new worker."""
    pool = WorkerPool("test", seconds=10.0)

    async def go() -> None:
        with pytest.raises(WorkFailed, match=r"worker died \(exit code 3\)") as died:
            await pool.run(_close_pipe_then_exit, 3)
        assert died.value.key == "worker_died" and died.value.values == {"code": "3"}
        assert await pool.run(math.hypot, 3.0, 4.0) == b"5.0"

    try:
        asyncio.run(go())
    finally:
        pool.close()


def test_a_worker_past_its_time_is_killed_and_replaced() -> None:
    pool = WorkerPool("test", seconds=0.5)

    async def go() -> None:
        t0 = time.monotonic()
        with pytest.raises(WorkTimeout, match=r"longer than 0\.5 s"):
            await pool.run(time.sleep, 60.0, seconds=0.5)
        assert time.monotonic() - t0 < 15.0  # the first job also starts the fork server
        assert pool.killed == 1
        assert await pool.run(math.hypot, 3.0, 4.0) == b"5.0"  # a new worker serves the next job
        with pytest.raises(WorkInvalid, match="math domain error"):
            await pool.run(math.sqrt, -1.0)
        # a request cancelled mid-job (the server stopping) kills its worker at once
        task = asyncio.ensure_future(pool.run(time.sleep, 60.0))
        await asyncio.sleep(0.3)
        task.cancel()
        with pytest.raises(asyncio.CancelledError):
            await task

    try:
        asyncio.run(go())
    finally:
        pool.close()
