"""LQR anti-sway feedback for a trolley crane (docs/cranes.md, docs/theory.md T-11.9), beside the open-loop
shapers. The trolley's acceleration u [m/s²] is the input (drives are speed/acceleration controlled);
the load hangs on a rope of length l [m] at the angle θ [rad]. Nonlinear planar model:

    ẍ = u,   l θ̈ = −g sin θ − u cos θ;

linearised about rest, z = (x − x_target, ẋ, θ, θ̇):

    ż = A z + B u,   A = [[0,1,0,0],[0,0,0,0],[0,0,0,1],[0,0,−g/l,0]],   B = (0, 1, 0, −1/l)ᵀ.

u = −K z minimises ∫ zᵀQz + R u² dt with K = R⁻¹BᵀP and P from the continuous algebraic Riccati
equation AᵀP + PA − PBR⁻¹BᵀP + Q = 0 (SciPy ``solve_continuous_are``). The closed loop runs in the
nonlinear planar model (SciPy DOP853); its trolley motion is a :class:`~pendulab.crane.paths.Path`
that can be replayed in the 3-D crane (``Crane(pivot=run.path)``). Units: m, s, rad, m/s².

SciPy's DOP853 steps in Python (about 0.5 ms a step, 0.4–0.7 ms measured), so the loop is bounded to
:data:`MAX_LOOP_STEPS` steps (minutes) before it starts, and runs in chunks of :data:`CHUNK_STEPS`
steps: a progress bar between chunks, and Ctrl-C returns the loop up to the last finished chunk's end
(the chunk under way dropped) with a RuntimeWarning (``LQRRun.interrupted``), as ``pendulab.simulate``
does. The core's ``ForceSolver`` is no faster path here: it calls a Python force for every evaluation
too, pushes the bob of a fixed pivot, and has no state for the trolley's x, ẋ that u = −K z needs.
"""

from __future__ import annotations

import contextlib
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt
from scipy.integrate import solve_ivp
from scipy.linalg import solve_continuous_are

from .. import memory
from .._core import InvalidInputError
from .._progress import seconds_bar
from .._warn import warn_user
from ..validate import flag, invalid
from ._checks import later, number, numbers, positive, real, time, times
from ._checks import rope as rope_length
from ._display import Row, Shown, lqr_rows, lqr_run_rows
from .paths import Path
from .shaper import FloatArray

# switches of the control into and out of its limit a_max that one run may have (chattering beyond)
MAX_SWITCHES = 10_000
STABLE_STEP = 6.0
"""h |p| of DOP853's steps where the loop has settled (its stability bound; 5.9–6.4 measured for
ropes 0.5–50 m): the loop over a span [s] takes about span |p| / STABLE_STEP steps, p its fastest pole."""
STEP_BYTES = 1024
"""Bytes one step of the loop keeps (SciPy's dense output; 0.9 kB measured)."""
MAX_LOOP_STEPS = 200_000
"""The most DOP853 steps one :meth:`LQR.simulate` may take: SciPy's DOP853 steps in Python at about
0.5 ms a step, so a few minutes (1.9e5 steps took 142 s on a loaded machine; a crane run's 2e7 steps,
its limit before, would be hours here)."""
PROGRESS_AFTER_STEPS = 5_000
"""Loops of more steps than this (a few seconds) show a progress bar unless told otherwise."""
CHUNK_STEPS = 200
"""Settled steps (:data:`STABLE_STEP`) of one chunk of the loop, a few tenths of a second of work (more
in the loop's transient, where its steps are shorter): the bar moves, and Ctrl-C is answered, between
chunks. The first chunk of a loop of fewer steps is the whole loop."""


def _matrices(rope: float, g: float) -> tuple[FloatArray, FloatArray]:
    a = np.array([[0, 1, 0, 0], [0, 0, 0, 0], [0, 0, 0, 1], [0, 0, -g / rope, 0]], dtype=float)
    b = np.array([[0.0], [1.0], [0.0], [-1.0 / rope]])
    return a, b


