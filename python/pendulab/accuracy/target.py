"""Runs to a requested accuracy: ``simulate(..., accuracy=a)`` with a the largest position error
allowed over the whole run, relative to the length l (global, up to t_end).

The method: RATTLE8 (the 8th-order symplectic composition, T-2.4 with the constraint kept exactly;
its global error grows only linearly in t, where DOP853's local error control lets the energy drift and
the error grow like t²: docs/integrators.md); when RATTLE8 stalls on round-off, DOP853 with
``conserve=True`` (E and J₃ projected) from rtol 1e-12 down; DOP853 without ``conserve`` for a
pendulum with a user force (which the RATTLE family cannot take; the force does work).

The step: a first guess dt = 0.5·a^{1/8}/ω from the motion's fastest rate ω = max(√(|g|/l), |v₀|/l)
[1/s] (a tolerance a for DOP853), on a sampled pivot at most its samples' spacing Δ (the mean over the
run) and a whole fraction Δ/n of it, then runs with the error estimate of
:mod:`pendulab.accuracy.estimate`, each refining dt by (estimate/a)^{1/p} (times 0.8, at least ×1/2)
until the estimate meets a. When refining no longer lowers the estimate — round-off, not truncation,
dominates — it raises :class:`pendulab.InvalidInputError` with the best accuracy float64 reached for
this motion. Work is bounded before every run: at most ``MAX_STEPS`` steps.

On a sampled pivot the runs take their steps on the samples (``steps_on_samples=True``): dt is the
longest step, and each interval between samples is taken in ⌈span/dt⌉ equal steps, so that no step
holds a sample, where p̈ is kinked. A plain step that holds one is split there: on unevenly spaced
samples nearly every step splits in two of uneven length, more steps for the same dt whose error
does not fall as dt^p when dt is refined near the spacing (docs/integrators.md). On evenly spaced
samples Δ/n puts the plain grid on every sample from a start on one, and the run is the plain run
bit for bit (a step longer than Δ split on every sample: dt = 16 ms on 10-ms samples took 1626
steps for 10 s at a = 1e-8, dt = Δ 1000, with less error).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import InvalidInputError
from ..model import Pendulum, State
from ..trajectory import Trajectory

#: The most steps one run of the search may take.
MAX_STEPS = 2e8
#: The most runs the search makes.
MAX_ROUNDS = 8
ORDER_RATTLE8 = 8

Runner = Callable[..., Trajectory]


def _rate(pendulum: Pendulum, state: State) -> float:
    """The motion's fastest rate ω [1/s]: √(|g|/l) or |v₀|/l, whichever is larger."""
    speed = math.sqrt(float(sum(c * c for c in state.v)))
    return max(math.sqrt(abs(pendulum.g) / pendulum.length), speed / pendulum.length, 1e-12)


def _spacing(pendulum: Pendulum, span: float, t0: float) -> float:
    """A sampled pivot's sample spacing Δ [s] over the run [t0, t0 + span] (the mean, from the samples
    next to the run: exact to round-off for uniform samples); +∞ for every other pivot."""
    samples = pendulum.pivot_samples
    if samples is None:
        return math.inf
    times = np.asarray(samples[0], dtype=float)
    first, last = np.searchsorted(times, [t0, t0 + span])
    lo, hi = max(int(first) - 1, 0), min(int(last), times.size - 1)
    return float((times[hi] - times[lo]) / (hi - lo)) if hi > lo else math.inf


def _on_samples(dt: float, spacing: float) -> float:
    """``dt`` [s] capped at the samples' ``spacing`` [s] as its largest whole fraction Δ/n ≤ dt."""
    return dt if not math.isfinite(spacing) else spacing / math.ceil(spacing / dt * (1 - 1e-12))


def check_accuracy(accuracy: float) -> float:
    """The requested accuracy as a float in [1e-15, 0.1], or InvalidInputError naming it."""
    try:
        a = float(accuracy)
    except (TypeError, ValueError):
        raise InvalidInputError(f"accuracy = {accuracy!r} must be a number (relative to l)") from None
    if not (1e-15 <= a <= 0.1):
        raise InvalidInputError(
            f"accuracy = {accuracy!r}: allowed is 1e-15 <= accuracy <= 0.1 (the largest position error "
            "over the run relative to the length l)"
        )
    return a


