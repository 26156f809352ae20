"""Profile-likelihood intervals of :func:`pendulab.fit` (docs/fit.md, "Error bars in curved valleys";
T-10.2): for a parameter p_j held at a value c, the profile misfit is
χ²_prof(c) = min over the other unknowns of Σ r², and {c : χ²_prof(c) − χ²_min ≤ χ²₁(level)} (3.84 at
95 %) is the interval, in units of the noise (σ given, or the residual variance when estimated). For a
linear model it is the ±1.96 σ interval; in a curved valley (g and l of a short record, a damping near
0) it is asymmetric and honest where the linearised one is not (Venzon & Moolgavkar 1988, Appl. Stat.
37:87). Each end: steps of growing size from the optimum until the rise exceeds the quantile, then
bisection of the crossing, every refit starting from the last one's values. Units: the parameter's.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from .problem import POSITIVE, Problem, bounds_of, scale_of
from .search import Search

#: Bisection steps of each end's crossing (the interval's end to 2⁻¹⁰ of the bracket).
BISECTIONS = 10


def profile_interval(res: Any, name: str, level: float, max_refits: int) -> tuple[float, float]:
    """See :meth:`pendulab.FitResult.profile` (``res`` is the FitResult: this module sits below it)."""
    from scipy import stats

    if name not in res.params:
        raise KeyError(f"{name!r} was not fitted; fitted: {', '.join(res.names)}")
    if not (isinstance(level, float | int) and 0.0 < level < 1.0):
        raise ValueError(f"level = {level!r} must be between 0 and 1")
    if isinstance(max_refits, bool) or not isinstance(max_refits, int) or not 4 <= max_refits <= 1000:
        raise ValueError(f"max_refits = {max_refits!r} must be an integer from 4 to 1000")
    problem: Problem = res._problem
    sigma, variance = res._search_sigma, res._variance
    target = float(stats.chi2.ppf(level, 1))
    values = {**res.fixed, **res.params}
    others = [n for n in res.names if n != name]
    period = 2.0 * math.pi * math.sqrt(values["length"] / max(abs(values["g"]), 1e-9))

    def rise(c: float, start: dict[str, float]) -> tuple[float, dict[str, float]]:
        held = dict(start)
        held[name] = c
        sub = Problem(problem.model, held, others, problem.obs)
        if others:
            scales = np.array([scale_of(n, held[n], held["length"], period) for n in others])
            lower, upper = (
                np.array(b) for b in zip(*(bounds_of(problem.model, n, held[n]) for n in others), strict=True)
            )
            logged = np.array([n in POSITIVE and held[n] > 0.0 for n in others])
            search = Search(
                sub,
                held,
                scales,
                (lower, upper),
                sigma,
                loss="linear",
                max_evaluations=200,
                time_limit=None,
                logged=logged,
            )
            result = search.from_start(held, [])
            held = sub.with_free(result.x)
        try:
            r = sub.residuals(held, sigma)
        except (InvalidInputError, IntegrationError):
            return math.inf, held
        return (float(r @ r) - res.misfit) / variance, held

    value = values[name]
    lo_bound, hi_bound = bounds_of(problem.model, name, value)
    step0 = (
        res.stderr[name]
        if math.isfinite(res.stderr[name]) and res.stderr[name] > 0
        else scale_of(name, value, values["length"], period)
    )
    ends = []
    for direction in (-1.0, 1.0):
        budget = max_refits // 2
        bound = lo_bound if direction < 0 else hi_bound
        inside, inside_vals, step = value, values, step0
        outside = None
        while budget > 0:
            c = min(max(inside + direction * step, lo_bound), hi_bound)
            budget -= 1
            d, vals = rise(c, inside_vals)
            if d >= target:
                outside = c
                break
            inside, inside_vals = c, vals
            if c == bound:
                break
            step *= 2.0
        if outside is None:
            ends.append(bound if math.isfinite(bound) and inside == bound else direction * math.inf)
            continue
        for _ in range(BISECTIONS):
            if budget <= 0:
                break
            mid = 0.5 * (inside + outside)
            budget -= 1
            d, vals = rise(mid, inside_vals)
            if d >= target:
                outside = mid
            else:
                inside, inside_vals = mid, vals
        ends.append(0.5 * (inside + outside))
    return ends[0], ends[1]
