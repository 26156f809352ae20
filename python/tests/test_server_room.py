"""The lab server as a classroom service (docs/web.md, "Security": "a pupil in the room"): the attacks
of issue 30, each of which froze, starved or crashed the server of before — a fit whose linear algebra
never returns, one client's greedy sessions and ``load_scenario`` flood, idle sockets, parallel
computing requests, GET floods, WebSocket pings without reading, an open redirect of the classroom
token, memory beyond what the machine has. Other clients are told apart by their address: a client
binds 127.0.0.N (all of 127/8 is this machine)."""

from __future__ import annotations

import asyncio
import base64
import contextlib
import json
import math
import os
import resource
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
import numpy as np
import pytest
from websockets.sync.client import connect
from ws_session import LabClient, frame_gaps, live_lab, receive

import pendulab as pl
from pendulab.server import create_app, tick
from pendulab.server.hygiene import MAX_WS_BUFFER
from pendulab.server.protocol import parse_command
from pendulab.server.room import MAX_CONNECTIONS_PER_CLIENT, MAX_REQUESTS_PER_CLIENT, Room
from pendulab.server.session import Session, resolve_scenario
from pendulab.server.worker import WorkerPool, WorkFailed, WorkInvalid, WorkTimeout

ROOT = Path(__file__).resolve().parents[2]
FILMED = ROOT / "examples" / "data" / "filmed_swing.csv"
POISON = FILMED.read_text().rstrip("\n") + "\n20.0,1e308,0.67\n"
"""Issue 30: this file made numpy's lstsq spin for good, holding the interpreter lock."""


def _local(n: int) -> str:
    return f"127.0.0.{n}"


def _ws(port: int, source: int = 1) -> Any:
    """A WebSocket to the lab from 127.0.0.``source``."""
    sock = socket.socket()
    sock.bind((_local(source), 0))
    sock.connect(("127.0.0.1", port))
    return connect(f"ws://127.0.0.1:{port}/ws", sock=sock, proxy=None, open_timeout=10, max_queue=None)


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


# --- 2. fairness per client and per room ------------------------------------------------------------------


def test_one_client_may_hold_only_its_share_of_sessions() -> None:
    client = LabClient(create_app("rosette", max_sessions_per_client=2))
    with client.websocket_connect("/ws") as a, client.websocket_connect("/ws") as b:
        assert receive(a)[1]["type"] == "status" and receive(b)[1]["type"] == "status"
        with client.websocket_connect("/ws") as c:
            _, notice = receive(c)
            assert notice["type"] == "error" and "too many lab sessions from your device" in notice["message"]
    with client.websocket_connect("/ws") as d:  # the closed ones are counted off
        assert receive(d)[1]["type"] == "status"


def test_the_room_budget_is_shared_by_clients_then_by_their_sessions() -> None:
    room = Room(per_client=8, room_budget=0.012)  # (the default is 8 ms)
    for _ in range(8):
        assert room.open_session("greedy") is None
    assert room.open_session("greedy") is not None
    for i in range(29):
        room.open_session(f"pupil{i}")
    assert room.share("pupil0") == pytest.approx(0.012 / 30)
    assert room.share("greedy") == pytest.approx(0.012 / 30 / 8)  # 8 sessions: the same as one page

    async def three() -> None:
        async with room.request("x") as first, room.request("x") as second:
            t0 = time.monotonic()
            async with room.request("x", wait=0.2) as third:
                assert first and second and not third and MAX_REQUESTS_PER_CLIENT == 2
            assert time.monotonic() - t0 >= 0.2  # it waited for a slot first
        async with room.request("x") as again:
            assert again

    asyncio.run(three())


def test_commands_are_carried_out_within_the_budget_and_the_rest_wait() -> None:
    s = Session(resolve_scenario("rosette"))
    names = ("damped", "rosette") * 10
    loads = [parse_command(json.dumps({"type": "load_scenario", "name": n})) for n in names]
    carry = tick.Carry()
    tick.tick_messages(s, loads, 1 / 60, 1e-6, carry=carry)
    assert s.commands == 1 and len(carry.left) == 19, "one command when the budget is spent at once"
    assert carry.debt > 0, "its cost beyond the budget is owed"
    left, carry.left = carry.left, []
    tick.tick_messages(s, left, 1 / 60, 1e-6, carry=carry)
    assert s.commands == 1 and len(carry.left) == 19, "none while the debt is paid off"
    carry = tick.Carry()
    s2 = Session(resolve_scenario("rosette"))
    tick.tick_messages(s2, left, 1 / 60, 1.0, carry=carry)
    assert s2.commands == 19 and not carry.left, "all of them within a large budget"
    assert s2.scenario == "rosette"