@dataclass(frozen=True, repr=False)
class LQR(Shown):
    """The LQR gain ``K`` (1, 4) for z = (x − x_target [m], ẋ [m/s], θ [rad], θ̇ [rad/s]), the closed-loop
    ``poles`` [1/s], the ``rope`` [m], ``g`` [m/s²] and the acceleration limit ``a_max`` [m/s²] (u is
    clipped to ±a_max; inf for none)."""

    K: FloatArray
    poles: npt.NDArray[np.inexact[Any]]  # eigenvalues of A − B K: complex in general
    rope: float
    g: float
    a_max: float

    def _rows(self) -> list[Row]:
        return lqr_rows(self)

    def control(self, z: FloatArray) -> FloatArray:
        """u = clip(−K z, ±a_max) [m/s²] for states z (…, 4)."""
        zz = numbers("z", z, "")
        if zz.ndim == 0 or zz.shape[-1] != 4:
            raise invalid(
                "z", z, f"states (…, 4): x − x_target [m], ẋ [m/s], θ [rad], θ̇ [rad/s] (got {zz.shape})"
            )
        return np.asarray(np.clip(-(zz @ self.K[0]), -self.a_max, self.a_max), dtype=np.float64)

    def simulate(
        self,
        distance: float,
        t_end: float,
        t_start: float = 0.0,
        sway: float = 0.0,
        *,
        progress: bool | None = None,
    ) -> LQRRun:
        """The closed loop moving the trolley by ``distance`` [m] from rest at x = 0 at ``t_start`` [s]
        (the load at the angle ``sway`` [rad]) until ``t_end`` [s], in the nonlinear planar model, at
        most :data:`MAX_LOOP_STEPS` steps (refused before it starts). ``progress`` shows a bar (default:
        for more than :data:`PROGRESS_AFTER_STEPS` steps); Ctrl-C returns the loop up to where it got
        (its ``t_end`` there, ``interrupted`` True) with a RuntimeWarning."""
        d = number("distance", distance, "m")
        t0 = time("t_start", t_start)
        t1 = later("t_end", t_end, t0)
        theta0 = number("sway", sway, "rad")
        if progress is not None:
            flag("progress", progress)
        steps = self._bound(t0, t1, t_end)
        show = steps > PROGRESS_AFTER_STEPS if progress is None else progress
        loop = _Loop(self, d)
        y: list[float] = [0.0, 0.0, theta0, 0.0]
        mode = loop.mode_at(y)
        pieces: list[tuple[float, Any]] = []
        switches: list[float] = []
        t = t0
        # chunks of CHUNK_STEPS settled steps, one solve_ivp call each; their ends depend on the input
        # alone (not on timing), so that the same call gives the same loop bit for bit
        span = (t1 - t0) * CHUNK_STEPS / max(steps, CHUNK_STEPS)
        interrupted = False
        # the bar counts seconds of simulated time (n, total in s; the rate in simulated s per s)
        bar = seconds_bar(t1 - t0, f"LQR loop, simulated s from t={t0:g}") if show else None
        with bar if bar is not None else contextlib.nullcontext():
            try:
                while t < t1:
                    sol = loop.piece(mode, t, t1 if t + span >= t1 else t + span, y)
                    pieces.append((t, sol.sol))
                    t, y = float(sol.t[-1]), sol.y[:, -1].tolist()
                    if bar is not None:
                        bar.update((t - t0) - bar.n)
                    if sol.status == 1 and t < t1:  # a switch (else the chunk's end, or t_end)
                        switches.append(t)
                        loop.check_switches(len(switches), t)
                        mode = loop.next_mode(mode, y)
            except KeyboardInterrupt:
                interrupted = True
                warn_user(
                    f"LQR.simulate interrupted at t = {t:g} s of t_end = {t1:g} s; returning the loop up to "
                    "there (the run's t_end)",
                    RuntimeWarning,
                )
        if not pieces:  # stopped before the first chunk: the start state alone
            rest = np.array([0.0, 0.0, theta0, 0.0])
            pieces.append((t0, lambda ts: np.repeat(rest[:, None], np.size(ts), axis=1)))
        return LQRRun(self, d, t0, t, _Pieces(pieces), np.array(switches), interrupted)

    def _bound(self, t0: float, t1: float, t_end: Any) -> float:
        """The steps a loop over [t0, t1] [s] takes, about; refuses more than :data:`MAX_LOOP_STEPS` or
        than fit in memory (:mod:`pendulab.memory`), before it starts."""
        rate = float(np.max(np.abs(self.poles)))
        steps = (t1 - t0) * rate / STABLE_STEP
        most, why = MAX_LOOP_STEPS, "SciPy's DOP853 steps in Python, about 0.5 ms a step: minutes"
        have = memory.available_bytes()
        if have is not None and memory.USABLE_FRACTION * have / STEP_BYTES < most:
            most = int(memory.USABLE_FRACTION * have / STEP_BYTES)
            why = f"what fits in the {have / 2**30:.3g} GiB this process can get, {STEP_BYTES} B a step"
        if steps > most:
            raise invalid(
                "t_end",
                t_end,
                f"at most {most} steps of the closed loop ({why}); over {t1 - t0:.6g} s from t_start = "
                f"{t0:g} s it takes about {steps:.3g} (DOP853 steps of at most about {STABLE_STEP:g}/|p| = "
                f"{STABLE_STEP / rate:.3g} s, |p| = {rate:.3g} 1/s its fastest pole): a shorter t_end "
                f"(t_end - t_start <= {most * STABLE_STEP / rate:.3g} s)",
            )
        return steps