def run_to_accuracy(
    run: Runner, pendulum: Pendulum, state: State, t_end: float, accuracy: float, kwargs: dict[str, Any]
) -> Trajectory:
    """Runs ``run(pendulum, state, t_end, error_estimate=True, ...)`` with a method and step (or
    tolerance) chosen and refined until ``tr.error_estimate.max_position <= accuracy * l``."""
    a = check_accuracy(accuracy)
    for key in ("method", "dt", "rtol", "atol"):
        if kwargs.get(key) is not None:
            raise InvalidInputError(
                f"accuracy = {accuracy!r} chooses the method and its step or tolerance itself: "
                f"leave out {key} = {kwargs[key]!r}"
            )
    span = t_end - float(kwargs.get("t0", 0.0))
    if not (span > 0 and math.isfinite(span)):
        raise InvalidInputError(f"t_end = {t_end!r} must be finite and after t0 for accuracy = {accuracy!r}")
    base = {k: v for k, v in kwargs.items() if k not in ("method", "dt", "rtol", "atol")}
    goal = a * pendulum.length
    history: list[tuple[str, float]] = []
    if pendulum.force is not None:
        tr = _dop853_search(run, pendulum, state, t_end, a, base, history, a, conserve=False)
        if tr is not None:
            return tr
        raise _best(a, pendulum, history)
    spacing = _spacing(pendulum, span, float(kwargs.get("t0", 0.0)))
    if pendulum.pivot_samples is not None:
        base["steps_on_samples"] = True
    dt = _on_samples(0.5 * a ** (1.0 / ORDER_RATTLE8) / _rate(pendulum, state), spacing)
    for _ in range(MAX_ROUNDS):
        if span / dt > MAX_STEPS:
            raise InvalidInputError(
                f"accuracy = {accuracy!r} needs more than {MAX_STEPS:.0e} steps of RATTLE8 "
                f"to t_end = {t_end!r} s "
                f"(dt = {dt:.2e} s); ask for less or a shorter run"
                + (
                    f" (tried: {', '.join(f'{h}: {e / pendulum.length:.1e}' for h, e in history)})"
                    if history
                    else ""
                )
            )
        tr = run(pendulum, state, t_end, method="rattle8", dt=dt, error_estimate=True, **base)
        err = _max_position(tr)
        history.append((f"dt {dt:.2e} s", err))
        if err <= goal:
            return _tagged(tr, a, history)
        if len(history) > 1 and err >= 0.5 * history[-2][1]:
            break  # refining no longer helps: round-off
        dt = _on_samples(dt * min(0.5, 0.8 * (goal / err) ** (1.0 / ORDER_RATTLE8)), spacing)
    # RATTLE8 stalled on round-off (e.g. next to the top, where each step's rounding of E becomes a
    # phase error): DOP853 with E and J₃ projected (conserve=True) from rtol 1e-12 down
    try:
        tr = _dop853_search(run, pendulum, state, t_end, a, base, history, 1e-12, conserve=True)
    except InvalidInputError:  # conserve refused (damping or drag: E and J₃ decay)
        tr = None
    if tr is not None:
        return tr
    raise _best(a, pendulum, history)


def _dop853_search(
    run: Runner,
    pendulum: Pendulum,
    state: State,
    t_end: float,
    a: float,
    base: dict[str, Any],
    history: list[tuple[str, float]],
    tol: float,
    conserve: bool,
) -> Trajectory | None:
    """DOP853 runs with the estimate from rtol = ``tol`` down (×1/10 or as the estimate asks, at least
    to 1e-15) until the estimate meets ``a`` l (that run is returned) or stops falling (None)."""
    goal = a * pendulum.length
    last = math.inf
    for _ in range(MAX_ROUNDS):
        rtol = max(tol, 1e-15)
        kw = base | {"conserve": conserve} if conserve else base
        tr = run(
            pendulum, state, t_end, method="dop853", rtol=rtol, atol=rtol * 1e-2, error_estimate=True, **kw
        )
        err = _max_position(tr)
        history.append((f"dop853{' conserve' if conserve else ''} rtol {rtol:.0e}", err))
        if err <= goal:
            return _tagged(tr, a, history)
        if rtol <= 1e-15 or err >= 0.5 * last:
            return None
        last = err
        tol = rtol * min(0.1, 0.5 * goal / err)
    return None


def _max_position(tr: Trajectory) -> float:
    """The estimated largest position error [m] of a run made with ``error_estimate=True``."""
    estimate = tr.error_estimate
    assert estimate is not None, "a run with error_estimate=True carries its estimate"
    return estimate.max_position


def _tagged(tr: Trajectory, a: float, history: list[tuple[str, float]]) -> Trajectory:
    tr.options["accuracy"] = a
    tr.options["accuracy_search"] = [f"{h}: {e:.2e} m" for h, e in history]
    return tr


def _best(a: float, pendulum: Pendulum, history: list[tuple[str, float]]) -> InvalidInputError:
    best = min(e for _, e in history) / pendulum.length
    tried = ", ".join(f"{h}: {e / pendulum.length:.1e}" for h, e in history)
    return InvalidInputError(
        f"accuracy = {a!r} is out of reach in float64 for this motion: the best estimated error was "
        f"{best:.1e} relative to l (tried {tried}); ask for accuracy >= {2 * best:.0e}"
    )