GREEDY = [
    {"type": "set_model", "model": "damped", "params": {"forcing_amplitude": 1e3, "forcing_omega": 1e4}},
    {"type": "set_method", "method": "dop853"},
    {"type": "set_time_scale", "time_scale": 1000.0},
]


PUPIL = """
import asyncio, json, sys, time
from websockets.asyncio.client import connect
port, sessions, flooding, seconds = (int(a) for a in sys.argv[1:5])
greedy = json.loads(sys.argv[5])

async def session(k):
    url = f"ws://127.0.0.1:{port}/ws"
    async with connect(url, max_queue=None, max_size=2**22, local_addr=("127.0.0.2", 0)) as ws:
        async def drain():
            async for _ in ws:
                pass
        reader = asyncio.create_task(drain())
        for c in greedy:
            await ws.send(json.dumps(c))
        end, i = time.monotonic() + seconds, 0
        while time.monotonic() < end and not reader.done():
            if k < flooding:
                await ws.send(json.dumps({"type": "load_scenario", "name": ("kepler", "rosette")[i % 2]}))
                i += 1
            await asyncio.sleep(0.002)
        reader.cancel()

async def main():
    await asyncio.gather(*(session(k) for k in range(sessions)), return_exceptions=True)

asyncio.run(main())
"""


@contextlib.contextmanager
def pupil(port: int, sessions: int, flooding: int, seconds: float) -> Iterator[None]:
    """A misbehaving client from 127.0.0.2 in another process: ``sessions`` greedy sessions, the first
    ``flooding`` of them sending ``load_scenario`` without pause, for ``seconds``."""
    args = [str(port), str(sessions), str(flooding), str(int(seconds)), json.dumps(GREEDY)]
    with subprocess.Popen([sys.executable, "-c", PUPIL, *args]) as proc:
        try:
            time.sleep(1.0)
            yield
        finally:
            proc.kill()


@pytest.fixture(scope="module")
def port() -> Iterator[int]:
    with live_lab(create_app("rosette")) as p:
        yield p


def test_greedy_sessions_and_a_load_scenario_flood_leave_the_others_their_frames(port: int) -> None:
    """Issue 30: 16 greedy sessions of one client cut others to 18 frames/s of 60, four sessions
    flooding ``load_scenario`` to 6.6 with 2.6 s gaps. Both at once left the neighbour 4-6 % of
    what it got alone on the server of before (on a machine with a load average of 17 on 2 cores:
    2-3 frames/s of 55-59), 20-65 % now; the margin is for the shared machine the tests run on (the
    load benchmark, bench/lab_load.py, measures the room on an idle one)."""
    alone = frame_gaps(port, 2.0)
    with pupil(port, sessions=16, flooding=4, seconds=6):
        beside = frame_gaps(port, 3.0)
    ratio = (len(beside) / 3.0) / (len(alone) / 2.0)
    assert ratio > 0.12, f"{len(beside)} frames in 3 s beside the pupil, {len(alone)} in 2 s alone"
    assert max(beside) < 1.0, f"a gap of {max(beside):.2f} s"


def _closed(s: socket.socket) -> bool:
    """True when the server has closed (or reset) the connection."""
    try:
        return s.recv(1, socket.MSG_DONTWAIT | socket.MSG_PEEK) == b""
    except BlockingIOError:
        return False
    except OSError:
        return True


def test_idle_sockets_of_one_client_cannot_fill_the_server(port: int) -> None:
    """Issue 30: ~150 idle sockets from one client made every other request 503."""
    idle = []
    try:
        for _ in range(150):
            s = socket.socket()
            s.bind((_local(3), 0))
            s.connect(("127.0.0.1", port))
            idle.append(s)
        time.sleep(0.3)
        r = httpx.get(f"http://127.0.0.1:{port}/api/schema", timeout=5)
        assert r.status_code == 200
        cut = sum(_closed(s) for s in idle)
        assert cut >= 150 - MAX_CONNECTIONS_PER_CLIENT
    finally:
        for s in idle:
            s.close()


def test_parallel_computing_requests_of_one_client_do_not_crowd_out_another(port: int) -> None:
    """Issue 30: 40 parallel ``/api/reduced`` requests got others' ``/api/exact`` 503 in 22 of 25 (they
    filled the shared queue); now one client has at most two under way or waiting, the rest wait for
    those (then 429) or are cut beyond its connection limit."""
    body = {"length": 1.0, "g": 9.81, "theta": 2.9, "phi_dot": 0.1, "n": 4000, "grid": 121}
    codes: list[int] = []

    def flood() -> None:
        transport = httpx.HTTPTransport(local_address=_local(4))
        with httpx.Client(base_url=f"http://127.0.0.1:{port}", transport=transport, timeout=30) as c:
            for _ in range(2):
                try:
                    codes.append(c.post("/api/reduced", json=body).status_code)
                except httpx.TransportError:
                    codes.append(-1)  # cut: more connections than one client may hold

    threads = [threading.Thread(target=flood) for _ in range(40)]
    for t in threads:
        t.start()
    time.sleep(0.3)
    mine = [
        httpx.post(f"http://127.0.0.1:{port}/api/exact", json={"theta": 1.0}, timeout=30) for _ in range(5)
    ]
    for t in threads:
        t.join(60)
    assert [r.status_code for r in mine] == [200] * 5, [r.text[:200] for r in mine]
    assert 200 in codes and set(codes) <= {200, 429, -1}, codes


