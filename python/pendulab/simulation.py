"""Batch simulation on top of the core's chunked solver (the incremental stepper: ``stepper.py``; the
integrators and the settings both check: ``integrators.py``).

``simulate`` advances the core solver in chunks of about 0.1 s of work with the GIL released,
updating a tqdm progress bar between chunks; Ctrl-C stops cleanly after the current chunk and
returns what was computed so far (``Trajectory.interrupted`` is True, and a warning says so).
Saving is separate from stepping: 10⁸ steps with ``save_every=10_000`` keep only 10⁴ samples.
"""

from __future__ import annotations

import dataclasses
import inspect
import warnings
from typing import Any

import numpy as np

from ._chunks import _PROGRESS_AFTER_STEPS, run_in_chunks
from ._core import ForceSolver, IntegrationError, InvalidInputError, RunOptions, Solver
from .accuracy import estimate, run_to_accuracy, true_error
from .integrators import (
    _U64,
    DEFAULTS,
    _check_conserve,
    _method_table,
    check_arithmetic,
    check_settings,
    unknown_method,
)
from .memory import SAMPLE_BYTES, SAMPLE_COPIES, check_memory, saved_bytes_cap
from .model import Pendulum, State, check_pendulum_state
from .trajectory import Trajectory
from .validate import LIMITS, MAX_SAMPLES, array, choice, flag, integer, invalid, number, planned_steps

DRIFT_TOLERANCE = 1e-2
"""The largest relative constraint error |(|x| − l)/l| an unprojected run (``rk4``, ``dop853`` with
``project=False``) may reach before :func:`simulate` stops it with :class:`pendulab.IntegrationError`
(``drift="warn"``: a warning instead). 1 % of the rod: beyond it the run no longer describes a rod."""


