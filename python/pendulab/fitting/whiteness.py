"""Tests that a residual series is white noise (goodness.py reads them per data kind; docs/fit.md,
"Noise and goodness of fit").

- the autocorrelations ρ_k and the Ljung–Box statistic Q = n(n+2) Σ_{k=1}^{h} ρ_k²/(n−k), χ²(h) for
  white residuals (Ljung & Box 1978, Biometrika 65:297);
- the Wald–Wolfowitz runs test of the residual's signs, z = (R − μ)/s with μ = 2n₊n₋/n + 1,
  s² = (μ−1)(μ−2)/(n−1);
- the band scan: a misfit too small to correlate neighbouring samples (a wrong damping law fitted to a
  long record leaves a residual of a fraction of the noise) is still a coherent oscillation near the
  swing's frequency, with its power in a few Fourier frequencies. The periodogram I_j = |Σ r_t
  e^{−2πijt/n}|²/n, j = 1 … ⌊(n−1)/2⌋, of white Gaussian noise has independent exponential ordinates,
  so the mean over a band of BAND of them against the mean of all the others is F(2·BAND, 2(m − BAND))
  distributed; the bands tiling the periodogram at two offsets (0 and BAND/2) are each tested and the
  smallest p-value is multiplied by their number (Bonferroni), so that for white residuals the scan
  alarms no more often than one test. A sinusoid at 0.55 Hz in n = 1500 samples 0.02 s apart of
  unit white noise, of energy E = Σ s_t², is found at p < 1e-4 half the time at E/σ² ≈ 47 (by
  Ljung–Box with 20 lags at ≈ 70; by χ², σ given, at ≈ 3.7 √(2n) ≈ 200), 90 % of the time at 68
  (Ljung–Box 42 %; 300 random phases each). The samples are taken as equally spaced (gaps only
  blur the band).
- χ² with σ given, for residuals that are AR(1) noise of lag-1 autocorrelation ρ: their sum of squares
  has the variance 2nσ⁴(1 + ρ²)/(1 − ρ²) (Bartlett 1946), not 2nσ⁴, so χ² is compared as χ²·f with
  χ²(dof·f), f = (1 − ρ²)/(1 + ρ²): the same mean, that variance (ρ = 0.8: a spread √4.6 ≈ 2.1x
  that of white noise's; the plain χ² test called the true σ too large in 11 of 150 fits of
  bench/fit_validate.py's case 8, this one in none).
Units: those of the series; frequencies in Hz.
"""

from __future__ import annotations

import math

import numpy as np

from ..model import FloatArray

#: Fourier frequencies per band of the band scan: a misfit's envelope over the record spreads its
#: power over a few of them around the swing's frequency.
BAND = 8


def autocorrelations(x: FloatArray, lags: int) -> FloatArray:
    """ρ_1 … ρ_lags of a series about its mean (0 for a constant series)."""
    y = np.asarray(x, dtype=np.float64) - float(np.mean(x))
    c0 = float(y @ y)
    if c0 <= 0.0:
        return np.zeros(lags)
    return np.array([float(y[:-k] @ y[k:]) / c0 for k in range(1, lags + 1)])


def ljung_box(x: FloatArray, lags: int) -> tuple[float, float]:
    """The Ljung–Box Q of the first ``lags`` autocorrelations and its χ²(lags) p-value."""
    n = len(x)
    h = max(1, min(lags, n // 5))
    rho = autocorrelations(x, h)
    q = float(n * (n + 2) * np.sum(rho**2 / (n - np.arange(1, h + 1))))
    from scipy import stats  # SciPy is imported on first use (the `fit` extra)

    return q, float(stats.chi2.sf(q, h))


def runs_z(x: FloatArray) -> float:
    """The Wald–Wolfowitz runs test z of the signs of ``x`` (0 when it cannot be formed)."""
    s = np.asarray(x) > 0.0
    n_pos = int(np.count_nonzero(s))
    n = len(s)
    n_neg = n - n_pos
    if n_pos == 0 or n_neg == 0 or n < 3:
        return 0.0
    runs = 1 + int(np.count_nonzero(s[1:] != s[:-1]))
    mu = 2.0 * n_pos * n_neg / n + 1.0
    var = (mu - 1.0) * (mu - 2.0) / (n - 1.0)
    return (runs - mu) / math.sqrt(var) if var > 0.0 else 0.0


def band_scan(x: FloatArray, dt: float, band: int = BAND) -> tuple[float, float, float]:
    """The band scan of the module doc: (its Bonferroni p-value, the centre frequency [Hz] of the
    band with the smallest p for samples ``dt`` [s] apart (0 for dt = 0), that band's mean power in
    units of the rest's). (1, 0, 1) for a record of fewer than 4 bands or a constant series."""
    y = np.asarray(x, dtype=np.float64)
    n = len(y)
    m = (n - 1) // 2
    if m < 4 * band:
        return 1.0, 0.0, 1.0
    power = (np.abs(np.fft.rfft(y - float(np.mean(y)))) ** 2)[1 : m + 1]
    total = float(np.sum(power))
    if not total > 0.0:
        return 1.0, 0.0, 1.0
    cumulative = np.concatenate(([0.0], np.cumsum(power)))
    starts = np.concatenate([np.arange(offset, m - band + 1, band) for offset in (0, band // 2)])
    inside = (cumulative[starts + band] - cumulative[starts]) / band
    outside = (total - inside * band) / (m - band)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = np.where(outside > 0.0, inside / outside, np.inf)
    from scipy import stats

    p = stats.f.sf(ratio, 2 * band, 2 * (m - band))
    i = int(np.argmin(p))
    centre = (starts[i] + 1 + (band - 1) / 2.0) / (n * dt) if dt > 0.0 else 0.0
    return float(min(1.0, p[i] * starts.size)), float(centre), float(ratio[i])


def chi2_tails(chi2: float, dof: int, rho: float = 0.0) -> tuple[float, float]:
    """P(χ² ≥ ``chi2``) and P(χ² ≤ ``chi2``) for ``dof`` degrees of freedom, for residuals that are
    AR(1) noise of lag-1 autocorrelation ``rho`` (0 or less: white; the module doc)."""
    f = (1.0 - rho * rho) / (1.0 + rho * rho) if 0.0 < rho < 1.0 else 1.0
    from scipy import stats

    return float(stats.chi2.sf(chi2 * f, dof * f)), float(stats.chi2.cdf(chi2 * f, dof * f))