def test_get_answers_are_cached(monkeypatch: pytest.MonkeyPatch) -> None:
    """Issue 30: 12 parallel ``GET /api/scenarios`` (a foreign page can send them) cut pages to 9.5
    frames/s: each listed and parsed every example file."""
    import pendulab.server.app as app_module

    calls = []
    listed = app_module.scenarios
    monkeypatch.setattr(app_module, "scenarios", lambda: calls.append(1) or listed())
    client = LabClient(create_app("rosette"))
    first = client.get("/api/scenarios")
    assert first.status_code == 200 and len(first.json()) > 3
    assert all(client.get("/api/scenarios").content == first.content for _ in range(5))
    assert len(calls) == 1


def _ws_frame(opcode: int, payload: bytes) -> bytes:
    mask = os.urandom(4)
    masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
    return bytes([0x80 | opcode, 0x80 | len(payload)]) + mask + masked


def test_a_client_that_pings_without_reading_is_cut_off(port: int) -> None:
    """Issue 30: pings without reading grew the server from 72 to 342 MiB."""
    s = socket.socket()
    s.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
    s.connect(("127.0.0.1", port))
    key = base64.b64encode(os.urandom(16)).decode()
    s.sendall(
        (
            f"GET /ws HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
            f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n"
        ).encode()
    )
    ping = _ws_frame(0x9, b"p" * 125) * 64
    sent = 0
    cut = False
    s.settimeout(5)
    try:
        while sent < 40 * MAX_WS_BUFFER:  # never reads: the pongs pile up on the server
            s.sendall(ping)
            sent += len(ping)
    except OSError:  # reset (or blocked: the server stopped reading us)
        cut = True
    finally:
        s.close()
    assert cut, f"{sent} bytes of pings sent and the connection still open"


# --- 4. no 500, no abort ---------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def client() -> LabClient:
    return LabClient(create_app("rosette"))


def _rows() -> list[list[str]]:
    return [r.split(",") for r in FILMED.read_text().splitlines()[2:]]


def _csv(rows: list[list[Any]]) -> str:
    return "t,x,z\n" + "\n".join(",".join(map(str, r)) for r in rows) + "\n"


EXTREME = {
    "times 1e-300 apart": lambda: _csv([[i * 1e-300, r[1], r[2]] for i, r in enumerate(_rows())]),
    "times 1e300 apart": lambda: _csv([[i * 1e300, r[1], r[2]] for i, r in enumerate(_rows())]),
    "a 200 kB cell": lambda: "t,x,z\n" + "1" * 200_000 + ",0.5,0.6\n" + _csv(_rows()[:50])[6:],
    "a 200 kB header": lambda: "t,x," + "z" * 200_000 + "\n" + _csv(_rows()[:50])[6:],
}


@pytest.mark.parametrize("case", sorted(EXTREME))
def test_extreme_fit_uploads_get_a_clear_4xx(client: LabClient, case: str) -> None:
    r = client.post("/api/fit", json={"csv": EXTREME[case](), "name": "extreme.csv"})
    assert r.status_code in (200, 422), (r.status_code, r.text[:300])
    if r.status_code == 422:
        assert "internal error" not in r.text and len(r.json()["detail"]) > 10


def test_a_sigma_of_1e_300_gets_a_clear_4xx(client: LabClient) -> None:
    r = client.post("/api/fit", json={"csv": _csv(_rows()), "sigma": 1e-300})
    assert r.status_code == 422, (r.status_code, r.text[:300])
    assert "sigma = 1e-300 m for positions is below 1e-15 m" in r.json()["detail"], r.text[:300]


@pytest.mark.parametrize("g", [1e-300, -1e-200, 5e-324])
def test_a_negligible_gravity_gets_the_great_circle_not_a_zero_period(client: LabClient, g: float) -> None:
    """The audit of issue 30: /api/exact with g = 1e-300 answered 200 with a "conical" orbit of
    z-period 0 s (the elliptic form overflowed); it is the great circle of g = 0, period 2π l/|v|."""
    body = {"theta": 1.0, "phi": 0.0, "theta_dot": 0.0, "phi_dot": 1.0, "g": g}
    r = client.post("/api/exact", json=body)
    assert r.status_code == 200, r.text[:300]
    assert r.json()["kind"] == "great_circle"
    assert r.json()["period_z"] == pytest.approx(2 * math.pi / math.sin(1.0), rel=1e-14)


