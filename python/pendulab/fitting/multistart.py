"""The fit's search strategy around :class:`pendulab.fitting.search.Search`: from which starts, in
which order, and when to stop.

- The starts (start.py): several phases for frame-free data, whose phase at t₀ is unknown; g (or l)
  from energy conservation beside the period's (T-2.6, T-10.4); starts with a sideways rate for data blind to
  the mirror y → −y (:func:`search_starts`).
- With more than two starts, the two that already fit best on the first window go on.
- Several dissipation laws free (T-7.1 …): the optimum of the nested models — the first law alone,
  then with the second, … (:data:`DISSIPATION`'s order), each from the previous optimum with the new
  law at 0 — is a start of the full search (:func:`nested_start`), so that adding a law never ends
  in a worse optimum than the chain of models without it.
- The search stops trying starts once the best explains the data to their noise: χ²/dof ≤
  :data:`FLOOR_CHI2` in units of the search's σ (:func:`at_noise_floor`).
- Several data kinds of unknown noise are reweighted by their own residual scatter and refitted; a
  robust loss (½Σρ(r²), T-10.2) refits from the plain optimum with its scale from the robust spread
  1.4826·median|r| of the plain fit's residual.
Ctrl-C and the time limit end the strategy with the best values so far (:func:`run_starts`).
Units: σ and residuals in each data kind's unit (docs/fit.md); times in s.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .._progress import tqdm
from .._warn import warn_user
from .data import Observations, residual
from .problem import Problem
from .search import Search, TimeUp, windows_of
from .start import gravity_starts, phase_starts, sideways_starts

#: Dissipation laws, in the order the nested search frees them (multistart.py, :func:`nested_start`).
DISSIPATION = ("damping", "friction", "drag")


def search_starts(
    obs: Observations, start: dict[str, Any], free: list[str]
) -> tuple[list[dict[str, Any]], bool]:
    """The starts of the search (start.py) and whether the data are blind to the mirror y → −y."""
    frame_free = not ({"positions", "horizontal", "angles", "planar_angle"} & set(obs.values))
    starts = phase_starts(start, set(free)) if frame_free else gravity_starts(obs, start, set(free))
    mirror_blind = frame_free or obs.columns.get("positions") == 2  # blind to y → −y (start.py)
    if mirror_blind:
        starts = sideways_starts(starts, set(free))
    return starts, mirror_blind


def run_starts(
    search: Search, starts: list[dict[str, Any]], period: float, show: bool
) -> tuple[bool, str, int]:
    """The search from the best starts, the nested start for several dissipation laws, and the
    re-weighting of several data kinds of unknown noise; (interrupted, why, number of starts)."""
    problem = search.problem
    windows = windows_of(problem.obs.t, period)
    if len(starts) > 2:  # optimise from the two starts that already fit best on the first window
        starts = _best_two(search, starts, windows)
    bar = tqdm(total=len(starts), desc="fit", unit="start", leave=False) if show else None
    robust, search.loss = search.loss, "linear"  # a robust loss refits from the plain optimum
    nested, ran = None, 0
    try:
        nested = nested_start(search, starts[0], windows)
        if nested is not None:  # already an optimum of the whole record: no windows
            search.from_start(nested, [])
        for s in starts:
            if at_noise_floor(search):  # no other start can do measurably better
                break
            search.from_start(s, windows)
            ran += 1
            if bar is not None:
                bar.update(1)
        _reweigh(search, robust)
    except (KeyboardInterrupt, TimeUp) as e:
        cause = "Ctrl-C" if isinstance(e, KeyboardInterrupt) else f"the time limit of {search.time_limit:g} s"
        why = f"interrupted ({cause})"
        warn_user(f"fit {why}: returning the best values reached", RuntimeWarning)
        return True, why, max(ran + (nested is not None), 1)
    finally:
        search.loss = robust
        if bar is not None:
            bar.close()
    return False, "", ran + (nested is not None)


def _best_two(search: Search, starts: list[dict[str, Any]], windows: Sequence[int]) -> list[dict[str, Any]]:
    """The two starts whose misfit on the first window (the whole record without windows) is least."""
    problem = search.problem
    first = problem.restricted(windows[0]) if windows else problem
    costs = [search.cost_at(s, first) for s in starts]
    return [starts[i] for i in np.argsort(costs)[:2]]


def _reweigh(search: Search, robust: str) -> None:
    """After the plain search: several data kinds with unknown noise weighed each by its own residual
    scatter [its unit], and refitted; a robust loss with its scale from the robust spread
    1.4826·median|r| of the plain fit's residual (noise-free data then stay exact, where a scale of the
    noise floor made every residual an outlier), refitted with that loss."""
    problem = search.problem
    unknown = [k for k, s in problem.obs.sigma.items() if s is None]
    if (len(problem.obs.values) > 1 and unknown) or robust != "linear":
        predicted = problem.predictions(problem.with_free(search.result.x))
        for kind in unknown:
            part = residual(kind, problem.obs.values[kind], predicted[kind])
            spread = 1.4826 * float(np.median(np.abs(part))) if robust != "linear" else 0.0
            search.sigma[kind] = max(spread or float(np.sqrt(np.mean(part**2))), 1e-300)
        search.loss = robust
        search.best_cost, search.result = math.inf, search.run(search.result.x)


#: The best result so far ends the search when its χ²/dof in units of the search's σ (the given σ, or
#: the noise floor read off the data) is at most this: it explains the data to their noise, so a
#: further start could only find an optimum that the data cannot tell from it.
FLOOR_CHI2 = 1.5

#: ... and when the record spans at least this many small-swing periods 2π√(l/|g|) of the best
#: result: over less (a third of a swing, bench/fit_validate.py case 20) optima that explain the data
#: equally well lie far apart, and stopping at the first one reported its length and g with confident
#: bars although the data do not determine them.
FLOOR_PERIODS = 1.0


def at_noise_floor(search: Search) -> bool:
    """Whether the best result so far explains the data to their noise (χ²/dof ≤ FLOOR_CHI2 in units
    of the search's σ; the anchor's k residuals are left out) over a record of at least FLOOR_PERIODS
    of its periods."""
    res = search.result
    if res is None or not res.success or search.loss != "linear":
        return False
    k = len(search.free)
    dof = max(int(res.fun.size) - 2 * k, 1)  # res.fun holds the data's residuals and the k anchors
    if not 2.0 * float(res.cost) <= FLOOR_CHI2 * dof:
        return False
    values = search.problem.with_free(res.x)
    length, g = values.get("length", math.nan), values.get("g", math.nan)
    if not (length > 0.0 and g != 0.0 and math.isfinite(length) and math.isfinite(g)):
        return True
    t = search.problem.obs.t
    return bool(float(t[-1] - t[0]) >= FLOOR_PERIODS * 2.0 * math.pi * math.sqrt(length / abs(g)))


def nested_start(
    search: Search, start: Mapping[str, float], windows: Sequence[int]
) -> dict[str, float] | None:
    """With several dissipation laws free, the optimum of the nested models — the first law alone,
    then with the second, … (DISSIPATION's order), each from the previous optimum with the new law at
    0 — as a start of the full search, so that adding a law never ends in a worse optimum than the
    chain of models without it."""
    free = search.free
    laws = [n for n in DISSIPATION if n in free]
    if len(laws) < 2:
        return None
    problem = search.problem
    current = dict(start) | dict.fromkeys(laws[1:], 0.0)
    for k in range(1, len(laws)):
        keep = [i for i, n in enumerate(free) if n not in laws[k:]]
        smaller = Problem(problem.model, current, [free[i] for i in keep], problem.obs)
        inner = Search(
            smaller,
            current,
            search.scales[keep],
            (search.lower[keep], search.upper[keep]),
            search.sigma,
            loss=search.loss,
            max_evaluations=search.max_evaluations,
            clock=search.clock,
            logged=search.logged[keep],
        )
        try:
            res = inner.from_start(current, windows if k == 1 else [])
        finally:
            problem.evaluations += smaller.evaluations
        current = current | dict(zip(smaller.free, (float(x) for x in res.x), strict=True))
        # the next law starts just off its bound 0, where a difference quotient can see it
        added = laws[k]
        current[added] = max(current[added], 0.01 * float(search.scales[free.index(added)]))
    return current
