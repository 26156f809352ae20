"""The wall-time budget of one session's tick (docs/web.md, "Pacing" and "Security").

Every tick a session may spend at most :data:`TICK_BUDGET` seconds of wall-clock time stepping — its
``step`` commands and its advance to the wall clock together, whatever the method: the fixed-step ones
(``Stepper.step(n)``, the spring's and the string's steppers) and the adaptive ``dop853``, whose number
of steps per simulated second has no bound the session could know beforehand (a forcing frequency of
10⁴ rad/s needs thousands). The core is called in *slices* (:class:`Slicer`): n steps for a
fixed-step method, ``step_to(t, max_steps=n)`` for ``dop853``, with n sized from the steps per second
measured on the earlier slices so that a slice takes about :data:`SLICE_TIME` (or half the budget when
that is smaller: a session's share of a full room, :mod:`.room`); the budget is checked
between slices, so a tick overruns it by at most one slice. Wall time, not CPU time: a session whose
thread waits for a core is charged for the wait, so a crowded machine makes every session do less
rather than every tick take longer. A session that runs out of budget before reaching the wall clock
falls behind real time and says so (``status.lagging``).
"""

from __future__ import annotations

import time
from collections.abc import Callable

TICK_BUDGET = 0.006
"""Wall-clock seconds one session may step per tick (a tick is 1/60 s ≈ 16.7 ms)."""

SLICE_TIME = 0.0005
"""Wall-clock seconds one call into the core aims at (the granularity of the budget)."""

MIN_SLICE_TIME = 0.00002
"""Shortest slice [s]: a small budget (a session's share in a full room, :mod:`.room`) is spent in
slices of half of it, at most :data:`SLICE_TIME`, at least this."""

FIRST_SLICE = 64
"""Steps of the first slice of a new stepper (before its speed is known)."""

MAX_SLICE = 1 << 22
"""Most steps of one slice."""


class Budget:
    """A deadline ``seconds`` from now (``time.perf_counter``)."""

    def __init__(self, seconds: float = TICK_BUDGET) -> None:
        self.seconds = seconds
        self.deadline = time.perf_counter() + seconds
        self.slice = max(MIN_SLICE_TIME, min(SLICE_TIME, 0.5 * seconds))

    def spent(self) -> bool:
        """True once the deadline has passed."""
        return time.perf_counter() >= self.deadline


class Slicer:
    """Calls into the core in slices of about :data:`SLICE_TIME` until the work is done or the budget is
    spent; remembers the stepper's speed (steps per second) between ticks. :meth:`reset` when the
    stepper changes."""

    def __init__(self) -> None:
        self.reset()

    def reset(self) -> None:
        """Forget the measured speed (a new stepper, method or model)."""
        self.rate: float | None = None  # steps per wall-clock second

    def _size(self, most: int, budget: Budget) -> int:
        n = FIRST_SLICE if self.rate is None else int(self.rate * budget.slice)
        return max(1, min(n, MAX_SLICE, most))

    def _learn(self, steps: int, seconds: float) -> None:
        rate = steps / max(seconds, 1e-7)
        self.rate = rate if self.rate is None else 0.5 * (self.rate + rate)

    def steps(self, step: Callable[[int], object], n: int, budget: Budget) -> int:
        """Takes up to ``n`` steps with ``step(k)`` (k steps per call), at least one slice, stopping
        when the budget is spent; returns the steps taken."""
        taken = 0
        while taken < n:
            k = self._size(n - taken, budget)
            t0 = time.perf_counter()
            step(k)
            self._learn(k, time.perf_counter() - t0)
            taken += k
            if budget.spent():
                break
        return taken

    def until(self, step_to: Callable[[int], bool], budget: Budget) -> bool:
        """Calls ``step_to(cap)`` (at most cap steps towards a target; True once there) in slices, at
        least one, until the target is reached (True) or the budget is spent (False)."""
        while True:
            k = self._size(MAX_SLICE, budget)
            t0 = time.perf_counter()
            reached = step_to(k)
            if not reached:  # a full slice: its time measures the speed
                self._learn(k, time.perf_counter() - t0)
            if reached:
                return True
            if budget.spent():
                return False