def simulate(
    pendulum: Pendulum,
    state: State,
    t_end: float,
    *,
    method: str | None = None,
    dt: float | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    project: bool = True,
    conserve: bool = False,
    save_every: int | None = None,
    save_at: Any = None,
    t0: float = 0.0,
    progress: bool | None = None,
    max_saved_bytes: int | None = None,
    error_estimate: bool = False,
    accuracy: float | None = None,
    drift: str = "raise",
    arithmetic: str = "auto",
) -> Trajectory:
    """Integrates from ``state`` at time ``t0`` [s] to ``t_end`` [s].

    Parameters
    ----------
    pendulum : the :class:`Pendulum` (model and parameters, SI units).
    state : the start, a :class:`State` on TS² of this pendulum (``pendulum.state_from_angles(...)``).
    t_end : the end time [s] (> ``t0``).
    method : a name from :func:`methods` (default ``"rattle"``; ``"dop853"`` for a pendulum with a
        user ``force`` callable, which the RATTLE family cannot integrate).
    dt : step size [s] (default 1e-3 s); for ``dop853`` its first step (default None: automatic; never 0).
    rtol, atol : tolerances of ``dop853`` (atol in m and m/s).
    project : ``dop853`` only: project onto TS² after every step (default True).
    conserve : ``dop853`` only (with ``project``): also project the velocity so that E (conservative
        models) and J₃ (axisymmetric ones) keep their initial values — removes the linear energy drift
        that near the separatrix turns into a growing phase error (docs/integrators.md). Refused for
        models with damping or drag, whose E and J₃ decay.
    save_every : keep every n-th step (default 1), plus the initial and final states.
    save_at : array of times [s] to keep instead (dense output for ``dop853``; fixed-step methods
        land on each time exactly).
    t0 : the start time [s] of ``state`` (default 0.0).
    progress : show a progress bar (default: only for runs of more than 5·10⁶ steps).
    max_saved_bytes : memory limit for saved samples [bytes] (default 4 GiB, or less: a third of 80 % of
        the memory this process can still get); exceeding it is an error
        raised before the run starts (fixed-step methods) or when reached (``dop853``).
    error_estimate : also estimate the global error at every sample, ``tr.error_estimate`` (position
        [m], velocity [m/s]): Richardson against a run at 2·dt (fixed-step methods; at dt/2 when the
        save times are off the 2·dt grid or the 2·dt run is unstable or not asymptotic), a companion
        run at a 10× tighter tolerance (``dop853``); for the ideal pendulum also the true error against
        the exact solution, ``tr.error``. The reference run costs 0.5× the plain run (2·dt), 2–2.5×
        (dt/2), ≈ 1.3× (``dop853``); docs/integrators.md, "Error estimates".
    accuracy : the largest position error allowed over the run, relative to l (1e-15 … 0.1): chooses
        the method (RATTLE8; DOP853 with a user force) and its step or tolerance, refining until the
        estimate meets it, or raises ``InvalidInputError`` with the best float64 reached. Do not give
        ``method`` or ``dt`` with it. Implies ``error_estimate``.
    drift : what a run that does not keep TS² (``rk4``; ``dop853`` with ``project=False``) does when its
        constraint error |(|x| − l)/l| passes :data:`DRIFT_TOLERANCE` (1e-2): ``"raise"`` (default) an
        :class:`pendulab.IntegrationError` saying what to do, ``"warn"`` a ``RuntimeWarning`` and the
        trajectory as computed.
    arithmetic : the RATTLE family's multiply-adds a·b + c: ``"auto"`` (default) is ``"fused"`` where
        the CPU does a fused multiply-add in one instruction (x86-64 with AVX2+FMA or AVX-512, every
        aarch64) and ``"unfused"`` elsewhere; ``"unfused"`` (two roundings) and
        ``"fused"`` (``f64::mul_add``, one rounding; 3–25× slower on CPUs without FMA) each give the
        same bits on every CPU, the unfused ones also those of the lab page's WebAssembly engine. Give
        one of them by name for results that are bit-identical across machines; a fused run says so in
        ``metadata["arithmetic"]`` (docs/performance.md, "No CPU left behind").
        ``simulate_ensemble`` gives each trajectory these numbers bit for bit.

    Every argument is checked against :mod:`pendulab.validate` before any work starts (docs/limits.md).

    The ``"string"`` model (a rope that goes slack) is hybrid and runs in
    :func:`pendulab.variants.string_pendulum.simulate_string`: methods rattle, rattle4, rattle6, rattle8 or
    rkmk4 with ``dt`` in the taut phases, ``save_every`` or ``save_at``, progress and Ctrl-C as here.

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> s0 = p.state_from_angles(theta=np.radians(60), phi_dot=2.0)
    >>> tr = pl.simulate(p, s0, t_end=1.0, dt=1e-3, save_every=100)
    >>> tr.t
    array([0. , 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1. ])
    >>> bool(abs(tr.energy - tr.energy[0]).max() < 1e-4)  # J: RATTLE's energy error at dt = 1 ms
    True
    >>> tr.method
    'rattle'
    """
    check_pendulum_state(pendulum, state)
    drift = choice("drift", drift, ("raise", "warn"))
    if accuracy is not None or error_estimate:  # pendulab/accuracy: a plain run plus a reference run
        plain = {
            "method": method,
            "dt": dt,
            "rtol": rtol,
            "atol": atol,
            "project": project,
            "conserve": conserve,
            "save_every": save_every,
            "save_at": save_at,
            "t0": t0,
            "progress": progress,
            "max_saved_bytes": max_saved_bytes,
            "drift": drift,
            "arithmetic": arithmetic,
        }
        return _with_error_estimate(pendulum, state, t_end, accuracy, plain)
    run = check_run(
        pendulum,
        t_end,
        method=method,
        dt=dt,
        rtol=rtol,
        atol=atol,
        project=project,
        conserve=conserve,
        save_every=save_every,
        save_at=save_at,
        t0=t0,
        progress=progress,
        max_saved_bytes=max_saved_bytes,
        drift=drift,
        arithmetic=arithmetic,
    )
    if pendulum.model == "string":  # hybrid: taut phases, events, analytic flight (string_pendulum.py)
        return _run_string(pendulum, state, run)
    return _run_in_core(pendulum, state, run)


def _with_error_estimate(
    pendulum: Pendulum, state: State, t_end: float, accuracy: float | None, plain: dict[str, Any]
) -> Trajectory:
    """``accuracy``: refined until the estimate meets it (pendulab/accuracy); else ``error_estimate``:
    the plain run with its estimated error and, for the ideal pendulum, its true error."""
    if accuracy is not None:
        plain = {k: v for k, v in plain.items() if k not in ("rtol", "atol")}
        return run_to_accuracy(simulate, pendulum, state, t_end, accuracy, plain)
    tr = simulate(pendulum, state, t_end, **plain)
    if tr.interrupted:
        return tr
    est = estimate(simulate, tr, state, plain | {"method": tr.method}, run_halved=_simulate_halved)
    return dataclasses.replace(tr, error_estimate=est, error=true_error(pendulum, state, tr))


@dataclasses.dataclass(frozen=True)
class RunSettings:
    """The settings of one :func:`simulate` run, checked (:func:`check_run`): SI units, t0 < t_end [s];
    ``dt`` None for the method's default (1 ms; dop853: automatic), ``save_at`` the save times [s]."""

    method: str
    dt: float | None
    rtol: float
    atol: float
    project: bool
    conserve: bool
    t0: float
    t_end: float
    save_every: int | None
    save_at: Any
    progress: bool | None
    max_saved_bytes: int | None
    drift: str
    arithmetic: str = "unfused"


