"""Uses the built wheel as a new user would: runs the README's install lines (the block after the
``wheel-install`` marker in README.md, without its ``make wheel``) exactly as written in bash, with HOME in a
temporary folder (so ``~/pendulab-env`` is a fresh virtual environment outside the checkout) and the wheel
in ``dist/`` beside it; then, from another folder, runs

1. the README's quickstart (the Python block after the ``quickstart`` marker in README.md),
2. ``pendulab scenarios`` (every shipped example listed) and ``pendulab run rosette`` by name,
3. ``pendulab serve --no-browser``: the page at the URL it prints, and one status notice plus one
   binary frame over its WebSocket (sent with the page's own Origin and Host),
4. the package's data: examples (scenarios, sweeps, measured data), the built lab page, ``py.typed``,
   the ``_core.pyi`` stubs and the LICENSE,
5. when ``qemu-x86_64`` is installed (Debian's ``qemu-user``) on an x86-64 machine: the import and a
   RATTLE run and an ensemble, each with the unfused and the fused arithmetic named, under an emulated CPU
   without AVX, AVX2, FMA or AVX-512 (``--qemu-cpu``, default Nehalem, x86-64-v2), whose numbers must equal
   the native run's bit for bit; and the default ``arithmetic="auto"`` fused only where the CPU has FMA.

Nothing here reads the checkout except README.md and the wheel. Every step has a time limit.
Usage: python3 tools/check_wheel.py [DIST_DIR] [--qemu-cpu MODEL] (``make test-wheel`` after ``make wheel``).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import re
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
STEP_TIMEOUT = 300.0  # s, any one command

# Runs whose numbers are compared between the native CPU and the emulated old one (printed as hex), with
# each arithmetic named (a named arithmetic gives the same bits on every CPU); then, on its own last line,
# what the default arithmetic ("auto") resolved to there: fused only where FMA is one instruction.
SAME_BITS = """
import numpy as np, pendulab as pl
p = pl.Pendulum(length=1.0, g=9.81, mass=1.0)
s0 = p.state_from_angles(theta=np.radians(60), phi=0.0, theta_dot=0.0, phi_dot=2.0)
starts = pl.states_from_angles(p, theta=np.linspace(0.1, 3.0, 70), phi_dot=1.0)
out = []
for ar in ("unfused", "fused"):
    tr = pl.simulate(p, s0, t_end=2.0, method="rattle", dt=1e-3, progress=False, arithmetic=ar)
    res = pl.simulate_ensemble(p, starts, t_end=0.5, dt=1e-3, progress=False, arithmetic=ar)
    out += [*tr.x[-1], *tr.v[-1], *res.x[:, -1].ravel()]
print(" ".join(float(v).hex() for v in out))
auto = pl.simulate(p, s0, t_end=0.01, method="rattle", dt=1e-3, progress=False)
print(pl._core.fused_is_fast(), auto.options.get("arithmetic", "unfused"))
"""


LICENSE_FILES = """
from importlib.metadata import files
print(" ".join(str(f) for f in files("pendulab") if "licenses" in str(f) or "LICENSE" in str(f)))
"""


def say(msg: str) -> None:
    print(f"check_wheel: {msg}", flush=True)


def run(cmd: list[str], cwd: Path, env: dict[str, str], timeout: float = STEP_TIMEOUT) -> str:
    """Runs `cmd`, returns its stdout; fails with its output on a non-zero exit."""
    t0 = time.perf_counter()
    p = subprocess.run(cmd, cwd=cwd, env=env, capture_output=True, text=True, timeout=timeout, check=False)
    if p.returncode != 0:
        sys.exit(f"check_wheel: FAILED ({p.returncode}): {' '.join(cmd)}\n{p.stdout}\n{p.stderr}")
    shown = " ".join(
        Path(c).name if "/" in c and "\n" not in c else c.strip().split("\n")[0][:40] for c in cmd
    )
    say(f"ok ({time.perf_counter() - t0:.1f} s): {shown}")
    return p.stdout


def quickstart() -> str:
    text = (REPO / "README.md").read_text(encoding="utf-8")
    m = re.search(r"<!-- quickstart[^>]*-->\s*```python\n(.*?)```", text, re.S)
    if m is None:
        sys.exit("check_wheel: README.md has no ```python block after a <!-- quickstart --> marker")
    return m.group(1)


def install_lines() -> list[str]:
    """The README's wheel-install block, without ``make wheel`` (done before this script runs)."""
    text = (REPO / "README.md").read_text(encoding="utf-8")
    m = re.search(r"<!-- wheel-install[^>]*-->\s*```\w*\n(.*?)```", text, re.S)
    if m is None:
        sys.exit("check_wheel: README.md has no code block after a <!-- wheel-install --> marker")
    lines = [line.split("  #")[0].strip() for line in m.group(1).splitlines()]
    lines = [line for line in lines if line]
    if not lines or lines[0] != "make wheel" or not any(line.startswith("pip install") for line in lines):
        sys.exit(f"check_wheel: the README's wheel-install block is not 'make wheel' then pip: {lines}")
    return lines[1:]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


