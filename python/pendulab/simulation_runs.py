"""The runs of :func:`pendulab.simulate`, one function per kind, each from the checked
:class:`~pendulab.simulation_settings.RunSettings`: a rod model in the core's solver, in chunks with a
progress bar and Ctrl-C (``_run_in_core``; every fixed step halved for the error estimate's dt/2
companion), the string model's hybrid run (``_run_string``), and the check that an unprojected run
kept its rod (``_check_drift``, :data:`DRIFT_TOLERANCE`). SI units: t [s], x [m], v [m/s]."""

from __future__ import annotations

from typing import Any

import numpy as np

from ._chunks import _PROGRESS_AFTER_STEPS, run_in_chunks
from ._core import ForceSolver, IntegrationError, InvalidInputError, RunOptions, Solver
from ._warn import warn_user
from .integrators import DEFAULTS, _check_conserve, _method_table, unknown_method
from .memory import SAMPLE_BYTES, SAMPLE_COPIES, check_memory, saved_bytes_cap
from .model import Pendulum, State
from .simulation_settings import RunSettings
from .trajectory import Trajectory
from .validate import planned_steps

DRIFT_TOLERANCE = 1e-2
"""The largest relative constraint error |(|x| − l)/l| an unprojected run (``rk4``, ``dop853`` with
``project=False``) may reach before :func:`pendulab.simulate` stops it with :class:`pendulab.IntegrationError`
(``drift="warn"``: a warning instead). 1 % of the rod: beyond it the run no longer describes a rod."""


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
    )


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
        steps_on_samples=run.steps_on_samples,
    )
    solver: Solver | ForceSolver
    if pendulum.force is not None:  # the slow path: the core calls back into Python (force.rs)
        solver = ForceSolver(pendulum.spec, state.pair, options, pendulum.force)
    else:
        solver = Solver(pendulum.spec, state.pair, options)
    expected_steps = (t_end - t0) / dt if dt > 0 and not info["adaptive"] else 0.0
    show = run.progress if run.progress is not None else expected_steps > _PROGRESS_AFTER_STEPS
    parts, interrupted = run_in_chunks(solver, show, method)
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
    if run.steps_on_samples and pendulum.pivot_samples is not None and not info["adaptive"]:
        meta["steps_on_samples"] = True
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
        warn_user(msg, RuntimeWarning)
        return
    raise IntegrationError(msg)
