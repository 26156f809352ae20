"""No client can starve or hang another (docs/web.md, "Security", "Pacing"): the attacks of issue 12
that stalled the whole server — three valid commands that made one tick endless, a stream of big
``step`` commands, a flood of heavy REST requests — run against a real uvicorn server while a
well-behaved page measures its frames (against what it gets alone, measured in the same test: the
machine is shared); Ctrl-C and SIGTERM stop the server within 2 s during such an attack; frames never
carry a non-finite number. Each attack stalled the server of before for seconds or for good."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from collections.abc import Iterator
from typing import Any

import httpx
import numpy as np
import pytest
from websockets.exceptions import ConnectionClosed
from websockets.sync.client import connect
from ws_session import frame_gaps, live_lab

import pendulab as pl
from pendulab.server import create_app
from pendulab.server.protocol import parse_command
from pendulab.server.session import Session, resolve_scenario
from pendulab.server.tick import tick_messages


def _limit(model: str, name: str) -> float:
    spec = next(p for m in pl.models() if m["name"] == model for p in m["params"] if p["name"] == name)
    return float(spec["max"]) if np.isfinite(spec["max"]) else 1e9


HANG = [  # issue 12: these three valid commands hung the server for good
    {
        "type": "set_model",
        "model": "damped",
        "params": {
            "forcing_amplitude": min(1000.0, _limit("damped", "forcing_amplitude")),
            "forcing_omega": _limit("damped", "forcing_omega"),
            "forcing_x": 1.0,
        },
    },
    {"type": "set_method", "method": "dop853"},
    {"type": "set_time_scale", "time_scale": 1000.0},
]


class Attacker:
    """A client in a thread: sends ``commands`` (then ``repeat`` every ``every`` s), reads everything."""

    def __init__(self, port: int, commands: list[dict[str, Any]], repeat: dict[str, Any] | None = None):
        self.port, self.commands, self.repeat = port, commands, repeat
        self.statuses: list[dict[str, Any]] = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True)

    def _run(self) -> None:
        with contextlib.suppress(ConnectionClosed), self._connect() as ws:
            for c in self.commands:
                ws.send(json.dumps(c))
            while not self.stop.is_set():
                if self.repeat is not None:
                    ws.send(json.dumps(self.repeat))
                try:
                    msg = ws.recv(timeout=0.02)
                except TimeoutError:
                    continue
                if isinstance(msg, str) and json.loads(msg)["type"] == "status":
                    self.statuses.append(json.loads(msg))

    def _connect(self) -> Any:
        return connect(f"ws://127.0.0.1:{self.port}/ws", proxy=None, max_queue=None)

    def __enter__(self) -> Attacker:
        self.thread.start()
        time.sleep(0.5)  # its commands are applied
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop.set()
        self.thread.join(10)


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    with live_lab(create_app("rosette")) as p:
        yield p


def fair(port: int, gaps: list[float]) -> None:
    """The neighbour beside an attacker got at least 40 % of the frames it gets alone (measured now,
    on the same machine: the CI machine is shared; the server of before gave it 0–15 %)."""
    alone = frame_gaps(port, 2.0)
    ratio = (len(gaps) / 3.0) / (len(alone) / 2.0)
    assert ratio > 0.4, f"{len(gaps)} frames in 3 s beside the attacker, {len(alone)} in 2 s alone"


def test_three_valid_commands_no_longer_hang_the_server(port: int) -> None:
    with Attacker(port, HANG) as attacker:
        gaps = frame_gaps(port, 3.0)
        t0 = time.monotonic()
        r = httpx.get(f"http://127.0.0.1:{port}/api/schema", timeout=10.0)
        answered = time.monotonic() - t0
    assert r.status_code == 200 and answered < 5.0, answered
    fair(port, gaps)
    assert attacker.statuses and attacker.statuses[-1]["lagging"], "the attacker is told it lags"
    assert attacker.statuses[-1]["method"] == "dop853"


def test_a_stream_of_big_steps_cannot_starve_a_neighbour(port: int) -> None:
    setup = [{"type": "set_method", "method": "rattle8", "dt": 1e-6}]
    with Attacker(port, setup, repeat={"type": "step", "n": 100_000}):
        gaps = frame_gaps(port, 3.0)
    fair(port, gaps)


FLOOD = """
import sys, threading, time, httpx
port, seconds = int(sys.argv[1]), float(sys.argv[2])
body = {"length": 1.0, "g": 9.81, "theta": 2.9, "phi_dot": 0.1, "n": 4000, "grid": 121}
codes = []
def flood():
    end = time.monotonic() + seconds
    with httpx.Client(base_url=f"http://127.0.0.1:{port}", timeout=30.0) as c:
        while time.monotonic() < end:
            codes.append(c.post("/api/reduced", json=body).status_code)
