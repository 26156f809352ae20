"""The statistics of the block check (blocks.py): the Particle Data Group's scale factor of the blocks'
estimates and the probability of their scatter for blocks that agree, the weighted trend of the damping
over the blocks, and the residual's lag-1 autocorrelation as the whole fit reads it. Units: those of the
estimates."""

from __future__ import annotations

import math

import numpy as np

from ..model import FloatArray
from .goodness import mean_lag1

#: ... and the share of the blocks' weighted scatter a trend must explain (R²; 4 blocks without a
#: trend reach it by chance with p = 1 − √0.8 ≈ 0.11).
TREND_SHARE = 0.8


def trend_z(values: FloatArray, errors: FloatArray) -> float:
    """The weighted least-squares slope of ``values`` ± ``errors`` against their index in units of its
    standard error; 0 unless there are at least three, all finite, and the line explains at least
    TREND_SHARE of their weighted scatter (a steady change, not one odd block)."""
    if values.size < 3 or not (np.all(np.isfinite(values)) and np.all(np.isfinite(errors) & (errors > 0.0))):
        return 0.0
    w = 1.0 / errors**2
    x = np.arange(values.size, dtype=np.float64)
    x = x - float(np.sum(w * x) / np.sum(w))
    y = values - float(np.sum(w * values) / np.sum(w))
    sxx, sxy, syy = float(np.sum(w * x * x)), float(np.sum(w * x * y)), float(np.sum(w * y * y))
    if not (syy > 0.0 and sxy * sxy >= TREND_SHARE * sxx * syy):
        return 0.0
    return sxy / math.sqrt(sxx)


def lag1_of(r: FloatArray, columns: dict[str, int], kinds: list[str]) -> float:
    """The largest over kinds of :func:`goodness.mean_lag1` of a kind's residual (``r`` holds each
    kind's (N, columns) residual, raveled, one kind after another), as the whole fit's check reads it."""
    out, at = 0.0, 0
    n = r.size // max(sum(columns[k] for k in kinds), 1)
    for k in kinds:
        part = r[at : at + n * columns[k]].reshape(n, columns[k])
        at += part.size
        if n > 2:
            out = max(out, mean_lag1(part))
    return out


def _chi2(values: FloatArray, errors: FloatArray) -> tuple[float, int]:
    """χ² of the estimates ``values`` ± ``errors`` about their weighted mean and their number N, over
    those with an error < 3√N σ̄ (module doc; a value that determines nothing is left out too)."""
    ok = np.isfinite(values) & np.isfinite(errors) & (errors > 0.0)
    x, e = values[ok], errors[ok]
    if x.size < 2:
        return 0.0, int(x.size)
    mean_err = 1.0 / math.sqrt(float(np.sum(1.0 / e**2)))
    keep = e < 3.0 * math.sqrt(x.size) * mean_err
    x, e = x[keep], e[keep]
    if x.size < 2:
        return 0.0, int(x.size)
    w = 1.0 / e**2
    mean = float(np.sum(w * x) / np.sum(w))
    return float(np.sum(w * (x - mean) ** 2)), int(x.size)


def scale_factor(values: FloatArray, errors: FloatArray) -> float:
    """The Particle Data Group's S = √(χ²/(N − 1)) of the estimates ``values`` ± ``errors`` (module
    doc; those with an error ≥ 3√N σ̄ left out, at least 1; 1 with fewer than two usable)."""
    chi2, n = _chi2(values, errors)
    return max(1.0, math.sqrt(chi2 / (n - 1))) if n >= 2 else 1.0


def disagreement_p(values: FloatArray, errors: FloatArray) -> float:
    """The probability of a scatter at least as large among estimates that agree: the χ²(N − 1) tail
    of :func:`scale_factor`'s χ² (1 with fewer than two usable)."""
    chi2, n = _chi2(values, errors)
    from scipy import stats

    return float(stats.chi2.sf(chi2, n - 1)) if n >= 2 else 1.0
