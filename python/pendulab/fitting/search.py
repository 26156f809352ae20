"""The search of :func:`pendulab.fit` (:class:`Search`: the trust-region search with its anchor, clock
and best-so-far record) and the two stages around it (estimator.py): the continuation
over growing time windows, which keeps each stage's phase error small so that a long record does not
trap the search in the wrong number of swings, and the Gauss–Newton polish after it, which takes
noise-free data to the float64 floor (least squares, T-10.2; docs/fit.md, "How it works"). Units: SI.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from .._core import IntegrationError, InvalidInputError
from ..model import FloatArray
from .identify import jacobian

if TYPE_CHECKING:
    from .problem import Problem

#: At most this many Gauss–Newton steps (see :func:`polish`).
POLISH_STEPS = 40
#: A window of the continuation gets this fraction of ``max_evaluations``: it only brings the search
#: near the optimum of the whole record (a model that misses the data would crawl in each window).
WINDOW_SHARE = 10
#: The anchor's pull per unit of ln p or of a parameter's scale, in units of the residuals' σ.
ANCHOR = 0.1


def windows_of(t: FloatArray, period: float) -> list[int]:
    """Sample counts of growing time windows [t₀, t₀ + 4T·2ᵏ) shorter than the data (T the estimated
    period): fitting them in turn keeps each stage's phase error small, so that a long record does
    not trap the search in the wrong number of swings."""
    span = float(t[-1] - t[0])
    out: list[int] = []
    width = 4.0 * period
    while width < 0.6 * span:
        n = int(np.searchsorted(t, t[0] + width))
        if n >= 16 and (not out or n > out[-1]):
            out.append(n)
        width *= 2.0
    return out


def polish(
    weighted: Any,
    u: FloatArray,
    r: FloatArray,
    jac: FloatArray,
    steps: FloatArray,
    positive: FloatArray,
    lo: FloatArray,
    hi: FloatArray,
    time_up: Callable[[], bool] = lambda: False,
    jac_of: Callable[[FloatArray], FloatArray | None] = lambda u: None,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Gauss–Newton steps with central-difference Jacobians after the trust-region search: near the
    optimum its forward differences stall short of the float64 floor on noise-free data; these steps
    reach it (directions the data do not determine are left alone by the pseudo-inverse). Four steps,
    and more (up to POLISH_STEPS) while each still cuts the misfit by 4× or more: along a direction
    where the residual is quadratic (a planar swing seen along y: r ∝ φ̇₀²) Gauss–Newton only halves
    the distance per step. ``jac_of(u)``: an exact Jacobian where there is one (None: central
    differences). Stops at ``time_up()`` and where the Jacobian or residual is not finite
    (LAPACK would not return on an infinite matrix)."""
    for k in range(POLISH_STEPS):
        if time_up() or not (np.all(np.isfinite(jac)) and np.all(np.isfinite(r))):
            break
        step = np.linalg.lstsq(jac, -r, rcond=1e-10)[0]
        trial = np.minimum(np.maximum(u + step, lo), hi)
        try:
            r_trial = weighted(trial)
        except (InvalidInputError, IntegrationError):  # a step into a state the model refuses
            break
        before, after = float(r @ r), float(r_trial @ r_trial)
        if not after < before or (k >= 4 and after > 0.25 * before):
            break
        small = np.all(np.abs(trial - u) <= 1e-13 * np.maximum(np.abs(u), 1.0))
        u, r = trial, r_trial
        exact = jac_of(u)
        jac = exact if exact is not None else jacobian(weighted, u, steps, positive)
        if small:
            break
    return u, r, jac


class TimeUp(Exception):
    """The search ran past ``time_limit``."""


def wall_clock() -> float:
    """The time every fit's :class:`Clock` reads [s] (``time.perf_counter()``): one place, so that a
    test can put a clock of its own here and check the time limit without measuring time."""
    return time.perf_counter()


#: After the time limit, the error analysis may run on for at most this long [s] (docs/fit.md, "The
#: time limit"): its Jacobian over the whole record is computed only if that fits, one run per
#: unknown estimated from the last run of the record; otherwise the error bars are not determined.
LATE_SECONDS = 1.0


