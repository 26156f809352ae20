"""The ensembles' worker threads (python/rust/threads.rs): one per CPU the process may use, each bound
to a CPU of its own when there are as many workers as CPUs (more than one), and left to the scheduler
otherwise or when ``PENDULAB_BIND_THREADS=0``. Read from /proc (Linux), not timed."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(not Path("/proc/self/task").is_dir(), reason="Linux /proc only")

PROBE = r"""
import json, os
import numpy as np
import pendulab as pl
from pendulab import _core
p = pl.Pendulum()
pl.simulate_ensemble(p, pl.states_from_angles(p, theta=np.linspace(0.1, 1.0, 300)), 0.01, progress=False)
workers = {}
for tid in os.listdir("/proc/self/task"):
    name = open(f"/proc/self/task/{tid}/comm").read().strip()
    if name.startswith("pendulab-"):
        workers[name] = sorted(os.sched_getaffinity(int(tid)))
print(json.dumps({"pool": _core.thread_pool(), "workers": workers,
                  "cpus": sorted(os.sched_getaffinity(0))}))
"""


def probe(**env: str) -> dict:
    """The pool and its workers' CPU sets in a fresh interpreter with ``env`` added."""
    out = subprocess.run(
        [sys.executable, "-c", PROBE], env={**os.environ, **env}, capture_output=True, text=True, check=True
    )
    return json.loads(out.stdout)


def test_one_worker_per_cpu_each_bound_to_its_own() -> None:
    got = probe(RAYON_NUM_THREADS="")
    cpus = got["cpus"]
    threads, bound = got["pool"]
    assert threads == len(cpus)
    assert sorted(got["workers"]) == [f"pendulab-{k}" for k in range(threads)]
    if len(cpus) < 2:
        assert not bound  # one CPU: nothing to bind
        return
    assert bound
    assert [got["workers"][f"pendulab-{k}"] for k in range(threads)] == [[c] for c in cpus]


def test_binding_off_by_environment_and_for_pools_of_another_size() -> None:
    off = probe(PENDULAB_BIND_THREADS="0", RAYON_NUM_THREADS="")
    assert off["pool"][1] is False
    assert all(cpus == off["cpus"] for cpus in off["workers"].values())
    one = probe(RAYON_NUM_THREADS="1")
    assert one["pool"] == [1, False]
    assert list(one["workers"].values()) == [one["cpus"]]
