"""The global error of a lab session's running motion, live (docs/web.md, "Error estimate"; issue 17).

Every frame record carries ``error_x`` [m]: the global position error |x − x_true| of its state, counted
from the start of the session's current stepper (a new scenario, state, model, parameters, method or
dt starts it afresh at 0), obtained as :mod:`pendulab.accuracy.estimate` does for a finished run,
with the companion stepper advanced alongside the session's:

- **exact** (the ideal pendulum): the true error against the exact solution from the same start
  (T-4.1–T-4.6, ``pl.exact``), evaluated at the record's time.
- **richardson** (fixed-step methods of order p, every other model, the spring and the string too): a
  *companion* stepper from the same start at dt/2 — ``estimate``'s fine companion —, advanced alongside
  to the same grid points; e ≈ |x_h − x_{h/2}| · 2^p/(2^p − 1) (Hairer, Nørsett & Wanner, *Solving
  ODEs I*, §II.4), p the method's order from the registry (``pendulab.methods()``). About 2× the run
  itself. (A finished run first tries the cheaper coarse companion at 2·dt, with tests of the
  asymptotic regime and of round-off over the whole run, and falls back to dt/2; live, records fall on
  every grid point, which only the dt/2 companion shares, and there is no whole run to test.)
- **companion** (``dop853``): a companion at the tolerance of
  :func:`pendulab.accuracy.estimate.reference_settings` (rtol and atol × 1/10; × 10, a looser one, when
  rtol is within 2× of the smallest allowed), landing on the same times by ``step_to``; with
  r = rtol_c/rtol, e ≈ |x − x_c|/|1 − r| (q/(q − 1) for q = 1/r = 10). About 1.3× the run (steps scale
  like tol^{−1/8}).

**The work budget.** The companion steps only in what is left of the tick's wall-time budget
(:mod:`.budget`) after the session's own stepping: the estimate never slows the lab. When the rest does
not carry it, the companion falls behind, the records it has not reached carry ``error_x`` = −1
(:data:`UNKNOWN`: the page shows "estimate paused"), and it catches up in later ticks' spare time.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import ExactSolution as _CoreExact
from .._core import IntegrationError, InvalidInputError
from ..accuracy.estimate import reference_settings
from ..model import Pendulum, State
from ..simulation import methods
from .budget import Budget, Slicer
from .protocol import FRAME_FIELDS

UNKNOWN = -1.0
"""``error_x`` of a record the estimate has not reached (the companion is behind: estimate paused)."""

_T = FRAME_FIELDS.index("t")
_X = FRAME_FIELDS.index("x1")
_ERR = FRAME_FIELDS.index("error_x")

StepperFactory = Callable[[dict[str, float]], Any]
"""Builds a stepper of the session's kind from the start with the given settings (dt or rtol, atol)."""


def _order(method: str) -> int:
    return int(next(m["order"] for m in methods() if m["name"] == method))


