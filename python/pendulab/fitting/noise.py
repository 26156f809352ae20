"""The noise floor of measured data, read off the data before any model is fitted (docs/fit.md,
"Noise and goodness of fit").

A smooth signal sampled densely has tiny high-order differences: the k-th difference of s(t) sampled
every Δt is about (ωΔt)ᵏ times its amplitude, while that of white noise of standard deviation σ has
the standard deviation σ·√C(2k, k) (the sum of the squared binomial coefficients). The floor is the
smallest of the robust estimates median|Δᵏs| / (0.6745 √C(2k, k)) over k = 2 … 6 (0.6745 turns a median
absolute deviation into a standard deviation): the signal's share falls with k, the noise's does not.
Values on a lattice of step q (an encoder, a digitised video, a rounded log) carry at least the
quantisation noise q/√12 (uniform rounding error), which the floor never goes below.

The floor sets the scale of the fit's search when σ is not given (estimator.py), so that the search
does not depend on the units of the data, and the goodness-of-fit check compares the residual with it
(goodness.py). Units: those of each data kind (m, rad, m/s², rad/s).
"""

from __future__ import annotations

import math

import numpy as np

from ..model import FloatArray

ORDERS = (2, 3, 4, 5, 6)
"""Orders k of the differences whose robust spread estimates the noise."""

MAD = 0.6745
"""The median absolute deviation of a unit normal variable."""

LATTICE_TOLERANCE = 1e-3
"""How far (in steps q) a level may lie from its lattice point: decimal rounding of stored values."""


def noise_level(t: FloatArray, s: FloatArray) -> float:
    """The white-noise σ of a smooth signal ``s`` sampled densely at times ``t`` (module doc), in
    the unit of ``s``; 0.0 for fewer than 8 samples or a constant signal."""
    y = np.asarray(s, dtype=np.float64)
    if len(y) < 8:
        return 0.0
    best = math.inf
    d = y
    for k in range(1, max(ORDERS) + 1):
        d = np.diff(d)
        if k in ORDERS and len(d) >= 4:
            best = min(best, float(np.median(np.abs(d))) / (MAD * math.sqrt(math.comb(2 * k, k))))
    return 0.0 if not math.isfinite(best) else best


def quantum(s: FloatArray) -> float:
    """The step q of the lattice the values lie on (an encoder's count, rounded digits), or 0.0 when
    they do not. The smallest gap between distinct values numbers the levels, n_i = round(Δ_i/gap);
    q is the least-squares slope of the levels against n_i, so that values stored with few decimals
    (an encoder's π − k q written to 8 digits: gaps of 1.5707e-4 and 1.5708e-4) still give their step.
    Accepted when at least 8 levels are each within LATTICE_TOLERANCE q of a multiple of q: values off
    any lattice lie up to q/2 from it, so continuous data pass with a chance of (2e-3)^6 at most."""
    y = np.asarray(s, dtype=np.float64).ravel()
    levels = np.unique(y)
    if len(levels) < 8:
        return 0.0
    gap = float(np.min(np.diff(levels)))
    if not gap > 0.0:
        return 0.0
    offset = levels - levels[0]
    n = np.round(offset / gap)
    if float(np.max(n)) > 1e9:
        return 0.0
    q = float(n @ offset) / float(n @ n)
    if not q > 0.0 or np.max(np.abs(offset - n * q)) > LATTICE_TOLERANCE * q:
        return 0.0
    return q


def floor_of(t: FloatArray, values: FloatArray) -> float:
    """The noise floor of one data kind (N, columns) [its unit]: the root mean square over its
    columns of max(noise_level, quantum/√12)."""
    a = np.asarray(values, dtype=np.float64)
    if a.ndim == 1:
        a = a[:, None]
    per = []
    for j in range(a.shape[1]):
        col = a[:, j]
        per.append(max(noise_level(t, col), quantum(col) / math.sqrt(12.0)))
    return float(math.sqrt(sum(p * p for p in per) / len(per))) if per else 0.0


def columns_for_noise(kind: str, values: FloatArray) -> FloatArray:
    """Smooth columns of a data kind whose noise is the residual's: angles as the unit vector
    (sin θ cos φ, sin θ sin φ, −cos θ) scaled by √(3/2) (its three components share the noise of θ and
    of the arc sin θ·φ, which the residual's two columns carry; φ itself jumps near the pole), a
    planar angle unwrapped; other kinds as they are."""
    if kind == "angles":
        theta, phi = values[:, 0], values[:, 1]
        unit = np.column_stack([np.sin(theta) * np.cos(phi), np.sin(theta) * np.sin(phi), -np.cos(theta)])
        return math.sqrt(1.5) * unit
    if kind == "planar_angle":
        return np.unwrap(values[:, 0])[:, None]
    return values


def spread_of(values: FloatArray) -> float:
    """The data's own spread [unit]: the root mean square over columns of their standard deviations
    (what a model must explain beyond a constant)."""
    a = np.asarray(values, dtype=np.float64)
    if a.ndim == 1:
        a = a[:, None]
    return float(math.sqrt(float(np.mean(np.var(a, axis=0)))))
