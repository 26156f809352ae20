"""Load of the lab server (``pendulab serve``, docs/web.md): many pages at once, and normal pages beside
a greedy one. A script, not a timed test (docs/performance.md, "Lab server under load").

Starts ``pendulab serve --no-browser`` on a free loopback port (a separate process, as a user runs it)
and connects WebSocket clients from this process (asyncio, ``websockets``); each client counts the
binary frame messages it receives (one per server tick, 60 Hz) and their wall-clock arrival times.
Three phases, in one run on this machine:

1. **baseline**: one client alone for T seconds — the reference the others are compared with;
2. **load**: N clients (default 50) at once for T seconds (default 60);
3. **greedy neighbour**: one client doing the most expensive things the server allows — the damped
   model with the largest forcing amplitude and frequency of the registry, ``dop853`` and time scale
   1000, then a stream of ``step n=100000`` at ``rattle8``, dt = 1e-6 — beside 10 normal clients;
4. **a pupil in the room** (issue 30): 30 normal clients beside one misbehaving pupil (:class:`Pupil`:
   16 greedy sessions, 4 of them flooding ``load_scenario``, 150 idle sockets reopened every 10 s, 40
   parallel ``/api/reduced``, 12 parallel ``GET /api/scenarios``, pings without reading), and a
   page's ``POST /api/exact`` every 0.5 s (the share answered 200 and the slowest answer). The pupil
   runs in a process of its own (it is another device: in this process its loops made the measured
   pages read their frames late), and the processor time of the server's worker processes, of the
   pages' clients and of the pupil is printed with the phase.

Every page connects from its own loopback address (127.0.1.1, 127.0.1.2, …: all of 127/8 is this
machine), as the pupils of a class come from their own devices; the server's limits per client
(docs/web.md, "A pupil in the room") apply to each address.

For each phase: frames/s per client (min, median), the inter-frame gaps pooled over the clients
(p50, p99, max) [ms], the server's CPU [% of one core] and resident memory (largest sampled) [MiB],
the ratio of the median frames/s to the baseline's, and the share of the normal clients' frame records
that carry a known error estimate (``error_x`` ≥ 0; −1 is "estimate paused", docs/web.md). With
``--model NAME`` every normal client first switches to that model (e.g. ``damped``: its error is
estimated by a companion stepper at dt/2, about twice the stepping, where the default scenario, the
ideal pendulum, takes the true error from the exact solution). Targets of issue 12 on a 2-core machine when
otherwise idle: 50 × 60 s at ≥ 57 frames/s each with p99 gap ≤ 40 ms; beside the greedy client the
normal ones ≥ 55 frames/s with no gap > 250 ms. The machine's load average is printed with the
figures: the clients share the machine with the server, and so does anything else running.

Run: ``.venv/bin/python bench/lab_load.py [--clients 50] [--seconds 60] [--model NAME] [--only WORDS]
[--markdown FILE]`` (about 3 min with the defaults; ``--only pupil`` runs only phase 4).
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import json
import math
import multiprocessing
import os
import socket
import subprocess
import sys
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


async def phase(
    url: str,
    n: int,
    seconds: float,
    server: psutil.Process,
    with_greedy: bool,
    model: str | None,
    with_pupil: bool = False,
) -> dict[str, Any]:
    clients = [Client(model, page_address(i)) for i in range(n)]
    start = asyncio.Event()
    tasks = [asyncio.create_task(c.run(url, seconds, start)) for c in clients]
    if with_greedy:
        tasks.append(asyncio.create_task(greedy(url, seconds, start)))
    port = int(url.split(":")[2].split("/")[0])
    probed: asyncio.Task[list[float]] | None = None
    pupil: asyncio.Future[tuple[dict[str, int], float]] | None = None
    begin = time.monotonic() + 1.0  # everyone connected and past the first frames
    if with_pupil:
        pupil = asyncio.get_running_loop().run_in_executor(None, pupil_process, port, seconds, begin)
        probed = asyncio.create_task(probe(port, seconds, start))
        tasks.append(probed)
    await asyncio.sleep(max(0.0, begin - time.monotonic()))
    cpu0, t0, rss = server.cpu_times(), time.monotonic(), 0
    me0, workers0 = _cpu(psutil.Process()), _children_cpu(server)
    start.set()
    while not all(t.done() for t in tasks):
        rss = max(rss, server.memory_info().rss)
        await asyncio.sleep(0.5)
    await asyncio.gather(*tasks)
    cpu1, t1 = server.cpu_times(), time.monotonic()
    busy = (cpu1.user + cpu1.system) - (cpu0.user + cpu0.system)
    workers = sum(t - workers0.get(pid, 0.0) for pid, t in _children_cpu(server).items())
    clients_cpu = _cpu(psutil.Process()) - me0
    codes, pupil_cpu = await pupil if pupil is not None else ({}, math.nan)
    fps = np.array([len(c.arrivals) / seconds for c in clients])
    gaps = np.concatenate([np.diff(c.arrivals) for c in clients if len(c.arrivals) > 1]) * 1e3
    return {
        "clients": n,
        "greedy": with_greedy,
        "fps_min": float(fps.min()),
        "fps_median": float(np.median(fps)),
        "gap_p50_ms": float(np.percentile(gaps, 50)),
        "gap_p99_ms": float(np.percentile(gaps, 99)),
        "gap_max_ms": float(gaps.max()),
        "server_cpu_percent": 100.0 * busy / (t1 - t0),
        "server_rss_mib": rss / 2**20,
        "workers_cpu_percent": 100.0 * workers / (t1 - t0),
        "clients_cpu_percent": 100.0 * clients_cpu / (t1 - t0),
        "pupil_cpu_percent": 100.0 * pupil_cpu / (t1 - t0),
        "estimate_known_percent": 100.0
        * sum(c.known for c in clients)
        / max(1, sum(c.records for c in clients)),
        **({} if probed is None else _probe_stats(probed.result(), codes)),
    }


def _cpu(proc: psutil.Process) -> float:
    """Processor seconds (user + system) of ``proc`` so far."""
    t = proc.cpu_times()
    return float(t.user + t.system)


def _children_cpu(server: psutil.Process) -> dict[int, float]:
    """Processor seconds of the server's worker processes (fits, analyses), by process id."""
    out = {}
    for child in server.children(recursive=True):
        with contextlib.suppress(psutil.Error):
            out[child.pid] = _cpu(child)
    return out


