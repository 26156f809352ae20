"""Error bars under AR(1) measurement noise with a right model (goodness.py, prewhitened_newey_west;
docs/fit.md, "Correlated noise with a right model, measured"): a camera's x, z of an elliptical swing,
its pivot fitted too, with AR(1) noise of ρ = 0.8 (bench/fit_validate.py case 8; data from the
independent SciPy integrator ``testdata/generate/independent_pendulum.py``, no Pendulab code). The
largest widening AR(1) noise can call for is √((1 + ρ)/(1 − ρ)) = 3; recolouring each score by its
own AR(1) coefficient widened length, g and the pivot's height by 10 to 29 (their errors' spread
was 0.2 of their error bars), one coefficient for all by 2.7 to 3.4. SI units."""

from __future__ import annotations

import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import pendulab as pl

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "testdata" / "generate"))
import independent_pendulum as ip

TRUTH = ip.Truth(length=0.6, g=9.81, damping=0.010)
T = 1.3 + np.arange(0.0, 15.0, 1.0 / 30.0)


@pytest.mark.parametrize("seed", [0, 2])
def test_ar1_noise_widens_the_error_bars_by_what_it_can(seed: int) -> None:
    x, _, _, _ = ip.simulate(TRUTH, ip.start_state(TRUTH, 0.5, 0.0, 0.0, 0.8), T)
    pos = ip.measure_positions(
        x, np.random.default_rng([7, seed + 1]), 1.5e-3, (0.31, 0.0, 1.25), (0, 2), 1.0, 0.8
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(
            T, positions=pos, pendulum=pl.Pendulum(model="damped"), fit=["length", "g", "damping", "pivot"]
        )
    said = [str(w.message) for w in caught]
    assert any("the residual is correlated noise" in s for s in said), said
    for name in ("length", "g", "damping", "pivot_x", "pivot_z"):
        assert 1.5 < res.goodness.inflation[name] < 4.5, (name, res.goodness.inflation)
    assert abs(res.params["g"] - 9.81) < 3.0 * res.stderr["g"]
