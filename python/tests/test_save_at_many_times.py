"""A run saving at many times costs O(steps + times): the core's ``Solver::advance`` reads its save
times in place. It cloned the whole list on every pass, O(n²): 50 k ``save_at`` times took 2.2 s,
100 k with ``rk4`` 10 s (so 400 k two to three minutes), and the error estimate of a 457 k-step
unprojected DOP853 run, whose companion saves at the plain run's 457 k times, 75 s. SI units: l = 1 m;
t [s].
"""

from __future__ import annotations

import time
import warnings

import numpy as np
import pytest

import pendulab as pl


@pytest.mark.parametrize("method", ["dop853", "rk4"])
def test_four_hundred_thousand_save_times_take_a_fraction_of_a_second(method: str) -> None:
    """400 001 save times over 1 s (the fixed steps shortened onto each, DOP853 by dense output): the
    samples are exactly the times asked for, in a fraction of a second (minutes before)."""
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=1.0, phi_dot=1.0)
    save = np.linspace(0.0, 1.0, 400_001)
    start = time.perf_counter()
    tr = pl.simulate(p, s0, 1.0, method=method, dt=None if method == "dop853" else 1e-3, save_at=save)
    elapsed = time.perf_counter() - start
    assert np.array_equal(tr.t, save)
    assert elapsed < 10.0, f"{elapsed:.2f} s for 400 001 save times"  # minutes before


def test_the_error_estimate_of_a_long_unprojected_dop853_run_is_linear_in_its_samples() -> None:
    """The slow case to 0.8 s (g = 1e4 m/s², from 1e-3 rad below the top, φ̇₀ = 0.5 rad/s,
    unprojected: it leaves the rod, ``drift="warn"``): over 100 k steps, each a sample the companion
    saves at too."""
    p = pl.Pendulum(g=1e4)
    s0 = p.state_from_angles(theta=np.pi - 1e-3, phi_dot=0.5)
    start = time.perf_counter()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", RuntimeWarning)  # the drift, as drift="warn" asks
        tr = pl.simulate(
            p,
            s0,
            0.8,
            method="dop853",
            project=False,
            rtol=1e-6,
            atol=1e-6,
            drift="warn",
            error_estimate=True,
        )
    elapsed = time.perf_counter() - start
    assert tr.error_estimate is not None and len(tr) > 100_000
    assert tr.error_estimate.reference["rtol"] == pytest.approx(1e-7)
    assert elapsed < 10.0, f"{elapsed:.2f} s for {len(tr)} samples"  # 30 s or more before