def pupil_process(port: int, seconds: float, begin: float) -> tuple[dict[str, int], float]:
    """The pupil in a process of its own (it is another device: its own work must not slow the pages'
    clients in this process); what the server answered it and the processor seconds it used."""
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        return pool.apply(_pupil_main, (port, seconds, begin))


def _pupil_main(port: int, seconds: float, begin: float) -> tuple[dict[str, int], float]:
    pupil, cpu0 = Pupil(), _cpu(psutil.Process())
    asyncio.run(pupil.run(port, seconds, begin))
    return dict(sorted(pupil.codes.items())), _cpu(psutil.Process()) - cpu0


def _probe_stats(times: list[float], codes: dict[str, int]) -> dict[str, Any]:
    ok = [t for t in times if math.isfinite(t)]
    return {
        "probe_ok_percent": 100.0 * len(ok) / max(1, len(times)),
        "probe_max_ms": 1e3 * max(ok) if ok else math.inf,
        "pupil": codes,
    }


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


async def main_async(args: argparse.Namespace) -> list[dict[str, Any]]:
    port = free_port()
    env = {**os.environ, "PENDULAB_NO_BROWSER": "1"}
    cmd = [sys.executable, "-c", "from pendulab.cli import main; main()", "serve", "--no-browser"]
    cmd += ["--port", str(port), "--max-sessions", str(args.clients + 32)]
    proc = subprocess.Popen(cmd, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        url = f"ws://127.0.0.1:{port}/ws"
        for _ in range(600):
            try:
                async with connect(url):
                    break
            except OSError:
                await asyncio.sleep(0.1)
        server = psutil.Process(proc.pid)
        rows = []
        phases = [
            ("baseline: 1 client", 1, False, False, min(args.seconds, 10.0)),
            (f"load: {args.clients} clients", args.clients, False, False, args.seconds),
            ("greedy neighbour: 10 clients + 1 greedy", 10, True, False, min(args.seconds, 30.0)),
            ("a pupil in the room: 30 clients + 1 pupil", 30, False, True, min(args.seconds, 30.0)),
        ]
        for name, n, greedy_on, pupil_on, seconds in phases:
            if args.only and not any(word in name for word in args.only.split(",")):
                continue
            print(f"{name} for {seconds:g} s ...", flush=True)
            rows.append(
                {
                    "phase": name,
                    "seconds": seconds,
                    **await phase(url, n, seconds, server, greedy_on, args.model, pupil_on),
                }
            )
        return rows
    finally:
        proc.terminate()
        proc.wait(10)


def markdown(rows: list[dict[str, Any]]) -> str:
    base = rows[0]["fps_median"]
    out = [
        f"Load average before the run: {LOAD_BEFORE}; after: {_load()} ({os.cpu_count()} cores).",
        "",
        "| phase | frames/s min | frames/s median | ÷ baseline | gap p50 [ms] | gap p99 [ms] | gap max [ms] "
        "| server CPU [% of a core] | server RSS [MiB] | error estimate known [%] |",
        "|---|---|---|---|---|---|---|---|---|---|",
    ]
    for r in rows:
        out.append(
            f"| {r['phase']} ({r['seconds']:g} s) | {r['fps_min']:.1f} | {r['fps_median']:.1f} "
            f"| {r['fps_median'] / base:.3f} | {r['gap_p50_ms']:.1f} | {r['gap_p99_ms']:.1f} "
            f"| {r['gap_max_ms']:.0f} | {r['server_cpu_percent']:.0f} | {r['server_rss_mib']:.0f} "
            f"| {r['estimate_known_percent']:.1f} |"
        )
    for r in rows:
        if "pupil" in r:
            out.append("")
            out.append(
                f"Beside the pupil, a page's `POST /api/exact` every 0.5 s: {r['probe_ok_percent']:.0f} % "
                f"answered 200, the slowest in {r['probe_max_ms']:.0f} ms. What the pupil got: "
                + ", ".join(f"{k}: {v}" for k, v in r["pupil"].items())
                + ". Processor time [% of a core]: the server's worker processes "
                f"{r['workers_cpu_percent']:.0f}, the pages' clients {r['clients_cpu_percent']:.0f}, "
                f"the pupil's process {r['pupil_cpu_percent']:.0f}."
            )
    return "\n".join(out) + "\n"


def _load() -> str:
    return ", ".join(f"{x:.2f}" for x in os.getloadavg())


LOAD_BEFORE = _load()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--clients", type=int, default=50, help="pages in the load phase (default 50)")
    parser.add_argument(
        "--seconds", type=float, default=60.0, help="length of the load phase [s] (default 60)"
    )
    parser.add_argument(
        "--model", help="the model every normal client switches to (default: the server's scenario's)"
    )
    parser.add_argument("--markdown", help="also write the table to this file")
    parser.add_argument(
        "--only", help="run only the phases whose names contain one of these words (comma-separated)"
    )
    args = parser.parse_args()
    rows = asyncio.run(main_async(args))
    table = markdown(rows)
    print(table)
    if args.markdown:
        with open(args.markdown, "w", encoding="utf-8") as f:
            f.write(table)


if __name__ == "__main__":
    main()