class Clock:
    """The clock of one fit: ``time_limit`` [s] (None: no limit) counted from ``began``
    (:func:`wall_clock` when it was made, unless given). Every :class:`Search` of a fit — its
    own, the nested models', the blocks', the profiles' refits — is given the same clock when it is
    made, so that one limit bounds them all from the fit's start. It also records what stopped the
    fit short (the result's ``interrupted``): ``ran_out``, a check found the limit passed (every
    check stops or skips a step: a search, the polish, the block check, a profile); ``ctrl_c``,
    Ctrl-C in a profile's refit (profile.py), which the error analysis survives."""

    def __init__(self, time_limit: float | None, began: float | None = None) -> None:
        self.time_limit = time_limit
        self.began = wall_clock() if began is None else began
        self.ran_out = False
        self.ctrl_c = False

    def elapsed(self) -> float:
        """Seconds since ``began`` by :func:`wall_clock`."""
        return wall_clock() - self.began

    def time_up(self, ahead: float = 0.0) -> bool:
        """Whether ``time_limit`` [s] has passed since ``began``, or will have after ``ahead`` more
        seconds of work (a Jacobian's run cannot be interrupted once begun); once True, ``ran_out``."""
        up = self.time_limit is not None and self.elapsed() + ahead > self.time_limit
        self.ran_out |= up
        return up

    def late_time_up(self, ahead: float) -> bool:
        """Whether ``ahead`` more seconds of work would end more than :data:`LATE_SECONDS` past
        ``time_limit`` (the bound of the error analysis after the limit)."""
        return self.time_limit is not None and self.elapsed() + ahead > self.time_limit + LATE_SECONDS

    def __repr__(self) -> str:
        return f"Clock(time_limit={self.time_limit!r}, elapsed={self.elapsed():.3g} s)"


class _Abandoned(Exception):
    """A later start used more than its share of model runs while still worse than the best."""


#: A start after the first may use this many times the first's model runs (plus 200) before it is
#: abandoned, unless it is already better than the best so far.
START_SHARE = 4
#: The secant step of an exactly flat Jacobian column, in units of the parameter's scale.
SECANT = 0.1