def _memory_limited(extra_bytes: int, body: str) -> str:
    """A script run with ``python -c`` whose address space may grow by only ``extra_bytes`` beyond what
    it has after importing pendulab (RLIMIT_AS), then runs ``body`` (``p``: the default pendulum)."""
    return f"""
import resource, sys, numpy as np, pendulab as pl
from pathlib import Path
vm = next(int(l.split()[1]) * 1024 for l in Path("/proc/self/status").read_text().splitlines()
          if l.startswith("VmSize:"))
resource.setrlimit(resource.RLIMIT_AS, (vm + {extra_bytes}, resource.RLIM_INFINITY))
p = pl.Pendulum()
{body}"""


def _run_limited(script: str, call: str) -> subprocess.CompletedProcess[str]:
    """``script`` in a fresh Python with ``call`` as its argument; it must exit normally."""
    out = subprocess.run(
        [sys.executable, "-c", script, call], capture_output=True, text=True, timeout=120, check=False
    )
    assert out.returncode == 0, out.stderr[-500:]
    return out


LIMITED = _memory_limited(
    2**30,  # 1 GiB more
    """try:
    if sys.argv[1] == "exact":
        pl.exact(p, p.state_from_angles(1.0, 0.0, 0.0, 1.0)).state(np.zeros(int(2.5e7)))
    else:
        n = int(3e6)
        pl.simulate_ensemble(p, np.tile([0.5, 0, -0.75**0.5, 0, 0.3, 0], (n, 1)), 0.01, progress=False)
    print("computed")
except pl.InvalidInputError as e:
    print("refused:", e)
""",
)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc: Linux")
@pytest.mark.parametrize("call", ["exact", "ensemble"])
def test_a_call_beyond_the_memory_left_is_refused_not_aborted(call: str) -> None:
    """Issue 30: ``exact(p, s).state(np.zeros(2e8))`` and a 1e7-row ensemble aborted the process under
    a memory limit (the core's allocation failed); now the need is estimated first."""
    out = _run_limited(LIMITED, call)
    assert out.stdout.startswith("refused:") and "GiB" in out.stdout and "chunks" in out.stdout, out.stdout


SAVING = _memory_limited(
    2**28,  # 256 MiB more
    """s = p.state_from_angles(1.0, 0.0, 0.0, 1.0)
try:
    if sys.argv[1] == "save_at":
        pl.simulate(p, s, 1.0, save_at=np.linspace(0.0, 1.0, 10**7))
    else:
        pl.simulate(p, s, 1e6, method="dop853", save_every=1)
    print("computed")
except pl.InvalidInputError as e:
    print("refused:", e)
""",
)


@pytest.mark.skipif(not sys.platform.startswith("linux"), reason="RLIMIT_AS and /proc: Linux")
@pytest.mark.parametrize("call", ["save_at", "adaptive"])
def test_a_run_saving_more_than_the_memory_left_is_refused_not_aborted(call: str) -> None:
    """The audit of issue 30: ``simulate`` with 10⁷ ``save_at`` times, or ``dop853`` saving every
    step over 10⁶ s, aborted the process under a memory limit (the core's allocation failed: the
    default cap on saved samples is 4 GiB whatever the machine has); now the save times are checked
    first and the cap is what the process can still get."""
    out = _run_limited(SAVING, call)
    assert out.stdout.startswith("refused:"), out.stdout
    words = "GiB of memory" if call == "save_at" else "above the limit of"
    assert words in out.stdout, out.stdout


def test_small_calls_are_not_refused() -> None:
    p = pl.Pendulum()
    x, v = pl.exact(p, p.state_from_angles(1.0, 0.0, 0.0, 1.0)).state(np.linspace(0, 1, 1000))
    assert x.shape == (1000, 3) and np.isfinite(v).all()
    assert resource.getrlimit(resource.RLIMIT_AS)  # the check reads the limits without changing them


# --- 5. the classroom token redirect stays on the server ---------------------------------------------------


@pytest.mark.parametrize("path", ["//evil.example/", "/\\evil.example/", "///evil.example/x"])
def test_the_token_redirect_is_not_an_open_redirect(path: str) -> None:
    client = LabClient(create_app("rosette", token="sesame-1234"), follow_redirects=False)
    r = client.get(f"http://127.0.0.1{path}?token=sesame-1234&a=1")
    assert r.status_code == 303
    location = r.headers["location"]
    assert location.startswith("/") and not location.startswith(("//", "/\\")), location
    assert "token" not in location and location.endswith("?a=1")
