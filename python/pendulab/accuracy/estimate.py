"""Global error estimates of a finished run, at every saved sample (``simulate(..., error_estimate=True)``).

- Fixed-step methods of order p (RK4, the RATTLE family, RKMK4, RK4 in angles): Richardson
  extrapolation. The same run at dt/2, saved at the same times y_{h/2}(t), gives
  e(t) ≈ (y_h(t) − y_{h/2}(t)) · 2^p/(2^p − 1) for the error of the plain run y_h (Hairer, Nørsett &
  Wanner, *Solving ODEs I*, §II.4). Extra cost: the half-step run, 2× the plain run.
- DOP853: a companion run at rtol/1000 (atol likewise; the tightest allowed, 1e-15, when that is
  below), saved at the same times by dense output: e(t) ≈ y(t) − y_c(t), the companion's own error
  being ~1000× smaller (its global error follows the tolerance). Extra cost ≈ 1000^{1/8} ≈ 2.4× the
  plain run (the step size scales like tol^{1/8}).
- The ideal pendulum also gets the true error against the exact solution (T-4.x, ``pl.exact``),
  ``Trajectory.error``.

Errors are |Δx| [m] and |Δv| [m/s] per sample. Where both runs sit at the float64 floor the
estimate is round-off noise of that size, not the error (see docs/integrators.md, "Error estimates").
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np

from .._core import ExactSolution as _CoreExact
from .._core import InvalidInputError, methods
from ..error_estimate import ErrorEstimate
from ..model import Pendulum, State
from ..trajectory import Trajectory

#: The companion run of DOP853 is this much tighter in rtol and atol.
COMPANION_FACTOR = 1e-3
#: The smallest rtol DOP853 accepts (crates/pendulab-core/src/integrate/dop853.rs, RTOL_MIN).
RTOL_MIN = 1e-15

Runner = Callable[..., Trajectory]


def _order(method: str) -> int:
    info = next((m for m in methods() if m["name"] == method), None)
    if info is None:
        raise InvalidInputError(f"unknown method {method!r}")
    return int(info["order"])


def _is_adaptive(method: str) -> bool:
    return bool(next(m for m in methods() if m["name"] == method)["adaptive"])


def _work(tr: Trajectory) -> float:
    return float(tr.stats.get("rhs_evals", 0) or tr.stats.get("steps", 0) or 1)


def reference_settings(method: str, options: dict[str, Any]) -> dict[str, Any]:
    """The settings of the reference run for a run with ``method`` and ``options`` (dt, rtol, atol)."""
    if _is_adaptive(method):
        rtol = max(float(options["rtol"]) * COMPANION_FACTOR, RTOL_MIN)
        return {"rtol": rtol, "atol": float(options["atol"]) * COMPANION_FACTOR}
    return {"dt": float(options["dt"]) / 2.0}


def estimate(run: Runner, tr: Trajectory, state: State, kwargs: dict[str, Any]) -> ErrorEstimate:
    """The error estimate of ``tr``, the result of ``run(pendulum, state, t_end, **kwargs)``.

    ``run`` is the plain simulation (``pendulab.simulate`` without ``error_estimate``); the reference
    is the same call with the settings of :func:`reference_settings`, saved at ``tr.t``."""
    method = tr.method
    ref = reference_settings(method, tr.options)
    ref_kwargs = {k: v for k, v in kwargs.items() if k not in ("save_every", "save_at", "dt")}
    ref_kwargs |= {"method": method, "save_at": tr.t} | ref
    if "dt" not in ref and kwargs.get("dt") is not None:
        ref_kwargs["dt"] = kwargs["dt"]
    companion = run(tr.pendulum, state, float(tr.t[-1]), **ref_kwargs)
    if len(companion) != len(tr):
        raise RuntimeError("the reference run was interrupted: no error estimate")
    dx = np.linalg.norm(tr.x - companion.x, axis=1)
    dv = np.linalg.norm(tr.v - companion.v, axis=1)
    if _is_adaptive(method):
        how = "companion"
    else:
        p = _order(method)
        scale = 2.0**p / (2.0**p - 1.0)
        dx, dv, how = dx * scale, dv * scale, "richardson"
    return ErrorEstimate(dx, dv, how, ref | {"method": method}, cost=_work(companion) / _work(tr))


def true_error(pendulum: Pendulum, state: State, tr: Trajectory) -> ErrorEstimate | None:
    """|x − x_exact| [m] and |v − v_exact| [m/s] at the samples for the ideal pendulum (None otherwise)."""
    if not pendulum.is_ideal or pendulum.force is not None:
        return None
    sol = _CoreExact(
        pendulum.length,
        pendulum.mass,
        pendulum.g,
        np.ascontiguousarray(state.x),
        np.ascontiguousarray(state.v),
    )
    x, v, _ = sol.states(np.ascontiguousarray(tr.t - tr.t[0]))
    return ErrorEstimate(
        np.linalg.norm(tr.x - x, axis=1), np.linalg.norm(tr.v - v, axis=1), "exact", {"method": "exact"}
    )
