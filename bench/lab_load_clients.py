"""The clients of the lab server's load benchmark (``bench/lab_load.py``, docs/performance.md "Lab
server under load"): a normal page (:class:`Client`, counting its frame messages, one per server
tick at 60 Hz, and their arrival times [s]), the greedy client (the most expensive run the registry
allows, then a stream of ``step n=100000`` at dt = 1e-6 s), the misbehaving pupil of issue 30
(:class:`Pupil`, run in a process of its own by :func:`pupil_process`) and the well-behaved page's
``POST /api/exact`` every 0.5 s beside it (:func:`probe`, answer times [s]).

Every page connects from its own loopback address (127.0.1.1, 127.0.1.2, …: all of 127/8 is this
machine), the pupil from 127.0.0.2 and the probe from 127.0.0.3, so that the server's limits per
client (docs/web.md, "A pupil in the room") apply to each. Processor time in seconds (user + system).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import math
import multiprocessing
import time
from dataclasses import dataclass, field
from typing import Any

import httpx
import numpy as np
import pendulab as pl
import psutil
from pendulab.server.protocol import FRAME_FIELDS
from websockets.asyncio.client import connect
from websockets.exceptions import ConnectionClosed

ERROR_X = FRAME_FIELDS.index("error_x")


def _max(model: str, name: str) -> float:
    """The registry's largest allowed value (1e4 where it has none)."""
    spec = next(p for m in pl.models() if m["name"] == model for p in m["params"] if p["name"] == name)
    return float(spec["max"]) if np.isfinite(spec["max"]) else 1e4


GREEDY_RUN = [
    {
        "type": "set_model",
        "model": "damped",
        "params": {
            "forcing_amplitude": _max("damped", "forcing_amplitude"),
            "forcing_omega": _max("damped", "forcing_omega"),
            "forcing_x": 1.0,
        },
    },
    {"type": "set_method", "method": "dop853"},
    {"type": "set_time_scale", "time_scale": 1000.0},
]
GREEDY_STEP = [
    {"type": "set_model", "model": "ideal"},
    {"type": "set_method", "method": "rattle8", "dt": 1e-6},
]


@dataclass
class Client:
    """One page: the arrival times [s] of its frame messages."""

    model: str | None = None
    source: str = "127.0.0.1"  # the address it connects from: each page is its own device
    arrivals: list[float] = field(default_factory=list)
    records: int = 0
    known: int = 0  # records with a known error estimate (error_x >= 0)

    async def run(self, url: str, seconds: float, start: asyncio.Event) -> None:
        """Receives all the time (nothing waits in a buffer); counts the frames that arrive within
        ``seconds`` after ``start`` is set."""
        async with connect(url, max_size=2**22, max_queue=None, local_addr=(self.source, 0)) as ws:
            if self.model is not None:
                await ws.send(json.dumps({"type": "set_model", "model": self.model}))
            end = None
            while end is None or time.monotonic() < end:
                if end is None and start.is_set():
                    end = time.monotonic() + seconds
                try:
                    msg = await asyncio.wait_for(ws.recv(), timeout=0.25)
                except TimeoutError:
                    continue
                if end is not None and isinstance(msg, bytes):
                    self.arrivals.append(time.monotonic())
                    err = np.frombuffer(msg, dtype="<f8").reshape(-1, len(FRAME_FIELDS))[:, ERROR_X]
                    self.records += len(err)
                    self.known += int(np.count_nonzero(err >= 0))


def page_address(i: int) -> str:
    """The address page i connects from (127.0.0.0/8 is all this machine): 127.0.1.1, 127.0.1.2, …"""
    return f"127.0.{1 + i // 250}.{1 + i % 250}"


PUPIL = "127.0.0.2"
"""The misbehaving pupil's address."""


async def greedy(url: str, seconds: float, start: asyncio.Event) -> None:
    """The greedy client: the expensive run for half the time, then a stream of big steps."""
    async with connect(url, max_size=2**22, max_queue=None, local_addr=(PUPIL, 0)) as ws:

        async def drain() -> None:
            async for _ in ws:
                pass

        reader = asyncio.create_task(drain())
        await start.wait()
        for c in GREEDY_RUN:
            await ws.send(json.dumps(c))
        await asyncio.sleep(seconds / 2)
        for c in GREEDY_STEP:
            await ws.send(json.dumps(c))
        end = time.monotonic() + seconds / 2
        while time.monotonic() < end:
            await ws.send(json.dumps({"type": "step", "n": 100_000}))
            await asyncio.sleep(0.05)
        reader.cancel()


