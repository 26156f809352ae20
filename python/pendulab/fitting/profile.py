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

    _check(res, name, level, max_refits)
    target = float(stats.chi2.ppf(level, 1))
    values = {**res.fixed, **res.params}
    period = 2.0 * math.pi * math.sqrt(values["length"] / max(abs(values["g"]), 1e-9))
    rise = _Rise(res, name, period)
    value = values[name]
    bounds = bounds_of(res._problem.model, name, value)
    step0 = (
        res.stderr[name]
        if math.isfinite(res.stderr[name]) and res.stderr[name] > 0
        else scale_of(name, value, values["length"], period)
    )
    lo, hi = (_end(rise, values, step0, bounds, d, max_refits // 2, target) for d in (-1.0, 1.0))
    return lo, hi


def _check(res: Any, name: str, level: float, max_refits: int) -> None:
    """The arguments of :func:`profile_interval`: a fitted name, 0 < level < 1, 4 ≤ max_refits ≤ 1000."""
    if name not in res.params:
        raise KeyError(f"{name!r} was not fitted; fitted: {', '.join(res.names)}")
    if not (isinstance(level, float | int) and 0.0 < level < 1.0):
        raise ValueError(f"level = {level!r} must be between 0 and 1")
    if isinstance(max_refits, bool) or not isinstance(max_refits, int) or not 4 <= max_refits <= 1000:
        raise ValueError(f"max_refits = {max_refits!r} must be an integer from 4 to 1000")


class _Rise:
    """The profile misfit's rise (χ²_prof(c) − χ²_min) / variance with the parameter ``name`` held at
    c, the other unknowns refitted from ``start`` (inf where the model cannot be run there)."""

    def __init__(self, res: Any, name: str, period: float) -> None:
        self.res, self.name, self.period = res, name, period
        self.problem: Problem = res._problem
        self.others = [n for n in res.names if n != name]

    def __call__(self, c: float, start: dict[str, float]) -> tuple[float, dict[str, float]]:
        res, problem, others = self.res, self.problem, self.others
        sigma, variance = res._search_sigma, res._variance
        held = dict(start)
        held[self.name] = c
        sub = Problem(problem.model, held, others, problem.obs)
        if others:
            scales = np.array([scale_of(n, held[n], held["length"], self.period) for n in others])
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


def _end(
    rise: _Rise,
    values: dict[str, float],
    step0: float,
    bounds: tuple[float, float],
    direction: float,
    budget: int,
    target: float,
    doublings: int | None = None,
) -> float:
    """One end of the interval (``direction`` −1 or +1): steps of doubling size from the optimum until
    the rise exceeds ``target``, then bisection of the crossing, at most ``budget`` refits; the bound
    (or ±inf) when the rise stays below the target up to it, and ±inf when it still does after
    ``doublings`` steps (None: as many as the budget allows; the last step reaches 2^doublings − 1
    times ``step0`` from the optimum)."""
    lo_bound, hi_bound = bounds
    bound = lo_bound if direction < 0 else hi_bound
    value = values[rise.name]
    inside, inside_vals, step = value, values, step0
    outside = None
    steps = 0
    while budget > 0 and (doublings is None or steps < doublings):
        steps += 1
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
        return bound if math.isfinite(bound) and inside == bound else direction * math.inf
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
    return 0.5 * (inside + outside)
