"""Features of a sampled swing that the fit's starting values are read from (start.py; docs/theory.md
T-10.4):

- the sphere (circle) through the positions by the algebraic fit |p|² = 2 c·p + k (:func:`sphere_fit`:
  the pivot c [m] and the length √(k + |c|²) [m]);
- a running median that removes isolated outliers (spikes of a tracked video) without moving a
  monotone run at the record's ends (:func:`running_median`, :func:`despiked`);
- the period T [s] from the crossings of the signal's mean, with hysteresis against noise
  (:func:`crossings_period`);
- g [m/s²] from energy conservation ½|v|² + g z = E₀ + E₁t (T-2.6; :func:`energy_gravity`), which
  holds for whirls over the top where the period's formula does not;
- the linear damping c [1/s] from the decay of the peaks, A(t) ∝ e^{−ct/2} (T-7.1; :func:`decay_rate`);
- value and rate at the first sample from a quadratic through the first samples (:func:`value_and_rate`).
Units: SI (m, s, rad, m/s²); a signal's value and rate are in its own unit and that unit per second.
"""

from __future__ import annotations

import math

import numpy as np

from ..model import FloatArray
from .noise import noise_level


def sphere_fit(p: FloatArray) -> tuple[FloatArray, float] | None:
    """Centre and radius of the sphere (or circle, for 2 columns) through the points, or None when
    the points do not determine one (too flat)."""
    a = np.column_stack([2.0 * p, np.ones(len(p))])
    b = np.einsum("ij,ij->i", p, p)
    sol, *_ = np.linalg.lstsq(a, b, rcond=None)
    if np.linalg.matrix_rank(a) < a.shape[1]:
        return None
    centre = sol[:-1]
    r2 = sol[-1] + centre @ centre
    if not (np.all(np.isfinite(centre)) and r2 > 0.0):
        return None
    return centre, math.sqrt(r2)


def _robust_line(s: FloatArray) -> tuple[float, float]:
    """(intercept at index 0, slope per sample) of a line through ``s``: the median of the consecutive
    slopes and the median intercept, so that a few spikes among the samples do not move it."""
    slope = float(np.median(np.diff(s)))
    return float(np.median(s - slope * np.arange(len(s)))), slope


def running_median(s: FloatArray, width: int = 5) -> FloatArray:
    """The median of each ``width`` consecutive samples centred on each sample. The ends are padded
    with a robust line through the first (last) 2·``width`` samples, extended outwards: a monotone run
    — a record that starts at a crossing, where the swing is fastest — keeps its first samples
    exactly (padding with the median of the first ``width`` samples moved them by a tenth of a radian:
    bench/fit_validate.py case 3), and a spike at the very first sample is still removed. Removes
    isolated outliers (spikes in a tracked video)."""
    n = len(s)
    if n < 2 * width:
        return s
    half = width // 2
    k = np.arange(1, half + 1, dtype=np.float64)
    a, b = _robust_line(s[: 2 * width])
    c, d = _robust_line(s[n - 2 * width :][::-1])
    # typed: numpy's stubs leave a concatenation's dtype Any, and so the median's result
    padded: FloatArray = np.concatenate([(a - b * k)[::-1], s, c - d * k])
    return np.median(np.lib.stride_tricks.sliding_window_view(padded, width), axis=1)


def despiked(s: FloatArray) -> FloatArray:
    """``s`` with isolated outliers replaced by the running median, when it has them (more than 0.5 %
    of its samples farther than 5 noise levels (noise.py) and 5 % of its spread from the running
    median); otherwise ``s``
    as it is (a median flattens a swing's turning points a little)."""
    smooth = running_median(s)
    dev = np.abs(s - smooth)
    # a spike stands out of the noise and is a sizable part of the swing (a median's flattening of
    # the turning points is neither, on densely sampled data)
    scale = max(5.0 * noise_level(np.arange(len(s), dtype=np.float64), s), 0.05 * float(np.std(s)))
    if scale > 0.0 and np.count_nonzero(dev > scale) > 0.005 * len(s):
        return smooth
    return s


