"""Many trajectories at once: ``simulate_ensemble`` on the core's ensemble kernel (RATTLE on blocks
of 64 trajectories, vectorised, all cores). Every trajectory gets exactly the numbers of
``simulate(..., method="rattle")`` with the same dt. Ideal pendulum; length l [m] and gravity g
[m/s²] may differ per trajectory. Memory is bounded by what is saved (final states, every n-th
step, a summary), never by trajectories × steps. A tqdm bar shows progress for long runs; Ctrl-C
stops cleanly within 1024 steps and returns the states reached (``EnsembleResult.interrupted``).
"""

from __future__ import annotations

import time
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from tqdm.auto import tqdm

from . import _core
from .model import FloatArray, Pendulum, State

_POLL_SECONDS = 0.05
_PROGRESS_AFTER = 5e7  # trajectory-steps


@dataclass(frozen=True)
class EnsembleResult:
    """Saved states of N trajectories: ``t`` (n_save,) [s], ``x`` and ``v`` (N, n_save, 3) [m, m/s];
    ``summary`` (if asked): per trajectory z_min, z_max [m], e_min, e_max [J/kg] (E/m), j3_min, j3_max
    [m²/s] (J₃/m), and derived ``energy_drift`` = (e_max − e_min)/(|g| l) and ``j3_drift``."""

    t: FloatArray
    x: FloatArray
    v: FloatArray
    summary: dict[str, FloatArray] | None
    interrupted: bool
    steps: int
    metadata: dict[str, Any] = field(default_factory=dict)

    def __len__(self) -> int:
        return int(self.x.shape[0])

    @property
    def final_x(self) -> FloatArray:
        """Final positions (N, 3) [m]."""
        return self.x[:, -1, :]

    @property
    def final_v(self) -> FloatArray:
        """Final velocities (N, 3) [m/s]."""
        return self.v[:, -1, :]


def _as_states(states: Any) -> tuple[FloatArray, FloatArray]:
    if isinstance(states, State):
        states = [states]
    if isinstance(states, (list, tuple)) and states and all(isinstance(s, State) for s in states):
        arr = np.array([s.as_array() for s in states])
    else:
        arr = np.asarray(states, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 6 or arr.shape[0] == 0:
        raise _core.InvalidInputError(
            f"states must be an (N, 6) array of (x, v) rows [m, m/s] or a list of State, "
            f"got shape {arr.shape}"
        )
    return np.ascontiguousarray(arr[:, :3]), np.ascontiguousarray(arr[:, 3:])


def _per_trajectory(name: str, value: Any, default: float, n: int) -> FloatArray:
    a = np.atleast_1d(np.asarray(default if value is None else value, dtype=np.float64)).ravel()
    if a.size not in (1, n):
        raise _core.InvalidInputError(f"{name} must be one value or one per trajectory ({n}), got {a.size}")
    return np.ascontiguousarray(a)


def simulate_ensemble(
    pendulum: Pendulum,
    states: Any,
    t_end: float,
    *,
    dt: float = 1e-3,
    save_every: int | None = None,
    summary: bool = True,
    length: Any = None,
    g: Any = None,
    progress: bool | None = None,
) -> EnsembleResult:
    """Integrates N starts (an (N, 6) array of (x, v) or a list of ``State``) to ``t_end`` [s] with
    RATTLE at step ``dt`` [s]. ``length`` [m] and ``g`` [m/s²] default to the pendulum's; give arrays of
    N values for per-trajectory parameters. ``save_every``: keep every n-th step (default: the final
    state only). The number of steps is round(t_end/dt); t_end must be a multiple of dt to 1e-9."""
    if not pendulum.is_ideal:
        raise _core.InvalidInputError(
            f"simulate_ensemble supports the ideal pendulum, not {pendulum.model!r}"
        )
    x, v = _as_states(states)
    n = x.shape[0]
    lengths = _per_trajectory("length", length, pendulum.length, n)
    gs = _per_trajectory("g", g, pendulum.g, n)
    if not (np.isfinite(dt) and dt > 0):
        raise _core.InvalidInputError(f"dt = {dt!r} must be a finite step > 0 s")
    steps = round(t_end / dt)
    if not (np.isfinite(t_end) and t_end > 0 and abs(steps * dt - t_end) <= 1e-9 * t_end):
        raise _core.InvalidInputError(f"t_end = {t_end!r} s must be > 0 and a multiple of dt = {dt!r} s")
    if save_every is not None and (int(save_every) != save_every or save_every < 1):
        raise _core.InvalidInputError(f"save_every = {save_every!r} must be an integer >= 1")
    n_save = 2 if save_every is None else steps // int(save_every) + 2
    if n * n_save * 48 > 4 * 2**30:
        raise _core.InvalidInputError(
            f"{n} trajectories × {n_save} samples need {n * n_save * 48 / 2**30:.1f} GiB (limit 4 GiB); "
            "save less often"
        )
    run = _core.EnsembleRun(x, v, lengths, gs, float(dt), int(steps), save_every, bool(summary))
    show = progress if progress is not None else n * steps > _PROGRESS_AFTER
    interrupted = False
    with tqdm(total=1000, disable=not show, unit="‰", desc=f"{n} trajectories", leave=False) as bar:
        try:
            while not run.done:
                time.sleep(_POLL_SECONDS)
                bar.update(int(run.progress * 1000) - bar.n)
        except KeyboardInterrupt:
            run.cancel()
            interrupted = True
    out = run.result()
    if interrupted:
        warnings.warn("interrupted: returning the states reached so far", RuntimeWarning, stacklevel=2)
    summ = None
    if summary:
        summ = {k: out[k] for k in ("z_min", "z_max", "e_min", "e_max", "j3_min", "j3_max")}
        scale = np.maximum(np.abs(gs) * lengths, 1e-300)
        summ["energy_drift"] = (summ["e_max"] - summ["e_min"]) / scale
        summ["j3_drift"] = summ["j3_max"] - summ["j3_min"]
    meta = {"method": "rattle", "dt": dt, "t_end": t_end, "pendulum": pendulum.params(), "n": n}
    return EnsembleResult(
        out["t"], out["x"], out["v"], summ, interrupted or out["cancelled"], out["steps"], meta
    )


def states_from_angles(
    pendulum: Pendulum, theta: Any, phi: Any = 0.0, theta_dot: Any = 0.0, phi_dot: Any = 0.0
) -> FloatArray:
    """(N, 6) array of (x, v) from arrays of θ [rad] (from the downward vertical), φ [rad], θ̇, φ̇
    [rad/s], broadcast together (the same formulas as ``Pendulum.state_from_angles``)."""
    th, ph, thd, phd = np.broadcast_arrays(
        *(np.asarray(a, dtype=np.float64) for a in (theta, phi, theta_dot, phi_dot))
    )
    rows = [
        pendulum.state_from_angles(float(a), float(b), float(c), float(d)).as_array()
        for a, b, c, d in zip(th.ravel(), ph.ravel(), thd.ravel(), phd.ravel(), strict=True)
    ]
    return np.array(rows).reshape(-1, 6)