def check_run(
    pendulum: Pendulum,
    t_end: Any,
    *,
    method: Any,
    dt: Any,
    rtol: Any,
    atol: Any,
    project: Any,
    conserve: Any,
    save_every: Any,
    save_at: Any,
    t0: Any,
    progress: Any,
    max_saved_bytes: Any,
    drift: str,
    arithmetic: Any = "auto",
) -> RunSettings:
    """Every argument of :func:`simulate` checked against :mod:`pendulab.validate` before any work
    starts (docs/limits.md), as one :class:`RunSettings`."""
    if method is None:
        method = "dop853" if pendulum.force is not None else "rattle"
    method, dt, rtol, atol, project, conserve, t0 = check_settings(
        method=method, dt=dt, rtol=rtol, atol=atol, project=project, conserve=conserve, t0=t0
    )
    t_end = number("t_end", t_end, "time")
    if not t_end > t0:
        raise invalid("t_end", t_end, f"a time after t0 = {t0!r} s")
    if progress is not None:
        progress = flag("progress", progress)
    if max_saved_bytes is not None:
        lim = LIMITS["saved_bytes"]
        max_saved_bytes = integer(
            "max_saved_bytes", max_saved_bytes, int(lim["min"]), int(lim["max"]), lim["allowed"]
        )
    if save_every is not None:
        save_every = integer("save_every", save_every, 1, _U64)
    if save_at is not None:
        save_at = array("save_at", save_at, "time", max_size=MAX_SAMPLES).ravel()
    if dt is not None and not _method_table()[method]["adaptive"]:
        planned_steps(t0, t_end, dt)
    if pendulum.force is not None and conserve:
        raise InvalidInputError(
            "conserve=True would hold E and J₃ fixed, but the user force does work (dE/dt = F·v)"
        )
    arithmetic = check_arithmetic(arithmetic, method, pendulum.model)
    if arithmetic == "fused" and pendulum.model == "string":
        raise InvalidInputError(
            "arithmetic='fused' is not available for the 'string' model (its stepper is unfused)"
        )
    return RunSettings(
        method,
        dt,
        rtol,
        atol,
        project,
        conserve,
        t0,
        t_end,
        save_every,
        save_at,
        progress,
        max_saved_bytes,
        drift,
        arithmetic,
    )


def _run_string(pendulum: Pendulum, state: State, run: RunSettings) -> Trajectory:
    """The string pendulum's hybrid run (variants/string_pendulum.py)."""
    from .variants.string_pendulum import check_string_settings, simulate_string

    check_string_settings(run.method, conserve=run.conserve)
    return simulate_string(
        pendulum,
        state,
        run.t_end,
        method=run.method,
        dt=run.dt,
        save_every=run.save_every,
        save_at=run.save_at,
        t0=run.t0,
        progress=run.progress,
        max_saved_bytes=run.max_saved_bytes,
        _stacklevel=4,
    )


def _simulate_halved(pendulum: Pendulum, state: State, t_end: float, **kwargs: Any) -> Trajectory:
    """:func:`simulate` with every fixed step (each sub-step on a sampled pivot, each shortened one) taken
    as two equal halves (``RunOptions.halved_steps``): the error estimate's dt/2 companion."""
    given, skip = inspect.signature(simulate).parameters.items(), ("error_estimate", "accuracy")
    defaults = {k: p.default for k, p in given if p.kind == p.KEYWORD_ONLY and k not in skip}
    run = check_run(pendulum, t_end, **(defaults | kwargs))
    return _run_in_core(pendulum, state, run, halved=True)


