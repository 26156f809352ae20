"""The pendulum on a string (model ``"string"``): a rope that can pull but not push. While the string
is taut the bob moves as on a rod (docs/theory.md §2); where the tension T = m(|v|² − g z)/l (T-2.3) would
turn negative — for the ideal pendulum at the height z* = 2E/(3 m g) — the string goes slack and the
bob flies freely on the exact parabola x_e + v_e τ − ½ g τ² e₃ until |x| = l again, when the string
snaps taut: the outward radial velocity u is removed (``restitution`` e = 0, inelastic, the default;
½ m |u|² is lost) or reflected (e = 1, elastic, E kept), in general v ← v − (1 + e)u.

The run is hybrid and done in the core (``StringRunner``, a ``StringStepper`` run to t_end),
driven in chunks of about 0.1 s of work with the GIL released, as :func:`pendulab.simulate` does for
every model: a tqdm progress bar for long runs, and Ctrl-C stops after the current chunk and returns
what was computed (``Trajectory.interrupted``). Chunks end on grid points and the run goes on as if
it had not stopped: the samples are those of the one-call ``string_simulate`` bit for bit. The
leave and snap events are located to round-off (bisection of the step length on T, closed form or
bisection of |x|² − l² on the parabola). Units: SI (m, kg, s, J).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .._chunks import _PROGRESS_AFTER_STEPS, run_in_chunks
from .._core import InvalidInputError, RunOptions, StringRunner
from ..model import Pendulum, State
from ..trajectory import Trajectory

STRING_METHODS = ("rattle", "rattle4", "rattle6", "rattle8", "rkmk4")
"""Methods for the taut phases: fixed step and keeping TS² (the leave is found by shortening a step)."""


def check_string_settings(method: str, conserve: bool = False) -> None:
    """Refuses what the hybrid string run cannot do, naming the alternative (save times are checked
    by the core when the run is set up)."""
    if method not in STRING_METHODS:
        raise InvalidInputError(
            f"method {method!r} cannot integrate the 'string' model: its taut phases need a fixed-step "
            f"method that keeps TS² (the leave is found by shortening a step); use one of "
            f"{', '.join(STRING_METHODS)}"
        )
    if conserve:
        raise InvalidInputError(
            "conserve=True is for dop853; the 'string' model's taut phases use the RATTLE family or rkmk4"
        )


def _concat_events(parts: list[dict[str, Any]]) -> dict[str, Any]:
    evs = [p["events"] for p in parts]
    out: dict[str, Any] = {
        k: np.concatenate([e[k] for e in evs]) for k in ("t", "x", "v_before", "v_after", "energy_lost")
    }
    out["kind"] = [k for e in evs for k in e["kind"]]
    return {k: out[k] for k in evs[0]}


def simulate_string(
    pendulum: Pendulum,
    state: State,
    t_end: float,
    *,
    method: str = "rattle",
    dt: float | None = None,
    save_every: int | None = None,
    save_at: Any = None,
    t0: float = 0.0,
    progress: bool | None = None,
    max_saved_bytes: int | None = None,
) -> Trajectory:
    """Simulates a ``model="string"`` pendulum (called by :func:`pendulab.simulate`) with step ``dt``
    [s] of the grid t0 + k·dt in the taut phases (default 1e-3 s). Samples: every ``save_every``-th
    grid point (default 1), every event (the state after it) and t_end; or exactly the times
    ``save_at`` [s] (strictly increasing, within [t0, t_end]): a taut phase lands on each by shortening
    the one step that crosses it, a flight evaluates its exact parabola there, and the run still goes
    to t_end, so ``Trajectory.events`` lists every event. ``Trajectory.taut`` flags the samples.
    ``progress``: a progress bar (default: only for runs of more than 5·10⁶ steps); Ctrl-C returns
    the samples computed so far with ``Trajectory.interrupted`` True and a RuntimeWarning."""

    check_string_settings(method)
    if save_every is not None and save_at is not None:
        raise InvalidInputError("give either save_every or save_at, not both")
    if save_every is not None and (
        isinstance(save_every, bool) or int(save_every) != save_every or save_every < 1
    ):
        raise InvalidInputError(f"save_every = {save_every!r} must be an integer >= 1")
    times = None if save_at is None else np.ascontiguousarray(np.asarray(save_at, dtype=np.float64).ravel())
    dt = 1e-3 if dt is None else float(dt)
    run = RunOptions(
        t0=float(t0),
        t_end=float(t_end),
        method=method,
        dt=dt,
        save_every=None if save_every is None else int(save_every),
        save_times=times,
        max_saved_bytes=max_saved_bytes,
    )
    runner = StringRunner(pendulum.spec, state.pair, run)
    expected_steps = (t_end - t0) / dt
    show = progress if progress is not None else expected_steps > _PROGRESS_AFTER_STEPS
    parts, interrupted = run_in_chunks(runner, show, method, take_rest=lambda: runner.take_samples(all=True))
    options: dict[str, Any] = {"dt": dt, "t0": t0, "t_end": t_end}
    if save_every is not None:
        options["save_every"] = int(save_every)
    if times is not None:
        options["save_at_times"] = int(times.size)  # how many save_at times were asked for
    return Trajectory(
        pendulum,
        np.concatenate([p["t"] for p in parts]),
        np.concatenate([p["x"] for p in parts]),
        np.concatenate([p["v"] for p in parts]),
        method,
        options,
        dict(runner.stats),
        interrupted,
        taut=np.concatenate([p["taut"] for p in parts]),
        events=_concat_events(parts),
    )