class _Loop:
    """The closed loop to the target ``distance`` [m]. u = clip(−K z, ±a_max) kinks where the clip starts
    and stops acting: the loop is integrated piecewise in three modes (0 free: u = −K z; ±1 saturated:
    u = ±a_max), each smooth, switching at the roots of −K z ∓ a_max (terminal events); the switch
    times are the path's breaks."""

    def __init__(self, ctrl: LQR, distance: float) -> None:
        self.rope, self.g, self.a_max, self.k, self.d = ctrl.rope, ctrl.g, ctrl.a_max, ctrl.K[0], distance

    def gain(self, y: Any) -> float:
        """−K z [m/s²] at the state y = (x, ẋ, θ, θ̇)."""
        return -float(self.k @ np.array([y[0] - self.d, y[1], y[2], y[3]]))

    def mode_at(self, y: Any) -> int:
        u = self.gain(y)
        return 1 if u > self.a_max else -1 if u < -self.a_max else 0

    def next_mode(self, mode: int, y: Any) -> int:
        """Out of saturation into the free mode, or from it into the limit on the side of u's sign."""
        return 0 if mode != 0 else (1 if self.gain(y) > 0 else -1)

    def _event(self, level: float, direction: int) -> Any:
        def ev(_t: float, y: FloatArray) -> float:
            return self.gain(y) - level

        ev.terminal, ev.direction = True, direction  # type: ignore[attr-defined]
        return ev

    def piece(self, mode: int, t: float, stop: float, y: list[float]) -> Any:
        """SciPy's DOP853 solution in ``mode`` from (t, y) to ``stop`` [s] or the next switch."""
        big_l, g, a_max = self.rope, self.g, self.a_max

        def rhs(_t: float, y: FloatArray) -> list[float]:
            u = self.gain(y) if mode == 0 else mode * a_max
            return [y[1], u, y[3], -(g * math.sin(y[2]) + u * math.cos(y[2])) / big_l]

        if not math.isfinite(a_max):
            events: list[Any] = []
        elif mode == 0:  # leaves the free mode when −K z rises through a_max or falls through −a_max
            events = [self._event(a_max, 1), self._event(-a_max, -1)]
        else:  # leaves saturation when −K z comes back inside (−a_max, a_max)
            events = [self._event(mode * a_max, -mode)]
        sol = solve_ivp(
            rhs,
            (t, stop),
            y,
            method="DOP853",
            rtol=1e-11,
            atol=1e-12,
            dense_output=True,
            events=events or None,
        )
        if not sol.success:
            raise InvalidInputError(f"the closed loop could not be integrated: {sol.message}")
        return sol

    def check_switches(self, n: int, t: float) -> None:
        if n > MAX_SWITCHES:
            raise InvalidInputError(
                f"the control switched into and out of its limit a_max = {self.a_max:g} m/s² more than "
                f"{MAX_SWITCHES} times before t = {t:g} s (chattering): use a smaller gain or a larger a_max"
            )


class _Pieces:
    """The dense outputs of the loop's pieces [(start [s], OdeSolution)], evaluated as one."""

    def __init__(self, pieces: list[tuple[float, Any]]) -> None:
        self.starts = np.array([a for a, _ in pieces])
        self.sols = [f for _, f in pieces]

    def __call__(self, t: FloatArray) -> FloatArray:
        idx = np.clip(np.searchsorted(self.starts, t, side="right") - 1, 0, len(self.sols) - 1)
        out = np.empty((4, t.size))
        for i in np.unique(idx):
            sel = idx == i
            out[:, sel] = self.sols[i](t[sel])
        return out


