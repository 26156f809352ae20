"""The hoist of a crane (docs/cranes.md "The crane model", docs/theory.md T-11.4): the rope length l(t)
[m] through samples (t_i [s], l_i [m]) as the clamped C² cubic spline (l̇ = 0 at t₀ and t_n), held
constant outside [t₀, t_n], so that l̈ steps at t₀ and t_n (breaks).

A spline can overshoot its samples: between t_i and t_{i+1} it is a cubic
l(t) = c₀ + c₁ s + c₂ s² + c₃ s³ (s = t − t_i), whose extremes on the piece are at its ends or at the
roots of l̇ = c₁ + 2c₂ s + 3c₃ s² inside it. :meth:`Hoist.length_range` takes them from the spline's
piecewise polynomials (SciPy's ``PPoly``): the true least and largest rope over a run, not the least
and largest sample. A spline that dips below 1e-6 m (the shortest pendulum, ``pl.limits()``) anywhere
between its samples is refused, naming the time and the length there; so is one
rising above the longest rope, 1e4 m (a pendulum's ``length`` limit, ``pl.limits()``; each sample too),
and one overshooting the samples' range [l_min, l_max] by more than their spread l_max − l_min: a
step between evenly spaced samples overshoots by 4/45 of it, by more than all of it only between
samples about 7.4 times closer in time than their neighbours (docs/cranes.md). Refused, not clamped:
a clamped length would no longer be the C² spline the core runs.
"""

from __future__ import annotations

from typing import Any

import numpy as np
from scipy.interpolate import CubicSpline

from .._core import InvalidInputError
from ..validate import LONGEST, LONGEST_TEXT, SHORTEST, SHORTEST_TEXT
from ._checks import ropes, time, times
from ._display import Row, Shown, hoist_rows
from .paths import Path
from .shaper import FloatArray


class Hoist(Path, Shown):
    """The rope length l(t) [m] through samples (``t`` [s] increasing, ``length`` [m] in [1e-6, 1e4],
    n ≥ 2): the C² cubic spline with l̇ = 0 at both ends (clamped), held constant outside [t₀, t_n];
    l̈ steps at t₀ and t_n (breaks). Refused when the spline dips below 1e-6 m between the samples,
    rises above 1e4 m or overshoots them by more than their spread (module doc).
    Stored in the first component of a 3-vector for the core."""

    def __init__(self, t: Any, length: Any) -> None:
        ts = times("t", t).ravel()
        ls = ropes("length", length).ravel()
        if ts.size < 2 or ls.shape != ts.shape:
            raise InvalidInputError(
                f"Hoist needs n >= 2 finite times t [s] and as many rope lengths [m], got {ts.size} times "
                f"and {ls.size} lengths"
            )
        if np.any(np.diff(ts) <= 0):
            raise InvalidInputError(f"Hoist times must be strictly increasing, got {ts.tolist()}")
        self._spline = CubicSpline(ts, ls, bc_type="clamped")
        self.span = (float(ts[0]), float(ts[-1]))
        self.breaks = np.array(self.span)
        self.nodes = ts
        self.t_end = self.span[1]
        self._check_range(ts, ls)

    def _check_range(self, ts: FloatArray, ls: FloatArray) -> None:
        """Refuses a spline whose true range (:meth:`extremes`) leaves what a rope may be: below the
        shortest rope (:data:`~pendulab.validate.SHORTEST`), above the longest
        (:data:`~pendulab.validate.LONGEST`), or beyond the samples' own range by more than their
        spread (module doc), naming the time, the length and the samples around it."""
        (t_low, low), (t_high, high) = self.extremes()
        top, bottom = float(ls.max()), float(ls.min())
        spread = top - bottom
        if not low >= SHORTEST:
            where, problem = t_low, f"dips to {low:.6g} m"
            why = (
                f"the rope length must stay >= {SHORTEST_TEXT} m (the shortest pendulum, pl.limits() length)"
            )
        elif high > LONGEST:
            where, problem = t_high, f"rises to {high:.6g} m"
            why = f"the rope length must stay <= {LONGEST_TEXT} m (the longest pendulum, pl.limits() length)"
        elif high - top > spread or bottom - low > spread:
            up = high - top >= bottom - low
            where, problem = (t_high, f"rises to {high:.6g} m") if up else (t_low, f"dips to {low:.6g} m")
            beyond = (
                f"{high - top:.6g} m above the largest" if up else f"{bottom - low:.6g} m below the least"
            )
            why = (
                f"{beyond} sample ({top if up else bottom:.6g} m), more than the samples' spread "
                f"({spread:.6g} m): a spline overshoots so far between samples much closer in time than "
                "their neighbours"
            )
        else:
            return
        i = min(max(int(np.searchsorted(ts, where, side="right")), 1), ts.size - 1)
        raise InvalidInputError(
            f"the Hoist spline through the lengths {problem} at t = {where:.10g} s, between the samples "
            f"({ts[i - 1]:.10g} s, {ls[i - 1]:.6g} m) and ({ts[i]:.10g} s, {ls[i]:.6g} m): {why}; give "
            "more samples there or a gentler change"
        )

    def _rows(self) -> list[Row]:
        return hoist_rows(self)

    def _pva(self, t: FloatArray, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        a, b = self.span
        inside = (t > a) & (t < b) | ((t == a) & (not left)) | ((t == b) & left)
        tc = np.clip(t, a, b)
        s = self._spline
        q, dq, ddq = np.zeros((t.size, 3)), np.zeros((t.size, 3)), np.zeros((t.size, 3))
        q[:, 0] = s(tc)
        dq[:, 0] = np.where(inside, s(tc, 1), 0.0)
        ddq[:, 0] = np.where(inside, s(tc, 2), 0.0)
        return q, dq, ddq

    def length(self, t: Any) -> FloatArray:
        """l(t) [m]."""
        return self.position(t)[:, 0]

    def extremes(
        self, t_start: float | None = None, t_end: float | None = None
    ) -> tuple[tuple[float, float], tuple[float, float]]:
        """((t_min [s], l_min [m]), (t_max [s], l_max [m])): where the rope is shortest and longest
        over [t_start, t_end] [s] (default the samples' span; held lengths outside it), the spline's
        true extremes (module doc: at the ends, the samples and the roots of l̇), not only its
        samples'."""
        a, b = self.span
        t0 = a if t_start is None else time("t_start", t_start)
        t1 = b if t_end is None else time("t_end", t_end)
        if t1 < t0:
            raise InvalidInputError(f"t_end = {t1!r} s is before t_start = {t0!r} s")
        lo, hi = min(max(t0, a), b), min(max(t1, a), b)  # held outside the span: its end values
        roots = np.asarray(self._spline.derivative().roots(discontinuity=False, extrapolate=False))
        candidates = np.concatenate([[lo, hi], self.nodes, roots[np.isfinite(roots)]])
        candidates = candidates[(candidates >= lo) & (candidates <= hi)]
        values = np.asarray(self._spline(candidates), dtype=np.float64)
        i, j = int(np.argmin(values)), int(np.argmax(values))
        return (float(candidates[i]), float(values[i])), (float(candidates[j]), float(values[j]))

    def length_range(self, t_start: float | None = None, t_end: float | None = None) -> tuple[float, float]:
        """(l_min, l_max) [m] over [t_start, t_end] [s] (default the samples' span): the spline's true
        least and largest rope length (:meth:`extremes`), which may lie beyond the samples'."""
        (_, low), (_, high) = self.extremes(t_start, t_end)
        return low, high
