"""Sweeps: one quantity (or a few) at every point of a grid or a random design, in chunks, on a thread
pool or a Dask cluster, written to Parquet chunk by chunk and resumable (``docs/sweeps.md``).

::

    sw = pl.sweep({"theta0": np.linspace(0.1, 3.0, 500), "phi_dot0": np.linspace(-3, 3, 500)},
                  "rotation_number")                      # exact: no integration
    sw.to_xarray()["rotation_number"].plot()
    pl.sweep(pl.sweep_design.random(10_000, {"theta0": (0.1, 1.5), "length": (0.5, 2.0)}, seed=1),
             ["max_sway", "energy_drift"], t_end=20.0, dt=1e-3, out="sway/", resume=True)

Quantities, per point (SI units):

=================== ======= ======================================================================
``final_state``     m, m/s  x, y, z, vx, vy, vz at ``t_end`` (RATTLE or ``method``, step ``dt``,
                            as ``simulate_ensemble``)
``rotation_number`` 1       W = Δφ/2π per z-period, exact (T-4.5); NaN for J₃ = 0 or g = 0
``period``          s       the z-period T_z of the exact solution (``ExactSolution.period_z``); inf
                            on the separatrix, NaN at rest
``max_sway``        rad     the largest polar angle from the downward vertical over 0 … t_end,
                            arccos(−z_max/l), z_max checked at every step
``energy_drift``    1       (max E − min E) over the run / (m|g|l): the integrator's energy error
=================== ======= ======================================================================

The exact quantities need no ``t_end``; the others integrate once for all of them. Every point is
computed independently of the chunking and of the backend, so results are the same bit for bit
whatever ``chunk_size``, ``workers`` or ``backend``.
"""

from __future__ import annotations

import math
import os
import time
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from .. import _core
from .. import validate as limits
from .._progress import tqdm
from .._warn import warn_user
from ..model import Pendulum
from .backends import Dask, Threads, connect, drive
from .compute import (
    QUANTITIES,
    SIMULATED,
    ChunkTask,
    SweepSpec,
    _bad,
    compute_chunk,
    fingerprint,
    make_spec,
    ran,
)
from .design import AXES, Design, as_design
from .results import MemorySink, OutputDir, SweepResult
from .resume import resume_settings
from .workers import check_ran, check_workers

BACKENDS = ("threads", "dask")

TARGET_CHUNK_WORK = 1e8
"""Trajectory-steps per chunk of a simulated sweep by default (≈ 0.5 s on 2 cores)."""

EXACT_CHUNK = 50_000
"""Points per chunk of an exact-only sweep by default."""

MAX_CHUNK = 10_000_000


# --- the sweep -----------------------------------------------------------------------------------


