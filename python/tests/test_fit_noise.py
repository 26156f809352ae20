"""The noise floor and the start read off the data before a fit (fitting/noise.py, fitting/start.py;
docs/fit.md "Noise and goodness of fit"): an encoder's step from values stored with few decimals, a
record that stops dead, a running median that keeps a record's first samples, and outliers told from
a misfit's smooth run (fitting/goodness.py). SI units (rad, s)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pendulab.fitting.goodness import check_kind
from pendulab.fitting.noise import floor_of, quantum
from pendulab.fitting.start import despiked, running_median

REAL = Path(__file__).resolve().parents[2] / "testdata" / "real"


def test_an_encoder_stored_to_eight_decimals_gives_its_step() -> None:
    """θ = k·2π/40000 − π written with 8 decimals: gaps of 1.5707e-4 and 1.5708e-4 rad."""
    q = 2.0 * math.pi / 40000.0
    k = np.round(2000.0 * np.sin(np.linspace(0.0, 30.0, 3000)))
    stored = np.round(k * q - math.pi, 8)
    assert quantum(stored) == pytest.approx(q, rel=1e-6)
    assert quantum(k * q) == pytest.approx(q, rel=1e-12)


def test_values_off_any_lattice_have_no_step() -> None:
    rng = np.random.default_rng(3)
    for _ in range(20):
        assert quantum(np.sin(np.linspace(0.0, 20.0, 2000)) + 1e-3 * rng.standard_normal(2000)) == 0.0
    assert quantum(np.array([0.0, 1.0, 2.0, 3.0])) == 0.0  # too few levels to tell


def test_a_pendulum_that_stops_dead_keeps_the_quantisation_floor() -> None:
    """The real small decay (testdata/real, 40 000 steps per turn) ends at rest: most differences are
    exactly 0, and the floor is the step/√12, not 1e-18."""
    d = np.loadtxt(REAL / "multiarm_single_small_decay.csv", delimiter=",", comments="#", skiprows=4)
    q = 2.0 * math.pi / 40000.0
    assert quantum(d[:, 1]) == pytest.approx(q, rel=1e-5)
    assert floor_of(d[:, 0], d[:, 1]) == pytest.approx(q / math.sqrt(12.0), rel=1e-5)


def test_the_running_median_keeps_a_monotone_start_and_removes_a_spike() -> None:
    """A record that starts at a crossing (fastest motion, monotone) keeps its first samples exactly;
    an isolated spike inside or at the first sample is replaced."""
    t = np.arange(0.0, 4.0, 0.02)
    s = 0.5 * np.sin(4.4 * t)
    assert np.array_equal(running_median(s)[:15], s[:15])  # the first quarter swing: 18 samples
    spiky = s.copy()
    spiky[100] += 2.0
    assert abs(running_median(spiky)[100] - s[100]) < 0.05
    first = s.copy()
    first[0] += 2.0  # a spike at the very first sample: the start read off the data must not see it
    assert abs(running_median(first)[0] - s[0]) < 0.05
    assert np.array_equal(despiked(s), s)  # no spikes: the data as they are


def test_further_starts_are_skipped_only_at_the_noise_floor() -> None:
    """estimator.at_noise_floor: a result whose χ²/dof (in units of the search's σ, the k anchor
    residuals left out) is at most FLOOR_CHI2 over a record of at least FLOOR_PERIODS of its
    small-swing periods 2π√(l/|g|) ends the search; one above it, over a shorter record, a failed one,
    or a robust loss's does not."""
    from types import SimpleNamespace

    from pendulab.fitting.multistart import FLOOR_CHI2, FLOOR_PERIODS, at_noise_floor

    n, k = 1000, 3
    dof = n - k
    period = 2 * np.pi * np.sqrt(1.0 / 9.81)  # l = 1 m, g = 9.81 m/s²

    def search(
        chi2: float, success: bool = True, loss: str = "linear", span: float = 10.0
    ) -> SimpleNamespace:
        fun = np.zeros(n + k)  # n data residuals and k anchor residuals
        result = SimpleNamespace(success=success, cost=0.5 * chi2, fun=fun, x=np.zeros(k))
        problem = SimpleNamespace(
            with_free=lambda x: {"length": 1.0, "g": 9.81, "damping": 0.0},
            obs=SimpleNamespace(t=np.linspace(2.0, 2.0 + span, n)),
        )
        return SimpleNamespace(result=result, free=["a", "b", "c"], loss=loss, problem=problem)

    assert at_noise_floor(search(FLOOR_CHI2 * dof))
    assert not at_noise_floor(search(1.01 * FLOOR_CHI2 * dof))
    assert not at_noise_floor(search(0.5 * dof, success=False))
    assert not at_noise_floor(search(0.5 * dof, loss="soft_l1"))
    assert not at_noise_floor(SimpleNamespace(result=None, free=["a"], loss="linear"))
    assert at_noise_floor(search(0.5 * dof, span=1.001 * FLOOR_PERIODS * period))
    assert not at_noise_floor(search(0.5 * dof, span=0.999 * FLOOR_PERIODS * period))


def test_outliers_are_isolated_values_not_a_smooth_run_of_a_misfit() -> None:
    """goodness.check_kind: spikes of 20 σ (one at each end, a burst of 3) are outliers; a smooth
    decaying run of 5-8 σ at the record's start (the first swings a wrong damping law misses) is not."""
    rng = np.random.default_rng(7)
    t = np.arange(1500) * 0.02
    r = 1e-3 * rng.standard_normal(t.size)
    run = r.copy()
    run[:10] += 1e-3 * np.linspace(8.0, 5.0, 10)
    assert check_kind(t, run, 1e-3, 0.5).outliers == 0
    spiked = r.copy()
    spiked[[0, 400, 401, 402, 900, 1499]] += 0.02
    assert check_kind(t, spiked, 1e-3, 0.5).outliers == 6
