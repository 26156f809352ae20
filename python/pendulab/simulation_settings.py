"""The arguments of :func:`pendulab.simulate` checked into one :class:`RunSettings` before any work
starts (:func:`check_run`; docs/limits.md): the method and its settings (``integrators.check_settings``),
t_end [s] after t0 [s], progress, the memory limit [bytes], save_every or save_at [s], the planned
steps, the user force with ``conserve``, the arithmetic, and ``steps_on_samples``. The runs that take
the settings: ``simulation_runs.py``."""

from __future__ import annotations

import dataclasses
from typing import Any

from ._core import InvalidInputError
from .integrators import _U64, _method_table, check_arithmetic, check_settings, check_steps_on_samples
from .model import Pendulum
from .validate import LIMITS, MAX_SAMPLES, array, flag, integer, invalid, number, planned_steps


@dataclasses.dataclass(frozen=True)
class RunSettings:
    """The settings of one :func:`pendulab.simulate` run, checked (:func:`check_run`): SI units,
    t0 < t_end [s]; ``dt`` None for the method's default (1 ms; dop853: automatic), ``save_at`` the save
    times [s]."""

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
    steps_on_samples: bool = False


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
    steps_on_samples: Any = False,
) -> RunSettings:
    """Every argument of :func:`pendulab.simulate` checked against :mod:`pendulab.validate` before any work
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
        check_steps_on_samples(steps_on_samples, pendulum),
    )