def default_chunk_size(spec: SweepSpec) -> int:
    """Points per chunk: :data:`EXACT_CHUNK` for exact quantities; for simulated ones about
    :data:`TARGET_CHUNK_WORK` trajectory-steps (RATTLE sub-steps: a composition's step counts as
    ``SUBSTEPS`` of them), a multiple of the kernel's block
    (``_core.ENSEMBLE_LANES``, 48 trajectories), from one block to 100 000 points. A resumed sweep
    keeps the chunk size its output records."""
    if not spec.simulated:
        return EXACT_CHUNK
    per = TARGET_CHUNK_WORK / max(spec.steps * spec.substeps, 1)
    block = _core.ENSEMBLE_LANES
    return int(min(max(block * round(per / block), block), 100_000 // block * block))


def check_work(design: Design, spec: SweepSpec) -> None:
    """Refuses, before any work, a sweep of more than ``MAX_SAMPLES`` points, or one whose RATTLE steps
    in all — points × t_end/dt × RATTLE sub-steps per step of its method — exceed ``MAX_STEPS``
    (:func:`pendulab.validate.planned_work`: the message names that product, each factor, the limit
    and the fixes); ``make_spec`` checks one point's. ``pl.sweep`` and a sweep file's loading both
    check it."""
    if design.n > limits.MAX_SAMPLES:
        raise limits.invalid("design", f"<{design.n} points>", f"at most {limits.MAX_SAMPLES:.0e} points")
    if spec.t_end is not None and spec.dt is not None:
        limits.planned_work(spec.t_end, spec.dt, design.n, "point", spec.method or "rattle", spec.substeps)


def _positive_int(name: str, value: Any, most: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or not 1 <= value <= most:
        raise _bad(f"{name} = {limits.show(value)} must be an integer from 1 to {most}")
    return int(value)


def _check_backend(
    backend: Any, scheduler: Any, workers: Any, chunk_size: Any
) -> tuple[str, int | None, int | None]:
    """The backend's name (default: threads, or dask with a scheduler), workers and chunk size, checked."""
    if backend is None:
        backend = "threads" if scheduler is None else "dask"
    if backend not in BACKENDS:
        raise _bad(f"backend = {limits.show(backend)}: use one of {', '.join(BACKENDS)}")
    if scheduler is not None and backend != "dask":
        raise _bad(f"scheduler = {limits.show(scheduler)} needs backend 'dask', not {limits.show(backend)}")
    if workers is not None:
        workers = _positive_int("workers", workers, 1024)
    if scheduler is not None and workers is not None:
        raise _bad("workers sets the threads pool or a new LocalCluster, not a given scheduler")
    if chunk_size is not None:
        chunk_size = _positive_int("chunk_size", chunk_size, MAX_CHUNK)
    return str(backend), workers, chunk_size


def _open_target(
    out: Any, resume: bool, meta: dict[str, Any], chunk_size: int | None, spec: Any, n: int, units: Any
) -> tuple[MemorySink | OutputDir, int]:
    """Where the chunks go (memory, or the directory / .parquet file ``out``) and the chunk size."""
    if out is None:
        if resume:
            raise _bad("resume=True needs out (the directory or .parquet file to continue)")
        return MemorySink(n, units), chunk_size or default_chunk_size(spec)
    target = OutputDir.open(out, meta, chunk_size, default_chunk_size(spec), n, resume)
    return target, target.chunk_size


def sweep(
    design: Any,
    quantity: str | Sequence[str],
    *,
    pendulum: Pendulum | None = None,
    fixed: Mapping[str, float] | None = None,
    t_end: float | None = None,
    dt: float | None = None,
    settle_angle: float | None = None,
    arithmetic: str = "auto",
    method: str = "rattle",
    backend: str | None = None,
    scheduler: Any = None,
    workers: int | None = None,
    chunk_size: int | None = None,
    out: str | os.PathLike[str] | None = None,
    resume: bool = False,
    progress: bool | None = None,
) -> SweepResult:
    """Computes ``quantity`` (a name of :data:`QUANTITIES`, or a list) at every point of ``design``.

    ``design``: a dict of axis name → 1-D array (a full factorial grid) or a design from
    :mod:`pendulab.sweeps.design`; axes ``theta0``, ``phi0`` [rad], ``theta_dot0``, ``phi_dot0`` [rad/s],
    ``length`` [m], ``g`` [m/s²], ``damping`` [1/s]. ``pendulum`` (ideal, or ``damped`` with linear
    damping only; default l = 1 m, g = 9.81 m/s², m = 1 kg) gives length, g and damping where the
    design does not vary them; ``fixed`` sets initial conditions that are not axes (default 0).
    Simulated quantities integrate with RATTLE to ``t_end`` [s] at step ``dt`` [s] (default 1e-3 s;
    t_end a multiple of dt), or with ``method="rattle4"``, ``"rattle6"`` or ``"rattle8"`` its symmetric
    compositions of order 4, 6 and 8 (3, 7 and 15 RATTLE sub-steps per step; the work bound counts
    them), each point's numbers those of :func:`pendulab.simulate_ensemble` with that method bit for
    bit; the method is recorded in ``metadata["spec"]["method"]`` and in ``out`` (simulated
    quantities only). ``settle_time`` (the time after which the sway from the stable
    equilibrium stays within ``settle_angle`` [rad]; +inf if not settled by t_end) needs
    ``settle_angle``. The exact quantities (rotation_number, period) need an undamped pendulum.
    ``arithmetic``: RATTLE's multiply-adds, as in :func:`pendulab.simulate_ensemble`: ``"auto"``
    (default; ``"fused"`` where the CPU has FMA, else ``"unfused"``), ``"unfused"`` or ``"fused"``;
    resolved once when the sweep is set up and recorded in ``metadata["spec"]["arithmetic"]`` and in
    ``out``, with the version of that arithmetic's bits in ``["arithmetic_version"]`` (simulated
    quantities only).

    The points are split into chunks of ``chunk_size`` (default :func:`default_chunk_size`), each one
    ensemble run or one vectorised exact evaluation, run by ``backend``: ``"threads"`` (default; a
    pool of ``workers`` threads, default the number of CPUs) or ``"dask"`` (a new LocalCluster of
    ``workers`` processes, or the scheduler at the address ``scheduler``, e.g. ``tcp://HOST:8786``,
    or a ``distributed.Client``; the default backend when ``scheduler`` is given).

    ``out``: a directory (one Parquet file per chunk and ``_manifest.json``) or a ``.parquet`` file
    (chunks staged beside it, merged at the end); each chunk is written atomically as it finishes.
    ``resume=True`` continues a sweep of the same settings in ``out``, skipping the chunks already
    there; a sweep computed with another ``method`` is refused (one that records none ran "rattle");
    with ``arithmetic="auto"`` it takes the arithmetic recorded there (a named one that differs
    is refused, and so is a sweep of another version of the arithmetic's bits, or of none recorded
    where this pendulab's version is not 1: start a new sweep then; a sweep written before the
    arithmetic was recorded continues with this run's and warns, ``RuntimeWarning``; refusals are
    ``ResumeConflict``, an ``InvalidInputError``). Ctrl-C writes the chunks that have finished, then
    raises ``KeyboardInterrupt``.
    ``progress``: a bar over chunks on stderr (default: for sweeps of more than a few seconds).

    Returns a :class:`~pendulab.sweeps.results.SweepResult` (columns as NumPy arrays, ``to_xarray()``).

    Examples
    --------
    >>> import numpy as np
    >>> import pendulab as pl
    >>> design = {'theta0': np.linspace(0.5, 1.5, 3), 'phi_dot0': [1.0]}
    >>> sw = pl.sweep(design, 'rotation_number', progress=False)
    >>> sw
    SweepResult(3 points (grid), quantities ['rotation_number'])
    >>> sw['rotation_number'].shape
    (3,)
    """
    t0 = time.perf_counter()
    d = as_design(design)
    spec = make_spec(d, quantity, pendulum, fixed, t_end, dt, settle_angle, arithmetic, method)
    check_work(d, spec)
    backend, workers, chunk_size = _check_backend(backend, scheduler, workers, chunk_size)
    spec, recorded, unrecorded = resume_settings(d, spec, arithmetic, out, resume)
    fp = fingerprint(d, recorded)
    units = {"point": "1", **{k: AXES[k] for k in d.names}, **spec.output_units()}
    meta = {"design": d.describe(), "spec": recorded.describe(), "fingerprint": fp, "columns": units}
    target, size = _open_target(out, resume, meta, chunk_size, spec, d.n, units)
    n_chunks = math.ceil(d.n / size)
    todo = [i for i in range(n_chunks) if not target.has(i)]
    if todo and unrecorded is not None:
        warn_user(unrecorded, RuntimeWarning)
    stats: dict[str, Any] = {"chunks": n_chunks, "chunk_size": size, "skipped": n_chunks - len(todo)}
    stats["computed"] = 0
    if progress is None:
        work = len(todo) * size * (max(spec.steps * spec.substeps, 1) / 2e8 if spec.simulated else 3e-6)
        progress = len(todo) > 1 and work > 3.0
    runner: Threads | Dask | None = None
    if todo:
        threads = backend == "threads"
        runner = Threads(workers or os.cpu_count() or 1) if threads else Dask(scheduler, workers)
        if isinstance(runner, Dask) and spec.simulated:
            try:  # every worker runs this pendulab's settings, before any chunk is computed
                check_workers(runner.ask(ran, spec), spec)
            except BaseException:
                runner.close()
                raise
    stats["backend"] = runner.name if runner is not None else backend

    def task(i: int) -> ChunkTask:
        start, stop = i * size, min((i + 1) * size, d.n)
        return ChunkTask(i, start, stop, d.columns(start, stop), spec)

    def done(i: int, cols: dict[str, Any]) -> None:
        target.add(i, i * size, check_ran(i, cols, spec))  # refused if the worker ran other settings
        stats["computed"] += 1

    bar = tqdm(
        total=n_chunks,
        initial=n_chunks - len(todo),
        disable=not progress,
        unit="chunk",
        desc=f"sweep {'+'.join(spec.quantities)}",
        leave=False,
    )
    try:
        with bar:
            if runner is not None:
                drive(runner, compute_chunk, todo, task, done, bar)
    finally:
        target.flush()
    stats["seconds"] = time.perf_counter() - t0
    return target.result(d, spec.quantities, meta, stats)


__all__ = [
    "BACKENDS",
    "QUANTITIES",
    "SIMULATED",
    "ChunkTask",
    "SweepResult",
    "SweepSpec",
    "compute_chunk",
    "connect",
    "default_chunk_size",
    "fingerprint",
    "make_spec",
    "sweep",
]
