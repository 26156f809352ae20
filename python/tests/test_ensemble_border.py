"""The ensemble's border between Python and the core, made cheaper per call (docs/performance.md,
"The fixed cost of a call"): the models' arrays copied once by ``EnsembleSpec`` and shared by its runs
(later changes to the numpy arrays reach no run; a strided array gives the bits of a contiguous one),
the saved states handed back in one pass (every trajectory equals ``simulate``), the array check told
by two reductions when every entry is good (the same acceptance and the same error, naming the first
bad entry, as the entry-by-entry check), and Ctrl-C of a long run still returning the samples reached
within 1024 steps. Units SI: l [m], g [m/s²], c [1/s], t [s].
"""

from __future__ import annotations

import importlib
import math
import os
import re
import signal
import threading
import time
from typing import Any

import numpy as np
import pytest

import pendulab as pl
from pendulab import validate as limits
from pendulab._core import EnsembleRun, EnsembleSpec, RunOptions


def _rows(n: int, lengths: np.ndarray) -> np.ndarray:
    """n starts (x, v) on the spheres of radius ``lengths`` (v ⟂ x)."""
    unit = pl.states_from_angles(pl.Pendulum(), theta=np.linspace(0.2, 2.6, n), phi_dot=0.8)
    return unit * lengths[:, None]


def test_spec_copies_its_arrays_once_and_every_run_shares_them() -> None:
    """Two runs of one spec, made from a strided length array, give simulate_ensemble's bits after the
    arrays it was made from were overwritten; trajectory k equals simulate() of its own pendulum."""
    n, dt, steps = 70, 1e-3, 400
    lengths = np.linspace(0.5, 2.0, n)
    g = np.linspace(3.7, 24.8, n)
    c = np.linspace(0.0, 0.6, n)
    rows = _rows(n, lengths)
    kw = {"dt": dt, "save_every": 100, "settle_angle": 0.3, "arithmetic": "unfused", "progress": False}
    ref = pl.simulate_ensemble(pl.Pendulum(), rows, steps * dt, length=lengths, g=g, damping=c, **kw)
    wide = np.zeros(2 * n)
    wide[::2] = lengths
    spec = EnsembleSpec(wide[::2], g.copy(), c.copy())
    wide[:] = 7.0  # after the spec was made: no run sees it
    x, v = np.ascontiguousarray(rows[:, :3]), np.ascontiguousarray(rows[:, 3:])
    options = RunOptions(dt=dt, save_every=100, arithmetic="unfused")
    for _ in range(2):
        out = EnsembleRun(spec, x, v, options, steps, True, 0.3).result()
        assert out["x"].shape == (n, 5, 3) and out["x"].flags.c_contiguous
        assert np.array_equal(out["x"], ref.x) and np.array_equal(out["v"], ref.v)
        assert np.array_equal(out["t"], ref.t) and np.array_equal(out["settle_time"], ref.settle_time)
        assert ref.summary is not None
        for key in ("z_min", "z_max", "e_min", "e_max", "j3_min", "j3_max", "crossings"):
            assert np.array_equal(out[key], ref.summary[key]), key
    for k in (0, 41, n - 1):
        p = pl.Pendulum(length=lengths[k], g=g[k], damping=c[k])
        s0 = p.state(rows[k, :3], rows[k, 3:])
        tr = pl.simulate(p, s0, steps * dt, method="rattle", dt=dt, save_every=100, arithmetic="unfused")
        assert np.array_equal(tr.x, ref.x[k]) and np.array_equal(tr.v, ref.v[k])


def test_a_run_above_the_free_later_size_gives_the_same_bits() -> None:
    """The core's buffers of a run are freed after the hand-over up to 64 MiB, before it above (so a
    next run never overlaps them by more): 4096 starts saved at every one of 350 steps (69 MB of
    states) give the rows of a 64-start run (freed later) bit for bit, with their summaries."""
    n, steps, dt = 4096, 350, 1e-3
    lengths = np.linspace(0.8, 1.2, n)
    rows = _rows(n, lengths)
    kw = {"dt": dt, "save_every": 1, "length": lengths, "progress": False}
    big = pl.simulate_ensemble(pl.Pendulum(), rows, steps * dt, **kw)
    assert big.x.shape == (n, steps + 1, 3) and big.x.nbytes * 2 > 2**26
    pick = np.arange(0, n, 64)
    kw["length"] = lengths[pick]
    small = pl.simulate_ensemble(pl.Pendulum(), rows[pick], steps * dt, **kw)
    assert np.array_equal(big.x[pick], small.x) and np.array_equal(big.v[pick], small.v)
    assert big.summary is not None and small.summary is not None
    assert np.array_equal(big.summary["e_max"][pick], small.summary["e_max"])


