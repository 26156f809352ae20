"""The lab server as a classroom service (docs/web.md, "Security": "a pupil in the room"), part 3 of
issue 30's attacks: no 500 and no abort. Extreme fit uploads (times 1e-300 s or 1e300 s apart, 200 kB
cells and headers, sigma = 1e-300 m) get a clear 4xx, a negligible gravity (m/s²) the great circle,
calls and runs needing more memory than the process can still get (RLIMIT_AS) a refusal instead of an
abort; and the classroom token redirect stays on the server."""

from __future__ import annotations

import math
import resource
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from ws_session import LabClient

import pendulab as pl
from pendulab.server import create_app

ROOT = Path(__file__).resolve().parents[2]
FILMED = ROOT / "examples" / "data" / "filmed_swing.csv"


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
