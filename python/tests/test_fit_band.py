"""The band scan of the goodness of fit (fitting/whiteness.py, goodness.py; docs/fit.md, "Noise and
goodness of fit"): a misfit smaller than the noise — dry (Coulomb) friction fitted as viscous damping
— is warned, and a right model is not. The encoder data come from the independent SciPy integrator
(``testdata/generate/independent_pendulum.py``, no Pendulab code). SI units (m, s, rad, m/s²)."""

from __future__ import annotations

import dataclasses
import sys
import warnings
from pathlib import Path

import numpy as np

import pendulab as pl
from pendulab.fitting import goodness
from pendulab.fitting.blocks import BlockCheck
from pendulab.fitting.whiteness import band_scan, ljung_box

sys.path.insert(0, str(Path(__file__).resolve().parents[2] / "testdata" / "generate"))
import independent_pendulum as ip

T = np.arange(0.0, 30.0, 0.02)


def _encoder_fit(truth: ip.Truth, seed: int) -> tuple[pl.FitResult, list[str]]:
    """A planar swing from 0.9 rad (θ̇ −0.5 rad/s), 30 s at 50 Hz, read by an encoder with 3 mrad of
    white noise, fitted with viscous damping (length and damping free, g held at 9.81)."""
    x, _, _, _ = ip.simulate(truth, ip.start_state(truth, 0.9, 0.0, -0.5), T)
    angle = ip.measure_encoder(x, np.random.default_rng(seed), sigma=0.003)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = pl.fit(
            T, planar_angle=angle, pendulum=pl.Pendulum(model="damped", g=9.81), fit=["length", "damping"]
        )
    return res, [str(w.message) for w in caught]


def test_dry_friction_fitted_as_viscous_damping_is_warned() -> None:
    """μ = 0.02 m/s² of pivot friction: the residual (at the noise floor, lag-1 autocorrelation ~0.06)
    passes Ljung–Box and the runs test in this seed, so only the band scan sees the swing's frequency
    in it; the length is biased by about 2 of its unwidened error bars."""
    res, said = _encoder_fit(ip.Truth(length=0.8, coulomb=0.02), seed=3)
    assert res.goodness is not None
    check = res.goodness.kinds["planar_angle"]
    old = dataclasses.replace(check, band_p=1.0, whitened_band_p=1.0)
    assert not goodness.findings({"planar_angle": old}, res.goodness.chi2_p, res.chi2, res.dof)
    assert check.band_p < 1e-6 and abs(check.band_hz - 0.55) < 0.05, check
    assert any("planar_angle: the residual is correlated" in m and "0.55 Hz" in m for m in said), said
    assert any("'friction'" in m for m in said), said
    # the blocks' damping rises as the swing dies down: the hint names dry friction
    assert res.blocks is not None
    assert any("rises as the swing dies down" in m and "dry friction" in m for m in said), said


def test_viscous_damping_fitted_as_viscous_damping_is_not_warned() -> None:
    res, said = _encoder_fit(ip.Truth(length=0.8, damping=0.03), seed=3)
    assert not said, said
    assert res.goodness is not None
    assert res.goodness.kinds["planar_angle"].band_p > 0.01
    assert abs(res.params["length"] - 0.8) < 3.0 * res.stderr["length"]


def test_the_band_scan_sees_a_weak_oscillation_that_ljung_box_does_not() -> None:
    """White noise: the scan's p-value is uniform (Bonferroni, conservative), so over 200 series at most
    a few fall below 0.01. Plus a sinusoid of 0.3 σ at 0.55 Hz (E/σ² = 68 over 1500 samples): the
    scan finds it at its frequency, the Ljung–Box test of 20 lags does not."""
    rng = np.random.default_rng(12)
    low = sum(band_scan(rng.standard_normal(1500), 0.02)[0] < 0.01 for _ in range(200))
    assert low <= 6, low
    noise = rng.standard_normal(1500)
    signal = 0.3 * np.sin(2.0 * np.pi * 0.55 * T)
    p, hz, ratio = band_scan(noise + signal, 0.02)
    assert p < 1e-4 and abs(hz - 0.55) < 0.1 and ratio > 3.0, (p, hz, ratio)
    assert ljung_box(noise + signal, 20)[1] > 1e-4
    assert band_scan(np.zeros(1500), 0.02) == (1.0, 0.0, 1.0)
    assert band_scan(rng.standard_normal(40), 0.02)[0] == 1.0  # too short for four bands


def test_the_blocks_name_a_damping_law_only_for_a_steady_trend() -> None:
    """Damping rising block after block (dry friction's c ∝ 1/amplitude), falling (drag's c ∝
    amplitude), and one odd block among equal ones (no trend: no hint)."""

    def said(damping: list[float]) -> str:
        check = BlockCheck(
            starts=[0.0, 7.5, 15.0, 22.5],
            values={"damping": damping},
            stderr={"damping": [1e-4] * 4},
            scale={"damping": 5.0},
            units={"damping": "1/s"},
        )
        return " ".join(check.findings())

    assert "dry friction" in said([0.0104, 0.0108, 0.0115, 0.0117])
    assert "air drag" in said([0.0117, 0.0115, 0.0108, 0.0104])
    odd = said([0.0110, 0.0110, 0.0125, 0.0110])
    assert "disagree" in odd and "dry friction" not in odd and "air drag" not in odd
    # the hint is a sentence of its own (was "...; res.blocks) The damping fitted...")
    for trend in ([0.0104, 0.0108, 0.0115, 0.0117], [0.0117, 0.0115, 0.0108, 0.0104]):
        assert "; res.blocks). The damping fitted to the blocks " in said(trend), said(trend)
    assert odd.endswith("; res.blocks)"), odd