def _first_bad(a: np.ndarray, lo: float, hi: float) -> tuple[int, ...] | None:
    """The first entry of ``a`` (C order) that is not a finite number in [lo, hi], by definition."""
    bad = ~(np.isfinite(a) & (a >= lo) & (a <= hi))
    return tuple(int(i) for i in np.unravel_index(int(np.argmax(bad)), a.shape)) if bad.any() else None


@pytest.mark.parametrize("limit", ["length", "g", "unbounded"])
def test_array_check_accepts_and_names_exactly_as_entry_by_entry(limit: str) -> None:
    """Random arrays (1-d, 2-d, 0-d) with NaN, ±inf, values one ulp outside the range and values on
    its ends: ``validate.array`` accepts exactly the arrays whose every entry is a finite number in
    the range, returns them unchanged, and names the first bad entry with its index."""
    spec = (
        limits.spec("unbounded", "", -math.inf, math.inf, "any finite number")
        if limit == "unbounded"
        else limits.COMMON[limit]
    )
    lo, hi = spec["min"], spec["max"]
    span_lo, span_hi = max(lo, -1e6), min(hi, 1e6)
    rng = np.random.default_rng(29)
    edges = [np.nan, np.inf, -np.inf, np.nextafter(hi, np.inf), np.nextafter(lo, -np.inf), lo, hi]
    accepted = refused = 0
    for trial in range(300):
        rows, cols = (int(k) for k in rng.integers(1, 6, size=2))
        shape = [(int(rng.integers(1, 40)),), (rows, cols), ()][trial % 3]
        a = rng.uniform(span_lo, span_hi, size=shape)
        for _ in range(int(rng.integers(0, 3))):
            a[tuple(int(rng.integers(0, s)) for s in a.shape)] = edges[int(rng.integers(0, len(edges)))]
        first = _first_bad(a, lo, hi)
        if first is None:
            out = limits.array("w", a, spec)
            assert np.array_equal(out, a) and out.dtype == np.float64
            accepted += 1
        else:
            where = "".join(f"[{i}]" for i in first)
            with pytest.raises(pl.InvalidInputError, match=re.escape(f"invalid w{where} = ")):
                limits.array("w", a, spec)
            refused += 1
    assert accepted > 50 and refused > 50  # both outcomes exercised


class _InterruptedWhileWaiting:
    """An ``EnsembleRun`` that sends this process SIGINT 0.2 s after Python first waits on it, so that
    the signal lands in the progress loop (where Ctrl-C is handled) however loaded the machine is."""

    def __init__(self, *args: Any) -> None:
        self.run = EnsembleRun(*args)
        self.timer: threading.Timer | None = None

    @property
    def progress(self) -> float:
        return float(self.run.progress)

    def wait(self, timeout: float) -> bool:
        if self.timer is None:
            self.timer = threading.Timer(0.2, lambda: os.kill(os.getpid(), signal.SIGINT))
            self.timer.start()
        return bool(self.run.wait(timeout))

    def cancel(self) -> None:
        self.run.cancel()

    def result(self) -> dict[str, Any]:
        return dict(self.run.result())


def test_ctrl_c_stops_a_long_run_with_the_samples_reached(
    pendulum: pl.Pendulum, monkeypatch: pytest.MonkeyPatch
) -> None:
    """SIGINT during a long run (on the pool, polled by Python): it stops within 1024 steps, warns,
    is flagged interrupted, and keeps the samples every trajectory reached, each equal to simulate()."""
    states = pl.states_from_angles(pendulum, theta=np.linspace(0.2, 2.9, 1024), phi_dot=1.0)
    dt, every, total = 1e-3, 10_000, 2_000_000
    monkeypatch.setattr(
        importlib.import_module("pendulab.ensemble.run"), "EnsembleRun", _InterruptedWhileWaiting
    )
    t0 = time.perf_counter()
    with pytest.warns(RuntimeWarning, match="interrupted") as said:
        res = pl.simulate_ensemble(pendulum, states, total * dt, dt=dt, save_every=every, progress=False)
    assert [w.filename for w in said] == [__file__]  # the caller's line
    assert time.perf_counter() - t0 < 60.0  # 2·10⁹ trajectory-steps would take far longer
    assert res.interrupted and res.steps < total
    assert len(res.t) == 1 + res.steps // every and np.all(np.isfinite(res.x))
    k = 777
    s0 = pendulum.state(states[k, :3], states[k, 3:])
    if len(res.t) > 1:
        tr = pl.simulate(pendulum, s0, res.t[-1], method="rattle", dt=dt, save_every=every)
        assert np.array_equal(tr.x, res.x[k]) and np.array_equal(tr.v, res.v[k])
    else:  # stopped before the first sample: the start is kept
        assert np.array_equal(res.x[k, 0], states[k, :3])