class LiveError:
    """The error estimate of one stepper's run from ``state`` at ``t0`` [s] (see the module doc).

    ``make`` builds the companion (a stepper like the session's, with the settings of
    :func:`~pendulab.accuracy.estimate.reference_settings`); ``exact=True`` (default) uses the exact
    solution where there is one (the ideal pendulum) instead of a companion. :meth:`fill` writes the
    ``error_x`` column of frame records; :meth:`describe` is the status notice's ``error_estimate``."""

    def __init__(
        self,
        pendulum: Any,
        state: State,
        t0: float,
        method: str,
        options: dict[str, float],
        adaptive: bool,
        make: StepperFactory,
        *,
        exact: bool = True,
    ) -> None:
        self.t0 = float(t0)
        self.start = state
        self.method = method
        self.adaptive = adaptive
        self.dt = float(options["dt"])
        self.how: str | None = None
        self.note: str | None = None
        self.reference: dict[str, float] = {}
        self.order: int | None = None
        self._exact: _CoreExact | None = None
        self._companion: Any = None
        self._steps = 0  # companion steps taken (fixed-step methods)
        self._slicer = Slicer()
        self._scale = 1.0  # e = scale · |x − x_companion|
        if exact and isinstance(pendulum, Pendulum) and pendulum.model == "ideal" and pendulum.is_ideal:
            try:
                self._exact = _CoreExact(
                    pendulum.length,
                    pendulum.mass,
                    pendulum.g,
                    np.ascontiguousarray(state.x, dtype=np.float64),
                    np.ascontiguousarray(state.v, dtype=np.float64),
                )
                self.how = "exact"
                return
            except (InvalidInputError, IntegrationError):
                self._exact = None  # no exact solution for this start: estimate as for the other models
        # dop853: estimate's companion tolerance; fixed steps: its fine companion at dt/2 (the module doc)
        self.reference = reference_settings(method, options) if adaptive else {"dt": self.dt / 2.0}
        try:
            self._companion = make(self.reference)
        except (InvalidInputError, IntegrationError, ValueError) as e:
            self.note = f"no estimate: the companion run cannot start ({' '.join(str(e).split())})"
            return
        if adaptive:
            self.how = "companion"
            self._scale = 1.0 / abs(1.0 - self.reference["rtol"] / float(options["rtol"]))
        else:
            p = self.order = _order(method)
            self.how = "richardson"
            self._scale = 2.0**p / (2.0**p - 1.0)

    def describe(self) -> dict[str, Any]:
        """The status notice's ``error_estimate``: ``how`` ("exact", "richardson", "companion" or None),
        the method's ``order`` (Richardson), the companion's settings ``reference`` (``dt`` [s], or
        ``rtol``, ``atol``), ``since`` [s] (the start the error is counted from) and ``note``."""
        return {
            "how": self.how,
            "order": self.order,
            "reference": dict(self.reference),
            "since": self.t0,
            "note": self.note,
        }

    def fill(self, records: np.ndarray | None, budget: Budget) -> None:
        """Sets the ``error_x`` column [m] of ``records`` (this stepper's, in time order) in place: 0 at
        the start, the error where known, :data:`UNKNOWN` where the companion did not get there within
        ``budget``."""
        if records is None or len(records) == 0:
            return
        since = records[:, _T] - self.t0
        if self._exact is not None:
            x_exact, _, _ = self._exact.states(np.maximum(since, 0.0))
            d = records[:, _X : _X + 3] - x_exact
            err = np.sqrt(np.einsum("ij,ij->i", d, d))
        else:
            err = np.full(len(records), UNKNOWN)
            for i in np.flatnonzero(since > 0.0) if self._companion is not None else ():
                if not self._reach(float(records[i, _T]), budget):
                    break  # out of budget: the rest stay unknown (estimate paused)
                d = records[i, _X : _X + 3] - self._companion.state.x
                err[i] = self._scale * math.sqrt(float(d @ d))
        err[since <= 0.0] = 0.0  # the start itself
        records[:, _ERR] = err

    def _reach(self, t: float, budget: Budget) -> bool:
        """Advances the companion to time ``t`` [s] within ``budget``; True once it is there."""
        c = self._companion
        try:
            if self.adaptive:
                if c.t >= t:
                    return c.t == t
                if budget.spent():
                    return False

                def capped(cap: int) -> bool:
                    c.step_to(t, max_steps=cap)
                    return bool(c.t >= t)

                return self._slicer.until(capped, budget)
            # fixed step: the record is grid point n of the run, the companion's grid point 2n
            want = 2 * round((t - self.t0) / self.dt) - self._steps
            if want < 0:
                return False  # behind the companion (cannot happen for this stepper's records)
            if want > 0:
                if budget.spent():
                    return False
                self._steps += self._slicer.steps(c.step, want, budget)
                drain = getattr(c, "take_events", None)
                if drain is not None:
                    drain()  # the string companion's events are not news
            return 2 * round((t - self.t0) / self.dt) == self._steps
        except (IntegrationError, InvalidInputError) as e:
            self._companion = None
            self.how = None
            self.note = f"no estimate: the companion run stopped ({' '.join(str(e).split())})"
            return False
