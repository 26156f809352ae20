"""The starts of an ensemble: an (N, 6) array of (x, v) rows [m, m/s] or a list of ``State`` checked
(shape, at most ``MAX_SAMPLES`` rows, components within the position and velocity limits; rows with NaN
or inf are left to the caller, which skips them), per-trajectory parameters (one value or N), and
``states_from_angles``: rows from arrays of the angles of T-1.1. SI units."""

from __future__ import annotations

from typing import Any

import numpy as np

from .. import validate as limits
from .._core import InvalidInputError
from ..model import FloatArray, Pendulum, State


def as_states(states: Any) -> tuple[FloatArray, FloatArray]:
    """x [m], v [m/s] of the starts as two contiguous (N, 3) arrays (:func:`start_rows`, copied)."""
    x, v, _ = start_rows(states)
    return np.ascontiguousarray(x), np.ascontiguousarray(v)


def start_rows(states: Any) -> tuple[FloatArray, FloatArray, bool]:
    """x [m], v [m/s] of the starts as (N, 3) views of one (N, 6) float64 array (not copied), checked,
    and whether every entry is finite and within its limit (then no row needs a second look; else the
    caller skips the rows with NaN or inf)."""
    if isinstance(states, State):
        states = [states]
    if isinstance(states, (list, tuple)) and states and all(isinstance(s, State) for s in states):
        arr = np.array([s.as_array() for s in states])
    else:
        try:
            if np.asarray(states).dtype.kind in "cUSV":  # complex or text: refused, not cast
                raise TypeError
            arr = np.asarray(states, dtype=np.float64)
        except (TypeError, ValueError, OverflowError, RecursionError):
            raise limits.invalid(
                "states", states, "an (N, 6) array of (x, v) rows [m, m/s] or a list of State"
            ) from None
    if arr.ndim != 2 or arr.shape[1] != 6 or arr.shape[0] == 0:
        raise InvalidInputError(
            f"states must be an (N, 6) array of (x, v) rows [m, m/s] or a list of State, "
            f"got shape {arr.shape}"
        )
    if arr.shape[0] > limits.MAX_SAMPLES:
        raise limits.invalid("states", f"<{arr.shape[0]} rows>", f"at most {limits.MAX_SAMPLES} rows")
    x, v = arr[:, :3], arr[:, 3:]
    # the usual case, every entry finite and within the (symmetric) limits, is told by one reduction
    # over the whole array (both halves within the smaller limit), else by one per half
    if within_limits(arr, "position", "velocity") or (
        within_limits(x, "position") and within_limits(v, "velocity")
    ):
        return x, v, True
    every = bool(np.isfinite(arr).all())
    rows = slice(None) if every else np.isfinite(arr).all(axis=1)
    limits.array("states x", x[rows], "position")
    limits.array("states v", v[rows], "velocity")
    return x, v, False


def within_limits(a: FloatArray, *names: str) -> bool:
    """Every entry of ``a`` finite and within each of the limits ``names`` (symmetric, ±max): its
    least and largest entry, no temporary array (NaN makes it false)."""
    specs = [limits.LIMITS[name] for name in names]
    if any(spec["min"] != -spec["max"] for spec in specs):
        return False
    bound = min(spec["max"] for spec in specs)
    return bool(-bound <= a.min() and a.max() <= bound)


def per_trajectory(name: str, value: Any, default: float, n: int, limit: Any) -> FloatArray:
    """``value`` as one number or N (checked against ``limit``), or, when None, the pendulum's own
    ``default`` (checked when the pendulum was made) as one number."""
    if value is None:
        return np.full(1, float(default))
    a = np.atleast_1d(limits.array(name, default if value is None else value, limit)).ravel()
    if a.size not in (1, n):
        raise InvalidInputError(f"{name} must be one value or one per trajectory ({n}), got {a.size}")
    return np.ascontiguousarray(a)


def states_from_angles(
    pendulum: Pendulum, theta: Any, phi: Any = 0.0, theta_dot: Any = 0.0, phi_dot: Any = 0.0
) -> FloatArray:
    """(N, 6) array of (x, v) from arrays of θ [rad] (from the downward vertical), φ [rad], θ̇, φ̇
    [rad/s], broadcast together (the same formulas as ``Pendulum.state_from_angles``).

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> pl.states_from_angles(p, theta=[0.1, 0.2], phi_dot=1.0).shape
    (2, 6)
    """
    th, ph, thd, phd = np.broadcast_arrays(
        *(np.asarray(a, dtype=np.float64) for a in (theta, phi, theta_dot, phi_dot))
    )
    rows = [
        pendulum.state_from_angles(float(a), float(b), float(c), float(d)).as_array()
        for a, b, c, d in zip(th.ravel(), ph.ravel(), thd.ravel(), phd.ravel(), strict=True)
    ]
    return np.array(rows).reshape(-1, 6)