def crossings_period(t: FloatArray, s: FloatArray) -> float | None:
    """The period [s] of an oscillating signal from its crossings of its mean: a crossing counts only
    once the signal has gone from below −h to above +h or back (hysteresis, h = 3× the noise, at most
    half the signal's spread), so that noise near zero adds none; its time is where the signal last
    crossed the mean (linear interpolation). The half-period is the median spacing of the crossings,
    refined over the whole record. None with fewer than 3 crossings."""
    y = s - np.mean(s)
    spread = float(np.percentile(np.abs(y), 90)) if len(y) else 0.0
    h = min(3.0 * noise_level(t, y), 0.5 * spread)
    times: list[float] = []
    side = 0  # −1 below −h, +1 above +h, 0 not yet known
    last = 0  # the index before the latest crossing of the mean
    for i in range(1, len(y)):
        if np.signbit(y[i - 1]) != np.signbit(y[i]):
            last = i - 1
        now = 1 if y[i] > h else -1 if y[i] < -h else 0
        if now != 0 and now != side:
            if side != 0:
                k = last
                times.append(float(t[k] - y[k] * (t[k + 1] - t[k]) / (y[k + 1] - y[k])))
            side = now
    if len(times) < 3:
        return None
    tc = np.asarray(times)
    half = float(np.median(np.diff(tc)))
    if not half > 0.0:
        return None
    count = max(1, round((tc[-1] - tc[0]) / half))
    return float(2.0 * (tc[-1] - tc[0]) / count)


def energy_gravity(t: FloatArray, rel: FloatArray) -> float | None:
    """g [m/s²] from energy conservation, ½|v|² + g z = E(t) ≈ E₀ + E₁t (T-2.6; the slow trend takes
    up a weak damping): the least-squares slope of ½|v|² against −z with velocities by central
    differences (not across gaps). It holds for any motion — swings, whirls over the top, conical
    ones excepted (z constant) — where the period's formula holds for swings only. None when z does
    not vary enough."""
    if len(t) < 16:
        return None
    dt = t[2:] - t[:-2]
    ok = dt <= 3.0 * np.median(dt)
    v = (rel[2:] - rel[:-2]) / dt[:, None]
    kinetic = 0.5 * np.einsum("ij,ij->i", v, v)[ok]
    z = rel[1:-1, 2][ok]
    tt = t[1:-1][ok]
    if len(z) < 16 or np.ptp(z) <= 0.0:
        return None
    a = np.column_stack([-z, np.ones_like(z), tt - tt[0]])
    (g, *_), *_ = np.linalg.lstsq(a, kinetic, rcond=None)
    return float(g) if math.isfinite(g) and g > 0.0 else None


def decay_rate(t: FloatArray, amplitude: FloatArray) -> float:
    """c [1/s] from A(t) ∝ e^{−ct/2} fitted to the local maxima of |amplitude| (0 when not decaying)."""
    a = np.abs(amplitude)
    k = np.flatnonzero((a[1:-1] >= a[:-2]) & (a[1:-1] > a[2:])) + 1
    k = k[a[k] > 0.0]
    if len(k) < 3:
        return 0.0
    slope = np.polyfit(t[k], np.log(a[k]), 1)[0]
    return max(0.0, -2.0 * float(slope))


def value_and_rate(t: FloatArray, y: FloatArray, span: float) -> tuple[float, float]:
    """Value and derivative at t[0] of a quadratic through the samples within ``span`` of t[0]."""
    n = max(5, int(np.searchsorted(t, t[0] + span)))
    n = min(n, len(t))
    c = np.polyfit(t[:n] - t[0], y[:n], min(2, n - 1))
    return float(c[-1]), float(c[-2])