class Search:
    """SciPy's trust-region reflective ``least_squares`` on a :class:`Problem`, with the anchor, the
    clock, the record of the best values seen (what Ctrl-C or the time limit returns) and the window
    continuation (this module's doc). ``sigma``: kind → the scale of its residuals [its unit]
    (the given σ, or the noise floor read off the data: noise.py), so that the search and its anchor do
    not depend on the units of the data. ``clock``: the fit's :class:`Clock`, shared by every search
    of the fit (its ``time_limit`` and ``began`` are read from it)."""

    def __init__(
        self,
        problem: Problem,
        start: Mapping[str, float],
        scales: FloatArray,
        bounds: tuple[FloatArray, FloatArray],
        sigma: dict[str, float],
        *,
        loss: str,
        max_evaluations: int,
        clock: Clock,
        logged: FloatArray,
    ) -> None:
        self.problem = problem
        self.free = problem.free
        self.u_start = np.array([start[n] for n in self.free], dtype=np.float64)
        self.scales = scales
        self.lower, self.upper = bounds
        self.sigma = sigma
        self.loss = loss
        self.max_evaluations = max_evaluations
        self.clock = clock
        self.logged = logged
        self.best_cost = math.inf
        self.best_u: FloatArray | None = None
        self.last_u: FloatArray | None = None
        self.result: Any = None
        self.calls = 0  # model runs through fun (the Jacobians' included)
        self.call_budget: int | None = None
        self.first_calls = 0
        self.start_cost = math.inf
        self.jacobian_seconds = 0.0  # the wall time of the last exact Jacobian [s]
        self.bars_late = False  # the Jacobian past the time limit was not computed (inference.py)
        # (problem, point and σ, Jacobian): the problem held, so that its id is not reused
        self._last_jacobian: tuple[Problem, bytes, FloatArray | None] | None = None

    @property
    def time_limit(self) -> float | None:
        """The fit's time limit [s] (its :class:`Clock`'s; None: no limit)."""
        return self.clock.time_limit

    @property
    def began(self) -> float:
        """When the fit's :class:`Clock` started (:func:`wall_clock`)."""
        return self.clock.began

    def time_up(self, ahead: float = 0.0) -> bool:
        """Whether the fit's time limit has passed (:meth:`Clock.time_up`)."""
        return self.clock.time_up(ahead)

    def anchor(self, u: FloatArray) -> FloatArray:
        """A faint pull towards the start (ANCHOR per unit of ln p or of the scale, in units of the
        residuals' σ): it holds the directions the data do not determine (g and l together, from
        angles) where they began instead of letting them drift to a bound, and biases the determined
        ones by ~ANCHOR²/(JᵀJ), nothing."""
        with np.errstate(divide="ignore", invalid="ignore"):
            z = np.where(
                self.logged,
                np.log(np.maximum(u, 1e-300) / np.where(self.logged, self.u_start, 1.0)),
                (u - self.u_start) / self.scales,
            )
        return ANCHOR * z

    def anchor_slope(self, u: FloatArray) -> FloatArray:
        """d(anchor)/du, the diagonal of the anchor's Jacobian."""
        with np.errstate(divide="ignore", invalid="ignore"):
            return ANCHOR * np.where(self.logged, 1.0 / np.maximum(u, 1e-300), 1.0 / self.scales)

    def exact_jacobian(self, on: Problem, u: FloatArray) -> FloatArray | None:
        """∂r/∂u by forward sensitivities (sensitivity.py) where the model has them, finite and
        evaluable at ``u``; None otherwise (the caller differences). Each counts as one model run."""
        from .sensitivity import exact_jacobian

        # the last one again (SciPy asks for the Jacobian at the start this probe already ran);
        # the key holds each kind's σ, which the re-weighting of unknown noise changes
        key = np.asarray(u, dtype=np.float64).tobytes() + repr(sorted(self.sigma.items())).encode()
        last = self._last_jacobian
        if last is not None and last[0] is on and last[1] == key:
            cached = last[2]
            return None if cached is None else cached.copy()
        began = wall_clock()
        before = on.evaluations  # its cheap re-evaluations of the predictions are not model runs
        try:
            j = exact_jacobian(on, on.with_free(u), self.sigma)
        except (InvalidInputError, IntegrationError, OverflowError, ZeroDivisionError, ValueError):
            return None
        finally:
            on.evaluations = before + 1
        self.calls += 1
        ok = j is not None and bool(np.all(np.isfinite(j)))
        j = self._flat_columns_one_sided(on, u, j) if ok and j is not None else None
        self.jacobian_seconds = wall_clock() - began
        self._last_jacobian = (on, key, None if j is None else j.copy())
        return j

    def _flat_columns_one_sided(self, on: Problem, u: FloatArray, j: FloatArray) -> FloatArray:
        """A column that is exactly zero marks an invariant set of the motion the data see only at
        second order — the mirror plane φ̇ ≡ 0 of a swing filmed from the side: there the exact
        Jacobian can never lead the search off the plane (bench/fit_validate.py case 6, an ellipse
        fitted as a planar swing 1.7e4 noise floors off). Such a column is replaced by the secant
        (r(u + h) − r(u))/h = ½ h ∂²r/∂u² + … over h = SECANT of the parameter's scale: for
        r ≈ r₀ + ½ a u² the Gauss–Newton step it gives is δ²/h, δ the true minimiser, so h of the size
        of a plausible sideways rate gives a step of that size (h → 0 would give a step ∝ 1/h that
        only the trust region stops, into a poor basin: case 8, AR(1) noise)."""
        flat = [k for k in range(j.shape[1]) if not np.any(j[:, k])]
        if not flat:
            return j
        r0 = on.safe_residuals(u, self.sigma)
        for k in flat:
            up = u.copy()
            h = SECANT * float(self.scales[k])
            up[k] = min(u[k] + h, self.upper[k]) if u[k] + h <= self.upper[k] else u[k] - h
            step = up[k] - u[k]
            if step != 0.0:
                j[:, k] = (on.safe_residuals(up, self.sigma) - r0) / step
                self.calls += 1
        return j

    def clip(self, u: FloatArray) -> FloatArray:
        return np.minimum(np.maximum(u, self.lower), self.upper)

    def run(
        self, u0: FloatArray, on: Problem | None = None, tol: float = 1e-10, evaluations: int | None = None
    ) -> Any:
        """One trust-region search from ``u0`` on ``on`` (default: the whole problem), with at most
        ``evaluations`` residual evaluations besides the Jacobians' (default ``max_evaluations``)."""
        from scipy.optimize import least_squares  # SciPy is imported on first use (the `fit` extra)

        on = self.problem if on is None else on

        def fun(u: FloatArray) -> FloatArray:
            if self.last_u is not None and self.time_up():
                raise TimeUp
            self.calls += 1
            r = on.safe_residuals(u, self.sigma)
            self.last_u = np.array(u, dtype=np.float64)  # on a window too: what an interruption returns
            cost = 0.5 * float(r @ r)
            self.start_cost = min(self.start_cost, cost)
            if on is self.problem and cost < self.best_cost:
                self.best_cost, self.best_u = cost, np.array(u, dtype=np.float64)
            if self.call_budget is not None and self.calls > self.call_budget and self._behind(on):
                raise _Abandoned
            return np.concatenate([r, self.anchor(u)])

        def jac(u: FloatArray) -> FloatArray:
            if self.time_up(self.jacobian_seconds):
                raise TimeUp
            j = self.exact_jacobian(on, u)
            if j is None:  # the model refused this point: central differences of the safe residuals
                j = jacobian(lambda uu: on.safe_residuals(uu, self.sigma), u, 1e-7 * self.scales)
            return np.vstack([j, np.diag(self.anchor_slope(u))])

        exact = self.exact_jacobian(on, self.clip(u0)) is not None
        # a search that wanders where the motion grows without bound (g < 0, an inverted swing) meets
        # Jacobians of 1e200: SciPy then shrinks its trust region, and numpy's overflow warnings
        # would reach the user by the hundred
        with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
            return least_squares(
                fun,
                self.clip(u0),
                jac=jac if exact else "2-point",
                bounds=(self.lower, self.upper),
                x_scale=self.scales,
                loss=self.loss,  # type: ignore[arg-type]  # one of SciPy's names (settings.check_settings)
                f_scale=1.0,
                max_nfev=self.max_evaluations if evaluations is None else evaluations,
                xtol=tol,
                ftol=tol,
                gtol=tol,
                diff_step=1e-8,  # type: ignore[arg-type]  # SciPy takes a scalar; its stubs want an array
                method="trf",
            )

    def _behind(self, on: Problem) -> bool:
        """Whether this start's best cost on ``on`` is still above that of the best result so far."""
        if on is self.problem:
            return self.start_cost > self.best_cost
        if self.result is None:
            return False
        best = 0.5 * self.cost_at(dict(zip(self.free, self.result.x, strict=True)), on)
        return self.start_cost > best

    def from_start(self, values: Mapping[str, float], windows: Sequence[int]) -> Any:
        """The continuation over the growing ``windows`` (sample counts), then the whole record; keeps
        the best result so far in ``self.result``. A start after the first that needs more than
        START_SHARE times the first's model runs while still worse than the best is abandoned (None):
        a model that misses the data can crawl for thousands of runs from a poor start."""
        first = self.result is None
        began = self.calls
        self.call_budget = None if first else began + START_SHARE * self.first_calls + 200
        self.start_cost = math.inf
        u0 = np.array([values[n] for n in self.free], dtype=np.float64)
        try:
            for n_samples in windows:
                part = self.problem.restricted(n_samples)
                self.start_cost = math.inf
                try:
                    u0 = self.run(u0, part, 1e-8, max(10, self.max_evaluations // WINDOW_SHARE)).x
                finally:
                    self.problem.evaluations += part.evaluations
            self.start_cost = math.inf
            res = self.run(u0)
        except _Abandoned:
            return None
        finally:
            self.call_budget = None
        if first:
            self.first_calls = self.calls - began
        if self.result is None or res.cost <= self.result.cost:
            self.result = res
        return res

    def cost_at(self, values: Mapping[str, float], on: Problem) -> float:
        """Σ r² of ``values`` on ``on`` (inf where the model refuses them)."""
        r = on.safe_residuals([values[n] for n in self.free], self.sigma)
        return float(r @ r)
