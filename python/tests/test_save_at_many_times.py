"""A run saving at many times costs O(steps + times): the core's ``Solver::advance`` reads its save
times in place. It cloned the whole list on every pass, O(n²): 50 k ``save_at`` times took 2.2 s,
100 k with ``rk4`` 10 s (so 400 k two to three minutes), and the error estimate of a 457 k-step
unprojected DOP853 run, whose companion saves at the plain run's 457 k times, 75 s.

The guards are ratios measured in the same test, not wall-clock bounds: the cost per saved sample of a
run with about 4× the samples of a smaller one, best of three runs each. Linear work keeps it near 1;
the quadratic pass made it about 4 (the number of samples' ratio). SI units: l = 1 m; t [s].
"""

from __future__ import annotations

import time
import warnings
from collections.abc import Callable

import numpy as np
import pytest

import pendulab as pl

ROUNDS = 3
# cost per sample at ~4x the samples over cost per sample at 1x: ~1 when linear, ~4 when quadratic
MOST_PER_SAMPLE_RATIO = 2.0


def _best_seconds_per_sample(run: Callable[[], pl.Trajectory]) -> float:
    """The least wall time per saved sample [s] of ``ROUNDS`` calls of ``run``."""
    best = np.inf
    for _ in range(ROUNDS):
        start = time.perf_counter()
        tr = run()
        best = min(best, (time.perf_counter() - start) / len(tr))
    return float(best)


@pytest.mark.parametrize("method", ["dop853", "rk4"])
def test_the_cost_of_save_times_is_linear_in_their_number(method: str) -> None:
    """100 001 and 400 001 save times over 1 s (the fixed steps shortened onto each, DOP853 by dense
    output): the samples are exactly the times asked for, and 4× the times cost 4× as much, not 16×."""
    p = pl.Pendulum()
    s0 = p.state_from_angles(theta=1.0, phi_dot=1.0)
    dt = None if method == "dop853" else 1e-3

    def saving(n: int) -> Callable[[], pl.Trajectory]:
        save = np.linspace(0.0, 1.0, n)

        def run() -> pl.Trajectory:
            tr = pl.simulate(p, s0, 1.0, method=method, dt=dt, save_at=save)
            assert np.array_equal(tr.t, save)
            return tr

        return run

    small, large = _best_seconds_per_sample(saving(100_001)), _best_seconds_per_sample(saving(400_001))
    assert large / small < MOST_PER_SAMPLE_RATIO, f"{large:.3g} s against {small:.3g} s per sample"


def test_the_error_estimate_of_a_long_unprojected_dop853_run_is_linear_in_its_samples() -> None:
    """The slow case (g = 1e4 m/s², from 1e-3 rad below the top, φ̇₀ = 0.5 rad/s, unprojected: it
    leaves the rod, ``drift="warn"``) to 0.6 s (~35 k samples) and to 0.8 s (over 100 k): each step is
    a sample the companion saves at too, and the cost per sample does not grow with their number."""
    p = pl.Pendulum(g=1e4)
    s0 = p.state_from_angles(theta=np.pi - 1e-3, phi_dot=0.5)

    def until(t_end: float) -> Callable[[], pl.Trajectory]:
        def run() -> pl.Trajectory:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", RuntimeWarning)  # the drift, as drift="warn" asks
                tr = pl.simulate(
                    p, s0, t_end, method="dop853", project=False, rtol=1e-6, atol=1e-6,
                    drift="warn", error_estimate=True,
                )  # fmt: skip
            assert tr.error_estimate is not None
            assert tr.error_estimate.reference["rtol"] == pytest.approx(1e-7)
            return tr

        return run

    fewer, more = len(until(0.6)()), len(until(0.8)())
    assert more > 4 * fewer and more > 100_000
    small, large = _best_seconds_per_sample(until(0.6)), _best_seconds_per_sample(until(0.8))
    assert large / small < MOST_PER_SAMPLE_RATIO, f"{large:.3g} s against {small:.3g} s per sample"
