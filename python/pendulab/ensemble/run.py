"""Many trajectories at once: ``simulate_ensemble`` on the core's ensemble kernel (RATTLE on blocks of
48 trajectories, vectorised, all cores, or its symmetric compositions of order 4, 6 and 8,
docs/theory.md T-8.2). Every trajectory gets exactly the numbers of ``simulate(..., method=...)``
with the same method ("rattle", "rattle4", "rattle6", "rattle8") and dt. Ideal pendulum, optionally
with linear damping c [1/s] (force −m c v; the ``damped`` model without drag or forcing, T-7.1);
length l [m], gravity g [m/s²] and damping may differ per trajectory. With ``settle_angle`` [rad]
each trajectory's settle time is tracked: the time after which its sway from the stable equilibrium
(−sign(g) e₃) stays within the angle (to one step dt; 0 if never outside, +inf if still outside at
the end). Memory is bounded by what is saved (final states, every n-th step, a summary), never by
trajectories × steps. Start rows with NaN or inf are reported (``invalid_rows``, a warning) and get
NaN results; the others run. A tqdm bar shows progress for long runs; Ctrl-C stops cleanly within
1024 steps and returns the samples that every trajectory reached (``EnsembleResult.interrupted``):
with ``save_every`` the saved samples up to the stop, with the final states only just the starts (t
= 0), since the blocks of trajectories stop at different steps and the result keeps one time axis.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from .. import validate as limits
from .._core import EnsembleRun, EnsembleSpec, InvalidInputError, RunOptions
from .._progress import tqdm
from .._warn import warn_user
from ..integrators import check_arithmetic, method_names, unknown_method
from ..memory import check_memory
from ..model import FloatArray, Pendulum
from .adaptive import simulate_adaptive
from .result import EnsembleResult
from .save import Save
from .starts import as_states, per_trajectory, start_rows, states_from_angles

__all__ = ["max_sway", "model_damping", "simulate_ensemble", "states_from_angles"]

_POLL_SECONDS = 0.05
BYTES_PER_ROW = 512
"""Memory [B] one start needs besides its saved samples (the copies of its state and parameters on
both sides of the core, the summary, the masks); a saved sample of x, v takes 48 B, twice while it is
handed back. Checked against the available memory before the run (:mod:`pendulab.memory`)."""

_PROGRESS_AFTER = 5e7  # trajectory-steps

SUBSTEPS = {"rattle": 1, "rattle4": 3, "rattle6": 7, "rattle8": 15}
"""The methods of the vectorised kernel and the RATTLE sub-steps one step of each takes (its
composition's weights, crates/pendulab-core/src/integrate/composition.rs): the work bound counts
them."""


_DAMPING = limits.param_spec("damped", "damping")
_SETTLE = limits.spec("settle_angle", "rad", 1e-300, math.pi, "an angle in (0, π] rad")

_DAMPED_ONLY = {"damping", "forcing_x", "forcing_y", "forcing_z", "forcing_omega", "forcing_phase"}


def max_sway(z_min: FloatArray, z_max: FloatArray, g: FloatArray, length: FloatArray) -> FloatArray:
    """The largest angle [rad] from the stable equilibrium −sign(g) e₃ (the bottom for g ≥ 0, the top
    for g < 0) reached by trajectories whose heights ranged over [z_min, z_max] [m]."""
    g = np.asarray(g)
    if g.size == 1:  # one gravity for all (the usual ensemble): one side, no mask
        cos_sway = (z_min if g.item() < 0.0 else -z_max) / length
    else:
        cos_sway = np.where(g < 0.0, z_min, -z_max) / length
    return np.arccos(np.clip(cos_sway, -1.0, 1.0))


def model_damping(pendulum: Pendulum) -> float:
    """The linear damping c [1/s] of an ideal or ``damped`` pendulum the kernel can run, else an error."""
    if pendulum.is_ideal:
        return 0.0
    extra = pendulum.extra
    gravity = (extra.get("gravity_x", 0.0), extra.get("gravity_y", 0.0), extra.get("gravity_z", -1.0))
    other = {
        k: v for k, v in extra.items() if k not in _DAMPED_ONLY and not k.startswith("gravity_") and v != 0.0
    }
    if (
        pendulum.model != "damped"
        or pendulum.force is not None
        or other
        or extra.get("forcing_amplitude", 0.0) != 0.0
        or (gravity[0] != 0.0 or gravity[1] != 0.0 or gravity[2] >= 0.0)
    ):
        raise InvalidInputError(
            f"simulate_ensemble runs the ideal pendulum with optional linear damping, not {pendulum!r}; "
            "use simulate() for drag, forcing, a force callable, tilted gravity and the other models"
        )
    return float(extra.get("damping", 0.0))


def simulate_ensemble(
    pendulum: Pendulum,
    states: Any,
    t_end: float,
    *,
    method: str = "rattle",
    dt: float = 1e-3,
    save: Save | None = None,
    save_every: int | None = None,
    summary: bool | None = None,
    length: Any = None,
    g: Any = None,
    damping: Any = None,
    settle_angle: float | None = None,
    progress: bool | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    conserve: bool = False,
    arithmetic: str = "auto",
) -> EnsembleResult:
    """Integrates N starts (an (N, 6) array of (x, v) or a list of ``State``) to ``t_end`` [s] with
    RATTLE at step ``dt`` [s], or with ``method="rattle4"``, ``"rattle6"`` or ``"rattle8"`` its
    symmetric compositions of order 4, 6 and 8 (3, 7 and 15 RATTLE sub-steps per step; symplectic,
    |x| = l, x·v = 0 and J₃ kept as by RATTLE; far more accurate per unit of work when the trajectory
    itself is wanted to better than about 1e-4: docs/performance.md, *Ensembles: accuracy per unit
    of work*). ``length`` [m], ``g`` [m/s²] and ``damping`` c [1/s] default to the
    pendulum's (an ideal pendulum, or a ``damped`` one with only linear damping); give arrays of N
    values for per-trajectory parameters. ``save``: what to keep, e.g. ``pl.Save.every(1000) |
    pl.Save.summary()`` (see :class:`~pendulab.save.Save`); or the older keywords ``save_every`` (keep
    every n-th step; default the final state only) and ``summary`` (default True: each trajectory's
    extremes of z, E and J₃ and its plane crossings, updated at every step, which costs about a third
    of the kernel's time; ``summary=False`` when the states are all you need).
    ``settle_angle`` [rad] in (0, π): also return each trajectory's settle time. The number of steps
    is round(t_end/dt); t_end must be a multiple of dt to 1e-9. ``arithmetic``: ``"auto"`` (default:
    ``"fused"`` where the CPU does a fused multiply-add in one instruction, else ``"unfused"``),
    ``"unfused"`` (the same bits on every CPU and in WebAssembly) or ``"fused"`` (one rounding: about
    1.4× the trajectory-steps per CPU second of unfused on CPUs with FMA, much slower without; the same
    bits on every CPU too, other bits than unfused), as ``simulate(..., arithmetic=...)``, whose numbers
    every trajectory gets bit for bit (docs/performance.md, "How fast, and why").

    ``method="dop853"``: any rod model of the registry (drag, forcing, friction, a moving pivot, …),
    each trajectory adaptive with tolerances ``rtol``, ``atol`` [m, m/s] (and ``conserve``, as in
    :func:`~pendulab.simulate`), exactly ``simulate(pendulum, start, t_end, method="dop853",
    save_at=[0, t_end])`` with trajectory k's ``length[k]``, ``g[k]`` and ``damping[k]`` (each one
    value or N; ``damping`` only for models that have it); vectorised across trajectories (each its
    own step size) on all cores; final states only (t = 0 and t_end), no summary (``dt`` is not
    used). No ``steps_on_samples``: the fixed-step kernel refuses a sampled pivot, and ``dop853``'s
    steps end on its samples anyway (docs/integrators.md, "Sampled pivot").

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> p = pl.Pendulum()
    >>> starts = pl.states_from_angles(p, theta=np.linspace(0.1, 1.0, 4))
    >>> res = pl.simulate_ensemble(p, starts, t_end=1.0, dt=1e-3, progress=False)
    >>> res.x.shape
    (4, 2, 3)
    >>> res
    EnsembleResult(4 trajectories, 2 saved times, t = 0 … 1 s, 1000 steps)
    """
    if not isinstance(pendulum, Pendulum):
        raise limits.invalid("pendulum", pendulum, "a pendulab.Pendulum")
    if isinstance(method, str) and method not in method_names():
        raise InvalidInputError(unknown_method(method))
    if not isinstance(method, str) or (method not in SUBSTEPS and method != "dop853"):
        raise InvalidInputError(
            f"method = {limits.show(method)}: simulate_ensemble runs 'rattle' or its compositions "
            "'rattle4', 'rattle6', 'rattle8' (vectorised; ideal or linearly damped pendulum) or 'dop853' "
            "(adaptive, any rod model); loop over pl.simulate for the other methods"
        )
    arithmetic = check_arithmetic(arithmetic, method)
    if method == "dop853":
        return _adaptive(pendulum, states, t_end, locals())
    if save is not None:
        if not isinstance(save, Save):
            raise InvalidInputError(f"save must be a pl.Save rule, got {limits.show(save)}")
        if save_every is not None or summary is not None:
            raise InvalidInputError("give save=pl.Save... or save_every/summary, not both")
        save_every, summary = save.every_n, save.with_summary
    run = (t_end, dt, method)
    plan = _plan(pendulum, states, run, save_every, summary, (length, g, damping), settle_angle)
    out, interrupted = _run_kernel(plan, progress, arithmetic)
    return _result(pendulum, plan, out, interrupted, arithmetic)


@dataclass(frozen=True)
class _Plan:
    """A RATTLE ensemble run, checked: the starts x [m], v [m/s] (N, 3), per-trajectory l [m], g
    [m/s²], c [1/s], which rows are finite (a mask; ``slice(None)`` when all are) and which are not,
    the method (RATTLE or a composition), dt, t_end [s], the step count, what is saved."""

    x: FloatArray
    v: FloatArray
    lengths: FloatArray
    gs: FloatArray
    cs: FloatArray
    finite: Any
    invalid: Any
    method: str
    dt: float
    t_end: float
    steps: int
    save_every: int | None
    summary: bool
    settle: float | None

    def good(self, a: FloatArray) -> FloatArray:
        """The rows of ``a`` the kernel runs (the finite starts; a broadcast value as it is; the core
        reads strided arrays too, so nothing is copied when every row runs)."""
        n = self.x.shape[0]
        return a if (a.shape[0] != n or not self.invalid.size) else a[self.finite]


def _plan(
    pendulum: Pendulum,
    states: Any,
    run: tuple[Any, Any, str],
    save_every: Any,
    summary: bool | None,
    params: tuple[Any, Any, Any],
    settle_angle: Any,
) -> _Plan:
    """The arguments of ``simulate_ensemble(method="rattle")`` checked, the work and memory bounded."""
    length, g, damping = params
    t_end, dt, method = run
    c_model = model_damping(pendulum)
    x, v, clean = start_rows(states)  # views: the core reads them without a copy
    n = x.shape[0]
    lengths = per_trajectory("length", length, pendulum.length, n, limits.COMMON["length"])
    gs = per_trajectory("g", g, pendulum.g, n, limits.COMMON["g"])
    cs = per_trajectory("damping", damping, c_model, n, _DAMPING)
    # every row finite when clean (start_rows's one reduction: no mask needed); else row by row
    finite: Any = slice(None)
    invalid = np.empty(0, dtype=np.intp)
    if not clean:
        finite = np.isfinite(x).all(axis=1) & np.isfinite(v).all(axis=1)
        invalid = np.flatnonzero(~finite)
    if invalid.size == n:
        raise InvalidInputError(f"every start row is non-finite (NaN or inf): {n} rows")
    dt = limits.number("dt", dt, "dt")
    t_end = limits.number("t_end", t_end, "time", positive=True)
    # RATTLE steps of all trajectories (a composition's step is SUBSTEPS of them): the whole work
    limits.planned_work(t_end, dt, n, "trajectory", method, SUBSTEPS[method])
    steps = round(t_end / dt)
    if not (math.isfinite(t_end) and t_end > 0 and abs(steps * dt - t_end) <= 1e-9 * t_end):
        raise InvalidInputError(
            f"t_end = {limits.show(t_end)} s must be > 0 and a multiple of dt = {limits.show(dt)} s"
        )
    if save_every is not None:
        save_every = limits.integer("save_every", save_every, 1, 2**63 - 1)
    _check_saved(n, 2 if save_every is None else steps // int(save_every) + 2)
    settle = None if settle_angle is None else limits.number("settle_angle", settle_angle, _SETTLE)
    if invalid.size:
        rows = ", ".join(str(i) for i in invalid[:10]) + (", …" if invalid.size > 10 else "")
        warn_user(
            f"{invalid.size} of {n} start rows are not finite (rows {rows}): not integrated, their "
            "results are NaN (EnsembleResult.invalid_rows)",
            RuntimeWarning,
        )
    summary = True if summary is None else bool(summary)
    return _Plan(
        x, v, lengths, gs, cs, finite, invalid, method, dt, t_end, steps, save_every, summary, settle
    )


def _check_saved(n: int, n_save: int) -> None:
    """``n`` trajectories × ``n_save`` saved samples: at most 4 GiB, and memory available for them
    (asked of the system only above 64 MiB, which any machine running this has to spare)."""
    if n * n_save * 48 > 4 * 2**30:
        raise InvalidInputError(
            f"{n} trajectories × {n_save} samples need {n * n_save * 48 / 2**30:.1f} GiB (limit 4 GiB); "
            "save less often"
        )
    need = n * (BYTES_PER_ROW + n_save * 96)
    if need <= 2**26:
        return
    check_memory(
        f"an ensemble of {n} trajectories with {n_save} saved samples each",
        need,
        "integrate fewer starts at once (in chunks), or save less often",
    )


def _run_kernel(plan: _Plan, progress: bool | None, arithmetic: str) -> tuple[dict[str, Any], bool]:
    """The core's run on its thread with a progress bar (Ctrl-C cancels): the result's arrays, back
    at the input's rows (NaN where the start was not finite), and whether it was interrupted."""
    n = plan.x.shape[0]
    good = plan.good
    run = EnsembleRun(
        EnsembleSpec(good(plan.lengths), good(plan.gs), good(plan.cs)),
        good(plan.x),
        good(plan.v),
        RunOptions(method=plan.method, dt=float(plan.dt), save_every=plan.save_every, arithmetic=arithmetic),
        int(plan.steps),
        plan.summary,
        plan.settle,
    )
    show = progress if progress is not None else n * plan.steps * SUBSTEPS[plan.method] > _PROGRESS_AFTER
    interrupted = False
    # no bar object at all when none is shown (a short run's call is ~5 ms: every 10 µs counts)
    # the bar counts trajectory-steps (the core's counter; run.progress is the fraction of them done)
    n_run, steps = n - plan.invalid.size, int(plan.steps)
    total = n_run * steps
    bar = (
        tqdm(
            total=total,
            unit="step",
            unit_scale=True,
            desc=f"{n_run} trajectories × {steps} steps",
            leave=False,
        )
        if show
        else None
    )
    try:
        # wait returns the moment the run ends; the bar (and Ctrl-C) are served every _POLL_SECONDS
        while not run.wait(_POLL_SECONDS):
            if bar is not None:
                bar.update(round(run.progress * total) - bar.n)
    except KeyboardInterrupt:
        run.cancel()
        interrupted = True
    finally:
        if bar is not None:
            bar.update(round(run.progress * total) - bar.n)
            bar.close()
    out = run.result()
    if plan.invalid.size:  # back to the input's rows, NaN where the start was not finite
        for key, a in list(out.items()):
            if isinstance(a, np.ndarray) and a is not out["t"]:
                full = np.full((n, *a.shape[1:]), np.nan)
                full[plan.finite] = a
                out[key] = full
    return out, interrupted


def _result(
    pendulum: Pendulum, plan: _Plan, out: dict[str, Any], interrupted: bool, arithmetic: str = "unfused"
) -> EnsembleResult:
    """The kernel's output as an ``EnsembleResult``: the summary with its drifts and sway, the run's
    metadata."""
    if interrupted:
        warn_user("interrupted: returning the states reached so far", RuntimeWarning)
    summ = None
    if plan.summary:
        summ = {k: out[k] for k in ("z_min", "z_max", "e_min", "e_max", "j3_min", "j3_max", "crossings")}
        scale = np.maximum(np.abs(plan.gs) * plan.lengths, 1e-300)
        summ["energy_drift"] = (summ["e_max"] - summ["e_min"]) / scale
        summ["j3_drift"] = summ["j3_max"] - summ["j3_min"]
        summ["max_sway"] = max_sway(summ["z_min"], summ["z_max"], plan.gs, plan.lengths)
    n = plan.x.shape[0]
    meta = {"method": plan.method, "dt": plan.dt, "t_end": plan.t_end, "pendulum": pendulum.params(), "n": n}
    if arithmetic != "unfused":
        meta["arithmetic"] = arithmetic
    if plan.settle is not None:
        meta["settle_angle"] = plan.settle
    return EnsembleResult(
        out["t"],
        out["x"],
        out["v"],
        summ,
        interrupted or out["cancelled"],
        out["steps"],
        meta,
        out.get("settle_time"),
        plan.invalid.astype(np.int64),
    )


_RATTLE_ONLY = ("save", "save_every", "summary", "settle_angle")


def _adaptive(pendulum: Pendulum, states: Any, t_end: Any, kw: dict[str, Any]) -> EnsembleResult:
    """``simulate_ensemble(method="dop853")``: the keywords checked, then :mod:`.adaptive`."""
    given = [k for k in _RATTLE_ONLY if kw[k] is not None]
    if given:
        raise InvalidInputError(
            f"simulate_ensemble(method='dop853') keeps the final states only: "
            f"{', '.join(given)} apply to method='rattle' only"
        )
    x, v = as_states(states)
    if not (np.isfinite(x).all() and np.isfinite(v).all()):
        raise InvalidInputError("method='dop853' needs every start row finite (no NaN or inf)")
    t_end = limits.number("t_end", t_end, "time", positive=True)
    n = x.shape[0]
    per: dict[str, FloatArray] = {}
    if any(kw[k] is not None for k in ("length", "g", "damping")):  # one model per distinct triple
        per["length"] = per_trajectory("length", kw["length"], pendulum.length, n, limits.COMMON["length"])
        per["g"] = per_trajectory("g", kw["g"], pendulum.g, n, limits.COMMON["g"])
        if kw["damping"] is not None:
            c_model = float(pendulum.extra.get("damping", 0.0))
            per["damping"] = per_trajectory("damping", kw["damping"], c_model, n, _DAMPING)
    return simulate_adaptive(
        pendulum,
        x,
        v,
        t_end,
        method="dop853",
        rtol=kw["rtol"],
        atol=kw["atol"],
        conserve=kw["conserve"],
        progress=kw["progress"],
        per_trajectory=per,
    )
