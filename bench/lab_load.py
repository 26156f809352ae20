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
[--markdown FILE]`` (about 3 min with the defaults; ``--only pupil`` runs only phase 4). The clients
(pages, the greedy one, the pupil, the probe) are in ``bench/lab_load_clients.py``; this file starts
the server, runs the phases and measures them.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import math
import os
import socket
import subprocess
import sys
import time
from typing import Any

import numpy as np
import psutil
from lab_load_clients import Client, cpu_seconds, greedy, page_address, probe, pupil_process
from websockets.asyncio.client import connect


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
    me0, workers0 = cpu_seconds(psutil.Process()), _children_cpu(server)
    start.set()
    while not all(t.done() for t in tasks):
        rss = max(rss, server.memory_info().rss)
        await asyncio.sleep(0.5)
    await asyncio.gather(*tasks)
    cpu1, t1 = server.cpu_times(), time.monotonic()
    busy = (cpu1.user + cpu1.system) - (cpu0.user + cpu0.system)
    workers = sum(t - workers0.get(pid, 0.0) for pid, t in _children_cpu(server).items())
    clients_cpu = cpu_seconds(psutil.Process()) - me0
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


def _children_cpu(server: psutil.Process) -> dict[int, float]:
    """Processor seconds of the server's worker processes (fits, analyses), by process id."""
    out = {}
    for child in server.children(recursive=True):
        with contextlib.suppress(psutil.Error):
            out[child.pid] = cpu_seconds(child)
    return out


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
