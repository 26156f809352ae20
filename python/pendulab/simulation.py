"""Batch simulation on top of the core's chunked solver: :func:`simulate`, which checks its arguments
into one settings object (``simulation_settings.py``), then hands them to the run of its kind
(``simulation_runs.py``: a rod model in the core, the string model's hybrid run) or, for ``accuracy``
and ``error_estimate``, to a plain run with its reference run (``accuracy/``). The incremental
stepper: ``stepper.py``; the integrators and the settings both check: ``integrators.py``.

``simulate`` advances the core solver in chunks of about 0.1 s of work with the GIL released,
updating a tqdm progress bar between chunks; Ctrl-C stops cleanly after the current chunk and
returns what was computed so far (``Trajectory.interrupted`` is True, and a warning says so).
Saving is separate from stepping: 10⁸ steps with ``save_every=10_000`` keep only 10⁴ samples.
"""

from __future__ import annotations

import dataclasses
import inspect
from typing import Any

from .accuracy import estimate, run_to_accuracy, true_error
from .model import Pendulum, State, check_pendulum_state
from .simulation_runs import DRIFT_TOLERANCE as DRIFT_TOLERANCE
from .simulation_runs import _run_in_core, _run_string
from .simulation_settings import check_run
from .trajectory import Trajectory
from .validate import choice


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
    steps_on_samples: bool = False,
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
    steps_on_samples : a sampled pivot's fixed-step runs: ``dt`` is the longest step and the steps land
        on every sample, each interval between samples taken in ⌈span/dt⌉ equal steps; ``accuracy=``
        runs so (default False). Without, the steps are dt, one that holds a sample split there
        (docs/integrators.md, "Sampled pivot"). No effect on ``dop853``; True without pivot samples is
        an ``InvalidInputError``. ``pl.Stepper`` takes it too, with the same steps bit for bit.

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
            "steps_on_samples": steps_on_samples,
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
        steps_on_samples=steps_on_samples,
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


def _simulate_halved(pendulum: Pendulum, state: State, t_end: float, **kwargs: Any) -> Trajectory:
    """:func:`simulate` with every fixed step (each sub-step on a sampled pivot, each shortened one) taken
    as two equal halves (``RunOptions.halved_steps``): the error estimate's dt/2 companion."""
    given, skip = inspect.signature(simulate).parameters.items(), ("error_estimate", "accuracy")
    defaults = {k: p.default for k, p in given if p.kind == p.KEYWORD_ONLY and k not in skip}
    run = check_run(pendulum, t_end, **(defaults | kwargs))
    return _run_in_core(pendulum, state, run, halved=True)