WS_CLIENT = """
import json, sys
from urllib.parse import urlsplit, urlunsplit
from websockets.sync.client import connect
from pendulab.server import decode_records
url = sys.argv[1]
parts = urlsplit(url)
ws_url = urlunsplit(("ws", parts.netloc, "/ws", parts.query, ""))
origin = f"{parts.scheme}://{parts.netloc}"
with connect(ws_url, origin=origin, open_timeout=20, close_timeout=5) as ws:
    status = json.loads(ws.recv(timeout=20))
    assert status["type"] == "status", status
    for _ in range(50):
        msg = ws.recv(timeout=20)
        if isinstance(msg, bytes):
            break
    else:
        raise SystemExit("no binary frame in 50 messages")
frames = decode_records(msg)
assert len(frames) >= 1
print(f"{status['type']} notice, then {len(frames)} frame record(s)")
"""


def check_serve(venv: Path, work: Path, env: dict[str, str]) -> None:
    port = free_port()
    cmd = [str(venv / "bin" / "pendulab"), "serve", "--no-browser", "--port", str(port)]
    t0 = time.perf_counter()
    server = subprocess.Popen(
        cmd, cwd=work, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True
    )
    try:
        url, seen = None, []
        assert server.stdout is not None
        deadline = time.monotonic() + 60
        while url is None and time.monotonic() < deadline:
            line = server.stdout.readline()
            if not line:
                break
            seen.append(line)
            m = re.search(r"(https?://\S+)", line)
            if m:
                url = m.group(1)
        if url is None:
            sys.exit("check_wheel: FAILED: pendulab serve printed no URL:\n" + "".join(seen))
        html = ""
        while time.monotonic() < deadline:
            try:
                with urllib.request.urlopen(url, timeout=10) as r:
                    html = r.read().decode("utf-8", "replace")
                break
            except OSError:
                time.sleep(0.2)
        if "<html" not in html.lower() or "<script" not in html.lower():
            sys.exit(f"check_wheel: FAILED: {url} did not serve the lab page:\n{html[:500]}")
        out = run([str(venv / "bin" / "python"), "-c", WS_CLIENT, url], work, env, timeout=60)
        say(f"ok ({time.perf_counter() - t0:.1f} s): pendulab serve: page and WebSocket ({out.strip()})")
    finally:
        server.terminate()
        try:
            server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            server.kill()
            server.wait()


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("dist", nargs="?", type=Path, default=REPO / "dist")
    ap.add_argument("--qemu-cpu", default="Nehalem", help="CPU model for qemu-x86_64 (default Nehalem)")
    args = ap.parse_args()
    wheels = sorted(args.dist.glob("pendulab-*.whl"))
    if len(wheels) != 1:
        sys.exit(
            f"check_wheel: expected one pendulab wheel in {args.dist}, found {len(wheels)}: run make wheel"
        )
    wheel = wheels[0].resolve()
    t_start = time.perf_counter()
    with tempfile.TemporaryDirectory(prefix="pendulab-wheel-") as tmp:
        home, src, work = Path(tmp) / "home", Path(tmp) / "src", Path(tmp) / "work"
        for d in (home, src, work):
            d.mkdir()
        (src / "dist").mkdir()
        (src / "dist" / wheel.name).symlink_to(wheel)
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
        # pip's download cache stays the user's own (~/.cache/pip), not the temporary HOME's
        env.setdefault("PIP_CACHE_DIR", str(Path.home() / ".cache" / "pip"))
        env["PYTHONUNBUFFERED"] = "1"
        # the README's lines as written (the `python3` on PATH, `~` = the temporary HOME)
        script = "set -e\n" + "\n".join(install_lines()) + "\n"
        run(["bash", "-c", script], src, {**env, "HOME": str(home)}, timeout=900)
        venv = home / "pendulab-env"
        if not (venv / "bin" / "python").is_file():
            sys.exit(f"check_wheel: FAILED: the README's install lines made no environment at {venv}")
        env["PATH"] = f"{venv / 'bin'}{os.pathsep}{env.get('PATH', '')}"
        py = str(venv / "bin" / "python")
        where = run(
            [py, "-c", "import pendulab, pathlib; print(pathlib.Path(pendulab.__file__).parent)"], work, env
        )
        pkg = Path(where.strip())
        if not pkg.is_relative_to(venv):
            sys.exit(f"check_wheel: FAILED: pendulab imported from {pkg}, not from the fresh environment")
        licence = run([py, "-c", LICENSE_FILES], work, env).split()
        if not any(Path(f).name == "LICENSE" for f in licence):
            sys.exit(
                f"check_wheel: FAILED: the wheel has no LICENSE file (dist-info licence files: {licence})"
            )
        data = {p.name for p in (REPO / "examples" / "data").glob("*.csv")}
        for rel in (
            "py.typed",
            "_core.pyi",
            "server/static/index.html",
            "examples/scenarios/rosette.toml",
            *(f"examples/data/{name}" for name in sorted(data)),
        ):
            if not (pkg / rel).is_file():
                sys.exit(f"check_wheel: FAILED: the installed package lacks {rel}")
        shipped = {p.stem for p in (REPO / "examples" / "scenarios").glob("*.toml")}
        installed = {p.stem for p in (pkg / "examples" / "scenarios").glob("*.toml")}
        sweeps = {p.stem for p in (REPO / "examples" / "sweeps").glob("*.toml")}
        if installed != shipped or {p.stem for p in (pkg / "examples" / "sweeps").glob("*.toml")} != sweeps:
            sys.exit(f"check_wheel: FAILED: the wheel's examples {sorted(installed)} != {sorted(shipped)}")
        say(
            f"ok: package data ({len(installed)} scenarios, {len(sweeps)} sweeps, {len(data)} data sets, "
            "lab page, py.typed, stubs, LICENSE)"
        )
        (work / "quickstart.py").write_text(quickstart(), encoding="utf-8")
        run([py, "quickstart.py"], work, env)
        listing = run([str(venv / "bin" / "pendulab"), "scenarios"], work, env)
        missing = [n for n in shipped if not re.search(rf"^{re.escape(n)}\b", listing, re.M)]
        if missing:
            sys.exit(f"check_wheel: FAILED: pendulab scenarios does not list {missing}:\n{listing}")
        pendulab = str(venv / "bin" / "pendulab")
        run([pendulab, "run", "rosette", "--t-end", "2", "--out", "rosette.csv"], work, env)
        rows = (work / "rosette.csv").read_text(encoding="utf-8").splitlines()
        if len(rows) < 10:
            sys.exit(f"check_wheel: FAILED: rosette.csv has {len(rows)} lines")
        check_serve(venv, work, env)
        qemu = shutil.which("qemu-x86_64")
        if platform.machine() != "x86_64":
            say(f"skipped: the old-CPU run (qemu-x86_64 emulates x86-64; this is {platform.machine()})")
        elif qemu is None:
            say("skipped: the old-CPU run (no qemu-x86_64: apt-get install qemu-user)")
        else:
            native, native_auto = run([py, "-c", SAME_BITS], work, env).strip().splitlines()
            out = run([qemu, "-cpu", args.qemu_cpu, py, "-c", SAME_BITS], work, env, timeout=600)
            emulated, emulated_auto = out.strip().splitlines()
            cpu = args.qemu_cpu
            if native.split() != emulated.split():
                n_diff = sum(a != b for a, b in zip(native.split(), emulated.split(), strict=False))
                sys.exit(f"check_wheel: FAILED: {n_diff} numbers differ between this CPU and qemu -cpu {cpu}")
            for where, line in (("this CPU", native_auto), (f"qemu -cpu {cpu}", emulated_auto)):
                fast, resolved = line.split()
                if resolved != ("fused" if fast == "True" else "unfused"):
                    sys.exit(f"check_wheel: FAILED: on {where} 'auto' ran {resolved} (FMA: {fast})")
            say(
                f"ok: under qemu -cpu {cpu} the same {len(native.split())} numbers, bit for bit, unfused and "
                f"fused; the default ran {native_auto.split()[1]} here, {emulated_auto.split()[1]} there"
            )
    say(json.dumps({"wheel": wheel.name, "seconds": round(time.perf_counter() - t_start, 1)}))


if __name__ == "__main__":
    main()
