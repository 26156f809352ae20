"""Profile-likelihood intervals of :func:`pendulab.fit` (docs/fit.md, "Error bars in curved valleys";
T-10.2): for a parameter p_j held at a value c, the profile misfit is
χ²_prof(c) = min over the other unknowns of Σ r², and {c : χ²_prof(c) − χ²_min ≤ χ²₁(level)} (3.84 at
95 %) is the interval, in units of the noise (σ given, or the residual variance when estimated). For a
linear model it is the ±1.96 σ interval; in a curved valley (g and l of a short record, a damping near
0) it is asymmetric and honest where the linearised one is not (Venzon & Moolgavkar 1988, Appl. Stat.
37:87). Each end: steps of growing size from the optimum until the rise exceeds the quantile, then
bisection of the crossing, every refit starting from the last one's values. A refit that spends its
:data:`REFIT_EVALUATIONS` model runs without meeting SciPy's tolerances is continued from where it
stopped, up to :data:`REFIT_ROUNDS` rounds; one still falling after them has a misfit above the
profile's, so a rise past the level from it would end the interval too soon; so would a refit begun
far off that SciPy calls converged at a poor point (case 20, seed 0: the length's profile closed at
3.5 m while g's ran to its bound). Each end's outer point is therefore refitted once more from the
nearest inside values (the check); past a refit that did not converge or that the check finds below
the level the steps go on, and an end that no checked refit closes is open (±inf, not settled:
:func:`profile_end`), which :meth:`pendulab.FitResult.profile` warns about. :class:`Rise` and
:func:`profile_end` are shared with short_record.py, whose refits the fit's ``time_limit`` bounds
(:class:`Rise`'s clock). Units: the parameter's.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from .._warn import warn_user
from .problem import POSITIVE, Problem, bounds_of, scale_of
from .search import Clock, Search, TimeUp

#: Bisection steps of each end's crossing (the interval's end to 2⁻¹⁰ of the bracket).
BISECTIONS = 10

#: Model runs of one round of a refit of the other unknowns.
REFIT_EVALUATIONS = 200

#: Rounds of a refit at most: a round that ends at its model runs is continued from where it stopped.
REFIT_ROUNDS = 3

#: A round that lowers the rise by less than this (in units of the noise, as the level's 3.84) counts
#: as converged though SciPy's tolerances (1e-10) are not met: the profile's end moves by ≲ 1e-3 of
#: the interval.
SETTLED = 0.01


def profile_interval(res: Any, name: str, level: float, max_refits: int) -> tuple[float, float]:
    """See :meth:`pendulab.FitResult.profile` (``res`` is the FitResult: this module sits below it)."""
    from scipy import stats

    _check(res, name, level, max_refits)
    target = float(stats.chi2.ppf(level, 1))
    values = {**res.fixed, **res.params}
    period = 2.0 * math.pi * math.sqrt(values["length"] / max(abs(values["g"]), 1e-9))
    rise = Rise(res, name, period)
    value = values[name]
    bounds = bounds_of(res._problem.model, name, value)
    step0 = (
        res.stderr[name]
        if math.isfinite(res.stderr[name]) and res.stderr[name] > 0
        else scale_of(name, value, values["length"], period)
    )
    ends = [profile_end(rise, values, step0, bounds, d, max_refits // 2, target) for d in (-1.0, 1.0)]
    for (end, settled), side in zip(ends, ("lower", "upper"), strict=True):
        if not settled:
            warn_user(
                f"the profile of {name}: its {side} end is not determined (returned as {end:g}): a refit "
                f"of the other unknowns did not converge in {REFIT_ROUNDS} x {REFIT_EVALUATIONS} model "
                "runs or, refitted from nearer, fell below the level, and no refit within max_refits "
                "closed the end",
                RuntimeWarning,
            )
    return ends[0][0], ends[1][0]


def _check(res: Any, name: str, level: float, max_refits: int) -> None:
    """The arguments of :func:`profile_interval`: a fitted name, 0 < level < 1, 4 ≤ max_refits ≤ 1000."""
    if name not in res.params:
        raise KeyError(f"{name!r} was not fitted; fitted: {', '.join(res.names)}")
    if not (isinstance(level, float | int) and 0.0 < level < 1.0):
        raise ValueError(f"level = {level!r} must be between 0 and 1")
    if isinstance(max_refits, bool) or not isinstance(max_refits, int) or not 4 <= max_refits <= 1000:
        raise ValueError(f"max_refits = {max_refits!r} must be an integer from 4 to 1000")


class Rise:
    """The profile misfit's rise (χ²_prof(c) − χ²_min) / variance with the parameter ``name`` of the
    FitResult ``res`` held at c, the other unknowns refitted from ``start`` (inf where the model cannot
    be run there); ``period`` [s] sets the refit's scales. A call returns the rise, the refitted values
    and whether the refit converged (module doc). ``clock``: the fit's :class:`Search`, whose
    :class:`~pendulab.fitting.search.Clock` each refit's search is given, so that the fit's
    ``time_limit`` bounds every refit from the fit's start (checked before each round and at each
    model run: :class:`pendulab.fitting.search.TimeUp` is raised; Ctrl-C in a refit is noted on the
    clock, ``ctrl_c``); None: no limit (``FitResult.profile``)."""

    def __init__(self, res: Any, name: str, period: float, clock: Search | None = None) -> None:
        self.res, self.name, self.period, self.clock = res, name, period, clock
        self.problem: Problem = res._problem
        self.others = [n for n in res.names if n != name]

    def __call__(self, c: float, start: dict[str, float]) -> tuple[float, dict[str, float], bool]:
        try:
            return self._refit(c, start)
        except KeyboardInterrupt:  # noted on the fit's clock: a fit that goes on is marked interrupted
            if self.clock is not None:
                self.clock.clock.ctrl_c = True
            raise

    def _refit(self, c: float, start: dict[str, float]) -> tuple[float, dict[str, float], bool]:
        res, problem, others = self.res, self.problem, self.others
        sigma = res._search_sigma
        held = dict(start)
        held[self.name] = c
        sub = Problem(problem.model, held, others, problem.obs)
        rise, converged = self._rise(sub, held), True
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
                max_evaluations=REFIT_EVALUATIONS,
                # the fit's clock: a refit is cut at a model run past its limit
                clock=Clock(None) if self.clock is None else self.clock.clock,
                logged=logged,
            )
            u = np.array([held[n] for n in others], dtype=np.float64)
            for _ in range(REFIT_ROUNDS):
                if search.time_up():
                    raise TimeUp
                result = search.run(u)
                u, before = result.x, rise
                held = sub.with_free(u)
                rise = self._rise(sub, held)
                converged = int(result.status) > 0 or before - rise < SETTLED
                if converged:
                    break
        return rise, held, converged

    def _rise(self, sub: Problem, held: dict[str, float]) -> float:
        try:
            r = sub.residuals(held, self.res._search_sigma)
        except (InvalidInputError, IntegrationError):
            return math.inf
        return (float(r @ r) - float(self.res.misfit)) / float(self.res._variance)


def profile_end(
    rise: Rise,
    values: dict[str, float],
    step0: float,
    bounds: tuple[float, float],
    direction: float,
    budget: int,
    target: float,
    doublings: int | None = None,
    bisections: int = BISECTIONS,
) -> tuple[float, bool]:
    """One end of the interval (``direction`` −1 or +1) and whether it is settled, in at most ``budget``
    refits: steps of doubling size from the optimum until the rise exceeds ``target``, ``bisections``
    bisections of the crossing, then the check: the outer point refitted again from the nearest inside
    values. The bound when the rise stays below the target up to it, and ±inf when it still does after
    ``doublings`` steps (None: up to the bound; the last step reaches 2^doublings − 1 times ``step0``
    from the optimum). A refit that did not converge (:class:`Rise`) or that the check finds below the
    target (a refit from far off that failed: case 20, seed 0, the length at 3.55 m gave a rise of
    2e5 from l = 1.66 m, 2.1 from l = 3.54 m) decides nothing: the steps go on past it. An end no
    checked refit closes is ±inf and not settled."""
    value = values[rise.name]
    bound = bounds[0] if direction < 0 else bounds[1]
    far = bound
    if doublings is not None:
        reach = value + direction * step0 * (2.0**doublings - 1.0)
        far = max(far, reach) if direction < 0 else min(far, reach)
    inside, inside_vals, step = value, values, step0
    outside: float | None = None
    halvings, doubt, cut = 0, False, False
    outside_from: dict[str, float] | None = None  # the values the outer point's refit began from
    while budget > 0:
        if outside is None:
            c = max(inside - step, far) if direction < 0 else min(inside + step, far)
        elif halvings < bisections:
            c = 0.5 * (inside + outside)
        elif outside_from is inside_vals:  # refitted from the nearest inside values already
            return outside if cut else 0.5 * (inside + outside), True
        else:
            c = outside
        budget -= 1
        d, vals, converged = rise(c, inside_vals)
        if outside is not None and c == outside:  # the check
            if d >= target and converged:
                return outside if cut else 0.5 * (inside + outside), True
            outside, halvings, doubt, cut = None, 0, d >= target, False
            if d < target:
                inside, inside_vals = c, vals
            step *= 2.0
        elif d >= target and converged:
            if outside is not None:
                halvings += 1
            outside, outside_from = c, inside_vals
        elif d >= target:  # not converged: no verdict; step past it, or end the bisection
            doubt = True
            if outside is None:
                step *= 2.0
            else:
                halvings, cut = bisections, True  # the bracket's outer end: wider, never narrower
        else:
            inside, inside_vals, doubt = c, vals, False  # past any refit that decided nothing
            if outside is not None:
                halvings += 1
            elif c == far:
                break
            else:
                step *= 2.0
        if outside is None and inside != c and c == far:
            break  # the last step was no verdict
    if doubt or outside is not None:
        return direction * math.inf, False
    return (bound if math.isfinite(bound) and inside == bound else direction * math.inf), True