threads = [threading.Thread(target=flood) for _ in range(6)]
for t in threads: t.start()
for t in threads: t.join()
print(" ".join(map(str, sorted(set(codes)))), len(codes))
"""


def test_a_flood_of_heavy_rest_requests_runs_beside_the_frames(port: int) -> None:
    """Six clients (another process, one address: beyond its two at once it gets 429) post the largest
    reduced view as fast as they can."""
    cmd = [sys.executable, "-c", FLOOD, str(port), "4.0"]
    with subprocess.Popen(cmd, stdout=subprocess.PIPE, text=True) as flood:
        try:
            time.sleep(0.7)
            gaps = frame_gaps(port, 3.0)
            out, _ = flood.communicate(timeout=60)
        finally:
            if flood.poll() is None:
                flood.kill()
    codes, count = out.split()[:-1], int(out.split()[-1])
    assert count >= 6 and set(codes) <= {"200", "429", "503"}, out  # 429: more than its share at once
    fair(port, gaps)


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_ctrl_c_and_sigterm_stop_the_server_within_2_s_during_an_attack(sig: int) -> None:
    port = _free_port()
    env = {**os.environ, "PENDULAB_NO_BROWSER": "1"}
    cmd = [sys.executable, "-c", "from pendulab.cli import main; main()", "serve", "--no-browser"]
    quiet = subprocess.DEVNULL
    with subprocess.Popen([*cmd, "--port", str(port)], env=env, stdout=quiet, stderr=quiet) as proc:
        try:
            for _ in range(300):
                try:
                    if httpx.get(f"http://127.0.0.1:{port}/api/schema", timeout=1.0).status_code == 200:
                        break
                except httpx.TransportError:
                    time.sleep(0.1)
            with Attacker(port, [*HANG, {"type": "step", "n": 100_000}]):
                time.sleep(0.5)
                t0 = time.monotonic()
                proc.send_signal(sig)
                proc.wait(timeout=10)
                took = time.monotonic() - t0
        finally:
            if proc.poll() is None:
                proc.kill()
    assert took < 2.0, f"stopped after {took:.2f} s"
    assert proc.returncode in (0, -sig), proc.returncode  # Ctrl-C: exit 0; SIGTERM: terminated by it


# --- 5. no frame carries a non-finite number ------------------------------------------------------------


def test_sessions_at_the_parameter_bounds_send_only_finite_frames() -> None:
    """Every lab model with each own parameter at its largest allowed value, at time scale 1000: the
    frames are finite, or the session pauses with an error naming the cause."""
    for model in ("damped", "rotating", "slewing", "vibrating", "spring", "string"):
        spec = next(m for m in pl.models() if m["name"] == model)
        own = {p["name"]: float(p["max"]) for p in spec["params"] if p["name"] not in ("length", "mass", "g")}
        own = {k: v for k, v in own.items() if np.isfinite(v)}
        s = Session(resolve_scenario("rosette"))
        out = tick_messages(
            s,
            [
                parse_command(json.dumps({"type": "set_model", "model": model, "params": own})),
                parse_command('{"type": "set_time_scale", "time_scale": 1000}'),
            ],
            0.0,
        )
        for _ in range(5):
            out += tick_messages(s, [], 1 / 60, budget_seconds=0.002)
        for m in out:
            if isinstance(m, bytes):
                assert np.isfinite(np.frombuffer(m, dtype="<f8")).all(), model
            elif m["type"] == "error":
                assert s.paused and ("finite" in m["message"] or "stopped" in m["message"]), m