class LQRRun(Path, Shown):
    """A closed-loop run: ``trolley(t)`` (x, ẋ, u), ``sway(t)`` θ [rad]; as a :class:`Path` along e₁ the
    trolley position [m], velocity and acceleration u (at rest at x = 0 before t_start, held at rest
    after t_end). Its ``breaks``: t_start (u steps from 0 to −K z₀) and ``switches``, the times [s]
    where the limit ±a_max starts or stops clipping u (P̈ kinks), so that the crane's integrator ends
    its steps there. A crane run past t_end is refused: the loop's trolley has not stopped then in
    general, and the hold would stop it dead (simulate the loop as long as the crane run).
    ``interrupted``: Ctrl-C stopped the loop, at its ``t_end``, before the t_end asked."""

    def __init__(
        self,
        ctrl: LQR,
        distance: float,
        t0: float,
        t1: float,
        dense: Any,
        switches: Any = (),
        interrupted: bool = False,
    ) -> None:
        self.ctrl, self.distance, self._dense = ctrl, distance, dense
        self.interrupted = interrupted
        self.span = (t0, t1)
        self.switches = np.asarray(switches, dtype=np.float64)
        self.breaks = np.union1d([t0], self.switches)
        self.t_end = t1

    def _rows(self) -> list[Row]:
        return lqr_run_rows(self)

    def check_run(self, t_start: float, t_end: float) -> None:
        if t_end > self.span[1]:
            raise InvalidInputError(
                f"the LQR run ends at t_end = {self.span[1]:.10g} s, but the crane run goes on to t_end = "
                f"{t_end:.10g} s: simulate the closed loop as long (LQR.simulate(..., t_end={t_end:.10g}))"
            )

    def _state(self, t: FloatArray) -> FloatArray:
        tc = np.clip(t, *self.span)
        return np.asarray(self._dense(tc).T, dtype=np.float64)  # (N, 4)

    def trolley(self, t: Any, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Trolley position [m], velocity [m/s], acceleration [m/s²] at times t [s] (at t_start those
        after it, or with ``left`` those before: at rest; at rest outside [t_start, t_end])."""
        ts = np.atleast_1d(times("t", t))
        y = self._state(ts)
        z = y - np.array([self.distance, 0.0, 0.0, 0.0])
        a, b = self.span
        inside = (ts > a) & (ts <= b) | ((ts == a) & (not left))
        return y[:, 0], np.where(inside, y[:, 1], 0.0), np.where(inside, self.ctrl.control(z), 0.0)

    def sway(self, t: Any) -> FloatArray:
        """The load's angle θ(t) [rad] in the planar model."""
        return self._state(np.atleast_1d(times("t", t)))[:, 2]

    def _pva(self, t: FloatArray, left: bool = False) -> tuple[FloatArray, FloatArray, FloatArray]:
        x, v, a = self.trolley(t, left)
        zero = np.zeros((t.size, 3))
        p, dp, ddp = zero.copy(), zero.copy(), zero.copy()
        p[:, 0], dp[:, 0], ddp[:, 0] = x, v, a
        return p, dp, ddp


def lqr(
    rope: float,
    g: float = 9.81,
    q: tuple[float, float, float, float] = (1.0, 1.0, 10.0, 1.0),
    r: float = 1.0,
    a_max: float = math.inf,
) -> LQR:
    """The LQR anti-sway controller for a trolley with a load on ``rope`` [m] (module doc): diagonal
    weights ``q`` on (x [m], ẋ [m/s], θ [rad], θ̇ [rad/s]) (≥ 0), ``r`` > 0 on u [m/s²], the
    acceleration limit ``a_max`` [m/s²] (> 0; inf: none)."""
    big_l = rope_length("rope", rope)
    gg = positive("g", g, "m/s²")
    qq = numbers("q", q, "", shape=(4,))
    if np.any(qq < 0) or qq[0] == 0:
        raise invalid("q", q, "four finite weights >= 0, the first > 0")
    rr = positive("r", r, "")
    # inf is the documented "no limit" (the default), the one non-finite value taken
    unlimited = isinstance(a_max, float | np.floating) and a_max == math.inf
    am = (
        math.inf
        if unlimited
        else real("a_max", a_max, "a finite number > 0 m/s² (inf: no limit)", lambda x: x > 0)
    )
    a, b = _matrices(big_l, gg)
    p = solve_continuous_are(a, b, np.diag(qq), np.array([[rr]]))
    k = (b.T @ p) / rr
    poles = np.linalg.eigvals(a - b @ k)
    return LQR(k, poles, big_l, gg, am)
