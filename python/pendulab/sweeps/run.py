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
``final_state``     m, m/s  x, y, z, vx, vy, vz at ``t_end`` (RATTLE, step ``dt``, as
                            ``simulate_ensemble``)
``rotation_number`` 1       W = Δφ/2π per z-period, exact (T-4.5); NaN for J₃ = 0 or g = 0
``period``          s       the z-period T_z of the exact solution (``ExactSolution.period_z``); inf
                            on the separatrix, NaN at rest
``max_sway``        rad     the largest polar angle from the downward vertical over 0 … t_end,
                            arccos(−z_max/l), z_max checked at every RATTLE step
``energy_drift``    1       (max E − min E) over the run / (m|g|l): RATTLE's energy error
=================== ======= ======================================================================

The exact quantities need no ``t_end``; the others integrate once for all of them. Every point is
computed independently of the chunking and of the backend, so results are the same bit for bit
whatever ``chunk_size``, ``workers`` or ``backend``.
"""

from __future__ import annotations

import difflib
import hashlib
import json
import math
import os
import threading
import time
from collections.abc import Mapping, Sequence
from dataclasses import asdict, dataclass
from typing import Any

import numpy as np
from tqdm.auto import tqdm

from . import _core
from .ensemble import max_sway, model_damping
from .model import FloatArray, Pendulum
from .sweep_backends import Dask, Threads, connect, drive
from .sweep_design import AXES, INITIAL_AXES, Design, as_design, check_axis_name
from .sweep_io import MemorySink, OutputDir, SweepResult

QUANTITIES: dict[str, dict[str, str]] = {
    "final_state": {"x": "m", "y": "m", "z": "m", "vx": "m/s", "vy": "m/s", "vz": "m/s"},
    "rotation_number": {"rotation_number": "1"},
    "period": {"period": "s"},
    "max_sway": {"max_sway": "rad"},
    "energy_drift": {"energy_drift": "1"},
    "settle_time": {"settle_time": "s"},
}
"""Quantity name → the result columns it makes, with their units."""

SIMULATED = ("final_state", "max_sway", "energy_drift", "settle_time")
"""The quantities that integrate (RATTLE to t_end); the others come from the exact solution."""

BACKENDS = ("threads", "dask")

TARGET_CHUNK_WORK = 1e8
"""Trajectory-steps per chunk of a simulated sweep by default (≈ 0.5 s on 2 cores)."""

EXACT_CHUNK = 50_000
"""Points per chunk of an exact-only sweep by default."""

MAX_CHUNK = 10_000_000


class _Cancelled(Exception):
    """A chunk stopped because the sweep was interrupted (never written)."""


def _bad(message: str) -> _core.InvalidInputError:
    return _core.InvalidInputError(message)


# --- what to compute -----------------------------------------------------------------------------


@dataclass(frozen=True)
class SweepSpec:
    """Everything but the points: the quantities, the pendulum (l [m], g [m/s²], m [kg]) used where
    the design does not vary length or g, the fixed initial conditions (``fixed``: axis → value; 0
    for those not given), for simulated quantities ``t_end`` [s] and ``dt`` [s], the linear damping
    c [1/s] where the design does not vary it, and for ``settle_time`` the ``settle_angle`` [rad]."""

    quantities: tuple[str, ...]
    length: float
    g: float
    mass: float
    fixed: dict[str, float]
    t_end: float | None = None
    dt: float | None = None
    damping: float = 0.0
    settle_angle: float | None = None

    @property
    def simulated(self) -> bool:
        return any(q in SIMULATED for q in self.quantities)

    @property
    def steps(self) -> int:
        return 0 if not self.simulated else round(float(self.t_end or 0.0) / float(self.dt or 1.0))

    def output_units(self) -> dict[str, str]:
        """The quantity columns with their units, in order."""
        return {c: u for q in self.quantities for c, u in QUANTITIES[q].items()}

    def describe(self) -> dict[str, Any]:
        d = asdict(self) | {"quantities": list(self.quantities)}
        # settings at their defaults are left out, so that sweeps written before they existed resume
        for key, default in (("damping", 0.0), ("settle_angle", None)):
            if d[key] == default:
                del d[key]
        return d


def _quantities(quantity: str | Sequence[str]) -> tuple[str, ...]:
    names = [quantity] if isinstance(quantity, str) else list(quantity)
    if not names:
        raise _bad(f"give at least one quantity: {', '.join(QUANTITIES)}")
    for q in names:
        if not isinstance(q, str) or q not in QUANTITIES:
            hint = difflib.get_close_matches(str(q), list(QUANTITIES), n=1)
            did = f" (did you mean {hint[0]!r}?)" if hint else ""
            raise _bad(f"unknown quantity {q!r}{did}; the quantities are {', '.join(QUANTITIES)}")
    return tuple(q for q in QUANTITIES if q in names)  # canonical order, no duplicates


def make_spec(
    design: Design,
    quantity: str | Sequence[str],
    pendulum: Pendulum | None = None,
    fixed: Mapping[str, float] | None = None,
    t_end: float | None = None,
    dt: float | None = None,
    settle_angle: float | None = None,
) -> SweepSpec:
    """Checks and collects the settings of a sweep over ``design`` (see :func:`sweep`)."""
    quantities = _quantities(quantity)
    p = Pendulum() if pendulum is None else pendulum
    if not isinstance(p, Pendulum):
        raise _bad(f"pendulum must be a pendulab.Pendulum, got {type(p).__name__}")
    try:
        damping = model_damping(p)
    except _core.InvalidInputError:
        raise _bad(
            f"sweeps run the ideal pendulum, optionally with linear damping (exact solution, ensemble "
            f"kernel), not {p!r}"
        ) from None
    exact = [q for q in quantities if q not in SIMULATED]
    if exact and (damping != 0.0 or "damping" in design.names):
        raise _bad(
            f"{', '.join(exact)} come from the exact solution of the undamped pendulum: "
            "remove the damping or compute simulated quantities only"
        )
    if "settle_time" in quantities:
        if settle_angle is None:
            raise _bad("settle_time needs settle_angle [rad]: the sway angle that counts as settled")
        if not (isinstance(settle_angle, int | float) and 0 < settle_angle < math.pi):
            raise _bad(f"settle_angle = {settle_angle!r} must be a sway angle in (0, π) rad")
        settle_angle = float(settle_angle)
    else:
        settle_angle = None
    fixed_values: dict[str, float] = {}
    for name, value in (fixed or {}).items():
        check_axis_name(name, "fixed value")
        if name not in INITIAL_AXES:
            raise _bad(
                f"fixed {name!r}: set length and g on the pendulum; fixed takes {', '.join(INITIAL_AXES)}"
            )
        if name in design.names:
            raise _bad(f"{name!r} is both an axis of the design and a fixed value")
        try:
            v = float(value)
        except (TypeError, ValueError):
            raise _bad(f"fixed {name} = {value!r}: must be a number in {AXES[name]}") from None
        if not math.isfinite(v):
            raise _bad(f"fixed {name} = {value!r} {AXES[name]} must be finite")
        fixed_values[name] = v
    for name in INITIAL_AXES:
        if name not in design.names:
            fixed_values.setdefault(name, 0.0)
    if any(q in SIMULATED for q in quantities):
        dt = 1e-3 if dt is None else dt
        sim = [q for q in quantities if q in SIMULATED]
        if t_end is None:
            verb = "integrates" if len(sim) == 1 else "integrate"
            raise _bad(f"{', '.join(sim)} {verb}: give t_end [s] (and dt [s])")
        if not (isinstance(dt, int | float) and math.isfinite(dt) and dt > 0):
            raise _bad(f"dt = {dt!r} must be a finite step > 0 s")
        steps = round(t_end / dt) if math.isfinite(t_end) else 0
        if not (math.isfinite(t_end) and t_end > 0 and abs(steps * dt - t_end) <= 1e-9 * t_end):
            raise _bad(f"t_end = {t_end!r} s must be > 0 and a multiple of dt = {dt!r} s")
        t_end, dt = float(t_end), float(dt)
    else:
        t_end = dt = None  # not used: not part of what the results depend on
    fixed_sorted = dict(sorted(fixed_values.items()))
    return SweepSpec(quantities, p.length, p.g, p.mass, fixed_sorted, t_end, dt, damping, settle_angle)


def fingerprint(design: Design, spec: SweepSpec) -> str:
    """SHA-256 of the points and the settings: equal prints, equal results (the key of resuming)."""
    text = json.dumps({"design": design.fingerprint(), "spec": spec.describe()}, sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


# --- one chunk -----------------------------------------------------------------------------------


@dataclass(frozen=True)
class ChunkTask:
    """Chunk ``index``: points ``start`` … ``stop − 1`` with their design values ``inputs``."""

    index: int
    start: int
    stop: int
    inputs: dict[str, FloatArray]
    spec: SweepSpec


def _full(task: ChunkTask) -> dict[str, FloatArray]:
    m, s = task.stop - task.start, task.spec
    base = {"length": s.length, "g": s.g, "damping": s.damping, **s.fixed}
    return {k: np.asarray(task.inputs[k]) if k in task.inputs else np.full(m, float(base[k])) for k in AXES}


def _states(c: dict[str, FloatArray], mass: float) -> tuple[FloatArray, FloatArray]:
    """(x, v) of every point, by the same core call as ``Pendulum.state_from_angles``."""
    m = len(c["theta0"])
    x, v = np.empty((m, 3)), np.empty((m, 3))
    for i in range(m):
        x[i], v[i] = _core.state_from_angles(
            float(c["length"][i]),
            mass,
            float(c["g"][i]),
            float(c["theta0"][i]),
            float(c["phi0"][i]),
            float(c["theta_dot0"][i]),
            float(c["phi_dot0"][i]),
        )
    return x, v


def _rotation_numbers(c: dict[str, FloatArray], mass: float) -> FloatArray:
    """W from ε = E/(m|g|l) and j = J₃/(m l² ω₀), computed from the angles; the few points the
    vectorised map leaves NaN with J₃ ≠ 0 (on the conical boundary, to rounding) go through the exact
    solution itself, as ``pl.exact(p, s).rotation_number`` does."""
    th, thd, phd, length, g = c["theta0"], c["theta_dot0"], c["phi_dot0"], c["length"], c["g"]
    s2 = np.sin(th) ** 2
    with np.errstate(divide="ignore", invalid="ignore"):
        omega0 = np.sqrt(np.abs(g) / length)
        eps = (0.5 * length * (thd**2 + s2 * phd**2) - g * np.cos(th)) / np.abs(g)
        j = s2 * phd / omega0
    ok = (g != 0.0) & np.isfinite(eps) & np.isfinite(j)
    w = np.full(len(th), np.nan)
    w[ok] = _core.rotation_numbers(np.ascontiguousarray(eps[ok]), np.ascontiguousarray(j[ok]))
    for i in np.flatnonzero(ok & np.isnan(w) & (j != 0.0)):
        one = {k: a[i : i + 1] for k, a in c.items()}
        x, v = _states(one, mass)
        adv = _core.ExactSolution(float(length[i]), mass, float(g[i]), x[0], v[0]).azimuth_advance
        w[i] = np.nan if adv is None else adv / (2.0 * math.pi)
    return w


def _periods(c: dict[str, FloatArray], mass: float) -> FloatArray:
    x, v = _states(c, mass)
    out = np.empty(len(x))
    for i in range(len(x)):
        tz = _core.ExactSolution(float(c["length"][i]), mass, float(c["g"][i]), x[i], v[i]).period_z
        out[i] = np.nan if tz is None else tz
    return out


def _simulate(
    c: dict[str, FloatArray], spec: SweepSpec, cancel: threading.Event | None
) -> dict[str, FloatArray]:
    x, v = _states(c, spec.mass)
    length, g = np.ascontiguousarray(c["length"]), np.ascontiguousarray(c["g"])
    need_summary = "max_sway" in spec.quantities or "energy_drift" in spec.quantities
    damping = np.ascontiguousarray(c["damping"])
    dt, settle = float(spec.dt or 0.0), spec.settle_angle
    run = _core.EnsembleRun(x, v, length, g, dt, spec.steps, None, need_summary, damping, settle)
    pause = 1e-3
    while not run.done:
        if cancel is not None and cancel.wait(pause):
            run.cancel()
            run.result()
            raise _Cancelled
        if cancel is None:
            time.sleep(pause)
        pause = min(2 * pause, 0.02)
    res = run.result()
    if res["cancelled"]:  # pragma: no cover - only a cancel above stops it
        raise _Cancelled
    out: dict[str, FloatArray] = {}
    if "final_state" in spec.quantities:
        xf, vf = res["x"][:, -1, :], res["v"][:, -1, :]
        for k, name in enumerate(("x", "y", "z")):
            out[name] = np.ascontiguousarray(xf[:, k])
            out["v" + name] = np.ascontiguousarray(vf[:, k])
    if "max_sway" in spec.quantities:
        out["max_sway"] = max_sway(res["z_min"], res["z_max"], g, length)
    if "settle_time" in spec.quantities:
        out["settle_time"] = res["settle_time"]
    if "energy_drift" in spec.quantities:
        scale = np.abs(g) * length
        scale = np.where(g != 0.0, scale, 0.5 * np.einsum("ij,ij->i", v, v))
        with np.errstate(divide="ignore", invalid="ignore"):
            out["energy_drift"] = np.where(scale > 0, (res["e_max"] - res["e_min"]) / scale, np.nan)
    return out


def compute_chunk(task: ChunkTask, cancel: threading.Event | None = None) -> dict[str, FloatArray]:
    """The result columns of one chunk: ``point`` (int64), the design's axes, then the quantity columns
    (float64), one row per point. Pure: the same task gives the same numbers anywhere (it is what the
    thread pool and the Dask workers run). ``cancel`` stops a simulation within ~1024 steps."""
    spec = task.spec
    c = _full(task)
    out: dict[str, Any] = {"point": np.arange(task.start, task.stop, dtype=np.int64)}
    out.update({k: np.asarray(v, dtype=np.float64) for k, v in task.inputs.items()})
    sim = _simulate(c, spec, cancel) if spec.simulated else {}
    for q in spec.quantities:
        if q == "rotation_number":
            out[q] = _rotation_numbers(c, spec.mass)
        elif q == "period":
            out[q] = _periods(c, spec.mass)
        else:
            out.update({k: sim[k] for k in QUANTITIES[q]})
    return out


# --- the sweep -----------------------------------------------------------------------------------


def default_chunk_size(spec: SweepSpec) -> int:
    """Points per chunk: :data:`EXACT_CHUNK` for exact quantities; for simulated ones about
    :data:`TARGET_CHUNK_WORK` trajectory-steps, a multiple of 64 (the kernel's block), 64 … 100 000."""
    if not spec.simulated:
        return EXACT_CHUNK
    per = TARGET_CHUNK_WORK / max(spec.steps, 1)
    return int(min(max(64 * round(per / 64), 64), 100_000))


def _positive_int(name: str, value: Any, most: int) -> int:
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or not 1 <= value <= most:
        raise _bad(f"{name} = {value!r} must be an integer from 1 to {most}")
    return int(value)


def sweep(
    design: Any,
    quantity: str | Sequence[str],
    *,
    pendulum: Pendulum | None = None,
    fixed: Mapping[str, float] | None = None,
    t_end: float | None = None,
    dt: float | None = None,
    settle_angle: float | None = None,
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
    :mod:`pendulab.sweep_design`; axes ``theta0``, ``phi0`` [rad], ``theta_dot0``, ``phi_dot0`` [rad/s],
    ``length`` [m], ``g`` [m/s²], ``damping`` [1/s]. ``pendulum`` (ideal, or ``damped`` with linear
    damping only; default l = 1 m, g = 9.81 m/s², m = 1 kg) gives length, g and damping where the
    design does not vary them; ``fixed`` sets initial conditions that are not axes (default 0).
    Simulated quantities integrate with RATTLE to ``t_end`` [s] at step ``dt`` [s] (default 1e-3 s;
    t_end a multiple of dt). ``settle_time`` (the time after which the sway from the stable
    equilibrium stays within ``settle_angle`` [rad]; +inf if not settled by t_end) needs
    ``settle_angle``. The exact quantities (rotation_number, period) need an undamped pendulum.

    The points are split into chunks of ``chunk_size`` (default :func:`default_chunk_size`), each one
    ensemble run or one vectorised exact evaluation, run by ``backend``: ``"threads"`` (default; a
    pool of ``workers`` threads, default the number of CPUs) or ``"dask"`` (a new LocalCluster of
    ``workers`` processes, or the scheduler at the address ``scheduler``, e.g. ``tcp://HOST:8786``,
    or a ``distributed.Client``; the default backend when ``scheduler`` is given).

    ``out``: a directory (one Parquet file per chunk and ``_manifest.json``) or a ``.parquet`` file
    (chunks staged beside it, merged at the end); each chunk is written atomically as it finishes.
    ``resume=True`` continues a sweep of the same settings in ``out``, skipping the chunks already
    there. Ctrl-C writes the chunks that have finished, then raises ``KeyboardInterrupt``.
    ``progress``: a bar over chunks on stderr (default: for sweeps of more than a few seconds).

    Returns a :class:`~pendulab.sweep_io.SweepResult` (columns as NumPy arrays, ``to_xarray()``).
    """
    t0 = time.perf_counter()
    d = as_design(design)
    spec = make_spec(d, quantity, pendulum, fixed, t_end, dt, settle_angle)
    if backend is None:
        backend = "threads" if scheduler is None else "dask"
    if backend not in BACKENDS:
        raise _bad(f"backend = {backend!r}: use one of {', '.join(BACKENDS)}")
    if scheduler is not None and backend != "dask":
        raise _bad(f"scheduler = {scheduler!r} needs backend 'dask', not {backend!r}")
    if workers is not None:
        workers = _positive_int("workers", workers, 1024)
    if scheduler is not None and workers is not None:
        raise _bad("workers sets the threads pool or a new LocalCluster, not a given scheduler")
    if chunk_size is not None:
        chunk_size = _positive_int("chunk_size", chunk_size, MAX_CHUNK)
    fp = fingerprint(d, spec)
    units = {"point": "1", **{k: AXES[k] for k in d.names}, **spec.output_units()}
    meta = {"design": d.describe(), "spec": spec.describe(), "fingerprint": fp, "columns": units}
    target: MemorySink | OutputDir
    if out is None:
        if resume:
            raise _bad("resume=True needs out (the directory or .parquet file to continue)")
        size = chunk_size or default_chunk_size(spec)
        target = MemorySink(d.n, units)
    else:
        target = OutputDir.open(out, meta, chunk_size, default_chunk_size(spec), d.n, resume)
        size = target.chunk_size
    n_chunks = math.ceil(d.n / size)
    todo = [i for i in range(n_chunks) if not target.has(i)]
    stats: dict[str, Any] = {"chunks": n_chunks, "chunk_size": size, "skipped": n_chunks - len(todo)}
    stats["computed"] = 0
    if progress is None:
        work = len(todo) * size * (max(spec.steps, 1) / 2e8 if spec.simulated else 3e-6)
        progress = len(todo) > 1 and work > 3.0
    runner: Threads | Dask | None = None
    if todo:
        threads = backend == "threads"
        runner = Threads(workers or os.cpu_count() or 1) if threads else Dask(scheduler, workers)
    stats["backend"] = runner.name if runner is not None else backend

    def task(i: int) -> ChunkTask:
        start, stop = i * size, min((i + 1) * size, d.n)
        return ChunkTask(i, start, stop, d.columns(start, stop), spec)

    def done(i: int, cols: dict[str, FloatArray]) -> None:
        target.add(i, i * size, cols)
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