@dataclass
class Pupil:
    """A misbehaving pupil (one address, :data:`PUPIL`) doing everything of issue 30 at once: 16 greedy
    sessions (GREEDY_RUN; 4 of them flooding ``load_scenario``), 150 idle sockets reopened every 10 s,
    40 parallel ``POST /api/reduced`` (the largest), 12 parallel ``GET /api/scenarios`` and one
    WebSocket pinging without reading. Counts what the server answered it."""

    codes: dict[str, int] = field(default_factory=dict)
    sessions: int = 0

    def count(self, what: str) -> None:
        self.codes[what] = self.codes.get(what, 0) + 1

    async def run(self, port: int, seconds: float, begin: float) -> None:
        """Everything at once from ``begin`` (``time.monotonic()``, the same clock in every process of
        this machine) for ``seconds``."""
        await asyncio.sleep(max(0.0, begin - time.monotonic()))
        end = time.monotonic() + seconds
        jobs = [self.session(port, end, flood=i < 4) for i in range(16)]
        jobs += [self.idle(port, end), self.pings(port, end)]
        async with httpx.AsyncClient(
            base_url=f"http://127.0.0.1:{port}",
            transport=httpx.AsyncHTTPTransport(local_address=PUPIL),
            timeout=60,
            limits=httpx.Limits(max_connections=60),
        ) as http:
            body = {"length": 1.0, "g": 9.81, "theta": 2.9, "phi_dot": 0.1, "n": 4000, "grid": 121}
            jobs += [self.rest(http, "POST", "/api/reduced", body, end) for _ in range(40)]
            jobs += [self.rest(http, "GET", "/api/scenarios", None, end) for _ in range(12)]
            await asyncio.gather(*jobs, return_exceptions=True)

    async def session(self, port: int, end: float, flood: bool) -> None:
        with contextlib.suppress(ConnectionClosed, OSError):
            await self._session(port, end, flood)

    async def _session(self, port: int, end: float, flood: bool) -> None:
        url = f"ws://127.0.0.1:{port}/ws"
        async with connect(url, max_size=2**22, max_queue=None, local_addr=(PUPIL, 0)) as ws:

            async def drain() -> None:
                with contextlib.suppress(ConnectionClosed):
                    async for msg in ws:
                        if isinstance(msg, str) and "too many lab sessions" in msg:
                            self.count("session refused")

            reader = asyncio.create_task(drain())
            for c in GREEDY_RUN:
                await ws.send(json.dumps(c))
            self.sessions += 1
            i = 0
            while time.monotonic() < end and not reader.done():
                if flood:
                    name = ("kepler", "rosette")[i % 2]
                    await ws.send(json.dumps({"type": "load_scenario", "name": name}))
                    i += 1
                await asyncio.sleep(0.005)
            reader.cancel()

    async def idle(self, port: int, end: float) -> None:
        while time.monotonic() < end:
            held = []
            for _ in range(150):
                try:
                    held.append(await asyncio.open_connection("127.0.0.1", port, local_addr=(PUPIL, 0)))
                except OSError:
                    self.count("idle socket refused")
            await asyncio.sleep(min(10.0, max(0.0, end - time.monotonic())))
            for _, w in held:
                w.close()

    async def pings(self, port: int, end: float) -> None:
        with contextlib.suppress(Exception):
            async with connect(
                f"ws://127.0.0.1:{port}/ws", max_queue=1, local_addr=(PUPIL, 0)
            ) as ws:  # never reads (max_queue=1: the client stops reading as soon as one message waits)
                while time.monotonic() < end:
                    await ws.ping()
                    await asyncio.sleep(0.0005)
        if time.monotonic() < end:
            self.count("ping socket cut")

    async def rest(self, http: Any, method: str, path: str, body: Any, end: float) -> None:
        while time.monotonic() < end:
            try:
                r = await http.request(method, path, json=body)
                self.count(f"{path} {r.status_code}")
                if r.status_code != 200:
                    await asyncio.sleep(0.02)
            except httpx.HTTPError:
                self.count(f"{path} failed")
                await asyncio.sleep(0.02)


async def probe(port: int, seconds: float, start: asyncio.Event) -> list[float]:
    """A well-behaved page's REST requests beside the pupil: ``POST /api/exact`` every 0.5 s from its
    own address; the answer times [s] (inf for anything but 200)."""
    await start.wait()
    end = time.monotonic() + seconds
    times: list[float] = []
    transport = httpx.AsyncHTTPTransport(local_address="127.0.0.3")
    async with httpx.AsyncClient(base_url=f"http://127.0.0.1:{port}", transport=transport, timeout=30) as c:
        while time.monotonic() < end:
            t0 = time.monotonic()
            try:
                r = await c.post("/api/exact", json={"theta": 1.0, "phi_dot": 1.0})
                times.append(time.monotonic() - t0 if r.status_code == 200 else math.inf)
            except httpx.HTTPError:
                times.append(math.inf)
            await asyncio.sleep(0.5)
    return times


def cpu_seconds(proc: psutil.Process) -> float:
    """Processor seconds (user + system) of ``proc`` so far."""
    t = proc.cpu_times()
    return float(t.user + t.system)


def pupil_process(port: int, seconds: float, begin: float) -> tuple[dict[str, int], float]:
    """The pupil in a process of its own (it is another device: its own work must not slow the pages'
    clients in this process); what the server answered it and the processor seconds it used."""
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        return pool.apply(_pupil_main, (port, seconds, begin))


def _pupil_main(port: int, seconds: float, begin: float) -> tuple[dict[str, int], float]:
    pupil, cpu0 = Pupil(), cpu_seconds(psutil.Process())
    asyncio.run(pupil.run(port, seconds, begin))
    return dict(sorted(pupil.codes.items())), cpu_seconds(psutil.Process()) - cpu0
