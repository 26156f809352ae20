"""Ensembles of any rod model with DOP853 (``simulate_ensemble(..., method="dop853")``): damping,
quadratic drag, periodic forcing, dry friction, a moving pivot, a rotating frame — the models the
RATTLE kernel does not run. Each trajectory is exactly ``simulate(pendulum_k, start, t_end,
method="dop853", rtol=…, atol=…, save_at=[0, t_end])`` (the same steps, step-size control and
projection, bit for bit), where ``pendulum_k`` is the pendulum with trajectory k's length [m], g
[m/s²] and damping [1/s] when these are given per trajectory. The trajectories run vectorised, 8 at a
time with a step size and an accept/reject decision each (``pendulab_core::ensemble::adaptive_lanes``),
in parallel on all cores. One model is built per distinct (length, g, damping) triple. Times in s,
states in m and m/s.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

from .. import validate as limits
from .._core import AdaptiveEnsembleRun, InvalidInputError, ModelSpec, RunOptions
from .._progress import tqdm
from ..memory import check_memory
from ..model import FloatArray, Pendulum
from .result import EnsembleResult

IntArray = npt.NDArray[np.int64]
_POLL_SECONDS = 0.05
BYTES_PER_ROW = 2048
"""Memory [B] one trajectory needs besides its saved samples: its solver (the stages of DOP853, the
dense output) and the copies of its start on both sides of the core."""


def simulate_adaptive(
    pendulum: Pendulum,
    x: FloatArray,
    v: FloatArray,
    t_end: float,
    *,
    method: str,
    rtol: Any,
    atol: Any,
    conserve: bool,
    progress: bool | None,
    per_trajectory: dict[str, FloatArray] | None = None,
) -> EnsembleResult:
    """The adaptive ensemble: starts x, v (N, 3) [m, m/s] (finite rows only), final states at
    ``t_end`` [s] with ``method`` (``"dop853"``) at tolerances ``rtol``, ``atol`` [m, m/s];
    ``per_trajectory``: checked arrays of one or N values, ``length`` [m], ``g`` [m/s²] and
    optionally ``damping`` [1/s] (the pendulum's own values where not given)."""
    if pendulum.force is not None:
        raise InvalidInputError(
            "simulate_ensemble(method='dop853') runs the registry's rod models in parallel threads; a "
            "Python force callable cannot run there: loop over pl.simulate for it"
        )
    if pendulum.model in ("spring", "string"):
        raise InvalidInputError(
            f"simulate_ensemble(method='dop853') runs rod models, not {pendulum.model!r} "
            "(use spring_simulate / simulate for it)"
        )
    tols = []
    for name, value in (("rtol", rtol), ("atol", atol)):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
            raise limits.invalid(name, value, "a finite tolerance > 0 (rtol relative, atol in m and m/s)")
        tols.append(float(value))
    n = x.shape[0]
    check_memory(
        f"an adaptive ensemble of {n} trajectories",
        n * (BYTES_PER_ROW + 2 * 96),
        "integrate fewer starts at once (in chunks)",
    )
    options = RunOptions(
        t0=0.0,
        t_end=float(t_end),
        method=method,
        dt=0.0,
        rtol=tols[0],
        atol=tols[1],
        project=True,
        conserve=bool(conserve),
        save_times=np.array([0.0, float(t_end)]),
    )
    models, index = _models(pendulum, n, per_trajectory or {})
    run = AdaptiveEnsembleRun(pendulum.spec, x, v, options, models, index)
    show = progress if progress is not None else n > 1000
    interrupted = False
    with tqdm(total=n, disable=not show, unit="traj", desc=f"{n} trajectories", leave=False) as bar:
        try:
            while not run.wait(_POLL_SECONDS):
                bar.update(round(run.progress * n) - bar.n)
            bar.update(round(run.progress * n) - bar.n)
        except KeyboardInterrupt:
            run.cancel()
            interrupted = True
    out = run.result()
    steps = out["steps"]
    meta = {
        "method": method,
        "rtol": tols[0],
        "atol": tols[1],
        "t_end": float(t_end),
        "pendulum": pendulum.params(),
        "n": n,
        "steps_per_trajectory": steps,
    }
    if models is not None and index is not None:
        meta["distinct_models"] = len(models)
    return EnsembleResult(
        np.array([0.0, float(t_end)]),
        out["x"],
        out["v"],
        None,
        interrupted or bool(out["cancelled"]),
        int(steps.max()) if steps.size else 0,
        meta,
    )


def _models(
    pendulum: Pendulum, n: int, per: dict[str, FloatArray]
) -> tuple[list[ModelSpec] | None, IntArray | None]:
    """One spec per distinct (length, g, damping) of the N trajectories and each trajectory's entry
    (None, None: the pendulum's own model for all). Distinct by their bits, so every trajectory gets
    exactly its own numbers. A ``damping`` for a model without that parameter is the core's error."""
    if not per:
        return None, None
    cols = {k: np.broadcast_to(a, (n,)) for k, a in per.items()}
    names = list(cols)
    table = np.ascontiguousarray(np.stack([cols[k] for k in names], axis=1))
    uniq, index = np.unique(table.view(np.int64), axis=0, return_inverse=True)
    models = []
    for row in uniq.view(np.float64):
        values = dict(zip(names, (float(v) for v in row), strict=True))
        extra = dict(pendulum.extra)
        if "damping" in values:
            extra["damping"] = values["damping"]
        # **extra holds only the model's own float parameters by name (never model/force/pivot_samples)
        q = Pendulum(
            length=values["length"],
            g=values["g"],
            mass=pendulum.mass,
            model=pendulum.model,
            pivot_samples=pendulum.pivot_samples,
            **extra,  # type: ignore[arg-type]
        )
        models.append(q.spec)
    return models, np.ascontiguousarray(index.ravel(), dtype=np.int64)