def _run_in_core(pendulum: Pendulum, state: State, run: RunSettings, halved: bool = False) -> Trajectory:
    """The run of a rod model in the core's ``Solver`` (``ForceSolver`` with a user force), in chunks
    (progress bar, Ctrl-C), as a :class:`Trajectory`; ``halved``: every fixed step as two halves."""
    method, t0, t_end, save_every, save_at = run.method, run.t0, run.t_end, run.save_every, run.save_at
    if pendulum.pivot_samples is not None:
        first, last = float(pendulum.pivot_samples[0][0]), float(pendulum.pivot_samples[0][-1])
        if not (first <= t0 and t_end <= last):
            raise InvalidInputError(
                f"the run [t0, t_end] = [{t0!r}, {t_end!r}] s leaves the pivot samples' span "
                f"[{first!r}, {last!r}] s: give samples covering the whole run"
            )
    info = _method_table().get(method)
    if info is None:
        raise InvalidInputError(unknown_method(method))
    dt = run.dt
    if dt is None:
        dt = 0.0 if info["adaptive"] else DEFAULTS["dt"]
        if not info["adaptive"]:
            planned_steps(t0, t_end, dt)
    if save_every is not None and save_at is not None:
        raise InvalidInputError("give either save_every or save_at, not both")
    _check_conserve(pendulum, run.conserve)
    times = None if save_at is None else np.ascontiguousarray(np.asarray(save_at, dtype=np.float64).ravel())
    if times is not None:  # the core copies the times, then keeps a sample at each (issue 30)
        check_memory(
            f"a run saving {times.size} times",
            times.size * (8.0 + SAMPLE_BYTES * SAMPLE_COPIES),
            "ask for fewer save_at times (or run in pieces)",
        )
    options = RunOptions(
        t0=float(t0),
        t_end=float(t_end),
        method=method,
        dt=float(dt),
        rtol=float(run.rtol),
        atol=float(run.atol),
        project=bool(run.project),
        conserve=bool(run.conserve),
        save_every=None if save_every is None else int(save_every),
        save_times=times,
        max_saved_bytes=saved_bytes_cap(run.max_saved_bytes),  # within the memory left (issue 30)
        arithmetic=run.arithmetic,
        halved_steps=halved,
    )
    solver: Solver | ForceSolver
    if pendulum.force is not None:  # the slow path: the core calls back into Python (force.rs)
        solver = ForceSolver(pendulum.spec, state.pair, options, pendulum.force)
    else:
        solver = Solver(pendulum.spec, state.pair, options)
    expected_steps = (t_end - t0) / dt if dt > 0 and not info["adaptive"] else 0.0
    show = run.progress if run.progress is not None else expected_steps > _PROGRESS_AFTER_STEPS
    parts, interrupted = run_in_chunks(solver, show, f"{method} to t={t_end:g} s", stacklevel=3)
    t = np.concatenate([p[0] for p in parts])
    x = np.concatenate([p[1] for p in parts])
    v = np.concatenate([p[2] for p in parts])
    meta: dict[str, Any] = {"dt": dt, "t0": t0, "t_end": t_end}
    if run.arithmetic != "unfused":
        meta["arithmetic"] = run.arithmetic
    if info["adaptive"]:  # no step size: its tolerances, a given first step (0.1.0 wrote "dt": 0.0)
        meta |= {"rtol": run.rtol, "atol": run.atol, "project": run.project, "first_step": meta.pop("dt")}
        meta = {k: v for k, v in meta.items() if k != "first_step" or dt > 0}
    if save_every is not None:
        meta["save_every"] = int(save_every)
    if times is not None:
        meta["save_at_times"] = int(times.size)  # how many save_at times were asked for
    if not info["preserves_ts2"] and not (info["adaptive"] and run.project):
        _check_drift(pendulum, t, x, v, method, run.project, run.drift)
    return Trajectory(pendulum, t, x, v, method, meta, dict(solver.stats), interrupted)


def _check_drift(pendulum: Pendulum, t: Any, x: Any, v: Any, method: str, project: bool, drift: str) -> None:
    """Stops (or warns about) an unprojected run whose |(|x| − l)/l| passed :data:`DRIFT_TOLERANCE`
    (l(t) of a hoisted rope, from the core's diagnostics)."""
    if pendulum.model == "hoisted":
        err = np.abs(pendulum.diagnostics(x, v, t)["radius_error"]) / pendulum.length
    else:
        err = np.abs(np.linalg.norm(x, axis=1) / pendulum.length - 1.0)
    bad = np.flatnonzero(~(err <= DRIFT_TOLERANCE))
    if bad.size == 0:
        return
    k = int(bad[0])
    how = (
        "use project=True (the default) or a method that keeps TS² such as 'rattle'"
        if method == "dop853"
        else "use 'rattle' (or another method that keeps TS²), or a smaller dt"
    )
    msg = (
        f"method {method!r}{' with project=False' if method == 'dop853' and not project else ''} left TS²: "
        f"the constraint error |(|x| - l)/l| = {float(err[k]):.3g} at t = {float(t[k]):.6g} s passed the "
        f"tolerance {DRIFT_TOLERANCE:g}; {how} (drift='warn' keeps the run with a warning)"
    )
    if drift == "warn":
        warnings.warn(msg, RuntimeWarning, stacklevel=4)
        return
    raise IntegrationError(msg)
